// The VM beyond what GOST programs use: expressions, typed variables, jumps, repeat
// loops, calls and block skip, built as IR, lowered, written to bytes, read back,
// verified and run. What a program computes is observed through the motion it makes.
#include <gtest/gtest.h>

#include "collect_issues.h"
#include "check/check.h"
#include "lower/lower.h"
#include "runtime/machine.h"
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
    VarSpace e{"E", 40, {{0, VarType::Byte}, {10, VarType::Integer}, {20, VarType::Long}, {25, VarType::Real}, {30, VarType::LongReal}}};
    p.spaces.push_back(e);
  }
  ir::Block& block() {
    ir::Block& b = p.units.back().blocks.emplace_back();
    b.range = {file, ++line, 1, line, 2};
    return b;
  }
  ir::ExprId num(double v) { return p.number(v, {}); }
  ir::ExprId var(uint32_t index) { return p.add({ir::ExprOp::Var, Builtin::Sin, 0, 0, num(index), ir::kNoExpr, {}}); }
  ir::ExprId var_at(ir::ExprId index) { return p.add({ir::ExprOp::Var, Builtin::Sin, 0, 0, index, ir::kNoExpr, {}}); }
  ir::ExprId bin(ir::ExprOp op, ir::ExprId a, ir::ExprId b) { return p.add({op, Builtin::Sin, 0, 0, a, b, {}}); }
  ir::ExprId call(Builtin f, ir::ExprId a, ir::ExprId b = ir::kNoExpr) {
    return p.add({ir::ExprOp::Call, f, 0, 0, a, b, {}});
  }
  void assign(ir::Block& b, ir::ExprId target, ir::ExprId value) {
    ir::Stmt s(ir::StmtKind::Assign, b.range);
    s.target = target;
    s.value = value;
    b.stmts.push_back(s);
  }
  // A rapid to X = value.
  void move_x(ir::Block& b, ir::ExprId value, bool optional = false) {
    ir::Word g{ir::WordKind::Code, 0, "G", "00", num(0), 0, false, {}};
    ir::Word x{ir::WordKind::Parameter, 'X' - 'A', "X", "", value, -1, optional, {}};
    b.words.push_back(g);
    b.words.push_back(x);
    b.stmts.emplace_back(ir::StmtKind::Machine, b.range);
  }

  struct Result {
    std::vector<double> xs;
    std::vector<RuntimeIssue> issues;
    vm::RunStatus status;
  };

  Result run(vm::VmOptions options = {}) {
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
    Machine machine(loaded->semantics, config, trace, issues);
    machine.power_on();
    vm::Vm vm(*loaded, machine, issues, options);
    Result r;
    r.status = vm.run(0);
    for (const Event& e : trace.events)
      if (e.kind == EventKind::Rapid) r.xs.push_back(e.pos[0]);
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
  t.assign(b, t.var(1), t.num(3.7));    // byte: truncated to 3
  t.assign(b, t.var(26), t.num(1000.1));  // real (float)
  t.assign(b, t.var(31), t.num(0.1));   // long real
  t.move_x(t.block(), t.var(1));
  t.move_x(t.block(), t.var(26));
  t.move_x(t.block(), t.var(31));
  t.move_x(t.block(), t.var_at(t.bin(ir::ExprOp::Add, t.num(30), t.num(1))));
  auto r = t.run();
  ASSERT_EQ(r.xs.size(), 4u);
  EXPECT_EQ(r.xs[0], 3);
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
  loop.number = 2;
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
    EXPECT_EQ(r.issues[0].id, DiagId::DomainError);
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
  b.number = 1;
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
    vm::VmOptions options;
    options.block_skip = skip;
    auto r = t.run(options);
    // With the switch on the last block keeps G00 but loses X: no motion.
    EXPECT_EQ(r.xs, (skip ? std::vector<double>{1} : std::vector<double>{1, 2, 3}));
  }
}

}  // namespace
}  // namespace ncc
