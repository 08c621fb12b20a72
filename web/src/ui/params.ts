/**
 * Every option in one lil-gui panel, labelled with the option's own name (as in C++, the worker
 * messages and the CLI), each with a tooltip saying what it changes and in which unit, plus presets.
 * The panel owns the current options; `onChange` says which ones the user changed.
 */
import GUI, { type Controller } from 'lil-gui';
import { defaultOptions, optionRanges } from '../../../lib/core/options.ts';
import type { Options } from '../../../lib/core/types.ts';

export type OptionKey = keyof Options;

/** Options of stage 1: a change re-runs the current source (and invalidates the whole-shape result). */
export const STAGE1_OPTIONS: readonly OptionKey[] = ['target', 'sphere', 'angleThreshold', 'laplacianThreshold', 'pruneDepth'];

/** What each option does, and its unit (every option is scale-free). */
export const OPTION_HELP: Readonly<Record<OptionKey, string>> = {
  target:
    'Which cut-locus point the loop is traced from: the one nearest to the source in space (euclid, the paper) or along the surface (geodesic). Re-runs the source.',
  sphere:
    'Keep the shortened loop inside a sphere around the source that reaches the farthest point of the approximate loop, so separators stay local (Sec. 4.1.6). Re-runs the source.',
  angleThreshold:
    'Cut locus: minimum turn of the distance gradient across a ridge, in radians (0 to π). Higher keeps only sharp ridges: fewer, cleaner cut-locus branches. Re-runs the source.',
  laplacianThreshold:
    'Cut locus: minimum ridge sharpness, −(mean edge length) × Laplacian of the distance, unitless. Higher drops faint ridges. Re-runs the source.',
  pruneDepth:
    'Cut locus: leaf branches with fewer edges than this are pruned (a count of mesh edges). Higher removes more short spurs. Re-runs the source.',
  n: 'Number of sources for the whole shape: more sources find more (and smaller) features but take longer. Re-runs the whole shape.',
  seed: 'Fixes the random choices of the whole-shape run (which sources are sampled); same seed, same skeleton. Re-runs the whole shape.',
  pruneLengthFactor:
    'Loops shorter than this many mean edge lengths enclose no feature and are pruned before packing (Sec. 4.2.2). Re-runs the whole shape.',
};

const N_AUTO_HELP =
  'auto: sample sources until 99% of the surface is near a source or a separator, or 20 more sources add less than 0.5% (at most 400).';

/** Named option sets; each starts from the defaults. */
export const PRESETS: Readonly<Record<string, Partial<Options>>> = {
  'Paper defaults': {},
  'Fast preview': { n: 20 },
  Fine: { n: 200, pruneLengthFactor: 2 },
};

/** The panel's model: the options, with `n` split into a checkbox and a number for lil-gui. */
interface Model extends Omit<Options, 'n'> {
  nAuto: boolean;
  n: number;
  preset: string;
}

const FALLBACK_N = 40;
const CUSTOM = 'custom';

export class ParamsPanel {
  /** The user changed these options (after editing finished: a slider released, a number entered). */
  onChange: ((changed: OptionKey[]) => void) | null = null;

  private readonly gui: GUI;
  private readonly model: Model;
  private readonly nController: Controller;

  constructor(container: HTMLElement, initial: Options) {
    this.model = { ...toModel(initial), preset: presetOf(initial) };
    const gui = new GUI({ container, title: 'Parameters', width: 284 });
    this.gui = gui;
    const m = this.model;
    const tag = (c: Controller, key: string, help: string) => {
      c.domElement.dataset.testid = `opt-${key}`;
      c.domElement.title = help;
      return c;
    };

    tag(gui.add(m, 'preset', [...Object.keys(PRESETS), CUSTOM]).name('preset'), 'preset', 'Sets every option: the paper’s defaults, a quick run with few sources, or a finer one with more.')
      .onChange((name: string) => this.applyPreset(name));

    // A slider only where the range is small and natural (an angle); elsewhere a number field with
    // the range lower bound, the upper bound applied by `options` (optionRanges, as the core checks).
    const one = gui.addFolder('Stage 1 · one source');
    const changed = (key: OptionKey) => () => this.changed([key]);
    const [angleMin, angleMax] = optionRanges.angleThreshold;
    tag(one.add(m, 'target', { 'euclid (space)': 'euclid', 'geodesic (surface)': 'geodesic' }), 'target', OPTION_HELP.target).onChange(changed('target'));
    tag(one.add(m, 'sphere'), 'sphere', OPTION_HELP.sphere).onChange(changed('sphere'));
    tag(one.add(m, 'angleThreshold', angleMin, angleMax, 0.01), 'angleThreshold', OPTION_HELP.angleThreshold).onFinishChange(changed('angleThreshold'));
    tag(one.add(m, 'laplacianThreshold').min(optionRanges.laplacianThreshold[0]).step(0.01), 'laplacianThreshold', OPTION_HELP.laplacianThreshold).onFinishChange(
      changed('laplacianThreshold'),
    );
    tag(one.add(m, 'pruneDepth').min(optionRanges.pruneDepth[0]).step(1), 'pruneDepth', OPTION_HELP.pruneDepth).onFinishChange(changed('pruneDepth'));

    const whole = gui.addFolder('Stage 2 · whole shape');
    tag(whole.add(m, 'nAuto').name('n auto'), 'n-auto', N_AUTO_HELP).onChange(() => {
      this.nController.disable(m.nAuto);
      this.changed(['n']);
    });
    this.nController = tag(whole.add(m, 'n').min(optionRanges.n[0]).step(1), 'n', OPTION_HELP.n).onFinishChange(changed('n'));
    this.nController.disable(m.nAuto);
    tag(whole.add(m, 'seed').min(optionRanges.seed[0]).step(1), 'seed', OPTION_HELP.seed).onFinishChange(changed('seed'));
    tag(whole.add(m, 'pruneLengthFactor').min(optionRanges.pruneLengthFactor[0]).step(0.5), 'pruneLengthFactor', OPTION_HELP.pruneLengthFactor).onFinishChange(
      changed('pruneLengthFactor'),
    );
  }

  /** The current options, clamped to their accepted ranges. */
  get options(): Options {
    const m = this.model;
    const clamp = (x: number, [lo, hi]: readonly [number, number], integer = false) => {
      const v = Number.isFinite(x) ? x : lo;
      return Math.min(hi, Math.max(lo, integer ? Math.round(v) : v));
    };
    return {
      target: m.target,
      sphere: m.sphere,
      seed: clamp(m.seed, optionRanges.seed, true),
      angleThreshold: clamp(m.angleThreshold, optionRanges.angleThreshold),
      laplacianThreshold: clamp(m.laplacianThreshold, optionRanges.laplacianThreshold),
      pruneDepth: clamp(m.pruneDepth, optionRanges.pruneDepth, true),
      n: m.nAuto ? 'auto' : clamp(m.n, optionRanges.n, true),
      pruneLengthFactor: clamp(m.pruneLengthFactor, optionRanges.pruneLengthFactor),
    };
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

function toModel(options: Options): Omit<Model, 'preset'> {
  const auto = options.n === 'auto';
  return { ...options, nAuto: auto, n: auto ? FALLBACK_N : (options.n as number) };
}

/** The preset whose options these are, or CUSTOM. */
function presetOf(options: Options): string {
  const same = (preset: Partial<Options>) =>
    (Object.keys(defaultOptions) as OptionKey[]).every((k) => ({ ...defaultOptions, ...preset })[k] === options[k]);
  return Object.keys(PRESETS).find((name) => same(PRESETS[name])) ?? CUSTOM;
}
