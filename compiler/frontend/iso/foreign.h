// Decision 56: a file in another control's language, told by the signatures of its
// first lines, gets one diagnostic instead of a syntax error on every line.
#pragma once

#include <optional>
#include <string>

#include "support/source.h"

namespace ncc::iso {

struct ForeignFile {
  std::string language;  // "Siemens Sinumerik"
  std::string evidence;  // "MSG( on line 3, DEF REAL on line 5"
  uint32_t line = 0;     // of the first signature
};

std::optional<ForeignFile> foreign_language(const SourceFile& source);

}  // namespace ncc::iso
