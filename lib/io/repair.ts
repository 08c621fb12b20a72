/**
 * Repair on load: turns the meshes people have (STL soups, OBJ texture seams, stray vertices, doubled
 * or flipped faces, fins, bow-ties) into what the core needs, a manifold and consistently oriented
 * triangle mesh, and says what it did, one sentence per repair. Pure TypeScript on typed arrays, no
 * Node or DOM APIs: the CLI and the page's worker share it.
 *
 * The steps, in order:
 * 1. weld vertices closer than WELD_TOLERANCE x the bounding-box diagonal (each joins the first
 *    earlier vertex in reach, whose position is kept; the box is that of the vertices in faces);
 * 2. flip caps (zero-area faces with a corner on the opposite edge) with their neighbour into two
 *    proper triangles, then remove the degenerate faces left: a repeated vertex, or zero area by the
 *    core's test (mesh_check.cpp);
 * 3. remove duplicate faces (the same three vertices as an earlier face, in any order);
 * 4. split non-manifold edges: of the faces on an edge, the first pair running along it in opposite
 *    directions (else the first two) stays joined; the others are detached, not dropped, so no
 *    surface is lost: they get their own copies of the edge's vertices (where the pair joins the
 *    others around a vertex anyway, as two closed surfaces sharing an edge do, all are cut apart);
 * 5. split non-manifold vertices: one copy of the vertex per fan of faces joined across edges;
 * 6. orient: per connected component, faces are flipped to agree with the majority of their
 *    component; then a closed component faces outward (positive volume) unless it lies inside an
 *    odd number of other closed components (a cavity, which faces inward);
 * 7. remove vertices used by no face.
 *
 * A mesh that needs none of this comes back as the very same object with no repairs, so vertex and
 * face indices match the file. After a repair, faces keep their relative order, surviving vertices
 * keep theirs, copies made by splits come after them, and `vertexMap` says where each input vertex went.
 * Meshes that are not arrays of a mesh (non-finite coordinates on faces, indices out of range) are
 * returned as they are for the core to refuse with its own message.
 */
import type { MeshArrays } from '../core/types.ts';
import { UnionFind } from '../graph/union-find.ts';
import { windingNumber } from '../mesh/winding.ts';
import { MeshFormatError } from './types.ts';

/** Welding reach, relative to the bounding-box diagonal: far below any real feature, far above rounding. */
export const WELD_TOLERANCE = 1e-6;
/** The core's zero-area test: twice the area at most this times the longest squared edge. */
const ZERO_AREA = 1e-12;
/** A closed component this flat (|volume| / diagonal^3) has no inside to face. */
const FLAT_VOLUME = 1e-12;
/** Points of a closed component tested for lying inside another one (a majority decides). */
const INSIDE_VOTES = 5;

export interface RepairResult<P extends MeshArrays['positions'] = MeshArrays['positions']> {
  /** Positions of the input's type. */
  mesh: { positions: P; triangles: Uint32Array };
  /** One sentence per repair made, with counts; empty when the mesh was returned as it came. */
  repairs: string[];
  /** Index of every input vertex in the repaired mesh, -1 for removed ones. */
  vertexMap: Int32Array;
}

export function repairMesh<P extends MeshArrays['positions']>(mesh: { positions: P; triangles: Uint32Array }): RepairResult<P> {
  const { positions } = mesh;
  const nV = positions.length / 3;
  const unchanged = (): RepairResult<P> => ({ mesh, repairs: [], vertexMap: identity(nV) });
  if (!Number.isInteger(nV) || mesh.triangles.length % 3 !== 0) return unchanged();
  for (const v of mesh.triangles) if (v >= nV) return unchanged();
  for (const v of mesh.triangles) {
    if (!Number.isFinite(positions[3 * v]) || !Number.isFinite(positions[3 * v + 1]) || !Number.isFinite(positions[3 * v + 2])) return unchanged();
  }

  const repairs: string[] = [];
  const nF0 = mesh.triangles.length / 3;
  let tri: Uint32Array = mesh.triangles.slice();
  // Positions as plain numbers; copies made by splits are appended.
  let pos: Float64Array = Float64Array.from(positions);
  let vertexCount = nV;

  const inFace = new Uint8Array(nV);
  for (let c = 0; c < tri.length; c++) inFace[tri[c]] = 1;
  // Unused vertices are left to the final compaction.
  const welded = weld(pos, WELD_TOLERANCE * boundingBoxDiagonal(pos, inFace), inFace);
  if (welded.count > 0) {
    for (let c = 0; c < tri.length; c++) tri[c] = welded.to[tri[c]];
    repairs.push(`welded ${count(welded.count, 'duplicate vertex', 'duplicate vertices')} (closer than ${WELD_TOLERANCE.toExponential()} of the bounding-box diagonal)`);
  }

  const capsFlipped = flipCaps(pos, tri, nV);
  if (capsFlipped > 0) {
    repairs.push(`flipped ${count(capsFlipped, 'zero-area face', 'zero-area faces')} with ${capsFlipped === 1 ? 'its neighbour' : 'their neighbours'} into proper triangles (the same surface)`);
  }
  const degenerate = removeFaces(tri, (f) => isDegenerate(pos, tri, f));
  if (degenerate.removed > 0) {
    tri = degenerate.tri;
    if (tri.length === 0) {
      throw new MeshFormatError(`all ${count(nF0, 'face', 'faces')} ${nF0 === 1 ? 'is' : 'are'} degenerate (zero area or a repeated vertex): there is no surface left`);
    }
    repairs.push(`removed ${count(degenerate.removed, 'degenerate face', 'degenerate faces')} (zero area or a repeated vertex)`);
  }
  const duplicate = removeFaces(tri, duplicateFaceTest(tri));
  if (duplicate.removed > 0) {
    tri = duplicate.tri;
    repairs.push(`removed ${count(duplicate.removed, 'duplicate face', 'duplicate faces')} (the same three vertices as an earlier face)`);
  }

  // Splits: first keep a consistent pair joined at each non-manifold edge; where that still leaves
  // an edge with more than two faces (the pair's fans join the others around a vertex), cut them all.
  const origin: number[] = []; // input vertex of every copy, in order
  let edges = buildEdges(tri, vertexCount);
  let nonManifold: number[][] = [], edgeCopies = 0, pointCopies = 0, pointVertices = 0;
  for (const mode of ['keep-pair', 'cut-all'] as const) {
    if (mode === 'cut-all' && !edges.hasNonManifoldEdge) break;
    const split = splitNonManifold(tri, edges, vertexCount, mode);
    if (mode === 'keep-pair') ({ nonManifold, pointVertices, pointCopies } = split);
    edgeCopies += split.edgeCopies;
    if (split.copyOf.length === 0) continue;
    // The second pass may copy a copy: record the input vertex.
    for (const v of split.copyOf) origin.push(v < nV ? v : origin[v - nV]);
    vertexCount += split.copyOf.length;
    edges = buildEdges(tri, vertexCount);
  }
  if (nonManifold.length > 0) {
    // What each edge became: the distinct vertex pairs of its faces now.
    const after = nonManifold.reduce((sum, corners) => sum + new Set(corners.map((c) => {
      const a = tri[c], b = tri[next(c)];
      return a < b ? `${a},${b}` : `${b},${a}`;
    })).size, 0);
    repairs.push(`split ${count(nonManifold.length, 'non-manifold edge', 'non-manifold edges')} (more than two faces on an edge) `
      + `into ${count(after, 'edge', 'edges')} with ${count(edgeCopies, 'copied vertex', 'copied vertices')}`);
  }
  if (pointVertices > 0) {
    repairs.push(`split ${count(pointVertices, 'non-manifold vertex', 'non-manifold vertices')} (faces meeting only at a point) into ${pointVertices + pointCopies}`);
  }
  if (origin.length > 0) {
    const grown = new Float64Array(3 * vertexCount);
    grown.set(pos);
    origin.forEach((v, i) => grown.set(pos.subarray(3 * v, 3 * v + 3), 3 * (nV + i)));
    pos = grown;
  }

  const oriented = orient(pos, tri, edges);
  if (oriented.flippedToAgree > 0) repairs.push(`flipped ${count(oriented.flippedToAgree, 'face', 'faces')} to agree with ${oriented.flippedToAgree === 1 ? 'its' : 'their'} neighbours`);
  if (oriented.reversedComponents > 0) {
    repairs.push(`reversed ${count(oriented.reversedComponents, 'closed component', 'closed components')} that faced inward (${count(oriented.reversedFaces, 'face', 'faces')})`);
  }

  // Compaction: surviving vertices in order, then the copies.
  const newIndex = new Int32Array(vertexCount).fill(-1);
  for (let c = 0; c < tri.length; c++) newIndex[tri[c]] = 0;
  let kept = 0;
  for (let v = 0; v < vertexCount; v++) if (newIndex[v] === 0) newIndex[v] = kept++;
  const unreferenced = vertexCount - kept - welded.count;
  if (unreferenced > 0) repairs.push(`removed ${count(unreferenced, 'unreferenced vertex', 'unreferenced vertices')} (used by no face)`);

  if (repairs.length === 0) return unchanged();
  const out = new (positions.constructor as new (n: number) => P)(3 * kept);
  for (let v = 0; v < vertexCount; v++) {
    const to = newIndex[v];
    if (to >= 0) out.set(pos.subarray(3 * v, 3 * v + 3), 3 * to);
  }
  for (let c = 0; c < tri.length; c++) tri[c] = newIndex[tri[c]];
  const vertexMap = new Int32Array(nV);
  for (let v = 0; v < nV; v++) vertexMap[v] = newIndex[welded.to[v]];
  return { mesh: { positions: out, triangles: tri }, repairs, vertexMap };
}

/** "1 face", "3 faces": a count for a message. */
export function count(n: number, one: string, many: string): string {
  return `${n} ${n === 1 ? one : many}`;
}

function identity(n: number): Int32Array {
  const map = new Int32Array(n);
  for (let i = 0; i < n; i++) map[i] = i;
  return map;
}

/** Diagonal of the bounding box of the points (of those marked in `used`, when given); 0 for none. */
export function boundingBoxDiagonal(pos: Float64Array, used: Uint8Array | null = null): number {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < pos.length / 3; v++) {
    if (used && !used[v]) continue;
    for (let k = 0; k < 3; k++) {
      const x = pos[3 * v + k];
      if (x < min[k]) min[k] = x;
      if (x > max[k]) max[k] = x;
    }
  }
  return min[0] > max[0] ? 0 : Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
}

/**
 * Welds every point (of those marked in `used`, when given) to the lowest-numbered earlier one within
 * `tolerance` that was not welded itself (so no chains form, and the points kept are all farther apart
 * than `tolerance`), found on a grid: only the cells near a point are searched. Returns the target of
 * every point (itself when kept or not used) and how many were welded. Shared by mesh repair and the
 * point-cloud checks and subsampling.
 */
export function weld(pos: Float64Array, tolerance: number, used: Uint8Array | null = null): { to: Int32Array; count: number } {
  const nV = pos.length / 3;
  const to = identity(nV);
  let usedCount = nV;
  if (used) {
    usedCount = 0;
    for (let v = 0; v < nV; v++) usedCount += used[v];
  }
  const min = [Infinity, Infinity, Infinity];
  for (let v = 0; v < nV; v++) {
    if (used && !used[v]) continue;
    for (let k = 0; k < 3; k++) if (pos[3 * v + k] < min[k]) min[k] = pos[3 * v + k];
  }
  // Cells twice the reach: a vertex's reach overlaps its own cell and at most one neighbour per axis,
  // 8 cells in all. With tolerance 0 (all faces on one point) only equal points weld; any size will do.
  const cell = tolerance > 0 ? 2 * tolerance : 1;
  const tolerance2 = tolerance * tolerance;

  let size = 1;
  while (size < 2 * usedCount) size *= 2;
  const mask = size - 1;
  const slotCell = new Int32Array(3 * size);
  const slotHead = new Int32Array(size).fill(-1); // first kept vertex of the slot's cell
  const nextInCell = new Int32Array(nV).fill(-1);
  /** The slot of a cell: its own, or the empty one where it would go. */
  const slotOf = (x: number, y: number, z: number) => {
    let s = (Math.imul(x, 73856093) ^ Math.imul(y, 19349663) ^ Math.imul(z, 83492791)) & mask;
    while (slotHead[s] >= 0 && (slotCell[3 * s] !== x || slotCell[3 * s + 1] !== y || slotCell[3 * s + 2] !== z)) s = (s + 1) & mask;
    return s;
  };

  let welded = 0;
  for (let v = 0; v < nV; v++) {
    if (used && !used[v]) continue;
    const px = pos[3 * v], py = pos[3 * v + 1], pz = pos[3 * v + 2];
    const gx = (px - min[0]) / cell, gy = (py - min[1]) / cell, gz = (pz - min[2]) / cell;
    const cx = Math.floor(gx), cy = Math.floor(gy), cz = Math.floor(gz);
    const sx = gx - cx < 0.5 ? -1 : 1, sy = gy - cy < 0.5 ? -1 : 1, sz = gz - cz < 0.5 ? -1 : 1;
    let target = -1;
    search: for (let i = 0; i < 8; i++) {
      const x = i & 1 ? cx + sx : cx, y = i & 2 ? cy + sy : cy, z = i & 4 ? cz + sz : cz;
      for (let w = slotHead[slotOf(x, y, z)]; w >= 0; w = nextInCell[w]) {
        const ex = pos[3 * w] - px, ey = pos[3 * w + 1] - py, ez = pos[3 * w + 2] - pz;
        const d2 = ex * ex + ey * ey + ez * ez;
        if (d2 <= tolerance2 && (target < 0 || w < target)) target = w;
        // Kept vertices are farther apart than the reach, so one at the same point is the only one in
        // reach: stop looking (the common case of exact duplicates, in the first cell searched).
        if (d2 === 0) break search;
      }
    }
    if (target >= 0) {
      to[v] = target;
      welded++;
      continue;
    }
    const s = slotOf(cx, cy, cz);
    if (slotHead[s] < 0) slotCell.set([cx, cy, cz], 3 * s);
    nextInCell[v] = slotHead[s];
    slotHead[s] = v;
  }
  return { to, count: welded };
}

function isDegenerate(pos: Float64Array, tri: Uint32Array, f: number): boolean {
  const a = 3 * tri[3 * f], b = 3 * tri[3 * f + 1], c = 3 * tri[3 * f + 2];
  if (a === b || b === c || a === c) return true;
  const ux = pos[b] - pos[a], uy = pos[b + 1] - pos[a + 1], uz = pos[b + 2] - pos[a + 2];
  const vx = pos[c] - pos[a], vy = pos[c + 1] - pos[a + 1], vz = pos[c + 2] - pos[a + 2];
  const wx = pos[c] - pos[b], wy = pos[c + 1] - pos[b + 1], wz = pos[c + 2] - pos[b + 2];
  const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const twiceArea = Math.sqrt(nx * nx + ny * ny + nz * nz);
  const longest = Math.max(ux * ux + uy * uy + uz * uz, vx * vx + vy * vy + vz * vz, wx * wx + wy * wy + wz * wz);
  return twiceArea <= ZERO_AREA * longest;
}

/** Rounds of cap flips: a cap next to one flipped in this round waits for the next. */
const CAP_ROUNDS = 4;

/**
 * A zero-area face with three distinct corners is a cap: one corner c lies on the opposite, longest
 * edge ab. Flipping ab with the face (b, a, d) across it gives (c, a, d) and (b, c, d), which cover the
 * same surface with proper triangles, where removing the cap would leave a slit. Done only where ab
 * has just those two faces running along it in opposite directions and c-d is not an edge yet; the
 * caps left are removed with the other degenerate faces. Flips faces in `tri` in place.
 */
function flipCaps(pos: Float64Array, tri: Uint32Array, nV: number): number {
  const nF = tri.length / 3;
  let flipped = 0;
  for (let round = 0; round < CAP_ROUNDS; round++) {
    const caps: number[] = [];
    for (let f = 0; f < nF; f++) {
      const a = tri[3 * f], b = tri[3 * f + 1], c = tri[3 * f + 2];
      if (a !== b && b !== c && a !== c && isDegenerate(pos, tri, f)) caps.push(f);
    }
    if (caps.length === 0) break;
    const { edgeOf, edgeStart, edgeCorners } = buildEdges(tri, nV);
    const faces = facesAround(tri, nV);
    const touched = new Uint8Array(nF);
    const newEdges = new Set<string>(); // made this round, unknown to `faces`
    const isEdge = (u: number, v: number) => newEdges.has(u < v ? `${u},${v}` : `${v},${u}`)
      || faces.of(u).some((g) => tri[3 * g] === v || tri[3 * g + 1] === v || tri[3 * g + 2] === v);
    let flippedNow = 0;
    for (const f of caps) {
      if (touched[f]) continue;
      // The longest edge starts at corner k.
      let k = 0, longest = -1;
      for (let i = 0; i < 3; i++) {
        const p = 3 * tri[3 * f + i], q = 3 * tri[3 * f + (i + 1) % 3];
        const l = (pos[q] - pos[p]) ** 2 + (pos[q + 1] - pos[p + 1]) ** 2 + (pos[q + 2] - pos[p + 2]) ** 2;
        if (l > longest) [k, longest] = [i, l];
      }
      const cab = 3 * f + k, e = edgeOf[cab];
      if (edgeStart[e + 1] - edgeStart[e] !== 2) continue;
      const other = edgeCorners[edgeStart[e]] === cab ? edgeCorners[edgeStart[e] + 1] : edgeCorners[edgeStart[e]];
      const g = (other / 3) | 0;
      const a = tri[cab], b = tri[next(cab)], c = tri[next(next(cab))], d = tri[next(next(other))];
      if (touched[g] || tri[other] !== b || d === c || isEdge(c, d)) continue;
      tri.set([c, a, d], 3 * f);
      tri.set([b, c, d], 3 * g);
      touched[f] = touched[g] = 1;
      newEdges.add(c < d ? `${c},${d}` : `${d},${c}`);
      flippedNow++;
    }
    flipped += flippedNow;
    if (flippedNow === 0) break;
  }
  return flipped;
}

/** The faces around each vertex (a counting sort of the corners). */
function facesAround(tri: Uint32Array, nV: number): { of(v: number): Int32Array } {
  const start = new Int32Array(nV + 1);
  for (let c = 0; c < tri.length; c++) start[tri[c] + 1]++;
  for (let v = 0; v < nV; v++) start[v + 1] += start[v];
  const fill = start.slice(0, nV);
  const face = new Int32Array(tri.length);
  for (let c = 0; c < tri.length; c++) face[fill[tri[c]]++] = (c / 3) | 0;
  return { of: (v) => face.subarray(start[v], start[v + 1]) };
}

/** A test that is true for a face with the same vertex set as an earlier face (call in face order). */
function duplicateFaceTest(tri: Uint32Array): (f: number) => boolean {
  const nF = tri.length / 3;
  let size = 1;
  while (size < 2 * nF) size *= 2;
  const mask = size - 1;
  const table = new Int32Array(size).fill(-1);
  const sorted = new Uint32Array(6);
  const sort3 = (f: number, o: number) => {
    let a = tri[3 * f], b = tri[3 * f + 1], c = tri[3 * f + 2], t;
    if (a > b) { t = a; a = b; b = t; }
    if (b > c) { t = b; b = c; c = t; }
    if (a > b) { t = a; a = b; b = t; }
    sorted[o] = a; sorted[o + 1] = b; sorted[o + 2] = c;
  };
  return (f) => {
    sort3(f, 0);
    let s = (Math.imul(sorted[0], 0x9e3779b1) ^ Math.imul(sorted[1], 0x85ebca6b) ^ Math.imul(sorted[2], 0xc2b2ae35)) & mask;
    for (let g = table[s]; g >= 0; g = table[s]) {
      sort3(g, 3);
      if (sorted[0] === sorted[3] && sorted[1] === sorted[4] && sorted[2] === sorted[5]) return true;
      s = (s + 1) & mask;
    }
    table[s] = f;
    return false;
  };
}

/** Drops the faces `remove` is true for (asked in face order); the others keep their order. */
function removeFaces(tri: Uint32Array, remove: (f: number) => boolean): { tri: Uint32Array; removed: number } {
  const nF = tri.length / 3;
  const out = new Uint32Array(tri.length);
  let n = 0;
  for (let f = 0; f < nF; f++) {
    if (remove(f)) continue;
    out[3 * n] = tri[3 * f];
    out[3 * n + 1] = tri[3 * f + 1];
    out[3 * n + 2] = tri[3 * f + 2];
    n++;
  }
  return { tri: n === nF ? tri : out.slice(0, 3 * n), removed: nF - n };
}

/**
 * Undirected edges of a triangle list. Corner c = 3f + k stands for the half-edge from tri[c] to the
 * next corner of face f. The corners of edge e are edgeCorners[edgeStart[e] .. edgeStart[e + 1]), in
 * face order. Built by grouping half-edges by their smaller vertex (a counting sort): no hashing.
 */
interface Edges {
  edgeOf: Int32Array;
  edgeStart: Int32Array;
  edgeCorners: Int32Array;
  hasNonManifoldEdge: boolean;
}

const next = (c: number) => (c % 3 === 2 ? c - 2 : c + 1);

function buildEdges(tri: Uint32Array, nV: number): Edges {
  const corners = tri.length;
  const byLow = new Int32Array(nV + 1);
  for (let c = 0; c < corners; c++) byLow[Math.min(tri[c], tri[next(c)]) + 1]++;
  for (let v = 0; v < nV; v++) byLow[v + 1] += byLow[v];
  const fill = byLow.slice(0, nV);
  const order = new Int32Array(corners);
  for (let c = 0; c < corners; c++) order[fill[Math.min(tri[c], tri[next(c)])]++] = c;

  const edgeOf = new Int32Array(corners);
  const stamp = new Int32Array(nV).fill(-1);
  const edgeForHigh = new Int32Array(nV);
  let edgeCount = 0;
  for (let v = 0; v < nV; v++) {
    for (let i = byLow[v]; i < byLow[v + 1]; i++) {
      const c = order[i];
      const high = Math.max(tri[c], tri[next(c)]);
      if (stamp[high] !== v) {
        stamp[high] = v;
        edgeForHigh[high] = edgeCount++;
      }
      edgeOf[c] = edgeForHigh[high];
    }
  }
  const edgeStart = new Int32Array(edgeCount + 1);
  for (let c = 0; c < corners; c++) edgeStart[edgeOf[c] + 1]++;
  let hasNonManifoldEdge = false;
  for (let e = 0; e < edgeCount; e++) {
    if (edgeStart[e + 1] > 2) hasNonManifoldEdge = true;
    edgeStart[e + 1] += edgeStart[e];
  }
  const at = edgeStart.slice(0, edgeCount);
  const edgeCorners = new Int32Array(corners);
  for (let c = 0; c < corners; c++) edgeCorners[at[edgeOf[c]]++] = c;
  return { edgeOf, edgeStart, edgeCorners, hasNonManifoldEdge };
}

/**
 * Joins the corners of each vertex across edges into fans, then gives every fan of a vertex but the
 * first (in face order) a copy of it, renumbering `tri` in place. Edges with two faces always join
 * them; at an edge with more faces, 'keep-pair' joins one pair (the first running along it in
 * opposite directions, else the first two) and 'cut-all' joins none.
 */
function splitNonManifold(tri: Uint32Array, edges: Edges, nV: number, mode: 'keep-pair' | 'cut-all') {
  const { edgeStart, edgeCorners } = edges;
  const corners = tri.length;
  const fans = new UnionFind(corners);
  const cornerAt = (c: number, v: number) => (tri[c] === v ? c : next(c));
  const join = (c1: number, c2: number) => {
    fans.union(cornerAt(c1, tri[c1]), cornerAt(c2, tri[c1]));
    fans.union(cornerAt(c1, tri[next(c1)]), cornerAt(c2, tri[next(c1)]));
  };
  const onCutEdge = new Uint8Array(nV);
  const nonManifold: number[][] = []; // the corners of each edge with more than two faces
  for (let e = 0; e + 1 < edgeStart.length; e++) {
    const first = edgeStart[e], n = edgeStart[e + 1] - first;
    if (n === 2) join(edgeCorners[first], edgeCorners[first + 1]);
    if (n <= 2) continue;
    const around = Array.from(edgeCorners.subarray(first, first + n));
    nonManifold.push(around);
    onCutEdge[tri[around[0]]] = onCutEdge[tri[next(around[0])]] = 1;
    if (mode === 'cut-all') continue;
    let pair = [around[0], around[1]];
    search: for (let i = 0; i < n; i++) {
      for (let j = i + 1; j < n; j++) {
        if (tri[around[i]] === tri[next(around[j])]) {
          pair = [around[i], around[j]];
          break search;
        }
      }
    }
    join(pair[0], pair[1]);
  }

  // The first fan of each vertex keeps it; every other fan gets a new vertex.
  const fanVertex = new Int32Array(corners).fill(-1);
  const taken = new Uint8Array(nV);
  const split = new Uint8Array(nV);
  const copyOf: number[] = [];
  let edgeCopies = 0, pointCopies = 0, pointVertices = 0;
  for (let c = 0; c < corners; c++) {
    const root = fans.find(c), v = tri[c];
    if (fanVertex[root] < 0) {
      if (!taken[v]) {
        taken[v] = 1;
        fanVertex[root] = v;
      } else {
        fanVertex[root] = nV + copyOf.length;
        copyOf.push(v);
        if (onCutEdge[v]) edgeCopies++;
        else {
          pointCopies++;
          if (!split[v]) pointVertices++;
          split[v] = 1;
        }
      }
    }
    tri[c] = fanVertex[root];
  }
  return { copyOf, nonManifold, edgeCopies, pointCopies, pointVertices };
}

/**
 * Orients faces consistently within each connected component (across edges with two faces), flipping
 * the minority, then makes each closed component face outward, or inward when it is a cavity (inside
 * an odd number of other closed components). Components that cannot be oriented (a Moebius strip)
 * are left as they are for the core to report. Flips faces in `tri` in place.
 */
function orient(pos: Float64Array, tri: Uint32Array, edges: Edges) {
  const { edgeOf, edgeStart, edgeCorners } = edges;
  const nF = tri.length / 3;
  const sign = new Int8Array(nF); // +1 keep, -1 flip, 0 not reached yet
  const queue = new Int32Array(nF);
  const components: { start: number; end: number; closed: boolean }[] = [];
  let flippedToAgree = 0;
  let head = 0, tail = 0;
  for (let root = 0; root < nF; root++) {
    if (sign[root] !== 0) continue;
    const start = tail;
    sign[root] = 1;
    queue[tail++] = root;
    let closed = true, orientable = true;
    while (head < tail) {
      const f = queue[head++];
      for (let c = 3 * f; c < 3 * f + 3; c++) {
        const e = edgeOf[c];
        if (edgeStart[e + 1] - edgeStart[e] !== 2) {
          closed = false;
          continue;
        }
        const other = edgeCorners[edgeStart[e]] === c ? edgeCorners[edgeStart[e] + 1] : edgeCorners[edgeStart[e]];
        const g = (other / 3) | 0;
        // Neighbours agree when they run along the shared edge in opposite directions.
        const want = tri[c] === tri[next(other)] ? sign[f] : -sign[f];
        if (sign[g] === 0) {
          sign[g] = want;
          queue[tail++] = g;
        } else if (sign[g] !== want) orientable = false;
      }
    }
    if (!orientable) {
      for (let i = start; i < tail; i++) sign[queue[i]] = 1;
      continue;
    }
    let minus = 0;
    for (let i = start; i < tail; i++) if (sign[queue[i]] < 0) minus++;
    if (2 * minus > tail - start) for (let i = start; i < tail; i++) sign[queue[i]] = -sign[queue[i]];
    flippedToAgree += Math.min(minus, tail - start - minus);
    components.push({ start, end: tail, closed });
  }
  for (let f = 0; f < nF; f++) if (sign[f] < 0) flipFace(tri, f);

  // Every depth is measured before any component is reversed: the winding numbers see one state.
  const closed = components.filter((c) => c.closed).map((c) => {
    const faces = queue.subarray(c.start, c.end);
    const box = componentBox(pos, tri, faces);
    return { faces, box, volume: signedVolume(pos, tri, faces, box) };
  }).filter((c) => Math.abs(c.volume) > FLAT_VOLUME * boxDiagonal(c.box) ** 3);
  const boxesAround = boxIndex(closed.map((c) => c.box));
  const mesh = { positions: pos, triangles: tri };
  const reverse = closed.filter((c, i) => {
    // Components may touch: one point could lie on another's surface, so a few points vote.
    const points = samplePoints(pos, tri, c.faces);
    const votes = new Map<number, number>();
    for (const p of points) {
      for (const j of boxesAround(p)) {
        if (j !== i && Math.abs(windingNumber(mesh, p, closed[j].faces)) > 0.5) votes.set(j, (votes.get(j) ?? 0) + 1);
      }
    }
    let depth = 0;
    for (const n of votes.values()) if (2 * n > points.length) depth++;
    return c.volume > 0 !== (depth % 2 === 0);
  });
  let reversedFaces = 0;
  for (const c of reverse) {
    for (const f of c.faces) flipFace(tri, f);
    reversedFaces += c.faces.length;
  }
  return { flippedToAgree, reversedComponents: reverse.length, reversedFaces };
}

type Box = [number, number, number, number, number, number];

/** Centroids of up to INSIDE_VOTES faces spread over the list. */
function samplePoints(pos: Float64Array, tri: Uint32Array, faces: Int32Array): number[][] {
  const n = Math.min(INSIDE_VOTES, faces.length);
  return Array.from({ length: n }, (_, i) => {
    const f = faces[Math.floor((i * faces.length) / n)];
    return [0, 1, 2].map((k) => (pos[3 * tri[3 * f] + k] + pos[3 * tri[3 * f + 1] + k] + pos[3 * tri[3 * f + 2] + k]) / 3);
  });
}

function componentBox(pos: Float64Array, tri: Uint32Array, faces: Int32Array): Box {
  const box: Box = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (const f of faces) {
    for (let c = 3 * f; c < 3 * f + 3; c++) {
      for (let k = 0; k < 3; k++) {
        const x = pos[3 * tri[c] + k];
        if (x < box[k]) box[k] = x;
        if (x > box[k + 3]) box[k + 3] = x;
      }
    }
  }
  return box;
}

function boxDiagonal(box: Box): number {
  return Math.hypot(box[3] - box[0], box[4] - box[1], box[5] - box[2]);
}

/**
 * The boxes that contain a point, found on a uniform grid over all of them with about one cell per box,
 * so that many small components cost little more than one each.
 */
function boxIndex(boxes: Box[]): (p: number[]) => number[] {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const b of boxes) {
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], b[k]);
      hi[k] = Math.max(hi[k], b[k + 3]);
    }
  }
  const r = Math.max(1, Math.round(Math.cbrt(boxes.length)));
  const cell = (x: number, k: number) => Math.min(r - 1, Math.max(0, Math.floor(((x - lo[k]) / (hi[k] - lo[k] || 1)) * r)));
  const cells: number[][] = Array.from({ length: r ** 3 }, () => []);
  boxes.forEach((b, i) => {
    for (let x = cell(b[0], 0); x <= cell(b[3], 0); x++) {
      for (let y = cell(b[1], 1); y <= cell(b[4], 1); y++) {
        for (let z = cell(b[2], 2); z <= cell(b[5], 2); z++) cells[(x * r + y) * r + z].push(i);
      }
    }
  });
  return (p) => cells[(cell(p[0], 0) * r + cell(p[1], 1)) * r + cell(p[2], 2)].filter((i) => inBox(p, boxes[i]));
}

function inBox(p: number[], box: Box): boolean {
  return p[0] >= box[0] && p[1] >= box[1] && p[2] >= box[2] && p[0] <= box[3] && p[1] <= box[4] && p[2] <= box[5];
}

/** Volume enclosed by the faces (positive when they face outward), about the box centre to limit cancellation. */
function signedVolume(pos: Float64Array, tri: Uint32Array, faces: Int32Array, box: Box): number {
  const o = [(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2];
  let sixTimes = 0;
  for (const f of faces) {
    const a = 3 * tri[3 * f], b = 3 * tri[3 * f + 1], c = 3 * tri[3 * f + 2];
    const ax = pos[a] - o[0], ay = pos[a + 1] - o[1], az = pos[a + 2] - o[2];
    const bx = pos[b] - o[0], by = pos[b + 1] - o[1], bz = pos[b + 2] - o[2];
    const cx = pos[c] - o[0], cy = pos[c + 1] - o[1], cz = pos[c + 2] - o[2];
    sixTimes += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  }
  return sixTimes / 6;
}

function flipFace(tri: Uint32Array, f: number): void {
  const t = tri[3 * f + 1];
  tri[3 * f + 1] = tri[3 * f + 2];
  tri[3 * f + 2] = t;
}
