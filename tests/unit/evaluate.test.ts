// The paper's reconstruction error: analytic skeletons score near zero, wrong ones clearly
// worse, the value does not depend on the mesh's scale or position, and `cscd evaluate` reads the
// skeleton files of CSCD Studio and of other tools.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { CoreError, loadCoreNode, type Core, type Evaluation, type MeshArrays, type SkeletonInput } from '../../lib/core/node.ts';
import { sharedMesh } from '../paths.ts';
import { cscd } from './support/cli.ts';
import { capsule, readMesh, torus } from './support/meshes.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

const tmp = mkdtempSync(path.join(tmpdir(), 'cscd-evaluate-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

// Capsule of radius 0.5 around the segment (-1, 0, 0)-(1, 0, 0); its skeleton is that segment.
const CAPSULE_R = 0.5;
const capsuleMesh = capsule(2, CAPSULE_R, 48);
function capsuleSkeleton(shift = 0, radii: number[] | null = [CAPSULE_R, CAPSULE_R]): SkeletonInput {
  return { nodes: Float64Array.from([-1, shift, 0, 1, shift, 0]), edges: Uint32Array.from([0, 1]), radii: radii && Float64Array.from(radii) };
}

// Torus with ring radius 1 and tube radius 0.3; its skeleton is the unit circle, here a 64-gon.
const TORUS_R = 0.3;
const torusMesh = torus(1, TORUS_R, 96, 32);
function circleSkeleton(count: number, radii: boolean): SkeletonInput {
  const nodes: number[] = [];
  const edges: number[] = [];
  for (let i = 0; i < count; i++) {
    const angle = (2 * Math.PI * i) / count;
    nodes.push(Math.cos(angle), Math.sin(angle), 0);
    edges.push(i, (i + 1) % count);
  }
  return { nodes: Float64Array.from(nodes), edges: Uint32Array.from(edges), radii: radii ? new Float64Array(count).fill(TORUS_R) : null };
}

const transformed = (xyz: ArrayLike<number>, scale: number, offset: number[]) => Float64Array.from(xyz, (x, i) => x * scale + offset[i % 3]);

describe('reconstruction error on analytic skeletons', () => {
  let centred: Evaluation;
  beforeAll(() => {
    centred = core.evaluate(capsuleMesh, capsuleSkeleton());
  });

  it('is near zero for the axis of a capsule with its radius', () => {
    // Only the two caps deviate: a convolution surface ends 0.1 radii short of the tip.
    expect(centred.reconError).toBeLessThan(0.1);
    expect(centred.median).toBeLessThan(1e-3);
    expect(centred.nodes).toBe(2);
    expect(centred.cycles).toBe(0);
    expect(centred.radiiSource).toBe('given');
    expect(centred.surface.triangles.length).toBeGreaterThan(1000);
  });

  it('is near zero for the core circle of a torus, with one cycle', () => {
    const result = core.evaluate(torusMesh, circleSkeleton(64, true));
    expect(result.reconError).toBeLessThan(0.01);
    expect(result.p95).toBeLessThan(0.01);
    expect(result.cycles).toBe(1);
  });

  it('is clearly worse for a skeleton shifted off the axis, or with a wrong radius', () => {
    const shifted = core.evaluate(capsuleMesh, capsuleSkeleton(CAPSULE_R / 2));
    expect(shifted.reconError).toBeGreaterThan(20 * centred.reconError);
    expect(shifted.reconError).toBeGreaterThan(1);
    const thin = core.evaluate(capsuleMesh, capsuleSkeleton(0, [CAPSULE_R / 2, CAPSULE_R / 2]));
    expect(thin.reconError).toBeGreaterThan(20 * centred.reconError);
  });

  it('derives the radii from the mesh when the skeleton has none', () => {
    const capsuleDerived = core.evaluate(capsuleMesh, capsuleSkeleton(0, null));
    expect(capsuleDerived.radiiSource).toBe('derived');
    for (const r of capsuleDerived.radii) expect(r).toBeCloseTo(CAPSULE_R, 2);
    expect(capsuleDerived.reconError).toBeLessThan(0.1);

    const torusDerived = core.evaluate(torusMesh, circleSkeleton(64, false));
    for (const r of torusDerived.radii) expect(Math.abs(r - TORUS_R)).toBeLessThan(0.01 * TORUS_R);
    expect(torusDerived.reconError).toBeLessThan(0.01);
  });

  it('does not change when mesh and skeleton are scaled and moved together', () => {
    for (const [mesh, skeleton] of [
      [capsuleMesh, capsuleSkeleton(CAPSULE_R / 3)],
      [torusMesh, circleSkeleton(64, true)],
    ] as [MeshArrays, SkeletonInput][]) {
      const base = core.evaluate(mesh, skeleton);
      const scale = 37.5;
      const offset = [120, -4, 9];
      const moved = core.evaluate(
        { positions: transformed(mesh.positions, scale, offset), triangles: mesh.triangles },
        { nodes: transformed(skeleton.nodes, scale, offset), edges: skeleton.edges, radii: skeleton.radii!.map((r) => r * scale) },
      );
      expect(moved.reconError).toBeCloseTo(base.reconError, 6);
      expect(moved.p95).toBeCloseTo(base.p95, 6);
      expect(moved.grid.dims).toEqual(base.grid.dims);
    }
  });

  it('puts the reconstructed surface where the tube is: every surface vertex near radius 0.3 from the circle', () => {
    const { positions } = core.evaluate(torusMesh, circleSkeleton(64, true)).surface;
    let worst = 0;
    for (let i = 0; i < positions.length; i += 3) {
      const ring = Math.hypot(positions[i], positions[i + 1]);
      worst = Math.max(worst, Math.abs(Math.hypot(ring - 1, positions[i + 2]) - TORUS_R));
    }
    expect(worst).toBeLessThan(0.05 * TORUS_R);
  });
});

describe('reconstruction error on a real skeleton', () => {
  it("ranks CSCD's fertility skeleton above the same skeleton moved by a tenth of the diagonal", () => {
    const mesh = readMesh(sharedMesh('fertility_9k.ply'));
    const surface = core.openSurface(mesh);
    const skeleton = surface.skeleton({});
    surface.dispose();
    const own = core.evaluate(mesh, skeleton);
    expect(own.radiiSource).toBe('given');
    expect(own.cycles).toBe(4); // fertility has genus 4
    expect(own.nodes).toBe(skeleton.nodes.length / 3);
    const diagonal = core.inspect(mesh).bboxDiagonal;
    const moved = core.evaluate(mesh, { ...skeleton, nodes: transformed(skeleton.nodes, 1, [diagonal / 10, 0, 0]) });
    expect(moved.reconError).toBeGreaterThan(5 * own.reconError);
    // Per-vertex errors average to the reported mean.
    const mean = own.vertexError.reduce((a, b) => a + b, 0) / own.vertexError.length;
    expect(mean).toBeCloseTo(own.reconError, 9);
  }, 60_000);
});

describe('bad skeletons', () => {
  const cases: [string, SkeletonInput, RegExp][] = [
    ['no nodes', { nodes: new Float64Array(), edges: new Uint32Array() }, /no nodes/],
    ['an edge to a missing node', { nodes: Float64Array.from([0, 0, 0, 1, 0, 0]), edges: Uint32Array.from([0, 2]) }, /names node 2/],
    ['a NaN coordinate', { nodes: Float64Array.from([0, NaN, 0]), edges: new Uint32Array() }, /not a finite number/],
    ['too few radii', { ...capsuleSkeleton(), radii: Float64Array.from([1]) }, /2 nodes but 1 radii/],
    ['a negative radius', { ...capsuleSkeleton(), radii: Float64Array.from([1, -1]) }, /radius/],
  ];
  it.each(cases)('reports %s in words', (_, skeleton, message) => {
    expect(() => core.evaluate(capsuleMesh, skeleton)).toThrow(CoreError);
    expect(() => core.evaluate(capsuleMesh, skeleton)).toThrow(message);
  });
});

describe('cscd evaluate', () => {
  const mesh = sharedMesh('fertility_9k.ply');
  type Printed = Pick<Evaluation, 'reconError' | 'median' | 'p95' | 'nodes' | 'cycles' | 'radiiSource'>;
  const evaluate = async (...args: string[]): Promise<Printed> => {
    const result = await cscd('evaluate', mesh, ...args);
    expect(result.stderr).toBe('');
    expect(result.status).toBe(0);
    return JSON.parse(result.stdout) as Printed;
  };

  it('scores the JSON, PLY and OBJ files of `cscd skeleton` alike', async () => {
    // A fixed small N (the formats are under test), at which the skeleton still has all four cycles.
    for (const format of ['json', 'ply', 'obj']) expect((await cscd('skeleton', mesh, '--n', '16', '--out', path.join(tmp, `s.${format}`))).status).toBe(0);
    const json = await evaluate(path.join(tmp, 's.json'));
    expect(Object.keys(json)).toEqual(['reconError', 'median', 'p95', 'nodes', 'cycles', 'radiiSource']);
    expect(json.cycles).toBe(4);
    expect(json.radiiSource).toBe('given');
    expect(json.reconError).toBeGreaterThan(0);
    expect(await evaluate(path.join(tmp, 's.ply'))).toEqual(json);
    expect(await evaluate(path.join(tmp, 's.obj'))).toEqual(json);
    expect((await evaluate(path.join(tmp, 's.json'), '--derive-radii')).radiiSource).toBe('derived');
  }, 60_000);

  it("reads another tool's OBJ polylines without radii", async () => {
    // Two polylines sharing the node 2, as skeleton tools write them: `l` with several indices.
    const obj = ['v -1 0 0', 'v 0 0 0', 'v 1 0 0', 'v 1 1 0', 'l 1 2 3', 'l 3 4', ''].join('\n');
    const file = path.join(tmp, 'other.obj');
    writeFileSync(file, obj);
    const result = await evaluate(file);
    expect(result).toMatchObject({ nodes: 4, cycles: 0, radiiSource: 'derived' });
  });

  it('says what is wrong with a skeleton that names a missing node', async () => {
    const file = path.join(tmp, 'broken.obj');
    writeFileSync(file, 'v 0 0 0\nv 1 0 0\nl 1 3\n');
    const result = await cscd('evaluate', mesh, file);
    expect(result.status).not.toBe(0);
    expect(result.stderr).toMatch(/^cscd: .*3/);
  });
});
