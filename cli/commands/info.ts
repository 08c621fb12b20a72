import type { CloudOptions } from '../../lib/core/types.ts';
import { refinementOf } from '../../lib/mesh/refine.ts';
import { AS_CLOUD } from '../../lib/cloud/from-mesh.ts';
import { asCloudFlag, asCloudOption, decimateIfAsked, decimateOption, getCore, openCloud, readShape, refuseFlags, subsampleFlag, subsampleOption, type CliIo, type Command, type InputCloud } from '../command.ts';
import { cloudFlagSpecs, cloudOnlyFlags, cloudOptionsFromFlags } from './separator.ts';

export const info: Command = {
  name: 'info',
  summary: 'print facts about a mesh (counts, topology, bounding box) or a point cloud as JSON',
  args: ['<mesh|cloud>'],
  options: { decimate: decimateOption, subsample: subsampleOption, ...cloudFlagSpecs(), [AS_CLOUD.flag]: asCloudOption },
  details: [
    'Prints {file, format, vertices, faces, edges, components, boundaryLoops, genus, ..., warnings, repairs}: the facts of',
    'the mesh after the repairs listed in `repairs` (see README, Accepted input and repairs), and after',
    '--decimate (then `decimatedFrom` is the face count before). `refined` is what the computing commands do to a',
    'coarse mesh first (lib/mesh/refine.ts: {fromFaces, toFaces, levels}), or null.',
    'For a point cloud, {file, format, points, neighbours, meanFlatNeighbours, components, lineLikeShare, lineSpacing,',
    'pointsAtLineSpacing, bboxMin, bboxMax, bboxDiagonal, meanSpacing, normalsFromFile, warnings, repairs}: the facts of the',
    'cloud opened with --neighbours K (see docs/pointcloud.md; meanFlatNeighbours: the neighbours kept on average where',
    'parts are thinner than K; lineLikeShare, lineSpacing, pointsAtLineSpacing: a cloud scanned in lines), after',
    '--subsample K (then `subsampledFrom` is the point count before).',
  ].join('\n'),
  async run([file], values, io) {
    const options = cloudOptionsFromFlags(values);
    const shape = await readShape(file, io, options.neighbours, { printWarnings: false, asCloud: asCloudFlag(values), subsample: subsampleFlag(values, options.neighbours) });
    if (shape.kind === 'cloud') {
      refuseFlags(values, ['decimate'], file, 'point cloud');
      return printReport(io, await cloudReport(file, shape, options, io));
    }
    refuseFlags(values, cloudOnlyFlags(), file, 'mesh');
    const mesh = decimateIfAsked(shape, values, file, io);
    const facts = (await getCore()).inspect(mesh);
    const decimated = mesh.decimatedFrom === null ? {} : { decimatedFrom: mesh.decimatedFrom };
    printReport(io, { file, format: mesh.format, ...facts, ...decimated, refined: refinementOf(facts), warnings: mesh.warnings, repairs: mesh.repairs });
  },
};

/** A cloud's facts come from opening it: its neighbours and triangulation give the components and the spacing. */
async function cloudReport(file: string, shape: InputCloud, options: CloudOptions, io: CliIo): Promise<object> {
  const cloud = await openCloud(shape, options, file, io);
  try {
    const subsampled = shape.subsampledFrom === null ? {} : { subsampledFrom: shape.subsampledFrom };
    return { file, format: shape.format, ...cloud.facts, ...subsampled, warnings: shape.warnings, repairs: shape.repairs };
  } finally {
    cloud.dispose();
  }
}

function printReport(io: CliIo, report: object): void {
  io.stdout.write(`${JSON.stringify(report, null, 2)}\n`);
}
