// The limits of docs/limits.md "Text and nesting" bound the stack: a program at every
// limit compiles, prints and runs in a thread with a small stack, as in a controller
// that embeds ncc, and the hostile inputs are refused there without a crash.
#include <gtest/gtest.h>
#include <pthread.h>

#include <functional>

#include "driver/pipeline.h"
#include "frontend/limits.h"

namespace ncc {
namespace {

// AddressSanitizer pads every stack frame with redzones: the same depth needs about four
// times the stack (the sanitizer build, .ci/sanitize, overflows 1 MB here).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NCC_ASAN_FRAMES 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(NCC_ASAN_FRAMES)
constexpr size_t kSmallStack = 4 * 512 * 1024;
#else
constexpr size_t kSmallStack = 512 * 1024;
#endif

// Runs `work` on a thread of `stack` bytes of stack.
void on_small_stack(const std::function<void()>& work, size_t stack = kSmallStack) {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  ASSERT_EQ(pthread_attr_setstacksize(&attr, stack), 0);
  pthread_t thread;
  auto body = [](void* arg) -> void* {
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
  };
  ASSERT_EQ(pthread_create(&thread, &attr, body, const_cast<std::function<void()>*>(&work)), 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
}

std::string repeat(std::string_view s, size_t n) {
  std::string out;
  for (size_t i = 0; i < n; ++i) out += s;
  return out;
}

// iso's deepest expression within the limits: 32 levels, each with 8 signs and the 6
// operators that leave the most values waiting on the VM's stack (OR AND EQ + * and
// ATAN's first argument), 256 operators in all.
std::string iso_at_limits() {
  std::string nested = repeat("1 OR 1 AND 1 EQ 1+1*" + std::string(kMaxSignsInARow, '-') + "ATAN[1]/[", kMaxNesting) +
                       "1" + repeat("]", kMaxNesting);
  return "#1=" + nested + repeat("+1", kMaxOperators - 6 * kMaxNesting) + "\nG01 X#1 F100\nM30\n";
}

struct Outcome {
  bool compiled = false, verified = false;
  uint32_t errors = 0;
  size_t ir_chars = 0, disasm_chars = 0;
  bool ran = false;
};

Outcome compile_print_run(const std::string& dialect, const std::string& text) {
  Outcome o;
  Session s;
  EXPECT_TRUE(load_profile(s, ""));
  const uint32_t file = s.sources.add("limits.nc", text);
  if (auto program = analyse(s, file, dialect)) o.ir_chars = ir::print(*program, s.sources).size();
  Session c;
  EXPECT_TRUE(load_profile(c, ""));
  const uint32_t again = c.sources.add("limits.nc", text);
  if (auto module = compile_source(c, again, dialect); module && !c.diags.has_errors()) {
    o.compiled = true;
    o.verified = vm::verify(*module).empty();  // the stack it needs is within the VM's
    o.disasm_chars = vm::disassemble(*module).size();
    NullSink sink;
    o.ran = run_module(c, *module, {}, sink).ok;
  }
  o.errors = c.diags.error_count();
  return o;
}

TEST(Limits, DeepestAcceptedProgramRunsOnASmallStack) {
  Outcome o;
  on_small_stack([&] { o = compile_print_run("iso", iso_at_limits()); });
  EXPECT_TRUE(o.compiled);
  EXPECT_TRUE(o.verified);
  EXPECT_EQ(o.errors, 0u);
  EXPECT_GT(o.ir_chars, 0u);
  EXPECT_GT(o.disasm_chars, 0u);
  EXPECT_TRUE(o.ran);
}

TEST(Limits, HostileInputsAreRefusedOnASmallStack) {
  const std::vector<std::pair<std::string, std::string>> inputs = {
      {"iso", "#1=" + repeat("[", 7000) + "1" + repeat("]", 7000) + "\nM30\n"},
      {"iso", "#1=" + repeat("ABS[", 3200) + "1" + repeat("]", 3200) + "\nM30\n"},
      {"iso", "#1=" + std::string(50000, '-') + "1\nM30\n"},
      {"iso", "#1=1" + repeat("+1", 79999) + "\nM30\n"},
      {"iso", "#1=" + repeat("[", kMaxNesting + 1) + "1" + repeat("]", kMaxNesting + 1) + "\nM30\n"},
      {"iso", "#1=1" + repeat("+1", kMaxOperators + 1) + "\nM30\n"},
      {"nc110", "E30=" + repeat("(", 12000) + "1" + repeat(")", 12000) + "\n"},
      {"nc110", "E30=1" + repeat("+1", 79999) + "\n"},
      {"nc110", "E30=" + repeat("(", kMaxNesting + 1) + "1" + repeat(")", kMaxNesting + 1) + "\n"},
  };
  for (const auto& [dialect, text] : inputs) {
    Outcome o;
    // Clang 14 does not capture structured bindings: the lambda takes references of its own.
    on_small_stack([&o, &d = dialect, &t = text] { o = compile_print_run(d, t); });
    EXPECT_FALSE(o.compiled) << text.substr(0, 40);
    EXPECT_EQ(o.errors, 1u) << text.substr(0, 40);
  }
}

}  // namespace
}  // namespace ncc
