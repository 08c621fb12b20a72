import { getCore, readMesh, type Command } from '../command.ts';

export const info: Command = {
  name: 'info',
  summary: 'print facts about a mesh (counts, topology, bounding box) as JSON',
  args: ['<mesh>'],
  options: {},
  details: 'Prints {file, format, vertices, faces, edges, components, boundaryLoops, genus, ..., warnings, repairs}: the facts of\nthe mesh after the repairs listed in `repairs` (see README, Accepted input and repairs).',
  async run([file]) {
    const mesh = await readMesh(file, { printWarnings: false });
    const facts = (await getCore()).inspect(mesh);
    const report = { file, format: mesh.format, ...facts, warnings: mesh.warnings, repairs: mesh.repairs };
    process.stdout.write(`${JSON.stringify(report, null, 2)}\n`);
  },
};
