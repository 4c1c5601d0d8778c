#include "writer.h"

#include <cmath>

#include <fmt/format.h>

namespace ncc::translate {
namespace {

// A number in fixed notation without trailing zeros, with a point when `point`.
std::string trimmed(std::string s, bool point) {
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.' && !point) s.pop_back();
  } else if (point) {
    s += '.';
  }
  return s;
}

}  // namespace

std::string Writer::decimal(double v, int decimals, bool point) {
  const double scale = std::pow(10.0, decimals);
  double r = std::round(v * scale) / scale;
  if (r == 0) r = 0;  // never "-0"
  return trimmed(fmt::format("{:.{}f}", r, decimals), point);
}

std::string exact(double v, bool point) {
  if (v == 0) v = 0;  // never "-0"
  std::string s;
  for (int decimals = 0; decimals <= 24; ++decimals) {
    s = fmt::format("{:.{}f}", v, decimals);
    if (std::strtod(s.c_str(), nullptr) == v) break;
  }
  return trimmed(std::move(s), point);
}

int Writer::rate_decimals(char letter) const {
  const auto it = tables().addresses.find(letter);
  if (it == tables().addresses.end() || !it->second.ranged) return 6;
  // The decimals the range writes, at either end (pp's F 0.001..24000 takes 3).
  const stdlib::AddressEntry& a = it->second;
  int decimals = a.decimals;
  while (decimals < 6 &&
         std::fabs(a.min * std::pow(10.0, decimals) - std::round(a.min * std::pow(10.0, decimals))) > 1e-9)
    ++decimals;
  return decimals;
}

std::optional<double> Writer::rounded_rate(const OutWord& w) const {
  if (w.kind != Value::Feed && w.kind != Value::Speed && w.kind != Value::Seconds && w.kind != Value::Count)
    return std::nullopt;
  const double scale = std::pow(10.0, rate_decimals(w.letter));
  const double v = std::round(w.value * scale) / scale;
  if (std::fabs(v - w.value) <= 1e-9 * std::max(1.0, std::fabs(w.value))) return std::nullopt;
  return v;
}

std::optional<std::string> Writer::unwritable(const OutWord& w) const {
  if (w.kind == Value::Code) return std::nullopt;
  const auto it = tables().addresses.find(w.letter);
  if (it == tables().addresses.end() || !it->second.ranged) return std::nullopt;
  const stdlib::AddressEntry& a = it->second;
  // A length is rounded to the step the target writes (resolution); a feed, a speed
  // or a dwell by a hundredth of itself at most; a count not at all.
  double v = w.value;
  if (auto r = rounded_rate(w)) {
    if (w.kind == Value::Count || std::fabs(*r - w.value) > kRateRounding * std::fabs(w.value))
      return fmt::format("{}{}: {} writes {} with {} decimals", w.letter, decimal(w.value, 6, false), dialect(),
                         w.letter, rate_decimals(w.letter));
    v = *r;
  }
  if (v >= a.min && v <= a.max) return std::nullopt;
  return fmt::format("{}{}: {} writes {} from {} to {}", w.letter, decimal(w.value, 4, false), dialect(), w.letter,
                     decimal(a.min, 4, false), decimal(a.max, 4, false));
}

std::string Writer::inline_comment(std::string_view text) const {
  std::string out = "(";
  for (char c : text) out += c == '(' ? '[' : c == ')' ? ']' : c;  // a comment does not nest
  return out + ")";
}

std::string Writer::number(const OutWord& w) const {
  return exact(w.value, w.kind != Value::Code && w.kind != Value::Count);
}

std::optional<int> Writer::end_code() const {
  std::optional<int> end;
  for (const auto& [number, entry] : tables().m_codes) {
    const std::vector<FnCall>& calls = entry.desc.calls;
    if (calls.size() != 1) continue;
    if (calls[0].fn == Fn::ProgramEndInformation) return number;
    if (calls[0].fn == Fn::ProgramEnd && !end) end = number;
  }
  return end;
}

bool is_target(std::string_view dialect) {
  return dialect == "gost" || dialect == "nc110" || dialect == "pp" || dialect == "iso" || dialect == "linuxcnc";
}

std::unique_ptr<Writer> make_writer(std::string_view dialect, const stdlib::Profile& profile, Diagnostics& diags) {
  // LinuxCNC's codes are the ISO dialect's, for everything a translation writes.
  auto target = make_frontend(dialect == "linuxcnc" ? "iso" : dialect, profile, diags);
  if (!target) return nullptr;
  if (dialect == "linuxcnc") {
    const uint32_t errors = diags.error_count();
    Conventions conventions = target->conventions();
    conventions.corners = false;  // no ,C ,R: a corner is written as its moves
    auto writer = make_iso_writer(std::move(target), true);
    writer->set_own(stdlib::load_dialect_tables("linuxcnc", diags), std::move(conventions));
    return diags.error_count() == errors ? std::move(writer) : nullptr;
  }
  if (dialect == "iso") return make_iso_writer(std::move(target), false);
  if (dialect == "gost") return make_gost_writer(std::move(target), profile);
  if (dialect == "pp") return make_pp_writer(std::move(target));
  return make_nc110_writer(std::move(target));
}

std::string header_text(const Header& h, std::string_view separator) {
  return fmt::format("{} from {}, dialect {}{}{}", h.flattened ? "flattened" : "translated", h.source, h.dialect,
                     h.title.empty() ? "" : separator, h.title);
}

std::string own_title(std::string_view title) {
  for (std::string_view kind : {"translated from ", "flattened from "}) {
    if (!title.starts_with(kind)) continue;
    for (std::string_view dialect : {"gost", "nc110", "pp", "iso", "linuxcnc"}) {
      const std::string mark = fmt::format(", dialect {}", dialect);
      const size_t at = title.find(mark);
      if (at == std::string_view::npos) continue;
      std::string_view rest = title.substr(at + mark.size());
      if (rest.empty()) return {};
      for (std::string_view separator : {": ", " - "})
        if (rest.starts_with(separator)) return std::string(rest.substr(separator.size()));
    }
  }
  return std::string(title);
}

}  // namespace ncc::translate
