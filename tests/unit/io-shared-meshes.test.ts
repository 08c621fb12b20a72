// Every mesh of the shared data set reads with the vertex and face counts listed in its MANIFEST.md.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { parseMesh } from '../../lib/io/index.ts';
import { sharedData, sharedMesh } from '../paths.ts';

/** Rows of the manifest's mesh table: | `meshes/name.ply` | V | F | ... */
function manifestMeshes(): [name: string, vertices: number, faces: number][] {
  const manifest = readFileSync(path.join(sharedData, 'MANIFEST.md'), 'utf8');
  return [...manifest.matchAll(/^\| `meshes\/([^`]+\.ply)` \| (\d+) \| (\d+) \|/gm)].map((m) => [m[1], Number(m[2]), Number(m[3])]);
}

describe('shared meshes', () => {
  const meshes = manifestMeshes();

  it('the manifest lists the meshes', () => {
    expect(meshes.length).toBeGreaterThanOrEqual(26);
    expect(meshes).toContainEqual(['fertility.ply', 12448, 24908]);
  });

  it.each(meshes)('%s has %i vertices and %i faces', (name, vertices, faces) => {
    const mesh = parseMesh(new Uint8Array(readFileSync(sharedMesh(name))), name);
    expect(mesh.format).toBe('ply');
    expect(mesh.positions.length).toBe(3 * vertices);
    expect(mesh.triangles.length).toBe(3 * faces);
    expect(mesh.warnings).toEqual([]);
    expect(mesh.positions.every(Number.isFinite)).toBe(true);
    expect(mesh.triangles.reduce((max, v) => Math.max(max, v), 0)).toBe(vertices - 1);
  });
});
