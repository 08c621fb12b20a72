/** Growable vertex and triangle arrays shared by the parsers, with fan triangulation of polygons. */
import { MeshFormatError, type MeshFormat, type ParsedMesh, type ShapeFormat } from './types.ts';

/** How each format names itself at the start of error messages and warnings. */
export const FORMAT_LABEL: Record<ShapeFormat, string> = { obj: 'OBJ', ply: 'PLY', stl: 'STL', off: 'OFF', glb: 'GLB', xyz: 'XYZ' };

export class MeshBuilder {
  private positions: Float64Array;
  private triangles: Uint32Array;
  private positionCount = 0;
  private triangleIndexCount = 0;
  /** Polygons with more than three vertices, split into triangle fans. */
  private polygonsSplit = 0;

  /** Capacity hints avoid regrowing when the header states the counts. */
  constructor(
    readonly format: MeshFormat,
    vertexHint = 1024,
    triangleHint = 1024,
  ) {
    this.positions = new Float64Array(Math.max(3, 3 * Math.ceil(vertexHint)));
    this.triangles = new Uint32Array(Math.max(3, 3 * Math.ceil(triangleHint)));
  }

  get vertexCount(): number {
    return this.positionCount / 3;
  }

  get triangleCount(): number {
    return this.triangleIndexCount / 3;
  }

  /** The vertices so far, x y z interleaved (for a file that turns out to be a point cloud). */
  vertices(): Float64Array {
    return trim(this.positions, this.positionCount);
  }

  addVertex(x: number, y: number, z: number): void {
    if (this.positionCount + 3 > this.positions.length) this.positions = grow(this.positions);
    const p = this.positions;
    const n = this.positionCount;
    p[n] = x;
    p[n + 1] = y;
    p[n + 2] = z;
    this.positionCount = n + 3;
  }

  /** Indices must already be checked to be vertex indices (integers in range). */
  addTriangle(a: number, b: number, c: number): void {
    if (this.triangleIndexCount + 3 > this.triangles.length) this.triangles = grow(this.triangles);
    const t = this.triangles;
    const n = this.triangleIndexCount;
    t[n] = a;
    t[n + 1] = b;
    t[n + 2] = c;
    this.triangleIndexCount = n + 3;
  }

  /** Adds polygon `p = poly[start..start + n)` (n >= 3) as the fan (p0, p[i], p[i+1]), which keeps its orientation. */
  addPolygon(poly: ArrayLike<number>, n: number, start = 0): void {
    if (n > 3) this.polygonsSplit++;
    const first = poly[start];
    for (let i = start + 1; i + 1 < start + n; i++) this.addTriangle(first, poly[i], poly[i + 1]);
  }

  /** Checks that there is something to return and trims the arrays to size. */
  finish(warnings: string[] = []): ParsedMesh {
    const label = FORMAT_LABEL[this.format];
    if (this.positionCount === 0) throw new MeshFormatError(`${label}: no vertices in file`);
    if (this.triangleIndexCount === 0) throw new MeshFormatError(`${label}: no faces in file`);
    if (this.polygonsSplit > 0) {
      warnings.push(`split ${this.polygonsSplit} polygons with more than 3 vertices into triangles`);
    }
    return {
      kind: 'mesh',
      positions: this.vertices(),
      triangles: trim(this.triangles, this.triangleIndexCount),
      format: this.format,
      warnings,
    };
  }
}

export function grow<T extends Float64Array | Float32Array | Uint32Array>(array: T): T {
  const bigger = new (array.constructor as new (n: number) => T)(array.length * 2);
  bigger.set(array);
  return bigger;
}

export function trim<T extends Float64Array | Float32Array | Uint32Array>(array: T, length: number): T {
  return (length === array.length ? array : array.slice(0, length)) as T;
}
