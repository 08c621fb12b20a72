/**
 * Wiring: files and samples -> worker (parse, inspect, prepare) -> viewer + panel, and the stage
 * timeline. The timeline's stages (stage-defs.ts) are views over two controllers: SingleSource (stage
 * 1 from one clicked or random vertex) and WholeShape (the whole pipeline). Entering a stage computes
 * what it needs; changing a parameter re-runs only what depends on it; the address bar keeps the view.
 *
 * `document.body.dataset.state` is loading | ready | computing | error, `dataset.stage` the stage shown
 * and `dataset.separatorRuns` counts the stage-1 replies shown, for tests.
 */
import './style.css';
import { AS_CLOUD } from '../../lib/cloud/from-mesh.ts';
import { scanLineSubsample, scanLineWarning } from '../../lib/cloud/scan-lines.ts';
import { SHAPE_EXTENSIONS } from '../../lib/io/index.ts';
import { SingleSource } from './single-source.ts';
import { STAGES, SOURCE_STAGES, stageDef, stageIndex, type StageKey } from './stage-defs.ts';
import type { StudioContext } from './studio-context.ts';
import { baseName, canvasPng, saveFile } from './ui/downloads.ts';
import { installFileSources } from './ui/files.ts';
import { DEFAULT_SAMPLE, installGallery, markSample, sampleByName, type Sample } from './ui/gallery.ts';
import { LimitOffer } from './ui/limit-offer.ts';
import { Panel, byTestId, formatMs, swatch } from './ui/panel.ts';
import { ParamsPanel, STAGE1_OPTIONS } from './ui/params.ts';
import { separatorCaption, separatorStageTimes } from './ui/separator-panel.ts';
import { SkeletonPanel } from './ui/skeleton-panel.ts';
import { Timeline, type PillState } from './ui/timeline.ts';
import { progressTextMs } from './ui/throttle.ts';
import { readUrl, writeUrl } from './ui/url-state.ts';
import { PointsLayer, SurfaceLayer, type ShapeLayer } from './viewer/layers.ts';
import { Viewer } from './viewer/viewer.ts';
import { WholeShape } from './whole-shape.ts';
import { GeometryClient, WorkerError } from './worker/client.ts';
import { CORE_MEMORY } from '../../lib/core/pool-size.ts';
import type { CloudFacts, Refinement } from '../../lib/core/types.ts';
import type { CloudOpenedReply, DecimatedReply, OpenChoice, OpenedReply, SkeletonReply, WriteRequest } from './worker/protocol.ts';

const initial = readUrl();
const panel = new Panel(() => progressTextMs(viewer.software));
const offer = new LimitOffer();
const statusCancel = byTestId<HTMLButtonElement>('status-cancel');
/** Runs the open mesh as a point cloud of its vertices, or as the mesh again. */
const asCloudBox = byTestId<HTMLInputElement>('as-cloud');
const subsampleLines = byTestId<HTMLButtonElement>('subsample-lines');
const viewer = new Viewer(document.querySelector<HTMLElement>('#viewport')!);
const timeline = new Timeline(document.querySelector<HTMLElement>('#timeline')!);
const params = new ParamsPanel(document.querySelector<HTMLElement>('#params')!, initial.options, initial.settings);
const flatBox = document.querySelector<HTMLInputElement>('#opt-flat')!;
const isolinesBox = document.querySelector<HTMLInputElement>('#opt-isolines')!;
const viewportHint = document.querySelector<HTMLElement>('#viewport-hint')!;
const gallery = document.querySelector<HTMLElement>('#gallery')!;

/** The stage the user chose (a source stage a run did not reach shows the last one it did). */
let wanted: StageKey = 'mesh';
/** Layers the user switched off in the layer list. */
const userHidden = new Set<string>();
const layerColors = new Map<string, string>();
let opening = 0;
let computing = 0;
let failed = false;
/** The choices a file is opened with besides the panel's `neighbours`: a cloud on all its points or on a subsample, a mesh as a cloud. */
type FileChoice = Omit<OpenChoice, 'neighbours'>;
const AS_GIVEN: FileChoice = Object.freeze({ allPoints: false, asCloud: false, subsample: null });
/** How the open file was opened, and how to open it again with other choices (or other neighbours). */
type OpenedFile = { choice: FileChoice; reopen: (choice: FileChoice) => Promise<boolean> };
/**
 * The open mesh or point cloud: whether it is a cloud (a cloud file, or a mesh run as one), how its
 * file was opened, its file name, the sample it is (null: a file of the user's), why it cannot be
 * computed on, its notes (parser warnings, repairs), its faces and the count it was decimated from (or null).
 */
let mesh: {
  cloud: boolean;
  file: OpenedFile;
  fileName: string;
  sample: string | null;
  surfaceError: string | null;
  openMs: number;
  notes: string[];
  faces: number;
  decimatedFrom: number | null;
} | null = null;

function updateState(): void {
  const state = opening > 0 ? 'loading' : computing > 0 ? 'computing' : failed ? 'error' : 'ready';
  viewer.flush(); // pixels match the state tests wait for
  document.body.dataset.state = state;
  statusCancel.hidden = computing === 0;
  statusCancel.disabled = false;
  asCloudBox.disabled = opening > 0;
  if (state === 'ready' || state === 'error') {
    const decimated = mesh?.decimatedFrom ? ` · decimated from ${mesh.decimatedFrom} to ${mesh.faces} faces` : '';
    panel.setStatus(viewer.surface ? `Ready${decimated}` : 'No mesh open');
  }
}

function fail(title: string, error: unknown): void {
  failed = true;
  panel.showError(title, error instanceof Error ? error.message : String(error));
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

/** Test hooks: `?memoryLimitMB=N` caps the WASM cores' memory, `?separatorCrash=N` aborts the first separator worker on its Nth request (see GeometryClient). */
const search = new URLSearchParams(location.search);
const testHooks = { memoryLimitMB: Number(search.get('memoryLimitMB')) || null, separatorCrash: Number(search.get('separatorCrash')) || null };

const client = new GeometryClient({
  onProgress: (event) => {
    panel.setProgressStatus(event.message);
    if (event.solverMs !== undefined) panel.setTimings({ prepareMs: event.solverMs });
  },
  onCrash: (message, restored) => {
    failed = true;
    panel.showError('The geometry worker stopped and was restarted', message);
    whole.invalidate(); // the new worker does not have the skeleton any more
    awaitRestart(restored);
  },
  // The worker was replaced to stop a cancelled run or to free its memory: the mesh is re-opened, no
  // error to show here. A skeleton it held is gone (a run being cancelled reports that itself).
  onRestart: (restored) => {
    if (!whole.running) whole.invalidate();
    awaitRestart(restored);
  },
}, testHooks);
const ctx: StudioContext = {
  viewer,
  client,
  layerColors,
  options: () => params.options,
  settings: () => params.settings,
  begin: (status) => {
    computing++;
    failed = false;
    panel.clearError();
    panel.setStatus(status, true);
    updateState();
  },
  end: () => {
    computing--;
    updateState();
  },
  fail,
  changed: () => refresh(),
  progressed: () => {
    timeline.show(shownStage(), pillStates());
    updateTimes();
  },
};

const single = new SingleSource(ctx);
const whole = new WholeShape(ctx);

// -- opening meshes ------------------------------------------------------------------------------

async function openBytes(
  fileName: string,
  bytes: ArrayBuffer,
  sample: string | null,
  reopen: (choice: FileChoice) => Promise<boolean>,
  choice: FileChoice,
): Promise<boolean> {
  if (whole.running) whole.invalidate(); // it would hold up the open; a finished result stays if the file is refused
  opening++;
  failed = false;
  panel.clearError();
  panel.setStatus(`opening ${fileName}…`, true);
  updateState();
  try {
    const reply = await client.open(fileName, bytes, { neighbours: params.neighbours, ...choice });
    if (reply.shape === 'cloud') showCloud(reply, sample, { choice, reopen });
    else showMesh(reply, sample, { choice, reopen });
    return true;
  } catch (error) {
    // A crash is reported by onCrash; the previous mesh stays either way.
    if (!(error instanceof WorkerError && error.kind === 'crash')) fail(`Could not open ${fileName}`, error);
    return false;
  } finally {
    opening--;
    updateState();
    refresh();
  }
}

/** The parser's warnings and the repairs (or a cloud's checks) on load, for the notes. */
const fileNotes = (reply: OpenedReply | CloudOpenedReply) => [...reply.warnings, ...reply.repairs.map((repair) => `Repaired: ${repair}`)];

function showMesh(reply: OpenedReply, sample: string | null, file: OpenedFile): void {
  const t = reply.timings;
  const notes = fileNotes(reply);
  const { degenerateFaces, unreferencedVertices, faces } = reply.facts;
  if (degenerateFaces) notes.push(`${degenerateFaces} degenerate face${degenerateFaces > 1 ? 's' : ''} (repeated vertex or zero area)`);
  if (unreferencedVertices) notes.push(`${unreferencedVertices} ${unreferencedVertices > 1 ? 'vertices' : 'vertex'} used by no face`);
  if (reply.surfaceError) notes.push(`Geodesic distance is unavailable: ${reply.surfaceError}`);
  if (reply.refined) notes.push(refinedNote(reply.refined));
  mesh = { cloud: false, file, fileName: reply.fileName, sample, surfaceError: reply.surfaceError, openMs: t.parseMs + t.inspectMs, notes, faces, decimatedFrom: null };
  showOpened(reply, new SurfaceLayer(reply.positions, reply.triangles), sample, notes);
  panel.setFacts(reply.facts);
  offer.show(faces, reply.facts.vertices);
  subsampleLines.hidden = true;
}

/** What a cloud is not computed on yet, in its notes. */
const CLOUD_NOTE = 'Point cloud: every stage runs on it (CSCD-PC); the reconstruction error is measured against its points';

/** A cloud file, or a mesh file run as a cloud (`sample`: the sample mesh it is, or null). */
function showCloud(reply: CloudOpenedReply, sample: string | null, file: OpenedFile): void {
  const t = reply.timings;
  const notes = [...fileNotes(reply), CLOUD_NOTE];
  mesh = { cloud: true, file, fileName: reply.fileName, sample, surfaceError: null, openMs: t.parseMs + t.inspectMs, notes, faces: 0, decimatedFrom: null };
  showOpened(reply, new PointsLayer(reply.positions, viewer.restPixelRatio, reply.leftOut, viewer.drawnPointLimit), sample, notes);
  panel.setCloudFacts(reply.facts);
  // The limit's offer is for a subsample the page chose, not for one asked for.
  offer.showCloud(file.choice.subsample === null ? reply.subsampledFrom : null, reply.facts.points, testHooks.memoryLimitMB ?? CORE_MEMORY.maximumMB);
  showLinesOffer(reply.facts, file);
}

/** For a cloud scanned in lines (lib/cloud/scan-lines.ts), a button that opens it thinned along its lines. */
function showLinesOffer(facts: CloudFacts, file: OpenedFile): void {
  const count = scanLineWarning(facts) === null ? 0 : scanLineSubsample(facts);
  subsampleLines.hidden = count === 0;
  subsampleLines.textContent = `Subsample to ${count} points (thinned along the lines)`;
  subsampleLines.onclick = () => void file.reopen({ ...file.choice, subsample: count });
}

/** What a mesh and a cloud just opened share in the view and the panel. */
function showOpened(reply: OpenedReply | CloudOpenedReply, layer: ShapeLayer, sample: string | null, notes: string[]): void {
  const cloud = reply.shape === 'cloud';
  showShape(layer);
  params.showCloudOptions(cloud);
  // Flat shading and isolines draw a mesh's faces.
  for (const box of [flatBox, isolinesBox]) box.closest('label')!.hidden = cloud;
  // A mesh can run as a cloud of its vertices, and back; a cloud file has no mesh to go back to.
  asCloudBox.closest('label')!.hidden = cloud && !reply.asCloud;
  asCloudBox.checked = cloud;
  const random = byTestId('random-source');
  random.textContent = cloud ? 'Random point' : 'Random vertex';
  random.title = `Run stage 1 from a ${cloud ? 'point' : 'vertex'} drawn at random`;
  viewer.frame();
  markSample(gallery, sample);
  panel.setFile(reply.fileName, reply.format);
  panel.setNotes(notes);
  // The solver is opened by the first computation, which fills in its time.
  panel.setTimings({ ...reply.timings, prepareMs: null });
  delete document.body.dataset.decimatedFrom;
}

/** The line in the notes for a mesh the worker refined to compute on (lib/mesh/refine.ts). */
function refinedNote({ fromFaces, toFaces }: Refinement): string {
  const count = (n: number) => n.toLocaleString('en-US');
  return `Refined for computation: ${count(fromFaces)} → ${count(toFaces)} faces, the same surface (each edge split at its midpoint)`;
}

/** The decimated mesh replaces the one shown (same view); every stage now computes on it. */
function showDecimated(reply: DecimatedReply): void {
  if (!mesh) return;
  const { faces } = reply.facts;
  const notes = [...mesh.notes, `Decimated from ${reply.decimatedFrom} to ${faces} faces (quadric edge collapse; genus, components and holes kept)`];
  if (reply.refined) notes.push(refinedNote(reply.refined));
  mesh = { ...mesh, faces, decimatedFrom: reply.decimatedFrom, notes };
  showShape(new SurfaceLayer(reply.positions, reply.triangles));
  panel.setFacts(reply.facts);
  panel.setNotes(mesh.notes);
  panel.setTimings({ prepareMs: null });
  document.body.dataset.decimatedFrom = String(reply.decimatedFrom);
}

/** A new shape in the view: every stage's result and layer is dropped. */
function showShape(layer: ShapeLayer): void {
  wanted = 'mesh';
  userHidden.clear();
  viewer.clearLayers();
  single.reset();
  whole.reset();
  viewer.setLayer('surface', layer);
  viewer.surface!.setFlatShading(flatBox.checked);
  viewer.surface!.setIsolines(isolinesBox.checked);
}

// -- a mesh run as a point cloud ---------------------------------------------------------------------

asCloudBox.closest('label')!.title = `${AS_CLOUD.help.charAt(0).toUpperCase()}${AS_CLOUD.help.slice(1)}, to compare CSCD-M and CSCD-PC on one shape. Opens the file again.`;
asCloudBox.addEventListener('change', () => {
  if (!mesh) return;
  // The box then says what is open: the other shape, or the same one if the file cannot be opened so.
  void mesh.file.reopen({ ...AS_GIVEN, asCloud: asCloudBox.checked }).then(() => (asCloudBox.checked = !!mesh?.cloud));
});

// -- shapes above the size limit: decimate a mesh or compute on it whole; a cloud's points all --------

offer.onDecimate = (targetFaces) => void decimateMesh(targetFaces);
offer.onFull = () => {
  if (mesh?.cloud) return void openAllPoints(mesh.file);
  offer.hide();
  refresh();
};

/** The cloud opened again on all its points; the offer stays if that fails (the subsample stays open). */
async function openAllPoints(file: OpenedFile): Promise<void> {
  offer.setBusy(true);
  try {
    await file.reopen({ ...file.choice, allPoints: true });
  } finally {
    offer.setBusy(false);
  }
}

async function decimateMesh(targetFaces: number): Promise<void> {
  offer.setBusy(true);
  ctx.begin(`decimating to ${targetFaces} faces…`);
  try {
    showDecimated(await client.decimate(targetFaces).result);
    offer.hide();
  } catch (error) {
    // A crash is reported by onCrash; a cancel leaves the offer as it was.
    if (!(error instanceof WorkerError && (error.kind === 'crash' || error.kind === 'cancelled'))) fail('Could not decimate the mesh', error);
  } finally {
    offer.setBusy(false);
    ctx.end();
    refresh();
  }
}

statusCancel.addEventListener('click', () => {
  statusCancel.disabled = true;
  panel.setStatus('cancelling…', true);
  client.cancelRunning();
});

/** Whether the file opened (else what was open stays, and the error says why). */
async function openFile(file: File, choice = AS_GIVEN): Promise<boolean> {
  let bytes: ArrayBuffer;
  try {
    bytes = await file.arrayBuffer();
  } catch (error) {
    fail(`Could not read ${file.name}`, error);
    updateState();
    return false;
  }
  return openBytes(file.name, bytes, null, (other) => openFile(file, other), choice);
}

async function openSample(sample: Sample, choice = AS_GIVEN): Promise<boolean> {
  try {
    const response = await fetch(`samples/${sample.file}`);
    if (!response.ok) throw new Error(`HTTP ${response.status} for samples/${sample.file}`);
    return await openBytes(sample.file, await response.arrayBuffer(), sample.name, (other) => openSample(sample, other), choice);
  } catch (error) {
    fail(`Could not load the sample mesh ${sample.file}`, error);
    updateState();
    return false;
  }
}

// -- stages ----------------------------------------------------------------------------------------

const canCompute = () => !!viewer.surface && !mesh?.surfaceError && !offer.pending;

/** The stage shown: the one wanted, or the last one the stage-1 run reached when it stopped earlier. */
function shownStage(): StageKey {
  if (stageDef(wanted).group === 'source' && single.reply && !single.has(wanted)) return single.reached!;
  return wanted;
}

function pillStates(): Map<StageKey, PillState> {
  const states = new Map<StageKey, PillState>();
  for (const { key, group } of STAGES) {
    let state: PillState;
    if (!viewer.surface) state = 'disabled';
    else if (group === 'mesh') state = 'ready';
    else if (!canCompute()) state = 'disabled';
    else if (group === 'source') state = single.has(key) ? 'ready' : single.reply ? 'disabled' : single.busy ? 'running' : 'pending';
    else if (key === 'reconstruction') state = whole.evaluation ? 'ready' : whole.result ? 'pending' : whole.running ? 'disabled' : 'pending';
    else state = whole.result ? 'ready' : whole.running ? (key === 'separators' ? 'running' : 'pending') : 'pending';
    states.set(key, state);
  }
  return states;
}

/** The user asks for a stage: it is shown, and computed when it is not yet. */
function enter(key: StageKey): void {
  wanted = key;
  refresh();
  if (!canCompute()) return;
  const group = stageDef(key).group;
  if (group === 'source' && !single.reply && !single.busy) void single.runRandom();
  if (group === 'shape') {
    // run() joins a run in progress.
    const computed = whole.result ? Promise.resolve() : whole.run();
    // Reconstruction needs the skeleton first, then its evaluation.
    if (key === 'reconstruction') {
      void computed.then(() => {
        if (wanted === 'reconstruction') return whole.evaluate();
      });
    }
  }
}
timeline.onSelect = enter;

/** Redraws the stage shown: layer visibility, the surface's colouring, the panel, the timeline and the address. */
function refresh(): void {
  const key = shownStage();
  const def = stageDef(key);
  const surface = viewer.surface;
  for (const [name, layer] of viewer.listLayers()) {
    if (name === 'surface') {
      layer.object.visible = !userHidden.has(name);
      continue;
    }
    layer.object.visible = def.layers.includes(name) && !userHidden.has(name);
    layer.setDimmed?.(!!def.dimmed?.includes(name));
  }
  if (surface) {
    if (def.group === 'shape') whole.applySurface(key);
    else if (def.group === 'source' && single.reply) single.applySurface(key, !!viewer.getLayer('sphere') && !userHidden.has('sphere'));
    else {
      surface.setScalarVisible(false);
      surface.setDimmed(false);
      surface.setRegion(null);
      surface.setRegionColorMix(0);
      surface.setTranslucent(false);
    }
  }

  // The panel: the stage card, and the results of the stage's group.
  document.body.dataset.stage = key;
  byTestId('stage-index').textContent = String(stageIndex(key) + 1);
  byTestId('stage-title').textContent = def.title;
  const own = mesh?.cloud ? def.cloud : undefined; // a cloud's own account of the step, where it differs
  byTestId('stage-section').textContent = own?.section ?? def.section;
  let caption = own?.caption ?? def.caption;
  if (def.group === 'source' && single.reply) caption += separatorCaption(key, single.reply);
  if (def.group === 'shape' && whole.result) caption += SkeletonPanel.caption(key, whole.result);
  byTestId('stage-caption').textContent = caption;
  const present = new Set(viewer.listLayers().map(([name]) => name));
  byTestId('stage-legend').replaceChildren(
    ...def.legend.filter(({ layer }) => present.has(layer)).map(({ label, color }) => swatch(color, label)),
    ...whole.legendExtras(key),
  );
  const reached = single.reached;
  byTestId('stage-card').classList.toggle('failed', def.group === 'source' && key === reached && single.reply?.separator.status !== 'ok');
  for (const section of document.querySelectorAll<HTMLElement>('[data-group]')) {
    section.hidden = section.dataset.group !== (def.group === 'mesh' ? 'source' : def.group);
  }
  byTestId('sk-recon-result').hidden = key !== 'reconstruction' || !whole.evaluation;
  viewportHint.textContent = [own?.click ?? def.click, '←/→ or 1–0: stages', 'drag to orbit', 'right-drag to pan', 'scroll to zoom'].filter(Boolean).join(' · ');

  timeline.show(key, pillStates());
  updateTimes();
  updateLayerList(def.layers, def.dimmed ?? []);
  updateDownloads();
  // A file of the user's cannot be linked to: its source vertex would mean nothing on the default sample.
  const sample = mesh?.sample ?? null;
  writeUrl({ mesh: sample, asCloud: !!mesh?.cloud, stage: key, source: sample ? single.source : null, options: params.options, settings: params.settings });
  // Drawn now, not at the next animation frame: a stage change leaves the state 'ready', so whoever
  // reads the picture once the page shows the new stage must get the new stage's pixels.
  viewer.requestRender();
  viewer.flush();
}

/** The time each stage's computation took, under its pill. */
function updateTimes(): void {
  const times: Partial<Record<StageKey, number>> = {
    mesh: mesh?.openMs,
    ...(single.reply ? separatorStageTimes(single.reply) : {}),
    ...(whole.result ? SkeletonPanel.stageTimes(whole.result) : {}),
    reconstruction: whole.evaluation?.timings.evaluateMs,
  };
  for (const { key } of STAGES) {
    const ms = times[key];
    timeline.setTime(key, ms !== undefined && Number.isFinite(ms) ? formatMs(ms) : '');
    timeline.setProgress(key, key === 'separators' ? whole.progress : null);
  }
}

/** The layer list: the surface and the layers of the stage shown that have data. */
let layerListKey = '';
function updateLayerList(names: string[], dimmed: string[]): void {
  const entries = ['surface', ...names]
    .map((name) => [name, viewer.getLayer(name)] as const)
    .filter(([, layer]) => layer)
    .map(([name, layer]) => ({
      name,
      label: layer!.label,
      visible: !userHidden.has(name),
      color: layerColors.get(name),
      dimmed: dimmed.includes(name),
    }));
  const key = JSON.stringify(entries);
  if (key === layerListKey) return; // rebuilt only when it changes (progress refreshes often)
  layerListKey = key;
  panel.setLayers(entries, (name, visible) => {
    if (visible) userHidden.delete(name);
    else userHidden.add(name);
    refresh();
  });
}

// -- clicks -----------------------------------------------------------------------------------------

viewer.onClick = (x, y) => {
  const key = shownStage();
  if (stageDef(key).group === 'shape') {
    if (!whole.result || (key !== 'regions' && key !== 'skeleton')) return;
    const node = key === 'skeleton' ? viewer.pickInstance('sk-nodes', x, y) : null;
    if (node !== null) return whole.select(node);
    const pick = viewer.pick(x, y);
    if (pick) whole.selectVertex(pick.vertex);
    else whole.select(null);
    return;
  }
  const pick = viewer.pick(x, y);
  if (!pick || !canCompute()) return;
  if (key === 'mesh') wanted = 'geodesics';
  void single.run(pick.vertex);
};

byTestId('random-source').addEventListener('click', () => {
  if (!canCompute()) return;
  if (stageDef(shownStage()).group !== 'source') wanted = 'geodesics';
  void single.runRandom();
});

// -- parameters: re-run only what depends on the change --------------------------------------------

params.onChange = (keys) => {
  if (keys.some((k) => STAGE1_OPTIONS.includes(k)) && single.reply) void single.rerun();
  // Every option shapes the whole-shape result: drop it, and compute it again if it is on screen.
  const had = whole.result !== null || whole.running;
  whole.invalidate();
  if (had && stageDef(shownStage()).group === 'shape') enter(shownStage());
  refresh();
};
// The cloud's neighbourhoods are made when it is opened: a change opens it again, every result dropped.
params.onNeighboursChange = () => void (mesh?.cloud && mesh.file.reopen(mesh.file.choice));
// A run setting changes how the next run is computed, not its result: the skeleton shown stays.
params.onSettingsChange = () => refresh();

// -- downloads ------------------------------------------------------------------------------------

const skeletonButtons = [...document.querySelectorAll<HTMLButtonElement>('.downloads [data-what]')];
function updateDownloads(): void {
  for (const button of skeletonButtons) button.disabled = !whole.result;
  byTestId<HTMLButtonElement>('dl-png').disabled = !viewer.surface;
}
for (const button of skeletonButtons) {
  button.addEventListener('click', async () => {
    if (!mesh || !whole.result) return;
    const what = button.dataset.what as WriteRequest['what'];
    try {
      const reply = await client.write(what, mesh.fileName);
      const [name, type] =
        what === 'separators-obj' ? [`${baseName(mesh.fileName)}-separators.obj`, 'text/plain'] : [`${baseName(mesh.fileName)}-skeleton.${what}`, what === 'json' ? 'application/json' : 'text/plain'];
      saveFile(name, reply.bytes as Uint8Array<ArrayBuffer>, type);
    } catch (error) {
      fail('Could not save the file', error);
      updateState();
    }
  });
}
byTestId('dl-png').addEventListener('click', async () => {
  if (!mesh) return;
  viewer.requestRender();
  viewer.flush();
  saveFile(`${baseName(mesh.fileName)}-${shownStage()}.png`, await canvasPng(viewer.renderer.domElement), 'image/png');
});

// -- view controls and files ----------------------------------------------------------------------

flatBox.addEventListener('change', () => {
  viewer.surface?.setFlatShading(flatBox.checked);
  viewer.requestRender();
  viewer.flush();
});
isolinesBox.addEventListener('change', () => {
  viewer.surface?.setIsolines(isolinesBox.checked);
  viewer.requestRender();
  viewer.flush();
});
document.querySelector('#reset-view')!.addEventListener('click', () => viewer.frame());
viewer.onLayersChange = () => updateLayerList(stageDef(shownStage()).layers, stageDef(shownStage()).dimmed ?? []);

document.querySelector('#formats-hint')!.textContent = `or drop ${SHAPE_EXTENSIONS.join(' ')} anywhere`;
installFileSources({
  button: document.querySelector<HTMLButtonElement>('#open-button')!,
  input: document.querySelector<HTMLInputElement>('#file-input')!,
  overlay: document.querySelector<HTMLElement>('#drop-overlay')!,
  extensions: SHAPE_EXTENSIONS,
  onFile: (file) => void openFile(file),
});
installGallery(gallery, (sample) => void openSample(sample));

/** For end-to-end tests and the console. */
declare global {
  interface Window {
    cscd?: {
      simulateCrash(how?: 'abort' | 'uncaught' | 'hang'): Promise<void>;
      projectVertex(index: number): { x: number; y: number } | null;
      /** Window position of a skeleton node's centre (null: no skeleton). */
      projectNode(index: number): { x: number; y: number } | null;
      /** Camera along `direction` (towards the camera) at a sphere around `center` (default: the mesh). */
      setView(view: { direction?: [number, number, number]; center?: [number, number, number]; radius?: number }): void;
      /** The worker's times of the skeleton shown, its number of sources and the threads stage 1 started on (null: none), for bench/page.ts and the tests. */
      skeletonRun(): (SkeletonReply['timings'] & { sources: number; workers: number }) | null;
      /** A cloud's points drawn and computed on (more drawn when subsampled; null: a mesh). */
      cloudPoints(): { drawn: number; computedOn: number } | null;
    };
  }
}
window.cscd = {
  simulateCrash: (how) => client.simulateCrash(how).catch(() => undefined),
  projectVertex: (index) => viewer.projectVertex(index),
  projectNode: (index) => {
    const nodes = whole.result?.skeleton.nodes;
    return nodes && 3 * index + 2 < nodes.length ? viewer.projectPoint(nodes.subarray(3 * index, 3 * index + 3)) : null;
  },
  setView: ({ direction, center, radius }) => {
    const v = (a?: [number, number, number]) => (a ? { x: a[0], y: a[1], z: a[2] } : undefined);
    viewer.frame({ direction: v(direction), center: v(center), radius });
    viewer.flush();
  },
  skeletonRun: () => (whole.result ? { ...whole.result.timings, sources: whole.result.skeleton.stats.n, workers: whole.result.pool.workers } : null),
  cloudPoints: () => {
    const surface = viewer.surface;
    return surface instanceof PointsLayer ? { drawn: surface.drawnCount, computedOn: surface.vertexCount } : null;
  },
};

// -- start: the linked view, or the default sample --------------------------------------------------

// The page writes its address with replaceState, which fires no hashchange: this is a link pasted or
// edited in the address bar, and reloading is the simplest way to follow it.
window.addEventListener('hashchange', () => location.reload());

void (async () => {
  refresh();
  const sample = sampleByName(initial.mesh) ?? DEFAULT_SAMPLE;
  if (!(await openSample(sample, { ...AS_GIVEN, asCloud: initial.asCloud }))) return;
  const surface = viewer.surface;
  if (initial.source !== null && surface && initial.source < surface.vertexCount && canCompute()) {
    wanted = initial.stage && SOURCE_STAGES.includes(initial.stage) ? initial.stage : 'geodesics';
    await single.run(initial.source);
  }
  if (initial.stage) enter(initial.stage);
})();
