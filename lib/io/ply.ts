/**
 * PLY (ascii, binary_little_endian, binary_big_endian). A mesh: x, y, z of the `vertex` element and
 * the `vertex_indices` (or `vertex_index`) list of the `face` element, polygons fan-triangulated. A
 * point cloud: a `vertex` element and no faces (no face element, or one of 0 rows), with nx, ny, nz
 * when the vertices have all three. Every other element and property is skipped. The header and data
 * are read by ply-elements.ts.
 */
import { MeshBuilder } from './mesh-builder.ts';
import { findElement, findProperty, parsePlyHeader, readPlyElements, type PlyElement, type PlyErrors, type PlyHeader } from './ply-elements.ts';
import { MeshFormatError, type ParsedCloud, type ParsedMesh } from './types.ts';

const ERRORS: PlyErrors = { fail };
const POSITION = ['x', 'y', 'z'];
const NORMAL = ['nx', 'ny', 'nz'];

export function parsePly(bytes: Uint8Array): ParsedMesh | ParsedCloud {
  const header = parsePlyHeader(bytes, ERRORS);
  const vertex = findVertex(header);
  const face = findElement(header, 'face');
  if (!face || face.count === 0) return parseCloud(bytes, header, vertex);

  const indicesProperty = face.properties.find((p) => p.name === 'vertex_indices' || p.name === 'vertex_index');
  if (!indicesProperty || !indicesProperty.countType) fail("face element has no 'vertex_indices' list property");
  const indices = indicesProperty.name;
  const vertexCount = vertex.count;
  const data = readPlyElements(bytes, header, {
    vertex: POSITION,
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

/** The vertex element, with scalar x, y, z and at least one row. */
function findVertex(header: PlyHeader): PlyElement {
  const vertex = findElement(header, 'vertex');
  if (!vertex) fail("no 'vertex' element in header");
  for (const axis of POSITION) {
    const property = findProperty(vertex, axis);
    if (!property) fail(`vertex element has no '${axis}' property`);
    if (property.countType) fail(`vertex property '${axis}' is a list`);
  }
  if (vertex.count === 0) fail('no vertices in file');
  return vertex;
}

function parseCloud(bytes: Uint8Array, header: PlyHeader, vertex: PlyElement): ParsedCloud {
  const edge = findElement(header, 'edge');
  // Vertices joined by edges make a graph (a skeleton file), which read as points would lose its edges.
  if (edge && edge.count > 0) fail("no faces in file but an 'edge' element (a skeleton?): neither a mesh nor a point cloud");
  const warnings: string[] = [];
  const normalNames = NORMAL.filter((name) => {
    const property = findProperty(vertex, name);
    return property && !property.countType;
  });
  const hasNormals = normalNames.length === NORMAL.length;
  if (normalNames.length > 0 && !hasNormals) {
    warnings.push(`the vertices have ${normalNames.join(', ')} but not all of nx, ny, nz: read without normals`);
  }
  const { scalars } = readPlyElements(bytes, header, { vertex: hasNormals ? [...POSITION, ...NORMAL] : POSITION }, ERRORS).vertex;
  return {
    kind: 'cloud',
    format: 'ply',
    positions: interleave(POSITION.map((name) => scalars[name]), new Float64Array(3 * vertex.count)),
    normals: hasNormals ? interleave(NORMAL.map((name) => scalars[name]), new Float32Array(3 * vertex.count)) : null,
    warnings,
  };
}

/** Writes the three per-axis arrays into `into` as x y z triples. */
function interleave<T extends Float64Array | Float32Array>(axes: Float64Array[], into: T): T {
  axes.forEach((values, k) => {
    for (let i = 0; i < values.length; i++) into[3 * i + k] = values[i];
  });
  return into;
}

function indexProblem(face: number, index: number, vertexCount: number): string | undefined {
  if (!Number.isInteger(index)) return `face ${face}: vertex index ${index} is not an integer`;
  if (index < 0 || index >= vertexCount) return `face ${face}: vertex index ${index} is out of range (the file has ${vertexCount} vertices)`;
  return undefined;
}
