#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace cscd {

// Milliseconds per stage: lap(stage) records the time since the previous lap (or construction).
class StageClock {
public:
  explicit StageClock(std::vector<std::pair<std::string, double>>& out) : out(out) {}
  void lap(const char* stage) {
    auto now = std::chrono::steady_clock::now();
    out.emplace_back(stage, std::chrono::duration<double, std::milli>(now - start).count());
    start = now;
  }

private:
  std::vector<std::pair<std::string, double>>& out;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};

} // namespace cscd
