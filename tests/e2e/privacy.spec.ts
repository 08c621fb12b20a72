/**
 * No data leaves the machine: under the page's content security policy, opening a mesh
 * from disk and computing its skeleton and reconstruction requests nothing but the page's own assets,
 * and nothing the policy would block is attempted.
 */
import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { sharedMesh } from '../paths.ts';
import { setCheck, setNumber } from './studio.ts';

test('opening and skeletonising a mesh makes no request beyond the page itself', async ({ page, baseURL }) => {
  test.slow();
  const origin = new URL(baseURL!).origin;
  const requests: string[] = [];
  page.on('request', (request) => requests.push(request.url()));
  await page.addInitScript(() => {
    const seen: string[] = [];
    (window as unknown as { cspViolations: string[] }).cspViolations = seen;
    document.addEventListener('securitypolicyviolation', (e) => seen.push(`${e.violatedDirective} ${e.blockedURI}`));
  });

  await page.goto('/');
  await expect(page.locator('body')).toHaveAttribute('data-state', 'ready', { timeout: 60_000 });
  const policy = await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content');
  expect(policy).toContain("connect-src 'self'");
  const afterLoad = requests.length;

  // A mesh from disk, the whole pipeline and the reconstruction, all in the worker.
  await page.getByTestId('file-input').setInputFiles({
    name: 'hand.ply',
    mimeType: 'application/octet-stream',
    buffer: readFileSync(sharedMesh('hand.ply')),
  });
  await expect(page.getByTestId('facts-vertices')).toHaveText('10345', { timeout: 60_000 });
  await setCheck(page, 'n-auto', false);
  await setNumber(page, 'n', 8);
  // Entering the Reconstruction stage computes the skeleton, then its reconstruction.
  await page.getByTestId('stage-reconstruction').click();
  await expect(page.locator('body')).toHaveAttribute('data-sk-run', 'done', { timeout: 60_000 });
  await expect(page.locator('body')).toHaveAttribute('data-sk-recon', /\d/, { timeout: 60_000 });

  const foreign = requests.filter((url) => !url.startsWith(`${origin}/`) && !url.startsWith('blob:') && !url.startsWith('data:'));
  expect(foreign, 'requests to other origins').toEqual([]);
  expect(requests.slice(afterLoad), 'requests after the page loaded (the mesh must not be uploaded)').toEqual([]);
  expect(await page.evaluate(() => (window as unknown as { cspViolations: string[] }).cspViolations)).toEqual([]);
});
