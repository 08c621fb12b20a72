/**
 * The bad-input corpus through the page, for a representative subset (every file goes through the CLI
 * in tests/unit/bad-input.test.ts): a refused file shows its message in the error box, a repaired one
 * lists "Repaired: ..." beside the warnings, neither hangs, and a good mesh opens afterwards.
 */
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { parseMesh } from '../../lib/io/index.ts';
import { fixture, sharedMesh } from '../paths.ts';

const expected = JSON.parse(readFileSync(fixture('bad', 'expected.json'), 'utf8')) as Record<string, { outcome: string; match: string }>;
const SUBSET = [
  'truncated_binary.ply',
  'huge_header_claim.ply',
  'binary_garbage.obj',
  'nan_coordinate.obj',
  'collinear.obj',
  'bow_tie.obj',
  'fin_edge.obj',
  'inside_out.obj',
  'point_cloud.ply',
];
/** What a refused or repaired file may take to show its outcome: a bound, not a wait. */
const BOUND_MS = 20_000;
const GOOD = 'two_torus.ply';

async function open(page: Page, name: string, buffer: Buffer): Promise<void> {
  await page.getByTestId('file-input').setInputFiles({ name, mimeType: 'application/octet-stream', buffer });
}

test.beforeEach(async ({ page }) => {
  await page.goto('/');
  await expect(page.locator('body')).toHaveAttribute('data-state', 'ready', { timeout: 60_000 });
});

for (const file of SUBSET) {
  const { outcome, match } = expected[file];
  test(`${file}: ${outcome} (${match}), then a good mesh opens`, async ({ page }) => {
    await open(page, file, readFileSync(path.join(fixture('bad'), file)));
    if (outcome === 'error') {
      await expect(page.getByTestId('error')).toBeVisible({ timeout: BOUND_MS });
      await expect(page.getByTestId('error')).toContainText(match);
    } else {
      await expect(page.getByTestId('warnings')).toContainText(`Repaired: ${match}`, { timeout: BOUND_MS });
      await expect(page.getByTestId('error')).toBeHidden();
    }

    const good = readFileSync(sharedMesh(GOOD));
    await open(page, GOOD, good);
    await expect(page.getByTestId('facts-vertices')).toHaveText(String(parseMesh(good, GOOD).positions.length / 3), { timeout: BOUND_MS });
    await expect(page.getByTestId('error')).toBeHidden();
    await expect(page.getByTestId('warnings')).not.toContainText('Repaired:');
  });
}
