// The structured translator's common part (structured.cpp): it walks the IR unit by
// unit and block by block and writes each block's machine words, assignments and
// expressions; a target's subclass says how its programs are laid out and how they
// jump, repeat and call (structured_iso.cpp: block numbers and GOTO;
// structured_ngc.cpp: LinuxCNC's o-words; structured_nc110.cpp: labels, branches,
// RPT and EPP; structured_pp.cpp: R words, G26-G29, G73 and G71;
// structured_gost.cpp: loops and calls written out). The lowerings of constructs a
// target has not are files of their own: structured_corner.cpp (ISO's corners),
// structured_frame.cpp (rotation, scaling, mirroring), structured_cycle.cpp (canned
// cycles between NC-110's two levels and the others' one).
#pragma once

#include <array>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "contract/machine_config.h"
#include "ir/ir.h"
#include "writer.h"

namespace ncc::cycle {
struct Step;
}

namespace ncc::translate {

// What the target cannot say (refused), says otherwise than the source without
// changing the path (dropped: a warning), or writes to its step (rounded: a warning).
struct Problem {
  SourceRange at;
  std::string what;
  Finding kind = Finding::Refused;
};

class Structured {
 public:
  Structured(std::string dialect, Writer& writer, const MachineConfig& target_machine);
  virtual ~Structured() = default;

  // The power-on functions of the source, when blocks are streamed before the
  // program that names them is read whole.
  void set_power_on(std::vector<FnCall> calls) { power_on_ = std::move(calls); }
  // The target machine's power-on functions, where ncc reads the target: the start
  // sets only where the source's differ.
  void set_target_power_on(std::vector<FnCall> calls) { target_power_on_ = std::move(calls); }
  // The source machine's offsets (NC-110's correctors name the axis of their length).
  void set_source_offsets(std::map<int, OffsetEntry> offsets) { source_offsets_ = std::move(offsets); }
  // One of the main program's leading blocks, as the compiler streams it: written
  // to the text taken from the writer (`take`) before it is dropped; `next`, the
  // block after it, where it looks ahead.
  void stream(const ir::Program& program, const ir::Block& b, const ir::Block* next);
  // The rest of the program (what was not streamed), and the start, made last
  // because it sets what the program uses; kept as text.
  void translate(const ir::Program& program, const Header& header);
  // The whole text to `out`: the start, the streamed blocks (`streamed`, a file, or
  // none) where the main program's others begin, then the rest. False if it could
  // not be written.
  [[nodiscard]] bool emit(std::FILE* streamed, std::FILE* out);
  // LinuxCNC: a jump back to a streamed block, where an o-word must open: the
  // program is to be read whole and translated again.
  bool needs_whole() const { return needs_whole_; }
  // A block the translation writes with the next one in view (ISO's corners into a
  // target without them, ISO's M06 into NC-110, an M05 that ends the coolant too):
  // streamed with it.
  bool looks_ahead(const ir::Program& program, const ir::Block& b) const;
  // A block with a frame code: every frame is lowered, or none (attach()), so the
  // stream stops there.
  int frame_codes(const ir::Program& program, const ir::Block& b) const;

  std::vector<Problem> problems;

 protected:
  // Expression levels, loosest first (iso decision 6; LinuxCNC puts AND with OR).
  enum Level : int { kOr = 1, kAnd, kCompare, kSum, kTerm, kSign, kPrimary };

  // --- what a target says its own way ---
  virtual void body() = 0;  // every unit, in the target's order (unit())
  virtual void open_unit(const ir::Unit& u, bool main) = 0;
  virtual void close_unit(const ir::Unit& u, bool main, bool returned) = 0;
  virtual void block_begun() {}  // a block's own state afresh (its scratch values), streamed or not
  virtual void before_block(size_t) {}
  virtual char sync_of(const ir::Block&) const { return 0; }  // NC-110's '#' or '&', where the target writes it
  virtual void after_block(size_t) {}
  virtual void jump(const ir::Stmt& s) = 0;
  virtual void repeat_begin(const ir::Stmt& s) = 0;
  virtual void repeat_end(const ir::Stmt& s) = 0;
  virtual void call(const ir::Stmt& s) = 0;
  virtual void ret(const ir::Stmt& s) = 0;
  virtual void conditional(const ir::Stmt& s) = 0;  // a statement that runs only if s.cond holds
  // The store of statement s into `var` (written), the value's expression `text`.
  virtual std::string assignment(const ir::Stmt& s, const std::string& var, std::string text) = 0;
  virtual void zero_all(uint32_t first, uint32_t count) = 0;  // #first.. at 0, when a program computes indexes
  // The target reads the source's parameter words as the source does (ISO and
  // LinuxCNC); its codes are still mapped by function unless it is the same dialect.
  virtual bool reads_source_words() const { return same_; }
  virtual int and_level() const { return kAnd; }
  virtual bool motion_code_moves() const { return false; }  // a motion code without axis words moves
  virtual std::string builtin(const ir::Expr& e);
  virtual std::string modulo(const ir::Expr& e, int min);
  virtual void check_variable(const ir::Expr&, uint32_t) {}
  // The block's words are the source's as written (a target of the source's dialect
  // whose syntax the common part writes: ISO).
  virtual bool verbatim() const { return same_; }
  // The target reads the main program's blocks after its end (GOST 20999 §1.9 and
  // pp §2.3.2 do not: they are not written).
  virtual bool reads_after_end() const { return true; }
  // The target writes a subprogram's return in a line after its last block (ISO's
  // M99): a last block that writes nothing but its number leaves the number to it
  // (end_number_), as pp's "N90 G70" is "N90 M99".
  virtual bool returns_after() const { return false; }
  // A code the target says otherwise than by a code of its tables (NC-110's UAO):
  // true when written.
  virtual bool own_code(const ir::Word&, const CodeDesc&) { return false; }
  // A frame function the target has as codes of its own (NC-110's MIR, URT, SCF):
  // such a frame is not lowered (own_code() writes it, or it is refused).
  virtual bool own_frame(Fn) const { return false; }
  // The start's parameters: set to 0 where the source's start at 0 and the target's
  // may not.
  virtual void start_parameters();
  virtual void start_modes(std::vector<FnCall>&) const {}  // the target's modes the source's power-on needs
  virtual void call_range(const ir::Stmt& s) { fail(s.range, "a call of a range of blocks (EPP)"); }
  virtual void display(const ir::Stmt& s);
  virtual bool next_program(const ir::Unit&) { return false; }  // a second program on the medium, started
  virtual bool skip_within(const ir::Block&) {
    return false;
  }  // a block with a '/' after its first word, written  // a comment, where the target shows the operator no values
  virtual void start_offset();
  // What the program's first line starts with (`first`, its first character) where
  // the start wrote nothing before it.
  virtual std::string first_block_prefix(char /*first*/) { return {}; }
  // The target's program starts with a line that holds its title (not NC-110).
  virtual bool title_line() const { return true; }
  // Expressions, variables and word values in the target's syntax (ISO's here).
  virtual std::string expr(ir::ExprId id, int min);
  virtual std::string var(const ir::Expr& e);
  virtual std::string value(ir::ExprId id, char letter);

  // --- the common part ---
  void unit(const ir::Unit& u, bool main);
  bool block(const ir::Block& b);  // true when its last statement returns
  void statement(const ir::Stmt& s);
  void line(std::string text);  // after the block number and the comments still to be written
  void comment(std::string_view text) { comments_.emplace_back(text); }
  void flush() {  // the block number and comments still to be written, on a line of their own
    if (pending_number_ || !comments_.empty() || !label_.empty()) line("");
  }
  void machine();
  void write_words(const std::vector<std::string>& words);
  std::string operand(ir::ExprId a);             // a function's operand
  std::string negation(ir::ExprId id, int min);  // not id
  void forget();                                 // the state the text says is not known any more (a label, a call)
  void forget_position() { position_ = {}; }     // a code that moves the origin or the frame
  bool ends_program(const ir::Unit& u) const;
  // ISO's #500+n as n, the number the dialects' numbered parameters share (E n, R n:
  // docs/translate.md, "Parameters"); nothing for any other variable.
  std::optional<uint32_t> common_number(const ir::Expr& e) const;
  // A target parameter for source variable `e`: its common number where that lies in
  // [first, end) and is free, else the next free one from `next`; nothing when none is.
  [[nodiscard]] std::optional<uint32_t> parameter_number(const ir::Expr& e, uint32_t first, uint32_t end,
                                                         std::set<uint32_t>& taken, uint32_t& next) const;
  // A dwell of `seconds` as the target's lines (structured_cycle.cpp).
  [[nodiscard]] bool dwell_lines(double seconds, std::vector<std::string>& lines);
  // Whether the block being written has a code word with function `fn`.
  bool block_has(Fn fn) const;
  bool block_has_call(const std::function<bool(const FnCall&)>& is,
                      const ir::Block* b = nullptr) const;  // b: this block
  bool coolant_ends_next() const;
  std::string doing_more(const FnCall& f, Scope scope) const;
  bool block_has_motion() const {
    return block_has_call([](const FnCall& c) { return fn_group(c.fn) == FnGroup::Motion; });
  }
  // Notes the variables block `b`'s words name (`s` none), or its statement `s`
  // names; sets first_store_.
  void note_access(const ir::Block& b, const ir::Stmt* s);
  void fail(SourceRange at, std::string what) { problems.push_back({at, std::move(what)}); }
  void drop(SourceRange at, std::string what) { problems.push_back({at, std::move(what), Finding::Dropped}); }

  struct Code {
    char letter;
    int number;
    const stdlib::CodeEntry* entry;
    std::string text() const;
  };
  std::optional<Code> target_code(const std::vector<FnCall>& calls, Scope scope) const;
  bool idle(const FnCall& f) const;
  void rescale(double factor);
  std::vector<std::vector<Code>> together(const std::vector<Code>& g) const;
  std::optional<Code> code_doing_more(const std::vector<FnCall>& calls, Scope scope) const;
  bool is_whole(ir::ExprId id) const;
  std::optional<double> constant_of(ir::ExprId id) const;
  ir::ExprId bare(ir::ExprId id) const;
  std::string number(const OutWord& w, SourceRange at);
  std::string iso_tool_change();
  std::string machine_reference(std::string_view axes, std::optional<bool> incremental, std::vector<std::string>& lines,
                                bool keep_length);
  void length(Fn fn);
  std::string length_around(std::vector<std::string>& off, std::vector<std::string>& on, bool keep);
  bool uses_locals(const std::string& unit) const;
  std::map<std::string, int> unit_numbers(std::set<int> taken, std::vector<const ir::Unit*>* unnamed = nullptr) const;
  // A block's number, where the target writes it (NC-110's N has four digits; GOST's
  // rise).
  virtual std::optional<int> number_of(const ir::Block& b);

  std::vector<FnCall> power_on() const;
  // Why work offset (origin) n is not the same on every axis of the target machine,
  // or nothing.
  [[nodiscard]] std::optional<std::string> partial_offset(int n, std::string_view name) const;

  const ir::Program* p_ = nullptr;
  Writer& w_;
  const MachineConfig& target_;
  Conventions src_;
  const Conventions& dst_;
  const bool same_;          // the target is the source's dialect
  const bool target_inch_;   // the target has an inch mode (pp has not)
  const bool target_polar_;  // ... polar coordinates (ISO's G16)
  const ir::Block* block_ = nullptr;
  std::optional<int> pending_number_;     // the block number the next line starts with
  char pending_sync_ = 0;                 // ... and NC-110's '#' or '&' after it
  bool main_number_ = false;              // ... written ':' (a GOST main block)
  std::string then_;                      // what the next line starts with after it (IF [c] THEN)
  std::string label_;                     // ... and before it (NC-110's "LABEL")
  std::vector<std::string> extra_words_;  // the block's words the target adds (pp's G70 of a subprogram's end)
  std::vector<std::string> later_lines_;  // the block's lines after its own (a reference return in machine coordinates)
  std::vector<std::string> hole_lines_;   // the moves of a cycle's hole after the block's own line (hole_moves())
  std::optional<Code> hole_rapid_;        // ... and the rapid code of that line
  std::optional<int> folded_corrector_;   // ISO's G43 H of the next block, into NC-110's M06 of this one
  bool folded_g43_ = false;               // ... and that G43 is written so
  bool skip_offset_word_ = false;         // ... and its H too
  std::vector<std::string> lines_before_;  // the block's lines before its own (NC-110's M06 of a G43's corrector)
  bool streamed_ = false;                  // the main program's leading blocks are written
  bool needs_whole_ = false;
  ir::ExprId scaled_ = ir::kNoExpr;          // an operand written times 1000 (rounding to pp's R)
  bool in_main_ = false;                     // the unit being written is the main program
  bool in_gtl_ = false;                      // between an NC-110 G21 and its G20 (a GTL profile)
  bool operand_words_ = false;               // the block's words are its code's operands (UAO, a dwell, a frame)
  bool offset_selected_ = false;             // the main program has selected a work offset
  bool moved_before_offset_ = false;         // ... or moved (or jumped) before it did
  bool moved_ = false;                       // a block has moved (or a label or call come)
  bool program_ended_ = false;               // the main program's end is written
  bool start_empty_ = false;                 // the start wrote no line
  bool main_begun_ = false;                  // a line of the main program is written
  std::optional<bool> per_minute_;           // the feed is per minute (G94), where the text says
  std::optional<double> timer_ = 0;          // NC-110's dwell time TMR, where the text says
  bool carry_ = false;                       // the block wrote nothing: its number goes to the next line
  std::optional<int> carried_number_;        // ... this one
  std::vector<std::string> title_comments_;  // the comment blocks before it

 private:
  struct Mapped;
  void attach(const ir::Program& program);
  [[nodiscard]] std::optional<uint32_t> space_base(uint16_t index);
  void begin_main();
  void lead(const ir::Block& b);
  bool at_power_on(const FnCall& c) const;
  bool still_at_power_on(const FnCall& c) const;
  static bool sets_as(const FnCall& o, const FnCall& c);
  // The plane (kPlanes' index: XY, ZX, YZ) and the letter of its normal, where plane_
  // is known.
  int plane_index() const { return *plane_ == 'K' ? 0 : *plane_ == 'J' ? 1 : 2; }
  char normal_axis() const { return *plane_ == 'K' ? 'Z' : *plane_ == 'J' ? 'Y' : 'X'; }
  // The plane's first and second axes (X Y Z: 0 1 2), where plane_ is known.
  size_t plane_u() const { return static_cast<size_t>(kPlanes[plane_index()].u); }
  size_t plane_v() const { return static_cast<size_t>(kPlanes[plane_index()].v); }
  // The word of an arc centre's k-th coordinate in the plane: I J of the plane
  // (NC-110), or the I J K of the plane's axes.
  char centre_letter(const Conventions& c, int k) const {
    return static_cast<char>('I' + (c.centre_words == CentreWords::Plane ? static_cast<size_t>(k)
                                    : k == 0                             ? plane_u()
                                                                         : plane_v()));
  }
  std::string unit_unknown() const {
    return "a length where G20 or G21 is not known: " + std::string(w_.dialect()) + " has no inch mode";
  }

 protected:
  bool start_needs(const FnCall& c) const;
  // A variable (the target's name) the program stores before anything reads it.
  bool starts_stored(const std::string& name) const { return starts_stored_.count(name) > 0; }
  std::optional<int> end_number_;                // returns_after()
  std::string verbatim_word(const ir::Word& w);  // a word of the same dialect, as written
  void state(const std::vector<FnCall>& calls);  // what the codes' functions set

 private:
  void start();
  void translated_machine();
  void code(const ir::Word& w, std::vector<Mapped>& out);
  std::vector<std::optional<Mapped>> merge_codes();
  void parameter(const ir::Word& w, std::vector<std::string>& words);
  std::string as_written(const ir::Word& w);
  std::optional<Code> exact_code(const std::vector<FnCall>& calls, Scope scope) const;
  std::optional<Code> aux_code(std::string_view name) const;  // an auxiliary function's code of that name
  using Position = std::array<std::optional<double>, 3>;
  void centre(const ir::Word& w, const Position& start, std::vector<std::string>& words);
  void absolute_centre(const Position& start, std::vector<std::string>& out);
  void plane_centre(const std::array<const ir::Word*, 3>& words, const Position& start, std::vector<std::string>& out);
  void track(const ir::Word& w);
  void origin(const ir::Word& w, const CodeDesc& desc, std::vector<Mapped>& out);
  void origin_shift(const ir::Word& w, const CodeDesc& desc);
  std::optional<int> offset_after_change() const;
  [[nodiscard]] bool corrector_change(bool on);
  int start_work_offset() const;
  bool lowers_parabola() const;
  void parabola(const std::array<const ir::Word*, 6>& words, const Position& start, std::vector<std::string>& out);
  // Canned cycles between NC-110's two levels and the others' one (structured_cycle.cpp).
  bool converts_cycle_levels() const;
  void level_cycle_code(const ir::Word& w, const CyclePattern& pattern);
  bool level_word(const ir::Word& w);
  bool level_cycle_lines(bool drills, const Position& start, std::vector<std::string>& before,
                         std::vector<std::string>& words);
  void end_level_cycle(bool by_motion, std::vector<std::string>& before);
  void unknown_level_cycle(bool moves);
  // ... and a one-level cycle the target has none of its pattern for: each hole as its moves.
  void moves_cycle_code(const ir::Word& w, const CyclePattern& pattern);
  bool hole_moves(const Position& start, std::vector<std::string>& before, std::vector<std::string>& words);
  bool hole_lines(const std::vector<cycle::Step>& steps, SourceRange at, const Position& start, bool relative,
                  std::vector<std::string>& before, std::vector<std::string>& words);
  bool refuse_moves(SourceRange at, const std::string& why);
  // The target's shift of its program zero: ISO's G52, else pp's G37.
  std::optional<Code> local_shift_code() const {
    if (auto g52 = target_code({{Fn::OffsetLocal}}, Scope::Block)) return g52;
    return target_code({{Fn::ShiftAxes}}, Scope::Modal);
  }
  void reference(const ir::Word& w, const CodeDesc& desc, std::vector<Mapped>& out);
  void timed_dwell(const ir::Word& w, const CodeDesc& desc, std::vector<Mapped>& out);
  bool lowers_corner(const ir::Word& w) const;
  std::vector<std::string> corner_moves(const ir::Word& corner, const Position& start,
                                        const std::optional<std::array<double, 2>>& chained,
                                        std::vector<std::string>& words);
  [[nodiscard]] std::optional<std::array<double, 2>> arc_centre(const Position& start);
  [[nodiscard]] std::optional<std::array<double, 2>> centre_by_radius(const ir::Word& r, const Position& start);
  void radius_centre(const ir::Word& r, const Position& start, std::vector<std::string>& words);
  // Rotation, scaling and mirroring where the target lacks one of them: every point
  // written transformed (structured_frame.cpp).
  struct Frame {
    std::array<double, 3> scale{1, 1, 1};
    std::array<bool, 3> mirror{};
    std::array<double, 3> scale_centre{};
    double rotation = 0;                                // degrees, counter-clockwise in the plane of the move
    std::array<double, 2> rotation_centre{};            // on the plane's axes when set (ISO G68)
    bool scales_others = false;                         // NC-110's (SCF,n) scales U V W as well
    bool moves(size_t axis, size_t u, size_t v) const;  // the frame changes the axis
    std::array<double, 3> apply(std::array<double, 3> p, size_t u, size_t v) const;
    std::array<double, 3> invert(std::array<double, 3> q, size_t u, size_t v) const;
  };
  bool lowers_frame(const CodeDesc& desc) const;
  void frame_code(const ir::Word& w, const CodeDesc& desc);
  bool framed(bool moves) const;
  bool framed_axis(size_t axis, bool arc) const;
  void framed_move(const Position& start, bool arc, std::vector<std::string>& words, std::string& arc_code);
  int polar_word(const ir::Word& w) const;
  void polar_point(const std::array<const ir::Word*, 2>& words, const Position& start, std::vector<std::string>& out,
                   size_t at);
  void helix(const Position& start, const ir::Word* lead, std::vector<std::string>& words, std::string& mode);
  [[nodiscard]] std::optional<std::string> length(SourceRange at, char to, std::optional<double> v);
  void arc_on_circle(const Position& start);
  void corrector(const ir::Word& w);
  char cycle_word(char letter) const;
  static bool reads_offset_number(const Conventions& c, char letter);
  std::string link_word(Fn fn) const;
  void dwell(const ir::Word& w, std::vector<std::string>& words);
  std::string length_offset(SourceRange at);
  static char corrector_axis(const std::map<int, OffsetEntry>& offsets, int corrector, const Conventions& c);
  static char tool_axis(const Conventions& c) { return c.tool_offset_axes.empty() ? 'Z' : c.tool_offset_axes[0]; }
  // A length in the target's unit as the target reads it (its step), and whether
  // writing it so moves it (the rounding warning).
  double on_step(double v) const;
  bool off_step(double v) const { return std::fabs(on_step(v) - v) > 1e-9 * std::max(1.0, std::fabs(v)); }
  // Refuses an arc whose end lies farther off its circle than the target takes: its
  // start, end and centre in the plane, as the target reads them.
  void on_circle(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c);
  void assign(const ir::Stmt& s);
  std::string builtin_of_scaled(ir::ExprId value, SourceRange at);
  bool is_thousandths(ir::ExprId id) const;

  int mapped_space_ = -1;                    // the source's space of numbered parameters
  std::map<uint16_t, uint32_t> space_base_;  // a space's first target variable
  uint32_t extra_ = 100;                     // the next one of #100..#149
  std::optional<std::vector<FnCall>> power_on_, target_power_on_;
  std::vector<FnCall> lead_;  // the functions of the main program's leading blocks (lead())
  bool lead_open_ = true;
  bool in_lead_ = false;         // the block being written is one of them
  bool lead_feed_ = false;       // ... and one of them has an F word
  size_t lead_before_ = 0;       // ... of the blocks before the one being written
  size_t main_at_ = 0;           // where the main program's text begins in text_
  std::string head_, text_;      // the start, and the rest, translated
  std::string deferred_motion_;  // the power-on motion code, for the main program's first move
  bool skip_ = false;
  bool words_written_ = false;
  std::vector<std::string> comments_;  // for the block's first line
  size_t lines_ = 0;                   // the lines line() has written
  std::set<uint32_t> used_;            // target variables the program reads or writes
  bool indirect_ = false;              // ... and one computed
  // The main program's start, up to its first jump, loop, call, condition or '/',
  // runs each statement once and in order: a variable it stores before anything
  // reads it needs no 0 at the start (a round trip adds no store).
  bool straight_ = true;
  std::set<std::pair<uint16_t, uint32_t>> accessed_;  // ... the variables named so far
  bool first_store_ = false;                          // the statement being written is such a store
  std::set<std::string> starts_stored_;               // the target's names of those variables
  // What the text says the spindle, the coolant and the plane are (nothing: not known).
  std::optional<bool> coolant_on_ = false, cycle_on_ = false, length_on_ = false, comp_on_ = false;
  std::optional<bool> rpm_;                         // the spindle speed is in rpm (not a cutting speed)
  std::optional<int> tool_selected_, tool_loaded_;  // by T, and in the spindle
  std::optional<int> spindle_turns_ = 0;            // 1 cw, -1 ccw, 0 stopped, 2 oriented
  std::optional<int> spindle_direction_ = 0;        // the last direction set (0: none yet)
  std::optional<bool> spindle_on() const {
    return spindle_turns_ ? std::optional(*spindle_turns_ == 1 || *spindle_turns_ == -1) : std::nullopt;
  }
  std::optional<char> plane_;            // the centre word along the plane's normal: a helix lead
  std::optional<int> corrector_ = 0;     // NC-110: the corrector the next M06 applies
  std::optional<int> length_entry_ = 0;  // the source's length offset entry in force (G43's H); 0: none
  std::map<int, OffsetEntry> source_offsets_;
  Position position_;                  // X Y Z where the text leaves them
  std::optional<bool> incremental_;    // G91
  std::optional<bool> inch_;           // G20
  std::optional<double> unit_ = 1.0;   // the source's length unit in the target's (25.4: inches into pp's mm)
  bool lowers_inch_ = false;           // ... and the program has inches where the target has none
  std::optional<bool> polar_ = false;  // G16, where the target has none (written in X Y Z)
  std::optional<bool> helix_mode_;     // the target's helix mode (pp's G09) is on
  // A canned cycle converted between two levels and one (structured_cycle.cpp).
  struct LevelCycle {
    struct Levels {
      std::optional<double> r1, r2, depth, dwell,
          peck;                               // R1 (approach), R2 (return): lengths in the source's unit; seconds
      std::optional<double> factor, minimum;  // NC-110's G83: K and J
    };
    const CyclePattern* pattern;
    Code code;  // the target's
    SourceRange at;
    Levels now, given;              // in force; this block's words
    std::optional<double> initial;  // the level the cycle began at (the one-level dialects' return level)
    bool defined_here = true;       // the block being written has the cycle's code
    bool written = false;           // its first hole is written (a one-level target's cycle block with it)
    bool restate = false;           // ... and its levels changed since
    bool carry = false;             // the cycle's block writes nothing: its number goes to the next line
    bool moves = false;             // the target has no cycle of its pattern: each hole is its moves (hole_moves())
  };
  bool level_cycles_ = false;  // the program has a converted cycle
  std::optional<LevelCycle> level_cycle_;
  std::optional<Position> parabola_middle_;  // GOST's two-block parabola: its intermediate point
  std::optional<bool> return_initial_;       // ISO's G98 (true) or G99, where the text says
  std::optional<int> source_origin_;         // NC-110's origin selected (UAO), where the text says
  std::optional<int> work_offset_;        // the work offset in force (the target's codes' G54 = 1), where the text says
  AxisValues shift_{};                    // ... its temporary or incremental shift on each axis (UOT, UIO)
  bool shift_known_ = true;               // ... as far as the text says
  std::string shifted_axes_;              // the axes a local shift (ISO's G52) has been written for
  bool lowers_polar_ = false;             // ... and the program has it
  bool lowers_frame_ = false;             // the program has a frame the target has not: every frame lowered
  std::optional<Frame> frame_ = Frame{};  // ... the one in force, where the text says
  double last_rotation_ = 0;              // ISO G68: the angle G91 adds to
  bool flipped_ = false;                  // a mirrored arc was written the other way round
  std::vector<const ir::Word*> frames_;   // the block's frame codes, lowered
  std::optional<Fn> motion_;              // the motion code in force
  Position centre_;                       // of the block's arc, where this translation computed it
  const ir::Block* next_ = nullptr;       // the block after this one in its unit
  std::optional<std::array<double, 2>> chained_start_;  // in the plane: where a corner's move left the tool
  std::string restore_motion_;                          // the motion code a fillet's move leaves to be written again
  std::optional<std::vector<std::string>> centre_override_;  // the next arc's centre words, from a corner's end
};

constexpr double kTwoPi = 2 * std::numbers::pi;
// An arc's sweep in radians from angle `from` to `to`, its way; a whole turn where
// they are the same.
double arc_sweep(double from, double to, bool ccw);
// A function of a rotation, scale or mirror frame (structured_frame.cpp).
bool is_frame(Fn fn);

std::unique_ptr<Structured> make_iso_structured(std::string dialect, Writer& writer, const MachineConfig& target);
std::unique_ptr<Structured> make_ngc_structured(std::string dialect, Writer& writer, const MachineConfig& target);
std::unique_ptr<Structured> make_pp_structured(std::string dialect, Writer& writer, const MachineConfig& target);
std::unique_ptr<Structured> make_gost_structured(std::string dialect, Writer& writer, const MachineConfig& target);
std::unique_ptr<Structured> make_nc110_structured(std::string dialect, Writer& writer, const MachineConfig& target,
                                                  uint32_t e_count);

}  // namespace ncc::translate
