#include "cscd/pack.h"

#include <algorithm>
#include <numeric>

namespace cscd {

std::vector<size_t> packSeparators(const std::vector<double>& scores, const std::vector<std::vector<size_t>>& overlaps) {
  const size_t n = scores.size();
  std::vector<double> weight(n, 0);
  for (size_t i = 0; i < n; i++) {
    double neighbourhood = scores[i];
    for (size_t j : overlaps[i]) neighbourhood += scores[j];
    weight[i] = neighbourhood > 0 ? scores[i] / neighbourhood : 0;
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return weight[a] > weight[b]; });

  std::vector<char> blocked(n, 0);
  std::vector<size_t> accepted;
  for (size_t i : order) {
    if (blocked[i] || !(scores[i] > 0)) continue;
    accepted.push_back(i);
    for (size_t j : overlaps[i]) blocked[j] = 1;
  }
  std::sort(accepted.begin(), accepted.end());
  return accepted;
}

} // namespace cscd
