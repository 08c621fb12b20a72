#include "bindings/convert.h"

#include "cscd/pipeline.h"

#include <sstream>
#include <stdexcept>

namespace cscd {
namespace binding {
namespace {

const OptionRange& rangeOf(const std::string& name) {
  for (const OptionRange& range : kOptionRanges)
    if (name == range.name) return range;
  throw std::logic_error("no range for option " + name);
}

} // namespace

Options toOptions(const val& given) {
  Options options;
  if (given.isUndefined() || given.isNull()) return options;
  auto number = [&](const char* name, double fallback) {
    val v = given[name];
    if (v.isUndefined()) return fallback;
    const auto [_, low, high] = rangeOf(name);
    double x = v.as<double>();
    if (!(x >= low && x <= high)) {
      std::ostringstream msg;
      msg << "option " << name << " must be between " << low << " and " << high << ", got " << x;
      throw InputError(msg.str());
    }
    return x;
  };
  if (!given["target"].isUndefined()) {
    std::string target = given["target"].as<std::string>();
    if (target != "euclid" && target != "geodesic")
      throw InputError("option target must be 'euclid' or 'geodesic', got '" + target + "'");
    options.target = target == "euclid" ? TargetMode::Euclidean : TargetMode::Geodesic;
  }
  if (!given["sphere"].isUndefined()) options.sphere = given["sphere"].as<bool>();
  options.seed = uint32_t(number("seed", options.seed));
  options.angleThreshold = number("angleThreshold", options.angleThreshold);
  options.laplacianThreshold = number("laplacianThreshold", options.laplacianThreshold);
  options.pruneDepth = int(number("pruneDepth", options.pruneDepth));
  val n = given["n"];
  if (!n.isUndefined()) {
    if (n.isString()) {
      if (n.as<std::string>() != "auto") throw InputError("option n must be a number of sources or 'auto'");
      options.n = 0;
    } else {
      options.n = int(number("n", options.n));
    }
  }
  options.pruneLengthFactor = number("pruneLengthFactor", options.pruneLengthFactor);
  options.drawAhead = int(number("drawAhead", options.drawAhead));
  options.neighbours = int(number("neighbours", options.neighbours));
  options.stage1Vertices = int(number("stage1Vertices", options.stage1Vertices));
  return options;
}

val optionLimits() {
  const Options d;
  val defaults = val::object();
  defaults.set("target", std::string(d.target == TargetMode::Euclidean ? "euclid" : "geodesic"));
  defaults.set("sphere", d.sphere);
  defaults.set("seed", d.seed);
  defaults.set("angleThreshold", d.angleThreshold);
  defaults.set("laplacianThreshold", d.laplacianThreshold);
  defaults.set("pruneDepth", d.pruneDepth);
  defaults.set("n", d.n == 0 ? val("auto") : val(d.n));
  defaults.set("pruneLengthFactor", d.pruneLengthFactor);
  defaults.set("drawAhead", d.drawAhead);
  defaults.set("neighbours", d.neighbours);
  defaults.set("stage1Vertices", d.stage1Vertices);
  val ranges = val::object();
  for (const OptionRange& range : kOptionRanges) {
    val pair = val::array();
    pair.call<void>("push", range.low);
    pair.call<void>("push", range.high);
    ranges.set(range.name, pair);
  }
  val autoN = val::object();
  autoN.set("covered", kAutoCovered);
  autoN.set("window", double(kAutoWindow));
  autoN.set("minGain", kAutoMinGain);
  autoN.set("max", double(kMaxAutoSources));
  val limits = val::object();
  limits.set("defaults", defaults);
  limits.set("ranges", ranges);
  limits.set("autoN", autoN);
  return limits;
}

Failure failureOf(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::bad_alloc&) {
    return {ErrorKind::Memory, "out of memory: the shape is too large for the WebAssembly heap"};
  } catch (const InputError& e) {
    return {ErrorKind::Input, e.what()};
  } catch (const std::exception& e) {
    return {ErrorKind::Internal, e.what()};
  } catch (...) {
    return {ErrorKind::Internal, "the core failed with an unknown error"};
  }
}

val toVal(const Failure& failure) {
  static const char* const kNames[] = {"input", "memory", "internal"};
  val o = val::object();
  o.set("coreError", std::string(kNames[int(failure.kind)]));
  o.set("message", failure.message);
  return o;
}

} // namespace binding
} // namespace cscd
