/**
 * PLY header and element data (ascii, binary_little_endian, binary_big_endian), shared by the PLY
 * readers of meshes and skeletons. The header gives the elements with their counts and scalar and
 * list properties of every PLY type; a reader then asks for properties by element and name and gets,
 * per scalar property, one Float64Array (a double holds every PLY type exactly) and, per list
 * property, the length of each row's list and all items in one array. Everything else is skipped.
 */
import { TextScanner, latin1 } from './scan.ts';

export type PlyEncoding = 'ascii' | 'binary_little_endian' | 'binary_big_endian';

export interface PlyType {
  size: number;
  read: (view: DataView, offset: number, littleEndian: boolean) => number;
}

const INT8: PlyType = { size: 1, read: (v, o) => v.getInt8(o) };
const UINT8: PlyType = { size: 1, read: (v, o) => v.getUint8(o) };
const INT16: PlyType = { size: 2, read: (v, o, le) => v.getInt16(o, le) };
const UINT16: PlyType = { size: 2, read: (v, o, le) => v.getUint16(o, le) };
const INT32: PlyType = { size: 4, read: (v, o, le) => v.getInt32(o, le) };
const UINT32: PlyType = { size: 4, read: (v, o, le) => v.getUint32(o, le) };
const FLOAT32: PlyType = { size: 4, read: (v, o, le) => v.getFloat32(o, le) };
const FLOAT64: PlyType = { size: 8, read: (v, o, le) => v.getFloat64(o, le) };

const PLY_TYPES: Record<string, PlyType> = {
  char: INT8, int8: INT8,
  uchar: UINT8, uint8: UINT8,
  short: INT16, int16: INT16,
  ushort: UINT16, uint16: UINT16,
  int: INT32, int32: INT32,
  uint: UINT32, uint32: UINT32,
  float: FLOAT32, float32: FLOAT32,
  double: FLOAT64, float64: FLOAT64,
};

export interface PlyProperty {
  name: string;
  type: PlyType;
  /** Set for list properties: the type of the item count (`type` is then the item type). */
  countType?: PlyType;
}

export interface PlyElement {
  name: string;
  count: number;
  properties: PlyProperty[];
}

export interface PlyHeader {
  encoding: PlyEncoding;
  elements: PlyElement[];
  /** The text of the `comment` lines, in order. */
  comments: string[];
  /** The text of the `obj_info` lines, in order. */
  objInfo: string[];
  /** Byte offset of the first data byte, just after `end_header` and its line break. */
  dataStart: number;
  /** Number of header lines, so that ASCII data errors can name file lines. */
  lineCount: number;
}

/** How the reader built on this module reports a file it cannot read (the messages have no format prefix). */
export interface PlyErrors {
  fail(message: string): never;
  /** For data that ends before the header's counts are read; `fail` when not given. */
  truncated?(message: string): never;
}

/** Checks run while a list property is read, so that a message can name the line (ascii) or row at fault. */
export interface PlyListCheck {
  /** A message if a row's list may not have this length (asked before its items are read). */
  length?: (row: number, length: number) => string | undefined;
  /** A message if the item may not stand in a row's list. */
  item?: (row: number, item: number) => string | undefined;
  /** Set when the items are integers, e.g. 'vertex index': ascii items are then integer tokens, named so in messages. */
  integers?: string;
}

/** Per element name (the first element of that name), the properties to read; absent ones are left out. */
export type PlyRequest = Record<string, (string | { name: string; check: PlyListCheck })[]>;

/** A list property: row r's items are `items[start .. start + lengths[r])`, start being the sum of the earlier lengths. */
export interface PlyList {
  lengths: Uint32Array;
  items: Float64Array;
}

export interface PlyElementData {
  scalars: Record<string, Float64Array>;
  lists: Record<string, PlyList>;
}

const END_HEADER = 'end_header';
/** Fewest ASCII bytes a value takes: one digit and a separator. */
const MIN_ASCII_VALUE_BYTES = 2;

/** The first element of that name, or undefined. */
export function findElement(header: PlyHeader, name: string): PlyElement | undefined {
  return header.elements.find((e) => e.name === name);
}

/** The element's first property with one of the names (in the order of the names), or undefined. */
export function findProperty(element: PlyElement, ...names: string[]): PlyProperty | undefined {
  for (const name of names) {
    const property = element.properties.find((p) => p.name === name);
    if (property) return property;
  }
  return undefined;
}

export function parsePlyHeader(bytes: Uint8Array, errors: PlyErrors): PlyHeader {
  if (!/^ply[\r\n]/.test(latin1(bytes, 0, Math.min(4, bytes.length)))) errors.fail("missing 'ply' magic line");
  const headerEnd = findHeaderEnd(bytes, errors);
  const text = latin1(bytes, 0, headerEnd.textEnd);
  const lines = text.split(/\r\n|\r|\n/);

  let encoding: PlyEncoding | undefined;
  const elements: PlyElement[] = [];
  const comments: string[] = [];
  const objInfo: string[] = [];
  for (let i = 1; i < lines.length; i++) {
    const words = lines[i].trim().split(/\s+/);
    const where = `header line ${i + 1}`;
    switch (words[0]) {
      case '':
      case END_HEADER:
        break;
      case 'comment':
        comments.push(afterKeyword(lines[i]));
        break;
      case 'obj_info':
        objInfo.push(afterKeyword(lines[i]));
        break;
      case 'format':
        if (words[1] !== 'ascii' && words[1] !== 'binary_little_endian' && words[1] !== 'binary_big_endian') {
          errors.fail(`${where}: unknown format '${words[1] ?? ''}'`);
        }
        encoding = words[1];
        break;
      case 'element': {
        const count = Number(words[2]);
        if (words.length !== 3 || !Number.isSafeInteger(count) || count < 0) errors.fail(`${where}: expected 'element <name> <count>'`);
        elements.push({ name: words[1], count, properties: [] });
        break;
      }
      case 'property': {
        const element = elements.at(-1);
        if (!element) errors.fail(`${where}: property before any element`);
        element.properties.push(parseProperty(words, where, errors));
        break;
      }
      default:
        errors.fail(`${where}: unknown keyword '${words[0]}'`);
    }
  }
  if (!encoding) errors.fail("no 'format' line in header");
  return { encoding, elements, comments, objInfo, dataStart: headerEnd.dataStart, lineCount: lines.length };
}

/** A header line's text after its first word. */
function afterKeyword(line: string): string {
  return line.trim().replace(/^\S+\s*/, '');
}

/** Finds `end_header` at the start of a line and the byte after its line break. */
function findHeaderEnd(bytes: Uint8Array, errors: PlyErrors): { textEnd: number; dataStart: number } {
  const marker = END_HEADER;
  let from = 0;
  for (;;) {
    const i = indexOfAscii(bytes, marker, from);
    if (i < 0) errors.fail("no 'end_header' line: the header is incomplete");
    const atLineStart = i > 0 && (bytes[i - 1] === 0x0a || bytes[i - 1] === 0x0d);
    let p = i + marker.length;
    while (p < bytes.length && (bytes[p] === 0x20 || bytes[p] === 0x09)) p++;
    if (atLineStart) {
      // Accept \n, \r\n or \r after end_header (and nothing at the very end of the file).
      if (bytes[p] === 0x0d) p++;
      if (bytes[p] === 0x0a) p++;
      return { textEnd: i + marker.length, dataStart: p };
    }
    from = i + 1;
  }
}

function indexOfAscii(bytes: Uint8Array, text: string, from: number): number {
  const first = text.charCodeAt(0);
  for (let i = bytes.indexOf(first, from); i >= 0 && i + text.length <= bytes.length; i = bytes.indexOf(first, i + 1)) {
    let k = 1;
    while (k < text.length && bytes[i + k] === text.charCodeAt(k)) k++;
    if (k === text.length) return i;
  }
  return -1;
}

function parseProperty(words: string[], where: string, errors: PlyErrors): PlyProperty {
  if (words[1] === 'list') {
    const countType = PLY_TYPES[words[2]];
    const type = PLY_TYPES[words[3]];
    if (words.length !== 5 || !countType || !type) errors.fail(`${where}: expected 'property list <count type> <item type> <name>'`);
    return { name: words[4], type, countType };
  }
  const type = PLY_TYPES[words[1]];
  if (words.length !== 3 || !type) errors.fail(`${where}: expected 'property <type> <name>' with a known type`);
  return { name: words[2], type };
}

/** Where the values of one property go while its element is read; null for a property that is skipped. */
type Target = Float64Array | ListTarget | null;

/** A list property's lengths and a growing array of its items. */
class ListTarget {
  readonly lengths: Uint32Array;
  items: Float64Array;
  size = 0;

  constructor(rows: number, readonly check: PlyListCheck) {
    this.lengths = new Uint32Array(rows);
    // Room for triangles: the usual face list, so that a mesh's indices never regrow.
    this.items = new Float64Array(Math.max(16, 3 * rows));
  }

  /** Makes room for n more items. */
  reserve(n: number): void {
    if (this.size + n <= this.items.length) return;
    const bigger = new Float64Array(Math.max(2 * this.items.length, this.size + n));
    bigger.set(this.items.subarray(0, this.size));
    this.items = bigger;
  }

  list(): PlyList {
    return { lengths: this.lengths, items: this.items.slice(0, this.size) };
  }
}

/**
 * Reads the requested properties of the data that follows the header. Checks first, before anything
 * is allocated, that the data can hold what the header claims.
 */
export function readPlyElements(bytes: Uint8Array, header: PlyHeader, request: PlyRequest, errors: PlyErrors): Record<string, PlyElementData> {
  const truncated = (message: string): never => (errors.truncated ? errors.truncated(message) : errors.fail(message));
  checkLength(header, bytes.length - header.dataStart, truncated);
  const targets = new Map<PlyElement, Target[]>();
  const data: Record<string, PlyElementData> = {};
  for (const [name, wanted] of Object.entries(request)) {
    const element = findElement(header, name);
    if (!element) continue;
    const byName = new Map(wanted.map((w) => (typeof w === 'string' ? [w, {}] : [w.name, w.check])));
    targets.set(element, element.properties.map((p) => {
      const check = byName.get(p.name);
      if (!check) return null;
      // Of properties with the same name, the first is read.
      byName.delete(p.name);
      return p.countType ? new ListTarget(element.count, check) : new Float64Array(element.count);
    }));
  }
  if (header.encoding === 'ascii') readAscii(bytes, header, targets, errors, truncated);
  else readBinary(bytes, header, targets, errors, truncated);

  for (const [element, elementTargets] of targets) {
    const elementData: PlyElementData = { scalars: {}, lists: {} };
    elementTargets.forEach((target, k) => {
      const { name } = element.properties[k];
      if (target instanceof ListTarget) elementData.lists[name] = target.list();
      else if (target) elementData.scalars[name] = target;
    });
    data[element.name] = elementData;
  }
  return data;
}

/** Every list counts as empty, so this is a lower bound on the size. */
function checkLength(header: PlyHeader, available: number, truncated: (message: string) => never): void {
  let needed = 0;
  for (const element of header.elements) {
    const rowBytes = header.encoding === 'ascii'
      ? MIN_ASCII_VALUE_BYTES * element.properties.length
      : element.properties.reduce((sum, p) => sum + (p.countType ?? p.type).size, 0);
    needed += element.count * rowBytes;
    // The last ASCII value needs no separator after it.
    if (needed - (header.encoding === 'ascii' ? 1 : 0) > available) {
      truncated(`header claims ${element.count} ${elementNoun(element)} but the file has only ${available} bytes of data`);
    }
  }
}

function elementNoun(element: PlyElement): string {
  if (element.name === 'vertex') return 'vertices';
  if (element.name === 'face') return 'faces';
  return `'${element.name}' elements`;
}

function readBinary(
  bytes: Uint8Array, header: PlyHeader, targets: Map<PlyElement, Target[]>, errors: PlyErrors, truncated: (message: string) => never,
): void {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const le = header.encoding === 'binary_little_endian';
  const end = bytes.length;
  const truncatedIn = (element: PlyElement, row: number) => truncated(`file is truncated in ${element.name} ${row} of ${element.count}`);
  let offset = header.dataStart;

  for (const element of header.elements) {
    const { properties, count } = element;
    const elementTargets = targets.get(element) ?? properties.map(() => null);
    if (properties.every((p) => !p.countType)) {
      // Rows of scalars have a fixed size: each property is read at a fixed offset in its row.
      const rowBytes = properties.reduce((sum, p) => sum + p.type.size, 0);
      // checkLength counted lists in earlier elements as empty, so this can still fail here.
      if (offset + count * rowBytes > end) truncatedIn(element, Math.floor((end - offset) / rowBytes));
      let at = offset;
      properties.forEach(({ type: { read, size } }, k) => {
        const values = elementTargets[k] as Float64Array | null;
        if (values) for (let row = 0, o = at; row < count; row++, o += rowBytes) values[row] = read(view, o, le);
        at += size;
      });
      offset += count * rowBytes;
      continue;
    }

    for (let row = 0; row < count; row++) {
      for (let k = 0; k < properties.length; k++) {
        const { countType, type } = properties[k];
        const target = elementTargets[k];
        if (!countType) {
          if (offset + type.size > end) truncatedIn(element, row);
          if (target) (target as Float64Array)[row] = type.read(view, offset, le);
          offset += type.size;
          continue;
        }
        if (offset + countType.size > end) truncatedIn(element, row);
        const n = countType.read(view, offset, le);
        offset += countType.size;
        if (!Number.isInteger(n) || n < 0) errors.fail(`${element.name} ${row}: bad list length ${n}`);
        if (offset + n * type.size > end) truncatedIn(element, row);
        if (!(target instanceof ListTarget)) {
          offset += n * type.size;
          continue;
        }
        const { length: checkLength, item: checkItem } = target.check;
        if (checkLength) {
          const problem = checkLength(row, n);
          if (problem) errors.fail(problem);
        }
        target.lengths[row] = n;
        target.reserve(n);
        const { items } = target;
        for (let i = target.size, last = target.size + n; i < last; i++, offset += type.size) {
          const item = type.read(view, offset, le);
          if (checkItem) {
            const problem = checkItem(row, item);
            if (problem) errors.fail(problem);
          }
          items[i] = item;
        }
        target.size += n;
      }
    }
  }
}

/** A scanner whose errors are the reader's own, naming the line. */
class PlyScanner extends TextScanner {
  constructor(bytes: Uint8Array, header: PlyHeader, private readonly errors: PlyErrors) {
    super(bytes, 'PLY', false, header.dataStart, header.lineCount + 1);
  }

  override fail(message: string): never {
    return this.errors.fail(`line ${this.line}: ${message}`);
  }
}

function readAscii(
  bytes: Uint8Array, header: PlyHeader, targets: Map<PlyElement, Target[]>, errors: PlyErrors, truncated: (message: string) => never,
): void {
  const s = new PlyScanner(bytes, header, errors);
  for (const element of header.elements) {
    const { properties, count } = element;
    const elementTargets = targets.get(element) ?? properties.map(() => null);
    for (let row = 0; row < count; row++) {
      s.skipWhitespace();
      if (s.atEnd()) truncated(`file ends after ${row} of ${count} ${elementNoun(element)}`);
      for (let k = 0; k < properties.length; k++) {
        const target = elementTargets[k];
        s.skipWhitespace();
        if (!properties[k].countType) {
          const value = s.readNumber();
          if (target) (target as Float64Array)[row] = value;
          continue;
        }
        const n = s.readInt('list length');
        if (n < 0) s.fail(`bad list length ${n}`);
        if (!(target instanceof ListTarget)) {
          for (let i = 0; i < n; i++) {
            s.skipWhitespace();
            s.readNumber();
          }
          continue;
        }
        const { length: checkLength, item: checkItem, integers } = target.check;
        const problem = checkLength?.(row, n);
        if (problem) s.fail(problem);
        target.lengths[row] = n;
        target.reserve(n);
        const { items } = target;
        for (let i = target.size, last = target.size + n; i < last; i++) {
          s.skipWhitespace();
          const item = integers ? s.readInt(integers) : s.readNumber();
          const itemProblem = checkItem?.(row, item);
          if (itemProblem) s.fail(itemProblem);
          items[i] = item;
        }
        target.size += n;
      }
    }
  }
}
