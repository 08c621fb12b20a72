// `cscd skeleton` (in-process) writing the curve skeleton in each format.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { defaultOptions } from '../../lib/core/options.ts';
import { parseSkeleton, spanningForest, type SkeletonJson } from '../../lib/io/skeleton.ts';
import { fixture, sharedMesh } from '../paths.ts';
import { decimate } from '../../lib/mesh/decimate.ts';
import { icosphere, offText, readMesh } from './support/meshes.ts';
import { cscd } from './support/cli.ts';

const tmp = mkdtempSync(path.join(tmpdir(), 'cscd-skeleton-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

const KEYS = ['mesh', 'nodes', 'radii', 'edges', 'vertexToNode', 'separators', 'separatorsClosed', 'stats', 'options'];
const STATS = ['n', 'candidates', 'pruned', 'packed', 'cycles', 'seed', 'timings', 'refined', 'simplified'];
/** The one part of the JSON that changes from run to run. */
const withoutTimings = (text: string) => text.replace(/"timings":\{[^{}]*\}/, '"timings":{}');

const twoTorus = sharedMesh('two_torus.ply');
const VERTICES = 766;

describe('cscd skeleton', () => {
  let text: string;
  let json: SkeletonJson;
  beforeAll(async () => {
    const out = path.join(tmp, 'skel.json');
    const result = await cscd('skeleton', twoTorus, '--out', out);
    // Not a terminal and no --verbose: nothing on stderr.
    expect(result).toEqual({ status: 0, stdout: '', stderr: '' });
    text = readFileSync(out, 'utf8');
    json = JSON.parse(text) as SkeletonJson;
  }, 120_000);

  it('writes every key, in order, with one node per input vertex and two cycles for genus 2', () => {
    expect(Object.keys(json)).toEqual(KEYS);
    expect(Object.keys(json.stats)).toEqual(STATS);
    expect(json.mesh).toBe(twoTorus);
    expect(json.options).toEqual({ ...defaultOptions });
    expect(json.stats.seed).toBe(defaultOptions.seed);
    // two_torus is fine enough to compute on as it is (lib/mesh/refine.ts).
    expect(json.stats.refined).toBeNull();

    const nodeCount = json.nodes.length;
    expect(nodeCount).toBeGreaterThan(0);
    expect(json.nodes.every((p) => p.length === 3 && p.every(Number.isFinite))).toBe(true);
    expect(json.radii).toHaveLength(nodeCount);
    expect(json.radii.every((r) => Number.isFinite(r) && r > 0)).toBe(true);
    expect(json.edges.flat().every((i) => Number.isInteger(i) && i >= 0 && i < nodeCount)).toBe(true);
    expect(json.vertexToNode).toHaveLength(VERTICES);
    expect(json.vertexToNode.every((i) => Number.isInteger(i) && i >= 0 && i < nodeCount)).toBe(true);

    expect(json.stats.cycles).toBe(2);
    // cycles is E - V + components of the graph written: the edges are the skeleton's own.
    const forest = spanningForest(nodeCount, Uint32Array.from(json.edges.flat()));
    expect(forest.cycleEdges).toHaveLength(json.stats.cycles);
    expect(forest.components).toBe(1);

    expect(json.separators).toHaveLength(json.stats.packed);
    expect(json.separators.every((loop) => loop.length >= 3 && loop.every((p) => p.length === 3 && p.every(Number.isFinite)))).toBe(true);
    // two_torus is closed: every separator is a loop.
    expect(json.separatorsClosed).toEqual(json.separators.map(() => true));
    expect(json.stats.packed).toBeGreaterThan(0);
    expect(json.stats.packed).toBeLessThanOrEqual(json.stats.candidates);
    expect(json.stats.candidates).toBeLessThanOrEqual(json.stats.n);
    expect(Object.values(json.stats.timings).every((ms) => Number.isFinite(ms) && ms >= 0)).toBe(true);
  });

  it('gives the same JSON, byte for byte but the timings, from the same seed', async () => {
    const again = await cscd('skeleton', twoTorus);
    expect(again.status).toBe(0);
    expect(withoutTimings(again.stdout)).toBe(withoutTimings(text));
    expect(Object.keys((JSON.parse(again.stdout) as SkeletonJson).stats.timings)).toEqual(Object.keys(json.stats.timings));
  }, 120_000);

  it('writes PLY, OBJ and SWC that read back to the same skeleton (format from --format, else the --out extension)', async () => {
    // A fixed small N (the formats are under test, not N), at which the skeleton still has both cycles.
    const n = ['--n', '12'];
    const ply = path.join(tmp, 'skel.ply');
    const swc = path.join(tmp, 'skel.txt');
    const runs = {
      json: await cscd('skeleton', twoTorus, ...n),
      ply: await cscd('skeleton', twoTorus, ...n, '--out', ply),
      obj: await cscd('skeleton', twoTorus, ...n, '--format', 'obj', '--verbose'),
      swc: await cscd('skeleton', twoTorus, ...n, '--format', 'swc', '--out', swc),
    };
    for (const [format, result] of Object.entries(runs)) expect(result.status, format).toBe(0);
    const reference = JSON.parse(runs.json.stdout) as SkeletonJson;
    expect(reference.stats).toMatchObject({ n: 12, cycles: 2 });
    const files = {
      ply: readFileSync(ply, 'utf8'),
      obj: runs.obj.stdout,
      swc: readFileSync(swc, 'utf8'),
    };
    expect(files.ply.startsWith('ply\nformat ascii 1.0\n')).toBe(true);
    expect(files.swc).toMatch(/\n# cycle edges: \d+-\d+ \d+-\d+\n/);

    const nodes = Float64Array.from(reference.nodes.flat());
    const edges = reference.edges.map(([a, b]) => `${Math.min(a, b)}-${Math.max(a, b)}`).sort();
    for (const [format, content] of Object.entries(files)) {
      const read = parseSkeleton(content, `skeleton.${format}`);
      expect(read.format).toBe(format);
      expect(read.nodes, format).toEqual(nodes);
      expect(read.radii, format).toEqual(Float64Array.from(reference.radii));
      const pairs: string[] = [];
      for (let k = 0; k < read.edges.length; k += 2) pairs.push(`${Math.min(read.edges[k], read.edges[k + 1])}-${Math.max(read.edges[k], read.edges[k + 1])}`);
      expect(pairs.sort(), format).toEqual(edges);
    }

    // --verbose: the summary line, although stderr is not a terminal.
    expect(runs.obj.stderr).toBe(`cscd: skeleton of two_torus.ply: ${reference.nodes.length} nodes, ${reference.edges.length} edges, 2 cycles, `
      + `N = ${reference.stats.n} (${reference.stats.packed} of ${reference.stats.candidates} separators kept), ${/, ([\d.]+) s\n$/.exec(runs.obj.stderr)?.[1]} s\n`);
    expect(runs.ply.stderr).toBe('');
  }, 240_000);

  it('writes a one-node skeleton for a sphere (no separator kept), with a warning and exit code 0', async () => {
    const mesh = icosphere(3);
    const sphere = path.join(tmp, 'sphere.off');
    writeFileSync(sphere, offText(mesh));

    const result = await cscd('skeleton', sphere, '--n', '10');
    expect(result.status).toBe(0);
    expect(result.stderr).toBe(`cscd: warning: ${sphere}: no separator was kept: the skeleton is one node per connected component\n`);
    const one = JSON.parse(result.stdout) as SkeletonJson;
    expect(one.nodes).toHaveLength(1);
    expect(one.edges).toEqual([]);
    expect(one.separators).toEqual([]);
    expect(one.stats).toMatchObject({ n: 10, packed: 0, cycles: 0 });
    expect(one.vertexToNode).toEqual(new Array(mesh.positions.length / 3).fill(0));
    // The centre of the unit sphere, and its radius.
    expect(Math.hypot(...one.nodes[0])).toBeLessThan(1e-6);
    expect(one.radii[0]).toBeCloseTo(1, 2);
  }, 120_000);

  it('refines a coarse mesh to compute on, and writes the skeleton for the mesh as given', async () => {
    // fertility_9k decimated to 200 faces: genus 4, which it loses unrefined (docs/refine.md).
    const mesh = decimate(readMesh(sharedMesh('fertility_9k.ply')), 200);
    const coarse = path.join(tmp, 'coarse.off');
    writeFileSync(coarse, offText(mesh));
    const faces = mesh.triangles.length / 3;

    const info = JSON.parse((await cscd('info', coarse)).stdout) as { faces: number; refined: { fromVertices: number; fromFaces: number; toFaces: number; levels: number } };
    expect(info.faces).toBe(faces);
    expect(info.refined.fromVertices).toBe(mesh.positions.length / 3);
    expect(info.refined.fromFaces).toBe(faces);
    expect(info.refined.toFaces).toBe(faces * 4 ** info.refined.levels);

    const result = await cscd('skeleton', coarse, '--n', '40');
    expect(result.status, result.stderr).toBe(0);
    expect(result.stderr).toBe(`cscd: refined ${coarse} for computation from ${faces} to ${info.refined.toFaces} faces (the same surface, sampled more densely)\n`);
    const skeleton = JSON.parse(result.stdout) as SkeletonJson;
    expect(skeleton.stats.refined).toEqual(info.refined);
    expect(skeleton.vertexToNode).toHaveLength(mesh.positions.length / 3);
    expect(skeleton.stats.cycles).toBe(4);
  }, 120_000);
});

// These stop before the core is loaded.
describe('cscd skeleton usage', () => {
  it('gives the same JSON on 1 and 2 threads (--workers) with --draw-ahead sources drawn ahead', async () => {
    const runs = [];
    for (const workers of ['1', '2']) runs.push(await cscd('skeleton', twoTorus, '--n', '8', '--draw-ahead', '4', '--workers', workers));
    expect(runs.map((r) => r.status)).toEqual([0, 0]);
    expect(withoutTimings(runs[1].stdout)).toBe(withoutTimings(runs[0].stdout));
    expect((JSON.parse(runs[0].stdout) as SkeletonJson).options.drawAhead).toBe(4);
  }, 120_000);

  it('reports a mesh the core refuses once, with its threads closed, when --workers starts a pool', async () => {
    const result = await cscd('skeleton', fixture('bad', 'moebius.obj'), '--n', '8', '--draw-ahead', '4', '--workers', '2');
    expect(result).toEqual({ status: 1, stdout: '', stderr: expect.stringMatching(/^cscd: the mesh is not a manifold surface: faces are not consistently oriented[^\n]*\n$/) });
  }, 120_000);

  it('rejects a bad --format, --n or --prune-length-factor with a usage error (exit 2, one cscd: line)', async () => {
    for (const [args, message] of [
      [['--format', 'off'], "--format must be one of json, ply, obj, swc, got 'off'"],
      [['--n', '0'], "--n must be auto or an integer from 1 to 100000, got '0'"],
      [['--n', 'many'], "--n must be auto or an integer from 1 to 100000, got 'many'"],
      [['--n', '2.5'], "--n must be auto or an integer from 1 to 100000, got '2.5'"],
      [['--n', '100001'], "--n must be auto or an integer from 1 to 100000, got '100001'"],
      [['--prune-length-factor', 'x'], "--prune-length-factor must be a number, got 'x'"],
      [['--prune-length-factor=-1'], "--prune-length-factor must be a number from 0 to 1000, got '-1'"],
      [['--workers', '0'], "--workers must be auto or an integer from 1 to 256, got '0'"],
      [['--workers', 'all'], "--workers must be auto or an integer from 1 to 256, got 'all'"],
    ] as [string[], string][]) {
      const result = await cscd('skeleton', twoTorus, ...args);
      expect(result, args.join(' ')).toEqual({ status: 2, stdout: '', stderr: `cscd: ${message}\n` });
    }
    // Stage-2 options are not flags of `cscd separator`.
    expect(await cscd('separator', twoTorus, '--n', '5')).toMatchObject({ status: 2, stdout: '' });
  });

  it('runs stage 1 on a simplified copy above --stage1-vertices and says so in the JSON; 0 never simplifies', async () => {
    const fertility = sharedMesh('fertility_9k.ply'); // 4494 vertices, genus 4
    const runs = await Promise.all(['2000', '0'].map((limit) => cscd('skeleton', fertility, '--n', '24', '--stage1-vertices', limit, '--workers', '1')));
    const [copy, full] = runs.map((r) => JSON.parse(r.stdout) as SkeletonJson);
    expect(copy.options).toMatchObject({ stage1Vertices: 2000 });
    expect(copy.stats.simplified).toMatchObject({ fromVertices: 4494, fromFaces: 9000 });
    expect(Math.abs(copy.stats.simplified!.toVertices - 2000)).toBeLessThan(100);
    expect(copy.vertexToNode).toHaveLength(4494);
    expect(copy.stats.cycles).toBe(4);
    expect(full.stats.simplified).toBeNull();
    expect(await cscd('skeleton', fertility, '--stage1-vertices=-5')).toEqual({ status: 2, stdout: '', stderr: "cscd: --stage1-vertices must be an integer from 0 to 100000000, got '-5'\n" });
  }, 120_000);

  it('is listed in the help with its options', async () => {
    expect((await cscd('--help')).stdout).toMatch(/skeleton <mesh\|cloud> \[options\]/);
    const help = (await cscd('help', 'skeleton')).stdout;
    expect(help).toMatch(/--n N\|auto\s+number of sources/);
    expect(help).toMatch(/--format json\|ply\|obj\|swc/);
    expect(help).toMatch(/--prune-length-factor X/);
  });
});
