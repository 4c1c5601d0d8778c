// iso front end: the main program file with its O subprograms and macros, and the O
// programs its M98 and G65 calls name that the file does not hold, each read once from
// the program library into one IR program.
#include "iso_frontend.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "frontend/limits.h"
#include "reader.h"

namespace ncc::iso {

namespace {

// The extensions a program file has (decision 72), compared in any case.
constexpr std::string_view kExtensions[] = {"", ".nc", ".ngc", ".tap", ".txt", ".cnc"};

std::string lower(std::string_view text) {
  std::string out(text);
  std::ranges::transform(out, out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// The O number a program file starts with (after '%', comment lines and blank
// lines, decision 51), read from its first 64 KiB; nothing if it starts otherwise.
std::optional<uint32_t> first_program_number(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(64 << 10, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  size_t i = 0;
  while (i < head.size()) {
    const char c = head[i];
    if (c == '(') {
      const size_t end = head.find(')', i);
      if (end == std::string::npos) return std::nullopt;
      i = end + 1;
    } else if (c == '%' || c == ';' || std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else {
      break;
    }
  }
  if (i >= head.size() || (head[i] != 'O' && head[i] != 'o')) return std::nullopt;
  size_t end = ++i;
  while (end < head.size() && end - i < 9 && std::isdigit(static_cast<unsigned char>(head[end]))) ++end;
  if (end == i) return std::nullopt;
  return static_cast<uint32_t>(std::stoul(head.substr(i, end - i)));
}

// The library folder's program files (decision 72), sorted by name: a call finds
// O3001 in `O3001.nc`, `o3001.NC`, `3001.nc` or `O3001`, else in the one file that
// starts with O3001 (`gauge_tool_o3001.cnc`).
class Library {
 public:
  explicit Library(std::string root) : root_(std::move(root)) {}

  struct Found {
    std::vector<std::string> files;  // none: not found; two or more: ambiguous
  };

  Found find(const std::string& name) {
    list();
    // By name: O<n>, o<n>, <n> (and without the zero padding), an extension of the list.
    const std::string digits = name.substr(1);
    std::string bare = digits.substr(std::min(digits.find_first_not_of('0'), digits.size() - 1));
    const std::string stems[] = {"o" + digits, digits, "o" + bare, bare};
    for (const std::string& stem : stems)
      for (std::string_view ext : kExtensions)
        for (const std::string& f : files_)
          if (lower(f) == stem + std::string(ext)) return {{f}};
    // By content: the files whose first O number is the one called.
    scan();
    auto [from, to] = numbered_.equal_range(static_cast<uint32_t>(std::stoul(digits)));
    Found found;
    for (auto it = from; it != to; ++it) found.files.push_back(it->second);
    return found;
  }

 private:
  void list() {
    if (listed_) return;
    listed_ = true;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(root_.empty() ? "." : root_, ec)) {
      const std::string file = e.path().filename().string();
      const std::string ext = lower(e.path().extension().string());
      if (e.is_regular_file(ec) && std::ranges::find(kExtensions, ext) != std::end(kExtensions)) files_.push_back(file);
    }
    std::ranges::sort(files_);
  }
  void scan() {
    if (scanned_) return;
    scanned_ = true;
    for (const std::string& f : files_)
      if (auto n = first_program_number(std::filesystem::path(root_.empty() ? "." : root_) / f))
        numbered_.emplace(*n, f);
  }

  std::string root_;
  bool listed_ = false, scanned_ = false;
  std::vector<std::string> files_;
  std::multimap<uint32_t, std::string> numbered_;  // in name order for each number
};

class IsoFrontend final : public DialectFrontend<Settings> {
 public:
  explicit IsoFrontend(Settings settings) : DialectFrontend(std::move(settings)) {
    rules_.block_number_order = false;  // any order; GOTO finds its block by number
    rules_.recursion = true;            // a macro may call itself until a condition stops it
    rules_.absent_jump_runs = true;     // decision 73
    rules_.group_last_wins = true;      // decision 75
  }

  ir::Program read(SourceManager& sources, uint32_t file, Diagnostics& diags, const ReadOptions& options) override {
    ir::Program program = start_program("iso", file);
    // #0..#999 (decision 3): #1-#33 local to each macro call, all vacant at the start.
    VarSpace vars{"#",
                  1000,
                  {{0, VarType::LongReal},
                   {34, VarType::Unavailable},
                   {100, VarType::LongReal},
                   {200, VarType::Unavailable},
                   {500, VarType::LongReal}}};
    vars.locals = 34;
    vars.vacant = true;
    const auto space = static_cast<uint16_t>(program.spaces.size());
    program.spaces.push_back(vars);

    Reader main(s_, program, sources.file(file), file, diags, space, std::nullopt, options.fast_path, options.sink);
    if (admit_text(sources.file(file), file, diags)) main.run();
    std::deque<ProgramCall> pending(main.calls().begin(), main.calls().end());
    // Called programs the file does not hold: O<nnnn>[.nc] in the library (decision 12).
    const std::string root = library_root(options, s_.library, sources.file(file).path());
    std::set<std::string> known, missing;
    Library library(root);
    for (const ir::Unit& u : program.units) known.insert(u.name);
    while (!pending.empty() && !diags.limit_reached()) {
      ProgramCall call = pending.front();
      pending.pop_front();
      if (missing.count(call.name)) program.units[call.unit].blocks[call.block].has_errors = true;
      if (!known.insert(call.name).second) continue;
      const Library::Found found = library.find(call.name);
      std::optional<uint32_t> f;
      if (found.files.size() == 1)
        f = load_called_file(sources, root, found.files[0], {""}, call.name, call.range, diags);
      else if (found.files.empty())
        diags.report(DiagId::ProgramNotFound, call.range, call.name,
                     fmt::format("{}[.nc|.ngc|.tap|.txt|.cnc] (in any case, with or without the O), and no file "
                                 "there starts with {}",
                                 (std::filesystem::path(root) / call.name).string(), call.name));
      else
        diags.report(DiagId::ProgramAmbiguous, call.range, call.name, fmt::join(found.files, ", "),
                     root.empty() ? "." : root);
      if (!f) {
        program.units[call.unit].blocks[call.block].has_errors = true;
        missing.insert(call.name);
        continue;
      }
      program.files.push_back(*f);
      Reader called(s_, program, sources.file(*f), *f, diags, space, call.name, options.fast_path);
      called.run();
      for (const ProgramCall& c : called.calls()) pending.push_back(c);
    }
    set_power_on(program, s_.tables, s_.power_on);
    add_dynamic_codes(program, s_.tables, {"G65", "M97", "M98", "M99"});
    return program;
  }
};

}  // namespace

std::unique_ptr<Frontend> make_iso_frontend(const stdlib::Profile& profile, Diagnostics& diags) {
  return make_dialect_frontend<IsoFrontend>(load_settings(profile, diags));
}

}  // namespace ncc::iso
