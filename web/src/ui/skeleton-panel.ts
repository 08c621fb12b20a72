/**
 * The whole-shape part of the panel: Compute / Cancel, the progress bar, the run's outcome, the
 * result's figures and timings, the reconstruction error's figures, and what the captions of the
 * whole-shape stages add about the result.
 */
import type { CandidateFate } from '../../../lib/core/types.ts';
import type { StageKey } from '../stage-defs.ts';
import type { EvaluationReply, SkeletonReply } from '../worker/protocol.ts';
import { colormapGradient } from '../viewer/colormap.ts';
import { byTestId, formatMs, timingRows } from './panel.ts';

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

  private readonly compute = byTestId<HTMLButtonElement>('sk-compute');
  private readonly cancel = byTestId<HTMLButtonElement>('sk-cancel');
  private readonly progress = byTestId('sk-progress');
  private readonly fill = this.progress.querySelector<HTMLElement>('.progress-fill')!;
  private readonly track = this.progress.querySelector<HTMLElement>('.progress-track')!;

  constructor() {
    byTestId('sk-recon-colorbar').style.background = colormapGradient();
    this.compute.addEventListener('click', () => this.onCompute?.());
    this.cancel.addEventListener('click', () => this.onCancel?.());
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

  /** The reply is in and its layers are being built: Cancel has nothing left to stop. */
  drawing(): void {
    this.cancel.disabled = true;
    byTestId('sk-progress-phase').textContent = 'drawing the skeleton…';
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
    this.compute.textContent = reply ? 'Compute again' : 'Compute skeleton';
    byTestId('sk-empty').hidden = !!reply || !byTestId('sk-progress').hidden;
    if (!reply) {
      for (const id of ['sk-timing-stage1', 'sk-timing-stage2']) byTestId(id).textContent = '–';
      byTestId('sk-timings').replaceChildren();
      return;
    }
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
    byTestId('sk-timings').replaceChildren(...timingRows(s.stats.timings, 'sk-timing-'));
  }

  /**
   * The reconstruction block: off (no evaluation yet), busy, failed, or the figures of an
   * evaluation; `max` is the error at the top of the colour bar.
   */
  setRecon(state: { kind: 'off' } | { kind: 'busy' } | { kind: 'failed'; message: string } | { kind: 'done'; reply: EvaluationReply; max: number }): void {
    const status = byTestId('sk-recon-status');
    const result = byTestId('sk-recon-result');
    status.hidden = state.kind !== 'busy' && state.kind !== 'failed';
    status.textContent = state.kind === 'busy' ? 'Reconstructing the surface from the skeleton…' : state.kind === 'failed' ? state.message : '';
    status.classList.toggle('error-text', state.kind === 'failed');
    result.hidden = state.kind !== 'done';
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

  /** What the caption of a whole-shape stage adds about this result. */
  static caption(key: StageKey, reply: SkeletonReply): string {
    const s = reply.skeleton;
    if (key === 'separators') {
      const counts = new Map<CandidateFate, number>();
      for (const f of s.candidates.fates) counts.set(f, (counts.get(f) ?? 0) + 1);
      const rejected = [...counts].filter(([f]) => f !== 'packed').map(([f, n]) => `${n} ${FATE_TEXT[f]}`);
      return ` ${s.candidates.fates.length} sources (seed ${s.stats.seed}): ${counts.get('packed') ?? 0} packed${rejected.length ? `; rejected: ${rejected.join(', ')}` : ''}.`;
    }
    if (key === 'packing') return ` ${s.stats.packed} of ${s.stats.candidates} loops kept, ${s.stats.pruned} pruned.`;
    if (key === 'skeleton') {
      const cycles = s.stats.cycles;
      return ` ${Math.floor(s.nodes.length / 3)} nodes, ${Math.floor(s.edges.length / 2)} edges, ${cycles} cycle${cycles === 1 ? '' : 's'}.`;
    }
    return '';
  }

  /** The time of each whole-shape stage (worker wall time of stage 1, the core's times of stage 2). */
  static stageTimes(reply: SkeletonReply): Partial<Record<StageKey, number>> {
    const t = reply.skeleton.stats.timings;
    // Bands belong to both the Regions stage (the pieces) and the Skeleton stage (their nodes): counted with the graph.
    return { separators: reply.timings.stage1Ms, packing: (t.prune ?? 0) + (t.pack ?? 0), regions: t.regions, skeleton: (t.graph ?? 0) + (t.bands ?? 0) };
  }
}
