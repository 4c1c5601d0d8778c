// ASSET files (NC-110 chapter 5): files of fixed-length records on the memory
// devices MP0-MP6, kept in a sandbox directory with one folder a device. The file
// format is docs/asset.md; every change is written crash-safe (the new file whole in
// a temporary, synced, then put in the old one's place), so a killed run leaves each
// file as it was before a change or as it is after it, never torn.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contract/asset_files.h"

namespace ncc::asset {

// Table 5.1: the formats a field may have, and their bytes.
enum class FieldType : uint8_t { Integer = 1, Real = 2, LongReal = 3, Chars = 4 };
struct Field {
  FieldType type = FieldType::Integer;
  uint8_t length = 2;  // IN 2, RE 4, LR 8, CH 1..32
  bool operator==(const Field&) const = default;
};
using Layout = std::vector<Field>;

// "IN", "RE", "LR", "5CH" (and back); a well-formed layout has 1..17 such fields.
std::string field_text(const Field& f);
[[nodiscard]] std::optional<Field> parse_field(std::string_view text);
bool well_formed(const Layout& layout);
size_t record_length(const Layout& layout);

// A file's contents.
struct File {
  Layout layout;
  uint32_t records = 0;
  bool write_protected = false;
  std::string data;  // records × record_length(layout) bytes
  bool operator==(const File&) const = default;
};
// A new file: numbers 0, characters blanks (unspecified, spec §6.5.6).
File blank_file(const Layout& layout, uint32_t records);
// A field of record `record` (1..records), field `field` (0-based): a number (IN, RE,
// LR) or characters (CH, blank-filled). Setting fails for a value the field cannot
// hold: IN a whole number -32768..32767, RE a finite binary32, CH at most its length.
double number(const File& f, uint32_t record, size_t field);
std::string_view chars(const File& f, uint32_t record, size_t field);
[[nodiscard]] bool set_number(File& f, uint32_t record, size_t field, double value);
[[nodiscard]] bool set_chars(File& f, uint32_t record, size_t field, std::string_view text);
std::string encode(const File& f);
// Code::Ok, or Code::Logical when `bytes` are not a well-formed file of this version.
Code decode(std::string_view bytes, File& f);

// The sandbox: a directory holding MP0..MP6. A device whose folder is missing (or is
// a link) is not connected (15); a file that is a link or not a regular file is not
// an ASSET file (14). Names are checked again here, so no name leaves the sandbox.
class Store {
 public:
  struct Options {
    uint64_t device_bytes = 1 << 20;  // the files of one device together, at most (17 beyond)
  };
  // The sandbox at `dir`, or nothing and why.
  [[nodiscard]] static std::unique_ptr<Store> open(const std::string& dir, const Options& options, std::string& why);
  // Whether any device folder MP0..MP6 exists (`ncc files init` makes them).
  bool prepared() const;
  ~Store();
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;

  Code load(const FileName& name, File& f) const;
  Code create(const FileName& name, const File& f);   // 5 if it exists
  Code replace(const FileName& name, const File& f);  // 4 unless it exists
  Code remove(const FileName& name);
  // The files of a device, by name (an unconnected device has none).
  std::vector<FileName> list(uint8_t device) const;

 private:
  Store(int dir, const Options& options);
  int device(uint8_t d) const;  // an open folder, or -1
  Code write(const FileName& name, const File& f, bool fresh);

  int dir_;
  Options options_;
};

}  // namespace ncc::asset
