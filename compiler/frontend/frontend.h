// A dialect front end: source text to IR, plus the tables the checker reads.
#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "check/check.h"
#include "ir/ir.h"
#include "stdlib/profile.h"

namespace ncc {

// Takes the blocks of the first unit as a front end reads them, to compile them
// while the rest is read (and drop them: compiling a file then holds no IR of it).
// A reader calls it at a block's end when it holds nothing of the blocks read so
// far: no index into them, no expression of theirs. The sink takes each block that
// comes first and has no flow statement, removes them from the unit (counting them
// in Unit::streamed, their labels in Unit::streamed_labels) and may drop their
// expressions.
class BlockSink {
 public:
  virtual ~BlockSink() = default;
  virtual void take(ir::Program& program, ir::Unit& unit) = 0;
};

struct ReadOptions {
  std::string library;        // where called programs are looked for ("" = the dialect's default)
  bool fast_path = true;      // plain word blocks by the hand-written scanner (false: every block by ANTLR)
  BlockSink* sink = nullptr;  // none: the whole program is held
  // Programs started in other processes when the run starts, as a controller's
  // keyboard selects them (NC-110 SPG): process number, NAME or NAME/DEVICE.
  std::vector<std::pair<uint8_t, std::string>> processes;
};

class Frontend {
 public:
  virtual ~Frontend() = default;
  // Reads one source file into IR, and the files it calls; every problem found on
  // the way is reported.
  virtual ir::Program read(SourceManager& sources, uint32_t file, Diagnostics& diags, const ReadOptions& options) = 0;
  // What the dialect-independent checks need to know about this dialect.
  virtual const CheckRules& rules() const = 0;
  // How the dialect's words are read (a translation writes them so).
  virtual const Conventions& conventions() const = 0;
};

// A front end over its dialect's validated settings, whose tables the checks read.
template <typename Settings>
class DialectFrontend : public Frontend {
 public:
  explicit DialectFrontend(Settings settings) : s_(std::move(settings)) { rules_.tables = &s_.tables; }
  DialectFrontend(const DialectFrontend&) = delete;  // rules_ points into s_
  DialectFrontend& operator=(const DialectFrontend&) = delete;
  const CheckRules& rules() const override { return rules_; }
  const Conventions& conventions() const override { return s_.conventions; }

 protected:
  // A program of `dialect` whose main file is `file`, with the settings' conventions
  // and cycles.
  ir::Program start_program(std::string_view dialect, uint32_t file) const {
    ir::Program program;
    program.dialect = program.semantics.dialect = dialect;
    program.files.push_back(file);
    program.semantics.conventions = s_.conventions;
    program.semantics.cycles = s_.tables.cycles;
    return program;
  }

  Settings s_;
  CheckRules rules_;
};

// The front end T over `settings`, or nothing when they are invalid (reported).
template <typename T, typename Settings>
[[nodiscard]] std::unique_ptr<Frontend> make_dialect_frontend(std::optional<Settings> settings) {
  if (!settings) return nullptr;
  return std::make_unique<T>(std::move(*settings));
}

std::vector<std::string_view> dialect_names();

// The text of a program file a program calls (NC-110 CLS, pp G72), a regular file of
// at most 256 MiB (its IR is held whole); nothing if there is none at `path`, or if
// there is one that cannot be read: that is reported at `at`, and `reported` set.
[[nodiscard]] std::optional<std::string> read_called_file(const std::string& path, Diagnostics& diags, SourceRange at,
                                                          bool& reported);

// Where the programs a program calls are: --lib, else the dialect's profile setting,
// else the calling program's folder.
std::string library_root(const ReadOptions& options, const std::string& setting, const std::string& caller);
// The program file a call names: the first `<root>/<name><extension>` that is one,
// added to the sources; nothing (reported at `at` as program `shown`) if none is, or
// if it is not text (admit_text).
[[nodiscard]] std::optional<uint32_t> load_called_file(SourceManager& sources, const std::string& root,
                                                       const std::string& name,
                                                       std::initializer_list<std::string_view> extensions,
                                                       const std::string& shown, SourceRange at, Diagnostics& diags);

// A character outside a comment, for a message: "'*'", "lower-case 'x'", "'Д'
// (U+0414)", "0x0D (a control character)", one nobody sees by name: "U+00A0 (a
// no-break space)"; `length` is set to its bytes.
std::string describe_char(std::string_view text, size_t at, size_t& length);

// A number as a program writes it, digits and a point ("12", "12.5", ".5", "12."): its
// value, or nothing when it is out of a double's range (reported at `at`, NC1040).
[[nodiscard]] std::optional<double> read_number(std::string_view written, SourceRange at, Diagnostics& diags);

// The index of a code in the program's code table, adding it on first use.
int32_t program_code(ir::Program& program, const CodeDesc& desc);

// The power-on state from a dialect's table: "G00" and "M05" name codes, anything
// else a canonical function ("spindle.stop").
void set_power_on(ir::Program& program, const stdlib::DialectTables& tables, const std::vector<std::string>& tokens);
// A machine builder's own codes from the profile's `<section>.tables` (`g_codes`,
// `m_codes`: files in the columns of stdlib/dialects/<dialect>/*_codes.tsv), for the
// letters given; a row replaces the table's code of its number. False if reported.
[[nodiscard]] bool read_machine_codes(const stdlib::Profile& p, std::string_view section, std::string_view letters,
                                      stdlib::DialectTables& tables, Diagnostics& diags);

// Codes a program chooses at run time (NC-110 `GE1`, pp `G R3`): the program then
// carries every code of the letters its dynamic words use, except those named in
// `fixed` (codes the front end reads itself), and the pairs of them that must not
// share a block: the compatibility matrix (without one, two codes of one G group),
// and the M conflict sets.
void add_dynamic_codes(ir::Program& program, const stdlib::DialectTables& tables,
                       const std::set<std::string>& fixed = {});

// Builds the front end of `dialect` configured by `profile`; nullptr when the
// dialect is unknown or its profile settings are invalid (reported).
[[nodiscard]] std::unique_ptr<Frontend> make_frontend(std::string_view dialect, const stdlib::Profile& profile,
                                                      Diagnostics& diags);

}  // namespace ncc
