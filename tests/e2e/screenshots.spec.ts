/**
 * The documentation screenshots of the timeline's stages (docs/stage-*.png). Skipped unless
 * SCREENSHOTS=1:
 *   SCREENSHOTS=1 npx playwright test screenshots
 */
import path from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { repoRoot } from '../paths.ts';
import { body, enterStage, openPage, waitForState } from './studio.ts';

type View = { direction?: [number, number, number]; center?: [number, number, number]; radius?: number };

/** Spot's right horn: the source vertex and a close view from above and in front. */
const HORN = 1502;
const HORN_VIEW: View = { direction: [0.3, 1, -0.5], center: [0.17, 0.74, -0.28], radius: 0.3 };

const SOURCE_SHOTS: Array<{ file: string; stage: string; view: View }> = [
  // The whole cow from behind and above: the cut locus runs far from the source, down the back legs.
  { file: 'stage-cut-locus.png', stage: 'cut-locus', view: { direction: [1, 0.7, 0.5] } },
  { file: 'stage-paths.png', stage: 'paths', view: { direction: [0.3, 1, -0.5], center: [0.15, 0.72, -0.28], radius: 0.4 } },
  { file: 'stage-loop.png', stage: 'loop', view: { direction: [0.6, 1, -0.7], center: [0.12, 0.7, -0.3], radius: 0.42 } },
];

test.skip(!process.env.SCREENSHOTS, 'documentation screenshots: set SCREENSHOTS=1');
test.use({ viewport: { width: 1440, height: 900 } });

async function shoot(page: Page, view: View, file: string): Promise<void> {
  await page.evaluate((v) => window.cscd!.setView(v), view);
  await page.mouse.move(0, 0);
  await page.waitForTimeout(300);
  await page.screenshot({ path: path.join(repoRoot, 'docs', file) });
}

for (const shot of SOURCE_SHOTS) {
  test(`screenshot ${shot.file}`, async ({ page }) => {
    test.slow();
    await openPage(page);
    await page.evaluate((v) => window.cscd!.setView(v), HORN_VIEW);
    const at = await page.evaluate((v) => window.cscd!.projectVertex(v), HORN);
    await page.mouse.click(at!.x, at!.y);
    await expect(body(page)).toHaveAttribute('data-separator-runs', '1', { timeout: 30_000 });
    await enterStage(page, shot.stage);
    await waitForState(page, 'ready');
    await shoot(page, shot.view, shot.file);
  });
}

/** The whole-shape stages (N auto, seed 1), Spot from her right side; a linked view opens each. */
const WHOLE_SHOTS: Array<{ file: string; stage: string; view: View }> = [
  { file: 'stage-regions.png', stage: 'regions', view: { direction: [1, 0.35, -0.45], radius: 0.93 } },
  { file: 'stage-skeleton.png', stage: 'skeleton', view: { direction: [1, 0.35, -0.45], radius: 0.93 } },
];

for (const shot of WHOLE_SHOTS) {
  test(`screenshot ${shot.file}`, async ({ page }) => {
    test.slow();
    await openPage(page, `/#stage=${shot.stage}`);
    await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 120_000 });
    await waitForState(page, 'ready');
    await shoot(page, shot.view, shot.file);
  });
}
