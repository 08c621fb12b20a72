/** The side panel: file, status, error box, mesh facts, notes, timings, layer list (stage 1: ui/stages.ts). */
import type { CloudFacts, MeshFacts } from '../../../lib/core/types.ts';
import { colormapGradient } from '../viewer/colormap.ts';
import { Throttle } from './throttle.ts';

function $<T extends HTMLElement = HTMLElement>(selector: string): T {
  const element = document.querySelector<T>(selector);
  if (!element) throw new Error(`missing element ${selector}`);
  return element;
}
/** The element with data-testid `id` (the page's markup names every element the code touches). */
export const byTestId = <T extends HTMLElement = HTMLElement>(id: string): T => $<T>(`[data-testid="${id}"]`);

/** "cutLocus" -> "Cut locus". */
export function humanize(key: string): string {
  const words = key.replace(/([a-z0-9])([A-Z])/g, '$1 $2').replace(/[-_]+/g, ' ').toLowerCase();
  return words.charAt(0).toUpperCase() + words.slice(1);
}

/** A legend entry: a colour chip and its label. */
export function swatch(color: string, label: string): HTMLLIElement {
  const li = document.createElement('li');
  const chip = document.createElement('span');
  chip.className = 'swatch';
  chip.style.background = color;
  li.append(chip, label);
  return li;
}

/** A length with four significant digits. */
export function formatLength(x: number): string {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-3 && a < 1e6 ? String(Number(x.toPrecision(4))) : x.toExponential(3);
}

/** Rows (dt, dd pairs) of a `{step: milliseconds}` record; each dd has test id `${prefix}${step}`. */
export function timingRows(timings: Record<string, number>, prefix: string): HTMLElement[] {
  return Object.entries(timings).flatMap(([key, ms]) => {
    const dt = document.createElement('dt');
    dt.textContent = humanize(key);
    const dd = document.createElement('dd');
    dd.dataset.testid = `${prefix}${key}`;
    dd.textContent = Number.isFinite(ms) ? formatMs(ms) : '–';
    return [dt, dd];
  });
}

export function formatMs(ms: number): string {
  return ms < 10 ? `${ms.toFixed(1)} ms` : ms < 10_000 ? `${Math.round(ms)} ms` : `${(ms / 1000).toFixed(1)} s`;
}

export class Panel {
  private readonly statusText = $('#status-text');
  private readonly status = byTestId('status');
  private readonly error = byTestId('error');
  private readonly progressStatus: Throttle;

  /** `progressInterval`: the least time between two progress texts in the status line (PROGRESS_TEXT_MS). */
  constructor(progressInterval: () => number) {
    this.progressStatus = new Throttle(progressInterval);
    $('#colorbar').style.background = colormapGradient();
  }

  setFile(name: string, format: string): void {
    const el = byTestId('file-name');
    el.textContent = name;
    el.title = name;
    const badge = byTestId('file-format');
    badge.textContent = format.toUpperCase();
    badge.hidden = false;
    document.title = `${name} · CSCD Studio`;
  }

  setStatus(text: string, busy = false): void {
    this.progressStatus.reset();
    this.statusText.textContent = text;
    this.status.classList.toggle('busy', busy);
  }

  /** A computation's progress in the status line: the latest, at most once per progress interval. */
  setProgressStatus(text: string): void {
    this.progressStatus.run(() => {
      this.statusText.textContent = text;
      this.status.classList.add('busy');
    });
  }

  showError(title: string, message: string): void {
    const strong = document.createElement('strong');
    strong.textContent = title;
    const body = document.createElement('span');
    body.textContent = message;
    this.error.replaceChildren(strong, body);
    this.error.hidden = false;
  }

  clearError(): void {
    this.error.hidden = true;
    this.error.replaceChildren();
  }

  setFacts(f: MeshFacts): void {
    const set = (id: string, text: string | number, warn = false) => {
      const el = byTestId(id);
      el.textContent = String(text);
      el.classList.toggle('warn', warn);
    };
    set('facts-vertices', f.vertices);
    set('facts-faces', f.faces);
    set('facts-edges', f.edges);
    set('facts-components', f.components);
    set('facts-boundary-loops', f.boundaryLoops);
    set('facts-genus', f.genus ?? '–');
    set('facts-euler', f.eulerCharacteristic);
    const nonManifold = [
      f.nonManifoldEdges ? `${f.nonManifoldEdges} edges` : '',
      f.nonManifoldVertices ? `${f.nonManifoldVertices} verts` : '',
    ].filter(Boolean);
    set('facts-manifold', f.manifold ? 'yes' : `no${nonManifold.length ? ` (${nonManifold.join(', ')})` : ''}`, !f.manifold);
    set('facts-oriented', f.consistentlyOriented ? 'yes' : 'no', !f.consistentlyOriented);
    set('facts-bbox-diagonal', formatLength(f.bboxDiagonal));
    set('facts-mean-edge', formatLength(f.meanEdgeLength));
  }

  /** A point cloud's facts in the same list: points for vertices, the mean spacing for the mean edge, no faces. */
  setCloudFacts(f: CloudFacts): void {
    const set = (id: string, text: string | number) => {
      const el = byTestId(id);
      el.textContent = String(text);
      el.classList.remove('warn');
    };
    set('facts-vertices', `${f.points} points`);
    for (const id of ['facts-faces', 'facts-edges', 'facts-boundary-loops', 'facts-genus', 'facts-euler', 'facts-manifold', 'facts-oriented']) set(id, '–');
    set('facts-components', f.components);
    set('facts-bbox-diagonal', formatLength(f.bboxDiagonal));
    set('facts-mean-edge', `${formatLength(f.meanSpacing)} (spacing, ${f.neighbours} neighbours, ${f.meanFlatNeighbours.toFixed(1)} flat)`);
  }

  /** Parser warnings plus the page's own notes about the mesh. */
  setNotes(notes: string[]): void {
    const list = byTestId('warnings');
    list.replaceChildren(
      ...notes.map((note) => {
        const li = document.createElement('li');
        li.textContent = note;
        return li;
      }),
    );
    byTestId('warnings-section').hidden = notes.length === 0;
  }

  /** Timings of opening the mesh; null shows '–' (not measured yet), undefined leaves a row as it is. */
  setTimings(t: { parseMs?: number; inspectMs?: number; prepareMs?: number | null }): void {
    const set = (id: string, ms: number | null | undefined) => {
      if (ms !== undefined) byTestId(id).textContent = ms === null ? '–' : formatMs(ms);
    };
    set('timing-parse', t.parseMs);
    set('timing-inspect', t.inspectMs);
    set('timing-prepare', t.prepareMs);
  }

  /** Checkbox list of the viewer's layers. */
  setLayers(
    layers: Array<{ name: string; label: string; visible: boolean; color?: string; dimmed?: boolean }>,
    onToggle: (name: string, visible: boolean) => void,
  ): void {
    $('#layers').replaceChildren(
      ...layers.map(({ name, label, visible, color, dimmed }) => {
        const row = document.createElement('label');
        row.className = 'check';
        row.classList.toggle('dimmed', !!dimmed);
        const box = document.createElement('input');
        box.type = 'checkbox';
        box.checked = visible;
        box.dataset.layer = name;
        box.addEventListener('change', () => onToggle(name, box.checked));
        row.append(box);
        if (color) {
          const chip = document.createElement('span');
          chip.className = 'swatch';
          chip.style.background = color;
          row.append(chip);
        }
        row.append(label);
        return row;
      }),
    );
  }
}
