// Branches reach their tips: on the synthetic shapes with a known skeleton (../shared/data/synthetic),
// every arm and twig gets a leaf of its own near the centre of its tip's end sphere, with the default
// options, and no other leaf sticks out further than a tube radius.
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core, type Skeleton } from '../../lib/core/node.ts';
import { readMesh } from './support/meshes.ts';
import { distance3, point } from './support/skeletons.ts';
import { sharedSynthetic } from '../paths.ts';

interface GroundTruth {
  nodes: number[][];
  edges: [number, number][];
  radii: number[];
}

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

function degrees(count: number, edges: ArrayLike<number>): number[] {
  const degree = new Array(count).fill(0);
  for (let i = 0; i < edges.length; i++) degree[edges[i]]++;
  return degree;
}

/** Length of the branch from a leaf to the first node of degree 3 or more (or to the branch's other end). */
function branchLength(skeleton: Skeleton, leaf: number): number {
  const count = skeleton.radii.length;
  const neighbours: number[][] = Array.from({ length: count }, () => []);
  for (let i = 0; i < skeleton.edges.length; i += 2) {
    neighbours[skeleton.edges[i]].push(skeleton.edges[i + 1]);
    neighbours[skeleton.edges[i + 1]].push(skeleton.edges[i]);
  }
  let [previous, at, length] = [leaf, neighbours[leaf][0], 0];
  length += distance3(point(skeleton.nodes, leaf), point(skeleton.nodes, at));
  while (neighbours[at].length === 2) {
    const next = neighbours[at][0] === previous ? neighbours[at][1] : neighbours[at][0];
    length += distance3(point(skeleton.nodes, at), point(skeleton.nodes, next));
    [previous, at] = [at, next];
  }
  return length;
}

describe.each([
  // Node 0 is not an arm or twig: the top of star8's body, the base of the tree's trunk (its README).
  // The trunk's base is a blunt end (a flat disk with a round rim); star8's body top is round.
  { shape: 'star8_coarse', apart: 0, bluntBase: false },
  { shape: 'tree_coarse', apart: 0, bluntBase: true },
])('the skeleton of $shape', ({ shape, apart, bluntBase }) => {
  let skeleton: Skeleton;
  let truth: GroundTruth;
  let diagonal: number;
  beforeAll(() => {
    const surface = core.openSurface(readMesh(sharedSynthetic(`${shape}.ply`)));
    try {
      skeleton = surface.skeleton({});
      diagonal = surface.facts.bboxDiagonal;
    } finally {
      surface.dispose();
    }
    truth = JSON.parse(readFileSync(sharedSynthetic(`${shape}__GT.json`), 'utf8')) as GroundTruth;
  });

  it('has a leaf of its own within 1% of the diagonal of every arm or twig tip', () => {
    const tips = degrees(truth.nodes.length, truth.edges.flat()).flatMap((d, i) => (d === 1 && i !== apart ? [i] : []));
    expect(tips).toHaveLength(8);
    const leaves = degrees(skeleton.radii.length, skeleton.edges).flatMap((d, i) => (d === 1 ? [i] : []));
    const nearest = tips.map((tip) => {
      const gap = (leaf: number) => distance3(point(skeleton.nodes, leaf), truth.nodes[tip]);
      const best = leaves.reduce((a, b) => (gap(a) <= gap(b) ? a : b));
      expect(gap(best) / diagonal, `tip ${tip}`).toBeLessThan(0.01);
      return best;
    });
    expect(new Set(nearest).size).toBe(tips.length);
  });

  it.runIf(bluntBase)('ends on the axis at the blunt end that is no tip (node 0)', () => {
    // The band nearest a blunt end is a crescent on one side when the separator above it is tilted; a
    // leaf of its own there bent the skeleton sideways, a trunk radius off the axis of tree_coarse.
    const [base, above] = [truth.nodes[apart], truth.nodes[truth.edges.find((e) => e.includes(apart))!.find((i) => i !== apart)!]];
    const leaves = degrees(skeleton.radii.length, skeleton.edges).flatMap((d, i) => (d === 1 ? [i] : []));
    const end = leaves.reduce((a, b) => (distance3(point(skeleton.nodes, a), base) <= distance3(point(skeleton.nodes, b), base) ? a : b));
    const axis = above.map((x, k) => x - base[k]);
    const along = point(skeleton.nodes, end).map((x, k) => x - base[k]);
    const t = along.reduce((sum, x, k) => sum + x * axis[k], 0) / axis.reduce((sum, x) => sum + x * x, 0);
    const offAxis = Math.hypot(...along.map((x, k) => x - t * axis[k]));
    expect(offAxis).toBeLessThan(truth.radii[apart] / 4);
  });

  it('has no other leaf whose branch is longer than the tube radius there', () => {
    const tips = degrees(truth.nodes.length, truth.edges.flat()).flatMap((d, i) => (d === 1 ? [i] : []));
    const leaves = degrees(skeleton.radii.length, skeleton.edges).flatMap((d, i) => (d === 1 ? [i] : []));
    for (const leaf of leaves) {
      const at = point(skeleton.nodes, leaf);
      if (tips.some((tip) => distance3(at, truth.nodes[tip]) < 0.01 * diagonal + truth.radii[tip])) continue;
      const closest = truth.nodes.reduce((a, _, i) => (distance3(at, truth.nodes[i]) < distance3(at, truth.nodes[a]) ? i : a), 0);
      expect(branchLength(skeleton, leaf), `leaf ${leaf} near ground-truth node ${closest}`).toBeLessThan(truth.radii[closest]);
    }
  });
});
