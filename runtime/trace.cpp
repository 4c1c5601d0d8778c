#include "trace.h"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "contract/asset_files.h"
#include "support/diagnostics.h"
#include "support/text.h"

namespace ncc {

namespace {

constexpr const char* kStopKinds[] = {"program", "optional", "optional_skipped", "manual_retract"};
constexpr const char* kPathModes[] = {"accelerate",      "decelerate", "tapping",        "spindle_sync",
                                      "corner_slowdown", "continuous", "point_to_point", "smooth"};
constexpr const char* kClamps[] = {"off", "on", "rotary_off", "rotary_on"};
constexpr const char* kCoolants[] = {"off", "mist", "flood", "3", "4", "off_3_4"};

// "X Z" for the axes of a mask.
std::string axis_list(int mask) {
  std::string s;
  for (int i = 0; i < kAxisCount; ++i)
    if (mask & (1 << i)) s += kAxisLetters[i];
  return s;
}

}  // namespace

std::string event_name(EventKind kind) {
  constexpr const char* names[] = {"units",         "plane",          "feed_mode",
                                   "feed_rate",     "spindle_mode",   "spindle_speed",
                                   "spindle_on",    "spindle_stop",   "spindle_orient",
                                   "rapid",         "linear",         "arc",
                                   "parabola",      "thread",         "dwell",
                                   "tool_select",   "tool_change",    "tool_length_offset",
                                   "cutter_comp",   "work_offset",    "position_offset",
                                   "coolant",       "clamp",          "override",
                                   "spindle_hold",  "path",           "comment",
                                   "message",       "stop",           "operator_move",
                                   "end",           "origin",         "transform",
                                   "tolerance",     "limits",         "zone",
                                   "configuration", "probe",          "spline",
                                   "spindle_range", "part_change",    "offset_load",
                                   "diameter",      "feed_reduction", "aux",
                                   "block",         "comp_load",      "asset",
                                   "input",         "screen",         "sync",
                                   "graphic",       "tooling",        "virtual"};
  static_assert(std::size(names) == static_cast<size_t>(EventKind::Virtual) + 1, "one name per event kind");
  return names[static_cast<int>(kind)];
}

namespace {

// "read 1 record 3", and what went wrong: "error 11 (record not found)".
std::string asset_text(const Event& e) {
  if (e.n == 0) return e.text;
  return fmt::format("{} error {} ({})", e.text, e.n, asset::meaning(static_cast<asset::Code>(e.n)));
}

std::string spindle_range(int n) { return n == 0 ? "none" : n < 0 ? "auto" : std::to_string(n); }

// An input event's prompt with the value offered, and the text answered (n = 1).
std::pair<std::string, std::string> input_parts(const Event& e) {
  if (!e.n) return {e.text, ""};
  const size_t cut = e.text.rfind('\n');
  return {e.text.substr(0, cut), e.text.substr(cut + 1)};
}

std::string canon_number(double v) { return fmt::format("{:.4f}", v); }

std::string json_number(double v) { return std::isfinite(v) ? shortest(v) : std::string("null"); }

// A JSON (and C) string literal: control characters escaped, broken UTF-8 as U+FFFD.
std::string quoted(const std::string& s) { return "\"" + json_escape(s) + "\""; }
// A text from the program or a file that ends the line (a statement, a field shown, a
// function): escaped as in a string literal, its quotes as they are.
std::string free_text(const std::string& s) { return json_escape(s, false); }

// Writes through a large buffer; formatting never waits on the stream.
class BufferedSink : public TraceSink {
 public:
  BufferedSink(std::FILE* out, const SourceMap& map, std::string axes) : out_(out), map_(map), axes_(std::move(axes)) {
    buffer_.reserve(kFlushAt + 4096);
  }
  ~BufferedSink() override { flush(); }
  void flush() override {
    if (!buffer_.empty()) std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
    buffer_.clear();
    std::fflush(out_);
  }

 protected:
  void line(const std::string& s) {
    buffer_ += s;
    buffer_ += '\n';
    if (buffer_.size() > kFlushAt) {
      std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
      buffer_.clear();
    }
  }
  SourceBlock block(const Event& e) const { return e.source < map_.size() ? map_.block(e.source) : SourceBlock{}; }
  bool has_axis(char letter) const { return axes_.find(letter) != std::string::npos; }

  static constexpr size_t kFlushAt = 1 << 16;
  std::FILE* out_;
  const SourceMap& map_;
  std::string axes_;
  std::string buffer_;
};

class TextSink final : public BufferedSink {
 public:
  using BufferedSink::BufferedSink;

  void event(const Event& e) override {
    const SourceBlock b = block(e);
    std::string s = e.process ? fmt::format("P{} ", e.process) : std::string();
    s += b.file == 0 ? fmt::format("{}", b.line)
                     : fmt::format("{}:{}", printable(b.file < map_.files.size() ? map_.files[b.file] : "?"), b.line);
    s += b.has_number ? fmt::format(" {}{} ", b.main_block ? ':' : 'N', b.number) : std::string(" - ");
    s += body(e);
    line(s);
  }

 private:
  // X Y Z always; another axis of the machine once it has been away from zero or has
  // moved (an endless rotary axis turning to B0 shows as B0).
  std::string position(const AxisValues& p, uint16_t moved = 0) {
    std::string s;
    for (int i = 0; i < kAxisCount; ++i) {
      if (i >= 3) {
        if (!has_axis(kAxisLetters[i])) continue;
        if (p[i] != 0 || (moved >> i & 1)) shown_[i] = true;
        if (!shown_[i]) continue;
      }
      if (!s.empty()) s += ' ';
      s += fmt::format("{}{}", kAxisLetters[i], four_decimals(p[i]));
    }
    return s;
  }

  std::string body(const Event& e) {
    switch (e.kind) {
      case EventKind::Units: return e.n ? "units inch" : "units mm";
      case EventKind::Plane: return "plane " + plane_name(e.plane);
      case EventKind::FeedMode:
        return fmt::format("feed_mode {}", e.n == 0 ? "inverse_time" : e.n == 1 ? "per_minute" : "per_revolution");
      case EventKind::FeedRate: return "feed_rate " + four_decimals(e.a);
      case EventKind::SpindleMode: return e.n ? "spindle_mode constant_surface" : "spindle_mode rpm";
      case EventKind::SpindleSpeed: return "spindle_speed " + four_decimals(e.a);
      case EventKind::SpindleOn: return e.n > 0 ? "spindle cw" : "spindle ccw";
      case EventKind::SpindleStop: return "spindle stop";
      case EventKind::SpindleOrient: return "spindle orient " + four_decimals(e.a);
      case EventKind::Rapid: return "rapid " + position(e.pos, e.moved);
      case EventKind::Linear: return "linear " + position(e.pos, e.moved);
      case EventKind::Arc:
        return fmt::format("arc {} {} {} centre {}{} {}{} radius {} sweep {}", e.rotation > 0 ? "ccw" : "cw",
                           plane_name(e.plane), position(e.pos, e.moved), kAxisLetters[e.plane.u],
                           four_decimals(e.centre[0]), kAxisLetters[e.plane.v], four_decimals(e.centre[1]),
                           four_decimals(e.a), four_decimals(e.b));
      case EventKind::Parabola:
        return fmt::format("parabola {} control X{} Y{} Z{}", position(e.pos), four_decimals(e.control[0]),
                           four_decimals(e.control[1]), four_decimals(e.control[2]));
      case EventKind::Thread: {
        std::string s = fmt::format("thread {} pitch {}", position(e.pos), four_decimals(e.a));
        if (e.b != 0) s += " change " + four_decimals(e.b);
        if (e.c != 0) s += " phase " + four_decimals(e.c);
        return s;
      }
      case EventKind::Spline:
        return fmt::format("spline {} control {} control {}", position(e.pos), position(e.control),
                           position(e.control2));
      case EventKind::Dwell: return "dwell " + four_decimals(e.a);
      case EventKind::SelectTool: return fmt::format("tool_select {}", e.n);
      case EventKind::ChangeTool: return fmt::format("tool_change {}", e.n);
      case EventKind::ToolLengthOffset: return "tool_length_offset " + position(e.pos);
      case EventKind::CutterComp:
        return e.n == 0 ? std::string("cutter_comp off")
                        : fmt::format("cutter_comp {} radius {}", e.n == 1 ? "left" : "right", four_decimals(e.a));
      case EventKind::WorkOffset:
        return e.n == 0 ? std::string("work_offset none") : fmt::format("work_offset {} {}", e.n, position(e.pos));
      case EventKind::PositionOffset: return "position_offset " + position(e.pos);
      case EventKind::Coolant: return fmt::format("coolant {}", kCoolants[e.n]);
      case EventKind::Clamp: return fmt::format("clamp {}", kClamps[e.n]);
      case EventKind::Override: return e.n ? "override enabled" : "override disabled";
      case EventKind::SpindleHold: return e.n ? "spindle_hold on" : "spindle_hold off";
      case EventKind::PathMode: return fmt::format("path {}", kPathModes[e.n]);
      case EventKind::Comment: return "comment " + quoted(e.text);
      case EventKind::Message: return "message " + quoted(e.text);
      case EventKind::Stop: return fmt::format("stop {}", kStopKinds[e.n]);
      case EventKind::OperatorMove: return "operator_move " + position(e.pos);
      case EventKind::End: return e.n ? "end information" : "end program";
      case EventKind::Origin: return "origin " + position(e.pos);
      case EventKind::Transform: {
        std::string s;
        if (e.a != 0) s += " rotation " + four_decimals(e.a);
        if (e.n) s += " mirror " + axis_list(e.n);
        std::string scale;
        for (int i = 0; i < kAxisCount; ++i)
          if (e.pos[i] != 1) scale += fmt::format(" {}{}", kAxisLetters[i], four_decimals(e.pos[i]));
        if (!scale.empty()) s += " scale" + scale;
        return "transform" + (s.empty() ? std::string(" none") : s);
      }
      case EventKind::Tolerance:
      case EventKind::Limits: {
        std::string s = e.kind == EventKind::Tolerance ? "tolerance" : "limits";
        for (int i = 0; i < kAxisCount; ++i) {
          if (!(e.n & (1 << i))) continue;
          s += fmt::format(" {}{}", kAxisLetters[i], four_decimals(e.pos[i]));
          if (e.kind == EventKind::Limits) s += ".." + four_decimals(e.control[i]);
        }
        return e.n ? s : s + " none";  // limits none: cancelled (RESET)
      }
      case EventKind::Zone: {
        std::string s = fmt::format("zone {} {}", e.rotation, e.n == 0 ? "off" : e.n == 1 ? "on" : "defined");
        if (e.n == 2)
          for (int a : {e.plane.u, e.plane.v})
            s += fmt::format(" {}{}..{}", kAxisLetters[a], four_decimals(e.pos[a]), four_decimals(e.control[a]));
        return s;
      }
      case EventKind::Configuration: return e.n ? "configuration turning" : "configuration milling";
      case EventKind::Probe: return fmt::format("probe {} {}", position(e.pos), e.n ? "contact" : "no_contact");
      case EventKind::SpindleRange: return "spindle_range " + spindle_range(e.n);
      case EventKind::PartChange: return "part_change";
      case EventKind::OffsetLoad: return fmt::format("offset_load {} {}", e.n, position(e.pos));
      case EventKind::Diameter: return e.n ? "diameter on" : "diameter off";
      case EventKind::FeedReduction: return e.n ? "feed_reduction on" : "feed_reduction off";
      case EventKind::Aux: return "aux " + free_text(e.text);
      case EventKind::Block: return "block";
      case EventKind::CompLoad:
        return fmt::format("comp_load {} length {} radius {}", e.n, four_decimals(e.a), four_decimals(e.b));
      case EventKind::Asset: return "asset " + free_text(asset_text(e));
      case EventKind::Input: {
        const auto [shown, answer] = input_parts(e);
        return fmt::format("input {} {}", quoted(shown), e.n ? quoted(answer) : four_decimals(e.a));
      }
      case EventKind::Screen: return "screen " + free_text(e.text);
      case EventKind::Sync: return "sync " + free_text(e.text);
      case EventKind::Graphic: return "graphic " + free_text(e.text);
      case EventKind::Tooling: return "tooling " + free_text(e.text);
      case EventKind::Virtual: return "virtual " + free_text(e.text);
    }
    return "?";
  }

  bool shown_[kAxisCount] = {};
};

void json_position(const Event& e, std::string_view axes, std::string& s) {
  for (int i = 0; i < kAxisCount; ++i)
    if (i < 3 || axes.find(kAxisLetters[i]) != std::string_view::npos)
      s += fmt::format(R"(,"{}":{})", kAxisLetters[i], json_number(e.pos[i]));
}

void json_fields(const Event& e, std::string_view axes, std::string& s) {
  auto num = [&](const char* key, double v) { s += fmt::format(R"(,"{}":{})", key, json_number(v)); };
  auto str = [&](const char* key, std::string_view v) { s += fmt::format(R"(,"{}":"{}")", key, v); };
  switch (e.kind) {
    case EventKind::Units: str("units", e.n ? "inch" : "mm"); break;
    case EventKind::Plane: str("plane", plane_name(e.plane)); break;
    case EventKind::FeedMode:
      str("mode", e.n == 0 ? "inverse_time" : e.n == 1 ? "per_minute" : "per_revolution");
      break;
    case EventKind::FeedRate:
    case EventKind::SpindleSpeed: num("value", e.a); break;
    case EventKind::SpindleMode: str("mode", e.n ? "constant_surface" : "rpm"); break;
    case EventKind::SpindleOn: str("direction", e.n > 0 ? "cw" : "ccw"); break;
    case EventKind::SpindleOrient: num("angle", e.a); break;
    case EventKind::Rapid:
    case EventKind::Linear:
    case EventKind::ToolLengthOffset:
    case EventKind::PositionOffset:
    case EventKind::OperatorMove: json_position(e, axes, s); break;
    case EventKind::Arc: {
      json_position(e, axes, s);
      str("plane", plane_name(e.plane));
      str("direction", e.rotation > 0 ? "ccw" : "cw");
      s += fmt::format(R"(,"centre":{{"{}":{},"{}":{}}})", kAxisLetters[e.plane.u], json_number(e.centre[0]),
                       kAxisLetters[e.plane.v], json_number(e.centre[1]));
      num("radius", e.a);
      num("sweep", e.b);
      s += fmt::format(R"(,"rotation":{})", e.rotation);
      break;
    }
    case EventKind::Parabola:
      json_position(e, axes, s);
      s += fmt::format(R"(,"control":{{"X":{},"Y":{},"Z":{}}})", json_number(e.control[0]), json_number(e.control[1]),
                       json_number(e.control[2]));
      break;
    case EventKind::Thread:
      json_position(e, axes, s);
      num("pitch", e.a);
      num("pitch_change", e.b);
      if (e.c != 0) num("phase", e.c);
      break;
    case EventKind::Spline: {
      json_position(e, axes, s);
      auto point = [&](const char* key, const AxisValues& p) {
        std::string inner;
        for (int i = 0; i < kAxisCount; ++i)
          if (i < 3 || axes.find(kAxisLetters[i]) != std::string_view::npos)
            inner += fmt::format(R"({}"{}":{})", inner.empty() ? "" : ",", kAxisLetters[i], json_number(p[i]));
        s += fmt::format(R"(,"{}":{{{}}})", key, inner);
      };
      point("control1", e.control);
      point("control2", e.control2);
      break;
    }
    case EventKind::Origin: json_position(e, axes, s); break;
    case EventKind::Transform: {
      num("rotation", e.a);
      str("mirror", axis_list(e.n));
      std::string inner;
      for (int i = 0; i < kAxisCount; ++i)
        if (i < 3 || axes.find(kAxisLetters[i]) != std::string_view::npos)
          inner += fmt::format(R"({}"{}":{})", inner.empty() ? "" : ",", kAxisLetters[i], json_number(e.pos[i]));
      s += fmt::format(R"(,"scale":{{{}}})", inner);
      break;
    }
    case EventKind::Tolerance:
    case EventKind::Limits:
      for (int i = 0; i < kAxisCount; ++i) {
        if (!(e.n & (1 << i))) continue;
        if (e.kind == EventKind::Tolerance)
          s += fmt::format(R"(,"{}":{})", kAxisLetters[i], json_number(e.pos[i]));
        else
          s += fmt::format(R"(,"{}":[{},{}])", kAxisLetters[i], json_number(e.pos[i]), json_number(e.control[i]));
      }
      break;
    case EventKind::Zone:
      s += fmt::format(R"(,"zone":{})", e.rotation);
      str("state", e.n == 0 ? "off" : e.n == 1 ? "on" : "defined");
      if (e.n == 2)
        for (int a : {e.plane.u, e.plane.v})
          s += fmt::format(R"(,"{}":[{},{}])", kAxisLetters[a], json_number(e.pos[a]), json_number(e.control[a]));
      break;
    case EventKind::Configuration: str("configuration", e.n ? "turning" : "milling"); break;
    case EventKind::Probe:
      json_position(e, axes, s);
      s += fmt::format(R"(,"contact":{})", e.n ? "true" : "false");
      break;
    case EventKind::SpindleRange: str("range", spindle_range(e.n)); break;
    case EventKind::PartChange: break;
    case EventKind::Dwell: num("seconds", e.a); break;
    case EventKind::SelectTool:
    case EventKind::ChangeTool: s += fmt::format(R"(,"tool":{})", e.n); break;
    case EventKind::CutterComp:
      str("side", e.n == 0 ? "off" : e.n == 1 ? "left" : "right");
      num("radius", e.a);
      break;
    case EventKind::WorkOffset:
      s += fmt::format(R"(,"index":{})", e.n);
      json_position(e, axes, s);
      break;
    case EventKind::Coolant: str("coolant", kCoolants[e.n]); break;
    case EventKind::OffsetLoad:
      s += fmt::format(R"(,"n":{})", e.n);
      json_position(e, axes, s);
      break;
    case EventKind::Diameter:
    case EventKind::FeedReduction: s += fmt::format(R"(,"on":{})", e.n ? "true" : "false"); break;
    case EventKind::Aux: s += R"(,"function":)" + quoted(e.text); break;
    case EventKind::Block: break;
    case EventKind::Asset: s += R"(,"statement":)" + quoted(e.text) + fmt::format(R"(,"code":{})", e.n); break;
    case EventKind::Input: {
      const auto [shown, answer] = input_parts(e);
      s += R"(,"prompt":)" + quoted(shown);
      if (e.n)
        s += R"(,"answer":)" + quoted(answer);
      else
        num("answer", e.a);
      break;
    }
    case EventKind::Screen:
    case EventKind::Sync:
    case EventKind::Graphic:
    case EventKind::Tooling:
    case EventKind::Virtual: s += R"(,"what":)" + quoted(e.text); break;
    case EventKind::CompLoad:
      s += fmt::format(R"(,"n":{})", e.n);
      num("length", e.a);
      num("radius", e.b);
      break;
    case EventKind::Clamp: str("clamp", kClamps[e.n]); break;
    case EventKind::Override:
    case EventKind::SpindleHold: s += fmt::format(R"(,"on":{})", e.n ? "true" : "false"); break;
    case EventKind::PathMode: str("mode", kPathModes[e.n]); break;
    case EventKind::Comment:
    case EventKind::Message: s += R"(,"text":)" + quoted(e.text); break;
    case EventKind::Stop: str("kind", kStopKinds[e.n]); break;
    case EventKind::End: str("kind", e.n ? "information" : "program"); break;
    case EventKind::SpindleStop: break;
  }
}

class JsonlSink final : public BufferedSink {
 public:
  using BufferedSink::BufferedSink;

  void event(const Event& e) override {
    const SourceBlock b = block(e);
    std::string s = fmt::format(R"({{"seq":{},"file":{},"line":{},"col":{})", ++seq_,
                                quoted(b.file < map_.files.size() ? map_.files[b.file] : ""), b.line, b.col);
    if (e.process) s += fmt::format(R"(,"process":{})", e.process);
    if (b.has_number) s += fmt::format(R"(,"block":"{}{}")", b.main_block ? ':' : 'N', b.number);
    s += R"(,"event":")" + event_name(e.kind) + '"';
    json_fields(e, axes_, s);
    line(s + "}");
  }

 private:
  uint64_t seq_ = 0;
};

// LinuxCNC's canonical calls as `rs274 -g` prints them, without its two leading
// columns. Events LinuxCNC has no call for print as COMMENT("ncc: ...") so that
// the output stays a list of canonical calls (docs/trace.md).
class CanonSink final : public BufferedSink {
 public:
  CanonSink(std::FILE* out, const SourceMap& map, std::string axes) : BufferedSink(out, map, std::move(axes)) {
    nine_ = has_axis('U') || has_axis('V') || has_axis('W');
  }

  void event(const Event& e) override {
    // The processes of a run take turns: each turn says whose calls follow.
    if (e.process != process_) line(fmt::format("COMMENT(\"ncc: process {}\")", process_ = e.process));
    switch (e.kind) {
      case EventKind::Units:
        line(e.n ? "USE_LENGTH_UNITS(CANON_UNITS_INCHES)" : "USE_LENGTH_UNITS(CANON_UNITS_MM)");
        break;
      case EventKind::Plane:
        // LinuxCNC names the ZX plane XZ and has no others.
        if (e.plane == kPlanes[0] || e.plane == kPlanes[1] || e.plane == kPlanes[2])
          line(fmt::format("SELECT_PLANE(CANON_PLANE_{})", e.plane == kPlanes[0]   ? "XY"
                                                           : e.plane == kPlanes[1] ? "XZ"
                                                                                   : "YZ"));
        else
          line(fmt::format("COMMENT(\"ncc: plane {}\")", plane_name(e.plane)));
        break;
      case EventKind::FeedMode: line(fmt::format("SET_FEED_MODE(0, {})", e.n == 2 ? 1 : 0)); break;
      case EventKind::FeedRate: line(fmt::format("SET_FEED_RATE({})", canon_number(e.a))); break;
      // LinuxCNC passes the maximum spindle speed for constant surface speed, 1e30
      // when the program gives none (GOST has no such word), and 0 for rpm.
      case EventKind::SpindleMode: line(fmt::format("SET_SPINDLE_MODE(0 {})", canon_number(e.n ? 1e30 : 0))); break;
      case EventKind::SpindleSpeed: line(fmt::format("SET_SPINDLE_SPEED(0, {})", canon_number(e.a))); break;
      case EventKind::SpindleOn:
        line(e.n > 0 ? "START_SPINDLE_CLOCKWISE(0)" : "START_SPINDLE_COUNTERCLOCKWISE(0)");
        break;
      case EventKind::SpindleStop: line("STOP_SPINDLE_TURNING(0)"); break;
      case EventKind::SpindleOrient: line(fmt::format("ORIENT_SPINDLE(0, {}, 0)", canon_number(e.a))); break;
      case EventKind::Rapid: line(fmt::format("STRAIGHT_TRAVERSE({})", axes_list(e.pos, 0))); break;
      case EventKind::Linear: line(fmt::format("STRAIGHT_FEED({})", axes_list(e.pos, 0))); break;
      case EventKind::Arc:
        line(fmt::format("ARC_FEED({}, {}, {}, {}, {}, {}, {})", canon_number(e.pos[e.plane.u]),
                         canon_number(e.pos[e.plane.v]), canon_number(e.centre[0]), canon_number(e.centre[1]),
                         e.rotation, canon_number(e.plane.w >= 0 ? e.pos[e.plane.w] : 0), axes_list(e.pos, 3)));
        break;
      case EventKind::Parabola:
        line(fmt::format("PARABOLA_FEED({}, {}, {}, {})", canon_number(e.control[0]), canon_number(e.control[1]),
                         canon_number(e.control[2]), axes_list(e.pos, 0)));
        break;
      case EventKind::Thread:
        line(fmt::format("START_SPEED_FEED_SYNC({:f},0)", e.a));
        if (e.b != 0) line(fmt::format("COMMENT(\"ncc: pitch change {} per revolution\")", canon_number(e.b)));
        line(fmt::format("STRAIGHT_FEED({})", axes_list(e.pos, 0)));
        line("STOP_SPEED_FEED_SYNCH()");
        break;
      case EventKind::Dwell: line(fmt::format("DWELL({})", canon_number(e.a))); break;
      case EventKind::SelectTool: line(fmt::format("SELECT_TOOL({})", e.n)); break;
      case EventKind::ChangeTool:
        line("START_CHANGE()");
        line(fmt::format("CHANGE_TOOL({})", e.n));
        break;
      case EventKind::ToolLengthOffset:
        line(fmt::format("USE_TOOL_LENGTH_OFFSET({} {} {}, {} {} {}, {} {} {})", canon_number(e.pos[0]),
                         canon_number(e.pos[1]), canon_number(e.pos[2]), canon_number(e.pos[3]), canon_number(e.pos[4]),
                         canon_number(e.pos[5]), canon_number(e.pos[6]), canon_number(e.pos[7]),
                         canon_number(e.pos[8])));
        break;
      case EventKind::CutterComp:
        line(e.n == 0 ? "COMMENT(\"interpreter: cutter radius compensation off\")"
                      : fmt::format("COMMENT(\"interpreter: cutter radius compensation on {}\")",
                                    e.n == 1 ? "left" : "right"));
        break;
      case EventKind::WorkOffset: line(fmt::format("SET_G5X_OFFSET({}, {})", e.n, axes_list(e.pos, 0))); break;
      case EventKind::PositionOffset: line(fmt::format("SET_G92_OFFSET({})", axes_list(e.pos, 0))); break;
      case EventKind::Coolant:
        if (e.n == 0) {
          line("MIST_OFF()");
          line("FLOOD_OFF()");
        } else {
          if (e.n <= 2)
            line(e.n == 1 ? "MIST_ON()" : "FLOOD_ON()");
          else
            line(fmt::format("COMMENT(\"ncc: coolant {}\")", kCoolants[e.n]));
        }
        break;
      case EventKind::OffsetLoad:  // a table entry: what is in force shows when it is selected
        line(fmt::format("COMMENT(\"ncc: offset_load {} {}\")", e.n, axes_list(e.pos, 0)));
        break;
      case EventKind::Diameter:
      case EventKind::FeedReduction:
        line(fmt::format("COMMENT(\"ncc: {} {}\")", event_name(e.kind), e.n ? "on" : "off"));
        break;
      case EventKind::Aux: line(fmt::format("COMMENT(\"ncc: aux {}\")", json_escape(e.text))); break;
      case EventKind::Block: break;  // LinuxCNC's calls have no block boundaries
      case EventKind::Asset: line(fmt::format("COMMENT(\"ncc: asset {}\")", json_escape(asset_text(e)))); break;
      case EventKind::Input: {
        const auto [shown, answer] = input_parts(e);
        line(fmt::format("COMMENT(\"ncc: input {} {}\")", json_escape(shown),
                         e.n ? json_escape(answer) : canon_number(e.a)));
        break;
      }
      case EventKind::Screen: line(fmt::format("COMMENT(\"ncc: screen {}\")", json_escape(e.text))); break;
      case EventKind::Sync: line(fmt::format("COMMENT(\"ncc: sync {}\")", json_escape(e.text))); break;
      case EventKind::Graphic: line(fmt::format("COMMENT(\"ncc: graphic {}\")", json_escape(e.text))); break;
      case EventKind::Tooling: line(fmt::format("COMMENT(\"ncc: tooling {}\")", json_escape(e.text))); break;
      case EventKind::Virtual: line(fmt::format("COMMENT(\"ncc: virtual {}\")", json_escape(e.text))); break;
      case EventKind::CompLoad:
        line(fmt::format("COMMENT(\"ncc: comp_load {} length {} radius {}\")", e.n, canon_number(e.a),
                         canon_number(e.b)));
        break;
      case EventKind::Override:
        line(e.n ? "ENABLE_FEED_OVERRIDE()" : "DISABLE_FEED_OVERRIDE()");
        line(e.n ? "ENABLE_SPEED_OVERRIDE(0)" : "DISABLE_SPEED_OVERRIDE(0)");
        break;
      case EventKind::Comment: line(fmt::format("COMMENT({})", quoted(e.text))); break;
      case EventKind::Message: line(fmt::format("MESSAGE({})", quoted(e.text))); break;
      case EventKind::Stop:
        if (e.n == 3) line("COMMENT(\"ncc: manual retract\")");
        line(e.n == 1 || e.n == 2 ? "OPTIONAL_PROGRAM_STOP()" : "PROGRAM_STOP()");
        break;
      case EventKind::End: line("PROGRAM_END()"); break;
      case EventKind::Clamp: line(fmt::format("COMMENT(\"ncc: clamp {}\")", kClamps[e.n])); break;
      case EventKind::SpindleHold:
        line(e.n ? "COMMENT(\"ncc: spindle hold on\")" : "COMMENT(\"ncc: spindle hold off\")");
        break;
      case EventKind::PathMode: line(fmt::format("COMMENT(\"ncc: path {}\")", kPathModes[e.n])); break;
      case EventKind::OperatorMove:
        line(fmt::format("COMMENT(\"ncc: operator move to {}\")", axes_list(e.pos, 0)));
        break;
      case EventKind::Spline:
        line(fmt::format("CUBIC_FEED({}, {}, {})", axes_list(e.control, 0), axes_list(e.control2, 0),
                         axes_list(e.pos, 0)));
        break;
      case EventKind::Probe: line(fmt::format("STRAIGHT_PROBE({})", axes_list(e.pos, 0))); break;
      case EventKind::Origin: line(fmt::format("SET_G5X_OFFSET(0, {})", axes_list(e.pos, 0))); break;
      case EventKind::Transform:
      case EventKind::Tolerance:
      case EventKind::Limits:
      case EventKind::Zone:
      case EventKind::Configuration:
      case EventKind::SpindleRange:
      case EventKind::PartChange: line(fmt::format("COMMENT(\"ncc: {}\")", event_name(e.kind))); break;
    }
  }

 private:
  // LinuxCNC prints X Y Z A B C (and U V W on machines that have them).
  std::string axes_list(const AxisValues& p, int from) const {
    std::string s;
    int last = nine_ ? 9 : 6;
    for (int i = from; i < last; ++i) {
      if (!s.empty()) s += ", ";
      s += canon_number(p[i]);
    }
    return s;
  }

  bool nine_ = false;
  uint8_t process_ = 0;  // whose calls the last ones were
};

}  // namespace

std::unique_ptr<TraceSink> make_trace_writer(TraceFormat format, std::FILE* out, const SourceMap& map,
                                             std::string axes) {
  switch (format) {
    case TraceFormat::Text: return std::make_unique<TextSink>(out, map, std::move(axes));
    case TraceFormat::Jsonl: return std::make_unique<JsonlSink>(out, map, std::move(axes));
    case TraceFormat::Canon: return std::make_unique<CanonSink>(out, map, std::move(axes));
  }
  return nullptr;
}

}  // namespace ncc
