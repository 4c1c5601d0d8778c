#include "tables.h"

#include "contract/machine_config.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <mutex>

#include "embedded.h"
#include "support/text.h"

namespace ncc::stdlib {

std::optional<std::string_view> embedded_file(std::string_view path) {
  for (const EmbeddedFile& f : embedded_files())
    if (f.path == path) return f.text;
  return std::nullopt;
}

namespace {

bool split_row(std::string_view line, std::vector<std::string>& cells, std::string& error) {
  size_t i = 0;
  while (i < line.size()) {
    char c = line[i];
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (c == '#') {
      break;
    } else if (c == '"') {
      size_t close = line.find('"', i + 1);
      if (close == std::string_view::npos) {
        error = "unterminated quoted text";
        return false;
      }
      cells.emplace_back(line.substr(i + 1, close - i - 1));
      i = close + 1;
    } else {
      size_t end = line.find_first_of(" \t\r#", i);
      if (end == std::string_view::npos) end = line.size();
      cells.emplace_back(line.substr(i, end - i));
      i = end;
    }
  }
  return true;
}

template <typename E>
bool pick(std::string_view cell, std::initializer_list<std::pair<std::string_view, E>> choices, E& out) {
  for (const auto& [name, value] : choices)
    if (cell == name) {
      out = value;
      return true;
    }
  return false;
}

void read_addresses(const Table& table, std::map<char, AddressEntry>& out, Diagnostics& diags) {
  // letter class repeat order [range params] meaning
  for (const TableRow& row : table.rows) {
    const auto& c = row.cells;
    AddressEntry a;
    a.letter = c[0].size() == 1 ? c[0][0] : 0;
    bool ok =
        (a.letter >= 'A' && a.letter <= 'Z') || (a.letter >= 'a' && a.letter <= 'z') || a.letter == '&';  // pp's link
    ok = ok && pick(c[1],
                    {{"dimension", WordClass::Dimension},
                     {"angular", WordClass::Angular},
                     {"interpolation", WordClass::Interpolation},
                     {"feed", WordClass::Feed},
                     {"nondimension", WordClass::NonDimension},
                     {"undefined", WordClass::Undefined},
                     {"element", WordClass::Element},
                     {"factor", WordClass::Factor}},
                    a.word_class);
    std::string_view repeat = c[2];
    if (repeat.starts_with("several(") && repeat.ends_with(")")) {
      auto n = parse_number<int>(repeat.substr(8, repeat.size() - 9));
      ok = ok && n && *n > 0;
      a.max_count = n.value_or(0);
      repeat = "several";
    }
    ok = ok && pick(repeat,
                    {{"once", Repeat::Once},
                     {"group", Repeat::Group},
                     {"several", Repeat::Several},
                     {"feed", Repeat::Feed},
                     {"twice", Repeat::Twice}},
                    a.repeat);
    auto order = parse_number<int>(c[3]);
    ok = ok && order && (c.size() == 5 || c.size() == 7);
    if (ok && c.size() == 7) {
      if (c[4] != "-") {
        size_t dots = c[4].find("..");
        std::string lo = c[4].substr(0, dots), hi = dots == std::string::npos ? "" : c[4].substr(dots + 2);
        auto min = parse_number<double>(lo), max = parse_number<double>(hi);
        ok = dots != std::string::npos && min && max && *min <= *max;
        a.ranged = true;
        a.min = min.value_or(0);
        a.max = max.value_or(0);
        size_t point = hi.find('.');
        a.decimals = point == std::string::npos ? 0 : static_cast<int>(hi.size() - point - 1);
      }
      if (c[5] != "-")
        for (const std::string& cls : split(c[5], ',')) {
          ok = ok && (cls == "BY" || cls == "IN" || cls == "LI" || cls == "RE" || cls == "LR" || cls == "R");
          a.params.push_back(cls);
        }
    }
    if (!ok || !order) {
      report(diags, table, row.line, "malformed address row");
      continue;
    }
    a.order = *order;
    a.meaning = c.back();
    out[a.letter] = a;
  }
}

}  // namespace

void report(Diagnostics& diags, const Table& t, uint32_t line, std::string_view what) {
  diags.report(DiagId::TableSyntax, {}, fmt::format("{}:{}: {}", t.name, line, what));
}

Table parse_table(std::string name, std::string_view text, size_t columns, Diagnostics& diags, size_t max_columns) {
  if (max_columns < columns) max_columns = columns;
  Table table{std::move(name), {}};
  uint32_t line_no = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    ++line_no;
    TableRow row{{}, line_no};
    std::string error;
    if (!split_row(line, row.cells, error)) {
      report(diags, table, line_no, error);
    } else if (!row.cells.empty()) {
      if (row.cells.size() < columns || row.cells.size() > max_columns)
        report(diags, table, line_no,
               columns == max_columns
                   ? fmt::format("expected {} columns, found {}", columns, row.cells.size())
                   : fmt::format("expected {} to {} columns, found {}", columns, max_columns, row.cells.size()));
      else
        table.rows.push_back(std::move(row));
    }
    pos = end + 1;
  }
  return table;
}

std::optional<Table> load_table(std::string_view dialect, std::string_view file, size_t columns, Diagnostics& diags,
                                size_t max_columns) {
  std::string path = fmt::format("dialects/{}/{}", dialect, file);
  auto text = embedded_file(path);
  if (!text) {
    diags.report(DiagId::TableSyntax, {}, fmt::format("missing table {}", path));
    return std::nullopt;
  }
  return parse_table(path, *text, columns, diags, max_columns);
}

bool parse_functions(std::string_view text, const std::vector<CyclePattern>& cycles, std::vector<FnCall>& out,
                     std::string& error) {
  if (text == "-") return true;  // none: a code the front end reads, or a state the trace records
  for (const std::string& part : split(text, '+')) {
    std::string_view name = part;
    std::string_view arg;
    if (size_t open = name.find('('); open != std::string_view::npos) {
      if (name.back() != ')') {
        error = fmt::format("'{}' lacks its closing ')'", part);
        return false;
      }
      arg = name.substr(open + 1, name.size() - open - 2);
      name = name.substr(0, open);
    }
    auto fn = fn_by_name(name);
    if (!fn) {
      error = fmt::format("unknown function '{}'", name);
      return false;
    }
    FnCall call{*fn, 0};
    if (*fn == Fn::Cycle) {
      size_t i = 0;
      while (i < cycles.size() && cycles[i].name != arg) ++i;
      if (i == cycles.size()) {
        error = fmt::format("cycle '{}' is not in the cycle table", arg);
        return false;
      }
      call.arg = static_cast<uint16_t>(i);
    } else if (*fn == Fn::WorkOffset || *fn == Fn::SpindleRangeForce) {
      // Work offsets beyond 99: ISO's extended ones (kExtendedWorkOffset + P).
      const int hi = *fn == Fn::WorkOffset ? kExtendedWorkOffset + kExtendedWorkOffsets : 99;
      auto n = parse_number<int>(arg);
      if (!n || *n < 0 || *n > hi) {
        error = fmt::format("'{}' needs a number 0..{}, not '{}'", name, hi, arg);
        return false;
      }
      call.arg = static_cast<uint16_t>(*n);
    } else if (!arg.empty()) {
      error = fmt::format("function '{}' takes no argument", name);
      return false;
    }
    out.push_back(call);
  }
  return true;
}

void read_code_table(const Table& table, char letter, const std::vector<CyclePattern>& cycles,
                     std::map<int, CodeEntry>& codes, Diagnostics& diags) {
  // G tables: code group scope function name
  // M tables: code timing scope conflict function name
  bool m = letter == 'M';
  for (const TableRow& row : table.rows) {
    const auto& c = row.cells;
    CodeEntry e;
    e.letter = letter;
    // G01, or a decimal code with one digit after the point (G54.1): code_key.
    const std::string_view digits = c[0].size() > 1 && c[0][0] == letter ? std::string_view(c[0]).substr(1) : "";
    const size_t point = digits.find('.');
    const bool form = point == std::string_view::npos || point + 2 == digits.size();
    auto number = form ? parse_number<double>(digits) : std::nullopt;
    auto key = number ? code_key(*number) : std::nullopt;
    if (!key || (point != std::string_view::npos && *key < kDecimalCode)) {
      report(diags, table, row.line, fmt::format("'{}' is not a {} code", c[0], letter));
      continue;
    }
    e.number = *key;
    e.desc.name = c[0];
    size_t col = 1;
    if (m) {
      if (!pick(c[col++], {{"before", Timing::Before}, {"after", Timing::After}}, e.desc.timing)) {
        report(diags, table, row.line, fmt::format("timing '{}' must be before or after", c[1]));
        continue;
      }
    } else {
      e.group = c[col++];
    }
    if (!pick(c[col++], {{"modal", Scope::Modal}, {"block", Scope::Block}}, e.desc.scope)) {
      report(diags, table, row.line, fmt::format("scope '{}' must be modal or block", c[col - 1]));
      continue;
    }
    if (m && c[col++] != "-") {
      e.conflict_sets = split(c[col - 1], ',');
      for (std::string& set : e.conflict_sets) std::replace(set.begin(), set.end(), '_', ' ');  // "spindle range"
    }
    std::string error;
    if (!parse_functions(c[col++], cycles, e.desc.calls, error)) {
      report(diags, table, row.line, error);
      continue;
    }
    // A block-only code gives its groups back after the block; coolant and clamps
    // have no single state to give back.
    bool restorable = true;
    for (const FnCall& call : e.desc.calls) {
      FnGroup g = fn_group(call.fn);
      restorable =
          restorable && g != FnGroup::Mist && g != FnGroup::Flood && g != FnGroup::Clamp && g != FnGroup::RotaryClamp;
    }
    if (e.desc.scope == Scope::Block && !restorable) {
      report(diags, table, row.line, "a block-only code cannot switch coolant or clamps: use a modal code");
      continue;
    }
    e.meaning = c[col];
    codes[e.number] = std::move(e);
  }
}

void add_class_pairs(DialectTables& t) {
  t.incompatible = t.printed_incompatible;
  for (const auto& [a, ea] : t.g_codes)
    for (const auto& [b, eb] : t.g_codes)
      if (ea.group != "-" && ea.group == eb.group) t.incompatible.push_back({a, b});
  std::sort(t.incompatible.begin(), t.incompatible.end());
  t.incompatible.erase(std::unique(t.incompatible.begin(), t.incompatible.end()), t.incompatible.end());
}

namespace {

DialectTables read_dialect_tables(std::string_view dialect, Diagnostics& diags) {
  DialectTables t;
  if (auto table = load_table(dialect, "addresses.tsv", 5, diags, 7)) read_addresses(*table, t.addresses, diags);
  if (auto table = load_table(dialect, "cycles.tsv", 6, diags)) {
    for (const TableRow& row : table->rows) {
      const auto& c = row.cells;
      CyclePattern p;
      p.name = c[0];
      using P = CyclePattern;
      bool ok = pick(c[1],
                     {{"feed", P::In::Feed},
                      {"peck", P::In::Peck},
                      {"spindle_feed", P::In::SpindleFeed},
                      {"chip_break", P::In::ChipBreak},
                      {"tap_cw", P::In::TapCw},
                      {"tap_ccw", P::In::TapCcw},
                      {"back", P::In::Back}},
                     p.in);
      ok = ok && pick(c[2], {{"yes", true}, {"no", false}}, p.dwell);
      ok = ok && pick(c[3],
                      {{"-", P::Bottom::None},
                       {"reverse", P::Bottom::Reverse},
                       {"stop", P::Bottom::Stop},
                       {"orient_shift", P::Bottom::OrientShift}},
                      p.bottom);
      ok = ok && pick(c[4], {{"rapid", P::Out::Rapid}, {"feed", P::Out::Feed}, {"manual", P::Out::Manual}}, p.out);
      if (!ok) {
        report(diags, *table, row.line, "malformed cycle row");
        continue;
      }
      t.cycles.push_back(std::move(p));
    }
  }
  if (auto table = load_table(dialect, "g_codes.tsv", 5, diags))
    read_code_table(*table, 'G', t.cycles, t.g_codes, diags);
  if (auto table = load_table(dialect, "m_codes.tsv", 6, diags))
    read_code_table(*table, 'M', t.cycles, t.m_codes, diags);
  if (auto table = load_table(dialect, "power_on.tsv", 3, diags)) {
    for (const TableRow& row : table->rows) {
      auto& list = t.power_on[row.cells[0]];
      for (size_t col = 1; col < 3; ++col)
        for (const std::string& token : split(row.cells[col], ' ')) {
          if (token.empty()) continue;
          // A token that is not a G or M code names functions ("units.mm").
          const bool code = token.size() > 1 && (token[0] == 'G' || token[0] == 'M') &&
                            std::isdigit(static_cast<unsigned char>(token[1]));
          std::vector<FnCall> calls;
          std::string error;
          if (!code && !parse_functions(token, t.cycles, calls, error)) report(diags, *table, row.line, error);
          list.push_back(token);
        }
    }
  }
  // The compatibility matrix: a pair is incompatible if either row says so, or if
  // both codes are of one group.
  if (embedded_file(fmt::format("dialects/{}/congruence.tsv", dialect))) {
    if (auto table = load_table(dialect, "congruence.tsv", 2, diags)) {
      auto g_number = [&](const std::string& cell, uint32_t line) -> std::optional<int> {
        auto n = cell.size() > 1 && cell[0] == 'G' ? parse_number<int>(std::string_view(cell).substr(1)) : std::nullopt;
        if (!n || !t.g_codes.count(*n))
          report(diags, *table, line, fmt::format("'{}' is not a G code of the table", cell));
        return n && t.g_codes.count(*n) ? n : std::nullopt;
      };
      for (const TableRow& row : table->rows) {
        auto a = g_number(row.cells[0], row.line);
        for (const std::string& cell : split(row.cells[1], ' ')) {
          auto b = cell.empty() ? std::nullopt : g_number(cell, row.line);
          if (a && b) {
            t.printed_incompatible.push_back({*a, *b});
            t.printed_incompatible.push_back({*b, *a});
          }
        }
      }
      auto& printed = t.printed_incompatible;
      std::sort(printed.begin(), printed.end());
      printed.erase(std::unique(printed.begin(), printed.end()), printed.end());
      add_class_pairs(t);
    }
  }
  if (auto table = load_table(dialect, "citations.tsv", 2, diags)) {
    for (const TableRow& row : table->rows) {
      if (auto id = diag_by_name(row.cells[0]))
        t.citations[*id] = row.cells[1];
      else
        report(diags, *table, row.line, fmt::format("unknown diagnostic '{}'", row.cells[0]));
    }
  }
  return t;
}

}  // namespace

DialectTables load_dialect_tables(std::string_view dialect, Diagnostics& diags) {
  // The tables are built in: read once a process (NC-110's took 2.4 million
  // instructions, a third of a small program's compile, and an embedding controller
  // compiles many), then copied, since a machine profile changes its copy. Tables
  // with problems are read anew each time, so that each compile reports them.
  static std::mutex mutex;
  static std::map<std::string, DialectTables, std::less<>> read;
  const std::lock_guard lock(mutex);
  if (auto it = read.find(dialect); it != read.end()) return it->second;
  Diagnostics found;
  DialectTables t = read_dialect_tables(dialect, found);
  if (found.all().empty()) read.emplace(std::string(dialect), t);
  for (const Diagnostic& d : found.all()) diags.add(d);
  return t;
}

}  // namespace ncc::stdlib
