/**
 * Mesh decimation by quadric error edge collapse (Garland & Heckbert 1997), for meshes too large for
 * the geodesic solver. Pure TypeScript (CLI, worker, tests).
 *
 * Every collapse keeps the surface's topology: the link condition (with a virtual vertex joined to
 * every boundary vertex, so holes neither close nor merge) keeps it a manifold of the same genus,
 * components and boundary loops; a collapse that would flip or flatten a face is refused. Boundary
 * edges carry extra quadrics (planes through the edge, perpendicular to its face) so outlines stay in
 * place. The order is fixed (cost, then vertex indices): the same input gives the same output.
 */
import type { MeshArrays } from '../core/types.ts';

/** Weight of a boundary edge's constraint plane, relative to the face planes (Garland & Heckbert's penalty). */
const BOUNDARY_WEIGHT = 100;
/** A collapse is refused when a face's normal turns by more than this (cosine), or the face degenerates. */
const MIN_NORMAL_COSINE = 0.2;
/** Relative size below which the quadric's 3x3 system is treated as singular (positions in a unit box). */
const SINGULAR_DETERMINANT = 1e-15;

export interface DecimateProgress {
  faces: number;
  target: number;
  /** Share of the collapses done, in [0, 1]. */
  fraction: number;
}

/** A binary min-heap of candidate collapses in parallel typed arrays, ordered by cost, then a, then b. */
class CollapseHeap {
  private cost = new Float64Array(1024);
  private a = new Int32Array(1024);
  private b = new Int32Array(1024);
  /** The endpoints' versions when the entry was pushed: stale when either has changed since. */
  private versionA = new Int32Array(1024);
  private versionB = new Int32Array(1024);
  size = 0;

  push(cost: number, a: number, b: number, versionA: number, versionB: number): void {
    if (this.size === this.cost.length) this.grow();
    let i = this.size++;
    while (i > 0) {
      const parent = (i - 1) >> 1;
      if (!this.less(cost, a, b, parent)) break;
      this.move(parent, i);
      i = parent;
    }
    this.set(i, cost, a, b, versionA, versionB);
  }

  /** Removes the smallest entry into `out` (cost, a, b, versionA, versionB). */
  pop(out: Float64Array): void {
    out[0] = this.cost[0];
    out[1] = this.a[0];
    out[2] = this.b[0];
    out[3] = this.versionA[0];
    out[4] = this.versionB[0];
    const last = --this.size;
    const cost = this.cost[last], a = this.a[last], b = this.b[last];
    const va = this.versionA[last], vb = this.versionB[last];
    let i = 0;
    for (;;) {
      let child = 2 * i + 1;
      if (child >= last) break;
      if (child + 1 < last && this.less(this.cost[child + 1], this.a[child + 1], this.b[child + 1], child)) child++;
      if (!this.less(this.cost[child], this.a[child], this.b[child], -1, cost, a, b)) break;
      this.move(child, i);
      i = child;
    }
    if (last > 0) this.set(i, cost, a, b, va, vb);
  }

  /** Whether (cost, a, b) comes before entry j (or before the given triple when j < 0). */
  private less(cost: number, a: number, b: number, j: number, cj = this.cost[j], aj = this.a[j], bj = this.b[j]): boolean {
    if (cost !== cj) return cost < cj;
    if (a !== aj) return a < aj;
    return b < bj;
  }

  private set(i: number, cost: number, a: number, b: number, va: number, vb: number): void {
    this.cost[i] = cost;
    this.a[i] = a;
    this.b[i] = b;
    this.versionA[i] = va;
    this.versionB[i] = vb;
  }

  private move(from: number, to: number): void {
    this.set(to, this.cost[from], this.a[from], this.b[from], this.versionA[from], this.versionB[from]);
  }

  private grow(): void {
    const n = this.cost.length * 2;
    const grown = <T extends Float64Array | Int32Array>(old: T, make: (n: number) => T) => {
      const next = make(n);
      next.set(old);
      return next;
    };
    this.cost = grown(this.cost, (k) => new Float64Array(k));
    this.a = grown(this.a, (k) => new Int32Array(k));
    this.b = grown(this.b, (k) => new Int32Array(k));
    this.versionA = grown(this.versionA, (k) => new Int32Array(k));
    this.versionB = grown(this.versionB, (k) => new Int32Array(k));
  }
}

/** Adds the quadric of the plane n·x + d = 0 (n unit), times `weight`, to q[at..at+10). */
function addPlane(q: Float64Array, at: number, nx: number, ny: number, nz: number, d: number, weight: number): void {
  q[at] += weight * nx * nx;
  q[at + 1] += weight * nx * ny;
  q[at + 2] += weight * nx * nz;
  q[at + 3] += weight * nx * d;
  q[at + 4] += weight * ny * ny;
  q[at + 5] += weight * ny * nz;
  q[at + 6] += weight * ny * d;
  q[at + 7] += weight * nz * nz;
  q[at + 8] += weight * nz * d;
  q[at + 9] += weight * d * d;
}

/**
 * A decimation in progress: `step` does a bounded number of collapses so a caller can report progress
 * and stop in between; `result` returns the mesh as it is (compacted, vertices in their original order).
 */
export class Decimator {
  readonly target: number;
  readonly initialFaces: number;
  faces: number;
  private readonly positions: Float64Array;
  private readonly triangles: Int32Array;
  private readonly faceAlive: Uint8Array;
  private readonly vertexFaces: number[][];
  private readonly quadrics: Float64Array;
  private readonly version: Int32Array;
  private readonly alive: Uint8Array;
  private readonly boundary: Uint8Array;
  /** Vertices on an edge with more than two faces: never moved (the mesh is not a manifold there). */
  private readonly locked: Uint8Array;
  private readonly heap = new CollapseHeap();
  private readonly mark: Int32Array;
  private readonly seen: Int32Array;
  private stamp = 0;
  private readonly center: [number, number, number];
  private readonly scale: number;
  private readonly entry = new Float64Array(5);
  private readonly best = new Float64Array(4);
  private readonly moved = new Float64Array(9);

  constructor(mesh: MeshArrays, targetFaces: number) {
    const n = mesh.positions.length / 3;
    const m = mesh.triangles.length / 3;
    this.initialFaces = this.faces = m;
    this.target = Math.max(0, Math.floor(targetFaces));
    // Work in a unit box so every tolerance is relative to the mesh's size.
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < n; i++) {
      for (let k = 0; k < 3; k++) {
        lo[k] = Math.min(lo[k], mesh.positions[3 * i + k]);
        hi[k] = Math.max(hi[k], mesh.positions[3 * i + k]);
      }
    }
    this.center = [0, 1, 2].map((k) => (n > 0 ? (lo[k] + hi[k]) / 2 : 0)) as [number, number, number];
    this.scale = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
    this.positions = new Float64Array(3 * n);
    for (let i = 0; i < 3 * n; i++) this.positions[i] = (mesh.positions[i] - this.center[i % 3]) / this.scale;
    this.triangles = Int32Array.from(mesh.triangles);
    this.faceAlive = new Uint8Array(m).fill(1);
    this.vertexFaces = Array.from({ length: n }, () => []);
    for (let f = 0; f < m; f++) for (let k = 0; k < 3; k++) this.vertexFaces[this.triangles[3 * f + k]].push(f);
    this.quadrics = new Float64Array(10 * n);
    this.version = new Int32Array(n);
    this.alive = new Uint8Array(n).fill(1);
    this.boundary = new Uint8Array(n);
    this.locked = new Uint8Array(n);
    this.mark = new Int32Array(n);
    this.seen = new Int32Array(n);

    for (let f = 0; f < m; f++) this.addFaceQuadric(f);
    // Each undirected edge once, from its smaller endpoint, with its face count.
    const count = new Int32Array(n);
    for (let a = 0; a < n; a++) {
      const stamp = this.nextStamp();
      for (const f of this.vertexFaces[a]) {
        for (let k = 0; k < 3; k++) {
          const b = this.triangles[3 * f + k];
          if (b <= a) continue;
          if (this.mark[b] !== stamp) {
            this.mark[b] = stamp;
            count[b] = 0;
          }
          count[b]++;
        }
      }
      for (const f of this.vertexFaces[a]) {
        for (let k = 0; k < 3; k++) {
          const b = this.triangles[3 * f + k];
          if (b <= a || this.mark[b] !== stamp) continue;
          this.mark[b] = stamp - 1; // visit the edge once
          if (count[b] === 1) this.addBoundaryEdge(a, b, f);
          else if (count[b] > 2) this.locked[a] = this.locked[b] = 1;
        }
      }
    }
    for (let a = 0; a < n; a++) {
      const stamp = this.nextStamp();
      for (const f of this.vertexFaces[a]) {
        for (let k = 0; k < 3; k++) {
          const b = this.triangles[3 * f + k];
          if (b <= a || this.mark[b] === stamp) continue;
          this.mark[b] = stamp;
          this.pushEdge(a, b);
        }
      }
    }
  }

  /** Whether the target is reached or no allowed collapse is left. */
  get finished(): boolean {
    return this.faces <= this.target || this.heap.size === 0;
  }

  get progress(): DecimateProgress {
    const total = this.initialFaces - this.target;
    const fraction = total > 0 ? Math.min(1, (this.initialFaces - this.faces) / total) : 1;
    return { faces: this.faces, target: this.target, fraction: this.finished ? 1 : fraction };
  }

  /** Performs up to `collapses` collapses; returns whether the decimation is finished. */
  step(collapses: number): boolean {
    let done = 0;
    const e = this.entry;
    while (done < collapses && !this.finished) {
      this.heap.pop(e);
      const a = e[1], b = e[2];
      if (!this.alive[a] || !this.alive[b] || this.version[a] !== e[3] || this.version[b] !== e[4]) continue;
      if (this.collapse(a, b)) done++;
    }
    return this.finished;
  }

  /** The mesh as it is now: live vertices in their original order, positions in the input's units. */
  result(): { positions: Float64Array; triangles: Uint32Array } {
    const n = this.alive.length;
    const index = new Int32Array(n).fill(-1);
    let count = 0;
    for (let v = 0; v < n; v++) if (this.alive[v] && this.vertexFaces[v].length > 0) index[v] = count++;
    const positions = new Float64Array(3 * count);
    for (let v = 0; v < n; v++) {
      if (index[v] < 0) continue;
      for (let k = 0; k < 3; k++) positions[3 * index[v] + k] = this.positions[3 * v + k] * this.scale + this.center[k];
    }
    const triangles = new Uint32Array(3 * this.faces);
    let t = 0;
    for (let f = 0; f < this.faceAlive.length; f++) {
      if (!this.faceAlive[f]) continue;
      for (let k = 0; k < 3; k++) triangles[t++] = index[this.triangles[3 * f + k]];
    }
    return { positions, triangles };
  }

  private nextStamp(): number {
    this.stamp += 2;
    return this.stamp;
  }

  /** Cross product of face f's two edges from its first corner: its normal times twice its area. */
  private faceCross(f: number): [number, number, number] {
    const [i, j, k] = [this.triangles[3 * f], this.triangles[3 * f + 1], this.triangles[3 * f + 2]];
    const p = this.positions;
    const ux = p[3 * j] - p[3 * i], uy = p[3 * j + 1] - p[3 * i + 1], uz = p[3 * j + 2] - p[3 * i + 2];
    const vx = p[3 * k] - p[3 * i], vy = p[3 * k + 1] - p[3 * i + 1], vz = p[3 * k + 2] - p[3 * i + 2];
    return [uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx];
  }

  private addFaceQuadric(f: number): void {
    const normal = this.faceCross(f);
    // Weighted by area, so large faces pull harder than slivers.
    const area = Math.hypot(...normal) / 2;
    for (let c = 0; c < 3; c++) this.addPlaneThrough(this.triangles[3 * f + c], this.triangles[3 * f], normal, area);
  }

  /** Adds to vertex v's quadric the plane with normal `normal` (any length but zero) through vertex `on`, times `weight`. */
  private addPlaneThrough(v: number, on: number, [nx, ny, nz]: [number, number, number], weight: number): void {
    const length = Math.hypot(nx, ny, nz);
    if (length === 0) return;
    const p = this.positions;
    const d = -(nx * p[3 * on] + ny * p[3 * on + 1] + nz * p[3 * on + 2]) / length;
    addPlane(this.quadrics, 10 * v, nx / length, ny / length, nz / length, d, weight);
  }

  /** The plane through boundary edge a-b perpendicular to its face f, added to both endpoints. */
  private addBoundaryEdge(a: number, b: number, f: number): void {
    this.boundary[a] = this.boundary[b] = 1;
    const p = this.positions;
    const [fx, fy, fz] = this.faceCross(f);
    const ex = p[3 * b] - p[3 * a], ey = p[3 * b + 1] - p[3 * a + 1], ez = p[3 * b + 2] - p[3 * a + 2];
    const normal: [number, number, number] = [ey * fz - ez * fy, ez * fx - ex * fz, ex * fy - ey * fx];
    const weight = BOUNDARY_WEIGHT * (ex * ex + ey * ey + ez * ez);
    this.addPlaneThrough(a, a, normal, weight);
    this.addPlaneThrough(b, a, normal, weight);
  }

  /** Makes (x, y, z) this.best when its error under the quadrics of a and b is lower. (No closures in the hot path.) */
  private consider(a: number, b: number, x: number, y: number, z: number): void {
    const q = this.quadrics, i = 10 * a, j = 10 * b;
    const e = (q[i] + q[j]) * x * x + 2 * (q[i + 1] + q[j + 1]) * x * y + 2 * (q[i + 2] + q[j + 2]) * x * z
      + 2 * (q[i + 3] + q[j + 3]) * x + (q[i + 4] + q[j + 4]) * y * y + 2 * (q[i + 5] + q[j + 5]) * y * z
      + 2 * (q[i + 6] + q[j + 6]) * y + (q[i + 7] + q[j + 7]) * z * z + 2 * (q[i + 8] + q[j + 8]) * z + (q[i + 9] + q[j + 9]);
    const cost = Math.max(0, e);
    const best = this.best;
    if (cost < best[3]) {
      best[0] = x;
      best[1] = y;
      best[2] = z;
      best[3] = cost;
    }
  }

  /** Where a and b should meet and at what cost, into this.best (x, y, z, cost). */
  private placement(a: number, b: number): void {
    const p = this.positions;
    this.best[3] = Infinity;
    // A boundary vertex stays where it is when an interior neighbour joins it.
    if (this.boundary[a] !== this.boundary[b]) {
      const keep = this.boundary[a] ? a : b;
      this.consider(a, b, p[3 * keep], p[3 * keep + 1], p[3 * keep + 2]);
      return;
    }
    const q = this.quadrics, i = 10 * a, j = 10 * b;
    const a00 = q[i] + q[j], a01 = q[i + 1] + q[j + 1], a02 = q[i + 2] + q[j + 2];
    const a11 = q[i + 4] + q[j + 4], a12 = q[i + 5] + q[j + 5], a22 = q[i + 7] + q[j + 7];
    const b0 = -(q[i + 3] + q[j + 3]), b1 = -(q[i + 6] + q[j + 6]), b2 = -(q[i + 8] + q[j + 8]);
    const m00 = a11 * a22 - a12 * a12, m01 = a02 * a12 - a01 * a22, m02 = a01 * a12 - a02 * a11;
    const det = a00 * m00 + a01 * m01 + a02 * m02;
    const norm = Math.max(Math.abs(a00), Math.abs(a11), Math.abs(a22));
    if (Math.abs(det) > SINGULAR_DETERMINANT * norm * norm * norm) {
      const m11 = a00 * a22 - a02 * a02, m12 = a01 * a02 - a00 * a12, m22 = a00 * a11 - a01 * a01;
      this.consider(a, b, (m00 * b0 + m01 * b1 + m02 * b2) / det, (m01 * b0 + m11 * b1 + m12 * b2) / det, (m02 * b0 + m12 * b1 + m22 * b2) / det);
    }
    this.consider(a, b, p[3 * a], p[3 * a + 1], p[3 * a + 2]);
    this.consider(a, b, p[3 * b], p[3 * b + 1], p[3 * b + 2]);
    this.consider(a, b, (p[3 * a] + p[3 * b]) / 2, (p[3 * a + 1] + p[3 * b + 1]) / 2, (p[3 * a + 2] + p[3 * b + 2]) / 2);
  }

  private pushEdge(a: number, b: number): void {
    if (this.locked[a] || this.locked[b]) return;
    this.placement(a, b);
    this.heap.push(this.best[3], Math.min(a, b), Math.max(a, b), this.version[Math.min(a, b)], this.version[Math.max(a, b)]);
  }

  /**
   * The link condition: the vertices adjacent to both a and b (the virtual boundary vertex counting
   * for boundary vertices) must be exactly the corners opposite a-b, one per face of the edge plus the
   * virtual one for a boundary edge. Returns the number of faces on a-b, or -1 when the collapse would
   * change the topology.
   */
  private edgeFacesIfLinkHolds(a: number, b: number): number {
    const stampA = this.nextStamp();
    let faces = 0;
    for (const f of this.vertexFaces[a]) {
      let hasB = false;
      for (let k = 0; k < 3; k++) {
        const v = this.triangles[3 * f + k];
        if (v === b) hasB = true;
        this.mark[v] = stampA;
      }
      if (hasB) faces++;
    }
    if (faces !== 1 && faces !== 2) return -1;
    const stampB = this.nextStamp();
    let common = 0;
    for (const f of this.vertexFaces[b]) {
      for (let k = 0; k < 3; k++) {
        const v = this.triangles[3 * f + k];
        if (v === a || v === b || this.seen[v] === stampB) continue;
        this.seen[v] = stampB;
        if (this.mark[v] === stampA) common++;
      }
    }
    if (this.boundary[a] && this.boundary[b]) common++;
    if (common !== 2) return -1;
    // Two degree-3 ends of an interior edge: the component is a tetrahedron, which would fold flat.
    if (faces === 2 && this.vertexFaces[a].length === 3 && this.vertexFaces[b].length === 3) return -1;
    return faces;
  }

  /** Whether moving the faces of v (but not those on a-b) to put v at (x, y, z) keeps them facing the same way. */
  private keepsNormals(v: number, a: number, b: number, x: number, y: number, z: number): boolean {
    const p = this.positions, t = this.triangles, moved = this.moved;
    for (const f of this.vertexFaces[v]) {
      const i = t[3 * f], j = t[3 * f + 1], k = t[3 * f + 2];
      if ((i === a || j === a || k === a) && (i === b || j === b || k === b)) continue;
      const ux = p[3 * j] - p[3 * i], uy = p[3 * j + 1] - p[3 * i + 1], uz = p[3 * j + 2] - p[3 * i + 2];
      const wx = p[3 * k] - p[3 * i], wy = p[3 * k + 1] - p[3 * i + 1], wz = p[3 * k + 2] - p[3 * i + 2];
      const ox = uy * wz - uz * wy, oy = uz * wx - ux * wz, oz = ux * wy - uy * wx;
      // The face's corners with v at (x, y, z).
      for (let c = 0; c < 3; c++) {
        const u = t[3 * f + c];
        moved[3 * c] = u === v ? x : p[3 * u];
        moved[3 * c + 1] = u === v ? y : p[3 * u + 1];
        moved[3 * c + 2] = u === v ? z : p[3 * u + 2];
      }
      const Ux = moved[3] - moved[0], Uy = moved[4] - moved[1], Uz = moved[5] - moved[2];
      const Wx = moved[6] - moved[0], Wy = moved[7] - moved[1], Wz = moved[8] - moved[2];
      const nx = Uy * Wz - Uz * Wy, ny = Uz * Wx - Ux * Wz, nz = Ux * Wy - Uy * Wx;
      const before = Math.hypot(ox, oy, oz), after = Math.hypot(nx, ny, nz);
      if (after <= 1e-12 * (Ux * Ux + Uy * Uy + Uz * Uz + Wx * Wx + Wy * Wy + Wz * Wz)) return false;
      if (ox * nx + oy * ny + oz * nz < MIN_NORMAL_COSINE * before * after) return false;
    }
    return true;
  }

  /** Collapses edge a-b (a < b) into a, if that keeps the topology and the normals; returns whether it did. */
  private collapse(a: number, b: number): boolean {
    if (this.edgeFacesIfLinkHolds(a, b) < 0) return false;
    this.placement(a, b);
    const x = this.best[0], y = this.best[1], z = this.best[2];
    if (!this.keepsNormals(a, a, b, x, y, z) || !this.keepsNormals(b, a, b, x, y, z)) return false;

    const t = this.triangles;
    const faces: number[] = [];
    for (const f of this.vertexFaces[a]) {
      if (t[3 * f] === b || t[3 * f + 1] === b || t[3 * f + 2] === b) {
        this.faceAlive[f] = 0;
        this.faces--;
      } else faces.push(f);
    }
    for (const f of this.vertexFaces[b]) {
      if (!this.faceAlive[f]) continue;
      for (let k = 0; k < 3; k++) if (t[3 * f + k] === b) t[3 * f + k] = a;
      faces.push(f);
    }
    // The faces that lost the edge drop out of their third vertex's list.
    for (const f of this.vertexFaces[b]) {
      if (this.faceAlive[f]) continue;
      for (let k = 0; k < 3; k++) {
        const v = t[3 * f + k];
        if (v !== a && v !== b) {
          const list = this.vertexFaces[v];
          list.splice(list.indexOf(f), 1);
        }
      }
    }
    this.vertexFaces[a] = faces;
    this.vertexFaces[b] = [];
    this.alive[b] = 0;
    this.positions[3 * a] = x;
    this.positions[3 * a + 1] = y;
    this.positions[3 * a + 2] = z;
    for (let k = 0; k < 10; k++) this.quadrics[10 * a + k] += this.quadrics[10 * b + k];
    this.boundary[a] ||= this.boundary[b];
    this.version[a]++;
    const stamp = this.nextStamp();
    for (const f of faces) {
      for (let k = 0; k < 3; k++) {
        const v = t[3 * f + k];
        if (v === a || this.mark[v] === stamp) continue;
        this.mark[v] = stamp;
        this.pushEdge(a, v);
      }
    }
    return true;
  }
}

/**
 * Decimates `mesh` to about `targetFaces` faces (fewer collapses when the topology or the normals
 * forbid more); `onProgress` is called every `collapsesPerStep` collapses.
 */
export function decimate(
  mesh: MeshArrays,
  targetFaces: number,
  onProgress?: (progress: DecimateProgress) => void,
  collapsesPerStep = 20_000,
): { positions: Float64Array; triangles: Uint32Array } {
  const decimator = new Decimator(mesh, targetFaces);
  while (!decimator.step(collapsesPerStep)) onProgress?.(decimator.progress);
  onProgress?.(decimator.progress);
  return decimator.result();
}
