/**
 * Limits (README "Limits", docs/limits.md): a ~1M-face mesh, generated here into a temporary folder,
 * opens and shows quickly because the geodesic solver waits for the first computation; the page offers
 * to decimate it, the skeleton is then computed on the decimated mesh; a cancel while the solver opens
 * replaces the worker and keeps the mesh; an out-of-memory error in a memory-capped core
 * (`?memoryLimitMB=`, the page's test hook) is reported and the page stays usable.
 */
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { binaryPly, torusOfFaces } from '../unit/support/big-mesh.ts';
import { body, runWhole, waitForState } from './studio.ts';

// One after the other in one worker: the meshes are made once, and two of these at a time would share 2 cores.
test.describe.configure({ mode: 'default' });
// No trace: its snapshots of a million software-rendered triangles hold the page up for longer than the bounds.
test.use({ trace: 'off' });

/** Loading and showing 1M faces (parse, repair, inspect, upload to the GPU) on this 2-core machine: a bound, not a wait. */
const SHOW_BOUND_MS = 30_000;

let folder: string;
let big: { file: string; faces: number };
let capped: { file: string; faces: number };

test.beforeAll(() => {
  folder = mkdtempSync(path.join(tmpdir(), 'cscd-limits-'));
  const write = (name: string, faces: number) => {
    const mesh = torusOfFaces(faces);
    const file = path.join(folder, name);
    writeFileSync(file, binaryPly(mesh));
    return { file, faces: mesh.triangles.length / 3 };
  };
  big = write('torus-1m.ply', 1_000_000);
  // Below the size limit (no offer), above what a 128 MB core can prefactor.
  capped = write('torus-180k.ply', 180_000);
});

test.afterAll(() => rmSync(folder, { recursive: true, force: true }));

async function openFile(page: Page, file: string): Promise<void> {
  await page.getByTestId('file-input').setInputFiles(file);
}

async function openPage(page: Page, url = '/'): Promise<void> {
  await page.goto(url);
  await waitForState(page, 'ready');
}

test('a 1M-face mesh shows in seconds, the page offers to decimate it, and the skeleton is computed on the decimated mesh', async ({ page }) => {
  test.setTimeout(300_000);
  await openPage(page);
  const started = Date.now();
  await openFile(page, big.file);
  await expect(page.getByTestId('facts-faces')).toHaveText(String(big.faces), { timeout: SHOW_BOUND_MS });
  await waitForState(page, 'ready');
  expect(Date.now() - started, 'open and show 1M faces').toBeLessThan(SHOW_BOUND_MS);
  await expect(page.getByTestId('timing-prepare')).toHaveText('–');

  const offer = page.getByTestId('limit-offer');
  await expect(offer).toBeVisible();
  await expect(page.getByTestId('limit-offer-text')).toContainText(`This mesh has ${big.faces} faces; preparing the geodesic solver takes about`);
  await expect(page.getByTestId('limit-decimate')).toHaveText('Decimate to 100,000 faces');
  // Until a choice is made nothing computes on the mesh.
  await expect(page.getByTestId('stage-separators')).toBeDisabled();

  await page.getByTestId('limit-target').fill('3000');
  await expect(page.getByTestId('limit-decimate')).toHaveText('Decimate to 3,000 faces');
  await page.getByTestId('limit-decimate').click();
  await expect(page.getByTestId('status')).toContainText(/decimat/);
  await expect(body(page)).toHaveAttribute('data-decimated-from', String(big.faces), { timeout: 180_000 });
  await waitForState(page, 'ready');
  await expect(offer).toBeHidden();
  const faces = Number(await page.getByTestId('facts-faces').textContent());
  expect(faces).toBeLessThanOrEqual(3000);
  expect(faces).toBeGreaterThan(2900);
  await expect(page.getByTestId('facts-genus')).toHaveText('1');
  await expect(page.getByTestId('warnings')).toContainText(`Decimated from ${big.faces} to ${faces} faces`);
  await expect(page.getByTestId('status')).toContainText(`decimated from ${big.faces} to ${faces} faces`);

  // A new worker (here after a simulated crash) gets the decimated mesh back, not the file: the skeleton
  // below is computed on it in seconds (on the full mesh the solver alone takes over a minute).
  await page.evaluate(() => window.cscd!.simulateCrash('abort'));
  await waitForState(page, 'error');
  await expect(page.getByTestId('facts-faces')).toHaveText(String(faces));
  await runWhole(page, 8);
  await expect(page.getByTestId('sk-cycles')).toHaveText('1');
  await expect(page.getByTestId('timing-prepare')).toHaveText(/\d+(\.\d)? (ms|s)/);
  await expect(page.getByTestId('error')).toBeHidden();
});

test('a cancel stops a decimation between steps, and the opening of the solver by replacing the worker; the mesh stays', async ({ page }) => {
  test.setTimeout(120_000);
  await openPage(page);
  await openFile(page, big.file);
  await expect(page.getByTestId('facts-faces')).toHaveText(String(big.faces), { timeout: SHOW_BOUND_MS });
  const cancel = page.getByTestId('status-cancel');

  // Decimation yields between steps: it stops at once, the offer stays.
  await page.getByTestId('limit-decimate').click();
  await expect(page.getByTestId('status')).toContainText('decimating:');
  const decimating = Date.now();
  await cancel.click();
  await waitForState(page, 'ready');
  expect(Date.now() - decimating, 'stopped between two steps, before the grace period').toBeLessThan(2_500);
  await expect(page.getByTestId('limit-offer')).toBeVisible();
  await expect(page.getByTestId('facts-faces')).toHaveText(String(big.faces));
  await expect(page.getByTestId('error')).toBeHidden();

  await page.getByTestId('limit-full').click();
  await expect(page.getByTestId('limit-offer')).toBeHidden();

  await page.getByTestId('random-source').click();
  await expect(page.getByTestId('status')).toContainText('preparing the geodesic solver…');
  await expect(cancel).toBeVisible();
  const cancelled = Date.now();
  await cancel.click();

  // The solver cannot stop between steps: after the grace period the worker is replaced.
  await waitForState(page, 'ready');
  expect(Date.now() - cancelled, 'the page is free again long before the solver would be').toBeLessThan(20_000);
  await expect(cancel).toBeHidden();
  await expect(page.getByTestId('error')).toBeHidden();
  await expect(page.getByTestId('facts-faces')).toHaveText(String(big.faces));
  await expect(page.getByTestId('timing-prepare')).toHaveText('–');
});

test('an out-of-memory error in the core is reported, and the page computes afterwards', async ({ page }) => {
  test.setTimeout(120_000);
  await openPage(page, '/?memoryLimitMB=128');
  await openFile(page, capped.file);
  await expect(page.getByTestId('facts-faces')).toHaveText(String(capped.faces), { timeout: SHOW_BOUND_MS });
  await expect(page.getByTestId('limit-offer')).toBeHidden();

  await page.getByTestId('random-source').click();
  await expect(page.getByTestId('error')).toContainText('out of memory: the mesh needs more than 128 MB; decimate it', { timeout: 60_000 });
  await expect(body(page)).toHaveAttribute('data-state', /ready|error/, { timeout: 30_000 });

  // A fresh worker (the old one's memory is gone with it) computes on a mesh that fits.
  await page.getByTestId('sample-spot').click();
  await expect(page.getByTestId('facts-vertices')).toHaveText('2930');
  await page.getByTestId('random-source').click();
  await expect(body(page)).toHaveAttribute('data-separator-runs', '1', { timeout: 60_000 });
  await expect(page.getByTestId('error')).toBeHidden();
});
