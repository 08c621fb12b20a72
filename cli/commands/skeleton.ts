import { writeFile } from 'node:fs/promises';
import path from 'node:path';
import { defaultWorkers, openNodePool } from '../../lib/core/node-pool.ts';
import { runStage1 } from '../../lib/core/pool.ts';
import type { PipelineProgress, Skeleton } from '../../lib/core/types.ts';
import { SKELETON_FORMATS, SKELETON_WRITERS, skeletonFormatFromName, type SkeletonFormat } from '../../lib/io/skeleton.ts';
import { UsageError, decimateIfAsked, decimateOption, openSolver, readMesh, type Command, type OptionValues, type Output } from '../command.ts';
import { optionFlagSpecs, optionsFromFlags } from './separator.ts';

/** --workers K: a whole number from 1 up; more threads than a round has sources would idle. */
function workersFrom(values: OptionValues, roundSize: number): number {
  if (values.workers === undefined) return Math.min(defaultWorkers(), roundSize);
  const k = Number(values.workers);
  if (!(Number.isInteger(k) && k >= 1 && k <= 256)) throw new UsageError(`--workers must be a whole number from 1 to 256, got '${String(values.workers)}'`);
  return Math.min(k, roundSize);
}
/** At most this often (ms) is the progress line redrawn. */
const PROGRESS_INTERVAL = 100;

/** --format, else the extension of --out, else JSON. */
function outputFormat(values: OptionValues): SkeletonFormat {
  if (values.format !== undefined) {
    const format = String(values.format).toLowerCase();
    if (!(SKELETON_FORMATS as string[]).includes(format)) {
      throw new UsageError(`--format must be one of ${SKELETON_FORMATS.join(', ')}, got '${String(values.format)}'`);
    }
    return format as SkeletonFormat;
  }
  return typeof values.out === 'string' ? skeletonFormatFromName(values.out) ?? 'json' : 'json';
}

/** A line on stderr that rewrites itself (only used when stderr is a terminal). */
class ProgressLine {
  private last = -Infinity;
  private shown = false;

  constructor(private readonly stderr: Output) {}

  update(text: string, force = false): void {
    const now = performance.now();
    if (!force && now - this.last < PROGRESS_INTERVAL) return;
    this.last = now;
    this.shown = true;
    this.stderr.write(`\r${text}\x1b[K`);
  }

  clear(): void {
    if (this.shown) this.stderr.write('\r\x1b[K');
    this.shown = false;
  }
}

export const skeleton: Command = {
  name: 'skeleton',
  summary: 'the curve skeleton of a mesh (CSCD-M, stages 1 and 2), as JSON, PLY, OBJ or SWC',
  args: ['<mesh>'],
  options: {
    ...optionFlagSpecs(),
    decimate: decimateOption,
    format: { type: 'string', value: SKELETON_FORMATS.join('|'), description: 'output format (default: from the --out extension, else json)' },
    out: { type: 'string', value: 'FILE', description: 'write the skeleton to FILE instead of stdout' },
    verbose: { type: 'boolean', short: 'v', description: 'print the summary line on stderr even when it is not a terminal' },
    workers: {
      type: 'string',
      value: 'K',
      description: `threads that compute stage 1 (default: every core but one, here ${defaultWorkers()}); with K > 1 this thread only draws the sources and takes the results, and the K threads share each round of --round-size sources, so with --round-size 1 they have nothing to share; the skeleton does not depend on K`,
    },
  },
  details: [
    'Draws N sources with the seed (--n auto: until new separators stop adding coverage), finds a local',
    'separator from each (stage 1, as `cscd separator`), then keeps the best non-overlapping ones and',
    'builds the skeleton from the regions they bound (stage 2). On a terminal, progress and a summary',
    '(nodes, edges, cycles, N, seconds) go to stderr. Formats and keys: docs/cli.md.',
  ].join('\n'),
  async run([file], values, io) {
    const options = optionsFromFlags(values);
    const format = outputFormat(values);
    const mesh = decimateIfAsked(await readMesh(file, io), values, file, io);
    const tty = io.stderr.isTTY === true;
    const progress = new ProgressLine(io.stderr);
    const name = path.basename(file);

    const workers = workersFrom(values, options.roundSize);
    const started = performance.now();
    let result: Skeleton;
    // The pool's threads open the mesh while this one does.
    const opening = workers > 1 ? openNodePool(mesh, options, { workers }) : null;
    const surface = await openSolver(mesh, file, io).catch(async (error) => {
      await opening?.then((pool) => pool.close(), () => undefined);
      throw error;
    });
    const pool = await opening?.catch((error) => {
      surface.dispose();
      throw error;
    });
    try {
      const pipeline = surface.pipeline(options);
      try {
        const report = (step: PipelineProgress) => {
          if (tty) progress.update(`cscd: skeleton of ${name}: stage 1, source ${step.done} of ${options.n === 'auto' ? `at most ${step.total}` : step.total}`);
        };
        await runStage1(pipeline, pool?.workers ?? [], {
          progress: report,
          lost: (_, error) => io.stderr.write(`cscd: warning: a worker thread failed (${error instanceof Error ? error.message : String(error)}); the others go on\n`),
        });
        if (tty) progress.update(`cscd: skeleton of ${name}: stage 2`, true);
        result = pipeline.finish();
      } finally {
        pipeline.dispose();
      }
    } finally {
      await pool?.close();
      surface.dispose();
      progress.clear();
    }
    const seconds = (performance.now() - started) / 1000;

    const text = SKELETON_WRITERS[format](result, { mesh: file, options });
    if (typeof values.out === 'string') await writeFile(values.out, text);
    else io.stdout.write(text);

    const { stats } = result;
    if (stats.packed === 0) io.stderr.write(`cscd: warning: ${file}: no separator was kept: the skeleton is one node per connected component\n`);
    if (tty || values.verbose === true) {
      const nodes = result.nodes.length / 3;
      const edges = result.edges.length / 2;
      io.stderr.write(`cscd: skeleton of ${name}: ${nodes} nodes, ${edges} edges, ${stats.cycles} cycles, `
        + `N = ${stats.n} (${stats.packed} of ${stats.candidates} separators kept), ${seconds.toFixed(1)} s\n`);
    }
  },
};
