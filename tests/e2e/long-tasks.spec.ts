/**
 * The page stays responsive while the worker computes: main-thread long tasks (PerformanceObserver
 * 'longtask', over 50 ms each) are recorded through a whole-shape run on the Hand sample and written
 * to .deps/bench/page-long-tasks.json.
 *
 * Wall time is not what the page's code costs here. Without a GPU (SwiftShader, as in CI) the
 * compositor reads every WebGL frame back on the main thread (a `Commit` with `ReadPixels`) and waits
 * for the software rasterizer, which shares the cores with the worker; and on a loaded machine the
 * main thread also waits for a core. A Chromium trace gives each task's main-thread CPU time, which
 * counts neither wait: the bound (200 ms, generous) is asserted on that. The file keeps all three.
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { expect, test } from '@playwright/test';
import { repoRoot } from '../paths.ts';
import { body, openPage, runWhole, waitForState } from './studio.ts';

const BOUND_MS = 200;

interface TraceEvent {
  name: string;
  ph: string;
  pid: number;
  tid: number;
  ts: number;
  dur?: number;
  /** Thread (CPU) time, µs. */
  tdur?: number;
  args?: { name?: string };
}

/** Long main-thread tasks of a trace: wall ms, the ms of frame read-backs inside them, and CPU ms. */
function splitTasks(events: TraceEvent[]): Array<{ ms: number; readbackMs: number; cpuMs: number }> {
  const names = new Map(events.filter((e) => e.name === 'thread_name').map((e) => [`${e.pid}:${e.tid}`, e.args?.name]));
  const main = events.filter((e) => e.ph === 'X' && names.get(`${e.pid}:${e.tid}`) === 'CrRendererMain');
  return main
    .filter((e) => e.name === 'RunTask' && e.dur! > 50_000)
    .map((task) => {
      const inside = (e: TraceEvent) => e.ts >= task.ts && e.ts + e.dur! <= task.ts + task.dur!;
      const readback = main.filter((e) => e.name === 'Commit' && inside(e)).reduce((sum, e) => sum + e.dur!, 0);
      return { ms: task.dur! / 1000, readbackMs: readback / 1000, cpuMs: (task.tdur ?? task.dur!) / 1000 };
    });
}

test('a whole-shape run keeps main-thread tasks short', async ({ page, browser }) => {
  test.slow();
  await page.addInitScript(() => {
    const tasks: number[] = [];
    (window as unknown as { longTasks: number[] }).longTasks = tasks;
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) tasks.push(entry.duration);
    }).observe({ type: 'longtask', buffered: true });
  });
  await openPage(page, '/#mesh=hand', '10345');
  // Only the run counts, not loading the page and the mesh.
  await page.evaluate(() => ((window as unknown as { longTasks: number[] }).longTasks.length = 0));
  const tracePath = path.join(tmpdir(), `cscd-long-tasks-${process.pid}.json`);
  await browser.startTracing(page, { path: tracePath, categories: ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'toplevel'] });
  await runWhole(page, 60, false);
  await expect(body(page)).toHaveAttribute('data-sk-run', 'done', { timeout: 120_000 });
  await waitForState(page, 'ready');
  await page.waitForTimeout(500); // the last frames
  await browser.stopTracing();
  const tasks = await page.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks);
  const split = splitTasks((JSON.parse(readFileSync(tracePath, 'utf8')) as { traceEvents: TraceEvent[] }).traceEvents);
  const renderer = await page.evaluate(() => {
    const gl = document.querySelector<HTMLCanvasElement>('[data-testid="viewport-canvas"]')!.getContext('webgl2')!;
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    return String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  });

  const round = (x: number) => Math.round(x);
  const record = {
    longestMs: round(Math.max(0, ...tasks)),
    count: tasks.length,
    longestWithoutReadbackMs: round(Math.max(0, ...split.map((t) => t.ms - t.readbackMs))),
    longestReadbackMs: round(Math.max(0, ...split.map((t) => t.readbackMs))),
    longestCpuMs: round(Math.max(0, ...split.map((t) => t.cpuMs))),
    mesh: 'hand.ply (10345 vertices, 20686 faces), n = 60',
    renderer,
    date: new Date().toISOString(),
  };
  const dir = path.join(repoRoot, '.deps', 'bench');
  mkdirSync(dir, { recursive: true });
  writeFileSync(path.join(dir, 'page-long-tasks.json'), `${JSON.stringify(record, null, 2)}\n`);
  const detail = split.map((t) => `${round(t.ms)} (${round(t.readbackMs)} read-back, ${round(t.cpuMs)} CPU)`).join(', ');
  expect(split.every((t) => t.cpuMs <= t.ms + 1), 'the trace has thread times').toBe(true);
  expect(record.longestCpuMs, `long tasks in ms: ${detail}`).toBeLessThan(BOUND_MS);
});
