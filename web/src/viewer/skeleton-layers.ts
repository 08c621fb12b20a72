/**
 * The viewer layers of a whole-shape run: candidate loops (as they arrive, then by fate), the packed
 * loops, per-vertex region colours and the curve skeleton (nodes as spheres, edges as tubes).
 */
import * as THREE from 'three';
import type { SkeletonData } from '../worker/protocol.ts';
import { COLORS } from '../stage-defs.ts';
import { turbo } from './colormap.ts';
import { DIM_GREY, DIM_MIX, SpheresLayer, type Layer, type ShapeLayer } from './layers.ts';
import { TubesLayer, graphSegments, liftOffSurface, polylineSegments } from './tubes.ts';
import type { NamedLayer } from './separator-layers.ts';

/** Sizes as fractions of the mesh's bounding-sphere radius. */
const RADIUS = { candidate: 0.0042, rejected: 0.0036, packed: 0.0072, edge: 0.0105, minNode: 0.016 };
/** Node spheres are drawn at this fraction of their radius (the full radius hides the skeleton in a blob). */
const NODE_SCALE = 0.27;

/**
 * Above this many segments a loop layer is drawn as lines instead of tubes: software renderers
 * (headless browsers, machines without a GPU) take seconds for a frame of hundreds of thousands of
 * tube triangles, and the page waits for every frame.
 */
const TUBE_SEGMENT_BUDGET = 6000;

/** Loops as thin tube segments (or lines, when there are very many) lifted off the surface. */
export class LoopSet {
  private readonly segments: Float32Array[] = [];

  constructor(
    private readonly surface: ShapeLayer,
    private readonly lift: number,
  ) {}

  /** `closed` false: an open path ending on the mesh boundary. */
  add(loop: Float32Array, closed: boolean): void {
    if (loop.length < (closed ? 9 : 6)) return; // failed source (empty) or degenerate
    const lifted = liftOffSurface(loop, this.surface, this.lift);
    this.segments.push(polylineSegments(lifted, closed));
  }

  get count(): number {
    return this.segments.length;
  }

  layer(label: string, color: string, radius: number): Layer {
    const segments = concat(this.segments);
    if (segments.length / 6 > TUBE_SEGMENT_BUDGET) return new LinesLayer(label, segments, color);
    // No joint balls: at a few pixels wide the corners do not show, and balls would triple the triangles.
    return new TubesLayer(label, segments, new Float32Array(0), { color, radius, detail: 'low' });
  }
}

/** Line segments (two xyz points each) in one colour, dimmable. */
export class LinesLayer implements Layer {
  readonly object: THREE.LineSegments<THREE.BufferGeometry, THREE.LineBasicMaterial>;
  private readonly color: THREE.Color;

  constructor(
    readonly label: string,
    segments: Float32Array,
    color: THREE.ColorRepresentation,
  ) {
    this.color = new THREE.Color(color);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(segments, 3));
    geometry.computeBoundingSphere();
    this.object = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: this.color }));
  }

  setDimmed(dimmed: boolean): void {
    this.object.material.color.copy(this.color);
    if (dimmed) this.object.material.color.lerp(DIM_GREY, DIM_MIX);
  }

  dispose(): void {
    this.object.geometry.dispose();
    this.object.material.dispose();
  }
}

/** Arrays one after the other in one array. */
export function concat(parts: Float32Array[]): Float32Array {
  const out = new Float32Array(parts.reduce((n, p) => n + p.length, 0));
  let at = 0;
  for (const p of parts) {
    out.set(p, at);
    at += p.length;
  }
  return out;
}

/** The tube radius (world units) of the progressive candidate loops. */
export function candidateRadius(surface: ShapeLayer): number {
  return RADIUS.candidate * surface.boundingSphere.radius;
}

/**
 * Layers of a finished run: `sk-rejected`, `sk-packed`, `sk-edges`, `sk-nodes` (those with data), built
 * one per iteration so the caller can let the page breathe in between (lifting hundreds of loops off
 * the surface takes a while on a large mesh).
 */
export function* skeletonLayers(s: SkeletonData, surface: ShapeLayer): Generator<NamedLayer> {
  const R = surface.boundingSphere.radius;
  for (const [name, label, packed, radius, color] of [
    ['sk-rejected', 'Rejected loops', false, RADIUS.rejected, COLORS.rejected],
    ['sk-packed', 'Packed loops', true, RADIUS.packed, COLORS.packed],
  ] as const) {
    const loops = new LoopSet(surface, radius * R * 0.6);
    s.candidates.loops.forEach((loop, i) => {
      if ((s.candidates.fates[i] === 'packed') === packed) loops.add(loop, s.candidates.closed[i] === 1);
    });
    if (loops.count > 0) yield { name, layer: loops.layer(label, color, radius * R), color };
  }

  if (s.edges.length >= 2) {
    yield {
      name: 'sk-edges',
      layer: new TubesLayer('Skeleton edges', graphSegments(s.nodes, s.edges), new Float32Array(0), {
        color: COLORS.edge,
        radius: RADIUS.edge * R,
        glow: 0.25,
      }),
      color: COLORS.edge,
    };
  }
  if (s.nodes.length >= 3) {
    yield { name: 'sk-nodes', layer: new SpheresLayer('Skeleton nodes', s.nodes, nodeRadii(s, R), COLORS.node), color: COLORS.node };
  }
}

/** Drawn node radii: the node's radius scaled, never thinner than the edges (branch nodes may have none). */
export function nodeRadii(s: SkeletonData, boundingRadius: number): Float32Array {
  const nodeCount = Math.floor(s.nodes.length / 3);
  const min = RADIUS.minNode * boundingRadius;
  const max = 0.25 * boundingRadius;
  return Float32Array.from({ length: nodeCount }, (_, i) => {
    const r = s.radii[i];
    return Number.isFinite(r) && r > 0 ? Math.min(max, Math.max(min, r * NODE_SCALE)) : min;
  });
}

/** A distinct colour per region (golden-ratio hues, three lightness levels), as sRGB hex strings. */
export function regionColor(i: number): string {
  const hue = (i * 0.618033988749895 + 0.05) % 1;
  const lightness = [0.58, 0.47, 0.68][i % 3];
  return `#${new THREE.Color().setHSL(hue, 0.68, lightness, THREE.SRGBColorSpace).getHexString(THREE.SRGBColorSpace)}`;
}

/** Linear RGB per vertex from its region (vertices of no region in a neutral grey). */
export function regionVertexColors(vertexToNode: Uint32Array, nodeCount: number, vertexCount: number): Float32Array {
  const palette = Array.from({ length: nodeCount }, (_, i) => new THREE.Color(regionColor(i)));
  const none = new THREE.Color(0x8a8780);
  const out = new Float32Array(3 * vertexCount);
  for (let v = 0; v < vertexCount; v++) {
    const node = v < vertexToNode.length ? vertexToNode[v] : nodeCount;
    const c = node < nodeCount ? palette[node] : none;
    out[3 * v] = c.r;
    out[3 * v + 1] = c.g;
    out[3 * v + 2] = c.b;
  }
  return out;
}

/**
 * Part of the surface (the triangles of a selected region) drawn over the see-through surface in its
 * region's colour, so it reads as solid. Shares the surface's vertex buffers; only the index is its own.
 */
export class RegionLayer implements Layer {
  readonly object: THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial>;

  constructor(
    readonly label: string,
    surface: THREE.BufferGeometry,
    triangles: Uint32Array,
    color: THREE.ColorRepresentation,
  ) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', surface.getAttribute('position'));
    geometry.setAttribute('normal', surface.getAttribute('normal'));
    geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
    geometry.boundingSphere = surface.boundingSphere;
    const material = new THREE.MeshStandardMaterial({
      color,
      roughness: 0.6,
      emissive: color,
      emissiveIntensity: 0.2,
      transparent: true,
      opacity: 0.62,
      depthWrite: false,
      side: THREE.DoubleSide,
    });
    this.object = new THREE.Mesh(geometry, material);
    this.object.renderOrder = 5; // over the see-through surface, under the glass halo
  }

  dispose(): void {
    // Let go of the shared buffers first: disposing frees the buffers of the attributes still held.
    const geometry = this.object.geometry;
    geometry.deleteAttribute('position');
    geometry.deleteAttribute('normal');
    geometry.dispose();
    this.object.material.dispose();
  }
}

/** The triangles whose three corners all belong to `node`'s region. */
export function regionTriangles(triangles: ArrayLike<number>, vertexToNode: Uint32Array, node: number): Uint32Array {
  const out: number[] = [];
  for (let t = 0; t + 2 < triangles.length; t += 3) {
    const a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    if (vertexToNode[a] === node && vertexToNode[b] === node && vertexToNode[c] === node) out.push(a, b, c);
  }
  return Uint32Array.from(out);
}

/** The skeleton's reconstructed (convolution) surface: a see-through shell over the input mesh. */
export class ReconstructionLayer implements Layer {
  readonly object: THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial>;

  constructor(
    readonly label: string,
    positions: Float32Array,
    triangles: Uint32Array,
  ) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
    geometry.computeVertexNormals();
    geometry.computeBoundingSphere();
    const material = new THREE.MeshStandardMaterial({
      color: COLORS.reconstruction,
      roughness: 0.5,
      transparent: true,
      opacity: 0.3,
      depthWrite: false,
      side: THREE.DoubleSide,
    });
    this.object = new THREE.Mesh(geometry, material);
  }

  dispose(): void {
    this.object.geometry.dispose();
    this.object.material.dispose();
  }
}

/** Linear RGB per vertex from its reconstruction error through the colormap, 0 to `max`. */
export function errorVertexColors(errors: Float32Array, max: number): Float32Array {
  const out = new Float32Array(3 * errors.length);
  const color = new THREE.Color();
  for (let v = 0; v < errors.length; v++) {
    const [r, g, b] = turbo(max > 0 ? errors[v] / max : 0);
    color.setRGB(r, g, b, THREE.SRGBColorSpace);
    out[3 * v] = color.r;
    out[3 * v + 1] = color.g;
    out[3 * v + 2] = color.b;
  }
  return out;
}
