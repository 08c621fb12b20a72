// Skeleton writers and reader on a hand-made skeleton: a triangle cycle 0-1-2 with a tail 2-3, small
// enough for the exact text of every format.
import { describe, expect, it } from 'vitest';
import { defaultOptions } from '../../lib/core/options.ts';
import type { Options, Skeleton } from '../../lib/core/types.ts';
import {
  SKELETON_FORMATS,
  SKELETON_WRITERS,
  SkeletonFormatError,
  parseSkeleton,
  skeletonFormatFromName,
  spanningForest,
  writeSkeletonJson,
  writeSkeletonObj,
  writeSkeletonPly,
  writeSkeletonSwc,
} from '../../lib/io/skeleton.ts';

function triangleWithTail(): Skeleton {
  return {
    nodes: Float64Array.from([0, 0, 0, 1, 0, 0, 0.1, 1, 0, 0.1, 2, -0.5]),
    radii: Float64Array.from([0.5, 0.25, 1 / 3, 1e-7]),
    // Edge order on purpose not sorted: 2-0 closes the triangle, 3-2 is the tail written backwards.
    edges: Uint32Array.from([0, 1, 1, 2, 2, 0, 3, 2]),
    vertexToNode: Uint32Array.from([0, 0, 1, 2, 3, 3]),
    candidates: {
      sources: Uint32Array.from([5, 1, 4]),
      loops: [Float64Array.from([0, 0, 1, 0, 1, 1, 1, 0, 1]), new Float64Array(0), Float64Array.from([2, 2, 2, 3, 3, 3, 4, 4, 4])],
      closed: Uint8Array.from([1, 1, 0]),
      scores: Float64Array.from([0.75, 0, 0.5]),
      fates: ['packed', 'failed', 'packed'],
    },
    packed: Uint32Array.from([2, 0]),
    stats: { n: 3, candidates: 3, pruned: 1, packed: 2, cycles: 1, seed: 7, timings: { stage1: 12.5, stage2: 0.25 } },
  };
}

// Built in another key order than defaultOptions: the writers print them in a fixed order.
const options: Options = { ...defaultOptions, n: 3, seed: 7, target: 'geodesic' };
const meta = { mesh: 'meshes/tri.ply', options: Object.fromEntries(Object.entries(options).reverse()) as unknown as Options };
const OPTIONS_JSON = '{"target":"geodesic","sphere":true,"seed":7,"angleThreshold":1.75,"laplacianThreshold":0.2,"pruneDepth":3,"n":3,"pruneLengthFactor":3,"drawAhead":4,"stage1Vertices":20000}';
const SUMMARY = '4 nodes, 4 edges, 1 independent cycles; 3 sources, 3 candidates, 2 packed';

describe('skeleton writers', () => {
  it('JSON: fixed keys in order, packed loops as separators, options in the defaultOptions order', () => {
    const text = writeSkeletonJson(triangleWithTail(), meta);
    expect(text).toBe(`${[
      '{"mesh":"meshes/tri.ply"',
      '"nodes":[[0,0,0],[1,0,0],[0.1,1,0],[0.1,2,-0.5]]',
      '"radii":[0.5,0.25,0.3333333333333333,1e-7]',
      '"edges":[[0,1],[1,2],[2,0],[3,2]]',
      '"vertexToNode":[0,0,1,2,3,3]',
      '"separators":[[[2,2,2],[3,3,3],[4,4,4]],[[0,0,1],[0,1,1],[1,0,1]]]',
      '"separatorsClosed":[false,true]',
      '"stats":{"n":3,"candidates":3,"pruned":1,"packed":2,"cycles":1,"seed":7,"timings":{"stage1":12.5,"stage2":0.25},"refined":null,"simplified":null}',
      `"options":${OPTIONS_JSON}}`,
    ].join(',')}\n`);
    expect(writeSkeletonJson(triangleWithTail(), meta)).toBe(text);
  });

  it('PLY: ascii, vertex x y z radius and edge vertex1 vertex2, comments with mesh and options', () => {
    expect(writeSkeletonPly(triangleWithTail(), meta)).toBe([
      'ply',
      'format ascii 1.0',
      'comment CSCD curve skeleton of meshes/tri.ply',
      `comment options ${OPTIONS_JSON}`,
      `comment ${SUMMARY}`,
      'element vertex 4',
      'property double x',
      'property double y',
      'property double z',
      'property double radius',
      'element edge 4',
      'property int vertex1',
      'property int vertex2',
      'end_header',
      '0 0 0 0.5',
      '1 0 0 0.25',
      '0.1 1 0 0.3333333333333333',
      '0.1 2 -0.5 1e-7',
      '0 1',
      '1 2',
      '2 0',
      '3 2',
      '',
    ].join('\n'));
  });

  it('OBJ: v per node with a radius comment after it, l per edge (1-based)', () => {
    expect(writeSkeletonObj(triangleWithTail(), meta)).toBe([
      '# CSCD curve skeleton of meshes/tri.ply',
      `# options ${OPTIONS_JSON}`,
      `# ${SUMMARY}`,
      '# a node is a `v x y z` line followed by `# radius R`; an edge is `l i j` (1-based node numbers)',
      'v 0 0 0',
      '# radius 0.5',
      'v 1 0 0',
      '# radius 0.25',
      'v 0.1 1 0',
      '# radius 0.3333333333333333',
      'v 0.1 2 -0.5',
      '# radius 1e-7',
      'l 1 2',
      'l 2 3',
      'l 3 1',
      'l 4 3',
      '',
    ].join('\n'));
  });

  it('SWC: breadth-first spanning tree from node 1, the edge it leaves out listed as a cycle edge', () => {
    expect(writeSkeletonSwc(triangleWithTail(), meta)).toBe([
      '# CSCD curve skeleton of meshes/tri.ply',
      `# options ${OPTIONS_JSON}`,
      `# ${SUMMARY}`,
      '# id type x y z radius parent: id = node index + 1, type 0 (undefined), parent -1 for the root of each component;',
      '# the parents form a breadth-first spanning forest, the skeleton edges left out of it are the cycle edges',
      '# cycle edges: 2-3',
      '1 0 0 0 0 0.5 -1',
      '2 0 1 0 0 0.25 1',
      '3 0 0.1 1 0 0.3333333333333333 1',
      '4 0 0.1 2 -0.5 1e-7 3',
      '',
    ].join('\n'));
  });

  it('SWC: a forest has one root per component and "cycle edges: none"; repeated edges and self-loops are cycles', () => {
    const forest = { ...triangleWithTail(), edges: Uint32Array.from([3, 2, 1, 0]) };
    const text = writeSkeletonSwc(forest, meta);
    expect(text).toContain('\n# cycle edges: none\n');
    expect(text.split('\n').filter((line) => /^\d/.test(line)).map((line) => line.split(' ').at(-1))).toEqual(['-1', '1', '-1', '3']);

    expect(spanningForest(3, Uint32Array.from([0, 1, 1, 0, 2, 2, 1, 2]))).toEqual({
      parent: Int32Array.from([-1, 0, 1]), cycleEdges: [1, 2], components: 1,
    });
    expect(spanningForest(5, new Uint32Array(0)).components).toBe(5);
    expect(() => spanningForest(2, Uint32Array.from([0, 2]))).toThrow(RangeError);
  });

  it('puts a mesh name with a line break on one comment line', () => {
    const text = writeSkeletonPly(triangleWithTail(), { ...meta, mesh: 'a\nb.ply' });
    expect(text).toContain('comment CSCD curve skeleton of a b.ply\n');
  });

  it('writes non-finite radii so that they read back as such (null in JSON)', () => {
    const skeleton = { ...triangleWithTail(), radii: Float64Array.from([NaN, Infinity, -Infinity, 1]) };
    expect(writeSkeletonJson(skeleton, meta)).toContain('"radii":[null,null,null,1]');
    expect(writeSkeletonPly(skeleton, meta)).toContain('\n0 0 0 nan\n1 0 0 inf\n0.1 1 0 -inf\n');
    for (const format of ['ply', 'obj', 'swc'] as const) {
      expect(Array.from(parseSkeleton(SKELETON_WRITERS[format](skeleton, meta), `s.${format}`).radii!)).toEqual([NaN, Infinity, -Infinity, 1]);
    }
    expect(Array.from(parseSkeleton(writeSkeletonJson(skeleton, meta), 's.json').radii!)).toEqual([NaN, NaN, NaN, 1]);
  });
});

/** Edges as sorted "i-j" strings with i <= j: the same graph whatever the order and orientation. */
const edgeSet = (edges: Uint32Array) => {
  const pairs: string[] = [];
  for (let k = 0; k < edges.length; k += 2) pairs.push(`${Math.min(edges[k], edges[k + 1])}-${Math.max(edges[k], edges[k + 1])}`);
  return pairs.sort();
};

describe('parseSkeleton', () => {
  it('reads every format back to the same nodes, radii and edges, bit for bit', () => {
    const skeleton = triangleWithTail();
    skeleton.nodes[4] = Math.PI;
    skeleton.nodes[11] = -1 / 7;
    for (const format of SKELETON_FORMATS) {
      const text = SKELETON_WRITERS[format](skeleton, meta);
      for (const input of [text, new TextEncoder().encode(text)]) {
        const read = parseSkeleton(input, `out/skel.${format.toUpperCase()}`);
        expect(read.format).toBe(format);
        expect(read.nodes).toEqual(skeleton.nodes);
        expect(read.radii).toEqual(skeleton.radii);
        // SWC keeps the graph, not the edge order: tree edges (parent, child) first, then the cycle edges.
        if (format === 'swc') expect(edgeSet(read.edges)).toEqual(edgeSet(skeleton.edges));
        else expect(read.edges).toEqual(skeleton.edges);
      }
    }
  });

  it('tells the format from the content when the extension does not', () => {
    for (const format of SKELETON_FORMATS) {
      expect(parseSkeleton(SKELETON_WRITERS[format](triangleWithTail(), meta), 'skeleton.txt').format).toBe(format);
    }
    expect(skeletonFormatFromName('a/b.Swc')).toBe('swc');
    expect(skeletonFormatFromName('a.off')).toBeNull();
  });

  it('reads skeletons of other tools: binary PLY with a vertex_indices edge list, OBJ polylines and negative indices, minimal JSON', () => {
    const head = 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
      + 'element edge 1\nproperty list uchar int vertex_indices\nend_header\n';
    const body = new DataView(new ArrayBuffer(3 * 12 + 1 + 3 * 4));
    [0, 0, 0, 1, 0, 0, 2, 0.5, 0].forEach((x, i) => body.setFloat32(4 * i, x, true));
    body.setUint8(36, 3);
    [0, 1, 2].forEach((v, i) => body.setInt32(37 + 4 * i, v, true));
    const bytes = new Uint8Array([...new TextEncoder().encode(head), ...new Uint8Array(body.buffer)]);
    expect(parseSkeleton(bytes, 'b.ply')).toEqual({
      nodes: Float64Array.from([0, 0, 0, 1, 0, 0, 2, 0.5, 0]), radii: null, edges: Uint32Array.from([0, 1, 1, 2]), format: 'ply',
    });

    const obj = parseSkeleton('v 0 0 0\nv 1 0 0\nv 1 1 0 # a comment\nl 1 2 3 1\nl -1 -3\n', 'p.obj');
    expect(Array.from(obj.edges)).toEqual([0, 1, 1, 2, 2, 0, 2, 0]);
    expect(obj.radii).toBeNull();

    expect(parseSkeleton('{"nodes":[[0,0,0],[1,1,1]],"edges":[[1,0]]}', 'm.json')).toEqual({
      nodes: Float64Array.from([0, 0, 0, 1, 1, 1]), radii: null, edges: Uint32Array.from([1, 0]), format: 'json',
    });
  });

  it('rejects broken files with one-line SkeletonFormatError messages', () => {
    for (const [text, name, message] of [
      ['', 'e.json', 'JSON skeleton: file is empty'],
      ['{"nodes":[[0,0]],"edges":[]}', 'a.json', "JSON skeleton: 'nodes' must be a list of [x, y, z]"],
      ['{"nodes":[[0,0,0]],"edges":[[0,1]]}', 'a.json', 'JSON skeleton: edge 0: node 1 does not exist (the file has 1 nodes, numbered from 0)'],
      ['{"nodes":', 'a.json', 'JSON skeleton: not valid JSON'],
      ['v 0 0 0\nl 1 2\n', 'a.obj', 'OBJ skeleton: edge 0: node 2 does not exist (the file has 1 nodes, numbered from 1)'],
      ['v 0 0\n', 'a.obj', "OBJ skeleton: line 1: expected 'v x y z'"],
      ['1 0 0 0 0 1 -1\n2 0 1 0 0 1 5\n', 'a.swc', 'SWC skeleton: line 2: there is no node with id 5'],
      ['ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n', 'a.ply',
        'PLY skeleton: the file ends before the data the header announces'],
      ['ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n', 'a.ply', "PLY skeleton: the vertex element has no 'y' property"],
    ] as [string, string, string][]) {
      let error: unknown;
      try {
        parseSkeleton(text, name);
      } catch (e) {
        error = e;
      }
      expect(error, name).toBeInstanceOf(SkeletonFormatError);
      expect((error as Error).message.startsWith(message), `${(error as Error).message} / ${message}`).toBe(true);
      expect((error as Error).message).not.toContain('\n');
    }
  });
});
