/** Helpers shared by the end-to-end tests: page state, stages of the timeline, parameters, layers. */
import { readFileSync } from 'node:fs';
import { expect, type Locator, type Page } from '@playwright/test';
import type { SkeletonJson } from '../../lib/io/skeleton.ts';

export const body = (page: Page): Locator => page.locator('body');

export async function waitForState(page: Page, state: 'loading' | 'ready' | 'computing' | 'error'): Promise<void> {
  await expect(body(page)).toHaveAttribute('data-state', state, { timeout: 60_000 });
}

/** Opens the page (optionally with a linked view in the hash) and waits for Spot, or `vertices`, to be open. */
export async function openPage(page: Page, url = '/', vertices = '2930'): Promise<void> {
  await page.goto(url);
  await waitForState(page, 'ready');
  await expect(page.getByTestId('facts-vertices')).toHaveText(vertices);
}

/** Clicks a stage's pill in the timeline. */
export async function enterStage(page: Page, key: string): Promise<void> {
  await page.getByTestId(`stage-${key}`).click();
  await expect(body(page)).toHaveAttribute('data-stage', key);
}

export async function expectStage(page: Page, key: string, title: string): Promise<void> {
  await expect(body(page)).toHaveAttribute('data-stage', key);
  await expect(page.getByTestId('stage-title')).toHaveText(title);
  await expect(page.getByTestId('stage-caption')).not.toBeEmpty();
  await expect(page.getByTestId(`stage-${key}`)).toHaveClass(/current/);
}

/** Types a number into a parameter of the panel and confirms it (as Enter does). */
export async function setNumber(page: Page, option: string, value: number): Promise<void> {
  const input = page.getByTestId(`opt-${option}`).locator('input');
  await input.fill(String(value));
  await input.press('Enter');
}

export async function setCheck(page: Page, option: string, on: boolean): Promise<void> {
  await page.getByTestId(`opt-${option}`).locator('input').setChecked(on);
}

/** The layer's checkbox in the viewport's layer list. */
export const layerBox = (page: Page, name: string): Locator => page.locator(`#layers input[data-layer="${name}"]`);

/** Sets N (not auto) and enters All separators, which starts the whole-shape run; waits for its end when asked. */
export async function runWhole(page: Page, n: number, wait = true): Promise<void> {
  await setCheck(page, 'n-auto', false);
  await setNumber(page, 'n', n);
  await enterStage(page, 'separators');
  if (wait) {
    await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 90_000 });
    await waitForState(page, 'ready');
  }
}

/** A number at the start of an element's text. */
export const figure = async (page: Page, id: string): Promise<number> =>
  Number((await page.getByTestId(id).textContent())?.match(/^\d+/)?.[0] ?? NaN);

/** The skeleton JSON the page saves (*Save* → JSON), read back. */
export async function downloadSkeletonJson(page: Page): Promise<SkeletonJson> {
  const [file] = await Promise.all([page.waitForEvent('download'), page.getByTestId('dl-skeleton-json').click()]);
  return JSON.parse(readFileSync(await file.path(), 'utf8')) as SkeletonJson;
}

/** Everything of a skeleton JSON but the run's wall-clock times and the file name it was given. */
export const comparable = ({ mesh: _mesh, stats: { timings: _timings, ...stats }, ...rest }: SkeletonJson) => ({ ...rest, stats });
