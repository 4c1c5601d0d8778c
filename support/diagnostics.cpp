#include "diagnostics.h"

#include <algorithm>
#include <array>
#include <deque>

#include "utf8.h"

namespace ncc {

namespace {

constexpr std::array kCatalogue = {
#define DIAG(id, number, name, severity, message) DiagInfo{DiagId::id, number, name, Severity::severity, message},
#include "diagnostics.def"
#undef DIAG
};

// One character of a quoted line as printed: a UTF-8 character takes a column (a
// control character prints as a space), a byte that is not UTF-8 four (`\xF4`).
struct Printed {
  size_t length = 1;  // bytes
  size_t width = 1;   // columns
};
Printed printed_at(std::string_view s, size_t i) {
  const Utf8Char c = decode_utf8(s, i);
  return c.length ? Printed{c.length, 1} : Printed{1, 4};
}

size_t display_width(std::string_view s) {
  size_t w = 0;
  for (size_t i = 0; i < s.size(); i += printed_at(s, i).length) w += printed_at(s, i).width;
  return w;
}

// The line as printed under a diagnostic: valid UTF-8 whatever the file holds, with
// the caret under the column; a long line is cut to a window around the column.
struct Excerpt {
  std::string text;
  size_t caret_col = 0;  // 0-based display column
  size_t caret_len = 1;
};

Excerpt make_excerpt(std::string_view line, uint32_t col, uint32_t end_col) {
  constexpr size_t kWindow = 120;  // columns
  const size_t start = std::min<size_t>(col > 0 ? col - 1 : 0, line.size());
  const size_t end = end_col > col ? std::min<size_t>(end_col - 1, line.size()) : start + 1;
  // The window begins at most half of it before the column, on a character.
  size_t begin = 0;
  if (display_width(line) > kWindow) {
    std::deque<std::pair<size_t, size_t>> recent;  // (offset, columns before it) of the characters before `start`
    size_t width = 0;
    for (size_t i = 0; i < start;) {
      recent.push_back({i, width});
      const Printed p = printed_at(line, i);
      width += p.width;
      i += p.length;
      while (width - recent.front().second > kWindow / 2) recent.pop_front();
    }
    if (!recent.empty() && width > kWindow / 2) begin = recent.front().first;
  }
  Excerpt e;
  if (begin > 0) e.text = "...";
  const size_t prefix = e.text.size();
  size_t width = 0, stop = begin;
  for (; stop < line.size() && width < kWindow;) {
    const Printed p = printed_at(line, stop);
    const unsigned char c = static_cast<unsigned char>(line[stop]);
    if (p.width == 4)
      e.text += fmt::format("\\x{:02X}", c);
    else if (c < 0x20 || c == 0x7F)
      e.text += ' ';
    else
      e.text.append(line.substr(stop, p.length));
    if (stop < start)
      e.caret_col += p.width;
    else if (stop < end)
      e.caret_len += p.width;
    width += p.width;
    stop += p.length;
  }
  if (stop < line.size()) e.text += "...";
  e.caret_col += prefix;
  e.caret_len = std::max<size_t>(1, e.caret_len - 1);
  return e;
}

std::string location_text(const SourceRange& r, const SourceManager& sources) {
  if (!r.valid() || r.file >= sources.size()) return "ncc";
  return fmt::format("{}:{}:{}", escape_invalid_utf8(sources.file(r.file).path()), r.line, r.col);
}

void append_quote(std::string& out, const SourceRange& r, const SourceManager& sources, bool color) {
  if (!r.valid() || r.file >= sources.size()) return;
  std::string_view line = sources.file(r.file).line(r.line);
  uint32_t end_col = r.end_line == r.line ? r.end_col : static_cast<uint32_t>(line.size() + 1);
  Excerpt e = make_excerpt(line, r.col, end_col);
  std::string gutter = fmt::format("{:>5} | ", r.line);
  out += gutter + e.text + "\n";
  out += std::string(gutter.size() - 2, ' ') + "| " + std::string(e.caret_col, ' ');
  if (color) out += "\033[1;32m";
  out += "^" + std::string(e.caret_len - 1, '~');
  if (color) out += "\033[0m";
  out += "\n";
}

const char* severity_color(Severity s) {
  switch (s) {
    case Severity::Error: return "\033[1;31m";
    case Severity::Warning: return "\033[1;35m";
    case Severity::Info: return "\033[1;36m";
    case Severity::Note: return "\033[1;30m";
  }
  return "";
}

// SARIF counts columns in characters (columnKind unicodeCodePoints; a byte that is not
// UTF-8 is one, U+FFFD in the JSON); ncc in bytes.
uint32_t char_column(const SourceManager& sources, const SourceRange& r, uint32_t byte_col, uint32_t line) {
  std::string_view text = sources.file(r.file).line(line).substr(0, byte_col - 1);
  uint32_t chars = 1;
  for (size_t i = 0; i < text.size(); i += printed_at(text, i).length) ++chars;
  return chars;
}

std::string sarif_region(const SourceManager& sources, const SourceRange& r) {
  return fmt::format(R"({{"startLine":{},"startColumn":{},"endLine":{},"endColumn":{}}})", r.line,
                     char_column(sources, r, r.col, r.line), r.end_line,
                     char_column(sources, r, r.end_col, r.end_line));
}

std::string sarif_level(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Info:
    case Severity::Note: return "note";
  }
  return "none";
}

std::string json_range(const SourceRange& r, const SourceManager& sources) {
  if (!r.valid() || r.file >= sources.size()) return "null";
  return fmt::format(R"({{"file":"{}","line":{},"column":{},"end_line":{},"end_column":{}}})",
                     json_escape(sources.file(r.file).path()), r.line, r.col, r.end_line, r.end_col);
}

}  // namespace

const DiagInfo& diag_info(DiagId id) { return kCatalogue[static_cast<size_t>(id)]; }

// Every message of diagnostics.def is well formed, the ones no call site names too.
constexpr bool all_messages_well_formed() {
  for (std::string_view message : diag_check::kMessages)
    if (diag_check::placeholders(message).malformed) return false;
  return true;
}
static_assert(all_messages_well_formed(), "a message of diagnostics.def is malformed: see diag_check::placeholders");

std::string diag_mismatch_message(DiagId id, size_t given) {
  return fmt::format("internal error: the arguments of {} do not fit its message: {} given, {} taken", diag_code(id),
                     given, diag_check::placeholders(diag_info(id).message).count);
}

std::string diag_code(DiagId id) { return fmt::format("NC{:04}", diag_info(id).number); }

std::string_view severity_name(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Info: return "info";
    case Severity::Note: return "note";
  }
  return "?";
}

std::optional<DiagId> diag_by_name(std::string_view name) {
  for (const DiagInfo& info : kCatalogue)
    if (info.name == name) return info.id;
  return std::nullopt;
}

Diagnostic* Diagnostics::add(Diagnostic d) {
  if (auto it = citations_.find(d.id); it != citations_.end()) d.message += " (" + it->second + ")";
  if (d.severity == Severity::Error) {
    if (limit_reached_) return nullptr;
    if (error_limit_ != 0 && errors_ >= error_limit_) {
      limit_reached_ = true;
      list_.push_back({DiagId::TooManyErrors, Severity::Error, {}, diag_message(DiagId::TooManyErrors, errors_), {}});
      return nullptr;
    }
    ++errors_;
  } else if (d.severity == Severity::Warning) {
    ++warnings_;
  }
  list_.push_back(std::move(d));
  return &list_.back();
}

void Diagnostics::clear() {
  list_.clear();
  errors_ = warnings_ = 0;
  limit_reached_ = false;
}

std::string format_text(const Diagnostic& d, const SourceManager& sources, bool color) {
  std::string out;
  if (color)
    out = fmt::format("\033[1m{}: {}{}:\033[0m \033[1m{}\033[0m [{}]\n", location_text(d.range, sources),
                      severity_color(d.severity), severity_name(d.severity), escape_invalid_utf8(d.message),
                      diag_code(d.id));
  else
    out = fmt::format("{}: {}: {} [{}]\n", location_text(d.range, sources), severity_name(d.severity),
                      escape_invalid_utf8(d.message), diag_code(d.id));
  append_quote(out, d.range, sources, color);
  for (const Note& n : d.notes) {
    out += fmt::format("{}: note: {}\n", location_text(n.range, sources), escape_invalid_utf8(n.message));
    append_quote(out, n.range, sources, color);
  }
  return out;
}

std::string json_escape(std::string_view s, bool quotes) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      // JSON text is UTF-8: a byte that is not becomes U+FFFD.
      const size_t n = decode_utf8(s, i).length;
      if (n == 0) {
        out += "\\ufffd";
      } else {
        out.append(s.substr(i, n));
        i += n - 1;
      }
      continue;
    }
    switch (c) {
      case '"': out += quotes ? "\\\"" : "\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20 || c == 0x7F)
          out += fmt::format("\\u{:04x}", c);
        else
          out += static_cast<char>(c);
    }
  }
  return out;
}

std::string format_all(const std::vector<Diagnostic>& list, const SourceManager& sources, DiagFormat format,
                       bool color) {
  std::string out;
  switch (format) {
    case DiagFormat::Text:
      for (const Diagnostic& d : list) out += format_text(d, sources, color);
      break;
    case DiagFormat::Json:
      // One JSON object per line.
      for (const Diagnostic& d : list) {
        out += fmt::format(R"({{"code":"{}","name":"{}","severity":"{}","message":"{}","range":{},"notes":[)",
                           diag_code(d.id), diag_info(d.id).name, severity_name(d.severity), json_escape(d.message),
                           json_range(d.range, sources));
        for (size_t i = 0; i < d.notes.size(); ++i)
          out += fmt::format(R"({}{{"message":"{}","range":{}}})", i ? "," : "", json_escape(d.notes[i].message),
                             json_range(d.notes[i].range, sources));
        out += "]}\n";
      }
      break;
    case DiagFormat::Sarif: {
      std::vector<DiagId> rules;
      for (const Diagnostic& d : list)
        if (std::find(rules.begin(), rules.end(), d.id) == rules.end()) rules.push_back(d.id);
      out +=
          R"({"$schema":"https://json.schemastore.org/sarif-2.1.0.json","version":"2.1.0","runs":[{"tool":{"driver":{"name":"ncc","informationUri":"https://example.invalid/ncc","rules":[)";
      for (size_t i = 0; i < rules.size(); ++i)
        out +=
            fmt::format(R"({}{{"id":"{}","name":"{}"}})", i ? "," : "", diag_code(rules[i]), diag_info(rules[i]).name);
      out += "]}},\"columnKind\":\"unicodeCodePoints\",\"results\":[";
      for (size_t i = 0; i < list.size(); ++i) {
        const Diagnostic& d = list[i];
        out += fmt::format(R"({}{{"ruleId":"{}","level":"{}","message":{{"text":"{}"}})", i ? "," : "", diag_code(d.id),
                           sarif_level(d.severity), json_escape(d.message));
        if (d.range.valid() && d.range.file < sources.size())
          out +=
              fmt::format(R"(,"locations":[{{"physicalLocation":{{"artifactLocation":{{"uri":"{}"}},"region":{}}}}}])",
                          json_escape(sources.file(d.range.file).path()), sarif_region(sources, d.range));
        if (!d.notes.empty()) {
          out += R"(,"relatedLocations":[)";
          for (size_t k = 0; k < d.notes.size(); ++k) {
            const Note& n = d.notes[k];
            out += fmt::format(R"({}{{"message":{{"text":"{}"}})", k ? "," : "", json_escape(n.message));
            if (n.range.valid() && n.range.file < sources.size())
              out += fmt::format(R"(,"physicalLocation":{{"artifactLocation":{{"uri":"{}"}},"region":{}}})",
                                 json_escape(sources.file(n.range.file).path()), sarif_region(sources, n.range));
            out += "}";
          }
          out += "]";
        }
        out += "}";
      }
      out += "]}]}\n";
      break;
    }
  }
  return out;
}

}  // namespace ncc
