#include "foreign.h"

#include <array>
#include <regex>
#include <vector>

#include <fmt/format.h>

namespace ncc::iso {

namespace {

constexpr uint32_t kLinesRead = 50;  // the header and the first blocks

// A construct of a language that an ISO program cannot hold (outside comments): a
// sure one tells the language by itself, two others together do.
struct Signature {
  const char* language;
  const char* shown;
  const char* pattern;  // ECMAScript, upper case; tried on a line without its ( ) comments,
                        // or with them when it has a '(' itself
  bool sure;
  bool first = false;  // tried on the first line that is not blank only (a header)
};

constexpr std::array kSignatures{
    Signature{"Siemens Sinumerik", "MSG(", R"(\bMSG\s*\()", true},
    Signature{"Siemens Sinumerik", "CYCLE81(", R"(\b(CYCLE\d+|POCKET\d|SLOT\d|HOLES\d)\s*\()", true},
    Signature{"Siemens Sinumerik", "DEF REAL", R"(^\s*(N\d+\s+)?DEF\s+(REAL|INT|BOOL|STRING|CHAR|AXIS|FRAME)\b)", true},
    Signature{"Siemens Sinumerik", "T=\"name\"", R"(\bT\s*=\s*")", true},
    Signature{"Siemens Sinumerik", "R1=", R"((^|\s)R\d+\s*=)", false},
    Signature{"Siemens Sinumerik", "G500", R"(\bG500\b)", false},
    Signature{"Siemens Sinumerik", "M17", R"(\bM17\b)", false},
    Signature{"Siemens Sinumerik", "; comments", R"(^\s*(N\d+\s*)?;)", false},
    Signature{"Heidenhain conversational", "BEGIN PGM", R"(^\s*\d*\s*BEGIN\s+PGM\b)", true},
    Signature{"Heidenhain conversational", "TOOL CALL", R"(^\s*\d*\s*TOOL\s+CALL\b)", true},
    Signature{"Heidenhain conversational", "L X+10 FMAX", R"(^\s*\d*\s*L\s+([XYZ][+-]|.*\bFMAX\b))", false},
    Signature{"Heidenhain conversational", "CC X Y", R"(^\s*\d*\s*CC\s+[XY][+-]?\d)", false},
    Signature{"Heidenhain conversational", "LBL", R"(^\s*\d*\s*(CALL\s+)?LBL\s+\w)", false},
    Signature{"Okuma OSP", "NLOOP", R"(^\s*N[A-Z][A-Z0-9]*\s)", false},
    Signature{"Okuma OSP", "VC1=", R"(\bVC\d+\s*=)", false},
    Signature{"Okuma OSP", "IF [..] N..", R"(\bIF\s*\[.*\]\s*N[A-Z0-9]+\s*$)", false},
    Signature{"Okuma OSP", "G15 H1", R"(\bG15\s*H\d)", false},
    Signature{"Philips 432 / MillPlus", "%PM", R"(^\s*%\s*PM)", true, true},
    Signature{"WinCNC (CAMaster)", "[ ] comments", R"(^\s*\[[^\]#]*\]\s*$)", true, true},
};

}  // namespace

std::optional<ForeignFile> foreign_language(const SourceFile& source) {
  static const std::vector<std::regex> kPatterns = [] {
    std::vector<std::regex> out;
    for (const Signature& s : kSignatures) out.emplace_back(s.pattern, std::regex::ECMAScript | std::regex::optimize);
    return out;
  }();
  std::array<uint32_t, kSignatures.size()> found{};  // the first line of each
  std::string text, raw;
  bool first = true;
  for (uint32_t n = 1; n <= source.line_count() && n <= kLinesRead; ++n) {
    text.assign(source.line(n));
    raw = text;
    for (char& c : raw)
      if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    // ( ) comments out, upper case: as the ISO reader sees the line.
    bool comment = false;
    for (char& c : text) {
      const bool in = comment || c == '(';
      comment = in && c != ')';
      if (in) c = ' ';
      if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    }
    for (size_t i = 0; i < kSignatures.size(); ++i)
      if (!found[i] && (first || !kSignatures[i].first) &&
          std::regex_search(std::string_view(kSignatures[i].pattern).find("\\(") != std::string_view::npos ? raw : text,
                            kPatterns[i]))
        found[i] = n;
    first = first && text.find_first_not_of(" \t\r") == std::string::npos;
  }
  for (size_t i = 0; i < kSignatures.size(); ++i) {
    if (!found[i]) continue;
    const std::string_view language = kSignatures[i].language;
    int score = 0;
    ForeignFile f{std::string(language), {}, found[i]};
    for (size_t j = i; j < kSignatures.size() && kSignatures[j].language == language; ++j) {
      if (!found[j]) continue;
      score += kSignatures[j].sure ? 2 : 1;
      f.evidence += fmt::format("{}{} on line {}", f.evidence.empty() ? "" : ", ", kSignatures[j].shown, found[j]);
      f.line = std::min(f.line, found[j]);
    }
    if (score >= 2) return f;
    while (i + 1 < kSignatures.size() && kSignatures[i + 1].language == language) ++i;
  }
  return std::nullopt;
}

}  // namespace ncc::iso
