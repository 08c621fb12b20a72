// Baseline `mcf` of the bench: CGAL's mean curvature flow skeleton (Tagliasacchi et al. 2012) with its
// default parameters.
//
//   mcf <mesh.ply|.off|.obj> <skeleton.obj>
//
// Writes the skeleton as OBJ (`v x y z` per node, `l i j` per edge, 1-based), its vertex map beside it as
// `<skeleton>.map.json` ({"vertexToNode": [...], "positions": [...]}: per mesh vertex the node it was
// contracted into, -1 for none, with the positions of the mesh's vertices in CGAL's order, in case
// reading repaired the mesh and renumbered them) and prints, as the last line of stdout,
// {"seconds": S}: the wall time of the skeleton call alone (reading and writing excluded).
// Built by bench/setup.sh against Debian's libcgal-dev with Eigen (CGAL_EIGEN3_ENABLED).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>
#include <boost/graph/graph_traits.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Skeleton = CGAL::Mean_curvature_flow_skeletonization<Mesh>::Skeleton;

static int fail(const char* message) {
  std::cerr << "mcf: " << message << "\n";
  return 1;
}

int main(int argc, char** argv) {
  if (argc != 3) return fail("usage: mcf <mesh> <skeleton.obj>");

  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(argv[1], mesh) || mesh.is_empty()) return fail("cannot read the mesh (or it is not a polygon mesh)");
  // The flow contracts a closed triangle surface: CGAL asserts on anything else.
  if (!CGAL::is_triangle_mesh(mesh)) return fail("the mesh is not a triangle mesh");
  if (!CGAL::is_closed(mesh)) return fail("the mesh is not closed (it has boundary edges)");

  Skeleton skeleton;
  const auto started = std::chrono::steady_clock::now();
  CGAL::extract_mean_curvature_flow_skeleton(mesh, skeleton);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::ofstream out(argv[2]);
  if (!out) return fail("cannot write the skeleton file");
  out << std::setprecision(17);
  out << "# CGAL mean curvature flow skeleton of " << argv[1] << "\n";
  // boost::adjacency_list with vecS: vertex descriptors are 0..n-1, in the order of vertices().
  for (auto v : CGAL::make_range(vertices(skeleton))) {
    const Point& p = skeleton[v].point;
    out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  }
  for (auto e : CGAL::make_range(edges(skeleton))) out << "l " << source(e, skeleton) + 1 << " " << target(e, skeleton) + 1 << "\n";
  out.close();
  if (!out) return fail("cannot write the skeleton file");

  std::vector<long> nodeOf(num_vertices(mesh), -1);
  for (auto v : CGAL::make_range(vertices(skeleton)))
    for (auto contracted : skeleton[v].vertices) nodeOf[contracted.idx()] = static_cast<long>(v);
  const std::string skeletonPath = argv[2];
  std::ofstream map(skeletonPath.substr(0, skeletonPath.rfind('.')) + ".map.json");
  map << std::setprecision(17) << "{\"vertexToNode\": [";
  for (size_t i = 0; i < nodeOf.size(); i++) map << (i ? "," : "") << nodeOf[i];
  map << "], \"positions\": [";
  bool first = true;
  for (auto vd : CGAL::make_range(mesh.vertices())) {
    const Point& p = mesh.point(vd);
    map << (first ? "" : ",") << p.x() << "," << p.y() << "," << p.z();
    first = false;
  }
  map << "]}\n";
  map.close();
  if (!map) return fail("cannot write the vertex map file");

  std::cout << std::setprecision(6) << "{\"seconds\": " << seconds << "}" << std::endl;
  return 0;
}
