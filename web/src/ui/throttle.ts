/**
 * Least time between two updates of progress shown as text (the status line, the progress bar and its
 * text, the timeline) while news arrives, with a GPU and without one: a pool sends news after every
 * accept, some 20 to 60 a second, and every change to the page is a frame, which a software renderer
 * draws on the cores the workers compute on (docs/parallel.md, "The status line").
 */
const PROGRESS_TEXT_MS = { gpu: 100, software: 500 };

/** PROGRESS_TEXT_MS for a renderer with a GPU or a software one. */
export const progressTextMs = (software: boolean) => PROGRESS_TEXT_MS[software ? 'software' : 'gpu'];

/**
 * Runs the latest of the actions it is given at most once per interval: at once when the interval since
 * the last has passed, else when it has (the latest action then, the earlier ones dropped), so what is
 * shown is never older than an interval.
 */
export class Throttle {
  private last = -Infinity;
  private timer: ReturnType<typeof setTimeout> | null = null;
  private pending: (() => void) | null = null;

  constructor(private readonly interval: () => number) {}

  /** Runs `action` now if an interval has passed since the last (or `now` says so), else at its end. */
  run(action: () => void, now = false): void {
    this.pending = action;
    const wait = this.last + this.interval() - performance.now();
    if (now || wait <= 0) this.flush();
    else if (this.timer === null) this.timer = setTimeout(() => this.flush(), wait);
  }

  /** Drops the action waiting, if any; the next one runs at once. */
  reset(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    this.pending = null;
    this.last = -Infinity;
  }

  private flush(): void {
    const action = this.pending;
    this.reset();
    this.last = performance.now();
    action?.();
  }
}
