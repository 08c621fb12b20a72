/**
 * The `cscd` command line: `cscd <command> [options]`, as `run(argv, io)` (the bin, cli/cscd.mjs,
 * calls it with the process's streams; tests call it in-process). To add a command, write it in
 * cli/commands/ and list it in COMMANDS.
 */
import { readFileSync } from 'node:fs';
import { parseArgs, type ParseArgsConfig } from 'node:util';
import { CoreError } from '../lib/core/types.ts';
import { CLOUD_EXTENSIONS, MESH_EXTENSIONS, MeshFormatError } from '../lib/io/index.ts';
import { SkeletonFormatError } from '../lib/io/skeleton.ts';
import { UsageError, discardCore, type CliIo, type Command, type Output } from './command.ts';
import { distance } from './commands/distance.ts';
import { evaluate } from './commands/evaluate.ts';
import { info } from './commands/info.ts';
import { separator } from './commands/separator.ts';
import { skeleton } from './commands/skeleton.ts';

const COMMANDS: Command[] = [info, distance, separator, skeleton, evaluate];

/**
 * Runs one command line (the arguments after `cscd`) with its output on `io` and resolves to the exit
 * code; it never rejects: errors are reported as `reportError` does.
 */
export async function run(argv: string[], io: CliIo): Promise<number> {
  try {
    await dispatch(argv, io);
    return 0;
  } catch (error) {
    // An aborted or trapped WASM module is not safe to call again: the next run loads a fresh one.
    if (error instanceof WebAssembly.RuntimeError) discardCore();
    return reportError(error, io);
  }
}

async function dispatch(argv: string[], io: CliIo): Promise<void> {
  const [first, ...rest] = argv;
  if (first === undefined || first === '--help' || first === '-h') return print(io.stdout, overview());
  if (first === '--version' || first === '-V') return print(io.stdout, version());
  if (first === 'help') return print(io.stdout, rest.length > 0 ? commandHelp(findCommand(rest[0])) : overview());
  const command = findCommand(first);

  const options: NonNullable<ParseArgsConfig['options']> = { help: { type: 'boolean', short: 'h' } };
  for (const [name, spec] of Object.entries(command.options)) {
    options[name] = spec.short ? { type: spec.type, short: spec.short } : { type: spec.type };
  }
  let parsed;
  try {
    parsed = parseArgs({ args: rest, options, allowPositionals: true, strict: true });
  } catch (error) {
    // parseArgs explains unknown options and missing values well; they are usage errors.
    const code = (error as NodeJS.ErrnoException).code;
    throw code?.startsWith('ERR_PARSE_ARGS') ? new UsageError(`${command.name}: ${(error as Error).message}`) : error;
  }
  const { values, positionals } = parsed;
  if (values.help) return print(io.stdout, commandHelp(command));
  if (positionals.length !== command.args.length) {
    throw new UsageError(`${command.name}: expected ${command.args.join(' ')}, got ${positionals.length} argument${positionals.length === 1 ? '' : 's'} (usage: ${usage(command)})`);
  }
  for (const [name, spec] of Object.entries(command.options)) {
    if (spec.required && values[name] === undefined) throw new UsageError(`${command.name}: --${name} is required (usage: ${usage(command)})`);
  }
  await command.run(positionals, values, io);
}

function findCommand(name: string): Command {
  const command = COMMANDS.find((c) => c.name === name);
  if (!command) throw new UsageError(`unknown command '${name}' (see cscd --help)`);
  return command;
}

function print(out: Output, text: string): void {
  out.write(`${text}\n`);
}

function version(): string {
  const packageJson = JSON.parse(readFileSync(new URL('../package.json', import.meta.url), 'utf8')) as { version: string };
  return packageJson.version;
}

function optionSyntax(name: string, spec: Command['options'][string]): string {
  const flag = spec.short ? `-${spec.short}, --${name}` : `--${name}`;
  return spec.type === 'string' ? `${flag} ${spec.value ?? 'VALUE'}` : flag;
}

function usage(command: Command): string {
  const options = Object.entries(command.options).map(([name, spec]) => {
    const syntax = optionSyntax(name, { ...spec, short: undefined });
    return spec.required ? syntax : `[${syntax}]`;
  });
  return ['cscd', command.name, ...command.args, ...options].join(' ');
}

/** Two aligned columns. */
function table(rows: [string, string][]): string {
  const width = Math.max(...rows.map(([left]) => left.length)) + 3;
  return rows.map(([left, right]) => `  ${left.padEnd(width)}${right}`).join('\n');
}

function overview(): string {
  return [
    `cscd ${version()}: curve skeletons of triangle meshes and point clouds (CSCD)`,
    '',
    'Usage: cscd <command> [options]',
    '',
    'Commands:',
    table([
      ...COMMANDS.map((c): [string, string] => [[c.name, ...c.args, Object.keys(c.options).length > 1 ? '[options]' : ''].join(' ').trim(), c.summary]),
      ['help <command>', 'show the options of a command'],
    ]),
    '',
    'Options:',
    table([
      ['-h, --help', 'show this help (after a command: its help)'],
      ['-V, --version', 'print the version'],
    ]),
    '',
    `Meshes: ${MESH_EXTENSIONS.join(' ')} (the format is checked against the content).`,
    `Point clouds (info, distance and skeleton): ${CLOUD_EXTENSIONS.join(' ')} (PLY and OBJ files without faces, point lists).`,
    'Errors: one line "cscd: <message>" on stderr; exit code 2 for usage errors, 1 otherwise.',
  ].join('\n');
}

function commandHelp(command: Command): string {
  const rows = Object.entries(command.options).map(([name, spec]): [string, string] => [optionSyntax(name, spec), spec.description]);
  rows.push(['-h, --help', 'show this help']);
  return [`Usage: ${usage(command)}`, '', command.summary, ...(command.details ? [command.details] : []), '', 'Options:', table(rows)].join('\n');
}

/**
 * One line on stderr, never a stack trace, and the exit code: 2 for usage errors, 1 otherwise. Our own
 * errors are meant for users as they are; others (a RangeError, a WASM RuntimeError...) keep their name
 * as a hint of what went wrong.
 */
export function reportError(error: unknown, io: CliIo): number {
  const ours = error instanceof MeshFormatError || error instanceof SkeletonFormatError || error instanceof CoreError || error instanceof UsageError;
  const message = !(error instanceof Error) ? String(error)
    : ours || error.constructor === Error ? error.message
    : `${error.name}: ${error.message}`;
  io.stderr.write(`cscd: ${message.split('\n')[0]}\n`);
  return error instanceof UsageError ? 2 : 1;
}
