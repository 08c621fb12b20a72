#include "cscd/separator_status.h"

namespace cscd {

const char* separatorStatusName(SeparatorStatus status) {
  switch (status) {
    case SeparatorStatus::Ok: return "ok";
    case SeparatorStatus::NoCutLocus: return "no-cut-locus";
    case SeparatorStatus::NoTarget: return "no-target";
    case SeparatorStatus::TraceFailed: return "trace-failed";
    case SeparatorStatus::DegenerateLoop: return "degenerate-loop";
    case SeparatorStatus::ShortenFailed: return "shorten-failed";
    case SeparatorStatus::NotSeparating: return "not-separating";
  }
  return "ok";
}

} // namespace cscd
