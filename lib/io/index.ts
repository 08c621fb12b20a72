/**
 * Mesh and point-cloud file reading shared by the CLI (Node) and the page's worker (browser): plain
 * bytes in, typed arrays out, no Node APIs.
 */
import { parseGlb } from './glb.ts';
import { FORMAT_LABEL } from './mesh-builder.ts';
import { parseObj } from './obj.ts';
import { parseOff } from './off.ts';
import { parsePly } from './ply.ts';
import { latin1 } from './scan.ts';
import { isBinaryStl, parseStl, startsWithSolid } from './stl.ts';
import { MeshFormatError, type MeshFormat, type ParsedMesh, type ParsedShape, type ShapeFormat } from './types.ts';
import { looksLikeXyz, parseXyz } from './xyz.ts';

export * from './types.ts';

/** File name extensions of the mesh formats, e.g. for a file picker's `accept`. */
export const MESH_EXTENSIONS: readonly string[] = ['.obj', '.ply', '.stl', '.off', '.glb'];

/** File name extensions of point clouds: PLY and OBJ files without faces, and text point lists. */
export const CLOUD_EXTENSIONS: readonly string[] = ['.ply', '.obj', '.xyz', '.pts', '.txt', '.csv'];

/** Every extension parseShape knows, once each. */
export const SHAPE_EXTENSIONS: readonly string[] = [...new Set([...MESH_EXTENSIONS, ...CLOUD_EXTENSIONS])];

const PARSERS: Record<ShapeFormat, (bytes: Uint8Array) => ParsedShape> = {
  obj: parseObj,
  ply: parsePly,
  stl: parseStl,
  off: parseOff,
  glb: parseGlb,
  xyz: parseXyz,
};

/** Formats of text files, which have no magic bytes: binary content means a wrong file. */
const TEXT_FORMATS: readonly ShapeFormat[] = ['obj', 'off', 'xyz'];

/** The format a file name's extension stands for (case-insensitive), or null. */
export function formatFromName(name: string): ShapeFormat | null {
  const ext = /\.([^./\\]+)$/.exec(name)?.[1].toLowerCase();
  if (!ext || !SHAPE_EXTENSIONS.includes(`.${ext}`)) return null;
  // .pts, .txt and .csv are point lists like .xyz.
  return ext in PARSERS ? (ext as ShapeFormat) : 'xyz';
}

/** Parses a mesh file as parseShape does, and refuses a point cloud with a message that says so. */
export function parseMesh(bytes: Uint8Array, fileName: string): ParsedMesh {
  const shape = parseShape(bytes, fileName);
  if (shape.kind === 'cloud') {
    const points = shape.positions.length / 3;
    throw new MeshFormatError(`${FORMAT_LABEL[shape.format]}: the file is a point cloud (${points} ${points === 1 ? 'point' : 'points'}, no faces), not a mesh`);
  }
  return shape;
}

/**
 * Parses a mesh or point-cloud file. The extension chooses the format unless the content clearly
 * belongs to another one (then that one is read, with a warning); a file of unknown extension is read
 * as what its content looks like. Throws MeshFormatError with a one-line message starting with the
 * format name.
 */
export function parseShape(bytes: Uint8Array, fileName: string): ParsedShape {
  const named = formatFromName(fileName);
  if (bytes.length === 0) throw new MeshFormatError(`${named ? FORMAT_LABEL[named] : fileName}: file is empty`);
  // Windows editors start UTF-8 text with a byte order mark, which no format expects (a binary STL's
  // free-form header may begin with the same bytes: its exact size tells it apart).
  if (bytes[0] === 0xef && bytes[1] === 0xbb && bytes[2] === 0xbf && !isBinaryStl(bytes)) bytes = bytes.subarray(3);
  // A point list has no magic, and a headerless OFF file also starts with rows of numbers: content
  // alone calls a file XYZ only when its extension says nothing.
  const sniffed = sniffFormat(bytes) ?? (named === null && looksLikePointList(bytes) ? 'xyz' : null);
  let format: ShapeFormat;
  let warning: string | null = null;
  if (named && (sniffed === named || sniffed === null)) {
    if (sniffed === null && TEXT_FORMATS.includes(named) && looksBinary(bytes)) {
      throw new MeshFormatError(`${FORMAT_LABEL[named]}: the file is binary, not a text ${FORMAT_LABEL[named]} file`);
    }
    format = named;
  } else if (sniffed) {
    format = sniffed;
    warning = named
      ? `the file is named like ${FORMAT_LABEL[named]} but contains ${FORMAT_LABEL[sniffed]}; read it as ${FORMAT_LABEL[sniffed]}`
      : `unknown file extension; read the file as ${FORMAT_LABEL[sniffed]}, which its content looks like`;
  } else {
    throw new MeshFormatError(
      `unknown format: '${fileName}' has no ${SHAPE_EXTENSIONS.join(', ')} extension and its content is not recognised as a mesh or a point cloud`,
    );
  }
  const shape = PARSERS[format](bytes);
  if (warning) shape.warnings.unshift(warning);
  return shape;
}

const OFF_HEADER = /^(ST)?C?N?4?n?OFF(\s|$)/;
const OBJ_STATEMENT = /^(v|vt|vn|f|o|g|s|l|usemtl|mtllib)\s/m;
const SNIFF_BYTES = 4096;

/** The format the content itself shows (magic line, keyword or exact binary STL size), or null. */
function sniffFormat(bytes: Uint8Array): MeshFormat | null {
  const head = latin1(bytes, 0, Math.min(bytes.length, SNIFF_BYTES));
  if (head.startsWith('glTF')) return 'glb';
  if (/^ply\r?\n/.test(head)) return 'ply';
  if (OFF_HEADER.test(head.replace(/^(\s*#[^\n]*\n)*\s*/, ''))) return 'off';
  if (isBinaryStl(bytes) || startsWithSolid(bytes)) return 'stl';
  if (!looksBinary(bytes) && OBJ_STATEMENT.test(head)) return 'obj';
  return null;
}

function looksLikePointList(bytes: Uint8Array): boolean {
  return !looksBinary(bytes) && looksLikeXyz(bytes.subarray(0, SNIFF_BYTES), bytes.length <= SNIFF_BYTES);
}

/** Text mesh files have no NUL bytes and hardly any other control characters. */
function looksBinary(bytes: Uint8Array): boolean {
  const n = Math.min(bytes.length, SNIFF_BYTES);
  let control = 0;
  for (let i = 0; i < n; i++) {
    const b = bytes[i];
    if (b === 0) return true;
    if (b < 0x20 && b !== 0x09 && b !== 0x0a && b !== 0x0d && b !== 0x0c && b !== 0x0b && b !== 0x1b) control++;
  }
  return control > n / 100;
}
