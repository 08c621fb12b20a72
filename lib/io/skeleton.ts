/**
 * Curve-skeleton files, written and read by the CLI (Node) and the page's downloads (browser): plain
 * strings and bytes, no Node APIs.
 *
 * Writers take the core's Skeleton and what it was made from; they are deterministic (same input, same
 * text: fixed key and line order, numbers printed as JavaScript's shortest round-trip form, the one
 * JSON.stringify uses), so a file read back gives the same doubles.
 *
 *   json  {mesh, nodes, radii, edges, vertexToNode, separators, stats, options}, one line
 *   ply   ascii: element vertex (x y z radius, double), element edge (vertex1 vertex2, int)
 *   obj   `v x y z` per node, each followed by a comment line `# radius R`; `l i j` per edge (1-based)
 *   swc   `id type x y z radius parent` per node, id = node index + 1, type 0 (undefined); parents
 *         form a spanning forest (breadth-first from the lowest-index node of each component, roots
 *         have parent -1); the edges left out of it close cycles and are listed in the comment line
 *         `# cycle edges: i-j ...` (1-based ids, `none` when the skeleton is a forest)
 *
 * parseSkeleton reads all four back to nodes, radii and edges (and PLY written by other tools: ascii or
 * binary, `edge` element with vertex1/vertex2 or a vertex_indices list; OBJ `l` polylines).
 */
import { defaultOptions } from '../core/options.ts';
import type { Polyline, ShapeOptions, Skeleton } from '../core/types.ts';
import { findElement, findProperty, parsePlyHeader, readPlyElements, type PlyErrors, type PlyProperty } from './ply-elements.ts';

export type SkeletonFormat = 'json' | 'ply' | 'obj' | 'swc';

/** Every skeleton format, in the order of help texts (the Record makes the compiler check that none is missing). */
export const SKELETON_FORMATS = Object.keys({ json: 0, ply: 0, obj: 0, swc: 0 } satisfies Record<SkeletonFormat, 0>) as SkeletonFormat[];

/** What a skeleton was made from: the mesh (a file name or path, as the caller wants it shown) and the options. */
export interface SkeletonMeta {
  mesh: string;
  options: ShapeOptions;
}

export type SkeletonWriter = (skeleton: Skeleton, meta: SkeletonMeta) => string;

export type Point = [number, number, number];

/** The JSON written by `cscd skeleton --format json`. */
export interface SkeletonJson {
  mesh: string;
  nodes: Point[];
  radii: number[];
  edges: [number, number][];
  vertexToNode: number[];
  /** The packed separators' loops, in the order of `packed`. */
  separators: Point[][];
  /** Per separator: false for an open path whose ends lie on the mesh boundary. */
  separatorsClosed: boolean[];
  stats: Skeleton['stats'];
  options: ShapeOptions;
}

/** A skeleton read from a file: positions (xyz per node), radii (null when the file has none) and node index pairs. */
export interface ParsedSkeleton {
  nodes: Float64Array;
  radii: Float64Array | null;
  edges: Uint32Array;
  format: SkeletonFormat;
}

/** A file that cannot be read as a skeleton: its message is one line for the user, starting with the format. */
export class SkeletonFormatError extends Error {
  override name = 'SkeletonFormatError';
}

const FORMAT_LABEL: Record<SkeletonFormat, string> = { json: 'JSON skeleton', ply: 'PLY skeleton', obj: 'OBJ skeleton', swc: 'SWC skeleton' };

/** The format a file name's extension stands for (case-insensitive), or null. */
export function skeletonFormatFromName(name: string): SkeletonFormat | null {
  const ext = /\.([^./\\]+)$/.exec(name)?.[1].toLowerCase();
  return ext && (SKELETON_FORMATS as string[]).includes(ext) ? (ext as SkeletonFormat) : null;
}

// ---------------------------------------------------------------------------------------------------
// Writers

/** A number as JSON.stringify prints it; non-finite values (which JSON cannot hold) as `nan`/`inf`/`-inf`. */
function num(x: number): string {
  if (Number.isFinite(x)) return String(x);
  return Number.isNaN(x) ? 'nan' : x > 0 ? 'inf' : '-inf';
}

function toPoints(xyz: Float64Array | number[]): Point[] {
  const points: Point[] = [];
  for (let i = 0; i + 2 < xyz.length; i += 3) points.push([xyz[i], xyz[i + 1], xyz[i + 2]]);
  return points;
}

function toPairs(indices: Uint32Array): [number, number][] {
  const pairs: [number, number][] = [];
  for (let i = 0; i + 1 < indices.length; i += 2) pairs.push([indices[i], indices[i + 1]]);
  return pairs;
}

/** Options in the order of defaultOptions (then any other key, sorted), whatever order the caller built them in. */
function orderedOptions(options: ShapeOptions): ShapeOptions {
  const keys = Object.keys(defaultOptions) as (keyof ShapeOptions)[];
  const extra = (Object.keys(options) as (keyof ShapeOptions)[]).filter((k) => !keys.includes(k)).sort();
  return Object.fromEntries([...keys, ...extra].filter((k) => k in options).map((k) => [k, options[k]])) as unknown as ShapeOptions;
}

/** One line of text: a path or JSON inside a comment must not start a new line of the file. */
function oneLine(text: string): string {
  return text.replace(/[\r\n]+/g, ' ');
}

function header(skeleton: Skeleton, meta: SkeletonMeta): string[] {
  const nodes = skeleton.nodes.length / 3;
  const edges = skeleton.edges.length / 2;
  const { n, candidates, packed, cycles } = skeleton.stats;
  return [
    `CSCD curve skeleton of ${oneLine(meta.mesh)}`,
    `options ${JSON.stringify(orderedOptions(meta.options))}`,
    `${nodes} nodes, ${edges} edges, ${cycles} independent cycles; ${n} sources, ${candidates} candidates, ${packed} packed`,
  ];
}

/** The skeleton as plain JSON data, keys in a fixed order. */
export function skeletonJson(skeleton: Skeleton, meta: SkeletonMeta): SkeletonJson {
  const { stats } = skeleton;
  const loops: Polyline[] = Array.from(skeleton.packed, (i) => skeleton.candidates.loops[i]);
  return {
    mesh: meta.mesh,
    nodes: toPoints(skeleton.nodes),
    radii: Array.from(skeleton.radii),
    edges: toPairs(skeleton.edges),
    vertexToNode: Array.from(skeleton.vertexToNode),
    separators: loops.map((loop) => toPoints(loop)),
    separatorsClosed: Array.from(skeleton.packed, (i) => skeleton.candidates.closed[i] === 1),
    stats: {
      n: stats.n,
      candidates: stats.candidates,
      pruned: stats.pruned,
      packed: stats.packed,
      cycles: stats.cycles,
      seed: stats.seed,
      timings: { ...stats.timings },
      refined: stats.refined ?? null,
      simplified: stats.simplified ?? null,
    },
    options: orderedOptions(meta.options),
  };
}

/** JSON, one line (non-finite numbers become null, as JSON.stringify writes them). */
export const writeSkeletonJson: SkeletonWriter = (skeleton, meta) => `${JSON.stringify(skeletonJson(skeleton, meta))}\n`;

/** ASCII PLY with the standard `vertex` and `edge` elements. */
export const writeSkeletonPly: SkeletonWriter = (skeleton, meta) => {
  const nodeCount = skeleton.nodes.length / 3;
  const edgeCount = skeleton.edges.length / 2;
  const lines = [
    'ply',
    'format ascii 1.0',
    ...header(skeleton, meta).map((line) => `comment ${line}`),
    `element vertex ${nodeCount}`,
    'property double x',
    'property double y',
    'property double z',
    'property double radius',
    `element edge ${edgeCount}`,
    'property int vertex1',
    'property int vertex2',
    'end_header',
  ];
  const { nodes, radii, edges } = skeleton;
  for (let i = 0; i < nodeCount; i++) lines.push(`${num(nodes[3 * i])} ${num(nodes[3 * i + 1])} ${num(nodes[3 * i + 2])} ${num(radii[i])}`);
  for (let k = 0; k < edgeCount; k++) lines.push(`${edges[2 * k]} ${edges[2 * k + 1]}`);
  return `${lines.join('\n')}\n`;
};

/** OBJ: `v` per node followed by `# radius R`, `l` per edge (1-based). */
export const writeSkeletonObj: SkeletonWriter = (skeleton, meta) => {
  const nodeCount = skeleton.nodes.length / 3;
  const edgeCount = skeleton.edges.length / 2;
  const lines = [
    ...header(skeleton, meta).map((line) => `# ${line}`),
    '# a node is a `v x y z` line followed by `# radius R`; an edge is `l i j` (1-based node numbers)',
  ];
  const { nodes, radii, edges } = skeleton;
  for (let i = 0; i < nodeCount; i++) {
    lines.push(`v ${num(nodes[3 * i])} ${num(nodes[3 * i + 1])} ${num(nodes[3 * i + 2])}`, `# radius ${num(radii[i])}`);
  }
  for (let k = 0; k < edgeCount; k++) lines.push(`l ${edges[2 * k] + 1} ${edges[2 * k + 1] + 1}`);
  return `${lines.join('\n')}\n`;
};

/**
 * A spanning forest of a graph: breadth-first from the lowest-index node of each component, neighbours
 * visited in increasing node index (then edge order), so the result depends only on the graph.
 * `parent` is -1 for roots; `cycleEdges` are the indices of the edges not in the forest (self-loops and
 * repeated edges included), in edge order: there are E - V + components of them.
 */
export function spanningForest(nodeCount: number, edges: Uint32Array): { parent: Int32Array; cycleEdges: number[]; components: number } {
  const edgeCount = edges.length >> 1;
  const adjacency: { to: number; edge: number }[][] = Array.from({ length: nodeCount }, () => []);
  for (let k = 0; k < edgeCount; k++) {
    const a = edges[2 * k], b = edges[2 * k + 1];
    if (!(a < nodeCount && b < nodeCount)) throw new RangeError(`skeleton edge ${k} (${a}, ${b}) refers to a node beyond the ${nodeCount} nodes`);
    if (a === b) continue;
    adjacency[a].push({ to: b, edge: k });
    adjacency[b].push({ to: a, edge: k });
  }
  for (const list of adjacency) list.sort((p, q) => p.to - q.to || p.edge - q.edge);
  const parent = new Int32Array(nodeCount).fill(-1);
  const visited = new Uint8Array(nodeCount);
  const inForest = new Uint8Array(edgeCount);
  const queue = new Int32Array(nodeCount);
  let components = 0;
  for (let root = 0; root < nodeCount; root++) {
    if (visited[root]) continue;
    components++;
    visited[root] = 1;
    let head = 0, tail = 0;
    queue[tail++] = root;
    while (head < tail) {
      const u = queue[head++];
      for (const { to, edge } of adjacency[u]) {
        if (visited[to]) continue;
        visited[to] = 1;
        parent[to] = u;
        inForest[edge] = 1;
        queue[tail++] = to;
      }
    }
  }
  const cycleEdges: number[] = [];
  for (let k = 0; k < edgeCount; k++) if (!inForest[k]) cycleEdges.push(k);
  return { parent, cycleEdges, components };
}

/** SWC (neuron morphology format): a spanning forest, cycle edges in a comment line. */
export const writeSkeletonSwc: SkeletonWriter = (skeleton, meta) => {
  const nodeCount = skeleton.nodes.length / 3;
  const { nodes, radii, edges } = skeleton;
  const { parent, cycleEdges } = spanningForest(nodeCount, edges);
  const cycles = cycleEdges.map((k) => `${edges[2 * k] + 1}-${edges[2 * k + 1] + 1}`);
  const lines = [
    ...header(skeleton, meta).map((line) => `# ${line}`),
    '# id type x y z radius parent: id = node index + 1, type 0 (undefined), parent -1 for the root of each component;',
    '# the parents form a breadth-first spanning forest, the skeleton edges left out of it are the cycle edges',
    `# cycle edges: ${cycles.length ? cycles.join(' ') : 'none'}`,
  ];
  for (let i = 0; i < nodeCount; i++) {
    lines.push(`${i + 1} 0 ${num(nodes[3 * i])} ${num(nodes[3 * i + 1])} ${num(nodes[3 * i + 2])} ${num(radii[i])} ${parent[i] < 0 ? -1 : parent[i] + 1}`);
  }
  return `${lines.join('\n')}\n`;
};

export const SKELETON_WRITERS: Readonly<Record<SkeletonFormat, SkeletonWriter>> = Object.freeze({
  json: writeSkeletonJson,
  ply: writeSkeletonPly,
  obj: writeSkeletonObj,
  swc: writeSkeletonSwc,
});

// ---------------------------------------------------------------------------------------------------
// Reader

/**
 * Reads a skeleton file written by the writers above (or a compatible one). The extension chooses the
 * format; without a known extension the content decides (`{` JSON, `ply` PLY, a numeric first data
 * line SWC, else OBJ). Throws SkeletonFormatError with a one-line message.
 */
export function parseSkeleton(bytes: Uint8Array | string, fileName: string): ParsedSkeleton {
  const data = typeof bytes === 'string' ? new TextEncoder().encode(bytes) : bytes;
  const format = skeletonFormatFromName(fileName) ?? sniff(data);
  if (data.length === 0) throw new SkeletonFormatError(`${FORMAT_LABEL[format]}: file is empty`);
  const text = () => new TextDecoder().decode(data);
  switch (format) {
    case 'json': return checked(readJson(text()), 'json');
    case 'ply': return checked(readPly(data), 'ply');
    case 'obj': return checked(readObj(text()), 'obj');
    case 'swc': return checked(readSwc(text()), 'swc');
  }
}

function sniff(data: Uint8Array): SkeletonFormat {
  const head = new TextDecoder().decode(data.subarray(0, 4096)).replace(/^\uFEFF/, '');
  if (/^\s*\{/.test(head)) return 'json';
  if (/^ply\r?\n/.test(head)) return 'ply';
  const firstData = head.split(/\r?\n/).map((line) => line.trim()).find((line) => line !== '' && !line.startsWith('#'));
  return firstData !== undefined && /^\d+\s+-?\d+(\s+\S+){5}$/.test(firstData) ? 'swc' : 'obj';
}

interface Raw {
  nodes: number[] | Float64Array;
  radii: number[] | Float64Array | null;
  edges: number[];
}

function fail(format: SkeletonFormat, message: string): never {
  throw new SkeletonFormatError(`${FORMAT_LABEL[format]}: ${message}`);
}

/** Checks the parts fit together (counts, finite positions, edge indices) and makes typed arrays. */
function checked(raw: Raw, format: SkeletonFormat): ParsedSkeleton {
  const nodeCount = raw.nodes.length / 3;
  if (!raw.nodes.every(Number.isFinite)) fail(format, 'a node position is not a finite number');
  if (raw.radii && raw.radii.length !== nodeCount) fail(format, `${raw.radii.length} radii for ${nodeCount} nodes`);
  // OBJ numbers nodes from 1 (SWC ids are mapped to nodes while reading, so they are always valid here).
  const base = format === 'obj' ? 1 : 0;
  for (let k = 0; k < raw.edges.length; k++) {
    const index = raw.edges[k];
    if (!Number.isInteger(index) || index < 0 || index >= nodeCount) {
      fail(format, `edge ${k >> 1}: node ${index + base} does not exist (the file has ${nodeCount} nodes, numbered from ${base})`);
    }
  }
  return {
    nodes: Float64Array.from(raw.nodes),
    radii: raw.radii ? Float64Array.from(raw.radii) : null,
    edges: Uint32Array.from(raw.edges),
    format,
  };
}

function readJson(text: string): Raw {
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch (error) {
    fail('json', `not valid JSON (${(error as Error).message.split('\n')[0]})`);
  }
  if (typeof json !== 'object' || json === null || Array.isArray(json)) fail('json', 'expected an object with nodes and edges');
  const { nodes, radii, edges } = json as Record<string, unknown>;
  const isTuple = (value: unknown, length: number) => Array.isArray(value) && value.length === length && value.every((x) => typeof x === 'number');
  if (!Array.isArray(nodes) || !nodes.every((p) => isTuple(p, 3))) fail('json', "'nodes' must be a list of [x, y, z]");
  if (!Array.isArray(edges) || !edges.every((e) => isTuple(e, 2))) fail('json', "'edges' must be a list of [i, j]");
  // JSON writes non-finite radii as null: read them back as NaN.
  if (radii !== undefined && radii !== null && !(Array.isArray(radii) && radii.every((r) => typeof r === 'number' || r === null))) {
    fail('json', "'radii' must be a list of numbers");
  }
  return {
    nodes: (nodes as number[][]).flat(),
    radii: Array.isArray(radii) ? radii.map((r: number | null) => r ?? NaN) : null,
    edges: (edges as number[][]).flat(),
  };
}

/** A number token of a text format: decimal, or nan/inf as the writers print non-finite values. */
function parseNumberToken(token: string | undefined): number {
  if (token === undefined) return NaN;
  const lower = token.toLowerCase();
  if (lower === 'nan' || lower === '-nan') return NaN;
  if (lower === 'inf' || lower === '+inf' || lower === 'infinity' || lower === '+infinity') return Infinity;
  if (lower === '-inf' || lower === '-infinity') return -Infinity;
  return /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(token) ? Number(token) : NaN;
}

function readObj(text: string): Raw {
  const nodes: number[] = [];
  const radii: number[] = [];
  const edges: number[] = [];
  const lines = text.split(/\r\n|\r|\n/);
  for (let n = 0; n < lines.length; n++) {
    const line = lines[n].trim();
    const radius = /^#\s*radius\s+(\S+)\s*$/.exec(line);
    if (radius) {
      radii.push(parseNumberToken(radius[1]));
      continue;
    }
    const words = line.replace(/#.*$/, '').trim().split(/\s+/);
    if (words[0] === 'v') {
      const xyz = words.slice(1, 4).map(parseNumberToken);
      if (xyz.length < 3 || !xyz.every(Number.isFinite)) fail('obj', `line ${n + 1}: expected 'v x y z'`);
      nodes.push(...xyz);
    } else if (words[0] === 'l') {
      // A polyline: consecutive pairs. `i/t` (texture index) keeps i; negative numbers count back from the last vertex.
      const count = nodes.length / 3;
      const chain = words.slice(1).map((word) => {
        const i = /^-?\d+/.exec(word) ? parseInt(word, 10) : NaN;
        if (!Number.isInteger(i) || i === 0) fail('obj', `line ${n + 1}: bad vertex number '${word}'`);
        return i > 0 ? i - 1 : count + i;
      });
      if (chain.length < 2) fail('obj', `line ${n + 1}: an 'l' line needs at least two vertices`);
      for (let k = 1; k < chain.length; k++) edges.push(chain[k - 1], chain[k]);
    }
  }
  // Radii are the writer's comments: only trusted when there is one per node.
  return { nodes, radii: radii.length > 0 && radii.length === nodes.length / 3 ? radii : null, edges };
}

function readSwc(text: string): Raw {
  const rows: { id: number; xyz: number[]; radius: number; parent: number; line: number }[] = [];
  const cycles: [number, number, number][] = [];
  const lines = text.split(/\r\n|\r|\n/);
  for (let n = 0; n < lines.length; n++) {
    const line = lines[n].trim();
    if (line.startsWith('#')) {
      const match = /^#\s*cycle edges:\s*(.*)$/.exec(line);
      if (match && match[1].trim() !== 'none') {
        for (const pair of match[1].trim().split(/\s+/)) {
          const ends = /^(\d+)-(\d+)$/.exec(pair);
          if (!ends) fail('swc', `line ${n + 1}: bad cycle edge '${pair}' (expected i-j)`);
          cycles.push([Number(ends[1]), Number(ends[2]), n + 1]);
        }
      }
      continue;
    }
    if (line === '') continue;
    const words = line.split(/\s+/);
    const values = words.map(parseNumberToken);
    if (words.length < 7 || !Number.isInteger(values[0]) || !Number.isInteger(values[6]) || !values.slice(2, 5).every(Number.isFinite)) {
      fail('swc', `line ${n + 1}: expected 'id type x y z radius parent'`);
    }
    rows.push({ id: values[0], xyz: values.slice(2, 5), radius: values[5], parent: values[6], line: n + 1 });
  }
  const indexOf = new Map<number, number>();
  rows.forEach((row, i) => {
    if (indexOf.has(row.id)) fail('swc', `line ${row.line}: id ${row.id} is used twice`);
    indexOf.set(row.id, i);
  });
  const index = (id: number, line: number) => {
    const i = indexOf.get(id);
    if (i === undefined) fail('swc', `line ${line}: there is no node with id ${id}`);
    return i;
  };
  const edges: number[] = [];
  for (const row of rows) if (row.parent !== -1) edges.push(index(row.parent, row.line), index(row.id, row.line));
  for (const [a, b, line] of cycles) edges.push(index(a, line), index(b, line));
  return { nodes: rows.flatMap((row) => row.xyz), radii: rows.map((row) => row.radius), edges };
}

// PLY: the header and data are read by ply-elements.ts, as for meshes.

const PLY_ERRORS: PlyErrors = {
  fail: (message) => fail('ply', message),
  truncated: (message) => fail('ply', `the file ends before the data the header announces (${message})`),
};

function readPly(data: Uint8Array): Raw {
  const header = parsePlyHeader(data, PLY_ERRORS);
  const vertex = findElement(header, 'vertex');
  if (!vertex) fail('ply', "no 'vertex' element");
  for (const axis of ['x', 'y', 'z']) if (!isScalar(findProperty(vertex, axis))) fail('ply', `the vertex element has no '${axis}' property`);
  // An edge is a vertex_indices (or vertex_index) list, read as a polyline, or vertex1 and vertex2.
  const edge = findElement(header, 'edge');
  const list = edge && findProperty(edge, 'vertex_indices', 'vertex_index');
  const chainList = list?.countType ? list.name : null;
  const noEnds = (row: number) => `edge ${row}: no vertex1 and vertex2 (or vertex_indices list)`;
  if (edge && edge.count > 0 && !chainList && !(isScalar(findProperty(edge, 'vertex1')) && isScalar(findProperty(edge, 'vertex2')))) {
    fail('ply', noEnds(0));
  }
  const elements = readPlyElements(data, header, {
    vertex: ['x', 'y', 'z', 'radius'],
    edge: chainList ? [{ name: chainList, check: { length: (row, n) => (n < 2 ? noEnds(row) : undefined) } }] : ['vertex1', 'vertex2'],
  }, PLY_ERRORS);

  const { x, y, z, radius } = elements.vertex.scalars;
  const nodes = new Float64Array(3 * vertex.count);
  for (let i = 0; i < vertex.count; i++) nodes.set([x[i], y[i], z[i]], 3 * i);
  const edges: number[] = [];
  if (chainList) {
    const { lengths, items } = elements.edge.lists[chainList];
    for (let row = 0, start = 0; row < lengths.length; start += lengths[row++]) {
      for (let k = start + 1; k < start + lengths[row]; k++) edges.push(items[k - 1], items[k]);
    }
  } else if (edge && edge.count > 0) {
    const { vertex1, vertex2 } = elements.edge.scalars;
    for (let row = 0; row < edge.count; row++) edges.push(vertex1[row], vertex2[row]);
  }
  return { nodes, radii: radius ?? null, edges };
}

function isScalar(property: PlyProperty | undefined): boolean {
  return property !== undefined && !property.countType;
}
