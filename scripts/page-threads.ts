// Where the CPU goes while the page runs stage 1 (docs/parallel.md, "The status line"): opens the
// production build in Debian's Chromium (as bench/page.ts does), loads a shared mesh, starts the
// whole-shape run and samples every Chromium thread's CPU time (/proc/<pid>/task/*/stat, in ticks of
// 10 ms) each `--every` ms until the run is done: per interval the geometry and separator workers one by
// one, the renderer's and the GPU process's threads by name. With --trace it also records a Chrome trace
// and prints the page's frames per second (BeginMainFrame), which every change to the page costs.
//
//   npx vite build && node --import tsx scripts/page-threads.ts [--workers 2] [--every 1000] [--trace] [--port 4190] [mesh]
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { withPreview } from '../bench/preview.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: {
    workers: { type: 'string', default: '2' },
    every: { type: 'string', default: '1000' },
    trace: { type: 'boolean', default: false },
    port: { type: 'string', default: '4190' },
  },
});
const mesh = positionals[0] ?? 'horse';
const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const file = path.join(repoRoot, '..', 'shared', 'data', 'meshes', `${mesh}.ply`);
const traceFile = '/tmp/page-threads-trace.json';

/** CPU ticks so far of every thread of every Chromium process, keyed by process type/pid/thread name/tid. */
function sample(): Map<string, number> {
  const ticks = new Map<string, number>();
  for (const pid of readdirSync('/proc').filter((p) => /^\d+$/.test(p))) {
    try {
      const cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
      if (!cmd.includes('chromium')) continue;
      const type = /--type=([a-z-]+)/.exec(cmd)?.[1] ?? 'browser';
      for (const tid of readdirSync(`/proc/${pid}/task`)) {
        const stat = readFileSync(`/proc/${pid}/task/${tid}/stat`, 'utf8');
        const name = readFileSync(`/proc/${pid}/task/${tid}/comm`, 'utf8').trim();
        const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
        ticks.set(`${type}/${pid}/${name}/${tid}`, Number(fields[11]) + Number(fields[12])); // utime + stime
      }
    } catch {
      // the process or thread ended meanwhile
    }
  }
  return ticks;
}

/** A thread's row: each worker by its id (they are the workers of the run), the others by process and name. */
const group = (key: string) => {
  const [type, , name, tid] = key.split('/');
  return name === 'DedicatedWorker' ? `worker ${tid}` : `${type === 'gpu-process' ? 'gpu' : type}:${name}`;
};

await withPreview(Number(values.port), async (browser, url) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  await page.goto(`${url}#workers=${values.workers}`);
  await page.locator('body[data-state="ready"]').waitFor({ timeout: 120_000 });
  await page.getByTestId('file-input').setInputFiles(file);
  await page.waitForFunction(() => document.body.dataset.state === 'ready' && document.querySelector('[data-testid="file-name"]')?.textContent !== '', null, { timeout: 300_000 });
  if (values.trace) await browser.startTracing(page, { path: traceFile, categories: ['devtools.timeline', 'cc', 'viz'] });
  const t0 = Date.now();
  let before = sample();
  const rows: string[] = [];
  const timer = setInterval(() => {
    const now = sample();
    const used = new Map<string, number>();
    for (const [key, ticks] of now) {
      const d = ticks - (before.get(key) ?? 0);
      if (d > 0) used.set(group(key), (used.get(group(key)) ?? 0) + d);
    }
    before = now;
    rows.push(`${((Date.now() - t0) / 1000).toFixed(1)} s: ${[...used].sort().map(([g, d]) => `${g} ${d}`).join(', ')}`);
  }, Number(values.every));
  await page.getByTestId('stage-separators').click();
  await page.locator('body[data-sk-run="done"]').waitFor({ timeout: 600_000 });
  clearInterval(timer);
  if (values.trace) await browser.stopTracing();
  const run = await page.evaluate(() => window.cscd!.skeletonRun());
  console.log(`${mesh}: stage 1 ${Math.round(run?.stage1Ms ?? NaN)} ms on ${run?.workers} worker(s), the run ${Date.now() - t0} ms; CPU ticks (10 ms) per interval:`);
  console.log(rows.join('\n'));
  if (values.trace) {
    const trace = JSON.parse(readFileSync(traceFile, 'utf8')) as { traceEvents: { name: string; ts: number }[] };
    const frames = trace.traceEvents.filter((e) => e.name === 'ProxyMain::BeginMainFrame').map((e) => e.ts);
    const start = Math.min(...frames);
    const perSecond = new Map<number, number>();
    for (const ts of frames) perSecond.set(Math.floor((ts - start) / 1e6), (perSecond.get(Math.floor((ts - start) / 1e6)) ?? 0) + 1);
    console.log(`frames per second from the first: ${[...perSecond.values()].join(' ')}`);
  }
});
