// A compiled program in memory, and its file form (.ncb): magic, format version,
// CRC-32, then sections (meta, semantics, constants, strings, code, line table,
// entry points, variable spaces, source map). docs/bytecode.md describes the bytes.
// Loading verifies every instruction, operand and jump before anything runs.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contract/program_semantics.h"
#include "contract/services.h"
#include "contract/source_map.h"
#include "contract/variables.h"
#include "support/diagnostics.h"

namespace ncc::vm {

constexpr uint16_t kFormatVersion = 14;
constexpr uint32_t kMaxStack = 256;
constexpr uint64_t kMaxVariables = 1u << 24;  // all spaces together
constexpr uint8_t kMaxProcesses = 5;          // NC-110 chapter 4

// A Process entry is a program that runs in a process of its own (NC-110 EXE, chapter 4).
enum class EntryKind : uint8_t { Program, MainBlock, Subprogram, Process };

struct Entry {
  std::string name;  // "%0001", ":100"
  EntryKind kind = EntryKind::Program;
  uint32_t pc = 0;
  uint8_t processes = 0;  // a Process entry started in process n when the run starts: bit n-1 (none: by EXE only)
};

// From `pc` on, the code belongs to source block `source` (until the next entry).
struct LineEntry {
  uint32_t pc = 0;
  uint32_t source = 0;
};

// A device's bit in Module::devices.
constexpr uint8_t device_bit(Device d) { return static_cast<uint8_t>(1u << static_cast<unsigned>(d)); }

struct Module {
  std::string dialect;
  std::string profile_name;
  std::string profile_text;  // the machine profile it was compiled with ("" = default)
  ProgramSemantics semantics;
  std::vector<double> numbers;
  std::vector<std::string> strings;
  std::vector<uint8_t> code;
  std::vector<LineEntry> lines;
  std::vector<Entry> entries;
  std::vector<VarSpace> spaces;
  SourceMap source_map;
  // The devices whose services its code calls, a bit each: not in the file, found by
  // lower() and by read_module()'s verifier.
  uint8_t devices = 0;

  uint32_t source_of(uint32_t pc) const;
  bool calls(Device d) const { return devices & device_bit(d); }
};

std::string write_module(const Module& m);
// The same bytes to a file opened for writing (seekable: the checksum goes in last),
// holding only a small buffer; false if a write failed.
[[nodiscard]] bool write_module(const Module& m, std::FILE* out);
// Parses, checks the checksum and verifies; reports and returns nothing on failure.
[[nodiscard]] std::optional<Module> read_module(std::string_view bytes, const std::string& name, Diagnostics& diags);
// The same from the `size` bytes of the file open at `fd`, read a section at a time:
// loading holds the module, not the file beside it.
[[nodiscard]] std::optional<Module> read_module(int fd, uint64_t size, const std::string& name, Diagnostics& diags);
// "" when the module is sound, else the first problem found.
[[nodiscard]] std::string verify(const Module& m);
std::string disassemble(const Module& m);

}  // namespace ncc::vm
