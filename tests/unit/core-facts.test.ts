// Mesh facts from the core against the shared data set's MANIFEST (computed there with pymeshlab/trimesh).
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { readMesh } from './support/meshes.ts';
import { sharedData } from '../paths.ts';

interface ManifestRow {
  file: string;
  vertices: number;
  faces: number;
  manifold: boolean;
  genus: number;
  euler: number;
  components: number;
  boundaryLoops: number;
  bboxDiagonal: number;
}

/** The rows of the meshes table in MANIFEST.md. */
function manifestMeshes(): ManifestRow[] {
  const text = readFileSync(path.join(sharedData, 'MANIFEST.md'), 'utf8');
  return text
    .split('\n')
    .filter((line) => line.startsWith('| `meshes/'))
    .map((line) => {
      const c = line.split('|').map((cell) => cell.trim());
      return {
        file: c[1].replaceAll('`', ''),
        vertices: Number(c[2]),
        faces: Number(c[3]),
        manifold: c[5] === 'yes',
        genus: Number(c[6]),
        euler: Number(c[7]),
        components: Number(c[8]),
        boundaryLoops: Number(c[9]),
        bboxDiagonal: Number(c[11]),
      };
    });
}

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

const rows = manifestMeshes();

describe('mesh facts', () => {
  it('reads the whole MANIFEST table', () => {
    expect(rows.length).toBeGreaterThanOrEqual(26);
  });

  for (const row of rows) {
    it(`match MANIFEST.md for ${row.file}`, () => {
      const facts = core.inspect(readMesh(path.join(sharedData, row.file)));
      expect(facts.vertices).toBe(row.vertices);
      expect(facts.faces).toBe(row.faces);
      expect(facts.manifold).toBe(row.manifold);
      expect(facts.genus).toBe(row.genus);
      expect(facts.eulerCharacteristic).toBe(row.euler);
      expect(facts.components).toBe(row.components);
      expect(facts.boundaryLoops).toBe(row.boundaryLoops);
      expect(facts.consistentlyOriented).toBe(true);
      // MANIFEST rounds the diagonal to 4 significant digits.
      expect(Math.abs(facts.bboxDiagonal - row.bboxDiagonal) / row.bboxDiagonal).toBeLessThan(1e-3);
      expect(facts.meanEdgeLength).toBeGreaterThan(0);
      expect(facts.meanEdgeLength).toBeLessThan(facts.bboxDiagonal / 10);
    });
  }
});
