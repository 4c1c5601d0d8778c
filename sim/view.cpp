// `ncc view`'s page: sim/view/page.html with its style, three.js and the script
// sim/view/view.js inlined, and the run as one JSON object (the script's `data`):
//
//   format                      1
//   title, dialect, axes        the program, its dialect, the machine's axis letters
//   origin [x, y, z]            machine coordinates of the work zero the positions are from (mm)
//   unit                        mm per integer of the positions in `moves` (0.0001)
//   tolerance                   mm: how far merged straight moves may leave the path (0: none merged)
//   arc_tolerance               mm: the chords the page draws for an arc stay this close to it
//   stock [x0 y0 z0 x1 y1 z1]   mm, or null; grid: the height map's cell (mm); cells [nx, ny]
//   tools [[tool, radius]]      mm
//   sources [{name, text}]      diagnostics [{file, line, column, severity, id, message}]
//   counts {moves, records}     the Toolpath's moves, and the records drawn for them
//   moves [op ...]              the path, record after record:
//       0 rapid, 1 line, 2 arc, 3 thread (+4: programmed, under compensation; +16 f:
//         the feed is now feeds[f - 1]), then dx dy dz in units from where the
//         record's lane (process, programmed) stands;
//         an arc then u*3+v of its plane (-1: not in X Y Z, drawn straight), the
//         centre's du dv from the start, the sweep in degrees (negative clockwise from +w)
//       8 x y z: the next record starts there; 9 t: the tool; 10 p: the process;
//       11 f: the feed (mm/min) of the moves after
//   feeds [f ...]               mm/min: the feeds records name (the first 4096 seen)
//   steps [dline, records ...]  the blocks that ran, in order: a block's step is the
//                               events (moves, pauses) it made one after another; its
//                               line from the step before's, the records it drew; -n
//                               stands for n steps of one record on the next line
//   files [[step, file]]        where the steps' file changes (steps count from 1)
//   tools_at [[step, tool]]     the tool in the spindle from that step on
//   notes [[step, text]]        what the block did besides moving (tool change, dwell...)
//   offsets [[step, number, x, y, z]]  the work offset in force from that step on
//   models [{name, cutting, rapid, tool_change, dwell, spindle, total}]  seconds
//   times [[dt ...] ...]        per model, each step's time from the start, in tenths of
//                               a second, less the step before's
//
// Besides the source text, the page grows with the blocks that ran, not with the
// moves: the moves of one block that go straight on (no vertex leaves the merged chord
// by more than `tolerance`) become one record, so the chords of a spline, a parabola
// or a block's fine steps cost one; every block's end point is kept exactly, and so is
// every corner more than `tolerance` off the chord. A block costs ~30 bytes.
#include "view.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>

#include "sim/view/embedded.h"
#include "support/text.h"
#include "support/utf8.h"

namespace ncc::sim {
namespace {

constexpr double kUnit = 1e-4;        // mm per integer of the page's positions
constexpr size_t kLongestMerge = 64;  // moves in one record at most (the check is quadratic)
constexpr double kMaxCells = 1e6;     // of the height map
constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
constexpr size_t kFeedTable = 4096;  // feeds a record names by their entry (more: written out)

std::string_view embedded(std::span<const view_files::EmbeddedFile> files, std::string_view path) {
  for (const auto& f : files)
    if (f.path == path) return f.text;
  return {};
}

// A JSON string that may stand inside <script>: '<' is escaped, bytes that are not
// UTF-8 read "\xCF" as ncc prints them elsewhere.
void json_string(std::string& out, std::string_view s) {
  out += '"';
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      const Utf8Char u = decode_utf8(s, i);
      if (u.length == 0) {
        out += fmt::format("\\\\x{:02X}", c);
        ++i;
      } else {
        out.append(s.substr(i, u.length));
        i += u.length;
      }
      continue;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      case '<': out += "\\u003c"; break;
      case '>': out += "\\u003e"; break;
      case '&': out += "\\u0026"; break;
      default:
        if (c < 0x20 || c == 0x7f)
          out += fmt::format("\\u{:04x}", c);
        else
          out += static_cast<char>(c);
    }
    ++i;
  }
  out += '"';
}

void json_number(std::string& out, double x) { out += std::isfinite(x) ? shortest(x) : std::string("0"); }

void json_int(std::string& out, int64_t x) { fmt::format_to(std::back_inserter(out), "{}", x); }

std::string html_escape(std::string_view s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '&': r += "&amp;"; break;
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '"': r += "&quot;"; break;
      default: r += c;
    }
  }
  return escape_invalid_utf8(r);
}

int64_t units(double mm) { return std::isfinite(mm) ? std::llround(mm / kUnit) : 0; }

using Units = std::array<int64_t, 3>;
Units units(const AxisValues& p) { return {units(p[0]), units(p[1]), units(p[2])}; }

// The smallest of 1, 2, 2.5, 5 times a power of ten that is at least x (> 0).
double nice_at_least(double x) {
  const int k = static_cast<int>(std::floor(std::log10(x)));
  const double power = k >= 0 ? std::pow(10.0, k) : 1.0 / std::pow(10.0, -k);
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * power >= x * (1 - 1e-12)) return m * power;
  return 10 * power;
}

// Distance from p to the segment a-b.
double segment_distance(const std::array<double, 3>& p, const std::array<double, 3>& a,
                        const std::array<double, 3>& b) {
  double d[3], w[3], dd = 0, wd = 0;
  for (int i = 0; i < 3; ++i) {
    d[i] = b[i] - a[i];
    w[i] = p[i] - a[i];
    dd += d[i] * d[i];
    wd += w[i] * d[i];
  }
  const double t = dd > 0 ? std::clamp(wd / dd, 0.0, 1.0) : 0.0;
  double s = 0;
  for (int i = 0; i < 3; ++i) s += (w[i] - t * d[i]) * (w[i] - t * d[i]);
  return std::sqrt(s);
}

std::array<double, 3> xyz(const AxisValues& p) { return {p[0], p[1], p[2]}; }

// Only X Y Z move (rotary and further axes stand still): the move may merge.
bool moves_in_xyz_only(const Move& m) {
  for (int i = 3; i < kAxisCount; ++i)
    if (m.start[i] != m.end[i]) return false;
  return true;
}

struct Step {
  uint32_t source = 0, run = 0;  // the block, and which run of it (Move::run)
  uint32_t first = 0, end = 0;   // its moves: PageData::order_ [first, end)
  uint32_t records = 0;
};

std::string pause_note(const Pause& p) {
  switch (p.kind) {
    case Pause::Kind::Dwell: return fmt::format("dwell {} s", four_decimals(p.seconds));
    case Pause::Kind::ToolChange: return fmt::format("tool change: T{}", p.tool);
    case Pause::Kind::Spindle:
      if (p.rpm_to == 0) return "spindle stop";
      if (p.rpm_from == 0) return fmt::format("spindle start: {} rpm", four_decimals(p.rpm_to));
      return fmt::format("spindle {} \u2192 {} rpm", four_decimals(p.rpm_from), four_decimals(p.rpm_to));
    case Pause::Kind::Stop: return "stop";
  }
  return {};
}

class PageData {
 public:
  PageData(const ViewInput& in, const Toolpath& path, std::string& out) : in_(in), path_(path), out_(out) {}

  void write() {
    make_steps();
    out_ += "{\"format\":1,\"title\":";
    json_string(out_, in_.title);
    out_ += ",\"dialect\":";
    json_string(out_, in_.dialect);
    out_ += ",\"axes\":";
    json_string(out_, path_.axes);
    out_ += ",\"origin\":[";
    for (int i = 0; i < 3; ++i) {
      if (i) out_ += ',';
      json_number(out_, path_.origin[i]);
    }
    out_ += "],\"unit\":";
    json_number(out_, kUnit);
    out_ += ",\"tolerance\":";
    json_number(out_, std::max(in_.tolerance, 0.0));
    out_ += ",\"arc_tolerance\":";
    json_number(out_, in_.tolerance > 0 ? in_.tolerance : 0.001);
    write_stock();
    write_tools();
    write_sources();
    write_diagnostics();
    write_moves();  // counts the steps' records
    write_steps();
    write_times();
    out_ += "}";
  }

 private:
  // The steps, and the order of the moves in them: a programmed move (it comes before
  // the tool centre's moves it became) waits for its block's step, so that stepping
  // to a block draws its programmed contour with it.
  void make_steps() {
    const auto& moves = path_.moves;
    const auto& pauses = path_.pauses;
    order_.reserve(moves.size());
    step_of_move_.assign(moves.size(), 0);
    std::vector<uint32_t> waiting;   // programmed moves, in order
    auto take = [&](size_t count) {  // the first `count` waiting moves join the step open
      for (size_t k = 0; k < count; ++k) join_step(waiting[k]);
      waiting.erase(waiting.begin(), waiting.begin() + static_cast<std::ptrdiff_t>(count));
    };
    auto at = [&](uint32_t source, uint32_t run) {
      if (steps_.empty() || steps_.back().source != source || steps_.back().run != run) {
        if (!steps_.empty() && waiting.size() > 16) take(waiting.size() - 16);  // not this one's, it seems
        const uint32_t here = static_cast<uint32_t>(order_.size());
        steps_.push_back({source, run, here, here, 0});
      }
      size_t mine = 0;
      for (size_t k = 0; k < waiting.size(); ++k)
        if (moves[waiting[k]].source == source) mine = k + 1;
      take(mine);
    };
    size_t p = 0;
    auto pauses_before = [&](uint32_t move) {
      for (; p < pauses.size() && pauses[p].after <= move; ++p) {
        at(pauses[p].source, pauses[p].run);
        pause_step_.push_back(static_cast<uint32_t>(steps_.size()));
      }
    };
    for (uint32_t i = 0; i < moves.size(); ++i) {
      pauses_before(i);
      const Move& m = moves[i];
      if (m.programmed && (steps_.empty() || steps_.back().source != m.source || steps_.back().run != m.run)) {
        waiting.push_back(i);
        continue;
      }
      at(m.source, m.run);
      join_step(i);
    }
    pauses_before(kNone);
    if (!waiting.empty()) {
      if (steps_.empty()) at(moves[waiting.front()].source, moves[waiting.front()].run);
      take(waiting.size());
    }
  }

  void join_step(uint32_t move) {
    step_of_move_[move] = static_cast<uint32_t>(steps_.size());
    order_.push_back(move);
    steps_.back().end = static_cast<uint32_t>(order_.size());
  }

  void write_stock() {
    const double* lo = in_.stock_min;
    const double* hi = in_.stock_max;
    const bool some = hi[0] > lo[0] && hi[1] > lo[1] && hi[2] > lo[2];
    out_ += ",\"stock\":";
    if (!some) {
      out_ += "null,\"grid\":0,\"cells\":[0,0]";
      return;
    }
    out_ += '[';
    for (int i = 0; i < 6; ++i) {
      if (i) out_ += ',';
      json_number(out_, i < 3 ? lo[i] : hi[i - 3]);
    }
    const double sx = hi[0] - lo[0], sy = hi[1] - lo[1];
    const double cell = view_grid(sx, sy, in_.grid);
    out_ += "],\"grid\":";
    json_number(out_, cell);
    out_ += fmt::format(",\"cells\":[{},{}]", std::max(1.0, std::ceil(sx / cell - 1e-9)),
                        std::max(1.0, std::ceil(sy / cell - 1e-9)));
  }

  void write_tools() {
    out_ += ",\"tools\":[";
    bool first = true;
    for (const auto& [tool, radius] : path_.tool_radii) {
      if (!first) out_ += ',';
      first = false;
      out_ += '[';
      json_int(out_, tool);
      out_ += ',';
      json_number(out_, radius);
      out_ += ']';
    }
    out_ += ']';
  }

  void write_sources() {
    out_ += ",\"sources\":[";
    for (size_t i = 0; i < in_.sources.size(); ++i) {
      if (i) out_ += ',';
      out_ += "{\"name\":";
      json_string(out_, in_.sources[i].name);
      out_ += ",\"text\":";
      json_string(out_, in_.sources[i].text);
      out_ += '}';
    }
    out_ += ']';
  }

  void write_diagnostics() {
    out_ += ",\"diagnostics\":[";
    for (size_t i = 0; i < in_.diagnostics.size(); ++i) {
      const ViewDiagnostic& d = in_.diagnostics[i];
      if (i) out_ += ',';
      out_ += fmt::format("{{\"file\":{},\"line\":{},\"column\":{},\"severity\":", d.file, d.line, d.column);
      json_string(out_, d.severity);
      out_ += ",\"id\":";
      json_string(out_, d.id);
      out_ += ",\"message\":";
      json_string(out_, d.message);
      out_ += '}';
    }
    out_ += ']';
  }

  // The records of the moves, step by step, merging straight runs (see the head comment).
  void write_moves() {
    const auto& moves = path_.moves;
    out_ += fmt::format(",\"moves\":[");
    first_value_ = true;
    for (size_t s = 0; s < steps_.size(); ++s) {
      Step& step = steps_[s];
      uint32_t i = step.first;
      while (i < step.end) {
        const uint32_t end = run_end(i, step.end);
        record(i, end);
        ++step.records;
        ++records_;
        i = end;
      }
    }
    out_ += fmt::format("],\"counts\":{{\"moves\":{},\"records\":{}}},\"feeds\":[", moves.size(), records_);
    first_value_ = true;
    for (double f : feeds_) value(f);
    out_ += ']';
  }

  // The end of the run of moves (order_ positions) from `first` that one straight
  // record can stand for.
  uint32_t run_end(uint32_t first, uint32_t limit) const {
    const auto& moves = path_.moves;
    const Move& a = moves[order_[first]];
    if (a.kind == MoveKind::Arc || in_.tolerance <= 0 || !moves_in_xyz_only(a)) return first + 1;
    const auto start = xyz(a.start);
    uint32_t end = first + 1;
    while (end < limit && end - first < kLongestMerge) {
      const Move& b = moves[order_[end]];
      if (b.kind != a.kind || b.programmed != a.programmed || b.process != a.process || b.tool != a.tool ||
          b.feed != a.feed || !moves_in_xyz_only(b) || units(b.start) != units(moves[order_[end - 1]].end))
        break;
      const auto chord_end = xyz(b.end);
      bool within = true;
      for (uint32_t k = first; k < end && within; ++k)
        within = segment_distance(xyz(moves[order_[k]].end), start, chord_end) <= in_.tolerance;
      if (!within) break;
      ++end;
    }
    return end;
  }

  void value(int64_t v) {
    if (!first_value_) out_ += ',';
    first_value_ = false;
    json_int(out_, v);
  }
  void value(double v) {
    if (!first_value_) out_ += ',';
    first_value_ = false;
    json_number(out_, v);
  }

  void record(uint32_t first, uint32_t end) {
    const Move& m = path_.moves[order_[first]];
    const Move& last = path_.moves[order_[end - 1]];
    if (m.process != process_) {
      value(int64_t{10});
      value(int64_t{m.process});
      process_ = m.process;
    }
    if (!m.programmed && m.tool != tool_) {
      value(int64_t{9});
      value(int64_t{m.tool});
      tool_ = m.tool;
    }
    int64_t feed = 0;  // the feed table's entry + 1 when the feed changes here
    if (!m.programmed && m.feed != feed_) {
      auto known = feed_index_.find(m.feed);
      if (known == feed_index_.end() && feeds_.size() < kFeedTable) {
        known = feed_index_.emplace(m.feed, feeds_.size()).first;
        feeds_.push_back(m.feed);
      }
      if (known != feed_index_.end()) {
        feed = static_cast<int64_t>(known->second) + 1;
      } else {
        value(int64_t{11});
        value(m.feed);
      }
      feed_ = m.feed;
    }
    const size_t lane = (m.process % 8) * 2 + (m.programmed ? 1 : 0);
    const Units start = units(m.start), stop = units(last.end);
    if (start != lanes_[lane]) {
      value(int64_t{8});
      for (int64_t c : start) value(c);
    }
    value(int64_t{static_cast<int>(m.kind) + (m.programmed ? 4 : 0)} + 16 * feed);
    for (int i = 0; i < 3; ++i) value(stop[i] - start[i]);
    if (m.kind == MoveKind::Arc) {
      const Plane& p = m.plane;
      const bool in_xyz = p.u >= 0 && p.u < 3 && p.v >= 0 && p.v < 3 && p.u != p.v;
      value(int64_t{in_xyz ? p.u * 3 + p.v : -1});
      value(in_xyz ? units(m.centre[0]) - start[p.u] : int64_t{0});
      value(in_xyz ? units(m.centre[1]) - start[p.v] : int64_t{0});
      value(std::round(m.sweep * 1e6) / 1e6);
    }
    lanes_[lane] = stop;
  }

  void write_steps() {
    out_ += ",\"steps\":[";
    first_value_ = true;
    int64_t line = 0;
    std::string files = "[", tools = "[", notes = "[", offsets = "[";
    uint32_t file = 0;
    int tool = 0;
    auto add = [](std::string& list, std::string item) {
      if (list.size() > 1) list += ',';
      list += item;
    };
    size_t pause = 0;
    int64_t ones = 0;  // steps of one record on the next line, written -n
    auto flush_ones = [&] {
      if (ones == 1) {
        value(int64_t{1});
        value(int64_t{1});
      } else if (ones > 1) {
        value(-ones);
      }
      ones = 0;
    };
    for (size_t s = 0; s < steps_.size(); ++s) {
      const Step& step = steps_[s];
      const uint32_t number = static_cast<uint32_t>(s + 1);
      const ViewBlock b = step.source < in_.blocks.size() ? in_.blocks[step.source] : ViewBlock{};
      const int64_t dline = static_cast<int64_t>(b.line) - line;
      if (dline == 1 && step.records == 1) {
        ++ones;
      } else {
        flush_ones();
        value(dline);
        value(int64_t{step.records});
      }
      line = b.line;
      if (b.file != file || s == 0) {
        add(files, fmt::format("[{},{}]", number, b.file));
        file = b.file;
      }
      // The tool: changes and the moves' tool, in the order they came.
      for (uint32_t k = step.first; k < step.end; ++k) {
        const uint32_t i = order_[k];
        for (; pause < path_.pauses.size() && pause_step_[pause] <= number && path_.pauses[pause].after <= i; ++pause)
          note(pause, number, tool, tools, notes, add);
        const Move& m = path_.moves[i];
        if (!m.programmed && m.tool != tool) {
          tool = m.tool;
          add(tools, fmt::format("[{},{}]", number, tool));
        }
      }
      for (; pause < path_.pauses.size() && pause_step_[pause] <= number; ++pause)
        note(pause, number, tool, tools, notes, add);
    }
    flush_ones();
    // A work offset from move `from` on: from the step that makes that move.
    for (const OffsetChange& o : path_.offsets) {
      const size_t step = o.from < step_of_move_.size() ? step_of_move_[o.from] : steps_.size();
      std::string item = fmt::format("[{},{}", step, o.number);
      for (int i = 0; i < 3; ++i) item += ',' + shortest(o.values[i]);
      add(offsets, item + ']');
    }
    out_ +=
        "],\"files\":" + files + "],\"tools_at\":" + tools + "],\"notes\":" + notes + "],\"offsets\":" + offsets + ']';
  }

  template <typename Add>
  void note(size_t pause, uint32_t step, int& tool, std::string& tools, std::string& notes, Add add) {
    const Pause& p = path_.pauses[pause];
    std::string item = fmt::format("[{},", step);
    json_string(item, pause_note(p));
    add(notes, item + ']');
    if (p.kind == Pause::Kind::ToolChange && p.tool != tool) {
      tool = p.tool;
      add(tools, fmt::format("[{},{}]", step, tool));
    }
  }

  void write_times() {
    out_ += ",\"models\":[";
    for (size_t k = 0; k < in_.times.size(); ++k) {
      const CycleTime& t = in_.times[k];
      if (k) out_ += ',';
      out_ += "{\"name\":";
      json_string(out_, model_name(t.model));
      const std::pair<const char*, double> fields[] = {{"cutting", t.cutting},         {"rapid", t.rapid},
                                                       {"tool_change", t.tool_change}, {"dwell", t.dwell},
                                                       {"spindle", t.spindle},         {"total", t.total()}};
      for (const auto& [name, seconds] : fields) {
        out_ += fmt::format(",\"{}\":", name);
        json_number(out_, std::round(seconds * 1000) / 1000);
      }
      out_ += '}';
    }
    out_ += "],\"times\":[";
    for (size_t k = 0; k < in_.times.size(); ++k) {
      const std::vector<double>& ends = in_.times[k].move_end;
      if (k) out_ += ',';
      out_ += '[';
      first_value_ = true;
      int64_t before = 0;
      for (const Step& step : steps_) {
        int64_t tenths = before;
        uint32_t last = kNone;
        for (uint32_t at = step.first; at < step.end; ++at)
          if (!path_.moves[order_[at]].programmed || last == kNone) last = order_[at];
        if (last != kNone && last < ends.size()) tenths = std::llround(ends[last] * 10);
        value(tenths - before);
        before = tenths;
      }
      out_ += ']';
    }
    out_ += ']';
  }

  const ViewInput& in_;
  const Toolpath& path_;
  std::string& out_;
  std::vector<Step> steps_;
  std::vector<uint32_t> order_;         // the moves, step after step
  std::vector<uint32_t> step_of_move_;  // the step (from 1) of each move
  std::vector<uint32_t> pause_step_;    // the step (from 1) of each pause
  std::array<Units, 16> lanes_{};       // where each lane's last record ended
  uint8_t process_ = 0;
  int tool_ = 0;
  double feed_ = 0;
  std::vector<double> feeds_;  // the feed table, in the order first used
  std::map<double, size_t> feed_index_;
  bool first_value_ = true;
  size_t records_ = 0;
};

}  // namespace

double view_grid(double size_x, double size_y, double requested) {
  const double longer = std::max(size_x, size_y);
  double cell = requested > 0 ? requested : longer > 0 ? nice_at_least(longer / 200) : 1;
  while (std::ceil(size_x / cell) * std::ceil(size_y / cell) > kMaxCells) cell = nice_at_least(cell * (1 + 1e-9));
  return cell;
}

void write_view(std::string& out, const ViewInput& in) {
  static const Toolpath kEmpty;
  const Toolpath& path = in.path ? *in.path : kEmpty;
  const auto page_files = view_files::page::embedded_files();
  const std::string_view page = embedded(page_files, "view/page.html");
  size_t sources = 0;
  for (const ViewSource& s : in.sources) sources += s.text.size();
  out.clear();
  out.reserve(page.size() + (1 << 20) + sources + sources / 8 + path.moves.size() * 40);
  // The markers in the order page.html has them, each replaced once.
  size_t at = 0;
  auto up_to = [&](std::string_view marker) {
    const size_t found = page.find(marker, at);
    if (found == std::string_view::npos) return false;
    out += page.substr(at, found - at);
    at = found + marker.size();
    return true;
  };
  if (up_to("@NCC_TITLE@")) out += html_escape(in.title.empty() ? std::string("ncc view") : in.title);
  if (up_to("@NCC_STYLE@")) out += embedded(page_files, "view/view.css");
  if (up_to("@NCC_THREE@")) {
#ifdef NCC_VIEW_THREE
    const auto three = view_files::three::embedded_files();
    out += "// three.js r111 (MIT licence, threejs.org/license), from Debian's libjs-three\n";
    out += embedded(three, "three.min.js");
    out += "\n</script>\n<script>\n";
    out += embedded(three, "examples/js/controls/OrbitControls.js");
#else
    out += "// this ncc was built without three.js (Debian's libjs-three): the 3-D view is missing";
#endif
  }
  if (up_to("@NCC_DATA@")) PageData(in, path, out).write();
  if (up_to("@NCC_SCRIPT@")) out += embedded(page_files, "view/view.js");
  out += page.substr(at);
}

}  // namespace ncc::sim
