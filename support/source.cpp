#include "source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "diagnostics.h"

namespace ncc {

SourceFile::SourceFile(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {
  line_starts_.push_back(0);
  for (size_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n' && i + 1 < text_.size()) line_starts_.push_back(static_cast<uint32_t>(i + 1));
}

std::string_view SourceFile::line(uint32_t number) const {
  if (number == 0 || number > line_starts_.size()) return {};
  size_t begin = line_starts_[number - 1];
  size_t end = text_.find('\n', begin);
  if (end == std::string::npos) end = text_.size();
  while (end > begin && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(begin, end - begin);
}

uint32_t SourceManager::add(std::string path, std::string text) {
  files_.emplace_back(std::move(path), std::move(text));
  return static_cast<uint32_t>(files_.size() - 1);
}

std::string program_text(std::string bytes) {
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.erase(0, 3);
  return bytes;
}

std::optional<std::string> read_file(const std::string& path, const FileLimit& limit, int& error) {
  // O_NONBLOCK: opening a FIFO does not wait for a writer before it is known to be one.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    error = errno;
    return std::nullopt;
  }
  struct stat st;
  error = 0;
  if (::fstat(fd, &st) != 0)
    error = errno;
  else if (S_ISDIR(st.st_mode))
    error = EISDIR;
  else if (S_ISREG(st.st_mode) && static_cast<uint64_t>(st.st_size) > limit.bytes)
    error = EFBIG;
  else if (!S_ISREG(st.st_mode) && limit.regular_only)
    error = EINVAL;
  else if (::fcntl(fd, F_SETFL, 0) != 0)
    error = errno;  // reads wait again
  std::string text;
  // A regular file's size is known: one allocation, read into; then whatever else
  // comes (a file that grew, a pipe) in pieces, up to one byte past the limit.
  if (!error && S_ISREG(st.st_mode)) text.resize(static_cast<size_t>(st.st_size));
  size_t have = 0;
  std::string piece;  // on the heap: an embedding controller's thread may have a small stack
  while (!error) {
    const bool room = have < text.size();
    if (!room) piece.resize(1 << 16);
    const ssize_t n =
        room ? ::read(fd, text.data() + have, text.size() - have) : ::read(fd, piece.data(), piece.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) error = errno;
    if (n <= 0) break;
    if (!room) text.append(piece.data(), static_cast<size_t>(n));
    have += static_cast<size_t>(n);
    if (have > limit.bytes) error = EFBIG;
  }
  ::close(fd);
  if (error) return std::nullopt;
  text.resize(have);
  return text;
}

std::string read_error(int error, const FileLimit& limit) {
  switch (error) {
    case EISDIR: return "it is a directory";
    case EFBIG: return fmt::format("it holds more than {} bytes, the most ncc reads of {}", limit.bytes, limit.what);
    case EINVAL: return "it is not a regular file";
    default: return std::strerror(error);
  }
}

std::optional<std::string> read_file(const std::string& path, const FileLimit& limit, Diagnostics& diags,
                                     SourceRange at) {
  int error = 0;
  auto text = read_file(path, limit, error);
  if (!text) diags.report(DiagId::FileUnreadable, at, path, read_error(error, limit));
  return text;
}

}  // namespace ncc
