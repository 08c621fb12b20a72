// Separators that end on the boundary (paper Sec. 3.2 and App. "Results on Meshes with Holes").
// Sheets made in code, so the right answer is known: a strip's cross-sections, a plus sign's arms.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core, type MeshArrays, type Surface } from '../../lib/core/node.ts';
import { cscd } from './support/cli.ts';
import { offText, readMesh, sheet } from './support/meshes.ts';
import { degrees } from './support/topology.ts';
import { sharedMesh } from '../paths.ts';

const point = (flat: ArrayLike<number>, i: number) => [flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]];

/** A 4 x 1 strip in the xy plane, centred on the origin. */
const STRIP = sheet([-2, 2], [-0.5, 0.5], 0.04, (x, y) => Math.abs(x) < 2 && Math.abs(y) < 0.5);
/** Two 3 x 0.6 bars crossing at the origin. */
const PLUS = sheet([-1.5, 1.5], [-1.5, 1.5], 0.04, (x, y) => (Math.abs(x) < 1.5 && Math.abs(y) < 0.3) || (Math.abs(x) < 0.3 && Math.abs(y) < 1.5));
/** A 4 x 0.8 strip bent into a U around the z axis: its middle line is an arc of radius 1.2 at z = 0. */
const BENT_RADIUS = 1.2;
const BENT = sheet([-2, 2], [-0.4, 0.4], 0.04, (x, y) => Math.abs(x) < 2 && Math.abs(y) < 0.4, (x, y) => [
  BENT_RADIUS * Math.sin(x / BENT_RADIUS),
  -BENT_RADIUS * Math.cos(x / BENT_RADIUS),
  y,
]);

/** A flat ring, radii 0.6 and 1: two boundary loops, its middle circle at radius 0.8. */
const WASHER = sheet([-1, 1], [-1, 1], 0.04, (x, y) => Math.hypot(x, y) < 1 && Math.hypot(x, y) > 0.6);
/** A 3 x 2 plate with a 2.2 x 1.2 window: four bars 0.4 wide, their middle lines at x = +-1.3, y = +-0.8. */
const FRAME = sheet([-1.5, 1.5], [-1, 1], 0.04, (x, y) => Math.abs(x) < 1.5 && Math.abs(y) < 1 && !(Math.abs(x) < 1.1 && Math.abs(y) < 0.6));

let core: Core;
const open: Surface[] = [];
beforeAll(async () => {
  core = await loadCoreNode();
});
afterAll(() => open.forEach((s) => s.dispose()));

function surfaceOf(mesh: MeshArrays): Surface {
  const surface = core.openSurface(mesh);
  open.push(surface);
  return surface;
}

/** The vertex nearest to (x, y, 0). */
function vertexNear(mesh: MeshArrays, x: number, y: number): number {
  let best = 0;
  for (let v = 1; v < mesh.positions.length / 3; v++)
    if (Math.hypot(mesh.positions[3 * v] - x, mesh.positions[3 * v + 1] - y) < Math.hypot(mesh.positions[3 * best] - x, mesh.positions[3 * best + 1] - y))
      best = v;
  return best;
}

describe('a separator on a sheet', () => {
  it.each([-1.2, -0.4, 0.5, 1.3])('from the middle of a strip at x = %s runs straight across it, side to side', (x) => {
    const source = vertexNear(STRIP, x, 0.05);
    const s = surfaceOf(STRIP).separator(source);
    expect(s.status).toBe('ok');
    expect(s.closed).toBe(false);
    expect(s.target).toBeNull();
    const ends = [point(s.endPoints!, 0), point(s.endPoints!, 1)];
    // One end on each long side, across from the source: the gradients there point in opposite directions.
    expect(ends.map((e) => Math.abs(e[1]))).toEqual([expect.closeTo(0.5, 2), expect.closeTo(0.5, 2)]);
    expect(Math.sign(ends[0][1])).toBe(-Math.sign(ends[1][1]));
    for (const e of ends) expect(Math.abs(e[0] - STRIP.positions[3 * source])).toBeLessThan(0.1);
    // Shortened with its ends held: the straight cross-section, one unit long.
    expect(s.length).toBeGreaterThan(0.99);
    expect(s.length).toBeLessThan(1.02);
    const loop = s.loop;
    expect(point(loop, 0)).toEqual(ends[0]);
    expect(point(loop, loop.length / 3 - 1)).toEqual(ends[1]);
    expect(s.areas[0]).toBeGreaterThan(0);
    expect(s.score).toBeGreaterThan(0);
  });

  it('only ever joins two points of the boundary that face each other: never across a corner', () => {
    const surface = surfaceOf(STRIP);
    let inner = 0;
    let innerPaths = 0;
    for (let x = -1.9; x <= 1.9; x += 0.3)
      for (const y of [-0.4, -0.2, 0, 0.2, 0.4]) {
        const s = surface.separator(vertexNear(STRIP, x, y));
        const interior = Math.abs(x) < 1.7 && Math.abs(y) < 0.3;
        inner += interior ? 1 : 0;
        if (s.status !== 'ok') continue;
        innerPaths += interior ? 1 : 0;
        const ends = [point(s.endPoints!, 0), point(s.endPoints!, 1)];
        // Both ends on the long sides, on opposite ones: a long side and an end (90 degrees apart at a
        // corner) are not a pair whose gradients cancel, nor are the two ends of the strip ever nearest.
        expect(ends.map((e) => Math.abs(e[1]) > 0.49)).toEqual([true, true]);
        expect(Math.sign(ends[0][1])).toBe(-Math.sign(ends[1][1]));
      }
    // Near the boundary and the corners there may be none (the heat distance bends there); inside, always.
    expect(innerPaths).toBe(inner);
  });

  it('has no cut locus along the boundary (a one-sided Laplacian is no ridge)', () => {
    const uses = new Map<string, number>();
    for (let f = 0; f < PLUS.triangles.length / 3; f++)
      for (let k = 0; k < 3; k++) {
        const [a, b] = [PLUS.triangles[3 * f + k], PLUS.triangles[3 * f + ((k + 1) % 3)]].sort((x, y) => x - y);
        uses.set(`${a} ${b}`, (uses.get(`${a} ${b}`) ?? 0) + 1);
      }
    const onBoundary = new Set([...uses].filter(([, n]) => n === 1).flatMap(([key]) => key.split(' ').map(Number)));
    const s = surfaceOf(PLUS).separator(vertexNear(PLUS, 0.9, 0.05));
    // Only the root (the farthest vertex, where the graph is grown from) may lie on the boundary.
    const onIt = Array.from(s.cutLocus.vertices).filter((v) => v !== s.cutLocus.root && onBoundary.has(v));
    expect(onIt).toEqual([]);
  });

  it('comes out of the CLI with its ends', async () => {
    const folder = mkdtempSync(path.join(tmpdir(), 'cscd-boundary-'));
    const file = path.join(folder, 'strip.off');
    writeFileSync(file, offText(STRIP));
    const { status, stdout } = await cscd('separator', file, '--source', String(vertexNear(STRIP, 0.3, 0)));
    expect(status).toBe(0);
    const json = JSON.parse(stdout);
    expect(json).toMatchObject({ status: 'ok', closed: false, target: null });
    expect(json.ends).toHaveLength(2);
    expect(json.boundaryExtremities.length).toBeGreaterThanOrEqual(2);
  });
});

/** The mesh without the faces that have a corner at or below `height` on axis `axis` (a scan cut open). */
function cutBelow(mesh: MeshArrays, axis: number, height: number): MeshArrays {
  const index = new Map<number, number>();
  const positions: number[] = [];
  const triangles: number[] = [];
  for (let f = 0; f < mesh.triangles.length / 3; f++) {
    const corners = [0, 1, 2].map((k) => mesh.triangles[3 * f + k]);
    if (corners.some((v) => mesh.positions[3 * v + axis] <= height)) continue;
    for (const v of corners) {
      if (!index.has(v)) {
        index.set(v, positions.length / 3);
        positions.push(...point(mesh.positions, v));
      }
      triangles.push(index.get(v)!);
    }
  }
  return { positions: Float64Array.from(positions), triangles: Uint32Array.from(triangles) };
}

describe('the skeleton of an open surface', () => {
  it('of the hand cut open at the wrist still has a leaf per finger and one at the wrist, from loops only', () => {
    // hand.ply spans y from -104 to 113, the wrist at the bottom: cutting at y = -95 leaves one boundary loop.
    const mesh = cutBelow(readMesh(sharedMesh('hand.ply')), 1, -95);
    const surface = surfaceOf(mesh);
    expect(surface.facts.boundaryLoops).toBe(1);
    const skeleton = surface.skeleton({});
    const degree = degrees(skeleton);
    expect(skeleton.stats.cycles).toBe(0);
    expect(degree.filter((d) => d === 1)).toHaveLength(6);
    // The rim is a single boundary loop around a tube: no two of its points face each other.
    expect(skeleton.candidates.closed.every((closed) => closed === 1)).toBe(true);
    const lowest = Math.min(...degree.map((_, i) => point(skeleton.nodes, i)[1]));
    expect(lowest).toBeLessThan(-85);
  });

  it('of a strip is one path along its middle, from end to end', () => {
    const skeleton = surfaceOf(STRIP).skeleton({});
    const degree = degrees(skeleton);
    expect(skeleton.stats.cycles).toBe(0);
    expect(degree.filter((d) => d === 1)).toHaveLength(2);
    expect(degree.every((d) => d >= 1 && d <= 2)).toBe(true);
    const nodes = degree.map((_, i) => point(skeleton.nodes, i));
    for (const p of nodes) expect(Math.abs(p[1])).toBeLessThan(0.05);
    const xs = nodes.map((p) => p[0]);
    expect(Math.min(...xs)).toBeLessThan(-1.6);
    expect(Math.max(...xs)).toBeGreaterThan(1.6);
    for (const i of skeleton.packed) expect(skeleton.candidates.closed[i]).toBe(0);
  });

  it('of a plus sign has four arms meeting at one branch node in the middle', () => {
    const skeleton = surfaceOf(PLUS).skeleton({});
    const degree = degrees(skeleton);
    expect(skeleton.stats.cycles).toBe(0);
    const leaves = degree.flatMap((d, i) => (d === 1 ? [point(skeleton.nodes, i)] : []));
    const branches = degree.flatMap((d, i) => (d >= 3 ? [point(skeleton.nodes, i)] : []));
    expect(branches).toHaveLength(1);
    expect(Math.hypot(branches[0][0], branches[0][1])).toBeLessThan(0.15);
    expect(leaves).toHaveLength(4);
    for (const tip of [[1.5, 0], [-1.5, 0], [0, 1.5], [0, -1.5]])
      expect(Math.min(...leaves.map((p) => Math.hypot(p[0] - tip[0], p[1] - tip[1])))).toBeLessThan(0.3);
  });

  it.each([
    { name: 'a washer', mesh: WASHER, offMiddle: (x: number, y: number) => Math.abs(Math.hypot(x, y) - 0.8) },
    // A bar's middle line: |x| = 1.3 or |y| = 0.8 (corners: both).
    { name: 'a frame', mesh: FRAME, offMiddle: (x: number, y: number) => Math.min(Math.abs(Math.abs(x) - 1.3), Math.abs(Math.abs(y) - 0.8)) },
  ])('of $name is one cycle along its middle line, from paths between its two boundary loops', ({ mesh, offMiddle }) => {
    const skeleton = surfaceOf(mesh).skeleton({});
    expect(skeleton.stats.cycles).toBe(1);
    expect(degrees(skeleton).every((d) => d === 2)).toBe(true);
    for (let i = 0; i < skeleton.radii.length; i++) {
      const [x, y] = point(skeleton.nodes, i);
      expect(offMiddle(x, y)).toBeLessThan(0.05);
    }
    for (const i of skeleton.packed) expect(skeleton.candidates.closed[i]).toBe(0);
  });

  it('of a bent strip follows its middle line', () => {
    const skeleton = surfaceOf(BENT).skeleton({});
    const degree = degrees(skeleton);
    expect(skeleton.stats.cycles).toBe(0);
    expect(degree.filter((d) => d === 1)).toHaveLength(2);
    for (let i = 0; i < degree.length; i++) {
      const [x, y, z] = point(skeleton.nodes, i);
      expect(Math.abs(z)).toBeLessThan(0.05);
      // On the arc or inside it (a node is a path's centroid, which lies on the chord side of the sheet).
      expect(Math.hypot(x, y)).toBeLessThan(BENT_RADIUS + 0.01);
      expect(Math.hypot(x, y)).toBeGreaterThan(BENT_RADIUS - 0.05);
    }
  });
});
