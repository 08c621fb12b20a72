import { writeFile } from 'node:fs/promises';
import { UsageError, getCore, readMesh, type Command } from '../command.ts';

export const distance: Command = {
  name: 'distance',
  summary: 'geodesic distance from a vertex to every vertex, as JSON',
  args: ['<mesh>'],
  options: {
    source: { type: 'string', value: 'V', required: true, description: 'source vertex index (0-based)' },
    out: { type: 'string', value: 'FILE', description: 'write the JSON to FILE instead of stdout' },
  },
  details: 'Writes {"distance":[...]} with one heat-method distance per vertex, in the order of the file.',
  async run([file], options) {
    const mesh = await readMesh(file);
    const vertexCount = mesh.positions.length / 3;
    const source = parseVertex(String(options.source), vertexCount);
    const surface = (await getCore()).openSurface(mesh);
    let json: string;
    try {
      json = JSON.stringify({ distance: Array.from(surface.distanceFromVertex(source)) });
    } finally {
      surface.dispose();
    }
    if (typeof options.out === 'string') await writeFile(options.out, `${json}\n`);
    else process.stdout.write(`${json}\n`);
  },
};

function parseVertex(text: string, vertexCount: number): number {
  const vertex = /^\d+$/.test(text) ? Number(text) : NaN;
  if (!(vertex < vertexCount)) {
    throw new UsageError(`--source must be a vertex index from 0 to ${vertexCount - 1}, got '${text}'`);
  }
  return vertex;
}
