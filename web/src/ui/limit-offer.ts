/**
 * The offer shown for a shape above the size limit (lib/mesh/limits.ts). A mesh: decimate it to a
 * target face count, or compute on the full mesh, with the solver time to expect; until one is chosen
 * the page does not compute on the mesh (nothing starts a minutes-long solver unasked). A point cloud
 * is computed on a subsample from the start (opening it whole is what takes long): the offer is to
 * compute on all its points instead, with the skeleton's time to expect.
 */
import { aboutDuration, DECIMATE_TARGET, expectedCloudCoreMB, expectedCloudSkeletonSeconds, POINT_LIMIT, sizeWarning } from '../../../lib/mesh/limits.ts';
import { byTestId } from './panel.ts';

export class LimitOffer {
  /** Decimate to this many faces pressed. */
  onDecimate: ((targetFaces: number) => void) | null = null;
  /** Compute on the full mesh (or on all of a cloud's points) pressed. */
  onFull: (() => void) | null = null;
  private readonly box = byTestId('limit-offer');
  private readonly target = byTestId<HTMLInputElement>('limit-target');
  private readonly decimate = byTestId<HTMLButtonElement>('limit-decimate');
  private readonly full = byTestId<HTMLButtonElement>('limit-full');
  /** The offer is a cloud's: its subsample is computed on meanwhile. */
  private forCloud = false;

  constructor() {
    this.target.addEventListener('input', () => this.label());
    this.decimate.addEventListener('click', () => {
      const faces = Math.round(Number(this.target.value));
      if (faces >= Number(this.target.min)) this.onDecimate?.(faces);
    });
    this.full.addEventListener('click', () => this.onFull?.());
  }

  /** Whether the user has yet to choose before anything is computed (a mesh's offer). */
  get pending(): boolean {
    return !this.box.hidden && !this.forCloud;
  }

  /** Shows the offer for a mesh above the limit, hides it otherwise. */
  show(faces: number, vertices: number): void {
    const warning = sizeWarning(faces, vertices);
    this.showFor(false, warning !== null);
    if (warning === null) return;
    byTestId('limit-offer-text').textContent = `${warning.charAt(0).toUpperCase()}${warning.slice(1)}. Decimating it first keeps every stage quick; the genus, components and holes are kept.`;
    this.target.max = String(faces - 1);
    this.target.value = String(DECIMATE_TARGET);
    this.label();
    this.full.textContent = 'Compute on the full mesh';
  }

  /**
   * Shows the offer for a cloud computed on a subsample of `points` of its `subsampledFrom` points (null:
   * not subsampled, hidden); all of them are offered only if a core of `coreLimitMB` can hold them.
   */
  showCloud(subsampledFrom: number | null, points: number, coreLimitMB: number): void {
    this.showFor(true, subsampledFrom !== null);
    if (subsampledFrom === null) return;
    const count = (n: number) => n.toLocaleString('en-US');
    const neededMB = expectedCloudCoreMB(subsampledFrom), fits = neededMB <= coreLimitMB;
    const whole = fits
      ? `A skeleton of all of them takes ${aboutDuration(expectedCloudSkeletonSeconds(subsampledFrom))} (measured on two workers).`
      : `A skeleton of all of them would need about ${count(Math.round(neededMB))} MB in a core, more than its ${count(coreLimitMB)} MB: subsample the file to fewer points to compute on more of them.`;
    byTestId('limit-offer-text').textContent =
      `This point cloud has ${count(subsampledFrom)} points, more than the ${count(POINT_LIMIT)} advised: every stage runs on a subsample of ${count(points)}. ${whole}`;
    this.full.hidden = !fits;
    this.full.textContent = `Compute on all ${count(subsampledFrom)} points`;
  }

  hide(): void {
    this.box.hidden = true;
  }

  /** A cloud's offer has no decimation target. */
  private showFor(cloud: boolean, shown: boolean): void {
    this.forCloud = cloud;
    this.box.hidden = !shown;
    this.full.hidden = false;
    this.decimate.hidden = cloud;
    this.target.closest('label')!.hidden = cloud;
  }

  /** Buttons off while a decimation (the status bar's Cancel stops it) or a cloud's opening on all its points runs. */
  setBusy(busy: boolean): void {
    for (const button of this.box.querySelectorAll('button')) button.disabled = busy;
    this.target.disabled = busy;
  }

  private label(): void {
    this.decimate.textContent = `Decimate to ${Number(this.target.value).toLocaleString('en-US')} faces`;
  }
}
