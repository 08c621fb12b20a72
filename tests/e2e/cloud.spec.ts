/**
 * Point clouds in the page: a cloud dropped on the window opens as points (its facts, the neighbours
 * option, the mesh-only stages disabled) and runs to a skeleton, stage 1 on the pool of separator workers
 * as a mesh's; a cloud the checks refuse shows the message the CLI gives, and the open shape stays.
 */
import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { fixture } from '../paths.ts';
import { body, downloadSkeletonJson, enterStage, figure, layerBox, openPage, waitForState } from './studio.ts';

/** Drops a file on the window as a user's drag and drop does. */
async function drop(page: Page, name: string, bytes: Buffer): Promise<void> {
  const transfer = await page.evaluateHandle(
    ({ name, data }) => {
      const dt = new DataTransfer();
      dt.items.add(new File([new Uint8Array(data)], name));
      return dt;
    },
    { name, data: [...bytes] },
  );
  await page.dispatchEvent('body', 'drop', { dataTransfer: transfer });
}

/** `rows` points of an XYZ file, z from `z(i)`. */
const xyz = (rows: number, z: (i: number) => number) =>
  Buffer.from(Array.from({ length: rows }, (_, i) => `${i % 10} ${Math.floor(i / 10)} ${z(i)}`).join('\n'));

test('a dropped point cloud runs to a skeleton with its cycle, on two workers', async ({ page }) => {
  // n = 40, seed 1: bob_subsample keeps its one cycle (tests/unit/cloud-skeleton.test.ts); two workers asked for.
  await openPage(page, '/#n=40&workers=2');
  await expect(page.getByTestId('opt-neighbours')).toBeHidden();
  await drop(page, 'bob_subsample.ply', readFileSync(fixture('clouds', 'bob_subsample.ply')));
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points', { timeout: 30_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-faces')).toHaveText('–');
  await expect(page.getByTestId('warnings')).toContainText('Point cloud:');
  await expect(page.getByTestId('opt-neighbours')).toBeVisible();
  for (const key of ['geodesics', 'cut-locus', 'paths', 'loop', 'reconstruction']) {
    await expect(page.getByTestId(`stage-${key}`), `${key} is for meshes`).toBeDisabled();
  }

  await enterStage(page, 'separators');
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await waitForState(page, 'ready');
  expect(await figure(page, 'sk-cycles')).toBe(1);
  expect(await figure(page, 'sk-nodes')).toBeGreaterThan(1);
  await expect(page.getByTestId('sk-n')).toHaveText('40');
  await expect(page.getByTestId('sk-status')).toContainText('Stage 1 on 2 workers.');
  const run = await page.evaluate(() => window.cscd!.skeletonRun());
  expect(run?.workers).toBe(2);
  // The file saved is the CLI's, with a node per point.
  const json = await downloadSkeletonJson(page);
  expect(json.vertexToNode).toHaveLength(1948);
  expect(json.stats.cycles).toBe(1);

  // A click on a point selects its node, whose region is its points.
  await enterStage(page, 'regions');
  const p = await page.evaluate(() => window.cscd!.projectVertex(0));
  await page.mouse.click(p!.x, p!.y);
  await expect(body(page)).toHaveAttribute('data-sk-selected', /^\d+$/);
  await expect(page.getByTestId('sk-selection')).toContainText('its region');

  await enterStage(page, 'skeleton');
  await expect(layerBox(page, 'sk-nodes')).toBeChecked();
  await expect(page.getByTestId('error')).toBeHidden();
});

test('a cloud above the point limit is computed on a subsample, said in the notes', async ({ page }) => {
  // 120,000 points on a Fibonacci sphere: above POINT_LIMIT (100,000), subsampled to at most 50,000.
  const n = 120_000;
  const rows = Array.from({ length: n }, (_, i) => {
    const z = 1 - (2 * i + 1) / n, r = Math.sqrt(1 - z * z), a = i * 2.399963229728653;
    return `${(r * Math.cos(a)).toFixed(6)} ${(r * Math.sin(a)).toFixed(6)} ${z.toFixed(6)}`;
  });
  await openPage(page);
  await page.getByTestId('file-input').setInputFiles({ name: 'sphere.xyz', mimeType: 'text/plain', buffer: Buffer.from(rows.join('\n')) });
  await expect(page.getByTestId('warnings')).toContainText(`Repaired: subsampled from ${n} to`, { timeout: 60_000 });
  await waitForState(page, 'ready');
  const points = Number((await page.getByTestId('facts-vertices').textContent())?.match(/^\d+/)?.[0]);
  expect(points).toBeGreaterThan(45_000);
  expect(points).toBeLessThanOrEqual(50_000);
});

test('a run on a cloud streams its candidate loops and can be cancelled', async ({ page }) => {
  await openPage(page, '/#n=2000');
  await page.getByTestId('file-input').setInputFiles({ name: 'bob_subsample.ply', mimeType: 'application/octet-stream', buffer: readFileSync(fixture('clouds', 'bob_subsample.ply')) });
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points', { timeout: 30_000 });
  await enterStage(page, 'separators');
  await expect(page.getByTestId('sk-progress')).toHaveAttribute('data-total', '2000');
  await expect.poll(async () => Number(await page.getByTestId('sk-progress').getAttribute('data-done')), { timeout: 30_000 }).toBeGreaterThan(0);
  await expect(layerBox(page, 'sk-progress')).toBeVisible();
  await page.getByTestId('sk-cancel').click();
  await expect(body(page)).toHaveAttribute('data-sk-run', 'cancelled', { timeout: 10_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('error')).toBeHidden();
});

test('after a crash of the core the worker is restarted with the cloud, and the skeleton is computed', async ({ page }) => {
  await openPage(page, '/#n=8');
  await page.getByTestId('file-input').setInputFiles({ name: 'bob_subsample.ply', mimeType: 'application/octet-stream', buffer: readFileSync(fixture('clouds', 'bob_subsample.ply')) });
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points', { timeout: 30_000 });
  await page.evaluate(() => window.cscd!.simulateCrash('abort'));
  await expect(page.getByRole('alert')).toContainText('Aborted(simulated crash)');
  await waitForState(page, 'error');
  await enterStage(page, 'separators');
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await expect(page.getByTestId('sk-n')).toHaveText('8');
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points');
});

test('changing neighbours opens the cloud again with them', async ({ page }) => {
  await openPage(page);
  await page.getByTestId('file-input').setInputFiles({ name: 'bob_subsample.ply', mimeType: 'application/octet-stream', buffer: readFileSync(fixture('clouds', 'bob_subsample.ply')) });
  await expect(page.getByTestId('facts-mean-edge')).toContainText('30 neighbours', { timeout: 30_000 });
  const input = page.getByTestId('opt-neighbours').locator('input');
  await input.fill('12');
  await input.press('Enter');
  await expect(page.getByTestId('facts-mean-edge')).toContainText('12 neighbours', { timeout: 30_000 });
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points');
});

for (const [name, bytes, message] of [
  ['flat.xyz', xyz(100, () => 0), 'all 100 points lie on one plane'],
  ['few.xyz', xyz(20, (i) => (i * 7) % 3), 'the cloud has 20 points, too few for the neighbour count k = 30'],
] as const) {
  test(`a bad cloud is refused with its message: ${name}`, async ({ page }) => {
    await openPage(page);
    await drop(page, name, bytes);
    await expect(page.getByTestId('error')).toBeVisible({ timeout: 20_000 });
    await expect(page.getByTestId('error')).toContainText(message);
    // Spot stays open.
    await expect(page.getByTestId('facts-vertices')).toHaveText('2930');
  });
}
