/**
 * The studio's stages, in the order of the timeline: what each one shows (its viewer layers, which of
 * them are context drawn muted, its legend), what it explains, and the layer colours. One list for
 * the whole page: the timeline, the stage card, the layer list and the viewer all read it.
 */

/** Layer colours (sRGB), shared by the viewer layers, the legends and the layer list. */
export const COLORS = {
  source: '#ffffff',
  cutLocus: '#ffd21a',
  target: '#a34dff',
  path1: '#ff3131',
  path2: '#74ff2e',
  approxLoop: '#ff8c00',
  sphere: '#8fc3ff',
  loop: '#00e1ff',
  /** A cloud's loop at the recorded steps of its shortening. */
  iterates: '#2f8fa3',
  /** Candidate loops while they arrive. */
  candidate: '#ffd21a',
  packed: '#00e1ff',
  rejected: '#ff4f9a',
  node: '#ff6a2b',
  edge: '#ffb02e',
  /** The selected skeleton node's halo. */
  highlight: '#ffffff',
  /** The reconstructed surface of the evaluation. */
  reconstruction: '#9fc4ff',
} as const;

export type StageKey =
  | 'mesh'
  | 'geodesics'
  | 'cut-locus'
  | 'paths'
  | 'loop'
  | 'separators'
  | 'packing'
  | 'regions'
  | 'skeleton'
  | 'reconstruction';

/** `source`: stage 1 from one source vertex (teaching); `shape`: the whole pipeline. */
export type StageGroup = 'mesh' | 'source' | 'shape';

export interface StageDef {
  key: StageKey;
  title: string;
  group: StageGroup;
  /** Paper reference. */
  section: string;
  /** What the picture shows and why the step exists, for a student who knows what a geodesic is. */
  caption: string;
  /** Viewer layers shown in this stage (the surface always is). */
  layers: string[];
  /** Of those, the ones drawn muted (context from an earlier stage). */
  dimmed?: string[];
  legend: Array<{ layer: string; label: string; color: string }>;
  /** What a click on the surface does here (the viewport hint); null: nothing. */
  click: string | null;
  /** On a point cloud (CSCD-PC), where its steps differ from the mesh's: their own paper reference and caption. */
  cloud?: { section: string; caption: string; click?: string };
}

const PICK = 'click the surface to run stage 1 from that vertex';
const PICK_POINT = 'click a point to run stage 1 from it';
const SOURCE = ['source'];
const PATHS = ['target', 'path-1', 'path-2'];

export const STAGES: readonly StageDef[] = [
  {
    key: 'mesh',
    title: 'Mesh',
    group: 'mesh',
    section: 'Sec. 3',
    caption:
      'The input: a closed triangle mesh, read as a continuous surface. CSCD needs it manifold and consistently oriented so that geodesic distances exist; the panel lists its facts (genus = the number of handles, which the skeleton will show as cycles).',
    layers: [],
    legend: [],
    click: PICK,
    cloud: {
      section: 'Sec. 4',
      caption:
        'The input: a point cloud, read as samples of a surface. CSCD-PC builds each point a local triangulation of its nearest neighbours; glued together as a tufted cover they carry the heat method, and their edges that stay in the tangent planes make the graph the cut locus and the paths run on. The panel lists its facts.',
      click: PICK_POINT,
    },
  },
  {
    key: 'geodesics',
    title: 'Geodesics',
    group: 'source',
    section: 'Sec. 4.1.1',
    caption:
      'Geodesic distance from the source vertex (heat method on the intrinsic Delaunay triangulation), blue near and red far, with isolines. Every later step of stage 1 is read off this field.',
    layers: SOURCE,
    legend: [{ layer: 'source', label: 'source', color: COLORS.source }],
    click: PICK,
    cloud: {
      section: 'Sec. 4.1.1',
      caption:
        'Geodesic distance from the source point by the heat method on the tufted Laplacian of the cloud (Sharp & Crane), blue near and red far. Every later step of stage 1 is read off this field.',
      click: PICK_POINT,
    },
  },
  {
    key: 'cut-locus',
    title: 'Cut locus',
    group: 'source',
    section: 'Sec. 4.1.2',
    caption:
      'Where shortest paths from the source collide: the ridges of the distance, kept as a graph on mesh vertices. It reaches around every part of the shape the source cannot see directly; on a closed surface its cycle rank is twice the genus. On an open surface the balls mark boundary points where the distance is lowest along the boundary: a separator may end at two of them.',
    layers: [...SOURCE, 'cut-locus', 'boundary-extremities'],
    legend: [
      { layer: 'cut-locus', label: 'cut locus', color: COLORS.cutLocus },
      { layer: 'boundary-extremities', label: 'boundary extremities', color: COLORS.cutLocus },
    ],
    click: PICK,
    cloud: {
      section: 'Sec. 4.1.2 and App.',
      caption:
        'Where shortest paths from the source collide, found by the paper\'s method for clouds (appendix "Our adaptation on point clouds") on the cloud\'s neighbourhood graph: points where the distance gradient (the point-cloud gradient operator) turns sharply across a neighbour and where the distance is ridge-like (its Laplacian), joined into a tree grown from the farthest point, whose short branches are pruned. A plain angle threshold would leave it in dozens of pieces: the tree bridges them.',
      click: PICK_POINT,
    },
  },
  {
    key: 'paths',
    title: 'Target & paths',
    group: 'source',
    section: 'Sec. 4.1.3–4.1.4',
    caption:
      'The target is the cut-locus point nearest to the source. From it, two steepest-descent paths run down the distance on the two sides of the cut locus until they meet: together they go once around the part the target sits on. On an open surface the target can instead be two boundary points of one boundary loop whose distance gradients point in opposite directions (Sec. 3.2): the paths from them make an open path across the sheet.',
    layers: [...SOURCE, 'cut-locus', 'boundary-extremities', ...PATHS],
    dimmed: ['cut-locus', 'boundary-extremities'],
    legend: [
      { layer: 'target', label: 'target', color: COLORS.target },
      { layer: 'path-1', label: 'path 1', color: COLORS.path1 },
      { layer: 'path-2', label: 'path 2', color: COLORS.path2 },
    ],
    click: PICK,
    cloud: {
      section: 'Sec. 4.1.3–4.1.4',
      caption:
        'The target is the cut-locus point nearest to the source where the fronts arriving from its two sides head into each other: the opposite gradients of the paper (the two sides of a feature meet there; on a clean cloud also at a shallow angle, as behind a leg; on a noisy one only at 90° or more, as most ridges of the noise are not). From it, two paths descend the distance along the neighbourhood graph on the two sides until they meet: together they go once around the part the target sits on.',
      click: PICK_POINT,
    },
  },
  {
    key: 'loop',
    title: 'Loop',
    group: 'source',
    section: 'Sec. 4.1.4–4.1.6, 4.2.1',
    caption:
      'The two paths joined give the approximate loop (orange): closed, but it zig-zags along edges. Edge flips shorten it inside the constraint sphere (translucent; the tinted patch is the surface inside it), which keeps the separator local. The result (cyan) cuts the surface in two locally; its score is A1 / (A2 · length), A1 ≤ A2 the areas on its two sides.',
    layers: [...SOURCE, 'cut-locus', 'boundary-extremities', ...PATHS, 'approx-loop', 'sphere', 'iterates', 'loop'],
    dimmed: ['cut-locus', 'boundary-extremities', ...PATHS],
    legend: [
      { layer: 'approx-loop', label: 'approximate loop', color: COLORS.approxLoop },
      { layer: 'sphere', label: 'constraint sphere', color: COLORS.sphere },
      { layer: 'iterates', label: 'shortening steps', color: COLORS.iterates },
      { layer: 'loop', label: 'shortened loop', color: COLORS.loop },
    ],
    click: PICK,
    cloud: {
      section: 'Sec. 4.1.4–4.1.6 and App.',
      caption:
        'The two paths joined give the approximate loop (orange). A cloud has no edges to flip (appendix "Curve Shortening using optimization based framework"): the loop is resampled to about one point spacing and moved by gradient descent of Σ H(|x_i − x_{i+1}|), H(s) = e^{s²} − 1, the gradient projected on the tangent planes, every step projected back onto the cloud\'s surface (on a clean cloud the blended local fits of its nearest points, on a noisy one the moving-least-squares surface), and a penalty (λ = 10) keeping it inside the constraint sphere. The thin lines are its recorded steps, the result is cyan; its score is A1 / (A2 · length), A1 ≤ A2 the areas on its two sides.',
      click: PICK_POINT,
    },
  },
  {
    key: 'separators',
    title: 'All separators',
    group: 'shape',
    section: 'Sec. 4.1, 4.2.1, Alg. 1',
    caption:
      'Stage 1 from N sources spread over the surface: each new source is drawn where the sources and loops so far are far away (adaptive sampling, Sec. 4.1.7), so unexplored features are visited first; auto N stops when the loops cover the surface. One candidate loop per source, drawn as they arrive.',
    layers: ['sk-progress', 'sk-rejected', 'sk-packed'],
    legend: [
      { layer: 'sk-progress', label: 'candidate', color: COLORS.candidate },
      { layer: 'sk-packed', label: 'packed', color: COLORS.packed },
      { layer: 'sk-rejected', label: 'rejected', color: COLORS.rejected },
    ],
    click: null,
  },
  {
    key: 'packing',
    title: 'Packing',
    group: 'shape',
    section: 'Sec. 4.2.2–4.2.3',
    caption:
      'Short loops and loops whose centroid lies outside the shape are pruned; greedy weighted set packing then keeps the high-scoring loops that overlap no other kept loop. Each kept loop is one local separator of the shape.',
    layers: ['sk-packed'],
    legend: [{ layer: 'sk-packed', label: 'packed loop', color: COLORS.packed }],
    click: null,
  },
  {
    key: 'regions',
    title: 'Regions',
    group: 'shape',
    section: 'Sec. 4.2.4',
    caption:
      'Every vertex belongs to the packed loop nearest to it along the surface (a watershed from all loops at once), so each loop owns the region around it. Each region is then cut into bands of that distance, about a loop radius wide, and every connected piece of a band becomes a node; each vertex then goes to its nearest node along the skeleton: one colour per node. A long or tapering region gets a node every radius and a tip one of its own; a band that splits around a fork gives each prong its own; pieces cut by a region border join the last whole cross-section.',
    layers: ['sk-packed'],
    dimmed: ['sk-packed'],
    legend: [],
    click: 'click a region to select its skeleton node',
  },
  {
    key: 'skeleton',
    title: 'Skeleton',
    group: 'shape',
    section: 'Sec. 4.2.4',
    caption:
      'One node per band piece of a region (see Regions), then centred: each node moves to the centre of the sphere that best fits the surface it stands for (the vertices nearest to it along the skeleton: the colour you see when you click it), so it sits on the medial axis even in a bend, a taper or a blob; a tip node moves only across its edge and keeps its reach. Nodes are about a radius apart, drawn as spheres a quarter of their radius (the tube that best fits the surface around them); edges join pieces that touch, and where three or more regions meet a branch node joins them. Bumps and end caps shorter than their branch’s radius stay in it (on a noisy cloud, even where a loop went round the bump). A cycle whose disk lies inside the shape closes no hole and is opened at its longest edge, and an edge that leaves the shape (several of its nodes’ radii from it, as between two twigs of a scanned tree) is dropped where it closes a cycle, so the cycles left are handles. The mesh is drawn see-through.',
    layers: ['sk-edges', 'sk-nodes', 'sk-highlight', 'sk-region'],
    legend: [
      { layer: 'sk-nodes', label: 'node', color: COLORS.node },
      { layer: 'sk-edges', label: 'edge', color: COLORS.edge },
    ],
    click: 'click a node or the surface to see its region',
  },
  {
    key: 'reconstruction',
    title: 'Reconstruction',
    group: 'shape',
    section: 'Sec. 5',
    caption:
      'The shape rebuilt from the skeleton alone (a convolution surface of its nodes and radii, see-through) and each vertex coloured by its squared distance to it: the paper’s reconstruction error, on the mesh scaled to unit bounding-box diagonal.',
    layers: ['sk-recon'],
    legend: [{ layer: 'sk-recon', label: 'reconstructed surface', color: COLORS.reconstruction }],
    click: null,
    cloud: {
      section: 'Sec. 5',
      caption:
        'The shape rebuilt from the skeleton alone (a convolution surface of its nodes and radii, see-through) and each point coloured by its squared distance to it: the paper’s reconstruction error, measured against the cloud’s points, the cloud scaled to unit bounding-box diagonal (`cscd evaluate` gives the same number).',
    },
  },
];

export const stageIndex = (key: StageKey): number => STAGES.findIndex((s) => s.key === key);
export const stageDef = (key: StageKey): StageDef => STAGES[stageIndex(key)];
export const isStageKey = (value: string | null | undefined): value is StageKey => STAGES.some((s) => s.key === value);

/** The source stages, in order (a stage-1 run that stopped early reaches only a prefix of them). */
export const SOURCE_STAGES: readonly StageKey[] = STAGES.filter((s) => s.group === 'source').map((s) => s.key);
