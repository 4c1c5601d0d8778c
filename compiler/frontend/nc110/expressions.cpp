// NC-110 assignment blocks (§2.10, §2.12): E parameters, the PLC packets and SYVAR,
// system variables, and the expressions on their right.
#include <algorithm>
#include <charconv>

#include "frontend/frontend.h"
#include "reader.h"
#include "support/text.h"

namespace ncc::nc110 {

namespace {

constexpr uint32_t kMaxTextChars = 32;  // n of nCH (§2.10.5)

std::string without_blanks(std::string_view s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '\t') out += c;
  return out;
}

struct Function {
  std::string_view name;
  int arity;
  std::optional<Builtin> builtin;  // else NEG (negation) or MOD (remainder)
};
// §1.2.29, §2.12: trigonometry in degrees; SQR is the square root; INT the integer part.
constexpr Function kFunctions[] = {
    {"SIN", 1, Builtin::Sin},      {"COS", 1, Builtin::Cos},      {"TAN", 1, Builtin::Tan},
    {"ARS", 1, Builtin::Asin},     {"ARC", 1, Builtin::Acos},     {"ART", 1, Builtin::Atan},
    {"SQR", 1, Builtin::Sqrt},     {"ABS", 1, Builtin::Abs},      {"INT", 1, Builtin::Trunc},
    {"NEG", 1, std::nullopt},      {"MOD", 2, std::nullopt},      {"FEL", 2, Builtin::GtlLine},
    {"FEP", 2, Builtin::GtlPoint}, {"FEC", 2, Builtin::GtlCircle}};

const Function* function(std::string_view name) {
  for (const Function& f : kFunctions)
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace

std::vector<std::string> function_names() {
  std::vector<std::string> names(static_cast<size_t>(Builtin::Count));
  for (const Function& f : kFunctions)
    if (f.builtin) names[static_cast<size_t>(*f.builtin)] = f.name;
  return names;
}

// ---- References ----------------------------------------------------------------------

std::optional<uint32_t> Reader::parameter(std::string_view text, SourceRange r) {
  std::string digits = without_blanks(text.substr(1));
  uint64_t index = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (ec != std::errc() || end != digits.data() + digits.size() || index >= s_.e_count) {
    diags_.report(DiagId::ParameterRange, r, "E" + digits, s_.e_count - 1);
    block_.has_errors = true;
    return std::nullopt;
  }
  return static_cast<uint32_t>(index);
}

ir::ExprId Reader::parameter_expr(uint32_t index, SourceRange r) {
  return program_.add({ir::ExprOp::Var, Builtin::Sin, 0, 0, program_.number(index, r), ir::kNoExpr, r});
}

bool Reader::check_class(uint32_t index, const std::vector<std::string>& classes, SourceRange r,
                         const std::string& what) {
  const ParameterClass& c = s_.class_of(index);
  if (std::find(classes.begin(), classes.end(), c.name) != classes.end()) return true;
  std::string takes = "constants only";
  if (!classes.empty()) {
    takes.clear();
    for (size_t i = 0; i < classes.size(); ++i)
      takes += (i ? (i + 1 == classes.size() ? " or " : ", ") : "") + classes[i];
    takes += " parameters";
  }
  diags_.report(DiagId::ParameterClass, r, fmt::format("E{}", index), c.name, what, takes);
  block_.has_errors = true;
  return false;
}

std::optional<Reader::MemoryRef> Reader::memory_ref(std::string_view written, SourceRange r) {
  // NAME[index][.[count]FORMAT] (§2.10.5, Table 2.7); blanks between the parts.
  std::string text = without_blanks(written);
  MemoryRef ref;
  ref.text = text;
  for (const Memory& m : s_.memories)
    if (text.starts_with(m.name) && (!ref.memory || m.name.size() > ref.memory->name.size())) ref.memory = &m;
  auto fail = [&](const std::string& why) -> std::optional<MemoryRef> {
    diags_.report(DiagId::ValueForm, r, ref.memory ? ref.memory->name : text, "NAME<index>.<format>", why);
    block_.has_errors = true;
    return std::nullopt;
  };
  if (!ref.memory) return fail(fmt::format("'{}' names no memory", text));
  size_t at = ref.memory->name.size();
  size_t digits = at;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') ++digits;
  if (digits - at > 9) return fail(fmt::format("'{}' has too large an index", text));
  ref.index = parse_number<uint32_t>(std::string_view(text).substr(at, digits - at)).value_or(0);  // at most 9 digits
  ref.format = ref.memory->format;
  if (digits < text.size()) {
    if (text[digits] != '.') return fail(fmt::format("'{}' is not a reference", text));
    std::string spec = text.substr(digits + 1);
    size_t letters = spec.find_first_not_of("0123456789");
    std::string count = spec.substr(0, letters);
    std::string format = letters == std::string::npos ? "" : spec.substr(letters);
    static const std::map<std::string, MemFormat> kFormats = {{"BL", MemFormat::Bit},     {"BY", MemFormat::Byte},
                                                              {"IN", MemFormat::Integer}, {"LI", MemFormat::Long},
                                                              {"RE", MemFormat::Real},    {"LR", MemFormat::LongReal}};
    if (format == "CH") {
      ref.chars = count.empty() ? 1 : parse_number<uint32_t>(std::string_view(count).substr(0, 4)).value_or(0);
      if (ref.chars < 1 || ref.chars > kMaxTextChars)
        return fail(fmt::format("a text holds 1 to {} characters, not {}", kMaxTextChars, count));
    } else if (auto f = kFormats.find(format); f != kFormats.end() && count.empty()) {
      ref.format = f->second;
    } else {
      return fail(fmt::format("'.{}' is not a format: BL BY IN LI RE LR or nCH", spec));
    }
  }
  // The reference must lie in the memory.
  uint64_t size = ref.chars ? ref.chars : mem_size(ref.format);
  uint64_t first = ref.chars ? ref.index : ref.format == MemFormat::Bit ? ref.index / 8 : uint64_t{ref.index} * size;
  if (ref.format == MemFormat::Bit && !ref.chars) size = 1;
  if (first + size > ref.memory->bytes) {
    diags_.report(DiagId::ValueRange, r, text, fmt::format("{} ({} bytes)", ref.memory->name, ref.memory->bytes), 0,
                  ref.chars                      ? static_cast<int64_t>(ref.memory->bytes) - ref.chars
                  : ref.format == MemFormat::Bit ? ref.memory->bytes * 8 - 1
                                                 : ref.memory->bytes / mem_size(ref.format) - 1);
    block_.has_errors = true;
    return std::nullopt;
  }
  return ref;
}

ir::ExprId Reader::memory_expr(const MemoryRef& ref, SourceRange r) {
  if (ref.memory->synchronised && block_.sync != '&') block_.waits_motion = true;
  ir::Expr e{ref.chars ? ir::ExprOp::Text : ir::ExprOp::Mem,
             Builtin::Sin,
             static_cast<uint16_t>(1 + (ref.memory - s_.memories.data())),
             0,
             program_.number(ref.index, r),
             ir::kNoExpr,
             r};
  e.format = ref.format;
  e.count = static_cast<uint8_t>(ref.chars);
  return program_.add(e);
}

bool Reader::system_number(antlr4::tree::TerminalNode* n, const std::string& name, SourceRange r,
                           std::optional<uint32_t>& out) {
  if (!n) return true;
  const std::string text = n->getText();
  if (text.find('.') != std::string::npos) {
    diags_.report(DiagId::ValueForm, r, name, "a whole number", name + text);
    block_.has_errors = true;
    return false;
  }
  auto v = read_number(text, r, diags_);
  block_.has_errors = block_.has_errors || !v;
  if (v) out = whole_in<uint32_t>(*v, 0, 999999).value_or(1000000);  // (digits only) beyond: no system variable has it
  return v.has_value();
}

std::optional<SysRef> Reader::system_ref(const std::string& name, std::optional<uint32_t> number, SourceRange r,
                                         bool writing, const SystemName** entry) {
  auto it = s_.system.find(name);
  std::string shown = name + (number ? std::to_string(*number) : "");
  auto fail = [&]<typename... Args>(DiagIdFor<Args...> id, const Args&... args) -> std::optional<SysRef> {
    diags_.report(id, r, args...);
    block_.has_errors = true;
    return std::nullopt;
  };
  if (name == "e") return fail(DiagId::AddressUnknown, "lower-case 'e' (an E parameter is written with a capital E)");
  if (it == s_.system.end()) return fail(DiagId::SystemUnknown, shown);
  const SystemName& n = it->second;
  if (!n.var)
    return fail(
        DiagId::SystemNotWritable, shown,
        writing ? "is set from the keyboard, not by a program" : "is a keyboard command, not a value a program reads");
  // RMNpq: process p, axis q 1..9 (§2.10.10).
  const bool axis_digit = n.var != SysVar::RemainingPath || !number || *number % 10 != 0;
  if (n.numbered != number.has_value() || (number && (*number < n.first || *number > n.last)) || !axis_digit)
    return fail(DiagId::ValueForm, name,
                n.var == SysVar::RemainingPath
                    ? fmt::format("a number pq: process p 1 to {}, axis q 1 to 9", n.last / 10)
                : n.numbered ? fmt::format("a number {} to {}", n.first, n.last)
                             : "no number",
                shown);
  SysRef ref{*n.var, static_cast<uint8_t>(number.value_or(0))};
  if (writing && (n.value == "-" || !sys_writable(ref))) return fail(DiagId::SystemNotWritable, shown, "is read-only");
  if (entry) *entry = &n;
  return ref;
}

ir::ExprId Reader::system_expr(SysRef ref, SourceRange r) {
  ir::Expr e{ir::ExprOp::Sys, Builtin::Sin, 0, 0, ir::kNoExpr, ir::kNoExpr, r};
  e.sys = ref.packed();
  return program_.add(e);
}

ir::ExprId Reader::string_expr(std::string text, SourceRange r) {
  program_.texts.push_back(std::move(text));
  ir::Expr e{ir::ExprOp::String, Builtin::Sin, 0, 0, ir::kNoExpr, ir::kNoExpr, r};
  e.text = static_cast<uint32_t>(program_.texts.size() - 1);
  return program_.add(e);
}

// ---- Expressions -----------------------------------------------------------------------

ir::ExprId Reader::expr(Nc110Parser::ExprContext* ctx) {
  auto terms = ctx->term();
  ir::ExprId value = term(terms[0]);
  for (size_t i = 1; i < terms.size(); ++i) {
    auto* op = dynamic_cast<antlr4::tree::TerminalNode*>(ctx->children[2 * i - 1]);
    ir::ExprOp kind = op && op->getSymbol()->getType() == Nc110Lexer::MINUS ? ir::ExprOp::Sub : ir::ExprOp::Add;
    value = program_.add({kind, Builtin::Sin, 0, 0, value, term(terms[i]), range(ctx)});
  }
  return value;
}

ir::ExprId Reader::term(Nc110Parser::TermContext* ctx) {
  auto factors = ctx->factor();
  ir::ExprId value = factor(factors[0]);
  for (size_t i = 1; i < factors.size(); ++i) {
    auto* op = dynamic_cast<antlr4::tree::TerminalNode*>(ctx->children[2 * i - 1]);
    ir::ExprOp kind = op && op->getSymbol()->getType() == Nc110Lexer::STAR ? ir::ExprOp::Mul : ir::ExprOp::Div;
    value = program_.add({kind, Builtin::Sin, 0, 0, value, factor(factors[i]), range(ctx)});
  }
  return value;
}

ir::ExprId Reader::factor(Nc110Parser::FactorContext* ctx) {
  ir::ExprId value = primary(ctx->primary());
  if (!ctx->MINUS()) return value;
  if (program_.is_constant(value)) return program_.number(-program_.exprs[value].number, range(ctx));
  return program_.add({ir::ExprOp::Neg, Builtin::Sin, 0, 0, value, ir::kNoExpr, range(ctx)});
}

ir::ExprId Reader::primary(Nc110Parser::PrimaryContext* ctx) {
  SourceRange r = range(ctx);
  auto invalid = [&] { return program_.number(0, r); };  // after an error, so the tree stays whole
  if (auto* n = dynamic_cast<Nc110Parser::NumberPrimaryContext*>(ctx)) {
    // Constants may have any number of digits in expressions (§2.12, `-0.00000124`),
    // as long as they are numbers.
    auto v = read_number(n->NUMBER()->getText(), r, diags_);
    block_.has_errors = block_.has_errors || !v;
    return v ? program_.number(*v, r) : invalid();
  }
  if (auto* p = dynamic_cast<Nc110Parser::ParameterPrimaryContext*>(ctx)) {
    auto index = parameter(p->EREF()->getText(), r);
    return index ? parameter_expr(*index, r) : invalid();
  }
  if (auto* m = dynamic_cast<Nc110Parser::MemoryPrimaryContext*>(ctx)) {
    auto ref = memory_ref(m->VARREF()->getText(), r);
    if (!ref) return invalid();
    if (ref->chars) {
      diags_.report(DiagId::TextMismatch, r,
                    fmt::format("{} is a text; it cannot be part of an expression", ref->text));
      block_.has_errors = true;
      return invalid();
    }
    return memory_expr(*ref, r);
  }
  if (auto* g = dynamic_cast<Nc110Parser::GroupPrimaryContext*>(ctx)) return expr(g->expr());
  if (auto* c = dynamic_cast<Nc110Parser::CallPrimaryContext*>(ctx)) {
    std::string name = c->NAME()->getText();
    const Function* f = function(name);
    if (!f) {
      diags_.report(DiagId::FunctionUnknown, range(c->NAME()), name);
      block_.has_errors = true;
      return invalid();
    }
    auto args = c->expr();
    if (static_cast<int>(args.size()) != f->arity) {
      diags_.report(DiagId::ValueForm, r, name, f->arity == 1 ? "one argument" : "two arguments, A,B",
                    fmt::format("{} given", args.size()));
      block_.has_errors = true;
      return invalid();
    }
    ir::ExprId a = expr(args[0]);
    ir::ExprId b = args.size() > 1 ? expr(args[1]) : ir::kNoExpr;
    if (!f->builtin)
      return program_.add({name == "NEG" ? ir::ExprOp::Neg : ir::ExprOp::Mod, Builtin::Sin, 0, 0, a, b, r});
    return program_.add({ir::ExprOp::Call, *f->builtin, 0, 0, a, b, r});
  }
  auto* s = dynamic_cast<Nc110Parser::SystemPrimaryContext*>(ctx);
  std::string name = s->NAME()->getText();
  if (function(name)) {
    diags_.report(DiagId::ValueForm, r, name, "its argument in parentheses", name + "(...)");
    block_.has_errors = true;
    return invalid();
  }
  std::optional<uint32_t> number;
  if (!system_number(s->NUMBER(), name, r, number)) return invalid();
  auto ref = system_ref(name, number, r, false);
  return ref ? system_expr(*ref, r) : invalid();
}

// ---- Assignment blocks -----------------------------------------------------------------

void Reader::assign_block(Nc110Parser::AssignBlockContext* ctx) {
  leading(ctx->leading(), true);
  auto* target = ctx->target();
  auto* value = ctx->value();
  SourceRange target_range = range(target);
  SourceRange value_range = range(value);
  std::string target_text = text(target->getStart(), target->getStop());
  ir::Stmt s(ir::StmtKind::Assign, block_.range);
  auto fail = [&]<typename... Args>(DiagIdFor<Args...> id, SourceRange r, const Args&... args) {
    diags_.report(id, r, args...);
    block_.has_errors = true;
  };
  // A text on the right: only a text reference takes it (§2.10.5).
  const bool string_value = value->STRING() || value->OPEN_STRING();
  if (value->OPEN_STRING()) return fail(DiagId::StringUnterminated, value_range);
  std::string string_text;
  if (value->STRING()) {
    string_text = text(value->getStart(), value->getStop());
    string_text = string_text.substr(1, string_text.size() - 2);
  }

  if (target->EREF()) {
    // §2.12: En = expression, converted to the class of En.
    auto index = parameter(target->EREF()->getText(), target_range);
    if (!index) return;
    if (string_value)
      return fail(DiagId::TextMismatch, value_range, fmt::format("{} holds a number, not a text", target_text));
    s.target = parameter_expr(*index, target_range);
    s.value = expr(value->expr());
    // A constant that cannot fit is known now (decision 8); others at run time.
    const ParameterClass& c = s_.class_of(*index);
    double v = program_.is_constant(s.value) ? program_.exprs[s.value].number : 0;
    if (program_.is_constant(s.value) && !convert_value(c.type, c.limit, v))
      return fail(DiagId::ValueOverflow, value_range, shortest(program_.exprs[s.value].number),
                  fmt::format("E{} (class {})", *index, c.name));
    block_.stmts.push_back(s);
    return;
  }

  if (target->VARREF()) {
    auto ref = memory_ref(target->VARREF()->getText(), target_range);
    if (!ref) return;
    s.target = memory_expr(*ref, target_range);
    if (ref->chars) {
      // A text: a "quoted" one, padded with blanks to the n characters (decision 19),
      // or another reference of n characters.
      if (string_value) {
        size_t chars = 0;
        for (unsigned char c : string_text) chars += (c & 0xC0) != 0x80;
        if (chars != string_text.size())
          return fail(DiagId::TextMismatch, value_range, "a text in memory holds one byte a character: ASCII only");
        if (chars > ref->chars)
          return fail(DiagId::TextTooLong, value_range, string_text, chars, ref->text, ref->chars);
        string_text.resize(ref->chars, ' ');
        s.value = string_expr(string_text, value_range);
      } else {
        auto* e = value->expr();
        auto* only = e->term().size() == 1 && e->term(0)->factor().size() == 1 && !e->term(0)->factor(0)->PLUS() &&
                             !e->term(0)->factor(0)->MINUS()
                         ? dynamic_cast<Nc110Parser::MemoryPrimaryContext*>(e->term(0)->factor(0)->primary())
                         : nullptr;
        auto source = only ? memory_ref(only->VARREF()->getText(), value_range) : std::nullopt;
        if (!source || source->chars != ref->chars)
          return fail(DiagId::TextMismatch, value_range,
                      fmt::format("{} holds a text of {}: assign a \"text\" or a reference .{}CH", ref->text,
                                  ref->chars, ref->chars));
        s.value = memory_expr(*source, value_range);
      }
      block_.stmts.push_back(s);
      return;
    }
    if (string_value)
      return fail(DiagId::TextMismatch, value_range, fmt::format("{} holds a number, not a text", ref->text));
    s.value = expr(value->expr());
    block_.stmts.push_back(s);
    return;
  }

  // A system variable: TMR = 2, USB = 0, TIM2 = TIM0 - TIM1 (§2.10).
  std::string name = target->NAME()->getText();
  std::optional<uint32_t> number;
  if (!system_number(target->NUMBER(), name, target_range, number)) return;
  const SystemName* entry = nullptr;
  auto ref = system_ref(name, number, target_range, true, &entry);
  if (!ref) return;
  if (string_value)
    return fail(DiagId::TextMismatch, value_range, fmt::format("{} holds a number, not a text", target_text));
  s.target = system_expr(*ref, target_range);
  auto* e = value->expr();
  if (entry->value != "expr") {
    // A constant, or one E parameter of the class the manual gives (§2.10, decision 38).
    auto* f = e->term().size() == 1 && e->term(0)->factor().size() == 1 ? e->term(0)->factor(0) : nullptr;
    auto* number_value = f ? dynamic_cast<Nc110Parser::NumberPrimaryContext*>(f->primary()) : nullptr;
    auto* parameter_value =
        f && !f->PLUS() && !f->MINUS() ? dynamic_cast<Nc110Parser::ParameterPrimaryContext*>(f->primary()) : nullptr;
    std::string cls = entry->value == "flag" ? "BY" : entry->value;
    if (!number_value && !parameter_value)
      return fail(DiagId::ValueForm, value_range, name, fmt::format("a constant or an E parameter of class {}", cls),
                  "an expression is not allowed here");
    if (parameter_value) {
      auto index = parameter(parameter_value->EREF()->getText(), value_range);
      if (!index || !check_class(*index, {cls}, value_range, name)) return;
    }
  }
  s.value = expr(e);
  // A constant the variable cannot hold is found now, by the run's own rule.
  if (program_.is_constant(s.value))
    if (auto why = sys_value_error(*ref, program_.exprs[s.value].number))
      return fail(DiagId::SystemValue, value_range, target_text, shortest(program_.exprs[s.value].number), *why);
  block_.stmts.push_back(s);
}

}  // namespace ncc::nc110
