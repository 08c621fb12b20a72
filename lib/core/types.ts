/** Types of the CSCD core as seen from TypeScript (CLI, worker, tests). */

/** An indexed triangle mesh: xyz per vertex, three vertex indices per triangle. */
export interface MeshArrays {
  positions: Float64Array | Float32Array;
  triangles: Uint32Array;
}

/** A point on the surface: a face of the input mesh and barycentric coordinates in it. */
export interface SurfacePoint {
  face: number;
  barycentric: [number, number, number];
}

/** Facts about a mesh, computed without requiring it to be manifold. */
export interface MeshFacts {
  vertices: number;
  faces: number;
  edges: number;
  /** Connected components of the faces (vertices referenced by no face are not counted). */
  components: number;
  boundaryLoops: number;
  /** V - E + F over the referenced vertices. */
  eulerCharacteristic: number;
  /** Sum over components of (2 - chi - boundary loops) / 2; null when the mesh is not manifold. */
  genus: number | null;
  manifold: boolean;
  /** Every edge shared by two faces is traversed in opposite directions by them. */
  consistentlyOriented: boolean;
  nonManifoldEdges: number;
  nonManifoldVertices: number;
  unreferencedVertices: number;
  /** Faces that repeat a vertex or have (near) zero area. */
  degenerateFaces: number;
  bboxMin: [number, number, number];
  bboxMax: [number, number, number];
  bboxDiagonal: number;
  meanEdgeLength: number;
}

/** Per-mesh state kept in the core: prefactored geodesic solver on the intrinsic Delaunay triangulation. */
export interface Surface {
  readonly facts: MeshFacts;
  /** Geodesic distance (heat method) from one vertex to every vertex. */
  distanceFromVertex(vertex: number): Float64Array;
  /** Exact polyhedral geodesic distance (MMP) from one vertex: slower, the reference for the heat method. */
  exactDistanceFromVertex(vertex: number): Float64Array;
  /** Geodesic distance from the nearest of a set of surface points to every vertex. */
  distanceFromPoints(points: SurfacePoint[]): Float64Array;
  /** Frees the WASM-side object; the Surface must not be used afterwards. */
  dispose(): void;
}

export interface Core {
  /** Checks the arrays (throws CoreError on empty input, bad indices, NaN/Inf) and reports mesh facts. */
  inspect(mesh: MeshArrays): MeshFacts;
  /** Builds the per-mesh state; throws CoreError when the mesh cannot be processed (e.g. non-manifold). */
  openSurface(mesh: MeshArrays): Surface;
}

/** An error the core reports about its input or a computation: its message is meant for the user. */
export class CoreError extends Error {
  override name = 'CoreError';
}
