/** Prev / Next buttons, numbered pills and the ←/→ keys over a fixed list of stages (both modes use one). */
import { byTestId } from './panel.ts';

export class Stepper {
  /** Called when the user asks for another stage. */
  onSelect: ((stage: number) => void) | null = null;

  private readonly prev: HTMLButtonElement;
  private readonly next: HTMLButtonElement;
  private readonly pills: HTMLButtonElement[];
  private stage = 1;

  /**
   * `ids`: test ids of the Prev and Next buttons and of the list that receives the pills;
   * `keysActive`: whether the arrow keys belong to this stepper right now.
   */
  constructor(ids: { prev: string; next: string; steps: string }, titles: string[], keysActive: () => boolean) {
    this.prev = byTestId<HTMLButtonElement>(ids.prev);
    this.next = byTestId<HTMLButtonElement>(ids.next);
    this.pills = titles.map((title, i) => {
      const button = document.createElement('button');
      button.type = 'button';
      button.className = 'step';
      button.textContent = String(i + 1);
      button.title = `${i + 1}. ${title}`;
      button.dataset.stage = String(i + 1);
      button.addEventListener('click', () => this.onSelect?.(i + 1));
      return button;
    });
    byTestId(ids.steps).replaceChildren(
      ...this.pills.map((pill) => {
        const li = document.createElement('li');
        li.append(pill);
        return li;
      }),
    );
    this.prev.addEventListener('click', () => this.onSelect?.(this.stage - 1));
    this.next.addEventListener('click', () => this.onSelect?.(this.stage + 1));
    document.addEventListener('keydown', (e) => {
      if (!keysActive() || e.defaultPrevented || e.altKey || e.ctrlKey || e.metaKey) return;
      const target = e.target as HTMLElement | null;
      if (target?.closest('input, select, textarea, [contenteditable="true"]')) return;
      if (e.key === 'ArrowRight') this.onSelect?.(this.stage + 1);
      else if (e.key === 'ArrowLeft') this.onSelect?.(this.stage - 1);
      else return;
      e.preventDefault();
    });
  }

  /** Marks `stage` as the current one; stages after `reached` cannot be entered. */
  show(stage: number, reached: number): void {
    this.stage = stage;
    this.prev.disabled = stage <= 1;
    this.next.disabled = stage >= reached;
    this.pills.forEach((pill, i) => {
      pill.classList.toggle('current', i + 1 === stage);
      pill.classList.toggle('done', i + 1 < stage);
      pill.disabled = i + 1 > reached;
      pill.setAttribute('aria-current', i + 1 === stage ? 'step' : 'false');
    });
  }
}
