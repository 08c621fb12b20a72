// Point clouds made in code: PLY files in every encoding.

export type PlyEncoding = 'ascii' | 'binary_little_endian' | 'binary_big_endian';

/** A PLY point cloud: x y z (then nx ny nz when given) of one scalar type, no face element. */
export function cloudPly(
  points: number[][], normals: number[][] | null, encoding: PlyEncoding, type: 'float' | 'double', comment = 'made by tests/unit/support/clouds.ts',
): Uint8Array {
  const names = normals ? ['x', 'y', 'z', 'nx', 'ny', 'nz'] : ['x', 'y', 'z'];
  const header = `ply\nformat ${encoding} 1.0\ncomment ${comment}\nelement vertex ${points.length}\n`
    + `${names.map((name) => `property ${type} ${name}\n`).join('')}end_header\n`;
  const rows = points.map((p, i) => (normals ? [...p, ...normals[i]] : p));
  if (encoding === 'ascii') return new TextEncoder().encode(header + rows.map((row) => row.join(' ')).join('\n') + '\n');
  const size = type === 'float' ? 4 : 8;
  const bytes = new Uint8Array(header.length + size * names.length * points.length);
  bytes.set(new TextEncoder().encode(header));
  const view = new DataView(bytes.buffer);
  const littleEndian = encoding === 'binary_little_endian';
  let o = header.length;
  for (const value of rows.flat()) {
    if (type === 'float') view.setFloat32(o, value, littleEndian);
    else view.setFloat64(o, value, littleEndian);
    o += size;
  }
  return bytes;
}
