/**
 * Open surfaces in the page (docs/separator.md "Separators that end on the boundary"): a
 * strip dropped on the page gets a separator that is an open path between two boundary points, shown
 * with the boundary extremities and its two ends, and a skeleton made of such paths.
 */
import { expect, test } from '@playwright/test';
import { offText, sheet } from '../unit/support/meshes.ts';
import { body, enterStage, layerBox, openPage, runWhole, waitForState } from './studio.ts';

/** A 4 x 1 strip in the xy plane (the one of tests/unit/boundary.test.ts). */
const STRIP = sheet([-2, 2], [-0.5, 0.5], 0.04, (x, y) => Math.abs(x) < 2 && Math.abs(y) < 0.5);

/** The strip's vertex nearest to (x, y). */
function vertexNear(x: number, y: number): number {
  const p = STRIP.positions;
  let best = 0;
  for (let v = 1; v < p.length / 3; v++)
    if (Math.hypot(p[3 * v] - x, p[3 * v + 1] - y) < Math.hypot(p[3 * best] - x, p[3 * best + 1] - y)) best = v;
  return best;
}

test('a strip gets open separators: ends on the boundary, a path along its middle', async ({ page }) => {
  test.slow();
  await openPage(page);
  await page.getByTestId('file-input').setInputFiles({ name: 'strip.off', mimeType: 'text/plain', buffer: Buffer.from(offText(STRIP)) });
  await expect(page.getByTestId('facts-vertices')).toHaveText(String(STRIP.positions.length / 3), { timeout: 30_000 });
  await expect(page.getByTestId('facts-boundary-loops')).toHaveText('1');
  await waitForState(page, 'ready');

  // From above, click the middle of the strip.
  await page.evaluate(() => window.cscd!.setView({ direction: [0, 0, 1] }));
  const source = vertexNear(0.3, 0);
  const at = await page.evaluate((v) => window.cscd!.projectVertex(v), source);
  expect(at).not.toBeNull();
  await page.mouse.click(at!.x, at!.y);
  await expect(body(page)).toHaveAttribute('data-separator-runs', '1', { timeout: 30_000 });
  await waitForState(page, 'ready');
  await expect(page.getByTestId('distance-source')).toHaveText(String(source));

  await enterStage(page, 'cut-locus');
  await expect(layerBox(page, 'boundary-extremities')).toBeChecked();
  await enterStage(page, 'paths');
  await expect(page.getByTestId('stage-caption')).toContainText('the separator is an open path');
  await enterStage(page, 'loop');
  await expect(page.getByTestId('separator-status')).toContainText('Path of length');
  await expect(page.getByTestId('separator-status')).toContainText('between two points of its boundary');

  await runWhole(page, 40);
  await expect(page.getByTestId('sk-status')).toContainText(/\d+ nodes/);
  await expect(layerBox(page, 'sk-packed')).toBeChecked();
});
