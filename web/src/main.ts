/**
 * Wiring: files -> worker (parse, inspect, prepare) -> viewer + panel; clicks -> worker (distance)
 * -> colormap. `document.body.dataset.state` is loading | ready | computing | error, for tests.
 */
import './style.css';
import { MESH_EXTENSIONS } from '../../lib/io/index.ts';
import { niceSpacing } from './viewer/colormap.ts';
import { SpheresLayer, SurfaceLayer } from './viewer/layers.ts';
import { Viewer, type Pick } from './viewer/viewer.ts';
import { GeometryClient, WorkerError } from './worker/client.ts';
import type { OpenedReply } from './worker/protocol.ts';
import { installFileSources } from './ui/files.ts';
import { Panel } from './ui/panel.ts';

const SAMPLE = 'samples/spot.ply';

const panel = new Panel();
const viewer = new Viewer(document.querySelector<HTMLElement>('#viewport')!);
const flatBox = document.querySelector<HTMLInputElement>('#opt-flat')!;
const isolinesBox = document.querySelector<HTMLInputElement>('#opt-isolines')!;

let opening = 0;
let computing = 0;
let failed = false;
/** Bumped whenever a different mesh is shown, so late distance replies for the old one are dropped. */
let meshGeneration = 0;
let latestDistanceRequest = 0;

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

const client = new GeometryClient({
  onProgress: (event) => panel.setStatus(event.message, true),
  onCrash: (message, restored) => {
    failed = true;
    panel.showError('The geometry worker stopped and was restarted', message);
    opening++;
    panel.setStatus('restarting the geometry worker…', true);
    updateState();
    restored
      .catch((error: unknown) => fail('Could not re-open the mesh after the restart', error))
      .finally(() => {
        opening--;
        updateState();
      });
  },
});

// -- opening meshes ------------------------------------------------------------------------------

async function openBytes(fileName: string, bytes: ArrayBuffer): Promise<void> {
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
  viewer.clearLayers();
  viewer.setLayer('surface', new SurfaceLayer(reply.positions, reply.triangles));
  viewer.surface!.setFlatShading(flatBox.checked);
  viewer.surface!.setIsolines(isolinesBox.checked);
  viewer.frame();

  panel.setFile(reply.fileName, reply.format);
  panel.setFacts(reply.facts);
  const notes = [...reply.warnings];
  const { degenerateFaces, unreferencedVertices } = reply.facts;
  if (degenerateFaces) notes.push(`${degenerateFaces} degenerate face${degenerateFaces > 1 ? 's' : ''} (repeated vertex or zero area)`);
  if (unreferencedVertices) notes.push(`${unreferencedVertices} ${unreferencedVertices > 1 ? 'vertices' : 'vertex'} used by no face`);
  if (reply.surfaceError) notes.push(`Geodesic distance is unavailable: ${reply.surfaceError}`);
  panel.setNotes(notes);
  panel.setTimings({ ...reply.timings, distanceMs: null });
  panel.setDistance(null);
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

// -- geodesic distance ---------------------------------------------------------------------------

async function computeDistance(pick: Pick): Promise<void> {
  const surface = viewer.surface;
  if (!surface || opening > 0) return;
  const generation = meshGeneration;
  const request = ++latestDistanceRequest;
  const radius = surface.boundingSphere.radius * 0.022;
  viewer.setLayer('source', new SpheresLayer('Source vertex', surface.vertexPosition(pick.vertex).toArray(), radius));

  computing++;
  startAction('computing distance…');
  updateState();
  try {
    const reply = await client.distance(pick.vertex);
    if (generation !== meshGeneration || request !== latestDistanceRequest) return; // superseded
    const spacing = niceSpacing(reply.max);
    surface.setScalarField({ values: reply.distance, max: reply.max, isolineSpacing: spacing });
    viewer.requestRender();
    panel.setDistance({ source: reply.source, max: reply.max, spacing });
    panel.setTimings({ distanceMs: reply.timings.distanceMs });
  } catch (error) {
    if (generation !== meshGeneration) return;
    if (request === latestDistanceRequest) viewer.setLayer('source', null);
    if (!(error instanceof WorkerError && error.kind === 'crash')) fail('Could not compute the geodesic distance', error);
  } finally {
    computing--;
    updateState();
  }
}

viewer.onPick = (pick) => void computeDistance(pick);

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
viewer.onLayersChange = () =>
  panel.setLayers(
    viewer.listLayers().map(([name, layer]) => ({ name, label: layer.label, visible: layer.object.visible })),
    (name, visible) => viewer.setLayerVisible(name, visible),
  );

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
    cscd?: { simulateCrash(how?: 'abort' | 'uncaught'): Promise<void>; projectVertex(index: number): { x: number; y: number } | null };
  }
}
window.cscd = {
  simulateCrash: (how) => client.simulateCrash(how).catch(() => undefined),
  projectVertex: (index) => viewer.projectVertex(index),
};

void openSample();
