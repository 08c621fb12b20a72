/**
 * Wiring: files -> worker (parse, inspect, prepare) -> viewer + panel. Two modes: "One source"
 * (clicks -> worker: stage 1 of CSCD-M from the picked vertex -> layers shown stage by stage) and
 * "Whole shape" (whole-shape.ts: the whole pipeline with progress and cancel -> skeleton views).
 * `document.body.dataset.state` is loading | ready | computing | error, `dataset.mode` single | whole,
 * `dataset.stage` the stage shown and `dataset.separatorRuns` counts the stage-1 replies shown, for tests.
 */
import './style.css';
import { defaultOptions } from '../../lib/core/options.ts';
import type { Options } from '../../lib/core/types.ts';
import { MESH_EXTENSIONS } from '../../lib/io/index.ts';
import { niceSpacing } from './viewer/colormap.ts';
import { SpheresLayer, SurfaceLayer } from './viewer/layers.ts';
import { separatorLayers } from './viewer/separator-layers.ts';
import { Viewer, type Pick } from './viewer/viewer.ts';
import { GeometryClient, WorkerError } from './worker/client.ts';
import type { OpenedReply, SeparatorReply } from './worker/protocol.ts';
import { installFileSources } from './ui/files.ts';
import { Panel } from './ui/panel.ts';
import { COLORS, LAYER_STAGE, STAGES, StagePanel } from './ui/stages.ts';
import { SkeletonPanel } from './ui/skeleton-panel.ts';
import { WholeShape, isSkeletonLayer } from './whole-shape.ts';

const SAMPLE = 'samples/spot.ply';

const panel = new Panel();
const viewer = new Viewer(document.querySelector<HTMLElement>('#viewport')!);
const flatBox = document.querySelector<HTMLInputElement>('#opt-flat')!;
const isolinesBox = document.querySelector<HTMLInputElement>('#opt-isolines')!;
const targetSelect = document.querySelector<HTMLSelectElement>('#opt-target')!;
const sphereBox = document.querySelector<HTMLInputElement>('#opt-sphere')!;
const stagePanel = new StagePanel();
const optionsHint = document.querySelector<HTMLElement>('#options-hint')!;
const viewportHint = document.querySelector<HTMLElement>('#viewport-hint')!;

type Mode = 'single' | 'whole';
let mode: Mode = 'single';

let opening = 0;
let computing = 0;
let failed = false;
/** Bumped whenever a different mesh is shown, so late replies for the old one are dropped. */
let meshGeneration = 0;
let latestSeparatorRequest = 0;

/** The stage-1 run shown, the stage shown, and the layers the user switched off. */
let separator: SeparatorReply | null = null;
let stage = 1;
/** The stage the user stepped to; a run that stopped earlier shows its last stage, the next run this one again. */
let wantedStage = 1;
const userHidden = new Set<string>();
const layerColors = new Map<string, string>([['source', COLORS.source]]);
let separatorRuns = 0;

function updateState(): void {
  const state = opening > 0 ? 'loading' : computing > 0 ? 'computing' : failed ? 'error' : 'ready';
  viewer.flush(); // pixels match the state tests wait for
  document.body.dataset.state = state;
  if (state === 'ready' || state === 'error') panel.setStatus(viewer.surface ? 'Ready' : 'No mesh open');
}

function fail(title: string, error: unknown): void {
  failed = true;
  panel.showError(title, error instanceof Error ? error.message : String(error));
}

function startAction(status: string): void {
  failed = false;
  panel.clearError();
  panel.setStatus(status, true);
}

/** Shows the worker being replaced until the mesh is open in the new one. */
function awaitRestart(restored: Promise<unknown>): void {
  opening++;
  panel.setStatus('restarting the geometry worker…', true);
  updateState();
  restored
    .catch((error: unknown) => fail('Could not re-open the mesh after the restart', error))
    .finally(() => {
      opening--;
      updateState();
    });
}

const client = new GeometryClient({
  onProgress: (event) => panel.setStatus(event.message, true),
  onCrash: (message, restored) => {
    failed = true;
    panel.showError('The geometry worker stopped and was restarted', message);
    awaitRestart(restored);
  },
  // The worker was replaced to stop a cancelled run: the mesh is re-opened, no error to show.
  onRestart: awaitRestart,
});

// -- opening meshes ------------------------------------------------------------------------------

async function openBytes(fileName: string, bytes: ArrayBuffer): Promise<void> {
  whole.cancel(); // a running skeleton would hold up the open
  opening++;
  startAction(`opening ${fileName}…`);
  updateState();
  try {
    showMesh(await client.open(fileName, bytes));
  } catch (error) {
    // A crash is reported by onCrash; the previous mesh stays either way.
    if (!(error instanceof WorkerError && error.kind === 'crash')) fail(`Could not open ${fileName}`, error);
  } finally {
    opening--;
    updateState();
  }
}

function showMesh(reply: OpenedReply): void {
  meshGeneration++;
  separator = null;
  stage = 1;
  wantedStage = 1;
  userHidden.clear();
  stagePanel.setResult(null);
  delete document.body.dataset.stage;
  viewer.clearLayers();
  viewer.setLayer('surface', new SurfaceLayer(reply.positions, reply.triangles));
  viewer.surface!.setFlatShading(flatBox.checked);
  viewer.surface!.setIsolines(isolinesBox.checked);
  whole.reset();
  viewer.frame();

  panel.setFile(reply.fileName, reply.format);
  panel.setFacts(reply.facts);
  const notes = [...reply.warnings];
  const { degenerateFaces, unreferencedVertices } = reply.facts;
  if (degenerateFaces) notes.push(`${degenerateFaces} degenerate face${degenerateFaces > 1 ? 's' : ''} (repeated vertex or zero area)`);
  if (unreferencedVertices) notes.push(`${unreferencedVertices} ${unreferencedVertices > 1 ? 'vertices' : 'vertex'} used by no face`);
  if (reply.surfaceError) notes.push(`Geodesic distance is unavailable: ${reply.surfaceError}`);
  panel.setNotes(notes);
  panel.setTimings(reply.timings);
}

async function openFile(file: File): Promise<void> {
  let bytes: ArrayBuffer;
  try {
    bytes = await file.arrayBuffer();
  } catch (error) {
    fail(`Could not read ${file.name}`, error);
    updateState();
    return;
  }
  await openBytes(file.name, bytes);
}

async function openSample(): Promise<void> {
  const name = SAMPLE.split('/').pop()!;
  try {
    const response = await fetch(SAMPLE);
    if (!response.ok) throw new Error(`HTTP ${response.status} for ${SAMPLE}`);
    await openBytes(name, await response.arrayBuffer());
  } catch (error) {
    fail(`Could not load the sample mesh ${name}`, error);
    updateState();
  }
}

// -- stage 1: one separator from the picked vertex ---------------------------------------------

/** Names of the layers a stage-1 run adds (besides the surface's colormap and the source marker). */
const SEPARATOR_LAYERS = Object.keys(LAYER_STAGE).filter((name) => name !== 'surface' && name !== 'source');

function currentOptions(): Options {
  return { ...defaultOptions, target: targetSelect.value as Options['target'], sphere: sphereBox.checked };
}

/** Only the options that differ from the defaults travel to the worker. */
function changedOptions(): Partial<Options> {
  const options = currentOptions();
  return Object.fromEntries(
    (Object.keys(options) as Array<keyof Options>).filter((k) => options[k] !== defaultOptions[k]).map((k) => [k, options[k]]),
  ) as Partial<Options>;
}

async function runSeparator(source: number): Promise<void> {
  const surface = viewer.surface;
  if (!surface || opening > 0) return;
  const generation = meshGeneration;
  const request = ++latestSeparatorRequest;
  if (separator?.separator.source !== source) {
    const radius = surface.boundingSphere.radius * 0.022;
    viewer.setLayer('source', new SpheresLayer('Source vertex', surface.vertexPosition(source).toArray(), radius));
  }

  computing++;
  startAction('computing stage 1…');
  updateState();
  try {
    const reply = await client.separator(source, changedOptions());
    if (generation !== meshGeneration || request !== latestSeparatorRequest) return; // superseded
    showSeparator(reply);
  } catch (error) {
    if (generation !== meshGeneration || request !== latestSeparatorRequest) return;
    clearSeparator();
    if (!(error instanceof WorkerError && error.kind === 'crash')) fail('Could not compute stage 1 (geodesic distance)', error);
  } finally {
    computing--;
    updateState();
  }
}

function showSeparator(reply: SeparatorReply): void {
  const surface = viewer.surface!;
  const s = reply.separator;
  const spacing = niceSpacing(reply.distanceMax);
  surface.setScalarField({ values: s.distance, max: reply.distanceMax, isolineSpacing: spacing });
  for (const name of SEPARATOR_LAYERS) viewer.setLayer(name, null);
  for (const { name, layer, color } of separatorLayers(s, surface)) {
    layerColors.set(name, color);
    viewer.setLayer(name, layer);
  }
  separator = reply;
  stagePanel.setResult(reply, spacing);
  document.body.dataset.separatorRuns = String(++separatorRuns);
  showStage(wantedStage);
}

/** The options the shown stage-1 run used differ from the current ones (changed in the other mode). */
function separatorStale(): boolean {
  if (!separator) return false;
  const now = currentOptions();
  return separator.options.target !== now.target || separator.options.sphere !== now.sphere;
}

function clearSeparator(): void {
  separator = null;
  for (const name of [...SEPARATOR_LAYERS, 'source']) viewer.setLayer(name, null);
  viewer.surface?.setScalarField(null);
  viewer.surface?.setDimmed(false);
  viewer.surface?.setRegion(null);
  stagePanel.setResult(null);
  delete document.body.dataset.stage;
  viewer.requestRender();
}

/** Shows layers up to `wanted` (clamped to the stages the run reached), earlier ones dimmed. */
function showStage(wanted: number): void {
  if (!separator) return;
  stage = Math.min(Math.max(1, wanted), stagePanel.reachedStage, STAGES.length);
  if (mode !== 'single') {
    // A reply that arrived after the switch to the whole-shape mode: shown when the user comes back.
    stagePanel.setStage(stage, separator, new Set(viewer.listLayers().map(([name]) => name)));
    whole.apply();
    return;
  }
  for (const [name, layer] of viewer.listLayers()) {
    if (isSkeletonLayer(name)) {
      layer.object.visible = false;
      continue;
    }
    const introduced = LAYER_STAGE[name] ?? 1;
    layer.object.visible = introduced <= stage && !userHidden.has(name);
    // The source marker stays bright; the surface dims its colormap once lines are drawn on it.
    layer.setDimmed?.(name !== 'source' && introduced < stage);
  }
  // The constraint region on the surface goes with the sphere layer.
  const sphere = separator.separator.sphere;
  const sphereShown = !!sphere && stage >= LAYER_STAGE.sphere && !userHidden.has('sphere');
  viewer.surface?.setRegion(sphereShown ? sphere : null, stage > LAYER_STAGE.sphere ? 0.35 : 1);
  stagePanel.setStage(stage, separator, new Set(viewer.listLayers().map(([name]) => name)));
  updateLayerList();
  viewer.requestRender();
}

stagePanel.onSelect = (wanted) => {
  if (!separator) return;
  showStage(wanted);
  wantedStage = stage;
};
viewer.onPick = (pick: Pick) => {
  if (mode === 'single') void runSeparator(pick.vertex);
};

function rerun(): void {
  if (separator && mode === 'single') void runSeparator(separator.separator.source);
}
targetSelect.addEventListener('change', rerun);
sphereBox.addEventListener('change', rerun);
targetSelect.value = defaultOptions.target;
sphereBox.checked = defaultOptions.sphere;

/** The layer list shows the layers of the stages up to the one shown. */
function updateLayerList(): void {
  if (mode === 'whole') {
    panel.setLayers(whole.layerEntries(), (name, visible) => {
      if (visible) userHidden.delete(name);
      else userHidden.add(name);
      if (name === 'surface') viewer.setLayerVisible(name, visible);
      else whole.apply();
    });
    return;
  }
  const shown = viewer
    .listLayers()
    .filter(([name]) => !isSkeletonLayer(name) && (!separator || (LAYER_STAGE[name] ?? 1) <= stage));
  panel.setLayers(
    shown.map(([name, layer]) => ({
      name,
      label: layer.label,
      visible: !userHidden.has(name),
      color: layerColors.get(name),
      dimmed: !!separator && name !== 'source' && (LAYER_STAGE[name] ?? 1) < stage,
    })),
    (name, visible) => {
      if (visible) userHidden.delete(name);
      else userHidden.add(name);
      if (separator) showStage(stage);
      else viewer.setLayerVisible(name, visible);
    },
  );
}

// -- whole shape ----------------------------------------------------------------------------------

const whole = new WholeShape(
  {
    viewer,
    client,
    userHidden,
    layerColors,
    baseOptions: currentOptions,
    begin: (status) => {
      computing++;
      startAction(status);
      updateState();
    },
    end: () => {
      computing--;
      updateState();
    },
    fail,
    setStatus: (text) => panel.setStatus(text, true),
    updateLayerList,
  },
  new SkeletonPanel(defaultOptions),
);

const HINTS: Record<Mode, { viewport: string; options: string }> = {
  single: {
    viewport: 'Click the surface to run stage 1 from that vertex · ←/→ step through stages · drag to orbit · right-drag to pan · scroll to zoom',
    options: 'Changes re-run stage 1 for the current source.',
  },
  whole: {
    viewport: 'Compute the skeleton in the panel · ←/→ step through the views · drag to orbit · right-drag to pan · scroll to zoom',
    options: 'Used by the next skeleton run (with N and the seed above).',
  },
};

function setMode(next: Mode): void {
  if (next === mode) return;
  mode = next;
  document.body.dataset.mode = mode;
  for (const tab of document.querySelectorAll<HTMLButtonElement>('.mode-tab')) {
    const selected = tab.dataset.mode === mode;
    tab.classList.toggle('selected', selected);
    tab.setAttribute('aria-selected', String(selected));
  }
  for (const section of document.querySelectorAll<HTMLElement>('[data-mode-section]')) section.hidden = section.dataset.modeSection !== mode;
  viewportHint.textContent = HINTS[mode].viewport;
  optionsHint.textContent = HINTS[mode].options;
  stagePanel.enabled = mode === 'single';
  if (mode === 'whole') {
    whole.activate();
    return;
  }
  whole.deactivate();
  viewer.surface?.setScalarVisible(true);
  if (separatorStale()) rerun();
  if (separator) showStage(stage);
  else {
    for (const [name, layer] of viewer.listLayers()) if (isSkeletonLayer(name)) layer.object.visible = false;
    updateLayerList();
  }
  viewer.requestRender();
}

for (const tab of document.querySelectorAll<HTMLButtonElement>('.mode-tab')) {
  tab.addEventListener('click', () => setMode(tab.dataset.mode as Mode));
}
document.body.dataset.mode = mode;

// -- panel controls ------------------------------------------------------------------------------

flatBox.addEventListener('change', () => {
  viewer.surface?.setFlatShading(flatBox.checked);
  viewer.requestRender();
});
isolinesBox.addEventListener('change', () => {
  viewer.surface?.setIsolines(isolinesBox.checked);
  viewer.requestRender();
});
document.querySelector('#reset-view')!.addEventListener('click', () => viewer.frame());
viewer.onLayersChange = updateLayerList;

document.querySelector('#formats-hint')!.textContent = `or drop ${MESH_EXTENSIONS.join(' ')} anywhere`;
installFileSources({
  button: document.querySelector<HTMLButtonElement>('#open-button')!,
  input: document.querySelector<HTMLInputElement>('#file-input')!,
  overlay: document.querySelector<HTMLElement>('#drop-overlay')!,
  extensions: MESH_EXTENSIONS,
  onFile: (file) => void openFile(file),
});

/** For end-to-end tests and the console. */
declare global {
  interface Window {
    cscd?: {
      simulateCrash(how?: 'abort' | 'uncaught' | 'hang'): Promise<void>;
      projectVertex(index: number): { x: number; y: number } | null;
      /** Camera along `direction` (towards the camera) at a sphere around `center` (default: the mesh). */
      setView(view: { direction?: [number, number, number]; center?: [number, number, number]; radius?: number }): void;
    };
  }
}
window.cscd = {
  simulateCrash: (how) => client.simulateCrash(how).catch(() => undefined),
  projectVertex: (index) => viewer.projectVertex(index),
  setView: ({ direction, center, radius }) => {
    const v = (a?: [number, number, number]) => (a ? { x: a[0], y: a[1], z: a[2] } : undefined);
    viewer.frame({ direction: v(direction), center: v(center), radius });
    viewer.flush();
  },
};

void openSample();
