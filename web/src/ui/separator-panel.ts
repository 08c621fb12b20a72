/**
 * Stage 1 of CSCD-M shown step by step: the stage list (titles, captions, colours, which layers
 * belong to which stage) and the panel part with the stepper, the caption and the results.
 */
import type { SeparatorStatus } from '../../../lib/core/types.ts';
import type { SeparatorReply } from '../worker/protocol.ts';
import { byTestId, formatLength, formatMs, humanize, swatch } from './panel.ts';
import { Stepper } from './stepper.ts';

/** Layer colours (sRGB), shared by the viewer layers and the panel legend. */
export const COLORS = {
  source: '#ffffff',
  cutLocus: '#ffd21a',
  target: '#a34dff',
  path1: '#ff3131',
  path2: '#74ff2e',
  approxLoop: '#ff8c00',
  sphere: '#8fc3ff',
  loop: '#00e1ff',
} as const;

export interface StageDef {
  title: string;
  /** Paper reference. */
  section: string;
  caption: string;
  /** The stage's layers (viewer layer names) with their legend labels. */
  legend: Array<{ layer: string; label: string; color: string }>;
}

export const STAGES: readonly StageDef[] = [
  {
    title: 'Distance',
    section: 'Sec. 4.1.1',
    caption: 'Geodesic distance from the source vertex (heat method), with isolines. Every later step is read off this field.',
    legend: [{ layer: 'source', label: 'source', color: COLORS.source }],
  },
  {
    title: 'Cut locus',
    section: 'Sec. 4.1.2',
    caption:
      'Where shortest paths from the source collide: the ridges of the distance, kept as a graph on mesh vertices. On a closed surface its cycle rank is twice the genus.',
    legend: [{ layer: 'cut-locus', label: 'cut locus', color: COLORS.cutLocus }],
  },
  {
    title: 'Target & paths',
    section: 'Sec. 4.1.3–4.1.4',
    caption:
      'The target is the cut-locus point nearest to the source. From it, two steepest-descent paths run down the distance on the two sides of the cut locus until they meet.',
    legend: [
      { layer: 'target', label: 'target', color: COLORS.target },
      { layer: 'path-1', label: 'path 1', color: COLORS.path1 },
      { layer: 'path-2', label: 'path 2', color: COLORS.path2 },
    ],
  },
  {
    title: 'Approximate loop',
    section: 'Sec. 4.1.4, Alg. 3',
    caption: 'The two paths joined into one closed loop around the part the target sits on. It follows mesh edges, so it zig-zags and is too long.',
    legend: [{ layer: 'approx-loop', label: 'approximate loop', color: COLORS.approxLoop }],
  },
  {
    title: 'Constraint sphere',
    section: 'Sec. 4.1.6',
    caption: 'A sphere around the source bounds where the loop may move while it is shortened, so the separator stays local. The tinted patch is the surface inside it.',
    legend: [{ layer: 'sphere', label: 'constraint sphere', color: COLORS.sphere }],
  },
  {
    title: 'Loop',
    section: 'Sec. 4.1.5, 4.2.1',
    caption:
      'The loop after shortening by edge flips: a short closed curve that cuts the surface in two locally. Its score is A1 / (A2 · length), A1 ≤ A2 the areas on its two sides.',
    legend: [{ layer: 'loop', label: 'loop', color: COLORS.loop }],
  },
];

/** The stage that introduces each viewer layer (layers of later stages are hidden). */
export const LAYER_STAGE: Readonly<Record<string, number>> = {
  surface: 1,
  source: 1,
  'cut-locus': 2,
  target: 3,
  'path-1': 3,
  'path-2': 3,
  'approx-loop': 4,
  sphere: 5,
  loop: 6,
};

/**
 * The last stage a run got to: a failure shows the stages before it and the one that failed (the
 * loop stage when shortening failed or the loop shrank to nothing).
 */
export function reachedStage(status: SeparatorStatus): number {
  switch (status) {
    case 'no-cut-locus':
      return 1;
    case 'no-target':
      return 2;
    case 'trace-failed':
      return 3;
    case 'degenerate-loop':
    case 'shorten-failed':
    case 'ok':
      return 6;
  }
}

export class StagePanel {
  /** Called when the user asks for another stage (buttons, pills, keys). */
  onSelect: ((stage: number) => void) | null = null;
  /** Keys step the stages only while this mode is shown. */
  enabled = true;

  private readonly stepper = new Stepper(
    { prev: 'stage-prev', next: 'stage-next', steps: 'stage-steps' },
    STAGES.map((def) => def.title),
    () => this.enabled && !byTestId('separator').hidden,
  );
  private reached = 1;

  constructor() {
    this.stepper.onSelect = (stage) => this.onSelect?.(stage);
  }

  /** Shows a run's results (or hides the whole block when `reply` is null). */
  setResult(reply: SeparatorReply | null, isolineSpacing = 0): void {
    byTestId('separator').hidden = !reply;
    byTestId('distance-empty').hidden = !!reply;
    if (!reply) {
      byTestId('timing-separator').textContent = '–';
      byTestId('stage-timings').replaceChildren();
      return;
    }
    const s = reply.separator;
    this.reached = reachedStage(s.status);
    const set = (id: string, text: string) => (byTestId(id).textContent = text);
    const length = (x: number, when: boolean) => (when && Number.isFinite(x) ? formatLength(x) : '–');
    set('distance-source', String(s.source));
    set('distance-max', formatLength(reply.distanceMax));
    set('distance-spacing', isolineSpacing > 0 ? formatLength(isolineSpacing) : '–');
    set('colorbar-max', formatLength(reply.distanceMax));
    set('cut-nodes', String(s.cutLocus.vertices.length));
    set('cut-edges', String(s.cutLocus.edges.length / 2));
    set('cut-cycle-rank', this.reached >= 2 ? String(s.cutLocus.cycleRank) : '–');
    set('target-vertex', s.target === null ? '–' : String(s.target));
    set('target-attempts', s.attempts > 0 ? String(s.attempts) : '–');
    set('approx-length', length(s.approxLength, s.approxLoop.length > 0));
    set('loop-length', length(s.length, s.loop.length > 0));
    set('sphere-radius', s.sphere ? formatLength(s.sphere.radius) : reply.options.sphere ? '–' : 'off');
    const done = s.status === 'ok';
    set('areas', done ? `${formatLength(s.areas[0])} / ${formatLength(s.areas[1])}` : '–');
    set('score', done && Number.isFinite(s.score) ? formatLength(s.score) : '–');
    set('centroid-inside', done ? (s.centroidInside ? 'yes' : 'no') : '–');

    const outcome = byTestId('separator-status');
    outcome.dataset.status = s.status;
    outcome.classList.toggle('failed', !done);
    const head = document.createElement('strong');
    head.textContent = done ? 'Separator found' : `Stopped at stage ${this.reached} · ${s.status}`;
    const body = document.createElement('span');
    body.textContent = done
      ? `Loop of length ${formatLength(s.length)} around the part the target lies on.`
      : s.message || 'The core gave no reason.';
    outcome.replaceChildren(head, body);

    set('timing-separator', formatMs(reply.timings.separatorMs));
    byTestId('stage-timings').replaceChildren(
      ...Object.entries(s.timings).flatMap(([key, ms]) => {
        const dt = document.createElement('dt');
        dt.textContent = humanize(key);
        const dd = document.createElement('dd');
        dd.dataset.testid = `timing-stage-${key}`;
        dd.textContent = Number.isFinite(ms) ? formatMs(ms) : '–';
        return [dt, dd];
      }),
    );
  }

  /** The stage shown; `present`: the layers the run has data for (the legend lists only those). */
  setStage(stage: number, reply: SeparatorReply, present: ReadonlySet<string>): void {
    const def = STAGES[stage - 1];
    const s = reply.separator;
    document.body.dataset.stage = String(stage);
    byTestId('stage-index').textContent = String(stage);
    byTestId('stage-title').textContent = def.title;
    byTestId('stage-section').textContent = def.section;
    let caption = def.caption;
    if (stage === 5 && !s.sphere) caption += ' The constraint is switched off: the loop was shortened without it.';
    if (stage === 3 && s.target !== null) {
      caption += ` Chosen ${reply.options.target === 'euclid' ? 'in space (Euclidean)' : 'along the surface (geodesic)'}`;
      caption += s.attempts > 1 ? `; ${s.attempts} targets were tried, the loops of the nearer ones enclosed nothing.` : '.';
    }
    if (stage === this.reached && s.status !== 'ok') caption += ` Stage 1 stopped here: ${s.message || s.status}.`;
    byTestId('stage-caption').textContent = caption;
    const legend = def.legend.filter(({ layer }) => present.has(layer));
    byTestId('stage-legend').replaceChildren(...legend.map(({ label, color }) => swatch(color, label)));
    byTestId('stage-card').classList.toggle('failed', stage === this.reached && s.status !== 'ok');

    this.stepper.show(stage, this.reached);
  }

  get reachedStage(): number {
    return this.reached;
  }
}
