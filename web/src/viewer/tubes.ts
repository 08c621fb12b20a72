/**
 * Layers for curves on the surface and for the constraint sphere: tubes (instanced cylinders with a
 * ball at every joint, so corners stay round and closed loops have no seam) and a translucent sphere.
 */
import * as THREE from 'three';
import { DIM_GREY, DIM_MIX, SurfaceLayer, type Layer, type ShapeLayer } from './layers.ts';

const Y = new THREE.Vector3(0, 1, 0);

/** Unit cylinder from y = 0 to y = 1, open ended (the joint balls close it). */
const cylinder = new THREE.CylinderGeometry(1, 1, 1, 14, 1, true).translate(0, 0.5, 0);
const ball = new THREE.SphereGeometry(1, 16, 10);
/**
 * Coarser versions for layers of many thin tubes (hundreds of loops, a few pixels wide on screen):
 * the software renderers of headless browsers and weak machines draw millions of triangles slowly.
 */
const lowCylinder = new THREE.CylinderGeometry(1, 1, 1, 5, 1, true).translate(0, 0.5, 0);
const lowBall = new THREE.SphereGeometry(1, 5, 3);

export interface TubeStyle {
  color: THREE.ColorRepresentation;
  radius: number;
  /** Radius of the joint balls; defaults to `radius`. */
  jointRadius?: number;
  /** Glow (emissive) so the colour reads the same on the lit and the shaded side. */
  glow?: number;
  /** 'low': coarse cylinders and balls, for layers of many thin tubes. */
  detail?: 'high' | 'low';
}

/** Tubes along segments: `segments` holds two xyz points per segment, `joints` xyz points for balls. */
export class TubesLayer implements Layer {
  readonly object = new THREE.Group();
  private readonly material: THREE.MeshStandardMaterial;
  private readonly color: THREE.Color;
  private readonly glow: number;

  constructor(
    readonly label: string,
    segments: ArrayLike<number>,
    joints: ArrayLike<number>,
    style: TubeStyle,
  ) {
    this.color = new THREE.Color(style.color);
    this.glow = style.glow ?? 0.35;
    this.material = new THREE.MeshStandardMaterial({
      color: this.color,
      roughness: 0.4,
      metalness: 0,
      emissive: this.color,
      emissiveIntensity: this.glow,
    });
    const r = style.radius;
    const a = new THREE.Vector3();
    const b = new THREE.Vector3();
    const dir = new THREE.Vector3();
    const q = new THREE.Quaternion();
    const scale = new THREE.Vector3();
    const m = new THREE.Matrix4();

    const count = Math.floor(segments.length / 6);
    const low = style.detail === 'low';
    const tubes = new THREE.InstancedMesh(low ? lowCylinder : cylinder, this.material, Math.max(count, 1));
    let used = 0;
    for (let i = 0; i < count; i++) {
      a.fromArray(segments as number[], 6 * i);
      b.fromArray(segments as number[], 6 * i + 3);
      dir.subVectors(b, a);
      const length = dir.length();
      if (!(length > 0)) continue;
      q.setFromUnitVectors(Y, dir.divideScalar(length));
      m.compose(a, q, scale.set(r, length, r));
      tubes.setMatrixAt(used++, m);
    }
    tubes.count = used;
    tubes.computeBoundingSphere();

    const jointCount = Math.floor(joints.length / 3);
    const jr = style.jointRadius ?? r;
    const balls = new THREE.InstancedMesh(low ? lowBall : ball, this.material, Math.max(jointCount, 1));
    for (let i = 0; i < jointCount; i++) {
      m.compose(a.fromArray(joints as number[], 3 * i), q.identity(), scale.set(jr, jr, jr));
      balls.setMatrixAt(i, m);
    }
    balls.count = jointCount;
    balls.computeBoundingSphere();
    this.object.add(tubes, balls);
  }

  setDimmed(dimmed: boolean): void {
    this.material.color.copy(this.color);
    if (dimmed) this.material.color.lerp(DIM_GREY, DIM_MIX);
    this.material.emissive.copy(this.material.color);
    this.material.emissiveIntensity = dimmed ? 0.1 : this.glow;
  }

  dispose(): void {
    this.material.dispose();
    for (const child of this.object.children) (child as THREE.InstancedMesh).dispose();
  }
}

/** Segments (point pairs) of a polyline given as xyz triples; `closed` joins the last point to the first. */
export function polylineSegments(points: ArrayLike<number>, closed: boolean): Float32Array {
  const n = Math.floor(points.length / 3);
  const m = n < 2 ? 0 : closed ? n : n - 1;
  const out = new Float32Array(6 * m);
  for (let i = 0; i < m; i++) {
    const j = (i + 1) % n;
    for (let k = 0; k < 3; k++) {
      out[6 * i + k] = points[3 * i + k];
      out[6 * i + 3 + k] = points[3 * j + k];
    }
  }
  return out;
}

/** Segments of a graph: `edges` holds pairs of indices into `points` (xyz triples). */
export function graphSegments(points: ArrayLike<number>, edges: ArrayLike<number>): Float32Array {
  const m = Math.floor(edges.length / 2);
  const out = new Float32Array(6 * m);
  for (let i = 0; i < m; i++) {
    for (let k = 0; k < 3; k++) {
      out[6 * i + k] = points[3 * edges[2 * i] + k];
      out[6 * i + 3 + k] = points[3 * edges[2 * i + 1] + k];
    }
  }
  return out;
}

/**
 * Moves points that lie on the surface a little along the normal of their nearest vertex, so tubes
 * drawn through them sit on the surface instead of half inside it. Over a cloud's points (no normals,
 * no surface to sink into) they stay where they are.
 */
export function liftOffSurface(points: ArrayLike<number>, surface: ShapeLayer, offset: number): Float32Array {
  const out = Float32Array.from(points);
  if (!(surface instanceof SurfaceLayer)) return out;
  const p = new THREE.Vector3();
  const normal = new THREE.Vector3();
  for (let i = 0; i + 2 < out.length; i += 3) {
    p.fromArray(out, i);
    const v = surface.nearestVertex(p);
    if (v < 0) continue;
    surface.vertexNormal(v, normal);
    p.addScaledVector(normal, offset).toArray(out, i);
  }
  return out;
}

/** A translucent sphere with a brighter rim (Fresnel-like), not writing depth so the mesh shows through. */
export class GlassSphereLayer implements Layer {
  readonly object: THREE.Mesh<THREE.SphereGeometry, THREE.MeshStandardMaterial>;
  private readonly uniforms = { rimAlpha: { value: 0.62 }, coreAlpha: { value: 0.12 } };

  constructor(
    readonly label: string,
    center: ArrayLike<number>,
    radius: number,
    color: THREE.ColorRepresentation = 0x8fc3ff,
  ) {
    const material = new THREE.MeshStandardMaterial({
      color,
      roughness: 0.25,
      metalness: 0,
      emissive: color,
      emissiveIntensity: 0.35,
      transparent: true,
      depthWrite: false,
      side: THREE.FrontSide,
    });
    material.onBeforeCompile = (shader) => {
      Object.assign(shader.uniforms, this.uniforms);
      shader.fragmentShader = shader.fragmentShader
        .replace('#include <common>', '#include <common>\nuniform float rimAlpha;\nuniform float coreAlpha;')
        .replace(
          '#include <opaque_fragment>',
          `float facing = abs(dot(normalize(normal), normalize(vViewPosition)));
diffuseColor.a = mix(rimAlpha, coreAlpha, smoothstep(0.0, 0.75, facing));
#include <opaque_fragment>`,
        );
    };
    material.customProgramCacheKey = () => 'cscd-glass-sphere';
    this.object = new THREE.Mesh(new THREE.SphereGeometry(1, 64, 32), material);
    this.object.scale.setScalar(radius);
    this.object.position.set(center[0], center[1], center[2]);
    this.object.renderOrder = 10; // after the opaque layers
  }

  setDimmed(dimmed: boolean): void {
    this.uniforms.rimAlpha.value = dimmed ? 0.25 : 0.62;
    this.uniforms.coreAlpha.value = dimmed ? 0.04 : 0.12;
  }

  dispose(): void {
    this.object.geometry.dispose();
    this.object.material.dispose();
  }
}
