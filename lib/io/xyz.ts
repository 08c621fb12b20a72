/**
 * Text point lists (.xyz .pts .txt .csv): one point per line, its numbers separated by blanks,
 * commas or semicolons; `#` and `//` comments and blank lines are skipped. When the first line that is
 * not a comment has a semicolon, the file is a spreadsheet export of a comma-decimal locale: `;`
 * separates and `,` is the decimal mark.
 *
 * Two kinds of lines may stand among the rows:
 * - a header of column names before the first row (CSV `x,y,z,nx,ny,nz`), recognised by its first
 *   word not being a number; it names x, y and z, in any order. A comment that starts with x y z and
 *   names as many columns as the rows have is a header too (CloudCompare writes `//X,Y,Z,Nx,Ny,Nz`);
 * - a line of one integer, a point count as in .pts, before the first row or right after as many
 *   rows as the previous count said (Leica files hold several scans, each after its count).
 *
 * Columns: every row has as many as the first. With a header, x y z and nx ny nz are the named
 * columns (normals only when all three are named); other columns are ignored. Without one, columns
 * 1-3 are x y z, and columns 4-6 are normals when they are unit vectors on every row: normals written
 * by any tool are, while colours (0-255 or 0-1), intensities or unnormalised vectors almost never are
 * on every row, and a wrong guess either way would be silent. Every column not read is named in a warning.
 */
import { grow, trim } from './mesh-builder.ts';
import { TextScanner, latin1 } from './scan.ts';
import { MeshFormatError, type ParsedCloud } from './types.ts';

const LF = 0x0a;
const SPACE = 0x20;
const HASH = 0x23;
const COMMA = 0x2c;
const DOT = 0x2e;
const SLASH = 0x2f;
const SEMICOLON = 0x3b;

/** A number as the scanner reads it, NaN and infinities included. */
const NUMBER = /^[+-]?((\d+\.?\d*|\.\d+)([eE][+-]?\d+)?|nan\S*|inf(inity)?)$/i;
/** Normals written with two decimals are unit vectors to within 1%. */
const UNIT_TOLERANCE = 0.01;
/** Accepted header names (lower case, quotes and underscores removed) of the columns read. */
const COLUMN_NAMES: Record<string, string> = { x: 'x', y: 'y', z: 'z', nx: 'nx', ny: 'ny', nz: 'nz', normalx: 'nx', normaly: 'ny', normalz: 'nz' };

/** A line of column names, and the line it stands on. */
interface Header {
  names: string[];
  line: number;
  commented: boolean;
}

/** Which column holds each value read. */
interface Layout {
  columns: number;
  position: number[];
  /** The columns of nx ny nz (without a header, only candidates until every row is checked), or null. */
  normal: number[] | null;
  /** The header's names of the columns not read; null without a header. */
  ignoredNames: string[] | null;
}

export function parseXyz(bytes: Uint8Array): ParsedCloud {
  const text = normalise(bytes);
  const { header, start, line } = findHeader(text);
  const s = new TextScanner(text, 'XYZ', true, start, line);
  const row: number[] = [];
  let positions = new Float64Array(Math.max(3, 3 * Math.ceil(text.length / 24)));
  let candidates: Float32Array | null = null;
  let layout: Layout | null = null;
  let count = 0;
  let countLine = 0;
  let blockRows = 0;
  let expected = -1;

  for (s.skipWhitespace(); !s.atEnd(); s.skipWhitespace()) {
    row.length = 0;
    while (!s.atLineEnd()) row.push(s.readNumber());
    const isCount = row.length === 1 && Number.isSafeInteger(row[0]) && row[0] >= 0;
    if (isCount && (expected < 0 ? layout === null : blockRows === expected)) {
      expected = row[0];
      countLine = s.line;
      blockRows = 0;
      continue;
    }
    if (row.length < 3) s.fail(`expected at least 3 numbers (x y z), found ${row.length}`);
    if (layout === null) {
      layout = chooseLayout(header, row.length, s);
      if (layout.normal) candidates = new Float32Array(positions.length);
    } else if (row.length !== layout.columns) {
      s.fail(`${row.length} columns, but the first row has ${layout.columns}`);
    }
    if (blockRows === expected) s.fail(`more rows than the ${expected} that the count line (line ${countLine}) says`);
    if (3 * count + 3 > positions.length) {
      positions = grow(positions);
      if (candidates) candidates = grow(candidates);
    }
    for (let k = 0; k < 3; k++) positions[3 * count + k] = row[layout.position[k]];
    if (candidates && layout.normal) for (let k = 0; k < 3; k++) candidates[3 * count + k] = row[layout.normal[k]];
    count++;
    blockRows++;
  }
  if (expected >= 0 && blockRows !== expected) {
    s.line = countLine;
    s.fail(`the count line says ${expected} points, but ${blockRows} rows follow`);
  }
  if (layout === null) throw new MeshFormatError('XYZ: no points in file');

  let normals = candidates && trim(candidates, 3 * count);
  if (normals && layout.ignoredNames === null && !allUnit(normals)) normals = null;
  const warning = columnsWarning(layout, normals !== null);
  return { kind: 'cloud', format: 'xyz', positions: trim(positions, 3 * count), normals, warnings: warning ? [warning] : [] };
}

/**
 * A copy of the file in which separators are blanks and `//` starts a `#` comment, so that the
 * scanner of the text mesh formats reads it.
 */
function normalise(bytes: Uint8Array): Uint8Array {
  const text = bytes.slice();
  const decimalCommas = firstRowHasSemicolon(text);
  for (let i = 0; i < text.length; i++) {
    const b = text[i];
    if (b === SEMICOLON) text[i] = SPACE;
    else if (b === COMMA) text[i] = decimalCommas ? DOT : SPACE;
    else if (b === SLASH && text[i + 1] === SLASH) text[i] = text[i + 1] = HASH;
  }
  return text;
}

/** Whether the first line that is neither blank nor a comment has a semicolon. */
function firstRowHasSemicolon(bytes: Uint8Array): boolean {
  for (let start = 0; start < bytes.length;) {
    const end = lineEnd(bytes, start);
    const line = latin1(bytes, start, end).trim();
    if (line !== '' && !line.startsWith('#') && !line.startsWith('//')) return line.includes(';');
    start = end + 1;
  }
  return false;
}

function lineEnd(bytes: Uint8Array, start: number): number {
  const end = bytes.indexOf(LF, start);
  return end < 0 ? bytes.length : end;
}

/**
 * The header among the lines before the first row, if any, and where the rows start (byte and line).
 * A line that is no comment and does not start with a number must be the header.
 */
function findHeader(text: Uint8Array): { header: Header | null; start: number; line: number } {
  let header: Header | null = null;
  let line = 1;
  let start = 0;
  for (; start < text.length; line++) {
    const end = lineEnd(text, start);
    const content = latin1(text, start, end).trim();
    const commented = content.startsWith('#');
    const names = (commented ? content.replace(/^#+/, '') : content.replace(/#.*/, '')).trim().split(/\s+/).filter((word) => word !== '');
    if (names.length === 0) {
      start = end + 1;
      continue;
    }
    if (!commented && NUMBER.test(names[0])) break;
    const columns = names.map(columnName);
    if (!commented) {
      if (!['x', 'y', 'z'].every((axis) => columns.includes(axis))) {
        throw new MeshFormatError(`XYZ: line ${line}: expected numbers or a header of column names with x, y and z, found '${content.slice(0, 40)}'`);
      }
      header = { names, line, commented };
    } else if (columns[0] === 'x' && columns[1] === 'y' && columns[2] === 'z') {
      header ??= { names, line, commented };
    }
    start = end + 1;
  }
  return { header, start, line };
}

function columnName(word: string): string {
  const name = word.toLowerCase().replace(/["'_]/g, '');
  return COLUMN_NAMES[name] ?? name;
}

/** The columns to read, from the header or, without one, from the number of columns of the first row. */
function chooseLayout(header: Header | null, columns: number, s: TextScanner): Layout {
  if (header && !header.commented && header.names.length !== columns) {
    s.fail(`${columns} columns, but the header (line ${header.line}) names ${header.names.length}`);
  }
  if (header && header.names.length === columns) {
    const names = header.names.map(columnName);
    const position = ['x', 'y', 'z'].map((axis) => names.indexOf(axis));
    const normal = ['nx', 'ny', 'nz'].map((axis) => names.indexOf(axis));
    const read = normal.every((i) => i >= 0) ? [...position, ...normal] : position;
    return { columns, position, normal: read.length === 6 ? normal : null, ignoredNames: header.names.filter((_, i) => !read.includes(i)) };
  }
  return { columns, position: [0, 1, 2], normal: columns >= 6 ? [3, 4, 5] : null, ignoredNames: null };
}

/** What was read of the columns, when that is not just x y z as named or as the only three columns. */
function columnsWarning({ columns, ignoredNames }: Layout, normalsRead: boolean): string | null {
  if (ignoredNames) return ignoredNames.length === 0 ? null : `ignored the ${ignoredNames.length === 1 ? 'column' : 'columns'} ${ignoredNames.join(', ')}`;
  if (columns === 3) return null;
  if (!normalsRead) {
    const why = columns >= 6 ? ' (columns 4-6 are not unit vectors on every row, so not normals)' : '';
    return `read columns 1-3 as x y z and ignored ${columnRange(4, columns)}${why}`;
  }
  const rest = columns > 6 ? `, and ignored ${columnRange(7, columns)}` : '';
  return `read columns 1-3 as x y z and columns 4-6 as normals (unit vectors on every row)${rest}`;
}

function columnRange(first: number, last: number): string {
  return first === last ? `column ${first}` : `columns ${first}-${last}`;
}

function allUnit(vectors: Float32Array): boolean {
  for (let i = 0; i < vectors.length; i += 3) {
    const length = Math.hypot(vectors[i], vectors[i + 1], vectors[i + 2]);
    if (!(Math.abs(length - 1) <= UNIT_TOLERANCE)) return false;
  }
  return true;
}

/**
 * Whether the start of a file (of unknown extension) looks like a point list: rows of at least three
 * numbers and nothing else but comments, blank lines and count lines. The last line may be cut off.
 */
export function looksLikeXyz(head: Uint8Array, complete: boolean): boolean {
  const lines = latin1(normalise(head), 0, head.length).split('\n');
  if (!complete) lines.pop();
  let rows = 0;
  for (const line of lines) {
    const words = line.replace(/#.*/, '').trim().split(/\s+/).filter((word) => word !== '');
    if (words.length === 0 || (words.length === 1 && /^\d+$/.test(words[0]))) continue;
    if (words.length < 3 || !words.every((word) => NUMBER.test(word))) return false;
    rows++;
  }
  return rows > 0;
}
