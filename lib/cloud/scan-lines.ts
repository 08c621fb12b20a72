/**
 * A cloud scanned in lines (the rings of a turntable or LiDAR scan) whose lines lie farther apart than
 * its points along them: each point's k nearest then all lie in its own line, its neighbourhood is a
 * line and not a patch of the surface, and the local triangulations, normals and MLS fits built from it
 * know nothing of the surface between the lines (the cloud falls apart into its lines, or its loops
 * shrink to points). More neighbours reach across the lines. The shared clouds have no such points but
 * for the trees' twigs (at most 1.5% of their points); a tube scanned in 30 rings of 600 points has
 * them all (docs/pointcloud.md, "Scan lines").
 */
import type { CloudFacts } from '../core/types.ts';

/** Above this share of points with their neighbours along a line, the cloud is taken for scan lines. */
export const SCAN_LINE_SHARE = 0.25;

/** The warning for a cloud whose neighbourhoods are mostly lines, or null. */
export function scanLineWarning(facts: CloudFacts): string | null {
  if (!(facts.linearNeighbourhoods > SCAN_LINE_SHARE * facts.points)) return null;
  const percent = Math.round((100 * facts.linearNeighbourhoods) / facts.points);
  return `${percent}% of the points have their ${facts.neighbours} nearest neighbours along a line, not around them on a surface `
    + `(a cloud scanned in lines farther apart than its points along them?): the surface between the lines cannot be found `
    + `from them; raise neighbours (--neighbours K) until they reach across the lines`;
}
