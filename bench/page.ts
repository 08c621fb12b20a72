// The page against Node (issue: all cores, "the page as fast as Node"): CSCD's skeleton of each mesh
// with the default options (auto N, seed 1), in the production build of the page in Debian's Chromium
// (driven by Playwright, the file dropped on the page's file input, the whole-shape run started by
// entering *All separators*) and in Node (bench/runners/cscd.ts, a process of its own), alternating
// page and Node `--repeats` times per mesh so that drift of the machine affects both alike. Reports
// stage 1 as each measures it (the page: the sum of the worker's `pipeline.step` calls, without
// messages or drawing; Node: from the first step to the last), the ratio of their medians and whether
// both drew the same number of sources, as a table in bench/results/<date>-page.md. With --workers K
// (and --draw-ahead R, the default by default: at 1 there is nothing to share) both run stage 1 on K threads:
// the page's workers setting, in its address, and the Node runner's pool.
//
//   node --import tsx bench/page.ts [--repeats 3] [--port 4180] [--no-build] [--workers K] [--draw-ahead R] [meshes...]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync, existsSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { defaultOptions, OPTIONS, optionProblem, parseSettingText, WORKERS } from '../lib/core/options.ts';
import { parseMesh } from '../lib/io/index.ts';
import { median } from './metrics.ts';
import { withPreview } from './preview.ts';
import { claimResultName } from './result-name.ts';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: {
    repeats: { type: 'string', default: '3' },
    port: { type: 'string', default: '4180' },
    'no-build': { type: 'boolean', default: false },
    workers: { type: 'string', default: '1' },
    'draw-ahead': { type: 'string', default: String(defaultOptions.drawAhead) },
  },
});
const repeats = Number(values.repeats), port = Number(values.port);
const workers = parseSettingText(WORKERS, values.workers);
const drawAhead = Number(values['draw-ahead']);
if (typeof workers !== 'number' || optionProblem(OPTIONS.find((o) => o.key === 'drawAhead')!, drawAhead)) throw new Error('--workers and --draw-ahead take whole numbers from 1 to 256');
/** The run's settings in the page's address (web/src/ui/url-state.ts). */
const pageHash = `#workers=${workers}&drawAhead=${drawAhead}`;
const DEFAULT_MESHES = ['bob', 'fertility_9k', 'hand', 'armadillo', 'horse'];
const folders = ['meshes', 'synthetic'].map((f) => path.resolve(repoRoot, '..', 'shared', 'data', f));
const all = folders.flatMap((d) => readdirSync(d).filter((f) => f.endsWith('.ply')).map((f) => path.join(d, f)));
const names = positionals.length ? positionals : DEFAULT_MESHES;
const files = names.map((name) => {
  const file = all.find((f) => path.basename(f, '.ply') === name);
  if (!file) throw new Error(`no shared mesh '${name}'`);
  return file;
});
const tmp = mkdtempSync(path.join(os.tmpdir(), 'cscd-page-'));
const loadBefore = os.loadavg();

function node(file: string): { stage1Ms: number; sources: number } {
  const out = path.join(tmp, `${path.basename(file)}.json`);
  const args = ['--workers', String(workers), '--draw-ahead', String(drawAhead)];
  const result = spawnSync(process.execPath, ['--import', 'tsx', 'bench/runners/cscd.ts', file, out, ...args], { cwd: repoRoot, encoding: 'utf8' });
  if (result.status !== 0) throw new Error(`${path.basename(file)} in Node: ${result.stderr.trim().split('\n').pop()}`);
  const { stage1Seconds } = JSON.parse(result.stdout.trim().split('\n').pop()!) as { stage1Seconds: number };
  return { stage1Ms: 1000 * stage1Seconds, sources: (JSON.parse(readFileSync(out, 'utf8')) as { stats: { n: number } }).stats.n };
}

if (!values['no-build']) {
  const build = spawnSync('npx', ['vite', 'build'], { cwd: repoRoot, stdio: ['ignore', 'ignore', 'inherit'] });
  if (build.status !== 0) throw new Error('vite build failed');
}
if (!existsSync(path.join(repoRoot, 'dist', 'index.html'))) throw new Error('no production build in dist/ (run without --no-build)');
type Row = { mesh: string; page: number[]; node: number[]; pageSources: number; nodeSources: number };
const rows: Row[] = [];
await withPreview(port, async (browser, url) => {
  for (const file of files) {
    const vertices = parseMesh(readFileSync(file), file).positions.length / 3;
    const row: Row = { mesh: path.basename(file, '.ply'), page: [], node: [], pageSources: 0, nodeSources: 0 };
    for (let r = 0; r < repeats; r++) {
      const first = r % 2 === 0 ? 'page' : 'node';
      for (const where of first === 'page' ? ['page', 'node'] : ['node', 'page']) {
        if (where === 'node') {
          const { stage1Ms, sources } = node(file);
          row.node.push(stage1Ms);
          row.nodeSources = sources;
          continue;
        }
        // A fresh page each time, as a person opening the site: its worker loads and compiles the core.
        const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
        await page.goto(`${url}${pageHash}`);
        await page.locator('body[data-state="ready"]').waitFor({ timeout: 120_000 });
        await page.getByTestId('file-input').setInputFiles(file);
        await page.waitForFunction((v) => document.querySelector('[data-testid="facts-vertices"]')?.textContent === String(v)
          && document.body.dataset.state === 'ready', vertices, { timeout: 300_000 });
        await page.getByTestId('stage-separators').click();
        await page.locator('body[data-sk-run="done"]').waitFor({ timeout: 600_000 });
        const run = await page.evaluate(() => window.cscd!.skeletonRun());
        if (!run) throw new Error(`${row.mesh}: the page shows no skeleton`);
        if (run.workers !== Math.min(workers, drawAhead)) throw new Error(`${row.mesh}: the page ran stage 1 on ${run.workers} workers, not ${workers}`);
        row.page.push(run.stage1Ms);
        row.pageSources = run.sources;
        await page.close();
      }
      process.stdout.write(`${row.mesh}: page ${Math.round(row.page.at(-1)!)} ms, node ${Math.round(row.node.at(-1)!)} ms\n`);
    }
    rows.push(row);
  }
});

const ms = (x: number) => String(Math.round(x));
const ratios = rows.map((r) => median(r.page)! / median(r.node)!);
const chromiumVersion = spawnSync(process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', ['--version'], { encoding: 'utf8' }).stdout.trim();
const lines = [
  `# The page against Node: stage 1`,
  '',
  `Run on ${new Date().toISOString().replace(/\.\d+Z$/, 'Z')}, commit ${spawnSync('git', ['rev-parse', '--short', 'HEAD'], { cwd: repoRoot, encoding: 'utf8' }).stdout.trim()}. `
    + `Machine: ${os.cpus().length} cores (${os.cpus()[0]?.model.trim()}), Node ${process.version}, ${chromiumVersion} (headless, --disable-gpu); `
    + `load average ${loadBefore.map((x) => x.toFixed(2)).join(' ')} at the start.`,
  '',
  `\`node --import tsx bench/page.ts${process.argv.slice(2).length ? ` ${process.argv.slice(2).join(' ')}` : ''}\`: default options (auto N, seed 1) but drawAhead ${drawAhead}, stage 1 on ${workers} thread${workers === 1 ? '' : 's'}, `
    + `${repeats} runs each, page and Node alternating; the page a fresh tab each run (its worker loads and compiles the core), Node a fresh process. `
    + `Stage 1: the page's worker sums its \`pipeline.step\` calls (no messages, no drawing), or on a pool times \`runStage1\` as Node's runner does.`,
  '',
  '| mesh | sources (page / Node) | page stage 1, ms (runs) | Node stage 1, ms (runs) | page / Node (medians) |',
  '| --- | ---: | ---: | ---: | ---: |',
  ...rows.map((r, i) => `| ${r.mesh} | ${r.pageSources} / ${r.nodeSources} | ${r.page.map(ms).join(', ')} | ${r.node.map(ms).join(', ')} | ${ratios[i].toFixed(2)} |`),
  '',
  `Median of the ratios: ${median(ratios)!.toFixed(2)}.`,
  '',
];
const date = new Date().toISOString().slice(0, 10);
const resultsDir = path.join(repoRoot, 'bench', 'results');
const out = path.join(resultsDir, `${claimResultName(resultsDir, `${date}-page${workers > 1 ? `-k${workers}` : ''}`, ['md'])}.md`);
writeFileSync(out, lines.join('\n'));
process.stdout.write(`${lines.join('\n')}\nwrote ${path.relative(repoRoot, out)}\n`);
