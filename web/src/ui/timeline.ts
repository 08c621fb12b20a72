/**
 * The stage timeline across the top of the viewport: one pill per stage (number, title, the time
 * its computation took, a progress bar while it runs), Prev / Next, the ←/→ keys and the digit keys
 * (1-9, 0 for the tenth). A pill is `ready` (computed), `pending` (entering it computes it), `running`
 * or `disabled`.
 */
import { STAGES, type StageGroup, type StageKey } from '../stage-defs.ts';

export type PillState = 'ready' | 'pending' | 'running' | 'disabled';

const GROUP_LABEL: Record<StageGroup, string> = { mesh: 'Input', source: 'Stage 1 · one source', shape: 'Stage 2 · whole shape' };

export class Timeline {
  /** Called when the user asks for a stage (pill, buttons, keys). */
  onSelect: ((key: StageKey) => void) | null = null;

  private readonly pills = new Map<StageKey, HTMLButtonElement>();
  private readonly prev: HTMLButtonElement;
  private readonly next: HTMLButtonElement;
  private current: StageKey = 'mesh';
  private states = new Map<StageKey, PillState>();

  constructor(root: HTMLElement) {
    this.prev = button('stage-prev', '‹', 'Previous stage (←)');
    this.next = button('stage-next', '›', 'Next stage (→)');
    const list = document.createElement('ol');
    list.className = 'timeline-stages';
    list.dataset.testid = 'stage-steps';
    STAGES.forEach((def, i) => {
      const pill = document.createElement('button');
      pill.type = 'button';
      pill.className = 'stage-pill';
      pill.dataset.stage = def.key;
      pill.dataset.testid = `stage-${def.key}`;
      pill.title = `${i + 1}. ${def.title} · ${def.section}`;
      const number = span('pill-number', String(i + 1));
      // A soft hyphen lets the one long word break in a narrow pill.
      const title = span('pill-title', def.title.replace('Reconstruction', 'Recon\u00ADstruction'));
      const time = span('pill-time', '');
      time.dataset.testid = `stage-time-${def.key}`;
      const bar = span('pill-bar', '');
      pill.append(number, time, title, bar);
      pill.addEventListener('click', () => this.onSelect?.(def.key));
      this.pills.set(def.key, pill);
      const li = document.createElement('li');
      li.className = `group-${def.group}`;
      // The first stage of each group carries the group's name above it.
      if (i === 0 || STAGES[i - 1].group !== def.group) li.dataset.groupLabel = GROUP_LABEL[def.group];
      li.append(pill);
      list.append(li);
    });
    root.replaceChildren(this.prev, list, this.next);
    this.prev.addEventListener('click', () => this.step(-1));
    this.next.addEventListener('click', () => this.step(1));
    document.addEventListener('keydown', (e) => {
      if (e.defaultPrevented || e.altKey || e.ctrlKey || e.metaKey) return;
      const target = e.target as HTMLElement | null;
      if (target?.closest('input, select, textarea, [contenteditable="true"]')) return;
      if (e.key === 'ArrowRight') this.step(1);
      else if (e.key === 'ArrowLeft') this.step(-1);
      else if (/^[0-9]$/.test(e.key)) this.jump(e.key === '0' ? 9 : Number(e.key) - 1);
      else return;
      e.preventDefault();
    });
  }

  /** Marks `current` and every pill's state. */
  show(current: StageKey, states: ReadonlyMap<StageKey, PillState>): void {
    this.current = current;
    this.states = new Map(states);
    for (const [key, pill] of this.pills) {
      const state = states.get(key) ?? 'disabled';
      pill.dataset.state = state;
      pill.classList.toggle('current', key === current);
      pill.disabled = state === 'disabled';
      pill.setAttribute('aria-current', key === current ? 'step' : 'false');
    }
    this.prev.disabled = this.neighbour(-1) === null;
    this.next.disabled = this.neighbour(1) === null;
  }

  /** The time a stage's computation took (empty: not computed). */
  setTime(key: StageKey, text: string): void {
    this.pills.get(key)!.querySelector('.pill-time')!.textContent = text;
  }

  /** A fraction done shown under the pill while it computes, or null. */
  setProgress(key: StageKey, fraction: number | null): void {
    const bar = this.pills.get(key)!.querySelector<HTMLElement>('.pill-bar')!;
    bar.style.width = fraction === null ? '0' : `${(100 * Math.min(1, Math.max(0, fraction))).toFixed(1)}%`;
  }

  private neighbour(direction: 1 | -1): StageKey | null {
    const keys = STAGES.map((s) => s.key);
    for (let i = keys.indexOf(this.current) + direction; i >= 0 && i < keys.length; i += direction) {
      if ((this.states.get(keys[i]) ?? 'disabled') !== 'disabled') return keys[i];
    }
    return null;
  }

  /** The stage at `index` (keys 1-9 and 0), when it can be entered. */
  private jump(index: number): void {
    const key = STAGES[index]?.key;
    if (key && (this.states.get(key) ?? 'disabled') !== 'disabled') this.onSelect?.(key);
  }

  private step(direction: 1 | -1): void {
    const key = this.neighbour(direction);
    if (key) this.onSelect?.(key);
  }
}

function button(testid: string, text: string, title: string): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.className = 'timeline-step';
  b.dataset.testid = testid;
  b.textContent = text;
  b.title = title;
  b.setAttribute('aria-label', title);
  return b;
}

function span(className: string, text: string): HTMLSpanElement {
  const s = document.createElement('span');
  s.className = className;
  s.textContent = text;
  return s;
}
