// What every stage knows of NC-110's ASSET files (chapter 5): their limits and the
// names they may have. The front end checks a program's files against them, the
// bytecode verifier a module's; the files themselves are runtime/asset_store.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ncc::asset {

constexpr size_t kMaxFields = 17;  // a structure binds at most 17 variables (§5.3.2.2)
constexpr size_t kMaxChars = 32;   // .32CH
constexpr uint32_t kMaxRecords = 32767;
constexpr uint8_t kDevices = 7;  // MP0..MP6

// A file's name: one to six capitals and digits, a letter first (the manual says "at
// most 6 characters" only, spec §6.4), on a device: "FILQ/MP3".
struct FileName {
  std::string name;
  uint8_t device = 1;
  std::string text() const;
  bool operator==(const FileName&) const = default;
};
// `text` with or without "/MPn"; nothing when it is not a name a file may have.
[[nodiscard]] std::optional<FileName> parse_file_name(std::string_view text, uint8_t default_device);

}  // namespace ncc::asset
