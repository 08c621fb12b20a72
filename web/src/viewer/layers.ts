/**
 * Things the viewer draws. Each layer owns one Object3D and its GPU resources; the viewer keeps
 * them by name (surface, source marker, and later cut locus polylines, skeleton points, spheres).
 */
import * as THREE from 'three';
import { colormapTexture } from './colormap.ts';

export interface Layer {
  /** Shown in the layer list. */
  readonly label: string;
  readonly object: THREE.Object3D;
  dispose(): void;
}

const BASE_COLOR = 0xc4c0b8;

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

/**
 * The triangle mesh, lit with a matte MeshStandardMaterial, optionally coloured by a per-vertex
 * scalar field through a colormap with anti-aliased isolines (patched into the standard shader).
 */
export class SurfaceLayer implements Layer {
  readonly label = 'Surface';
  readonly object: THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial>;
  readonly geometry = new THREE.BufferGeometry();
  private readonly uniforms = {
    scalarLut: { value: colormapTexture() },
    scalarMax: { value: 0 },
    isoSpacing: { value: 0 },
    isoStrength: { value: 0.75 },
  };
  private isolines = true;
  private field: ScalarField | null = null;

  constructor(positions: Float32Array, triangles: Uint32Array) {
    this.geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    this.geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
    this.geometry.setAttribute('scalar', new THREE.BufferAttribute(new Float32Array(positions.length / 3).fill(NO_VALUE), 1));
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
        .replace('#include <common>', '#include <common>\nattribute float scalar;\nvarying float vScalar;')
        .replace('#include <begin_vertex>', '#include <begin_vertex>\nvScalar = scalar;');
      shader.fragmentShader = shader.fragmentShader
        .replace(
          '#include <common>',
          `#include <common>
uniform sampler2D scalarLut;
uniform float scalarMax;
uniform float isoSpacing;
uniform float isoStrength;
varying float vScalar;`,
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
  diffuseColor.rgb = c;
}`,
        );
    };
    material.customProgramCacheKey = () => 'cscd-scalar-surface';
    this.object = new THREE.Mesh(this.geometry, material);
    this.object.name = 'surface';
  }

  get vertexCount(): number {
    return this.geometry.getAttribute('position').count;
  }

  get boundingSphere(): THREE.Sphere {
    return this.geometry.boundingSphere!;
  }

  vertexPosition(index: number, target = new THREE.Vector3()): THREE.Vector3 {
    return target.fromBufferAttribute(this.geometry.getAttribute('position') as THREE.BufferAttribute, index);
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
    this.uniforms.scalarMax.value = field ? field.max : 0;
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
    this.uniforms.isoSpacing.value = this.isolines && this.field ? this.field.isolineSpacing : 0;
  }

  dispose(): void {
    this.geometry.dispose();
    this.object.material.dispose();
    this.uniforms.scalarLut.value.dispose();
  }
}

/** Spheres with their own centres and radii (source markers, medial balls). */
export class SpheresLayer implements Layer {
  readonly object: THREE.InstancedMesh;
  private static readonly sphere = new THREE.SphereGeometry(1, 32, 16);

  constructor(
    readonly label: string,
    centers: ArrayLike<number>,
    radii: number | ArrayLike<number>,
    color: THREE.ColorRepresentation = 0xffffff,
  ) {
    const count = centers.length / 3;
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

  dispose(): void {
    (this.object.material as THREE.Material).dispose();
    this.object.dispose();
  }
}

/** Line segments: `positions` holds two xyz points per segment (cut locus, skeleton edges). */
export class PolylineLayer implements Layer {
  readonly object: THREE.LineSegments;

  constructor(
    readonly label: string,
    positions: Float32Array,
    color: THREE.ColorRepresentation = 0x111111,
  ) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    this.object = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color }));
  }

  dispose(): void {
    this.object.geometry.dispose();
    (this.object.material as THREE.Material).dispose();
  }
}

/** Points of a fixed screen size (skeleton nodes, samples). */
export class PointsLayer implements Layer {
  readonly object: THREE.Points;

  constructor(
    readonly label: string,
    positions: Float32Array,
    color: THREE.ColorRepresentation = 0xffffff,
    sizePx = 6,
  ) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    const material = new THREE.PointsMaterial({ color, size: sizePx, sizeAttenuation: false });
    this.object = new THREE.Points(geometry, material);
  }

  dispose(): void {
    this.object.geometry.dispose();
    (this.object.material as THREE.Material).dispose();
  }
}
