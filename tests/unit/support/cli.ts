// The CLI run as users run it: a child process, with its exit status and both output streams.
import { spawnSync } from 'node:child_process';
import { repoRoot } from '../../paths.ts';

export function cscd(...args: string[]) {
  const { status, stdout, stderr } = run(args);
  return { status, stdout, stderr };
}

/** The same, killed after `ms` milliseconds: a hang fails the test instead of blocking it. */
export function cscdWithin(ms: number, ...args: string[]) {
  return run(args, ms);
}

function run(args: string[], timeout?: number) {
  const started = performance.now();
  const result = spawnSync(process.execPath, ['cli/cscd.mjs', ...args], { cwd: repoRoot, encoding: 'utf8', timeout });
  const timedOut = (result.error as NodeJS.ErrnoException | undefined)?.code === 'ETIMEDOUT';
  return { status: result.status, stdout: result.stdout, stderr: result.stderr, timedOut, ms: performance.now() - started };
}
