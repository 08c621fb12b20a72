#!/usr/bin/env node
// Entry point of the `cscd` command: builds the WASM core on first use, then runs the TypeScript CLI
// (cli/main.ts `run`) through tsx (no separate compile step for the CLI) on the process's streams.
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const packageRoot = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const built = ['cscd.wasm', 'cscd.js'].every((file) => existsSync(path.join(packageRoot, 'build', 'wasm', file)));
if (!built) {
  // The build's own output goes to stderr so that stdout stays the command's JSON.
  const build = spawnSync('bash', ['scripts/build-wasm.sh'], { cwd: packageRoot, stdio: ['ignore', 2, 2] });
  if (build.status !== 0) {
    process.stderr.write('cscd: could not build the WASM core (bash scripts/build-wasm.sh failed)\n');
    process.exit(1);
  }
}

const { register } = await import('tsx/esm/api');
register();
const { run, reportError } = await import('./main.ts');

const io = { stdout: process.stdout, stderr: process.stderr };
// `cscd distance ... | head` closes stdout early, which is not an error worth a stack trace.
process.stdout.on('error', (error) => {
  if (error.code === 'EPIPE') process.exit(0);
  process.exitCode = reportError(error, io);
});

// exitCode rather than process.exit(): a large JSON on stdout must be flushed before Node exits. A
// failed write to stdout (above) may have set it already.
const code = await run(process.argv.slice(2), io);
process.exitCode ||= code;
