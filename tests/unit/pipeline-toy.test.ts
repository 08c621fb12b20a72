// The generic pipeline (wasm/src/cscd/pipeline.h: prune, pack, regions to graph, clique to star, bands,
// the auto stop) on a toy realization (wasm/tests/toy_pipeline.cpp), through the same binding template
// as CSCD-M's, in milliseconds. The toy's rules are restated here from that file's header: points one
// unit apart on the axes of tubes of radius 1, a star of three arms of 20 points or a ring of 60.
import { readFile } from 'node:fs/promises';
import { beforeAll, describe, expect, it } from 'vitest';
import createToyModule, { type ToyModule } from '../../build/wasm/cscd_toy.js';
import type { CoreFailure } from '../../build/wasm/cscd.js';
import { AUTO_N } from '../../lib/core/options.ts';
import type { PipelineProgress, Skeleton } from '../../lib/core/types.ts';

const ARM = 20;

let toy: ToyModule;
beforeAll(async () => {
  toy = await createToyModule({ wasmBinary: await readFile(new URL('../../build/wasm/cscd_toy.wasm', import.meta.url)) });
});

type Kind = 'star' | 'ring' | 'lopsided';

/** Runs `steps` (sources per call) of stage 1, then stage 2, and returns the progress reports and the skeleton. */
function run(kind: Kind, options: object, steps: number[] = []): { progress: PipelineProgress[]; skeleton: Skeleton } {
  const shape = new toy.ToyShape(kind);
  const pipeline = new toy.Pipeline(shape, options);
  try {
    expect(pipeline.error()).toBeNull();
    const progress = steps.map((count) => pipeline.step(count) as PipelineProgress);
    return { progress, skeleton: pipeline.finish() as Skeleton };
  } finally {
    pipeline.delete();
    shape.delete();
  }
}

/** Graph distance between toy points: the star's arm a point k is 1 + a * ARM + (k - 1), its centre 0. */
function hops(kind: Kind, s: number, t: number): number {
  if (kind === 'ring') return Math.min(Math.abs(s - t), 60 - Math.abs(s - t));
  const arm = (p: number) => Math.floor((p - 1) / ARM);
  const step = (p: number) => ((p - 1) % ARM) + 1;
  if (s === 0 || t === 0) return s === 0 ? (t === 0 ? 0 : step(t)) : step(s);
  return arm(s) === arm(t) ? Math.abs(step(s) - step(t)) : step(s) + step(t) - 1; // across the joined first points
}

const pointCount = (kind: Kind) => (kind === 'ring' ? 60 : 1 + 3 * ARM);

/** The fate the pipeline's prune step must give the toy's loop from source s (a live loop: packed or overlapping). */
function prunedFate(kind: Kind, s: number): 'failed' | 'short' | 'outside' | 'live' {
  const step = ((s - 1) % ARM) + 1;
  if (kind !== 'ring' && (s === 0 || step <= 2)) return 'failed';
  if (kind !== 'ring' && step === ARM) return 'short'; // a loop of 2π·0.2 < 3 units
  return s % 7 === 3 ? 'outside' : 'live';
}

function degrees(skeleton: Skeleton): number[] {
  const degree = new Array<number>(skeleton.nodes.length / 3).fill(0);
  for (const e of skeleton.edges) degree[e]++;
  return degree;
}

const node = (skeleton: Skeleton, i: number) => [0, 1, 2].map((k) => skeleton.nodes[3 * i + k]);

describe('the generic pipeline on a toy realization', () => {
  it('prunes failed, short and outside loops and packs the rest without overlaps', () => {
    const { skeleton } = run('star', { n: 40, seed: 3 });
    const { sources, fates } = skeleton.candidates;
    expect(fates).toHaveLength(40);
    const counts = { failed: 0, short: 0, outside: 0 };
    sources.forEach((s, i) => {
      const expected = prunedFate('star', s);
      if (expected === 'live') expect(['packed', 'overlapping'], `source ${s}`).toContain(fates[i]);
      else {
        expect(fates[i], `source ${s}`).toBe(expected);
        counts[expected]++;
      }
    });
    expect(counts.failed + counts.short + counts.outside).toBeGreaterThan(0);
    expect(skeleton.stats.pruned).toBe(counts.short + counts.outside);
    expect(skeleton.stats.candidates).toBe(40 - counts.failed);

    const packed = [...skeleton.packed].map((i) => sources[i]);
    expect(packed.length).toBe(skeleton.stats.packed);
    expect([...skeleton.packed].every((i) => fates[i] === 'packed')).toBe(true);
    for (const a of packed) for (const b of packed) if (a !== b) expect(hops('star', a, b), `${a} and ${b}`).toBeGreaterThan(3);
    // Greedy packing is maximal: a live loop left out overlaps one that was kept.
    sources.forEach((s, i) => {
      if (fates[i] === 'overlapping') expect(packed.some((p) => hops('star', s, p) <= 3), `source ${s}`).toBe(true);
    });
  });

  it('turns the star into a tree with one branch node, a leaf at each tip and nodes about a unit apart', () => {
    const { skeleton } = run('star', { n: 40, seed: 3 });
    const degree = degrees(skeleton);
    expect(skeleton.stats.cycles).toBe(0);
    expect(degree.filter((d) => d === 3)).toHaveLength(1);
    expect(degree.filter((d) => d > 3)).toHaveLength(0);
    const branch = node(skeleton, degree.indexOf(3));
    expect(Math.hypot(...branch)).toBeLessThan(2);
    const leaves = degree.flatMap((d, i) => (d === 1 ? [node(skeleton, i)] : []));
    expect(leaves).toHaveLength(3);
    for (let arm = 0; arm < 3; arm++) {
      const a = (2 * Math.PI * arm) / 3;
      const tip = [ARM * Math.cos(a), ARM * Math.sin(a), 0];
      // Within a tube radius and a spacing of the tip (the toy has no cap for the leaf to reach into).
      expect(Math.min(...leaves.map((l) => Math.hypot(l[0] - tip[0], l[1] - tip[1], l[2] - tip[2]))), `arm ${arm}`).toBeLessThan(2 + 1e-9);
    }
    // Bands one separator radius (1) wide: about one node per unit of the 60-unit star, and every
    // point of the shape owned by a node.
    expect(degree.length).toBeGreaterThan(30);
    expect(skeleton.vertexToNode).toHaveLength(pointCount('star'));
    expect(Math.max(...skeleton.vertexToNode)).toBeLessThan(degree.length);
    expect([...skeleton.radii]).toEqual(new Array(degree.length).fill(1));
  });

  it('keeps the ring a cycle: three regions that touch pairwise around it are not a junction', () => {
    const { skeleton } = run('ring', { n: 12, seed: 2 });
    expect(skeleton.stats.packed).toBeGreaterThanOrEqual(3);
    expect(skeleton.stats.cycles).toBe(1);
    expect(degrees(skeleton).every((d) => d === 2)).toBe(true);
  });

  it('stops auto mode by the rule of lib/core/options.ts: covered, or too little gain over a window', () => {
    for (const kind of ['star', 'lopsided'] as const) {
      const { skeleton } = run(kind, { n: 'auto', seed: 5 });
      const sources = [...skeleton.candidates.sources];
      const covered = new Set<number>();
      const history: number[] = [];
      let stop = 0;
      for (const s of sources) {
        for (let p = 0; p < pointCount(kind); p++) if (hops(kind, s, p) <= 2) covered.add(p);
        history.push(covered.size / pointCount(kind));
        const k = history.length;
        if (history[k - 1] >= AUTO_N.covered || (k > AUTO_N.window && history[k - 1] - history[k - 1 - AUTO_N.window] < AUTO_N.minGain)) {
          stop = k;
          break;
        }
      }
      expect(skeleton.stats.n, kind).toBe(stop);
      // The star is covered; the lopsided star, never drawn on its third arm, stops by the window with
      // at most its 41 drawable points and the third arm's first two covered.
      if (kind === 'star') expect(history.at(-1)).toBeGreaterThanOrEqual(AUTO_N.covered);
      else expect(history.at(-1)).toBeLessThanOrEqual(43 / 61);
    }
  });

  it('reports stage 1 and its loops source by source, and gives the same skeleton whatever the steps', () => {
    const { progress, skeleton } = run('star', { n: 20, seed: 4, drawAhead: 4 }, [5, 6, 10]);
    expect(progress.map((p) => [p.done, p.total, p.finished])).toEqual([[5, 20, false], [11, 20, false], [20, 20, true]]);
    expect(progress.map((p) => p.newLoops.length)).toEqual([5, 6, 9]);
    expect(progress.flatMap((p) => p.newLoops.map((l) => l.length))).toEqual(skeleton.candidates.loops.map((l) => l.length));
    const whole = run('star', { n: 20, seed: 4, drawAhead: 4 }).skeleton;
    skeleton.stats.timings = whole.stats.timings = {};
    expect(skeleton).toEqual(whole);
    const auto = run('star', { seed: 4, drawAhead: 3 }, [3]).progress[0];
    expect([auto.done, auto.total]).toEqual([3, AUTO_N.max]);
  });

  it('draws other sources for another seed', () => {
    const a = run('star', { n: 20, seed: 1 }).skeleton.candidates.sources;
    const b = run('star', { n: 20, seed: 2 }).skeleton.candidates.sources;
    expect([...a]).not.toEqual([...b]);
  });

  it('returns failures as values of their kind', () => {
    const shape = new toy.ToyShape('cube');
    expect(shape.error()).toMatchObject({ coreError: 'input', message: expect.stringContaining("'cube'") });
    const pipeline = new toy.Pipeline(shape, {});
    expect(pipeline.error()).toMatchObject({ coreError: 'input', message: 'the shape could not be opened' });
    pipeline.delete();
    shape.delete();
    const star = new toy.ToyShape('star');
    const bad = new toy.Pipeline(star, { angleThreshold: 9 });
    expect((bad.error() as CoreFailure).coreError).toBe('input');
    bad.delete();
    star.delete();
  });
});
