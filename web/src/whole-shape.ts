/**
 * The whole-shape half of the timeline: runs the CSCD-M pipeline in the worker with progress and
 * cancel, draws the candidate loops as they arrive, builds the result's layers (`sk-*`: candidates by
 * fate, packed loops, skeleton nodes and edges), the per-vertex region colours, the reconstruction
 * error (evaluated once, when its stage is first entered) and the selection of a node and its region.
 *
 * For tests: `document.body.dataset.skRun` is running | done | cancelled | failed,
 * `dataset.skeletonRuns` counts the results shown, `dataset.skRecon` is the mean reconstruction error
 * shown and `dataset.skSelected` the selected node.
 */
import * as THREE from 'three';
import { changedOptions, type StudioContext } from './studio-context.ts';
import { COLORS, type StageKey } from './stage-defs.ts';
import { byTestId, formatLength } from './ui/panel.ts';
import { SkeletonPanel } from './ui/skeleton-panel.ts';
import { progressTextMs, Throttle } from './ui/throttle.ts';
import {
  LoopSet,
  ReconstructionLayer,
  RegionLayer,
  candidateRadius,
  errorVertexColors,
  nodeRadii,
  regionColor,
  regionTriangles,
  regionVertexColors,
  skeletonLayers,
} from './viewer/skeleton-layers.ts';
import { SurfaceLayer } from './viewer/layers.ts';
import { GlassSphereLayer } from './viewer/tubes.ts';
import { WorkerError, type SkeletonJob } from './worker/client.ts';
import type { EvaluationReply, PipelineNews, PoolReport, SkeletonReply } from './worker/protocol.ts';

/** Lets the page handle input and draw between two pieces of work. */
const nextTask = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/**
 * Least time between two redraws of the candidate loops while they arrive, with a GPU and without one.
 * A software renderer draws each frame on the cores the workers compute on, in the GPU process, where
 * the page cannot time it: two workers on this 2-core machine took 1.41x Node's time for bob's stage 1
 * with a redraw every 400 ms, 1.15x without redraws (docs/parallel.md).
 */
const PROGRESS_REDRAW_MS = { gpu: 400, software: 1500 };

const isSkeletonLayer = (name: string) => name.startsWith('sk-');

const sentence = (text: string) => `${text.charAt(0).toUpperCase()}${text.slice(1)}.`;

/** What stage 1 ran on, when there is something to say: a pool, memory that held it back, a worker lost. */
function poolSentences(pool: PoolReport): string[] {
  const on = `Stage 1 on ${pool.workers} worker${pool.workers === 1 ? '' : 's'}`;
  const head = pool.memoryCapped ? [`${on}: this browser's memory allows no more on a mesh this large.`] : pool.workers > 1 ? [`${on}.`] : [];
  return [...head, ...pool.notices.map(sentence)];
}

export class WholeShape {
  result: SkeletonReply | null = null;
  /** The evaluation of the result (null until the reconstruction stage first asks for it). */
  evaluation: EvaluationReply | null = null;
  /** The selected skeleton node, or null. */
  private selected: number | null = null;
  /** Fraction of the sources done while running (null otherwise). */
  progress: number | null = null;

  private readonly panel = new SkeletonPanel();
  private job: SkeletonJob | null = null;
  private runPromise: Promise<void> | null = null;
  private jobId = 0;
  private cancelRequested = false;
  /** The running job chooses N itself (the total may shrink). */
  private auto = false;
  private progressLoops: LoopSet | null = null;
  private lastNews: PipelineNews | null = null;
  private regionColors: string[] = [];
  private vertexColors: Float32Array | null = null;
  /** The region colours with every region but the selected one greyed. */
  private selectedColors: Float32Array | null = null;
  private errorColors: Float32Array | null = null;
  private evaluating: Promise<void> | null = null;
  private runs = 0;
  private redrawTimer: number | null = null;
  private lastRedraw = -Infinity;
  /** The latest news in the panel and the timeline, at most every PROGRESS_TEXT_MS. */
  private readonly newsShown = new Throttle(() => progressTextMs(this.ctx.viewer.software));
  /** Measured cost of the last redraw of the candidate loops (ms). */
  private frameCost = 0;

  constructor(private readonly ctx: StudioContext) {
    this.panel.onCompute = () => void this.run();
    this.panel.onCancel = () => this.cancel();
  }

  get running(): boolean {
    return this.job !== null;
  }

  /** A new mesh is shown: stop any run and forget the result (the viewer's layers are already gone). */
  reset(): void {
    this.invalidate();
    this.panel.setStatus(null);
    delete document.body.dataset.skRun;
  }

  /** The options changed: stop any run and drop the result, its layers and evaluation. */
  invalidate(): void {
    this.cancelRedraw();
    this.newsShown.reset();
    this.job?.cancel();
    this.job = null;
    this.runPromise = null;
    this.progress = null;
    this.jobId++;
    this.result = null;
    this.progressLoops = null;
    this.lastNews = null;
    this.vertexColors = null;
    this.regionColors = [];
    this.forgetEvaluation();
    this.select(null);
    for (const [name] of this.ctx.viewer.listLayers()) if (isSkeletonLayer(name)) this.ctx.viewer.setLayer(name, null);
    this.panel.endRun(false);
    this.panel.setResult(null);
  }

  // -- running --------------------------------------------------------------------------------------

  /** Starts a run with the current options (or returns the one running); resolves when it ends. */
  run(): Promise<void> {
    if (!this.runPromise) {
      const run: Promise<void> = this.runJob().finally(() => {
        if (this.runPromise === run) this.runPromise = null; // not a newer run's
      });
      this.runPromise = run;
    }
    return this.runPromise;
  }

  private async runJob(): Promise<void> {
    const { viewer, client } = this.ctx;
    const surface = viewer.surface;
    if (!surface) return;
    const options = this.ctx.options();
    this.invalidate();
    this.progressLoops = new LoopSet(surface, 0.6 * candidateRadius(surface));
    this.lastRedraw = performance.now(); // the first loops wait too: a short run is drawn less often
    this.ctx.layerColors.set('sk-progress', COLORS.candidate);
    this.cancelRequested = false;
    this.auto = options.n === 'auto';
    this.progress = 0;
    this.panel.startRun(options.n);
    document.body.dataset.skRun = 'running';

    const id = ++this.jobId;
    this.ctx.begin('stage 1: starting…');
    const job = client.skeleton(changedOptions(options), this.ctx.settings().workers, (news) => {
      if (id === this.jobId) this.receive(news);
    });
    this.job = job;
    this.ctx.changed();
    let keepProgress = false;
    try {
      const reply = await job.result;
      if (id !== this.jobId) return;
      if (this.cancelRequested) throw new WorkerError('cancelled', 'The computation was cancelled.');
      // Nothing is left to stop: a Cancel pressed while the result is drawn would be a no-op.
      this.panel.drawing();
      if (!(await this.showResult(reply, id))) return;
    } catch (error) {
      if (id !== this.jobId) return;
      const news = this.lastNews as PipelineNews | null; // set by the progress callback meanwhile
      const done = news ? `${news.done} / ${news.total} sources` : 'before the first source';
      if (error instanceof WorkerError && error.kind === 'cancelled') {
        keepProgress = !!news;
        if (this.redrawTimer !== null) {
          this.cancelRedraw();
          this.drawProgress(); // the loops found before the cancel, all of them
        }
        document.body.dataset.skRun = 'cancelled';
        this.panel.setStatus({
          kind: 'cancelled',
          title: 'Cancelled',
          text: `Stopped after ${done}${this.progressLoops?.count ? '; the loops found so far are shown' : ''}.`,
        });
      } else {
        document.body.dataset.skRun = 'failed';
        const message = error instanceof Error ? error.message : String(error);
        this.cancelRedraw();
        this.panel.setStatus({ kind: 'failed', title: 'The skeleton could not be computed', text: message });
        // A crash is reported by the page's crash handler; anything else in the error box too.
        if (!(error instanceof WorkerError && error.kind === 'crash')) this.ctx.fail('Could not compute the skeleton', error);
      }
    } finally {
      if (id === this.jobId) {
        this.newsShown.reset();
        this.job = null;
        this.progress = null;
        this.panel.endRun(keepProgress);
        if (!this.result) this.panel.setResult(null);
        this.ctx.changed();
      }
      this.ctx.end();
    }
  }

  cancel(): void {
    if (!this.job || this.cancelRequested) return;
    this.cancelRequested = true;
    this.panel.cancelling();
    this.job.cancel();
  }

  private receive(news: PipelineNews): void {
    // A separator worker lost: said at once, the run goes on.
    if (news.notices.length > (this.lastNews?.notices.length ?? 0)) {
      this.panel.setStatus({ kind: 'running', title: 'Stage 1 goes on', text: news.notices.map(sentence).join(' ') });
    }
    this.lastNews = news;
    this.progress = news.total > 0 ? news.done / news.total : 0;
    // The first news of a run and the last at once, the others at most every PROGRESS_TEXT_MS.
    this.newsShown.run(() => this.showNews(), news.finished);
    if (!this.progressLoops) return;
    const before = this.progressLoops.count;
    news.newLoops.forEach((loop, i) => this.progressLoops!.add(loop, news.newClosed[i] === 1));
    if (this.progressLoops.count === before) return;
    // Redrawn at most every PROGRESS_REDRAW_MS, and rarer when frames are slow (a software
    // renderer with the worker busy on the same cores), so the page stays responsive.
    if (this.redrawTimer === null) {
      const every = Math.max(PROGRESS_REDRAW_MS[this.ctx.viewer.software ? 'software' : 'gpu'], 4 * this.frameCost);
      const wait = Math.max(0, this.lastRedraw + every - performance.now());
      this.redrawTimer = window.setTimeout(() => this.drawProgress(), wait);
    }
  }

  /** The latest news in the panel and the timeline. */
  private showNews(): void {
    const news = this.lastNews;
    if (!news) return;
    this.panel.setProgress(news.done, news.total, this.auto ? 'stage 1 · auto: ends when loops stop adding coverage' : 'stage 1');
    if (news.finished) this.panel.setStage2();
    if (this.cancelRequested) this.panel.cancelling();
    this.ctx.progressed();
  }

  private drawProgress(): void {
    this.redrawTimer = null;
    this.lastRedraw = performance.now();
    const surface = this.ctx.viewer.surface;
    if (!surface || !this.progressLoops) return;
    const layer = this.progressLoops.layer(`Candidate loops (${this.progressLoops.count})`, COLORS.candidate, candidateRadius(surface));
    this.ctx.viewer.setLayer('sk-progress', layer);
    this.ctx.changed();
    // The time to the frame after the next one: how long the page is held up by drawing the loops.
    const t = performance.now();
    requestAnimationFrame(() => requestAnimationFrame(() => (this.frameCost = performance.now() - t)));
  }

  private cancelRedraw(): void {
    if (this.redrawTimer !== null) window.clearTimeout(this.redrawTimer);
    this.redrawTimer = null;
  }

  // -- the result -----------------------------------------------------------------------------------

  /** Builds the result's layers a task at a time (the page stays responsive); false if a newer run took over. */
  private async showResult(reply: SkeletonReply, id: number): Promise<boolean> {
    const { viewer } = this.ctx;
    const surface = viewer.surface!;
    const s = reply.skeleton;
    this.cancelRedraw();
    for (const { name, layer, color } of skeletonLayers(s, surface)) {
      await nextTask();
      if (id !== this.jobId) {
        layer.dispose();
        return false;
      }
      this.ctx.layerColors.set(name, color);
      layer.object.visible = false; // until the stage shown asks for it
      viewer.setLayer(name, layer);
    }
    await nextTask();
    if (id !== this.jobId) return false;
    viewer.setLayer('sk-progress', null);
    this.progressLoops = null;
    const nodeCount = Math.floor(s.nodes.length / 3);
    // The legend lists the band pieces (nodes that own vertices; branch nodes own none).
    const owned = new Set<number>();
    for (const node of s.vertexToNode) if (node < nodeCount) owned.add(node);
    this.regionColors = [...owned].sort((a, b) => a - b).map(regionColor);
    this.vertexColors = regionVertexColors(s.vertexToNode, nodeCount, surface.vertexCount);
    this.result = reply;
    this.panel.setResult(reply, owned.size);
    this.panel.setStatus({
      kind: 'done',
      title: 'Skeleton computed',
      text: [
        `${nodeCount} nodes and ${Math.floor(s.edges.length / 2)} edges from ${s.stats.packed} packed loops of ${s.stats.candidates} candidates.`,
        ...(s.stats.simplified ? [`Stage 1 ran on a copy simplified to ${s.stats.simplified.toVertices} vertices (option stage1Vertices).`] : []),
        ...poolSentences(reply.pool),
      ].join(' '),
    });
    document.body.dataset.skRun = 'done';
    document.body.dataset.skeletonRuns = String(++this.runs);
    return true;
  }

  /** The surface for a whole-shape stage: plain, in region colours, see-through or in error colours. */
  applySurface(key: StageKey): void {
    const surface = this.ctx.viewer.surface;
    if (!surface) return;
    surface.setScalarVisible(false);
    surface.setRegion(null);
    surface.setDimmed(false);
    const selected = this.selectedColors;
    if (key === 'reconstruction' && this.errorColors) {
      // The error colours on the opaque surface; the shell over it shows where the reconstruction
      // bulges out, the colours where it falls short.
      surface.setRegionColors(this.errorColors, 1);
    } else if (key === 'regions' && this.vertexColors) {
      surface.setRegionColors(selected ?? this.vertexColors, 1);
    } else {
      surface.setRegionColorMix(0);
    }
    surface.setTranslucent(key === 'skeleton');
  }

  /** Legend entries a stage adds: one chip per band piece (a node's vertices) in the Regions stage. */
  legendExtras(key: StageKey): HTMLLIElement[] {
    if (key !== 'regions' || !this.result) return [];
    const li = document.createElement('li');
    li.className = 'region-chips';
    li.append(`${this.regionColors.length} band piece${this.regionColors.length === 1 ? '' : 's'}`);
    for (const [i, color] of this.regionColors.entries()) {
      const chip = document.createElement('span');
      chip.className = 'swatch';
      chip.style.background = color;
      chip.title = `band piece ${i + 1}`;
      li.append(chip);
    }
    return [li];
  }

  // -- selection ------------------------------------------------------------------------------------

  /** Selects the node whose region holds `vertex`. */
  selectVertex(vertex: number): void {
    const s = this.result?.skeleton;
    if (!s) return;
    const node = vertex < s.vertexToNode.length ? s.vertexToNode[vertex] : -1;
    this.select(node >= 0 && node < s.nodes.length / 3 ? node : null);
  }

  /** Selects a skeleton node (null: none): a halo around it and its region picked out on the surface. */
  select(node: number | null): void {
    const { viewer } = this.ctx;
    const s = this.result?.skeleton;
    const surface = viewer.surface;
    this.selected = s && surface ? node : null;
    this.selectedColors = null;
    viewer.setLayer('sk-highlight', null);
    viewer.setLayer('sk-region', null);
    const info = byTestId('sk-selection');
    if (this.selected === null || !s || !surface || !this.vertexColors) {
      info.hidden = true;
      delete document.body.dataset.skSelected;
      this.ctx.changed();
      return;
    }
    const n = this.selected;
    const grey = new THREE.Color(0x8a8780).toArray();
    const colors = Float32Array.from(this.vertexColors);
    let owned = 0;
    for (let v = 0; v < surface.vertexCount; v++) {
      if (s.vertexToNode[v] === n) {
        owned++;
        continue;
      }
      for (let k = 0; k < 3; k++) colors[3 * v + k] = colors[3 * v + k] * 0.3 + grey[k] * 0.7;
    }
    this.selectedColors = colors;
    const r = nodeRadii(s, surface.boundingSphere.radius)[n] * 1.9;
    this.ctx.layerColors.set('sk-highlight', COLORS.highlight);
    viewer.setLayer('sk-highlight', new GlassSphereLayer('Selected node', s.nodes.subarray(3 * n, 3 * n + 3), r, COLORS.highlight));
    // A cloud's region is its points, coloured above: there are no triangles to draw solid.
    if (owned > 0 && surface instanceof SurfaceLayer) {
      const triangles = regionTriangles(surface.geometry.getIndex()!.array, s.vertexToNode, n);
      this.ctx.layerColors.set('sk-region', regionColor(n));
      viewer.setLayer('sk-region', new RegionLayer('Selected region', surface.geometry, triangles, regionColor(n)));
    }
    const radius = s.radii[n];
    const chip = document.createElement('span');
    chip.className = 'swatch';
    chip.style.background = owned > 0 ? regionColor(n) : COLORS.node;
    const what = owned > 0 ? `its region: ${owned} vertices` : 'a branch node (no region of its own)';
    info.replaceChildren(chip, `Node ${n} · radius ${Number.isFinite(radius) ? formatLength(radius) : '–'} · ${what}`);
    info.hidden = false;
    document.body.dataset.skSelected = String(n);
    this.ctx.changed();
  }

  // -- reconstruction error ------------------------------------------------------------------------

  private forgetEvaluation(): void {
    this.evaluation = null;
    this.errorColors = null;
    this.evaluating = null;
    this.ctx.viewer.setLayer('sk-recon', null);
    this.panel.setRecon({ kind: 'off' });
    delete document.body.dataset.skRecon;
  }

  /** Evaluates the result once (in the worker); resolves when the figures are shown (or it failed). */
  evaluate(): Promise<void> {
    if (!this.result || this.evaluation) return Promise.resolve();
    if (!this.evaluating) {
      const job: Promise<void> = this.evaluateJob().finally(() => {
        if (this.evaluating === job) this.evaluating = null; // not a newer result's
      });
      this.evaluating = job;
    }
    return this.evaluating;
  }

  private async evaluateJob(): Promise<void> {
    const result = this.result;
    this.panel.setRecon({ kind: 'busy' });
    this.ctx.begin('reconstructing the surface from the skeleton…');
    try {
      const reply = await this.ctx.client.evaluate();
      if (result !== this.result) return; // a new run replaced the skeleton meanwhile
      this.evaluation = reply;
      const e = reply.evaluation;
      // The top of the colour bar at the 95th percentile: the worst vertices saturate, the rest spread.
      this.errorColors = errorVertexColors(e.vertexError, e.p95);
      this.ctx.layerColors.set('sk-recon', COLORS.reconstruction);
      this.ctx.viewer.setLayer('sk-recon', new ReconstructionLayer('Reconstructed surface', e.surface.positions, e.surface.triangles));
      this.panel.setRecon({ kind: 'done', reply, max: e.p95 });
    } catch (error) {
      if (result === this.result) {
        const message = error instanceof Error ? error.message : String(error);
        this.panel.setRecon({ kind: 'failed', message: `The reconstruction failed: ${message}` });
      }
    } finally {
      this.ctx.end();
      this.ctx.changed();
    }
  }
}
