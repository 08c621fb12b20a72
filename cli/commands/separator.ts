import { writeFile } from 'node:fs/promises';
import {
  CLOUD_OPTIONS,
  cliFlag,
  defaultCloudOptions,
  defaultOptions,
  defaultRunSettings,
  MESH_OPTIONS,
  NUMBER_TEXT,
  OPTIONS,
  optionProblem,
  parseSpecText,
  SETTINGS,
  type OptionSpec,
  type RunSettings,
  type SettingSpec,
} from '../../lib/core/options.ts';
import { random } from '../../lib/core/random.ts';
import type { CloudOptions, CloudSeparatorStages, MeshArrays, Options, Polyline, Refinement, Separator } from '../../lib/core/types.ts';
import { AS_CLOUD } from '../../lib/cloud/from-mesh.ts';
import {
  UsageError, asCloudFlag, asCloudOption, openCloud, openSolver, readShape, refuseFlags, subsampleFlag, subsampleOption,
  type CliIo, type Command, type InputCloud, type InputMesh, type OptionSpec as CliOptionSpec, type OptionValues,
} from '../command.ts';

export type Point = [number, number, number];

/**
 * The JSON written by `cscd separator` (and checked by scripts/check-separators.ts): the Separator
 * record with its arrays as JSON arrays (points as xyz triples), plus the options it was run with.
 */
export type SeparatorJson = Omit<
  Separator,
  'attempts' | 'distance' | 'cutLocus' | 'boundaryExtremities' | 'target' | 'targetPoint' | 'ends' | 'endPoints' | 'paths' | 'approxLoop' | 'loop' | 'refined'
> & {
  distance: number[];
  cutLocus: { points: Point[]; edges: [number, number][]; vertices: number[]; root: number; cycleRank: number };
  boundaryExtremities: Point[];
  target: Point | null;
  /** The two boundary points an open separator (closed: false) runs between; null for a loop. */
  ends: [Point, Point] | null;
  paths: [Point[], Point[]];
  approxLoop: Point[];
  loop: Point[];
  options: Options;
  /** How a coarse mesh was refined to compute on (lib/mesh/refine.ts), or null; vertex indices >= the mesh's count are new vertices. */
  refined: Refinement | null;
};

function flagSpec(spec: OptionSpec | SettingSpec): CliOptionSpec {
  if (spec.kind === 'switch') return { type: 'boolean', description: spec.default ? `do not ${spec.help}` : spec.help };
  const value = spec.kind === 'choice' ? Object.keys(spec.choices).join('|') : spec.placeholder;
  return { type: 'string', value, description: `${spec.help} (default ${String(spec.default)})` };
}

/** An option's or run setting's value from its flag; a usage error names the flag and what it accepts. */
function parseFlag(spec: OptionSpec | SettingSpec, given: string | boolean, flag: string): unknown {
  if (spec.kind === 'switch') return spec.default ? !given : Boolean(given);
  const text = String(given);
  const parsed = parseSpecText(spec, text);
  if (parsed !== null) return parsed;
  const notANumber = spec.kind === 'number' && !NUMBER_TEXT.test(text);
  throw new UsageError(`--${flag} ${notANumber ? 'must be a number' : optionProblem(spec, NaN)}, got '${text}'`);
}

/** The flags of these options as parseArgs specs. */
function flagSpecsOf(specs: readonly OptionSpec[]): Record<string, CliOptionSpec> {
  return Object.fromEntries(specs.map((o) => [cliFlag(o), flagSpec(o)]));
}

/**
 * The mesh option flags as parseArgs specs (lib/core/options.ts), e.g. for scripts that take the same
 * options as the command; with `pipeline: false`, only those of `cscd separator`.
 */
export function optionFlagSpecs({ pipeline = true } = {}): Record<string, CliOptionSpec> {
  return flagSpecsOf(MESH_OPTIONS.filter((o) => pipeline || o.commands === 'all'));
}

/** The point-cloud-only option flags (`--neighbours`), for the commands that open a cloud. */
export function cloudFlagSpecs(): Record<string, CliOptionSpec> {
  return flagSpecsOf(OPTIONS.filter((o) => o.shapes === 'cloud'));
}

/** The flags that apply to point clouds only (those options and `--subsample`): given with a mesh, a usage error. */
export function cloudOnlyFlags(): string[] {
  return [...Object.keys(cloudFlagSpecs()), 'subsample'];
}

/** `defaults`, overridden by the flags that were given of these options. */
function valuesFromFlags(specs: readonly OptionSpec[], defaults: object, values: OptionValues): Record<string, unknown> {
  const options: Record<string, unknown> = { ...defaults };
  for (const spec of specs) {
    const flag = cliFlag(spec);
    const value = values[flag];
    if (value !== undefined && !Array.isArray(value)) options[spec.key] = parseFlag(spec, value, flag);
  }
  return options;
}

/** The full Options of a command line on a mesh: defaults, overridden by the flags that were given. */
export function optionsFromFlags(values: OptionValues): Options {
  return valuesFromFlags(MESH_OPTIONS, defaultOptions, values) as unknown as Options;
}

/** The full CloudOptions of a command line on a point cloud: defaults, overridden by the flags that were given. */
export function cloudOptionsFromFlags(values: OptionValues): CloudOptions {
  return valuesFromFlags(CLOUD_OPTIONS, defaultCloudOptions, values) as unknown as CloudOptions;
}

/** The run settings' flags (`--workers`), for the commands that can run stage 1 on a pool. */
export function settingFlagSpecs(): Record<string, CliOptionSpec> {
  return Object.fromEntries(SETTINGS.map((s) => [s.flag, flagSpec(s)]));
}

/** The run settings of a command line: defaults, overridden by the flags that were given. */
export function settingsFromFlags(values: OptionValues): RunSettings {
  const settings: Record<string, unknown> = { ...defaultRunSettings };
  for (const spec of SETTINGS) {
    const value = values[spec.flag];
    if (value !== undefined && !Array.isArray(value)) settings[spec.key] = parseFlag(spec, value, spec.flag);
  }
  return settings as unknown as RunSettings;
}

/**
 * `count` distinct source vertices drawn with the seed among the vertices used by a face (fewer if
 * the mesh has fewer). The first one is the source `cscd separator` takes when --source is not given,
 * so a source reported by scripts/check-separators.ts with the same seed can be rerun alone.
 */
export function randomSources(mesh: MeshArrays, seed: number, count: number): number[] {
  const used = new Uint8Array(mesh.positions.length / 3);
  for (const vertex of mesh.triangles) used[vertex] = 1;
  const candidates: number[] = [];
  used.forEach((flag, vertex) => flag && candidates.push(vertex));
  const next = random(seed);
  const n = Math.min(count, candidates.length);
  // Partial Fisher-Yates shuffle.
  for (let i = 0; i < n; i++) {
    const j = i + Math.floor(next() * (candidates.length - i));
    [candidates[i], candidates[j]] = [candidates[j], candidates[i]];
  }
  return candidates.slice(0, n);
}

/** xyz triples as [[x,y,z], ...]. */
function toPoints(polyline: Polyline): Point[] {
  const points: Point[] = [];
  for (let i = 0; i + 2 < polyline.length; i += 3) points.push([polyline[i], polyline[i + 1], polyline[i + 2]]);
  return points;
}

/** The fields a mesh's and a cloud's separator share, up to the cut locus, as plain JSON data. */
function stagesJson(result: Pick<Separator, 'source' | 'status' | 'message' | 'distance' | 'cutLocus'>) {
  const edges: [number, number][] = [];
  for (let i = 0; i + 1 < result.cutLocus.edges.length; i += 2) edges.push([result.cutLocus.edges[i], result.cutLocus.edges[i + 1]]);
  return {
    source: result.source,
    status: result.status,
    message: result.message,
    distance: Array.from(result.distance),
    cutLocus: {
      points: toPoints(result.cutLocus.points),
      edges,
      vertices: Array.from(result.cutLocus.vertices),
      root: result.cutLocus.root,
      cycleRank: result.cutLocus.cycleRank,
    },
  };
}

/** The core's result as plain JSON data (typed arrays become arrays, polylines lists of points). */
export function separatorJson(result: Separator, options: Options): SeparatorJson {
  return {
    ...stagesJson(result),
    boundaryExtremities: toPoints(result.boundaryExtremities.points),
    target: result.targetPoint ? [...result.targetPoint] : null,
    ends: result.endPoints ? (toPoints(result.endPoints) as [Point, Point]) : null,
    closed: result.closed,
    paths: [toPoints(result.paths[0]), toPoints(result.paths[1])],
    approxLoop: toPoints(result.approxLoop),
    loop: toPoints(result.loop),
    sphere: result.sphere ? { center: [...result.sphere.center], radius: result.sphere.radius } : null,
    approxLength: result.approxLength,
    length: result.length,
    areas: [result.areas[0], result.areas[1]],
    score: result.score,
    centroidInside: result.centroidInside,
    timings: { ...result.timings },
    options,
    refined: result.refined ?? null,
  };
}

/** The JSON of `cscd separator` on a point cloud: the stages by point index and position. */
export function cloudSeparatorJson(result: CloudSeparatorStages, options: CloudOptions) {
  return {
    ...stagesJson(result),
    target: result.targetPoint ? [...result.targetPoint] : null,
    closed: true,
    paths: [toPoints(result.paths[0]), toPoints(result.paths[1])],
    approxLoop: toPoints(result.approxLoop),
    loop: toPoints(result.loop),
    sphere: result.sphere ? { center: [...result.sphere.center], radius: result.sphere.radius } : null,
    length: result.length,
    areas: [result.areas[0], result.areas[1]],
    score: result.score,
    centroidInside: result.centroidInside,
    iterations: result.iterations,
    timings: { ...result.timings },
    options,
  };
}

export const separator: Command = {
  name: 'separator',
  summary: 'stage 1 of CSCD: one local separator (a shortened loop) from a source vertex or point, as JSON',
  args: ['<mesh|cloud>'],
  options: {
    source: { type: 'string', value: 'V', description: 'source vertex (or point) index (0-based; default: one drawn with the seed)' },
    ...optionFlagSpecs({ pipeline: false }),
    ...cloudFlagSpecs(),
    [AS_CLOUD.flag]: asCloudOption,
    subsample: subsampleOption,
    out: { type: 'string', value: 'FILE', description: 'write the JSON to FILE instead of stdout' },
  },
  details: [
    'Writes {source, status, message, distance, cutLocus, boundaryExtremities, target, ends, closed, paths, approxLoop, loop, sphere,',
    'approxLength, length, areas, score, centroidInside, timings, options, refined} (see docs/cli.md). A source',
    'without a separator is not an error: status tells why, with a warning on stderr and exit code 0. On a point',
    'cloud: the same keys less boundaryExtremities, ends, approxLength and refined, plus iterations (docs/cli.md).',
  ].join('\n'),
  async run([file], values, io) {
    const cloudOptions = cloudOptionsFromFlags(values);
    const shape = await readShape(file, io, cloudOptions.neighbours, { asCloud: asCloudFlag(values), subsample: subsampleFlag(values, cloudOptions.neighbours) });
    const json = shape.kind === 'cloud'
      ? await cloudSeparator(shape, cloudOptions, values, file, io)
      : await meshSeparator(shape, values, file, io);
    const text = `${JSON.stringify(json)}\n`;
    if (typeof values.out === 'string') await writeFile(values.out, text);
    else io.stdout.write(text);
    if (json.status !== 'ok') {
      const reason = json.message.split('\n')[0];
      io.stderr.write(`cscd: warning: ${file}: no separator from source ${json.source}: ${json.status}${reason ? ` (${reason})` : ''}\n`);
    }
  },
};

/** --source (an index below `count`), else the one `drawn` with the seed. */
function sourceOf(values: OptionValues, count: number, element: 'vertex' | 'point', drawn: () => number | undefined): number {
  if (typeof values.source !== 'string') return drawn() ?? NaN;
  const source = /^\d+$/.test(values.source) ? Number(values.source) : NaN;
  if (!(source < count)) throw new UsageError(`--source must be a ${element} index from 0 to ${count - 1}, got '${values.source}'`);
  return source;
}

async function meshSeparator(mesh: InputMesh, values: OptionValues, file: string, io: CliIo): Promise<SeparatorJson> {
  refuseFlags(values, cloudOnlyFlags(), file, 'mesh');
  const options = optionsFromFlags(values);
  const source = sourceOf(values, mesh.positions.length / 3, 'vertex', () => randomSources(mesh, options.seed, 1)[0]);
  if (Number.isNaN(source)) throw new UsageError(`${file}: no vertex to draw a source from (the mesh has no faces)`);
  const surface = await openSolver(mesh, file, io);
  try {
    return separatorJson(surface.separator(source, options), options);
  } finally {
    surface.dispose();
  }
}

async function cloudSeparator(shape: InputCloud, options: CloudOptions, values: OptionValues, file: string, io: CliIo) {
  const count = shape.positions.length / 3;
  // Indices are those of the cloud after its checks (as `cscd skeleton`'s vertexToNode).
  const source = sourceOf(values, count, 'point', () => Math.floor(random(options.seed)() * count));
  const cloud = await openCloud(shape, options, file, io);
  try {
    return cloudSeparatorJson(cloud.separatorStages(source, options), options);
  } finally {
    cloud.dispose();
  }
}
