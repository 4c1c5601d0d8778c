#include "machine_config.h"

namespace ncc {

int axis_index(char letter) {
  // A table: the runtime asks for every word of every block.
  static constexpr auto kIndex = [] {
    std::array<int8_t, 256> t{};
    t.fill(-1);
    for (size_t i = 0; i < kAxisLetters.size(); ++i) t[static_cast<uint8_t>(kAxisLetters[i])] = static_cast<int8_t>(i);
    return t;
  }();
  return kIndex[static_cast<uint8_t>(letter)];
}

std::string plane_name(const Plane& p) { return {kAxisLetters[p.u], kAxisLetters[p.v]}; }

std::string number_ranges(const std::vector<int>& sorted, bool work_offsets) {
  std::string out;
  for (size_t i = 0; i < sorted.size();) {
    size_t j = i;
    // A range does not run from the plain numbers into the extended work offsets.
    const bool extended = work_offsets && sorted[i] > kExtendedWorkOffset;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1 &&
           (work_offsets && sorted[j + 1] > kExtendedWorkOffset) == extended)
      ++j;
    auto name = [&](int n) { return extended ? "P" + std::to_string(n - kExtendedWorkOffset) : std::to_string(n); };
    out += (out.empty() ? "" : ", ") + name(sorted[i]) + (j > i ? "-" + name(sorted[j]) : "");
    i = j + 1;
  }
  return out.empty() ? "none" : out;
}

}  // namespace ncc
