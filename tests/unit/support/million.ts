// A million-triangle wavy grid (full-precision coordinates, the slow number path) in three formats,
// for the parse-time bound of `npm run check:corpus`.
const SIDE = 708; // (SIDE - 1)^2 * 2 = 999 698 triangles
export const VERTICES = SIDE * SIDE;
export const TRIANGLES = (SIDE - 1) * (SIDE - 1) * 2;

/** A wavy grid with full-precision coordinates (17 significant digits, the slow number path). */
export function grid(): { positions: Float64Array; triangles: Uint32Array } {
  const positions = new Float64Array(3 * VERTICES);
  for (let j = 0, v = 0; j < SIDE; j++) {
    for (let i = 0; i < SIDE; i++, v += 3) positions.set([i / 3, j / 7, Math.sin(i / 10) * Math.cos(j / 10)], v);
  }
  const triangles = new Uint32Array(3 * TRIANGLES);
  for (let j = 0, t = 0; j < SIDE - 1; j++) {
    for (let i = 0; i < SIDE - 1; i++, t += 6) {
      const a = j * SIDE + i;
      triangles.set([a, a + 1, a + SIDE + 1, a, a + SIDE + 1, a + SIDE], t);
    }
  }
  return { positions, triangles };
}

export function toObj({ positions, triangles }: ReturnType<typeof grid>): Uint8Array {
  const lines: string[] = [];
  for (let v = 0; v < positions.length; v += 3) lines.push(`v ${positions[v]} ${positions[v + 1]} ${positions[v + 2]}`);
  for (let t = 0; t < triangles.length; t += 3) lines.push(`f ${triangles[t] + 1} ${triangles[t + 1] + 1} ${triangles[t + 2] + 1}`);
  return new TextEncoder().encode(lines.join('\n'));
}

export function toBinaryPly({ positions, triangles }: ReturnType<typeof grid>): Uint8Array {
  const header = new TextEncoder().encode(
    `ply\nformat binary_little_endian 1.0\nelement vertex ${VERTICES}\nproperty float x\nproperty float y\nproperty float z\n` +
      `element face ${TRIANGLES}\nproperty list uchar int vertex_indices\nend_header\n`,
  );
  const bytes = new Uint8Array(header.length + 12 * VERTICES + 13 * TRIANGLES);
  bytes.set(header);
  const view = new DataView(bytes.buffer);
  let offset = header.length;
  for (const x of positions) view.setFloat32((offset += 4) - 4, x, true);
  for (let t = 0; t < triangles.length; t += 3) {
    view.setUint8(offset++, 3);
    for (let c = 0; c < 3; c++, offset += 4) view.setInt32(offset, triangles[t + c], true);
  }
  return bytes;
}

export function toBinaryStl({ positions, triangles }: ReturnType<typeof grid>): Uint8Array {
  const bytes = new Uint8Array(84 + 50 * TRIANGLES);
  const view = new DataView(bytes.buffer);
  view.setUint32(80, TRIANGLES, true);
  for (let t = 0; t < TRIANGLES; t++) {
    for (let c = 0; c < 3; c++) {
      for (let d = 0; d < 3; d++) view.setFloat32(84 + 50 * t + 12 + 12 * c + 4 * d, positions[3 * triangles[3 * t + c] + d], true);
    }
  }
  return bytes;
}
