/**
 * The offer shown for a mesh above the size limit (lib/mesh/limits.ts): decimate it to a target face
 * count, or compute on the full mesh, with the solver time to expect. Until one is chosen the page
 * does not compute on the mesh (nothing starts a minutes-long solver unasked).
 */
import { DECIMATE_TARGET, sizeWarning } from '../../../lib/mesh/limits.ts';
import { byTestId } from './panel.ts';

export class LimitOffer {
  /** Decimate to this many faces pressed. */
  onDecimate: ((targetFaces: number) => void) | null = null;
  /** Compute on the full mesh pressed. */
  onFull: (() => void) | null = null;
  private readonly box = byTestId('limit-offer');
  private readonly target = byTestId<HTMLInputElement>('limit-target');
  private readonly decimate = byTestId<HTMLButtonElement>('limit-decimate');

  constructor() {
    this.target.addEventListener('input', () => this.label());
    this.decimate.addEventListener('click', () => {
      const faces = Math.round(Number(this.target.value));
      if (faces >= Number(this.target.min)) this.onDecimate?.(faces);
    });
    byTestId('limit-full').addEventListener('click', () => this.onFull?.());
  }

  /** Whether the user has yet to choose. */
  get pending(): boolean {
    return !this.box.hidden;
  }

  /** Shows the offer for a mesh above the limit, hides it otherwise. */
  show(faces: number, vertices: number): void {
    const warning = sizeWarning(faces, vertices);
    this.box.hidden = warning === null;
    if (warning === null) return;
    byTestId('limit-offer-text').textContent = `${warning.charAt(0).toUpperCase()}${warning.slice(1)}. Decimating it first keeps every stage quick; the genus, components and holes are kept.`;
    this.target.max = String(faces - 1);
    this.target.value = String(DECIMATE_TARGET);
    this.label();
  }

  hide(): void {
    this.box.hidden = true;
  }

  /** Buttons off while a decimation runs (the status bar's Cancel stops it). */
  setBusy(busy: boolean): void {
    for (const button of this.box.querySelectorAll('button')) button.disabled = busy;
    this.target.disabled = busy;
  }

  private label(): void {
    this.decimate.textContent = `Decimate to ${Number(this.target.value).toLocaleString('en-US')} faces`;
  }
}
