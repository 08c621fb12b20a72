// The records the core returns (C++ struct → one toVal in wasm/src/bindings/ → one type in
// lib/core/types.ts) have exactly the keys of their TypeScript type, each of the array type it names,
// so callers (the worker, the CLI) can use them without fallbacks. Each contract below must list every
// key of its type (the compiler checks that); the test checks the core's values against it.
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import type { Evaluation, MeshFacts, PipelineProgress, Refinement, Separator, Skeleton } from '../../lib/core/types.ts';
import { icosphere, sheet, torus } from './support/meshes.ts';

type Field =
  | 'number'
  | 'string'
  | 'boolean'
  | 'Float64Array'
  | 'Float32Array'
  | 'Uint32Array'
  | 'Uint8Array'
  | 'milliseconds' // an object of numbers
  | { nullable: Field }
  | { list: Field; length?: number }
  | { object: Record<string, Field> };

/** Every key of T, with the field it holds. */
type Contract<T> = { [K in keyof T]-?: Field };

const VECTOR: Field = { list: 'number', length: 3 };

const FACTS: Contract<MeshFacts> = {
  vertices: 'number', faces: 'number', edges: 'number', components: 'number', boundaryLoops: 'number',
  eulerCharacteristic: 'number', genus: { nullable: 'number' }, manifold: 'boolean', consistentlyOriented: 'boolean',
  nonManifoldEdges: 'number', nonManifoldVertices: 'number', unreferencedVertices: 'number', degenerateFaces: 'number',
  bboxMin: VECTOR, bboxMax: VECTOR, bboxDiagonal: 'number', meanEdgeLength: 'number',
};

const CUT_LOCUS: Contract<Separator['cutLocus']> = {
  vertices: 'Uint32Array', points: 'Float64Array', edges: 'Uint32Array', angleDeviation: 'Float64Array',
  laplacian: 'Float64Array', root: 'number', cycleRank: 'number',
};

// `refined` is added by a RefinedSurface (checked below), not by the core.
const SEPARATOR: Omit<Contract<Separator>, 'refined'> = {
  source: 'number', status: 'string', message: 'string', distance: 'Float64Array', cutLocus: { object: CUT_LOCUS },
  boundaryExtremities: { object: { vertices: 'Uint32Array', points: 'Float64Array' } satisfies Contract<Separator['boundaryExtremities']> },
  target: { nullable: 'number' }, attempts: 'number', targetPoint: { nullable: VECTOR }, ends: { nullable: 'Uint32Array' },
  endPoints: { nullable: 'Float64Array' }, closed: 'boolean', paths: { list: 'Float64Array', length: 2 }, approxLoop: 'Float64Array',
  loop: 'Float64Array',
  sphere: { nullable: { object: { center: VECTOR, radius: 'number' } satisfies Contract<NonNullable<Separator['sphere']>> } },
  approxLength: 'number', length: 'number', areas: { list: 'number', length: 2 }, score: 'number', centroidInside: 'boolean',
  timings: 'milliseconds',
};

const PROGRESS: Contract<PipelineProgress> = {
  done: 'number', total: 'number', finished: 'boolean', newLoops: { list: 'Float64Array' }, newClosed: 'Uint8Array',
};

const SKELETON: Contract<Skeleton> = {
  nodes: 'Float64Array', radii: 'Float64Array', edges: 'Uint32Array', vertexToNode: 'Uint32Array',
  candidates: {
    object: {
      sources: 'Uint32Array', loops: { list: 'Float64Array' }, closed: 'Uint8Array', scores: 'Float64Array', fates: { list: 'string' },
    } satisfies Contract<Skeleton['candidates']>,
  },
  packed: 'Uint32Array',
  // `refined` and `simplified` are added by a RefinedSurface.
  stats: {
    object: { n: 'number', candidates: 'number', pruned: 'number', packed: 'number', cycles: 'number', seed: 'number', timings: 'milliseconds' } satisfies Omit<
      Contract<Skeleton['stats']>,
      'refined' | 'simplified'
    >,
  },
};

const EVALUATION: Contract<Evaluation> = {
  reconError: 'number', median: 'number', p95: 'number', nodes: 'number', cycles: 'number', radiiSource: 'string',
  radii: 'Float64Array', vertexError: 'Float64Array',
  surface: { object: { positions: 'Float32Array', triangles: 'Uint32Array' } },
  grid: { object: { cell: 'number', dims: VECTOR } },
  timings: 'milliseconds',
};

/** Where `value` departs from `field`, as paths (empty: it keeps the contract). */
function breaches(value: unknown, field: Field, path: string): string[] {
  if (typeof field === 'string') {
    if (field === 'milliseconds') {
      const ok = typeof value === 'object' && value !== null && Object.values(value).every((v) => typeof v === 'number' && v >= 0);
      return ok ? [] : [`${path}: expected an object of milliseconds`];
    }
    const type = typeof value === 'object' && value !== null ? value.constructor.name : typeof value;
    return type === field ? [] : [`${path}: expected ${field}, got ${value === null ? 'null' : type}`];
  }
  if ('nullable' in field) return value === null ? [] : breaches(value, field.nullable, path);
  if ('list' in field) {
    if (!Array.isArray(value)) return [`${path}: expected an array`];
    if (field.length !== undefined && value.length !== field.length) return [`${path}: expected ${field.length} items, got ${value.length}`];
    return value.flatMap((v, i) => breaches(v, field.list, `${path}[${i}]`));
  }
  if (typeof value !== 'object' || value === null || Array.isArray(value)) return [`${path}: expected an object`];
  const keys = Object.keys(value).sort(), expected = Object.keys(field.object).sort();
  if (keys.join() !== expected.join()) return [`${path}: keys ${keys.join(', ')}; expected ${expected.join(', ')}`];
  return expected.flatMap((k) => breaches((value as Record<string, unknown>)[k], field.object[k], `${path}.${k}`));
}

const keeps = (value: unknown, contract: Record<string, Field>) => breaches(value, { object: contract }, 'record');

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

const TORUS = torus(2, 0.6, 24, 12);
// An open strip: its separators are paths between boundary points (ends and endPoints set).
const STRIP = sheet([-2, 2], [-0.5, 0.5], 0.05, (x, y) => Math.abs(x) < 2 && Math.abs(y) < 0.5);

/** The vertex nearest to (x, y, 0). */
function vertexNear({ positions }: { positions: ArrayLike<number> }, x: number, y: number): number {
  let best = 0;
  for (let v = 1; v < positions.length / 3; v++)
    if (Math.hypot(positions[3 * v] - x, positions[3 * v + 1] - y) < Math.hypot(positions[3 * best] - x, positions[3 * best + 1] - y)) best = v;
  return best;
}

describe('the core’s records', () => {
  it('inspect returns MeshFacts', () => {
    expect(keeps(core.inspect(TORUS), FACTS)).toEqual([]);
    expect(core.inspect(TORUS).genus).toBe(1);
  });

  it('separator returns a Separator for a loop, a path and a failure alike', () => {
    const torusSurface = core.openSurface(TORUS);
    const strip = core.openSurface(STRIP);
    const sphere = core.openSurface(icosphere(3)); // its loops enclose nothing
    try {
      const loop = torusSurface.separator(0);
      expect(loop.status).toBe('ok');
      expect(loop.closed).toBe(true);
      expect(keeps(loop, SEPARATOR)).toEqual([]);
      const path = strip.separator(vertexNear(STRIP, -1.2, 0));
      expect(path.closed).toBe(false);
      expect(path.ends).not.toBeNull();
      expect(keeps(path, SEPARATOR)).toEqual([]);
      const failed = sphere.separator(0);
      expect(failed.status).not.toBe('ok');
      expect(keeps(failed, SEPARATOR)).toEqual([]);
    } finally {
      torusSurface.dispose();
      strip.dispose();
      sphere.dispose();
    }
  });

  it('a refined surface adds only `refined` (and `simplified`, null on a mesh this small)', () => {
    const surface = core.openRefinedSurface(TORUS); // coarse enough to be refined
    const REFINEMENT = { object: { fromVertices: 'number', fromFaces: 'number', toFaces: 'number', levels: 'number' } satisfies Contract<Refinement> } as const;
    try {
      const { refined, ...rest } = surface.separator(0);
      expect(breaches(refined, REFINEMENT, 'refined')).toEqual([]);
      expect(keeps(rest, SEPARATOR)).toEqual([]);
      const skeleton = surface.skeleton({ n: 4 });
      const { refined: again, simplified, ...stats } = skeleton.stats;
      expect(again).toEqual(refined);
      expect(simplified).toBeNull();
      expect(keeps({ ...skeleton, stats }, SKELETON)).toEqual([]);
    } finally {
      surface.dispose();
    }
  });

  it('a pipeline’s step returns PipelineProgress and finish a Skeleton', () => {
    const surface = core.openSurface(TORUS);
    const pipeline = surface.pipeline({ n: 6, drawAhead: 3 });
    try {
      const progress = pipeline.step(3);
      expect(keeps(progress, PROGRESS)).toEqual([]);
      expect(progress.newLoops).toHaveLength(3);
      const skeleton = pipeline.finish();
      expect(keeps(skeleton, SKELETON)).toEqual([]);
      expect(skeleton.candidates.loops).toHaveLength(6);
      expect(skeleton.stats.cycles).toBe(1);
    } finally {
      pipeline.dispose();
      surface.dispose();
    }
  });

  it('evaluate returns an Evaluation, with radii given or derived', () => {
    const surface = core.openSurface(TORUS);
    try {
      const skeleton = surface.skeleton({ n: 6 });
      expect(keeps(core.evaluate(TORUS, skeleton), EVALUATION)).toEqual([]);
      expect(keeps(core.evaluate(TORUS, { nodes: skeleton.nodes, edges: skeleton.edges }), EVALUATION)).toEqual([]);
    } finally {
      surface.dispose();
    }
  });
});
