/**
 * The view in the address bar, so a link restores it: `#mesh=bob&stage=skeleton&source=812&n=40`, and
 * `asCloud=1` for a sample run as a point cloud. Only options and run settings that differ from the
 * defaults are written; anything unreadable is ignored.
 */
import { defaultOptions, defaultRunSettings, MESH_OPTIONS, parseOptionText, parseSettingText, SETTINGS, type RunSettings } from '../../../lib/core/options.ts';
import { AS_CLOUD } from '../../../lib/cloud/from-mesh.ts';
import type { Options } from '../../../lib/core/types.ts';
import { isStageKey, type StageKey } from '../stage-defs.ts';

export interface ViewState {
  /** A sample's name (files the user opened cannot be linked to). */
  mesh: string | null;
  /** The sample runs as a point cloud of its vertices. */
  asCloud: boolean;
  stage: StageKey | null;
  source: number | null;
  options: Options;
  settings: RunSettings;
}

export function readUrl(hash = location.hash): ViewState {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const options: Record<string, unknown> = { ...defaultOptions };
  for (const spec of MESH_OPTIONS) {
    const raw = params.get(spec.key);
    const value = raw === null ? null : parseOptionText(spec, raw.trim());
    if (value !== null) options[spec.key] = value;
  }
  const settings: Record<string, unknown> = { ...defaultRunSettings };
  for (const spec of SETTINGS) {
    const value = parseSettingText(spec, params.get(spec.key)?.trim() ?? '');
    if (value !== null) settings[spec.key] = value;
  }
  const source = Number(params.get('source') ?? NaN);
  const stage = params.get('stage');
  const mesh = params.get('mesh');
  return {
    mesh: mesh && /^[\w-]+$/.test(mesh) ? mesh : null,
    asCloud: params.get(AS_CLOUD.key) === '1',
    stage: isStageKey(stage) ? stage : null,
    source: Number.isInteger(source) && source >= 0 ? source : null,
    options: options as unknown as Options,
    settings: settings as unknown as RunSettings,
  };
}

/** Replaces the address (no history entry per click). */
export function writeUrl(state: ViewState): void {
  const params = new URLSearchParams();
  if (state.mesh) params.set('mesh', state.mesh);
  if (state.mesh && state.asCloud) params.set(AS_CLOUD.key, '1');
  if (state.stage) params.set('stage', state.stage);
  if (state.source !== null) params.set('source', String(state.source));
  for (const key of Object.keys(defaultOptions) as Array<keyof Options>) {
    if (state.options[key] !== defaultOptions[key]) params.set(key, String(state.options[key]));
  }
  for (const { key } of SETTINGS) if (state.settings[key] !== defaultRunSettings[key]) params.set(key, String(state.settings[key]));
  const hash = params.toString();
  if (hash !== location.hash.replace(/^#/, '')) history.replaceState(null, '', hash ? `#${hash}` : location.pathname + location.search);
}
