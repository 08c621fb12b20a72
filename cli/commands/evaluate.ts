import { parseSkeleton } from '../../lib/io/skeleton.ts';
import { AS_CLOUD } from '../../lib/cloud/from-mesh.ts';
import { asCloudFlag, asCloudOption, getCore, readBytes, readShape, type Command } from '../command.ts';
import { cloudOptionsFromFlags } from './separator.ts';

export const evaluate: Command = {
  name: 'evaluate',
  summary: "score a skeleton by the paper's reconstruction error against its mesh or point cloud, as JSON",
  args: ['<mesh|cloud>', '<skeleton>'],
  options: {
    'derive-radii': { type: 'boolean', description: "ignore the skeleton file's radii and derive them from the mesh" },
    [AS_CLOUD.flag]: asCloudOption,
  },
  details: [
    'Prints {"reconError", "median", "p95", "nodes", "cycles", "radiiSource"}: the squared distance from each',
    "mesh vertex to the skeleton's convolution surface, on the mesh scaled to unit bounding-box diagonal, x1e3",
    '(mean, median, 95th percentile). The skeleton may be JSON (as written by `cscd skeleton`), PLY with an',
    'edge element, OBJ with `l` lines or SWC; without radii they are derived from the mesh (docs/evaluation.md).',
    "Against a point cloud, the same error at the cloud's points (after its checks), radii derived around them.",
  ].join('\n'),
  async run([meshFile, skeletonFile], options, io) {
    const shape = await readShape(meshFile, io, cloudOptionsFromFlags({}).neighbours, { asCloud: asCloudFlag(options) });
    const skeleton = parseSkeleton(await readBytes(skeletonFile), skeletonFile);
    const input = { nodes: skeleton.nodes, edges: skeleton.edges, radii: options['derive-radii'] ? null : skeleton.radii };
    const core = await getCore();
    const result = shape.kind === 'cloud' ? core.evaluateCloud(shape, input) : core.evaluate(shape, input);
    const { reconError, median, p95, nodes, cycles, radiiSource } = result;
    io.stdout.write(`${JSON.stringify({ reconError, median, p95, nodes, cycles, radiiSource })}\n`);
  },
};
