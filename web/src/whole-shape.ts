/**
 * The whole-shape mode: runs the CSCD-M pipeline in the worker with progress and cancel, draws the
 * candidate loops as they arrive, then shows the result view by view (Candidates, Packing, Regions,
 * Skeleton). Its viewer layers are named `sk-*`; the surface is shared with the single-source mode.
 *
 * The reconstruction toggle adds the skeleton's convolution surface (`sk-recon`) over the input and
 * colours the input by each vertex's reconstruction error, in whichever view is shown.
 *
 * For tests: `document.body.dataset.skRun` is running | done | cancelled | failed,
 * `dataset.skeletonRuns` counts the results shown, `dataset.skStage` is the view shown and
 * `dataset.skRecon` the mean reconstruction error shown.
 */
import { defaultOptions } from '../../lib/core/options.ts';
import type { Options } from '../../lib/core/types.ts';
import { SK_COLORS, SK_REGIONS_STAGE, SK_SKELETON_STAGE, SK_STAGES, SkeletonPanel } from './ui/skeleton-panel.ts';
import {
  LoopSet,
  ReconstructionLayer,
  candidateRadius,
  errorVertexColors,
  regionColor,
  regionVertexColors,
  skeletonLayers,
} from './viewer/skeleton-layers.ts';
import type { Viewer } from './viewer/viewer.ts';
import { WorkerError, type GeometryClient, type SkeletonJob } from './worker/client.ts';
import type { EvaluationReply, PipelineNews, SkeletonReply } from './worker/protocol.ts';

export interface WholeShapeContext {
  viewer: Viewer;
  client: GeometryClient;
  /** Layers the user switched off in the layer list (shared with the other mode). */
  userHidden: Set<string>;
  layerColors: Map<string, string>;
  /** The options shared with stage 1 (target, sphere constraint). */
  baseOptions(): Options;
  /** A computation starts / ends (page state, busy status). */
  begin(status: string): void;
  end(): void;
  /** Shows an error box. */
  fail(title: string, error: unknown): void;
  setStatus(text: string): void;
  updateLayerList(): void;
}

/** Least time between two redraws of the candidate loops while they arrive. */
const PROGRESS_REDRAW_MS = 400;

export const isSkeletonLayer = (name: string) => name.startsWith('sk-');

export interface LayerEntry {
  name: string;
  label: string;
  visible: boolean;
  color?: string;
  dimmed?: boolean;
}

export class WholeShape {
  /** The mode is shown (its layers and surface colours apply). */
  private active = false;
  private job: SkeletonJob | null = null;
  private jobId = 0;
  private cancelRequested = false;
  /** The running job chooses N itself (the total may shrink). */
  private auto = false;
  private result: SkeletonReply | null = null;
  private progressLoops: LoopSet | null = null;
  private lastNews: PipelineNews | null = null;
  private stage = 1;
  /** The view the user stepped to; the next result shows it again. */
  private wantedStage = 1;
  private regionColors: string[] = [];
  private vertexColors: Float32Array | null = null;
  /** The evaluation of the result shown (null until the toggle first asks for it) and its colours. */
  private evaluation: EvaluationReply | null = null;
  private errorColors: Float32Array | null = null;
  private evaluating = false;
  private runs = 0;
  private redrawTimer: number | null = null;
  private lastRedraw = -Infinity;
  /** Measured cost of the last redraw of the candidate loops (ms). */
  private frameCost = 0;

  constructor(
    private readonly ctx: WholeShapeContext,
    private readonly panel: SkeletonPanel,
  ) {
    panel.onCompute = () => void this.run();
    panel.onCancel = () => this.cancel();
    panel.onRecon = () => void this.toggleRecon();
    panel.onSelect = (stage) => {
      if (!this.result) return;
      this.showStage(stage);
      this.wantedStage = this.stage;
    };
  }

  get running(): boolean {
    return this.job !== null;
  }

  // -- mode ---------------------------------------------------------------------------------------

  activate(): void {
    this.active = true;
    this.panel.active = true;
    this.apply();
  }

  /** Hides this mode's layers and surface colouring (the other mode takes over). */
  deactivate(): void {
    this.active = false;
    this.panel.active = false;
    const surface = this.ctx.viewer.surface;
    surface?.setRegionColorMix(0);
    surface?.setTranslucent(false);
    for (const [name, layer] of this.ctx.viewer.listLayers()) if (isSkeletonLayer(name)) layer.object.visible = false;
    this.ctx.viewer.requestRender();
  }

  /** A new mesh is shown: stop any run and forget the result (the viewer's layers are already gone). */
  reset(): void {
    this.cancelRedraw();
    this.job?.cancel();
    this.job = null;
    this.jobId++;
    this.result = null;
    this.progressLoops = null;
    this.lastNews = null;
    this.vertexColors = null;
    this.regionColors = [];
    this.forgetEvaluation();
    this.panel.endRun(false);
    this.panel.setStatus(null);
    this.panel.setResult(null);
    delete document.body.dataset.skRun;
    delete document.body.dataset.skStage;
    if (this.active) this.apply();
  }

  /** Makes the viewer show this mode: other layers hidden, the surface plain or per the view. */
  apply(): void {
    if (!this.active) return;
    const surface = this.ctx.viewer.surface;
    surface?.setScalarVisible(false);
    surface?.setRegion(null);
    surface?.setDimmed(false);
    if (this.result) {
      this.showStage(this.stage);
      return;
    }
    surface?.setRegionColorMix(0);
    surface?.setTranslucent(false);
    for (const [name, layer] of this.ctx.viewer.listLayers()) {
      if (name === 'surface') continue;
      layer.object.visible = name === 'sk-progress' && !this.ctx.userHidden.has(name);
      layer.setDimmed?.(false);
    }
    this.ctx.updateLayerList();
    this.ctx.viewer.requestRender();
  }

  /** The layer list's entries for this mode (the layers of the view shown). */
  layerEntries(): LayerEntry[] {
    const def = this.result ? SK_STAGES[this.stage - 1] : null;
    return this.ctx.viewer
      .listLayers()
      .filter(([name]) => (def ? this.viewLayers(def.layers).includes(name) : name === 'sk-progress') || name === 'surface')
      .map(([name, layer]) => ({
        name,
        label: layer.label,
        visible: !this.ctx.userHidden.has(name),
        color: this.ctx.layerColors.get(name),
        dimmed: !!def?.dimmed?.includes(name),
      }));
  }

  // -- running --------------------------------------------------------------------------------------

  async run(): Promise<void> {
    const { viewer, client } = this.ctx;
    const surface = viewer.surface;
    if (!surface || this.job) return;
    const options: Options = { ...this.ctx.baseOptions(), ...this.panel.readOptions(defaultOptions) };
    const changed = Object.fromEntries(
      (Object.keys(options) as Array<keyof Options>).filter((k) => options[k] !== defaultOptions[k]).map((k) => [k, options[k]]),
    ) as Partial<Options>;

    // Forget the previous result; candidate loops are drawn as they come.
    this.result = null;
    this.forgetEvaluation();
    this.lastNews = null;
    for (const [name] of viewer.listLayers()) if (isSkeletonLayer(name)) viewer.setLayer(name, null);
    this.progressLoops = new LoopSet(surface, 0.6 * candidateRadius(surface));
    this.ctx.layerColors.set('sk-progress', SK_COLORS.candidate);
    this.cancelRequested = false;
    this.auto = options.n === 'auto';
    this.panel.startRun(options.n);
    document.body.dataset.skRun = 'running';
    delete document.body.dataset.skStage;
    this.apply();

    const id = ++this.jobId;
    this.ctx.begin('stage 1: starting…');
    const job = client.skeleton(changed, (news) => {
      if (id === this.jobId) this.receive(news);
    });
    this.job = job;
    let keepProgress = false;
    try {
      const reply = await job.result;
      if (id !== this.jobId) return;
      if (this.cancelRequested) throw new WorkerError('cancelled', 'The computation was cancelled.');
      this.showResult(reply);
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
        this.job = null;
        this.panel.endRun(keepProgress);
        if (!this.result) this.panel.setResult(null);
      }
      this.ctx.end();
    }
  }

  cancel(): void {
    if (!this.job || this.cancelRequested) return;
    this.cancelRequested = true;
    this.panel.cancelling();
    this.ctx.setStatus('cancelling…');
    this.job.cancel();
  }

  private receive(news: PipelineNews): void {
    this.lastNews = news;
    this.panel.setProgress(news.done, news.total, this.auto ? 'stage 1 · auto: ends when loops stop adding coverage' : 'stage 1');
    if (news.finished) this.panel.setStage2();
    if (this.cancelRequested) this.panel.cancelling();
    if (!this.progressLoops) return;
    const before = this.progressLoops.count;
    for (const loop of news.newLoops) this.progressLoops.add(loop);
    if (this.progressLoops.count === before) return;
    // Redrawn at most every PROGRESS_REDRAW_MS, and rarer when frames are slow (a software
    // renderer with the worker busy on the same cores), so the page stays responsive.
    if (this.redrawTimer === null) {
      const every = Math.max(PROGRESS_REDRAW_MS, 4 * this.frameCost);
      const wait = Math.max(0, this.lastRedraw + every - performance.now());
      this.redrawTimer = window.setTimeout(() => this.drawProgress(), wait);
    }
  }

  private drawProgress(): void {
    this.redrawTimer = null;
    this.lastRedraw = performance.now();
    const surface = this.ctx.viewer.surface;
    if (!surface || !this.progressLoops) return;
    const layer = this.progressLoops.layer(`Candidate loops (${this.progressLoops.count})`, SK_COLORS.candidate, candidateRadius(surface));
    layer.object.visible = this.active && !this.ctx.userHidden.has('sk-progress');
    this.ctx.viewer.setLayer('sk-progress', layer);
    // The time to the frame after the next one: how long the page is held up by drawing the loops.
    const t = performance.now();
    requestAnimationFrame(() => requestAnimationFrame(() => (this.frameCost = performance.now() - t)));
  }

  private cancelRedraw(): void {
    if (this.redrawTimer !== null) window.clearTimeout(this.redrawTimer);
    this.redrawTimer = null;
  }

  // -- the result -----------------------------------------------------------------------------------

  private showResult(reply: SkeletonReply): void {
    const { viewer } = this.ctx;
    const surface = viewer.surface!;
    const s = reply.skeleton;
    this.cancelRedraw();
    viewer.setLayer('sk-progress', null);
    this.progressLoops = null;
    for (const { name, layer, color } of skeletonLayers(s, surface)) {
      this.ctx.layerColors.set(name, color);
      layer.object.visible = false;
      viewer.setLayer(name, layer);
    }
    const nodeCount = Math.floor(s.nodes.length / 3);
    // The legend lists the regions (nodes that own vertices; branch nodes own none).
    const owned = new Set<number>();
    for (const node of s.vertexToNode) if (node < nodeCount) owned.add(node);
    this.regionColors = [...owned].sort((a, b) => a - b).map(regionColor);
    this.vertexColors = regionVertexColors(s.vertexToNode, nodeCount, surface.vertexCount);
    surface.setRegionColors(this.vertexColors, 0);
    this.result = reply;
    this.panel.setResult(reply, owned.size);
    this.panel.setStatus({
      kind: 'done',
      title: 'Skeleton computed',
      text: `${nodeCount} nodes and ${Math.floor(s.edges.length / 2)} edges from ${s.stats.packed} packed loops of ${s.stats.candidates} candidates.`,
    });
    document.body.dataset.skRun = 'done';
    document.body.dataset.skeletonRuns = String(++this.runs);
    this.showStage(this.wantedStage);
  }

  private showStage(wanted: number): void {
    if (!this.result) return;
    this.stage = Math.min(Math.max(1, wanted), SK_STAGES.length);
    if (!this.active) return;
    const def = SK_STAGES[this.stage - 1];
    const { viewer, userHidden } = this.ctx;
    const shown = this.viewLayers(def.layers);
    for (const [name, layer] of viewer.listLayers()) {
      if (name === 'surface') continue;
      layer.object.visible = shown.includes(name) && !userHidden.has(name);
      layer.setDimmed?.(!!def.dimmed?.includes(name));
    }
    const surface = viewer.surface;
    if (this.errorColors && this.panel.reconShown) {
      // The error colours replace the view's colouring; the shell over an opaque surface shows where
      // the reconstruction bulges out, the colours where it falls short.
      surface?.setRegionColors(this.errorColors, 1);
      surface?.setTranslucent(false);
    } else {
      if (this.vertexColors) surface?.setRegionColors(this.vertexColors, 0);
      surface?.setRegionColorMix(this.stage === SK_REGIONS_STAGE ? 1 : 0);
      surface?.setTranslucent(this.stage === SK_SKELETON_STAGE);
    }
    const present = new Set(viewer.listLayers().map(([name]) => name));
    this.panel.setStage(this.stage, this.result, present, this.regionColors);
    this.ctx.updateLayerList();
    viewer.requestRender();
  }

  // -- reconstruction error ------------------------------------------------------------------------

  /** A view's layers, plus the reconstructed surface while the toggle is on. */
  private viewLayers(layers: string[]): string[] {
    return this.errorColors && this.panel.reconShown ? [...layers, 'sk-recon'] : layers;
  }

  private forgetEvaluation(): void {
    this.evaluation = null;
    this.errorColors = null;
    this.ctx.viewer.setLayer('sk-recon', null);
    this.panel.setRecon({ kind: 'off' });
    delete document.body.dataset.skRecon;
  }

  /** The toggle changed: evaluate the result once (in the worker), then show or hide it. */
  private async toggleRecon(): Promise<void> {
    const result = this.result;
    if (this.panel.reconShown && result && !this.evaluation && !this.evaluating) {
      this.evaluating = true;
      this.panel.setRecon({ kind: 'busy' });
      this.ctx.begin('reconstructing the surface from the skeleton…');
      try {
        const reply = await this.ctx.client.evaluate();
        if (result !== this.result) return; // a new run replaced the skeleton meanwhile
        this.evaluation = reply;
        const e = reply.evaluation;
        // The top of the colour bar at the 95th percentile: the worst vertices saturate, the rest spread.
        this.errorColors = errorVertexColors(e.vertexError, e.p95);
        this.ctx.layerColors.set('sk-recon', SK_COLORS.reconstruction);
        this.ctx.viewer.setLayer('sk-recon', new ReconstructionLayer('Reconstructed surface', e.surface.positions, e.surface.triangles));
      } catch (error) {
        if (result === this.result) {
          const message = error instanceof Error ? error.message : String(error);
          this.panel.setRecon({ kind: 'failed', message: `The reconstruction failed: ${message}` });
        }
        return;
      } finally {
        this.evaluating = false;
        this.ctx.end();
      }
    }
    if (this.evaluation) this.panel.setRecon({ kind: 'done', reply: this.evaluation, max: this.evaluation.evaluation.p95 });
    this.showStage(this.stage);
  }
}
