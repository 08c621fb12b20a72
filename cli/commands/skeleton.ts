import { writeFile } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { openNodeCloudPool, openNodePool, type NodePool } from '../../lib/core/node-pool.ts';
import { AUTO_N, type RunSettings } from '../../lib/core/options.ts';
import { runStage1 } from '../../lib/core/pool.ts';
import { CLOUD_VERTICES_PER_POINT, poolSize } from '../../lib/core/pool-size.ts';
import type { CloudOptions, Options, Pipeline, PipelineProgress, ShapeOptions, Skeleton } from '../../lib/core/types.ts';
import { SKELETON_FORMATS, SKELETON_WRITERS, skeletonFormatFromName, type SkeletonFormat } from '../../lib/io/skeleton.ts';
import { AS_CLOUD } from '../../lib/cloud/from-mesh.ts';
import {
  UsageError, asCloudFlag, asCloudOption, decimateIfAsked, decimateOption, getCore, openCloud, openSolver, readShape, refuseFlags, subsampleFlag, subsampleOption,
  type CliIo, type Command, type InputCloud, type InputMesh, type OptionValues, type Output,
} from '../command.ts';
import { cloudFlagSpecs, cloudOnlyFlags, cloudOptionsFromFlags, optionFlagSpecs, optionsFromFlags, settingFlagSpecs, settingsFromFlags } from './separator.ts';

/**
 * Threads of stage 1 (lib/core/pool-size.ts: the page's rule, with this machine's cores and memory);
 * `vertices`: of the mesh as read (refinement only touches coarse meshes, which are small), or a
 * cloud's points in mesh vertices of the same memory.
 */
function threadsFor(settings: RunSettings, options: ShapeOptions, vertices: number): number {
  return poolSize({
    workers: settings.workers,
    cores: os.availableParallelism(),
    memoryGB: os.totalmem() / 2 ** 30,
    vertices,
    drawAhead: options.drawAhead,
    sourcesLeft: options.n === 'auto' ? AUTO_N.max : options.n,
  }).workers;
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
  summary: 'the curve skeleton of a mesh (CSCD-M) or a point cloud (CSCD-PC), stages 1 and 2, as JSON, PLY, OBJ or SWC',
  args: ['<mesh|cloud>'],
  options: {
    ...optionFlagSpecs(),
    ...cloudFlagSpecs(),
    [AS_CLOUD.flag]: asCloudOption,
    decimate: decimateOption,
    subsample: subsampleOption,
    format: { type: 'string', value: SKELETON_FORMATS.join('|'), description: 'output format (default: from the --out extension, else json)' },
    out: { type: 'string', value: 'FILE', description: 'write the skeleton to FILE instead of stdout' },
    verbose: { type: 'boolean', short: 'v', description: 'print the summary line on stderr even when it is not a terminal' },
    ...settingFlagSpecs(),
  },
  details: [
    'Draws N sources with the seed (--n auto: until new separators stop adding coverage), finds a local',
    'separator from each (stage 1, as `cscd separator`), then keeps the best non-overlapping ones and',
    'builds the skeleton from the regions they bound (stage 2). On a terminal, progress and a summary',
    '(nodes, edges, cycles, N, seconds) go to stderr. Formats and keys: docs/cli.md. A point cloud (a file',
    'without faces) runs CSCD-PC, on worker threads as meshes do; vertexToNode is then per point.',
  ].join('\n'),
  async run([file], values, io) {
    const cloudOptions = cloudOptionsFromFlags(values);
    const settings = settingsFromFlags(values);
    const format = outputFormat(values);
    const shape = await readShape(file, io, cloudOptions.neighbours, { asCloud: asCloudFlag(values), subsample: subsampleFlag(values, cloudOptions.neighbours) });
    const progress = new ProgressLine(io.stderr);
    const started = performance.now();
    let result: Skeleton;
    let options: ShapeOptions;
    try {
      if (shape.kind === 'cloud') {
        refuseFlags(values, ['decimate', 'stage1-vertices'], file, 'point cloud');
        options = cloudOptions;
        result = await cloudSkeleton(shape, cloudOptions, settings, file, io, progress);
      } else {
        refuseFlags(values, cloudOnlyFlags(), file, 'mesh');
        options = optionsFromFlags(values);
        result = await meshSkeleton(decimateIfAsked(shape, values, file, io), options, settings, file, io, progress);
      }
    } finally {
      progress.clear();
    }
    const seconds = (performance.now() - started) / 1000;

    const text = SKELETON_WRITERS[format](result, { mesh: file, options });
    if (typeof values.out === 'string') await writeFile(values.out, text);
    else io.stdout.write(text);

    const { stats } = result;
    const tty = io.stderr.isTTY === true;
    const name = path.basename(file);
    if (stats.packed === 0) io.stderr.write(`cscd: warning: ${file}: no separator was kept: the skeleton is one node per connected component\n`);
    if (tty || values.verbose === true) {
      const nodes = result.nodes.length / 3;
      const edges = result.edges.length / 2;
      io.stderr.write(`cscd: skeleton of ${name}: ${nodes} nodes, ${edges} edges, ${stats.cycles} cycles, `
        + `N = ${stats.n} (${stats.packed} of ${stats.candidates} separators kept), ${seconds.toFixed(1)} s\n`);
    }
  },
};

/** Stage 1 with its progress line, then stage 2. */
async function runPipeline(pipeline: Pipeline, workers: Parameters<typeof runStage1>[1], options: ShapeOptions, file: string, io: CliIo, progress: ProgressLine): Promise<Skeleton> {
  const name = path.basename(file);
  const tty = io.stderr.isTTY === true;
  try {
    const report = (step: PipelineProgress) => {
      if (tty) progress.update(`cscd: skeleton of ${name}: stage 1, source ${step.done} of ${options.n === 'auto' ? `at most ${step.total}` : step.total}`);
    };
    await runStage1(pipeline, workers, {
      progress: report,
      lost: (_, error) => io.stderr.write(`cscd: warning: a worker thread failed (${error instanceof Error ? error.message : String(error)}); the others go on\n`),
    });
    if (tty) progress.update(`cscd: skeleton of ${name}: stage 2`, true);
    return pipeline.finish();
  } finally {
    pipeline.dispose();
  }
}

async function meshSkeleton(mesh: InputMesh, options: Options, settings: RunSettings, file: string, io: CliIo, progress: ProgressLine): Promise<Skeleton> {
  const workers = threadsFor(settings, options, mesh.positions.length / 3);
  return onPool(workers > 1 ? openNodePool((await getCore()).stage1Input(mesh, options), options, { workers }) : null, () => openSolver(mesh, file, io), options, file, io, progress);
}

async function cloudSkeleton(shape: InputCloud, options: CloudOptions, settings: RunSettings, file: string, io: CliIo, progress: ProgressLine): Promise<Skeleton> {
  const workers = threadsFor(settings, options, CLOUD_VERTICES_PER_POINT * (shape.positions.length / 3));
  return onPool(workers > 1 ? openNodeCloudPool(shape, options, { workers }) : null, () => openCloud(shape, options, file, io), options, file, io, progress);
}

/** Opens the shape here while the pool's threads open it too, then runs the pipeline on them. */
async function onPool(
  opening: Promise<NodePool> | null,
  open: () => Promise<{ pipeline(options: ShapeOptions): Pipeline; dispose(): void }>,
  options: ShapeOptions,
  file: string,
  io: CliIo,
  progress: ProgressLine,
): Promise<Skeleton> {
  const shape = await open().catch(async (error) => {
    await opening?.then((pool) => pool.close(), () => undefined);
    throw error;
  });
  const pool = await opening?.catch((error) => {
    shape.dispose();
    throw error;
  });
  try {
    return await runPipeline(shape.pipeline(options), pool?.workers ?? [], options, file, io, progress);
  } finally {
    await pool?.close();
    shape.dispose();
  }
}
