// Running a method of the bench: a process of its own, pinned to one core, one thread for every library,
// killed at the timeout; what it printed kept in a log beside its skeleton.
import { execFileSync, spawnSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { OPTIONS, parseSpecText } from '../lib/core/options.ts';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const venvPython = path.join(repoRoot, '.deps', 'bench-venv', 'bin', 'python');
/** pc-skeletor's own environment (bench/setup.sh skeletor): it needs numpy < 1.24. */
export const skeletorPython = path.join(repoRoot, '.deps', 'skeletor-venv', 'bin', 'python');

/**
 * Node's flags for a run of our WebAssembly core timed against methods compiled ahead of time (MSLS's
 * C++): the whole module compiled by V8's optimising compiler as it is loaded, before the clock starts.
 * Without them it starts on the baseline compiler and is tiered up function by function while it runs,
 * which on one pinned core competes with the run itself (dtorus: 1.40 s cold, 0.43 s compiled; the
 * compiling takes about 2 s and is excluded, as loading the module and MSLS's compilation are).
 */
export const COMPILED_CORE = ['--no-liftoff', '--no-wasm-lazy-compilation'];

/** A `--seed` argument read by the option table's rule for the seed; null when it does not accept it. */
export function seedArgument(text: string): number | null {
  return parseSpecText(OPTIONS.find((o) => o.key === 'seed')!, text) as number | null;
}

/** One thread for every library that would start more (OpenMP in Eigen, BLAS under numpy). */
const ONE_THREAD_ENV = {
  OMP_NUM_THREADS: '1',
  OPENBLAS_NUM_THREADS: '1',
  MKL_NUM_THREADS: '1',
  NUMEXPR_NUM_THREADS: '1',
  VECLIB_MAXIMUM_THREADS: '1',
};

export interface Run {
  status: 'ok' | 'timeout' | 'failed';
  seconds: number | null;
  /** Why it failed, one short line. */
  reason: string;
  file: string;
}

function reasonOf(stderr: string): string {
  const lines = stderr.split('\n').map((l) => l.trim()).filter((l) => l && !/^at\s/.test(l) && !/^Node\.js v/.test(l));
  const line = lines[lines.length - 1] ?? '';
  return line.length > 100 ? `${line.slice(0, 97)}...` : line;
}

/**
 * Runs `command` (which writes the skeleton `file` and prints {"seconds": S} as its last line of stdout)
 * pinned to core `cpu`, its output kept in `log`.
 */
export function runPinned(command: string[], file: string, log: string, timeout: number, cpu: number): Run {
  const pinned = ['taskset', '-c', String(cpu), ...command];
  const result = spawnSync(pinned[0], pinned.slice(1), {
    cwd: repoRoot,
    env: { ...process.env, ...ONE_THREAD_ENV },
    encoding: 'utf8',
    timeout: timeout * 1000,
    killSignal: 'SIGKILL',
    maxBuffer: 1 << 28,
  });
  writeFileSync(log, `$ ${pinned.join(' ')}\n--- stdout\n${result.stdout ?? ''}\n--- stderr\n${result.stderr ?? ''}`);

  const failed = (reason: string): Run => ({ status: 'failed', seconds: null, reason, file });
  if ((result.error as NodeJS.ErrnoException | undefined)?.code === 'ETIMEDOUT') return { status: 'timeout', seconds: null, reason: '', file };
  if (result.error) return failed(result.error.message);
  if (result.status !== 0) {
    const why = reasonOf(result.stderr);
    return failed(result.signal ? `${why ? `${why}, ` : ''}killed by ${result.signal}` : why || `exit code ${result.status}`);
  }
  const last = result.stdout.trim().split('\n').pop() ?? '';
  try {
    const seconds = (JSON.parse(last) as { seconds?: unknown }).seconds;
    if (typeof seconds === 'number' && Number.isFinite(seconds)) return { status: 'ok', seconds, reason: '', file };
  } catch {
    // Not JSON: reported below.
  }
  return failed('no {"seconds": S} line on stdout');
}

/** A command's output, trimmed, or 'unknown'. */
export function shell(command: string, args: string[]): string {
  try {
    return execFileSync(command, args, { cwd: repoRoot, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
  } catch {
    return 'unknown';
  }
}
