// Skeleton topology on the shared meshes, second half (tests/unit/support/skeletons.ts).
import { skeletonTopologySuite } from './support/skeletons.ts';

skeletonTopologySuite(1);
