#include "frontend.h"

#include <filesystem>

#include "limits.h"
#include "support/text.h"
#include "support/utf8.h"

#include "gost/gost_frontend.h"
#include "iso/iso_frontend.h"
#include "linuxcnc/linuxcnc_frontend.h"
#include "nc110/nc110_frontend.h"
#include "pp/pp_frontend.h"

namespace ncc {

namespace {
struct DialectEntry {
  std::string_view name;
  std::unique_ptr<Frontend> (*make)(const stdlib::Profile&, Diagnostics&);
};
constexpr DialectEntry kDialects[] = {
    {"gost", gost::make_gost_frontend}, {"nc110", nc110::make_nc110_frontend},          {"pp", pp::make_pp_frontend},
    {"iso", iso::make_iso_frontend},    {"linuxcnc", linuxcnc::make_linuxcnc_frontend},
};

// What a character nobody sees on screen is, so that a message names it rather than
// printing it: they come from text pasted out of web pages and word processors.
std::string_view invisible(uint32_t code_point) {
  switch (code_point) {
    case 0x00A0: return "a no-break space";
    case 0x00AD: return "a soft hyphen";
    case 0x202F: return "a narrow no-break space";
    case 0x2028: return "a line separator";
    case 0x2029: return "a paragraph separator";
    case 0x3000: return "an ideographic space";
    case 0xFEFF: return "a byte-order mark";
  }
  if (code_point >= 0x2000 && code_point <= 0x200A) return "a typographic space";
  if ((code_point >= 0x200B && code_point <= 0x200F) || (code_point >= 0x2060 && code_point <= 0x2064))
    return "an invisible formatting character";
  return {};
}

}  // namespace

std::optional<std::string> read_called_file(const std::string& path, Diagnostics& diags, SourceRange at,
                                            bool& reported) {
  constexpr FileLimit kCalledProgram{256 << 20, "a called program (its IR is held whole)", true};
  int error = 0;
  auto text = read_file(path, kCalledProgram, error);
  // A folder or a device of that name is no program file: the next name is tried.
  if (!text && error != ENOENT && error != EISDIR && error != EINVAL) {
    diags.report(DiagId::FileUnreadable, at, path, read_error(error, kCalledProgram));
    reported = true;
  }
  if (text) *text = program_text(std::move(*text));
  return text;
}

std::string library_root(const ReadOptions& options, const std::string& setting, const std::string& caller) {
  namespace fs = std::filesystem;
  fs::path root = !options.library.empty() ? fs::path(options.library)
                  : !setting.empty()       ? fs::path(setting)
                                           : fs::path(caller).parent_path();
  return root.lexically_normal().string();
}

std::optional<uint32_t> load_called_file(SourceManager& sources, const std::string& root, const std::string& name,
                                         std::initializer_list<std::string_view> extensions, const std::string& shown,
                                         SourceRange at, Diagnostics& diags) {
  const std::filesystem::path base = std::filesystem::path(root) / name;
  std::string tried;
  bool reported = false;
  for (std::string_view ext : extensions) {
    const std::string path = base.string() + std::string(ext);
    if (auto text = read_called_file(path, diags, at, reported)) {
      const uint32_t file = sources.add(path, std::move(*text));
      if (!admit_text(sources.file(file), file, diags)) return std::nullopt;
      return file;
    }
    if (reported) return std::nullopt;
    if (!ext.empty()) tried += (tried.empty() ? "" : "|") + std::string(ext);
  }
  diags.report(DiagId::ProgramNotFound, at, shown, base.string() + (tried.empty() ? "" : "[" + tried + "]"));
  return std::nullopt;
}

std::string describe_char(std::string_view text, size_t at, size_t& length) {
  length = 1;
  unsigned char c = static_cast<unsigned char>(text[at]);
  if (c >= 'a' && c <= 'z') return fmt::format("lower-case '{}'", static_cast<char>(c));
  if (c >= 0x20 && c < 0x7F) return fmt::format("'{}'", static_cast<char>(c));
  if (c < 0x80) return fmt::format("0x{:02X} (a control character)", c);
  if (const Utf8Char u = decode_utf8(text, at); u.length) {
    length = u.length;
    if (std::string_view what = invisible(u.code_point); !what.empty())
      return fmt::format("U+{:04X} ({})", u.code_point, what);
    return fmt::format("'{}' (U+{:04X})", text.substr(at, u.length), u.code_point);
  }
  return fmt::format("0x{:02X} (not UTF-8)", c);  // (admit_text lets none through)
}

std::optional<double> read_number(std::string_view written, SourceRange at, Diagnostics& diags) {
  if (auto v = parse_number<double>(written)) return v;
  diags.report(DiagId::NumberOutOfRange, at, abbreviated(written));
  return std::nullopt;
}

int32_t program_code(ir::Program& program, const CodeDesc& desc) {
  auto& codes = program.semantics.codes;
  for (size_t i = 0; i < codes.size(); ++i)
    if (codes[i].name == desc.name && codes[i].calls == desc.calls) return static_cast<int32_t>(i);
  codes.push_back(desc);
  return static_cast<int32_t>(codes.size() - 1);
}

void set_power_on(ir::Program& program, const stdlib::DialectTables& tables, const std::vector<std::string>& tokens) {
  for (const std::string& token : tokens) {
    CodeDesc desc;
    if (token.size() > 1 && (token[0] == 'G' || token[0] == 'M') &&
        std::isdigit(static_cast<unsigned char>(token[1]))) {
      const auto& codes = token[0] == 'G' ? tables.g_codes : tables.m_codes;
      auto number = parse_number<int>(std::string_view(token).substr(1));
      auto it = number ? codes.find(*number) : codes.end();
      if (it == codes.end()) continue;
      desc = it->second.desc;
    } else {
      desc.name = token;
      std::string error;  // reported when the table was read (stdlib/tables.cpp)
      if (!stdlib::parse_functions(token, tables.cycles, desc.calls, error)) continue;
    }
    program.semantics.power_on.push_back(static_cast<uint16_t>(program_code(program, desc)));
  }
}

void add_dynamic_codes(ir::Program& program, const stdlib::DialectTables& tables, const std::set<std::string>& fixed) {
  std::set<char> letters;
  for (const ir::Unit& u : program.units)
    for (const ir::Block& b : u.blocks)
      for (const ir::Word& w : b.words)
        if (w.kind == ir::WordKind::Code && w.code == ir::kDynamicCode) letters.insert(w.address[0]);
  auto& sem = program.semantics;
  std::map<int, uint16_t> g_index;
  std::map<std::string, std::vector<uint16_t>> groups;  // G group -> its codes (no matrix)
  std::map<std::string, std::vector<uint16_t>> sets;    // M conflict set -> its codes
  for (char letter : letters)
    for (const auto& [number, entry] : letter == 'G' ? tables.g_codes : tables.m_codes) {
      if (fixed.count(entry.desc.name)) continue;
      auto index = static_cast<uint16_t>(program_code(program, entry.desc));
      sem.numbered.push_back({static_cast<uint8_t>(letter_slot(letter)), static_cast<uint16_t>(number), index});
      if (letter == 'G') g_index[number] = index;
      if (letter == 'G' && tables.incompatible.empty() && entry.group != "-") groups[entry.group].push_back(index);
      for (const std::string& set : entry.conflict_sets) sets[set].push_back(index);
    }
  for (const auto& [a, b] : tables.incompatible)
    if (g_index.count(a) && g_index.count(b)) sem.incompatible.push_back({g_index[a], g_index[b], ""});
  auto pairs = [&](const std::map<std::string, std::vector<uint16_t>>& of, bool named) {
    for (const auto& [name, codes] : of)
      for (uint16_t a : codes)
        for (uint16_t b : codes)
          if (a != b) sem.incompatible.push_back({a, b, named ? name : ""});
  };
  pairs(groups, false);
  pairs(sets, true);
}

std::vector<std::string_view> dialect_names() {
  std::vector<std::string_view> names;
  for (const DialectEntry& d : kDialects) names.push_back(d.name);
  return names;
}

std::unique_ptr<Frontend> make_frontend(std::string_view dialect, const stdlib::Profile& profile, Diagnostics& diags) {
  for (const DialectEntry& d : kDialects)
    if (d.name == dialect) return d.make(profile, diags);
  std::string known;
  for (const DialectEntry& d : kDialects) known += (known.empty() ? "" : ", ") + std::string(d.name);
  diags.report(DiagId::DialectUnknown, {}, fmt::format("unknown dialect '{}' (known: {})", dialect, known));
  return nullptr;
}

bool read_machine_codes(const stdlib::Profile& p, std::string_view section, std::string_view letters,
                        stdlib::DialectTables& tables, Diagnostics& diags) {
  bool ok = true;
  for (char letter : letters) {
    const std::string key = fmt::format("{}.tables.{}_codes", section, letter == 'G' ? 'g' : 'm');
    auto file = p.string(key, diags);
    if (!file || file->empty()) continue;
    std::string path;
    auto text = p.file_text(key, *file, path, diags);
    if (!text) {
      ok = false;
      continue;
    }
    size_t errors = diags.error_count();
    auto table = stdlib::parse_table(path, *text, letter == 'G' ? 5 : 6, diags);
    stdlib::read_code_table(table, letter, tables.cycles, letter == 'G' ? tables.g_codes : tables.m_codes, diags);
    ok &= diags.error_count() == errors;
  }
  return ok;
}

}  // namespace ncc
