// Stage 1 on a pool of workers, the same in Node (lib/core/node-pool.ts) and in the page: the pipeline
// draws a round, its sources go to whoever is free (the pipeline's own thread computes too), and the
// round is accepted in draw order, so the skeleton is the one `step` gives, whatever the pool's size.
import type { CandidateRecord, Pipeline, PipelineProgress } from './types.ts';

/** Another pipeline on the same mesh and options, elsewhere (a worker thread, a Web Worker). */
export interface SeparatorWorker {
  separators(sources: Uint32Array): Promise<CandidateRecord[]>;
}

/**
 * Sources a worker holds at once: while the pipeline's thread computes one of its own (and cannot
 * answer), each worker still has the next one to work on.
 */
const IN_FLIGHT = 2;

/** Lets the workers' replies in between two sources computed here. */
const yieldToEvents = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/** How often a cancel is looked for while only workers compute (ms). */
const CHECK_MS = 20;

/** Waits for `work`, calling `check` meanwhile: a worker may hold a source for seconds, a cancel must not wait for it. */
async function waitHearing(work: Promise<unknown>, check?: () => void): Promise<void> {
  if (!check) {
    await work;
    return;
  }
  let done = false;
  const settled = work.then(() => (done = true));
  while (!done) {
    await Promise.race([settled, new Promise((resolve) => setTimeout(resolve, CHECK_MS))]);
    check();
  }
}

export interface Stage1Hooks {
  /** After each round. */
  progress?: (progress: PipelineProgress) => void;
  /** Between two sources computed here: throws to stop (a cancel). */
  check?: () => void;
  /** A worker failed (it crashed, ran out of memory): its sources are computed by the others. */
  lost?: (worker: SeparatorWorker, error: unknown) => void;
}

/** Stage 1 of `pipeline` with `workers` beside it (none: all here, by `step`); then `finish` gives the skeleton. */
export async function runStage1(pipeline: Pipeline, workers: readonly SeparatorWorker[], hooks: Stage1Hooks = {}): Promise<PipelineProgress> {
  const alive = new Set(workers);
  for (;;) {
    hooks.check?.();
    if (alive.size === 0) {
      // Alone: the round in place, its candidates never copied out of the core and back.
      const progress = pipeline.step(1);
      hooks.progress?.(progress);
      if (progress.finished) return progress;
      // Every worker lost: a cancel must still get in between rounds (a caller without workers has none to hear).
      if (workers.length > 0) await yieldToEvents();
      continue;
    }
    const round = pipeline.drawRound();
    if (round.length === 0) return pipeline.accept([]);
    const records: CandidateRecord[] = new Array(round.length);
    const queue = [...round.keys()];
    const lane = async (worker: SeparatorWorker) => {
      while (alive.has(worker) && queue.length > 0) {
        const i = queue.shift()!;
        try {
          records[i] = (await worker.separators(round.slice(i, i + 1)))[0];
        } catch (error) {
          queue.unshift(i);
          if (alive.delete(worker)) hooks.lost?.(worker, error);
        }
      }
    };
    const remote = [...alive].flatMap((worker) => Array.from({ length: IN_FLIGHT }, () => lane(worker)));
    for (let i = queue.shift(); i !== undefined; i = queue.shift()) {
      records[i] = pipeline.separators(round.slice(i, i + 1))[0];
      await yieldToEvents();
      hooks.check?.();
    }
    await waitHearing(Promise.all(remote), hooks.check);
    // A worker lost at the end of the round left its source to nobody.
    for (let i = queue.shift(); i !== undefined; i = queue.shift()) records[i] = pipeline.separators(round.slice(i, i + 1))[0];
    const progress = pipeline.accept(records);
    hooks.progress?.(progress);
    if (progress.finished) return progress;
  }
}
