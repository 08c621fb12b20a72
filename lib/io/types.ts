import type { CloudArrays } from '../core/types.ts';

/** The arrays of a point cloud: declared with the core's types, which take them. */
export type { CloudArrays };

/** Mesh file formats read by CSCD Studio (CLI and page alike). */
export type MeshFormat = 'obj' | 'ply' | 'stl' | 'off' | 'glb';

/** Point-cloud formats: PLY and OBJ files with vertices and no faces, and text lists of coordinates. */
export type CloudFormat = 'ply' | 'obj' | 'xyz';

export type ShapeFormat = MeshFormat | CloudFormat;

export interface ParsedMesh {
  kind: 'mesh';
  positions: Float64Array;
  triangles: Uint32Array;
  format: MeshFormat;
  /** Things the parser did that the user should know (polygons triangulated, STL vertices merged...). */
  warnings: string[];
}

export interface ParsedCloud extends CloudArrays {
  kind: 'cloud';
  format: CloudFormat;
  /** Things the parser did that the user should know (columns ignored, normals not read...). */
  warnings: string[];
}

/** What a file holds: a mesh or a point cloud. */
export type ParsedShape = ParsedMesh | ParsedCloud;

/** A file that cannot be read as a mesh or a point cloud: its message is one clear line for the user. */
export class MeshFormatError extends Error {
  override name = 'MeshFormatError';
}
