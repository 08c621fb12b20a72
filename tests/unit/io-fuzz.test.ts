// Randomly damaged fixtures (seeded, so reproducible) must either parse into a valid indexed mesh
// or throw a one-line MeshFormatError: never a RangeError, a hang or out-of-range indices.
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { MeshFormatError, parseMesh } from '../../lib/io/index.ts';
import { fixture } from '../paths.ts';

const MUTATIONS_PER_FILE = 1000;
const TEXT_BYTES = '0123456789 -+.e\n/#';

/** mulberry32: a tiny deterministic PRNG. */
function random(seed: number): () => number {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 2 ** 32;
  };
}

/** Random bytes overwritten, a random cut, or one byte replaced by something number-like. */
function mutate(original: Uint8Array, rnd: () => number): Uint8Array {
  const at = () => Math.floor(rnd() * original.length);
  const kind = rnd();
  if (kind < 0.3) return original.subarray(0, at());
  const bytes = original.slice();
  if (kind < 0.65) for (let i = 0; i < 3; i++) bytes[at()] = Math.floor(rnd() * 256);
  else bytes[at()] = TEXT_BYTES.charCodeAt(Math.floor(rnd() * TEXT_BYTES.length));
  return bytes;
}

describe('damaged fixtures', () => {
  const files = readdirSync(fixture('formats')).filter((name) => name.startsWith('cube'));

  it.each(files)('%s', (file) => {
    const original = new Uint8Array(readFileSync(fixture('formats', file)));
    const rnd = random(file.length * 7919);
    for (let k = 0; k < MUTATIONS_PER_FILE; k++) {
      const bytes = mutate(original, rnd);
      let mesh;
      try {
        mesh = parseMesh(bytes, file);
      } catch (error) {
        if (!(error instanceof MeshFormatError)) throw error;
        expect(error.message).not.toContain('\n');
        continue;
      }
      const vertexCount = mesh.positions.length / 3;
      expect(Number.isInteger(vertexCount) && mesh.triangles.length % 3 === 0).toBe(true);
      expect(mesh.triangles.every((v) => v < vertexCount)).toBe(true);
    }
  });
});
