import { fileURLToPath } from 'node:url';
import path from 'node:path';

/** The repository root and the shared data set that CI checks out beside it. */
export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const sharedData = path.resolve(repoRoot, '..', 'shared', 'data');
export const sharedMesh = (name: string) => path.join(sharedData, 'meshes', name);
export const fixture = (...parts: string[]) => path.join(repoRoot, 'tests', 'fixtures', ...parts);
