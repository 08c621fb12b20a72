#pragma once

#include <cstddef>
#include <vector>

namespace cscd {

// Greedy weighted set packing (paper Sec. 4.2.3, after LS): each separator's score is normalised by the
// opportunity cost of keeping it, the total score of its closed neighbourhood in the overlap graph
// (itself and every separator it overlaps): w_i = s_i / (s_i + sum_j s_j). Separators are accepted in
// decreasing w (ties by index) when they overlap no accepted one. Returns the accepted indices, sorted.
std::vector<size_t> packSeparators(const std::vector<double>& scores, const std::vector<std::vector<size_t>>& overlaps);

} // namespace cscd
