/**
 * The generalised winding number of triangles around a point, by the exact sum of their solid angles
 * (Van Oosterom and Strackee): about 1 inside a closed outward-facing surface, 0 outside. Shared by
 * repair on load (which components lie inside others) and the tests (skeleton nodes inside the shape);
 * the core has its own fast one (wasm/src/mesh/winding.cpp).
 */
import type { MeshArrays } from '../core/types.ts';

/** Over the faces listed, or over every face of the mesh. */
export function windingNumber(mesh: MeshArrays, p: ArrayLike<number>, faces?: ArrayLike<number>): number {
  const { positions: pos, triangles: tri } = mesh;
  const faceCount = faces ? faces.length : tri.length / 3;
  let total = 0;
  for (let i = 0; i < faceCount; i++) {
    const f = faces ? faces[i] : i;
    const a = 3 * tri[3 * f], b = 3 * tri[3 * f + 1], c = 3 * tri[3 * f + 2];
    const ax = pos[a] - p[0], ay = pos[a + 1] - p[1], az = pos[a + 2] - p[2];
    const bx = pos[b] - p[0], by = pos[b + 1] - p[1], bz = pos[b + 2] - p[2];
    const cx = pos[c] - p[0], cy = pos[c + 1] - p[1], cz = pos[c + 2] - p[2];
    const la = Math.hypot(ax, ay, az), lb = Math.hypot(bx, by, bz), lc = Math.hypot(cx, cy, cz);
    const det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    const denominator = la * lb * lc + (ax * bx + ay * by + az * bz) * lc + (bx * cx + by * cy + bz * cz) * la + (cx * ax + cy * ay + cz * az) * lb;
    total += 2 * Math.atan2(det, denominator);
  }
  return total / (4 * Math.PI);
}
