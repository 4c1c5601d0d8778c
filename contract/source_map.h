// Where each block of a module came from: its file, range, block number and flags,
// and where its words stand (so that a run-time problem points at the word). The
// bytecode file stores it (docs/bytecode.md, SRCS), and memory holds it the same way,
// encoded: a few bytes a block instead of a structure per block and per word. A block
// is decoded when asked for: the next one cheaply, any other from the checkpoint
// before it.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "support/bytes.h"

namespace ncc {

struct SourceBlock {
  uint32_t file = 0;
  uint32_t line = 0, col = 0, end_line = 0, end_col = 0;
  bool has_number = false;
  bool main_block = false;
  bool has_errors = false;  // the compiler reported errors here (the dry run stays quiet)
  uint32_t number = 0;      // with has_number (0 otherwise)
  bool operator==(const SourceBlock&) const = default;
};

struct WordPosition {
  uint8_t slot = 0;
  int16_t code = -1;  // a G/M word: its index in ProgramSemantics::codes
  uint32_t line = 0, col = 0, end_col = 0;
  bool operator==(const WordPosition&) const = default;
};

class SourceMap {
 public:
  std::vector<std::string> files;

  uint32_t size() const { return count_; }
  void add(const SourceBlock& b, std::span<const WordPosition> words);
  void reserve(size_t bytes) { bytes_.reserve(bytes); }
  SourceBlock block(uint32_t i) const;  // i < size()
  std::vector<WordPosition> words(uint32_t i) const;
  // Every block in order, with its words.
  void visit(const std::function<void(const SourceBlock&, const std::vector<WordPosition>&)>& f) const;
  // The blocks as the file stores them after their count; read() takes the
  // `encoded` bytes of `count` blocks from a file, checked (false if they are not
  // exactly that), and keeps them as they are.
  std::string_view encoded() const { return bytes_; }
  [[nodiscard]] bool read(std::string encoded, uint32_t count);
  bool operator==(const SourceMap& o) const {
    return files == o.files && count_ == o.count_ && encoded() == o.encoded();
  }

 private:
  struct Cursor {  // before block `index`
    uint32_t index = 0;
    size_t offset = 0;
    uint32_t line = 0;  // of the block before
  };
  static constexpr uint32_t kCheckpointEvery = 16;
  // Decodes the block at `c` (its words too, if asked) and moves `c` past it.
  SourceBlock decode(Cursor& c, std::vector<WordPosition>* words) const;
  Cursor seek(uint32_t i) const;
  void checkpoint();          // before a block is appended
  void added(uint32_t line);  // after it, on `line`

  std::string bytes_;
  ByteWriter block_;  // the block being added
  uint32_t count_ = 0;
  uint32_t last_line_ = 0;
  std::vector<Cursor> checkpoints_;  // before blocks 0, 16, 32...
  mutable Cursor next_;              // after the block decoded last: a run asks in order
};

}  // namespace ncc
