// Skeleton topology on the shared meshes, first half (tests/unit/support/skeletons.ts).
import { skeletonTopologySuite } from './support/skeletons.ts';

skeletonTopologySuite(0);
