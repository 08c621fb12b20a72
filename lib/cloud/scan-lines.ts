/**
 * A cloud scanned in lines (the rings of a turntable or LiDAR scan) whose lines lie farther apart than
 * its points along them: the MLS fits, which weigh a point's k nearest by a Gaussian that falls to 0 at
 * the farthest, then see its own line only (the next line's points are the farthest), and cannot tell the
 * surface's normal from a direction in it; far enough apart, the neighbourhoods hold no point of another
 * line at all and the cloud falls apart into its lines. The skeletons then have leaves out to the
 * surface, or no separator at all. More neighbours reach across the lines; points thinned along the lines
 * (the core measures the lines' spacing, CloudFacts.lineSpacing) make a cloud the fits see whole. The shared
 * clouds have no such points but for the trees' twigs (under 1%) (docs/pointcloud.md, "Scan lines").
 */
import type { CloudFacts } from '../core/types.ts';

/**
 * Above this share of points whose fits see a line (CloudFacts.lineLikeShare), the cloud is taken for scan
 * lines: meshes sliced in lines had 0.10-0.98 (and stray cycles from 0.10), clouds sampled over surfaces 0,
 * tree scans' twigs up to 0.012.
 */
export const SCAN_LINE_SHARE = 0.05;

/**
 * How much denser than the lines' spacing a cloud scanned in lines is thinned along them: its points half
 * the spacing apart along the lines. Points r apart along lines D apart put a point's k nearest within
 * about sqrt(k r D / pi) of it, 2.2 lines at k = 30. Thinner (r = D) suits tubes scanned in rings but
 * leaves sliced meshes coarse; denser (r = D / 3, D / 4) lowers their errors but closed stray cycles
 * (docs/pointcloud.md, "Scan lines").
 */
const ALONG_PER_SPACING = 2;

/** About how many points a cloud scanned in lines keeps thinned along them (--subsample, the page's offer); 0 where its lines were not measured. */
export function scanLineSubsample(facts: CloudFacts): number {
  return Math.min(facts.points, ALONG_PER_SPACING * facts.pointsAtLineSpacing);
}

/** The warning for a cloud whose neighbourhoods are mostly lines, or null. */
export function scanLineWarning(facts: CloudFacts): string | null {
  if (!(facts.lineLikeShare > SCAN_LINE_SHARE)) return null;
  const percent = Math.round(100 * facts.lineLikeShare);
  const count = scanLineSubsample(facts);
  const thinned = count > 0 ? ` (they lie ${facts.lineSpacing.toPrecision(2)} apart: to about ${count} points, --subsample ${count})` : '';
  return `${percent}% of the points have their ${facts.neighbours} nearest neighbours along a line as the surface fits weigh them, not around them `
    + `(a cloud scanned in lines farther apart than its points along them?): the surface between the lines cannot be found `
    + `from them; raise neighbours (--neighbours K) until they reach across the lines, or thin the points along the lines${thinned}`;
}
