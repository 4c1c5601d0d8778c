#include "vm.h"

#include <cmath>
#include <limits>

#include "opcodes.h"
#include "support/text.h"
#include "stdlib/builtins.h"

namespace ncc::vm {

namespace {

constexpr size_t kMaxLoops = 64;
constexpr double kMaxRepeat = 2147483647;
constexpr size_t kMaxFrames = 64;

inline uint32_t u32_at(const uint8_t* p) { return read_operand(p, 4); }
inline uint16_t u16_at(const uint8_t* p) { return static_cast<uint16_t>(read_operand(p, 2)); }

// Stores keep the value type of the variable (NC-110's typed E parameters).
bool convert(VarType type, double& v) {
  auto integral = [&](double lo, double hi) {
    v = std::trunc(v);
    return v >= lo && v <= hi;
  };
  switch (type) {
    case VarType::Byte: return integral(-128, 127);
    case VarType::Integer: return integral(-32768, 32767);
    case VarType::Long: return integral(-2147483648.0, 2147483647.0);
    case VarType::Real:
      if (!(std::fabs(v) <= std::numeric_limits<float>::max())) return false;
      v = static_cast<float>(v);
      return true;
    default: return std::isfinite(v);
  }
}


}  // namespace

Vm::Vm(const Module& module, Machine& machine, RuntimeIssues& issues, VmOptions options)
    : m_(module), machine_(machine), issues_(issues), options_(options) {
  for (const VarSpace& s : m_.spaces) vars_.emplace_back(s.size, 0.0);
}

template <typename... Args>
RunStatus Vm::fail(uint32_t pc, DiagId id, const Args&... args) {
  issues_.issue({id, diag_message(id, args...), m_.source_of(pc), 0});
  return RunStatus::Error;
}

double Vm::load(uint8_t space, double index, uint32_t pc, bool& ok) {
  const VarSpace& s = m_.spaces[space];
  if (!(index >= 0 && index < s.size) || index != std::trunc(index)) {
    fail(pc, DiagId::DomainError, fmt::format("index {}", shortest(index)), s.name);
    ok = false;
    return 0;
  }
  return vars_[space][static_cast<size_t>(index)];
}

bool Vm::store(uint8_t space, double index, double value, uint32_t pc) {
  const VarSpace& s = m_.spaces[space];
  if (!(index >= 0 && index < s.size) || index != std::trunc(index)) {
    fail(pc, DiagId::DomainError, fmt::format("index {}", shortest(index)), s.name);
    return false;
  }
  double v = value;
  if (!convert(s.type_of(static_cast<uint32_t>(index)), v)) {
    fail(pc, DiagId::ValueOverflow, shortest(value), fmt::format("{}{}", s.name, shortest(index)));
    return false;
  }
  vars_[space][static_cast<size_t>(index)] = v;
  return true;
}

RunStatus Vm::run(uint32_t entry) {
  Process& p = process_;
  p = Process{};
  p.pc = m_.entries[entry].pc;
  codes_.clear();
  words_.clear();
  const uint8_t* code = m_.code.data();
  std::vector<double>& st = p.stack;
  auto pop = [&] {
    double v = st.back();
    st.pop_back();
    return v;
  };
  // Verified code: opcodes, operands, jumps and stack depths are all in range.
  while (true) {
    const uint32_t pc = p.pc;
    const Op op = static_cast<Op>(code[pc]);
    const uint8_t* operands = code + pc + 1;
    p.pc += static_cast<uint32_t>(instruction_size(op));
    switch (op) {
      case Op::Nop: break;
      case Op::Const: st.push_back(m_.numbers[u32_at(operands)]); break;
      case Op::Load: {
        bool ok = true;
        double v = load(operands[0], u32_at(operands + 1), pc, ok);
        if (!ok) return RunStatus::Error;
        st.push_back(v);
        break;
      }
      case Op::LoadX: {
        bool ok = true;
        double v = load(operands[0], pop(), pc, ok);
        if (!ok) return RunStatus::Error;
        st.push_back(v);
        break;
      }
      case Op::Store:
        if (!store(operands[0], u32_at(operands + 1), pop(), pc)) return RunStatus::Error;
        break;
      case Op::StoreX: {
        double value = pop();
        if (!store(operands[0], pop(), value, pc)) return RunStatus::Error;
        break;
      }
      case Op::Neg: st.back() = -st.back(); break;
      case Op::Not: st.back() = st.back() == 0; break;
      case Op::Add: { double b = pop(); st.back() += b; break; }
      case Op::Sub: { double b = pop(); st.back() -= b; break; }
      case Op::Mul: { double b = pop(); st.back() *= b; break; }
      case Op::Div: {
        double b = pop();
        if (b == 0) return fail(pc, DiagId::DivisionByZero);
        st.back() /= b;
        break;
      }
      case Op::Mod: {
        double b = pop();
        if (b == 0) return fail(pc, DiagId::DivisionByZero);
        st.back() = std::fmod(st.back(), b);
        break;
      }
      case Op::Pow: {
        double b = pop();
        double r = std::pow(st.back(), b);
        if (!std::isfinite(r)) return fail(pc, DiagId::DomainError, shortest(st.back()), "a power");
        st.back() = r;
        break;
      }
      case Op::Eq: { double b = pop(); st.back() = st.back() == b; break; }
      case Op::Ne: { double b = pop(); st.back() = st.back() != b; break; }
      case Op::Lt: { double b = pop(); st.back() = st.back() < b; break; }
      case Op::Le: { double b = pop(); st.back() = st.back() <= b; break; }
      case Op::Gt: { double b = pop(); st.back() = st.back() > b; break; }
      case Op::Ge: { double b = pop(); st.back() = st.back() >= b; break; }
      case Op::And: { double b = pop(); st.back() = st.back() != 0 && b != 0; break; }
      case Op::Or: { double b = pop(); st.back() = st.back() != 0 || b != 0; break; }
      case Op::Xor: { double b = pop(); st.back() = (st.back() != 0) != (b != 0); break; }
      case Op::Call1:
      case Op::Call2: {
        Builtin b = static_cast<Builtin>(operands[0]);
        double args[2];
        int arity = op == Op::Call1 ? 1 : 2;
        for (int i = arity - 1; i >= 0; --i) args[i] = pop();
        double r = 0;
        std::string_view why;
        if (!eval_builtin(b, args, r, why))
          return fail(pc, DiagId::DomainError, shortest(args[0]), fmt::format("{} ({})", builtin_info(b).name, why));
        st.push_back(r);
        break;
      }
      case Op::Jump: p.pc = u32_at(operands); break;
      case Op::JumpIfNot:
        if (pop() == 0) p.pc = u32_at(operands);
        break;
      case Op::JumpIf:
        if (pop() != 0) p.pc = u32_at(operands);
        break;
      case Op::JumpSkip:
        if (options_.block_skip) p.pc = u32_at(operands);
        break;
      case Op::Step:
        if (options_.max_steps && ++steps_ > options_.max_steps) return fail(pc, DiagId::StepLimit, options_.max_steps);
        break;
      case Op::Code: codes_.push_back(u16_at(operands)); break;
      case Op::Word: words_.set(operands[0], m_.numbers[u32_at(operands + 1)]); break;
      case Op::WordPop: {
        double v = pop();
        if (!std::isfinite(v)) return fail(pc, DiagId::DomainError, shortest(v), "word values");
        words_.set(operands[0], v);
        break;
      }
      case Op::Exec: {
        BlockRequest request{codes_.data(), codes_.size(), &words_, m_.source_of(pc)};
        BlockResult result = machine_.execute(request);
        codes_.clear();
        words_.clear();
        switch (result) {
          case BlockResult::Continue: break;
          case BlockResult::ProgramEnd: return RunStatus::ProgramEnd;
          case BlockResult::EndOfInformation: return RunStatus::EndOfInformation;
          case BlockResult::Error: return RunStatus::Error;
        }
        break;
      }
      case Op::Comment: machine_.comment(m_.strings[u32_at(operands)], m_.source_of(pc)); break;
      case Op::Repeat: {
        double count = std::trunc(pop());
        if (!(count <= kMaxRepeat)) return fail(pc, DiagId::DomainError, shortest(count), "repeat counts");
        if (count < 1) {
          p.pc = u32_at(operands);
          break;
        }
        if (p.loops.size() >= kMaxLoops) return fail(pc, DiagId::CallDepth, kMaxLoops);
        p.loops.push_back({static_cast<int64_t>(count)});
        break;
      }
      case Op::EndRepeat:
        if (p.loops.size() <= (p.frames.empty() ? 0 : p.frames.back().loops))
          return fail(pc, DiagId::BytecodeInvalid, "program", "an end of repeat without its repeat");
        if (--p.loops.back().remaining > 0) p.pc = u32_at(operands);
        else p.loops.pop_back();
        break;
      case Op::CallEntry:
        if (p.frames.size() >= kMaxFrames) return fail(pc, DiagId::CallDepth, kMaxFrames);
        p.frames.push_back({p.pc, p.loops.size()});
        p.pc = m_.entries[u16_at(operands)].pc;
        break;
      case Op::Return:
        if (p.frames.empty()) {
          p.pc = pc;
          return RunStatus::UnitEnded;
        }
        p.loops.resize(p.frames.back().loops);
        p.pc = p.frames.back().return_pc;
        p.frames.pop_back();
        break;
      case Op::End:
        p.pc = pc;
        return RunStatus::UnitEnded;
      case Op::Count: return fail(pc, DiagId::BytecodeInvalid, "program", "an unknown opcode");
    }
  }
}

}  // namespace ncc::vm
