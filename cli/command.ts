/** What every CLI command shares: its description for help and parsing, errors, mesh input. */
import { readFile } from 'node:fs/promises';
import { loadCoreNode } from '../lib/core/node.ts';
import type { Core } from '../lib/core/types.ts';
import { parseMesh, type ParsedMesh } from '../lib/io/index.ts';

export interface OptionSpec {
  type: 'string' | 'boolean';
  short?: string;
  /** Placeholder of a string option's value in help, e.g. "V" in "--source V". */
  value?: string;
  required?: boolean;
  description: string;
}

/** Option values as node:util parseArgs returns them. */
export type OptionValues = Record<string, string | boolean | (string | boolean)[] | undefined>;

export interface Command {
  name: string;
  /** One line for the command list. */
  summary: string;
  /** Placeholders of the positional arguments, e.g. ["<mesh>"]. */
  args: string[];
  options: Record<string, OptionSpec>;
  /** More text for `cscd help <command>`. */
  details?: string;
  run(args: string[], options: OptionValues): Promise<void>;
}

/** A mistake in the command line: reported with exit code 2. */
export class UsageError extends Error {
  override name = 'UsageError';
}

let core: Promise<Core> | undefined;

/** The WASM core, loaded on first use (help and usage errors never pay for it). */
export function getCore(): Promise<Core> {
  core ??= loadCoreNode();
  return core;
}

/** A file's bytes, or an error that says in plain words why it cannot be read. */
export async function readBytes(file: string): Promise<Uint8Array> {
  try {
    return await readFile(file);
  } catch (error) {
    const code = (error as NodeJS.ErrnoException).code;
    const reason = code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'it is a directory' : (error as Error).message;
    throw new Error(`cannot read '${file}': ${reason}`);
  }
}

/** Reads and parses a mesh file; parser warnings go to stderr unless the command reports them itself. */
export async function readMesh(file: string, { printWarnings = true } = {}): Promise<ParsedMesh> {
  const mesh = parseMesh(await readBytes(file), file);
  if (printWarnings) for (const warning of mesh.warnings) process.stderr.write(`cscd: warning: ${file}: ${warning}\n`);
  return mesh;
}
