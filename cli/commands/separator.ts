import { writeFile } from 'node:fs/promises';
import { defaultOptions, optionRanges } from '../../lib/core/options.ts';
import { random } from '../../lib/core/random.ts';
import type { MeshArrays, Options, Polyline, Refinement, Separator } from '../../lib/core/types.ts';
import { UsageError, openSolver, readMesh, type Command, type OptionSpec, type OptionValues } from '../command.ts';

export type Point = [number, number, number];

/** The JSON written by `cscd separator` (and checked by scripts/check-separators.ts). */
export interface SeparatorJson {
  source: number;
  status: Separator['status'];
  message: string;
  distance: number[];
  cutLocus: { points: Point[]; edges: [number, number][]; vertices: number[]; root: number; cycleRank: number };
  boundaryExtremities: Point[];
  target: Point | null;
  /** The two boundary points an open separator (closed: false) runs between; null for a loop. */
  ends: [Point, Point] | null;
  closed: boolean;
  paths: [Point[], Point[]];
  approxLoop: Point[];
  loop: Point[];
  sphere: { center: Point; radius: number } | null;
  approxLength: number;
  length: number;
  areas: [number, number];
  score: number;
  centroidInside: boolean;
  timings: Record<string, number>;
  options: Options;
  /** How a coarse mesh was refined to compute on (lib/mesh/refine.ts), or null; vertex indices >= the mesh's count are new vertices. */
  refined: Refinement | null;
}

/** Every value of Options['target'] (the Record makes the compiler check that none is missing). */
const TARGETS: Record<Options['target'], string> = {
  euclid: 'in space',
  geodesic: 'along the surface',
};

interface OptionFlag<K extends keyof Options> {
  /** The kebab-case of the field name; a boolean that is on by default is switched off by --no-NAME. */
  flag: string;
  /** Only the pipeline (stage 2) uses the option: `cscd separator` does not take its flag. */
  pipelineOnly?: true;
  spec: OptionSpec;
  parse(value: string | boolean, flag: string): Options[K];
}

/**
 * The CLI flag of every field of Options (the mapped type makes the compiler check that none is missing).
 * Ranges are those the core accepts (`optionRanges`), so that a value out of range is a usage error
 * here rather than a core error.
 */
const OPTION_FLAGS: { [K in keyof Options]: OptionFlag<K> } = {
  target: {
    flag: 'target',
    spec: { type: 'string', value: Object.keys(TARGETS).join('|'), description: `target: the cut-locus point nearest the source ${describeTargets()} (default ${defaultOptions.target})` },
    parse(value, flag) {
      if (typeof value === 'string' && Object.hasOwn(TARGETS, value)) return value as Options['target'];
      throw new UsageError(`--${flag} must be one of ${Object.keys(TARGETS).join(', ')}, got '${String(value)}'`);
    },
  },
  sphere: {
    flag: 'no-sphere',
    spec: { type: 'boolean', description: 'do not keep the shortened loop inside a sphere around the source' },
    parse: (value) => !value,
  },
  seed: {
    flag: 'seed',
    spec: { type: 'string', value: 'S', description: `seed of every random choice: the sources drawn (0 to 2^32-1, default ${defaultOptions.seed})` },
    parse: (value, flag) => parseInteger(value, flag, optionRanges.seed[1]),
  },
  angleThreshold: {
    flag: 'angle-threshold',
    spec: { type: 'string', value: 'X', description: `cut locus: minimum turn of the distance gradient at a ridge, radians in [0, pi] (default ${defaultOptions.angleThreshold})` },
    parse(value, flag) {
      const angle = parseNumber(value, flag);
      const [low, high] = optionRanges.angleThreshold;
      if (angle < low || angle > high) throw new UsageError(`--${flag} must be an angle in radians from 0 to pi, got '${String(value)}'`);
      return angle;
    },
  },
  laplacianThreshold: {
    flag: 'laplacian-threshold',
    spec: { type: 'string', value: 'X', description: `cut locus: minimum ridge sharpness, scale-free, >= 0 (default ${defaultOptions.laplacianThreshold})` },
    parse(value, flag) {
      const threshold = parseNumber(value, flag);
      const [low, high] = optionRanges.laplacianThreshold;
      if (threshold < low || threshold > high) throw new UsageError(`--${flag} must be a number from ${low} to ${high}, got '${String(value)}'`);
      return threshold;
    },
  },
  pruneDepth: {
    flag: 'prune-depth',
    spec: { type: 'string', value: 'N', description: `cut locus: prune leaf branches with fewer edges than N (default ${defaultOptions.pruneDepth})` },
    parse: (value, flag) => parseInteger(value, flag, optionRanges.pruneDepth[1]),
  },
  n: {
    flag: 'n',
    pipelineOnly: true,
    spec: { type: 'string', value: 'N|auto', description: `number of sources (separators tried), or auto: draw sources until new separators stop adding coverage (default ${defaultOptions.n})` },
    parse(value, flag) {
      if (value === 'auto') return 'auto';
      const [low, high] = optionRanges.n;
      const text = String(value);
      const n = /^\d+$/.test(text) ? Number(text) : NaN;
      if (!(n >= low && n <= high)) throw new UsageError(`--${flag} must be auto or an integer from ${low} to ${high}, got '${text}'`);
      return n;
    },
  },
  pruneLengthFactor: {
    flag: 'prune-length-factor',
    pipelineOnly: true,
    spec: { type: 'string', value: 'X', description: `prune loops shorter than X mean edge lengths: they enclose no feature (default ${defaultOptions.pruneLengthFactor})` },
    parse(value, flag) {
      const factor = parseNumber(value, flag);
      const [low, high] = optionRanges.pruneLengthFactor;
      if (factor < low || factor > high) throw new UsageError(`--${flag} must be a number from ${low} to ${high}, got '${String(value)}'`);
      return factor;
    },
  },
};

/**
 * The option flags as parseArgs specs, e.g. for scripts that take the same options as the command;
 * with `pipeline: false`, only those of stage 1 (what `cscd separator` takes).
 */
export function optionFlagSpecs({ pipeline = true } = {}): Record<string, OptionSpec> {
  const flags: OptionFlag<keyof Options>[] = Object.values(OPTION_FLAGS);
  return Object.fromEntries(flags.filter((f) => pipeline || !f.pipelineOnly).map(({ flag, spec }) => [flag, spec]));
}

function describeTargets(): string {
  return Object.entries(TARGETS).map(([name, text]) => `${text} (${name})`).join(' or ');
}

function parseNumber(value: string | boolean, flag: string): number {
  const text = String(value);
  if (!/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(text) || !Number.isFinite(Number(text))) {
    throw new UsageError(`--${flag} must be a number, got '${text}'`);
  }
  return Number(text);
}

function parseInteger(value: string | boolean, flag: string, max: number): number {
  const text = String(value);
  const number = /^\d+$/.test(text) ? Number(text) : NaN;
  if (!(number <= max)) throw new UsageError(`--${flag} must be an integer from 0 to ${max}, got '${text}'`);
  return number;
}

/** The full Options of a command line: defaults, overridden by the flags that were given. */
export function optionsFromFlags(values: OptionValues): Options {
  const options: Options = { ...defaultOptions };
  const set = <K extends keyof Options>(key: K, { flag, parse }: OptionFlag<K>) => {
    const value = values[flag];
    if (value !== undefined && !Array.isArray(value)) options[key] = parse(value, flag);
  };
  for (const key of Object.keys(OPTION_FLAGS) as (keyof Options)[]) set(key, OPTION_FLAGS[key] as OptionFlag<typeof key>);
  return options;
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

/** The core's result as plain JSON data (typed arrays become arrays, polylines lists of points). */
export function separatorJson(result: Separator, options: Options): SeparatorJson {
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

export const separator: Command = {
  name: 'separator',
  summary: 'stage 1 of CSCD-M: one local separator (a shortened loop) from a source vertex, as JSON',
  args: ['<mesh>'],
  options: {
    source: { type: 'string', value: 'V', description: 'source vertex index (0-based; default: a vertex drawn with the seed)' },
    ...optionFlagSpecs({ pipeline: false }),
    out: { type: 'string', value: 'FILE', description: 'write the JSON to FILE instead of stdout' },
  },
  details: [
    'Writes {source, status, message, distance, cutLocus, boundaryExtremities, target, ends, closed, paths, approxLoop, loop, sphere,',
    'approxLength, length, areas, score, centroidInside, timings, options, refined} (see docs/cli.md). A source',
    'without a separator is not an error: status tells why, with a warning on stderr and exit code 0.',
  ].join('\n'),
  async run([file], values) {
    const options = optionsFromFlags(values);
    const mesh = await readMesh(file);
    const vertexCount = mesh.positions.length / 3;
    let source: number;
    if (typeof values.source === 'string') {
      source = /^\d+$/.test(values.source) ? Number(values.source) : NaN;
      if (!(source < vertexCount)) throw new UsageError(`--source must be a vertex index from 0 to ${vertexCount - 1}, got '${values.source}'`);
    } else {
      [source] = randomSources(mesh, options.seed, 1);
      if (source === undefined) throw new UsageError(`${file}: no vertex to draw a source from (the mesh has no faces)`);
    }
    const surface = await openSolver(mesh, file);
    let json: SeparatorJson;
    try {
      json = separatorJson(surface.separator(source, options), options);
    } finally {
      surface.dispose();
    }
    const text = `${JSON.stringify(json)}\n`;
    if (typeof values.out === 'string') await writeFile(values.out, text);
    else process.stdout.write(text);
    if (json.status !== 'ok') {
      const reason = json.message.split('\n')[0];
      process.stderr.write(`cscd: warning: ${file}: no separator from source ${source}: ${json.status}${reason ? ` (${reason})` : ''}\n`);
    }
  },
};
