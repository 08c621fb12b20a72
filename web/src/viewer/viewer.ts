/**
 * The 3D view: renderer, camera, orbit controls, lights, named layers, picking. Renders on demand
 * (after a change), so an idle page costs nothing.
 */
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { PointsLayer, SurfaceLayer, type Layer, type ShapeLayer } from './layers.ts';

export interface Pick {
  /** The hit face; -1 on a point cloud. */
  face: number;
  /** The corner of the hit face nearest to the hit point. */
  vertex: number;
  point: THREE.Vector3;
}

/** Whether WebGL runs on a CPU rasterizer (SwiftShader, llvmpipe...), asked of a throwaway context. */
function isSoftwareRenderer(): boolean {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|software|softpipe/i.test(name);
}

/**
 * Points of a subsampled cloud a software renderer draws (a GPU draws them all): a still frame took
 * 1.25 s with a million points in Chromium's SwiftShader here, 0.29 s with 150,000 and 0.14 s with
 * 100,000 (scripts/page-big-cloud.ts, docs/limits.md).
 */
const SOFTWARE_DRAWN_POINTS = 100_000;

/** Pointer travel (px) below which a press-release counts as a click rather than an orbit drag. */
const CLICK_SLOP_PX = 5;

export class Viewer {
  readonly renderer: THREE.WebGLRenderer;
  /** Whether WebGL draws on the CPU: every frame then takes time from the cores the workers compute on. */
  readonly software: boolean;
  readonly scene = new THREE.Scene();
  readonly camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
  readonly controls: OrbitControls;
  /** Called with the window position when the user clicks (not drags) on the canvas. */
  onClick: ((clientX: number, clientY: number) => void) | null = null;
  /** Called when layers are added or removed. */
  onLayersChange: (() => void) | null = null;

  private readonly layers = new Map<string, Layer>();
  private readonly raycaster = new THREE.Raycaster();
  private frameRequested = false;
  /** Drawing-buffer pixels per CSS pixel when the view is still. */
  private readonly pixelRatio: number;
  private renderPending = false;
  private pointerDown: { x: number; y: number; id: number } | null = null;

  constructor(private readonly container: HTMLElement) {
    // A software renderer (no GPU) draws on the CPU cores the worker computes on, and the page waits
    // for each frame: there, no multisampling, one pixel per CSS pixel, and half that while orbiting
    // (and of a cloud drawn whole beside its subsample, the subsample alone).
    this.software = isSoftwareRenderer();
    const software = this.software;
    this.renderer = new THREE.WebGLRenderer({ antialias: !software, alpha: true, preserveDrawingBuffer: true });
    this.pixelRatio = software ? 1 : Math.min(window.devicePixelRatio, 2);
    this.renderer.setPixelRatio(this.pixelRatio);
    this.renderer.setClearColor(0x000000, 0); // the page background shows through
    this.renderer.outputColorSpace = THREE.SRGBColorSpace;
    const canvas = this.renderer.domElement;
    canvas.dataset.testid = 'viewport-canvas';
    container.append(canvas);

    this.scene.add(this.camera);
    this.addLights();

    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = true;
    this.controls.dampingFactor = 0.12;
    this.controls.addEventListener('change', () => this.requestRender());
    if (software) {
      this.controls.addEventListener('start', () => this.setMoving(true));
      this.controls.addEventListener('end', () => this.setMoving(false));
    }

    canvas.addEventListener('pointerdown', (e) => {
      if (e.button === 0 && e.isPrimary) this.pointerDown = { x: e.clientX, y: e.clientY, id: e.pointerId };
    });
    canvas.addEventListener('pointerup', (e) => this.pointerUp(e));
    canvas.addEventListener('pointercancel', () => (this.pointerDown = null));

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  private addLights(): void {
    // Sky/ground ambient, plus a key and a fill light that move with the camera so the visible side
    // is always lit the same way.
    this.scene.add(new THREE.HemisphereLight(0xe8ecf5, 0x2a2622, 0.55));
    const key = new THREE.DirectionalLight(0xfff4e6, 3.0);
    key.position.set(-1.0, 1.3, 0.9);
    const fill = new THREE.DirectionalLight(0xd8e4ff, 0.8);
    fill.position.set(1.6, -0.2, 0.7);
    const rim = new THREE.DirectionalLight(0xffffff, 1.0);
    rim.position.set(0.6, 0.9, -1.4);
    for (const light of [key, fill, rim]) {
      light.target.position.set(0, 0, -1);
      this.camera.add(light, light.target);
    }
  }

  // -- layers -----------------------------------------------------------------------------------

  /** Replaces (and disposes) the layer of that name; `null` removes it. */
  setLayer(name: string, layer: Layer | null): void {
    const old = this.layers.get(name);
    if (old) {
      this.scene.remove(old.object);
      old.dispose();
      this.layers.delete(name);
    }
    if (layer) {
      this.layers.set(name, layer);
      this.scene.add(layer.object);
    }
    this.onLayersChange?.();
    this.requestRender();
  }

  getLayer(name: string): Layer | undefined {
    return this.layers.get(name);
  }

  listLayers(): Array<[name: string, layer: Layer]> {
    return [...this.layers];
  }

  setLayerVisible(name: string, visible: boolean): void {
    const layer = this.layers.get(name);
    if (layer) {
      layer.object.visible = visible;
      this.requestRender();
    }
  }

  clearLayers(): void {
    for (const name of [...this.layers.keys()]) this.setLayer(name, null);
  }

  /** The shape: a mesh's surface (picking target, scalar fields) or a cloud's points. */
  get surface(): ShapeLayer | null {
    const layer = this.layers.get('surface');
    return layer instanceof SurfaceLayer || layer instanceof PointsLayer ? layer : null;
  }

  /** Drawing-buffer pixels per CSS pixel at rest (point sprites are sized in them). */
  get restPixelRatio(): number {
    return this.pixelRatio;
  }

  /** How many of a subsampled cloud's points to draw. */
  get drawnPointLimit(): number {
    return this.software ? SOFTWARE_DRAWN_POINTS : Infinity;
  }

  // -- camera -----------------------------------------------------------------------------------

  /**
   * Points the camera at the surface's bounding sphere from the front, slightly above; or, for close
   * views (tests, screenshots), along `direction` (from the target towards the camera) at a sphere
   * of `radius` around `center`.
   */
  frame(view: { direction?: THREE.Vector3Like; center?: THREE.Vector3Like; radius?: number } = {}): void {
    const sphere = this.surface?.boundingSphere;
    if (!sphere) return;
    const center = new THREE.Vector3().copy(view.center ?? sphere.center);
    const radius = Math.max(view.radius ?? sphere.radius, 1e-9);
    const fov = THREE.MathUtils.degToRad(this.camera.fov);
    const fit = Math.min(fov, 2 * Math.atan(Math.tan(fov / 2) * this.camera.aspect)) / 2;
    const distance = (radius / Math.sin(fit)) * 1.08;
    const direction = new THREE.Vector3().copy(view.direction ?? { x: 0.75, y: 0.35, z: -1 }).normalize();
    this.camera.position.copy(center).addScaledVector(direction, distance);
    const whole = (sphere.radius / Math.sin(fit)) * 1.08;
    this.camera.near = Math.min(distance, whole) / 100;
    this.camera.far = Math.max(distance, whole) * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.minDistance = sphere.radius * 0.05;
    this.controls.maxDistance = whole * 20;
    this.controls.update();
    this.requestRender();
  }

  /** While orbiting on a software renderer: half the pixels, and of a subsampled cloud the points computed on alone. */
  private setMoving(moving: boolean): void {
    const surface = this.surface;
    if (surface instanceof PointsLayer) surface.setMoving(moving);
    this.setPixelRatio(moving ? this.pixelRatio / 2 : this.pixelRatio);
  }

  private setPixelRatio(ratio: number): void {
    this.renderer.setPixelRatio(ratio);
    this.resize();
  }

  private resize(): void {
    const { clientWidth: w, clientHeight: h } = this.container;
    if (w === 0 || h === 0) return;
    this.renderer.setSize(w, h, false); // CSS sizes the canvas; this sets its drawing buffer
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
    this.flush();
  }

  // -- picking ----------------------------------------------------------------------------------

  private pointerUp(e: PointerEvent): void {
    const down = this.pointerDown;
    this.pointerDown = null;
    if (!down || down.id !== e.pointerId || e.button !== 0) return;
    if (Math.hypot(e.clientX - down.x, e.clientY - down.y) > CLICK_SLOP_PX) return;
    this.onClick?.(e.clientX, e.clientY);
  }

  private rayAt(clientX: number, clientY: number): void {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
  }

  /** The instance of a layer's InstancedMesh (e.g. a skeleton node sphere) under a window position, or null. */
  pickInstance(layerName: string, clientX: number, clientY: number): number | null {
    const object = this.layers.get(layerName)?.object;
    if (!object?.visible) return null;
    this.rayAt(clientX, clientY);
    return this.raycaster.intersectObject(object, true)[0]?.instanceId ?? null;
  }

  /** The surface point under a window position, or null. */
  pick(clientX: number, clientY: number): Pick | null {
    const surface = this.surface;
    if (!surface || !surface.object.visible) return null;
    this.rayAt(clientX, clientY);
    if (surface instanceof PointsLayer) return this.pickPoint(surface);
    const hit = this.raycaster.intersectObject(surface.object, false)[0];
    if (!hit?.face || hit.faceIndex == null) return null;
    let vertex = hit.face.a;
    let best = Infinity;
    const p = new THREE.Vector3();
    for (const v of [hit.face.a, hit.face.b, hit.face.c]) {
      const d = surface.vertexPosition(v, p).distanceToSquared(hit.point);
      if (d < best) [best, vertex] = [d, v];
    }
    return { face: hit.faceIndex, vertex, point: hit.point.clone() };
  }

  /** The point nearest the camera among those within a hundredth of the cloud's radius of the ray. */
  private pickPoint(points: PointsLayer): Pick | null {
    this.raycaster.params.Points.threshold = points.boundingSphere.radius * 0.01;
    const hit = points.intersect(this.raycaster);
    return hit && { face: -1, vertex: hit.point, point: hit.at };
  }

  /** Window position of a vertex (for tests and overlays). */
  projectVertex(index: number): { x: number; y: number } | null {
    const surface = this.surface;
    return surface ? this.projectPoint(surface.vertexPosition(index).toArray()) : null;
  }

  /** Window position of a point in space. */
  projectPoint(xyz: ArrayLike<number>): { x: number; y: number } {
    const p = new THREE.Vector3(xyz[0], xyz[1], xyz[2]).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  // -- rendering --------------------------------------------------------------------------------

  requestRender(): void {
    this.renderPending = true;
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      this.frameRequested = false;
      this.flush();
    });
  }

  /** Renders now if anything changed since the last frame (so pixels are current when state changes). */
  flush(): void {
    if (!this.renderPending) return;
    this.renderPending = false;
    this.controls.update(); // while damping, this emits 'change', which requests the next frame
    this.renderer.render(this.scene, this.camera);
  }
}
