import { writeFile } from 'node:fs/promises';
import type { CloudOptions } from '../../lib/core/types.ts';
import { AS_CLOUD } from '../../lib/cloud/from-mesh.ts';
import { UsageError, asCloudFlag, asCloudOption, openCloud, openSolver, readShape, refuseFlags, subsampleFlag, subsampleOption, type CliIo, type Command, type InputCloud, type InputMesh, type OptionValues } from '../command.ts';
import { cloudFlagSpecs, cloudOnlyFlags, cloudOptionsFromFlags } from './separator.ts';

export const distance: Command = {
  name: 'distance',
  summary: 'geodesic distance from a vertex (or point) to every vertex (or point), as JSON',
  args: ['<mesh|cloud>'],
  options: {
    source: { type: 'string', value: 'V', required: true, description: 'source vertex index (0-based; in a point cloud, point index)' },
    ...cloudFlagSpecs(),
    [AS_CLOUD.flag]: asCloudOption,
    subsample: subsampleOption,
    out: { type: 'string', value: 'FILE', description: 'write the JSON to FILE instead of stdout' },
  },
  details: [
    'Writes {"distance":[...], "refined"} with one heat-method distance per vertex, in the order of the file (null for',
    'vertices in other components and for vertices the repair removed); `refined` says how a coarse mesh was',
    'refined to compute on (null: it was not). For a point cloud, {"distance":[...]} with one distance per point of the',
    'file, on the tufted triangulation of its --neighbours K nearest neighbours (null for points in other components',
    'and for points the checks removed; merged duplicates get the distance of the point they joined).',
  ].join('\n'),
  async run([file], options, io) {
    const cloudOptions = cloudOptionsFromFlags(options);
    const shape = await readShape(file, io, cloudOptions.neighbours, { asCloud: asCloudFlag(options), subsample: subsampleFlag(options, cloudOptions.neighbours) });
    // Indices are those of the file, in and out, even when the repair or the checks renumbered them.
    const json = shape.kind === 'cloud'
      ? await cloudDistance(shape, parseSource(String(options.source), shape.pointMap, 'point'), file, io, cloudOptions)
      : await meshDistance(shape, parseSource(String(options.source), shape.vertexMap, 'vertex'), file, io, options);
    if (typeof options.out === 'string') await writeFile(options.out, `${json}\n`);
    else io.stdout.write(`${json}\n`);
  },
};

async function meshDistance(mesh: InputMesh, source: number, file: string, io: CliIo, flags: OptionValues): Promise<string> {
  refuseFlags(flags, cloudOnlyFlags(), file, 'mesh');
  if (mesh.vertexMap[source] < 0) throw new UsageError(`--source ${source} is a vertex used by no face, which the repair removed`);
  const surface = await openSolver(mesh, file, io);
  try {
    const distance = surface.distanceFromVertex(mesh.vertexMap[source]);
    return JSON.stringify({ distance: Array.from(mesh.vertexMap, (v) => (v < 0 ? null : distance[v])), refined: surface.refined });
  } finally {
    surface.dispose();
  }
}

async function cloudDistance(cloudFile: InputCloud, source: number, file: string, io: CliIo, options: CloudOptions): Promise<string> {
  const { pointMap } = cloudFile;
  if (pointMap[source] < 0) throw new UsageError(`--source ${source} is a point the checks removed (a non-finite coordinate, a stray point, or with --${AS_CLOUD.flag} a vertex used by no face)`);
  const cloud = await openCloud(cloudFile, options, file, io);
  try {
    // Infinity (another component) is written as null by JSON.stringify.
    const distance = cloud.distance(pointMap[source]);
    return JSON.stringify({ distance: Array.from(pointMap, (p) => (p < 0 ? null : distance[p])) });
  } finally {
    cloud.dispose();
  }
}

/** The --source index, a vertex or point of the file. */
function parseSource(text: string, map: Int32Array, element: 'vertex' | 'point'): number {
  const index = /^\d+$/.test(text) ? Number(text) : NaN;
  if (!(index < map.length)) {
    throw new UsageError(`--source must be a ${element} index from 0 to ${map.length - 1}, got '${text}'`);
  }
  return index;
}
