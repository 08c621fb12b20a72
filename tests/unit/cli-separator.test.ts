// `cscd separator` (in-process) writing the stage-1 JSON.
import type { Point, SeparatorJson } from '../../cli/commands/separator.ts';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { defaultOptions } from '../../lib/core/options.ts';
import { sharedMesh } from '../paths.ts';
import { icosphere, offText, readMesh } from './support/meshes.ts';
import { cscd } from './support/cli.ts';

const tmp = mkdtempSync(path.join(tmpdir(), 'cscd-separator-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

const KEYS = [
  'source', 'status', 'message', 'distance', 'cutLocus', 'boundaryExtremities', 'target', 'ends', 'closed', 'paths',
  'approxLoop', 'loop', 'sphere',
  'approxLength', 'length', 'areas', 'score', 'centroidInside', 'timings', 'options', 'refined',
];


const torus = sharedMesh('torus.ply');
const dist = (a: number[], b: number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const isPoint = (p: unknown) => Array.isArray(p) && p.length === 3 && p.every(Number.isFinite);

/** Length of a polyline given as points, with the closing segment when `closed`. */
function polylineLength(points: Point[], closed: boolean): number {
  let length = 0;
  for (let i = 1; i < points.length; i++) length += dist(points[i - 1], points[i]);
  return closed ? length + dist(points[points.length - 1], points[0]) : length;
}

describe('cscd separator', () => {
  /** A vertex on the outer equator of the torus: farthest from its axis (the thinnest bbox axis). */
  let outer: number;
  let vertexCount: number;
  let json: SeparatorJson;
  beforeAll(async () => {
    const { positions } = readMesh(torus);
    vertexCount = positions.length / 3;
    const extent = [0, 1, 2].map((k) => {
      let min = Infinity, max = -Infinity;
      for (let i = k; i < positions.length; i += 3) [min, max] = [Math.min(min, positions[i]), Math.max(max, positions[i])];
      return max - min;
    });
    const axis = extent.indexOf(Math.min(...extent));
    const [u, v] = [0, 1, 2].filter((k) => k !== axis);
    let best = -1;
    for (let i = 0; i < vertexCount; i++) {
      const r = Math.hypot(positions[3 * i + u], positions[3 * i + v]);
      if (r > best) [best, outer] = [r, i];
    }
    const out = path.join(tmp, 'sep.json');
    const result = await cscd('separator', torus, '--source', String(outer), '--out', out);
    expect(result).toEqual({ status: 0, stdout: '', stderr: '' });
    json = JSON.parse(readFileSync(out, 'utf8')) as SeparatorJson;
  });

  it('writes every key, in order, for a source on the outer equator of the torus', () => {
    expect(Object.keys(json)).toEqual(KEYS);
    expect(json).toMatchObject({ source: outer, status: 'ok', message: '', options: { ...defaultOptions } });
    expect(Object.keys(json.cutLocus)).toEqual(['points', 'edges', 'vertices', 'root', 'cycleRank']);
    expect(json.distance).toHaveLength(vertexCount);
    expect(json.distance[outer]).toBeCloseTo(0, 6);
    // The cut locus of a torus from a generic source has cycle rank 2 (docs/cut-locus.md).
    expect(json.cutLocus.cycleRank).toBe(2);
    expect(json.cutLocus.points).toHaveLength(json.cutLocus.vertices.length);
    expect(json.cutLocus.points.every(isPoint)).toBe(true);
    expect(json.cutLocus.edges.flat().every((i) => Number.isInteger(i) && i >= 0 && i < json.cutLocus.points.length)).toBe(true);
    expect(isPoint(json.target)).toBe(true);
    // A closed surface: no boundary, so a loop, no boundary ends.
    expect(json).toMatchObject({ boundaryExtremities: [], ends: null, closed: true });
    expect(json.paths).toHaveLength(2);
    expect(json.paths.every((p) => p.length >= 2 && p.every(isPoint))).toBe(true);
    expect(json.sphere).not.toBeNull();
    expect(isPoint(json.sphere!.center)).toBe(true);
    expect(json.sphere!.radius).toBeGreaterThan(0);
    expect(json.areas.every(Number.isFinite)).toBe(true);
    expect(json.areas[0]).toBeLessThanOrEqual(json.areas[1]);
    expect(Number.isFinite(json.score)).toBe(true);
    expect(typeof json.centroidInside).toBe('boolean');
    expect(Object.values(json.timings).every((ms) => Number.isFinite(ms) && ms >= 0)).toBe(true);
  });

  it('gives a closed loop, shortened: 0 < length <= approxLength', () => {
    for (const loop of [json.loop, json.approxLoop]) {
      expect(loop.length).toBeGreaterThanOrEqual(3);
      expect(loop.every(isPoint)).toBe(true);
      // Closed: the segment from the last point back to the first is no longer than the loop's other segments.
      const steps = loop.slice(1).map((p, i) => dist(loop[i], p));
      expect(dist(loop[loop.length - 1], loop[0])).toBeLessThanOrEqual(Math.max(...steps) + 1e-9);
    }
    expect(json.length).toBeGreaterThan(0);
    expect(json.length).toBeLessThanOrEqual(json.approxLength);
    expect(json.length).toBeCloseTo(polylineLength(json.loop, true), 6);
    expect(json.approxLength).toBeCloseTo(polylineLength(json.approxLoop, true), 6);
    // A separator on the torus is a meridian or longer: at least the tube circumference 2 pi r = pi.
    expect(json.length).toBeGreaterThan(0.9 * Math.PI);
  });

  it('accepts --target geodesic and --no-sphere and reports them in options', async () => {
    const result = await cscd('separator', torus, '--source', String(outer), '--target', 'geodesic', '--no-sphere', '--prune-depth', '4');
    expect(result.status).toBe(0);
    const other = JSON.parse(result.stdout) as SeparatorJson;
    expect(other.options).toEqual({ ...defaultOptions, target: 'geodesic', sphere: false, pruneDepth: 4 });
    expect(other.sphere).toBeNull();
    expect(other.source).toBe(outer);
  });

  it('draws the same source from the same seed when --source is not given', async () => {
    const source = async (...args: string[]) => {
      const result = await cscd('separator', sharedMesh('two_torus.ply'), ...args);
      expect(result.status).toBe(0);
      return (JSON.parse(result.stdout) as SeparatorJson).source;
    };
    const first = await source('--seed', '7');
    expect(await source('--seed', '7')).toBe(first);
    expect(first).toBeGreaterThanOrEqual(0);
    expect(first).toBeLessThan(766);
    expect([await source(), await source('--seed', '8'), await source('--seed', '9')]).not.toEqual([first, first, first]);
  });

  it('reports a source without a separator as a status, not an error: exit 0, JSON, one warning', async () => {
    // A sphere has no feature for a loop to separate: the loop must shrink to a point (or fail earlier).
    const mesh = icosphere(3);
    const sphere = path.join(tmp, 'sphere.off');
    writeFileSync(sphere, offText(mesh));

    const result = await cscd('separator', sphere, '--source', '0');
    expect(result.status).toBe(0);
    const failed = JSON.parse(result.stdout) as SeparatorJson;
    expect(Object.keys(failed)).toEqual(KEYS);
    expect(['no-cut-locus', 'no-target', 'trace-failed', 'degenerate-loop', 'shorten-failed', 'not-separating']).toContain(failed.status);
    expect(failed.message).not.toBe('');
    expect(failed.distance).toHaveLength(mesh.positions.length / 3);
    expect(failed.loop).toEqual([]);
    expect(result.stderr).toBe(`cscd: warning: ${sphere}: no separator from source 0: ${failed.status} (${failed.message})\n`);
  });

  it('rejects bad flags with a usage error (exit 2, one cscd: line)', async () => {
    for (const [args, message] of [
      [['--target', 'foo'], "--target must be one of euclid, geodesic, got 'foo'"],
      [['--angle-threshold', 'abc'], "--angle-threshold must be a number, got 'abc'"],
      [['--laplacian-threshold', '1x'], "--laplacian-threshold must be a number, got '1x'"],
      [['--prune-depth=-1'], "--prune-depth must be an integer from 0 to 1000, got '-1'"],
      [['--laplacian-threshold=-0.5'], "--laplacian-threshold must be a number from 0 to 1000000, got '-0.5'"],
      [['--angle-threshold', '4'], "--angle-threshold must be a number from 0 to pi, got '4'"],
      [['--seed', '1.5'], "--seed must be an integer from 0 to 4294967295, got '1.5'"],
      [['--source', '7200'], "--source must be a vertex index from 0 to 7199, got '7200'"],
    ] as [string[], string][]) {
      const result = await cscd('separator', torus, ...args);
      expect(result.status).toBe(2);
      expect(result.stdout).toBe('');
      expect(result.stderr).toBe(`cscd: ${message}\n`);
    }
  });
});
