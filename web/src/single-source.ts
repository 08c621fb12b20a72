/**
 * Stage 1 from one source vertex or point (the teaching half of the timeline): runs it in the worker
 * for a clicked or random vertex of a mesh or point of a cloud, re-runs the same source when a stage-1
 * option changes (per-shape data is cached in the core, so that is quick), and builds the layers of
 * every intermediate result.
 */
import { SOURCE_STAGES, type StageKey } from './stage-defs.ts';
import { changedOptions, type StudioContext } from './studio-context.ts';
import { reachedStage, showSeparatorFigures } from './ui/separator-panel.ts';
import { niceSpacing } from './viewer/colormap.ts';
import { PointsLayer, SpheresLayer } from './viewer/layers.ts';
import { separatorLayers } from './viewer/separator-layers.ts';
import { WorkerError } from './worker/client.ts';
import type { SeparatorReply } from './worker/protocol.ts';

/** Names of the layers a stage-1 run adds (besides the surface's colormap). */
const SEPARATOR_LAYERS = ['source', 'cut-locus', 'boundary-extremities', 'target', 'path-1', 'path-2', 'approx-loop', 'sphere', 'iterates', 'loop'];

export class SingleSource {
  /** The run shown (null: none yet, or it failed). */
  reply: SeparatorReply | null = null;
  private latest = 0;
  private runs = 0;
  /** Requests sent and not answered yet. */
  private inFlight = 0;
  /** Bumped when the mesh changes, so late replies for the old one are dropped. */
  private generation = 0;

  constructor(private readonly ctx: StudioContext) {}

  /** A run is on its way (entering a stage should wait for it rather than start another). */
  get busy(): boolean {
    return this.inFlight > 0;
  }

  get source(): number | null {
    return this.reply?.separator.source ?? null;
  }

  /** The last source stage the shown run reached (null: no run). */
  get reached(): StageKey | null {
    return this.reply ? reachedStage(this.reply.separator.status) : null;
  }

  /** Whether `key` (a source stage) has data to show. */
  has(key: StageKey): boolean {
    const reached = this.reached;
    return reached !== null && SOURCE_STAGES.indexOf(key) <= SOURCE_STAGES.indexOf(reached);
  }

  /** A new mesh is shown: forget the run (the viewer's layers are already gone). */
  reset(): void {
    this.generation++;
    this.reply = null;
    showSeparatorFigures(null);
  }

  /** Runs stage 1 from `source` with the current options; resolves when it is shown (or failed). */
  async run(source: number): Promise<void> {
    const { viewer, client } = this.ctx;
    const surface = viewer.surface;
    if (!surface || source < 0 || source >= surface.vertexCount) return;
    const generation = this.generation;
    const request = ++this.latest;
    const current = () => generation === this.generation && request === this.latest;
    if (this.source !== source) {
      const radius = surface.boundingSphere.radius * 0.022;
      this.ctx.layerColors.set('source', '#ffffff');
      const label = surface instanceof PointsLayer ? 'Source point' : 'Source vertex';
      viewer.setLayer('source', new SpheresLayer(label, surface.vertexPosition(source).toArray(), radius));
    }
    this.ctx.begin('computing stage 1…');
    this.inFlight++;
    this.ctx.progressed(); // the pills say it is computing
    try {
      const reply = await client.separator(source, changedOptions(this.ctx.options()));
      if (current()) this.show(reply);
    } catch (error) {
      if (!current()) return;
      this.clear();
      // A crash is reported by the page's crash handler; a cancel is the user's own doing.
      if (!(error instanceof WorkerError && (error.kind === 'crash' || error.kind === 'cancelled'))) {
        this.ctx.fail('Could not compute stage 1 (geodesic distance)', error);
      }
    } finally {
      this.inFlight--;
      this.ctx.end();
      if (current()) this.ctx.changed();
    }
  }

  /** A vertex (or point) drawn at random (uniformly), for "Random". */
  runRandom(): Promise<void> {
    const count = this.ctx.viewer.surface?.vertexCount ?? 0;
    return count > 0 ? this.run(Math.floor(Math.random() * count)) : Promise.resolve();
  }

  /** The options changed: the same source again. */
  rerun(): Promise<void> {
    const source = this.source;
    return source === null ? Promise.resolve() : this.run(source);
  }

  /** The surface for a source stage: the distance colormap (muted once lines are drawn on it) and the constraint region. */
  applySurface(key: StageKey, sphereShown: boolean): void {
    const surface = this.ctx.viewer.surface;
    if (!surface || !this.reply) return;
    surface.setScalarVisible(true);
    surface.setDimmed(key !== 'geodesics');
    const sphere = this.reply.separator.sphere;
    surface.setRegion(key === 'loop' && sphereShown ? sphere : null, 0.6);
  }

  private show(reply: SeparatorReply): void {
    const { viewer, layerColors } = this.ctx;
    const surface = viewer.surface!;
    const s = reply.separator;
    const spacing = niceSpacing(reply.distanceMax);
    surface.setScalarField({ values: s.distance, max: reply.distanceMax, isolineSpacing: spacing });
    for (const name of SEPARATOR_LAYERS) if (name !== 'source') viewer.setLayer(name, null);
    for (const { name, layer, color } of separatorLayers(s, surface)) {
      layerColors.set(name, color);
      viewer.setLayer(name, layer);
    }
    this.reply = reply;
    showSeparatorFigures(reply, spacing);
    document.body.dataset.separatorRuns = String(++this.runs);
  }

  private clear(): void {
    this.reply = null;
    for (const name of SEPARATOR_LAYERS) this.ctx.viewer.setLayer(name, null);
    this.ctx.viewer.surface?.setScalarField(null);
    showSeparatorFigures(null);
  }
}
