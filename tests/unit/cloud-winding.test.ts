// The point cloud's inside test (pointcloud/winding.cpp): the generalised winding number of points
// whose normals it orients itself. Held to the file's outward normals of bob_subsample (sampled from
// the bob mesh): points moved a little inwards must be inside, a little outwards outside, whatever
// the normals the cloud is opened with (none: PCA, with no sign; the file's with half of them flipped).
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { parseShape, type ParsedCloud } from '../../lib/io/index.ts';
import { boundingBoxDiagonal } from '../../lib/io/repair.ts';
import { parseSkeleton } from '../../lib/io/skeleton.ts';
import { fixture, sharedData } from '../paths.ts';
import { spherePoints } from './support/clouds.ts';

function readCloud(file: string): ParsedCloud {
  const shape = parseShape(new Uint8Array(readFileSync(file)), path.basename(file));
  if (shape.kind !== 'cloud') throw new Error(`${file} holds a mesh`);
  return shape;
}

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

const bob = readCloud(fixture('clouds', 'bob_subsample.ply'));
const normals = bob.normals!;

/** Every point moved by `offset` along its outward (file) normal. */
function moved(offset: number): Float64Array {
  const q = new Float64Array(bob.positions.length);
  for (let i = 0; i < q.length; i++) q[i] = bob.positions[i] + offset * normals[i];
  return q;
}

/** Share of the points whose winding number falls on the expected side of 1/2. */
function share(numbers: Float64Array, inside: boolean): number {
  return numbers.filter((w) => (w > 0.5) === inside).length / numbers.length;
}

describe('winding numbers of a point cloud', () => {
  const cases: [string, Float32Array | null][] = [
    ['PCA normals (no sign)', null],
    ['file normals, every other one flipped', normals.map((n, i) => (Math.floor(i / 3) % 2 ? -n : n))],
  ];
  it.each(cases)('tell inside from outside on bob_subsample with %s', (_, given) => {
    const cloud = core.openCloud({ positions: bob.positions, normals: given });
    try {
      const offset = 0.01 * cloud.facts.bboxDiagonal;
      const inwards = cloud.windingNumbers(moved(-offset));
      const outwards = cloud.windingNumbers(moved(offset));
      expect(share(inwards, true)).toBeGreaterThan(0.97);
      expect(share(outwards, false)).toBeGreaterThan(0.97);
      const far = cloud.windingNumbers(Float64Array.from([10, 10, 10]).map((x) => x * cloud.facts.bboxDiagonal));
      expect(Math.abs(far[0])).toBeLessThan(0.01);
    } finally {
      cloud.dispose();
    }
  });

  it('orients horse_clean outwards, whose topmost point lies on a thin feature', () => {
    // The first rule (the topmost point's normal points up) turned this cloud inside out.
    const horse = readCloud(path.join(sharedData, 'pointclouds', 'horse_clean.ply'));
    const cloud = core.openCloud({ positions: horse.positions, normals: null });
    try {
      const offset = 0.005 * cloud.facts.bboxDiagonal;
      const along = (sign: number) => horse.positions.map((x, i) => x + sign * offset * horse.normals![i]);
      expect(share(cloud.windingNumbers(along(-1)), true)).toBeGreaterThan(0.95);
      expect(share(cloud.windingNumbers(along(1)), false)).toBeGreaterThan(0.95);
    } finally {
      cloud.dispose();
    }
  });

  it('orients the sparse, open tree_woodske_HS outwards: about 1 inside its branches', () => {
    // Its normals enclose a negative "volume" (an open scan of thin branches): the volume rule alone
    // turned it inside out, about -1 at the centroid of every loop around a branch.
    const tree = core.openCloud(readCloud(path.join(sharedData, 'pointclouds', 'tree_woodske_HS.ply')));
    try {
      const inside: number[] = [];
      for (let source = 0; source < tree.facts.points && inside.length < 6; source += 605) {
        const stages = tree.separatorStages(source);
        if (stages.status !== 'ok' || stages.length > 40 * tree.facts.meanSpacing) continue; // around one branch
        const n = stages.loop.length / 3;
        const centroid = [0, 1, 2].map((k) => stages.loop.filter((_, i) => i % 3 === k).reduce((a, b) => a + b, 0) / n);
        inside.push(tree.windingNumbers(Float64Array.from(centroid))[0]);
      }
      expect(inside.length).toBe(6);
      for (const w of inside) expect(w).toBeGreaterThan(0.5);
    } finally {
      tree.dispose();
    }
  }, 60_000);

  it('no longer turns the trunk of tree_woodske_SW inside out, below branches its normals reached through a junction', () => {
    // One propagation tree held trunk and crown; the crown's many points decided its sign and the trunk
    // came out inside out (-0.97 to -1.10 on its axis) until patches could be turned on their own: 0.13 to
    // 0.50 now, its lowest patches still inverted (those whose own sums do not say so are left as they are).
    const shape = readCloud(path.join(sharedData, 'pointclouds', 'tree_woodske_SW.ply'));
    const tree = core.openCloud({ positions: shape.positions, normals: null });
    try {
      const p = shape.positions;
      let low = Infinity, high = -Infinity;
      for (let i = 2; i < p.length; i += 3) [low, high] = [Math.min(low, p[i]), Math.max(high, p[i])];
      // The trunk's axis: the centre of the points in thin slices at 2-10% of the height (a cylinder there).
      const axis: number[] = [];
      for (const f of [0.02, 0.04, 0.06, 0.08, 0.1]) {
        const z = low + f * (high - low);
        const centre = [0, 0, 0];
        let count = 0;
        for (let i = 0; i < p.length; i += 3)
          if (Math.abs(p[i + 2] - z) < 0.01 * (high - low)) {
            for (let k = 0; k < 3; k++) centre[k] += p[i + k];
            count++;
          }
        axis.push(...centre.map((x) => x / count));
      }
      for (const w of tree.windingNumbers(Float64Array.from(axis))) expect(w).toBeGreaterThan(0);
    } finally {
      tree.dispose();
    }
  }, 60_000);

  it("keeps the file's normal signs where they agree: the loops around elephant_small's trunk and tusks are inside", () => {
    // Its normals are the faces' of a 2,775-vertex mesh: propagated along the tree they came out turned
    // across the creases of the thin parts, the winding number there fell below 1/2 and these loops
    // failed the centroid test (the skeleton then lost the handles: 0, 0, 1 cycles at seeds 1-3, now 2, 3, 3).
    const cloud = core.openCloud(readCloud(path.join(sharedData, 'pointclouds', 'elephant_small_clean.ply')));
    try {
      for (const source of [3456, 1760]) {
        const stages = cloud.separatorStages(source);
        expect(stages.status, `source ${source}`).toBe('ok');
        expect(stages.centroidInside, `source ${source}`).toBe(true);
      }
    } finally {
      cloud.dispose();
    }
  });

  it('is about 1 at the centre of a sphere cloud and 0 outside it', () => {
    const sphere = spherePoints(3000, 7);
    const cloud = core.openCloud({ positions: sphere.positions, normals: null });
    try {
      const [centre, near, outside] = cloud.windingNumbers(Float64Array.from([0, 0, 0, 0.5, 0, 0, 1.5, 0, 0]));
      expect(centre).toBeCloseTo(1, 1);
      expect(near).toBeCloseTo(1, 1);
      expect(Math.abs(outside)).toBeLessThan(0.1);
    } finally {
      cloud.dispose();
    }
  });
});

describe('inside a noisy cloud', () => {
  // deer_noise1.0: noise of 1% of the diagonal, about as thick as the deer's legs and antlers. PCA normals
  // there lie across the thin parts in any direction, and no orientation makes the winding number about 1
  // inside them; Cloud.inside floods the outside through the empty space of a grid instead.
  const deerSkeleton = path.join(sharedData, 'reference_skeletons', 'deer_skeleton.obj');
  const deerNodes = parseSkeleton(readFileSync(deerSkeleton), deerSkeleton).nodes;
  const clean = readCloud(path.join(sharedData, 'pointclouds', 'deer_clean.ply'));
  const diagonal = boundingBoxDiagonal(clean.positions);
  /** Every 5th of deer_clean's points moved `offset` diagonals along its outward (file) normal. */
  const outwards = (offset: number) => Float64Array.from({ length: 3 * Math.floor(clean.positions.length / 15) },
    (_, k) => clean.positions[15 * Math.floor(k / 3) + (k % 3)] + offset * diagonal * clean.normals![15 * Math.floor(k / 3) + (k % 3)]);

  it("has the deer's reference skeleton inside, where the winding number of its PCA normals does not", () => {
    const cloud = core.openCloud(readCloud(path.join(sharedData, 'pointclouds', 'deer_noise1.0.ply')));
    try {
      expect(cloud.neighbourhood().noisy).toBe(true);
      const nodes = deerNodes.length / 3;
      expect(nodes).toBe(47);
      const inside = cloud.inside(deerNodes);
      expect(inside.filter((flag) => flag === 1).length / nodes).toBeGreaterThan(0.95);
      expect(share(cloud.windingNumbers(deerNodes), true)).toBeLessThan(0.5);
      expect(Array.from(cloud.inside(Float64Array.from([NaN, 0, 0, 0, Infinity, 0])))).toEqual([0, 0]);

      // Beyond the noise, outside stays outside: points a tenth of the diagonal out from deer_clean's
      // surface that the clean cloud's winding number puts outside (8% inside measured: pockets between
      // antler branches that the grown shell closes).
      const far = outwards(0.1);
      const reference = core.openCloud(clean);
      try {
        const outsideByClean = reference.windingNumbers(far).map((w) => (w < 0.5 ? 1 : 0));
        const flags = cloud.inside(far);
        let outsideCount = 0, insideAnyway = 0;
        for (let i = 0; i < flags.length; i++) {
          if (!outsideByClean[i]) continue;
          outsideCount++;
          insideAnyway += flags[i];
        }
        expect(outsideCount).toBeGreaterThan(3000);
        expect(insideAnyway / outsideCount).toBeLessThan(0.15);
      } finally {
        reference.dispose();
      }
    } finally {
      cloud.dispose();
    }
  });

  it('is the winding number over one half on a clean cloud', () => {
    const cloud = core.openCloud(clean);
    try {
      expect(cloud.neighbourhood().noisy).toBe(false);
      const queries = Float64Array.from([...deerNodes, ...outwards(0.02), ...outwards(-0.005)]);
      const winding = cloud.windingNumbers(queries);
      expect(Array.from(cloud.inside(queries))).toEqual(Array.from(winding, (w) => (w > 0.5 ? 1 : 0)));
    } finally {
      cloud.dispose();
    }
  });
});
