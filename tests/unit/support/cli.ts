// The CLI two ways: in-process through run(argv, io) (no Node start-up per call, one core per test
// file), and as users run it, a child process of cli/cscd.mjs (the smoke tests).
import { spawnSync } from 'node:child_process';
import { expect, vi } from 'vitest';
import { run } from '../../../cli/main.ts';
import { repoRoot } from '../../paths.ts';

/**
 * `cscd ...args` in-process: its exit code and what it wrote, stderr not being a terminal. Anything
 * written around the io (to process.stdout, process.stderr or the console) fails the test: a user would
 * see it, a test of the io would not.
 */
export async function cscd(...args: string[]) {
  let stdout = '';
  let stderr = '';
  let around = '';
  const capture = (...chunks: unknown[]) => {
    around += `${chunks.map(String).join(' ')}\n`;
    return true;
  };
  const spies = [
    vi.spyOn(process.stdout, 'write').mockImplementation(capture),
    vi.spyOn(process.stderr, 'write').mockImplementation(capture),
    ...(['log', 'info', 'warn', 'error'] as const).map((method) => vi.spyOn(console, method).mockImplementation(capture)),
  ];
  let status: number;
  try {
    status = await run(args, {
      stdout: { write: (text: string) => (stdout += text) },
      stderr: { write: (text: string) => (stderr += text) },
    });
  } finally {
    for (const spy of spies) spy.mockRestore();
  }
  expect(around, `cscd ${args.join(' ')} wrote around its io`).toBe('');
  return { status, stdout, stderr };
}

/** `cscd ...args` as a child process, killed after `timeout` ms if given: a hang fails the test. */
export function cscdProcess(args: string[], { timeout }: { timeout?: number } = {}) {
  const result = spawnSync(process.execPath, ['cli/cscd.mjs', ...args], { cwd: repoRoot, encoding: 'utf8', timeout });
  const timedOut = (result.error as NodeJS.ErrnoException | undefined)?.code === 'ETIMEDOUT';
  return { status: result.status, stdout: result.stdout, stderr: result.stderr, timedOut };
}
