#include "files.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "devices/asset_store.h"
#include "support/diagnostics.h"
#include "support/source.h"

namespace ncc {

const char* const kFilesUsage = R"(usage: ncc files COMMAND DIR [...]

The ASSET sandbox of NC-110 file I/O (docs/asset.md): a directory with one folder a
device, MP0..MP6. A file is NAME/MPn (NAME: one to six capitals and digits, a letter
first; without /MPn, MP1).

commands:
  init DIR                          make DIR and its device folders
  create DIR NAME FIELDS RECORDS    a new file: FIELDS like IN,CH,LR,3CH (IN RE LR kCH),
                                    RECORDS 1..32767; numbers 0, characters blanks
  load DIR TEXT...                  the files a text gives (the form dump prints), made
                                    or replaced; records it does not list are blank
  dump DIR [NAME...]                the files as text (without names, every file)
  check DIR                         every file well formed, or which are not
  protect DIR NAME / unprotect DIR NAME
                                    set or clear the file's write protection

exit status: 0 success, 1 a text or file has errors, 2 usage or I/O errors
)";

namespace {

constexpr int kOk = 0, kErrors = 1, kUsage = 2;

using asset::Code;
using asset::File;
using asset::FileName;

// ---- The text form (docs/asset.md, "As text") ----------------------------------------

std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\')
      out += fmt::format("\\{}", c);
    else if (u < 0x20 || u > 0x7E)
      out += fmt::format("\\x{:02X}", u);
    else
      out += c;
  }
  return out + "\"";
}

std::string value_text(const File& f, uint32_t record, size_t field) {
  switch (f.layout[field].type) {
    case asset::FieldType::Chars: return quoted(asset::chars(f, record, field));
    case asset::FieldType::Real: return fmt::format("{}", static_cast<float>(asset::number(f, record, field)));
    default: return fmt::format("{}", asset::number(f, record, field));
  }
}

std::string file_text(const FileName& name, const File& f) {
  std::string out = "file " + name.text();
  for (const asset::Field& field : f.layout) out += " " + asset::field_text(field);
  out += fmt::format(" records {}{}\n", f.records, f.write_protected ? " protected" : "");
  for (uint32_t r = 1; r <= f.records; ++r) {
    out += std::to_string(r);
    for (size_t i = 0; i < f.layout.size(); ++i) out += "\t" + value_text(f, r, i);
    out += "\n";
  }
  return out;
}

// Reads a text of files, reporting each problem at its place.
class TextReader {
 public:
  TextReader(const SourceFile& text, uint32_t id, Diagnostics& diags) : text_(text), id_(id), diags_(diags) {}

  std::vector<std::pair<FileName, File>> read() {
    for (line_ = 1; line_ <= text_.line_count(); ++line_) {
      std::string_view line = text_.line(line_);
      tokens_.clear();
      if (!split(line) || tokens_.empty() || tokens_[0].text.starts_with('#')) continue;
      if (tokens_[0].text == "file")
        header();
      else if (files_.empty())
        error(tokens_[0], "a record before any 'file NAME FIELDS... records N' line");
      else
        record();
    }
    return std::move(files_);
  }

 private:
  struct Token {
    std::string text;  // a string without its quotes, escapes read
    bool quoted = false;
    uint32_t col = 0, end = 0;  // 1-based, end exclusive
  };

  void error(const Token& t, const std::string& what) {
    diags_.report(DiagId::AssetText, {id_, line_, t.col, line_, t.end}, what);
  }

  bool split(std::string_view line) {
    size_t i = 0;
    while (i < line.size()) {
      if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
        ++i;
        continue;
      }
      Token t;
      t.col = static_cast<uint32_t>(i + 1);
      if (line[i] != '"') {
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') t.text += line[i++];
      } else {
        t.quoted = true;
        ++i;
        bool closed = false;
        while (i < line.size() && !closed) {
          char c = line[i++];
          if (c == '"') {
            closed = true;
          } else if (c != '\\') {
            t.text += c;
          } else if (i < line.size() && (line[i] == '"' || line[i] == '\\')) {
            t.text += line[i++];
          } else if (i + 2 < line.size() && line[i] == 'x' && hex(line[i + 1]) >= 0 && hex(line[i + 2]) >= 0) {
            t.text += static_cast<char>(hex(line[i + 1]) * 16 + hex(line[i + 2]));
            i += 3;
          } else {
            t.end = static_cast<uint32_t>(i + 1);
            error(t, "a '\\' in a string stands before '\"', '\\' or xNN (two hex digits)");
            return false;
          }
        }
        if (!closed) {
          t.end = static_cast<uint32_t>(line.size() + 1);
          error(t, "the string is not closed by '\"'");
          return false;
        }
      }
      t.end = static_cast<uint32_t>(i + 1);
      tokens_.push_back(std::move(t));
    }
    return true;
  }

  // file NAME FIELD... records N [protected]
  void header() {
    auto records_at = std::find_if(tokens_.begin(), tokens_.end(), [](const Token& t) { return t.text == "records"; });
    if (tokens_.size() < 2 || records_at == tokens_.end() || records_at + 1 == tokens_.end() ||
        records_at - tokens_.begin() < 3) {
      error(tokens_[0], "a file's line is 'file NAME FIELDS... records N', optionally 'protected' after");
      return;
    }
    auto name = asset::parse_file_name(tokens_[1].text, 1);
    if (!name)
      return error(
          tokens_[1],
          fmt::format(
              "'{}' is not a file name: one to six capitals and digits, a letter first, then /MP0../MP6 or nothing",
              tokens_[1].text));
    asset::Layout layout;
    for (auto t = tokens_.begin() + 2; t != records_at; ++t) {
      auto field = asset::parse_field(t->text);
      if (!field) return error(*t, fmt::format("'{}' is not a field: IN, RE, LR or kCH (k = 1..32)", t->text));
      layout.push_back(*field);
    }
    if (layout.size() > asset::kMaxFields)
      return error(*(records_at - 1),
                   fmt::format("{} fields: a record has at most {}", layout.size(), asset::kMaxFields));
    uint32_t records = 0;
    const Token& n = *(records_at + 1);
    if (!whole(n.text, records) || records < 1 || records > asset::kMaxRecords)
      return error(n, fmt::format("'{}' records: a file has 1 to {}", n.text, asset::kMaxRecords));
    bool protect = false;
    for (auto t = records_at + 2; t != tokens_.end(); ++t) {
      if (t->text != "protected" || protect)
        return error(*t, fmt::format("'{}' after the record count: only 'protected' may stand there", t->text));
      protect = true;
    }
    for (const auto& [other, f] : files_)
      if (other == *name) return error(tokens_[1], fmt::format("{} is given twice", name->text()));
    File f = asset::blank_file(layout, records);
    f.write_protected = protect;
    files_.push_back({*name, std::move(f)});
    seen_.assign(records + 1, false);
  }

  // N VALUE...
  void record() {
    File& f = files_.back().second;
    uint32_t r = 0;
    if (!whole(tokens_[0].text, r) || r < 1 || r > f.records)
      return error(tokens_[0], fmt::format("'{}' is not a record of {}: 1 to {}", tokens_[0].text,
                                           files_.back().first.text(), f.records));
    if (seen_[r]) return error(tokens_[0], fmt::format("record {} is given twice", r));
    seen_[r] = true;
    if (tokens_.size() - 1 != f.layout.size())
      return error(tokens_.back(), fmt::format("record {} has {} values; the file's records have {} fields", r,
                                               tokens_.size() - 1, f.layout.size()));
    for (size_t i = 0; i < f.layout.size(); ++i) {
      const Token& t = tokens_[i + 1];
      const asset::Field& field = f.layout[i];
      if (field.type == asset::FieldType::Chars) {
        if (!t.quoted || !asset::set_chars(f, r, i, t.text))
          error(t, fmt::format("field {} is {}: a string of at most {} character{} in quotes", i + 1,
                               asset::field_text(field), field.length, field.length == 1 ? "" : "s"));
        continue;
      }
      double v = 0;
      auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
      if (t.quoted || ec != std::errc() || end != t.text.data() + t.text.size() || !asset::set_number(f, r, i, v))
        error(t, fmt::format("field {} is {}: {}", i + 1, asset::field_text(field),
                             field.type == asset::FieldType::Integer ? "a whole number from -32768 to 32767"
                                                                     : "a finite number the format holds"));
    }
  }

  static int hex(char c) {
    return c >= '0' && c <= '9'   ? c - '0'
           : c >= 'A' && c <= 'F' ? c - 'A' + 10
           : c >= 'a' && c <= 'f' ? c - 'a' + 10
                                  : -1;
  }

  static bool whole(const std::string& s, uint32_t& v) {
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size();
  }

  const SourceFile& text_;
  uint32_t id_;
  Diagnostics& diags_;
  uint32_t line_ = 0;
  std::vector<Token> tokens_;
  std::vector<std::pair<FileName, File>> files_;
  std::vector<bool> seen_;  // the last file's records given so far
};

// ---- The commands ----------------------------------------------------------------------

class Files {
 public:
  int run(const std::vector<std::string>& args) {
    const std::string& command = args[0];
    const size_t operands = args.size() - 2;
    auto wants = [&](bool ok) {
      if (!ok) std::fprintf(stderr, "ncc files %s: error: wrong operands\n%s", command.c_str(), kFilesUsage);
      return ok;
    };
    if (command == "init") return wants(operands == 0) ? init(args[1]) : kUsage;
    if (!open(args[1])) return finish(kUsage);
    if (command == "create") return wants(operands == 3) ? create(args[2], args[3], args[4]) : kUsage;
    if (command == "load") return wants(operands >= 1) ? load({args.begin() + 2, args.end()}) : kUsage;
    if (command == "dump") return dump({args.begin() + 2, args.end()});
    if (command == "check") return wants(operands == 0) ? check() : kUsage;
    if (command == "protect" || command == "unprotect")
      return wants(operands == 1) ? protect(args[2], command == "protect") : kUsage;
    std::fprintf(stderr, "ncc files: error: unknown command '%s'\n%s", command.c_str(), kFilesUsage);
    return kUsage;
  }

 private:
  int init(const std::string& dir) {
    for (int d = -1; d < asset::kDevices; ++d) {
      const std::string path = d < 0 ? dir : fmt::format("{}/MP{}", dir, d);
      if (std::string why = folder_problem(path, d >= 0); !why.empty()) {
        diags_.report(DiagId::FileUnwritable, {}, path, why);
        return finish(kUsage);
      }
    }
    return finish(kOk);
  }

  // Why `path` cannot be a folder of the sandbox, made if it is missing ("" if it can).
  // A device's must not be a link: the store follows none (the device would not be
  // connected, code 15).
  static std::string folder_problem(const std::string& path, bool device) {
    if (::mkdir(path.c_str(), 0755) == 0) return "";
    if (errno != EEXIST) return std::strerror(errno);
    struct stat st;
    if ((device ? ::lstat(path.c_str(), &st) : ::stat(path.c_str(), &st)) != 0) return std::strerror(errno);
    if (S_ISLNK(st.st_mode)) return "it is a symbolic link, which the sandbox does not follow";
    return S_ISDIR(st.st_mode) ? "" : "it is not a directory";
  }

  bool open(const std::string& dir) {
    std::string why;
    store_ = asset::Store::open(dir, {.device_bytes = UINT64_MAX}, why);
    if (!store_) diags_.report(DiagId::FileUnreadable, {}, dir, why);
    return store_ != nullptr;
  }

  std::optional<FileName> name(const std::string& text) {
    auto n = asset::parse_file_name(text, 1);
    if (!n)
      diags_.report(DiagId::AssetFile, {}, text,
                    "not a file name: one to six capitals and digits, a letter first, then /MP0../MP6 or nothing");
    return n;
  }

  void report(const FileName& n, Code c) {
    diags_.report(DiagId::AssetFile, {}, n.text(),
                  fmt::format("{} (code {}){}", asset::meaning(c), static_cast<int>(c),
                              c == Code::Logical ? ": not a well-formed ASSET file, or a link (docs/asset.md)" : ""));
  }

  // A store's answer other than Ok, as an error; `usage` for what is not the file's fault.
  int failed(const FileName& n, Code c) {
    report(n, c);
    return finish(c == Code::Logical || c == Code::Exists || c == Code::NotFound || c == Code::Protected ? kErrors
                                                                                                         : kUsage);
  }

  int create(const std::string& name_text, const std::string& fields, const std::string& count) {
    auto n = name(name_text);
    if (!n) return finish(kErrors);
    asset::Layout layout;
    for (size_t at = 0; at <= fields.size();) {
      size_t comma = std::min(fields.find(',', at), fields.size());
      auto field = asset::parse_field(std::string_view(fields).substr(at, comma - at));
      if (!field) {
        diags_.report(DiagId::AssetFile, {}, n->text(),
                      fmt::format("'{}' is not a field: IN, RE, LR or kCH (k = 1..32)", fields.substr(at, comma - at)));
        return finish(kErrors);
      }
      layout.push_back(*field);
      at = comma + 1;
    }
    uint32_t records = 0;
    auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), records);
    if (layout.size() > asset::kMaxFields || ec != std::errc() || end != count.data() + count.size() || records < 1 ||
        records > asset::kMaxRecords) {
      diags_.report(
          DiagId::AssetFile, {}, n->text(),
          fmt::format("a file has 1 to {} fields and 1 to {} records", asset::kMaxFields, asset::kMaxRecords));
      return finish(kErrors);
    }
    Code c = store_->create(*n, asset::blank_file(layout, records));
    return c == Code::Ok ? finish(kOk) : failed(*n, c);
  }

  int load(const std::vector<std::string>& texts) {
    std::vector<std::pair<FileName, File>> files;
    for (const std::string& path : texts) {
      // The text of the largest files: 17.8 MB each, a byte up to four characters.
      constexpr FileLimit kFilesText{256 << 20, "a text of ASSET files"};
      auto bytes = read_file(path, kFilesText, diags_);
      if (!bytes) return finish(kUsage);
      const uint32_t id = sources_.add(path, std::move(*bytes));
      for (auto& f : TextReader(sources_.file(id), id, diags_).read()) files.push_back(std::move(f));
    }
    if (diags_.has_errors()) return finish(kErrors);  // all or nothing
    for (const auto& [n, f] : files) {
      Code c = store_->create(n, f);
      if (c == Code::Exists) c = store_->replace(n, f);
      if (c != Code::Ok) return failed(n, c);
    }
    return finish(kOk);
  }

  int dump(const std::vector<std::string>& names) {
    std::vector<FileName> which;
    for (const std::string& text : names)
      if (auto n = name(text)) which.push_back(*n);
    if (diags_.has_errors()) return finish(kErrors);
    if (names.empty())
      for (uint8_t d = 0; d < asset::kDevices; ++d)
        for (const FileName& n : store_->list(d)) which.push_back(n);
    // Every file it can read; each it cannot, reported (exit 1).
    for (const FileName& n : which) {
      File f;
      if (Code c = store_->load(n, f); c != Code::Ok)
        report(n, c);
      else
        std::fputs(file_text(n, f).c_str(), stdout);
    }
    return finish(kOk);
  }

  int check() {
    size_t files = 0;
    for (uint8_t d = 0; d < asset::kDevices; ++d)
      for (const FileName& n : store_->list(d)) {
        File f;
        ++files;
        if (Code c = store_->load(n, f); c != Code::Ok) report(n, c);
      }
    if (!diags_.has_errors()) std::printf("%zu file%s, all well formed\n", files, files == 1 ? "" : "s");
    return finish(kOk);
  }

  int protect(const std::string& name_text, bool on) {
    auto n = name(name_text);
    if (!n) return finish(kErrors);
    File f;
    Code c = store_->load(*n, f);
    if (c == Code::Ok) {
      f.write_protected = on;
      c = store_->replace(*n, f);
    }
    return c == Code::Ok ? finish(kOk) : failed(*n, c);
  }

  int finish(int status) {
    std::string text = format_all(diags_.all(), sources_, DiagFormat::Text);
    std::fputs(text.c_str(), stderr);
    return status == kOk && diags_.has_errors() ? kErrors : status;
  }

  SourceManager sources_;
  Diagnostics diags_{100};
  std::unique_ptr<asset::Store> store_;
};

}  // namespace

int files_command(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "-h" || args[0] == "--help")) {
    std::fputs(kFilesUsage, stdout);
    return kOk;
  }
  if (args.size() < 2) {
    std::fprintf(stderr, "ncc files: error: a command and a directory are needed\n%s", kFilesUsage);
    return kUsage;
  }
  return Files().run(args);
}

}  // namespace ncc
