/**
 * Stage 1 of CSCD-M on the timeline (Geodesics, Cut locus, Target & paths, Loop): a click on Spot's
 * horn runs the separator; every stage's layer must show up in its colour, and option changes must
 * re-run it in place.
 */
import { expect, test, type Page } from '@playwright/test';
import { canvasStats, colorCensus, frameDifference, type LayerHue, type PixelStats } from './pixels.ts';
import { body, expectStage, layerBox, openPage, setCheck, waitForState } from './studio.ts';

/** A vertex at the base of Spot's right horn: its separator is a loop around the horn. */
const HORN = 1502;
/** A close view of that horn from above and in front (camera direction, centre, radius of view). */
const HORN_VIEW = { direction: [0.3, 1, -0.5], center: [0.17, 0.74, -0.28], radius: 0.3 } as const;

async function waitForRun(page: Page, run: number): Promise<void> {
  await expect(body(page)).toHaveAttribute('data-separator-runs', String(run), { timeout: 30_000 });
  await waitForState(page, 'ready');
}

/** Opens the sample, looks at the horn and clicks the horn vertex, as a user would. */
async function clickHorn(page: Page): Promise<void> {
  await openPage(page);
  await page.evaluate((view) => window.cscd!.setView(view as never), HORN_VIEW);
  const at = await page.evaluate((v) => window.cscd!.projectVertex(v), HORN);
  expect(at).not.toBeNull();
  await page.mouse.click(at!.x, at!.y);
  await waitForRun(page, 1);
  await expect(page.getByTestId('distance-source')).toHaveText(String(HORN));
}

/** Opens the sample and clicks a vertex in the default view. */
async function clickVertex(page: Page, vertex: number): Promise<void> {
  await openPage(page);
  const at = await page.evaluate((v) => window.cscd!.projectVertex(v), vertex);
  expect(at).not.toBeNull();
  await page.mouse.click(at!.x, at!.y);
  await waitForRun(page, 1);
  await expect(page.getByTestId('distance-source')).toHaveText(String(vertex));
}

/**
 * Pixels of `hue` with the layer shown must clearly outnumber those with it switched off through the
 * layer list (so the colour is the layer's, not the surface's); returns the count with it shown.
 */
async function expectLayerColor(page: Page, layer: string, hue: LayerHue, minPixels: number): Promise<number> {
  const shown = (await colorCensus(page))[hue];
  await layerBox(page, layer).uncheck();
  const hidden = (await colorCensus(page))[hue];
  await layerBox(page, layer).check();
  expect(shown, `${hue} pixels of the ${layer} layer`).toBeGreaterThan(minPixels);
  expect(hidden, `${hue} pixels left with the ${layer} layer switched off`).toBeLessThan(shown * 0.2);
  return shown;
}

test('a click runs stage 1 and Next steps through every stage, each drawing its layer', async ({ page }) => {
  test.slow(); // about 25 pixel reads of the WebGL canvas on a software renderer
  await clickHorn(page);
  await expect(page.getByTestId('separator-status')).toHaveAttribute('data-status', 'ok');
  await expect(page.getByTestId('separator-status')).toContainText('Separator found');

  // Geodesics: the distance colormap, no stage-1 layer yet; the click moved on from the Mesh stage.
  await expectStage(page, 'geodesics', 'Geodesics');
  await expect(page.getByTestId('stage-index')).toHaveText('2');
  const distance = await canvasStats(page);
  expect(distance.hueBins, 'the colormap spans many hues').toBeGreaterThanOrEqual(5);
  expect(distance.saturatedFraction, 'most of the mesh is coloured').toBeGreaterThan(0.5);
  await expect(layerBox(page, 'cut-locus')).toHaveCount(0);
  await expect(page.getByTestId('timing-separator')).toHaveText(/\d+(\.\d)? (ms|s)/);
  await expect(page.getByTestId('timing-stage-distance')).toHaveText(/\d+(\.\d)? (ms|s)/);
  for (const key of ['geodesics', 'cut-locus', 'paths', 'loop']) {
    await expect(page.getByTestId(`stage-time-${key}`), `the time of ${key} under its pill`).toHaveText(/\d+(\.\d)? (ms|s)/);
  }

  const next = page.getByTestId('stage-next');
  const frames: PixelStats[] = [distance];
  const step = async (key: string, title: string) => {
    await next.click();
    await expectStage(page, key, title);
    await waitForState(page, 'ready');
    const frame = await canvasStats(page);
    expect(frameDifference(frames[frames.length - 1], frame), `${key} changes the picture`).toBeGreaterThan(0.3);
    frames.push(frame);
  };

  // The cut locus in yellow, over a dimmed colormap.
  await step('cut-locus', 'Cut locus');
  await expectLayerColor(page, 'cut-locus', 'yellow', 150);
  expect(Number(await page.getByTestId('cut-nodes').textContent())).toBeGreaterThan(10);
  await expect(page.getByTestId('cut-cycle-rank')).toHaveText('0'); // Spot has genus 0
  expect((await canvasStats(page)).saturatedFraction, 'the colormap is dimmed').toBeLessThan(distance.saturatedFraction);

  // The target (purple) and the two descent paths (red, lime).
  await step('paths', 'Target & paths');
  await expect(page.getByTestId('target-vertex')).toHaveText(/^\d+$/);
  await expectLayerColor(page, 'target', 'purple', 150);
  await expectLayerColor(page, 'path-1', 'red', 100);
  await expectLayerColor(page, 'path-2', 'lime', 100);
  const dimmedCutLocus = (await colorCensus(page)).yellow;
  expect(dimmedCutLocus, 'the cut locus is dimmed, not bright yellow any more').toBeLessThan(100);
  await expect(layerBox(page, 'cut-locus')).toBeChecked(); // but still drawn and listed

  // The loop: the approximate loop (orange), the translucent constraint sphere with the region
  // inside it tinted on the surface, and the shortened loop (cyan, thick).
  await step('loop', 'Loop');
  await expectLayerColor(page, 'approx-loop', 'orange', 100);
  await expectLayerColor(page, 'loop', 'cyan', 400);
  const withSphere = await canvasStats(page);
  const blueWith = (await colorCensus(page, 0.3)).blue;
  await layerBox(page, 'sphere').uncheck();
  const noSphere = await canvasStats(page);
  const blueWithout = (await colorCensus(page, 0.3)).blue;
  await layerBox(page, 'sphere').check();
  expect(frameDifference(withSphere, noSphere), 'the sphere changes the picture').toBeGreaterThan(1);
  expect(blueWith, 'the sphere and the region inside it are blue').toBeGreaterThan(blueWithout + 300);
  await expect(page.getByTestId('sphere-radius')).toHaveText(/^\d/);
  await expect(page.getByTestId('loop-length')).toHaveText(/^\d/);
  await expect(page.getByTestId('areas')).toHaveText(/^\d\S* \/ \d/);
  await expect(page.getByTestId('score')).toHaveText(/^\d/);
  await expect(page.getByTestId('centroid-inside')).toHaveText(/^(yes|no)$/);
  const loopLength = Number(await page.getByTestId('loop-length').textContent());
  const approxLength = Number(await page.getByTestId('approx-length').textContent());
  expect(loopLength, 'shortening does not lengthen the loop').toBeLessThanOrEqual(approxLength * 1.0001);
  // The whole shape is not computed yet: its pills say so (entering one computes it).
  await expect(page.getByTestId('stage-separators')).toHaveAttribute('data-state', 'pending');

  // Keyboard and Previous go back; any computed stage can be entered directly.
  await page.keyboard.press('ArrowLeft');
  await expectStage(page, 'paths', 'Target & paths');
  await page.keyboard.press('ArrowRight');
  await expectStage(page, 'loop', 'Loop');
  await page.keyboard.press('4'); // digits enter stages by number
  await expectStage(page, 'paths', 'Target & paths');
  await page.getByTestId('stage-cut-locus').click();
  await expectStage(page, 'cut-locus', 'Cut locus');
  await page.getByTestId('stage-prev').click();
  await expectStage(page, 'geodesics', 'Geodesics');
  await waitForState(page, 'ready');
  expect(frameDifference(frames[0], await canvasStats(page)), 'back at Geodesics, the picture is the first one').toBeLessThan(1);
  // The Mesh stage: the plain surface again, the source kept.
  await page.getByTestId('stage-prev').click();
  await expectStage(page, 'mesh', 'Mesh');
  await waitForState(page, 'ready');
  expect((await canvasStats(page)).hueBins, 'no colormap on the plain mesh').toBeLessThanOrEqual(2);
});

test('changing an option re-runs stage 1 for the same source and keeps the stage', async ({ page }) => {
  await clickHorn(page);
  await page.getByTestId('stage-loop').click();
  await expectStage(page, 'loop', 'Loop');
  await waitForState(page, 'ready');
  const before = await canvasStats(page);
  await expect(layerBox(page, 'sphere')).toHaveCount(1);

  // Sphere constraint off: a new reply, no sphere layer, still at the loop, same source.
  await setCheck(page, 'sphere', false);
  await waitForRun(page, 2);
  await expectStage(page, 'loop', 'Loop');
  await expect(page.getByTestId('distance-source')).toHaveText(String(HORN));
  await expect(layerBox(page, 'sphere')).toHaveCount(0);
  await expect(page.getByTestId('sphere-radius')).toHaveText('off');
  await expect(page.getByTestId('stage-caption')).toContainText('switched off');
  const after = await canvasStats(page);
  expect(frameDifference(before, after), 'the sphere is gone from the picture').toBeGreaterThan(1);

  // And back on.
  await setCheck(page, 'sphere', true);
  await waitForRun(page, 3);
  await expect(layerBox(page, 'sphere')).toHaveCount(1);
  expect(frameDifference(before, await canvasStats(page)), 'the same picture as before').toBeLessThan(1);

  // Target mode: another re-run, stage kept.
  await page.getByTestId('opt-target').locator('select').selectOption('geodesic (surface)');
  await waitForRun(page, 4);
  await expectStage(page, 'loop', 'Loop');
  await expect(page.getByTestId('separator-status')).toHaveAttribute('data-status', /.+/);

  // A cut-locus threshold typed in: one more re-run of the same source.
  await page.getByTestId('stage-cut-locus').click();
  await page.getByTestId('opt-pruneDepth').locator('input').fill('8');
  await page.getByTestId('opt-pruneDepth').locator('input').press('Enter');
  await waitForRun(page, 5);
  await expectStage(page, 'cut-locus', 'Cut locus');
  await expect(page.getByTestId('distance-source')).toHaveText(String(HORN));
});

test('a source whose loop shrinks away shows its reason and the stages it got to', async ({ page }) => {
  // Low on Spot's front leg: every target's loop encloses nothing inside the sphere and shrinks away.
  await clickVertex(page, 1167);
  const outcome = page.getByTestId('separator-status');
  await expect(outcome).toHaveAttribute('data-status', 'degenerate-loop');
  await expect(outcome).toContainText('Stopped at Loop');
  await expect(outcome).toContainText('shrank');
  await expect(page.getByTestId('loop-length')).toHaveText('–');
  await expect(page.getByTestId('score')).toHaveText('–');
  expect(Number(await page.getByTestId('target-attempts').textContent())).toBeGreaterThan(1);

  for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowRight');
  await expectStage(page, 'loop', 'Loop');
  await expect(page.getByTestId('stage-caption')).toContainText('stopped here');
  await expect(page.getByTestId('stage-card')).toHaveClass(/failed/);
  await expect(layerBox(page, 'loop')).toHaveCount(0);
  await expect(layerBox(page, 'approx-loop')).toHaveCount(1); // the stages before it are there
  await expect(layerBox(page, 'cut-locus')).toHaveCount(1);
});
