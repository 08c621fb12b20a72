// A cloud scanned in lines farther apart than its points along them (lib/cloud/scan-lines.ts): its points'
// fits see lines (and farther apart, the cloud falls apart into its lines), and it is said, with what to
// do: more neighbours reach across the lines, and the points thinned along the lines (to a count from the
// spacing the core measures) make a cloud whose skeleton runs along the tube's axis, where all the points
// give nodes on its surface. The shared clouds (fixtures from them) have no such neighbourhoods.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { scanLineSubsample, scanLineWarning } from '../../lib/cloud/scan-lines.ts';
import { subsampleCloud } from '../../lib/cloud/subsample.ts';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { defaultCloudOptions } from '../../lib/core/options.ts';
import type { CloudFacts } from '../../lib/core/types.ts';
import { fixture } from '../paths.ts';
import { cscd } from './support/cli.ts';
import { readCloudFile, ringScannedTube, xyzText } from './support/clouds.ts';

let core: Core;
let folder: string;
beforeAll(async () => {
  core = await loadCoreNode();
  folder = mkdtempSync(path.join(tmpdir(), 'cscd-scan-lines-'));
});
afterAll(() => rmSync(folder, { recursive: true, force: true }));

function factsOf(positions: Float64Array, neighbours: number): CloudFacts {
  const cloud = core.openCloud({ positions, normals: null }, { neighbours });
  try {
    return cloud.facts;
  } finally {
    cloud.dispose();
  }
}

// 12 rings of 300 points, 0.36 apart: 0.021 between points round a ring, so 30 neighbours reach 0.31 along it.
const tube = ringScannedTube(12, 300, 0.36);

describe('clouds scanned in lines', () => {
  it('counts every point of a ring-scanned tube as having its neighbours along a line, and says what to do', () => {
    const facts = factsOf(tube, 30);
    expect(facts.lineLikeShare).toBe(1);
    expect(facts.components, 'the cloud falls apart into its rings').toBe(12);
    expect(facts.lineSpacing).toBeCloseTo(0.36, 3);
    // 0.021 between points round a ring, 0.36 between rings: about 3600 x 0.021 / 0.36 points at the rings'
    // spacing, twice as many at half of it.
    expect(facts.pointsAtLineSpacing).toBe(210);
    expect(scanLineSubsample(facts)).toBe(420);
    expect(scanLineWarning(facts)).toBe(
      '100% of the points have their 30 nearest neighbours along a line as the surface fits weigh them, not around them (a cloud scanned in lines '
      + 'farther apart than its points along them?): the surface between the lines cannot be found from them; raise '
      + 'neighbours (--neighbours K) until they reach across the lines, or thin the points along the lines '
      + '(they lie 0.36 apart: to about 420 points, --subsample 420)',
    );
  });

  it('thinned along the lines to the count given, is one piece with no line in sight, and its skeleton runs along the axis', () => {
    const farthestOffAxis = (nodes: Float64Array) => Math.max(...Array.from({ length: nodes.length / 3 }, (_, i) => Math.hypot(nodes[3 * i], nodes[3 * i + 1])));
    const whole = core.openCloud({ positions: ringScannedTube(12, 300, 0.3), normals: null }, { neighbours: 30 });
    try {
      expect(farthestOffAxis(whole.skeleton(defaultCloudOptions).nodes), 'all the points: nodes on the surface').toBeGreaterThan(0.9);
    } finally {
      whole.dispose();
    }
    for (const gap of [0.36, 0.3]) {
      const positions = ringScannedTube(12, 300, gap);
      const thinned = subsampleCloud({ positions, normals: null }, scanLineSubsample(factsOf(positions, 30)), 1);
      const cloud = core.openCloud(thinned, { neighbours: 30 });
      try {
        expect(cloud.facts, `rings ${gap} apart`).toMatchObject({ components: 1, lineLikeShare: 0 });
        const skeleton = cloud.skeleton(defaultCloudOptions);
        expect(skeleton.stats.cycles).toBe(0);
        expect(skeleton.nodes.length / 3).toBeGreaterThanOrEqual(5);
        expect(farthestOffAxis(skeleton.nodes), 'within half the radius, 1').toBeLessThan(0.5);
      } finally {
        cloud.dispose();
      }
    }
  });

  it('warns where the rings are near enough to join but every fit still sees one ring', () => {
    // 0.3 apart: the 30 nearest reach the next ring, but it is the farthest, which the fits weigh 0.
    const facts = factsOf(ringScannedTube(12, 300, 0.3), 30);
    expect(facts.components).toBe(1);
    expect(facts.lineLikeShare).toBe(1);
    expect(scanLineWarning(facts)).not.toBeNull();
    expect(factsOf(ringScannedTube(12, 300, 0.3), 60).lineLikeShare).toBe(0);
  });

  it('no longer warns once the neighbours reach the next rings, and the tube is one piece', () => {
    const facts = factsOf(tube, 100);
    expect(facts.lineLikeShare).toBe(0);
    expect(facts.components).toBe(1);
    expect(scanLineWarning(facts)).toBeNull();
  });

  it('finds none on clouds sampled from meshes, clean or noisy, and too few on a tree scan to warn', () => {
    for (const [name, most] of [['hand_subsample.ply', 0], ['bob_noise_subsample.ply', 0], ['tree_woodske_HS.ply', 0.01]] as const) {
      const cloud = core.openCloud(readCloudFile(fixture('clouds', name)));
      try {
        expect(cloud.facts.lineLikeShare, name).toBeLessThanOrEqual(most);
        expect(scanLineWarning(cloud.facts), name).toBeNull();
      } finally {
        cloud.dispose();
      }
    }
  });

  it('is said on stderr by the CLI, which still prints the facts', async () => {
    const file = path.join(folder, 'tube.xyz');
    writeFileSync(file, xyzText(tube));
    const result = await cscd('info', file);
    expect(result.status).toBe(0);
    expect(result.stderr).toBe(`cscd: warning: ${file}: ${scanLineWarning(factsOf(tube, 30))}\n`);
    expect(JSON.parse(result.stdout)).toMatchObject({ points: 3600, lineLikeShare: 1, components: 12 });
    expect(await cscd('info', file, '--neighbours', '100')).toMatchObject({ status: 0, stderr: '' });
  });
});
