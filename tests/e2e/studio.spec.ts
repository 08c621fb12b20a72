/**
 * The studio around the stages: the sample gallery, Random, a view restored from its link, parameter
 * changes re-running only what depends on them, the downloads (read back with lib/io), and picking a
 * skeleton node or a region.
 */
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { expect, test, type Download, type Page } from '@playwright/test';
import { parseMesh } from '../../lib/io/index.ts';
import { parseSkeleton, type SkeletonJson } from '../../lib/io/skeleton.ts';
import { repoRoot } from '../paths.ts';
import { canvasStats, frameDifference, maxCellDifference } from './pixels.ts';
import { body, enterStage, expectStage, figure, layerBox, openPage, runWhole, setCheck, setNumber, waitForState } from './studio.ts';

/** Spot's right horn and a close view of it (as in stages.spec.ts). */
const HORN = 1502;
const HORN_VIEW = { direction: [0.3, 1, -0.5], center: [0.17, 0.74, -0.28], radius: 0.3 } as const;

async function clickVertex(page: Page, vertex: number): Promise<void> {
  const at = await page.evaluate((v) => window.cscd!.projectVertex(v), vertex);
  expect(at).not.toBeNull();
  await page.mouse.click(at!.x, at!.y);
}

async function download(page: Page, testid: string): Promise<{ name: string; bytes: Buffer }> {
  const [file] = await Promise.all([page.waitForEvent('download'), page.getByTestId(testid).click()]);
  return { name: (file as Download).suggestedFilename(), bytes: readFileSync((await (file as Download).path())!) };
}

test('the gallery opens samples of each kind, and Random picks a source', async ({ page }) => {
  await openPage(page);
  await expect(page.getByTestId('sample-spot')).toHaveClass(/current/);
  const spot = await canvasStats(page);

  await page.getByTestId('sample-bob').click();
  await expect(page.getByTestId('file-name')).toHaveText('bob.ply');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-genus')).toHaveText('1');
  await expect(page.getByTestId('sample-bob')).toHaveClass(/current/);
  expect(page.url()).toContain('mesh=bob');
  expect(frameDifference(spot, await canvasStats(page)), 'Bob is drawn').toBeGreaterThan(10);

  await page.getByTestId('sample-fertility').click();
  await expect(page.getByTestId('facts-genus')).toHaveText('4');
  await page.getByTestId('sample-hand').click();
  await expect(page.getByTestId('facts-vertices')).toHaveText('10345');
  await waitForState(page, 'ready');
  await expectStage(page, 'mesh', 'Mesh');

  await page.getByTestId('random-source').click();
  await expect(body(page)).toHaveAttribute('data-separator-runs', '1', { timeout: 30_000 });
  await expectStage(page, 'geodesics', 'Geodesics');
  await waitForState(page, 'ready');
  const source = Number(await page.getByTestId('distance-source').textContent());
  expect(source).toBeGreaterThanOrEqual(0);
  expect(source).toBeLessThan(10345);
  expect((await canvasStats(page)).hueBins, 'the distance colormap').toBeGreaterThanOrEqual(5);
});

test('a link restores the mesh, the options, the stage and the source', async ({ page, context }) => {
  test.slow();
  await openPage(page);
  await page.evaluate((view) => window.cscd!.setView(view as never), HORN_VIEW);
  await clickVertex(page, HORN);
  await expect(body(page)).toHaveAttribute('data-separator-runs', '1', { timeout: 30_000 });
  await enterStage(page, 'loop');
  await setCheck(page, 'sphere', false);
  await expect(body(page)).toHaveAttribute('data-separator-runs', '2', { timeout: 30_000 });
  await setNumber(page, 'angleThreshold', 1.5);
  await expect(body(page)).toHaveAttribute('data-separator-runs', '3', { timeout: 30_000 });
  await waitForState(page, 'ready');
  const link = page.url();
  expect(link).toMatch(/stage=loop/);
  expect(link).toMatch(/source=1502/);
  expect(link).toMatch(/sphere=false/);
  expect(link).toMatch(/angleThreshold=1\.5/);

  const other = await context.newPage();
  await other.goto(link);
  await expect(body(other)).toHaveAttribute('data-separator-runs', '1', { timeout: 60_000 });
  await waitForState(other, 'ready');
  await expectStage(other, 'loop', 'Loop');
  await expect(other.getByTestId('distance-source')).toHaveText(String(HORN));
  await expect(other.getByTestId('sphere-radius')).toHaveText('off');
  await expect(other.getByTestId('opt-sphere').locator('input')).not.toBeChecked();
  await expect(other.getByTestId('opt-angleThreshold').locator('input')).toHaveValue('1.5');
  await expect(other.getByTestId('loop-length')).toHaveText((await page.getByTestId('loop-length').textContent())!);

  // A whole-shape stage in a link computes the skeleton with the linked options on arrival; a link
  // pasted into the same tab (only the hash changes) is followed too.
  await other.goto('/#mesh=wolf&stage=packing&n=12&seed=3');
  await expect(body(other)).toHaveAttribute('data-sk-run', 'done', { timeout: 90_000 });
  await waitForState(other, 'ready');
  await expectStage(other, 'packing', 'Packing');
  await expect(other.getByTestId('file-name')).toHaveText('wolf.ply');
  await expect(other.getByTestId('sk-n')).toHaveText('12');
  await expect(other.getByTestId('sk-seed')).toHaveText('3');
  await expect(other.getByTestId('opt-seed').locator('input')).toHaveValue('3');
});

test('a parameter change re-runs only what depends on it', async ({ page }) => {
  test.slow();
  await openPage(page);
  await page.evaluate((view) => window.cscd!.setView(view as never), HORN_VIEW);
  await clickVertex(page, HORN);
  await expect(body(page)).toHaveAttribute('data-separator-runs', '1', { timeout: 30_000 });
  await runWhole(page, 12);
  await enterStage(page, 'skeleton');
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', '1');

  // Every parameter says what it changes, in which unit, and what it re-runs.
  const tips: Record<string, RegExp> = {
    target: /euclid.*geodesic.*Re-runs the source/,
    sphere: /sphere.*Re-runs the source/,
    angleThreshold: /radians/,
    laplacianThreshold: /unitless/,
    pruneDepth: /edges/,
    'n-auto': /auto/,
    n: /Re-runs the whole shape/,
    seed: /same seed, same skeleton/,
    pruneLengthFactor: /mean edge lengths/,
  };
  for (const [option, tip] of Object.entries(tips)) await expect(page.getByTestId(`opt-${option}`)).toHaveAttribute('title', tip);

  // n: the whole shape again (it is on screen), not the single source.
  await setNumber(page, 'n', 14);
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', '2', { timeout: 60_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('sk-n')).toHaveText('14');
  await expect(body(page)).toHaveAttribute('data-separator-runs', '1');
  await expectStage(page, 'skeleton', 'Skeleton');

  // A stage-1 option: both depend on it.
  await setCheck(page, 'sphere', false);
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', '3', { timeout: 60_000 });
  await expect(body(page)).toHaveAttribute('data-separator-runs', '2', { timeout: 30_000 });
  await waitForState(page, 'ready');

  // A preset: Fast preview is 20 sources with the other defaults.
  await page.getByTestId('opt-preset').locator('select').selectOption('Fast preview');
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', '4', { timeout: 60_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('sk-n')).toHaveText('20');
  await expect(page.getByTestId('opt-sphere').locator('input')).toBeChecked();

  // Away from the whole shape, its result is dropped and recomputed only when entered again.
  await enterStage(page, 'geodesics');
  await setNumber(page, 'seed', 5);
  await expect(page.getByTestId('stage-skeleton')).toHaveAttribute('data-state', 'pending');
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', '4');
  await enterStage(page, 'skeleton');
  await expect(body(page)).toHaveAttribute('data-skeleton-runs', '5', { timeout: 60_000 });
  await expect(page.getByTestId('sk-seed')).toHaveText('5');
});

test('the skeleton, the separators and the picture download, and read back', async ({ page }) => {
  test.slow();
  await openPage(page);
  await expect(page.getByTestId('dl-skeleton-json')).toBeDisabled();
  await runWhole(page, 12);
  await enterStage(page, 'skeleton');
  await waitForState(page, 'ready');
  const nodes = await figure(page, 'sk-nodes');
  const edges = await figure(page, 'sk-edges');
  const packed = await figure(page, 'sk-packed');

  const json = await download(page, 'dl-skeleton-json');
  expect(json.name).toBe('spot-skeleton.json');
  const data = JSON.parse(json.bytes.toString('utf8')) as SkeletonJson;
  expect(data.mesh).toBe('spot.ply');
  expect(data.nodes).toHaveLength(nodes);
  expect(data.edges).toHaveLength(edges);
  expect(data.vertexToNode).toHaveLength(2930);
  expect(data.separators).toHaveLength(packed);
  expect(data.options.n).toBe(12);

  for (const format of ['json', 'ply', 'obj', 'swc'] as const) {
    const file = format === 'json' ? json : await download(page, `dl-skeleton-${format}`);
    expect(file.name).toBe(`spot-skeleton.${format}`);
    const skeleton = parseSkeleton(new Uint8Array(file.bytes), file.name);
    expect(skeleton.nodes.length / 3, `${format} nodes`).toBe(nodes);
    // SWC is a forest: cycles are broken (Spot has none, so nothing is lost).
    expect(skeleton.edges.length / 2, `${format} edges`).toBe(edges);
    for (let i = 0; i < 3 * nodes; i++) expect(Math.abs(skeleton.nodes[i] - data.nodes[Math.floor(i / 3)][i % 3])).toBeLessThan(1e-6);
  }

  // The separators: one closed polyline per packed loop, full precision.
  const loops = await download(page, 'dl-separators-obj');
  expect(loops.name).toBe('spot-separators.obj');
  const graph = parseSkeleton(new Uint8Array(loops.bytes), loops.name);
  expect(graph.nodes.length / 3).toBe(data.separators.reduce((n, loop) => n + loop.length, 0));
  expect(graph.edges.length / 2, 'closed loops: as many edges as points').toBe(graph.nodes.length / 3);
  expect(graph.nodes[0]).toBe(data.separators[0][0][0]);

  // The picture: a PNG of the canvas's size.
  const png = await download(page, 'dl-png');
  expect(png.name).toBe('spot-skeleton.png');
  expect(png.bytes.subarray(1, 4).toString('latin1')).toBe('PNG');
  const { width, height } = await canvasStats(page);
  expect([png.bytes.readUInt32BE(16), png.bytes.readUInt32BE(20)]).toEqual([width, height]);
});

test('clicking a skeleton node highlights its region; clicking a region selects its node', async ({ page }) => {
  test.slow();
  await openPage(page);
  await runWhole(page, 20);
  await enterStage(page, 'skeleton');
  await waitForState(page, 'ready');
  const before = await canvasStats(page);
  const data = JSON.parse((await download(page, 'dl-skeleton-json')).bytes.toString('utf8')) as SkeletonJson;

  // Node 0 owns the region of the first packed separator.
  const at = await page.evaluate(() => window.cscd!.projectNode(0));
  await page.mouse.click(at!.x, at!.y);
  await expect(body(page)).toHaveAttribute('data-sk-selected', '0');
  await waitForState(page, 'ready');
  const owned = data.vertexToNode.filter((n) => n === 0).length;
  await expect(page.getByTestId('sk-selection')).toContainText(`Node 0`);
  await expect(page.getByTestId('sk-selection')).toContainText(`${owned} vertices`);
  await expect(layerBox(page, 'sk-highlight')).toBeChecked();
  expect(maxCellDifference(before, await canvasStats(page)), 'the region is coloured on the see-through mesh, the node haloed').toBeGreaterThan(12);

  // In the Regions stage a click on the horn selects the node of the horn's region.
  await enterStage(page, 'regions');
  await page.evaluate((view) => window.cscd!.setView(view as never), HORN_VIEW);
  const mesh = parseMesh(new Uint8Array(readFileSync(path.join(repoRoot, 'public/samples/spot.ply'))), 'spot.ply');
  const ring = new Set<number>([data.vertexToNode[HORN]]);
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    const tri = [mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]];
    if (tri.includes(HORN)) for (const v of tri) ring.add(data.vertexToNode[v]);
  }
  await clickVertex(page, HORN);
  await expect(body(page)).not.toHaveAttribute('data-sk-selected', '0');
  const node = Number(await body(page).getAttribute('data-sk-selected'));
  expect([...ring], 'the node of the clicked vertex (or of a corner of its face)').toContain(node);

  // A click beside the mesh clears the selection.
  const canvas = (await page.getByTestId('viewport-canvas').boundingBox())!;
  await page.mouse.click(canvas.x + canvas.width - 8, canvas.y + canvas.height / 2);
  await expect(body(page)).not.toHaveAttribute('data-sk-selected', /./);
  await expect(page.getByTestId('sk-selection')).toBeHidden();
});
