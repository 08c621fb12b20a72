/**
 * PLY (ascii, binary_little_endian, binary_big_endian). Reads x, y, z of the `vertex` element
 * and the `vertex_indices` (or `vertex_index`) list of the `face` element; every other element and
 * property is skipped. Polygons are fan-triangulated. The header and data are read by ply-elements.ts.
 */
import { MeshBuilder } from './mesh-builder.ts';
import { findElement, findProperty, parsePlyHeader, readPlyElements, type PlyElement, type PlyErrors, type PlyHeader } from './ply-elements.ts';
import { MeshFormatError, type ParsedMesh } from './types.ts';

/** Where the parts of the mesh are in the header. */
interface Layout {
  vertex: PlyElement;
  face: PlyElement;
  /** The name of the face element's index list. */
  indices: string;
}

const ERRORS: PlyErrors = { fail };

export function parsePly(bytes: Uint8Array): ParsedMesh {
  const header = parsePlyHeader(bytes, ERRORS);
  const { vertex, face, indices } = findLayout(header);
  const vertexCount = vertex.count;
  const data = readPlyElements(bytes, header, {
    vertex: ['x', 'y', 'z'],
    face: [{
      name: indices,
      check: {
        length: (row, n) => (n < 3 ? `face ${row} has ${n} vertices, at least 3 are needed` : undefined),
        item: (row, index) => indexProblem(row, index, vertexCount),
        integers: 'vertex index',
      },
    }],
  }, ERRORS);

  const builder = new MeshBuilder('ply', vertexCount, face.count);
  const { x, y, z } = data.vertex.scalars;
  for (let v = 0; v < vertexCount; v++) builder.addVertex(x[v], y[v], z[v]);
  const { lengths, items } = data.face.lists[indices];
  for (let row = 0, start = 0; row < lengths.length; start += lengths[row++]) builder.addPolygon(items, lengths[row], start);
  return builder.finish();
}

function fail(message: string): never {
  throw new MeshFormatError(`PLY: ${message}`);
}

function findLayout(header: PlyHeader): Layout {
  const vertex = findElement(header, 'vertex');
  if (!vertex) fail("no 'vertex' element in header");
  for (const axis of ['x', 'y', 'z']) {
    const property = findProperty(vertex, axis);
    if (!property) fail(`vertex element has no '${axis}' property`);
    if (property.countType) fail(`vertex property '${axis}' is a list`);
  }
  const face = findElement(header, 'face');
  if (!face) fail("no 'face' element in header (a point cloud?)");
  const indices = face.properties.find((p) => p.name === 'vertex_indices' || p.name === 'vertex_index');
  if (!indices || !indices.countType) fail("face element has no 'vertex_indices' list property");
  if (vertex.count === 0) fail('no vertices in file');
  if (face.count === 0) fail('no faces in file');
  return { vertex, face, indices: indices.name };
}

function indexProblem(face: number, index: number, vertexCount: number): string | undefined {
  if (!Number.isInteger(index)) return `face ${face}: vertex index ${index} is not an integer`;
  if (index < 0 || index >= vertexCount) return `face ${face}: vertex index ${index} is out of range (the file has ${vertexCount} vertices)`;
  return undefined;
}
