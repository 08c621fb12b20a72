// The name of a bench run's result files in bench/results/: never one an earlier run wrote.
import { existsSync, writeFileSync } from 'node:fs';
import path from 'node:path';

/**
 * `<base>`, then `<base>-2`, `-3`... until no file `<name>.<ext>` of the run exists; the name is claimed
 * at once by creating its first file (exclusively), so that two runs started together (one per core) do
 * not write to the same files.
 */
export function claimResultName(resultsDir: string, base: string, extensions: readonly string[]): string {
  const taken = (name: string) => extensions.some((ext) => existsSync(path.join(resultsDir, `${name}.${ext}`)));
  for (let k = 1; ; k++) {
    const name = k === 1 ? base : `${base}-${k}`;
    if (taken(name)) continue;
    try {
      writeFileSync(path.join(resultsDir, `${name}.${extensions[0]}`), '', { flag: 'wx' });
      return name;
    } catch (error) {
      if ((error as NodeJS.ErrnoException).code !== 'EEXIST') throw error;
    }
  }
}
