/** The panel's figures of one stage-1 run (the source stages), and what its captions add per stage. */
import type { SeparatorStatus } from '../../../lib/core/types.ts';
import type { StageKey } from '../stage-defs.ts';
import type { SeparatorReply } from '../worker/protocol.ts';
import { byTestId, formatLength, formatMs, humanize, timingRows } from './panel.ts';

/**
 * The last stage a run got to: a failure shows the stages before it and the one that failed (the
 * loop stage when shortening failed or the loop shrank to nothing).
 */
export function reachedStage(status: SeparatorStatus): StageKey {
  switch (status) {
    case 'no-cut-locus':
      return 'geodesics';
    case 'no-target':
      return 'cut-locus';
    case 'trace-failed':
      return 'paths';
    case 'degenerate-loop':
    case 'shorten-failed':
    case 'not-separating':
    case 'ok':
      return 'loop';
  }
}

/** Shows a run's results (or hides the block when `reply` is null). */
export function showSeparatorFigures(reply: SeparatorReply | null, isolineSpacing = 0): void {
  byTestId('separator').hidden = !reply;
  byTestId('distance-empty').hidden = !!reply;
  if (!reply) {
    byTestId('timing-separator').textContent = '–';
    byTestId('stage-timings').replaceChildren();
    return;
  }
  const s = reply.separator;
  const reached = reachedStage(s.status);
  const set = (id: string, text: string) => (byTestId(id).textContent = text);
  const length = (x: number, when: boolean) => (when && Number.isFinite(x) ? formatLength(x) : '–');
  set('distance-source', String(s.source));
  set('distance-max', formatLength(reply.distanceMax));
  set('distance-spacing', isolineSpacing > 0 ? formatLength(isolineSpacing) : '–');
  set('colorbar-max', formatLength(reply.distanceMax));
  set('cut-nodes', String(s.cutLocus.vertices.length));
  set('cut-edges', String(s.cutLocus.edges.length / 2));
  set('cut-cycle-rank', reached !== 'geodesics' ? String(s.cutLocus.cycleRank) : '–');
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
  head.textContent = done ? 'Separator found' : `Stopped at ${humanize(reached)} · ${s.status}`;
  const body = document.createElement('span');
  const what = s.closed
    ? `Loop of length ${formatLength(s.length)} around the part the target lies on.`
    : `Path of length ${formatLength(s.length)} across the sheet, between two points of its boundary.`;
  body.textContent = done ? what : s.message || 'The core gave no reason.';
  outcome.replaceChildren(head, body);

  set('timing-separator', formatMs(reply.timings.separatorMs));
  byTestId('stage-timings').replaceChildren(...timingRows(s.timings, 'timing-stage-'));
}

/** What the caption of a source stage adds about this run (its choices, where it stopped). */
export function separatorCaption(key: StageKey, reply: SeparatorReply): string {
  const s = reply.separator;
  let extra = '';
  if (key === 'paths' && s.ends !== null) extra += ' Here the nearest were two boundary points facing each other: the separator is an open path.';
  if (key === 'paths' && s.target !== null) {
    extra += ` Chosen ${reply.options.target === 'euclid' ? 'in space (Euclidean)' : 'along the surface (geodesic)'}`;
    extra += s.attempts > 1 ? `; ${s.attempts} targets were tried, the loops of the nearer ones enclosed nothing.` : '.';
  }
  if (key === 'loop' && !s.sphere) extra += ' The sphere constraint is switched off: the loop was shortened without it.';
  if (key === 'loop' && !s.closed) extra += ' Here the separator is an open path: its two ends stay on the boundary while the edge flips shorten it.';
  if (key === reachedStage(s.status) && s.status !== 'ok') extra += ` Stage 1 stopped here: ${s.message || s.status}.`;
  return extra;
}

/** The stage-1 times per timeline stage (the core's own per-step times). */
export function separatorStageTimes(reply: SeparatorReply): Partial<Record<StageKey, number>> {
  const t = reply.separator.timings;
  return { geodesics: t.distance, 'cut-locus': t.cutLocus, paths: t.target, loop: (t.loop ?? 0) + (t.measures ?? 0) };
}
