/**
 * STL, ASCII and binary. STL stores a triangle soup, so corners with exactly equal coordinates
 * are merged into shared vertices to give an indexed mesh.
 */
import { MeshBuilder } from './mesh-builder.ts';
import { TextScanner, ascii, clip } from './scan.ts';
import { MeshFormatError, type ParsedMesh } from './types.ts';

const BINARY_HEADER_BYTES = 84;
const BINARY_TRIANGLE_BYTES = 50;

/**
 * Binary STLs often start with "solid" too, so the size decides: a binary file is exactly
 * 84 + 50 n bytes, n being the triangle count stored at byte 80.
 */
export function isBinaryStl(bytes: Uint8Array): boolean {
  if (bytes.length < BINARY_HEADER_BYTES) return false;
  const n = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(80, true);
  return bytes.length === BINARY_HEADER_BYTES + BINARY_TRIANGLE_BYTES * n;
}

/** Whether the file starts (after blanks) with the ASCII STL keyword. */
export function startsWithSolid(bytes: Uint8Array): boolean {
  let p = 0;
  while (p < bytes.length && (bytes[p] === 0x20 || bytes[p] === 0x09 || bytes[p] === 0x0d || bytes[p] === 0x0a)) p++;
  return latin1Prefix(bytes, p, 5) === 'solid';
}

export function parseStl(bytes: Uint8Array): ParsedMesh {
  if (isBinaryStl(bytes)) return parseBinaryStl(bytes);
  // A NUL byte means a binary file even when its header starts with "solid".
  const solid = startsWithSolid(bytes);
  if (solid && !bytes.subarray(0, 1024).includes(0)) return parseAsciiStl(bytes);
  const notAscii = `not an ASCII STL (${solid ? "binary content after 'solid'" : "no 'solid' keyword"})`;
  if (bytes.length < BINARY_HEADER_BYTES) {
    throw new MeshFormatError(`STL: ${notAscii} and too short (${bytes.length} bytes) for a binary STL`);
  }
  const n = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(80, true);
  throw new MeshFormatError(
    `STL: ${notAscii} and not a binary STL: ${n} triangles need ` +
      `${BINARY_HEADER_BYTES + BINARY_TRIANGLE_BYTES * n} bytes but the file has ${bytes.length}`,
  );
}

function parseBinaryStl(bytes: Uint8Array): ParsedMesh {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const triangleCount = view.getUint32(80, true);
  if (triangleCount === 0) throw new MeshFormatError('STL: no faces in file');
  const corners = new Float64Array(9 * triangleCount);
  for (let t = 0; t < triangleCount; t++) {
    const offset = BINARY_HEADER_BYTES + BINARY_TRIANGLE_BYTES * t + 12; // skip the normal
    for (let i = 0; i < 9; i++) corners[9 * t + i] = view.getFloat32(offset + 4 * i, true);
  }
  return mergeCorners(corners);
}

const SOLID = ascii('solid');
const FACET = ascii('facet');
const OUTER = ascii('outer');
const VERTEX = ascii('vertex');
const ENDLOOP = ascii('endloop');
const ENDFACET = ascii('endfacet');
const ENDSOLID = ascii('endsolid');

function parseAsciiStl(bytes: Uint8Array): ParsedMesh {
  const s = new TextScanner(bytes, 'STL', false);
  // An ASCII facet takes about 250 bytes; the corner array grows if the guess is short.
  let corners = new Float64Array(9 * Math.max(1, Math.ceil(bytes.length / 200)));
  let cornerCount = 0;
  const loop: number[] = [];
  let loopsSplit = 0;

  for (s.skipWhitespace(); !s.atEnd(); s.skipWhitespace()) {
    if (s.tokenIs(VERTEX)) {
      s.skipToken();
      loop.push(s.readNumber(), s.readNumber(), s.readNumber());
      s.skipLine();
    } else if (s.tokenIs(ENDLOOP)) {
      const n = loop.length / 3;
      if (n < 3) s.fail(`facet has ${n} vertices, at least 3 are needed`);
      if (n > 3) loopsSplit++;
      // Fan-triangulate (loops of more than 3 vertices are not standard but cost nothing).
      if (3 * (cornerCount + 3 * (n - 2)) > corners.length) {
        const bigger = new Float64Array(2 * corners.length + 9 * n);
        bigger.set(corners);
        corners = bigger;
      }
      for (let i = 1; i + 1 < n; i++) {
        for (let j = 0; j < 3; j++) {
          const k = j === 0 ? 0 : i + j - 1;
          corners[3 * cornerCount] = loop[3 * k];
          corners[3 * cornerCount + 1] = loop[3 * k + 1];
          corners[3 * cornerCount + 2] = loop[3 * k + 2];
          cornerCount++;
        }
      }
      loop.length = 0;
      s.skipLine();
    } else if (s.tokenIs(SOLID) || s.tokenIs(FACET) || s.tokenIs(OUTER) || s.tokenIs(ENDFACET) || s.tokenIs(ENDSOLID)) {
      s.skipLine(); // names and facet normals are not needed
    } else {
      s.fail(`unexpected '${clip(s.peekToken())}' (expected facet, vertex, endloop...)`);
    }
  }
  if (cornerCount === 0) throw new MeshFormatError('STL: no faces in file');
  const mesh = mergeCorners(corners.subarray(0, 3 * cornerCount));
  if (loopsSplit > 0) mesh.warnings.push(`split ${loopsSplit} facets with more than 3 vertices into triangles`);
  return mesh;
}

/**
 * Builds an indexed mesh from triangle corners (x y z per corner, three corners per triangle),
 * merging corners whose coordinates are exactly equal. Hashes the float64 bit patterns in an
 * open-addressing table: no per-vertex objects or strings.
 */
function mergeCorners(corners: Float64Array): ParsedMesh {
  const cornerCount = corners.length / 3;
  // -0 and +0 are the same coordinate but not the same bits.
  for (let i = 0; i < corners.length; i++) if (corners[i] === 0) corners[i] = 0;
  const cornerBits = new Uint32Array(corners.buffer, corners.byteOffset, 2 * corners.length);

  let tableSize = 1;
  while (tableSize < 2 * cornerCount) tableSize *= 2;
  const mask = tableSize - 1;
  const table = new Int32Array(tableSize).fill(-1); // corner index of each distinct vertex
  const builder = new MeshBuilder('stl', cornerCount / 2, cornerCount / 3);
  const vertexOf = new Uint32Array(cornerCount);

  for (let c = 0; c < cornerCount; c++) {
    const w = 6 * c;
    let h = 0x811c9dc5;
    for (let i = 0; i < 6; i++) h = Math.imul(h ^ cornerBits[w + i], 0x01000193);
    h ^= h >>> 15;
    let slot = h & mask;
    for (;;) {
      const other = table[slot];
      if (other < 0) {
        table[slot] = c;
        vertexOf[c] = builder.vertexCount;
        builder.addVertex(corners[3 * c], corners[3 * c + 1], corners[3 * c + 2]);
        break;
      }
      if (sameBits(cornerBits, 6 * other, w)) {
        vertexOf[c] = vertexOf[other];
        break;
      }
      slot = (slot + 1) & mask;
    }
  }
  for (let c = 0; c < cornerCount; c += 3) builder.addTriangle(vertexOf[c], vertexOf[c + 1], vertexOf[c + 2]);

  const mesh = builder.finish();
  if (builder.vertexCount === cornerCount && cornerCount > 3) {
    mesh.warnings.push('no two triangles share a vertex (the mesh is a triangle soup)');
  }
  return mesh;
}

function sameBits(bits: Uint32Array, a: number, b: number): boolean {
  for (let i = 0; i < 6; i++) if (bits[a + i] !== bits[b + i]) return false;
  return true;
}

function latin1Prefix(bytes: Uint8Array, start: number, length: number): string {
  return String.fromCharCode(...bytes.subarray(start, start + length));
}
