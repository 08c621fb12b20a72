// Separators as OBJ polylines: every point once, one `l` line per loop back to its first point, so
// the skeleton reader sees one cycle per loop; an open path (ending on the boundary) stays a chain.
import { describe, expect, it } from 'vitest';
import { writeLoopsObj } from '../../lib/io/loops.ts';
import { parseSkeleton } from '../../lib/io/skeleton.ts';

describe('writeLoopsObj', () => {
  const square = Float64Array.of(0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0);
  const triangle = Float64Array.of(0, 0, 2, 0.5, 0, 2, 0.25, 0.125, 2);

  it('writes each loop as a closed polyline with full-precision coordinates', () => {
    const text = writeLoopsObj([square, new Float64Array(0), triangle], [1, 1, 1], ['packed separators of a test\nmesh']);
    const lines = text.trim().split('\n');
    expect(lines[0]).toBe('# packed separators of a test mesh');
    expect(lines.filter((l) => l.startsWith('v '))).toHaveLength(7);
    expect(lines.filter((l) => l.startsWith('l '))).toEqual(['l 1 2 3 4 1', 'l 5 6 7 5']);
    expect(lines).toContain('v 0.25 0.125 2');
  });

  it('reads back as one cycle per loop', () => {
    const graph = parseSkeleton(writeLoopsObj([square, triangle], [1, 1]), 'loops.obj');
    expect(graph.nodes.length / 3).toBe(7);
    expect(graph.edges.length / 2).toBe(7);
    expect(Array.from(graph.nodes.subarray(12, 21))).toEqual(Array.from(triangle));
  });

  it('leaves an open path open: one edge fewer than points', () => {
    const text = writeLoopsObj([square, triangle], [0, 1]);
    expect(text).toContain('1 closed loops');
    expect(text).toContain('1 open paths');
    const graph = parseSkeleton(text, 'loops.obj');
    expect(graph.edges.length / 2).toBe(3 + 3);
  });
});
