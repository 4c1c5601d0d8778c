// The bytecode file: a round trip keeps everything (read from memory or from a file a
// section at a time), a flipped or cut byte is caught, and the verifier refuses each
// operand out of its range (bytecode_mutation_test.cpp changes every byte).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "driver/pipeline.h"
#include "support/bytes.h"
#include "vm/opcodes.h"

namespace ncc {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

vm::Module compile_example(Session& s) {
  uint32_t file = s.sources.add("bracket.nc", read_text(NCC_TEST_DATA "/../examples/gost/bracket.nc"));
  auto program = analyse(s, file, "gost");
  EXPECT_TRUE(program);
  EXPECT_FALSE(s.diags.has_errors());
  return lower_program(s, *program);
}

void fix_checksum(std::string& bytes) {
  uint32_t crc = crc32({reinterpret_cast<const uint8_t*>(bytes.data()) + 16, bytes.size() - 16});
  for (int i = 0; i < 4; ++i) bytes[12 + i] = static_cast<char>((crc >> (8 * i)) & 0xFF);
}

// A module of `dialect` from program text.
vm::Module compile_text(Session& s, const std::string& dialect, const std::string& text) {
  uint32_t file = s.sources.add("p.nc", text);
  auto m = compile_source(s, file, dialect);
  EXPECT_TRUE(m && !s.diags.has_errors());
  return m ? *m : vm::Module{};
}

// The pc of the first instruction `op` in the module's code.
size_t find_op(const vm::Module& m, vm::Op op) {
  size_t pc = 0;
  while (pc < m.code.size() && m.code[pc] != static_cast<uint8_t>(op))
    pc += static_cast<size_t>(vm::instruction_size(&m.code[pc]));
  EXPECT_LT(pc, m.code.size());
  return pc;
}
// The same of a SERVICE instruction of `service`.
size_t find_service(const vm::Module& m, Service service) {
  size_t pc = 0;
  while (pc < m.code.size() &&
         !(m.code[pc] == static_cast<uint8_t>(vm::Op::Service) && m.code[pc + 1] == static_cast<uint8_t>(service)))
    pc += static_cast<size_t>(vm::instruction_size(&m.code[pc]));
  EXPECT_LT(pc, m.code.size());
  return pc;
}

// The one diagnostic loading the module's file gives ("" if it loads).
std::string load_problem(const vm::Module& m) {
  Session s;
  if (vm::read_module(vm::write_module(m), "x.ncb", s.diags)) return "";
  EXPECT_EQ(s.diags.all().size(), 1u);
  return s.diags.all().empty() ? "?" : fmt::format("{} [{}]", s.diags.all()[0].message, diag_code(s.diags.all()[0].id));
}

TEST(Bytecode, AValueTypeOutOfRangeIsRefused) {
  // Issue 17: (DIS,"A",E30) with its type byte made 6 (Unavailable, the first past the
  // types a value is shown as) and the checksum recomputed was accepted, and ncc disasm
  // read past its table of type names.
  Session s;
  vm::Module m = compile_text(s, "nc110", "(DIS,\"A\",E30)\nM30\n");
  const size_t pc = find_op(m, vm::Op::ShowValue);
  EXPECT_EQ(load_problem(m), "");
  m.code[pc + 1] = static_cast<uint8_t>(VarType::Unavailable);
  EXPECT_EQ(load_problem(m),
            fmt::format("'x.ncb' is invalid: ShowValue at {} has an operand out of range (6) [NC5004]", pc));
}

TEST(Bytecode, AnAssetFileNameThatIsNoneIsRefused) {
  // The store checks a name before it opens a file; the trace prints it before that.
  Session s;
  vm::Module m = compile_text(s, "nc110", "(CAN,PUNTXZ/MP3)\nM30\n");
  const size_t pc = find_service(m, Service::AssetDelete);
  for (const std::string& bad : {std::string("PUN\0XZ/MP3", 10), std::string("../X"), std::string("PUNTXZ/MP7")}) {
    m.strings[vm::read_operand(&m.code[pc + 2], 4)] = bad;
    EXPECT_EQ(load_problem(m),
              fmt::format("'x.ncb' is invalid: asset.delete at {} has an operand out of range (0) [NC5004]", pc));
  }
}

TEST(Bytecode, EveryConventionRoundTrips) {
  // contract/conventions.def makes the writer and the reader: each field, away from its
  // default, comes back as it went.
  Session s;
  vm::Module m = compile_example(s);
  Conventions& c = m.semantics.conventions;
  c.arc_centre = ArcCentre::Absolute;
  c.helix_lead = HelixLead::PerRevolution;
  c.parabola_tangent = ParabolaTangent::Incremental;
  c.angle_unit = AngleUnit::Radian;
  c.dwell_word = 'X';
  c.dwell_seconds_per_unit = 0.001;
  c.peck_word = 'K';
  c.cycle_level_word = 'W';
  c.pitch_change_word = 'E';
  c.thread_allow_j = c.arc_single_quadrant = c.m06_stops_spindle = c.helix_by_end = c.fanuc_cycles = true;
  c.arc_tolerance = 0.01;
  c.lead_resolution = 0.0001;
  c.tool_offset_axes = "XZ";
  c.axes = "XYZAC";
  c.max_call_depth = 8;
  VarSpace& results = m.spaces.emplace_back();  // the example has none
  results.name = "R";
  results.size = 10;
  c.result_space = static_cast<uint8_t>(m.spaces.size() - 1);
  c.centre_words = CentreWords::Plane;
  c.radius_word = 'R';
  c.cycle_repeat_words = "LK";
  c.peck_clearance = 0.254;
  c.chip_break_retract = 0.1;
  c.boring_shift = -1;
  c.tool_change_iso = c.tool_change_retract = c.fanuc_rules = c.corners = true;
  c.initial_feed = 250;
  c.cutter = CutterStyle::Nc110;
  c.cycle_two_levels = c.cycle_defines_only = c.cycle_needs_cancel = true;
  c.peck_factor_word = 'K';
  c.peck_minimum_word = 'J';
  c.tap_pitch_word = 'K';
  c.corrector_in_tool_word = c.mirror_toggles = true;
  c.diameter_axis = 'X';
  c.link_axes = "XZ";
  c.aux_words = "HP";
  c.comp_length_word = 'L';
  c.comp_radius_word = 'R';
  c.feed_limits = {{{0, 0}, {1, 24000}, {0.001, 99.999}}};
  EXPECT_EQ(load_problem(m), "");
  auto back = vm::read_module(vm::write_module(m), "x.ncb", s.diags);
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->semantics.conventions == c);
  EXPECT_FALSE(back->semantics.conventions == Conventions{});
}

TEST(Bytecode, EachConventionCheckRefuses) {
  // A convention outside what conventions.def lets it hold is refused by name.
  struct Case {
    void (*spoil)(Conventions&);
    std::string why;
  };
  const Case cases[] = {
      {[](Conventions& c) { c.dwell_word = '1'; }, "the convention dwell_word: '1' is not an address letter"},
      {[](Conventions& c) { c.aux_words = "H1"; }, "the convention aux_words: holds what is not an address letter"},
      {[](Conventions& c) { c.diameter_axis = 'E'; }, "the convention diameter_axis: 'E' is not an axis"},
      {[](Conventions& c) { c.axes = "XYZX"; },
       "the convention axes: holds 'X', which is not an axis or appears twice"},
      {[](Conventions& c) { c.boring_shift = 0; }, "the convention boring_shift: is neither 1 nor -1"},
      {[](Conventions& c) { c.peck_clearance = -1; }, "the convention peck_clearance: is negative or not finite"},
      {[](Conventions& c) { c.dwell_seconds_per_unit = 0; },
       "the convention dwell_seconds_per_unit: is not a finite number above 0"},
      {[](Conventions& c) {
         c.feed_limits[1] = {10, 5};
       },
       "the convention feed_limits: holds what is not a range of feeds"},
  };
  for (const Case& k : cases) {
    Session s;
    vm::Module m = compile_example(s);
    k.spoil(m.semantics.conventions);
    EXPECT_EQ(load_problem(m), fmt::format("'x.ncb' is invalid: {} [NC5004]", k.why));
  }
}

TEST(Bytecode, RoundTripKeepsEverything) {
  Session s;
  vm::Module m = compile_example(s);
  std::string bytes = vm::write_module(m);
  auto back = vm::read_module(bytes, "x.ncb", s.diags);
  ASSERT_TRUE(back);
  EXPECT_EQ(vm::write_module(*back), bytes);
  EXPECT_EQ(vm::disassemble(*back), vm::disassemble(m));
  EXPECT_EQ(back->code, m.code);
  EXPECT_EQ(back->numbers, m.numbers);
  EXPECT_TRUE(back->source_map == m.source_map);
  ASSERT_EQ(back->lines.size(), m.lines.size());
  for (size_t i = 0; i < m.lines.size(); ++i) {
    EXPECT_EQ(back->lines[i].pc, m.lines[i].pc);
    EXPECT_EQ(back->lines[i].source, m.lines[i].source);
  }
  EXPECT_EQ(back->semantics.codes.size(), m.semantics.codes.size());
}

TEST(Bytecode, WritingToAFileGivesTheSameBytes) {
  // In pieces through a small buffer, the checksum put in last.
  Session s;
  vm::Module m = compile_example(s);
  m.code.insert(m.code.end() - 1, 200000, static_cast<uint8_t>(vm::Op::Nop));  // beyond one piece
  const std::string bytes = vm::write_module(m);
  std::FILE* f = std::tmpfile();
  ASSERT_TRUE(f);
  ASSERT_TRUE(vm::write_module(m, f));
  std::string back(bytes.size() + 1, '\0');
  std::rewind(f);
  back.resize(std::fread(back.data(), 1, back.size(), f));
  std::fclose(f);
  EXPECT_EQ(back, bytes);
}

TEST(Bytecode, AFileReadASectionAtATimeGivesWhatMemoryGives) {
  // The same module from a file, and the same one diagnostic for a flipped byte, a
  // cut file and bytes after the last section (the checksum first).
  Session s;
  const std::string bytes = vm::write_module(compile_example(s));
  auto from_file = [](const std::string& b, std::string& problem) {
    std::FILE* f = std::tmpfile();
    std::fwrite(b.data(), 1, b.size(), f);
    std::fflush(f);
    std::rewind(f);
    Session t;
    auto m = vm::read_module(fileno(f), b.size(), "x.ncb", t.diags);
    std::fclose(f);
    problem = t.diags.all().empty() ? "" : t.diags.all()[0].message;
    EXPECT_LE(t.diags.all().size(), 1u);
    return m;
  };
  std::string problem;
  auto m = from_file(bytes, problem);
  ASSERT_TRUE(m) << problem;
  EXPECT_EQ(vm::write_module(*m), bytes);
  std::string flipped = bytes, cut = bytes.substr(0, bytes.size() - 3), longer = bytes + "x";
  flipped[bytes.size() / 2] ^= 0x10;
  fix_checksum(cut);
  fix_checksum(longer);
  for (const std::string& bad : {flipped, cut, longer}) {
    Session t;
    EXPECT_FALSE(vm::read_module(bad, "x.ncb", t.diags));
    ASSERT_EQ(t.diags.all().size(), 1u);
    EXPECT_FALSE(from_file(bad, problem));
    EXPECT_EQ(problem, t.diags.all()[0].message);
  }
}

TEST(Bytecode, WritingIsDeterministic) {
  Session a, b;
  EXPECT_EQ(vm::write_module(compile_example(a)), vm::write_module(compile_example(b)));
}

TEST(Bytecode, EveryFlippedByteIsCaughtByTheChecksum) {
  Session s;
  std::string bytes = vm::write_module(compile_example(s));
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::string bad = bytes;
    bad[i] = static_cast<char>(bad[i] ^ 0x5A);
    Session t;
    EXPECT_FALSE(vm::read_module(bad, "x.ncb", t.diags)) << "byte " << i;
    ASSERT_EQ(t.diags.all().size(), 1u);
  }
}

TEST(Bytecode, EveryTruncationIsRejected) {
  Session s;
  std::string bytes = vm::write_module(compile_example(s));
  for (size_t n = 0; n < bytes.size(); ++n) {
    std::string cut = bytes.substr(0, n);
    if (n > 16) fix_checksum(cut);
    Session t;
    EXPECT_FALSE(vm::read_module(cut, "x.ncb", t.diags)) << "length " << n;
  }
}

TEST(Bytes, Crc32IsZlibsOnEveryLength) {
  // The standard check value, and every length around the 8-byte steps against a
  // byte-at-a-time reference.
  const std::string check = "123456789";
  EXPECT_EQ(crc32({reinterpret_cast<const uint8_t*>(check.data()), check.size()}), 0xCBF43926u);
  std::string data;
  for (int i = 0; i < 40; ++i) data += static_cast<char>(i * 37 + 11);
  for (size_t n = 0; n <= data.size(); ++n) {
    uint32_t crc = 0;
    for (size_t i = 0; i < n; ++i) crc = crc32({reinterpret_cast<const uint8_t*>(data.data()) + i, 1}, crc);
    EXPECT_EQ(crc32({reinterpret_cast<const uint8_t*>(data.data()), n}), crc) << n;
  }
}

TEST(Bytes, VariableLengthNumbersRoundTripAndRejectOverlongOnes) {
  ByteWriter w;
  const std::vector<uint64_t> u = {0, 1, 127, 128, 16383, 16384, UINT32_MAX, UINT64_MAX};
  const std::vector<int64_t> sv = {0, -1, 1, -64, 64, INT32_MIN, INT64_MIN, INT64_MAX};
  for (uint64_t v : u) w.uvar(v);
  for (int64_t v : sv) w.svar(v);
  ByteReader r(w.data());
  for (uint64_t v : u) EXPECT_EQ(r.uvar(), v);
  for (int64_t v : sv) EXPECT_EQ(r.svar(), v);
  EXPECT_TRUE(r.at_end());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(std::string(w.data().substr(0, 3)), std::string("\x00\x01\x7F", 3));
  // Eleven bytes, a tenth byte above 1, and a cut one are not numbers.
  for (std::string bad : {std::string(10, '\x80') + '\x01', std::string(9, '\xFF') + '\x02', std::string("\x80")}) {
    ByteReader b(bad);
    b.uvar();
    EXPECT_TRUE(b.failed());
  }
}

TEST(Bytecode, SourceMapRoundTripsEdgeValues) {
  // Lines going back (an included file), a block ending before it starts (the
  // placeholder block of an empty program), a word on a later line, large values.
  vm::Module m;
  m.code = {static_cast<uint8_t>(vm::Op::Step), static_cast<uint8_t>(vm::Op::End)};
  m.entries.push_back({"%1", vm::EntryKind::Program, 0});
  m.semantics.codes.resize(301);
  for (CodeDesc& c : m.semantics.codes) c.name = "G01";
  m.source_map.files = {"a.nc", "b.nc"};
  const std::vector<SourceBlock> blocks = {{1, 4000000000u, 7, 4000000002u, 1, true, true, false, UINT32_MAX},
                                           {0, 3, 1, 0, 0, false, false, true, 0},
                                           {0, 2, 9, 2, 30, true, false, false, 10}};
  const std::vector<std::vector<WordPosition>> words = {
      {{3, 12, 4000000001u, 1, 9}, {0, -1, 4000000002u, 1, 0}}, {}, {{25, 300, 2, 20, 30}}};
  for (size_t i = 0; i < blocks.size(); ++i) m.source_map.add(blocks[i], words[i]);
  m.lines = {{0, 0}, {1, 2}};
  std::string bytes = vm::write_module(m);
  Session s;
  auto back = vm::read_module(bytes, "x.ncb", s.diags);
  ASSERT_TRUE(back) << (s.diags.all().empty() ? "" : s.diags.all()[0].message);
  ASSERT_EQ(back->source_map.size(), 3u);
  for (uint32_t i : {2u, 0u, 1u, 2u}) {  // out of order too
    EXPECT_EQ(back->source_map.block(i), blocks[i]) << i;
    EXPECT_EQ(back->source_map.words(i), words[i]) << i;
  }
  EXPECT_EQ(vm::write_module(*back), bytes);
}

TEST(SourceMap, AnyBlockInAnyOrder) {
  // Blocks are held encoded: asked in order, backwards, or across checkpoints, each
  // decodes to what was added.
  SourceMap map;
  std::vector<SourceBlock> blocks;
  for (uint32_t i = 0; i < 100; ++i) {
    SourceBlock b{i % 3,
                  10 + i * 2 - (i % 7 == 0 ? 5 : 0),
                  1 + i % 4,
                  10 + i * 2,
                  40,
                  i % 2 == 0,
                  false,
                  i % 5 == 0,
                  i % 2 == 0 ? i * 10 : 0};
    std::vector<WordPosition> w;
    for (uint32_t k = 0; k < i % 6; ++k)
      w.push_back({static_cast<uint8_t>(k), static_cast<int16_t>(int(k) - 1), b.line, 3 + 4 * k, 6 + 4 * k});
    map.add(b, w);
    blocks.push_back(b);
  }
  for (uint32_t i : {0u, 1u, 2u, 99u, 50u, 15u, 16u, 17u, 3u, 98u}) {
    EXPECT_EQ(map.block(i), blocks[i]) << i;
    EXPECT_EQ(map.words(i).size(), i % 6) << i;
  }
  uint32_t seen = 0;
  map.visit([&](const SourceBlock& b, const std::vector<WordPosition>& w) {
    EXPECT_EQ(b, blocks[seen]);
    EXPECT_EQ(w.size(), seen % 6);
    ++seen;
  });
  EXPECT_EQ(seen, 100u);
}

// A module with hand-written code, to reach the verifier's rules one by one. The
// entry point is at 0.
std::string verify_code(std::vector<uint8_t> code, size_t numbers = 1) {
  vm::Module m;
  m.numbers.assign(numbers, 1.0);
  m.code = std::move(code);
  m.source_map.files.push_back("x.nc");
  m.source_map.add({}, {});
  m.entries.push_back({"%1", vm::EntryKind::Program, 0});
  return vm::verify(m);
}

constexpr uint8_t op(vm::Op o) { return static_cast<uint8_t>(o); }
constexpr uint8_t kStep = op(vm::Op::Step);

TEST(Verifier, AcceptsSoundCode) {
  using vm::Op;
  // 0 Step; 1 Const 1.0; 6 Neg; 7 JumpIf 0 (back to the Step); 12 End
  EXPECT_EQ(verify_code({kStep, op(Op::Const), 0, 0, 0, 0, op(Op::Neg), op(Op::JumpIf), 0, 0, 0, 0, op(Op::End)}), "");
}

TEST(Verifier, RejectsEachKindOfUnsoundCode) {
  using vm::Op;
  EXPECT_NE(verify_code({kStep, 0xEE}), "");                                               // unknown opcode
  EXPECT_NE(verify_code({kStep, op(Op::Const), 0, 0}), "");                                // cut off
  EXPECT_NE(verify_code({kStep, op(Op::Const), 5, 0, 0, 0, op(Op::End)}), "");             // constant out of range
  EXPECT_NE(verify_code({kStep, op(Op::Add), op(Op::End)}), "");                           // stack underflow
  EXPECT_NE(verify_code({kStep, op(Op::Jump), 4, 0, 0, 0, op(Op::End)}), "");              // jump into an instruction
  EXPECT_NE(verify_code({kStep, op(Op::Jump), 99, 0, 0, 0, op(Op::End)}), "");             // jump outside the code
  EXPECT_NE(verify_code({kStep, op(Op::Nop)}), "");                                        // runs off the end
  EXPECT_NE(verify_code({kStep, op(Op::Code), 0, 0, op(Op::End)}), "");                    // no such G/M code
  EXPECT_NE(verify_code({kStep, op(Op::Word), kWordSlots, 0, 0, 0, 0, op(Op::End)}), "");  // no such word slot
  // A decimal of 9 places is sound, one of 10 is not (m / 10^p: there is no 10^10).
  EXPECT_EQ(verify_code({kStep, op(Op::WordDec), 23, 9, 1, 0, 0, 0, op(Op::End)}), "");
  EXPECT_NE(verify_code({kStep, op(Op::WordDec), 23, 10, 1, 0, 0, 0, op(Op::End)}), "");
  EXPECT_NE(verify_code({kStep, op(Op::Load), 0, 0, 0, 0, 0, op(Op::End)}), "");  // no such variable space
  EXPECT_NE(verify_code({kStep, op(Op::Call1), 6, op(Op::End)}), "");             // atan2 takes two arguments
  EXPECT_NE(verify_code({op(Op::Nop), kStep, op(Op::End)}), "");                  // the entry is not a Step
  // A loop that passes no Step: --max-steps could not stop it.
  EXPECT_NE(verify_code({kStep, op(Op::Nop), op(Op::Jump), 1, 0, 0, 0}), "");
  // A value left on the stack at the end.
  EXPECT_NE(verify_code({kStep, op(Op::Const), 0, 0, 0, 0, op(Op::End)}), "");
  // Paths that meet with different stack depths.
  EXPECT_NE(verify_code({kStep, op(Op::Const), 0, 0, 0, 0, op(Op::JumpIf), 16, 0, 0, 0, op(Op::Const), 0, 0, 0, 0,
                         op(Op::End)}),
            "");
  // A stack that grows without bound in a loop.
  EXPECT_NE(verify_code({kStep, op(Op::Const), 0, 0, 0, 0, op(Op::Jump), 0, 0, 0, 0}), "");
}

TEST(Verifier, ChecksAServiceByItsCatalogueLine) {
  using vm::Op;
  auto service = [](Service s) { return static_cast<uint8_t>(s); };
  EXPECT_EQ(verify_code({kStep, op(Op::Service), service(Service::ScreenOn), op(Op::End)}), "");
  EXPECT_EQ(verify_code({kStep, op(Op::Service), 0xEE, op(Op::End)}), "Service at 1 has an operand out of range (238)");
  EXPECT_EQ(verify_code({kStep, op(Op::Service)}), "Service at 1 is cut off by the end of the code");
  // Its own operands: a string, cut off; out of range.
  EXPECT_EQ(verify_code({kStep, op(Op::Service), service(Service::ScreenShowText), 0, 0}),
            "screen.show_text at 1 is cut off by the end of the code");
  EXPECT_EQ(verify_code({kStep, op(Op::Const), 0, 0, 0, 0, op(Op::Service), service(Service::ScreenShowText), 0, 0, 0,
                         0, op(Op::End)}),
            "screen.show_text at 6 has an operand out of range (0)");
  // Its stack effect: asset.close pops a channel.
  EXPECT_EQ(verify_code({kStep, op(Op::Service), service(Service::AssetClose), op(Op::End)}),
            "asset.close at 1 pops more values than the stack holds");
  EXPECT_EQ(verify_code({kStep, op(Op::Const), 0, 0, 0, 0, op(Op::Service), service(Service::AssetClose), op(Op::End)}),
            "");
}

TEST(Verifier, ChecksEachOperandKindsRange) {
  // A memory SA of 16 bytes: Service process.wait_until SA, byte, relation q,
  // strings[0] (NC-110 WAI); the relations are 1..4. CopyText SA, SA, n bytes: n is 1..255.
  using vm::Op;
  auto verify_with_memory = [](uint8_t relation, uint8_t bytes) {
    vm::Module m;
    m.numbers = {0.0};
    m.strings = {"SA0=1"};
    m.spaces.push_back({"SA", 16, {}});
    m.spaces[0].memory = true;
    m.code = {kStep,
              op(Op::Const),
              0,
              0,
              0,
              0,
              op(Op::Const),
              0,
              0,
              0,
              0,
              op(Op::Service),
              static_cast<uint8_t>(Service::ProcessWaitUntil),
              0,
              1,
              relation,
              0,
              0,
              0,
              0,
              op(Op::Const),
              0,
              0,
              0,
              0,
              op(Op::Const),
              0,
              0,
              0,
              0,
              op(Op::CopyText),
              0,
              0,
              bytes,
              op(Op::End)};
    m.source_map.files.push_back("x.nc");
    m.source_map.add({}, {});
    m.entries.push_back({"%1", vm::EntryKind::Program, 0});
    return vm::verify(m);
  };
  EXPECT_EQ(verify_with_memory(1, 1), "");
  EXPECT_EQ(verify_with_memory(4, 255), "");
  EXPECT_EQ(verify_with_memory(0, 1), "process.wait_until at 11 has an operand out of range (0)");
  EXPECT_EQ(verify_with_memory(5, 1), "process.wait_until at 11 has an operand out of range (5)");
  EXPECT_EQ(verify_with_memory(1, 0), "CopyText at 30 has an operand out of range (0)");
}

TEST(Verifier, RejectsNumbersAndNamesThatCannotBeTrusted) {
  vm::Module m;
  m.numbers = {std::nan("")};
  m.code = {kStep, op(vm::Op::End)};
  m.source_map.files.push_back("x.nc");
  m.entries.push_back({"%1", vm::EntryKind::Program, 0});
  EXPECT_NE(vm::verify(m), "");
  m.numbers = {1.0};
  EXPECT_EQ(vm::verify(m), "");
  m.source_map.files[0] = "x\033[2J.nc";
  EXPECT_NE(vm::verify(m), "");
  m.source_map.files[0] = "x.nc";
  m.spaces = {{"E", 1u << 23, {}}, {"F", 1u << 23, {}}, {"G", 1, {}}};
  EXPECT_NE(vm::verify(m), "");
}

}  // namespace
}  // namespace ncc
