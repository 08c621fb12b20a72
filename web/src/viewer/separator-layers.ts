/**
 * The viewer layers of one stage-1 run: cut locus and boundary extremities, target (or the two
 * boundary ends of an open separator), paths, loops, constraint sphere, and on a point cloud the
 * loop's shortening as it went. On a mesh, lines are lifted off the surface along its normals so
 * that they show; a cloud's points are sprites that hide nothing, so its lines stay where they are.
 */
import * as THREE from 'three';
import type { SeparatorData } from '../worker/protocol.ts';
import { COLORS } from '../stage-defs.ts';
import { LinesLayer, concat } from './skeleton-layers.ts';
import { SpheresLayer, SurfaceLayer, type Layer, type ShapeLayer } from './layers.ts';
import { GlassSphereLayer, TubesLayer, graphSegments, liftOffSurface, polylineSegments } from './tubes.ts';

export interface NamedLayer {
  name: string;
  layer: Layer;
  color: string;
}

/** Tube radii as fractions of the mesh's bounding-sphere radius. */
const RADIUS = { cutLocus: 0.0042, extremity: 0.014, path: 0.0058, approxLoop: 0.0072, loop: 0.0105, target: 0.03 };

/** Every layer the run has data for (a failed run has fewer). */
export function separatorLayers(s: SeparatorData, surface: ShapeLayer): NamedLayer[] {
  const R = surface.boundingSphere.radius;
  const out: NamedLayer[] = [];

  const c = s.cutLocus;
  if (c.vertices.length > 0) {
    // Nodes are mesh vertices: lift each along its own vertex normal.
    const r = RADIUS.cutLocus * R;
    const lifted = Float32Array.from(c.points);
    const p = new THREE.Vector3();
    const n = new THREE.Vector3();
    for (let i = 0; i < c.vertices.length && surface instanceof SurfaceLayer; i++) {
      const v = c.vertices[i];
      if (v >= surface.vertexCount) continue;
      p.fromArray(lifted, 3 * i).addScaledVector(surface.vertexNormal(v, n), 0.6 * r).toArray(lifted, 3 * i);
    }
    out.push({
      name: 'cut-locus',
      layer: new TubesLayer('Cut locus', graphSegments(lifted, c.edges), lifted, { color: COLORS.cutLocus, radius: r, jointRadius: r * 1.15 }),
      color: COLORS.cutLocus,
    });
  }

  // Points on the surface as ball centres, each lifted along its nearest vertex's normal.
  const balls = (name: string, label: string, points: ArrayLike<number>, radius: number, color: string) => {
    if (points.length < 3) return;
    const r = radius * R;
    const centres = Float32Array.from(points);
    const p = new THREE.Vector3();
    for (let i = 0; i < centres.length / 3 && surface instanceof SurfaceLayer; i++) {
      p.fromArray(centres, 3 * i);
      const v = surface.nearestVertex(p);
      if (v >= 0) p.addScaledVector(surface.vertexNormal(v), 0.35 * r);
      p.toArray(centres, 3 * i);
    }
    out.push({ name, layer: new SpheresLayer(label, centres, r, color), color });
  };
  // Where the distance is lowest along the boundary: candidate ends of open separators (Sec. 3.2).
  balls('boundary-extremities', 'Boundary extremities', s.boundaryExtremities.points, RADIUS.extremity, COLORS.cutLocus);
  if (s.targetPoint) balls('target', 'Target', s.targetPoint, RADIUS.target, COLORS.target);
  if (s.endPoints) balls('target', 'Boundary ends', s.endPoints, RADIUS.target, COLORS.target);

  const tube = (name: string, label: string, points: Float32Array, closed: boolean, radius: number, color: string) => {
    if (points.length < 6) return;
    const r = radius * R;
    const lifted = liftOffSurface(points, surface, 0.6 * r);
    out.push({ name, layer: new TubesLayer(label, polylineSegments(lifted, closed), lifted, { color, radius: r }), color });
  };
  tube('path-1', 'Path 1', s.paths[0], false, RADIUS.path, COLORS.path1);
  tube('path-2', 'Path 2', s.paths[1], false, RADIUS.path, COLORS.path2);
  tube('approx-loop', s.closed ? 'Approximate loop' : 'Approximate path', s.approxLoop, s.closed, RADIUS.approxLoop, COLORS.approxLoop);

  if (s.sphere) {
    out.push({
      name: 'sphere',
      layer: new GlassSphereLayer('Constraint sphere', s.sphere.center, s.sphere.radius, COLORS.sphere),
      color: COLORS.sphere,
    });
  }

  // A cloud's loop as its descent moved it (App. "Curve Shortening using optimization based framework"):
  // thin lines, every recorded step but the last, which is the loop itself.
  const steps = s.iterates?.slice(0, -1) ?? [];
  if (steps.length > 0) {
    const label = `Shortening (${steps.length} of its steps)`;
    out.push({ name: 'iterates', layer: new LinesLayer(label, concat(steps.map((loop) => polylineSegments(loop, true))), COLORS.iterates), color: COLORS.iterates });
  }
  tube('loop', s.closed ? 'Loop' : 'Path', s.loop, s.closed, RADIUS.loop, COLORS.loop);
  return out;
}

