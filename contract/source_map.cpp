#include "source_map.h"

namespace ncc {

// docs/bytecode.md, SRCS: the block as deltas from the one before (most are a line
// on), then its words as deltas from the block and the word before.
void SourceMap::add(const SourceBlock& b, std::span<const WordPosition> words) {
  checkpoint();
  ByteWriter& w = block_;
  w.data().clear();
  w.uvar(b.file);
  w.svar(int64_t(b.line) - last_line_);
  w.uvar(b.col);
  w.svar(int64_t(b.end_line) - b.line);
  w.uvar(b.end_col);
  w.u8(static_cast<uint8_t>(b.has_number | (b.main_block << 1) | (b.has_errors << 2)));
  if (b.has_number) w.uvar(b.number);
  w.uvar(words.size());
  uint32_t col = b.col;
  for (const WordPosition& p : words) {
    w.u8(p.slot);
    w.svar(p.code);
    w.svar(int64_t(p.line) - b.line);
    w.svar(int64_t(p.col) - col);
    w.svar(int64_t(p.end_col) - p.col);
    col = p.col;
  }
  bytes_ += w.data();
  added(b.line);
}

void SourceMap::checkpoint() {
  if (count_ % kCheckpointEvery == 0) checkpoints_.push_back({count_, bytes_.size(), last_line_});
}

void SourceMap::added(uint32_t line) {
  last_line_ = line;
  ++count_;
}

namespace {

// One block after the block on line `line` (and its words, if asked); false if the
// bytes are not one. Bytes the map has checked (`trusted`) are skipped, not read,
// where no words are asked for: a run asks for every block it reports at.
bool decode_block(ByteReader& r, uint32_t line, SourceBlock& b, std::vector<WordPosition>* words,
                  bool trusted = false) {
  bool ok = true;
  b.file = r.var32(ok);
  b.line = r.delta32(line, ok);
  b.col = r.var32(ok);
  b.end_line = r.delta32(b.line, ok);
  b.end_col = r.var32(ok);
  const uint8_t flags = r.u8();
  if (flags > 7) return false;
  b.has_number = flags & 1;
  b.main_block = flags & 2;
  b.has_errors = flags & 4;
  b.number = b.has_number ? r.var32(ok) : 0;
  const uint64_t n = r.uvar();
  if (n * 5 > r.remaining()) return false;  // each word takes at least 5 bytes
  if (!words && trusted) {                  // a slot and four numbers each
    for (uint64_t k = 0; k < n; ++k) {
      r.u8();
      r.skip_varints(4);
    }
    return ok && !r.failed();
  }
  uint32_t col = b.col;
  for (uint64_t k = 0; k < n; ++k) {
    WordPosition p;
    p.slot = r.u8();
    const int64_t code = r.svar();
    if (code < INT16_MIN || code > INT16_MAX) return false;
    p.code = static_cast<int16_t>(code);
    p.line = r.delta32(b.line, ok);
    p.col = r.delta32(col, ok);
    p.end_col = r.delta32(p.col, ok);
    col = p.col;
    if (words) words->push_back(p);
  }
  return ok && !r.failed();
}

}  // namespace

bool SourceMap::read(std::string encoded, uint32_t count) {
  ByteReader r(encoded);
  for (uint32_t i = 0; i < count; ++i) {
    if (count_ % kCheckpointEvery == 0) checkpoints_.push_back({count_, r.pos(), last_line_});
    SourceBlock b;
    if (!decode_block(r, last_line_, b, nullptr)) return false;
    added(b.line);
  }
  if (!r.at_end()) return false;
  bytes_ = std::move(encoded);
  return true;
}

SourceMap::Cursor SourceMap::seek(uint32_t i) const {
  if (next_.index == i && i < count_) return next_;
  Cursor c = checkpoints_[i / kCheckpointEvery];
  if (next_.index < i && next_.index > c.index) c = next_;  // nearer
  while (c.index < i) decode(c, nullptr);
  return c;
}

SourceBlock SourceMap::decode(Cursor& c, std::vector<WordPosition>* words) const {
  // The map's own bytes: add() wrote them, or read() checked them.
  ByteReader r(encoded().substr(c.offset));
  SourceBlock b;
  decode_block(r, c.line, b, words, true);
  c = {c.index + 1, c.offset + r.pos(), b.line};
  return b;
}

SourceBlock SourceMap::block(uint32_t i) const {
  Cursor c = seek(i);
  SourceBlock b = decode(c, nullptr);
  next_ = c;
  return b;
}

void SourceMap::visit(const std::function<void(const SourceBlock&, const std::vector<WordPosition>&)>& f) const {
  Cursor c;
  std::vector<WordPosition> words;
  while (c.index < count_) {
    words.clear();
    const SourceBlock b = decode(c, &words);
    f(b, words);
  }
}

std::vector<WordPosition> SourceMap::words(uint32_t i) const {
  Cursor c = seek(i);
  std::vector<WordPosition> out;
  decode(c, &out);
  next_ = c;
  return out;
}

}  // namespace ncc
