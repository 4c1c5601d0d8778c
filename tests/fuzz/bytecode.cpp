// Fuzz target of the bytecode loader: the input is a bytecode file whose checksum is
// made right (header bytes 12-15, the CRC-32 of every byte after the 16-byte header:
// docs/bytecode.md), so that mutations reach the parser and the verifier rather than
// stopping at the checksum. A file the loader accepts goes where `ncc run` and
// `ncc disasm` take it: written and read back, disassembled, run.
#include <string>

#include "fuzz.h"
#include "support/bytes.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ncc;
  std::string bytes(reinterpret_cast<const char*>(data), size);
  constexpr size_t kHeader = 16;
  if (bytes.size() >= kHeader) {
    uint32_t crc = crc32({data + kHeader, size - kHeader});
    for (size_t i = 0; i < 4; ++i) bytes[12 + i] = static_cast<char>((crc >> (8 * i)) & 0xFF);
  }
  Session s(100);
  if (auto m = vm::read_module(bytes, "fuzz.ncb", s.diags)) {
    fuzz::round_trip(*m);
    fuzz::run(s, *m);
  }
  fuzz::format_diagnostics(s);
  return 0;
}
