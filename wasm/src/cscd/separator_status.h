#pragma once

namespace cscd {

// Why a source has no separator (Ok when it has one), on any shape; separatorStatusName gives the name
// the bindings, the CLI JSON and the page use (SeparatorStatus in lib/core/types.ts).
enum class SeparatorStatus { Ok, NoCutLocus, NoTarget, TraceFailed, DegenerateLoop, ShortenFailed, NotSeparating };
const char* separatorStatusName(SeparatorStatus status);

} // namespace cscd
