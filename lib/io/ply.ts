/**
 * PLY (ascii, binary_little_endian, binary_big_endian). Reads x, y, z of the `vertex` element
 * and the `vertex_indices` (or `vertex_index`) list of the `face` element; every other element and
 * property is skipped. Polygons are fan-triangulated.
 */
import { MeshBuilder } from './mesh-builder.ts';
import { TextScanner, latin1 } from './scan.ts';
import { MeshFormatError, type ParsedMesh } from './types.ts';

type Encoding = 'ascii' | 'binary_little_endian' | 'binary_big_endian';
type Reader = (view: DataView, offset: number, littleEndian: boolean) => number;

interface ScalarType {
  size: number;
  read: Reader;
}

const INT8: ScalarType = { size: 1, read: (v, o) => v.getInt8(o) };
const UINT8: ScalarType = { size: 1, read: (v, o) => v.getUint8(o) };
const INT16: ScalarType = { size: 2, read: (v, o, le) => v.getInt16(o, le) };
const UINT16: ScalarType = { size: 2, read: (v, o, le) => v.getUint16(o, le) };
const INT32: ScalarType = { size: 4, read: (v, o, le) => v.getInt32(o, le) };
const UINT32: ScalarType = { size: 4, read: (v, o, le) => v.getUint32(o, le) };
const FLOAT32: ScalarType = { size: 4, read: (v, o, le) => v.getFloat32(o, le) };
const FLOAT64: ScalarType = { size: 8, read: (v, o, le) => v.getFloat64(o, le) };

const SCALAR_TYPES: Record<string, ScalarType> = {
  char: INT8, int8: INT8,
  uchar: UINT8, uint8: UINT8,
  short: INT16, int16: INT16,
  ushort: UINT16, uint16: UINT16,
  int: INT32, int32: INT32,
  uint: UINT32, uint32: UINT32,
  float: FLOAT32, float32: FLOAT32,
  double: FLOAT64, float64: FLOAT64,
};

interface Property {
  name: string;
  type: ScalarType;
  /** Set for list properties: the type of the item count (`type` is then the item type). */
  countType?: ScalarType;
}

interface Element {
  name: string;
  count: number;
  properties: Property[];
}

interface Header {
  encoding: Encoding;
  elements: Element[];
  /** Byte offset of the first data byte, just after `end_header` and its line break. */
  dataStart: number;
  /** Number of header lines, so that ASCII data errors can name file lines. */
  lineCount: number;
}

/** Where the parts of the mesh are in the header. */
interface Layout {
  vertex: Element;
  xyz: [Property, Property, Property];
  face: Element;
  indices: Property;
}

const END_HEADER = 'end_header';
/** Fewest ASCII bytes a value takes: one digit and a separator. */
const MIN_ASCII_VALUE_BYTES = 2;

export function parsePly(bytes: Uint8Array): ParsedMesh {
  const header = parseHeader(bytes);
  const layout = findLayout(header.elements);
  checkLength(header, bytes.length - header.dataStart);
  const builder = new MeshBuilder('ply', layout.vertex.count, layout.face.count);
  if (header.encoding === 'ascii') readAscii(bytes, header, layout, builder);
  else readBinary(bytes, header, layout, builder);
  return builder.finish();
}

function fail(message: string): never {
  throw new MeshFormatError(`PLY: ${message}`);
}

function parseHeader(bytes: Uint8Array): Header {
  if (!/^ply[\r\n]/.test(latin1(bytes, 0, Math.min(4, bytes.length)))) fail("missing 'ply' magic line");
  const headerEnd = findHeaderEnd(bytes);
  const text = latin1(bytes, 0, headerEnd.textEnd);
  const lines = text.split(/\r\n|\r|\n/);

  let encoding: Encoding | undefined;
  const elements: Element[] = [];
  for (let i = 1; i < lines.length; i++) {
    const words = lines[i].trim().split(/\s+/);
    const where = `header line ${i + 1}`;
    switch (words[0]) {
      case '':
      case 'comment':
      case 'obj_info':
      case END_HEADER:
        break;
      case 'format':
        if (words[1] !== 'ascii' && words[1] !== 'binary_little_endian' && words[1] !== 'binary_big_endian') {
          fail(`${where}: unknown format '${words[1] ?? ''}'`);
        }
        encoding = words[1];
        break;
      case 'element': {
        const count = Number(words[2]);
        if (words.length !== 3 || !Number.isSafeInteger(count) || count < 0) fail(`${where}: expected 'element <name> <count>'`);
        elements.push({ name: words[1], count, properties: [] });
        break;
      }
      case 'property': {
        const element = elements.at(-1);
        if (!element) fail(`${where}: property before any element`);
        element.properties.push(parseProperty(words, where));
        break;
      }
      default:
        fail(`${where}: unknown keyword '${words[0]}'`);
    }
  }
  if (!encoding) fail("no 'format' line in header");
  return { encoding, elements, dataStart: headerEnd.dataStart, lineCount: lines.length };
}

/** Finds `end_header` at the start of a line and the byte after its line break. */
function findHeaderEnd(bytes: Uint8Array): { textEnd: number; dataStart: number } {
  const marker = END_HEADER;
  let from = 0;
  for (;;) {
    const i = indexOfAscii(bytes, marker, from);
    if (i < 0) fail("no 'end_header' line: the header is incomplete");
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

function parseProperty(words: string[], where: string): Property {
  if (words[1] === 'list') {
    const countType = SCALAR_TYPES[words[2]];
    const type = SCALAR_TYPES[words[3]];
    if (words.length !== 5 || !countType || !type) fail(`${where}: expected 'property list <count type> <item type> <name>'`);
    return { name: words[4], type, countType };
  }
  const type = SCALAR_TYPES[words[1]];
  if (words.length !== 3 || !type) fail(`${where}: expected 'property <type> <name>' with a known type`);
  return { name: words[2], type };
}

function findLayout(elements: Element[]): Layout {
  const vertex = elements.find((e) => e.name === 'vertex');
  if (!vertex) fail("no 'vertex' element in header");
  const xyz = (['x', 'y', 'z'] as const).map((axis) => {
    const property = vertex.properties.find((p) => p.name === axis);
    if (!property) fail(`vertex element has no '${axis}' property`);
    if (property.countType) fail(`vertex property '${axis}' is a list`);
    return property;
  }) as [Property, Property, Property];
  const face = elements.find((e) => e.name === 'face');
  if (!face) fail("no 'face' element in header (a point cloud?)");
  const indices = face.properties.find((p) => p.name === 'vertex_indices' || p.name === 'vertex_index');
  if (!indices || !indices.countType) fail("face element has no 'vertex_indices' list property");
  if (vertex.count === 0) fail('no vertices in file');
  if (face.count === 0) fail('no faces in file');
  return { vertex, xyz, face, indices };
}

/**
 * Checks, before anything is allocated, that the data can hold what the header claims: every
 * list counts as empty, so this is a lower bound on the size.
 */
function checkLength(header: Header, available: number): void {
  let needed = 0;
  for (const element of header.elements) {
    const rowBytes = header.encoding === 'ascii'
      ? MIN_ASCII_VALUE_BYTES * element.properties.length
      : element.properties.reduce((sum, p) => sum + (p.countType ?? p.type).size, 0);
    needed += element.count * rowBytes;
    // The last ASCII value needs no separator after it.
    if (needed - (header.encoding === 'ascii' ? 1 : 0) > available) {
      fail(`header claims ${element.count} ${elementNoun(element)} but the file has only ${available} bytes of data`);
    }
  }
}

function elementNoun(element: Element): string {
  if (element.name === 'vertex') return 'vertices';
  if (element.name === 'face') return 'faces';
  return `'${element.name}' elements`;
}

function readBinary(bytes: Uint8Array, header: Header, layout: Layout, builder: MeshBuilder): void {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const le = header.encoding === 'binary_little_endian';
  const vertexCount = layout.vertex.count;
  const poly: number[] = [];
  const xyz = [0, 0, 0];
  let offset = header.dataStart;

  for (const element of header.elements) {
    if (element === layout.vertex && element.properties.every((p) => !p.countType)) {
      // The usual vertex rows have a fixed size: read x, y, z at fixed offsets.
      const rowBytes = element.properties.reduce((sum, p) => sum + p.type.size, 0);
      // checkLength counted lists in earlier elements as empty, so this can still fail here.
      if (offset + element.count * rowBytes > bytes.length) truncated(element, Math.floor((bytes.length - offset) / rowBytes));
      const [x, y, z] = layout.xyz.map((p) => ({ at: offsetInRow(element, p), read: p.type.read }));
      for (let v = 0; v < element.count; v++, offset += rowBytes) {
        builder.addVertex(x.read(view, offset + x.at, le), y.read(view, offset + y.at, le), z.read(view, offset + z.at, le));
      }
      continue;
    }

    const axisOf = element.properties.map((p) => (element === layout.vertex ? layout.xyz.indexOf(p) : -1));
    for (let row = 0; row < element.count; row++) {
      for (let k = 0; k < element.properties.length; k++) {
        const property = element.properties[k];
        const { countType, type } = property;
        if (!countType) {
          if (offset + type.size > bytes.length) truncated(element, row);
          if (axisOf[k] >= 0) xyz[axisOf[k]] = type.read(view, offset, le);
          offset += type.size;
          continue;
        }
        if (offset + countType.size > bytes.length) truncated(element, row);
        const n = countType.read(view, offset, le);
        offset += countType.size;
        if (!Number.isInteger(n) || n < 0) fail(`${element.name} ${row}: bad list length ${n}`);
        if (offset + n * type.size > bytes.length) truncated(element, row);
        if (property === layout.indices) {
          if (n < 3) fail(`face ${row} has ${n} vertices, at least 3 are needed`);
          poly.length = 0;
          for (let i = 0; i < n; i++, offset += type.size) {
            poly.push(checkIndex(type.read(view, offset, le), vertexCount, row));
          }
          builder.addPolygon(poly, n);
        } else {
          offset += n * type.size;
        }
      }
      if (element === layout.vertex) builder.addVertex(xyz[0], xyz[1], xyz[2]);
    }
  }
}

function offsetInRow(element: Element, property: Property): number {
  let at = 0;
  for (const p of element.properties) {
    if (p === property) return at;
    at += p.type.size;
  }
  throw new Error('property not in element');
}

function truncated(element: Element, row: number): never {
  fail(`file is truncated in ${element.name} ${row} of ${element.count}`);
}

function checkIndex(index: number, vertexCount: number, face: number): number {
  if (!Number.isInteger(index)) fail(`face ${face}: vertex index ${index} is not an integer`);
  if (index < 0 || index >= vertexCount) {
    fail(`face ${face}: vertex index ${index} is out of range (the file has ${vertexCount} vertices)`);
  }
  return index;
}

function readAscii(bytes: Uint8Array, header: Header, layout: Layout, builder: MeshBuilder): void {
  const s = new TextScanner(bytes, 'PLY', false, header.dataStart, header.lineCount + 1);
  const vertexCount = layout.vertex.count;
  const poly: number[] = [];
  const xyz = [0, 0, 0];

  for (const element of header.elements) {
    const axisOf = element.properties.map((p) => (element === layout.vertex ? layout.xyz.indexOf(p) : -1));
    for (let row = 0; row < element.count; row++) {
      s.skipWhitespace();
      if (s.atEnd()) fail(`file ends after ${row} of ${element.count} ${elementNoun(element)}`);
      for (let k = 0; k < element.properties.length; k++) {
        const property = element.properties[k];
        s.skipWhitespace();
        if (!property.countType) {
          const value = s.readNumber();
          if (axisOf[k] >= 0) xyz[axisOf[k]] = value;
          continue;
        }
        const n = s.readInt('list length');
        if (n < 0) s.fail(`bad list length ${n}`);
        if (property === layout.indices) {
          if (n < 3) s.fail(`face ${row} has ${n} vertices, at least 3 are needed`);
          poly.length = 0;
          for (let i = 0; i < n; i++) {
            s.skipWhitespace();
            const index = s.readInt('vertex index');
            if (index < 0 || index >= vertexCount) {
              s.fail(`face ${row}: vertex index ${index} is out of range (the file has ${vertexCount} vertices)`);
            }
            poly.push(index);
          }
          builder.addPolygon(poly, n);
        } else {
          for (let i = 0; i < n; i++) {
            s.skipWhitespace();
            s.readNumber();
          }
        }
      }
      if (element === layout.vertex) builder.addVertex(xyz[0], xyz[1], xyz[2]);
    }
  }
}
