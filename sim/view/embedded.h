// The files of `ncc view`'s page compiled into the binary (sim/CMakeLists.txt): the
// page's own from sim/view/, and three.js with its orbit controls from Debian's
// libjs-three when the build found it (NCC_VIEW_THREE).
#pragma once

#include <span>
#include <string_view>

namespace ncc::sim::view_files {

struct EmbeddedFile {
  std::string_view path;  // "view/page.html"; "three.min.js", "examples/js/controls/OrbitControls.js"
  std::string_view text;
};

namespace page {
std::span<const EmbeddedFile> embedded_files();
}
namespace three {
std::span<const EmbeddedFile> embedded_files();
}

}  // namespace ncc::sim::view_files
