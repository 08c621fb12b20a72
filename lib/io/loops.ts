/**
 * Closed polylines on a surface (the packed separators) as an OBJ file: a `v` per point and one `l`
 * line per loop that returns to its first point, so any OBJ reader (and `parseSkeleton`) sees a cycle
 * per loop. Shared by the page's worker and the CLI.
 */
import type { Polyline } from '../core/types.ts';

export function writeLoopsObj(loops: readonly Polyline[], comments: readonly string[] = []): string {
  const lines = comments.map((c) => `# ${c.replace(/[\r\n]+/g, ' ')}`);
  lines.push(`# ${loops.length} closed loops: 'l' lines that end at the point they start from`);
  const chains: string[] = [];
  let next = 1;
  for (const loop of loops) {
    const count = Math.floor(loop.length / 3);
    if (count < 2) continue;
    for (let i = 0; i < count; i++) lines.push(`v ${loop[3 * i]} ${loop[3 * i + 1]} ${loop[3 * i + 2]}`);
    const indices = Array.from({ length: count }, (_, i) => next + i);
    chains.push(`l ${[...indices, next].join(' ')}`);
    next += count;
  }
  return `${[...lines, ...chains].join('\n')}\n`;
}
