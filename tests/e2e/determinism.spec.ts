/**
 * Determinism across platforms: the skeleton the page computes in its worker is the one the
 * CLI computes in Node for the same mesh, options and seed, number for number.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { expect, test } from '@playwright/test';
import type { SkeletonJson } from '../../lib/io/skeleton.ts';
import { comparable, downloadSkeletonJson, enterStage, openPage, runWhole, setNumber } from './studio.ts';

test('the page and the CLI give the same skeleton for the same mesh, options and seed', async ({ page }) => {
  test.slow();
  await openPage(page);
  await setNumber(page, 'seed', 5);
  await runWhole(page, 16);
  await enterStage(page, 'skeleton');
  const browser = await downloadSkeletonJson(page);
  expect(browser.options).toMatchObject({ n: 16, seed: 5 });

  const dir = mkdtempSync(path.join(tmpdir(), 'cscd-determinism-'));
  try {
    const out = path.join(dir, 'spot.json');
    execFileSync(process.execPath, ['cli/cscd.mjs', 'skeleton', 'public/samples/spot.ply', '--n', '16', '--seed', '5', '--out', out]);
    const node = JSON.parse(readFileSync(out, 'utf8')) as SkeletonJson;
    expect(comparable(browser)).toEqual(comparable(node));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('above stage1Vertices the page computes stage 1 on the CLI’s simplified copy, on two workers, and gives its skeleton', async ({ page }) => {
  test.slow();
  await openPage(page, '/#stage1Vertices=1500&workers=2');
  await setNumber(page, 'seed', 5);
  await runWhole(page, 16);
  await expect(page.getByTestId('sk-status')).toContainText(/Stage 1 ran on a copy simplified to \d+ vertices/);
  await expect(page.getByTestId('sk-status')).toContainText('Stage 1 on 2 workers.');
  await enterStage(page, 'skeleton');
  const browser = await downloadSkeletonJson(page);
  expect(browser.options).toMatchObject({ n: 16, seed: 5, stage1Vertices: 1500 });
  expect(browser.stats.simplified).toMatchObject({ fromVertices: 2930 });
  expect(browser.vertexToNode).toHaveLength(2930);

  const dir = mkdtempSync(path.join(tmpdir(), 'cscd-determinism-'));
  try {
    const out = path.join(dir, 'spot.json');
    execFileSync(process.execPath, ['cli/cscd.mjs', 'skeleton', 'public/samples/spot.ply', '--n', '16', '--seed', '5', '--stage1-vertices', '1500', '--out', out]);
    const node = JSON.parse(readFileSync(out, 'utf8')) as SkeletonJson;
    expect(comparable(browser)).toEqual(comparable(node));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
