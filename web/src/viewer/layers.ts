/**
 * Things the viewer draws. Each layer owns one Object3D and its GPU resources; the viewer keeps
 * them by name (surface, source marker, and later cut locus polylines, skeleton points, spheres).
 */
import * as THREE from 'three';
import { colormapTexture, turbo } from './colormap.ts';

export interface Layer {
  /** Shown in the layer list. */
  readonly label: string;
  readonly object: THREE.Object3D;
  /** Drawn muted (a layer of an earlier stage than the one shown). */
  setDimmed?(dimmed: boolean): void;
  dispose(): void;
}

/** The grey that dimmed layers are mixed towards, and how far. */
export const DIM_GREY = new THREE.Color(0x8f8b84);
export const DIM_MIX = 0.62;

const BASE_COLOR = 0xc4c0b8;
/** The surface's colour while translucent: cool and light, so a warm skeleton inside stands out. */
const TRANSLUCENT_COLOR = 0xdfe8f5;

/** Values below this in the scalar attribute mean "no value" (drawn in the base colour). */
const NO_VALUE = -1;

export interface ScalarField {
  /** One value per vertex; non-finite values are drawn as "no value". */
  values: Float32Array;
  /** Value mapped to the top of the colormap (the bottom is 0). */
  max: number;
  /** Distance between isolines in value units; 0 for none. */
  isolineSpacing: number;
}

/** What a mesh's surface and a cloud's points share: positions in one geometry, and its bounds. */
abstract class PositionsLayer {
  readonly geometry = new THREE.BufferGeometry();

  get vertexCount(): number {
    return this.geometry.getAttribute('position').count;
  }

  get boundingSphere(): THREE.Sphere {
    return this.geometry.boundingSphere!;
  }

  vertexPosition(index: number, target = new THREE.Vector3()): THREE.Vector3 {
    return target.fromBufferAttribute(this.geometry.getAttribute('position') as THREE.BufferAttribute, index);
  }
}

/**
 * The triangle mesh, lit with a matte MeshStandardMaterial, optionally coloured by a per-vertex
 * scalar field through a colormap with anti-aliased isolines (patched into the standard shader).
 */
export class SurfaceLayer extends PositionsLayer implements Layer {
  readonly label = 'Surface';
  readonly object: THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial>;
  private readonly uniforms = {
    scalarLut: { value: colormapTexture() },
    scalarMax: { value: 0 },
    isoSpacing: { value: 0 },
    isoStrength: { value: 0.75 },
    scalarDim: { value: 0 },
    regionCenter: { value: new THREE.Vector3() },
    regionRadius: { value: 0 },
    regionTint: { value: new THREE.Color(0x6fa8ff) },
    regionStrength: { value: 0 },
    /** 0..1: how much the per-vertex `regionColor` replaces the surface colour. */
    regionColorMix: { value: 0 },
    /** 1: see-through, more opaque where the surface is seen edge-on (the skeleton shows inside). */
    translucent: { value: 0 },
  };
  private scalarShown = true;
  private grid: VertexGrid | null = null;
  private isolines = true;
  private field: ScalarField | null = null;

  constructor(positions: Float32Array, triangles: Uint32Array) {
    super();
    this.geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    this.geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
    this.geometry.setAttribute('scalar', new THREE.BufferAttribute(new Float32Array(positions.length / 3).fill(NO_VALUE), 1));
    this.geometry.setAttribute('regionColor', new THREE.BufferAttribute(new Float32Array(positions.length), 3));
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingSphere();

    const material = new THREE.MeshStandardMaterial({
      color: BASE_COLOR,
      roughness: 0.62,
      metalness: 0.0,
      side: THREE.DoubleSide,
      polygonOffset: true, // lets later line layers on the surface win the depth test
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    material.onBeforeCompile = (shader) => {
      Object.assign(shader.uniforms, this.uniforms);
      shader.vertexShader = shader.vertexShader
        .replace(
          '#include <common>',
          '#include <common>\nattribute float scalar;\nattribute vec3 regionColor;\nvarying float vScalar;\nvarying vec3 vWorld;\nvarying vec3 vRegionColor;',
        )
        .replace(
          '#include <begin_vertex>',
          '#include <begin_vertex>\nvScalar = scalar;\nvRegionColor = regionColor;\nvWorld = (modelMatrix * vec4(transformed, 1.0)).xyz;',
        );
      shader.fragmentShader = shader.fragmentShader
        .replace(
          '#include <common>',
          `#include <common>
uniform sampler2D scalarLut;
uniform float scalarMax;
uniform float isoSpacing;
uniform float isoStrength;
uniform float scalarDim;
uniform vec3 regionCenter;
uniform float regionRadius;
uniform vec3 regionTint;
uniform float regionStrength;
uniform float regionColorMix;
uniform float translucent;
varying float vScalar;
varying vec3 vWorld;
varying vec3 vRegionColor;`,
        )
        .replace(
          '#include <color_fragment>',
          `#include <color_fragment>
if (scalarMax > 0.0 && vScalar >= 0.0) {
  float t = clamp(vScalar / scalarMax, 0.0, 1.0);
  vec3 c = texture2D(scalarLut, vec2(t * (255.0 / 256.0) + 0.5 / 256.0, 0.5)).rgb;
  if (isoSpacing > 0.0) {
    float v = vScalar / isoSpacing;
    float w = max(fwidth(v), 1e-6);
    float d = abs(fract(v + 0.5) - 0.5);                  // distance to the nearest isoline, in v units
    float line = 1.0 - smoothstep(0.6 * w, 1.6 * w, d);   // about 1.5 px wide, anti-aliased
    c = mix(c, c * 0.12, line * isoStrength);
  }
  // Dimmed: mostly a light grey carrying a hint of the colormap, so lines drawn on it stand out.
  float lum = dot(c, vec3(0.2126, 0.7152, 0.0722));
  c = mix(c, mix(diffuseColor.rgb, vec3(lum) * 0.45 + 0.42, 0.55), scalarDim * 0.7);
  diffuseColor.rgb = c;
}
if (regionRadius > 0.0 && regionStrength > 0.0) {
  // A region given by a sphere (the constraint region): tinted inside, outlined where it meets the surface.
  float r = length(vWorld - regionCenter) - regionRadius;
  float w = max(fwidth(r), 1e-6);
  float inside = 1.0 - smoothstep(-w, w, r);
  float edge = 1.0 - smoothstep(1.0 * w, 2.5 * w, abs(r));
  diffuseColor.rgb = mix(diffuseColor.rgb, diffuseColor.rgb * 0.55 + regionTint * 0.45, inside * regionStrength * 0.8);
  diffuseColor.rgb = mix(diffuseColor.rgb, regionTint * 0.35, edge * regionStrength);
}
if (regionColorMix > 0.0) diffuseColor.rgb = mix(diffuseColor.rgb, vRegionColor, regionColorMix);`,
        )
        .replace(
          '#include <opaque_fragment>',
          `if (translucent > 0.0) {
  // X-ray look: faint where the surface faces the camera, denser towards the silhouette.
  float facing = abs(dot(normalize(normal), normalize(vViewPosition)));
  diffuseColor.a = mix(0.62, 0.07, smoothstep(0.0, 0.9, facing));
}
#include <opaque_fragment>`,
        );
    };
    material.customProgramCacheKey = () => 'cscd-scalar-surface';
    this.object = new THREE.Mesh(this.geometry, material);
    this.object.name = 'surface';
  }

  /** The vertex nearest to a point in space (for placing markers and lifting lines off the surface). */
  nearestVertex(point: THREE.Vector3): number {
    this.grid ??= new VertexGrid(this.geometry.getAttribute('position') as THREE.BufferAttribute);
    return this.grid.nearest(point);
  }

  vertexNormal(index: number, target = new THREE.Vector3()): THREE.Vector3 {
    return target.fromBufferAttribute(this.geometry.getAttribute('normal') as THREE.BufferAttribute, index);
  }

  /** Tints the part of the surface inside a sphere (strength 0..1; null: none). */
  setRegion(sphere: { center: ArrayLike<number>; radius: number } | null, strength = 1): void {
    this.uniforms.regionRadius.value = sphere ? sphere.radius : 0;
    if (sphere) this.uniforms.regionCenter.value.set(sphere.center[0], sphere.center[1], sphere.center[2]);
    this.uniforms.regionStrength.value = strength;
  }

  /** Mutes the colormap (when later stages are drawn on top of it). */
  setDimmed(dimmed: boolean): void {
    this.uniforms.scalarDim.value = dimmed ? 1 : 0;
  }

  /**
   * Colours the surface per vertex (linear RGB, three per vertex; e.g. one colour per skeleton
   * region), over the scalar field and the base colour; null: back to those.
   */
  setRegionColors(colors: Float32Array | null, mix = 1): void {
    if (colors) {
      const attribute = this.geometry.getAttribute('regionColor') as THREE.BufferAttribute;
      (attribute.array as Float32Array).set(colors.subarray(0, attribute.array.length));
      attribute.needsUpdate = true;
    }
    this.uniforms.regionColorMix.value = colors ? mix : 0;
  }

  /** Shows the colour mix of the last `setRegionColors` again at `mix` (0: hidden), keeping the colours. */
  setRegionColorMix(mix: number): void {
    this.uniforms.regionColorMix.value = mix;
  }

  /** See-through surface (so lines and spheres inside it show), or opaque again. */
  setTranslucent(on: boolean): void {
    const material = this.object.material;
    if (material.transparent === on) return;
    material.transparent = on;
    material.depthWrite = !on;
    material.color.set(on ? TRANSLUCENT_COLOR : BASE_COLOR);
    material.needsUpdate = true;
    this.uniforms.translucent.value = on ? 1 : 0;
  }

  /** Hides the scalar field (another mode colours the surface) or shows it again; keeps its values. */
  setScalarVisible(visible: boolean): void {
    this.scalarShown = visible;
    this.uniforms.scalarMax.value = visible && this.field ? this.field.max : 0;
    this.updateIsolines();
  }

  setScalarField(field: ScalarField | null): void {
    this.field = field;
    const attribute = this.geometry.getAttribute('scalar') as THREE.BufferAttribute;
    if (field) {
      const values = attribute.array as Float32Array;
      values.set(field.values);
      for (let i = 0; i < values.length; i++) if (!Number.isFinite(values[i])) values[i] = NO_VALUE;
    } else {
      (attribute.array as Float32Array).fill(NO_VALUE);
    }
    attribute.needsUpdate = true;
    this.uniforms.scalarMax.value = field && this.scalarShown ? field.max : 0;
    this.updateIsolines();
  }

  setIsolines(on: boolean): void {
    this.isolines = on;
    this.updateIsolines();
  }

  setFlatShading(on: boolean): void {
    this.object.material.flatShading = on;
    this.object.material.needsUpdate = true;
  }

  private updateIsolines(): void {
    this.uniforms.isoSpacing.value = this.isolines && this.field && this.scalarShown ? this.field.isolineSpacing : 0;
  }

  dispose(): void {
    this.geometry.dispose();
    this.object.material.dispose();
    this.uniforms.scalarLut.value.dispose();
  }
}

/** Point size in CSS pixels: the same on screen at any zoom, so a dense cloud reads as a surface. */
const POINT_SIZE_PX = 3;

/**
 * A point cloud: one THREE.Points draw call over the worker's float32 positions, sprites of a fixed
 * screen size. Region colours and a scalar field (the distance of stage 1, in the surface's colormap,
 * muted like the surface when lines are drawn on it) go into a per-point colour attribute, rewritten
 * only when what it shows changes; the mesh-only looks (isolines, flat shading, the sphere tint) have
 * no counterpart on points and are no-ops, so the stages drive both layers alike.
 *
 * A subsampled cloud is drawn whole: the points computed on come first (vertex i is point i, as the
 * stages index them), then those left out, each coloured and picked as the computed point that stands
 * in for it. A software renderer draws fewer (`drawnAtMost`), and while the view moves, `setMoving`
 * can draw the computed ones alone.
 */
export class PointsLayer extends PositionsLayer implements Layer {
  readonly label = 'Points';
  readonly object: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  private readonly base = new THREE.Color(BASE_COLOR).convertSRGBToLinear();
  private regionColors: Float32Array | null = null;
  private regionMix = 0;
  private field: ScalarField | null = null;
  private scalarShown = false;
  private dimmed = false;
  /** What the colour attribute holds now (null: not written yet). */
  private shown: { field: ScalarField | null; regionColors: Float32Array | null; regionMix: number; dimmed: boolean } | null = null;

  /** The points computed on: the first of those drawn. */
  private readonly computedCount: number;
  /** For each point left out of a subsample and drawn (after the computed ones), the point standing in for it. */
  private readonly standIn: Uint32Array;

  /** `drawnAtMost`: the points drawn, at least those computed on; of those left out, the first (they come shuffled). */
  constructor(
    positions: Float32Array,
    pixelRatio: number,
    leftOut: { positions: Float32Array; standIn: Uint32Array } = { positions: new Float32Array(0), standIn: new Uint32Array(0) },
    drawnAtMost = Infinity,
  ) {
    super();
    this.computedCount = positions.length / 3;
    this.standIn = leftOut.standIn.subarray(0, Math.max(0, drawnAtMost - this.computedCount));
    const drawn = this.standIn.length ? new Float32Array(positions.length + 3 * this.standIn.length) : positions;
    if (drawn !== positions) {
      drawn.set(positions);
      drawn.set(leftOut.positions.subarray(0, 3 * this.standIn.length), positions.length);
    }
    this.geometry.setAttribute('position', new THREE.BufferAttribute(drawn, 3));
    this.geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(drawn.length), 3));
    this.geometry.computeBoundingSphere();
    const material = new THREE.PointsMaterial({ size: POINT_SIZE_PX * pixelRatio, sizeAttenuation: false, vertexColors: true });
    this.object = new THREE.Points(this.geometry, material);
    this.object.name = 'surface';
    this.setRegionColorMix(0);
  }

  /** The points computed on (those the stages' arrays are over), not those left out of a subsample. */
  override get vertexCount(): number {
    return this.computedCount;
  }

  /** Points drawn: those computed on and those of a subsample's left out that are drawn. */
  get drawnCount(): number {
    return this.geometry.getAttribute('position').count;
  }

  /** The computed point a drawn point is, or that stands in for it. */
  computedPoint(drawn: number): number {
    return drawn < this.computedCount ? drawn : this.standIn[drawn - this.computedCount];
  }

  /**
   * The drawn point nearest the ray's origin among those within the raycaster's threshold of it, as the
   * computed point it is or stands in for. Every drawn point counts, also while the view moves (a click
   * ends a move after the page has picked).
   */
  intersect(raycaster: THREE.Raycaster): { point: number; at: THREE.Vector3 } | null {
    const { count } = this.geometry.drawRange;
    this.geometry.setDrawRange(0, Infinity);
    const hit = raycaster.intersectObject(this.object, false)[0];
    this.geometry.setDrawRange(0, count);
    return hit?.index == null ? null : { point: this.computedPoint(hit.index), at: hit.point.clone() };
  }

  /** While the view moves, only the points computed on are drawn: fewer to draw on a software renderer. */
  setMoving(moving: boolean): void {
    this.geometry.setDrawRange(0, moving ? this.computedCount : Infinity);
  }

  setRegionColors(colors: Float32Array | null, mix = 1): void {
    this.regionColors = colors;
    this.setRegionColorMix(colors ? mix : 0);
  }

  setRegionColorMix(mix: number): void {
    this.regionMix = mix;
    this.recolor();
  }

  setScalarField(field: ScalarField | null): void {
    this.field = field;
    this.recolor();
  }

  setScalarVisible(visible: boolean): void {
    this.scalarShown = visible;
    this.recolor();
  }

  setDimmed(dimmed: boolean): void {
    this.dimmed = dimmed;
    this.recolor();
  }

  /** The scalar field when it is shown, else the region colours mixed in by regionMix. */
  private recolor(): void {
    const field = this.scalarShown ? this.field : null;
    const regionColors = field ? null : this.regionColors;
    const regionMix = field || !regionColors ? 0 : this.regionMix;
    const dimmed = !!field && this.dimmed;
    const want = { field, regionColors, regionMix, dimmed };
    const had = this.shown;
    if (had && had.field === field && had.regionColors === regionColors && had.regionMix === regionMix && had.dimmed === dimmed) return;
    this.shown = want;
    const attribute = this.geometry.getAttribute('color') as THREE.BufferAttribute;
    const out = attribute.array as Float32Array;
    const { r, g, b } = this.base;
    const computed = 3 * this.computedCount;
    if (field) {
      const color = new THREE.Color();
      for (let i = 0; i < this.computedCount; i++) {
        const value = field.values[i];
        if (Number.isFinite(value)) color.setRGB(...turbo(value / field.max), THREE.SRGBColorSpace);
        else color.copy(this.base);
        if (dimmed) color.lerp(DIM_GREY, 0.5 * DIM_MIX);
        color.toArray(out, 3 * i);
      }
    } else {
      for (let i = 0; i < computed; i += 3) {
        out[i] = r + (regionColors ? (regionColors[i] - r) * regionMix : 0);
        out[i + 1] = g + (regionColors ? (regionColors[i + 1] - g) * regionMix : 0);
        out[i + 2] = b + (regionColors ? (regionColors[i + 2] - b) * regionMix : 0);
      }
    }
    this.standIn.forEach((p, j) => out.copyWithin(computed + 3 * j, 3 * p, 3 * p + 3));
    attribute.needsUpdate = true;
  }

  /** See-through: faint points, so the skeleton inside shows. */
  setTranslucent(on: boolean): void {
    const material = this.object.material;
    if (material.transparent === on) return;
    material.transparent = on;
    material.opacity = on ? 0.35 : 1;
    material.depthWrite = !on;
    material.needsUpdate = true;
  }

  setRegion(): void {}
  setIsolines(): void {}
  setFlatShading(): void {}

  dispose(): void {
    this.geometry.dispose();
    this.object.material.dispose();
  }
}

/** What the viewer shows the shape with: a mesh's surface or a cloud's points. */
export type ShapeLayer = SurfaceLayer | PointsLayer;

/** Spheres with their own centres and radii (source markers, medial balls). */
export class SpheresLayer implements Layer {
  readonly object: THREE.InstancedMesh;
  private static readonly sphere = new THREE.SphereGeometry(1, 32, 16);
  private readonly color: THREE.Color;

  constructor(
    readonly label: string,
    centers: ArrayLike<number>,
    radii: number | ArrayLike<number>,
    color: THREE.ColorRepresentation = 0xffffff,
  ) {
    const count = centers.length / 3;
    this.color = new THREE.Color(color);
    const material = new THREE.MeshStandardMaterial({ color, roughness: 0.35, metalness: 0, emissive: color, emissiveIntensity: 0.15 });
    this.object = new THREE.InstancedMesh(SpheresLayer.sphere, material, count);
    const m = new THREE.Matrix4();
    for (let i = 0; i < count; i++) {
      const r = typeof radii === 'number' ? radii : radii[i];
      m.makeScale(r, r, r).setPosition(centers[3 * i], centers[3 * i + 1], centers[3 * i + 2]);
      this.object.setMatrixAt(i, m);
    }
    this.object.computeBoundingSphere();
  }

  setDimmed(dimmed: boolean): void {
    const material = this.object.material as THREE.MeshStandardMaterial;
    material.color.copy(this.color);
    if (dimmed) material.color.lerp(DIM_GREY, DIM_MIX);
    material.emissive.copy(material.color);
  }

  dispose(): void {
    (this.object.material as THREE.Material).dispose();
    this.object.dispose();
  }
}

/** Uniform grid over the vertices for nearest-vertex queries (ring search, exact). */
class VertexGrid {
  private readonly cells = new Map<number, number[]>();
  private readonly min = new THREE.Vector3();
  private readonly size: number;
  private readonly dims: [number, number, number];

  constructor(private readonly positions: THREE.BufferAttribute) {
    const box = new THREE.Box3().setFromBufferAttribute(positions);
    this.min.copy(box.min);
    const extent = box.getSize(new THREE.Vector3());
    const n = Math.max(1, positions.count);
    // About two vertices per cell on a surface: cells of the mean spacing of n points on the box.
    const area = 2 * (extent.x * extent.y + extent.y * extent.z + extent.z * extent.x) || 1;
    this.size = Math.max(Math.sqrt(area / n) * 1.5, 1e-12);
    this.dims = [extent.x, extent.y, extent.z].map((e) => Math.max(1, Math.ceil(e / this.size) + 1)) as [number, number, number];
    for (let i = 0; i < n; i++) {
      const key = this.key(this.cellOf(positions.getX(i), 0), this.cellOf(positions.getY(i), 1), this.cellOf(positions.getZ(i), 2));
      const list = this.cells.get(key);
      if (list) list.push(i);
      else this.cells.set(key, [i]);
    }
  }

  private cellOf(x: number, axis: 0 | 1 | 2): number {
    const c = Math.floor((x - this.min.getComponent(axis)) / this.size);
    return Math.min(this.dims[axis] - 1, Math.max(0, c));
  }

  private key(i: number, j: number, k: number): number {
    return (k * this.dims[1] + j) * this.dims[0] + i;
  }

  nearest(p: THREE.Vector3): number {
    const ci = this.cellOf(p.x, 0), cj = this.cellOf(p.y, 1), ck = this.cellOf(p.z, 2);
    let best = -1;
    let bestD = Infinity;
    const maxRing = Math.max(...this.dims);
    for (let r = 0; r <= maxRing; r++) {
      for (let k = ck - r; k <= ck + r; k++) {
        if (k < 0 || k >= this.dims[2]) continue;
        for (let j = cj - r; j <= cj + r; j++) {
          if (j < 0 || j >= this.dims[1]) continue;
          for (let i = ci - r; i <= ci + r; i++) {
            if (i < 0 || i >= this.dims[0]) continue;
            if (Math.max(Math.abs(i - ci), Math.abs(j - cj), Math.abs(k - ck)) !== r) continue; // shell only
            for (const v of this.cells.get(this.key(i, j, k)) ?? []) {
              const dx = this.positions.getX(v) - p.x, dy = this.positions.getY(v) - p.y, dz = this.positions.getZ(v) - p.z;
              const d = dx * dx + dy * dy + dz * dz;
              if (d < bestD) [bestD, best] = [d, v];
            }
          }
        }
      }
      // Every point outside the searched block is at least r cells (minus the offset in the cell) away.
      if (best >= 0 && Math.sqrt(bestD) <= r * this.size) break;
    }
    return best;
  }
}
