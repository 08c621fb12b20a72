/**
 * How large a mesh the geodesic solver handles in reasonable time, from the measurements in
 * docs/limits.md (scripts/measure-limits.ts), and how large a point cloud is let in: shared by the
 * page (the decimation and subsampling offers) and the CLI (its warnings), so both say the same.
 */
import { CLOUD_VERTICES_PER_POINT, coreMemoryMB } from '../core/pool-size.ts';

/** Above this many faces the page offers to decimate and the CLI warns: the solver then takes over ~6 s. */
export const FACE_LIMIT = 200_000;

/** The face count the page offers to decimate to (about 2 s to open the solver). */
export const DECIMATE_TARGET = 100_000;

// Point clouds: as many points as a closed mesh at the limits has vertices (half its faces). Measured
// (docs/limits.md, "Point clouds"): a skeleton's time and memory grow about linearly with the points,
// 37 s and 2.6 GB for three opened copies at 96K points on two workers, 17 s at 48K; a million points are
// read, checked and subsampled in about 2 s.

/** Above this many points the page computes on a subsample (lib/cloud/subsample.ts) and the CLI warns. */
export const POINT_LIMIT = FACE_LIMIT / 2;

/** The point count the page subsamples to. */
export const SUBSAMPLE_TARGET = DECIMATE_TARGET / 2;

// A cloud skeleton's seconds per point in auto mode on two workers: 3.6-3.9e-4 over the measured clouds
// of 20K to 192K points (docs/limits.md, "Point clouds").
const CLOUD_SKELETON_SECONDS_PER_POINT = 3.7e-4;

/** Expected time, in seconds, of a point cloud's skeleton (auto mode, two workers) on `points` points. */
export function expectedCloudSkeletonSeconds(points: number): number {
  return CLOUD_SKELETON_SECONDS_PER_POINT * points;
}

// A whole skeleton's core (auto mode, stage 2 included) against the pool's rule for a cloud (lib/core/pool-size.ts,
// fitted on 12 sources): measured 1.37 and 1.40 times it at 48K and 96K points (docs/limits.md, "Point clouds").
const CLOUD_SKELETON_MEMORY_FACTOR = 1.4;

/** Expected peak memory, in MB, of the core that computes a point cloud's skeleton on `points` points. */
export function expectedCloudCoreMB(points: number): number {
  return CLOUD_SKELETON_MEMORY_FACTOR * coreMemoryMB(CLOUD_VERTICES_PER_POINT * points);
}

// Least-squares fit of log(seconds) against log(vertices) over the measured tori of 50K to 1M faces:
// seconds = SOLVER_FIT_A * vertices^SOLVER_FIT_B (within 35% of every measurement).
const SOLVER_FIT_A = 8.0e-8;
const SOLVER_FIT_B = 1.58;

/** Expected time, in seconds, to open the geodesic solver (heat-method prefactorisation) on a mesh of `vertices` vertices. */
export function expectedSolverSeconds(vertices: number): number {
  return SOLVER_FIT_A * Math.pow(vertices, SOLVER_FIT_B);
}

/** "about 50 s", "about 3 min": a rough duration for a message. */
export function aboutDuration(seconds: number): string {
  if (seconds < 90) return `about ${Math.max(1, Math.round(seconds))} s`;
  return `about ${Math.round(seconds / 60)} min`;
}

/** The warning for a mesh above FACE_LIMIT, or null (the page's offer and the CLI's warning). */
export function sizeWarning(faces: number, vertices: number): string | null {
  if (faces <= FACE_LIMIT) return null;
  return `this mesh has ${faces} faces; preparing the geodesic solver takes ${aboutDuration(expectedSolverSeconds(vertices))}`;
}

/** The warning for a point cloud above POINT_LIMIT, or null (the CLI's warning). */
export function cloudSizeWarning(points: number): string | null {
  if (points <= POINT_LIMIT) return null;
  return `this point cloud has ${points} points, more than the ${POINT_LIMIT} advised; subsample it to about ${SUBSAMPLE_TARGET}`;
}
