// Skeleton topology on a representative part of the shared meshes (tests/unit/support/skeletons.ts);
// every closed connected shared mesh: `npm run check:corpus`.
import { skeletonTopologySuite } from './support/skeletons.ts';

skeletonTopologySuite();
