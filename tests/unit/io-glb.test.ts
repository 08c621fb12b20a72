// GLB (binary glTF 2.0): files built here by a small writer, so every feature the parser reads
// (strides, offsets, index types, node transforms, several primitives) and every way a file can be
// malformed is covered without fixtures.
import { describe, expect, it } from 'vitest';
import { MeshFormatError, parseMesh } from '../../lib/io/index.ts';

interface PrimitiveSpec {
  positions: number[];
  indices?: number[];
  indexType?: 5121 | 5123 | 5125;
  /** Bytes between vertices (default 12: packed); extra bytes are filled with garbage. */
  stride?: number;
  /** Bytes before the first vertex inside its buffer view (accessor byteOffset). */
  offset?: number;
  mode?: number;
}

/** A GLB file: one BIN chunk holding every primitive's data, and `gltf` JSON merged over the generated one. */
function writeGlb(primitives: PrimitiveSpec[][], gltf: Record<string, unknown> = {}): Uint8Array {
  const bin: number[] = [];
  const bufferViews: object[] = [];
  const accessors: object[] = [];
  const align = () => {
    while (bin.length % 4) bin.push(0);
  };
  const push = (bytes: Uint8Array) => bin.push(...bytes);
  const meshes = primitives.map((prims) => ({
    primitives: prims.map((p) => {
      const stride = p.stride ?? 12;
      const offset = p.offset ?? 0;
      const count = p.positions.length / 3;
      align();
      const viewStart = bin.length;
      const data = new DataView(new ArrayBuffer(offset + stride * count));
      for (let i = 0; i < data.byteLength; i++) data.setUint8(i, 0xcd);
      for (let v = 0; v < count; v++) for (let k = 0; k < 3; k++) data.setFloat32(offset + v * stride + 4 * k, p.positions[3 * v + k], true);
      push(new Uint8Array(data.buffer));
      bufferViews.push({ buffer: 0, byteOffset: viewStart, byteLength: data.byteLength, ...(p.stride ? { byteStride: stride } : {}) });
      accessors.push({ bufferView: bufferViews.length - 1, byteOffset: offset, componentType: 5126, count, type: 'VEC3' });
      const primitive: Record<string, unknown> = { attributes: { POSITION: accessors.length - 1 } };
      if (p.mode !== undefined) primitive.mode = p.mode;
      if (p.indices) {
        const type = p.indexType ?? 5125;
        const size = type === 5121 ? 1 : type === 5123 ? 2 : 4;
        align();
        const start = bin.length;
        const idx = new DataView(new ArrayBuffer(size * p.indices.length));
        p.indices.forEach((x, i) => (size === 1 ? idx.setUint8(i, x) : size === 2 ? idx.setUint16(2 * i, x, true) : idx.setUint32(4 * i, x, true)));
        push(new Uint8Array(idx.buffer));
        bufferViews.push({ buffer: 0, byteOffset: start, byteLength: idx.byteLength });
        accessors.push({ bufferView: bufferViews.length - 1, componentType: type, count: p.indices.length, type: 'SCALAR' });
        primitive.indices = accessors.length - 1;
      }
      return primitive;
    }),
  }));
  align();
  const json = {
    asset: { version: '2.0' },
    buffers: [{ byteLength: bin.length }],
    bufferViews,
    accessors,
    meshes,
    nodes: meshes.map((_, i) => ({ mesh: i })),
    scenes: [{ nodes: meshes.map((_, i) => i) }],
    scene: 0,
    ...gltf,
  };
  return container(JSON.stringify(json), new Uint8Array(bin));
}

function container(json: string, bin: Uint8Array | null): Uint8Array {
  const text = new TextEncoder().encode(json);
  const jsonLength = Math.ceil(text.length / 4) * 4;
  const binLength = bin ? Math.ceil(bin.length / 4) * 4 : 0;
  const total = 12 + 8 + jsonLength + (bin ? 8 + binLength : 0);
  const out = new Uint8Array(total);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true);
  out.fill(0x20, 20, 20 + jsonLength); // JSON padding is spaces
  out.set(text, 20);
  if (bin) {
    const at = 20 + jsonLength;
    view.setUint32(at, binLength, true);
    view.setUint32(at + 4, 0x004e4942, true);
    out.set(bin, at + 8);
  }
  return out;
}

/** A unit tetrahedron, outward-facing. */
const TET = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], indices: [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3] };

const rows = (a: ArrayLike<number>, n = 3) => Array.from({ length: a.length / n }, (_, i) => Array.from(a).slice(n * i, n * i + n));

function signedVolume(mesh: { positions: Float64Array; triangles: Uint32Array }): number {
  let v = 0;
  const p = (i: number) => [mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]];
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    const [a, b, c] = [p(mesh.triangles[t]), p(mesh.triangles[t + 1]), p(mesh.triangles[t + 2])];
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  return v;
}

const expectFormatError = (bytes: Uint8Array, message: RegExp) => {
  expect(() => parseMesh(bytes, 'model.glb')).toThrow(MeshFormatError);
  expect(() => parseMesh(bytes, 'model.glb')).toThrow(message);
};

describe('GLB', () => {
  it('reads an indexed primitive with every index type', () => {
    for (const indexType of [5121, 5123, 5125] as const) {
      const mesh = parseMesh(writeGlb([[{ ...TET, indexType }]]), 'tet.glb');
      expect(mesh.format).toBe('glb');
      expect(Array.from(mesh.positions)).toEqual(TET.positions);
      expect(Array.from(mesh.triangles)).toEqual(TET.indices);
      expect(mesh.warnings).toEqual([]);
      expect(signedVolume(mesh)).toBeCloseTo(1 / 6);
    }
  });

  it('reads interleaved positions (byteStride, byteOffset) and non-indexed primitives', () => {
    const soup = TET.indices.flatMap((v) => TET.positions.slice(3 * v, 3 * v + 3));
    const mesh = parseMesh(writeGlb([[{ positions: soup, stride: 32, offset: 8 }]]), 'soup.glb');
    expect(mesh.positions.length).toBe(soup.length);
    expect(Array.from(mesh.positions)).toEqual(soup);
    expect(Array.from(mesh.triangles)).toEqual(soup.map((_, i) => i).filter((i) => i < soup.length / 3));
    expect(signedVolume(mesh)).toBeCloseTo(1 / 6);
  });

  it('merges several meshes and primitives and skips non-triangle ones with a warning', () => {
    const line = { positions: [0, 0, 0, 1, 1, 1], mode: 1 };
    const mesh = parseMesh(writeGlb([[TET, line], [{ ...TET, mode: 4 }]]), 'two.glb');
    expect(mesh.positions.length).toBe(2 * 12);
    expect(rows(mesh.triangles).slice(4)).toEqual(rows(TET.indices).map((t) => t.map((v) => v + 4)));
    expect(mesh.warnings).toEqual(['skipped 1 lines primitive (only triangles are read)']);
  });

  it('applies node transforms through the scene graph (matrix, TRS, nesting) and keeps mirrored meshes outward', () => {
    const nodes = [
      { translation: [10, 0, 0], children: [1] },
      // 90° about z, then scale 2: x -> 2y.
      { rotation: [0, 0, Math.SQRT1_2, Math.SQRT1_2], scale: [2, 2, 2], mesh: 0 },
      // A column-major matrix mirroring x and moving up by 5.
      { matrix: [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1], mesh: 0 },
    ];
    const mesh = parseMesh(writeGlb([[TET]], { nodes, scenes: [{ nodes: [0, 2] }] }), 'scene.glb');
    const points = rows(mesh.positions).map((p) => p.map((x) => Math.round(x * 1e6) / 1e6 + 0));
    // Node 1 under node 0: vertex (1,0,0) -> rotated (0,1,0) -> scaled (0,2,0) -> moved (10,2,0).
    expect(points.slice(0, 4)).toEqual([[10, 0, 0], [10, 2, 0], [8, 0, 0], [10, 0, 2]]);
    expect(points.slice(4)).toEqual([[0, 5, 0], [-1, 5, 0], [0, 6, 0], [0, 5, 1]]);
    const first = { positions: mesh.positions.slice(0, 12), triangles: mesh.triangles.slice(0, 12) };
    const second = { positions: mesh.positions, triangles: mesh.triangles.slice(12) };
    expect(signedVolume(first)).toBeCloseTo(8 / 6); // scale 2 in all axes: volume x8
    expect(signedVolume(second), 'the mirrored copy still faces out').toBeCloseTo(1 / 6);
  });

  it('reads a buffer given as a base64 data URI and detects GLB content under another name', () => {
    const base = writeGlb([[TET]]);
    const json = JSON.parse(new TextDecoder().decode(base.subarray(20, 20 + new DataView(base.buffer).getUint32(12, true))));
    const binStart = 20 + new DataView(base.buffer).getUint32(12, true) + 8;
    const bin = base.subarray(binStart);
    json.buffers = [{ byteLength: bin.length, uri: `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}` }];
    const mesh = parseMesh(container(JSON.stringify(json), null), 'renamed.ply');
    expect(mesh.format).toBe('glb');
    expect(mesh.warnings[0]).toMatch(/named like PLY but contains GLB/);
    expect(Array.from(mesh.triangles)).toEqual(TET.indices);
  });

  describe('malformed files throw MeshFormatError with a clear message', () => {
    const good = writeGlb([[TET]]);
    it('bad magic', () => {
      const bad = good.slice();
      bad[0] = 0x78;
      expectFormatError(bad, /^GLB: bad magic/);
    });
    it('too short for a header', () => expectFormatError(good.subarray(0, 8), /too short/));
    it('unsupported version', () => {
      const bad = good.slice();
      new DataView(bad.buffer).setUint32(4, 1, true);
      expectFormatError(bad, /version 1 is not supported/);
    });
    it('truncated file', () => expectFormatError(good.subarray(0, good.length - 10), /truncated/));
    it('truncated chunk (length field larger than the file)', () => {
      const bad = good.slice();
      const jsonLength = new DataView(bad.buffer).getUint32(12, true);
      new DataView(bad.buffer).setUint32(20 + jsonLength, 1 << 20, true); // the BIN chunk's length
      expectFormatError(bad, /chunk 1 is truncated/);
    });
    it('JSON that does not parse', () => expectFormatError(container('{"asset": ', null), /not valid JSON/));
    it('missing POSITION', () => {
      expectFormatError(writeGlb([[TET]], { meshes: [{ primitives: [{ attributes: { NORMAL: 0 } }] }] }), /mesh 0 primitive 0 has no POSITION/);
    });
    it('index out of range', () => {
      expectFormatError(writeGlb([[{ ...TET, indices: [0, 1, 7] }]]), /index 7 is out of range \(the primitive has 4 vertices\)/);
    });
    it('accessor past its buffer view', () => {
      const bytes = writeGlb([[TET]], {
        accessors: [{ bufferView: 0, componentType: 5126, count: 40, type: 'VEC3' }],
        meshes: [{ primitives: [{ attributes: { POSITION: 0 } }] }],
      });
      expectFormatError(bytes, /accessor 0 needs 480 bytes/);
    });
    it('external buffer', () => {
      expectFormatError(writeGlb([[TET]], { buffers: [{ byteLength: 10, uri: 'model.bin' }] }), /external file/);
    });
    it('cyclic node graph', () => {
      expectFormatError(writeGlb([[TET]], { nodes: [{ children: [1] }, { children: [0], mesh: 0 }], scenes: [{ nodes: [0] }] }), /cycle/);
    });
    it('only lines', () => expectFormatError(writeGlb([[{ positions: [0, 0, 0, 1, 1, 1], mode: 1 }]]), /no triangle primitives/));
  });
});
