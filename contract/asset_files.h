// What every stage knows of NC-110's ASSET files (chapter 5): their limits and the
// names they may have. The front end checks a program's files against them, the
// bytecode verifier a module's, the trace the codes a statement ends with; the files
// themselves are devices/asset_store.h.
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

// Table 5.2: what an ASSET statement leaves in IOSTA (0: it worked).
// [[nodiscard]] on a declaration first: clang-format 14 mangles it on the definition.
enum class [[nodiscard]] Code : uint8_t;
enum class Code : uint8_t {
  Ok = 0,
  ChannelState = 1,  // channel already open / still closed
  BadChannel = 2,
  NoChannel = 3,
  NotFound = 4,
  Exists = 5,
  Illegal = 6,
  AlreadyOpen = 7,
  NotOpen = 8,
  Protected = 9,
  Format = 10,
  NoRecord = 11,
  Hardware = 12,
  EndOfFile = 13,
  Logical = 14,  // the file is not a well-formed ASSET file (docs/asset.md)
  BadDevice = 15,
  NoStructure = 16,
  Overflow = 17,
  NotConfigured = 18,
};
std::string_view meaning(Code c);  // the table's words

}  // namespace ncc::asset
