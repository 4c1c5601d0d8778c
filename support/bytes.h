// Portable byte-level helpers: fixed little-endian encoding and CRC-32, used by the
// bytecode file format so a file means the same on every host.
#pragma once

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <string_view>

namespace ncc {

uint32_t crc32(std::span<const uint8_t> data, uint32_t crc = 0);

// Little-endian values into a buffer: kept in memory (data()), or passed on to a file
// in pieces as they come (a stream: only the piece being filled is held).
class ByteWriter {
 public:
  ByteWriter() = default;
  // A stream to `out`; nullptr: nowhere, only counting the bytes.
  explicit ByteWriter(std::FILE* out) : stream_(true), file_(out) {}

  void u8(uint8_t v) {
    out_.push_back(static_cast<char>(v));
    if (stream_ && out_.size() >= kPiece) pass_on();
  }
  void u16(uint16_t v) { put(v, 2); }
  void u32(uint32_t v) { put(v, 4); }
  void u64(uint64_t v) { put(v, 8); }
  void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
  void bytes(std::string_view s) {
    if (stream_ && out_.size() + s.size() >= kPiece) {
      pass_on();
      emit(s);  // a large block goes as it is
      return;
    }
    out_.append(s);
  }
  void str(std::string_view s) {
    u32(static_cast<uint32_t>(s.size()));
    bytes(s);
  }
  // LEB128: 7 bits a byte, low first; small numbers (deltas, counts) take one byte.
  void uvar(uint64_t v) {
    for (; v >= 0x80; v >>= 7) u8(static_cast<uint8_t>(v | 0x80));
    u8(static_cast<uint8_t>(v));
  }
  // Signed as zigzag LEB128: -1 is one byte, as 1 is.
  void svar(int64_t v) { uvar((static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63)); }
  void patch_u32(size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) out_[at + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
  }
  size_t size() const { return out_.size(); }
  std::string& data() { return out_; }
  const std::string& data() const { return out_; }

  // A stream: passes the rest on; false if a write failed.
  [[nodiscard]] bool finish() {
    pass_on();
    return ok_;
  }
  uint64_t written() const { return passed_ + out_.size(); }
  uint32_t crc() const { return crc_; }  // of the bytes passed on to a file

 private:
  static constexpr size_t kPiece = 1 << 16;
  void put(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) u8(static_cast<uint8_t>((v >> (8 * i)) & 0xFF));
  }
  void pass_on() {
    emit(out_);
    out_.clear();
  }
  void emit(std::string_view s) {
    passed_ += s.size();
    if (!file_ || s.empty()) return;  // counting only: no checksum wanted
    crc_ = crc32({reinterpret_cast<const uint8_t*>(s.data()), s.size()}, crc_);
    if (std::fwrite(s.data(), 1, s.size(), file_) != s.size()) ok_ = false;
  }
  std::string out_;
  bool stream_ = false;
  std::FILE* file_ = nullptr;
  uint64_t passed_ = 0;
  uint32_t crc_ = 0;
  bool ok_ = true;
};

// Reads fixed-width little-endian values; any read past the end sets failed() and
// returns zeros, so a truncated file can be detected once at the end.
class ByteReader {
 public:
  explicit ByteReader(std::string_view data) : data_(data) {}
  uint8_t u8() { return static_cast<uint8_t>(get(1)); }
  uint16_t u16() { return static_cast<uint16_t>(get(2)); }
  uint32_t u32() { return static_cast<uint32_t>(get(4)); }
  uint64_t u64() { return get(8); }
  double f64() { return std::bit_cast<double>(u64()); }
  std::string_view bytes(size_t n) {
    if (n > data_.size() - pos_) {
      failed_ = true;
      pos_ = data_.size();
      return {};
    }
    std::string_view s = data_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  std::string_view str() { return bytes(u32()); }
  // LEB128 (ByteWriter::uvar); more than 64 bits of it is a failure.
  uint64_t uvar() {
    uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      uint64_t b = get(1);
      if (failed_) return 0;
      v |= (b & 0x7F) << shift;
      if (!(b & 0x80)) return (shift == 63 && b > 1) ? fail() : v;
    }
    return fail();
  }
  // Past `count` LEB128 numbers, unread (bytes known to hold them: a failure at the end).
  void skip_varints(uint64_t count) {
    for (; count > 0 && pos_ < data_.size(); ++pos_)
      if (!(static_cast<uint8_t>(data_[pos_]) & 0x80)) --count;
    if (count > 0) fail();
  }
  int64_t svar() {
    uint64_t v = uvar();
    return static_cast<int64_t>(v >> 1) ^ -static_cast<int64_t>(v & 1);
  }
  // A 32-bit field written as a uvar, or as an svar from `base`; a value outside 32
  // bits clears `ok`.
  uint32_t var32(bool& ok) {
    uint64_t v = uvar();
    if (v > UINT32_MAX) ok = false;
    return static_cast<uint32_t>(v);
  }
  uint32_t delta32(uint32_t base, bool& ok) {
    int64_t d = svar();
    if (d < -int64_t(base) || d > int64_t(UINT32_MAX - base)) {
      ok = false;  // and no sum: base + d may not fit in 64 bits either
      return 0;
    }
    return static_cast<uint32_t>(base + d);
  }
  bool failed() const { return failed_; }
  bool at_end() const { return pos_ == data_.size(); }
  size_t pos() const { return pos_; }
  size_t remaining() const { return data_.size() - pos_; }
  std::string_view data() const { return data_; }

 private:
  uint64_t get(int n) {
    if (static_cast<size_t>(n) > data_.size() - pos_) return fail();
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<uint64_t>(static_cast<uint8_t>(data_[pos_ + i])) << (8 * i);
    pos_ += n;
    return v;
  }
  uint64_t fail() {
    failed_ = true;
    pos_ = data_.size();
    return 0;
  }
  std::string_view data_;
  size_t pos_ = 0;
  bool failed_ = false;
};

}  // namespace ncc
