// The VM beyond what GOST programs use: expressions, typed variables, jumps, repeat
// loops, calls and block skip, built as IR, lowered, written to bytes, read back,
// verified and run. What a program computes is observed through the motion it makes.
#include <gtest/gtest.h>

#include "check/check.h"
#include "collect_issues.h"
#include "lower/lower.h"
#include "runtime/machine.h"
#include "vm/processes.h"
#include "vm/vm.h"

namespace ncc {
namespace {

// A one-unit program whose blocks the test fills; code 0 is G00 (rapid).
struct Builder {
  ir::Program p;
  SourceManager sources;
  uint32_t file = sources.add("test.nc", "");
  uint32_t line = 0;

  Builder() {
    p.dialect = "test";
    p.files.push_back(file);
    p.semantics.codes.push_back({"G00", Scope::Modal, Timing::None, {{Fn::MotionRapid}}});
    p.semantics.conventions.axes = "XYZ";
    p.units.push_back({});
    p.units.back().name = "%1";
    VarSpace e{"E",
               40,
               {{0, VarType::Byte},
                {10, VarType::Integer},
                {20, VarType::Long},
                {25, VarType::Real},
                {30, VarType::LongReal}}};
    p.spaces.push_back(e);
    VarSpace memory{"M", 16, {}};
    memory.memory = true;
    p.spaces.push_back(memory);
  }
  ir::Block& block() {
    ir::Block& b = p.units.back().blocks.emplace_back();
    b.range = {file, ++line, 1, line, 2};
    return b;
  }
  ir::ExprId num(double v) { return p.number(v, {}); }
  ir::ExprId var(uint32_t index) { return p.add({ir::ExprOp::Var, Builtin::Sin, 0, 0, num(index), ir::kNoExpr, {}}); }
  // A variable space of the test's own, and a variable of it.
  uint16_t space(const VarSpace& vars) {
    p.spaces.push_back(vars);
    return static_cast<uint16_t>(p.spaces.size() - 1);
  }
  ir::ExprId var_in(uint16_t space, double index) {
    return p.add({ir::ExprOp::Var, Builtin::Sin, space, 0, num(index), ir::kNoExpr, {}});
  }
  ir::ExprId var_at(ir::ExprId index) { return p.add({ir::ExprOp::Var, Builtin::Sin, 0, 0, index, ir::kNoExpr, {}}); }
  ir::ExprId bin(ir::ExprOp op, ir::ExprId a, ir::ExprId b) { return p.add({op, Builtin::Sin, 0, 0, a, b, {}}); }
  ir::ExprId call(Builtin f, ir::ExprId a, ir::ExprId b = ir::kNoExpr) {
    return p.add({ir::ExprOp::Call, f, 0, 0, a, b, {}});
  }
  ir::ExprId mem(MemFormat f, double index) {
    ir::Expr e{ir::ExprOp::Mem, Builtin::Sin, 1, 0, num(index), ir::kNoExpr, {}};
    e.format = f;
    return p.add(e);
  }
  ir::ExprId text(double index, uint8_t count) {
    ir::Expr e{ir::ExprOp::Text, Builtin::Sin, 1, 0, num(index), ir::kNoExpr, {}};
    e.count = count;
    return p.add(e);
  }
  ir::ExprId string(std::string s) {
    p.texts.push_back(std::move(s));
    ir::Expr e{ir::ExprOp::String, Builtin::Sin, 0, 0, ir::kNoExpr, ir::kNoExpr, {}};
    e.text = static_cast<uint32_t>(p.texts.size() - 1);
    return p.add(e);
  }
  ir::ExprId sys(SysVar v, uint8_t index = 0) {
    ir::Expr e{ir::ExprOp::Sys, Builtin::Sin, 0, 0, ir::kNoExpr, ir::kNoExpr, {}};
    e.sys = SysRef{v, index}.packed();
    return p.add(e);
  }
  void jump(ir::Block& b, std::string label, ir::ExprId cond = ir::kNoExpr) {
    ir::Stmt s(ir::StmtKind::Jump, b.range);
    s.label = std::move(label);
    s.cond = cond;
    b.stmts.push_back(s);
  }
  void stmt(ir::Block& b, ir::StmtKind kind, ir::ExprId value = ir::kNoExpr) {
    b.stmts.push_back({kind, b.range});
    b.stmts.back().value = value;
  }
  void assign(ir::Block& b, ir::ExprId target, ir::ExprId value) {
    ir::Stmt s(ir::StmtKind::Assign, b.range);
    s.target = target;
    s.value = value;
    b.stmts.push_back(s);
  }
  // A rapid to X = value.
  void move_x(ir::Block& b, ir::ExprId value, bool optional = false) {
    ir::Word g, x;
    g.kind = ir::WordKind::Code;
    g.address = "G";
    g.text = "00";
    g.value = num(0);
    g.code = 0;
    x.slot = 'X' - 'A';
    x.optional = optional;
    x.address = "X";
    x.value = value;
    b.words.push_back(g);
    b.words.push_back(x);
    b.stmts.emplace_back(ir::StmtKind::Machine, b.range);
  }

  struct Result {
    std::vector<double> xs;
    std::vector<std::string> messages;
    std::vector<RuntimeIssue> issues;
    vm::RunStatus status;
  };

  Result run(vm::VmOptions options = {}, bool block_skip = false) {
    Diagnostics diags;
    auto profile = stdlib::Profile::parse(sources, "", "", diags);
    vm::Module m = lower(p, sources, *profile);
    // Through the file format and its verifier, as `ncc run X.ncb` does.
    auto loaded = vm::read_module(vm::write_module(m), "test.ncb", diags);
    if (!loaded) {
      ADD_FAILURE() << (diags.all().empty() ? "" : diags.all().front().message);
      return {};
    }
    CollectSink trace;
    CollectIssues issues;
    MachineConfig config;
    config.block_skip = block_skip;
    Machine machine(loaded->semantics, config, trace, issues);
    machine.power_on();
    vm::Vm vm(*loaded, machine, issues, options);
    Result r;
    r.status = vm.run(0);
    for (const Event& e : trace.events) {
      if (e.kind == EventKind::Rapid) r.xs.push_back(e.pos[0]);
      if (e.kind == EventKind::Message) r.messages.push_back(e.text);
    }
    r.issues = issues.list;
    return r;
  }
};

TEST(Vm, ArithmeticAndBuiltins) {
  Builder t;
  using O = ir::ExprOp;
  t.move_x(t.block(), t.bin(O::Add, t.num(2), t.bin(O::Mul, t.num(3), t.num(4))));
  t.move_x(t.block(), t.bin(O::Div, t.num(7), t.num(2)));
  t.move_x(t.block(), t.bin(O::Mod, t.num(-7), t.num(3)));
  t.move_x(t.block(), t.call(Builtin::Sqrt, t.num(16)));
  t.move_x(t.block(), t.call(Builtin::Atan2, t.num(1), t.num(1)));
  t.move_x(t.block(), t.call(Builtin::Sin, t.num(30)));
  t.move_x(t.block(), t.bin(O::Gt, t.num(3), t.num(2)));
  t.move_x(t.block(), t.p.add({O::Neg, Builtin::Sin, 0, 0, t.num(5), ir::kNoExpr, {}}));
  auto r = t.run();
  EXPECT_EQ(r.status, vm::RunStatus::UnitEnded);
  ASSERT_EQ(r.xs.size(), 8u);
  EXPECT_DOUBLE_EQ(r.xs[0], 14);
  EXPECT_DOUBLE_EQ(r.xs[1], 3.5);
  EXPECT_DOUBLE_EQ(r.xs[2], -1);
  EXPECT_DOUBLE_EQ(r.xs[3], 4);
  EXPECT_DOUBLE_EQ(r.xs[4], 45);
  EXPECT_NEAR(r.xs[5], 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(r.xs[6], 1);
  EXPECT_DOUBLE_EQ(r.xs[7], -5);
}

TEST(Vm, DivisionByZeroIsALocatedError) {
  Builder t;
  t.move_x(t.block(), t.num(1));
  t.move_x(t.block(), t.bin(ir::ExprOp::Div, t.num(1), t.num(0)));
  auto r = t.run();
  EXPECT_EQ(r.status, vm::RunStatus::Error);
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::DivisionByZero);
  EXPECT_EQ(r.issues[0].source, 1u);  // the second block
  EXPECT_EQ(r.xs.size(), 1u);
}

TEST(Vm, DomainErrors) {
  for (auto [f, v] : {std::pair{Builtin::Sqrt, -1.0}, {Builtin::Asin, 2.0}, {Builtin::Ln, 0.0}, {Builtin::Tan, 90.0}}) {
    Builder t;
    t.move_x(t.block(), t.call(f, t.num(v)));
    auto r = t.run();
    EXPECT_EQ(r.status, vm::RunStatus::Error) << builtin_info(f).name;
    ASSERT_EQ(r.issues.size(), 1u);
    EXPECT_EQ(r.issues[0].id, DiagId::DomainError);
  }
}

TEST(Vm, TypedVariables) {
  Builder t;
  ir::Block& b = t.block();
  t.assign(b, t.var(1), t.num(3.5));      // byte: rounded half away from zero to 4
  t.assign(b, t.var(26), t.num(1000.1));  // real (float)
  t.assign(b, t.var(31), t.num(0.1));     // long real
  t.move_x(t.block(), t.var(1));
  t.move_x(t.block(), t.var(26));
  t.move_x(t.block(), t.var(31));
  t.move_x(t.block(), t.var_at(t.bin(ir::ExprOp::Add, t.num(30), t.num(1))));
  auto r = t.run();
  ASSERT_EQ(r.xs.size(), 4u);
  EXPECT_EQ(r.xs[0], 4);
  EXPECT_NEAR(r.xs[1], static_cast<double>(1000.1f), 1e-9);  // positions live on a nanometre grid
  EXPECT_GT(std::fabs(r.xs[1] - 1000.1), 1e-5);
  EXPECT_EQ(r.xs[2], 0.1);
  EXPECT_EQ(r.xs[3], 0.1);
}

TEST(Vm, ByteOverflowIsAnError) {
  Builder t;
  t.assign(t.block(), t.var(2), t.num(300));
  auto r = t.run();
  EXPECT_EQ(r.status, vm::RunStatus::Error);
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::ValueOverflow);
}

TEST(Vm, IndexOutOfRangeIsAnError) {
  Builder t;
  // A constant index out of range never gets this far: the verifier rejects it.
  t.move_x(t.block(), t.var_at(t.bin(ir::ExprOp::Add, t.num(39), t.num(1))));
  auto r = t.run();
  EXPECT_EQ(r.status, vm::RunStatus::Error);
  EXPECT_EQ(r.issues.at(0).id, DiagId::DomainError);
}

TEST(Vm, RepeatLoopsNest) {
  Builder t;
  ir::Block& outer = t.block();
  t.assign(outer, t.var(30), t.num(0));
  outer.stmts.push_back({ir::StmtKind::RepeatBegin, outer.range});
  outer.stmts.back().value = t.num(3);
  ir::Block& inner = t.block();
  inner.stmts.push_back({ir::StmtKind::RepeatBegin, inner.range});
  inner.stmts.back().value = t.num(2);
  ir::Block& body = t.block();
  t.assign(body, t.var(30), t.bin(ir::ExprOp::Add, t.var(30), t.num(1)));
  t.move_x(body, t.var(30));
  ir::Block& end_inner = t.block();
  end_inner.stmts.push_back({ir::StmtKind::RepeatEnd, end_inner.range});
  ir::Block& end_outer = t.block();
  end_outer.stmts.push_back({ir::StmtKind::RepeatEnd, end_outer.range});
  auto r = t.run();
  EXPECT_EQ(r.xs, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(Vm, RepeatCountBelowOneSkipsTheBody) {
  Builder t;
  ir::Block& b = t.block();
  b.stmts.push_back({ir::StmtKind::RepeatBegin, b.range});
  b.stmts.back().value = t.num(0);
  t.move_x(t.block(), t.num(9));
  ir::Block& e = t.block();
  e.stmts.push_back({ir::StmtKind::RepeatEnd, e.range});
  t.move_x(t.block(), t.num(1));
  EXPECT_EQ(t.run().xs, (std::vector<double>{1}));
}

TEST(Vm, ConditionalJumpsMakeALoop) {
  // E30 = 0; N2: E30 = E30 + 1; X = E30; if E30 < 4 goto N2; X = 100
  Builder t;
  t.assign(t.block(), t.var(30), t.num(0));
  ir::Block& loop = t.block();
  loop.label = "N2";
  t.assign(loop, t.var(30), t.bin(ir::ExprOp::Add, t.var(30), t.num(1)));
  t.move_x(loop, t.var(30));
  ir::Block& test = t.block();
  ir::Stmt jump(ir::StmtKind::Jump, test.range);
  jump.label = "N2";
  jump.cond = t.bin(ir::ExprOp::Lt, t.var(30), t.num(4));
  test.stmts.push_back(jump);
  t.move_x(t.block(), t.num(100));
  EXPECT_EQ(t.run().xs, (std::vector<double>{1, 2, 3, 4, 100}));
}

TEST(Vm, RepeatCountMustBeAWholeNumberInRange) {
  for (bool nan : {false, true}) {
    Builder t;
    ir::Block& b = t.block();
    b.stmts.push_back({ir::StmtKind::RepeatBegin, b.range});
    // Computed, as constants are finite: 1e300, and inf - inf.
    ir::ExprId inf = t.bin(ir::ExprOp::Mul, t.num(1e300), t.num(1e300));
    b.stmts.back().value = nan ? t.bin(ir::ExprOp::Sub, inf, inf) : t.num(1e300);
    t.move_x(t.block(), t.num(1));
    ir::Block& e = t.block();
    e.stmts.push_back({ir::StmtKind::RepeatEnd, e.range});
    auto r = t.run();
    EXPECT_EQ(r.status, vm::RunStatus::Error) << nan;
    ASSERT_EQ(r.issues.size(), 1u);
    EXPECT_EQ(r.issues[0].id, DiagId::RepeatCount);
  }
}

TEST(Vm, WordsMustBeFinite) {
  Builder t;
  t.move_x(t.block(), t.bin(ir::ExprOp::Mul, t.num(1e300), t.num(1e300)));
  auto r = t.run();
  EXPECT_EQ(r.status, vm::RunStatus::Error);
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::DomainError);
}

TEST(Vm, UndefinedTargetsAreCheckedBeforeLowering) {
  Builder t;
  ir::Block& b = t.block();
  ir::Stmt jump(ir::StmtKind::Jump, b.range);
  jump.label = "N9";
  b.stmts.push_back(jump);
  ir::Stmt call(ir::StmtKind::Call, b.range);
  call.label = "%9";
  b.stmts.push_back(call);
  Diagnostics diags;
  stdlib::DialectTables tables = stdlib::load_dialect_tables("gost", diags);
  check(t.p, {&tables}, diags);
  ASSERT_EQ(diags.all().size(), 2u);
  EXPECT_EQ(diags.all()[0].id, DiagId::LabelUndefined);
  EXPECT_EQ(diags.all()[1].id, DiagId::CallUndefined);
}

TEST(Vm, StepLimitStopsARunawayLoop) {
  Builder t;
  ir::Block& b = t.block();
  b.label = "N1";
  ir::Stmt jump(ir::StmtKind::Jump, b.range);
  jump.label = "N1";
  b.stmts.push_back(jump);
  vm::VmOptions options;
  options.max_steps = 1000;
  auto r = t.run(options);
  EXPECT_EQ(r.status, vm::RunStatus::Error);
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::StepLimit);
}

TEST(Vm, BlockSkipDropsSkippableBlocksAndOptionalWords) {
  for (bool skip : {false, true}) {
    Builder t;
    t.move_x(t.block(), t.num(1));
    ir::Block& skippable = t.block();
    skippable.skippable = true;
    t.move_x(skippable, t.num(2));
    ir::Block& partly = t.block();
    t.move_x(partly, t.num(3), true);  // X after a mid-block '/'
    auto r = t.run({}, skip);
    // With the switch on the last block keeps G00 but loses X: no motion.
    EXPECT_EQ(r.xs, (skip ? std::vector<double>{1} : std::vector<double>{1, 2, 3}));
  }
}

TEST(Vm, MemoryFormatsAreLittleEndianAtIndexTimesSize) {
  Builder t;
  ir::Block& b = t.block();
  t.assign(b, t.mem(MemFormat::Integer, 1), t.num(-2));  // bytes 2-3: FE FF
  t.assign(b, t.mem(MemFormat::Bit, 33), t.num(1));      // byte 4, bit 1
  t.assign(b, t.mem(MemFormat::Real, 2), t.num(0.5));    // bytes 8-11
  t.move_x(t.block(), t.mem(MemFormat::Byte, 2));        // 0xFE
  t.move_x(t.block(), t.mem(MemFormat::Byte, 4));        // 2
  t.move_x(t.block(), t.mem(MemFormat::Long, 0));        // bytes 0-3: 0xFFFE0000
  t.move_x(t.block(), t.mem(MemFormat::Real, 2));
  t.move_x(t.block(), t.mem(MemFormat::Bit, 33));
  auto r = t.run();
  ASSERT_TRUE(r.issues.empty()) << r.issues[0].message;
  EXPECT_EQ(r.xs, (std::vector<double>{254, 2, -131072, 0.5, 1}));
}

TEST(Vm, MemoryStoresCheckTheFormatAndTheSize) {
  for (auto [format, index, value, id] : {std::tuple{MemFormat::Bit, 0.0, 2.0, DiagId::ValueOverflow},
                                          {MemFormat::Byte, 0.0, 256.0, DiagId::ValueOverflow},
                                          {MemFormat::LongReal, 2.0, 1.0, DiagId::MemoryRange},
                                          {MemFormat::Integer, 8.0, 1.0, DiagId::MemoryRange}}) {
    Builder t;
    t.assign(t.block(), t.mem(format, index), t.num(value));
    auto r = t.run();
    EXPECT_EQ(r.status, vm::RunStatus::Error);
    ASSERT_EQ(r.issues.size(), 1u);
    EXPECT_EQ(r.issues[0].id, id);
  }
}

TEST(Vm, TextIsStoredComparedCopiedAndShown) {
  Builder t;
  ir::Block& b = t.block();
  t.assign(b, t.text(7, 3), t.string("RIF"));
  t.assign(b, t.text(0, 3), t.text(7, 3));
  ir::Block& equal = t.block();
  t.jump(equal, "L1", t.p.add({ir::ExprOp::TextEq, Builtin::Sin, 0, 0, t.text(0, 3), t.string("RIF"), {}}));
  t.move_x(t.block(), t.num(9));  // skipped
  ir::Block& l1 = t.block();
  l1.label = "L1";
  ir::Stmt show(ir::StmtKind::Display, l1.range);
  show.items = {{t.string("K="), VarType::LongReal},
                {t.text(7, 3), VarType::LongReal},
                {t.num(0.5), VarType::LongReal},
                {t.num(3), VarType::Byte}};
  l1.stmts.push_back(show);
  t.move_x(t.block(), t.p.add({ir::ExprOp::TextEq, Builtin::Sin, 0, 0, t.text(0, 3), t.text(1, 3), {}}));
  auto r = t.run();
  ASSERT_TRUE(r.issues.empty()) << r.issues[0].message;
  EXPECT_EQ(r.messages, (std::vector<std::string>{"K=RIF0.53"}));
  EXPECT_EQ(r.xs, (std::vector<double>{0}));
}

TEST(Vm, RangeCallRunsBothEndsThenComesBack) {
  // X1; call 2..3; X4; stop; "2" X2; "3" X3
  Builder t;
  t.move_x(t.block(), t.num(1));
  ir::Block& call = t.block();
  call.stmts.push_back({ir::StmtKind::CallRange, call.range});
  call.stmts.back().label = "2";
  call.stmts.back().end_label = "3";
  t.move_x(t.block(), t.num(4));
  t.jump(t.block(), "END");
  ir::Block& two = t.block();
  two.label = "2";
  t.move_x(two, t.num(2));
  ir::Block& three = t.block();
  three.label = "3";
  t.move_x(three, t.num(3));
  t.block().label = "END";
  EXPECT_EQ(t.run().xs, (std::vector<double>{1, 2, 3, 4}));
}

TEST(Vm, RangesDoNotNestAndAJumpOutEndsThem) {
  Builder t;
  ir::Block& call = t.block();
  call.stmts.push_back({ir::StmtKind::CallRange, call.range});
  call.stmts.back().label = "A";
  call.stmts.back().end_label = "B";
  t.move_x(t.block(), t.num(5));
  t.jump(t.block(), "END");
  ir::Block& a = t.block();
  a.label = "A";
  t.move_x(a, t.num(1));
  t.jump(t.block(), "OUT");  // leaves the range: it ends, nothing comes back
  ir::Block& b = t.block();
  b.label = "B";
  ir::Block& out = t.block();
  out.label = "OUT";
  t.move_x(out, t.num(2));
  ir::Block& again = t.block();
  again.stmts.push_back({ir::StmtKind::CallRange, again.range});
  again.stmts.back().label = "OUT";
  again.stmts.back().end_label = "NEST";
  ir::Block& nest = t.block();
  nest.label = "NEST";
  nest.stmts.push_back({ir::StmtKind::CallRange, nest.range});
  nest.stmts.back().label = "OUT";
  nest.stmts.back().end_label = "OUT";
  t.block().label = "END";
  auto r = t.run();
  EXPECT_EQ(r.xs, (std::vector<double>{1, 2, 2}));
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::RangeNested);
}

TEST(Vm, AJumpOutOfRepeatLoopsClosesThem) {
  // repeat 3 { repeat 2 { E30 += 1; if E30 == 2 goto OUT } }; OUT: X = E30; repeat 2 { X = 7 }
  Builder t;
  t.stmt(t.block(), ir::StmtKind::RepeatBegin, t.num(3));
  t.stmt(t.block(), ir::StmtKind::RepeatBegin, t.num(2));
  ir::Block& body = t.block();
  t.assign(body, t.var(30), t.bin(ir::ExprOp::Add, t.var(30), t.num(1)));
  t.jump(body, "OUT", t.bin(ir::ExprOp::Eq, t.var(30), t.num(2)));
  t.stmt(t.block(), ir::StmtKind::RepeatEnd);
  t.stmt(t.block(), ir::StmtKind::RepeatEnd);
  ir::Block& out = t.block();
  out.label = "OUT";
  t.move_x(out, t.var(30));
  t.stmt(t.block(), ir::StmtKind::RepeatBegin, t.num(2));
  t.move_x(t.block(), t.num(7));
  t.stmt(t.block(), ir::StmtKind::RepeatEnd);
  auto r = t.run();
  EXPECT_TRUE(r.issues.empty());
  EXPECT_EQ(r.xs, (std::vector<double>{2, 7, 7}));
}

TEST(Vm, RepeatCountLimitOfTheDialect) {
  Builder t;
  ir::Block& b = t.block();
  t.stmt(b, ir::StmtKind::RepeatBegin, t.num(100));
  b.stmts.back().limit = 99;
  t.move_x(t.block(), t.num(1));
  t.stmt(t.block(), ir::StmtKind::RepeatEnd);
  auto r = t.run();
  EXPECT_EQ(r.status, vm::RunStatus::Error);
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::RepeatCount);
}

TEST(Vm, SystemVariablesReachTheRuntime) {
  // USB = 0 skips the '/' block; the dwell time is stored and read back.
  Builder t;
  ir::Block& b = t.block();
  t.assign(b, t.sys(SysVar::BlockEnable), t.num(0));
  t.assign(b, t.sys(SysVar::DwellTime), t.num(2.5));
  ir::Block& skipped = t.block();
  skipped.skippable = true;
  t.move_x(skipped, t.num(1));
  t.move_x(t.block(), t.sys(SysVar::DwellTime));
  t.assign(t.block(), t.sys(SysVar::Timer, 0), t.num(1));  // the clock is read-only
  auto r = t.run();
  EXPECT_EQ(r.xs, (std::vector<double>{2.5}));
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::SystemValue);
}

TEST(Vm, CallDepthLimitOfTheDialect) {
  Builder t;
  t.p.semantics.conventions.max_call_depth = 1;
  ir::Block& b = t.block();
  t.move_x(b, t.num(1));
  ir::Stmt call(ir::StmtKind::Call, b.range);
  call.label = "%1";
  b.stmts.push_back(call);  // calls itself: the second call is one too many
  auto r = t.run();
  EXPECT_EQ(r.xs, (std::vector<double>{1, 1}));
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::CallDepth);
}

// A subprogram called three times by one call, with a local counter: each repetition
// starts it at zero, and the caller's own value comes back after the call.
TEST(Vm, CallCountRepeatsTheSubprogramWithFreshLocals) {
  Builder t;
  VarSpace local{"C", 1, {}};
  local.locals = local.size;
  const uint16_t c = t.space(local);
  auto counter = [&] { return t.var_in(c, 0); };
  ir::Block& set = t.block();
  t.assign(set, counter(), t.num(7));
  ir::Block& caller = t.block();
  ir::Stmt call(ir::StmtKind::Call, caller.range);
  call.label = "sub";
  call.value = t.num(3);
  caller.stmts.push_back(call);
  t.move_x(t.block(), counter());  // 7 again after the call
  t.p.units.push_back({});
  t.p.units.back().kind = ir::UnitKind::Subprogram;
  t.p.units.back().name = "sub";
  ir::Block& body = t.block();
  t.assign(body, counter(), t.bin(ir::ExprOp::Add, counter(), t.num(1)));
  t.move_x(body, counter());  // 1 in every repetition
  auto r = t.run();
  EXPECT_TRUE(r.issues.empty());
  EXPECT_EQ(r.xs, (std::vector<double>{1, 1, 1, 7}));
}

TEST(Vm, CheckStopsAValueOutsideItsRule) {
  Builder t;
  t.p.semantics.value_rules.push_back({"Q", 1, 9999, true});
  ir::Expr check{ir::ExprOp::Check, Builtin::Sin, 0, 0, t.num(2.5), ir::kNoExpr, {}};
  check.slot = 'X' - 'A';
  t.move_x(t.block(), t.num(4));
  t.move_x(t.block(), t.p.add(check));
  auto r = t.run();
  EXPECT_EQ(r.xs, (std::vector<double>{4}));
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::ParameterValue);
  EXPECT_EQ(r.issues[0].message,
            "Q 2.5, given by a parameter, is outside the values the address takes: whole numbers from 1 to 9999");
}

TEST(Vm, ThousandthsRoundHalfAwayFromZero) {
  Builder t;
  VarSpace r{"R", 2, {{0, VarType::Thousandths}}};
  r.limit = 70000;
  const uint16_t space = t.space(r);
  auto var = [&](double i) { return t.var_in(space, i); };
  ir::Block& b = t.block();
  t.assign(b, var(0), t.bin(ir::ExprOp::Div, t.num(10), t.num(3)));
  t.assign(b, var(1), t.num(-0.0125));
  t.move_x(b, var(0));
  t.move_x(t.block(), var(1));
  ir::Block& over = t.block();
  t.assign(over, var(0), t.num(70000));
  auto result = t.run();
  EXPECT_EQ(result.xs, (std::vector<double>{3.333, -0.013}));
  ASSERT_EQ(result.issues.size(), 1u);
  EXPECT_EQ(result.issues[0].id, DiagId::ValueOverflow);
}

// Macro B: a space whose variables start vacant. A vacant word value leaves the word
// out, arithmetic reads vacant as 0, EQ tells vacant from 0.
TEST(Vm, VacantVariables) {
  Builder t;
  VarSpace vars{"#", 10, {}};
  vars.vacant = true;
  const uint16_t s = t.space(vars);
  auto var = [&](double i) { return t.var_in(s, i); };
  auto zero_if_vacant = [&](ir::ExprId e) {
    return t.p.add({ir::ExprOp::ZeroIfVacant, Builtin::Sin, 0, 0, e, ir::kNoExpr, {}});
  };
  t.move_x(t.block(), t.num(5));
  t.move_x(t.block(), var(1));                                                    // left out: X stays 5
  t.move_x(t.block(), t.bin(ir::ExprOp::Add, zero_if_vacant(var(1)), t.num(2)));  // 0 + 2
  ir::Block& b = t.block();
  t.assign(b, var(2), var(1));                                   // a copy stays vacant
  t.move_x(t.block(), t.bin(ir::ExprOp::Eq, var(2), var(0)));    // 1: both vacant
  t.move_x(t.block(), t.bin(ir::ExprOp::Eq, var(2), t.num(0)));  // 0: vacant is not 0
  ir::Block& set0 = t.block();
  t.assign(set0, var(0), t.num(1));  // #0 cannot be set
  auto r = t.run();
  EXPECT_EQ(r.xs, (std::vector<double>{5, 2, 1, 0}));
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::VacantVariable);
}

// G65: arguments set the callee's locals, which start vacant; M98 (shared locals)
// keeps the caller's.
TEST(Vm, CallArgumentsAndSharedLocals) {
  Builder t;
  VarSpace vars{"#", 10, {}};
  vars.vacant = true;
  vars.locals = 5;
  const uint16_t s = t.space(vars);
  auto var = [&](double i) { return t.var_in(s, i); };
  ir::Block& set = t.block();
  t.assign(set, var(1), t.num(7));
  t.assign(set, var(3), t.num(9));
  ir::Block& caller = t.block();
  ir::Stmt macro(ir::StmtKind::Call, caller.range);
  macro.label = "sub";
  macro.args.push_back({s, 3, t.num(4)});  // #3 = 4 in the macro; #1 vacant there
  caller.stmts.push_back(macro);
  ir::Stmt shared(ir::StmtKind::Call, caller.range);
  shared.label = "sub";
  shared.shares_locals = true;  // #1 = 7 and #3 = 9 seen from the subprogram
  caller.stmts.push_back(shared);
  t.move_x(t.block(), var(3));  // 9: the caller's own after both calls
  t.p.units.push_back({});
  t.p.units.back().kind = ir::UnitKind::Subprogram;
  t.p.units.back().name = "sub";
  ir::Block& body = t.block();
  t.move_x(body, var(3));
  t.move_x(t.block(), var(1));
  auto r = t.run();
  EXPECT_TRUE(r.issues.empty());
  EXPECT_EQ(r.xs, (std::vector<double>{4, 9, 7, 9}));
}

// A computed GOTO to a number no block has stops the run at the jump.
TEST(Vm, ComputedJumpWithoutItsBlockIsAnError) {
  Builder t;
  ir::Block& target = t.block();
  target.number = 10;
  target.label = "N10";
  ir::Block& b = t.block();
  ir::Stmt jump(ir::StmtKind::Jump, b.range);
  jump.value = t.num(20);
  b.stmts.push_back(jump);
  auto r = t.run();
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].id, DiagId::JumpTargetMissing);
}

// A module runs on the scheduler only when it has a process or calls a process
// service (WAI for the PLC in a one-process program); any other on one ProgramRun.
TEST(Vm, OnlyProcessFeaturesNeedTheScheduler) {
  vm::Module m;
  m.devices = vm::device_bit(Device::Screen);
  EXPECT_FALSE(vm::Processes::needed(m));
  m.devices |= vm::device_bit(Device::Process);
  EXPECT_TRUE(vm::Processes::needed(m));
  m.devices = 0;
  m.entries.push_back({"%2", vm::EntryKind::Process, 0});
  EXPECT_TRUE(vm::Processes::needed(m));
}

}  // namespace
}  // namespace ncc
