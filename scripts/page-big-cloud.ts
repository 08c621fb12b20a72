// A big point cloud in the page (docs/limits.md, "Point clouds"): opens the production build in Debian's
// Chromium (bench/preview.ts), drops a binary PLY of `--points` random points on a torus
// and times it until drawn and ready; then frames per second while orbiting with the mouse (the
// controls' moving view) and while the view turns without them (every drawn point in each frame), on the
// sample mesh first for comparison. Chromium runs with --disable-gpu: a software renderer, whose draw
// budget (SOFTWARE_DRAWN_POINTS, web/src/viewer/viewer.ts) is what it measures.
//
//   npx vite build && node --import tsx scripts/page-big-cloud.ts [--points 1000000] [--port 4191]
import { writeFileSync } from 'node:fs';
import { parseArgs } from 'node:util';
import type { Page } from '@playwright/test';
import { withPreview } from '../bench/preview.ts';
import { cloudPly, torusPoints } from '../tests/unit/support/clouds.ts';

const { values } = parseArgs({ options: { points: { type: 'string', default: '1000000' }, port: { type: 'string', default: '4191' } } });
const n = Number(values.points);
const { positions } = torusPoints(n, 10, 3, 1);
const file = `/tmp/page-big-cloud-${n}.ply`;
writeFileSync(file, cloudPly(Array.from({ length: n }, (_, i) => Array.from(positions.subarray(3 * i, 3 * i + 3))), null, 'binary_little_endian', 'float'));

/** Frames per second over five seconds; strings, as the page's content security policy allows no eval of functions built here. */
const COUNT_FRAMES = `new Promise((resolve) => {
  let frames = 0;
  const t0 = performance.now();
  const tick = () => { frames++; if (performance.now() - t0 < 5000) requestAnimationFrame(tick); else resolve(frames / ((performance.now() - t0) / 1000)); };
  requestAnimationFrame(tick);
})`;
const TURN_VIEW = `new Promise((resolve) => {
  let frames = 0;
  const t0 = performance.now();
  const tick = () => {
    frames++;
    window.cscd.setView({ direction: [Math.sin(frames / 20), 0.3, Math.cos(frames / 20)] });
    if (performance.now() - t0 < 5000) requestAnimationFrame(tick); else resolve(frames / ((performance.now() - t0) / 1000));
  };
  requestAnimationFrame(tick);
})`;

/** Frames per second while the mouse orbits the view (a drag of 100 moves 40 ms apart). */
async function orbiting(page: Page): Promise<number> {
  const box = (await page.getByTestId('viewport-canvas').boundingBox())!;
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  const frames = page.evaluate(COUNT_FRAMES) as Promise<number>;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let i = 0; i < 100; i++) {
    await page.mouse.move(x + 200 * Math.sin(i / 10), y + 50 * Math.cos(i / 10));
    await page.waitForTimeout(40);
  }
  await page.mouse.up();
  return frames;
}

const turning = (page: Page) => page.evaluate(TURN_VIEW) as Promise<number>;

await withPreview(Number(values.port), async (browser, url) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  await page.goto(url);
  await page.locator('body[data-state="ready"]').waitFor({ timeout: 120_000 });
  console.log(`sample mesh: ${(await orbiting(page)).toFixed(1)} frames/s orbiting, ${(await turning(page)).toFixed(1)} turning`);

  const t0 = Date.now();
  await page.getByTestId('file-input').setInputFiles(file);
  await page.getByTestId('facts-vertices').filter({ hasText: 'points' }).waitFor({ timeout: 300_000 });
  await page.locator('body[data-state="ready"]').waitFor({ timeout: 300_000 });
  const seconds = (Date.now() - t0) / 1000;
  const points = (await page.evaluate('window.cscd.cloudPoints()')) as { drawn: number; computedOn: number };
  console.log(`${n} points: drawn and ready ${seconds.toFixed(1)} s after the drop; ${points.drawn} drawn, ${points.computedOn} computed on`);
  console.log(`the cloud: ${(await orbiting(page)).toFixed(1)} frames/s orbiting, ${(await turning(page)).toFixed(1)} turning`);
});
