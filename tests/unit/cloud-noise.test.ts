// Noisy clouds (docs/pointcloud.md, "Noisy clouds"): the neighbourhood graph's bridge test on the MLS
// surface where the noise hides the curvature, so that the graph of a noisy cloud holds together; clean
// clouds keep the graph they had. Farther targets where the nearest loops enclose nothing. Orientation
// patches not turned on noise. Regions that tile a noisy surface joined by a tree, not one star (also where
// one large loop lies among the tiles), and a ring they tile keeps its cycle. Loops round a tube the scan
// left open are cross-sections, though the exterior flood reaches their centroids; loops round the deep
// hole of a ring with a thick wall are not.
// Nodes of regions of sparse twigs among their twigs; twigs that graze each other keep their branches.
// Spurs round bumps of the noise merged into their junctions.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { subsampleCloud } from '../../lib/cloud/subsample.ts';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { fixture, repoRoot, sharedData, sharedMesh } from '../paths.ts';
import { readCloudFile } from './support/clouds.ts';
import { degrees, distance3, point } from './support/topology.ts';
import { graphTopology } from '../../lib/graph/topology.ts';
import { leafIndices, meanDistanceToSkeleton } from '../../bench/metrics.ts';
import { boundingBoxDiagonal } from '../../lib/io/repair.ts';

const readCloud = (name: string) => readCloudFile(fixture('clouds', name));
/** The mean of a polyline's points (xyz triples). */
const centroidOf = (points: ArrayLike<number>) => [0, 1, 2].map((k) => {
  let sum = 0;
  for (let i = k; i < points.length; i += 3) sum += points[i];
  return sum / (points.length / 3);
});

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

/** A noisy cloud sampled from a shared mesh by scripts/sample-cloud.ts, as docs/pointcloud.md's clouds from other meshes were. */
const sampledClouds = new Map<string, ReturnType<typeof readCloudFile>>();
function sampledCloud(mesh: string, points: number, noisePercent: number, seed: number) {
  const key = `${mesh} ${points} ${noisePercent} ${seed}`;
  const known = sampledClouds.get(key);
  if (known) return known;
  const folder = mkdtempSync(path.join(tmpdir(), 'cscd-sampled-'));
  const file = path.join(folder, 'cloud.ply');
  execFileSync(process.execPath, ['--import', 'tsx', path.join(repoRoot, 'scripts', 'sample-cloud.ts'), sharedMesh(mesh), file,
    '--points', String(points), '--noise', String(noisePercent), '--seed', String(seed)], { stdio: 'ignore' });
  const cloud = readCloudFile(file);
  rmSync(folder, { recursive: true });
  sampledClouds.set(key, cloud);
  return cloud;
}
// hanger.ply's noisy cloud (the mesh's repository states no licence: no copy kept here).
const noisyHanger = () => sampledCloud('hanger.ply', 10000, 0.5, 19);

/** The cycles among the hanger skeleton's nodes of each ring: the left one (x < 9), the collar below the arm (z < -3). */
function hangerRingCycles(skeleton: { nodes: ArrayLike<number>; radii: ArrayLike<number>; edges: ArrayLike<number> }) {
  const cyclesAmong = (keep: (p: number[]) => boolean) => {
    const index = new Map<number, number>();
    for (let i = 0; i < skeleton.radii.length; i++) if (keep(point(skeleton.nodes, i))) index.set(i, index.size);
    const edges: number[] = [];
    for (let e = 0; e < skeleton.edges.length; e += 2)
      if (index.has(skeleton.edges[e]) && index.has(skeleton.edges[e + 1])) edges.push(index.get(skeleton.edges[e])!, index.get(skeleton.edges[e + 1])!);
    return graphTopology(index.size, edges).cycleRank;
  };
  return { left: cyclesAmong((p) => p[0] < 9), collar: cyclesAmong((p) => p[2] < -3) };
}

describe('noisy clouds', () => {
  it('tells noisy clouds from clean ones, and leaves the clean ones their graph', () => {
    for (const [name, noisy] of [['hand_noise_subsample.ply', true], ['bob_noise_subsample.ply', true], ['hand_subsample.ply', false], ['bob_subsample.ply', false]] as const) {
      const cloud = core.openCloud(readCloud(name));
      try {
        const graph = cloud.neighbourhood();
        expect(graph.noisy, name).toBe(noisy);
        if (!noisy) expect(graph.keptOnMls, name).toBe(0);
      } finally {
        cloud.dispose();
      }
    }
    // The clean hand's bridges, as measured before the second test existed (docs/pointcloud.md), since
    // its neighbours are trimmed to those that lie flat (553 with all 30: the folded local triangulations
    // had more edges to leave out).
    const hand = core.openCloud(readCloud('hand_subsample.ply'));
    try {
      expect(hand.neighbourhood().bridgesRemoved).toBe(189);
    } finally {
      hand.dispose();
    }
  });

  it('holds the graph of a noisy hand together: the tangent-plane test alone broke it into 47 pieces', () => {
    const cloud = core.openCloud(readCloud('hand_noise_subsample.ply'));
    try {
      const graph = cloud.neighbourhood();
      expect(graph.components).toBeLessThanOrEqual(2);
      expect(graph.keptOnMls).toBeGreaterThan(1000);
    } finally {
      cloud.dispose();
    }
  });

  it('tries farther targets where a loop encloses nothing (a ridge of the noise), each 1.5 times farther, as a mesh does', () => {
    const shape = readCloud('hand_noise_subsample.ply');
    const cloud = core.openCloud(shape);
    const at = (p: number) => [0, 1, 2].map((k) => shape.positions[3 * p + k]);
    const apart = (p: number, q: number) => Math.hypot(...at(p).map((x, k) => x - at(q)[k]));
    try {
      let fallbacks = 0;
      for (let source = 0; source < cloud.facts.points; source += 97) {
        const stages = cloud.separatorStages(source);
        expect(stages.attempts).toBeLessThanOrEqual(6);
        if (stages.status !== 'ok' || stages.attempts === 1) continue;
        fallbacks++;
        // The nearest target failed first; the one that made the separator is at least 1.5 times as far.
        expect(apart(source, stages.target!)).toBeGreaterThanOrEqual(1.5 * apart(source, stages.targets[0]));
      }
      expect(fallbacks).toBeGreaterThanOrEqual(5);
    } finally {
      cloud.dispose();
    }
  });

  it('gives the noisy hand no stray cycle at seeds 1-5: regions touch across a gap the graph bridges no more, and meet where they meet', () => {
    // Before the contact rule and the tufted junctions (and the fall-back above): 1, 3, 0, 0, 1 cycles;
    // before a noisy loop's sides could be measured by its plane (2026-12-05), 0, 0, 0, 1, 0. Over seeds
    // 1-24 the stray cycles left at 18 and 19 are opened since (the next test).
    const hand = core.openCloud(readCloud('hand_noise_subsample.ply'));
    try {
      const cycles = [1, 2, 3, 4, 5].map((seed) => hand.skeleton({ n: 40, seed }).stats.cycles);
      expect(cycles).toEqual([0, 0, 0, 0, 0]);
    } finally {
      hand.dispose();
    }
  });

  it('opens a cycle whose disk lies inside the cloud, and keeps a handle: the noisy hand at seeds 18 and 19, the noisy bob', () => {
    // At n = 40 the noisy hand's skeleton had a cycle at seeds 18 and 19 (of 1-24): three regions of one
    // finger that touched past each other. The bob's cycle goes round its hole, and stays.
    const hand = core.openCloud(readCloud('hand_noise_subsample.ply'));
    try {
      for (const seed of [18, 19]) {
        const skeleton = hand.skeleton({ n: 40, seed });
        expect(skeleton.stats.cycles).toBe(0);
        expect(graphTopology(skeleton.nodes.length / 3, skeleton.edges).components).toBe(1);
      }
    } finally {
      hand.dispose();
    }
    const bob = core.openCloud(readCloud('bob_noise_subsample.ply'));
    try {
      for (const seed of [18, 19]) expect(bob.skeleton({ n: 40, seed }).stats.cycles).toBe(1);
    } finally {
      bob.dispose();
    }
  });

  it('traces a loop where the descent along the graph stops at a local minimum of the distance', () => {
    // On the noisy deer the heat distance (from the tufted triangulation) has local minima along the
    // sparser graph: 17 of 40 sources found no loop so, these three among them (trace-failed before
    // 2026-12-04). The path goes on along the graph's shortest path towards the source.
    const deer = core.openCloud(readCloudFile(path.join(sharedData, 'pointclouds', 'deer_noise1.0.ply')));
    try {
      for (const source of [4935, 9513, 16327]) {
        const stages = deer.separatorStages(source);
        expect(stages.status, `source ${source}`).not.toBe('trace-failed');
        // A closed loop through distinct points, from the target to where the two paths meet and back.
        const points = Array.from(stages.approxLoopPoints);
        expect(points.length, `source ${source}`).toBeGreaterThanOrEqual(3);
        expect(new Set(points).size, `source ${source}`).toBe(points.length);
        expect(points[0], `source ${source}`).toBe(stages.target);
      }
    } finally {
      deer.dispose();
    }
  });

  it('leaves no skeleton node without an edge: points the graph cuts off go with their nearest larger piece', () => {
    // The bridge test cuts a point or two off this cloud's graph; with no separator through them, each
    // became a node of its own with no edge (one at seeds 1 and 2 before 2026-12-04).
    const hand = core.openCloud(readCloud('hand_noise_subsample.ply'));
    try {
      const graph = hand.neighbourhood();
      expect(graph.components).toBeGreaterThan(1);
      for (const seed of [1, 2]) {
        const skeleton = hand.skeleton({ n: 40, seed });
        const degree = new Array<number>(skeleton.radii.length).fill(0);
        skeleton.edges.forEach((node) => degree[node]++);
        expect(degree.filter((d) => d === 0), `seed ${seed}`).toEqual([]);
        // Every point still has a node.
        expect(skeleton.vertexToNode).toHaveLength(hand.facts.points);
        expect(Math.max(...skeleton.vertexToNode)).toBeLessThan(skeleton.radii.length);
      }
    } finally {
      hand.dispose();
    }
  });

  it('gives the noisy horse four legs, a head and a tail: its orientation is not turned in patches', () => {
    // Orientation patches turned wherever that fitted the winding number a little better (half of what
    // righting a lone inverted patch gains, not twice) turned two patches of this cloud's noisy belly:
    // 5 leaves and an error of 1.43 (x1e3) against the horse mesh at n = 60, against 6 and 0.53.
    const horse = core.openCloud(readCloudFile(path.join(sharedData, 'pointclouds', 'horse_noise0.5.ply')));
    try {
      const skeleton = horse.skeleton({ n: 60, seed: 1 });
      expect(skeleton.stats.cycles).toBe(0);
      expect(leafIndices(skeleton.radii.length, skeleton.edges).length).toBeGreaterThanOrEqual(6);
    } finally {
      horse.dispose();
    }
  }, 60_000);

  it('merges spurs round bumps of the noise into their junctions: every leaf branch of the noisy horse reaches two junction radii', () => {
    // A packed loop round a bump of the noise makes a region, and the region a spur that its separator
    // kept as a feature: at n = 100, seed 1, three (two on the torso's sides, one on a leg) whose points
    // all lie within 1.79, 1.79 and 1.98 of the junction's radii from the junction's node. On a noisy
    // cloud the bump rule's two radii apply to branches with a separator too (docs/pointcloud.md, "Spurs
    // of the noise").
    const cloud = readCloudFile(path.join(sharedData, 'pointclouds', 'horse_noise0.5.ply'));
    const horse = core.openCloud(cloud);
    try {
      const skeleton = horse.skeleton({ n: 100, seed: 1 });
      expect(skeleton.stats.cycles).toBe(0);
      const degree = degrees(skeleton);
      const neighbours = degree.map(() => [] as number[]);
      for (let e = 0; e < skeleton.edges.length; e += 2) {
        neighbours[skeleton.edges[e]].push(skeleton.edges[e + 1]);
        neighbours[skeleton.edges[e + 1]].push(skeleton.edges[e]);
      }
      const leaves = leafIndices(skeleton.radii.length, skeleton.edges);
      expect(leaves.length).toBeGreaterThanOrEqual(5); // four legs and the head at least
      for (const leaf of leaves) {
        const chain = new Set([leaf]);
        let previous = leaf, at = neighbours[leaf][0];
        while (degree[at] === 2) {
          chain.add(at);
          [previous, at] = [at, neighbours[at][0] === previous ? neighbours[at][1] : neighbours[at][0]];
        }
        const junction = point(skeleton.nodes, at);
        let reach = 0;
        skeleton.vertexToNode.forEach((node, v) => {
          if (chain.has(node)) reach = Math.max(reach, distance3(point(cloud.positions, v), junction));
        });
        expect(reach / skeleton.radii[at]).toBeGreaterThanOrEqual(2);
      }
    } finally {
      horse.dispose();
    }
  }, 60_000);

  it('joins the tiles of a noisy cloud by their shortest edges, not by one star across the shape', () => {
    // On the deer under 1% noise the packed loops go round the noise and their regions tile the whole
    // surface; the triangles where three tiles meet chain into one group, which made one star: in its
    // 7750-point subsample at n = 60 a hub of degree 15 and 14 at seeds 1 and 2 (78 spokes on the whole cloud). Its
    // junctions spread over many separator radii around no deep middle: its tiles are joined by the
    // shortest tree of their edges instead (docs/skeleton.md, "Tilings"), with the same cycles. At
    // seed 4, n = 100, the tiles also go round a part of the deer (a cycle of 5 tiles that the group's
    // triangles do not fill, its middle inside): no hole of the shape, so no cycle is kept for it
    // (docs/skeleton.md, "Holes of a group").
    // Read from the shared data (the deer mesh comes from a GPL-2.0 repository: no copy kept here).
    const shared = readCloudFile(path.join(sharedData, 'pointclouds', 'deer_noise1.0.ply'));
    const deer = core.openCloud(subsampleCloud(shared, 8000, 1));
    try {
      for (const [seed, n] of [[1, 60], [2, 60], [4, 100]]) {
        const skeleton = deer.skeleton({ n, seed });
        expect(skeleton.stats.cycles).toBe(0);
        expect(Math.max(...degrees(skeleton))).toBeLessThanOrEqual(5);
      }
    } finally {
      deer.dispose();
    }
  }, 60_000);

  // Clouds sampled from shared meshes with noise of 0.75% of the diagonal, where the tiles round the noise
  // chain into one group of dozens of regions that a star joined by one hub (its degree on the core before).
  // cheburashka.ply (a round body and head, two flat ears): one loop round the body (radius about 0.2, the
  // tiles' median 0.02) kept the group within 4 of its largest radius; over 15 of its median radius and
  // 10 depths it is a tiling (in auto mode at seed 2: 56 regions, 25 median radii, 11 depths;
  // docs/skeleton.md, "Tilings round one large loop"). dolphin.ply: the tiles cover the whole body, so
  // their places' mean lies deep inside, as a ball's with arms does; on a noisy cloud a group of 12
  // members or more over 15 median radii is a tiling at any depth (docs/skeleton.md, "Tilings of a whole
  // blob").
  it.each([
    { mesh: 'cheburashka.ply', n: 200, seed: 2, hubBefore: 51, maxDegree: 6 },
    { mesh: 'dolphin.ply', n: 150, seed: 2, hubBefore: 36, maxDegree: 8 },
  ])('joins the tiles of the noisy $mesh by a tree: no hub of degree $hubBefore', ({ mesh, n, seed, maxDegree }) => {
    const cloud = core.openCloud(sampledCloud(mesh, 20000, 0.75, 7));
    try {
      expect(cloud.neighbourhood().noisy).toBe(true);
      const skeleton = cloud.skeleton({ n, seed });
      expect(skeleton.stats.cycles).toBe(0);
      expect(Math.max(...degrees(skeleton))).toBeLessThanOrEqual(maxDegree);
    } finally {
      cloud.dispose();
    }
  }, 90_000);

  it('keeps a handle that tiles go round: the noisy hanger has a cycle in each of its two rings', () => {
    // hanger.ply is two rings of flat strips (1-1.2 thick, 5-6.5 wide; the noise 0.14) joined by an
    // arm. On its noisy cloud the tiles of the left ring's faces chain into one group of junction
    // triangles round the ring's hole, and the tree that joined the group instead of a star dropped the
    // ring's cycle (1 cycle here at seed 2, n = 100, where the hole's edge now closes it). A cycle of the
    // group that its triangles do not fill and whose middle is outside goes round a hole of the shape:
    // its edge is kept (docs/skeleton.md, "Holes of a group").
    const hanger = core.openCloud(noisyHanger());
    try {
      expect(hanger.neighbourhood().noisy).toBe(true);
      const skeleton = hanger.skeleton({ n: 100, seed: 2 });
      expect(skeleton.stats.cycles).toBe(2);
      expect(hangerRingCycles(skeleton)).toEqual({ left: 1, collar: 1 });
    } finally {
      hanger.dispose();
    }
  }, 60_000);

  it('leaves a loop round the hole of a ring with a thick wall outside: the noisy hanger keeps its left ring', () => {
    // The left ring is a napkin ring (its hole about 3.6 wide and 7.5 deep, its wall 1 thick). Loops round
    // its hole on the wall's inner face have their centroids on the hole's axis, where the exterior flood
    // reaches; but the hole is deep, so few directions from there lead out, and they passed as
    // cross-sections of a tube open at its ends. Their regions wrapped round the ring with no cycle:
    // at n = 180, seed 1, the left ring had none. On the wall's side of such a loop the shell runs a cube
    // or more deeper than on the hole's (1.25-3.25 here); a cross-section of an open tube lies on one
    // shell, alike on both sides (docs/pointcloud.md, "Loops round the hole of a thick ring").
    const hanger = core.openCloud(noisyHanger());
    try {
      for (const source of [602, 2555, 3101]) {
        const stages = hanger.separatorStages(source);
        expect(stages.status, `source ${source}`).toBe('ok');
        const [x, y] = centroidOf(stages.loop);
        expect(Math.hypot(x - 5.3, y - 6.2), `source ${source}`).toBeLessThan(0.5); // on the hole's axis
        expect(stages.centroidInside, `source ${source}`).toBe(false);
      }
      expect(hangerRingCycles(hanger.skeleton({ n: 180, seed: 1 }))).toEqual({ left: 1, collar: 1 });
    } finally {
      hanger.dispose();
    }
  }, 60_000);

  it('gives the noisy bob its one handle', () => {
    const bob = core.openCloud(readCloud('bob_noise_subsample.ply'));
    try {
      const skeleton = bob.skeleton({ n: 40, seed: 1 });
      expect(skeleton.stats.cycles).toBe(1);
      expect(skeleton.stats.packed).toBeGreaterThanOrEqual(5);
    } finally {
      bob.dispose();
    }
  });

  it('gives a scan open at its ends a skeleton along it: loops round an open trunk are cross-sections', () => {
    // The trunk of tree_woodske_SW below its branches, open at the ground and where it was cut: the
    // exterior flood comes in at both ends and reaches the trunk's axis, so every loop round it failed the
    // centroid test and the skeleton was one node (docs/pointcloud.md, "Scans open at an end").
    const shape = readCloud('tree_sw_trunk.ply');
    const trunk = core.openCloud(shape);
    try {
      expect(trunk.neighbourhood().noisy).toBe(true);
      const skeleton = trunk.skeleton({ n: 20, seed: 1 });
      expect(skeleton.stats.cycles).toBe(0);
      expect(leafIndices(skeleton.radii.length, skeleton.edges)).toHaveLength(2);
      const z = (values: ArrayLike<number>) => Array.from({ length: values.length / 3 }, (_, i) => values[3 * i + 2]);
      const [pointsZ, nodesZ] = [z(shape.positions), z(skeleton.nodes)];
      const height = Math.max(...pointsZ) - Math.min(...pointsZ);
      expect(Math.max(...nodesZ) - Math.min(...nodesZ)).toBeGreaterThan(0.75 * height);
      // Each node on the axis: the centre of the points within a tenth of the trunk's radius (0.28) of its height.
      for (let node = 0; node < nodesZ.length; node++) {
        const near = Array.from({ length: pointsZ.length }, (_, i) => i).filter((i) => Math.abs(pointsZ[i] - nodesZ[node]) < 0.03);
        const centre = [0, 1].map((k) => near.reduce((sum, i) => sum + shape.positions[3 * i + k], 0) / near.length);
        const off = Math.hypot(skeleton.nodes[3 * node] - centre[0], skeleton.nodes[3 * node + 1] - centre[1]);
        expect(off, `node ${node}`).toBeLessThan(0.05);
      }
      // A loop round the trunk passes the centroid test though the flood puts its centroid outside.
      const stages = trunk.separatorStages(0);
      expect(stages.status).toBe('ok');
      expect(stages.centroidInside).toBe(true);
      expect(trunk.inside(new Float64Array(centroidOf(stages.loop)))[0]).toBe(0);
    } finally {
      trunk.dispose();
    }
  });

  it('puts each node among the points it stands for: regions of sparse twigs get nodes on the twigs', () => {
    // Two whorls of tree_woodske_HS's sparse twigs round its trunk: five regions of twigs had their nodes on
    // the trunk or in the air, 0.5-2.6 units (20-100 spacings) from every point they held, which a detached
    // node now moves to (a leaf) or sprouts a leaf at (docs/skeleton.md, "Detached nodes").
    const shape = readCloud('tree_hs_whorls.ply');
    const whorls = core.openCloud(shape);
    try {
      const { nodes, vertexToNode } = whorls.skeleton({ n: 40, seed: 1 });
      const points = Array.from({ length: shape.positions.length / 3 }, (_, i) => [0, 1, 2].map((k) => shape.positions[3 * i + k]));
      const owned: number[][][] = Array.from({ length: nodes.length / 3 }, () => []);
      points.forEach((p, i) => owned[vertexToNode[i]].push(p));
      const distance = (a: number[], b: number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
      const apart: number[] = [];
      owned.forEach((own, node) => {
        if (own.length < 2) return;
        const at = [0, 1, 2].map((k) => nodes[3 * node + k]);
        const mean = [0, 1, 2].map((k) => own.reduce((sum, p) => sum + p[k], 0) / own.length);
        const spread = Math.sqrt(own.reduce((sum, p) => sum + distance(p, mean) ** 2, 0) / own.length);
        const nearestOwn = Math.min(...own.map((p) => distance(p, at)));
        const nearestAny = Math.min(...points.map((p) => distance(p, at)));
        // Apart: farther from all its points than twice their spread (a ring round its node is within one),
        // and three times as far as from the cloud (a node deep in the trunk owning a patch of its surface is not).
        if (nearestOwn > 2 * spread && nearestOwn > 3 * nearestAny) apart.push(node);
      });
      expect(apart).toEqual([]);
    } finally {
      whorls.dispose();
    }
  });

  it('opens a cycle that an edge through the air between two twigs closed, and keeps one piece', () => {
    // At n = 40, seeds 1 and 9 (of 1-12), the whorls' skeleton had one cycle, closed by the same edge 0.32
    // long between nodes of radii 0.047 and 0.01, whose farthest point lies 0.15 (3.2 times the larger radius)
    // from every point: it leaves the shape and is dropped (docs/skeleton.md, "Cycles through the air").
    const whorls = core.openCloud(readCloud('tree_hs_whorls.ply'));
    try {
      for (const seed of [1, 9]) {
        const skeleton = whorls.skeleton({ n: 40, seed });
        const topology = graphTopology(skeleton.nodes.length / 3, skeleton.edges);
        expect([seed, topology.cycleRank, topology.components]).toEqual([seed, 0, 1]);
      }
    } finally {
      whorls.dispose();
    }
  });

  it('follows the twigs of a whole tree scan into its crown, where they graze each other and bend', () => {
    // In the crown the twigs cross and touch: a leaf band piece that touched any piece but its neighbour
    // joined the neighbour, which then did the same, until one node on a branch stood for a whole stretch
    // of crown (3.90% of the diagonal from these reference points at this seed). A leaf that reaches three
    // of its neighbour's radii from the neighbour's node and holds to it by at least as many element edges
    // as to the rest now stays a branch (docs/skeleton.md, "Grazing twigs"): 1.97%; 1.90% with the twigs below.
    const shape = readCloud('tree_woodske_HS.ply');
    const tree = core.openCloud(shape);
    try {
      const skeleton = tree.skeleton({ n: 40, seed: 1 });
      expect(skeleton.stats.cycles).toBe(0);
      const reference = readCloud('tree_woodske_HS_reference.ply').positions;
      const diagonal = boundingBoxDiagonal(shape.positions);
      expect(meanDistanceToSkeleton(reference, skeleton, diagonal)).toBeLessThan(2.5);
      // A twig that bends within its last band: the slice's centroid is in the air, and the leaf joined its
      // neighbour, folding the twig back. As a twig by the rule above it now stands at its point nearest that
      // centroid: its reference points (the 4 within 0.3 of its end) 4.88% of the diagonal away before, 0.40% now.
      const end = [-2.9, 0.42, 5.95];
      const twigEnd = Array.from({ length: reference.length / 3 }, (_, i) => [0, 1, 2].map((k) => reference[3 * i + k]))
        .filter((p) => Math.hypot(p[0] - end[0], p[1] - end[1], p[2] - end[2]) < 0.3);
      expect(twigEnd).toHaveLength(4);
      expect(meanDistanceToSkeleton(twigEnd.flat(), skeleton, diagonal)).toBeLessThan(1.5);
      // A branch node that centreNodes put on its heaviest neighbour, and that neither moved from, is that
      // neighbour: no edge of no length (docs/skeleton.md, "Coincident nodes"; one here before).
      const edgeCount = skeleton.edges.length / 2;
      const lengths = Array.from({ length: edgeCount }, (_, e) => {
        const [a, b] = [skeleton.edges[2 * e], skeleton.edges[2 * e + 1]];
        return Math.hypot(...[0, 1, 2].map((k) => skeleton.nodes[3 * a + k] - skeleton.nodes[3 * b + k]));
      });
      expect(lengths.filter((length) => length === 0)).toEqual([]);
    } finally {
      tree.dispose();
    }
  });

  it('gives a noisy torus with holes through its tube its cycle, and leaves a loop round its hole outside', () => {
    // The flood comes in through the holes and fills the tube: all 20 loops failed the centroid test, one
    // node. Cross-sections pass as a trunk's do; a loop round the torus's hole is round, flat and enclosed
    // in its plane too, but more than half of the directions from its centroid lead out of the grid.
    const torus = core.openCloud(readCloud('torus_open_noise_subsample.ply'));
    try {
      expect(torus.neighbourhood().noisy).toBe(true);
      expect(torus.skeleton({ n: 20, seed: 1 }).stats.cycles).toBe(1);
      const aroundHole = torus.separatorStages(1025);
      expect(aroundHole.status).toBe('ok');
      expect(Math.hypot(...centroidOf(aroundHole.loop))).toBeLessThan(0.1); // the torus's centre (radii 1 and 0.4)
      expect(aroundHole.centroidInside).toBe(false);
    } finally {
      torus.dispose();
    }
  });
});
