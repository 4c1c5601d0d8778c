// Source files and positions shared by every stage.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncc {

// 1-based line and column (columns count bytes). A range may span lines (the pp
// dialect's blocks do). file indexes SourceManager's list.
struct SourceRange {
  uint32_t file = 0;
  uint32_t line = 0;
  uint32_t col = 0;
  uint32_t end_line = 0;
  uint32_t end_col = 0;  // exclusive

  bool valid() const { return line != 0; }
  static SourceRange point(uint32_t file, uint32_t line, uint32_t col) { return {file, line, col, line, col + 1}; }
};

class SourceFile {
 public:
  SourceFile(std::string path, std::string text);
  const std::string& path() const { return path_; }
  std::string_view text() const { return text_; }
  uint32_t line_count() const { return static_cast<uint32_t>(line_starts_.size()); }
  // The line's text without its end-of-line characters; empty when out of range.
  std::string_view line(uint32_t number) const;
  uint32_t line_offset(uint32_t number) const { return line_starts_[number - 1]; }

 private:
  std::string path_;
  std::string text_;
  std::vector<uint32_t> line_starts_;
};

// Owns every file a compilation or a run reads, so diagnostics can quote them. Files
// stay where they are as more are added (a front end reads the programs a program calls).
class SourceManager {
 public:
  // `text` holds at most kProgramFile.bytes (read_file's limit): positions are 32-bit.
  uint32_t add(std::string path, std::string text);
  const SourceFile& file(uint32_t index) const { return files_[index]; }
  size_t size() const { return files_.size(); }

 private:
  std::deque<SourceFile> files_;
};

class Diagnostics;

// The most bytes ncc reads of a kind of file, what the kind is (for the message) and
// whether it must be a regular file (never a device or a pipe, which could hang a read).
struct FileLimit {
  uint64_t bytes;
  std::string_view what;
  bool regular_only = false;
};
// A program or bytecode file: every position in it, and one past its end, is a 32-bit
// number (line starts, columns, lengths, code offsets).
inline constexpr FileLimit kProgramFile{UINT32_MAX - 1, "a program file (positions in it are 32-bit)"};

// The bytes of the file at `path`, read straight into one string (a pipe or a device
// too, piece by piece). Nothing if it cannot be read, and why in `error`: EISDIR a
// directory, EFBIG more than `limit` bytes (a regular file's size is checked before it
// is read), EINVAL not a regular file where `limit` wants one, or the system's errno.
[[nodiscard]] std::optional<std::string> read_file(const std::string& path, const FileLimit& limit, int& error);
// Why read_file gave nothing, as a message says it: "it is a directory".
std::string read_error(int error, const FileLimit& limit);
// A program's text as its author sees it: the bytes of its file without the UTF-8
// byte-order mark (EF BB BF) that some editors write first and none shows, so that
// line 1's columns are the editor's.
std::string program_text(std::string bytes);

// read_file, reporting why not at `at` (NC6001).
[[nodiscard]] std::optional<std::string> read_file(const std::string& path, const FileLimit& limit, Diagnostics& diags,
                                                   SourceRange at = {});

}  // namespace ncc
