// CSCD-PC's stage 1 up to the approximate loop, through the real WASM module: the neighbourhood graph
// without bridges, the cut locus (one piece after the tree bridges the passing points, far from the
// source), the targets and the two descents joined into a closed loop, on a torus sampled here (the loop
// winds once around the tube), on bob and on a finger of the hand.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { CoreError, loadCoreNode, type Cloud, type CloudSeparatorStages, type Core } from '../../lib/core/node.ts';
import { meshAsCloud } from '../../lib/cloud/from-mesh.ts';
import { random } from '../../lib/core/random.ts';
import { parseShape, type ParsedCloud } from '../../lib/io/index.ts';
import { fixture, sharedMesh } from '../paths.ts';
import { nearestPoints } from './support/clouds.ts';

function readCloud(name: string): ParsedCloud {
  const shape = parseShape(new Uint8Array(readFileSync(fixture('clouds', name))), path.basename(name));
  if (shape.kind !== 'cloud') throw new Error(`${name} holds a mesh`);
  return shape;
}

/** `count` points spread uniformly (by area, from the seed) over a torus of radii R and r about the z axis, with normals. */
function torusPoints(count: number, R: number, r: number, seed: number): { positions: Float64Array; normals: Float32Array } {
  const next = random(seed);
  const positions = new Float64Array(3 * count), normals = new Float32Array(3 * count);
  for (let i = 0; i < count;) {
    const u = 2 * Math.PI * next(), v = 2 * Math.PI * next();
    if (next() * (R + r) > R + r * Math.cos(v)) continue; // area grows with the distance from the axis
    normals.set([Math.cos(v) * Math.cos(u), Math.cos(v) * Math.sin(u), Math.sin(v)], 3 * i);
    positions.set([(R + r * Math.cos(v)) * Math.cos(u), (R + r * Math.cos(v)) * Math.sin(u), r * Math.sin(v)], 3 * i);
    i++;
  }
  return { positions, normals };
}

/** Neighbour lists of the cloud's graph. */
function adjacency(cloud: Cloud): number[][] {
  const { edges } = cloud.neighbourhood();
  const adjacent: number[][] = Array.from({ length: cloud.facts.points }, () => []);
  for (let e = 0; e < edges.length; e += 2) {
    adjacent[edges[e]].push(edges[e + 1]);
    adjacent[edges[e + 1]].push(edges[e]);
  }
  return adjacent;
}

/** Connected pieces of the graph once the loop's points and their neighbours are taken out: each piece's points. */
function sidesOf(loop: Uint32Array, adjacent: number[][]): number[][] {
  const removed = new Uint8Array(adjacent.length);
  for (const p of loop) {
    removed[p] = 1;
    for (const q of adjacent[p]) removed[q] = 1;
  }
  const sides: number[][] = [];
  const seen = new Uint8Array(adjacent.length);
  for (let start = 0; start < adjacent.length; start++) {
    if (removed[start] || seen[start]) continue;
    const side = [start];
    seen[start] = 1;
    for (let k = 0; k < side.length; k++) {
      for (const q of adjacent[side[k]]) {
        if (!removed[q] && !seen[q]) {
          seen[q] = 1;
          side.push(q);
        }
      }
    }
    sides.push(side);
  }
  return sides.sort((a, b) => b.length - a.length);
}

function loopLength(loop: Uint32Array, positions: Float64Array): number {
  let length = 0;
  for (let i = 0; i < loop.length; i++) {
    const a = 3 * loop[i], b = 3 * loop[(i + 1) % loop.length];
    length += Math.hypot(positions[a] - positions[b], positions[a + 1] - positions[b + 1], positions[a + 2] - positions[b + 2]);
  }
  return length;
}

/** What every traced loop must be: closed along graph edges, through the target, through or next to the source. */
function expectClosedLoop(stages: CloudSeparatorStages, adjacent: number[][], spacing: number) {
  const loop = stages.approxLoopPoints;
  expect(stages.status, stages.message).toBe('ok');
  expect(loop.length).toBeGreaterThanOrEqual(3);
  expect(new Set(loop).size, 'no point twice').toBe(loop.length);
  loop.forEach((p, i) => expect(adjacent[p], `loop step ${i}`).toContain(loop[(i + 1) % loop.length]));
  expect(loop[0]).toBe(stages.target);
  expect(stages.pathPoints[0][0]).toBe(stages.target);
  expect(stages.pathPoints[1][0]).toBe(stages.target);
  expect(Math.min(...Array.from(loop, (p) => stages.distance[p]))).toBeLessThanOrEqual(2 * spacing);
  expect(stages.approxLoop).toHaveLength(3 * loop.length);
}

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

describe('the neighbourhood graph of a cloud', () => {
  it('keeps the hand in one piece without the edges that cross between fingers', () => {
    const hand = readCloud('hand_subsample.ply');
    const cloud = core.openCloud(hand);
    try {
      const graph = cloud.neighbourhood();
      expect(graph.components).toBe(1);
      // About three edges per point: each point's Delaunay ring in its tangent plane, about six wide.
      expect(graph.edges.length / 2 / cloud.facts.points).toBeGreaterThan(2.5);
      expect(graph.edges.length / 2 / cloud.facts.points).toBeLessThan(3.5);
      expect(graph.bridgesRemoved).toBeGreaterThan(0);
      // The file's normals point out of the hand: an edge between two points whose normals point against
      // each other crosses a gap (between two fingers) or a thin rim. Without the bridge test the local
      // triangulations of hand_clean hold 136 of them, with it 2 (docs/pointcloud.md).
      const normals = hand.normals!;
      let acrossGap = 0;
      for (let e = 0; e < graph.edges.length; e += 2) {
        const a = 3 * graph.edges[e], b = 3 * graph.edges[e + 1];
        if (normals[a] * normals[b] + normals[a + 1] * normals[b + 1] + normals[a + 2] * normals[b + 2] < 0) acrossGap++;
      }
      expect(acrossGap).toBeLessThanOrEqual(10);
    } finally {
      cloud.dispose();
    }
  });
});

describe('the cut locus on a cloud', () => {
  let bob: Cloud;
  beforeAll(() => {
    bob = core.openCloud(readCloud('bob_subsample.ply'));
  });
  afterAll(() => bob.dispose());

  it('is one piece after the tree bridges the points that pass the tests, and lies far from the source', () => {
    for (const source of [0, 400, 800, 1200, 1600]) {
      const { cutLocus, distance } = bob.separatorStages(source);
      // A plain threshold leaves pieces; the ridge tree joins them.
      expect(cutLocus.passingPieces, `source ${source}`).toBeGreaterThan(1);
      expect(cutLocus.passingPoints).toBeGreaterThan(cutLocus.passingPieces);
      const parent = Array.from(cutLocus.vertices, (_, i) => i);
      const find = (i: number): number => (parent[i] === i ? i : (parent[i] = find(parent[i])));
      for (let e = 0; e < cutLocus.edges.length; e += 2) parent[find(cutLocus.edges[e])] = find(cutLocus.edges[e + 1]);
      expect(cutLocus.vertices.filter((_, i) => find(i) === i), `source ${source}: pieces`).toHaveLength(1);
      // A tree on bob (no homology step on clouds yet).
      expect(cutLocus.cycleRank).toBe(0);
      expect(cutLocus.vertices.length).toBeGreaterThan(20);
      // Rooted at the farthest point, and far out: most points are nearer the source than its median node.
      expect(distance[cutLocus.root]).toBe(Math.max(...distance));
      expect(Array.from(cutLocus.vertices)).toContain(cutLocus.root);
      const nodeDistances = Array.from(cutLocus.vertices, (v) => distance[v]).sort((a, b) => a - b);
      const medianNode = nodeDistances[Math.floor(nodeDistances.length / 2)];
      expect(distance.filter((d) => d < medianNode).length / distance.length, `source ${source}`).toBeGreaterThan(0.6);
      expect(Math.min(...nodeDistances)).toBeGreaterThan(5 * bob.facts.meanSpacing);
    }
  });

  it('has its per-point fields where the source reaches, and ridges with negative Laplacians', () => {
    const { cutLocus, gradient } = bob.separatorStages(700);
    expect(cutLocus.angleDeviation.every((a) => a >= 0 && a <= Math.PI)).toBe(true);
    expect(cutLocus.laplacian.every((l) => Number.isFinite(l))).toBe(true);
    expect(gradient).toHaveLength(3 * bob.facts.points);
    // The distance grows at unit rate almost everywhere (the gradient is fitted over each point's ring).
    const lengths = Array.from({ length: bob.facts.points }, (_, p) => Math.hypot(gradient[3 * p], gradient[3 * p + 1], gradient[3 * p + 2]));
    const sorted = [...lengths].sort((a, b) => a - b);
    expect(sorted[Math.floor(sorted.length / 2)]).toBeGreaterThan(0.85);
    expect(sorted[Math.floor(sorted.length / 2)]).toBeLessThan(1.15);
    for (const v of cutLocus.vertices.slice(0, 5)) expect(cutLocus.laplacian[v]).toBeLessThan(0.2);
  });

  it('is the same on every call', () => {
    const first = bob.separatorStages(321), second = bob.separatorStages(321);
    expect(second.cutLocus.vertices).toEqual(first.cutLocus.vertices);
    expect(second.cutLocus.edges).toEqual(first.cutLocus.edges);
    expect(second.approxLoopPoints).toEqual(first.approxLoopPoints);
  });

  it('gives bob closed loops through their targets and sources', () => {
    const adjacent = adjacency(bob);
    for (const source of [0, 400, 800, 1200, 1600]) expectClosedLoop(bob.separatorStages(source), adjacent, bob.facts.meanSpacing);
  });

  it('refuses a source that is no point, and options out of range, as input errors', () => {
    expect(() => bob.separatorStages(1948)).toThrow(new CoreError('point 1948 is out of range (the cloud has 1948 points)'));
    expect(() => bob.separatorStages(2, { angleThreshold: 4 })).toThrow(new CoreError('option angleThreshold must be between 0 and 3.14159, got 4'));
  });
});

describe('the approximate loop on a cloud', () => {
  it('goes round the leg behind which the fronts close in at a shallow angle, not round the body', () => {
    // The spider's vertices as a cloud. From a source on the body beside a leg's base, the two halves of
    // the front pass the leg and meet behind it running nearly side by side (their gradients well under 90°
    // apart there): the fronts head into each other all the same, and CSCD-M on the mesh takes that point as its
    // target. Requiring the gradients 90° apart skipped it, and the loop went round the body's rim from
    // the far end of the body (length 1.06), the loop the spider's skeletons packed in place of its legs'.
    const mesh = parseShape(new Uint8Array(readFileSync(sharedMesh('spider.ply'))), 'spider.ply');
    if (mesh.kind !== 'mesh') throw new Error('spider.ply holds no mesh');
    const points = meshAsCloud(mesh).cloud;
    const cloud = core.openCloud(points);
    try {
      const [source] = nearestPoints([0.4577, 0.658, 0.3791], points.positions);
      const legBase = [0.2957, 0.6276, 0.5049];
      const stages = cloud.separatorStages(source);
      expect(stages.status).toBe('ok');
      expect(Math.hypot(...stages.targetPoint!.map((x, i) => x - legBase[i]))).toBeLessThan(0.02);
      // Round the leg (some 0.18 about), not round the body (1.06).
      expect(stages.length).toBeGreaterThan(0.1);
      expect(stages.length).toBeLessThan(0.3);
      expect(stages.centroidInside).toBe(true);
    } finally {
      cloud.dispose();
    }
  });

  it('winds once around the tube of a torus sampled with a seed, from any source', () => {
    const R = 1, r = 0.35;
    const torus = torusPoints(3000, R, r, 7);
    const cloud = core.openCloud(torus);
    try {
      const adjacent = adjacency(cloud);
      const { positions } = torus;
      const aroundTube = (p: number) => Math.atan2(positions[3 * p + 2], Math.hypot(positions[3 * p], positions[3 * p + 1]) - R);
      const aroundHole = (p: number) => Math.atan2(positions[3 * p + 1], positions[3 * p]);
      const winding = (loop: Uint32Array, angle: (p: number) => number) => {
        let turn = 0;
        for (let i = 0; i < loop.length; i++) {
          const step = angle(loop[(i + 1) % loop.length]) - angle(loop[i]);
          turn += step - 2 * Math.PI * Math.round(step / (2 * Math.PI));
        }
        return turn / (2 * Math.PI);
      };
      for (const source of [0, 500, 1000, 1500, 2000, 2500]) {
        const stages = cloud.separatorStages(source);
        expectClosedLoop(stages, adjacent, cloud.facts.meanSpacing);
        expect(Math.abs(winding(stages.approxLoopPoints, aroundTube)), `source ${source}`).toBeCloseTo(1, 6);
        expect(winding(stages.approxLoopPoints, aroundHole), `source ${source}`).toBeCloseTo(0, 6);
        // Around the tube, not far along it: about its circumference 2πr, well short of the hole's 2πR.
        expect(loopLength(stages.approxLoopPoints, positions)).toBeLessThan(2 * Math.PI * r * 1.6);
      }
    } finally {
      cloud.dispose();
    }
  });

  it('goes around a finger of the hand, cutting its tip off', () => {
    const hand = readCloud('hand_subsample.ply');
    const cloud = core.openCloud(hand);
    try {
      const { positions } = hand;
      const { bboxDiagonal, meanSpacing, points } = cloud.facts;
      // The tip of the longest finger reaches farthest along y; the source lies a finger's width below it.
      let tip = 0;
      for (let p = 0; p < points; p++) if (positions[3 * p + 1] > positions[3 * tip + 1]) tip = p;
      const fromTip = cloud.distance(tip);
      let source = 0;
      for (let p = 0; p < points; p++) if (Math.abs(fromTip[p] - 0.08 * bboxDiagonal) < Math.abs(fromTip[source] - 0.08 * bboxDiagonal)) source = p;

      const stages = cloud.separatorStages(source);
      const adjacent = adjacency(cloud);
      expectClosedLoop(stages, adjacent, meanSpacing);
      // A finger is some 15 across: its loop is short next to the hand (bbox diagonal 292).
      const length = loopLength(stages.approxLoopPoints, positions);
      expect(length / bboxDiagonal).toBeGreaterThan(0.08);
      expect(length / bboxDiagonal).toBeLessThan(0.25);
      // Taken out of the graph, the loop leaves the tip on a small side of its own and the hand on the other.
      const sides = sidesOf(stages.approxLoopPoints, adjacent);
      expect(sides.length).toBeGreaterThanOrEqual(2);
      expect(sides[0].length / points).toBeGreaterThan(0.9);
      const tipSide = sides.find((side) => side.includes(tip));
      expect(tipSide, 'the tip is not on the loop').toBeDefined();
      expect(tipSide).not.toBe(sides[0]);
      expect(tipSide!.length / points).toBeLessThan(0.05);
    } finally {
      cloud.dispose();
    }
  });
});
