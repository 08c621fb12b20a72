/**
 * The view in the address bar, so a link restores it: `#mesh=bob&stage=skeleton&source=812&n=40`.
 * Only options that differ from the defaults are written; anything unreadable is ignored.
 */
import { defaultOptions, optionRanges } from '../../../lib/core/options.ts';
import type { Options } from '../../../lib/core/types.ts';
import { isStageKey, type StageKey } from '../stage-defs.ts';

export interface ViewState {
  /** A sample's name (files the user opened cannot be linked to). */
  mesh: string | null;
  stage: StageKey | null;
  source: number | null;
  options: Options;
}

export function readUrl(hash = location.hash): ViewState {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const options: Options = { ...defaultOptions };
  const number = (key: keyof typeof optionRanges, integer: boolean): number | null => {
    const raw = params.get(key);
    if (raw === null || raw.trim() === '') return null;
    const x = Number(raw);
    const [lo, hi] = optionRanges[key];
    return Number.isFinite(x) && x >= lo && x <= hi && (!integer || Number.isInteger(x)) ? x : null;
  };
  const target = params.get('target');
  if (target === 'euclid' || target === 'geodesic') options.target = target;
  const sphere = params.get('sphere');
  if (sphere === 'true' || sphere === 'false') options.sphere = sphere === 'true';
  options.seed = number('seed', true) ?? options.seed;
  options.angleThreshold = number('angleThreshold', false) ?? options.angleThreshold;
  options.laplacianThreshold = number('laplacianThreshold', false) ?? options.laplacianThreshold;
  options.pruneDepth = number('pruneDepth', true) ?? options.pruneDepth;
  options.pruneLengthFactor = number('pruneLengthFactor', false) ?? options.pruneLengthFactor;
  options.n = params.get('n') === 'auto' ? 'auto' : (number('n', true) ?? options.n);
  const source = Number(params.get('source') ?? NaN);
  const stage = params.get('stage');
  const mesh = params.get('mesh');
  return {
    mesh: mesh && /^[\w-]+$/.test(mesh) ? mesh : null,
    stage: isStageKey(stage) ? stage : null,
    source: Number.isInteger(source) && source >= 0 ? source : null,
    options,
  };
}

/** Replaces the address (no history entry per click). */
export function writeUrl(state: ViewState): void {
  const params = new URLSearchParams();
  if (state.mesh) params.set('mesh', state.mesh);
  if (state.stage) params.set('stage', state.stage);
  if (state.source !== null) params.set('source', String(state.source));
  for (const key of Object.keys(defaultOptions) as Array<keyof Options>) {
    if (state.options[key] !== defaultOptions[key]) params.set(key, String(state.options[key]));
  }
  const hash = params.toString();
  if (hash !== location.hash.replace(/^#/, '')) history.replaceState(null, '', hash ? `#${hash}` : location.pathname + location.search);
}
