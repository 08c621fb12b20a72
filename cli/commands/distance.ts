import { writeFile } from 'node:fs/promises';
import { UsageError, openSolver, readMesh, type Command } from '../command.ts';

export const distance: Command = {
  name: 'distance',
  summary: 'geodesic distance from a vertex to every vertex, as JSON',
  args: ['<mesh>'],
  options: {
    source: { type: 'string', value: 'V', required: true, description: 'source vertex index (0-based)' },
    out: { type: 'string', value: 'FILE', description: 'write the JSON to FILE instead of stdout' },
  },
  details: 'Writes {"distance":[...], "refined"} with one heat-method distance per vertex, in the order of the file (null for\nvertices in other components and for vertices the repair removed); `refined` says how a coarse mesh was\nrefined to compute on (null: it was not).',
  async run([file], options, io) {
    const mesh = await readMesh(file, io);
    // Vertices are numbered as in the file, in and out, even when the repair renumbered them.
    const source = parseVertex(String(options.source), mesh.vertexMap.length);
    if (mesh.vertexMap[source] < 0) throw new UsageError(`--source ${source} is a vertex used by no face, which the repair removed`);
    const surface = await openSolver(mesh, file, io);
    let json: string;
    try {
      const distance = surface.distanceFromVertex(mesh.vertexMap[source]);
      json = JSON.stringify({ distance: Array.from(mesh.vertexMap, (v) => (v < 0 ? null : distance[v])), refined: surface.refined });
    } finally {
      surface.dispose();
    }
    if (typeof options.out === 'string') await writeFile(options.out, `${json}\n`);
    else io.stdout.write(`${json}\n`);
  },
};

function parseVertex(text: string, vertexCount: number): number {
  const vertex = /^\d+$/.test(text) ? Number(text) : NaN;
  if (!(vertex < vertexCount)) {
    throw new UsageError(`--source must be a vertex index from 0 to ${vertexCount - 1}, got '${text}'`);
  }
  return vertex;
}
