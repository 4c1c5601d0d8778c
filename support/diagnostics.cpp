#include "diagnostics.h"

#include <algorithm>
#include <array>

namespace ncc {

namespace {

constexpr std::array kCatalogue = {
#define DIAG(id, number, name, severity, message) DiagInfo{DiagId::id, number, name, Severity::severity, message},
#include "diagnostics.def"
#undef DIAG
};

// The length of the valid, printable UTF-8 sequence at s[i], or 0.
size_t utf8_length(std::string_view s, size_t i) {
  unsigned char c = static_cast<unsigned char>(s[i]);
  if (c >= 0x20 && c < 0x7F) return 1;
  size_t n = c >= 0xF0 && c < 0xF5 ? 4 : c >= 0xE0 ? (c < 0xF0 ? 3 : 0) : c >= 0xC2 ? 2 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  return n;
}

// Display width of a line prefix: one column per character, valid or not.
size_t display_width(std::string_view s) {
  size_t w = 0;
  for (size_t i = 0; i < s.size(); ++w) {
    size_t n = utf8_length(s, i);
    i += n ? n : 1;
  }
  return w;
}

// The line as printed under a diagnostic: control characters become spaces so the
// caret stays aligned; very long lines are cut to a window around the column.
struct Excerpt {
  std::string text;
  size_t caret_col = 0;  // 0-based display column
  size_t caret_len = 1;
};

Excerpt make_excerpt(std::string_view line, uint32_t col, uint32_t end_col) {
  constexpr size_t kWindow = 120;
  size_t begin = 0;
  size_t start = col > 0 ? col - 1 : 0;
  start = std::min(start, line.size());
  size_t end = (end_col > col) ? std::min<size_t>(end_col - 1, line.size()) : start + 1;
  if (line.size() > kWindow && start > kWindow / 2) begin = start - kWindow / 2;
  // Keep whole UTF-8 sequences.
  while (begin > 0 && begin < line.size() && (static_cast<unsigned char>(line[begin]) & 0xC0) == 0x80) --begin;
  size_t stop = std::min(line.size(), begin + kWindow);
  while (stop < line.size() && (static_cast<unsigned char>(line[stop]) & 0xC0) == 0x80) ++stop;
  Excerpt e;
  if (begin > 0) e.text = "...";
  // Control characters print as spaces and broken UTF-8 as '?', one column each.
  for (size_t i = begin; i < stop;) {
    unsigned char c = static_cast<unsigned char>(line[i]);
    size_t n = utf8_length(line, i);
    if (n == 0) {
      e.text += (c < 0x80 && (c < 0x20 || c == 0x7F)) ? ' ' : '?';
      ++i;
    } else {
      e.text.append(line.substr(i, n));
      i += n;
    }
  }
  if (stop < line.size()) e.text += "...";
  size_t prefix = begin > 0 ? 3 : 0;
  e.caret_col = prefix + display_width(line.substr(begin, start - begin));
  size_t visible_end = std::min(end, stop);
  e.caret_len = visible_end > start ? std::max<size_t>(1, display_width(line.substr(start, visible_end - start))) : 1;
  return e;
}

std::string location_text(const SourceRange& r, const SourceManager& sources) {
  if (!r.valid() || r.file >= sources.size()) return "ncc";
  return fmt::format("{}:{}:{}", sources.file(r.file).path(), r.line, r.col);
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

// SARIF counts columns in characters (columnKind unicodeCodePoints); ncc in bytes.
uint32_t char_column(const SourceManager& sources, const SourceRange& r, uint32_t byte_col, uint32_t line) {
  std::string_view text = sources.file(r.file).line(line);
  return static_cast<uint32_t>(display_width(text.substr(0, std::min<size_t>(byte_col - 1, text.size())))) + 1;
}

std::string sarif_region(const SourceManager& sources, const SourceRange& r) {
  return fmt::format(R"({{"startLine":{},"startColumn":{},"endLine":{},"endColumn":{}}})", r.line,
                     char_column(sources, r, r.col, r.line), r.end_line, char_column(sources, r, r.end_col, r.end_line));
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
                      severity_color(d.severity), severity_name(d.severity), d.message, diag_code(d.id));
  else
    out = fmt::format("{}: {}: {} [{}]\n", location_text(d.range, sources), severity_name(d.severity), d.message,
                      diag_code(d.id));
  append_quote(out, d.range, sources, color);
  for (const Note& n : d.notes) {
    out += fmt::format("{}: note: {}\n", location_text(n.range, sources), n.message);
    append_quote(out, n.range, sources, color);
  }
  return out;
}

std::string json_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      // JSON text is UTF-8: a byte that starts no valid sequence becomes U+FFFD.
      size_t n = utf8_length(s, i);
      if (n == 0) {
        out += "\\ufffd";
      } else {
        out.append(s.substr(i, n));
        i += n - 1;
      }
      continue;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20 || c == 0x7F) out += fmt::format("\\u{:04x}", c);
        else out += static_cast<char>(c);
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
      out += R"({"$schema":"https://json.schemastore.org/sarif-2.1.0.json","version":"2.1.0","runs":[{"tool":{"driver":{"name":"ncc","informationUri":"https://example.invalid/ncc","rules":[)";
      for (size_t i = 0; i < rules.size(); ++i)
        out += fmt::format(R"({}{{"id":"{}","name":"{}"}})", i ? "," : "", diag_code(rules[i]),
                           diag_info(rules[i]).name);
      out += "]}},\"columnKind\":\"unicodeCodePoints\",\"results\":[";
      for (size_t i = 0; i < list.size(); ++i) {
        const Diagnostic& d = list[i];
        out += fmt::format(R"({}{{"ruleId":"{}","level":"{}","message":{{"text":"{}"}})", i ? "," : "",
                           diag_code(d.id), sarif_level(d.severity), json_escape(d.message));
        if (d.range.valid() && d.range.file < sources.size())
          out += fmt::format(
              R"(,"locations":[{{"physicalLocation":{{"artifactLocation":{{"uri":"{}"}},"region":{}}}}}])",
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
