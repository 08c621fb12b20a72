// Stage 1 on a pool of worker threads (lib/core/pool.ts, node-pool.ts): the skeleton does not depend
// on the number of workers, a lost worker's sources are computed by the others, a cancel stops the run.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { openNodePool, type NodePool } from '../../lib/core/node-pool.ts';
import { runStage1, type SeparatorWorker } from '../../lib/core/pool.ts';
import { PooledWorker, type PoolReply, type PoolRequest } from '../../lib/core/pool-worker.ts';
import { defaultOptions } from '../../lib/core/options.ts';
import type { CandidateRecord, MeshArrays, Options, Pipeline, PipelineProgress, Skeleton } from '../../lib/core/types.ts';
import { writeSkeletonJson } from '../../lib/io/skeleton.ts';
import { sharedMesh } from '../paths.ts';
import { readMesh } from './support/meshes.ts';

const MESH: MeshArrays = readMesh(sharedMesh('fertility_9k.ply'));
const OPTIONS: Options = { ...defaultOptions, n: 12, drawAhead: 4, seed: 7 };

let core: Core;
let pool: NodePool;
beforeAll(async () => {
  core = await loadCoreNode();
  pool = await openNodePool(core.stage1Input(MESH, OPTIONS), OPTIONS, { workers: 3 });
}, 60_000);
afterAll(() => pool?.close());

/** The skeleton JSON without timings: what must not depend on the pool. */
const json = (s: Skeleton) => writeSkeletonJson({ ...s, stats: { ...s.stats, timings: {} } }, { mesh: 'fertility_9k.ply', options: OPTIONS });

async function skeletonWith(workers: readonly SeparatorWorker[], hooks = {}): Promise<Skeleton> {
  const surface = core.openRefinedSurface(MESH);
  const pipeline = surface.pipeline(OPTIONS);
  try {
    await runStage1(pipeline, workers, hooks);
    return pipeline.finish();
  } finally {
    pipeline.dispose();
    surface.dispose();
  }
}

describe('stage 1 on a pool of worker threads', () => {
  it('gives the skeleton of a single thread, byte for byte, on 1, 2 or 3 worker threads', async () => {
    const surface = core.openRefinedSurface(MESH);
    const alone = surface.skeleton(OPTIONS);
    surface.dispose();
    expect(alone.stats.n).toBe(12);
    for (const workers of [[], pool.workers.slice(0, 1), pool.workers.slice(0, 2), pool.workers]) expect(json(await skeletonWith(workers)), `${workers.length} worker threads`).toBe(json(alone));
  }, 120_000);

  it('takes candidates in batches of any size, each draw right after its candidate, as step() does', () => {
    const sources = (drawAhead: number, batches: boolean) => {
      const surface = core.openRefinedSurface(MESH);
      const pipeline = surface.pipeline({ ...OPTIONS, drawAhead });
      try {
        if (batches) for (let drawn = pipeline.draw(); drawn.length > 0; drawn = pipeline.draw()) pipeline.accept(pipeline.separators(drawn));
        return json(pipeline.finish());
      } finally {
        pipeline.dispose();
        surface.dispose();
      }
    };
    expect(sources(4, true)).toBe(sources(4, false));
    // Drawn ahead, sources land elsewhere than one at a time.
    expect(sources(1, false)).not.toBe(sources(4, false));
  }, 120_000);

  it('gives a worker its next source before taking the candidate it answered', async () => {
    // The accept covers and draws (a millisecond or two): the worker must not wait for it.
    const events: string[] = [];
    const worker: SeparatorWorker = {
      separators: async (sources) => {
        events.push(`give ${sources[0]}`);
        return pool.workers[0].separators(sources);
      },
    };
    const surface = core.openRefinedSurface(MESH);
    const pipeline = surface.pipeline(OPTIONS);
    const accept = pipeline.accept.bind(pipeline);
    pipeline.accept = (records) => {
      events.push(`accept ${records.map((r) => r.source).join(',')}`);
      return accept(records);
    };
    try {
      await runStage1(pipeline, [worker]);
      expect(pipeline.finish().stats.n).toBe(12);
    } finally {
      pipeline.dispose();
      surface.dispose();
    }
    const gives = events.filter((e) => e.startsWith('give'));
    expect(gives).toHaveLength(12);
    // One worker, one source at a time: before the k-th accept (from 0), the source it takes and the
    // next one were given, k + 2 in all (but at the last, with no source left).
    const accepts = events.flatMap((e, i) => (e.startsWith('accept') ? [i] : []));
    expect(accepts).toHaveLength(12);
    accepts.slice(0, -1).forEach((at, k) => expect(events.slice(0, at).filter((e) => e.startsWith('give')), events.slice(0, at + 1).join('; ')).toHaveLength(k + 2));
  }, 120_000);

  it('hands the sources of a worker that fails to the others and reports it', async () => {
    const surface = core.openRefinedSurface(MESH);
    const alone = json(surface.skeleton(OPTIONS));
    surface.dispose();
    let calls = 0;
    const failing: SeparatorWorker = {
      separators: (sources) => (++calls === 3 ? Promise.reject(new Error('worker crashed')) : pool.workers[0].separators(sources)),
    };
    const lost: unknown[] = [];
    const skeleton = await skeletonWith([failing, pool.workers[1]], { lost: (_: SeparatorWorker, e: unknown) => lost.push(e) });
    expect(lost).toEqual([new Error('worker crashed')]);
    expect(json(skeleton)).toBe(alone);
  }, 120_000);

  it('goes on without a thread that stops mid-run', async () => {
    const spare = await openNodePool(core.stage1Input(MESH, OPTIONS), OPTIONS, { workers: 2 });
    const lost: unknown[] = [];
    let reports = 0;
    const skeleton = await skeletonWith(spare.workers, {
      lost: (_: SeparatorWorker, e: unknown) => lost.push(e),
      progress: () => {
        if (++reports === 1) void spare.workers[0].close();
      },
    });
    expect(lost).toHaveLength(1);
    expect(String(lost[0])).toMatch(/worker thread stopped/);
    expect(skeleton.stats.n).toBe(12);
    await spare.close();
  }, 120_000);

  it('still hears a cancel, an event, once every worker is lost', async () => {
    const lost: SeparatorWorker = { separators: () => Promise.reject(new Error('worker crashed')) };
    let cancelled = false;
    let reports = 0;
    let done = 0;
    const run = skeletonWith([lost], {
      // The cancel comes as a message would: after the run has let events in.
      progress: (progress: PipelineProgress) => {
        done = progress.done;
        if (++reports === 2) setTimeout(() => (cancelled = true), 0);
      },
      check: () => {
        if (cancelled) throw new Error('cancelled');
      },
    });
    await expect(run).rejects.toThrow('cancelled');
    expect(done).toBeLessThan(OPTIONS.n as number);
  }, 120_000);

  it('hears a cancel while the workers hold their sources without answering', async () => {
    // Two workers, a source each, never answering: this thread only waits.
    const silent = (): SeparatorWorker => ({ separators: () => new Promise(() => {}) });
    let cancelled = false;
    setTimeout(() => (cancelled = true), 200);
    const run = skeletonWith([silent(), silent()], {
      check: () => {
        if (cancelled) throw new Error('cancelled');
      },
    });
    await expect(run).rejects.toThrow('cancelled');
  }, 20_000);

  it('fails the run, not the process, when taking a candidate fails', async () => {
    const broken = {
      draw: () => Uint32Array.of(1, 2),
      accept: () => {
        throw new Error('the core refused the candidate');
      },
    } as unknown as Pipeline;
    const echo: SeparatorWorker = { separators: (sources) => Promise.resolve([...sources].map((source) => ({ source }) as CandidateRecord)) };
    await expect(runStage1(broken, [echo])).rejects.toThrow('the core refused the candidate');
    // The worker already holds its next source when the accept fails; the pool closing then fails that
    // request, which nobody awaits any more: no unhandled rejection (Vitest would report it).
    let calls = 0;
    const closing: SeparatorWorker = {
      separators: (sources) =>
        ++calls === 1
          ? echo.separators(sources)
          : new Promise((_, reject) => setTimeout(() => reject(new Error('worker thread stopped')), 10)),
    };
    await expect(runStage1(broken, [closing])).rejects.toThrow('the core refused the candidate');
    expect(calls).toBe(2);
    await new Promise((resolve) => setTimeout(resolve, 50));
  });

  it('stops at a cancel', async () => {
    let checks = 0;
    const cancelled = skeletonWith(pool.workers, {
      check: () => {
        if (++checks === 3) throw new Error('cancelled');
      },
    });
    await expect(cancelled).rejects.toThrow('cancelled');
  }, 120_000);
});

/** A pool worker's owner side on a fake worker that answers when the test says. */
class FakeWorker extends PooledWorker {
  readonly sent: PoolRequest[] = [];
  protected send(request: PoolRequest): void {
    this.sent.push(request);
  }
  reply(reply: PoolReply): void {
    this.receive(reply);
  }
}

describe('the owner side of a pool worker (PooledWorker, Node and page alike)', () => {
  it('settles each request by its reply, and an error of the core by its kind', async () => {
    const worker = new FakeWorker();
    const a = worker.separators(Uint32Array.of(1));
    const b = worker.separators(Uint32Array.of(2));
    expect(worker.sent.map((r) => [r.id, [...r.sources]])).toEqual([[0, [1]], [1, [2]]]);
    worker.reply({ id: 1, error: { message: 'out of memory: x', kind: 'memory' } });
    worker.reply({ id: 0, records: [] });
    await expect(a).resolves.toEqual([]);
    await expect(b).rejects.toMatchObject({ kind: 'memory', message: 'out of memory: x' });
    expect(worker.failed).toBe(false); // a core out of memory still answers
  });

  it('after a crash reply rejects that request, every other pending one and every later one', async () => {
    const worker = new FakeWorker();
    const a = worker.separators(Uint32Array.of(1));
    const b = worker.separators(Uint32Array.of(2));
    worker.reply({ id: 0, error: { message: 'Aborted(simulated crash)', kind: 'crash' } });
    await expect(a).rejects.toThrow('Aborted(simulated crash)');
    await expect(b).rejects.toThrow('Aborted(simulated crash)');
    await expect(worker.separators(Uint32Array.of(3))).rejects.toThrow('Aborted(simulated crash)');
    expect(worker.failed).toBe(true);
  });
});
