/**
 * The whole-shape mode's panel: options (N, seed, prune length), Compute / Cancel, the progress bar,
 * the run's outcome, and the result's views stepped like stage 1 (Candidates, Packing, Regions,
 * Skeleton) with captions, legends, figures and timings.
 */
import { optionRanges } from '../../../lib/core/options.ts';
import type { CandidateFate, Options } from '../../../lib/core/types.ts';
import type { EvaluationReply, SkeletonReply } from '../worker/protocol.ts';
import { colormapGradient } from '../viewer/colormap.ts';
import { byTestId, formatMs, humanize, swatch } from './panel.ts';
import { Stepper } from './stepper.ts';

/** Layer colours (sRGB), shared by the viewer layers and the legends. */
export const SK_COLORS = {
  /** Candidate loops while they arrive. */
  candidate: '#ffd21a',
  packed: '#00e1ff',
  rejected: '#ff4f9a',
  node: '#ff6a2b',
  edge: '#ffb02e',
  /** The reconstructed surface of the evaluation. */
  reconstruction: '#9fc4ff',
} as const;

export interface SkeletonStageDef {
  title: string;
  section: string;
  caption: string;
  /** Viewer layers shown in this view (`surface` always is). */
  layers: string[];
  /** Layers drawn muted (context from an earlier view). */
  dimmed?: string[];
  legend: Array<{ layer: string; label: string; color: string }>;
}

export const SK_STAGES: readonly SkeletonStageDef[] = [
  {
    title: 'Candidates',
    section: 'Sec. 4.1, 4.2.1',
    caption: 'Stage 1 ran from every source and gave one candidate loop each, scored A1 / (A2 · length).',
    layers: ['sk-rejected', 'sk-packed'],
    legend: [
      { layer: 'sk-packed', label: 'packed', color: SK_COLORS.packed },
      { layer: 'sk-rejected', label: 'rejected', color: SK_COLORS.rejected },
    ],
  },
  {
    title: 'Packing',
    section: 'Sec. 4.2.2–4.2.3',
    caption:
      'Short loops and loops whose centroid lies outside the shape are pruned; greedy weighted set packing then keeps high-scoring loops that overlap no other kept loop.',
    layers: ['sk-packed'],
    legend: [{ layer: 'sk-packed', label: 'packed loop', color: SK_COLORS.packed }],
  },
  {
    title: 'Regions',
    section: 'Sec. 4.2.4',
    caption:
      'Every vertex belongs to the packed loop nearest to it along the surface (a watershed from all loops at once), so each loop owns the region around it; one colour per region. Each region becomes a node of the skeleton.',
    layers: ['sk-packed'],
    dimmed: ['sk-packed'],
    legend: [],
  },
  {
    title: 'Skeleton',
    section: 'Sec. 4.2.4',
    caption:
      'One node per region at its centroid, drawn as a sphere sized by its radius (the mean distance from the node to its region); edges join regions that touch, and where three or more regions meet a branch node joins them. The mesh is drawn see-through.',
    layers: ['sk-edges', 'sk-nodes'],
    legend: [
      { layer: 'sk-nodes', label: 'node', color: SK_COLORS.node },
      { layer: 'sk-edges', label: 'edge', color: SK_COLORS.edge },
    ],
  },
];

export const SK_REGIONS_STAGE = 3;
export const SK_SKELETON_STAGE = 4;

const FATE_TEXT: Record<CandidateFate, string> = {
  packed: 'packed',
  overlapping: 'overlapping a better loop',
  short: 'too short',
  outside: 'centroid outside',
  failed: 'no loop',
};

export type RunStatus = 'running' | 'done' | 'cancelled' | 'failed';

export class SkeletonPanel {
  /** Compute / Cancel pressed. */
  onCompute: (() => void) | null = null;
  onCancel: (() => void) | null = null;
  /** The user asks for another view (buttons, pills, keys). */
  onSelect: ((stage: number) => void) | null = null;
  /** The reconstruction toggle changed. */
  onRecon: ((on: boolean) => void) | null = null;
  /** Keys step the views only while the mode is shown. */
  active = false;

  private readonly compute = byTestId<HTMLButtonElement>('sk-compute');
  private readonly cancel = byTestId<HTMLButtonElement>('sk-cancel');
  private readonly progress = byTestId('sk-progress');
  private readonly fill = this.progress.querySelector<HTMLElement>('.progress-fill')!;
  private readonly track = this.progress.querySelector<HTMLElement>('.progress-track')!;
  private readonly nInput = byTestId<HTMLInputElement>('opt-n');
  private readonly nAuto = byTestId<HTMLInputElement>('opt-n-auto');
  private readonly seedInput = byTestId<HTMLInputElement>('opt-seed');
  private readonly pruneInput = byTestId<HTMLInputElement>('opt-prune-length');
  private readonly recon = byTestId<HTMLInputElement>('sk-recon');
  private readonly stepper = new Stepper(
    { prev: 'sk-prev', next: 'sk-next', steps: 'sk-steps' },
    SK_STAGES.map((def) => def.title),
    () => this.active && !byTestId('sk-result').hidden,
  );

  constructor(defaults: Options) {
    this.nAuto.checked = defaults.n === 'auto';
    if (typeof defaults.n === 'number') this.nInput.value = String(defaults.n);
    this.nInput.disabled = this.nAuto.checked;
    this.nAuto.addEventListener('change', () => (this.nInput.disabled = this.nAuto.checked));
    this.seedInput.value = String(defaults.seed);
    this.pruneInput.value = String(defaults.pruneLengthFactor);

    byTestId('sk-recon-colorbar').style.background = colormapGradient();
    this.recon.addEventListener('change', () => this.onRecon?.(this.recon.checked));
    this.compute.addEventListener('click', () => this.onCompute?.());
    this.cancel.addEventListener('click', () => this.onCancel?.());
    this.stepper.onSelect = (stage) => this.onSelect?.(stage);
    for (const input of [this.nInput, this.seedInput, this.pruneInput]) {
      input.addEventListener('keydown', (e) => {
        if (e.key === 'Enter' && !this.compute.disabled) this.onCompute?.();
      });
    }
  }

  /** The run options from the inputs (clamped to their ranges; bad input falls back to `defaults`). */
  readOptions(defaults: Options): Pick<Options, 'n' | 'seed' | 'pruneLengthFactor'> {
    const read = (input: HTMLInputElement, [lo, hi]: readonly [number, number], fallback: number, integer: boolean) => {
      let x = Number(input.value);
      if (input.value.trim() === '' || !Number.isFinite(x)) x = fallback;
      if (integer) x = Math.round(x);
      x = Math.min(hi, Math.max(lo, x));
      input.value = String(x);
      return x;
    };
    const fallbackN = typeof defaults.n === 'number' ? defaults.n : 40;
    const n = this.nAuto.checked ? 'auto' : read(this.nInput, optionRanges.n, fallbackN, true);
    return {
      n,
      seed: read(this.seedInput, optionRanges.seed, defaults.seed, true),
      pruneLengthFactor: read(this.pruneInput, optionRanges.pruneLengthFactor, defaults.pruneLengthFactor, false),
    };
  }

  /** A run started: the progress bar at zero, the previous result hidden. */
  startRun(n: number | 'auto'): void {
    this.compute.disabled = true;
    this.cancel.hidden = false;
    this.cancel.disabled = false;
    this.progress.hidden = false;
    this.setProgress(0, typeof n === 'number' ? n : 0, 'stage 1');
    byTestId('sk-progress-text').textContent = 'starting…';
    this.setStatus(null);
    this.setResult(null);
  }

  setProgress(done: number, total: number, phase: string): void {
    this.progress.dataset.done = String(done);
    this.progress.dataset.total = String(total);
    const fraction = total > 0 ? Math.min(1, done / total) : 0;
    this.fill.style.width = `${(100 * fraction).toFixed(1)}%`;
    this.track.setAttribute('aria-valuemax', String(total));
    this.track.setAttribute('aria-valuenow', String(done));
    byTestId('sk-progress-text').textContent = total > 0 ? `${done} / ${total} sources` : `${done} sources`;
    byTestId('sk-progress-phase').textContent = phase;
    this.progress.classList.remove('indeterminate');
  }

  /** Stage 2 runs in one call: the bar shows that it is busy rather than a fraction. */
  setStage2(): void {
    byTestId('sk-progress-phase').textContent = 'stage 2: packing, regions, skeleton';
    this.progress.classList.add('indeterminate');
  }

  /** The run ended (any way): buttons back, the progress bar hidden unless the run stopped early. */
  endRun(keepProgress: boolean): void {
    this.compute.disabled = false;
    this.cancel.hidden = true;
    this.progress.hidden = !keepProgress;
    this.progress.classList.remove('indeterminate');
  }

  /** Disables Cancel once pressed (the worker stops between two steps). */
  cancelling(): void {
    this.cancel.disabled = true;
    byTestId('sk-progress-phase').textContent = 'cancelling…';
  }

  setStatus(status: { kind: RunStatus; title: string; text: string } | null): void {
    const el = byTestId('sk-status');
    el.hidden = !status;
    if (!status) {
      delete el.dataset.status;
      el.replaceChildren();
      return;
    }
    el.dataset.status = status.kind;
    el.classList.toggle('failed', status.kind === 'failed' || status.kind === 'cancelled');
    const head = document.createElement('strong');
    head.textContent = status.title;
    const body = document.createElement('span');
    body.textContent = status.text;
    el.replaceChildren(head, body);
  }

  /** Shows a result's figures (or hides the block when null). */
  setResult(reply: SkeletonReply | null, regions = 0): void {
    byTestId('sk-result').hidden = !reply;
    byTestId('sk-empty').hidden = !!reply || !byTestId('sk-progress').hidden;
    if (!reply) return;
    const s = reply.skeleton;
    const set = (id: string, text: string | number) => (byTestId(id).textContent = String(text));
    set('sk-n', `${s.stats.n}${reply.options.n === 'auto' ? ' (auto)' : ''}`);
    set('sk-candidates', s.stats.candidates);
    set('sk-pruned', s.stats.pruned);
    set('sk-packed', s.stats.packed);
    set('sk-regions', regions);
    set('sk-nodes', Math.floor(s.nodes.length / 3));
    set('sk-edges', Math.floor(s.edges.length / 2));
    set('sk-cycles', s.stats.cycles);
    set('sk-seed', s.stats.seed);
    set('sk-timing-stage1', formatMs(reply.timings.stage1Ms));
    set('sk-timing-stage2', formatMs(reply.timings.stage2Ms));
    byTestId('sk-timings').replaceChildren(
      ...Object.entries(s.stats.timings).flatMap(([key, ms]) => {
        const dt = document.createElement('dt');
        dt.textContent = humanize(key);
        const dd = document.createElement('dd');
        dd.dataset.testid = `sk-timing-${key}`;
        dd.textContent = Number.isFinite(ms) ? formatMs(ms) : '–';
        return [dt, dd];
      }),
    );
  }

  get reconShown(): boolean {
    return this.recon.checked;
  }

  /**
   * The reconstruction block: off (unticked, for a new result), busy, failed, or the figures of an
   * evaluation; `max` is the error at the top of the colour bar.
   */
  setRecon(state: { kind: 'off' } | { kind: 'busy' } | { kind: 'failed'; message: string } | { kind: 'done'; reply: EvaluationReply; max: number }): void {
    const status = byTestId('sk-recon-status');
    const result = byTestId('sk-recon-result');
    if (state.kind === 'off') this.recon.checked = false;
    status.hidden = state.kind !== 'busy' && state.kind !== 'failed';
    status.textContent = state.kind === 'busy' ? 'Reconstructing the surface from the skeleton…' : state.kind === 'failed' ? state.message : '';
    status.classList.toggle('error-text', state.kind === 'failed');
    result.hidden = state.kind !== 'done' || !this.recon.checked;
    if (state.kind !== 'done') return;
    const e = state.reply.evaluation;
    const set = (id: string, text: string) => (byTestId(id).textContent = text);
    const format = (x: number) => x.toPrecision(3);
    set('sk-recon-mean', format(e.reconError));
    set('sk-recon-median', format(e.median));
    set('sk-recon-p95', format(e.p95));
    set('sk-recon-colorbar-max', format(state.max));
    set('sk-recon-grid', `${e.grid.dims.join(' × ')} cells`);
    set('sk-recon-time', formatMs(state.reply.timings.evaluateMs));
    document.body.dataset.skRecon = String(e.reconError);
  }

  /** The view shown; `present`: layers with data; `regionColors`: one per region, for its legend. */
  setStage(stage: number, reply: SkeletonReply, present: ReadonlySet<string>, regionColors: string[]): void {
    const def = SK_STAGES[stage - 1];
    const s = reply.skeleton;
    document.body.dataset.skStage = String(stage);
    byTestId('sk-stage-index').textContent = String(stage);
    byTestId('sk-stage-title').textContent = def.title;
    byTestId('sk-stage-section').textContent = def.section;
    let caption = def.caption;
    const fates = s.candidates.fates;
    if (stage === 1) {
      const counts = new Map<CandidateFate, number>();
      for (const f of fates) counts.set(f, (counts.get(f) ?? 0) + 1);
      const rejected = [...counts].filter(([f]) => f !== 'packed').map(([f, n]) => `${n} ${FATE_TEXT[f]}`);
      caption += ` ${fates.length} sources (seed ${s.stats.seed}): ${counts.get('packed') ?? 0} packed`;
      caption += rejected.length ? `; rejected: ${rejected.join(', ')}.` : '.';
    } else if (stage === 2) {
      caption += ` ${s.stats.packed} of ${s.stats.candidates} loops kept, ${s.stats.pruned} pruned.`;
    } else if (stage === 4) {
      const cycles = s.stats.cycles;
      caption += ` ${Math.floor(s.nodes.length / 3)} nodes, ${Math.floor(s.edges.length / 2)} edges, ${cycles} cycle${cycles === 1 ? '' : 's'}.`;
    }
    byTestId('sk-stage-caption').textContent = caption;
    const legend = def.legend.filter(({ layer }) => present.has(layer)).map(({ label, color }) => swatch(color, label));
    if (stage === SK_REGIONS_STAGE) {
      // One chip per region, unlabelled (the colours are what matters), after a count.
      const li = document.createElement('li');
      li.className = 'region-chips';
      li.append(`${regionColors.length} region${regionColors.length === 1 ? '' : 's'}`);
      for (const [i, color] of regionColors.entries()) {
        const chip = document.createElement('span');
        chip.className = 'swatch';
        chip.style.background = color;
        chip.title = `region ${i + 1}`;
        li.append(chip);
      }
      legend.push(li);
    }
    byTestId('sk-stage-legend').replaceChildren(...legend);
    this.stepper.show(stage, SK_STAGES.length);
  }
}
