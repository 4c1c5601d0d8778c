// Dialect tables as data: the text files in stdlib/dialects/<dialect>/ parsed into
// rows. Columns are separated by blanks; "quoted text" is one cell; '#' starts a
// comment. Each dialect front end gives the rows their meaning.
#pragma once

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contract/program_semantics.h"
#include "support/diagnostics.h"

namespace ncc::stdlib {

struct TableRow {
  std::vector<std::string> cells;
  uint32_t line = 0;
};

struct Table {
  std::string name;  // file name, for diagnostics
  std::vector<TableRow> rows;
};

// Parses `text`; rows whose cell count is not within [columns, max_columns] are
// reported (max_columns 0: exactly `columns`).
Table parse_table(std::string name, std::string_view text, size_t columns, Diagnostics& diags, size_t max_columns = 0);

// A problem with the row at `line` of a table (NC6006, "file:line: what").
void report(Diagnostics& diags, const Table& t, uint32_t line, std::string_view what);

// Loads stdlib/dialects/<dialect>/<file> from the embedded data.
[[nodiscard]] std::optional<Table> load_table(std::string_view dialect, std::string_view file, size_t columns,
                                              Diagnostics& diags, size_t max_columns = 0);
// The embedded file, if there is one.
std::optional<std::string_view> embedded_file(std::string_view path);

enum class WordClass : uint8_t { Dimension, Angular, Interpolation, Feed, NonDimension, Undefined, Element, Factor };
enum class Repeat : uint8_t { Once, Group, Several, Feed, Twice };

struct AddressEntry {
  char letter = 0;
  WordClass word_class = WordClass::Undefined;
  Repeat repeat = Repeat::Once;
  int max_count = 0;  // Several: at most this many in a block (0: no limit)
  int order = 0;
  // The constants the address takes (when `ranged`), with the decimals of the
  // format, and the E parameter classes that may stand for the value (NC-110).
  bool ranged = false;
  double min = 0, max = 0;
  int decimals = 0;
  std::vector<std::string> params;
  std::string meaning;
};

// A G or M code of a dialect table.
struct CodeEntry {
  char letter = 'G';
  int number = 0;
  std::string group;                       // the dialect's group label; "-" = none
  std::vector<std::string> conflict_sets;  // M codes: sets that must not share a block (the function they control)
  CodeDesc desc;                           // name, scope, timing, canonical functions
  std::string meaning;
};

// Pairs of code numbers, sorted, each once: a vector, so that copying the tables
// (load_dialect_tables) is a copy of memory, not thousands of allocations.
using CodePairs = std::vector<std::pair<int, int>>;
inline bool has_pair(const CodePairs& pairs, int a, int b) {
  return std::binary_search(pairs.begin(), pairs.end(), std::pair{a, b});
}

struct DialectTables {
  std::map<char, AddressEntry> addresses;
  // G codes that must not share a block (a compatibility matrix, NC-110 Table 2.4):
  // pairs of G numbers, both orders. Empty when the dialect has no matrix.
  CodePairs incompatible;          // printed pairs and class pairs (add_class_pairs)
  CodePairs printed_incompatible;  // the matrix as the manual prints it
  std::map<int, CodeEntry> g_codes;
  std::map<int, CodeEntry> m_codes;
  std::vector<CyclePattern> cycles;
  std::map<std::string, std::vector<std::string>> power_on;  // control type -> codes/functions
  std::map<DiagId, std::string> citations;                   // the manual's rule per diagnostic
};

// Parses "motion.rapid", "comp.off+length.off", "offset(3)", "cycle(G81)" (the
// cycle argument names a row of `cycles`). Returns false with `error` set.
[[nodiscard]] bool parse_functions(std::string_view text, const std::vector<CyclePattern>& cycles,
                                   std::vector<FnCall>& out, std::string& error);

// Reads a G or M code table; rows replace codes already in `codes`.
void read_code_table(const Table& table, char letter, const std::vector<CyclePattern>& cycles,
                     std::map<int, CodeEntry>& codes, Diagnostics& diags);

DialectTables load_dialect_tables(std::string_view dialect, Diagnostics& diags);

// With a compatibility matrix: the printed pairs, and two G codes of one class never
// share a block (NC-110 Table 2.5); made anew after a machine adds or changes codes.
void add_class_pairs(DialectTables& t);

}  // namespace ncc::stdlib
