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
  await expect(page.getByTestId('timing-prepare')).toHaveText(/\d+(\.\d)? (ms|s)/);
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

test('a non-manifold mesh is shown with its facts and refuses stage 1 with a message', async ({ page }) => {
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
  await expect(page.getByTestId('facts-manifold')).toContainText('no');
  const shown = await canvasStats(page);
  expect(frameDifference(before, shown), 'the new mesh is drawn').toBeGreaterThan(15);

  await clickMesh(page, shown);
  await waitForState(page, 'error');
  await expect(page.getByRole('alert')).toContainText('Could not compute stage 1');
  await expect(page.getByRole('alert')).toContainText('non-manifold');
  await expect(page.getByTestId('separator')).toBeHidden();
  await expect(page.getByTestId('file-name')).toHaveText('fins.obj');
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
