/**
 * Wavefront OBJ: `v x y z [w] [r g b]` and `f` with `i`, `i/t`, `i//n`, `i/t/n` and negative
 * (relative) indices. Polygons are fan-triangulated; every other statement (vt, vn, g, o, s, l, p,
 * usemtl, mtllib...) is ignored. A file with vertices and no faces (and no `l` lines) is a point
 * cloud, with the `vn` normals when there are as many as vertices (the n-th for the n-th vertex, as
 * point-cloud exporters write them; otherwise which belongs to which is unknown and they are ignored).
 */
import { MeshBuilder } from './mesh-builder.ts';
import { TextScanner, ascii, clip, isBlank } from './scan.ts';
import { MeshFormatError, type ParsedCloud, type ParsedMesh } from './types.ts';

const LF = 0x0a;
const HASH = 0x23;
const SLASH = 0x2f;
const LOWER_V = 0x76;
const LOWER_F = 0x66;
const LOWER_L = 0x6c;
const VN = ascii('vn');

export function parseObj(bytes: Uint8Array): ParsedMesh | ParsedCloud {
  const s = new TextScanner(bytes, 'OBJ', true);
  // A typical OBJ line is 20-40 bytes: start near the final size instead of regrowing many times.
  const builder = new MeshBuilder('obj', bytes.length / 64, bytes.length / 64);
  const poly: number[] = [];
  // Positive indices may refer to vertices defined later in the file, so their range is checked
  // at the end; the line of the largest one is kept for the message.
  let maxIndex = -1;
  let maxIndexLine = 0;
  // Counted only: a point cloud's normals are read in a second pass (see cloud).
  let normalCount = 0;
  let lineCount = 0;

  while (!s.atEnd()) {
    s.skipBlanks();
    const b = s.pos < bytes.length ? bytes[s.pos] : LF;
    const next = s.pos + 1 < bytes.length ? bytes[s.pos + 1] : LF;
    // Only the one-letter statements `v` and `f` matter (not vt, vn, vp, fo...).
    const oneLetter = isBlank(next) || next === LF;
    if (oneLetter && b === LOWER_V) {
      s.pos++;
      builder.addVertex(s.readNumber(), s.readNumber(), s.readNumber());
    } else if (oneLetter && b === LOWER_F) {
      s.pos++;
      poly.length = 0;
      const vertexCount = builder.vertexCount;
      while (!s.atLineEnd()) {
        const index = readIndex(s);
        if (index === 0) s.fail('vertex index 0 is invalid (OBJ indices start at 1)');
        if (index < 0) {
          if (vertexCount + index < 0) s.fail(`relative vertex index ${index} points before the first vertex`);
          poly.push(vertexCount + index);
        } else {
          if (index > maxIndex) {
            maxIndex = index;
            maxIndexLine = s.line;
          }
          poly.push(index - 1);
        }
      }
      if (poly.length < 3) s.fail(`face has ${poly.length} vertices, at least 3 are needed`);
      builder.addPolygon(poly, poly.length);
    } else if (oneLetter && b === LOWER_L) {
      lineCount++;
    } else if (s.tokenIs(VN)) {
      normalCount++;
    }
    s.skipLine();
  }

  if (maxIndex > builder.vertexCount) {
    s.line = maxIndexLine;
    s.fail(`vertex index ${maxIndex} is out of range (the file has ${builder.vertexCount} vertices)`);
  }
  if (builder.triangleCount > 0 || builder.vertexCount === 0) return builder.finish();
  return cloud(bytes, builder.vertices(), normalCount, lineCount);
}

function cloud(bytes: Uint8Array, positions: Float64Array, normalCount: number, lineCount: number): ParsedCloud {
  // Vertices joined by lines make a graph (a skeleton file), which read as points would lose its lines.
  if (lineCount > 0) throw new MeshFormatError('OBJ: no faces in file but lines (a skeleton?): neither a mesh nor a point cloud');
  const pointCount = positions.length / 3;
  const paired = normalCount === pointCount;
  const warnings = normalCount > 0 && !paired
    ? [`ignored the normals (vn): the file has ${normalCount} of them for ${pointCount} vertices, so which belongs to which vertex is not known`]
    : [];
  return { kind: 'cloud', format: 'obj', positions, normals: paired ? readNormals(bytes, pointCount) : null, warnings };
}

/**
 * The `vn` normals in file order. A second pass, made for point clouds only, so that a mesh never
 * depends on its vn lines (which meshes ignore, malformed or not).
 */
function readNormals(bytes: Uint8Array, count: number): Float32Array {
  const s = new TextScanner(bytes, 'OBJ', true);
  const normals = new Float32Array(3 * count);
  for (let i = 0; !s.atEnd(); s.skipLine()) {
    s.skipBlanks();
    if (!s.tokenIs(VN)) continue;
    s.skipToken();
    for (let k = 0; k < 3; k++) normals[i++] = s.readNumber();
  }
  return normals;
}

/** Reads the vertex part of `i`, `i/t`, `i//n` or `i/t/n` and skips the rest of the token. */
function readIndex(s: TextScanner): number {
  const start = s.pos;
  const value = s.readDigits();
  const { bytes, pos } = s;
  const endsWell = pos >= bytes.length || bytes[pos] === SLASH || bytes[pos] === LF || bytes[pos] === HASH || isBlank(bytes[pos]);
  if (Number.isNaN(value) || !endsWell || Math.abs(value) > 0xffffffff) {
    s.pos = start;
    s.fail(`bad vertex index '${clip(s.peekToken())}'`);
  }
  s.skipToken();
  return value;
}
