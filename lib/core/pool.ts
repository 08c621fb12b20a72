// Stage 1 on a pool of workers, the same in Node (lib/core/node-pool.ts) and in the page: the pipeline
// draws `drawAhead` sources ahead, each goes to whichever worker is free, and their candidates are
// accepted in draw order as they come (each accept draws the next source), so the skeleton is the one
// `step` gives, whatever the pool's size, and no worker waits for another's source unless all the
// sources drawn ahead are taken.
//
// The pipeline's own thread only draws and accepts: were it to compute sources too, it could not hand a
// worker its next one while it computes (stage 1 on two threads against one, 15 meshes: 1.53x that way,
// 1.72x this way; docs/parallel.md).
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
  /** After each accept (one or more candidates taken). */
  progress?: (progress: PipelineProgress) => void;
  /** Before each source, and while waiting for the workers: throws to stop (a cancel). */
  check?: () => void;
  /** A worker failed (it crashed, ran out of memory): its sources are computed by the others. */
  lost?: (worker: SeparatorWorker, error: unknown) => void;
}

/** Stage 1 here, a source at a time; `between`: let events in between two sources (a cancel). */
async function stepHere(pipeline: Pipeline, hooks: Stage1Hooks, between: boolean): Promise<PipelineProgress> {
  for (;;) {
    hooks.check?.();
    // The candidates never copied out of the core and back.
    const progress = pipeline.step(1);
    hooks.progress?.(progress);
    if (progress.finished) return progress;
    if (between) await yieldToEvents();
  }
}

/** Stage 1 of `pipeline` on `workers` (none: all here, by `step`); then `finish` gives the skeleton. */
export async function runStage1(pipeline: Pipeline, workers: readonly SeparatorWorker[], hooks: Stage1Hooks = {}): Promise<PipelineProgress> {
  if (workers.length === 0) return stepHere(pipeline, hooks, false);
  const alive = new Set(workers);
  const sources: number[] = []; // every source drawn, in draw order
  const records = new Map<number, CandidateRecord>(); // by draw index, until accepted
  const queue: number[] = []; // draw indices not given to a worker
  let taken = 0; // candidates accepted
  let progress: PipelineProgress | null = null;
  let finished = false;
  let over = () => {};
  const ended = new Promise<void>((resolve) => (over = resolve));
  // Lanes with nothing to take wait for a change: sources drawn, a source given back, the end.
  let wake = () => {};
  let changed = new Promise<void>((resolve) => (wake = resolve));
  const signal = () => {
    wake();
    changed = new Promise<void>((resolve) => (wake = resolve));
  };
  const drawMore = () => {
    for (const source of pipeline.draw()) {
      queue.push(sources.length);
      sources.push(source);
    }
  };
  const takeReady = () => {
    let end = taken;
    while (records.has(end)) end++;
    if (end === taken || finished) return;
    const ready: CandidateRecord[] = [];
    for (let i = taken; i < end; i++) {
      ready.push(records.get(i)!);
      records.delete(i);
    }
    taken = end;
    progress = pipeline.accept(ready);
    hooks.progress?.(progress);
    if (progress.finished) {
      finished = true;
      queue.length = 0;
      over();
    } else drawMore();
    signal();
  };
  const check = () => {
    try {
      hooks.check?.();
    } catch (error) {
      queue.length = 0; // the other workers take no more
      throw error;
    }
  };
  // The next queued source, sent to `worker` (undefined: none queued). Its answer may never be awaited
  // (the run stopped, or an accept failed, while the worker held it): a failure of it is then nobody's.
  const give = (worker: SeparatorWorker) => {
    const i = queue.shift();
    if (i === undefined) return undefined;
    const work = worker.separators(Uint32Array.of(sources[i]));
    work.catch(() => {});
    return { i, work };
  };
  const lane = async (worker: SeparatorWorker) => {
    let held: ReturnType<typeof give>;
    while (alive.has(worker) && !finished) {
      check();
      held ??= give(worker);
      if (held === undefined) {
        await changed;
        continue;
      }
      const { i, work } = held;
      held = undefined;
      try {
        records.set(i, (await work)[0]);
      } catch (error) {
        if (finished) return; // stopped after the run (a source dropped by the auto stop): not lost
        queue.unshift(i);
        if (alive.delete(worker)) hooks.lost?.(worker, error);
        signal();
        return;
      }
      // The worker gets its next source before the accept: the accept's covering and draw take a
      // millisecond or two (a few % of a source) that it would otherwise spend waiting.
      if (!finished) {
        check();
        held = give(worker);
      }
      takeReady();
    }
  };

  drawMore();
  if (sources.length === 0) return pipeline.accept([]);
  // Finished, a worker may still hold a source drawn ahead that the auto stop dropped: not waited for.
  const lanes = Promise.all([...alive].map(lane));
  await waitHearing(Promise.race([lanes, ended]), hooks.check && check);
  if (finished) return progress!;
  // Every worker lost: the sources drawn ahead here, then the rest.
  for (let i = taken; i < sources.length; i++) {
    hooks.check?.();
    if (!records.has(i)) records.set(i, pipeline.separators(Uint32Array.of(sources[i]))[0]);
  }
  takeReady();
  return finished ? progress! : stepHere(pipeline, hooks, true);
}
