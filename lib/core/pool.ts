// Stage 1 on a pool of workers, the same in Node (lib/core/node-pool.ts) and in the page: the pipeline
// draws a round, its sources go to whichever worker is free, and the round is accepted in draw order, so
// the skeleton is the one `step` gives, whatever the pool's size.
//
// The pipeline's own thread only draws and accepts: were it to compute sources too, it could not hand a
// worker its next one while it computes, so each worker would need a second source queued, and at the
// end of a round a worker would still hold one that the idle pipeline thread could have done (stage 1
// on two threads against one, 15 meshes: 1.53x that way, 1.72x this way; docs/parallel.md).
import type { CandidateRecord, Pipeline, PipelineProgress } from './types.ts';

/** Another pipeline on the same mesh and options, elsewhere (a worker thread, a Web Worker). */
export interface SeparatorWorker {
  separators(sources: Uint32Array): Promise<CandidateRecord[]>;
}

/** Lets events (a cancel) in between two rounds computed here. */
const yieldToEvents = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/** How often a cancel is looked for while the workers compute (ms). */
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
  /** Before each source, and while waiting for the workers: throws to stop (a cancel). */
  check?: () => void;
  /** A worker failed (it crashed, ran out of memory): its sources are computed by the others. */
  lost?: (worker: SeparatorWorker, error: unknown) => void;
}

/** Stage 1 of `pipeline` on `workers` (none: all here, by `step`); then `finish` gives the skeleton. */
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
    const check = () => {
      try {
        hooks.check?.();
      } catch (error) {
        queue.length = 0; // the other workers take no more
        throw error;
      }
    };
    const lane = async (worker: SeparatorWorker) => {
      while (alive.has(worker) && queue.length > 0) {
        check();
        const i = queue.shift()!;
        try {
          records[i] = (await worker.separators(round.slice(i, i + 1)))[0];
        } catch (error) {
          queue.unshift(i);
          if (alive.delete(worker)) hooks.lost?.(worker, error);
        }
      }
    };
    await waitHearing(Promise.all([...alive].map(lane)), hooks.check && check);
    // Every worker lost during the round: the rest of it here.
    for (let i = queue.shift(); i !== undefined; i = queue.shift()) {
      hooks.check?.();
      records[i] = pipeline.separators(round.slice(i, i + 1))[0];
    }
    const progress = pipeline.accept(records);
    hooks.progress?.(progress);
    if (progress.finished) return progress;
  }
}
