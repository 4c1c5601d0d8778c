// The bytecode file: a round trip keeps everything, and no corruption of a file
// (flipped, cut or rewritten bytes, even with a recomputed checksum) crashes the
// loader or the VM: each is rejected with a diagnostic or runs safely.
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

// Loads and, if the loader accepts the file, runs it with a step limit.
bool load_and_run(const std::string& bytes) {
  Session s;
  auto m = vm::read_module(bytes, "x.ncb", s.diags);
  if (!m) {
    EXPECT_TRUE(s.diags.has_errors());
    return false;
  }
  NullSink none;
  RunSettings settings;
  settings.max_steps = 10000;
  run_module(s, *m, settings, none);
  return true;
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
  EXPECT_EQ(back->source_map.blocks.size(), m.source_map.blocks.size());
  EXPECT_EQ(back->semantics.codes.size(), m.semantics.codes.size());
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

TEST(Bytecode, CorruptionWithAValidChecksumNeverCrashes) {
  // Rewrite each byte (three ways) and recompute the checksum: the verifier must
  // reject the file, or the VM must run it safely.
  Session s;
  std::string bytes = vm::write_module(compile_example(s));
  size_t accepted = 0;
  for (size_t i = 16; i < bytes.size(); ++i)
    for (uint8_t mask : {0x01, 0x80, 0xFF}) {
      std::string bad = bytes;
      bad[i] = static_cast<char>(bad[i] ^ mask);
      fix_checksum(bad);
      accepted += load_and_run(bad);
    }
  // Many rewrites only change a number or a name, and those files are still sound.
  EXPECT_GT(accepted, 0u);
}

// A module with hand-written code, to reach the verifier's rules one by one. The
// entry point is at 0.
std::string verify_code(std::vector<uint8_t> code, size_t numbers = 1) {
  vm::Module m;
  m.numbers.assign(numbers, 1.0);
  m.code = std::move(code);
  m.source_map.files.push_back("x.nc");
  m.source_map.blocks.push_back({});
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
  EXPECT_NE(verify_code({kStep, 0xEE}), "");                                       // unknown opcode
  EXPECT_NE(verify_code({kStep, op(Op::Const), 0, 0}), "");                        // cut off
  EXPECT_NE(verify_code({kStep, op(Op::Const), 5, 0, 0, 0, op(Op::End)}), "");     // constant out of range
  EXPECT_NE(verify_code({kStep, op(Op::Add), op(Op::End)}), "");                   // stack underflow
  EXPECT_NE(verify_code({kStep, op(Op::Jump), 4, 0, 0, 0, op(Op::End)}), "");      // jump into an instruction
  EXPECT_NE(verify_code({kStep, op(Op::Jump), 99, 0, 0, 0, op(Op::End)}), "");     // jump outside the code
  EXPECT_NE(verify_code({kStep, op(Op::Nop)}), "");                                // runs off the end
  EXPECT_NE(verify_code({kStep, op(Op::Code), 0, 0, op(Op::End)}), "");            // no such G/M code
  EXPECT_NE(verify_code({kStep, op(Op::Word), kWordSlots, 0, 0, 0, 0, op(Op::End)}), "");  // no such word slot
  // A decimal of 9 places is sound, one of 10 is not (m / 10^p: there is no 10^10).
  EXPECT_EQ(verify_code({kStep, op(Op::WordDec), 23, 9, 1, 0, 0, 0, op(Op::End)}), "");
  EXPECT_NE(verify_code({kStep, op(Op::WordDec), 23, 10, 1, 0, 0, 0, op(Op::End)}), "");
  EXPECT_NE(verify_code({kStep, op(Op::Load), 0, 0, 0, 0, 0, op(Op::End)}), "");   // no such variable space
  EXPECT_NE(verify_code({kStep, op(Op::Call1), 6, op(Op::End)}), "");              // atan2 takes two arguments
  EXPECT_NE(verify_code({op(Op::Nop), kStep, op(Op::End)}), "");                   // the entry is not a Step
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
