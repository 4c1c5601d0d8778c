// `ncc ir`: the IR as stable text (docs/ir.md). Golden tests read it, so the format
// changes only on purpose.
#include <fmt/format.h>

#include <algorithm>

#include "support/text.h"

#include "ir.h"
#include "support/diagnostics.h"

namespace ncc::ir {

namespace {

const char* op_name(ExprOp op) {
  switch (op) {
    case ExprOp::Neg: return "neg";
    case ExprOp::ZeroIfVacant: return "or0";
    case ExprOp::Not: return "not";
    case ExprOp::Add: return "+";
    case ExprOp::Sub: return "-";
    case ExprOp::Mul: return "*";
    case ExprOp::Div: return "/";
    case ExprOp::Mod: return "mod";
    case ExprOp::Pow: return "pow";
    case ExprOp::Eq: return "==";
    case ExprOp::Ne: return "!=";
    case ExprOp::Lt: return "<";
    case ExprOp::Le: return "<=";
    case ExprOp::Gt: return ">";
    case ExprOp::Ge: return ">=";
    case ExprOp::And: return "and";
    case ExprOp::Or: return "or";
    case ExprOp::Xor: return "xor";
    default: return "?";
  }
}

std::string range_text(const SourceRange& r) { return fmt::format("{}:{}", r.line, r.col); }

template <typename E>
const char* pick(E value, std::initializer_list<const char*> names) {
  return names.begin()[static_cast<size_t>(value)];
}

std::string code_text(const CodeDesc& c) {
  std::string out = fmt::format("{} {}", c.name, c.scope == Scope::Block ? "block" : "modal");
  if (c.timing != Timing::None) out += c.timing == Timing::Before ? " before" : " after";
  std::string calls;
  for (const FnCall& call : c.calls) {
    if (!calls.empty()) calls += '+';
    calls += fn_name(call.fn);
    if (call.fn == Fn::WorkOffset || call.fn == Fn::Cycle) calls += fmt::format("({})", call.arg);
  }
  return out + " " + calls;
}

}  // namespace

std::string print_expr(const Program& p, ExprId id) {
  if (id == kNoExpr) return "<none>";
  const Expr& e = p.exprs[id];
  switch (e.op) {
    case ExprOp::Number: return shortest(e.number);
    case ExprOp::Var: {
      const std::string& space = e.space < p.spaces.size() ? p.spaces[e.space].name : "?";
      if (p.is_constant(e.a)) return space + shortest(p.exprs[e.a].number);
      return fmt::format("{}[{}]", space, print_expr(p, e.a));
    }
    case ExprOp::Neg:
    case ExprOp::Not:
    case ExprOp::ZeroIfVacant: return fmt::format("({} {})", op_name(e.op), print_expr(p, e.a));
    case ExprOp::Mem: {
      constexpr const char* formats[] = {"BL", "BY", "IN", "LI", "RE", "LR"};
      return fmt::format("{}[{}].{}", p.spaces[e.space].name, print_expr(p, e.a), formats[static_cast<int>(e.format)]);
    }
    case ExprOp::Text: return fmt::format("{}[{}].{}CH", p.spaces[e.space].name, print_expr(p, e.a), e.count);
    case ExprOp::Sys: {
      SysRef ref = SysRef::unpack(e.sys);
      std::string name(sys_name(ref.var));
      return sys_indices(ref.var) > 1 ? fmt::format("{}[{}]", name, ref.index) : name;
    }
    case ExprOp::String: return "\"" + json_escape(p.texts[e.text]) + "\"";
    case ExprOp::TextEq: return fmt::format("(text== {} {})", print_expr(p, e.a), print_expr(p, e.b));
    case ExprOp::Check: {
      const ValueRule* rule = e.rule < p.semantics.value_rules.size() ? &p.semantics.value_rules[e.rule] : nullptr;
      return rule ? fmt::format("(check {} {} {}..{}{})", rule->address, print_expr(p, e.a), shortest(rule->lo),
                                shortest(rule->hi), rule->whole ? " whole" : "")
                  : fmt::format("(check ? {})", print_expr(p, e.a));
    }
    case ExprOp::Call:
      if (builtin_info(e.builtin).arity == 2)
        return fmt::format("({} {} {})", builtin_info(e.builtin).name, print_expr(p, e.a), print_expr(p, e.b));
      return fmt::format("({} {})", builtin_info(e.builtin).name, print_expr(p, e.a));
    default: return fmt::format("({} {} {})", op_name(e.op), print_expr(p, e.a), print_expr(p, e.b));
  }
}

std::string print(const Program& p, const SourceManager& sources) {
  std::string out = fmt::format("ir {}\n", p.dialect);
  const Conventions& c = p.semantics.conventions;
  auto letter = [](char l) { return l ? std::string(1, l) : std::string("-"); };
  out += fmt::format(
      "conventions arc_centre={} helix_lead={} parabola={} angle={} dwell={}*{}s peck={} cycle_level={} "
      "pitch_change={} thread_j={} single_quadrant={} arc_tolerance={} lead_resolution={} m06_stops_spindle={} "
      "length_axes={} "
      "axes={}\n",
      pick(c.arc_centre, {"incremental", "absolute"}), pick(c.helix_lead, {"per_radian", "per_revolution"}),
      pick(c.parabola_tangent, {"coordinates", "incremental"}), pick(c.angle_unit, {"deg", "rad", "rev"}),
      letter(c.dwell_word), shortest(c.dwell_seconds_per_unit), letter(c.peck_word), letter(c.cycle_level_word),
      letter(c.pitch_change_word), c.thread_allow_j, c.arc_single_quadrant, shortest(c.arc_tolerance),
      shortest(c.lead_resolution), c.m06_stops_spindle, c.tool_offset_axes, c.axes);
  for (size_t i = 0; i < p.semantics.cycles.size(); ++i) {
    const CyclePattern& cy = p.semantics.cycles[i];
    out += fmt::format("cycle #{} {} in={} dwell={} bottom={} out={}\n", i, cy.name,
                       pick(cy.in, {"feed", "peck", "spindle_feed", "chip_break", "tap_cw", "tap_ccw", "back"}),
                       cy.dwell ? "yes" : "no", pick(cy.bottom, {"-", "reverse", "stop", "orient_shift"}),
                       pick(cy.out, {"rapid", "feed", "manual"}));
  }
  for (size_t i = 0; i < p.semantics.codes.size(); ++i)
    out += fmt::format("code #{} {}\n", i, code_text(p.semantics.codes[i]));
  out += "power_on";
  for (uint16_t i : p.semantics.power_on) out += fmt::format(" {}", p.semantics.codes[i].name);
  out += "\n";
  for (const VarSpace& s : p.spaces)
    out += fmt::format("space {} size={}{}{}{}\n", s.name, s.size, s.memory ? " memory" : "",
                       s.locals == 0        ? std::string()
                       : s.locals >= s.size ? std::string(" local")
                                            : fmt::format(" locals={}", s.locals),
                       s.vacant ? " vacant" : "");

  for (const Unit& u : p.units) {
    const char* kind = pick(u.kind, {"program", "subprogram", "macro", "process"});
    std::string file = u.range.file < sources.size() ? sources.file(u.range.file).path() : "?";
    out += fmt::format("unit {} {} @{}:{}", kind, u.name, file, range_text(u.range));
    if (!u.title.empty()) out += " \"" + json_escape(u.title) + "\"";
    if (u.ends_information) out += " end_of_information";
    out += "\n";
    for (const Block& b : u.blocks) {
      out += fmt::format("  block @{}", range_text(b.range));
      if (b.number) out += fmt::format(" {}{}", b.main_block ? ":" : "N", *b.number);
      if (b.skippable) out += " skippable";
      if (b.sync) out += fmt::format(" sync{}", b.sync);
      if (b.waits_motion && b.sync != '#') out += " waits_motion";
      if (b.has_errors) out += " has_errors";
      if (!b.label.empty()) out += fmt::format(" label=\"{}\"", b.label);
      out += "\n";
      // Text the dialect does not show the operator (an NC-110 ';' block).
      bool shown =
          std::any_of(b.stmts.begin(), b.stmts.end(), [](const Stmt& s) { return s.kind == StmtKind::Comment; });
      if (!shown)
        for (const std::string& text : b.comments) out += fmt::format("    note \"{}\"\n", json_escape(text));
      if (!b.words.empty()) {
        out += "    words";
        for (const Word& w : b.words) out += fmt::format(" {}{}{}", w.optional ? "/" : "", w.address, w.text);
        out += "\n";
      }
      for (const Stmt& s : b.stmts) {
        if (s.cond != kNoExpr && s.kind != StmtKind::Jump) out += fmt::format("    if {}:\n", print_expr(p, s.cond));
        switch (s.kind) {
          case StmtKind::Comment:
            out += fmt::format("    comment {}\"{}\"\n", s.optional ? "/" : "", json_escape(s.label));
            break;
          case StmtKind::Machine: {
            out += "    machine";
            for (const Word& w : b.words) {
              if (w.kind != WordKind::Code && w.kind != WordKind::Parameter) continue;
              out += ' ';
              if (w.optional) out += '/';
              if (w.kind == WordKind::Code && w.code == kDynamicCode)
                out += fmt::format("{}={}", w.address, print_expr(p, w.value));  // the code comes at run time
              else if (w.kind == WordKind::Code)
                out += w.code >= 0 ? p.semantics.codes[w.code].name : w.address + w.text + "{undefined}";
              else
                out += fmt::format("{}={}", w.address, print_expr(p, w.value));
            }
            out += "\n";
            break;
          }
          case StmtKind::Assign:
            out += fmt::format("    assign {} = {}\n", print_expr(p, s.target), print_expr(p, s.value));
            break;
          case StmtKind::Jump:
            out += s.label.empty() ? fmt::format("    goto N[{}]", print_expr(p, s.value))
                                   : fmt::format("    goto {}", s.label);
            if (s.cond != kNoExpr) out += " if " + print_expr(p, s.cond);
            out += "\n";
            break;
          case StmtKind::RepeatBegin: out += fmt::format("    repeat {}\n", print_expr(p, s.value)); break;
          case StmtKind::RepeatEnd: out += "    end_repeat\n"; break;
          case StmtKind::Call:
            out += fmt::format("    call {} x{}{}", s.label, print_expr(p, s.value), s.shares_locals ? " shared" : "");
            for (const CallArg& a : s.args)
              out += fmt::format(" {}{}={}", p.spaces[a.space].name, a.index, print_expr(p, a.value));
            out += "\n";
            break;
          case StmtKind::Return: out += "    return\n"; break;
          case StmtKind::CallRange: out += fmt::format("    call_range {} {}\n", s.label, s.end_label); break;
          case StmtKind::Display: {
            out += "    display";
            for (const DisplayItem& item : s.items) out += " " + print_expr(p, item.value);
            out += "\n";
            break;
          }
          case StmtKind::Service: {
            out += fmt::format("    service {}", service_info(s.service).name);
            if (!s.label.empty()) out += fmt::format(" \"{}\"", json_escape(s.label));
            if (s.target != kNoExpr) out += " " + print_expr(p, s.target);
            if (s.value != kNoExpr) out += " " + print_expr(p, s.value);
            for (const DisplayItem& item : s.items) out += " " + print_expr(p, item.value);
            out += "\n";
            break;
          }
        }
      }
    }
  }
  return out;
}

}  // namespace ncc::ir
