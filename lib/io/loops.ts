/**
 * Polylines on a surface (the packed separators) as an OBJ file: a `v` per point and one `l` line per
 * polyline; a closed loop's line returns to its first point, so any OBJ reader (and `parseSkeleton`)
 * sees a cycle per loop, while an open path (ending on the mesh boundary) stays a chain. Shared by the
 * page's worker and the CLI.
 */
import type { Polyline } from '../core/types.ts';

export function writeLoopsObj(loops: readonly Polyline[], closed: ArrayLike<number>, comments: readonly string[] = []): string {
  const lines = comments.map((c) => `# ${c.replace(/[\r\n]+/g, ' ')}`);
  const paths = Array.from({ length: loops.length }, (_, i) => closed[i]).filter((c) => !c).length;
  lines.push(`# ${loops.length - paths} closed loops ('l' lines that end at the point they start from), ${paths} open paths`);
  const chains: string[] = [];
  let next = 1;
  for (const [k, loop] of loops.entries()) {
    const count = Math.floor(loop.length / 3);
    if (count < 2) continue;
    for (let i = 0; i < count; i++) lines.push(`v ${loop[3 * i]} ${loop[3 * i + 1]} ${loop[3 * i + 2]}`);
    const indices = Array.from({ length: count }, (_, i) => next + i);
    chains.push(`l ${[...indices, ...(closed[k] ? [next] : [])].join(' ')}`);
    next += count;
  }
  return `${[...lines, ...chains].join('\n')}\n`;
}
