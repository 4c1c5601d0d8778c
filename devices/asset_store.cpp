#include "asset_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <dirent.h>
#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "support/bytes.h"

namespace ncc::asset {

namespace {

constexpr std::string_view kMagic = "NCAF";
constexpr uint16_t kVersion = 1;
constexpr size_t kHeader = 24;
constexpr std::string_view kSuffix = ".nca";
// The bytes of a file: its header, its layout, its records.
constexpr uint64_t file_bytes(uint64_t fields, uint64_t data) { return kHeader + 2 * fields + data; }
// The largest well-formed file: 17 fields of 32 characters in 32767 records.
constexpr uint64_t kMaxFileBytes = file_bytes(kMaxFields, uint64_t{kMaxRecords} * kMaxFields * kMaxChars);
static_assert(kMaxFileBytes == 17'825'306);

uint32_t crc_of(std::string_view s) { return crc32({reinterpret_cast<const uint8_t*>(s.data()), s.size()}); }

std::string device_name(uint8_t d) { return fmt::format("MP{}", d); }

// Closes a descriptor when it goes out of scope.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

bool write_all(int fd, std::string_view s) {
  while (!s.empty()) {
    ssize_t n = ::write(fd, s.data(), s.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    s.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

Code code_of_errno(int e) { return e == ENOSPC || e == EDQUOT ? Code::Overflow : Code::Hardware; }

}  // namespace

std::string field_text(const Field& f) {
  switch (f.type) {
    case FieldType::Integer: return "IN";
    case FieldType::Real: return "RE";
    case FieldType::LongReal: return "LR";
    case FieldType::Chars: return f.length == 1 ? "CH" : fmt::format("{}CH", f.length);  // the manual's .CH
  }
  return "?";
}

std::optional<Field> parse_field(std::string_view text) {
  if (text == "IN") return Field{FieldType::Integer, 2};
  if (text == "RE") return Field{FieldType::Real, 4};
  if (text == "LR") return Field{FieldType::LongReal, 8};
  if (!text.ends_with("CH")) return std::nullopt;
  text.remove_suffix(2);
  unsigned n = 1;  // "CH" is one character
  if (!text.empty()) {
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  }
  if (n < 1 || n > kMaxChars) return std::nullopt;
  return Field{FieldType::Chars, static_cast<uint8_t>(n)};
}

bool well_formed(const Layout& layout) {
  if (layout.empty() || layout.size() > kMaxFields) return false;
  return std::all_of(layout.begin(), layout.end(), [](const Field& f) {
    switch (f.type) {
      case FieldType::Integer: return f.length == 2;
      case FieldType::Real: return f.length == 4;
      case FieldType::LongReal: return f.length == 8;
      case FieldType::Chars: return f.length >= 1 && f.length <= kMaxChars;
    }
    return false;
  });
}

size_t record_length(const Layout& layout) {
  size_t n = 0;
  for (const Field& f : layout) n += f.length;
  return n;
}

File blank_file(const Layout& layout, uint32_t records) {
  File f;
  f.layout = layout;
  f.records = records;
  std::string record;
  for (const Field& field : layout) record.append(field.length, field.type == FieldType::Chars ? ' ' : '\0');
  f.data.reserve(record.size() * records);
  for (uint32_t i = 0; i < records; ++i) f.data += record;
  return f;
}

namespace {

size_t field_offset(const File& f, uint32_t record, size_t field) {
  size_t at = size_t{record - 1} * record_length(f.layout);
  for (size_t i = 0; i < field; ++i) at += f.layout[i].length;
  return at;
}

}  // namespace

double number(const File& f, uint32_t record, size_t field) {
  ByteReader r(std::string_view(f.data).substr(field_offset(f, record, field), f.layout[field].length));
  switch (f.layout[field].type) {
    case FieldType::Integer: return static_cast<int16_t>(r.u16());
    case FieldType::Real: return std::bit_cast<float>(r.u32());
    case FieldType::LongReal: return r.f64();
    case FieldType::Chars: break;
  }
  return 0;
}

std::string_view chars(const File& f, uint32_t record, size_t field) {
  return std::string_view(f.data).substr(field_offset(f, record, field), f.layout[field].length);
}

bool set_number(File& f, uint32_t record, size_t field, double value) {
  ByteWriter w;
  switch (f.layout[field].type) {
    case FieldType::Integer:
      if (value != std::trunc(value) || value < -32768 || value > 32767) return false;
      w.u16(static_cast<uint16_t>(static_cast<int16_t>(value)));
      break;
    case FieldType::Real: {
      // Beyond FLT_MAX and half its last step the nearest binary32 is infinite; below
      // that it is FLT_MAX, which the clamp gives without converting a value a float
      // cannot hold.
      constexpr double kMax = std::numeric_limits<float>::max();
      if (!(std::fabs(value) < kMax + 0x1p103)) return false;
      w.u32(std::bit_cast<uint32_t>(static_cast<float>(std::clamp(value, -kMax, kMax))));
      break;
    }
    case FieldType::LongReal:
      if (!std::isfinite(value)) return false;
      w.f64(value);
      break;
    case FieldType::Chars: return false;
  }
  f.data.replace(field_offset(f, record, field), w.data().size(), w.data());
  return true;
}

bool set_chars(File& f, uint32_t record, size_t field, std::string_view text) {
  const Field& at = f.layout[field];
  if (at.type != FieldType::Chars || text.size() > at.length) return false;
  std::string cell(text);
  cell.resize(at.length, ' ');
  f.data.replace(field_offset(f, record, field), cell.size(), cell);
  return true;
}

// docs/asset.md, "The file".
std::string encode(const File& f) {
  ByteWriter body;
  for (const Field& field : f.layout) {
    body.u8(static_cast<uint8_t>(field.type));
    body.u8(field.length);
  }
  body.bytes(f.data);
  ByteWriter head;
  head.bytes(kMagic);
  head.u16(kVersion);
  head.u16(f.write_protected ? 1 : 0);
  head.u16(static_cast<uint16_t>(f.layout.size()));
  head.u16(static_cast<uint16_t>(record_length(f.layout)));
  head.u32(f.records);
  head.u32(crc_of(body.data()));
  head.u32(crc_of(head.data()));
  return head.data() + body.data();
}

Code decode(std::string_view bytes, File& f) {
  ByteReader r(bytes);
  if (r.bytes(kMagic.size()) != kMagic || r.u16() != kVersion) return Code::Logical;
  const uint16_t flags = r.u16();
  const uint16_t fields = r.u16();
  const uint16_t length = r.u16();
  const uint32_t records = r.u32();
  const uint32_t body_crc = r.u32();
  const uint32_t head_crc = r.u32();
  if (r.failed() || head_crc != crc_of(bytes.substr(0, kHeader - 4)) || (flags & ~1u) || fields == 0 ||
      fields > kMaxFields || records == 0 || records > kMaxRecords)
    return Code::Logical;
  if (bytes.size() != file_bytes(fields, uint64_t{records} * length) || body_crc != crc_of(bytes.substr(kHeader)))
    return Code::Logical;
  File out;
  out.write_protected = flags & 1;
  out.records = records;
  for (uint16_t i = 0; i < fields; ++i) {
    const uint8_t type = r.u8(), size = r.u8();
    out.layout.push_back({static_cast<FieldType>(type), size});
  }
  if (!well_formed(out.layout) || record_length(out.layout) != length) return Code::Logical;
  out.data = std::string(r.bytes(r.remaining()));
  f = std::move(out);
  return Code::Ok;
}

// ---- The sandbox --------------------------------------------------------------------

std::unique_ptr<Store> Store::open(const std::string& dir, const Options& options, std::string& why) {
  int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) {
    why = std::strerror(errno);
    return nullptr;
  }
  return std::unique_ptr<Store>(new Store(fd, options));
}

Store::Store(int dir, const Options& options) : dir_(dir), options_(options) {}
Store::~Store() { ::close(dir_); }

bool Store::prepared() const {
  for (uint8_t d = 0; d < kDevices; ++d)
    if (Fd dev{device(d)}; dev.fd >= 0) return true;
  return false;
}

int Store::device(uint8_t d) const {
  if (d >= kDevices) return -1;
  return ::openat(dir_, device_name(d).c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
}

Code Store::load(const FileName& name, File& f) const {
  if (!parse_file_name(name.text(), name.device)) return Code::NotFound;
  Fd dev{device(name.device)};
  if (dev.fd < 0) return Code::BadDevice;
  // O_NONBLOCK: a FIFO in the sandbox must not hang the run (it is refused below).
  Fd file{::openat(dev.fd, (name.name + std::string(kSuffix)).c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) return errno == ENOENT ? Code::NotFound : errno == ELOOP ? Code::Logical : Code::Hardware;
  struct stat st;
  if (::fstat(file.fd, &st) != 0) return Code::Hardware;
  // No larger file is well formed: its size is not memory to give it.
  if (!S_ISREG(st.st_mode) || static_cast<uint64_t>(st.st_size) > kMaxFileBytes) return Code::Logical;
  std::string bytes(static_cast<size_t>(st.st_size), '\0');
  size_t got = 0;
  while (got < bytes.size()) {
    ssize_t n = ::read(file.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return Code::Hardware;
    if (n == 0) break;
    got += static_cast<size_t>(n);
  }
  bytes.resize(got);
  return decode(bytes, f);
}

Code Store::create(const FileName& name, const File& f) { return write(name, f, true); }

Code Store::replace(const FileName& name, const File& f) { return write(name, f, false); }

// The new contents go whole into a temporary file beside the old one, which is synced
// and then takes the old one's place (rename is atomic; a fresh file is linked, which
// fails rather than replace one that exists), and the folder is synced: a file is the
// old one or the new one whenever the process dies.
Code Store::write(const FileName& name, const File& f, bool fresh) {
  if (!parse_file_name(name.text(), name.device) || !well_formed(f.layout) || f.records == 0 ||
      f.records > kMaxRecords || f.data.size() != f.records * record_length(f.layout))
    return Code::Illegal;
  Fd dev{device(name.device)};
  if (dev.fd < 0) return Code::BadDevice;
  const std::string final_name = name.name + std::string(kSuffix);
  struct stat old;
  const bool exists = ::fstatat(dev.fd, final_name.c_str(), &old, AT_SYMLINK_NOFOLLOW) == 0;
  if (fresh && exists) return Code::Exists;
  if (!fresh && !exists) return Code::NotFound;
  if (exists && !S_ISREG(old.st_mode)) return Code::Logical;
  // The device's room: its other files and this one (a file that does not grow, as a
  // WRT's, takes no more: the folder is not listed for it).
  const uint64_t size = file_bytes(f.layout.size(), f.data.size());
  if (!exists || size > static_cast<uint64_t>(old.st_size)) {
    uint64_t used = size;
    for (const FileName& other : list(name.device)) {
      struct stat st;
      if (other.name != name.name &&
          ::fstatat(dev.fd, (other.name + std::string(kSuffix)).c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0)
        used += static_cast<uint64_t>(st.st_size);
    }
    if (used > options_.device_bytes) return Code::Overflow;
  }

  const std::string bytes = encode(f);
  const std::string temp = "." + final_name + ".tmp";
  ::unlinkat(dev.fd, temp.c_str(), 0);  // left by a run that died
  Fd out{::openat(dev.fd, temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644)};
  if (out.fd < 0) return code_of_errno(errno);
  if (!write_all(out.fd, bytes) || ::fsync(out.fd) != 0) {
    Code c = code_of_errno(errno);
    ::unlinkat(dev.fd, temp.c_str(), 0);
    return c;
  }
  int placed = fresh ? ::linkat(dev.fd, temp.c_str(), dev.fd, final_name.c_str(), 0)
                     : ::renameat(dev.fd, temp.c_str(), dev.fd, final_name.c_str());
  if (placed != 0) {
    Code c = errno == EEXIST ? Code::Exists : code_of_errno(errno);
    ::unlinkat(dev.fd, temp.c_str(), 0);
    return c;
  }
  if (fresh) ::unlinkat(dev.fd, temp.c_str(), 0);
  return ::fsync(dev.fd) == 0 ? Code::Ok : Code::Hardware;
}

Code Store::remove(const FileName& name) {
  if (!parse_file_name(name.text(), name.device)) return Code::NotFound;
  Fd dev{device(name.device)};
  if (dev.fd < 0) return Code::BadDevice;
  const std::string final_name = name.name + std::string(kSuffix);
  struct stat st;
  if (::fstatat(dev.fd, final_name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) return Code::NotFound;
  if (!S_ISREG(st.st_mode)) return Code::Logical;
  if (::unlinkat(dev.fd, final_name.c_str(), 0) != 0) return Code::Hardware;
  return ::fsync(dev.fd) == 0 ? Code::Ok : Code::Hardware;
}

std::vector<FileName> Store::list(uint8_t d) const {
  std::vector<FileName> files;
  int fd = device(d);
  if (fd < 0) return files;
  DIR* dir = ::fdopendir(fd);
  if (!dir) {
    ::close(fd);
    return files;
  }
  while (dirent* e = ::readdir(dir)) {
    std::string_view entry = e->d_name;
    if (!entry.ends_with(kSuffix)) continue;
    entry.remove_suffix(kSuffix.size());
    if (auto name = parse_file_name(entry, d)) files.push_back(*name);
  }
  ::closedir(dir);
  std::sort(files.begin(), files.end(), [](const FileName& a, const FileName& b) { return a.name < b.name; });
  return files;
}

}  // namespace ncc::asset
