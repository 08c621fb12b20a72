/**
 * The whole-shape stages of the timeline: entering All separators runs the pipeline in the worker
 * with a progress bar, its result is stepped through (All separators, Packing, Regions, Skeleton)
 * with each stage drawing its layers, a run can be cancelled without harming the page, and the
 * Reconstruction stage scores the skeleton.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { canvasStats, clickMesh, frameDifference, hueCensus } from './pixels.ts';
import { body, enterStage, expectStage, figure, layerBox, openPage, setCheck, setNumber, waitForState } from './studio.ts';

async function expectView(page: Page, key: string, title: string): Promise<void> {
  await expectStage(page, key, title);
  await waitForState(page, 'ready');
}

/** Hue ranges (degrees) of the whole-shape layers (web/src/ui/skeleton-panel.ts SK_COLORS). */
const HUES = {
  packed: [[175, 200]], // #00e1ff
  rejected: [[318, 346]], // #ff4f9a
  skeleton: [[5, 45]], // nodes #ff6a2b, edges #ffb02e
} as const;

/** Opens the sample with N sources set (the run starts when a whole-shape stage is entered). */
async function openWhole(page: Page, n: number): Promise<void> {
  await openPage(page);
  await setCheck(page, 'n-auto', false);
  await setNumber(page, 'n', n);
}

/** Records every value the progress bar shows ("done/total"), and when the status line said stage 1's progress, from the page itself. */
async function recordProgress(page: Page): Promise<void> {
  await page.evaluate(() => {
    const bar = document.querySelector<HTMLElement>('[data-testid="sk-progress"]')!;
    const status = document.querySelector<HTMLElement>('#status-text')!;
    const seen: string[] = [];
    const statusTimes: number[] = [];
    Object.assign(window, { progressSeen: seen, statusTimes });
    new MutationObserver(() => seen.push(`${bar.dataset.done}/${bar.dataset.total}`)).observe(bar, {
      attributes: true,
      attributeFilter: ['data-done', 'data-total'],
    });
    new MutationObserver(() => {
      if (status.textContent?.startsWith('stage 1')) statusTimes.push(performance.now());
    }).observe(status, { childList: true, characterData: true, subtree: true });
  });
}

const progressSeen = (page: Page) => page.evaluate(() => (window as unknown as { progressSeen: string[] }).progressSeen);
/** Times (ms) at which the status line was set to stage 1's progress. */
const statusTimes = (page: Page) => page.evaluate(() => (window as unknown as { statusTimes: number[] }).statusTimes);

test('entering All separators shows progress, then candidates, packing, regions and the skeleton', async ({ page }) => {
  test.slow(); // a pipeline run and a dozen pixel reads on a software renderer
  await openWhole(page, 20);
  const plain = await canvasStats(page);
  await recordProgress(page);
  await enterStage(page, 'separators');
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await waitForState(page, 'ready');

  // The bar advanced through several values up to 20 / 20.
  const seen = [...new Set(await progressSeen(page))];
  const done = seen.map((v) => Number(v.split('/')[0])).filter((d) => d > 0);
  expect(new Set(done).size, `distinct progress values seen: ${seen.join(' ')}`).toBeGreaterThanOrEqual(2);
  expect(seen).toContain('20/20');
  expect(done, 'progress never goes back').toEqual([...done].sort((a, b) => a - b));
  await expect(page.getByTestId('sk-progress')).toBeHidden();
  await expect(page.getByTestId('sk-status')).toHaveAttribute('data-status', 'done');
  // The status line follows the news at most every 500 ms on this software renderer (PROGRESS_TEXT_MS):
  // it was set after every source, a frame each, drawn on the cores the run computes on.
  const times = await statusTimes(page);
  expect(times.length, 'the status line showed stage 1').toBeGreaterThanOrEqual(1);
  const gaps = times.slice(1).map((t, i) => t - times[i]);
  expect(Math.min(...gaps, Infinity), `status updates ${times.map(Math.round).join(' ')} ms`).toBeGreaterThanOrEqual(450);

  // The figures.
  await expect(page.getByTestId('sk-n')).toHaveText('20');
  await expect(page.getByTestId('sk-seed')).toHaveText('1');
  const nodes = await figure(page, 'sk-nodes');
  const edges = await figure(page, 'sk-edges');
  const packed = await figure(page, 'sk-packed');
  const candidates = await figure(page, 'sk-candidates');
  expect(nodes, 'skeleton nodes').toBeGreaterThan(1);
  expect(edges, 'skeleton edges').toBeGreaterThanOrEqual(1);
  expect(packed, 'packed loops').toBeGreaterThanOrEqual(1);
  expect(candidates, 'candidates').toBeGreaterThanOrEqual(packed);
  expect(candidates).toBeLessThanOrEqual(20);
  expect(await figure(page, 'sk-pruned')).toBeGreaterThanOrEqual(0);
  expect(await figure(page, 'sk-cycles')).toBeGreaterThanOrEqual(0);
  expect(await figure(page, 'sk-regions')).toBeGreaterThan(1);
  await expect(page.getByTestId('sk-timing-stage1')).toHaveText(/\d+(\.\d)? (ms|s)/);
  await expect(page.getByTestId('sk-timing-stage2')).toHaveText(/\d+(\.\d)? (ms|s)/);

  for (const key of ['separators', 'packing', 'regions', 'skeleton']) {
    await expect(page.getByTestId(`stage-time-${key}`), `the time of ${key} under its pill`).toHaveText(/\d+(\.\d)? (ms|s)/);
  }

  // All separators: packed loops in cyan, the rejected ones in pink.
  await expectView(page, 'separators', 'All separators');
  const candidatesView = await hueCensus(page, HUES);
  expect(candidatesView.counts.packed, 'cyan pixels of the packed loops').toBeGreaterThan(150);
  if (candidates > packed) expect(candidatesView.counts.rejected, 'pink pixels of the rejected loops').toBeGreaterThan(50);
  await expect(page.getByTestId('stage-legend')).toContainText('packed');

  // Packing: only the packed loops.
  await page.getByTestId('stage-next').click();
  await expectView(page, 'packing', 'Packing');
  const packingView = await hueCensus(page, HUES);
  expect(packingView.counts.packed).toBeGreaterThan(150);
  expect(packingView.counts.rejected, 'no rejected loops any more').toBeLessThan(Math.max(20, candidatesView.counts.rejected * 0.1));
  await expect(layerBox(page, 'sk-rejected')).toHaveCount(0);

  // Regions: the surface in many distinct colours.
  await page.keyboard.press('ArrowRight');
  await expectView(page, 'regions', 'Regions');
  const regions = await canvasStats(page);
  expect(regions.saturatedFraction, 'the surface is coloured by region').toBeGreaterThan(0.5);
  expect(regions.hueBins, 'regions in many hues').toBeGreaterThanOrEqual(Math.min(5, nodes));
  expect(frameDifference(plain, regions), 'the picture changed').toBeGreaterThan(15);

  // Skeleton: warm spheres and tubes inside a see-through mesh.
  await page.getByTestId('stage-next').click();
  await expectView(page, 'skeleton', 'Skeleton');
  const skeleton = await hueCensus(page, HUES);
  const { width, height } = await canvasStats(page);
  expect(skeleton.counts.skeleton, 'orange pixels of the skeleton').toBeGreaterThan(300);
  expect(skeleton.translucent, 'the see-through mesh covers much of the view').toBeGreaterThan(0.05 * width * height);
  await layerBox(page, 'sk-nodes').uncheck();
  await layerBox(page, 'sk-edges').uncheck();
  const withoutSkeleton = await hueCensus(page, HUES);
  expect(withoutSkeleton.counts.skeleton, 'the orange is the skeleton layers').toBeLessThan(skeleton.counts.skeleton * 0.2);
  expect(withoutSkeleton.translucent, 'the mesh stays').toBeGreaterThan(skeleton.translucent * 0.8);
  await layerBox(page, 'sk-nodes').check();
  await layerBox(page, 'sk-edges').check();

  // Back to the Mesh stage: no skeleton layers, an opaque mesh, and a click runs stage 1.
  await enterStage(page, 'mesh');
  await waitForState(page, 'ready');
  const single = await canvasStats(page);
  expect(frameDifference(plain, single), 'the plain mesh again').toBeLessThan(2);
  await clickMesh(page, single);
  await expect(body(page)).toHaveAttribute('data-separator-runs', '1', { timeout: 30_000 });
  await expectView(page, 'geodesics', 'Geodesics');
  expect((await canvasStats(page)).hueBins, 'the distance colormap').toBeGreaterThanOrEqual(5);

  // And to the skeleton again: as it was left, not computed again.
  await enterStage(page, 'skeleton');
  await expectView(page, 'skeleton', 'Skeleton');
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', '1');
  expect((await hueCensus(page, HUES)).counts.skeleton).toBeGreaterThan(300);
});

test('a skeleton run can be cancelled and the page stays usable', async ({ page }) => {
  test.slow();
  // Far more sources than the test waits for: spot's 400 took 3 s on two workers, and a Cancel
  // pressed after the last source is too late (the result is being drawn).
  await openWhole(page, 3000);
  await enterStage(page, 'separators');
  await expect(body(page)).toHaveAttribute('data-sk-run', 'running');
  await expect(page.getByTestId('stage-separators')).toHaveAttribute('data-state', 'running');
  await expect(page.getByTestId('sk-progress')).toBeVisible();
  await expect.poll(async () => Number(await page.getByTestId('sk-progress').getAttribute('data-done')), { timeout: 30_000 }).toBeGreaterThan(0);
  await expect(page.getByTestId('sk-progress')).toHaveAttribute('data-total', '3000');
  await expect(page.getByTestId('sk-compute')).toBeDisabled();
  await page.getByTestId('sk-cancel').click();

  await expect(body(page)).toHaveAttribute('data-sk-run', 'cancelled', { timeout: 10_000 });
  await expect(page.getByTestId('sk-status')).toContainText('Cancelled');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('error')).toBeHidden();
  await expect(page.getByTestId('sk-cancel')).toBeHidden();
  await expect(page.getByTestId('sk-compute')).toBeEnabled();
  await expect(page.getByTestId('sk-result')).toBeHidden();
  const done = Number(await page.getByTestId('sk-progress').getAttribute('data-done'));
  expect(done, 'stopped long before the end').toBeLessThan(3000);

  // A later run works.
  await setNumber(page, 'n', 12);
  await setNumber(page, 'seed', 7);
  await page.getByTestId('sk-compute').click();
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await expect(page.getByTestId('sk-n')).toHaveText('12');
  await expect(page.getByTestId('sk-seed')).toHaveText('7');
  expect(await figure(page, 'sk-nodes')).toBeGreaterThan(1);
  await expect(page.getByTestId('sk-status')).toHaveAttribute('data-status', 'done');
});

test('a cancel that the worker cannot hear (a step that hangs) replaces the worker', async ({ page }) => {
  test.slow();
  await openWhole(page, 12);
  // The worker is stuck for a minute before it gets to the skeleton request.
  await page.evaluate(() => void window.cscd!.simulateCrash('hang'));
  await enterStage(page, 'separators');
  await expect(body(page)).toHaveAttribute('data-sk-run', 'running');
  await page.getByTestId('sk-cancel').click();
  await expect(page.getByTestId('sk-cancel')).toBeDisabled();

  // After the grace period the worker is replaced and the mesh re-opened: cancelled, no error.
  await expect(body(page)).toHaveAttribute('data-sk-run', 'cancelled', { timeout: 15_000 });
  await expect(page.getByTestId('sk-status')).toContainText('Cancelled');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('error')).toBeHidden();
  await expect(page.getByTestId('facts-vertices')).toHaveText('2930');

  // The new worker computes.
  await page.getByTestId('sk-compute').click();
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  expect(await figure(page, 'sk-nodes')).toBeGreaterThan(1);
});

test('the Reconstruction stage shows the convolution surface and each vertex error, with the number the CLI prints', async ({ page }) => {
  test.slow();
  await openWhole(page, 12);
  await enterStage(page, 'skeleton');
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await expectView(page, 'skeleton', 'Skeleton');
  const skeletonView = await canvasStats(page);
  await expect(page.getByTestId('stage-reconstruction')).toHaveAttribute('data-state', 'pending');

  // Entering the stage evaluates the skeleton (once).
  await enterStage(page, 'reconstruction');
  await expect(body(page)).toHaveAttribute('data-sk-recon', /\d/, { timeout: 60_000 });
  await expectView(page, 'reconstruction', 'Reconstruction');
  await expect(page.getByTestId('sk-recon-result')).toBeVisible();
  await expect(layerBox(page, 'sk-recon')).toBeChecked();
  await expect(page.getByTestId('stage-time-reconstruction')).toHaveText(/\d+(\.\d)? (ms|s)/);
  const shown = Number(await body(page).getAttribute('data-sk-recon'));
  await expect(page.getByTestId('sk-recon-mean')).toHaveText(shown.toPrecision(3));
  for (const id of ['sk-recon-median', 'sk-recon-p95']) await expect(page.getByTestId(id)).toHaveText(/^\d/);

  // The same skeleton and score from the CLI (the worker evaluates in full precision).
  const dir = mkdtempSync(path.join(tmpdir(), 'cscd-e2e-'));
  try {
    const run = (...args: string[]) => execFileSync(process.execPath, ['cli/cscd.mjs', ...args], { encoding: 'utf8' });
    const sample = 'public/samples/spot.ply';
    run('skeleton', sample, '--n', '12', '--out', path.join(dir, 's.json'));
    const printed = JSON.parse(run('evaluate', sample, path.join(dir, 's.json'))) as { reconError: number };
    expect(Math.abs(shown - printed.reconError) / printed.reconError).toBeLessThan(1e-9);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }

  // The surface in the colours of the error (many hues, opaque) under the see-through reconstruction.
  const recon = await canvasStats(page);
  expect(recon.hueBins, 'the error colormap').toBeGreaterThanOrEqual(5);
  expect(recon.saturatedFraction, 'the surface is coloured by the error').toBeGreaterThan(0.4);
  expect(frameDifference(skeletonView, recon), 'the picture changed').toBeGreaterThan(10);
  await layerBox(page, 'sk-recon').uncheck();
  expect(frameDifference(recon, await canvasStats(page)), 'the reconstructed shell is drawn').toBeGreaterThan(1);

  await layerBox(page, 'sk-recon').check();

  // Back at the Skeleton stage: the skeleton view as before.
  await enterStage(page, 'skeleton');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('sk-recon-result')).toBeHidden();
  expect(frameDifference(skeletonView, await canvasStats(page)), 'back to the skeleton view').toBeLessThan(2);
});
