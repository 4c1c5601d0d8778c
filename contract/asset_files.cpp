#include "asset_files.h"

#include <algorithm>

#include <fmt/format.h>

namespace ncc::asset {

std::string FileName::text() const { return fmt::format("{}/MP{}", name, device); }

std::optional<FileName> parse_file_name(std::string_view text, uint8_t default_device) {
  FileName f;
  f.device = default_device;
  if (size_t slash = text.find('/'); slash != std::string_view::npos) {
    std::string_view dev = text.substr(slash + 1);
    if (dev.size() != 3 || !dev.starts_with("MP") || dev[2] < '0' || dev[2] >= '0' + kDevices) return std::nullopt;
    f.device = static_cast<uint8_t>(dev[2] - '0');
    text = text.substr(0, slash);
  }
  auto upper = [](char c) { return c >= 'A' && c <= 'Z'; };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (text.empty() || text.size() > 6 || !upper(text[0])) return std::nullopt;
  if (!std::all_of(text.begin(), text.end(), [&](char c) { return upper(c) || digit(c); })) return std::nullopt;
  if (f.device >= kDevices) return std::nullopt;
  f.name = std::string(text);
  return f;
}

std::string_view meaning(Code c) {
  static constexpr std::string_view kText[] = {"no error",
                                               "channel already open or still closed",
                                               "invalid channel number",
                                               "no permitted channel",
                                               "file not found",
                                               "file already exists",
                                               "illegal operation",
                                               "file already open",
                                               "file not open",
                                               "protected file",
                                               "format error",
                                               "record not found",
                                               "hardware error",
                                               "end of file",
                                               "logical I/O error",
                                               "invalid device",
                                               "record structure not defined",
                                               "memory overflow",
                                               "ASSET area not configured"};
  return kText[static_cast<size_t>(c)];
}

}  // namespace ncc::asset
