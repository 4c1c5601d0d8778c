// The public API as a host uses it: only include/ncc/ and the shared library.
#include <gtest/gtest.h>
#include <ncc/ncc.h>

#include <cstdio>
#include <string>
#include <vector>

namespace api = ncc::api;

namespace {

constexpr const char* kProgram =
    "N10 G21 G90 G17 G54\n"
    "N20 T2 M06\n"
    "N30 S1000 M03\n"
    "N40 G00 X10 Y0 Z5\n"
    "N50 G01 Z-1 F300\n"
    "N60 X20\n"
    "N70 G00 Z5\n"
    "N80 M30\n";

std::string xyz(const api::Axes& a) {
  char s[96];
  std::snprintf(s, sizeof s, "X%g Y%g Z%g", a[0], a[1], a[2]);
  return s;
}

// " B0": the rotary axes a move turned, where they end.
std::string turned(const api::Axes& end, api::AxisMask moved) {
  std::string s;
  for (size_t i = 3; i < 6; ++i)
    if (moved >> i & 1) s += " " + std::string(1, api::kAxisLetters[i]) + std::to_string(static_cast<int>(end[i]));
  return s;
}

// Writes down every call it receives, a line each: "5 straight_feed X10 Y0 Z-1".
class Recorder : public api::MachineInterface {
 public:
  std::vector<std::string> calls;

  api::Reply straight_traverse(const api::Block& b, const api::Axes& end, api::AxisMask moved) override {
    return add(b, "straight_traverse " + xyz(end) + turned(end, moved));
  }
  api::Reply straight_feed(const api::Block& b, const api::Axes& end, api::AxisMask moved) override {
    return add(b, "straight_feed " + xyz(end) + turned(end, moved));
  }
  api::Reply arc_feed(const api::Block& b, const api::Arc& a) override {
    return add(b, "arc_feed " + xyz(a.end) + " centre " + std::to_string(a.centre_first) + " " +
                      std::to_string(a.centre_second) + " rotation " + std::to_string(a.rotation));
  }
  api::Reply units(const api::Block& b, api::Units u) override {
    return add(b, u == api::Units::Millimetres ? "units mm" : "units inch");
  }
  api::Reply plane(const api::Block& b, const api::Plane& p) override {
    return add(b, "plane " + std::string{api::kAxisLetters[static_cast<size_t>(p.first)],
                                         api::kAxisLetters[static_cast<size_t>(p.second)]});
  }
  api::Reply feed_rate(const api::Block& b, double rate) override {
    return add(b, "feed_rate " + std::to_string(static_cast<int>(rate)));
  }
  api::Reply spindle_speed(const api::Block& b, double speed) override {
    return add(b, "spindle_speed " + std::to_string(static_cast<int>(speed)));
  }
  api::Reply spindle_start(const api::Block& b, api::Direction d) override {
    return add(b, d == api::Direction::Clockwise ? "spindle_start cw" : "spindle_start ccw");
  }
  api::Reply spindle_stop(const api::Block& b) override { return add(b, "spindle_stop"); }
  api::Reply tool_select(const api::Block& b, int tool) override {
    return add(b, "tool_select " + std::to_string(tool));
  }
  api::Reply tool_change(const api::Block& b, int tool) override {
    return add(b, "tool_change " + std::to_string(tool));
  }
  api::Reply work_offset(const api::Block& b, int n, const api::Axes& offset) override {
    return add(b, "work_offset " + std::to_string(n) + " " + xyz(offset));
  }
  api::Reply coolant(const api::Block& b, api::Coolant c) override {
    return add(b, c == api::Coolant::Off ? "coolant off" : "coolant on");
  }
  api::Reply program_end(const api::Block& b, bool information) override {
    return add(b, information ? "end information" : "end program");
  }
  api::Reply origin(const api::Block& b, const api::Axes& zero) override { return add(b, "origin " + xyz(zero)); }

 protected:
  virtual api::Reply add(const api::Block& b, std::string call) {
    calls.push_back(std::to_string(b.line) + " " + call);
    return {};
  }
};

const std::vector<std::string> kCalls = {"1 units mm",
                                         "1 plane XY",
                                         "1 work_offset 1 X0 Y0 Z0",
                                         "2 tool_select 2",
                                         "2 tool_change 2",
                                         "3 spindle_speed 1000",
                                         "3 spindle_start cw",
                                         "4 straight_traverse X10 Y0 Z5",
                                         "5 feed_rate 300",
                                         "5 straight_feed X10 Y0 Z-1",
                                         "6 straight_feed X20 Y0 Z-1",
                                         "7 straight_traverse X20 Y0 Z5",
                                         "8 spindle_stop",
                                         "8 coolant off",
                                         "8 end information"};

api::CompileOptions in(const std::string& dialect) {
  api::CompileOptions o;
  o.dialect = dialect;
  return o;
}

api::Program compiled(const char* text = kProgram, const std::string& dialect = "iso") {
  api::Result<api::Program> p = api::Program::compile(text, "part.nc", in(dialect));
  for (const api::Diagnostic& d : p.diagnostics()) ADD_FAILURE() << d.text;
  EXPECT_TRUE(p.ok());
  return std::move(p.value());
}

api::Run started(const api::Program& p, api::MachineInterface& host) {
  api::Result<api::Run> r = api::Run::start(p, host);
  EXPECT_TRUE(r.ok());
  return std::move(r.value());
}

TEST(Api, RunsToTheEnd) {
  const api::Program program = compiled();
  Recorder host;
  api::Run run = started(program, host);
  EXPECT_EQ(run.run(), api::Status::Ended);
  EXPECT_EQ(host.calls, kCalls);
  EXPECT_TRUE(run.diagnostics().empty());
  EXPECT_EQ(run.axes(), "XYZ");
}

TEST(Api, StepsABlockAtATime) {
  const api::Program program = compiled();
  ASSERT_EQ(program.block_count(), 8u);
  Recorder host;
  api::Run run = started(program, host);
  // Each step runs the block next_block() named, and makes that block's calls only.
  std::vector<size_t> calls_per_block;
  for (uint32_t expected = 0; expected < 8; ++expected) {
    const std::optional<api::Block> next = run.next_block();
    ASSERT_TRUE(next);
    EXPECT_EQ(next->index, expected);
    EXPECT_EQ(next->line, expected + 1);
    EXPECT_EQ(next->number, (expected + 1) * 10);
    EXPECT_EQ(next->file, "part.nc");
    const size_t before = host.calls.size();
    EXPECT_EQ(run.step(), expected < 7 ? api::Status::Ready : api::Status::Ended);
    for (size_t i = before; i < host.calls.size(); ++i)
      EXPECT_EQ(host.calls[i].substr(0, 2), std::to_string(expected + 1) + " ");
    calls_per_block.push_back(host.calls.size() - before);
  }
  EXPECT_EQ(calls_per_block, (std::vector<size_t>{3, 2, 2, 1, 2, 1, 1, 3}));
  EXPECT_EQ(host.calls, kCalls);
  EXPECT_FALSE(run.next_block());
  EXPECT_EQ(run.step(), api::Status::Ended);  // nothing more
  EXPECT_EQ(host.calls.size(), kCalls.size());
}

TEST(Api, ReadsTheStateBetweenBlocks) {
  const api::Program program = compiled();
  Recorder host;
  api::Run run = started(program, host);
  for (int i = 0; i < 5; ++i) ASSERT_EQ(run.step(), api::Status::Ready);  // through N50
  const api::State s = run.state();
  EXPECT_EQ(xyz(s.position), "X10 Y0 Z-1");
  EXPECT_EQ(s.units, api::Units::Millimetres);
  EXPECT_TRUE(s.absolute);
  EXPECT_EQ(s.plane, (api::Plane{0, 1, 2}));
  EXPECT_EQ(s.feed, 300);
  EXPECT_EQ(s.spindle_speed, 1000);
  EXPECT_EQ(s.spindle, api::Direction::Clockwise);
  EXPECT_EQ(s.tool, 2);
  EXPECT_EQ(s.work_offset, 1);
  EXPECT_EQ(s.motion, "G01");
  EXPECT_GT(s.seconds, 0);
}

// A host that pauses the run from inside a call (as an operator's feed hold would
// from another thread): run() returns after that block and goes on from the next.
class Pauser : public Recorder {
 public:
  api::Run* run = nullptr;

 protected:
  api::Reply add(const api::Block& b, std::string call) override {
    if (b.line == 4) run->pause();
    return Recorder::add(b, std::move(call));
  }
};

TEST(Api, PausesAfterTheBlockAndGoesOn) {
  const api::Program program = compiled();
  Pauser host;
  api::Run run = started(program, host);
  host.run = &run;
  EXPECT_EQ(run.run(), api::Status::Paused);
  EXPECT_EQ(host.calls.back(), "4 straight_traverse X10 Y0 Z5");
  ASSERT_TRUE(run.next_block());
  EXPECT_EQ(run.next_block()->line, 5u);
  EXPECT_EQ(run.run(), api::Status::Ended);
  EXPECT_EQ(host.calls, kCalls);
}

TEST(Api, StopsAndResetsToPowerOn) {
  const api::Program program = compiled();
  Recorder host;
  api::Run run = started(program, host);
  for (int i = 0; i < 4; ++i) ASSERT_EQ(run.step(), api::Status::Ready);
  EXPECT_EQ(run.stop(), api::Status::Stopped);
  EXPECT_EQ(run.step(), api::Status::Stopped);
  EXPECT_EQ(run.run(), api::Status::Stopped);
  EXPECT_FALSE(run.next_block());
  EXPECT_EQ(host.calls, std::vector<std::string>(kCalls.begin(), kCalls.begin() + 8));
  // Reset: powered on again; the same run makes the same calls.
  run.reset();
  EXPECT_EQ(run.status(), api::Status::Ready);
  EXPECT_EQ(xyz(run.state().position), "X0 Y0 Z0");
  host.calls.clear();
  EXPECT_EQ(run.run(), api::Status::Ended);
  EXPECT_EQ(host.calls, kCalls);
}

TEST(Api, RestartsAtABlockWithTheModesInForce) {
  const api::Program program = compiled();
  Recorder host;
  api::Run run = started(program, host);
  const std::optional<uint32_t> block = program.block_at_line(6);
  ASSERT_EQ(block, 5u);
  EXPECT_EQ(run.restart_at(*block), api::Status::Ready);
  // The modes the blocks before it set, each from the block that set it, in the order
  // they were set; no move.
  EXPECT_EQ(host.calls, (std::vector<std::string>{"1 units mm", "1 plane XY", "1 work_offset 1 X0 Y0 Z0",
                                                  "2 tool_select 2", "2 tool_change 2", "3 spindle_speed 1000",
                                                  "3 spindle_start cw", "5 feed_rate 300"}));
  EXPECT_EQ(run.next_block()->line, 6u);
  EXPECT_EQ(xyz(run.state().position), "X10 Y0 Z-1");  // where the block before it left the tool
  host.calls.clear();
  EXPECT_EQ(run.run(), api::Status::Ended);
  EXPECT_EQ(host.calls, std::vector<std::string>(kCalls.begin() + 10, kCalls.end()));
}

TEST(Api, RestartBeyondTheProgramIsAnError) {
  const api::Program program = compiled();
  Recorder host;
  api::Run run = started(program, host);
  EXPECT_EQ(run.restart_at(8), api::Status::Error);
  ASSERT_EQ(run.diagnostics().size(), 1u);
  EXPECT_EQ(run.diagnostics()[0].code, "NC6016");
  EXPECT_EQ(run.diagnostics()[0].message, "the run cannot restart at block 8: the program has 8 blocks");
  EXPECT_TRUE(host.calls.empty());
  // A block the run never reaches: the program ends before it (M02 at line 2).
  const api::Program ends = compiled("N10 G00 X1\nN20 M02\nN30 G00 X2\n");
  api::Run early = started(ends, host);
  EXPECT_EQ(early.restart_at(2), api::Status::Error);
  EXPECT_EQ(early.diagnostics()[0].message, "the run cannot restart at block 2 (part.nc:3): the run ends before it");
  EXPECT_TRUE(host.calls.empty());
}

// Refuses a feed below Z0: the run stops with an error at the block.
class Guard : public Recorder {
 public:
  api::Reply straight_feed(const api::Block& b, const api::Axes& end, api::AxisMask moved) override {
    if (end[2] < 0) return api::Reply::refuse("Z" + std::to_string(static_cast<int>(end[2])) + " is below the table");
    return Recorder::straight_feed(b, end, moved);
  }
};

TEST(Api, AHostThatRefusesAMoveStopsTheRunAtItsBlock) {
  const api::Program program = compiled();
  Guard host;
  api::Run run = started(program, host);
  EXPECT_EQ(run.run(), api::Status::Error);
  EXPECT_EQ(host.calls, std::vector<std::string>(kCalls.begin(), kCalls.begin() + 9));  // up to the feed rate of N50
  ASSERT_EQ(run.diagnostics().size(), 1u);
  const api::Diagnostic& d = run.diagnostics()[0];
  EXPECT_EQ(d.severity, api::Severity::Error);
  EXPECT_EQ(d.code, "NC6015");
  EXPECT_EQ(d.message, "the machine refused straight_feed: Z-1 is below the table");
  EXPECT_EQ(d.location.file, "part.nc");
  EXPECT_EQ(d.location.line, 5u);
  EXPECT_EQ(d.location.column, 1u);
  EXPECT_EQ(d.text,
            "part.nc:5:1: error: the machine refused straight_feed: Z-1 is below the table [NC6015]\n"
            "    5 | N50 G01 Z-1 F300\n"
            "      | ^~~~~~~~~~~~~~~~\n");
  EXPECT_EQ(run.step(), api::Status::Error);
  EXPECT_FALSE(run.next_block());
}

TEST(Api, TwoRunsInOneProcessDoNotMeet) {
  const api::Program program = compiled();
  Recorder first, second;
  api::Run a = started(program, first);
  api::Run b = started(program, second);
  // Interleaved, and one ahead of the other.
  ASSERT_EQ(a.step(), api::Status::Ready);
  while (a.status() == api::Status::Ready || b.status() == api::Status::Ready) {
    (void)b.step();
    (void)a.step();
  }
  EXPECT_EQ(first.calls, kCalls);
  EXPECT_EQ(second.calls, kCalls);
}

TEST(Api, CompileErrorsAreValues) {
  api::Result<api::Program> p = api::Program::compile("N10 G01 X10 F100\nN20 G02 X20\n", "bad.nc", in("iso"));
  EXPECT_FALSE(p.ok());
  ASSERT_FALSE(p.diagnostics().empty());
  const api::Diagnostic& d = p.diagnostics()[0];
  EXPECT_EQ(d.severity, api::Severity::Error);
  EXPECT_EQ(d.location.file, "bad.nc");
  EXPECT_EQ(d.location.line, 2u);
  EXPECT_EQ(d.code.substr(0, 2), "NC");
  EXPECT_NE(d.text.find("bad.nc:2:"), std::string::npos);
  // A dialect ncc does not read.
  api::Result<api::Program> q = api::Program::compile("G00 X1\n", "x.nc", in("heidenhain"));
  EXPECT_FALSE(q.ok());
  ASSERT_FALSE(q.diagnostics().empty());
}

TEST(Api, BytecodeRoundTripsAndIsVerified) {
  const api::Program program = compiled();
  const std::string bytes = program.bytes();
  api::Result<api::Program> loaded = api::Program::load_bytes(bytes, "part.ncb");
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(loaded->dialect(), "iso");
  EXPECT_EQ(loaded->bytes(), bytes);
  Recorder host;
  api::Run run = started(*loaded, host);
  EXPECT_EQ(run.run(), api::Status::Ended);
  EXPECT_EQ(host.calls, kCalls);
  // One byte changed: the checksum says so, and nothing runs.
  std::string corrupt = bytes;
  corrupt[corrupt.size() / 2] ^= 0x20;
  api::Result<api::Program> bad = api::Program::load_bytes(corrupt, "bad.ncb");
  EXPECT_FALSE(bad.ok());
  ASSERT_EQ(bad.diagnostics().size(), 1u);
  EXPECT_EQ(bad.diagnostics()[0].code, "NC5003");
}

TEST(Api, ADialectsOwnCallsAreTyped) {
  // NC-110's origin shift (UOT) comes as origin(); the moves after it are in the new
  // frame.
  const api::Program program = compiled("%\nN1 G90 G01 X10 F100\nN2 (UOT,0,X5)\nN3 X20\nN4 M30\n", "nc110");
  Recorder host;
  api::Run run = started(program, host);
  EXPECT_EQ(run.run(), api::Status::Ended);
  EXPECT_EQ(host.calls, (std::vector<std::string>{"2 feed_rate 100", "2 straight_feed X10 Y0 Z0", "3 origin X5 Y0 Z0",
                                                  "4 straight_feed X20 Y0 Z0", "5 spindle_stop", "5 coolant off",
                                                  "5 origin X0 Y0 Z0", "5 end information"}));
}

TEST(Api, AMoveSaysWhichAxesMoved) {
  // An endless rotary axis turning a full turn ends where it began: the call says it
  // moved, for a planner must turn it.
  const api::Program program = compiled("%\nN1 G X10 Y0\nN2 G91 G1 B360 F3600\nN3 G90 X20\n", "nc110");
  api::RunOptions options;
  options.profile = NCC_GOLDEN_DIR "/nc110/profiles/motion-endless.toml";
  Recorder host;
  api::Result<api::Run> run = api::Run::start(program, host, options);
  ASSERT_TRUE(run.ok());
  EXPECT_EQ(run->run(), api::Status::Ended);
  ASSERT_GE(host.calls.size(), 4u);
  EXPECT_EQ(host.calls[0], "2 straight_traverse X10 Y0 Z0");
  EXPECT_EQ(host.calls[2], "3 straight_feed X10 Y0 Z0 B0");
  EXPECT_EQ(host.calls[3], "4 straight_feed X20 Y0 Z0");
}

}  // namespace
