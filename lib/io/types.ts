/** Mesh file formats read by CSCD Studio (CLI and page alike). */
export type MeshFormat = 'obj' | 'ply' | 'stl' | 'off' | 'glb';

export interface ParsedMesh {
  positions: Float64Array;
  triangles: Uint32Array;
  format: MeshFormat;
  /** Things the parser did that the user should know (polygons triangulated, STL vertices merged...). */
  warnings: string[];
}

/** A file that cannot be read as a mesh: its message is one clear line for the user. */
export class MeshFormatError extends Error {
  override name = 'MeshFormatError';
}
