/** What every CLI command shares: its description for help and parsing, errors, mesh input. */
import { readFile } from 'node:fs/promises';
import { loadCoreNode } from '../lib/core/node.ts';
import type { Core, MeshArrays, RefinedSurface } from '../lib/core/types.ts';
import { parseMesh, type ParsedMesh } from '../lib/io/index.ts';
import { repairMesh } from '../lib/io/repair.ts';
import { decimate } from '../lib/mesh/decimate.ts';
import { DECIMATE_TARGET, FACE_LIMIT, sizeWarning } from '../lib/mesh/limits.ts';

export interface OptionSpec {
  type: 'string' | 'boolean';
  short?: string;
  /** Placeholder of a string option's value in help, e.g. "V" in "--source V". */
  value?: string;
  required?: boolean;
  description: string;
}

/** A text stream: the process's stdout or stderr, or a string collector in tests. */
export interface Output {
  write(text: string): unknown;
  /** On stderr: a terminal, which gets the skeleton's progress line and summary. */
  isTTY?: boolean;
}

/** Where a command writes: all of its output goes through these, never to `process` directly. */
export interface CliIo {
  stdout: Output;
  stderr: Output;
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
  run(args: string[], options: OptionValues, io: CliIo): Promise<void>;
}

/** A mistake in the command line: reported with exit code 2. */
export class UsageError extends Error {
  override name = 'UsageError';
}

let core: Promise<Core> | undefined;

/**
 * The WASM core, loaded on first use (help and usage errors never pay for it) and shared by every
 * command run in the process.
 */
export function getCore(): Promise<Core> {
  core ??= loadCoreNode();
  return core;
}

/** Forgets the shared core, so that the next getCore() loads a fresh one. */
export function discardCore(): void {
  core = undefined;
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

/** A mesh file as every command works on it: parsed, then repaired (lib/io/repair.ts). */
export interface InputMesh extends ParsedMesh {
  /** What the repair did, one sentence each; empty when the mesh is as in the file. */
  repairs: string[];
  /** Index of every vertex of the file in the repaired mesh, -1 for removed ones. */
  vertexMap: Int32Array;
}

/**
 * Reads, parses and repairs a mesh file; parser warnings and repairs go to stderr unless the command
 * reports them itself.
 */
export async function readMesh(file: string, io: CliIo, { printWarnings = true } = {}): Promise<InputMesh> {
  const parsed = parseMesh(await readBytes(file), file);
  const { mesh, repairs, vertexMap } = repairMesh(parsed);
  if (printWarnings) {
    for (const warning of parsed.warnings) io.stderr.write(`cscd: warning: ${file}: ${warning}\n`);
    for (const repair of repairs) io.stderr.write(`cscd: repaired: ${repair}\n`);
  }
  return { ...parsed, ...mesh, repairs, vertexMap };
}

/** --decimate K, for the commands that take it (the page's "Decimate to K faces"). */
export const decimateOption: OptionSpec = {
  type: 'string',
  value: 'K',
  description: `decimate the mesh to about K faces first (quadric edge collapse; genus, components and holes kept); advised above ${FACE_LIMIT} faces`,
};

/**
 * The mesh decimated to `--decimate K` faces when it has more (said on stderr), else as it is;
 * `decimatedFrom` is the face count before, or null.
 */
export function decimateIfAsked<M extends MeshArrays>(mesh: M, values: OptionValues, file: string, io: CliIo): M & { decimatedFrom: number | null } {
  if (values.decimate === undefined) return { ...mesh, decimatedFrom: null };
  const target = Number(values.decimate);
  if (!Number.isInteger(target) || target < 4) throw new UsageError(`--decimate must be a whole number of faces (at least 4), got '${String(values.decimate)}'`);
  const faces = mesh.triangles.length / 3;
  if (faces <= target) return { ...mesh, decimatedFrom: null };
  const started = performance.now();
  const decimated = decimate(mesh, target);
  const seconds = ((performance.now() - started) / 1000).toFixed(1);
  io.stderr.write(`cscd: decimated ${file} from ${faces} to ${decimated.triangles.length / 3} faces in ${seconds} s\n`);
  return { ...mesh, ...decimated, decimatedFrom: faces };
}

/**
 * Opens the geodesic solver, on the mesh refined when it is coarse (lib/mesh/refine.ts; said on
 * stderr, results stay per vertex of `mesh`), first warning on stderr when the mesh is above the size
 * limit (lib/mesh/limits.ts).
 */
export async function openSolver(mesh: MeshArrays, file: string, io: CliIo): Promise<RefinedSurface> {
  const warning = sizeWarning(mesh.triangles.length / 3, mesh.positions.length / 3);
  if (warning) io.stderr.write(`cscd: warning: ${file}: ${warning} (--decimate ${DECIMATE_TARGET} makes it faster)\n`);
  const surface = (await getCore()).openRefinedSurface(mesh);
  const { refined } = surface;
  if (refined) io.stderr.write(`cscd: refined ${file} for computation from ${refined.fromFaces} to ${refined.toFaces} faces (the same surface, sampled more densely)\n`);
  return surface;
}
