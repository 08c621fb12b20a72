// The page's link format (web/src/ui/url-state.ts): what a hash restores, and that anything out of
// range or unknown falls back to the defaults instead of reaching the core.
import { describe, expect, it } from 'vitest';
import { defaultOptions, defaultRunSettings } from '../../lib/core/options.ts';
import { readUrl } from '../../web/src/ui/url-state.ts';

describe('readUrl', () => {
  it('reads the sample, stage, source, every option and the run settings', () => {
    const state = readUrl(
      '#mesh=bob&asCloud=1&stage=skeleton&source=812&target=geodesic&sphere=false&seed=7&angleThreshold=1.5&laplacianThreshold=0.4&pruneDepth=5&n=40&pruneLengthFactor=2.5&drawAhead=4&stage1Vertices=30000&workers=3',
    );
    expect(state).toEqual({
      mesh: 'bob',
      asCloud: true,
      stage: 'skeleton',
      source: 812,
      options: { target: 'geodesic', sphere: false, seed: 7, angleThreshold: 1.5, laplacianThreshold: 0.4, pruneDepth: 5, n: 40, pruneLengthFactor: 2.5, drawAhead: 4, stage1Vertices: 30000 },
      settings: { workers: 3 },
    });
    expect(readUrl('#n=auto').options.n).toBe('auto');
    expect(readUrl('#workers=auto').settings.workers).toBe('auto');
  });

  it('gives the defaults for an empty hash', () => {
    expect(readUrl('')).toEqual({ mesh: null, asCloud: false, stage: null, source: null, options: defaultOptions, settings: defaultRunSettings });
  });

  it('ignores values out of range, of the wrong kind or unknown', () => {
    const state = readUrl(
      '#mesh=../etc&stage=nowhere&source=-3&target=far&sphere=yes&seed=1.5&angleThreshold=4&laplacianThreshold=-1&pruneDepth=2.5&n=0&pruneLengthFactor=abc&workers=0',
    );
    expect(state).toEqual({ mesh: null, asCloud: false, stage: null, source: null, options: defaultOptions, settings: defaultRunSettings });
    expect(readUrl('#asCloud=yes').asCloud).toBe(false);
    expect(readUrl('#workers=257').settings).toEqual(defaultRunSettings);
  });
});
