// `ncc disasm`: a bytecode file as readable text, one instruction per line with its
// operands resolved and the source block it came from.
#include <fmt/format.h>

#include "support/text.h"

#include "contract/builtins.h"
#include "contract/system_vars.h"
#include "module.h"
#include "opcodes.h"
#include "support/diagnostics.h"

namespace ncc::vm {

namespace {

constexpr std::string_view kFormatNames[] = {"bit", "byte", "int16", "int32", "float", "double"};
static_assert(std::size(kFormatNames) == static_cast<size_t>(MemFormat::Count));
constexpr std::string_view kTypeNames[] = {"long_real", "real", "byte", "integer", "long", "thousandths"};
static_assert(std::size(kTypeNames) == kShownTypes);

std::string source_text(const Module& m, uint32_t source) {
  if (source >= m.source_map.size()) return "?";
  const SourceBlock b = m.source_map.block(source);
  std::string s = fmt::format("{}:{}:{}", m.source_map.files[b.file], b.line, b.col);
  if (b.has_number) s += fmt::format(" {}{}", b.main_block ? ':' : 'N', b.number);
  return s;
}

std::string calls_text(const CodeDesc& c) {
  std::string s;
  for (const FnCall& call : c.calls) {
    if (!s.empty()) s += '+';
    s += fn_name(call.fn);
    if (call.fn == Fn::WorkOffset || call.fn == Fn::Cycle) s += fmt::format("({})", call.arg);
  }
  return s;
}

// An operand as text, by its kind (verified: in range).
std::string operand_text(const Module& m, Operand kind, uint32_t v, uint32_t places) {
  switch (kind) {
    case Operand::Number: return shortest(m.numbers[v]);
    case Operand::String: return "\"" + json_escape(m.strings[v]) + "\"";
    case Operand::Code: return m.semantics.codes[v].name;
    case Operand::Slot: return slot_name(static_cast<int>(v));
    case Operand::Target: return fmt::format("-> {}", v);
    case Operand::Entry: return m.entries[v].name;
    case Operand::Space: return m.spaces[v].name;
    case Operand::Index: return fmt::format("[{}]", v);
    case Operand::Builtin: return std::string(builtin_info(static_cast<Builtin>(v)).name);
    case Operand::Format: return std::string(kFormatNames[v]);
    case Operand::Type: return std::string(kTypeNames[v]);
    case Operand::Bytes:
    case Operand::Relation:
    case Operand::LoopDepth:
    case Operand::Rule: return fmt::format("{}", v);
    case Operand::SysVar: {
      const SysRef ref = SysRef::unpack(static_cast<uint16_t>(v));
      std::string s(sys_name(ref.var));
      if (sys_indices(ref.var) > 1) s += fmt::format("[{}]", ref.index);
      return s;
    }
    case Operand::Places: break;  // shown with its digits
    case Operand::Digits: return shortest(decimal(places, static_cast<int32_t>(v)));
    case Operand::Service: return std::string(service_info(static_cast<Service>(v)).name);
    case Operand::Count: break;
  }
  return "?";
}

}  // namespace

std::string disassemble(const Module& m) {
  std::string out = fmt::format("; ncc bytecode format {}, dialect {}, profile {}\n", kFormatVersion, m.dialect,
                                m.profile_name.empty() ? "default" : m.profile_name);
  out += fmt::format("; {} bytes of code, {} numbers, {} strings, {} codes, {} source blocks\n", m.code.size(),
                     m.numbers.size(), m.strings.size(), m.semantics.codes.size(), m.source_map.size());
  out += "; codes\n";
  for (size_t i = 0; i < m.semantics.codes.size(); ++i) {
    const CodeDesc& c = m.semantics.codes[i];
    out += fmt::format(";   c{:<3} {:<6} {}{} {}\n", i, c.name, c.scope == Scope::Block ? "block" : "modal",
                       c.timing == Timing::Before  ? " before"
                       : c.timing == Timing::After ? " after"
                                                   : "",
                       calls_text(c));
  }
  out += "; power-on:";
  for (uint16_t i : m.semantics.power_on) out += fmt::format(" c{}", i);
  out += "\n; entries\n";
  for (const Entry& e : m.entries) {
    static constexpr const char* kKinds[] = {"program", "main block", "subprogram", "process"};
    out += fmt::format(";   {:<10} {:<10} at {}", e.name, kKinds[static_cast<int>(e.kind)], e.pc);
    for (int n = 1; n <= kMaxProcesses; ++n)
      if (e.processes >> (n - 1) & 1) out += fmt::format(", started in process {}", n);
    out += "\n";
  }
  out += "; code\n";
  size_t line = 0;
  for (uint32_t pc = 0; pc < m.code.size();) {
    for (const Entry& e : m.entries)
      if (e.pc == pc) out += fmt::format("{}:\n", e.name);
    while (line < m.lines.size() && m.lines[line].pc <= pc) {
      if (m.lines[line].pc == pc) out += fmt::format("      ; {}\n", source_text(m, m.lines[line].source));
      ++line;
    }
    // A SERVICE shows its service's name, then the service's operands.
    const OpInfo& info = op_info(static_cast<Op>(m.code[pc]));
    std::string operands;
    uint32_t at = pc + 1;
    uint32_t places = 0;
    for (char f : instruction_info(&m.code[pc]).format) {
      uint32_t v = read_operand(&m.code[at], operand_size(f));
      at += static_cast<uint32_t>(operand_size(f));
      if (operand_kind(f) == Operand::Places) {  // shown with its digits: WORDDEC X, 12.5
        places = v;
        continue;
      }
      if (!operands.empty()) operands += ", ";
      operands += operand_text(m, operand_kind(f), v, places);
    }
    // A name of ten letters or more keeps a blank before its operands.
    out += fmt::format("{:5}  {:<10}{}{}\n", pc, info.name, info.name.size() >= 10 && !operands.empty() ? " " : "",
                       operands);
    pc = at;
  }
  return out;
}

}  // namespace ncc::vm
