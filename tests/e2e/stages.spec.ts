/**
 * Stage 1 of CSCD-M shown step by step: a click on Spot's horn runs the separator; every stage's
 * layer must show up in its colour, and option changes must re-run it in place.
 */
import { expect, test, type Page } from '@playwright/test';
import { canvasStats, colorCensus, frameDifference, type LayerHue, type PixelStats } from './pixels.ts';

/** A vertex at the base of Spot's right horn: its separator is a loop around the horn. */
const HORN = 1502;
/** A close view of that horn from above and in front (camera direction, centre, radius of view). */
const HORN_VIEW = { direction: [0.3, 1, -0.5], center: [0.17, 0.74, -0.28], radius: 0.3 } as const;

async function waitForState(page: Page, state: string): Promise<void> {
  await expect(page.locator('body')).toHaveAttribute('data-state', state, { timeout: 60_000 });
}

async function waitForRun(page: Page, run: number): Promise<void> {
  await expect(page.locator('body')).toHaveAttribute('data-separator-runs', String(run), { timeout: 30_000 });
  await waitForState(page, 'ready');
}

/** Opens the sample, looks at the horn and clicks the horn vertex, as a user would. */
async function clickHorn(page: Page): Promise<void> {
  await page.goto('/');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-vertices')).toHaveText('2930');
  await page.evaluate((view) => window.cscd!.setView(view as never), HORN_VIEW);
  const at = await page.evaluate((v) => window.cscd!.projectVertex(v), HORN);
  expect(at).not.toBeNull();
  await page.mouse.click(at!.x, at!.y);
  await waitForRun(page, 1);
  await expect(page.getByTestId('distance-source')).toHaveText(String(HORN));
}

async function expectStage(page: Page, stage: number, title: string): Promise<void> {
  await expect(page.locator('body')).toHaveAttribute('data-stage', String(stage));
  await expect(page.getByTestId('stage-index')).toHaveText(String(stage));
  await expect(page.getByTestId('stage-title')).toHaveText(title);
  await expect(page.getByTestId('stage-caption')).not.toBeEmpty();
}

/** Opens the sample and clicks a vertex in the default view. */
async function clickVertex(page: Page, vertex: number): Promise<void> {
  await page.goto('/');
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-vertices')).toHaveText('2930');
  const at = await page.evaluate((v) => window.cscd!.projectVertex(v), vertex);
  expect(at).not.toBeNull();
  await page.mouse.click(at!.x, at!.y);
  await waitForRun(page, 1);
  await expect(page.getByTestId('distance-source')).toHaveText(String(vertex));
}

/** The layer's checkbox in the viewport's layer list. */
const layerBox = (page: Page, name: string) => page.locator(`#layers input[data-layer="${name}"]`);

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

  // 1: the distance colormap, no stage-1 layer yet.
  await expectStage(page, 1, 'Distance');
  await expect(page.getByTestId('stage-prev')).toBeDisabled();
  const distance = await canvasStats(page);
  expect(distance.hueBins, 'the colormap spans many hues').toBeGreaterThanOrEqual(5);
  expect(distance.saturatedFraction, 'most of the mesh is coloured').toBeGreaterThan(0.5);
  await expect(layerBox(page, 'cut-locus')).toHaveCount(0);
  await expect(page.getByTestId('timing-separator')).toHaveText(/\d+(\.\d)? (ms|s)/);
  await expect(page.getByTestId('timing-stage-distance')).toHaveText(/\d+(\.\d)? (ms|s)/);

  const next = page.getByTestId('stage-next');
  const frames: PixelStats[] = [distance];
  const step = async (stage: number, title: string) => {
    await next.click();
    await expectStage(page, stage, title);
    await waitForState(page, 'ready');
    const frame = await canvasStats(page);
    expect(frameDifference(frames[frames.length - 1], frame), `stage ${stage} changes the picture`).toBeGreaterThan(0.3);
    frames.push(frame);
  };

  // 2: the cut locus in yellow, over a dimmed colormap.
  await step(2, 'Cut locus');
  await expectLayerColor(page, 'cut-locus', 'yellow', 150);
  expect(Number(await page.getByTestId('cut-nodes').textContent())).toBeGreaterThan(10);
  await expect(page.getByTestId('cut-cycle-rank')).toHaveText('0'); // Spot has genus 0
  expect((await canvasStats(page)).saturatedFraction, 'the colormap is dimmed').toBeLessThan(distance.saturatedFraction);

  // 3: the target (purple) and the two descent paths (red, lime).
  await step(3, 'Target & paths');
  await expect(page.getByTestId('target-vertex')).toHaveText(/^\d+$/);
  await expectLayerColor(page, 'target', 'purple', 150);
  await expectLayerColor(page, 'path-1', 'red', 100);
  await expectLayerColor(page, 'path-2', 'lime', 100);
  const dimmedCutLocus = (await colorCensus(page)).yellow;
  expect(dimmedCutLocus, 'the cut locus is dimmed, not bright yellow any more').toBeLessThan(100);
  await expect(layerBox(page, 'cut-locus')).toBeChecked(); // but still drawn and listed

  // 4: the approximate loop (orange).
  await step(4, 'Approximate loop');
  await expectLayerColor(page, 'approx-loop', 'orange', 150);

  // 5: the constraint sphere: translucent, and the region inside it tinted on the surface.
  await step(5, 'Constraint sphere');
  const withSphere = await canvasStats(page);
  const blueWith = (await colorCensus(page, 0.3)).blue;
  await layerBox(page, 'sphere').uncheck();
  const noSphere = await canvasStats(page);
  const blueWithout = (await colorCensus(page, 0.3)).blue;
  await layerBox(page, 'sphere').check();
  expect(frameDifference(withSphere, noSphere), 'the sphere changes the picture').toBeGreaterThan(2);
  expect(blueWith, 'the sphere and the region inside it are blue').toBeGreaterThan(blueWithout + 500);
  await expect(page.getByTestId('sphere-radius')).toHaveText(/^\d/);

  // 6: the shortened loop (cyan, thick); the run's measures are in the panel.
  await step(6, 'Loop');
  await expectLayerColor(page, 'loop', 'cyan', 400);
  await expect(next).toBeDisabled();
  await expect(page.getByTestId('loop-length')).toHaveText(/^\d/);
  await expect(page.getByTestId('areas')).toHaveText(/^\d\S* \/ \d/);
  await expect(page.getByTestId('score')).toHaveText(/^\d/);
  await expect(page.getByTestId('centroid-inside')).toHaveText(/^(yes|no)$/);
  const loopLength = Number(await page.getByTestId('loop-length').textContent());
  const approxLength = Number(await page.getByTestId('approx-length').textContent());
  expect(loopLength, 'shortening does not lengthen the loop').toBeLessThanOrEqual(approxLength * 1.0001);

  // Keyboard and Previous go back; earlier layers stay listed.
  await page.keyboard.press('ArrowLeft');
  await expectStage(page, 5, 'Constraint sphere');
  await page.keyboard.press('ArrowRight');
  await expectStage(page, 6, 'Loop');
  for (let stage = 5; stage >= 1; stage--) await page.getByTestId('stage-prev').click();
  await expectStage(page, 1, 'Distance');
  await waitForState(page, 'ready');
  expect(frameDifference(frames[0], await canvasStats(page)), 'back at stage 1, the picture is the first one').toBeLessThan(1);
});

test('changing an option re-runs stage 1 for the same source and keeps the stage', async ({ page }) => {
  await clickHorn(page);
  for (let stage = 2; stage <= 5; stage++) await page.getByTestId('stage-next').click();
  await expectStage(page, 5, 'Constraint sphere');
  await waitForState(page, 'ready');
  const before = await canvasStats(page);
  await expect(layerBox(page, 'sphere')).toHaveCount(1);

  // Sphere constraint off: a new reply, no sphere layer, still at stage 5, same source.
  await page.getByTestId('opt-sphere').uncheck();
  await waitForRun(page, 2);
  await expectStage(page, 5, 'Constraint sphere');
  await expect(page.getByTestId('distance-source')).toHaveText(String(HORN));
  await expect(layerBox(page, 'sphere')).toHaveCount(0);
  await expect(page.getByTestId('sphere-radius')).toHaveText('off');
  await expect(page.getByTestId('stage-caption')).toContainText('switched off');
  const after = await canvasStats(page);
  expect(frameDifference(before, after), 'the sphere is gone from the picture').toBeGreaterThan(2);

  // And back on.
  await page.getByTestId('opt-sphere').check();
  await waitForRun(page, 3);
  await expect(layerBox(page, 'sphere')).toHaveCount(1);
  expect(frameDifference(before, await canvasStats(page)), 'the same picture as before').toBeLessThan(1);

  // Target mode: another re-run, stage kept.
  await page.getByTestId('opt-target').selectOption('geodesic');
  await waitForRun(page, 4);
  await expectStage(page, 5, 'Constraint sphere');
  await page.getByTestId('stage-next').click();
  await expectStage(page, 6, 'Loop');
  await expect(page.getByTestId('separator-status')).toHaveAttribute('data-status', /.+/);
});

test('a source whose loop shrinks away shows its reason and the stages it got to', async ({ page }) => {
  // Low on Spot's front leg: every target's loop encloses nothing inside the sphere and shrinks away.
  await clickVertex(page, 1167);
  const outcome = page.getByTestId('separator-status');
  await expect(outcome).toHaveAttribute('data-status', 'degenerate-loop');
  await expect(outcome).toContainText('Stopped at stage 6');
  await expect(outcome).toContainText('shrank');
  await expect(page.getByTestId('loop-length')).toHaveText('–');
  await expect(page.getByTestId('score')).toHaveText('–');
  expect(Number(await page.getByTestId('target-attempts').textContent())).toBeGreaterThan(1);

  for (let stage = 2; stage <= 6; stage++) await page.keyboard.press('ArrowRight');
  await expectStage(page, 6, 'Loop');
  await expect(page.getByTestId('stage-next')).toBeDisabled();
  await expect(page.getByTestId('stage-caption')).toContainText('stopped here');
  await expect(page.getByTestId('stage-card')).toHaveClass(/failed/);
  await expect(layerBox(page, 'loop')).toHaveCount(0);
  await expect(layerBox(page, 'approx-loop')).toHaveCount(1); // the stages before it are there
  await expect(layerBox(page, 'cut-locus')).toHaveCount(1);
});
