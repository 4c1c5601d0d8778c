// Fuzz target: the fast path and the ANTLR parser give the same IR and diagnostics.
//
// Each input is a program of one dialect (its first byte picks the dialect: iso, gost,
// pp, nc110); it goes through the front end and the checks twice, with the
// hand-written scanner for plain blocks and with every block by ANTLR, and the two
// printed IRs and diagnostic lists must be equal byte for byte.
//
//   ncc_fuzz_fastpath [--dialect D] [--programs N] [--seed S]   deterministic random programs
//   ncc_fuzz_fastpath --replay FILE --dialect D                 one program from a file
//   ncc_fuzz_fastpath FILE|DIR...                               fuzz inputs, once each (fuzz.h)
//
// The random programs mix well-formed address words (the scanner's), their near misses
// (a blank inside a value, a second point, a sign alone, lower case, E and R
// parameters, labels, comments, multi-byte characters) and byte mutations, so that most
// blocks sit on the boundary between the two paths. Built with -DNCC_LIBFUZZER=ON
// (Clang) it is a libFuzzer target instead.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz.h"

namespace {

const std::vector<std::string> kDialects = {"iso", "gost", "pp", "nc110"};

// The printed IR and diagnostics of `text` read as `dialect`.
std::string read_as(const std::string& dialect, const std::string& text, bool fast_path) {
  ncc::Session s(0);
  ncc::fuzz::start_session(s);
  s.fast_path = fast_path;
  uint32_t file = s.sources.add("fuzz.nc", text);
  auto program = ncc::analyse(s, file, dialect);
  std::string out = program ? ncc::ir::print(*program, s.sources) : std::string("(no program)\n");
  return out + ncc::format_all(s.diags.all(), s.sources, ncc::DiagFormat::Text);
}

// The first line where the two differ, or "" if they are equal.
std::string compare(const std::string& dialect, const std::string& text) {
  const std::string fast = read_as(dialect, text, true), antlr = read_as(dialect, text, false);
  if (fast == antlr) return {};
  std::istringstream a(fast), b(antlr);
  std::string la, lb;
  for (int line = 1;; ++line) {
    bool more_a = static_cast<bool>(std::getline(a, la)), more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a) la = "<none>";
    if (!more_b) lb = "<none>";
    if (la != lb) return "output line " + std::to_string(line) + "\n  fast:  " + la + "\n  antlr: " + lb;
  }
}

class Generator {
 public:
  Generator(std::string dialect, uint32_t seed) : dialect_(std::move(dialect)), rng_(seed) {}

  std::string program(int blocks) {
    std::string text = dialect_ == "gost" ? "%\n" : dialect_ == "pp" ? "%1\n" : "";
    for (int k = 0; k < blocks; ++k) {
      std::string b = block();
      if (dialect_ == "pp") {  // a pp block begins with its N; an N inside would cut it
        for (char& c : b)
          if (c == 'N') c = 'X';
        b = "N" + std::to_string(k + 1) + pick({" ", "", "  "}) + b;
      }
      text += b + pick({"\n", "\n", "\n", "\r\n", " \n"});
    }
    return text + "M30\n";
  }

 private:
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  bool chance(int percent) { return below(100) < percent; }
  std::string pick(std::initializer_list<const char*> list) {
    return *(list.begin() + below(static_cast<int>(list.size())));
  }
  std::string digits(int max) {
    std::string d;
    for (int n = 1 + below(max); n > 0; --n) d += static_cast<char>('0' + below(10));
    return d;
  }
  std::string blanks() { return chance(70) ? "" : pick({" ", "  ", "\t"}); }

  std::string number() {
    switch (below(6)) {
      case 0: return digits(5);
      case 1: return digits(4) + "." + digits(4);
      case 2: return digits(3) + ".";
      case 3: return "." + digits(4);
      case 4: return digits(2);
      default: return digits(1) + "." + digits(1);
    }
  }

  std::string word() {
    static const std::string kLetters = "GXYZXYZIJKFSMTDHPQRLABCUVWEO";
    std::string letter(1, kLetters[static_cast<size_t>(below(static_cast<int>(kLetters.size())))]);
    if (letter == "G" || letter == "M")
      return letter + blanks() + pick({"0", "1", "01", "2", "3", "17", "90", "91", "94", "4", "8", "9", "30"});
    std::string sign = chance(60) ? "" : pick({"-", "+"});
    return letter + blanks() + sign + blanks() + number();
  }

  // What the parser must take: each dialect's constructs beside plain words, and damage.
  std::string other() {
    if (dialect_ == "iso")
      return pick({"#1=2", "X#1", "G65 P1000 A1", "IF [#1 GT 2] GOTO 10", "(comment)", "X[1+2]", ",C1.", "O100",
                   "GOTO 5", "WHILE [#1 LT 3] DO1", "END1", "#3=SIN[30]", "/", "N", "x12", "X1.2.3"});
    if (dialect_ == "gost")
      return pick({"(comment)", ":10", "/", "(unterminated", "%", "X1 .5", "N", "x12", "X1.2.3", "*"});
    if (dialect_ == "pp")
      return pick(
          {"R5 10", "XR5", "&1", "/", "\"comment\"", "4.50", "5.-10", "X-  3", "X3.  12", "R1 -2", "%", "\"open"});
    return pick({"XE31", "GE1", "T1.1", "\"LABEL\"", "#", "&", "E32", "G X10", "X - 5", "x10", "E1=5", "(RPT,3)",
                 "(ERP)", ";note", "/",
                 "\xd0\x95"
                 "30"});
  }

  std::string block() {
    std::string b;
    if (chance(10)) b += "/" + blanks();
    if (chance(50)) b += "N" + blanks() + digits(5);
    for (int n = below(7); n > 0; --n) {
      std::string part = chance(12) ? other() : word();
      b += (b.empty() ? "" : chance(75) ? " " : blanks()) + part;
    }
    if (chance(8)) mutate(b);
    return b;
  }

  void mutate(std::string& b) {
    static const std::string kBytes = " \t.+-/()\"#[];=,&%*NERTOx05\x01";
    const size_t at = b.empty() ? 0 : static_cast<size_t>(below(static_cast<int>(b.size())));
    const char c = kBytes[static_cast<size_t>(below(static_cast<int>(kBytes.size())))];
    switch (below(3)) {
      case 0: b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), c); break;
      case 1:
        if (!b.empty()) b.erase(at, 1);
        break;
      default:
        if (!b.empty()) b[at] = c;
        break;
    }
  }

  std::string dialect_;
  std::mt19937 rng_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string& dialect = kDialects[data[0] % kDialects.size()];
  std::string diff = compare(dialect, std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  if (!diff.empty()) ncc::fuzz::fail("fast path and ANTLR differ (" + dialect + "): " + diff);
  return 0;
}

#ifndef NCC_LIBFUZZER
int main(int argc, char** argv) {
  if (argc > 1 && !std::string_view(argv[1]).starts_with("--")) return ncc::fuzz::replay(argc, argv);
  std::vector<std::string> dialects = kDialects;
  int programs = 200;
  uint32_t seed = 1;
  std::string replay;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string option = argv[i], value = argv[i + 1];
    if (option == "--dialect")
      dialects = {value};
    else if (option == "--programs")
      programs = std::atoi(value.c_str());
    else if (option == "--seed")
      seed = static_cast<uint32_t>(std::strtoul(value.c_str(), nullptr, 10));
    else if (option == "--replay")
      replay = value;
    else {
      std::fprintf(stderr, "usage: %s [--dialect D] [--programs N] [--seed S] [--replay FILE]\n", argv[0]);
      return 2;
    }
  }
  if (!replay.empty()) {
    std::ifstream in(replay, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::string diff = compare(dialects.front(), text.str());
    std::printf("%s\n", diff.empty() ? "identical" : diff.c_str());
    return diff.empty() ? 0 : 1;
  }
  int failures = 0;
  for (const std::string& dialect : dialects) {
    Generator gen(dialect, seed);
    for (int p = 0; p < programs; ++p) {
      std::string text = gen.program(20);
      std::string diff = compare(dialect, text);
      if (diff.empty()) continue;
      if (++failures <= 3)
        std::printf("DIFFER %s program %d (seed %u):\n%s\n--- program ---\n%s---\n", dialect.c_str(), p, seed,
                    diff.c_str(), text.c_str());
    }
    std::printf("%s: %d random programs of 20 blocks, seed %u\n", dialect.c_str(), programs, seed);
  }
  std::printf("%d differ\n", failures);
  return failures ? 1 : 0;
}
#endif
