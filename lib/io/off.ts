/**
 * Geomview OFF and its variants (COFF, NOFF, CNOFF, STOFF...): header keyword, `nv nf [ne]`
 * (possibly on the keyword's line), one vertex per line (values after x y z such as colours,
 * normals and texture coordinates are ignored), then `n i1 ... in [colour]` per face.
 */
import { MeshBuilder } from './mesh-builder.ts';
import { TextScanner, clip } from './scan.ts';
import { MeshFormatError, type ParsedMesh } from './types.ts';

const HEADER = /^(ST)?C?N?(4)?(n)?OFF$/;
/** Fewest bytes a vertex line ("0 0 0\n") and a triangle line ("3 0 1 2\n") can take. */
const MIN_VERTEX_BYTES = 6;
const MIN_FACE_BYTES = 8;

export function parseOff(bytes: Uint8Array): ParsedMesh {
  const s = new TextScanner(bytes, 'OFF', true);
  s.skipWhitespace();
  const keyword = s.peekToken();
  const header = HEADER.exec(keyword);
  if (header) {
    if (header[2] || header[3]) throw new MeshFormatError(`OFF: ${keyword} files (not 3D) are not supported`);
    s.skipToken();
    if (!s.atLineEnd() && s.peekToken() === 'BINARY') throw new MeshFormatError('OFF: binary OFF files are not supported');
  } else if (!/^\d/.test(keyword)) {
    // The keyword is optional, but then the file must start with the counts.
    s.fail(`expected the OFF header, found '${clip(keyword)}'`);
  }

  s.skipWhitespace();
  const vertexCount = s.readInt('vertex count');
  const faceCount = s.readInt('face count');
  if (vertexCount < 0 || faceCount < 0) s.fail('negative vertex or face count');
  s.skipLine(); // the edge count, which nobody uses
  const available = bytes.length - s.pos;
  if (vertexCount * MIN_VERTEX_BYTES + faceCount * MIN_FACE_BYTES - 1 > available) {
    throw new MeshFormatError(
      `OFF: header claims ${vertexCount} vertices and ${faceCount} faces but the file has only ${available} bytes of data`,
    );
  }

  const builder = new MeshBuilder('off', vertexCount, faceCount);
  for (let v = 0; v < vertexCount; v++) {
    s.skipWhitespace();
    if (s.atEnd()) throw new MeshFormatError(`OFF: file ends after ${v} of ${vertexCount} vertices`);
    builder.addVertex(s.readNumber(), s.readNumber(), s.readNumber());
    s.skipLine();
  }

  const poly: number[] = [];
  for (let f = 0; f < faceCount; f++) {
    s.skipWhitespace();
    if (s.atEnd()) throw new MeshFormatError(`OFF: file ends after ${f} of ${faceCount} faces`);
    const n = s.readInt('polygon size');
    if (n < 3) s.fail(`face ${f} has ${n} vertices, at least 3 are needed`);
    poly.length = 0;
    for (let i = 0; i < n; i++) {
      const index = s.readInt('vertex index');
      if (index < 0 || index >= vertexCount) {
        s.fail(`vertex index ${index} is out of range (the file has ${vertexCount} vertices)`);
      }
      poly.push(index);
    }
    builder.addPolygon(poly, n);
    s.skipLine();
  }
  return builder.finish();
}
