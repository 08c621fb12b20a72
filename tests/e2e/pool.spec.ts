/**
 * Stage 1 on the page's pool of separator workers (web/src/worker/page-pool.ts): the skeleton JSON
 * does not depend on the `workers` setting, a cancel stops every worker and a later run works, and a
 * separator worker that crashes is reported while the run finishes on the others, with the same
 * skeleton. On Spot (the page's sample, 2930 vertices), n = 12, 4 drawn ahead, seed 7.
 */
import { expect, test, type Page } from '@playwright/test';
import { body, comparable, downloadSkeletonJson, enterStage, openPage, setCheck, setNumber, waitForState } from './studio.ts';

const RUN = 'n=12&drawAhead=4&seed=7';

/** The run shown: its sources and the threads stage 1 started on. */
const shownRun = (page: Page) => page.evaluate(() => window.cscd!.skeletonRun());

/** Runs the whole shape again with `workers` threads and waits for its result (the `runs`-th shown). */
async function runWith(page: Page, workers: number, runs: number): Promise<void> {
  await setCheck(page, 'workers-auto', false);
  await setNumber(page, 'workers', workers);
  // A run setting, not an option: the skeleton shown stays (an option change would drop it at once).
  expect(await shownRun(page)).not.toBeNull();
  await page.getByTestId('sk-compute').click();
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', String(runs), { timeout: 60_000 });
  await waitForState(page, 'ready');
}

/** The saved skeleton JSON without its wall-clock times and file name, as text. */
const savedJson = async (page: Page) => JSON.stringify(comparable(await downloadSkeletonJson(page)));

test('the saved skeleton is the same, byte for byte, on 1, 2 and 3 workers', async ({ page }) => {
  test.slow();
  await openPage(page, `/#${RUN}&workers=1&stage=separators`);
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await waitForState(page, 'ready');
  expect(await shownRun(page)).toMatchObject({ sources: 12, workers: 1 });
  await enterStage(page, 'skeleton');
  const alone = await savedJson(page);
  expect(JSON.parse(alone)).toMatchObject({ options: { n: 12, drawAhead: 4, seed: 7 } });
  expect(alone).not.toMatch(/workers/);
  await expect(page.getByTestId('opt-workers')).toHaveAttribute('title', /Threads that compute stage 1.*the skeleton does not depend on it/);

  for (const [workers, runs] of [[2, 2], [3, 3]]) {
    await runWith(page, workers, runs);
    expect(await shownRun(page), `${workers} workers`).toMatchObject({ sources: 12, workers });
    await expect(page.getByTestId('sk-status')).toContainText(`Stage 1 on ${workers} workers.`);
    expect(await savedJson(page), `${workers} workers`).toBe(alone);
  }
  await expect(page).toHaveURL(/workers=3/);
});

test('a cancel during stage 1 stops every worker; the next run finishes on a new pool', async ({ page }) => {
  test.slow();
  await openPage(page, '/#n=3000&drawAhead=4&workers=2');
  const started: { script: string; closed: boolean }[] = [];
  page.on('worker', (worker) => {
    const seen = { script: /assets\/([a-z-]+)-/.exec(worker.url())?.[1] ?? worker.url(), closed: false };
    started.push(seen);
    worker.on('close', () => (seen.closed = true));
  });
  await enterStage(page, 'separators');
  await expect.poll(async () => Number(await page.getByTestId('sk-progress').getAttribute('data-done')), { timeout: 30_000 }).toBeGreaterThanOrEqual(8);
  expect(started).toEqual([{ script: 'separator-worker', closed: false }, { script: 'separator-worker', closed: false }]);
  await page.getByTestId('sk-cancel').click();
  await expect(body(page)).toHaveAttribute('data-sk-run', 'cancelled', { timeout: 10_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('error')).toBeHidden();
  expect(Number(await page.getByTestId('sk-progress').getAttribute('data-done'))).toBeLessThan(3000);
  // The separator workers are stopped; the geometry worker stopped the run itself (the page did not have to replace it).
  await expect.poll(() => started).toEqual([{ script: 'separator-worker', closed: true }, { script: 'separator-worker', closed: true }]);

  await setNumber(page, 'n', 12);
  await page.getByTestId('sk-compute').click();
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  expect(await shownRun(page)).toMatchObject({ sources: 12, workers: 2 });
  await expect(page.getByTestId('sk-status')).not.toContainText('crashed');
  expect(started.map((w) => w.script)).toEqual(Array(4).fill('separator-worker'));
});

test('a separator worker that crashes is reported, the run finishes with the same skeleton, and it is replaced', async ({ page }) => {
  test.slow();
  // The first separator worker aborts on its 2nd request (main.ts, client.ts test hook).
  await openPage(page, `/?separatorCrash=2#${RUN}&workers=2&stage=separators`);
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('sk-status')).toContainText('A separator worker crashed (Aborted(simulated crash)): continuing on 1 worker.');
  await expect(page.getByTestId('error')).toBeHidden();
  expect(await shownRun(page)).toMatchObject({ sources: 12, workers: 2 });
  await enterStage(page, 'skeleton');
  const crashed = await savedJson(page);

  // The next run has a new separator worker, which does not crash.
  await runWith(page, 2, 2);
  await expect(page.getByTestId('sk-status')).toContainText('Stage 1 on 2 workers.');
  await expect(page.getByTestId('sk-status')).not.toContainText('crashed');
  expect(await savedJson(page)).toBe(crashed);

  await runWith(page, 1, 3);
  expect(await savedJson(page), 'the skeleton of one worker').toBe(crashed);
});
