/**
 * Coarse meshes (lib/mesh/refine.ts, docs/refine.md): the worker refines a mesh of a few hundred faces
 * when it opens it, the page shows the refined mesh with a note beside the file's facts, the skeleton has cycles = genus and
 * its JSON is the CLI's, number for number (vertexToNode over the file's vertices); a restarted worker
 * refines the file again the same way.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { expect, test } from '@playwright/test';
import type { Refinement } from '../../lib/core/types.ts';
import type { SkeletonJson } from '../../lib/io/skeleton.ts';
import { decimate } from '../../lib/mesh/decimate.ts';
import { offText, readMesh } from '../unit/support/meshes.ts';
import { sharedMesh } from '../paths.ts';
import { comparable, downloadSkeletonJson, enterStage, openPage, runWhole, waitForState } from './studio.ts';

let folder: string;
let file: string;
let vertices: number;

test.beforeAll(() => {
  folder = mkdtempSync(path.join(tmpdir(), 'cscd-refine-'));
  file = path.join(folder, 'fertility-200.off');
  // Genus 4 in 200 faces: no cycle survives without refinement.
  const mesh = decimate(readMesh(sharedMesh('fertility_9k.ply')), 200);
  vertices = mesh.positions.length / 3;
  writeFileSync(file, offText(mesh));
});

test.afterAll(() => rmSync(folder, { recursive: true, force: true }));

const cli = (...args: string[]) => execFileSync(process.execPath, ['cli/cscd.mjs', ...args], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] });

test('a coarse mesh is refined to compute on, shown refined, and gets the CLI skeleton with cycles = genus', async ({ page }) => {
  test.slow();
  const { refined } = JSON.parse(cli('info', file)) as { refined: Refinement };
  expect(refined.fromFaces).toBe(200);

  await openPage(page);
  await page.getByTestId('file-input').setInputFiles(file);
  // The facts are the file's; the view and the computations have the refined mesh.
  await expect(page.getByTestId('facts-faces')).toHaveText('200');
  await expect(page.getByTestId('facts-genus')).toHaveText('4');
  await expect(page.getByTestId('warnings')).toContainText(`Refined for computation: 200 → ${refined.toFaces.toLocaleString('en-US')} faces, the same surface`);

  await runWhole(page, 40);
  await expect(page.getByTestId('sk-cycles')).toHaveText('4');
  await enterStage(page, 'skeleton');
  const browser = await downloadSkeletonJson(page);
  expect(browser.vertexToNode).toHaveLength(vertices);
  expect(browser.stats.refined).toEqual(refined);
  const node = JSON.parse(cli('skeleton', file, '--n', '40')) as SkeletonJson;
  expect(comparable(browser)).toEqual(comparable(node));

  // A new worker opens the file again and refines it the same way.
  await page.evaluate(() => window.cscd!.simulateCrash('abort'));
  await waitForState(page, 'error');
  await runWhole(page, 40);
  await expect(page.getByTestId('sk-cycles')).toHaveText('4');
  await enterStage(page, 'skeleton');
  expect(comparable(await downloadSkeletonJson(page))).toEqual(comparable(node));
});
