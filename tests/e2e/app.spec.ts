import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { sharedMesh } from '../paths.ts';
import { canvasStats, clickMesh, frameDifference, type PixelStats } from './pixels.ts';

type State = 'loading' | 'ready' | 'computing' | 'error';

async function waitForState(page: Page, state: State): Promise<void> {
  await expect(page.locator('body')).toHaveAttribute('data-state', state, { timeout: 60_000 });
}

/** Drops a file on the page as a user would (a DataTransfer holding a File), bytes passed from Node. */
async function dropFile(page: Page, name: string, bytes: Uint8Array): Promise<void> {
  await page.evaluate(
    ({ name, base64 }) => {
      const raw = atob(base64);
      const data = new Uint8Array(raw.length);
      for (let i = 0; i < raw.length; i++) data[i] = raw.charCodeAt(i);
      const transfer = new DataTransfer();
      transfer.items.add(new File([data], name));
      const target = document.querySelector('[data-testid="viewport-canvas"]')!;
      for (const type of ['dragenter', 'dragover', 'drop']) {
        target.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
      }
    },
    { name, base64: Buffer.from(bytes).toString('base64') },
  );
}

/** Clicks the mesh and waits for the distance to be drawn. */
async function pickAndWait(page: Page, before: PixelStats): Promise<PixelStats> {
  await clickMesh(page, before);
  await expect(page.getByTestId('distance-source')).toHaveText(/^\d+$/);
  await waitForState(page, 'ready');
  return canvasStats(page);
}

function expectColormap(before: PixelStats, after: PixelStats): void {
  expect(after.hueBins, 'the colormap spans many hues').toBeGreaterThanOrEqual(6);
  expect(after.saturatedFraction, 'most of the mesh is coloured').toBeGreaterThan(0.6);
  expect(frameDifference(before, after), 'the picture changed').toBeGreaterThan(15);
}

async function openSample(page: Page): Promise<PixelStats> {
  await page.goto('/');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-vertices')).toHaveText('2930');
  return canvasStats(page);
}

test('loads the sample mesh and draws it lit', async ({ page }) => {
  const stats = await openSample(page);
  await expect(page.getByTestId('file-name')).toHaveText('spot.ply');
  await expect(page.getByTestId('facts-faces')).toHaveText('5856');
  await expect(page.getByTestId('facts-genus')).toHaveText('0');
  await expect(page.getByTestId('facts-euler')).toHaveText('2');
  await expect(page.getByTestId('facts-manifold')).toHaveText('yes');
  // The geodesic solver is opened by the first computation, not on load.
  await expect(page.getByTestId('timing-prepare')).toHaveText('–');
  await expect(page.getByTestId('error')).toBeHidden();

  expect(stats.coveredFraction, 'the mesh covers a good part of the view').toBeGreaterThan(0.1);
  expect(stats.meanLuminance, 'the mesh is lit, not black').toBeGreaterThan(0.25);
  expect(stats.luminanceStd, 'shading varies over the surface').toBeGreaterThan(0.04);
  expect(stats.hueBins, 'no colormap yet').toBeLessThanOrEqual(2);
});

test('a click on the mesh shows geodesic distance (the Geodesics stage) as a colormap', async ({ page }) => {
  const before = await openSample(page);
  const after = await pickAndWait(page, before);
  expectColormap(before, after);
  await expect(page.getByTestId('timing-prepare')).toHaveText(/\d+(\.\d)? (ms|s)/);
  await expect(page.getByTestId('timing-separator')).toHaveText(/\d+(\.\d)? (ms|s)/);
  await expect(page.getByTestId('timing-stage-distance')).toHaveText(/\d+(\.\d)? (ms|s)/);
  await expect(page.getByTestId('stage-index')).toHaveText('2');
  await expect(page.locator('body')).toHaveAttribute('data-stage', 'geodesics');
  await expect(page.getByTestId('distance-max')).toHaveText(/^\d/);
  await expect(page.getByTestId('status')).toContainText('Ready');
});

test('dropping a PLY file replaces the mesh', async ({ page }) => {
  const before = await openSample(page);
  await dropFile(page, 'two_torus.ply', readFileSync(sharedMesh('two_torus.ply')));
  await expect(page.getByTestId('facts-vertices')).toHaveText('766');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('file-name')).toHaveText('two_torus.ply');
  await expect(page.getByTestId('facts-genus')).toHaveText('2');
  const after = await canvasStats(page);
  expect(after.coveredFraction).toBeGreaterThan(0.05);
  expect(frameDifference(before, after), 'the new mesh is drawn').toBeGreaterThan(15);

  const colored = await pickAndWait(page, after);
  expectColormap(after, colored);
});

test('a malformed file shows an error and keeps the previous mesh working', async ({ page }) => {
  const before = await openSample(page);
  const ply = readFileSync(sharedMesh('two_torus.ply'));
  const cases: Array<[string, Uint8Array]> = [
    ['truncated.ply', ply.subarray(0, Math.floor(ply.length * 0.6))],
    ['garbage.obj', new TextEncoder().encode('this is not\na mesh at all\n\u0001\u0002 ### }{\n')],
  ];
  for (const [name, bytes] of cases) {
    await dropFile(page, name, bytes);
    await waitForState(page, 'error');
    const alert = page.getByRole('alert');
    await expect(alert).toBeVisible();
    await expect(alert).toContainText(`Could not open ${name}`);
    await expect(page.getByTestId('facts-vertices')).toHaveText('2930');
    await expect(page.getByTestId('file-name')).toHaveText('spot.ply');
    const still = await canvasStats(page);
    expect(frameDifference(before, still), 'the previous mesh is still drawn').toBeLessThan(1);
  }

  const after = await pickAndWait(page, before);
  expectColormap(before, after);
  await expect(page.getByRole('alert')).toBeHidden();
});

test('a non-manifold mesh is repaired on load, says so, and stage 1 runs on it', async ({ page }) => {
  const before = await openSample(page);
  // Three sheets sharing the edge x = z = 0 (a non-manifold edge), each a 2x2 grid of quads.
  const lines: string[] = [];
  for (let j = 0; j < 3; j++) lines.push(`v 0 ${j / 2} 0`); // the shared spine: vertices 1..3
  const sheets = [[1, 0], [-1, 0], [0, 1]];
  sheets.forEach(([dx, dz], s) => {
    for (let i = 1; i < 3; i++) for (let j = 0; j < 3; j++) lines.push(`v ${(dx * i) / 2} ${j / 2} ${(dz * i) / 2}`);
    const at = (i: number, j: number) => (i === 0 ? j + 1 : 3 + s * 6 + (i - 1) * 3 + j + 1);
    for (let i = 0; i < 2; i++) for (let j = 0; j < 2; j++) lines.push(`f ${at(i, j)} ${at(i + 1, j)} ${at(i + 1, j + 1)} ${at(i, j + 1)}`);
  });
  await dropFile(page, 'fins.obj', new TextEncoder().encode(lines.join('\n') + '\n'));
  await expect(page.getByTestId('file-name')).toHaveText('fins.obj');
  await waitForState(page, 'ready');
  // The shared edge is split (lib/io/repair.ts): a manifold mesh, and the notes say what was done.
  await expect(page.getByTestId('facts-manifold')).toHaveText('yes');
  await expect(page.getByTestId('warnings')).toContainText('Repaired:');
  const shown = await canvasStats(page);
  expect(frameDifference(before, shown), 'the new mesh is drawn').toBeGreaterThan(15);

  await clickMesh(page, shown);
  await expect(page.locator('body')).toHaveAttribute('data-separator-runs', '1', { timeout: 30_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('separator-status')).toHaveAttribute('data-status', /.+/);
  await expect(page.getByRole('alert')).toBeHidden();
  await expect(page.getByTestId('file-name')).toHaveText('fins.obj');
});

/** A GLB file of an octahedron (one node, translated) built here: 6 float32 VEC3 positions, 24 uint16 indices. */
function octahedronGlb(): Uint8Array {
  const positions = [1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1];
  const indices = [0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5];
  const bin = Buffer.alloc(72 + 48);
  positions.forEach((x, i) => bin.writeFloatLE(x, 4 * i));
  indices.forEach((x, i) => bin.writeUInt16LE(x, 72 + 2 * i));
  const json = JSON.stringify({
    asset: { version: '2.0' },
    buffers: [{ byteLength: bin.length }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: 72 }, { buffer: 0, byteOffset: 72, byteLength: 48 }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 6, type: 'VEC3' },
      { bufferView: 1, componentType: 5123, count: 24, type: 'SCALAR' },
    ],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
    nodes: [{ mesh: 0, translation: [0, 2, 0] }],
    scenes: [{ nodes: [0] }],
  });
  const text = Buffer.from(json.padEnd(Math.ceil(json.length / 4) * 4, ' '));
  const header = Buffer.alloc(12);
  header.write('glTF', 0, 'latin1');
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + text.length + 8 + bin.length, 8);
  const chunk = (type: number, data: Buffer) => {
    const h = Buffer.alloc(8);
    h.writeUInt32LE(data.length, 0);
    h.writeUInt32LE(type, 4);
    return Buffer.concat([h, data]);
  };
  return new Uint8Array(Buffer.concat([header, chunk(0x4e4f534a, text), chunk(0x004e4942, bin)]));
}

test('dropping a GLB file opens its triangles', async ({ page }) => {
  const before = await openSample(page);
  await dropFile(page, 'octahedron.glb', octahedronGlb());
  await expect(page.getByTestId('file-name')).toHaveText('octahedron.glb');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('file-format')).toHaveText('GLB');
  await expect(page.getByTestId('facts-vertices')).toHaveText('6');
  await expect(page.getByTestId('facts-faces')).toHaveText('8');
  await expect(page.getByTestId('facts-genus')).toHaveText('0');
  await expect(page.getByTestId('facts-manifold')).toHaveText('yes');
  expect(frameDifference(before, await canvasStats(page)), 'the octahedron is drawn').toBeGreaterThan(15);
});

for (const how of ['abort', 'uncaught'] as const) {
  test(`the page recovers when the geometry worker crashes (${how})`, async ({ page }) => {
    const before = await openSample(page);
    await page.evaluate((how) => window.cscd!.simulateCrash(how), how);
    const alert = page.getByRole('alert');
    await expect(alert).toContainText('restarted');
    await expect(alert).toContainText(how === 'abort' ? 'Aborted(simulated crash)' : 'simulated uncaught error');
    await waitForState(page, 'error');
    await expect(page.getByTestId('facts-vertices')).toHaveText('2930');
    const after = await pickAndWait(page, before);
    expectColormap(before, after);
  });
}
