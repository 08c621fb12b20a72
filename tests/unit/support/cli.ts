// The CLI run as users run it: a child process, with its exit status and both output streams.
import { spawnSync } from 'node:child_process';
import { repoRoot } from '../../paths.ts';

export function cscd(...args: string[]) {
  const result = spawnSync(process.execPath, ['cli/cscd.mjs', ...args], { cwd: repoRoot, encoding: 'utf8' });
  return { status: result.status, stdout: result.stdout, stderr: result.stderr };
}
