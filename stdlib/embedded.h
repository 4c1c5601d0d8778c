// Data files compiled into the binary (dialect tables, default profile).
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace ncc::stdlib {

struct EmbeddedFile {
  std::string_view path;  // relative to stdlib/, e.g. "dialects/gost/g_codes.tsv"
  std::string_view text;
};

std::span<const EmbeddedFile> embedded_files();
std::optional<std::string_view> embedded_file(std::string_view path);

}  // namespace ncc::stdlib
