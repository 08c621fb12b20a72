// embind surface of the core. Arrays cross as typed arrays (one copy in, one copy out: JS owns every
// result, so heap growth cannot invalidate it). Nothing here throws into JS: a call that fails returns
// the error message as a string, which lib/core turns into a CoreError.
#include "mesh/surface.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

using namespace emscripten;
using geometrycentral::surface::SurfacePoint;

namespace cscd {
namespace {

MeshArrays toArrays(const val& positions, const val& triangles) {
  MeshArrays arrays;
  arrays.positions = convertJSArrayToNumberVector<double>(positions);
  arrays.triangles = convertJSArrayToNumberVector<uint32_t>(triangles);
  return arrays;
}

val toFloat64Array(const std::vector<double>& values) {
  return val::global("Float64Array").new_(typed_memory_view(values.size(), values.data()));
}

val toArray3(const std::array<double, 3>& v) {
  val a = val::array();
  for (double x : v) a.call<void>("push", x);
  return a;
}

val toVal(const MeshFacts& f) {
  val o = val::object();
  o.set("vertices", f.vertices);
  o.set("faces", f.faces);
  o.set("edges", f.edges);
  o.set("components", f.components);
  o.set("boundaryLoops", f.boundaryLoops);
  o.set("eulerCharacteristic", f.eulerCharacteristic);
  o.set("genus", f.genus ? val(*f.genus) : val::null());
  o.set("manifold", f.manifold);
  o.set("consistentlyOriented", f.consistentlyOriented);
  o.set("nonManifoldEdges", f.nonManifoldEdges);
  o.set("nonManifoldVertices", f.nonManifoldVertices);
  o.set("unreferencedVertices", f.unreferencedVertices);
  o.set("degenerateFaces", f.degenerateFaces);
  o.set("bboxMin", toArray3(f.bboxMin));
  o.set("bboxMax", toArray3(f.bboxMax));
  o.set("bboxDiagonal", f.bboxDiagonal);
  o.set("meanEdgeLength", f.meanEdgeLength);
  return o;
}

template <class Body>
val reportingErrors(Body&& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return val(std::string("out of memory: the mesh is too large for the WebAssembly heap"));
  } catch (const std::exception& e) {
    return val(std::string(e.what()));
  }
}

val inspect(const val& positions, const val& triangles) {
  return reportingErrors([&] { return toVal(checkMesh(toArrays(positions, triangles)).facts); });
}

class SurfaceBinding {
public:
  SurfaceBinding(const val& positions, const val& triangles) {
    try {
      surface = std::make_unique<Surface>(toArrays(positions, triangles));
    } catch (const std::bad_alloc&) {
      failure = "out of memory: the mesh is too large for the WebAssembly heap";
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }

  std::string error() const { return failure; }

  val facts() const { return surface ? toVal(surface->facts()) : val::null(); }

  val distanceFromVertex(double vertex) {
    return reportingErrors([&] {
      return toFloat64Array(surface->geodesics().fromVertex(checkedVertex(vertex)));
    });
  }

  val exactDistanceFromVertex(double vertex) {
    return reportingErrors([&] {
      return toFloat64Array(surface->geodesics().exactFromVertex(checkedVertex(vertex)));
    });
  }

  // faces: one input face index per point; barycentric: three coordinates per point.
  val distanceFromPoints(const val& faces, const val& barycentric) {
    return reportingErrors([&] {
      std::vector<uint32_t> faceIds = convertJSArrayToNumberVector<uint32_t>(faces);
      std::vector<double> bary = convertJSArrayToNumberVector<double>(barycentric);
      if (faceIds.empty()) throw InputError("no source points given");
      if (bary.size() != 3 * faceIds.size()) throw InputError("three barycentric coordinates are needed per point");
      std::vector<SurfacePoint> points;
      for (size_t i = 0; i < faceIds.size(); i++) {
        if (faceIds[i] >= surface->faceCount())
          throw InputError("source point " + std::to_string(i) + " names face " + std::to_string(faceIds[i]) +
                           ", but the mesh has only " + std::to_string(surface->faceCount()) + " faces");
        geometrycentral::Vector3 b{bary[3 * i], bary[3 * i + 1], bary[3 * i + 2]};
        double sum = b.x + b.y + b.z;
        if (!std::isfinite(sum) || b.x < -1e-9 || b.y < -1e-9 || b.z < -1e-9 || std::abs(sum - 1) > 1e-6)
          throw InputError("source point " + std::to_string(i) + " has barycentric coordinates outside its face");
        points.emplace_back(surface->mesh().face(faceIds[i]), b / sum);
      }
      return toFloat64Array(surface->geodesics().fromPoints(points));
    });
  }

private:
  size_t checkedVertex(double vertex) const {
    if (!(vertex >= 0) || vertex != std::floor(vertex) || vertex >= double(surface->vertexCount())) {
      std::ostringstream msg;
      msg << "vertex " << vertex << " is out of range (the mesh has " << surface->vertexCount() << " vertices)";
      throw InputError(msg.str());
    }
    return size_t(vertex);
  }

  std::unique_ptr<Surface> surface;
  std::string failure;
};

} // namespace
} // namespace cscd

EMSCRIPTEN_BINDINGS(cscd) {
  using namespace cscd;
  function("inspect", &inspect);
  class_<SurfaceBinding>("Surface")
      .constructor<const val&, const val&>()
      .function("error", &SurfaceBinding::error)
      .function("facts", &SurfaceBinding::facts)
      .function("distanceFromVertex", &SurfaceBinding::distanceFromVertex)
      .function("exactDistanceFromVertex", &SurfaceBinding::exactDistanceFromVertex)
      .function("distanceFromPoints", &SurfaceBinding::distanceFromPoints);
}
