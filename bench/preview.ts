// The production build (dist/) in a browser, for the page's benchmarks and probes: `vite preview` and
// Debian's Chromium with a software renderer (--disable-gpu, as the e2e tests run it).
import { spawn } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium, type Browser } from '@playwright/test';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

/** Serves dist/ on `port` and opens Chromium; gives both to `use`, then closes them whatever happens. */
export async function withPreview<T>(port: number, use: (browser: Browser, url: string) => Promise<T>): Promise<T> {
  const server = spawn('npx', ['vite', 'preview', '--port', String(port), '--strictPort'], { cwd: repoRoot, stdio: 'ignore', detached: true });
  const url = `http://localhost:${port}/`;
  const browser = await chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
  try {
    for (let k = 0; k < 60 && !(await fetch(url).then((r) => r.ok, () => false)); k++) await new Promise((r) => setTimeout(r, 500));
    return await use(browser, url);
  } finally {
    await browser.close();
    try {
      process.kill(-server.pid!);
    } catch {
      // already gone
    }
  }
}
