import { fileURLToPath } from 'node:url';
import path from 'node:path';

/** The repository root and the shared data set that CI checks out beside it. */
export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const sharedData = path.resolve(repoRoot, '..', 'shared', 'data');
export const sharedMesh = (name: string) => path.join(sharedData, 'meshes', name);
/** A shape with a known skeleton (../shared/data/synthetic/README.md): `<name>.ply` and `<name>__GT.json`. */
export const sharedSynthetic = (name: string) => path.join(sharedData, 'synthetic', name);
export const fixture = (...parts: string[]) => path.join(repoRoot, 'tests', 'fixtures', ...parts);
