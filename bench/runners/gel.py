"""Baselines `ls` and `msls` of the bench: Local Separators (Baerentzen & Rotenberg 2021) and Multi-Scale
Local Separators from PyGEL (pygel3d 0.8.2), with the defaults the authors document.

    python gel.py ls|msls <mesh.ply|.obj|.off> <skeleton.obj>
    python gel.py ls|msls --graph <graph.json> <skeleton.obj>

With --graph the input is a point cloud's neighbourhood graph ({"positions": [x, y, z, ...], "edges":
[a, b, ...]}, written by bench/runners/cscd-cloud.ts): what people run MSLS on when they have points.

Writes the skeleton as OBJ (`v x y z` per node, `l i j` per edge, 1-based), its vertex map beside it as
`<skeleton>.map.json` ({"vertexToNode": [...], "positions": [...]}, see below), and prints, as the last
line of stdout, {"seconds": S}: the wall time of building the mesh's edge graph and skeletonising it
(reading and writing excluded).
"""
import json
import os
import sys
import time

from pygel3d import graph, hmesh

SKELETONISERS = {
    # sampling=True (the default): separators are grown from a sample of the vertices, not all of them.
    # The _and_map variants run the same C++ call as LS_skeleton/MSLS_skeleton, which computes the map
    # either way, so timing them times the same work.
    "ls": lambda g: graph.LS_skeleton_and_map(g),
    # grow_thresh=64 (the default).
    "msls": lambda g: graph.MSLS_skeleton_and_map(g),
}


def graph_from_json(path):
    with open(path) as f:
        data = json.load(f)
    g = graph.Graph()
    p = data["positions"]
    nodes = [g.add_node([p[i], p[i + 1], p[i + 2]]) for i in range(0, len(p), 3)]
    e = data["edges"]
    for i in range(0, len(e), 2):
        g.connect_nodes(nodes[e[i]], nodes[e[i + 1]])
    return g


def main() -> int:
    args = sys.argv[1:]
    from_graph = len(args) == 4 and args[1] == "--graph"
    if from_graph:
        args = [args[0], args[2], args[3]]
    if len(args) != 3 or args[0] not in SKELETONISERS:
        print("usage: gel.py ls|msls <mesh> <skeleton.obj>  or  gel.py ls|msls --graph <graph.json> <skeleton.obj>", file=sys.stderr)
        return 2
    method, mesh_path, out_path = args

    # GEL reports its progress on stdout from C++; send all of it to stderr so that our JSON stays the
    # last line of stdout whatever the C and C++ runtimes flush at exit.
    result_out = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)

    if from_graph:
        # Building the graph is reading the input here, not skeletonising: not timed.
        edge_graph = graph_from_json(mesh_path)
        started = time.perf_counter()
    else:
        mesh = hmesh.load(mesh_path)
        if mesh is None:
            print(f"gel: cannot read {mesh_path}", file=sys.stderr)
            return 1
        started = time.perf_counter()
        edge_graph = graph.from_mesh(mesh)
    skeleton, node_of = SKELETONISERS[method](edge_graph)
    seconds = time.perf_counter() - started

    # Nodes numbered 0..n-1 in the order of nodes() (the ones in use), by us rather than by cleanup(),
    # which renumbers them without saying how, while the map holds the old numbers.
    used = list(skeleton.nodes())
    index = {n: i for i, n in enumerate(used)}
    positions = skeleton.positions()
    with open(out_path, "w") as out:
        out.write(f"# PyGEL {method.upper()} skeleton of {mesh_path}\n")
        for n in used:
            x, y, z = positions[n]
            out.write(f"v {float(x)!r} {float(y)!r} {float(z)!r}\n")
        for n in used:
            for m in skeleton.neighbors(n):
                if n < m:
                    out.write(f"l {index[n] + 1} {index[m] + 1}\n")

    # The map indexes the nodes of the edge graph, i.e. the vertices of GEL's mesh, which GEL numbers its
    # own way (not the file's order): the positions it indexes go with it, so that the bench can match
    # them to the file's vertices.
    with open(os.path.splitext(out_path)[0] + ".map.json", "w") as out:
        json.dump({
            "vertexToNode": [index.get(int(k), -1) for k in node_of],
            "positions": [float(c) for p in edge_graph.positions() for c in p],
        }, out)

    result_out.write(json.dumps({"seconds": seconds}) + "\n")
    result_out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
