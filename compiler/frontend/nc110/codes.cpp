// NC-110 three-letter codes (§2.13): `(CODE,operand,...)`. The grammar keeps each
// operand as its pieces; its meaning comes from the code's signature
// (three_letter_codes.tsv) and the position, so they are read here.
#include <algorithm>
#include <charconv>

#include "contract/asset_files.h"
#include "reader.h"
#include "support/text.h"

namespace ncc::nc110 {

namespace {

constexpr size_t kMaxAxisOperands = 6;  // §2.13.1: "up to 6 axes"

// The service of a statement whose last operand is a text in quotes, a text in memory
// or a value: each goes to the service its own way (compiler/lower/lower.cpp).
Service by_form(const ir::Program& program, ir::ExprId value, Service text, Service memory, Service other) {
  const ir::ExprOp op = program.exprs[value].op;
  return op == ir::ExprOp::String ? text : op == ir::ExprOp::Text ? memory : other;
}

std::string kind_name(OperandKind k) {
  switch (k) {
    case OperandKind::Origin: return "an origin number 0..99";
    case OperandKind::Axis: return "an axis letter";
    case OperandKind::Dim: return "an axis and its value";
    case OperandKind::Pair: return "an axis and two values";
    case OperandKind::Angle: return "an angle";
    case OperandKind::Factor: return "a scale factor";
    case OperandKind::Count: return "a count 0..99";
    case OperandKind::Program: return "a program name";
    case OperandKind::Label: return "a label";
    case OperandKind::Comparand: return "a value to compare";
    case OperandKind::Item: return "a text or a value";
    case OperandKind::Seconds: return "a time 0..32 s";
    case OperandKind::Zone: return "a zone number 1..3";
    case OperandKind::Turning: return "the letter T";
    case OperandKind::Condition: return "an end condition 0..3";
    case OperandKind::Mode: return "a display mode 1..3";
    case OperandKind::Tool: return "a tool number 1..9999";
    case OperandKind::Corrector: return "a corrector number 1..9999";
    case OperandKind::Increment: return "an increment of the length (axis) or the diameter (K)";
    case OperandKind::Distance: return "a distance in mm";
    case OperandKind::Speed: return "a speed in mm/min";
    case OperandKind::Virtual: return "a mode 0..4";
    case OperandKind::Axes: return "axis letters";
    case OperandKind::Value: return "a value";
    case OperandKind::Channel: return "a channel 0..255";
    case OperandKind::Structure: return "a record structure 0..255";
    case OperandKind::Record: return "a record 1..32767";
    case OperandKind::Records: return "a record count 1..32767";
    case OperandKind::File: return "a file NAME/MPn";
    case OperandKind::Access: return "R or W";
    case OperandKind::Binding: return "a variable of an ASSET format";
    case OperandKind::Prompt: return "a prompt";
    case OperandKind::Target: return "a variable";
    case OperandKind::Field: return "a screen field 1..255";
    case OperandKind::Row: return "a screen row 1..20";
    case OperandKind::Column: return "a screen column 1..64";
    case OperandKind::Format: return "a field format 1..7";
    case OperandKind::Switch: return "ON or OFF";
    case OperandKind::Attribute: return "R or A0..A255";
    case OperandKind::Process: return "a process 1..5";
    case OperandKind::Wait: return "a process 1..5, or a condition";
  }
  return "?";
}

// The numbers an operand takes and the E parameter class that may stand for it
// (§2.13, Table 2.9; none: any E parameter, its value checked when the block runs).
struct NumericOperand {
  OperandKind kind;
  double lo, hi;
  bool whole;
  const char* param_class;
};
// ASSET (§5.3.1) and the user screen (§5.6.2): a channel, a structure or a record
// count, a field, row, column or format, a constant or any E parameter; a record, a
// constant or an IN parameter.
constexpr NumericOperand kNumericOperands[] = {{OperandKind::Origin, 0, 99, true, "IN"},
                                               {OperandKind::Count, 0, 99, true, "BY"},
                                               {OperandKind::Zone, 1, 3, true, "BY"},
                                               {OperandKind::Condition, 0, 3, true, "BY"},
                                               {OperandKind::Mode, 1, 3, true, "BY"},
                                               {OperandKind::Tool, 1, 9999, true, "IN"},
                                               {OperandKind::Corrector, 1, 9999, true, "IN"},
                                               {OperandKind::Distance, 0.001, 9999.999, false, "LR"},
                                               {OperandKind::Speed, 1, 99999, false, "LR"},
                                               {OperandKind::Virtual, 0, 4, true, "BY"},
                                               {OperandKind::Value, -99999.9999, 99999.9999, false, nullptr},
                                               {OperandKind::Angle, -99999.9999, 99999.9999, false, "RE"},
                                               {OperandKind::Factor, 0.0001, 99999.9999, false, "RE"},
                                               {OperandKind::Seconds, 0, 32, false, "LR"},
                                               {OperandKind::Channel, 0, 255, true, nullptr},
                                               {OperandKind::Structure, 0, 255, true, nullptr},
                                               {OperandKind::Records, 1, asset::kMaxRecords, true, nullptr},
                                               {OperandKind::Record, 1, asset::kMaxRecords, true, "IN"},
                                               {OperandKind::Field, 1, 255, true, nullptr},
                                               {OperandKind::Row, 1, 20, true, nullptr},
                                               {OperandKind::Column, 1, 64, true, nullptr},
                                               {OperandKind::Format, 1, 7, true, nullptr},
                                               {OperandKind::Process, 1, 5, true, "BY"}};

const NumericOperand& numeric_operand(OperandKind kind) {
  for (const NumericOperand& n : kNumericOperands)
    if (n.kind == kind) return n;
  return kNumericOperands[0];
}

bool is_letter(const std::string& s) { return s.size() == 1 && std::isalpha(static_cast<unsigned char>(s[0])); }

}  // namespace

struct Reader::Piece {
  size_t type;
  std::string text;
  SourceRange range;
  bool blank_before;
};

struct Reader::Operand {
  OperandKind kind = OperandKind::Origin;
  SourceRange range;
  std::string text;
  ir::ExprId value = ir::kNoExpr;       // a number, an E parameter, a memory or system value, a text
  ir::ExprId second = ir::kNoExpr;      // the upper value of a pair
  std::string first_text, second_text;  // an axis value as written: "-300"
  char axis = 0;
  std::string name, device;           // a label or a program
  std::optional<uint32_t> parameter;  // an axis value that is an E parameter: its index
  bool is_text = false;               // value is a String or a Text
  uint32_t chars = 0;                 // of a Text
  VarType type = VarType::LongReal;   // how DIS shows the value
};

std::optional<Reader::Operand> Reader::operand(const std::vector<Piece>& pieces, OperandKind kind,
                                               const std::string& code) {
  Operand op;
  op.kind = kind;
  op.range = {file_, line_no_, pieces.front().range.col, line_no_, pieces.back().range.end_col};
  op.text = std::string(line_.substr(op.range.col - 1, op.range.end_col - op.range.col));
  size_t at = 0;
  auto fail = [&](const std::string& why) -> std::optional<Operand> {
    diags_.report(DiagId::OperandKind, op.range, op.text, kind_name(kind), code, why);
    block_.has_errors = true;
    return std::nullopt;
  };
  auto type = [&](size_t i) { return i < pieces.size() ? pieces[i].type : antlr4::Token::EOF; };
  auto adjacent = [&](size_t i) { return i < pieces.size() && !pieces[i].blank_before; };
  // A Cyrillic look-alike of a Latin letter gets its own message.
  for (const Piece& p : pieces)
    if (p.type == Nc110Lexer::LETTER && static_cast<unsigned char>(p.text[0]) >= 0x80 && kind != OperandKind::Label &&
        kind != OperandKind::Program) {
      report_cyrillic(p.range, p.text);
      return std::nullopt;
    }
  // [sign] digits [. digits] | . digits. `bad_number`: one out of range, already reported.
  bool bad_number = false;
  auto number = [&](std::string& written, bool signs = true) -> std::optional<double> {
    bad_number = false;
    size_t i = at;
    std::string text;
    if (signs && (type(i) == Nc110Lexer::PLUS || type(i) == Nc110Lexer::MINUS)) text += pieces[i++].text;
    bool digits = false;
    if (type(i) == Nc110Lexer::DIGITS && (i == at || adjacent(i))) text += pieces[i++].text, digits = true;
    if (type(i) == Nc110Lexer::DOT && (i == at || adjacent(i))) {
      text += pieces[i++].text;
      if (type(i) == Nc110Lexer::DIGITS && adjacent(i)) text += pieces[i++].text, digits = true;
    }
    if (!digits) return std::nullopt;
    const SourceRange r{file_, line_no_, pieces[at].range.col, line_no_, pieces[i - 1].range.end_col};
    at = i;
    written = text;
    auto v = read_number(text[0] == '+' ? text.substr(1) : text, r, diags_);
    bad_number = !v;
    block_.has_errors = block_.has_errors || bad_number;
    return v;
  };
  // E<digits> (a blank between them is allowed, as in `ZE 35`). `bad_parameter`: one
  // that does not exist, already reported.
  bool bad_parameter = false;
  auto parameter_at = [&]() -> std::optional<uint32_t> {
    if (type(at) != Nc110Lexer::LETTER || pieces[at].text != "E" || type(at + 1) != Nc110Lexer::DIGITS)
      return std::nullopt;
    SourceRange r{file_, line_no_, pieces[at].range.col, line_no_, pieces[at + 1].range.end_col};
    auto index = parameter("E" + pieces[at + 1].text, r);
    at += 2;
    bad_parameter = !index;
    return index;
  };
  auto letter_o = [&](size_t i) { return type(i) == Nc110Lexer::LETTER && pieces[i].text == "O"; };
  // A constant of a range, or an E parameter of one of `classes`.
  auto value = [&](double lo, double hi, bool whole, std::vector<std::string> classes) -> bool {
    if (auto e = parameter_at()) {
      if (!check_class(*e, classes, op.range, code)) return false;
      op.value = parameter_expr(*e, op.range);
      op.type = parameter_type(*e);
      return true;
    }
    if (bad_parameter) return false;
    std::string written;
    auto v = number(written);
    if (bad_number) return false;
    if (!v) {
      if (letter_o(at) && pieces.size() == 1)
        fail("the letter O where the digit 0 is meant");
      else
        fail("not a number");
      return false;
    }
    if (whole && *v != std::trunc(*v)) return fail("it must be a whole number"), false;
    if (*v < lo || *v > hi)
      return fail(fmt::format("it must lie between {} and {}", shortest(lo), shortest(hi))), false;
    op.value = program_.number(*v, op.range);
    return true;
  };
  // An axis word: letter, then a value, an E parameter or nothing (zero).
  auto axis_word = [&](char& axis, ir::ExprId& out, std::string& shown, bool or_diameter = false) -> bool {
    if (type(at) != Nc110Lexer::LETTER || !is_letter(pieces[at].text)) return fail("an axis letter comes first"), false;
    axis = pieces[at].text[0];
    if (s_.conventions.axes.find(axis) == std::string::npos && !(or_diameter && axis == 'K'))
      return fail(fmt::format("{} is not an axis of this machine ({})", axis, s_.conventions.axes)), false;
    ++at;
    if (letter_o(at) && adjacent(at)) return fail("the letter O where the digit 0 is meant"), false;
    if ((type(at) == Nc110Lexer::PLUS || type(at) == Nc110Lexer::MINUS) && adjacent(at) &&
        type(at + 1) == Nc110Lexer::LETTER && pieces[at + 1].text == "E") {
      diags_.report(DiagId::SignedParameter, op.range, op.text);
      block_.has_errors = true;
      return false;
    }
    if (at < pieces.size() && pieces[at].text == "E" && adjacent(at)) {
      shown = "E" + (at + 1 < pieces.size() ? pieces[at + 1].text : "");
      auto e = parameter_at();
      if (!e || !check_class(*e, {"RE", "LR"}, op.range, code)) return false;
      out = parameter_expr(*e, op.range);
      op.parameter = e;
      return true;
    }
    std::string written;
    size_t start = at;
    auto v = adjacent(at) ? number(written) : std::nullopt;
    if (bad_number) return false;
    if (!v) {
      at = start;
      out = program_.number(0, op.range);
      return true;
    }
    shown = written;
    auto c = constant(axis, written[0] == '-' || written[0] == '+' ? written.substr(1) : written, written[0] == '-',
                      op.range, std::string(1, axis) + written);
    if (!c) return false;
    out = program_.number(*c, op.range);
    return true;
  };
  // An E parameter (of `classes`, if any are named), or a memory (SYVAR10.IN): `ref`
  // takes the memory's reference; for a parameter, op's value and type are set.
  // The letters the operand starts with, before piece `end`, begin with a memory's name
  // (SYVAR, SA, SK).
  auto names_memory = [&](size_t end) {
    std::string letters;
    for (size_t i = 0; i < end && pieces[i].type == Nc110Lexer::LETTER; ++i) letters += pieces[i].text;
    return std::any_of(s_.memories.begin(), s_.memories.end(),
                       [&](const Memory& m) { return letters.starts_with(m.name); });
  };
  auto variable = [&](const std::vector<std::string>& classes, const char* what, std::optional<MemoryRef>& ref) {
    if (auto e = parameter_at()) {
      if (!classes.empty() && !check_class(*e, classes, op.range, code)) return false;
      op.value = parameter_expr(*e, op.range);
      op.type = parameter_type(*e);
      return true;
    }
    if (bad_parameter) return false;
    if (!names_memory(pieces.size())) return fail(what), false;
    ref = memory_ref(op.text, op.range);
    at = pieces.size();
    return ref.has_value();
  };
  auto letters_and_digits = [&](bool& ok) {
    std::string s;
    ok = true;
    for (size_t i = at, first = at; i < pieces.size(); ++i) {
      if (pieces[i].type != Nc110Lexer::LETTER && pieces[i].type != Nc110Lexer::DIGITS) break;
      if (i > first && !adjacent(i)) ok = false;
      s += pieces[i].text;
      at = i + 1;
    }
    return s;
  };

  switch (kind) {
    case OperandKind::Origin:
    case OperandKind::Count:
    case OperandKind::Zone:
    case OperandKind::Condition:
    case OperandKind::Mode:
    case OperandKind::Tool:
    case OperandKind::Corrector:
    case OperandKind::Distance:
    case OperandKind::Speed:
    case OperandKind::Virtual:
    case OperandKind::Value:
    case OperandKind::Angle:
    case OperandKind::Factor:
    case OperandKind::Seconds:
    case OperandKind::Channel:
    case OperandKind::Structure:
    case OperandKind::Records:
    case OperandKind::Record:
    case OperandKind::Field:
    case OperandKind::Row:
    case OperandKind::Column:
    case OperandKind::Format:
    case OperandKind::Process: {
      const NumericOperand& n = numeric_operand(kind);
      std::vector<std::string> classes;
      if (n.param_class)
        classes.push_back(n.param_class);
      else
        for (const ParameterClass& c : s_.classes) classes.push_back(c.name);
      if (!value(n.lo, n.hi, n.whole, classes)) return std::nullopt;
      break;
    }
    case OperandKind::Axis:
    case OperandKind::Turning: {
      if (pieces.size() != 1 || !is_letter(pieces[0].text)) return fail("one letter");
      char letter = pieces[0].text[0];
      if (kind == OperandKind::Turning && letter != 'T') return fail("only T (turning) may stand here");
      if (kind == OperandKind::Axis && s_.conventions.axes.find(letter) == std::string::npos)
        return fail(fmt::format("{} is not an axis of this machine ({})", letter, s_.conventions.axes));
      op.axis = letter;
      at = 1;
      break;
    }
    case OperandKind::Dim:
      if (!axis_word(op.axis, op.value, op.first_text)) return std::nullopt;
      break;
    case OperandKind::Axes: {
      // UAV: letters written together, "XC", each an axis once; they travel packed,
      // a hex digit each (the axis' index + 1), the first lowest.
      bool ok = false;
      op.name = letters_and_digits(ok);
      if (!ok || op.name.empty() || op.name.size() > 4 || op.name.find_first_of("0123456789") != std::string::npos)
        return fail("1 to 4 axis letters written together, as XC");
      uint32_t packed = 0;
      for (size_t i = 0; i < op.name.size(); ++i) {
        const char a = op.name[i];
        if (s_.conventions.axes.find(a) == std::string::npos)
          return fail(fmt::format("{} is not an axis of this machine ({})", a, s_.conventions.axes));
        if (op.name.find(a) != i) return fail(fmt::format("{} is written twice", a));
        packed |= static_cast<uint32_t>(axis_index(a) + 1) << (4 * i);
      }
      op.value = program_.number(packed, op.range);
      break;
    }
    case OperandKind::Increment:
      // RQU, RQP (§2.13.8): the length's axis and its increment, or K and the
      // diameter's; nothing after the letter is 0 ("(RQU,10,1,ZE30,K)").
      if (!axis_word(op.axis, op.value, op.first_text, true)) return std::nullopt;
      break;
    case OperandKind::Pair: {
      char second = 0;
      if (!axis_word(op.axis, op.value, op.first_text)) return std::nullopt;
      if (at == pieces.size())
        return fail(fmt::format("the second value of {0} is missing (a pair is written {0}-300 {0}300, with a blank)",
                                op.axis));
      if (!axis_word(second, op.second, op.second_text)) return std::nullopt;
      if (second != op.axis)
        return fail(fmt::format("the two values must belong to one axis, not {} and {}", op.axis, second));
      break;
    }
    case OperandKind::Label: {
      bool ok = false;
      op.name = letters_and_digits(ok);
      size_t count = 0;
      bool valid = ok && !op.name.empty();
      for (size_t i = 0; i < op.name.size(); ++i) {
        unsigned char c = static_cast<unsigned char>(op.name[i]);
        if ((c & 0xC0) != 0x80) ++count;
        valid = valid && !(c >= 'a' && c <= 'z');
      }
      if (!ok) return fail("a label is written without blanks");
      if (!valid || count > 6) return fail("a label is 1 to 6 capital letters and digits, unquoted");
      break;
    }
    case OperandKind::Program: {
      // NAME[/DEVice]: 1-6 capitals and digits, a letter first; a device of 2-3 (§2.13.2.2).
      bool ok = false;
      op.name = letters_and_digits(ok);
      if (!ok) return fail("a program name is written without blanks");
      if (!capitals_and_digits(op.name, 1, 6))
        return fail("a program name is 1 to 6 capitals and digits, a letter first");
      if (type(at) == Nc110Lexer::SLASH) {
        ++at;
        op.device = letters_and_digits(ok);
        if (!ok || !capitals_and_digits(op.device, 2, 3))
          return fail("a device name is 2 or 3 capitals and digits, a letter first");
      }
      break;
    }
    case OperandKind::File: {
      bool ok = false;
      std::string name = letters_and_digits(ok);
      if (ok && type(at) == Nc110Lexer::SLASH && adjacent(at)) {
        ++at;
        name += "/" + letters_and_digits(ok);
      }
      auto file = ok ? asset::parse_file_name(name, 1) : std::nullopt;  // MP1 unless named (§5.3.2.1)
      if (!file)
        return fail("a file is 1 to 6 capitals and digits, a letter first, then /MP0 to /MP6 or nothing (MP1)");
      op.name = file->text();
      break;
    }
    case OperandKind::Access:
      if (pieces.size() != 1 || (pieces[0].text != "R" && pieces[0].text != "W"))
        return fail("R (read) or W (read and write)");
      op.name = pieces[0].text;
      at = 1;
      break;
    case OperandKind::Binding: {
      // Table 5.1: IN, RE, LR and CH; E0-E9 (BY) and E20-E24 (LI) have none of them,
      // and a memory's own format (BY, BL) is not one either: it is written.
      std::optional<MemoryRef> ref;
      if (!variable({"IN", "RE", "LR"}, "an IN, RE or LR E parameter, or SYVAR, SA or SK with .IN, .RE, .LR or .kCH",
                    ref))
        return std::nullopt;
      if (!ref) break;
      const bool asset_format = ref->chars > 0 || ref->format == MemFormat::Integer || ref->format == MemFormat::Real ||
                                ref->format == MemFormat::LongReal;
      if (!asset_format)
        return fail(fmt::format("{} is not of an ASSET format: write .IN, .RE, .LR or .kCH (table 5.1)", ref->text));
      if (ref->chars > asset::kMaxChars)
        return fail(fmt::format("an ASSET field holds at most {} characters", asset::kMaxChars));
      op.value = memory_expr(*ref, op.range);
      op.is_text = ref->chars > 0;
      op.chars = ref->chars;
      break;
    }
    // INP (§5.5): the prompt is a text, or the number of a screen field holding one.
    case OperandKind::Prompt:
      if (pieces.size() == 1 && pieces[0].type == Nc110Lexer::STRING) {
        op.name = pieces[0].text.substr(1, pieces[0].text.size() - 2);
        op.is_text = true;
        at = 1;
      } else if (!value(1, 255, true, {"IN"})) {
        return std::nullopt;
      }
      break;
    case OperandKind::Switch: {
      bool ok = false;
      op.name = letters_and_digits(ok);
      if (!ok || (op.name != "ON" && op.name != "OFF")) return fail("ON or OFF");
      break;
    }
    case OperandKind::Attribute: {
      // R, or A and a colour 0..255 (16 × background + text, table 5.4).
      bool ok = false;
      op.name = letters_and_digits(ok);
      unsigned colour = 256;
      const bool colour_ok = op.name.size() > 1 && op.name[0] == 'A' &&
                             std::from_chars(op.name.data() + 1, op.name.data() + op.name.size(), colour).ptr ==
                                 op.name.data() + op.name.size() &&
                             colour <= 255;
      if (!ok || (op.name != "R" && !colour_ok)) return fail("R (inverse) or A and a colour 0..255 (A179)");
      break;
    }
    case OperandKind::Target: {
      std::optional<MemoryRef> ref;
      if (!variable({}, "an E parameter, or SYVAR, SA or SK", ref)) return std::nullopt;
      if (ref) op.value = memory_expr(*ref, op.range);
      break;
    }
    // WAI (§4.1.3): a process, or SYVAR, SA or SK of format BL, BY or IN, a relation
    // (= always; < > and # for "not equal" with BY and IN) and a number or an E parameter.
    case OperandKind::Wait: {
      size_t relop = 0;
      while (relop < pieces.size() && pieces[relop].type != Nc110Lexer::RELOP) ++relop;
      if (relop == pieces.size()) {
        const NumericOperand& n = numeric_operand(OperandKind::Process);
        if (!value(n.lo, n.hi, n.whole, {n.param_class})) return std::nullopt;
        break;
      }
      const std::string& rel = pieces[relop].text;
      if (!names_memory(relop)) return fail(fmt::format("SYVAR, SA or SK comes before '{}'", rel));
      SourceRange left{file_, line_no_, pieces[0].range.col, line_no_, pieces[relop - 1].range.end_col};
      auto ref = memory_ref(line_.substr(left.col - 1, left.end_col - left.col), left);
      if (!ref) return std::nullopt;
      if (ref->chars > 0 ||
          (ref->format != MemFormat::Bit && ref->format != MemFormat::Byte && ref->format != MemFormat::Integer))
        return fail(fmt::format("{} is not of format BL, BY or IN: a wait compares those only", ref->text));
      if (rel != "=" && ref->format == MemFormat::Bit)
        return fail(fmt::format("{} is a bit (BL): it is waited for with '=' only", ref->text));
      at = relop + 1;
      if (at == pieces.size()) return fail(fmt::format("a number or an E parameter comes after '{}'", rel));
      std::vector<std::string> classes;
      for (const ParameterClass& c : s_.classes) classes.push_back(c.name);
      if (!value(-1e15, 1e15, false, classes)) return std::nullopt;
      const ir::ExprOp compare = rel == "="   ? ir::ExprOp::Eq
                                 : rel == "<" ? ir::ExprOp::Lt
                                 : rel == ">" ? ir::ExprOp::Gt
                                              : ir::ExprOp::Ne;
      op.value = program_.add({compare, Builtin::Sin, 0, 0, memory_expr(*ref, left), op.value, op.range});
      op.name = op.text;  // the condition, as written
      break;
    }
    case OperandKind::Comparand:
    case OperandKind::Item: {
      if (pieces.size() == 1 && pieces[0].type == Nc110Lexer::STRING) {
        std::string s = pieces[0].text.substr(1, pieces[0].text.size() - 2);
        op.is_text = true;
        op.chars = static_cast<uint32_t>(s.size());
        op.value = string_expr(s, op.range);
        at = 1;
        break;
      }
      if (auto e = parameter_at()) {
        op.value = parameter_expr(*e, op.range);
        op.type = parameter_type(*e);
        break;
      }
      if (bad_parameter) return std::nullopt;
      if (letter_o(0) && pieces.size() == 1) return fail("the letter O where the digit 0 is meant");
      if (pieces.size() == 2 && type(0) == Nc110Lexer::LETTER && type(1) == Nc110Lexer::DIGITS && adjacent(1) &&
          pieces[0].text.size() == 1 && kGtlElements.find(pieces[0].text[0]) != std::string_view::npos) {
        return fail(
            fmt::format("{} is a GTL element, not a value: FEP, FEL and FEC read its numbers (§2.12)", op.text));
      }
      if (type(0) == Nc110Lexer::LETTER) {
        bool ok = false;
        if (names_memory(pieces.size())) {
          auto ref = memory_ref(op.text, op.range);
          if (!ref) return std::nullopt;
          op.value = memory_expr(*ref, op.range);
          op.is_text = ref->chars > 0;
          op.chars = ref->chars;
          static constexpr VarType kShow[] = {VarType::Byte, VarType::Byte, VarType::Integer,
                                              VarType::Long, VarType::Real, VarType::LongReal};
          op.type = kShow[static_cast<int>(ref->format)];
          at = pieces.size();
          break;
        }
        std::string written = letters_and_digits(ok);
        size_t digits = written.find_first_of("0123456789");
        std::optional<uint32_t> n;
        if (digits != std::string::npos) {
          if (written.find_first_not_of("0123456789", digits) != std::string::npos || written.size() - digits > 6)
            return fail("not a value");
          n = parse_number<uint32_t>(std::string_view(written).substr(digits));  // at most 6 digits
        }
        if (!ok) return fail("not a value");
        const SystemName* entry = nullptr;
        auto ref = system_ref(written.substr(0, digits), n, op.range, false, &entry);
        if (!ref) return std::nullopt;
        op.value = system_expr(*ref, op.range);
        // Shown as its class: the flags and RMS as integers, TIM and TOT as reals (§2.10).
        op.type = entry->value == "flag" || entry->value == "BY"   ? VarType::Byte
                  : entry->value == "RE" || entry->value == "expr" ? VarType::Real
                                                                   : VarType::LongReal;
        break;
      }
      std::string written;
      auto v = number(written);
      if (bad_number) return std::nullopt;
      if (!v) return fail("not a value");
      op.value = program_.number(*v, op.range);
      break;
    }
  }
  if (at < pieces.size())
    return fail(fmt::format("'{}' is left over",
                            line_.substr(pieces[at].range.col - 1, op.range.end_col - pieces[at].range.col)));
  return op;
}

bool Reader::virtual_operands(const CodeSignature& sig, const std::vector<Operand>& ops, SourceRange code_range) {
  // UAV (§2.17-2.19): what follows the mode depends on it.
  auto fail = [&](const Operand& op, const std::string& why) {
    diags_.report(DiagId::OperandKind, op.range, op.text, kind_name(op.kind), sig.code, why);
    block_.has_errors = true;
    return false;
  };
  const ir::Expr& m = program_.exprs[ops[0].value];
  if (m.op != ir::ExprOp::Number)
    return fail(ops[0], "the mode is written as a number: the operands after it depend on it");
  const auto mode = static_cast<size_t>(m.number);
  const VirtualForm& form = kVirtualForms[mode];
  const size_t expected = mode == 0 ? 1 : 3 + form.values;
  if (ops.size() != expected) {
    if (ops.size() > expected) return fail(ops[expected], fmt::format("mode {} is written {}", mode, form.written));
    diags_.report(DiagId::OperandMissing, code_range, sig.code,
                  fmt::format("the operands of mode {}: {}", mode, form.written));
    block_.has_errors = true;
    return false;
  }
  if (mode == 0) return true;
  const Operand& real = ops[1];
  const Operand& virt = ops[2];
  if (real.name.size() < form.real_lo || real.name.size() > form.real_hi)
    return fail(real, fmt::format("mode {} is written {}", mode, form.written));
  if (virt.name.size() < form.virt_lo || virt.name.size() > form.virt_hi)
    return fail(virt, fmt::format("mode {} is written {}", mode, form.written));
  for (char a : virt.name)
    if (real.name.find(a) != std::string::npos) return fail(virt, fmt::format("{} stands in both lists", a));
  if (mode != 3) return true;
  // The digit strings: one digit a slave, a master's place 1..masters, a mirror 1 or 2.
  for (size_t k = 0; k < 2; ++k) {
    const Operand& op = ops[3 + k];
    const std::string digits = program_.exprs[op.value].op == ir::ExprOp::Number ? op.text : std::string();
    const char top = k == 0 ? static_cast<char>('0' + virt.name.size()) : '2';
    const bool ok = digits.size() == real.name.size() &&
                    std::all_of(digits.begin(), digits.end(), [&](char c) { return c >= '1' && c <= top; });
    if (!ok)
      return fail(op, fmt::format("{} digits, one a slave, each 1 to {} ({})", real.name.size(), top,
                                  k == 0 ? "the place of its master in the list" : "1 normal, 2 mirrored"));
  }
  return true;
}

void Reader::unsynced(const std::string& code, SourceRange at, const char* why) {
  auto it = std::find_if(unsynced_.begin(), unsynced_.end(), [&](const Unsynced& u) { return u.code == code; });
  if (it == unsynced_.end())
    unsynced_.push_back({code, at, why, 0});
  else
    ++it->more;
}

bool Reader::measured(const std::vector<Operand>& operands) const {
  return std::all_of(operands.begin(), operands.end(), [&](const Operand& op) {
    if (op.kind != OperandKind::Increment || op.first_text.empty()) return true;  // "K": 0
    return op.parameter && *op.parameter < measured_.size() && measured_[*op.parameter];
  });
}

void Reader::code_block(Nc110Parser::TlcBlockContext* ctx) {
  leading(ctx->leading(), true);
  SourceRange code_range = ctx->code()->LETTER().empty() ? range(ctx->LPAREN()) : range(ctx->code());
  std::string code;
  bool adjacent = true;
  auto letters = ctx->code()->LETTER();
  for (size_t i = 0; i < letters.size(); ++i) {
    code += letters[i]->getText();
    if (i > 0 && letters[i]->getSymbol()->getStartIndex() != letters[i - 1]->getSymbol()->getStopIndex() + 1)
      adjacent = false;
  }
  auto it = s_.codes.find(code);
  if (it == s_.codes.end() || !adjacent) {
    for (auto* l : letters)
      if (static_cast<unsigned char>(l->getText()[0]) >= 0x80) {
        report_cyrillic(range(l), l->getText());
        return;
      }
    // As written: "(U RT)" shows the blank that makes it unknown.
    diags_.report(
        DiagId::TlcUnknown, code_range,
        code.empty() ? code : std::string(line_.substr(code_range.col - 1, code_range.end_col - code_range.col)));
    block_.has_errors = true;
    return;
  }
  const CodeSignature& sig = it->second;
  code_operands(ctx, sig, code_range);
  // A loop's begin or end stays when its operands are wrong (reported), so that the
  // loops around it still pair up; the loop runs no time.
  if (block_.has_errors && block_.stmts.empty() && (sig.action == Action::Repeat || sig.action == Action::EndRepeat)) {
    ir::Stmt s(sig.action == Action::Repeat ? ir::StmtKind::RepeatBegin : ir::StmtKind::RepeatEnd, code_range);
    if (sig.action == Action::Repeat) s.value = program_.number(0, code_range);
    block_.stmts.push_back(s);
  }
}

void Reader::code_operands(Nc110Parser::TlcBlockContext* ctx, const CodeSignature& sig, SourceRange code_range) {
  const std::string& code = sig.code;
  // The operands' pieces.
  std::vector<std::vector<Piece>> operands;
  std::vector<SourceRange> commas;
  for (size_t i = 0; i < ctx->COMMA().size(); ++i) commas.push_back(range(ctx->COMMA(i)));
  for (auto* o : ctx->operand()) {
    std::vector<Piece>& pieces = operands.emplace_back();
    size_t previous_end = SIZE_MAX;
    for (auto* p : o->piece()) {
      antlr4::Token* t = p->getStart();
      pieces.push_back({t->getType(), text(t, t), range(t, t), previous_end != t->getStartIndex()});
      previous_end = t->getStopIndex() + 1;
    }
  }

  // Match them to the signature: fixed items first, the repeated one takes the rest.
  std::vector<Operand> matched;
  size_t next = 0;
  bool group_decided = false, group_present = false;
  size_t axis_operands = 0;
  // "an axis and two values", or "another ..." where one of its kind came before.
  auto describe_missing = [&](const OperandItem& item) {
    std::string what = kind_name(item.kind);
    bool again = std::any_of(matched.begin(), matched.end(), [&](const Operand& o) { return o.kind == item.kind; });
    if (!again) return what;
    return "another " + what.substr(what.find(' ') + 1);
  };
  for (const OperandItem& item : sig.operands) {
    if (item.in_group && !group_decided) {
      group_decided = true;
      group_present = next < operands.size();
    }
    if (item.in_group && !group_present) continue;
    size_t taken = 0;
    while (next < operands.size() && (taken == 0 || item.repeat == '*' || item.repeat == '+')) {
      if (operands[next].empty() && item.repeat == '~') {
        // Left out (an empty place between commas): the column 1, no prompt (§5.5, §5.6.2.2).
        SourceRange at = next < commas.size() ? commas[next] : code_range;
        Operand none;
        none.kind = item.kind;
        none.range = at;
        if (item.kind == OperandKind::Prompt)
          none.is_text = true;
        else
          none.value = program_.number(1, at);
        matched.push_back(std::move(none));
        ++next;
        ++taken;
        continue;
      }
      if (operands[next].empty()) {
        SourceRange at = next < commas.size() ? commas[next] : code_range;
        diags_.report(DiagId::OperandMissing, at, code, kind_name(item.kind) + " here: the operand is empty");
        block_.has_errors = true;
        return;
      }
      auto op = operand(operands[next], item.kind, code);
      ++next;
      ++taken;
      if (!op) return;
      // At most six axes (§2.13.1: "up to 6 axes").
      if ((item.repeat == '*' || item.repeat == '+') && ++axis_operands > kMaxAxisOperands &&
          sig.action == Action::Function && op->axis) {
        diags_.report(DiagId::OperandKind, op->range, op->text, kind_name(item.kind), code,
                      fmt::format("a code takes at most {} axes", kMaxAxisOperands));
        block_.has_errors = true;
        return;
      }
      matched.push_back(std::move(*op));
    }
    if (taken == 0 && (item.repeat == '1' || item.repeat == '+')) {
      diags_.report(DiagId::OperandMissing, range(ctx->RPAREN()), code, describe_missing(item));
      block_.has_errors = true;
      return;
    }
  }
  if (next < operands.size()) {
    const auto& pieces = operands[next];
    // An empty one is the comma before it (operand i follows comma i).
    SourceRange at =
        pieces.empty() ? (next < commas.size() ? commas[next] : code_range)
                       : SourceRange{file_, line_no_, pieces.front().range.col, line_no_, pieces.back().range.end_col};
    diags_.report(DiagId::OperandExtra, at, code, std::string(line_.substr(at.col - 1, at.end_col - at.col)));
    block_.has_errors = true;
    return;
  }
  // Axes: each once, at most six (§2.13.1).
  std::map<char, const Operand*> axes;
  for (const Operand& op : matched) {
    if (!op.axis || op.kind == OperandKind::Turning) continue;
    if (axes.emplace(op.axis, &op).second) continue;
    if (op.axis == 'K' && op.kind == OperandKind::Increment)  // K is no axis
      diags_.report(DiagId::OperandKind, op.range, op.text, kind_name(op.kind), code,
                    "K, the diameter's increment, is given twice");
    else
      diags_.report(DiagId::AxisTwice, op.range, op.axis, code);
    block_.has_errors = true;
    return;
  }
  code_action(sig, matched, code_range);
}

void Reader::code_action(const CodeSignature& sig, const std::vector<Operand>& ops, SourceRange code_range) {
  ir::Stmt s(ir::StmtKind::Machine, block_.range);
  auto fail = [&]<typename... Args>(DiagIdFor<Args...> id, SourceRange r, const Args&... args) {
    diags_.report(id, r, args...);
    block_.has_errors = true;
  };
  switch (sig.action) {
    case Action::Function: {
      // §2.13.6.2, §2.13.7.1, §2.13.8: these need the motion before them done ('#', §2.16).
      if (block_.sync != '#') {
        if (sig.fn == Fn::DwellSeconds) unsynced(sig.code, code_range, "dwells once the motion before it ends");
        if (sig.fn == Fn::GraphicField) unsynced(sig.code, code_range, "in a program waits for the motion before it");
        if (sig.fn == Fn::CorrectorRequalify && !measured(ops))
          unsynced(sig.code, code_range,
                   "changes the corrector while the moves before it still run, with values no measuring cycle stores");
      }
      if (sig.fn == Fn::VirtualAxes && !virtual_operands(sig, ops, code_range)) return;
      if (sig.fn == Fn::CorrectorRequalify || sig.fn == Fn::CorrectorModify) {
        // One length (a corrector has one) and one diameter.
        const Operand* length = nullptr;
        for (const Operand& op : ops)
          if (op.kind == OperandKind::Increment && op.axis != 'K') {
            if (length)
              return fail(DiagId::OperandKind, op.range, op.text, kind_name(op.kind), sig.code,
                          fmt::format("a corrector has one length: {} and {} both give it", length->axis, op.axis));
            length = &op;
          }
      }
      // The code, then its operands as words: an axis list at the axes' slots, axis
      // values there too (a pair's second one at the second slots), the rest at the
      // operand slots in order (contract/word_slots.h).
      add_word(0, 0, program_.number(0, code_range), "", code_range, ir::WordKind::Code,
               program_code(program_, {sig.code, Scope::Modal, Timing::None, {{sig.fn}}}));
      block_.words.back().address = sig.code;
      int operand_number = 0;
      for (size_t i = 0; i < ops.size(); ++i) {
        const Operand& op = ops[i];
        const OperandItem& item = sig.operands[std::min(i, sig.operands.size() - 1)];
        bool listed_axis = op.kind == OperandKind::Axis && item.repeat != '1';
        if (op.kind == OperandKind::Dim || op.kind == OperandKind::Pair || op.kind == OperandKind::Increment ||
            listed_axis) {
          add_word(op.axis, letter_slot(op.axis), listed_axis ? program_.number(0, op.range) : op.value, op.first_text,
                   op.range);
          if (op.kind == OperandKind::Pair)
            add_word(op.axis, second_slot(op.axis), op.second, op.second_text, op.range);
          continue;
        }
        // An axis in a fixed place (DPI, BSP): its number; T of CTL: 1.
        ir::ExprId value = op.kind == OperandKind::Axis      ? program_.number(axis_index(op.axis), op.range)
                           : op.kind == OperandKind::Turning ? program_.number(1, op.range)
                                                             : op.value;
        add_word('#', operand_slot(operand_number++), value, "=" + op.text, op.range);
      }
      break;
    }
    case Action::Repeat:
      s = ir::Stmt(ir::StmtKind::RepeatBegin, block_.range);
      s.value = ops[0].value;
      s.limit = 99;  // §2.13.2.1
      break;
    case Action::EndRepeat: s = ir::Stmt(ir::StmtKind::RepeatEnd, block_.range); break;
    case Action::Call: {
      s = ir::Stmt(ir::StmtKind::Call, ops[0].range);
      std::string device = ops[0].device.empty() ? s_.default_device : ops[0].device;
      s.label = device + "/" + ops[0].name;
      s.value = program_.number(1, ops[0].range);
      calls_.push_back({ops[0].name, device, s.label, ops[0].range, program_.units.size(), unit_->blocks.size()});
      break;
    }
    case Action::CallRange:
      s = ir::Stmt(ir::StmtKind::CallRange, ops[0].range);
      s.label = ops[0].name;
      s.end_label = ops[1].name;
      s.end_range = ops[1].range;
      break;
    case Action::Jump:
      s = ir::Stmt(ir::StmtKind::Jump, ops[0].range);
      s.label = ops[0].name;
      break;
    case Action::JumpIf: {
      const Operand& a = ops[0];
      const Operand& b = ops[1];
      s = ir::Stmt(ir::StmtKind::Jump, ops[2].range);
      s.label = ops[2].name;
      const std::string& c = sig.comparison;
      if (a.is_text || b.is_text) {
        // Texts compare for equality only, a text reference with a text (decision 11).
        if (!a.is_text || !b.is_text)
          return fail(DiagId::TextMismatch, (a.is_text ? b : a).range,
                      fmt::format("({}) compares a text with a number", sig.code));
        if (c != "eq" && c != "ne")
          return fail(DiagId::TextMismatch, code_range,
                      fmt::format("({}) cannot compare texts: BEQ and BNE can", sig.code));
        const Operand& memory = program_.exprs[a.value].op == ir::ExprOp::Text ? a : b;
        const Operand& other = &memory == &a ? b : a;
        if (program_.exprs[memory.value].op != ir::ExprOp::Text)
          return fail(DiagId::TextMismatch, code_range,
                      "two quoted texts compare the same way every time: compare a text memory with a text");
        ir::ExprId right = other.value;
        if (program_.exprs[other.value].op == ir::ExprOp::String) {
          std::string t = program_.texts[program_.exprs[other.value].text];
          if (t.size() != memory.chars) {
            diags_.report(DiagId::TextPadded, other.range, t, t.size(), memory.chars, memory.text,
                          t.size() < memory.chars ? "blanks are added" : "the rest is not compared");
            t.resize(memory.chars, ' ');
            right = string_expr(t, other.range);
          }
        } else if (other.chars != memory.chars) {
          return fail(DiagId::TextMismatch, other.range,
                      fmt::format("{} and {} hold texts of different lengths", memory.text, other.text));
        }
        s.cond = program_.add({ir::ExprOp::TextEq, Builtin::Sin, 0, 0, memory.value, right, code_range});
        if (c == "ne") s.cond = program_.add({ir::ExprOp::Not, Builtin::Sin, 0, 0, s.cond, ir::kNoExpr, code_range});
        break;
      }
      ir::ExprOp op = c == "gt"   ? ir::ExprOp::Gt
                      : c == "lt" ? ir::ExprOp::Lt
                      : c == "eq" ? ir::ExprOp::Eq
                      : c == "ne" ? ir::ExprOp::Ne
                      : c == "ge" ? ir::ExprOp::Ge
                                  : ir::ExprOp::Le;
      s.cond = program_.add({op, Builtin::Sin, 0, 0, a.value, b.value, code_range});
      break;
    }
    case Action::Display: {
      // Items one after the other; a value alone shows as NAME=value, apart from an item
      // before it (§2.13.6.1, decision 37); a text has at most 32 characters.
      s = ir::Stmt(ir::StmtKind::Display, block_.range);
      for (size_t i = 0; i < ops.size(); ++i) {
        const Operand& op = ops[i];
        const ir::Expr& e = program_.exprs[op.value];
        if (e.op == ir::ExprOp::String) {
          std::string t = program_.texts[e.text];
          size_t chars = 0;
          for (unsigned char ch : t) chars += (ch & 0xC0) != 0x80;
          if (chars > 32) return fail(DiagId::TextTooLong, op.range, t, chars, "(DIS)", 32);
          s.items.push_back({op.value, op.type});
          continue;
        }
        if (e.op == ir::ExprOp::Number) {
          s.items.push_back({string_expr(op.text, op.range), op.type});  // as written
          continue;
        }
        // A value after another item stands apart from it: "E10=5 E40=2.5".
        if (i == 0 || program_.exprs[ops[i - 1].value].op != ir::ExprOp::String)
          s.items.push_back({string_expr((i == 0 ? "" : " ") + op.text + "=", op.range), op.type});
        s.items.push_back({op.value, op.type});
      }
      break;
    }
    case Action::Asset: {
      s = ir::Stmt(ir::StmtKind::Service, block_.range);
      s.service = sig.service;
      for (const Operand& op : ops) {
        if (op.kind == OperandKind::File)
          s.label = op.name;
        else if (op.kind == OperandKind::Access)
          s.service = op.name == "W" ? Service::AssetOpenWrite : Service::AssetOpen;
        else
          s.items.push_back({op.value, op.type});
      }
      // A record named: that one, not the next; CLO without a channel: every channel.
      if (s.items.size() > 2 && s.service == Service::AssetRead) s.service = Service::AssetReadAt;
      if (s.items.size() > 2 && s.service == Service::AssetWrite) s.service = Service::AssetWriteAt;
      if (s.service == Service::AssetClose && s.items.empty()) s.service = Service::AssetCloseAll;
      if (s.service == Service::AssetDefine && s.items.size() - 1 > asset::kMaxFields)
        return fail(DiagId::OperandKind, ops[asset::kMaxFields + 1].range, ops[asset::kMaxFields + 1].text,
                    kind_name(OperandKind::Binding), sig.code,
                    fmt::format("a structure binds at most {} variables (§5.3.2.2)", asset::kMaxFields));
      break;
    }
    case Action::Input: {
      // The prompt in quotes (or none), or the text of a screen field; a field may show the answer.
      s = ir::Stmt(ir::StmtKind::Service, block_.range);
      s.label = ops[0].name;
      s.items.push_back({ops[0].is_text ? program_.number(0, code_range) : ops[0].value, VarType::Integer});
      s.target = ops[1].value;
      if (ops.size() > 2) s.items.push_back({ops[2].value, VarType::Integer});
      const bool text = program_.exprs[s.target].op == ir::ExprOp::Text;
      s.service = ops[0].is_text ? (text ? Service::InputText : Service::InputValue)
                                 : (text ? Service::InputFieldText : Service::InputField);
      break;
    }
    case Action::Screen: {
      s = ir::Stmt(ir::StmtKind::Service, block_.range);
      s.service = sig.service;
      if (sig.service == Service::ScreenOn) {
        if (ops[0].name != "ON") s.service = Service::ScreenOff;
        break;
      }
      for (const Operand& op : ops) {
        if (op.kind == OperandKind::Attribute)
          s.label = op.name;
        else
          s.items.push_back({op.value, op.type});
      }
      if (sig.service == Service::ScreenDefineValue) {
        if (s.items.size() > 3)
          s.service =
              by_form(program_, s.items[3].value, Service::ScreenDefineText, Service::ScreenDefineMem, s.service);
        break;
      }
      // OUT: fields (a constant field may have '-': inverse), at most six; with two
      // operands the second is the first's new value (§5.6.2.3, decision 61).
      if (ops.empty()) s.service = Service::ScreenShowAll;
      if (ops.size() == 2) {
        s.items = {{ops[0].value, VarType::Integer}, {ops[1].value, ops[1].type}};
        s.service =
            by_form(program_, ops[1].value, Service::ScreenShowText, Service::ScreenShowMem, Service::ScreenShowValue);
      }
      if (ops.size() > 6)
        return fail(DiagId::OperandKind, ops[6].range, ops[6].text, "a screen field", sig.code,
                    "OUT shows at most 6 fields");
      for (size_t i = 0; i < (ops.size() == 2 ? 1 : ops.size()); ++i) {
        const ir::Expr& e = program_.exprs[ops[i].value];
        const bool field = e.op == ir::ExprOp::Var || (e.op == ir::ExprOp::Number && e.number == std::trunc(e.number) &&
                                                       std::fabs(e.number) >= 1 && std::fabs(e.number) <= 255);
        if (!field)
          return fail(DiagId::OperandKind, ops[i].range, ops[i].text, "a screen field", sig.code,
                      "a field 1..255, -n for inverse, or an E parameter");
      }
      break;
    }
    case Action::Process:
      s = ir::Stmt(ir::StmtKind::Service, block_.range);
      s.service = sig.service;
      if (s.service == Service::ProcessStart) {
        // A program of device MP0..MP3 (§4.1.1), read like a called one (decision 62).
        const Operand& program = ops[1];
        if (!program.device.empty() && !exe_device(program.device))
          return fail(DiagId::OperandKind, program.range, program.text, kind_name(OperandKind::Program), sig.code,
                      "EXE loads from devices MP0 to MP3");
        const std::string device = program.device.empty() ? s_.default_device : program.device;
        s.label = device + "/" + program.name;
        calls_.push_back({program.name, device, s.label, program.range, program_.units.size(), unit_->blocks.size(),
                          ir::UnitKind::Process});
      }
      if (!ops.empty()) s.value = ops[0].value;
      if (s.service == Service::ProcessWait && !ops[0].name.empty()) {
        s.service = Service::ProcessWaitUntil;
        s.label = ops[0].name;
      }
      break;
  }
  block_.stmts.push_back(s);
}

}  // namespace ncc::nc110
