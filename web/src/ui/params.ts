/**
 * Every option in one lil-gui panel, labelled with the option's own name (as in C++, the worker
 * messages and the CLI), each with a tooltip saying what it changes and in which unit, plus presets;
 * and the run settings (`workers`) in a folder of their own, which change how a run is computed,
 * not its result. The panel owns the current options and settings; `onChange` says which options
 * the user changed, `onSettingsChange` that a setting changed. The point-cloud options (`shapes:
 * 'cloud'`, i.e. `neighbours`) have a folder of their own, shown only while a cloud is open; the
 * mesh-only ones (`stage1Vertices`) are hidden then.
 */
import GUI, { type Controller } from 'lil-gui';
import { AUTO_N_RULE, defaultCloudOptions, defaultOptions, MESH_OPTIONS, OPTIONS, optionRanges, WORKERS, type MeshOptionSpec, type RunSettings } from '../../../lib/core/options.ts';
import type { Options } from '../../../lib/core/types.ts';

export type OptionKey = keyof Options;

/** Options of stage 1: a change re-runs the current source (and invalidates the whole-shape result). */
export const STAGE1_OPTIONS: readonly OptionKey[] = MESH_OPTIONS.filter((o) => o.stage === 'separator').map((o) => o.key);

/** The tooltip of an option: its help, and what a change re-runs. */
export function optionTooltip(spec: MeshOptionSpec): string {
  const help = spec.help.charAt(0).toUpperCase() + spec.help.slice(1);
  return `${help}. Re-runs ${spec.stage === 'separator' ? 'the source' : 'the whole shape'}.`;
}

const N_AUTO_HELP = `auto: sample sources ${AUTO_N_RULE}.`;
const WORKERS_AUTO_HELP = 'auto: every core but one, fewer when memory is short (the panel says when), at most drawAhead.';

/** Named option sets; each starts from the defaults. */
export const PRESETS: Readonly<Record<string, Partial<Options>>> = {
  'Paper defaults': {},
  'Fast preview': { n: 20 },
  Fine: { n: 200, pruneLengthFactor: 2 },
};

/** The panel's model: the options and settings, each count (`n`, `workers`) split into a checkbox and a number for lil-gui. */
interface Model extends Omit<Options, 'n'> {
  nAuto: boolean;
  n: number;
  workersAuto: boolean;
  workers: number;
  preset: string;
  neighbours: number;
}

/** The one cloud-only option: how many neighbours each point's local triangulation is built from. */
const NEIGHBOURS = OPTIONS.find((o) => o.shapes === 'cloud' && o.key === 'neighbours')!;

const FALLBACK_N = 40;
const FALLBACK_WORKERS = 2;
const CUSTOM = 'custom';

export class ParamsPanel {
  /** The user changed these options (after editing finished: a slider released, a number entered). */
  onChange: ((changed: OptionKey[]) => void) | null = null;
  /** The user changed a run setting. */
  onSettingsChange: (() => void) | null = null;
  /** The user changed `neighbours` (the open cloud is opened again with it). */
  onNeighboursChange: (() => void) | null = null;

  private readonly gui: GUI;
  private readonly model: Model;
  private readonly nController: Controller;
  private readonly workersController: Controller;
  private readonly cloudFolder: GUI;
  /** The controllers of the mesh-only options, hidden while a cloud is open. */
  private readonly meshOnly: Controller[] = [];

  constructor(container: HTMLElement, initial: Options, settings: RunSettings) {
    this.model = { ...toModel(initial), ...settingsModel(settings), preset: presetOf(initial), neighbours: defaultCloudOptions.neighbours };
    const gui = new GUI({ container, title: 'Parameters', width: 284 });
    this.gui = gui;
    const m = this.model;

    tag(gui.add(m, 'preset', [...Object.keys(PRESETS), CUSTOM]).name('preset'), 'preset', 'Sets every option: the paper’s defaults, a quick run with few sources, or a finer one with more.')
      .onChange((name: string) => this.applyPreset(name));

    // A slider only where the range is small and natural (an angle); elsewhere a number field with
    // the range's lower bound, the upper bound applied by `options` (optionRanges, as the core checks).
    const folders = { separator: gui.addFolder('Stage 1 · one source'), skeleton: gui.addFolder('Stage 2 · whole shape') };
    const changed = (key: OptionKey) => () => this.changed([key]);
    let nController: Controller | null = null;
    for (const spec of MESH_OPTIONS) {
      const folder = folders[spec.stage];
      const tip = optionTooltip(spec);
      switch (spec.kind) {
        case 'choice': {
          const labels = Object.fromEntries(Object.entries(spec.choices).map(([value, label]) => [`${value} (${label})`, value]));
          tag(folder.add(m, spec.key, labels), spec.key, tip).onChange(changed(spec.key));
          break;
        }
        case 'switch':
          tag(folder.add(m, spec.key), spec.key, tip).onChange(changed(spec.key));
          break;
        case 'integer': {
          const c = tag(folder.add(m, spec.key).min(spec.range[0]).step(1), spec.key, tip).onFinishChange(changed(spec.key));
          if (spec.shapes === 'mesh') this.meshOnly.push(c);
          break;
        }
        case 'number': {
          const c = spec.slider ? folder.add(m, spec.key, spec.range[0], spec.range[1], spec.step) : folder.add(m, spec.key).min(spec.range[0]).step(spec.step);
          tag(c, spec.key, tip).onFinishChange(changed(spec.key));
          break;
        }
        case 'count':
          nController = addCount(folder, m, 'n', 'nAuto', spec.range, [N_AUTO_HELP, tip], () => this.changed(['n']));
          break;
      }
    }
    this.nController = nController!;
    this.cloudFolder = gui.addFolder('Point cloud');
    const neighboursTip = `${NEIGHBOURS.help.charAt(0).toUpperCase()}${NEIGHBOURS.help.slice(1)}. Opens the cloud again.`;
    tag(this.cloudFolder.add(this.model, 'neighbours').min(NEIGHBOURS.range[0]).step(1), 'neighbours', neighboursTip).onFinishChange(() => {
      this.model.neighbours = this.neighbours; // shown clamped, as it is used
      this.cloudFolder.controllersRecursive().forEach((c) => c.updateDisplay());
      this.onNeighboursChange?.();
    });
    this.cloudFolder.hide();
    const run = gui.addFolder('Run · how, not what');
    const workersTip = `${WORKERS.help.charAt(0).toUpperCase()}${WORKERS.help.slice(1)}.`;
    this.workersController = addCount(run, m, 'workers', 'workersAuto', WORKERS.range, [WORKERS_AUTO_HELP, workersTip], () => {
      // Out-of-range input is shown clamped, as it is used.
      Object.assign(this.model, settingsModel(this.settings));
      this.workersController.updateDisplay();
      this.onSettingsChange?.();
    });
  }

  /** The current run settings, clamped to their accepted ranges. */
  get settings(): RunSettings {
    const { workersAuto, workers } = this.model;
    return { workers: workersAuto ? 'auto' : clamp(workers, WORKERS.range, true) };
  }

  /** Neighbours per point for a cloud, clamped to its accepted range. */
  get neighbours(): number {
    return clamp(this.model.neighbours, NEIGHBOURS.range as readonly [number, number], true);
  }

  /** Shows the point-cloud options while a cloud is open, hides them (and shows the mesh-only ones) for a mesh. */
  showCloudOptions(on: boolean): void {
    this.cloudFolder.show(on);
    for (const c of this.meshOnly) c.show(!on);
  }

  /** The current options, clamped to their accepted ranges. */
  get options(): Options {
    const m = this.model;
    const options: Record<string, unknown> = {};
    for (const spec of MESH_OPTIONS) {
      if (spec.kind === 'choice' || spec.kind === 'switch') options[spec.key] = m[spec.key];
      else if (spec.kind === 'count') options.n = m.nAuto ? 'auto' : clamp(m.n, optionRanges.n, true);
      else options[spec.key] = clamp(m[spec.key], spec.range, spec.kind === 'integer');
    }
    return options as unknown as Options;
  }

  /** Shows `options` (a shared link, a preset) without reporting a change. */
  set(options: Options): void {
    Object.assign(this.model, toModel(options), { preset: presetOf(options) });
    for (const c of this.gui.controllersRecursive()) c.updateDisplay();
    this.nController.disable(this.model.nAuto);
  }

  private applyPreset(name: string): void {
    const preset = PRESETS[name];
    if (!preset) return; // 'custom' only names the options as they are
    const before = this.options;
    this.set({ ...defaultOptions, ...preset });
    const after = this.options;
    const keys = (Object.keys(after) as OptionKey[]).filter((k) => after[k] !== before[k]);
    if (keys.length) this.onChange?.(keys);
  }

  private changed(keys: OptionKey[]): void {
    const options = this.options;
    // Out-of-range input is shown clamped, as it is used.
    Object.assign(this.model, toModel(options), { preset: presetOf(options) });
    for (const c of this.gui.controllersRecursive()) c.updateDisplay();
    this.onChange?.(keys);
  }
}

function tag(c: Controller, id: string, help: string): Controller {
  c.domElement.dataset.testid = `opt-${id}`;
  c.domElement.title = help;
  return c;
}

function clamp(x: number, [lo, hi]: readonly [number, number], integer: boolean): number {
  const v = Number.isFinite(x) ? x : lo;
  return Math.min(hi, Math.max(lo, integer ? Math.round(v) : v));
}

/**
 * A count as lil-gui shows it: a checkbox `<key> auto` and a number field, disabled while auto is on
 * (testids `opt-<key>-auto` and `opt-<key>`).
 */
function addCount<K extends 'n' | 'workers'>(folder: GUI, m: Model, key: K, autoKey: `${K}Auto`, range: readonly [number, number], tips: [auto: string, value: string], onChange: () => void): Controller {
  const box = tag(folder.add(m, autoKey).name(`${key} auto`), `${key}-auto`, tips[0]);
  const field = tag(folder.add(m, key).min(range[0]).step(1), key, tips[1]).onFinishChange(onChange);
  box.onChange(() => {
    field.disable(m[autoKey]);
    onChange();
  });
  field.disable(m[autoKey]);
  return field;
}

function settingsModel(settings: RunSettings): Pick<Model, 'workersAuto' | 'workers'> {
  const auto = settings.workers === 'auto';
  return { workersAuto: auto, workers: auto ? FALLBACK_WORKERS : (settings.workers as number) };
}

function toModel(options: Options): Omit<Model, 'preset' | 'workersAuto' | 'workers' | 'neighbours'> {
  const auto = options.n === 'auto';
  return { ...options, nAuto: auto, n: auto ? FALLBACK_N : (options.n as number) };
}

/** The preset whose options these are, or CUSTOM. */
function presetOf(options: Options): string {
  const same = (preset: Partial<Options>) =>
    (Object.keys(defaultOptions) as OptionKey[]).every((k) => ({ ...defaultOptions, ...preset })[k] === options[k]);
  return Object.keys(PRESETS).find((name) => same(PRESETS[name])) ?? CUSTOM;
}
