/**
 * Binary glTF 2.0 (GLB): the container, its JSON chunk and BIN chunk, every triangle primitive of
 * every mesh instanced by the scene's nodes, with node transforms applied, merged into one indexed
 * mesh. Only what a surface needs is read (POSITION and indices); materials, normals, UVs, skins and
 * animations are ignored. No DOM, no three.js: shared by the CLI and the worker.
 */
import { MeshBuilder } from './mesh-builder.ts';
import { MeshFormatError, type ParsedMesh } from './types.ts';

const MAGIC = 0x46546c67; // 'glTF'
const CHUNK_JSON = 0x4e4f534a;
const CHUNK_BIN = 0x004e4942;
const HEADER_BYTES = 12;
const CHUNK_HEADER_BYTES = 8;

const FLOAT = 5126;
const INDEX_TYPES: Record<number, { size: number; name: string }> = {
  5121: { size: 1, name: 'unsigned byte' },
  5123: { size: 2, name: 'unsigned short' },
  5125: { size: 4, name: 'unsigned int' },
};
const TRIANGLES = 4;
const MODE_NAMES = ['points', 'lines', 'line loop', 'line strip', 'triangles', 'triangle strip', 'triangle fan'];

interface Accessor {
  bufferView?: number;
  byteOffset?: number;
  componentType: number;
  count: number;
  type: string;
  normalized?: boolean;
  sparse?: unknown;
}
interface BufferView {
  buffer: number;
  byteOffset?: number;
  byteLength: number;
  byteStride?: number;
}
interface Primitive {
  attributes?: Record<string, number>;
  indices?: number;
  mode?: number;
}
interface GltfNode {
  mesh?: number;
  children?: number[];
  matrix?: number[];
  translation?: number[];
  rotation?: number[];
  scale?: number[];
}
interface Gltf {
  asset?: { version?: string };
  buffers?: Array<{ byteLength: number; uri?: string }>;
  bufferViews?: BufferView[];
  accessors?: Accessor[];
  meshes?: Array<{ primitives?: Primitive[] }>;
  nodes?: GltfNode[];
  scenes?: Array<{ nodes?: number[] }>;
  scene?: number;
}

/** Column-major 4x4, as glTF stores matrices. */
type Mat4 = Float64Array;

const fail = (message: string): never => {
  throw new MeshFormatError(`GLB: ${message}`);
};

export function parseGlb(bytes: Uint8Array): ParsedMesh {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (bytes.length < HEADER_BYTES) fail(`file too short for a GLB header (${bytes.length} bytes)`);
  if (view.getUint32(0, true) !== MAGIC) fail("bad magic: the file does not start with 'glTF'");
  const version = view.getUint32(4, true);
  if (version !== 2) fail(`version ${version} is not supported (only glTF 2.0)`);
  const length = view.getUint32(8, true);
  if (length > bytes.length) fail(`the header says ${length} bytes but the file has ${bytes.length} (truncated?)`);

  // Chunks: JSON first, then an optional BIN chunk; others are skipped, as the spec asks.
  let json: Gltf | null = null;
  let bin: Uint8Array | null = null;
  for (let at = HEADER_BYTES, index = 0; at < length; index++) {
    if (at + CHUNK_HEADER_BYTES > length) fail(`chunk ${index} header is cut off at byte ${at}`);
    const chunkLength = view.getUint32(at, true);
    const type = view.getUint32(at + 4, true);
    const start = at + CHUNK_HEADER_BYTES;
    if (start + chunkLength > length) {
      fail(`chunk ${index} is truncated: it needs ${chunkLength} bytes from byte ${start} but the file ends at ${length}`);
    }
    const data = bytes.subarray(start, start + chunkLength);
    if (index === 0) {
      if (type !== CHUNK_JSON) fail('the first chunk is not the JSON chunk');
      json = parseJson(data);
    } else if (type === CHUNK_BIN && !bin) {
      bin = data;
    }
    at = start + chunkLength;
  }
  if (!json) fail('no JSON chunk');
  return buildMesh(json!, bin);
}

function parseJson(data: Uint8Array): Gltf {
  let value: unknown;
  try {
    value = JSON.parse(new TextDecoder().decode(data));
  } catch (error) {
    fail(`the JSON chunk is not valid JSON (${error instanceof Error ? error.message : String(error)})`);
  }
  if (!value || typeof value !== 'object' || Array.isArray(value)) fail('the JSON chunk is not an object');
  return value as Gltf;
}

function buildMesh(gltf: Gltf, bin: Uint8Array | null): ParsedMesh {
  const warnings: string[] = [];
  const builder = new MeshBuilder('glb');
  const buffers = (gltf.buffers ?? []).map((buffer, i) => loadBuffer(buffer, i, bin));
  const skipped = new Map<string, number>();

  const addPrimitive = (p: Primitive, where: string, matrix: Mat4) => {
    const mode = p.mode ?? TRIANGLES;
    if (mode !== TRIANGLES) {
      const name = MODE_NAMES[mode] ?? `mode ${mode}`;
      skipped.set(name, (skipped.get(name) ?? 0) + 1);
      return;
    }
    const positionIndex = p.attributes?.POSITION;
    if (positionIndex === undefined) fail(`${where} has no POSITION attribute`);
    const positions = readPositions(gltf, buffers, positionIndex!, where);
    const count = positions.length / 3;
    const base = builder.vertexCount;
    for (let v = 0; v < count; v++) {
      const x = positions[3 * v], y = positions[3 * v + 1], z = positions[3 * v + 2];
      builder.addVertex(
        matrix[0] * x + matrix[4] * y + matrix[8] * z + matrix[12],
        matrix[1] * x + matrix[5] * y + matrix[9] * z + matrix[13],
        matrix[2] * x + matrix[6] * y + matrix[10] * z + matrix[14],
      );
    }
    const indices = p.indices === undefined ? null : readIndices(gltf, buffers, p.indices, where);
    const n = indices ? indices.length : count;
    if (n % 3 !== 0) fail(`${where} has ${n} ${indices ? 'indices' : 'vertices'}, not a multiple of 3`);
    // A mirroring transform turns the faces inside out: swap two corners to keep them facing out.
    const mirrored = determinant3(matrix) < 0;
    for (let t = 0; t < n; t += 3) {
      let a = t, b = t + 1, c = t + 2;
      if (indices) {
        a = indices[a];
        b = indices[b];
        c = indices[c];
        const bad = a >= count ? a : b >= count ? b : c >= count ? c : -1;
        if (bad >= 0) fail(`${where}: index ${bad} is out of range (the primitive has ${count} vertices)`);
      }
      if (mirrored) builder.addTriangle(base + a, base + c, base + b);
      else builder.addTriangle(base + a, base + b, base + c);
    }
  };

  const meshes = gltf.meshes ?? [];
  const addMesh = (meshIndex: number, matrix: Mat4) => {
    const mesh = meshes[meshIndex] ?? fail(`node refers to mesh ${meshIndex}, which does not exist`);
    (mesh.primitives ?? []).forEach((p, i) => addPrimitive(p, `mesh ${meshIndex} primitive ${i}`, matrix));
  };

  const nodes = gltf.nodes ?? [];
  const roots = sceneRoots(gltf);
  if (roots) {
    const onPath = new Set<number>();
    const visit = (index: number, parent: Mat4) => {
      const node = nodes[index] ?? fail(`node ${index} does not exist`);
      if (onPath.has(index)) fail(`node ${index} is its own ancestor (the node graph has a cycle)`);
      onPath.add(index);
      const matrix = multiply(parent, localMatrix(node, index));
      if (node.mesh !== undefined) addMesh(node.mesh, matrix);
      for (const child of node.children ?? []) visit(child, matrix);
      onPath.delete(index);
    };
    for (const root of roots) visit(root, identity());
  } else if (meshes.length > 0) {
    // No scene to place them: every mesh once, untransformed (what most viewers do).
    warnings.push('the file has no scene or nodes; every mesh was read once, untransformed');
    meshes.forEach((_, i) => addMesh(i, identity()));
  }

  for (const [name, n] of skipped) warnings.push(`skipped ${n} ${name} primitive${n > 1 ? 's' : ''} (only triangles are read)`);
  if (builder.vertexCount === 0) fail(skipped.size > 0 ? 'no triangle primitives (only points or lines)' : 'no meshes in the scene');
  return builder.finish(warnings);
}

/** Root nodes of the default scene (or of all nodes nobody parents); null when there are no nodes. */
function sceneRoots(gltf: Gltf): number[] | null {
  const nodes = gltf.nodes ?? [];
  if (gltf.scenes && gltf.scenes.length > 0) {
    const scene = gltf.scenes[gltf.scene ?? 0] ?? fail(`the default scene ${gltf.scene} does not exist`);
    return scene.nodes ?? [];
  }
  if (nodes.length === 0) return null;
  const children = new Set(nodes.flatMap((node) => node.children ?? []));
  return nodes.map((_, i) => i).filter((i) => !children.has(i));
}

function loadBuffer(buffer: { byteLength: number; uri?: string }, index: number, bin: Uint8Array | null): Uint8Array {
  if (buffer.uri === undefined) {
    if (index !== 0 || !bin) fail(`buffer ${index} has no uri and the file has no BIN chunk for it`);
    if (bin!.length < buffer.byteLength) fail(`the BIN chunk has ${bin!.length} bytes, buffer 0 needs ${buffer.byteLength}`);
    return bin!;
  }
  const data = /^data:[^,]*;base64,(.*)$/s.exec(buffer.uri);
  if (!data) fail(`buffer ${index} refers to an external file ('${buffer.uri.slice(0, 60)}'); only self-contained GLB files can be read`);
  let raw: string;
  try {
    raw = atob(data![1]);
  } catch {
    fail(`buffer ${index} has a malformed base64 data URI`);
  }
  const out = new Uint8Array(raw!.length);
  for (let i = 0; i < raw!.length; i++) out[i] = raw!.charCodeAt(i);
  return out;
}

/** The bytes an accessor covers: its view, offsets and stride checked against the buffer. */
function accessorData(
  gltf: Gltf,
  buffers: Uint8Array[],
  index: number,
  where: string,
  elementBytes: number,
): { data: DataView; stride: number; count: number } {
  const accessor = gltf.accessors?.[index] ?? fail(`${where} refers to accessor ${index}, which does not exist`);
  if (accessor.sparse) fail(`${where}: sparse accessors are not supported`);
  if (accessor.bufferView === undefined) fail(`${where}: accessor ${index} has no buffer view`);
  const bufferView = gltf.bufferViews?.[accessor.bufferView!] ?? fail(`${where}: buffer view ${accessor.bufferView} does not exist`);
  const buffer = buffers[bufferView.buffer] ?? fail(`${where}: buffer ${bufferView.buffer} does not exist`);
  const stride = bufferView.byteStride ?? elementBytes;
  if (stride < elementBytes) fail(`${where}: byte stride ${stride} is smaller than an element (${elementBytes} bytes)`);
  const viewStart = bufferView.byteOffset ?? 0;
  if (viewStart + bufferView.byteLength > buffer.length) fail(`${where}: buffer view ${accessor.bufferView} runs past the end of its buffer`);
  const start = accessor.byteOffset ?? 0;
  const count = accessor.count;
  if (!Number.isInteger(count) || count < 0) fail(`${where}: accessor ${index} has a bad count`);
  const needed = count === 0 ? 0 : start + (count - 1) * stride + elementBytes;
  if (needed > bufferView.byteLength) fail(`${where}: accessor ${index} needs ${needed} bytes, its buffer view has ${bufferView.byteLength}`);
  const data = new DataView(buffer.buffer, buffer.byteOffset + viewStart + start, Math.max(0, needed - start));
  return { data, stride, count };
}

function readPositions(gltf: Gltf, buffers: Uint8Array[], index: number, where: string): Float64Array {
  const accessor = gltf.accessors?.[index];
  if (accessor && (accessor.type !== 'VEC3' || accessor.componentType !== FLOAT)) {
    fail(`${where}: POSITION must be float VEC3 (got componentType ${accessor.componentType} ${accessor.type}; quantized meshes are not supported)`);
  }
  const { data, stride, count } = accessorData(gltf, buffers, index, `${where} POSITION`, 12);
  const out = new Float64Array(3 * count);
  for (let v = 0; v < count; v++) {
    for (let k = 0; k < 3; k++) {
      const x = data.getFloat32(v * stride + 4 * k, true);
      if (!Number.isFinite(x)) fail(`${where}: vertex ${v} has a non-finite coordinate`);
      out[3 * v + k] = x;
    }
  }
  return out;
}

function readIndices(gltf: Gltf, buffers: Uint8Array[], index: number, where: string): Uint32Array {
  const accessor = gltf.accessors?.[index];
  const type = accessor ? INDEX_TYPES[accessor.componentType] : undefined;
  if (accessor && (!type || accessor.type !== 'SCALAR')) {
    fail(`${where}: indices must be unsigned byte, short or int SCALAR (got componentType ${accessor.componentType} ${accessor.type})`);
  }
  const size = type?.size ?? 4;
  // Index views are tightly packed (the spec forbids a byteStride on them).
  const { data, count } = accessorData(gltf, buffers, index, `${where} indices`, size);
  const out = new Uint32Array(count);
  for (let i = 0; i < count; i++) {
    out[i] = size === 1 ? data.getUint8(i) : size === 2 ? data.getUint16(2 * i, true) : data.getUint32(4 * i, true);
  }
  return out;
}

// -- transforms ----------------------------------------------------------------------------------

function identity(): Mat4 {
  return Float64Array.of(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
}

function multiply(a: Mat4, b: Mat4): Mat4 {
  const out = new Float64Array(16);
  for (let col = 0; col < 4; col++) {
    for (let row = 0; row < 4; row++) {
      let sum = 0;
      for (let k = 0; k < 4; k++) sum += a[4 * k + row] * b[4 * col + k];
      out[4 * col + row] = sum;
    }
  }
  return out;
}

/** A node's own transform: its matrix, or translation * rotation * scale. */
function localMatrix(node: GltfNode, index: number): Mat4 {
  const numbers = (value: unknown, length: number, name: string): number[] | undefined => {
    if (value === undefined) return undefined;
    if (!Array.isArray(value) || value.length !== length || !value.every((x) => typeof x === 'number' && Number.isFinite(x))) {
      fail(`node ${index}: ${name} must be ${length} finite numbers`);
    }
    return value as number[];
  };
  const matrix = numbers(node.matrix, 16, 'matrix');
  if (matrix) return Float64Array.from(matrix);
  const [tx, ty, tz] = numbers(node.translation, 3, 'translation') ?? [0, 0, 0];
  const [qx, qy, qz, qw] = numbers(node.rotation, 4, 'rotation') ?? [0, 0, 0, 1];
  const [sx, sy, sz] = numbers(node.scale, 3, 'scale') ?? [1, 1, 1];
  const x2 = qx + qx, y2 = qy + qy, z2 = qz + qz;
  const xx = qx * x2, xy = qx * y2, xz = qx * z2, yy = qy * y2, yz = qy * z2, zz = qz * z2;
  const wx = qw * x2, wy = qw * y2, wz = qw * z2;
  return Float64Array.of(
    (1 - (yy + zz)) * sx, (xy + wz) * sx, (xz - wy) * sx, 0,
    (xy - wz) * sy, (1 - (xx + zz)) * sy, (yz + wx) * sy, 0,
    (xz + wy) * sz, (yz - wx) * sz, (1 - (xx + yy)) * sz, 0,
    tx, ty, tz, 1,
  );
}

function determinant3(m: Mat4): number {
  return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) + m[8] * (m[1] * m[6] - m[5] * m[2]);
}
