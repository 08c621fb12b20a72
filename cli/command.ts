/** What every CLI command shares: its description for help and parsing, errors, mesh and point-cloud input. */
import { readFile } from 'node:fs/promises';
import { loadCoreNode } from '../lib/core/node.ts';
import { AS_CLOUD, meshAsCloud } from '../lib/cloud/from-mesh.ts';
import { scanLineWarning } from '../lib/cloud/scan-lines.ts';
import { subsample } from '../lib/cloud/subsample.ts';
import { defaultOptions } from '../lib/core/options.ts';
import type { Cloud, CloudArrays, CloudOptions, Core, MeshArrays, RefinedSurface } from '../lib/core/types.ts';
import { checkCloud } from '../lib/io/cloud-check.ts';
import { parseMesh, parseShape, type ParsedCloud, type ParsedMesh } from '../lib/io/index.ts';
import type { ShapeFormat } from '../lib/io/types.ts';
import { repairMesh } from '../lib/io/repair.ts';
import { decimate } from '../lib/mesh/decimate.ts';
import { cloudSizeWarning, DECIMATE_TARGET, FACE_LIMIT, POINT_LIMIT, SUBSAMPLE_TARGET, sizeWarning } from '../lib/mesh/limits.ts';

export interface OptionSpec {
  type: 'string' | 'boolean';
  short?: string;
  /** Placeholder of a string option's value in help, e.g. "V" in "--source V". */
  value?: string;
  required?: boolean;
  description: string;
}

/** A text stream: the process's stdout or stderr, or a string collector in tests. */
export interface Output {
  write(text: string): unknown;
  /** On stderr: a terminal, which gets the skeleton's progress line and summary. */
  isTTY?: boolean;
}

/** Where a command writes: all of its output goes through these, never to `process` directly. */
export interface CliIo {
  stdout: Output;
  stderr: Output;
}

/** Option values as node:util parseArgs returns them. */
export type OptionValues = Record<string, string | boolean | (string | boolean)[] | undefined>;

export interface Command {
  name: string;
  /** One line for the command list. */
  summary: string;
  /** Placeholders of the positional arguments, e.g. ["<mesh>"]. */
  args: string[];
  options: Record<string, OptionSpec>;
  /** More text for `cscd help <command>`. */
  details?: string;
  run(args: string[], options: OptionValues, io: CliIo): Promise<void>;
}

/** A mistake in the command line: reported with exit code 2. */
export class UsageError extends Error {
  override name = 'UsageError';
}

let core: Promise<Core> | undefined;

/**
 * The WASM core, loaded on first use (help and usage errors never pay for it) and shared by every
 * command run in the process.
 */
export function getCore(): Promise<Core> {
  core ??= loadCoreNode();
  return core;
}

/** Forgets the shared core, so that the next getCore() loads a fresh one. */
export function discardCore(): void {
  core = undefined;
}

/** A file's bytes, or an error that says in plain words why it cannot be read. */
export async function readBytes(file: string): Promise<Uint8Array> {
  try {
    return await readFile(file);
  } catch (error) {
    const code = (error as NodeJS.ErrnoException).code;
    const reason = code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'it is a directory' : (error as Error).message;
    throw new Error(`cannot read '${file}': ${reason}`);
  }
}

/** A mesh file as every command works on it: parsed, then repaired (lib/io/repair.ts). */
export interface InputMesh extends ParsedMesh {
  /** What the repair did, one sentence each; empty when the mesh is as in the file. */
  repairs: string[];
  /** Index of every vertex of the file in the repaired mesh, -1 for removed ones. */
  vertexMap: Int32Array;
}

/**
 * A point-cloud file as every command works on it: parsed, then checked (lib/io/cloud-check.ts); or a
 * mesh file run as a cloud of its vertices (--as-cloud), repaired first, its format the mesh file's.
 */
export interface InputCloud extends Omit<ParsedCloud, 'format'> {
  format: ShapeFormat;
  /** What the checks (and a mesh's repairs) did, one sentence each; empty when the cloud is as in the file. */
  repairs: string[];
  /**
   * Index of every point (or vertex) of the file in the checked cloud, -1 for removed ones; after
   * --subsample, in the subsample (a point left out: the kept point that stands for it).
   */
  pointMap: Int32Array;
  /** The point count before --subsample, or null (not asked, or no more points than asked for). */
  subsampledFrom: number | null;
}

interface ReadSettings {
  /** Parser warnings and repairs go to stderr unless the command reports them itself. */
  printWarnings?: boolean;
  /** A mesh file is run as a point cloud of its vertices (--as-cloud). */
  asCloud?: boolean;
  /** A cloud is computed on about this many of its points (--subsample K). */
  subsample?: number;
}

/** --as-cloud, for every command that reads a mesh or a cloud (the page's `asCloud` box). */
export const asCloudOption: OptionSpec = { type: 'boolean', description: AS_CLOUD.help };

/** The read settings of a command line: --as-cloud given or not. */
export const asCloudFlag = (values: OptionValues): boolean => values[AS_CLOUD.flag] === true;

/** --subsample K, for every command that opens a cloud (the page's subsample of a cloud above the point limit). */
export const subsampleOption: OptionSpec = {
  type: 'string',
  value: 'K',
  description: `compute on about K of the cloud's points (Poisson-disk, seed ${defaultOptions.seed}, as the page subsamples); advised above ${POINT_LIMIT} points`,
};

/** --subsample K as a point count (more than `neighbours`), or undefined when not given. */
export function subsampleFlag(values: OptionValues, neighbours: number): number | undefined {
  if (values.subsample === undefined) return undefined;
  const target = Number(values.subsample);
  if (!Number.isInteger(target) || target <= neighbours) {
    throw new UsageError(`--subsample must be a whole number of points above the ${neighbours} neighbours, got '${String(values.subsample)}'`);
  }
  return target;
}

function reportInput(file: string, warnings: string[], repairs: string[], io: CliIo, { printWarnings = true }: ReadSettings): void {
  if (!printWarnings) return;
  for (const warning of warnings) io.stderr.write(`cscd: warning: ${file}: ${warning}\n`);
  for (const repair of repairs) io.stderr.write(`cscd: repaired: ${repair}\n`);
}

function inputMesh(parsed: ParsedMesh, file: string, io: CliIo, settings: ReadSettings): InputMesh {
  const { mesh, repairs, vertexMap } = repairMesh(parsed);
  reportInput(file, parsed.warnings, repairs, io, settings);
  return { ...parsed, ...mesh, repairs, vertexMap };
}

/** Reads, parses and repairs a mesh file (a point cloud is refused, saying so). */
export async function readMesh(file: string, io: CliIo, settings: ReadSettings = {}): Promise<InputMesh> {
  return inputMesh(parseMesh(await readBytes(file), file), file, io, settings);
}

/**
 * Reads a mesh or a point-cloud file, as the file turns out to hold: a mesh parsed and repaired as
 * readMesh does, a cloud parsed and checked for `neighbours` neighbours per point.
 */
export async function readShape(file: string, io: CliIo, neighbours: number, settings: ReadSettings = {}): Promise<InputMesh | InputCloud> {
  const parsed = parseShape(await readBytes(file), file);
  if (parsed.kind === 'mesh' && !settings.asCloud) return inputMesh(parsed, file, io, settings);
  if (parsed.kind === 'mesh') return meshCloud(parsed, file, io, neighbours, settings);
  if (settings.asCloud) throw new UsageError(`--${AS_CLOUD.flag} does not apply to ${file}: it is a point cloud already`);
  const { cloud, repairs, pointMap } = checkCloud(parsed, neighbours);
  reportInput(file, parsed.warnings, repairs, io, settings);
  return subsampled({ ...cloud, repairs, pointMap, subsampledFrom: null }, file, io, settings);
}

/**
 * The checked cloud, or about `settings.subsample` of its points when it has more (said on stderr): the
 * page's subsample (lib/cloud/subsample.ts), with the same seed; the file's points map to the kept ones.
 */
function subsampled(cloud: InputCloud, file: string, io: CliIo, { subsample: target }: ReadSettings): InputCloud {
  const points = cloud.positions.length / 3;
  if (target === undefined || points <= target) return cloud;
  const started = performance.now();
  const { cloud: kept, pointOf } = subsample(cloud, target, defaultOptions.seed);
  const pointMap = cloud.pointMap.map((point) => (point < 0 ? -1 : pointOf[point]));
  const seconds = ((performance.now() - started) / 1000).toFixed(1);
  io.stderr.write(`cscd: subsampled ${file} from ${points} to ${kept.positions.length / 3} points (Poisson-disk, seed ${defaultOptions.seed}) in ${seconds} s\n`);
  return { ...kept, pointMap, subsampledFrom: points };
}

/** A mesh file's vertices as a cloud (--as-cloud): repaired as a mesh, then checked as a cloud; the file's vertex indices map to its points. */
function meshCloud(parsed: ParsedMesh, file: string, io: CliIo, neighbours: number, settings: ReadSettings): InputCloud {
  const mesh = inputMesh(parsed, file, io, { printWarnings: false });
  const { cloud: vertices, pointOfVertex, note } = meshAsCloud(mesh);
  const { cloud, repairs, pointMap: checkedPoint } = checkCloud(vertices, neighbours, { outliers: false });
  const warnings = [...parsed.warnings, note], allRepairs = [...mesh.repairs, ...repairs];
  reportInput(file, warnings, allRepairs, io, settings);
  const pointMap = mesh.vertexMap.map((v) => (v < 0 || pointOfVertex[v] < 0 ? -1 : checkedPoint[pointOfVertex[v]]));
  return subsampled({ kind: 'cloud', format: parsed.format, ...cloud, warnings, repairs: allRepairs, pointMap, subsampledFrom: null }, file, io, settings);
}

/** Refuses flags that do nothing for this kind of shape (--decimate on a cloud, --neighbours on a mesh). */
export function refuseFlags(values: OptionValues, flags: string[], file: string, shape: 'mesh' | 'point cloud'): void {
  const given = flags.find((flag) => values[flag] !== undefined);
  if (given !== undefined) throw new UsageError(`--${given} does not apply to ${file}: it is a ${shape}`);
}

/** --decimate K, for the commands that take it (the page's "Decimate to K faces"). */
export const decimateOption: OptionSpec = {
  type: 'string',
  value: 'K',
  description: `decimate the mesh to about K faces first (quadric edge collapse; genus, components and holes kept); advised above ${FACE_LIMIT} faces`,
};

/**
 * The mesh decimated to `--decimate K` faces when it has more (said on stderr), else as it is;
 * `decimatedFrom` is the face count before, or null.
 */
export function decimateIfAsked<M extends MeshArrays>(mesh: M, values: OptionValues, file: string, io: CliIo): M & { decimatedFrom: number | null } {
  if (values.decimate === undefined) return { ...mesh, decimatedFrom: null };
  const target = Number(values.decimate);
  if (!Number.isInteger(target) || target < 4) throw new UsageError(`--decimate must be a whole number of faces (at least 4), got '${String(values.decimate)}'`);
  const faces = mesh.triangles.length / 3;
  if (faces <= target) return { ...mesh, decimatedFrom: null };
  const started = performance.now();
  const decimated = decimate(mesh, target);
  const seconds = ((performance.now() - started) / 1000).toFixed(1);
  io.stderr.write(`cscd: decimated ${file} from ${faces} to ${decimated.triangles.length / 3} faces in ${seconds} s\n`);
  return { ...mesh, ...decimated, decimatedFrom: faces };
}

/**
 * Opens a point cloud in the core, first warning on stderr when it is above the size limit (lib/mesh/limits.ts),
 * then when its neighbourhoods are scan lines (lib/cloud/scan-lines.ts).
 */
export async function openCloud(cloud: CloudArrays, options: CloudOptions, file: string, io: CliIo): Promise<Cloud> {
  const warning = cloudSizeWarning(cloud.positions.length / 3);
  if (warning) io.stderr.write(`cscd: warning: ${file}: ${warning} (--subsample ${SUBSAMPLE_TARGET})\n`);
  const opened = (await getCore()).openCloud(cloud, options);
  const scanLines = scanLineWarning(opened.facts);
  if (scanLines) io.stderr.write(`cscd: warning: ${file}: ${scanLines}\n`);
  return opened;
}

/**
 * Opens the geodesic solver, on the mesh refined when it is coarse (lib/mesh/refine.ts; said on
 * stderr, results stay per vertex of `mesh`), first warning on stderr when the mesh is above the size
 * limit (lib/mesh/limits.ts).
 */
export async function openSolver(mesh: MeshArrays, file: string, io: CliIo): Promise<RefinedSurface> {
  const warning = sizeWarning(mesh.triangles.length / 3, mesh.positions.length / 3);
  if (warning) io.stderr.write(`cscd: warning: ${file}: ${warning} (--decimate ${DECIMATE_TARGET} makes it faster)\n`);
  const surface = (await getCore()).openRefinedSurface(mesh);
  const { refined } = surface;
  if (refined) io.stderr.write(`cscd: refined ${file} for computation from ${refined.fromFaces} to ${refined.toFaces} faces (the same surface, sampled more densely)\n`);
  return surface;
}
