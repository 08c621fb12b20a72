#pragma once

// What every binding of the core shares: arrays out as typed arrays (one copy out: JS owns every result,
// so heap growth cannot invalidate it), options in, and failures as values. Nothing a binding exposes
// throws into JS: a call that fails returns {coreError: kind, message} (ErrorKind below), which
// lib/core turns into a CoreError of that kind.
#include "cscd/errors.h"
#include "cscd/options.h"

#include "geometrycentral/utilities/vector3.h"

#include <emscripten/val.h>

#include <array>
#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace cscd {
namespace binding {

using emscripten::val;

template <class T>
val toTypedArray(const char* type, const std::vector<T>& values) {
  return val::global(type).new_(emscripten::typed_memory_view(values.size(), values.data()));
}

inline val toFloat64Array(const std::vector<double>& values) { return toTypedArray("Float64Array", values); }

inline val toFloat64Array(const std::vector<geometrycentral::Vector3>& points) {
  std::vector<double> flat;
  flat.reserve(3 * points.size());
  for (const auto& p : points) flat.insert(flat.end(), {p.x, p.y, p.z});
  return toFloat64Array(flat);
}

// Index pairs (edges) as one flat Uint32Array.
template <class Pairs>
val toPairArray(const Pairs& pairs) {
  std::vector<uint32_t> flat;
  flat.reserve(2 * pairs.size());
  for (const auto& e : pairs) flat.insert(flat.end(), {uint32_t(e[0]), uint32_t(e[1])});
  return toTypedArray("Uint32Array", flat);
}

inline val toArray3(const geometrycentral::Vector3& v) {
  val a = val::array();
  for (double x : {v.x, v.y, v.z}) a.call<void>("push", x);
  return a;
}

inline val toVal(const std::vector<std::pair<std::string, double>>& timings) {
  val o = val::object();
  for (const auto& [stage, ms] : timings) o.set(stage, ms);
  return o;
}

// The options given from JS, checked against their ranges (kOptionRanges); a bad one is an InputError.
Options toOptions(const val& given);

// The core's option defaults, ranges and auto-N constants, for the test that holds lib/core/options.ts to them.
val optionLimits();

// What went wrong, as the caller can act on it: its input or arguments (InputError), the heap (a failed
// allocation), or anything else (a library's failure or a bug).
enum class ErrorKind { Input, Memory, Internal };

struct Failure {
  ErrorKind kind;
  std::string message;
};

Failure failureOf(std::exception_ptr error);

val toVal(const Failure& failure);

template <class Body>
val reportingErrors(Body&& body) {
  try {
    return body();
  } catch (...) {
    return toVal(failureOf(std::current_exception()));
  }
}

} // namespace binding
} // namespace cscd
