#include "vm.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "contract/builtins.h"
#include "opcodes.h"
#include "support/numbers.h"
#include "support/text.h"

namespace ncc::vm {

namespace {

constexpr size_t kMaxLoops = 64;
constexpr int64_t kMaxRepeat = 2147483647;
constexpr size_t kMaxFrames = 64;
const double kVacant = std::numeric_limits<double>::quiet_NaN();
constexpr int64_t kMaxCallCount = 9999;  // pp Q (the largest count a dialect writes)

inline uint32_t u32_at(const uint8_t* p) { return read_operand(p, 4); }
inline uint16_t u16_at(const uint8_t* p) { return static_cast<uint16_t>(read_operand(p, 2)); }

// Memories are little-endian whatever the host is.
template <typename T>
T read_le(const uint8_t* p) {
  using U = std::make_unsigned_t<T>;
  U v = 0;
  for (size_t i = 0; i < sizeof(T); ++i) v = static_cast<U>(v | U(p[i]) << (8 * i));
  return static_cast<T>(v);
}

template <typename T>
void write_le(uint8_t* p, T value) {
  auto v = static_cast<std::make_unsigned_t<T>>(value);
  for (size_t i = 0; i < sizeof(T); ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}

// The byte where element `index` of a memory in format f begins (bits: eight to a
// byte), for bytes(); an index that is no element (a fraction, a negative) as it is,
// which bytes() refuses.
double first_byte(double index, MemFormat f) {
  const std::optional<uint64_t> i = whole_in<uint64_t>(index, 0, UINT64_MAX);
  if (!i) return index;
  return f == MemFormat::Bit ? static_cast<double>(*i / 8) : static_cast<double>(*i) * mem_size(f);
}
// The bit in its byte of bit `index`, which first_byte() has found in the memory.
uint32_t bit_of(double index) {
  return static_cast<uint32_t>(whole_in<uint64_t>(index, 0, UINT64_MAX).value_or(0) % 8);
}

// How DIS shows a value of each type (NC-110 D20).
std::string show(VarType type, double v) {
  switch (type) {
    case VarType::Byte:
    case VarType::Integer:
    case VarType::Long:
      if (auto n = whole_in<int64_t>(std::trunc(v), INT64_MIN, INT64_MAX)) return fmt::format("{}", *n);
      return fmt::format("{:.10g}", v);  // only a hostile file gets here: no integer type holds it
    case VarType::Real: return fmt::format("{:.7g}", v == 0 ? 0.0 : v);
    default: return fmt::format("{:.10g}", v == 0 ? 0.0 : v);
  }
}

}  // namespace

Vm::Vm(const Module& module, BlockMachine& machine, RuntimeIssues& issues, VmOptions options)
    : m_(module), machine_(machine), issues_(issues), options_(options),
      shared_(options.shared ? *options.shared : own_) {
  const bool fresh = shared_.memories.empty();
  for (const VarSpace& s : m_.spaces) {
    vars_.emplace_back(s.memory ? 0 : s.size, s.vacant ? kVacant : 0.0);
    vacancy_ = vacancy_ || s.vacant;
    // Later ranges override earlier ones, as in type_of.
    std::vector<VarType>& types = types_.emplace_back();
    if (!s.memory && !s.types.empty()) {
      types.assign(s.size, VarType::LongReal);
      for (const VarSpace::Range& r : s.types)
        if (r.first < s.size) std::fill(types.begin() + r.first, types.end(), r.type);
    }
    if (fresh) shared_.memories.emplace_back(s.memory ? s.size : 0, uint8_t{0});
  }
}

template <typename... Args>
void Vm::report_error(uint32_t pc, DiagIdFor<Args...> id, const Args&... args) {
  issues_.issue({id.id(), diag_message(id, args...), m_.source_of(pc), -1, -1, 0});
}

template <typename... Args>
RunStatus Vm::fail(uint32_t pc, DiagIdFor<Args...> id, const Args&... args) {
  report_error(pc, id, args...);
  return RunStatus::Error;
}

template <typename... Args>
RunStatus Vm::fail_at(uint32_t pc, int slot, int nth, DiagIdFor<Args...> id, const Args&... args) {
  issues_.issue({id.id(), diag_message(id, args...), m_.source_of(pc), slot, -1, nth});
  return RunStatus::Error;
}

std::optional<uint32_t> Vm::variable(uint8_t space, double index, uint32_t pc) {
  const VarSpace& s = m_.spaces[space];
  const std::optional<uint32_t> i = s.size ? whole_in<uint32_t>(index, 0, s.size - 1) : std::nullopt;
  if (!i)
    report_error(
        pc, DiagId::DomainError, fmt::format("index {}", shortest(index)),
        s.size ? fmt::format("{}: 0 to {}", s.name, s.size - 1) : fmt::format("{}, which has no variables", s.name));
  else if (type_at(space, *i) == VarType::Unavailable)
    return (report_error(pc, DiagId::VariableNumber, *i), std::nullopt);
  return i;
}

double Vm::load(uint8_t space, double index, uint32_t pc, bool& ok) {
  const std::optional<uint32_t> i = variable(space, index, pc);
  ok = i.has_value();
  return i ? vars_[space][*i] : 0;
}

bool Vm::store(uint8_t space, double index, double value, uint32_t pc) {
  const VarSpace& s = m_.spaces[space];
  if (s.vacant && index == 0) {
    report_error(pc, DiagId::VacantVariable, fmt::format("{}0", s.name));
    return false;
  }
  const std::optional<uint32_t> i = variable(space, index, pc);
  if (!i) return false;
  if (s.vacant && std::isnan(value)) {
    vars_[space][*i] = kVacant;
    return true;
  }
  double v = value;
  if (!convert_value(type_at(space, *i), s.limit, v)) {
    report_error(pc, DiagId::ValueOverflow, shortest(value), fmt::format("{}{}", s.name, *i));
    return false;
  }
  vars_[space][*i] = v;
  return true;
}

uint8_t* Vm::bytes(uint8_t space, double index, uint32_t count, uint32_t pc) {
  const VarSpace& s = m_.spaces[space];
  const std::optional<uint32_t> at = count <= s.size ? whole_in<uint32_t>(index, 0, s.size - count) : std::nullopt;
  if (!at) {
    report_error(pc, DiagId::MemoryRange, s.name, shortest(index), count, s.size);
    return nullptr;
  }
  return shared_.memories[space].data() + *at;
}

bool Vm::load_mem(uint8_t space, MemFormat f, double index, uint32_t pc, double& out) {
  const uint8_t* p = bytes(space, first_byte(index, f), mem_size(f), pc);
  if (!p) return false;
  switch (f) {
    case MemFormat::Bit: out = (*p >> bit_of(index)) & 1; break;
    case MemFormat::Byte: out = *p; break;
    case MemFormat::Integer: out = read_le<int16_t>(p); break;
    case MemFormat::Long: out = read_le<int32_t>(p); break;
    case MemFormat::Real: out = std::bit_cast<float>(read_le<uint32_t>(p)); break;
    default: out = std::bit_cast<double>(read_le<uint64_t>(p)); break;
  }
  return true;
}

bool Vm::store_mem(uint8_t space, MemFormat f, double index, double value, uint32_t pc) {
  const VarSpace& s = m_.spaces[space];
  double v = value;
  static constexpr VarType kTypes[] = {VarType::Byte, VarType::Byte, VarType::Integer,
                                       VarType::Long, VarType::Real, VarType::LongReal};
  bool fits = f == MemFormat::Bit ? (v == 0 || v == 1) : convert_value(kTypes[static_cast<int>(f)], 0, v);
  if (!fits) {
    static constexpr const char* kNames[] = {"BL", "BY", "IN", "LI", "RE", "LR"};
    report_error(pc, DiagId::ValueOverflow, shortest(value),
                 fmt::format("{}{}.{}", s.name, shortest(index), kNames[static_cast<int>(f)]));
    return false;
  }
  uint8_t* p = bytes(space, first_byte(index, f), mem_size(f), pc);
  if (!p) return false;
  wrote_memory();
  switch (f) {
    case MemFormat::Bit: {
      const auto bit = static_cast<uint8_t>(1u << bit_of(index));
      *p = v != 0 ? (*p | bit) : (*p & ~bit);
      break;
    }
    case MemFormat::Byte: *p = static_cast<uint8_t>(v); break;  // convert_value made it a whole number that fits
    case MemFormat::Integer: write_le(p, static_cast<int16_t>(v)); break;
    case MemFormat::Long: write_le(p, static_cast<int32_t>(v)); break;
    case MemFormat::Real: write_le(p, std::bit_cast<uint32_t>(static_cast<float>(v))); break;
    default: write_le(p, std::bit_cast<uint64_t>(v)); break;
  }
  return true;
}

std::vector<double> Vm::take_locals(const std::vector<Arg>& args) {
  std::vector<double> saved;
  for (size_t i = 0; i < m_.spaces.size(); ++i)
    if (const VarSpace& s = m_.spaces[i]; s.locals) {
      auto end = vars_[i].begin() + static_cast<std::ptrdiff_t>(s.locals);
      saved.insert(saved.end(), vars_[i].begin(), end);
      std::fill(vars_[i].begin(), end, s.vacant ? kVacant : 0.0);
    }
  for (const Arg& a : args) vars_[a.space][a.index] = a.value;
  return saved;
}

void Vm::restore_locals(const std::vector<double>& saved) {
  auto from = saved.begin();
  for (size_t i = 0; i < m_.spaces.size(); ++i)
    if (const VarSpace& s = m_.spaces[i]; s.locals) {
      std::copy(from, from + static_cast<std::ptrdiff_t>(s.locals), vars_[i].begin());
      from += static_cast<std::ptrdiff_t>(s.locals);
    }
}

// The block is evaluated once the look-ahead has room: when the block look_ahead
// blocks back has ended its motion, and a block cycle after the block before (a
// controller takes time to run a block: a loop that does not move lets the others on).
void Vm::look_ahead() {
  const size_t n = options_.look_ahead;
  if (ends_.empty()) ends_.assign(n, 0);
  const uint64_t k = steps_ + 1;                     // this block, counted from 1
  if (k > 1) ends_[(k - 2) % n] = machine_.clock();  // the block before ended its motion then
  eval_ += kBlockCycle;
  if (k > n) eval_ = std::max(eval_, ends_[(k - 1) % n]);
}

size_t Vm::calls() const {
  size_t n = 0;
  for (const Frame& f : process_.frames) n += !f.range;
  return n;
}

// A jump that leaves the range being run ends it (NC-110 §2.13.2.3).
void Vm::jump_to(uint32_t target) {
  Process& p = process_;
  while (!p.frames.empty() && p.frames.back().range &&
         (target < p.frames.back().start || target > p.frames.back().end)) {
    if (p.loops.size() > p.frames.back().loops) p.loops.resize(p.frames.back().loops);
    p.frames.pop_back();
  }
  if (landing_depth_) {
    size_t keep = (p.frames.empty() ? 0 : p.frames.back().base) + *landing_depth_;
    if (p.loops.size() > keep) p.loops.resize(keep);
    landing_depth_.reset();
  }
  p.pc = target;
}

void Vm::start(uint32_t entry) {
  process_ = Process{};
  process_.pc = m_.entries[entry].pc;
  codes_.clear();
  words_.clear();
  args_.clear();
  waiting_ = false;
  mid_block_ = false;
}

RunStatus Vm::resume() {
  Process& p = process_;
  // A turn is one block: it ends at the next Step, or at this block's end when the
  // turn goes on with an instruction that waited.
  bool stepped = waiting_ || mid_block_;
  mid_block_ = false;
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
      case Op::ConstDec: st.push_back(decimal_at(operands)); break;
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
      case Op::Add: {
        double b = pop();
        st.back() += b;
        break;
      }
      case Op::Sub: {
        double b = pop();
        st.back() -= b;
        break;
      }
      case Op::Mul: {
        double b = pop();
        st.back() *= b;
        break;
      }
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
      // Two vacant values are equal (Macro B: `#1 EQ #0` is true when #1 is vacant).
      case Op::Eq: {
        double b = pop();
        st.back() = st.back() == b || (std::isnan(b) && std::isnan(st.back()));
        break;
      }
      case Op::Ne: {
        double b = pop();
        st.back() = !(st.back() == b || (std::isnan(b) && std::isnan(st.back())));
        break;
      }
      case Op::Lt: {
        double b = pop();
        st.back() = st.back() < b;
        break;
      }
      case Op::Le: {
        double b = pop();
        st.back() = st.back() <= b;
        break;
      }
      case Op::Gt: {
        double b = pop();
        st.back() = st.back() > b;
        break;
      }
      case Op::Ge: {
        double b = pop();
        st.back() = st.back() >= b;
        break;
      }
      case Op::And: {
        double b = pop();
        st.back() = st.back() != 0 && b != 0;
        break;
      }
      case Op::Or: {
        double b = pop();
        st.back() = st.back() != 0 || b != 0;
        break;
      }
      case Op::Xor: {
        double b = pop();
        st.back() = (st.back() != 0) != (b != 0);
        break;
      }
      case Op::Call1:
      case Op::Call2: {
        Builtin b = static_cast<Builtin>(operands[0]);
        double args[2];
        int arity = op == Op::Call1 ? 1 : 2;
        for (int i = arity - 1; i >= 0; --i) args[i] = pop();
        double r = 0;
        std::string_view why;
        bool ok = eval_builtin(b, args, r, why);
        // FEP, FEL, FEC read the runtime's GTL store (their arguments checked).
        if (!ok && why == "undefined") {
          const int kind = b == Builtin::GtlPoint ? 1 : b == Builtin::GtlLine ? 2 : 3;  // gtl::Kind
          ok = machine_.gtl_field(kind, args[0], args[1], r);
        }
        if (!ok) {
          if (why == "undefined")
            return fail(pc, DiagId::GtlElementUndefined,
                        b == Builtin::GtlLine    ? 'l'
                        : b == Builtin::GtlPoint ? 'p'
                                                 : 'c',
                        shortest(args[0]));
          // The GTL functions' second argument is the field.
          bool field = b >= Builtin::GtlLine && !why.starts_with("element");
          // By the dialect's name of the function, as the program writes it.
          const auto& names = m_.semantics.builtin_names;
          const size_t i = static_cast<size_t>(b);
          std::string_view name =
              i < names.size() && !names[i].empty() ? std::string_view(names[i]) : builtin_info(b).name;
          return fail(pc, DiagId::DomainError, shortest(args[field ? 1 : 0]), fmt::format("{} ({})", name, why));
        }
        st.push_back(r);
        break;
      }
      case Op::Jump: jump_to(u32_at(operands)); break;
      case Op::JumpIfNot:
        if (pop() == 0) jump_to(u32_at(operands));
        break;
      case Op::JumpIf:
        if (pop() != 0) jump_to(u32_at(operands));
        break;
      case Op::JumpSkip:
        if (machine_.block_skip()) p.pc = u32_at(operands);
        break;
      case Op::Step:
        if ((options_.slice || options_.by_block) && stepped) {
          p.pc = pc;
          return RunStatus::Yield;
        }
        stepped = true;
        if (options_.look_ahead) look_ahead();
        if (++steps_ + machine_.moves_beyond_first() > options_.max_steps && options_.max_steps)
          return fail(pc, DiagId::StepLimit, options_.max_steps);
        if (options_.max_memory && machine_.held_bytes() > options_.max_memory)
          return fail(pc, DiagId::RunMemory, options_.max_memory >> 20, machine_.held_what());
        // A block that the block-skip switch skips whole (its JUMPSKIP follows) does not run.
        if (options_.trace_blocks &&
            !(p.pc < m_.code.size() && static_cast<Op>(code[p.pc]) == Op::JumpSkip && machine_.block_skip()))
          machine_.block_start(m_.source_of(pc));
        break;
      case Op::Sync:
        // In turns, a block that waits for the motion lets the processes behind it in
        // time go first.
        if (machine_.clock() > eval_ && options_.slice) {
          eval_ = machine_.clock();
          mid_block_ = true;
          return RunStatus::Yield;
        }
        eval_ = std::max(eval_, machine_.clock());
        break;
      case Op::Code:
        if (codes_.size() >= 64) return fail(pc, DiagId::BytecodeInvalid, "program", "more than 64 codes in a block");
        codes_.push_back(u16_at(operands));
        break;
      case Op::Check: {
        const ValueRule& rule = m_.semantics.value_rules[operands[1]];
        const double v = st.back();
        if (!(v >= rule.lo && v <= rule.hi) || (rule.whole && v != std::trunc(v)))
          return fail_at(pc, operands[0], 0, DiagId::ParameterValue, rule.address, shortest(v),
                         fmt::format("{} from {} to {}", rule.whole ? "whole numbers" : "values", shortest(rule.lo),
                                     shortest(rule.hi)));
        break;
      }
      case Op::CodeOf: {
        double v = pop();
        if (vacancy_ && std::isnan(v)) break;  // G#1 with #1 vacant: no code
        const auto& numbered = m_.semantics.numbered;
        const int key = code_key(v).value_or(-1);  // G#1 with #1 = 54.1 is G54.1
        auto it = std::find_if(numbered.begin(), numbered.end(),
                               [&](const NumberedCode& c) { return c.slot == operands[0] && c.number == key; });
        // The word is found by its slot and its place among this block's (GE1 GE2).
        const int nth = static_cast<int>(std::count(dynamic_slots_.begin(), dynamic_slots_.end(), operands[0]));
        if (it == numbered.end()) {
          // As the table writes it: G05.
          const std::optional<int> two_digits = whole_in(v, 0, 99);
          return fail_at(pc, operands[0], nth, DiagId::CodeUnknown, slot_name(operands[0]),
                         two_digits ? fmt::format("{:02}", *two_digits) : shortest(v));
        }
        if (codes_.size() >= 64) return fail(pc, DiagId::BytecodeInvalid, "program", "more than 64 codes in a block");
        dynamic_codes_ |= uint64_t{1} << codes_.size();
        dynamic_slots_.push_back(operands[0]);
        codes_.push_back(it->code);
        break;
      }
      case Op::Word: words_.set(operands[0], m_.numbers[u32_at(operands + 1)]); break;
      case Op::WordDec: words_.set(operands[0], decimal_at(operands + 1)); break;
      case Op::WordPop: {
        double v = pop();
        if (vacancy_ && std::isnan(v)) break;  // X#1 with #1 vacant: no X word
        if (!std::isfinite(v)) return fail(pc, DiagId::DomainError, shortest(v), "word values");
        words_.set(operands[0], v);
        break;
      }
      case Op::Exec: {
        if (options_.look_ahead) machine_.wait_until(eval_);  // a move does not start before its block is evaluated
        BlockRequest request{codes_.data(), codes_.size(), &words_, m_.source_of(pc), dynamic_codes_};
        BlockResult result = machine_.execute(request);
        codes_.clear();
        words_.clear();
        dynamic_codes_ = 0;
        dynamic_slots_.clear();
        // Measured values the block stores (NC-110 G72-G74), where the dialect keeps them.
        for (auto [index, value] : machine_.take_results()) {
          if (m_.semantics.conventions.result_space == kNoSpace)
            return fail(pc, DiagId::BytecodeInvalid, "program",
                        "a measuring code in a dialect with no place for its values");
          if (!store(m_.semantics.conventions.result_space, index, value, pc)) return RunStatus::Error;
        }
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
        const double count = pop();
        // The dialect's largest count, which the lowering writes (at most kMaxRepeat).
        const double largest = std::min(std::floor(m_.numbers[u32_at(operands + 4)]), static_cast<double>(kMaxRepeat));
        const int64_t limit = whole_in<int64_t>(largest, 0, kMaxRepeat).value_or(0);
        const std::optional<int64_t> n = whole_in<int64_t>(count, 0, limit);
        if (!n) return fail(pc, DiagId::RepeatCount, shortest(count), limit);
        if (*n == 0) {
          p.pc = u32_at(operands);
          break;
        }
        if (p.loops.size() >= kMaxLoops) return fail(pc, DiagId::CallDepth, kMaxLoops);
        p.loops.push_back({*n});
        break;
      }
      case Op::EndRepeat:
        if (p.loops.size() <= (p.frames.empty() ? 0 : p.frames.back().loops))
          return fail(pc, DiagId::BytecodeInvalid, "program", "an end of repeat without its repeat");
        if (--p.loops.back().remaining > 0)
          p.pc = u32_at(operands);
        else
          p.loops.pop_back();
        break;
      case Op::Unloop: landing_depth_ = operands[0]; break;
      case Op::CallEntry:
      case Op::CallShared: {
        if (op == Op::CallShared && !args_.empty())
          return fail(pc, DiagId::BytecodeInvalid, "program", "arguments to a call that keeps the caller's locals");
        const double count = pop();
        const std::optional<int64_t> n = whole_in<int64_t>(count, 1, kMaxCallCount);
        if (!n)
          return fail(pc, DiagId::ParameterValue, "the call count", shortest(count),
                      fmt::format("whole numbers from 1 to {}", kMaxCallCount));
        uint32_t limit = m_.semantics.conventions.max_call_depth;
        if (p.frames.size() >= kMaxFrames || (limit && calls() >= limit))
          return fail(pc, DiagId::CallDepth, limit ? limit : kMaxFrames);
        const uint32_t start = m_.entries[u16_at(operands)].pc;
        p.frames.push_back({p.pc, p.loops.size(), false, 0, 0, p.loops.size(), start, *n - 1,
                            op == Op::CallShared ? std::vector<double>{} : take_locals(args_), op == Op::CallShared,
                            std::move(args_)});
        args_.clear();
        p.pc = start;
        break;
      }
      case Op::Arg: {
        const VarSpace& s = m_.spaces[operands[0]];
        const uint32_t index = u32_at(operands + 1);
        if (args_.size() >= 256)
          return fail(pc, DiagId::BytecodeInvalid, "program", "more than 256 arguments to a call");
        if (index >= s.locals)
          return fail(pc, DiagId::BytecodeInvalid, "program", "an argument that is not a local variable");
        double value = pop();
        // As a store would keep it (a vacant value only where variables may be vacant).
        if (!(s.vacant && std::isnan(value)) && !convert_value(type_at(operands[0], index), s.limit, value))
          return fail(pc, DiagId::ValueOverflow, shortest(value), fmt::format("{}{}", s.name, index));
        args_.push_back({operands[0], index, value});
        break;
      }
      case Op::ZeroIfVacant:
        if (std::isnan(st.back())) st.back() = 0;
        break;
      case Op::NoBlock: return fail(pc, DiagId::JumpTargetMissing, shortest(pop()));
      case Op::Service: {
        const auto service = static_cast<Service>(operands[0]);
        p.pc += static_cast<uint32_t>(service_operand_size(service));
        switch (call_service(service, operands + 1, pc)) {
          case ServiceResult::Done: break;
          case ServiceResult::Wait: return RunStatus::Blocked;
          case ServiceResult::Error: return RunStatus::Error;
          case ServiceResult::Release: return RunStatus::Released;
        }
        break;
      }
      case Op::CallRange:
        for (const Frame& f : p.frames)
          if (f.range) return fail(pc, DiagId::RangeNested);
        if (p.frames.size() >= kMaxFrames) return fail(pc, DiagId::CallDepth, kMaxFrames);
        if (p.loops.size() < operands[8])
          return fail(pc, DiagId::BytecodeInvalid, "program", "a range deeper in repeat loops than its call");
        // The range's code counts its loop depth from its first block's.
        p.frames.push_back({p.pc,
                            p.loops.size(),
                            true,
                            u32_at(operands),
                            u32_at(operands + 4),
                            p.loops.size() - operands[8],
                            0,
                            0,
                            {},
                            false,
                            {}});
        p.pc = u32_at(operands);
        break;
      case Op::RangeEnd:
        if (!p.frames.empty() && p.frames.back().range && p.frames.back().end == pc) {
          p.loops.resize(p.frames.back().loops);
          p.pc = p.frames.back().return_pc;
          p.frames.pop_back();
        }
        break;
      case Op::Return:
        // A range the subprogram was running ends with it.
        while (!p.frames.empty() && p.frames.back().range) p.frames.pop_back();
        if (p.frames.empty()) {
          p.pc = pc;
          return RunStatus::UnitEnded;
        }
        p.loops.resize(p.frames.back().loops);
        if (p.frames.back().remaining > 0) {
          // The next repetition starts afresh, as a new call would.
          --p.frames.back().remaining;
          if (!p.frames.back().shared) take_locals(p.frames.back().args);
          p.pc = p.frames.back().entry;
          break;
        }
        if (!p.frames.back().shared) restore_locals(p.frames.back().locals);
        p.pc = p.frames.back().return_pc;
        p.frames.pop_back();
        break;
      case Op::LoadMem: {
        double v = 0;
        if (!load_mem(operands[0], static_cast<MemFormat>(operands[1]), pop(), pc, v)) return RunStatus::Error;
        st.push_back(v);
        break;
      }
      case Op::StoreMem: {
        double value = pop();
        if (!store_mem(operands[0], static_cast<MemFormat>(operands[1]), pop(), value, pc)) return RunStatus::Error;
        break;
      }
      case Op::StoreText: {
        const std::string& text = m_.strings[u32_at(operands + 1)];
        uint8_t* b = bytes(operands[0], pop(), static_cast<uint32_t>(text.size()), pc);
        if (!b) return RunStatus::Error;
        std::memcpy(b, text.data(), text.size());
        wrote_memory();
        break;
      }
      case Op::CopyText: {
        const uint8_t n = operands[2];
        const uint8_t* from = bytes(operands[1], pop(), n, pc);
        uint8_t* to = from ? bytes(operands[0], pop(), n, pc) : nullptr;
        if (!to) return RunStatus::Error;
        std::memmove(to, from, n);
        wrote_memory();
        break;
      }
      case Op::EqText: {
        const std::string& text = m_.strings[u32_at(operands + 1)];
        const uint8_t* b = bytes(operands[0], pop(), static_cast<uint32_t>(text.size()), pc);
        if (!b) return RunStatus::Error;
        st.push_back(std::memcmp(b, text.data(), text.size()) == 0);
        break;
      }
      case Op::EqMem: {
        const uint8_t n = operands[2];
        const uint8_t* b = bytes(operands[1], pop(), n, pc);
        const uint8_t* a = b ? bytes(operands[0], pop(), n, pc) : nullptr;
        if (!a) return RunStatus::Error;
        st.push_back(std::memcmp(a, b, n) == 0);
        break;
      }
      case Op::GetSys: {
        st.push_back(machine_.system(SysRef::unpack(u16_at(operands))));
        break;
      }
      case Op::SetSys:
        if (!machine_.set_system(SysRef::unpack(u16_at(operands)), pop(), m_.source_of(pc))) return RunStatus::Error;
        break;
      case Op::Show:
      case Op::ShowValue:
      case Op::ShowText: {
        if (op == Op::Show) message_ += m_.strings[u32_at(operands)];
        if (op == Op::ShowValue) message_ += show(static_cast<VarType>(operands[0]), pop());
        if (op == Op::ShowText) {
          const uint8_t* b = bytes(operands[0], pop(), operands[1], pc);
          if (!b) return RunStatus::Error;
          message_.append(reinterpret_cast<const char*>(b), operands[1]);
        }
        // A message is a line for the operator; a file that builds one without end is not.
        if (message_.size() > 65536)
          return fail(pc, DiagId::BytecodeInvalid, "program", "a message longer than 64 KiB");
        break;
      }
      case Op::Message:
        machine_.message(message_, m_.source_of(pc));
        message_.clear();
        break;
      case Op::End: p.pc = pc; return RunStatus::UnitEnded;
      case Op::Count: return fail(pc, DiagId::BytecodeInvalid, "program", "an unknown opcode");
    }
  }
}

// ---- Services (contract/services.h) ------------------------------------------------------

// What a service sees of the VM: its operands by the catalogue's format, the values it
// pops (left on the stack until it is done: one that waits finds them again), the
// program's variables, its block.
class Vm::Call final : public ServiceCall {
 public:
  Call(Vm& vm, const ServiceInfo& info, const uint8_t* operands, uint32_t pc)
      : vm_(vm), info_(info), operands_(operands), pc_(pc), next_(vm.process_.stack.size()) {}

  uint32_t operand(size_t i) const override {
    if (i >= info_.format.size()) return 0;
    const uint8_t* at = operands_;
    for (size_t k = 0; k < i; ++k) at += operand_size(info_.format[k]);
    return read_operand(at, operand_size(info_.format[i]));
  }
  const std::string& string(uint32_t index) const override { return vm_.m_.strings[index]; }
  const std::string& entry_name(uint32_t index) const override { return vm_.m_.entries[index].name; }
  // Past the catalogue's pops a service reads 0 (a host's mistake must not reach
  // below its operands).
  double pop() override { return next_ > first() ? vm_.process_.stack[--next_] : 0; }
  void push(double value) override {
    if (pushes_ < pushed_.size()) pushed_[pushes_++] = value;
  }
  const VarSpace& space(uint8_t space) const override { return vm_.m_.spaces[space]; }
  VarType type_of(uint8_t space, uint32_t index) const override {
    return space < vm_.m_.spaces.size() && index < vm_.m_.spaces[space].size && !vm_.m_.spaces[space].memory
               ? vm_.type_at(space, index)
               : VarType::Unavailable;
  }
  bool load(uint8_t space, double index, double& out) override {
    bool ok = true;
    out = vm_.load(space, index, pc_, ok);
    return ok;
  }
  bool store(uint8_t space, double index, double value) override { return vm_.store(space, index, value, pc_); }
  bool load_mem(uint8_t space, MemFormat format, double index, double& out) override {
    return vm_.load_mem(space, format, index, pc_, out);
  }
  bool store_mem(uint8_t space, MemFormat format, double index, double value) override {
    return vm_.store_mem(space, format, index, value, pc_);
  }
  uint8_t* bytes(uint8_t space, double index, uint32_t count) override { return vm_.bytes(space, index, count, pc_); }
  void wrote_memory() override { vm_.wrote_memory(); }
  uint32_t block() const override { return vm_.m_.source_of(pc_); }
  BlockMachine& machine() override { return vm_.machine_; }
  bool waited() const override { return vm_.waiting_; }
  void waits_for(std::string what) override { vm_.waits_ = std::move(what); }
  void report(DiagId id, std::string message) override {
    vm_.issues_.issue({id, std::move(message), vm_.m_.source_of(pc_), -1, -1, 0});
  }

  // Done: its operands leave the stack, and its results (the catalogue's count) go on.
  void finish() {
    std::vector<double>& stack = vm_.process_.stack;
    stack.resize(first());
    for (size_t i = 0; i < info_.push; ++i) stack.push_back(i < pushes_ ? pushed_[i] : 0);
  }

 private:
  size_t first() const { return vm_.process_.stack.size() - info_.pop; }  // where its operands start

  Vm& vm_;
  const ServiceInfo& info_;
  const uint8_t* operands_;
  uint32_t pc_;
  size_t next_;                                   // the stack above the values it has popped
  std::array<double, kMaxServicePush> pushed_{};  // beyond the catalogue's pushes: ignored
  size_t pushes_ = 0;
};

ServiceResult Vm::call_service(Service service, const uint8_t* operands, uint32_t pc) {
  const ServiceInfo& info = service_info(service);
  ServiceHost* host = options_.services[static_cast<size_t>(info.device)];
  if (!host) {
    report_error(pc, DiagId::BytecodeInvalid, "program",
                 fmt::format("{}: this run has no {} device", info.name, device_name(info.device)));
    return ServiceResult::Error;
  }
  Call call(*this, info, operands, pc);
  const ServiceResult result = host->call(service, call);
  waiting_ = result == ServiceResult::Wait;
  if (waiting_) {
    process_.pc = pc;  // to run again, its operands as they were
  } else if (result == ServiceResult::Done) {
    call.finish();
  }
  return result;
}

}  // namespace ncc::vm
