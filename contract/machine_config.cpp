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

}  // namespace ncc
