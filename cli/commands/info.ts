import { refinementOf } from '../../lib/mesh/refine.ts';
import { decimateIfAsked, decimateOption, getCore, readMesh, type Command } from '../command.ts';

export const info: Command = {
  name: 'info',
  summary: 'print facts about a mesh (counts, topology, bounding box) as JSON',
  args: ['<mesh>'],
  options: { decimate: decimateOption },
  details: 'Prints {file, format, vertices, faces, edges, components, boundaryLoops, genus, ..., warnings, repairs}: the facts of\nthe mesh after the repairs listed in `repairs` (see README, Accepted input and repairs), and after\n--decimate (then `decimatedFrom` is the face count before). `refined` is what the computing commands do to a\ncoarse mesh first (lib/mesh/refine.ts: {fromFaces, toFaces, levels}), or null.',
  async run([file], values, io) {
    const mesh = decimateIfAsked(await readMesh(file, io, { printWarnings: false }), values, file, io);
    const facts = (await getCore()).inspect(mesh);
    const decimated = mesh.decimatedFrom === null ? {} : { decimatedFrom: mesh.decimatedFrom };
    const report = { file, format: mesh.format, ...facts, ...decimated, refined: refinementOf(facts), warnings: mesh.warnings, repairs: mesh.repairs };
    io.stdout.write(`${JSON.stringify(report, null, 2)}\n`);
  },
};
