/**
 * Point clouds in the page: a cloud dropped on the window opens as points (its facts, the neighbours
 * option), shows stage 1 from a clicked point stage by stage, and runs to a skeleton (stage 1 on the
 * pool of separator workers as a mesh's) and its reconstruction error; a cloud the checks refuse shows
 * the message the CLI gives, and the open shape stays.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { fixture } from '../paths.ts';
import { ringScannedTube, xyzText } from '../unit/support/clouds.ts';
import { canvasStats } from './pixels.ts';
import { body, downloadSkeletonJson, enterStage, expectStage, figure, layerBox, openPage, waitForState } from './studio.ts';

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

  // The reconstruction error against the cloud's points: the points in the error's colours, the number `cscd evaluate` prints.
  const skeletonView = await canvasStats(page);
  await enterStage(page, 'reconstruction');
  await expect(body(page)).toHaveAttribute('data-sk-recon', /\d/, { timeout: 60_000 });
  await expect(layerBox(page, 'sk-recon')).toBeChecked();
  await expect(page.getByTestId('stage-caption')).toContainText('against the cloud’s points');
  const shown = Number(await body(page).getAttribute('data-sk-recon'));
  const dir = mkdtempSync(path.join(tmpdir(), 'cscd-e2e-'));
  try {
    const run = (...args: string[]) => execFileSync(process.execPath, ['cli/cscd.mjs', ...args], { encoding: 'utf8' });
    const cloud = fixture('clouds', 'bob_subsample.ply');
    run('skeleton', cloud, '--n', '40', '--out', path.join(dir, 's.json'));
    const printed = JSON.parse(run('evaluate', cloud, path.join(dir, 's.json'))) as { reconError: number };
    expect(Math.abs(shown - printed.reconError) / printed.reconError).toBeLessThan(1e-9);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  expect((await canvasStats(page)).hueBins, 'the points in the error colormap').toBeGreaterThan(skeletonView.hueBins);
});

test('a cloud with stray points opens without them, and the notes say how many went', async ({ page }) => {
  // bob_strays.ply: bob_subsample's 1948 points and 24 strays around them (tests/fixtures/clouds/make.ts).
  await openPage(page);
  await drop(page, 'bob_strays.ply', readFileSync(fixture('clouds', 'bob_strays.ply')));
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points', { timeout: 30_000 });
  await expect(page.getByTestId('warnings')).toContainText('Repaired: removed 24 stray points');
});

test('a click on a point shows stage 1 on the cloud: the distance, cut locus, paths, the shortening steps and the loop', async ({ page }) => {
  await openPage(page);
  await page.getByTestId('file-input').setInputFiles({ name: 'bob_subsample.ply', mimeType: 'application/octet-stream', buffer: readFileSync(fixture('clouds', 'bob_subsample.ply')) });
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points', { timeout: 30_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('stage-section')).toHaveText('Sec. 4');
  const plain = await canvasStats(page);
  expect(plain.hueBins, 'the points are plain before a source').toBeLessThanOrEqual(2);

  // Points whose loop is found: the first of a few front points that gives one (a source can fail).
  const status = page.getByTestId('separator-status');
  for (let i = 0, runs = 0; i < 1948 && (await status.getAttribute('data-status')) !== 'ok'; i += 97) {
    const p = await page.evaluate((k) => window.cscd!.projectVertex(k), i);
    if (!p) continue;
    await page.mouse.click(p.x, p.y);
    await expect(body(page)).toHaveAttribute('data-separator-runs', String(++runs), { timeout: 30_000 });
    await waitForState(page, 'ready');
  }
  await expect(status).toHaveAttribute('data-status', 'ok');
  await expectStage(page, 'geodesics', 'Geodesics');
  await expect(page.getByTestId('stage-caption')).toContainText('tufted Laplacian');
  expect((await canvasStats(page)).hueBins, 'the points are coloured by their distance').toBeGreaterThanOrEqual(5);
  expect(Number(await page.getByTestId('distance-source').textContent())).toBeLessThan(1948);

  await enterStage(page, 'cut-locus');
  await expect(layerBox(page, 'cut-locus')).toBeChecked();
  expect(Number(await page.getByTestId('cut-nodes').textContent())).toBeGreaterThan(3);
  await enterStage(page, 'paths');
  for (const layer of ['target', 'path-1', 'path-2']) await expect(layerBox(page, layer)).toBeChecked();

  await enterStage(page, 'loop');
  await expect(page.getByTestId('stage-caption')).toContainText('optimization based framework');
  await expect(page.getByTestId('stage-caption')).toContainText('moving-least-squares');
  for (const layer of ['approx-loop', 'iterates', 'loop']) await expect(layerBox(page, layer)).toBeChecked();
  await expect(page.getByTestId('stage-legend')).toContainText('shortening steps');
  const loopLength = Number(await page.getByTestId('loop-length').textContent());
  const approxLength = Number(await page.getByTestId('approx-length').textContent());
  expect(loopLength, 'the shortening shortens').toBeLessThan(approxLength);
  await expect(page.getByTestId('score')).toHaveText(/^\d/);
  await expect(page.getByTestId('error')).toBeHidden();
});

/** `n` points on a Fibonacci sphere, as an XYZ file. */
function sphereXyz(n: number): Buffer {
  const rows = Array.from({ length: n }, (_, i) => {
    const z = 1 - (2 * i + 1) / n, r = Math.sqrt(1 - z * z), a = i * 2.399963229728653;
    return `${(r * Math.cos(a)).toFixed(6)} ${(r * Math.sin(a)).toFixed(6)} ${z.toFixed(6)}`;
  });
  return Buffer.from(rows.join('\n'));
}

test('a cloud above the point limit is computed on a subsample, said in the notes, and on all its points when asked', async ({ page }) => {
  // 120,000 points: above POINT_LIMIT (100,000), subsampled to at most 50,000; three of them strays far
  // from the sphere, removed from the points computed on either way.
  const n = 120_000;
  const strays = Buffer.from('\n5 5 5\n-5 4 3\n0 -6 2');
  await openPage(page);
  await page.getByTestId('file-input').setInputFiles({ name: 'sphere.xyz', mimeType: 'text/plain', buffer: Buffer.concat([sphereXyz(n - 3), strays]) });
  await expect(page.getByTestId('warnings')).toContainText(`Repaired: subsampled from ${n} to`, { timeout: 60_000 });
  await expect(page.getByTestId('warnings')).toContainText('removed 3 stray points');
  await waitForState(page, 'ready');
  const points = Number((await page.getByTestId('facts-vertices').textContent())?.match(/^\d+/)?.[0]);
  expect(points).toBeGreaterThan(45_000);
  expect(points).toBeLessThanOrEqual(50_000);
  // The offer: every stage runs on the subsample meanwhile; all the points when asked.
  await expect(page.getByTestId('limit-offer-text')).toContainText(`has 120,000 points, more than the 100,000 advised: every stage runs on a subsample of ${points.toLocaleString('en-US')}`);
  await expect(page.getByTestId('limit-decimate')).toBeHidden();
  await expect(page.getByTestId('stage-separators'), 'the subsample computes meanwhile').toBeEnabled();
  // Drawn: the subsample and points left out of it, 100,000 in all on a software renderer (these tests'), all on a GPU.
  expect(await page.evaluate(() => window.cscd!.cloudPoints())).toEqual({ drawn: 100_000, computedOn: points });
  await page.getByTestId('limit-full').click();
  await expect(page.getByTestId('facts-vertices')).toHaveText(`${n - 3} points`, { timeout: 60_000 });
  await waitForState(page, 'ready');
  expect(await page.evaluate(() => window.cscd!.cloudPoints())).toEqual({ drawn: n - 3, computedOn: n - 3 });
  await expect(page.getByTestId('limit-offer')).toBeHidden();
  await expect(page.getByTestId('warnings')).not.toContainText('subsampled');
  await expect(page.getByTestId('warnings')).toContainText('removed 3 stray points');
});

test('a cloud whose points all would not fit in a core is not offered whole, and is drawn with points left out of its subsample', async ({ page }) => {
  // Cores capped at 640 MB: the 49,000-point subsample opens (about 400 MB), a skeleton of all 120,000 points would need about 1.4 GB.
  await openPage(page, '/?memoryLimitMB=640');
  await page.getByTestId('file-input').setInputFiles({ name: 'sphere.xyz', mimeType: 'text/plain', buffer: sphereXyz(120_000) });
  await expect(page.getByTestId('warnings')).toContainText('Repaired: subsampled from 120000 to', { timeout: 60_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('limit-offer-text')).toContainText('MB in a core, more than its 640 MB');
  await expect(page.getByTestId('limit-full')).toBeHidden();
  await expect(page.getByTestId('stage-separators')).toBeEnabled();
  // Points left out of the subsample are drawn too (up to 100,000 in all on a software renderer, as here);
  // a click on any point drawn is a source among the points computed on.
  const points = await page.evaluate(() => window.cscd!.cloudPoints());
  expect(points?.drawn).toBe(100_000);
  expect(points?.computedOn).toBeLessThanOrEqual(50_000);
  // About half the points drawn are left out of the subsample: of four clicks some fall on them.
  const box = (await page.getByTestId('viewport-canvas').boundingBox())!;
  for (let k = 1; k <= 4; k++) {
    await page.mouse.click(box.x + box.width / 2 + 9 * k, box.y + box.height / 2);
    await expect(body(page)).toHaveAttribute('data-separator-runs', String(k), { timeout: 60_000 });
    await waitForState(page, 'ready');
    expect(Number(await page.getByTestId('distance-source').textContent())).toBeLessThan(points!.computedOn);
  }
  expect((await canvasStats(page)).hueBins, 'every point drawn coloured by the distance').toBeGreaterThanOrEqual(5);
});

test('a mesh runs as a point cloud of its vertices, and as the mesh again', async ({ page }) => {
  // Bob (genus 1) as the cloud of its 5344 vertices, n = 24 (1 cycle from the CLI: tests/unit/mesh-as-cloud.test.ts runs spot).
  await openPage(page, '/#mesh=bob&n=24', '5344');
  await expect(page.getByTestId('as-cloud-row')).toBeVisible();
  await expect(page.getByTestId('as-cloud')).not.toBeChecked();
  await page.getByTestId('as-cloud').check();
  await expect(page.getByTestId('facts-vertices')).toHaveText('5344 points', { timeout: 30_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-faces')).toHaveText('–');
  await expect(page.getByTestId('warnings')).toContainText('the mesh runs as a point cloud: its 5344 vertices, with their faces’ normals');
  await expect(page.getByTestId('opt-neighbours')).toBeVisible();
  await expect(page.getByTestId('as-cloud')).toBeChecked();
  await expect(page, 'a link keeps the choice').toHaveURL(/asCloud=1/);
  await enterStage(page, 'separators');
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await waitForState(page, 'ready');
  expect(await figure(page, 'sk-cycles'), 'bob\'s handle, from its vertices').toBe(1);

  await page.getByTestId('as-cloud').uncheck();
  await expect(page.getByTestId('facts-vertices')).toHaveText('5344', { timeout: 30_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-faces')).toHaveText('10688');
  await expect(page.getByTestId('opt-neighbours')).toBeHidden();
  await expect(page.getByTestId('as-cloud-row')).toBeVisible();
  await expect(page).not.toHaveURL(/asCloud/);

  // The link of a sample run as a cloud opens it so.
  await openPage(page, '/#mesh=spot&asCloud=1', '2930 points');
  await expect(page.getByTestId('as-cloud')).toBeChecked();

  // A cloud file has no mesh to go back to.
  await page.getByTestId('file-input').setInputFiles({ name: 'bob_subsample.ply', mimeType: 'application/octet-stream', buffer: readFileSync(fixture('clouds', 'bob_subsample.ply')) });
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points', { timeout: 30_000 });
  await expect(page.getByTestId('as-cloud-row')).toBeHidden();
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

test('changing neighbours opens the cloud again with them, and the panel says how many lie flat', async ({ page }) => {
  await openPage(page);
  await page.getByTestId('file-input').setInputFiles({ name: 'bob_subsample.ply', mimeType: 'application/octet-stream', buffer: readFileSync(fixture('clouds', 'bob_subsample.ply')) });
  // 19.2 of bob_subsample's 30 nearest lie flat on average (tests/unit/cloud-flat-neighbours.test.ts); at 12, all 12.
  await expect(page.getByTestId('facts-mean-edge')).toContainText('30 neighbours, 19.2 flat', { timeout: 30_000 });
  const input = page.getByTestId('opt-neighbours').locator('input');
  await input.fill('12');
  await input.press('Enter');
  await expect(page.getByTestId('facts-mean-edge')).toContainText('12 neighbours, 12.0 flat', { timeout: 30_000 });
  await expect(page.getByTestId('facts-vertices')).toHaveText('1948 points');
});

test('a cloud scanned in lines too far apart for its neighbours is said in the notes, until more neighbours reach across', async ({ page }) => {
  // The tube of tests/unit/cloud-scan-lines.test.ts: 12 rings of 300 points; 100 neighbours reach the next rings.
  await openPage(page);
  await drop(page, 'tube.xyz', Buffer.from(xyzText(ringScannedTube(12, 300, 0.36))));
  await expect(page.getByTestId('facts-vertices')).toHaveText('3600 points', { timeout: 30_000 });
  await expect(page.getByTestId('warnings')).toContainText('100% of the points have their 30 nearest neighbours along a line');
  await expect(page.getByTestId('facts-components')).toHaveText('12');
  const input = page.getByTestId('opt-neighbours').locator('input');
  await input.fill('100');
  await input.press('Enter');
  await expect(page.getByTestId('facts-mean-edge')).toContainText('100 neighbours', { timeout: 30_000 });
  await expect(page.getByTestId('facts-components')).toHaveText('1');
  await expect(page.getByTestId('warnings')).not.toContainText('along a line');
});

test('a cloud scanned in lines is offered a subsample thinned along its lines, which opens it in one piece', async ({ page }) => {
  await openPage(page);
  await drop(page, 'tube.xyz', Buffer.from(xyzText(ringScannedTube(12, 300, 0.36))));
  await expect(page.getByTestId('facts-vertices')).toHaveText('3600 points', { timeout: 30_000 });
  await expect(page.getByTestId('warnings')).toContainText('thin the points along the lines (they lie 0.36 apart: to about 420 points');
  const offer = page.getByTestId('subsample-lines');
  await expect(offer).toHaveText('Subsample to 420 points (thinned along the lines)');
  await offer.click();
  // The subsample of tests/unit/cloud-scan-lines.test.ts (lib/cloud/subsample.ts, seed 1).
  await expect(page.getByTestId('facts-vertices')).toHaveText('398 points', { timeout: 30_000 });
  await expect(page.getByTestId('facts-components')).toHaveText('1');
  await expect(page.getByTestId('warnings')).toContainText('Repaired: subsampled from 3600 to 398 points (Poisson-disk, seed 1): as asked');
  await expect(page.getByTestId('warnings')).not.toContainText('along a line');
  await expect(offer).toBeHidden();
  await expect(page.getByTestId('limit-offer'), 'no offer of all the points: the subsample was asked for').toBeHidden();
});

test('a mesh too small to run as a cloud is refused with the message, and stays open as a mesh', async ({ page }) => {
  await openPage(page);
  await page.getByTestId('file-input').setInputFiles({ name: 'cube.obj', mimeType: 'text/plain', buffer: readFileSync(fixture('formats', 'cube.obj')) });
  await expect(page.getByTestId('facts-vertices')).toHaveText('8', { timeout: 30_000 });
  await waitForState(page, 'ready');
  // A click, not check(): the refusal can untick the box before check() looks at it.
  await page.getByTestId('as-cloud').click();
  await expect(page.getByTestId('error')).toBeVisible({ timeout: 20_000 });
  await expect(page.getByTestId('error')).toContainText('the cloud has 8 points, too few for the neighbour count k = 30');
  await expect(page.getByTestId('as-cloud'), 'the box says what is open').not.toBeChecked();
  await expect(page.getByTestId('facts-vertices')).toHaveText('8');
  await expect(page.getByTestId('facts-faces')).toHaveText('12');
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
