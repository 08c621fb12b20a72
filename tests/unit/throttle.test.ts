// The page's progress throttle (web/src/ui/throttle.ts): news arrives after every accept, the page
// shows the latest at most once per interval, and never leaves the latest unshown.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { Throttle } from '../../web/src/ui/throttle.ts';

describe('Throttle', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  it('runs the first action at once and the latest of the others once per interval', () => {
    const shown: number[] = [];
    const throttle = new Throttle(() => 500);
    throttle.run(() => shown.push(1));
    expect(shown).toEqual([1]);
    for (let i = 2; i <= 20; i++) {
      vi.advanceTimersByTime(20); // news every 20 ms, as a pool sends it on a small mesh
      throttle.run(() => shown.push(i));
    }
    expect(shown).toEqual([1]); // 380 ms after the first: nothing more yet
    vi.advanceTimersByTime(120);
    expect(shown).toEqual([1, 20]); // the latest, at the end of the interval
    vi.advanceTimersByTime(1000);
    expect(shown).toEqual([1, 20]); // nothing new, nothing shown twice
  });

  it('runs an action asked for at once (the run\'s last news) without waiting, and drops the one waiting', () => {
    const shown: string[] = [];
    const throttle = new Throttle(() => 500);
    throttle.run(() => shown.push('first'));
    throttle.run(() => shown.push('waiting'));
    throttle.run(() => shown.push('last'), true);
    vi.advanceTimersByTime(1000);
    expect(shown).toEqual(['first', 'last']);
  });

  it('drops the waiting action on reset, and runs the next one at once', () => {
    const shown: string[] = [];
    const throttle = new Throttle(() => 500);
    throttle.run(() => shown.push('a'));
    throttle.run(() => shown.push('stale'));
    throttle.reset(); // e.g. a final status set meanwhile: the stale progress must not overwrite it
    vi.advanceTimersByTime(1000);
    expect(shown).toEqual(['a']);
    throttle.run(() => shown.push('b'));
    expect(shown).toEqual(['a', 'b']);
  });
});
