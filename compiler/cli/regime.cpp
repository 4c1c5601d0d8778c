#include "regime.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "sim/regime.h"
#include "support/text.h"

namespace ncc {

const char* const kRegimeUsage =
    R"(usage: ncc regime --diameter D [--teeth Z] [--material NAME --tool KIND] [--vc V] [--fz F | --fn F] [options]
       ncc regime --list [--material NAME] [--tool KIND]

Cutting conditions: the spindle speed and the feed for a tool from its diameter, its
teeth, the cutting speed and the feed per tooth (per revolution for a drill), given or
taken from the reference table stdlib/cutting_data.tsv, which names its sources:
  n  = 1000 Vc / (pi D)   rpm
  Vf = fz z n             mm/min, milling          Vf = f n   mm/min, drilling
A value from the table is the middle of its range; the ranges that follow from the
table's min..max are printed too. A given value overrides the table's. The block:
S is n rounded to a whole rpm, F the feed at that S rounded to a whole mm/min (with
--inch, to 0.1 in/min), M3 the spindle on clockwise.

options:
  --diameter D       the tool's diameter, mm
  --teeth Z          the teeth (flutes, inserts) of a mill; not used for a drill
  --material NAME    reference values for a material group (--list names them)
  --tool KIND        reference values for a tool kind, which also says whether the
                     feed is per tooth or per revolution (--list names them)
  --vc V             cutting speed, m/min
  --fz F             feed per tooth, mm (a mill)
  --fn F             feed per revolution, mm (a drill)
  --max-rpm N        the machine's highest spindle speed: n is clamped to it and the
                     feed follows from fz z n at the clamped n
  --max-feed F       the machine's highest feed, mm/min: Vf is clamped to it and the
                     feed per tooth (revolution) follows
  --inch             inch units: D, fz, fn in inches, Vc in ft/min (SFM), feeds in
                     in/min; n = 12 Vc / (pi D)
  --list             the table: materials, tool kinds, reference values, sources
  -h, --help         show this help

exit status: 0 success, 2 usage errors (a missing or bad value, an unknown material or
tool kind, no reference value where one is needed)
)";

namespace {

constexpr int kOk = 0, kUsage = 2;
constexpr double kInch = 25.4, kFoot = 0.3048;

struct Args {
  std::optional<double> diameter, vc, fz, fn, max_rpm, max_feed;
  std::optional<int> teeth;
  std::string material, tool;
  bool inch = false, list = false;
};

// Up to `decimals` decimals, trailing zeros removed.
std::string num(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

std::string range(double lo, double hi, int decimals) {
  return lo == hi ? num(lo, decimals) : num(lo, decimals) + ".." + num(hi, decimals);
}

// What the user reads and writes, and the metric values inside.
struct Units {
  bool inch = false;
  double length(double mm) const { return inch ? mm / kInch : mm; }
  double speed(double m_per_min) const { return inch ? m_per_min / kFoot : m_per_min; }
  int length_decimals() const { return 4; }
  int speed_decimals() const { return inch ? 0 : 1; }  // whole ft/min: the inch sources' own numbers
  int feed_decimals() const { return inch ? 5 : 4; }
  const char* mm() const { return inch ? "in" : "mm"; }
  const char* per_min() const { return inch ? "in/min" : "mm/min"; }
  const char* vc() const { return inch ? "ft/min" : "m/min"; }
  std::string d(double mm) const { return num(length(mm), length_decimals()); }
  std::string feed(double mm) const { return num(length(mm), feed_decimals()); }
};

int usage_error(const std::string& message) {
  std::fprintf(stderr,
               "ncc regime: error: %s\nusage: ncc regime --diameter D [--teeth Z] [--material NAME --tool KIND] "
               "[--vc V] [--fz F | --fn F] [options]\n",
               message.c_str());
  return kUsage;
}

int error(const std::string& message) {
  std::fprintf(stderr, "ncc regime: error: %s\n", message.c_str());
  return kUsage;
}

// Returns an error message, or "" when the arguments are good.
std::string parse(const std::vector<std::string>& args, Args& a) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& opt = args[i];
    auto value = [&](std::optional<double>& out) -> std::string {
      if (i + 1 >= args.size()) return fmt::format("{} needs a number", opt);
      const std::string& text = args[++i];
      auto v = parse_number<double>(text);
      if (!v || !std::isfinite(*v))
        return fmt::format("{} needs a number, not '{}'", opt, printable(abbreviated(text)));
      if (*v <= 0) return fmt::format("{} must be positive, not {}", opt, text);
      // Bounds that keep n and S within what a long and a printed line hold.
      if (*v < 1e-6 || *v > 1e6) return fmt::format("{} must be 0.000001 to 1000000, not {}", opt, text);
      out = *v;
      return {};
    };
    auto word = [&](std::string& out) -> std::string {
      if (i + 1 >= args.size()) return fmt::format("{} needs a name", opt);
      out = args[++i];
      return {};
    };
    std::string problem;
    if (opt == "--diameter")
      problem = value(a.diameter);
    else if (opt == "--vc")
      problem = value(a.vc);
    else if (opt == "--fz")
      problem = value(a.fz);
    else if (opt == "--fn")
      problem = value(a.fn);
    else if (opt == "--max-rpm")
      problem = value(a.max_rpm);
    else if (opt == "--max-feed")
      problem = value(a.max_feed);
    else if (opt == "--material")
      problem = word(a.material);
    else if (opt == "--tool")
      problem = word(a.tool);
    else if (opt == "--inch")
      a.inch = true;
    else if (opt == "--list")
      a.list = true;
    else if (opt == "--teeth") {
      if (i + 1 >= args.size()) return "--teeth needs a number";
      const std::string& text = args[++i];
      auto z = parse_number<int>(text);
      if (!z || *z < 1 || *z > 1000)
        return fmt::format("--teeth needs a whole number 1 to 1000, not '{}'", printable(abbreviated(text)));
      a.teeth = *z;
    } else if (opt.size() > 1 && opt[0] == '-') {
      return fmt::format("unknown option '{}' for 'ncc regime'", printable(abbreviated(opt)));
    } else {
      return fmt::format("unexpected argument '{}': ncc regime reads options only", printable(abbreviated(opt)));
    }
    if (!problem.empty()) return problem;
  }
  return {};
}

template <typename T>
std::string keys(const std::vector<T>& list) {
  std::string out;
  for (const T& item : list) out += (out.empty() ? "" : ", ") + item.key;
  return out;
}

std::string band(const sim::CuttingRow& r, const Units& u) {
  const bool open = std::isinf(r.d_max);
  if (r.d_min == 0 && open) return "any D";
  if (open) return fmt::format("D {} {} and over", u.d(r.d_min), u.mm());
  if (r.d_min == r.d_max) return fmt::format("D {} {}", u.d(r.d_min), u.mm());
  return fmt::format("D {}..{} {}", u.d(r.d_min), u.d(r.d_max), u.mm());
}

const char* feed_unit(sim::FeedPer per, const Units& u) {
  if (per == sim::FeedPer::Tooth) return u.inch ? "in/tooth" : "mm/tooth";
  return u.inch ? "in/rev" : "mm/rev";
}

void print_line(std::string_view label, std::string_view value, std::string_view note) {
  std::string text = fmt::format("{:<11}{:<19} {}", label, value, note);
  while (!text.empty() && text.back() == ' ') text.pop_back();
  std::printf("%s\n", text.c_str());
}

void print_list(const sim::CuttingTable& table, const Args& a, const Units& u) {
  std::printf("materials\n");
  for (const sim::CuttingMaterial& m : table.materials)
    if (a.material.empty() || table.material(a.material) == &m)
      std::printf("  %-18s %s\n", m.key.c_str(), m.name.c_str());
  std::printf("tool kinds\n");
  for (const sim::ToolKind& t : table.tools)
    if (a.tool.empty() || table.tool(a.tool) == &t)
      std::printf("  %-18s %-21s %s\n", t.key.c_str(),
                  t.feed_per == sim::FeedPer::Tooth ? "feed per tooth (fz)" : "feed per rev (f)", t.name.c_str());
  std::set<std::string> used;  // the sources of the rows printed
  std::printf("reference values (D %s, Vc %s, fz %s, f %s)\n", u.mm(), u.vc(), feed_unit(sim::FeedPer::Tooth, u),
              feed_unit(sim::FeedPer::Revolution, u));
  for (const sim::ToolKind& t : table.tools) {
    if (!a.tool.empty() && table.tool(a.tool) != &t) continue;
    bool header = false;
    for (const sim::CuttingMaterial& m : table.materials) {
      if (!a.material.empty() && table.material(a.material) != &m) continue;
      for (const sim::CuttingRow* r : table.rows_for(t.key, m.key)) {
        if (!header) std::printf("  %s\n", t.key.c_str());
        header = true;
        used.insert(r->source);
        const std::string f = r->has_feed ? range(u.length(r->f_min), u.length(r->f_max), u.feed_decimals()) : "-";
        std::printf("    %-18s %-20s Vc %-14s %-3s %-16s %s\n", m.key.c_str(), band(*r, u).c_str(),
                    range(u.speed(r->vc_min), u.speed(r->vc_max), u.speed_decimals()).c_str(),
                    t.feed_per == sim::FeedPer::Tooth ? "fz" : "f", f.c_str(), r->source.c_str());
      }
    }
  }
  std::printf("sources (stdlib/cutting_data.tsv says where each was read)\n");
  for (const sim::CuttingSource& s : table.sources)
    if (used.count(s.key)) std::printf("  %-8s %s\n", s.key.c_str(), s.title.c_str());
}

// Where a value comes from: given (and what the table has), or the table's.
std::string origin(bool given, bool in_table, double lo, double hi, int decimals) {
  const std::string table = range(lo, hi, decimals);
  if (given) return in_table ? fmt::format("given (the table: {})", table) : "given";
  return lo == hi ? "the table" : fmt::format("the middle of the table's {}", table);
}

}  // namespace

int regime_command(const std::vector<std::string>& args) {
  for (const std::string& a : args)
    if (a == "-h" || a == "--help") {
      std::fputs(kRegimeUsage, stdout);
      return kOk;
    }
  Args a;
  if (std::string problem = parse(args, a); !problem.empty()) return usage_error(problem);
  const Units u{a.inch};

  std::vector<std::string> table_errors;
  const sim::CuttingTable table = sim::load_cutting_table(table_errors);
  for (const std::string& e : table_errors) error(fmt::format("the cutting data table: {}", e));
  if (!table_errors.empty()) return kUsage;

  const sim::CuttingMaterial* material = nullptr;
  const sim::ToolKind* tool = nullptr;
  if (!a.material.empty() && !(material = table.material(a.material)))
    return error(fmt::format("unknown material '{}'; the table knows {}", printable(abbreviated(a.material)),
                             keys(table.materials)));
  if (!a.tool.empty() && !(tool = table.tool(a.tool)))
    return error(
        fmt::format("unknown tool kind '{}'; the table knows {}", printable(abbreviated(a.tool)), keys(table.tools)));
  if (a.list) {
    print_list(table, a, u);
    return kOk;
  }

  // What is asked: the feed per tooth or per revolution, the tool's size.
  if (!a.diameter) return usage_error("--diameter is needed: the tool's diameter");
  if (material && !tool) return error("--material needs --tool: the table's values are for a tool kind in a material");
  if (a.fz && a.fn) return error("--fz (per tooth, a mill) or --fn (per revolution, a drill), not both");
  sim::FeedPer per = sim::FeedPer::Tooth;
  if (tool) {
    per = tool->feed_per;
    if (per == sim::FeedPer::Revolution && a.fz)
      return error(fmt::format("{} is a drill: its feed is per revolution, --fn", tool->key));
    if (per == sim::FeedPer::Tooth && a.fn)
      return error(fmt::format("{} is a mill: its feed is per tooth, --fz", tool->key));
  } else if (a.fn) {
    per = sim::FeedPer::Revolution;
  } else if (!a.fz) {
    return error("no feed: give --fz (per tooth, a mill) or --fn (per revolution, a drill), or --material and --tool");
  }
  if (!tool && !a.vc) return error("no cutting speed: give --vc, or --material and --tool");
  if (per == sim::FeedPer::Tooth && !a.teeth) return error("--teeth is needed: a mill's feed is per tooth");

  const double to_mm = a.inch ? kInch : 1, to_m = a.inch ? kFoot : 1;
  sim::RegimeInput in;
  in.diameter = *a.diameter * to_mm;
  in.teeth = per == sim::FeedPer::Tooth ? *a.teeth : 1;
  if (a.max_rpm) in.max_rpm = *a.max_rpm;
  if (a.max_feed) in.max_feed = *a.max_feed * to_mm;
  const std::optional<double> given_feed = a.fz ? a.fz : a.fn;
  const char* f_name = per == sim::FeedPer::Tooth ? "fz" : "f";
  const char* f_option = per == sim::FeedPer::Tooth ? "--fz" : "--fn";

  // The table's values, where it has them.
  std::optional<sim::Reference> ref;
  if (tool && material) ref = table.reference(tool->key, material->key, in.diameter);
  if (tool && (!a.vc || !given_feed) && !ref) {
    if (!material) return error(fmt::format("no cutting speed or feed: give --vc and {}, or --material", f_option));
    return error(fmt::format("the table has no reference values for {} in {} ('ncc regime --list'); give --vc and {}",
                             tool->key, material->key, f_option));
  }
  if (ref && !given_feed && !ref->has_feed)
    return error(fmt::format("the table gives no feed for {} in {} ({} gives a cutting speed only); give {}", tool->key,
                             material->key, ref->source, f_option));
  const bool table_feed = ref && ref->has_feed;
  const double vc_lo = a.vc ? *a.vc * to_m : ref->vc_min, vc_hi = a.vc ? *a.vc * to_m : ref->vc_max;
  const double f_lo = given_feed ? *given_feed * to_mm : ref->f_min,
               f_hi = given_feed ? *given_feed * to_mm : ref->f_max;
  in.vc = (vc_lo + vc_hi) / 2;
  in.feed = (f_lo + f_hi) / 2;
  const sim::Regime r = sim::compute_regime(in);

  // What was asked and where each value came from.
  std::string tool_text = tool ? fmt::format("{} ({}), ", tool->key, tool->name) : "";
  tool_text += fmt::format("D {} {}", u.d(in.diameter), u.mm());
  if (per == sim::FeedPer::Tooth)
    tool_text += fmt::format(", {} {}", in.teeth, in.teeth == 1 ? "tooth" : "teeth");
  else
    tool_text += a.teeth ? ", feed per revolution (--teeth is not used)" : ", feed per revolution";
  print_line("tool", tool_text, "");
  if (material) print_line("material", fmt::format("{}: {}", material->key, material->name), "");
  if (tool && material && !ref) print_line("reference", "none in the table for this pair", "");
  if (ref) {
    std::string text;
    auto row_text = [&](const sim::CuttingRow& row) {
      return row.note.empty() ? row.source : fmt::format("{} \"{}\"", row.source, row.note);
    };
    if (ref->how == sim::Reference::How::Row)
      text = fmt::format("the row for {}: {}", band(*ref->below, u), row_text(*ref->below));
    else if (ref->how == sim::Reference::How::Interpolated)
      text = fmt::format("between the rows for {} and {}, linear in D: {}", band(*ref->below, u), band(*ref->above, u),
                         ref->source);
    else
      text = fmt::format("D {} {} is outside the table's rows; the nearest, for {}: {}", u.d(in.diameter), u.mm(),
                         band(*ref->below, u), row_text(*ref->below));
    print_line("reference", text, "");
  }
  print_line("Vc", fmt::format("{} {}", num(u.speed(in.vc), u.speed_decimals()), u.vc()),
             origin(a.vc.has_value(), ref.has_value(), u.speed(ref ? ref->vc_min : 0), u.speed(ref ? ref->vc_max : 0),
                    u.speed_decimals()));
  print_line(f_name, fmt::format("{} {}", u.feed(in.feed), feed_unit(per, u)),
             origin(given_feed.has_value(), table_feed, u.length(table_feed ? ref->f_min : 0),
                    u.length(table_feed ? ref->f_max : 0), u.feed_decimals()));

  // The results, and the ranges over the table's min..max.
  const bool ranged = vc_lo != vc_hi || f_lo != f_hi;
  sim::RegimeInput lo = in, hi = in;
  lo.vc = vc_lo, lo.feed = f_lo, hi.vc = vc_hi, hi.feed = f_hi;
  const sim::Regime r_lo = sim::compute_regime(lo), r_hi = sim::compute_regime(hi);
  const std::string formula = per == sim::FeedPer::Tooth ? "fz z n" : "f n";
  const char* n_formula = a.inch ? "12 Vc / (pi D)" : "1000 Vc / (pi D)";
  auto span = [](double lo_value, double hi_value) {
    return lo_value == hi_value ? fmt::format("{:.1f}", lo_value) : fmt::format("{:.1f}..{:.1f}", lo_value, hi_value);
  };
  if (r.rpm_clamped)
    print_line("n", fmt::format("{:.1f} rpm", r.rpm),
               fmt::format("clamped to --max-rpm {} from {} = {:.1f}: Vc becomes {} {}", num(in.max_rpm, 1), n_formula,
                           r.rpm_wanted, num(u.speed(r.vc), u.speed_decimals()), u.vc()));
  else
    print_line("n", fmt::format("{:.1f} rpm", r.rpm), fmt::format("= {}", n_formula));
  if (vc_lo != vc_hi)
    print_line("", span(r_lo.rpm, r_hi.rpm),
               r_hi.rpm_clamped ? "over the table's Vc range, clamped" : "over the table's Vc range");
  if (r.feed_clamped)
    print_line("Vf", fmt::format("{:.1f} {}", u.length(r.feed_rate), u.per_min()),
               fmt::format("clamped to --max-feed {} from {} = {:.1f}: {} becomes {} {}", num(u.length(in.max_feed), 1),
                           formula, u.length(r.feed_wanted), f_name, u.feed(r.feed), feed_unit(per, u)));
  else
    print_line("Vf", fmt::format("{:.1f} {}", u.length(r.feed_rate), u.per_min()),
               r.rpm_clamped ? "= " + formula + " at the clamped n" : "= " + formula);
  if (ranged)
    print_line("", span(u.length(r_lo.feed_rate), u.length(r_hi.feed_rate)),
               fmt::format("over the table's {}{}", vc_lo != vc_hi && f_lo != f_hi ? "ranges" : "range",
                           r_hi.rpm_clamped || r_hi.feed_clamped ? ", clamped" : ""));
  const sim::BlockWords words = sim::block_words(r, in, a.inch);
  print_line("block", words.text,
             fmt::format("S: n to a whole rpm; F: {} to {}", per == sim::FeedPer::Tooth ? "fz z S" : "f S",
                         a.inch ? "0.1 in/min" : "a whole mm/min"));
  if (ref)
    for (const std::string& key : split(ref->source, '/'))
      if (const sim::CuttingSource* s = table.source(key))
        print_line("source", fmt::format("{}: {}", s->key, s->title), "");
  return kOk;
}

}  // namespace ncc
