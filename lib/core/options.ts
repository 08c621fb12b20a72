/**
 * Every option, declared once: name, kind, default, accepted range, stage, CLI flag and help. The CLI
 * flags (cli/commands/separator.ts), the parameter panel (web/src/ui/params.ts), the address-bar state
 * (web/src/ui/url-state.ts) and the option tables of the README and docs/cli.md (`optionTable`, checked
 * by tests/unit/options.test.ts) are derived from it; the core declares the same defaults and ranges in
 * C++ (wasm/src/cscd/options.h), and the same test holds the two to each other through the bindings.
 */
import type { CloudOptions, Options } from './types.ts';

/** Auto mode of `n` (wasm/src/cscd/pipeline.h): sampling stops when this share of the surface is near
 * a source or a separator, or when the last `window` sources added less than `minGain`; never past `max`. */
export const AUTO_N = Object.freeze({ covered: 0.99, window: 20, minGain: 0.005, max: 400 });

/** The auto-N rule in words, for help texts and docs. */
export const AUTO_N_RULE = `until ${AUTO_N.covered * 100}% of the surface is near a source or a separator, or ${AUTO_N.window} more sources add less than ${AUTO_N.minGain * 100}% (at most ${AUTO_N.max})`;

/** Every option of meshes and clouds together. */
export type AnyOptions = Options & CloudOptions;

interface Common<K extends keyof AnyOptions> {
  key: K;
  /** CLI flag, kebab-case of the key; a switch that is on by default is turned off by --no-<flag>. */
  flag: string;
  /**
   * The CLI commands that take the flag: every one that runs stage 1 (a point-cloud option: every one
   * that opens a cloud), or `skeleton` only.
   */
  commands: 'all' | 'skeleton';
  default: AnyOptions[K];
  /** One line: what it changes, in which unit. */
  help: string;
}
/** An option of meshes and point clouds alike. */
interface EveryShape {
  shapes: 'all';
  /** separator: stage 1, from one source (a change re-runs the source); skeleton: the whole shape only. */
  stage: 'separator' | 'skeleton';
}
/** An option of point clouds only: how the cloud is made into a surface (a change opens it again, then re-runs everything). */
interface CloudOnly {
  shapes: 'cloud';
  stage: 'open';
}
/** An option of meshes only, of the whole-shape run. */
interface MeshOnly {
  shapes: 'mesh';
  stage: 'skeleton';
}
export type OptionSpec =
  | (Common<'target'> & EveryShape & { kind: 'choice'; /** each value with its label in the panel */ choices: Readonly<Record<Options['target'], string>> })
  | (Common<'sphere'> & EveryShape & { kind: 'switch' })
  | (Common<'seed' | 'pruneDepth' | 'drawAhead'> & EveryShape & { kind: 'integer'; range: readonly [number, number]; placeholder: string })
  | (Common<'angleThreshold' | 'laplacianThreshold' | 'pruneLengthFactor'> & EveryShape & {
      kind: 'number';
      range: readonly [number, number];
      placeholder: string;
      /** The panel's step; `slider` where the range is small and natural (an angle). */
      step: number;
      slider?: true;
    })
  | (Common<'n'> & EveryShape & { kind: 'count'; range: readonly [number, number]; placeholder: string })
  | (Common<'neighbours'> & CloudOnly & { kind: 'integer'; range: readonly [number, number]; placeholder: string })
  | (Common<'stage1Vertices'> & MeshOnly & { kind: 'integer'; range: readonly [number, number]; placeholder: string });

/** The options a mesh takes: all but the point-cloud ones. */
export type MeshOptionSpec = Extract<OptionSpec, { shapes: 'all' | 'mesh' }>;

export const OPTIONS: readonly OptionSpec[] = Object.freeze([
  {
    key: 'target', flag: 'target', shapes: 'all', stage: 'separator', commands: 'all', kind: 'choice', default: 'euclid',
    choices: { euclid: 'space', geodesic: 'surface' },
    help: 'target: the cut-locus point nearest the source in space (euclid, the paper) or along the surface (geodesic)',
  },
  {
    key: 'sphere', flag: 'sphere', shapes: 'all', stage: 'separator', commands: 'all', kind: 'switch', default: true,
    help: 'keep the shortened loop inside a sphere around the source reaching the farthest point of the approximate loop (paper Sec. 4.1.6)',
  },
  {
    key: 'seed', flag: 'seed', shapes: 'all', stage: 'skeleton', commands: 'all', kind: 'integer', default: 1, range: [0, 0xffffffff], placeholder: 'S',
    help: 'seed of every random choice (the sources drawn); same seed, same skeleton',
  },
  {
    key: 'angleThreshold', flag: 'angle-threshold', shapes: 'all', stage: 'separator', commands: 'all', kind: 'number', default: 1.75, range: [0, Math.PI],
    placeholder: 'X', step: 0.01, slider: true,
    help: 'cut locus: minimum turn of the distance gradient at a ridge, radians in [0, π]',
  },
  {
    key: 'laplacianThreshold', flag: 'laplacian-threshold', shapes: 'all', stage: 'separator', commands: 'all', kind: 'number', default: 0.2, range: [0, 1e6],
    placeholder: 'X', step: 0.01,
    help: 'cut locus: minimum ridge sharpness, −(mean edge length)·(Laplacian of the distance), unitless',
  },
  {
    key: 'pruneDepth', flag: 'prune-depth', shapes: 'all', stage: 'separator', commands: 'all', kind: 'integer', default: 3, range: [0, 1000], placeholder: 'N',
    help: 'cut locus: leaf branches with fewer edges than this are pruned',
  },
  {
    key: 'n', flag: 'n', shapes: 'all', stage: 'skeleton', commands: 'skeleton', kind: 'count', default: 'auto', range: [1, 100000], placeholder: 'N|auto',
    help: `number of sources (separators tried), or auto: draw sources ${AUTO_N_RULE}`,
  },
  {
    key: 'pruneLengthFactor', flag: 'prune-length-factor', shapes: 'all', stage: 'skeleton', commands: 'skeleton', kind: 'number', default: 3, range: [0, 1000],
    placeholder: 'X', step: 0.5,
    help: 'loops shorter than this many mean edge lengths enclose no feature and are pruned (paper Sec. 4.2.2)',
  },
  {
    key: 'drawAhead', flag: 'draw-ahead', shapes: 'all', stage: 'skeleton', commands: 'skeleton', kind: 'integer', default: 4, range: [1, 256], placeholder: 'K',
    help: 'sources drawn in stage 1 before the separators of the earlier ones are known (each draw knows all but the K − 1 before it); up to K are computed side by side by workers: the skeleton depends on it, not on the number of workers; 1: one at a time',
  },
  {
    key: 'stage1Vertices', flag: 'stage1-vertices', shapes: 'mesh', stage: 'skeleton', commands: 'skeleton', kind: 'integer', default: 20000,
    range: [0, 100_000_000], placeholder: 'V',
    help: 'meshes only: above this many vertices, stage 1 runs on a copy simplified to about as many (quadric edge collapse, topology kept) and its separators are mapped back; stage 2 and the skeleton use the mesh as given; 0: never (docs/multiscale.md)',
  },
  {
    key: 'neighbours', flag: 'neighbours', shapes: 'cloud', stage: 'open', commands: 'all', kind: 'integer', default: 30, range: [3, 256], placeholder: 'K',
    help: 'point clouds only: neighbours of each point (k of the k-nearest-neighbour search) that its local triangulation, and so the distances, are built from, on a clean cloud cut to those that lie flat (at least 12); fewer follow parts thinner than the neighbourhood, more span sparse regions, open rims and noise',
  },
] satisfies OptionSpec[]);

/** The options of meshes, in their declared order (every front end that opens only meshes shows these). */
export const MESH_OPTIONS: readonly MeshOptionSpec[] = Object.freeze(OPTIONS.filter((o): o is MeshOptionSpec => o.shapes !== 'cloud'));

/** The options of point clouds, in their declared order: all but the mesh-only ones. */
export const CLOUD_OPTIONS: readonly OptionSpec[] = Object.freeze(OPTIONS.filter((o) => o.shapes !== 'mesh'));

/**
 * Settings of a run: how it is computed, never what it gives. Unlike the options they reach neither
 * the core nor the skeleton's JSON, so the same options give the same file whatever they are.
 */
export interface RunSettings {
  /** Threads that compute stage 1 (beyond 1, the caller's only draws and accepts), or auto (poolSize, lib/core/pool-size.ts). */
  workers: number | 'auto';
}

/** A run setting, declared as an option is: its CLI flag, the page's label (the key) and its link parameter. */
export interface SettingSpec {
  key: keyof RunSettings;
  flag: string;
  kind: 'count';
  default: 'auto';
  range: readonly [number, number];
  placeholder: string;
  help: string;
}

export const WORKERS: SettingSpec = Object.freeze({
  key: 'workers', flag: 'workers', kind: 'count', default: 'auto', range: Object.freeze([1, 256] as const), placeholder: 'K|auto',
  help: 'threads that compute stage 1 (with more than 1, the pipeline\'s own thread only draws the sources and takes the results); they share the drawAhead sources drawn ahead, so with drawAhead 1 there is nothing to share; auto: every core but one, fewer when memory is short (docs/parallel.md); the skeleton does not depend on it',
});

export const SETTINGS: readonly SettingSpec[] = Object.freeze([WORKERS]);

export const defaultRunSettings: Readonly<RunSettings> = Object.freeze({ workers: WORKERS.default });

/** Defaults of every option of a mesh. */
export const defaultOptions: Readonly<Options> = Object.freeze(
  Object.fromEntries(MESH_OPTIONS.map((o) => [o.key, o.default])) as unknown as Options,
);

/** A mesh's options as a point cloud's: the mesh-only ones left out, `neighbours` added. */
export function cloudOptionsOf(options: Options, neighbours: number): CloudOptions {
  const all: Record<string, unknown> = { ...options, neighbours };
  return Object.fromEntries(CLOUD_OPTIONS.map((o) => [o.key, all[o.key]])) as unknown as CloudOptions;
}

/** Defaults of every option of a point cloud. */
export const defaultCloudOptions: Readonly<CloudOptions> = Object.freeze(
  Object.fromEntries(CLOUD_OPTIONS.map((o) => [o.key, o.default])) as unknown as CloudOptions,
);

type NumericKey = Extract<OptionSpec, { range: readonly [number, number] }>['key'];
/** Accepted ranges of the numeric options (the core checks the same, wasm/src/cscd/options.h). */
export const optionRanges: Readonly<Record<NumericKey, readonly [number, number]>> = Object.freeze(
  Object.fromEntries(OPTIONS.flatMap((o) => ('range' in o ? [[o.key, o.range]] : []))) as Record<NumericKey, readonly [number, number]>,
);

/** Why a value is not acceptable for an option (null when it is). */
export function optionProblem(spec: OptionSpec | SettingSpec, value: unknown): string | null {
  switch (spec.kind) {
    case 'choice':
      return typeof value === 'string' && Object.hasOwn(spec.choices, value) ? null : `must be one of ${Object.keys(spec.choices).join(', ')}`;
    case 'switch':
      return typeof value === 'boolean' ? null : 'must be true or false';
    case 'integer':
    case 'count': {
      if (spec.kind === 'count' && value === 'auto') return null;
      const [lo, hi] = spec.range;
      const ok = typeof value === 'number' && Number.isInteger(value) && value >= lo && value <= hi;
      return ok ? null : `must be ${spec.kind === 'count' ? 'auto or ' : ''}an integer from ${lo} to ${hi}`;
    }
    case 'number': {
      const [lo, hi] = spec.range;
      return typeof value === 'number' && Number.isFinite(value) && value >= lo && value <= hi ? null : `must be a number from ${lo} to ${hi === Math.PI ? 'pi' : hi}`;
    }
  }
}

/** How a number may be written (a CLI argument, an address-bar parameter). */
export const NUMBER_TEXT = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/** The CLI flag of an option: a switch that is on by default is turned off by --no-<flag>. */
export function cliFlag(spec: OptionSpec): string {
  return spec.kind === 'switch' && spec.default ? `no-${spec.flag}` : spec.flag;
}

/** An option's value from its text (String(value) writes it); null when it is not acceptable. */
export function parseOptionText<K extends keyof AnyOptions>(spec: Extract<OptionSpec, { key: K }>, text: string): AnyOptions[K] | null {
  return parseSpecText(spec as OptionSpec, text) as AnyOptions[K] | null;
}

/** Options from `key=value` texts (the scripts' --set), each read as the address bar reads it, among `specs`; throws on any other. */
export function optionsFromPairs(pairs: readonly string[], specs: readonly OptionSpec[] = OPTIONS): Partial<CloudOptions> {
  return Object.fromEntries(pairs.map((pair) => {
    const [key, text] = pair.split('=');
    const spec = specs.find((o) => o.key === key);
    const value = spec && text !== undefined ? parseSpecText(spec, text) : null;
    if (value === null) throw new Error(`--set ${pair}: not an option and a value it accepts`);
    return [key, value];
  }));
}

/** A run setting's value from its text; null when it is not acceptable. */
export function parseSettingText<K extends keyof RunSettings>(spec: SettingSpec & { key: K }, text: string): RunSettings[K] | null {
  return parseSpecText(spec, text) as RunSettings[K] | null;
}

/** The value of an option or run setting from its text, of the type its spec says; null when it is not acceptable. */
export function parseSpecText(spec: OptionSpec | SettingSpec, text: string): unknown {
  let value: unknown = text;
  if (spec.kind === 'switch') value = text === 'true' ? true : text === 'false' ? false : null;
  else if (spec.kind === 'integer' || (spec.kind === 'count' && text !== 'auto')) value = /^\d+$/.test(text) ? Number(text) : null;
  else if (spec.kind === 'number') value = NUMBER_TEXT.test(text) ? Number(text) : null;
  return optionProblem(spec, value) === null ? value : null;
}


/** The option table of the README and docs/cli.md: flag, option, default, meaning. */
export function optionTable(): string {
  const flag = (o: OptionSpec) =>
    o.kind === 'switch' ? `\`--${cliFlag(o)}\`` : o.kind === 'choice' ? `\`--${o.flag} ${Object.keys(o.choices).join('\\|')}\`` : `\`--${o.flag} ${o.placeholder.replace('|', '\\|')}\``;
  const rows = OPTIONS.map((o) => `| ${flag(o)} | \`${o.key}\` | \`${String(o.default)}\` | ${{ separator: 'stage 1', skeleton: 'whole shape', open: 'opening a cloud' }[o.stage]} | ${o.help.replaceAll('|', '\\|')} |`);
  return ['| CLI flag | option | default | stage | meaning |', '|---|---|---|---|---|', ...rows].join('\n');
}
