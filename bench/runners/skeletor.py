"""Baseline `skeletor` of the cloud bench: pc-skeletor's Laplacian-based contraction (LBC; Cao et al.
2010, "Point cloud skeletons via Laplacian-based contraction"), pc-skeletor 1.0.0 (MIT), default options.

    python skeletor.py <cloud.ply> <skeleton.obj>

LBC's weights are absolute, so its defaults suit one size of cloud: the cloud is given to it scaled to a
bounding-box diagonal of 1 and centred at (1, 1, 1) (pc-skeletor drops contracted points within 0.01 of the
origin as artifacts), and the skeleton mapped back. On armadillo_gel_pts (diagonal 229) the error against
the mesh was 9.15e-3 at its own size, 0.145e-3 so scaled (0.094e-3 at a diagonal of 0.5, 0.207e-3 at 1
but centred at the origin). The skeleton is pc-skeletor's `skeleton_graph`: a minimum spanning tree over
farthest points sampled from the contracted cloud (so it has no cycles by construction). Writes it as OBJ (`v x y z` per node, `l i j`
per edge, 1-based) and prints, as the last line of stdout, {"seconds": S}: the wall time of contraction
and graph extraction (reading and writing excluded).

pc-skeletor's package imports its learned method (Point2Skeleton: torch, dgl) on import; only LBC is run
here, so its module is loaded without the package's __init__ (bench/setup.sh installs LBC's needs alone).
"""
import json
import os
import sys
import time
import types


def load_lbc():
    """pc_skeletor.laplacian.LBC, its package set up as an empty namespace so that its __init__ never runs."""
    site = next(p for p in sys.path if p.endswith("site-packages") and os.path.isdir(os.path.join(p, "pc_skeletor")))
    package = types.ModuleType("pc_skeletor")
    package.__path__ = [os.path.join(site, "pc_skeletor")]
    sys.modules["pc_skeletor"] = package
    from pc_skeletor.laplacian import LBC

    return LBC


def main() -> int:
    if len(sys.argv) != 3:
        print("usage: skeletor.py <cloud.ply> <skeleton.obj>", file=sys.stderr)
        return 2
    cloud_path, out_path = sys.argv[1:]
    import open3d as o3d

    import numpy as np

    LBC = load_lbc()
    points = np.asarray(o3d.io.read_point_cloud(cloud_path).points)
    low, high = points.min(axis=0), points.max(axis=0)
    centre, diagonal = (low + high) / 2, float(np.linalg.norm(high - low))
    scaled = o3d.geometry.PointCloud(o3d.utility.Vector3dVector((points - centre) / diagonal + 1))
    started = time.perf_counter()
    lbc = LBC(point_cloud=scaled)
    lbc.extract_skeleton()
    lbc.extract_topology()
    seconds = time.perf_counter() - started
    graph = lbc.skeleton_graph
    index = {node: i for i, node in enumerate(graph.nodes)}
    with open(out_path, "w") as f:
        for node in graph.nodes:
            x, y, z = (np.asarray(graph.nodes[node]["pos"]) - 1) * diagonal + centre
            f.write(f"v {x} {y} {z}\n")
        for a, b in graph.edges:
            f.write(f"l {index[a] + 1} {index[b] + 1}\n")
    print(json.dumps({"seconds": seconds}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
