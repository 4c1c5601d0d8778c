// No bytecode file crashes ncc: golden programs of every dialect that together use
// every instruction the compiler makes are compiled, and each byte of each module is
// changed in turn (three ways), each operand byte of each instruction takes every
// value (in the first sample that has the instruction), and random groups of bytes
// are set, the checksum recomputed each time. Each changed file must be refused with
// an NC5xxx diagnostic, or disassemble and run (a step limit, a trace, an ASSET
// sandbox) without touching memory out of bounds: the sanitizer build of the suite is
// the judge of that.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "devices/asset_store.h"
#include "driver/pipeline.h"
#include "support/bytes.h"
#include "vm/opcodes.h"

namespace ncc {
namespace {

struct Sample {
  const char* dialect;
  const char* file;  // in tests/golden/<dialect>/
  const char* lib = "";
  const char* machine = "";
};

// Chosen greedily from the goldens (the most instructions not yet used, the smallest
// program first); their union is checked below.
const Sample kSamples[] = {
    {"nc110", "asset-codes.nc"},
    {"nc110", "asset-operands.nc"},
    {"nc110", "screen-text.nc"},
    {"nc110", "expressions-manual-examples.nc"},
    {"nc110", "epp-jump-out-loops.nc"},
    {"nc110", "corpus-4.3-PROG91.nc", "lib"},
    {"nc110", "branches-text.nc"},
    {"nc110", "corpus-5.6-user-screen.nc"},
    {"nc110", "screen-off.nc"},
    {"nc110", "screen-mismatch.nc"},
    {"nc110", "expressions-mod-zero.nc"},
    {"nc110", "inp-text-errors.nc"},
    {"nc110", "memory-text.nc"},
    {"nc110", "corpus-5.3.2.6-CRE.nc"},
    {"nc110", "corpus-5.3.2.7-CAN.nc"},
    {"nc110", "parameters-classes.nc"},
    {"iso", "macro-logic.nc"},
    {"iso", "g65-error-location.nc", "sub-lib"},
    {"iso", "corpus-8.34.1-address-values.nc", "", "simulator.toml"},
    {"iso", "corpus-8.34.2-IF-example-2.nc", "", "simulator.toml"},
    {"iso", "macro-vars.nc"},
    {"iso", "sub-l-zero.nc"},
    {"iso", "bytecode-constants.nc"},
    {"gost", "skip-whole-block.nc"},
    {"pp", "jumps.pp"},
    {"pp", "dynamic-codes-g.pp"},
};

std::string golden_dir(const Sample& x) { return std::string(NCC_TEST_DATA "/golden/") + x.dialect; }

std::string compile_sample(const Sample& x) {
  Session s;
  const std::string dir = golden_dir(x);
  if (*x.machine) { EXPECT_TRUE(load_profile(s, dir + "/" + x.machine)); }
  if (*x.lib) s.library = dir + "/" + x.lib;
  auto input = read_input(s, dir + "/" + x.file);
  EXPECT_TRUE(input);
  if (!input) return {};
  auto m = compile_source(s, input->second, x.dialect);
  EXPECT_TRUE(m && !s.diags.has_errors()) << x.file;
  return m ? vm::write_module(*m) : std::string();
}

// An instruction as the samples must cover them: an opcode, and a SERVICE by its service.
using Instruction = std::pair<vm::Op, Service>;
std::string name(Instruction i) {
  return std::string(i.first == vm::Op::Service ? service_info(i.second).name : vm::op_info(i.first).name);
}

// The first instruction of each kind the module's code has, by its pc.
std::map<Instruction, size_t> first_instructions(const vm::Module& m) {
  std::map<Instruction, size_t> first;
  for (size_t pc = 0; pc < m.code.size(); pc += static_cast<size_t>(vm::instruction_size(&m.code[pc]))) {
    const auto op = static_cast<vm::Op>(m.code[pc]);
    first.emplace(Instruction{op, op == vm::Op::Service ? static_cast<Service>(m.code[pc + 1]) : Service::Count}, pc);
  }
  return first;
}

vm::Module module_of(const std::string& bytes) {
  Session s;
  auto m = vm::read_module(bytes, "x.ncb", s.diags);
  EXPECT_TRUE(m);
  return m ? *m : vm::Module{};
}

// Where the code section's bytes start in a file (docs/bytecode.md: a 16-byte header,
// then sections of a tag, a size and the bytes).
size_t code_offset(const std::string& bytes) {
  size_t at = 16;
  while (at + 8 <= bytes.size() && bytes.compare(at, 4, "CODE") != 0)
    at += 8 + ByteReader(std::string_view(bytes).substr(at + 4, 4)).u32();
  return at + 8;
}

void fix_checksum(std::string& bytes) {
  const uint32_t crc = crc32({reinterpret_cast<const uint8_t*>(bytes.data()) + 16, bytes.size() - 16});
  for (int i = 0; i < 4; ++i) bytes[12 + i] = static_cast<char>((crc >> (8 * i)) & 0xFF);
}

// A fresh ASSET sandbox with every device, removed at the end; in memory where there is
// a tmpfs (the store syncs every file it writes).
struct Sandbox {
  std::filesystem::path dir;
  Sandbox() {
    const std::filesystem::path tmp =
        std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    dir = tmp / ("ncc-mutation-" + std::to_string(::getpid()) + "-" +
                 testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir);
    for (int d = 0; d < asset::kDevices; ++d) std::filesystem::create_directories(dir / ("MP" + std::to_string(d)));
  }
  ~Sandbox() { std::filesystem::remove_all(dir); }
};

// Refused with a bytecode diagnostic, or disassembled and run; true if it ran.
bool load_disassemble_and_run(const std::string& bytes, const Sandbox& sandbox, TraceFormat format) {
  Session s;
  auto m = vm::read_module(bytes, "x.ncb", s.diags);
  if (!m) {
    EXPECT_EQ(s.diags.all().size(), 1u);
    for (const Diagnostic& d : s.diags.all()) EXPECT_EQ(diag_info(d.id).number / 1000, 5) << d.message;
    return false;
  }
  EXPECT_FALSE(vm::disassemble(*m).empty());
  RunSettings settings;
  settings.max_steps = 2000;
  settings.files = sandbox.dir.string();
  std::FILE* out = std::fopen("/dev/null", "wb");
  auto writer = make_trace_writer(format, out, m->source_map, m->semantics.conventions.axes);
  (void)run_module(s, *m, settings, *writer);  // any outcome will do: the run must only not crash
  writer.reset();
  std::fclose(out);
  return true;
}

TEST(BytecodeMutation, TheSamplesUseEveryInstructionTheCompilerMakes) {
  std::set<Instruction> used;
  for (const Sample& x : kSamples) {
    Session s;
    auto m = vm::read_module(compile_sample(x), x.file, s.diags);
    ASSERT_TRUE(m) << x.file << ": " << (s.diags.all().empty() ? "" : s.diags.all()[0].message);
    for (auto [instruction, pc] : first_instructions(*m)) used.insert(instruction);
  }
  std::vector<Instruction> all;
  for (size_t i = 0; i < static_cast<size_t>(vm::Op::Count); ++i)
    if (static_cast<vm::Op>(i) != vm::Op::Service) all.push_back({static_cast<vm::Op>(i), Service::Count});
  for (size_t i = 0; i < kServiceCount; ++i) all.push_back({vm::Op::Service, static_cast<Service>(i)});
  for (Instruction i : all) {
    if (i.first == vm::Op::Nop || i.first == vm::Op::Pow) continue;  // the lowering makes neither
    EXPECT_TRUE(used.count(i)) << name(i) << " is in no sample";
  }
}

class EveryByte : public testing::TestWithParam<Sample> {};

TEST_P(EveryByte, IsRefusedOrRunsSafely) {
  const std::string bytes = compile_sample(GetParam());
  ASSERT_FALSE(bytes.empty());
  const Sandbox sandbox;
  size_t ran = 0, tried = 0;
  auto attempt = [&](std::string bad) {
    fix_checksum(bad);
    ran += load_disassemble_and_run(bad, sandbox, static_cast<TraceFormat>(tried++ % 3));
  };
  for (size_t i = 16; i < bytes.size(); ++i)
    for (uint8_t mask : {0x01, 0x80, 0xFF}) {
      std::string bad = bytes;
      bad[i] = static_cast<char>(bad[i] ^ mask);
      attempt(bad);
    }
  // Every value of each operand byte (a service's number too) of the instructions no
  // sample before this one has.
  std::set<Instruction> earlier;
  for (const Sample& x : kSamples) {
    if (std::string_view(x.dialect) == GetParam().dialect && std::string_view(x.file) == GetParam().file) break;
    for (auto [instruction, pc] : first_instructions(module_of(compile_sample(x)))) earlier.insert(instruction);
  }
  const size_t code = code_offset(bytes);
  const vm::Module m = module_of(bytes);
  for (auto [instruction, pc] : first_instructions(m))
    if (!earlier.count(instruction))
      for (size_t i = code + pc + 1; i < code + pc + static_cast<size_t>(vm::instruction_size(&m.code[pc])); ++i)
        for (int v = 0; v < 256; ++v) {
          std::string bad = bytes;
          bad[i] = static_cast<char>(v);
          attempt(bad);
        }
  // Groups of two to eight bytes anywhere after the header, set at random.
  std::mt19937 random(20261127);
  for (int n = 0; n < 500; ++n) {
    std::string bad = bytes;
    const int count = 2 + static_cast<int>(random() % 7);
    for (int k = 0; k < count; ++k) bad[16 + random() % (bad.size() - 16)] = static_cast<char>(random());
    attempt(bad);
  }
  // Many changes only change a number or a name, and those files are still sound.
  EXPECT_GT(ran, 0u);
}

INSTANTIATE_TEST_SUITE_P(Goldens, EveryByte, testing::ValuesIn(kSamples),
                         [](const testing::TestParamInfo<Sample>& sample) {
                           std::string name = std::string(sample.param.dialect) + "_" + sample.param.file;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace ncc
