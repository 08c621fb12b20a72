// Large meshes made at test time (never committed): a torus of about N faces as a binary PLY file.
import type { MeshArrays } from '../../../lib/core/types.ts';
import { torus } from './meshes.ts';

/** A torus (R = 10, r = 3) with about `faces` faces, its tube and ring resolutions in the ratio r : R. */
export function torusOfFaces(faces: number): MeshArrays {
  const nv = Math.max(3, Math.round(Math.sqrt((faces / 2) * (3 / 10))));
  const nu = 2 * Math.max(2, Math.round(faces / 2 / nv / 2));
  return torus(10, 3, nu, nv);
}

/** The mesh as a binary little-endian PLY file (float xyz, uchar-count int indices). */
export function binaryPly({ positions, triangles }: MeshArrays): Uint8Array {
  const vertices = positions.length / 3, faces = triangles.length / 3;
  const header = new TextEncoder().encode(
    ['ply', 'format binary_little_endian 1.0', `element vertex ${vertices}`, 'property float x', 'property float y',
      'property float z', `element face ${faces}`, 'property list uchar int vertex_indices', 'end_header', ''].join('\n'),
  );
  const bytes = new Uint8Array(header.length + 12 * vertices + 13 * faces);
  bytes.set(header);
  const view = new DataView(bytes.buffer);
  let at = header.length;
  for (let i = 0; i < positions.length; i++, at += 4) view.setFloat32(at, positions[i], true);
  for (let f = 0; f < faces; f++) {
    view.setUint8(at++, 3);
    for (let k = 0; k < 3; k++, at += 4) view.setInt32(at, triangles[3 * f + k], true);
  }
  return bytes;
}
