#!/usr/bin/env node
// Entry point of the `cscd` command: builds the WASM core on first use, then runs the TypeScript CLI
// through tsx (no separate compile step for the CLI).
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
await import('./main.ts');
