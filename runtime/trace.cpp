#include "trace.h"

#include <fmt/format.h>

#include <cmath>

#include "contract/asset_files.h"
#include "runtime/machine_interface_sink.h"
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

using api::Axes;
using api::AxisMask;
using api::Reply;

constexpr const char* kFeedModes[] = {"inverse_time", "per_minute", "per_revolution"};
constexpr const char* kZoneStates[] = {"off", "on", "defined"};

int ordinal(auto e) { return static_cast<int>(e); }
Plane plane_of(const api::Plane& p) { return {p.first, p.second, p.normal}; }

// "read 1 record 3", and what went wrong: "error 11 (record not found)".
std::string asset_text(std::string_view statement, int code) {
  if (code == 0) return std::string(statement);
  return fmt::format("{} error {} ({})", statement, code, asset::meaning(static_cast<asset::Code>(code)));
}

std::string spindle_range(int n) { return n == 0 ? "none" : n < 0 ? "auto" : std::to_string(n); }

std::string canon_number(double v) { return fmt::format("{:.4f}", v); }

std::string json_number(double v) { return std::isfinite(v) ? shortest(v) : std::string("null"); }

// A JSON (and C) string literal: control characters escaped, broken UTF-8 as U+FFFD.
std::string quoted(std::string_view s) { return "\"" + json_escape(s) + "\""; }
// A text from the program or a file that ends the line (a statement, a field shown, a
// function): escaped as in a string literal, its quotes as they are.
std::string free_text(std::string_view s) { return json_escape(s, false); }

// A trace writer: the calls of a run as lines, through a large buffer (formatting
// never waits on the stream). `axes` are the letters the machine has.
class TraceWriter : public api::MachineInterface {
 public:
  TraceWriter(std::FILE* out, std::string axes) : out_(out), axes_(std::move(axes)) {
    buffer_.reserve(kFlushAt + 4096);
  }
  ~TraceWriter() override { flush(); }
  void flush() {
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
  bool has_axis(char letter) const { return axes_.find(letter) != std::string::npos; }
  // X Y Z and the machine's other axes.
  bool lists_axis(int i) const { return i < 3 || has_axis(kAxisLetters[i]); }

  static constexpr size_t kFlushAt = 1 << 16;
  std::FILE* out_;
  std::string axes_;
  std::string buffer_;
};

class TextWriter final : public TraceWriter {
 public:
  using TraceWriter::TraceWriter;

  Reply units(const api::Block& b, api::Units u) override {
    return write(b, u == api::Units::Inches ? "units inch" : "units mm");
  }
  Reply plane(const api::Block& b, const api::Plane& p) override {
    return write(b, "plane " + plane_name(plane_of(p)));
  }
  Reply feed_mode(const api::Block& b, api::FeedMode m) override {
    return write(b, fmt::format("feed_mode {}", kFeedModes[ordinal(m)]));
  }
  Reply feed_rate(const api::Block& b, double rate) override { return write(b, "feed_rate " + four_decimals(rate)); }
  Reply spindle_mode(const api::Block& b, api::SpindleMode m) override {
    return write(b, m == api::SpindleMode::ConstantSurfaceSpeed ? "spindle_mode constant_surface" : "spindle_mode rpm");
  }
  Reply spindle_speed(const api::Block& b, double speed) override {
    return write(b, "spindle_speed " + four_decimals(speed));
  }
  Reply spindle_start(const api::Block& b, api::Direction d) override {
    return write(b, d == api::Direction::Clockwise ? "spindle cw" : "spindle ccw");
  }
  Reply spindle_stop(const api::Block& b) override { return write(b, "spindle stop"); }
  Reply spindle_orient(const api::Block& b, double angle) override {
    return write(b, "spindle orient " + four_decimals(angle));
  }
  Reply straight_traverse(const api::Block& b, const Axes& end, AxisMask moved) override {
    return write(b, "rapid " + position(end, moved));
  }
  Reply straight_feed(const api::Block& b, const Axes& end, AxisMask moved) override {
    return write(b, "linear " + position(end, moved));
  }
  Reply arc_feed(const api::Block& b, const api::Arc& a) override {
    return write(b, fmt::format("arc {} {} {} centre {}{} {}{} radius {} sweep {}", a.rotation > 0 ? "ccw" : "cw",
                                plane_name(plane_of(a.plane)), position(a.end, a.moved), kAxisLetters[a.plane.first],
                                four_decimals(a.centre_first), kAxisLetters[a.plane.second],
                                four_decimals(a.centre_second), four_decimals(a.radius), four_decimals(a.sweep)));
  }
  Reply parabola(const api::Block& b, const Axes& end, const Axes& control) override {
    return write(b, fmt::format("parabola {} control X{} Y{} Z{}", position(end), four_decimals(control[0]),
                                four_decimals(control[1]), four_decimals(control[2])));
  }
  Reply thread(const api::Block& b, const Axes& end, double pitch, double pitch_change, double start_angle) override {
    std::string s = fmt::format("thread {} pitch {}", position(end), four_decimals(pitch));
    if (pitch_change != 0) s += " change " + four_decimals(pitch_change);
    if (start_angle != 0) s += " phase " + four_decimals(start_angle);
    return write(b, s);
  }
  Reply spline(const api::Block& b, const Axes& end, const Axes& control1, const Axes& control2) override {
    return write(b,
                 fmt::format("spline {} control {} control {}", position(end), position(control1), position(control2)));
  }
  Reply probe(const api::Block& b, const Axes& end, bool contact) override {
    return write(b, fmt::format("probe {} {}", position(end), contact ? "contact" : "no_contact"));
  }
  Reply dwell(const api::Block& b, double seconds) override { return write(b, "dwell " + four_decimals(seconds)); }
  Reply path_mode(const api::Block& b, api::PathMode m) override {
    return write(b, fmt::format("path {}", kPathModes[ordinal(m)]));
  }
  Reply tool_select(const api::Block& b, int tool) override { return write(b, fmt::format("tool_select {}", tool)); }
  Reply tool_change(const api::Block& b, int tool) override { return write(b, fmt::format("tool_change {}", tool)); }
  Reply tool_length_offset(const api::Block& b, const Axes& offset) override {
    return write(b, "tool_length_offset " + position(offset));
  }
  Reply cutter_compensation(const api::Block& b, api::CutterSide side, double radius) override {
    return write(b, side == api::CutterSide::Off
                        ? std::string("cutter_comp off")
                        : fmt::format("cutter_comp {} radius {}", side == api::CutterSide::Left ? "left" : "right",
                                      four_decimals(radius)));
  }
  Reply work_offset(const api::Block& b, int number, const Axes& offset) override {
    return write(
        b, number == 0 ? std::string("work_offset none") : fmt::format("work_offset {} {}", number, position(offset)));
  }
  Reply position_offset(const api::Block& b, const Axes& offset) override {
    return write(b, "position_offset " + position(offset));
  }
  Reply coolant(const api::Block& b, api::Coolant c) override {
    return write(b, fmt::format("coolant {}", kCoolants[ordinal(c)]));
  }
  Reply comment(const api::Block& b, std::string_view text) override { return write(b, "comment " + quoted(text)); }
  Reply message(const api::Block& b, std::string_view text) override { return write(b, "message " + quoted(text)); }
  Reply stop(const api::Block& b, api::StopKind k) override {
    return write(b, fmt::format("stop {}", kStopKinds[ordinal(k)]));
  }
  Reply program_end(const api::Block& b, bool end_of_information) override {
    return write(b, end_of_information ? "end information" : "end program");
  }
  Reply operator_move(const api::Block& b, const Axes& to) override {
    return write(b, "operator_move " + position(to));
  }
  Reply input(const api::Block& b, std::string_view prompt, double answer) override {
    return write(b, fmt::format("input {} {}", quoted(prompt), four_decimals(answer)));
  }
  Reply input_text(const api::Block& b, std::string_view prompt, std::string_view answer) override {
    return write(b, fmt::format("input {} {}", quoted(prompt), quoted(answer)));
  }
  Reply clamp(const api::Block& b, api::Clamp c) override {
    return write(b, fmt::format("clamp {}", kClamps[ordinal(c)]));
  }
  Reply override_enable(const api::Block& b, bool enabled) override {
    return write(b, enabled ? "override enabled" : "override disabled");
  }
  Reply spindle_hold(const api::Block& b, bool on) override {
    return write(b, on ? "spindle_hold on" : "spindle_hold off");
  }
  Reply spindle_range(const api::Block& b, int range) override {
    return write(b, "spindle_range " + ncc::spindle_range(range));
  }
  Reply aux(const api::Block& b, std::string_view function) override { return write(b, "aux " + free_text(function)); }
  Reply block_start(const api::Block& b) override { return write(b, "block"); }
  Reply origin(const api::Block& b, const Axes& zero) override { return write(b, "origin " + position(zero)); }
  Reply transform(const api::Block& b, double rotation, AxisMask mirrored, const Axes& scale) override {
    std::string s;
    if (rotation != 0) s += " rotation " + four_decimals(rotation);
    if (mirrored) s += " mirror " + axis_list(mirrored);
    std::string scales;
    for (int i = 0; i < kAxisCount; ++i)
      if (scale[i] != 1) scales += fmt::format(" {}{}", kAxisLetters[i], four_decimals(scale[i]));
    if (!scales.empty()) s += " scale" + scales;
    return write(b, "transform" + (s.empty() ? std::string(" none") : s));
  }
  Reply tolerance(const api::Block& b, AxisMask axes, const Axes& tolerance) override {
    return write(b, bounds("tolerance", axes, tolerance, nullptr));
  }
  Reply limits(const api::Block& b, AxisMask axes, const Axes& lower, const Axes& upper) override {
    return write(b, bounds("limits", axes, lower, &upper));  // limits none: cancelled (RESET)
  }
  Reply zone(const api::Block& b, int zone, api::ZoneState state, const api::Plane& p, const Axes& lower,
             const Axes& upper) override {
    std::string s = fmt::format("zone {} {}", zone, kZoneStates[ordinal(state)]);
    if (state == api::ZoneState::Defined)
      for (int a : {p.first, p.second})
        s += fmt::format(" {}{}..{}", kAxisLetters[a], four_decimals(lower[a]), four_decimals(upper[a]));
    return write(b, s);
  }
  Reply configuration(const api::Block& b, api::Configuration c) override {
    return write(b, c == api::Configuration::Turning ? "configuration turning" : "configuration milling");
  }
  Reply part_change(const api::Block& b) override { return write(b, "part_change"); }
  Reply virtual_axes(const api::Block& b, std::string_view what) override {
    return write(b, "virtual " + free_text(what));
  }
  Reply offset_load(const api::Block& b, int number, const Axes& offset) override {
    return write(b, fmt::format("offset_load {} {}", number, position(offset)));
  }
  Reply comp_load(const api::Block& b, int entry, double length, double radius) override {
    return write(b,
                 fmt::format("comp_load {} length {} radius {}", entry, four_decimals(length), four_decimals(radius)));
  }
  Reply tooling(const api::Block& b, api::ToolingChange, std::string_view what) override {
    return write(b, "tooling " + free_text(what));
  }
  Reply diameter(const api::Block& b, bool on) override { return write(b, on ? "diameter on" : "diameter off"); }
  Reply feed_reduction(const api::Block& b, bool on) override {
    return write(b, on ? "feed_reduction on" : "feed_reduction off");
  }
  Reply asset(const api::Block& b, std::string_view statement, int code) override {
    return write(b, "asset " + free_text(asset_text(statement, code)));
  }
  Reply screen(const api::Block& b, std::string_view what) override { return write(b, "screen " + free_text(what)); }
  Reply sync(const api::Block& b, std::string_view what) override { return write(b, "sync " + free_text(what)); }
  Reply graphic(const api::Block& b, std::string_view what) override { return write(b, "graphic " + free_text(what)); }

 private:
  // The block's line (and file, when not the main one) and number, then the call.
  Reply write(const api::Block& b, const std::string& call) {
    std::string s = b.process ? fmt::format("P{} ", b.process) : std::string();
    s += b.main_file ? fmt::format("{}", b.line) : fmt::format("{}:{}", printable(b.file), b.line);
    s += b.number ? fmt::format(" {}{} ", b.main_block ? ':' : 'N', *b.number) : std::string(" - ");
    s += call;
    line(s);
    return {};
  }

  // X Y Z always; another axis of the machine once it has been away from zero or has
  // moved (an endless rotary axis turning to B0 shows as B0).
  std::string position(const Axes& p, AxisMask moved = 0) {
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

  // "limits X0..100 Y0..50" of the axes of a mask, "limits none" without any.
  static std::string bounds(std::string s, AxisMask axes, const Axes& lower, const Axes* upper) {
    for (int i = 0; i < kAxisCount; ++i) {
      if (!(axes & (1 << i))) continue;
      s += fmt::format(" {}{}", kAxisLetters[i], four_decimals(lower[i]));
      if (upper) s += ".." + four_decimals((*upper)[i]);
    }
    return axes ? s : s + " none";
  }

  bool shown_[kAxisCount] = {};
};

class JsonlWriter final : public TraceWriter {
 public:
  using TraceWriter::TraceWriter;

  Reply units(const api::Block& b, api::Units u) override {
    std::string s = open(b, "units");
    str(s, "units", u == api::Units::Inches ? "inch" : "mm");
    return close(s);
  }
  Reply plane(const api::Block& b, const api::Plane& p) override {
    std::string s = open(b, "plane");
    str(s, "plane", plane_name(plane_of(p)));
    return close(s);
  }
  Reply feed_mode(const api::Block& b, api::FeedMode m) override {
    std::string s = open(b, "feed_mode");
    str(s, "mode", kFeedModes[ordinal(m)]);
    return close(s);
  }
  Reply feed_rate(const api::Block& b, double rate) override { return value(b, "feed_rate", rate); }
  Reply spindle_mode(const api::Block& b, api::SpindleMode m) override {
    std::string s = open(b, "spindle_mode");
    str(s, "mode", m == api::SpindleMode::ConstantSurfaceSpeed ? "constant_surface" : "rpm");
    return close(s);
  }
  Reply spindle_speed(const api::Block& b, double speed) override { return value(b, "spindle_speed", speed); }
  Reply spindle_start(const api::Block& b, api::Direction d) override {
    std::string s = open(b, "spindle_on");
    str(s, "direction", d == api::Direction::Clockwise ? "cw" : "ccw");
    return close(s);
  }
  Reply spindle_stop(const api::Block& b) override { return bare(b, "spindle_stop"); }
  Reply spindle_orient(const api::Block& b, double angle) override {
    std::string s = open(b, "spindle_orient");
    num(s, "angle", angle);
    return close(s);
  }
  Reply straight_traverse(const api::Block& b, const Axes& end, AxisMask) override { return at(b, "rapid", end); }
  Reply straight_feed(const api::Block& b, const Axes& end, AxisMask) override { return at(b, "linear", end); }
  Reply arc_feed(const api::Block& b, const api::Arc& a) override {
    std::string s = open(b, "arc");
    position(s, a.end);
    str(s, "plane", plane_name(plane_of(a.plane)));
    str(s, "direction", a.rotation > 0 ? "ccw" : "cw");
    s += fmt::format(R"(,"centre":{{"{}":{},"{}":{}}})", kAxisLetters[a.plane.first], json_number(a.centre_first),
                     kAxisLetters[a.plane.second], json_number(a.centre_second));
    num(s, "radius", a.radius);
    num(s, "sweep", a.sweep);
    s += fmt::format(R"(,"rotation":{})", a.rotation);
    return close(s);
  }
  Reply parabola(const api::Block& b, const Axes& end, const Axes& control) override {
    std::string s = open(b, "parabola");
    position(s, end);
    s += fmt::format(R"(,"control":{{"X":{},"Y":{},"Z":{}}})", json_number(control[0]), json_number(control[1]),
                     json_number(control[2]));
    return close(s);
  }
  Reply thread(const api::Block& b, const Axes& end, double pitch, double pitch_change, double start_angle) override {
    std::string s = open(b, "thread");
    position(s, end);
    num(s, "pitch", pitch);
    num(s, "pitch_change", pitch_change);
    if (start_angle != 0) num(s, "phase", start_angle);
    return close(s);
  }
  Reply spline(const api::Block& b, const Axes& end, const Axes& control1, const Axes& control2) override {
    std::string s = open(b, "spline");
    position(s, end);
    point(s, "control1", control1);
    point(s, "control2", control2);
    return close(s);
  }
  Reply probe(const api::Block& b, const Axes& end, bool contact) override {
    std::string s = open(b, "probe");
    position(s, end);
    s += fmt::format(R"(,"contact":{})", contact);
    return close(s);
  }
  Reply dwell(const api::Block& b, double seconds) override {
    std::string s = open(b, "dwell");
    num(s, "seconds", seconds);
    return close(s);
  }
  Reply path_mode(const api::Block& b, api::PathMode m) override {
    std::string s = open(b, "path");
    str(s, "mode", kPathModes[ordinal(m)]);
    return close(s);
  }
  Reply tool_select(const api::Block& b, int tool) override { return count(b, "tool_select", "tool", tool); }
  Reply tool_change(const api::Block& b, int tool) override { return count(b, "tool_change", "tool", tool); }
  Reply tool_length_offset(const api::Block& b, const Axes& offset) override {
    return at(b, "tool_length_offset", offset);
  }
  Reply cutter_compensation(const api::Block& b, api::CutterSide side, double radius) override {
    std::string s = open(b, "cutter_comp");
    str(s, "side", side == api::CutterSide::Off ? "off" : side == api::CutterSide::Left ? "left" : "right");
    num(s, "radius", radius);
    return close(s);
  }
  Reply work_offset(const api::Block& b, int number, const Axes& offset) override {
    std::string s = open(b, "work_offset");
    s += fmt::format(R"(,"index":{})", number);
    position(s, offset);
    return close(s);
  }
  Reply position_offset(const api::Block& b, const Axes& offset) override { return at(b, "position_offset", offset); }
  Reply coolant(const api::Block& b, api::Coolant c) override {
    std::string s = open(b, "coolant");
    str(s, "coolant", kCoolants[ordinal(c)]);
    return close(s);
  }
  Reply comment(const api::Block& b, std::string_view text) override { return text_of(b, "comment", "text", text); }
  Reply message(const api::Block& b, std::string_view text) override { return text_of(b, "message", "text", text); }
  Reply stop(const api::Block& b, api::StopKind k) override {
    std::string s = open(b, "stop");
    str(s, "kind", kStopKinds[ordinal(k)]);
    return close(s);
  }
  Reply program_end(const api::Block& b, bool end_of_information) override {
    std::string s = open(b, "end");
    str(s, "kind", end_of_information ? "information" : "program");
    return close(s);
  }
  Reply operator_move(const api::Block& b, const Axes& to) override { return at(b, "operator_move", to); }
  Reply input(const api::Block& b, std::string_view prompt, double answer) override {
    std::string s = open(b, "input");
    s += R"(,"prompt":)" + quoted(prompt);
    num(s, "answer", answer);
    return close(s);
  }
  Reply input_text(const api::Block& b, std::string_view prompt, std::string_view answer) override {
    std::string s = open(b, "input");
    s += R"(,"prompt":)" + quoted(prompt);
    s += R"(,"answer":)" + quoted(answer);
    return close(s);
  }
  Reply clamp(const api::Block& b, api::Clamp c) override {
    std::string s = open(b, "clamp");
    str(s, "clamp", kClamps[ordinal(c)]);
    return close(s);
  }
  Reply override_enable(const api::Block& b, bool enabled) override { return on_off(b, "override", enabled); }
  Reply spindle_hold(const api::Block& b, bool on) override { return on_off(b, "spindle_hold", on); }
  Reply spindle_range(const api::Block& b, int range) override {
    std::string s = open(b, "spindle_range");
    str(s, "range", ncc::spindle_range(range));
    return close(s);
  }
  Reply aux(const api::Block& b, std::string_view function) override { return text_of(b, "aux", "function", function); }
  Reply block_start(const api::Block& b) override { return bare(b, "block"); }
  Reply origin(const api::Block& b, const Axes& zero) override { return at(b, "origin", zero); }
  Reply transform(const api::Block& b, double rotation, AxisMask mirrored, const Axes& scale) override {
    std::string s = open(b, "transform");
    num(s, "rotation", rotation);
    str(s, "mirror", axis_list(mirrored));
    point(s, "scale", scale);
    return close(s);
  }
  Reply tolerance(const api::Block& b, AxisMask axes, const Axes& tolerance) override {
    std::string s = open(b, "tolerance");
    for (int i = 0; i < kAxisCount; ++i)
      if (axes & (1 << i)) s += fmt::format(R"(,"{}":{})", kAxisLetters[i], json_number(tolerance[i]));
    return close(s);
  }
  Reply limits(const api::Block& b, AxisMask axes, const Axes& lower, const Axes& upper) override {
    std::string s = open(b, "limits");
    for (int i = 0; i < kAxisCount; ++i)
      if (axes & (1 << i)) range(s, i, lower, upper);
    return close(s);
  }
  Reply zone(const api::Block& b, int zone, api::ZoneState state, const api::Plane& p, const Axes& lower,
             const Axes& upper) override {
    std::string s = open(b, "zone");
    s += fmt::format(R"(,"zone":{})", zone);
    str(s, "state", kZoneStates[ordinal(state)]);
    if (state == api::ZoneState::Defined)
      for (int a : {p.first, p.second}) range(s, a, lower, upper);
    return close(s);
  }
  Reply configuration(const api::Block& b, api::Configuration c) override {
    std::string s = open(b, "configuration");
    str(s, "configuration", c == api::Configuration::Turning ? "turning" : "milling");
    return close(s);
  }
  Reply part_change(const api::Block& b) override { return bare(b, "part_change"); }
  Reply virtual_axes(const api::Block& b, std::string_view what) override {
    return text_of(b, "virtual", "what", what);
  }
  Reply offset_load(const api::Block& b, int number, const Axes& offset) override {
    std::string s = open(b, "offset_load");
    s += fmt::format(R"(,"n":{})", number);
    position(s, offset);
    return close(s);
  }
  Reply comp_load(const api::Block& b, int entry, double length, double radius) override {
    std::string s = open(b, "comp_load");
    s += fmt::format(R"(,"n":{})", entry);
    num(s, "length", length);
    num(s, "radius", radius);
    return close(s);
  }
  Reply tooling(const api::Block& b, api::ToolingChange, std::string_view what) override {
    return text_of(b, "tooling", "what", what);
  }
  Reply diameter(const api::Block& b, bool on) override { return on_off(b, "diameter", on); }
  Reply feed_reduction(const api::Block& b, bool on) override { return on_off(b, "feed_reduction", on); }
  Reply asset(const api::Block& b, std::string_view statement, int code) override {
    std::string s = open(b, "asset");
    s += R"(,"statement":)" + quoted(statement) + fmt::format(R"(,"code":{})", code);
    return close(s);
  }
  Reply screen(const api::Block& b, std::string_view what) override { return text_of(b, "screen", "what", what); }
  Reply sync(const api::Block& b, std::string_view what) override { return text_of(b, "sync", "what", what); }
  Reply graphic(const api::Block& b, std::string_view what) override { return text_of(b, "graphic", "what", what); }

 private:
  // The line's place and event: {"seq":1,"file":"part.nc","line":3,"col":1,"block":"N30","event":"rapid"
  std::string open(const api::Block& b, std::string_view event) {
    std::string s = fmt::format(R"({{"seq":{},"file":{},"line":{},"col":{})", ++seq_, quoted(b.file), b.line, b.column);
    if (b.process) s += fmt::format(R"(,"process":{})", b.process);
    if (b.number) s += fmt::format(R"(,"block":"{}{}")", b.main_block ? ':' : 'N', *b.number);
    s += R"(,"event":")";
    s += event;
    s += '"';
    return s;
  }
  Reply close(std::string& s) {
    s += '}';
    line(s);
    return {};
  }

  static void num(std::string& s, const char* key, double v) { s += fmt::format(R"(,"{}":{})", key, json_number(v)); }
  static void str(std::string& s, const char* key, std::string_view v) { s += fmt::format(R"(,"{}":"{}")", key, v); }
  // "X":1,"Y":2,"Z":3 and the machine's other axes.
  void position(std::string& s, const Axes& p) const {
    for (int i = 0; i < kAxisCount; ++i)
      if (lists_axis(i)) s += fmt::format(R"(,"{}":{})", kAxisLetters[i], json_number(p[i]));
  }
  // The same as an object: "scale":{"X":1,"Y":1,"Z":1}.
  void point(std::string& s, const char* key, const Axes& p) const {
    std::string inner;
    for (int i = 0; i < kAxisCount; ++i)
      if (lists_axis(i))
        inner += fmt::format(R"({}"{}":{})", inner.empty() ? "" : ",", kAxisLetters[i], json_number(p[i]));
    s += fmt::format(R"(,"{}":{{{}}})", key, inner);
  }
  static void range(std::string& s, int axis, const Axes& lower, const Axes& upper) {
    s += fmt::format(R"(,"{}":[{},{}])", kAxisLetters[axis], json_number(lower[axis]), json_number(upper[axis]));
  }

  Reply bare(const api::Block& b, std::string_view event) {
    std::string s = open(b, event);
    return close(s);
  }
  Reply at(const api::Block& b, std::string_view event, const Axes& p) {
    std::string s = open(b, event);
    position(s, p);
    return close(s);
  }
  Reply value(const api::Block& b, std::string_view event, double v) {
    std::string s = open(b, event);
    num(s, "value", v);
    return close(s);
  }
  Reply count(const api::Block& b, std::string_view event, const char* key, int n) {
    std::string s = open(b, event);
    s += fmt::format(R"(,"{}":{})", key, n);
    return close(s);
  }
  Reply on_off(const api::Block& b, std::string_view event, bool on) {
    std::string s = open(b, event);
    s += fmt::format(R"(,"on":{})", on);
    return close(s);
  }
  Reply text_of(const api::Block& b, std::string_view event, const char* key, std::string_view text) {
    std::string s = open(b, event);
    s += fmt::format(R"(,"{}":)", key) + quoted(text);
    return close(s);
  }

  uint64_t seq_ = 0;
};

// LinuxCNC's canonical calls as `rs274 -g` prints them, without its two leading
// columns. Calls LinuxCNC has no call for print as COMMENT("ncc: ...") so that the
// output stays a list of canonical calls (docs/trace.md).
class CanonWriter final : public TraceWriter {
 public:
  CanonWriter(std::FILE* out, std::string axes) : TraceWriter(out, std::move(axes)) {
    nine_ = has_axis('U') || has_axis('V') || has_axis('W');
  }

  Reply units(const api::Block& b, api::Units u) override {
    return write(b,
                 u == api::Units::Inches ? "USE_LENGTH_UNITS(CANON_UNITS_INCHES)" : "USE_LENGTH_UNITS(CANON_UNITS_MM)");
  }
  Reply plane(const api::Block& b, const api::Plane& p) override {
    // LinuxCNC names the ZX plane XZ and has no others.
    const Plane plane = plane_of(p);
    if (plane == kPlanes[0] || plane == kPlanes[1] || plane == kPlanes[2])
      return write(b, fmt::format("SELECT_PLANE(CANON_PLANE_{})", plane == kPlanes[0]   ? "XY"
                                                                  : plane == kPlanes[1] ? "XZ"
                                                                                        : "YZ"));
    return write(b, fmt::format("COMMENT(\"ncc: plane {}\")", plane_name(plane)));
  }
  Reply feed_mode(const api::Block& b, api::FeedMode m) override {
    return write(b, fmt::format("SET_FEED_MODE(0, {})", m == api::FeedMode::PerRevolution ? 1 : 0));
  }
  Reply feed_rate(const api::Block& b, double rate) override {
    return write(b, fmt::format("SET_FEED_RATE({})", canon_number(rate)));
  }
  // LinuxCNC passes the maximum spindle speed for constant surface speed, 1e30 when
  // the program gives none (GOST has no such word), and 0 for rpm.
  Reply spindle_mode(const api::Block& b, api::SpindleMode m) override {
    return write(
        b, fmt::format("SET_SPINDLE_MODE(0 {})", canon_number(m == api::SpindleMode::ConstantSurfaceSpeed ? 1e30 : 0)));
  }
  Reply spindle_speed(const api::Block& b, double speed) override {
    return write(b, fmt::format("SET_SPINDLE_SPEED(0, {})", canon_number(speed)));
  }
  Reply spindle_start(const api::Block& b, api::Direction d) override {
    return write(b,
                 d == api::Direction::Clockwise ? "START_SPINDLE_CLOCKWISE(0)" : "START_SPINDLE_COUNTERCLOCKWISE(0)");
  }
  Reply spindle_stop(const api::Block& b) override { return write(b, "STOP_SPINDLE_TURNING(0)"); }
  Reply spindle_orient(const api::Block& b, double angle) override {
    return write(b, fmt::format("ORIENT_SPINDLE(0, {}, 0)", canon_number(angle)));
  }
  Reply straight_traverse(const api::Block& b, const Axes& end, AxisMask) override {
    return write(b, fmt::format("STRAIGHT_TRAVERSE({})", axes_list(end, 0)));
  }
  Reply straight_feed(const api::Block& b, const Axes& end, AxisMask) override {
    return write(b, fmt::format("STRAIGHT_FEED({})", axes_list(end, 0)));
  }
  Reply arc_feed(const api::Block& b, const api::Arc& a) override {
    const api::Plane& p = a.plane;
    return write(b,
                 fmt::format("ARC_FEED({}, {}, {}, {}, {}, {}, {})", canon_number(a.end[p.first]),
                             canon_number(a.end[p.second]), canon_number(a.centre_first), canon_number(a.centre_second),
                             a.rotation, canon_number(p.normal >= 0 ? a.end[p.normal] : 0), axes_list(a.end, 3)));
  }
  Reply parabola(const api::Block& b, const Axes& end, const Axes& control) override {
    return write(b, fmt::format("PARABOLA_FEED({}, {}, {}, {})", canon_number(control[0]), canon_number(control[1]),
                                canon_number(control[2]), axes_list(end, 0)));
  }
  Reply thread(const api::Block& b, const Axes& end, double pitch, double pitch_change, double) override {
    turn(b);
    line(fmt::format("START_SPEED_FEED_SYNC({:f},0)", pitch));
    if (pitch_change != 0)
      line(fmt::format("COMMENT(\"ncc: pitch change {} per revolution\")", canon_number(pitch_change)));
    line(fmt::format("STRAIGHT_FEED({})", axes_list(end, 0)));
    line("STOP_SPEED_FEED_SYNCH()");
    return {};
  }
  Reply spline(const api::Block& b, const Axes& end, const Axes& control1, const Axes& control2) override {
    return write(
        b, fmt::format("CUBIC_FEED({}, {}, {})", axes_list(control1, 0), axes_list(control2, 0), axes_list(end, 0)));
  }
  Reply probe(const api::Block& b, const Axes& end, bool) override {
    return write(b, fmt::format("STRAIGHT_PROBE({})", axes_list(end, 0)));
  }
  Reply dwell(const api::Block& b, double seconds) override {
    return write(b, fmt::format("DWELL({})", canon_number(seconds)));
  }
  Reply path_mode(const api::Block& b, api::PathMode m) override {
    // LinuxCNC's motion control modes: exact stop (its G61.1) and blending (G64).
    if (m == api::PathMode::PointToPoint) return write(b, "SET_MOTION_CONTROL_MODE(CANON_EXACT_STOP)");
    if (m == api::PathMode::Continuous || m == api::PathMode::Smooth)
      return write(b, "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.000000)");
    return write(b, fmt::format("COMMENT(\"ncc: path {}\")", kPathModes[ordinal(m)]));
  }
  Reply tool_select(const api::Block& b, int tool) override { return write(b, fmt::format("SELECT_TOOL({})", tool)); }
  Reply tool_change(const api::Block& b, int tool) override {
    turn(b);
    line("START_CHANGE()");
    return write(b, fmt::format("CHANGE_TOOL({})", tool));
  }
  Reply tool_length_offset(const api::Block& b, const Axes& o) override {
    return write(b, fmt::format("USE_TOOL_LENGTH_OFFSET({} {} {}, {} {} {}, {} {} {})", canon_number(o[0]),
                                canon_number(o[1]), canon_number(o[2]), canon_number(o[3]), canon_number(o[4]),
                                canon_number(o[5]), canon_number(o[6]), canon_number(o[7]), canon_number(o[8])));
  }
  Reply cutter_compensation(const api::Block& b, api::CutterSide side, double) override {
    return write(b, side == api::CutterSide::Off
                        ? std::string("COMMENT(\"interpreter: cutter radius compensation off\")")
                        : fmt::format("COMMENT(\"interpreter: cutter radius compensation on {}\")",
                                      side == api::CutterSide::Left ? "left" : "right"));
  }
  Reply work_offset(const api::Block& b, int number, const Axes& offset) override {
    return write(b, fmt::format("SET_G5X_OFFSET({}, {})", number, axes_list(offset, 0)));
  }
  Reply position_offset(const api::Block& b, const Axes& offset) override {
    return write(b, fmt::format("SET_G92_OFFSET({})", axes_list(offset, 0)));
  }
  Reply coolant(const api::Block& b, api::Coolant c) override {
    switch (c) {
      case api::Coolant::Off:
        turn(b);
        line("MIST_OFF()");
        return write(b, "FLOOD_OFF()");
      case api::Coolant::Mist: return write(b, "MIST_ON()");
      case api::Coolant::Flood: return write(b, "FLOOD_ON()");
      default: return write(b, fmt::format("COMMENT(\"ncc: coolant {}\")", kCoolants[ordinal(c)]));
    }
  }
  Reply comment(const api::Block& b, std::string_view text) override {
    return write(b, fmt::format("COMMENT({})", quoted(text)));
  }
  Reply message(const api::Block& b, std::string_view text) override {
    return write(b, fmt::format("MESSAGE({})", quoted(text)));
  }
  Reply stop(const api::Block& b, api::StopKind k) override {
    if (k == api::StopKind::ManualRetract) write(b, "COMMENT(\"ncc: manual retract\")");
    return write(b, k == api::StopKind::OptionalTaken || k == api::StopKind::OptionalSkipped ? "OPTIONAL_PROGRAM_STOP()"
                                                                                             : "PROGRAM_STOP()");
  }
  Reply program_end(const api::Block& b, bool) override { return write(b, "PROGRAM_END()"); }
  Reply operator_move(const api::Block& b, const Axes& to) override {
    return write(b, fmt::format("COMMENT(\"ncc: operator move to {}\")", axes_list(to, 0)));
  }
  Reply input(const api::Block& b, std::string_view prompt, double answer) override {
    return write(b, fmt::format("COMMENT(\"ncc: input {} {}\")", json_escape(prompt), canon_number(answer)));
  }
  Reply input_text(const api::Block& b, std::string_view prompt, std::string_view answer) override {
    return write(b, fmt::format("COMMENT(\"ncc: input {} {}\")", json_escape(prompt), json_escape(answer)));
  }
  Reply clamp(const api::Block& b, api::Clamp c) override {
    return write(b, fmt::format("COMMENT(\"ncc: clamp {}\")", kClamps[ordinal(c)]));
  }
  Reply override_enable(const api::Block& b, bool enabled) override {
    write(b, enabled ? "ENABLE_FEED_OVERRIDE()" : "DISABLE_FEED_OVERRIDE()");
    return write(b, enabled ? "ENABLE_SPEED_OVERRIDE(0)" : "DISABLE_SPEED_OVERRIDE(0)");
  }
  Reply spindle_hold(const api::Block& b, bool on) override {
    return write(b, on ? "COMMENT(\"ncc: spindle hold on\")" : "COMMENT(\"ncc: spindle hold off\")");
  }
  Reply aux(const api::Block& b, std::string_view function) override { return ncc_text(b, "aux", function); }
  Reply block_start(const api::Block& b) override {  // LinuxCNC's calls have no block boundaries
    turn(b);
    return {};
  }
  Reply origin(const api::Block& b, const Axes& zero) override {
    return write(b, fmt::format("SET_G5X_OFFSET(0, {})", axes_list(zero, 0)));
  }
  Reply transform(const api::Block& b, double, AxisMask, const Axes&) override { return ncc_only(b, "transform"); }
  Reply tolerance(const api::Block& b, AxisMask, const Axes&) override { return ncc_only(b, "tolerance"); }
  Reply limits(const api::Block& b, AxisMask, const Axes&, const Axes&) override { return ncc_only(b, "limits"); }
  Reply zone(const api::Block& b, int, api::ZoneState, const api::Plane&, const Axes&, const Axes&) override {
    return ncc_only(b, "zone");
  }
  Reply configuration(const api::Block& b, api::Configuration) override { return ncc_only(b, "configuration"); }
  Reply spindle_range(const api::Block& b, int) override { return ncc_only(b, "spindle_range"); }
  Reply part_change(const api::Block& b) override { return ncc_only(b, "part_change"); }
  Reply virtual_axes(const api::Block& b, std::string_view what) override { return ncc_text(b, "virtual", what); }
  // A table entry: what is in force shows when it is selected.
  Reply offset_load(const api::Block& b, int number, const Axes& offset) override {
    return write(b, fmt::format("COMMENT(\"ncc: offset_load {} {}\")", number, axes_list(offset, 0)));
  }
  Reply comp_load(const api::Block& b, int entry, double length, double radius) override {
    return write(b, fmt::format("COMMENT(\"ncc: comp_load {} length {} radius {}\")", entry, canon_number(length),
                                canon_number(radius)));
  }
  Reply tooling(const api::Block& b, api::ToolingChange, std::string_view what) override {
    return ncc_text(b, "tooling", what);
  }
  Reply diameter(const api::Block& b, bool on) override {
    return write(b, fmt::format("COMMENT(\"ncc: diameter {}\")", on ? "on" : "off"));
  }
  Reply feed_reduction(const api::Block& b, bool on) override {
    return write(b, fmt::format("COMMENT(\"ncc: feed_reduction {}\")", on ? "on" : "off"));
  }
  Reply asset(const api::Block& b, std::string_view statement, int code) override {
    return ncc_text(b, "asset", asset_text(statement, code));
  }
  Reply screen(const api::Block& b, std::string_view what) override { return ncc_text(b, "screen", what); }
  Reply sync(const api::Block& b, std::string_view what) override { return ncc_text(b, "sync", what); }
  Reply graphic(const api::Block& b, std::string_view what) override { return ncc_text(b, "graphic", what); }

 private:
  // The processes of a run take turns: each turn says whose calls follow.
  void turn(const api::Block& b) {
    if (b.process != process_) line(fmt::format("COMMENT(\"ncc: process {}\")", process_ = b.process));
  }
  Reply write(const api::Block& b, const std::string& call) {
    turn(b);
    line(call);
    return {};
  }
  // A call LinuxCNC has not: its name alone, or with its text.
  Reply ncc_only(const api::Block& b, const char* name) { return write(b, fmt::format("COMMENT(\"ncc: {}\")", name)); }
  Reply ncc_text(const api::Block& b, const char* name, std::string_view text) {
    return write(b, fmt::format("COMMENT(\"ncc: {} {}\")", name, json_escape(text)));
  }

  // LinuxCNC prints X Y Z A B C (and U V W on machines that have them).
  std::string axes_list(const Axes& p, int from) const {
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

// The writer behind the adapter that calls it.
class WriterSink final : public TraceSink {
 public:
  WriterSink(std::unique_ptr<TraceWriter> writer, const SourceMap& map, bool places)
      : writer_(std::move(writer)), calls_(*writer_, map, places) {}
  void event(const Event& e) override { calls_.event(e); }
  void flush() override { writer_->flush(); }

 private:
  std::unique_ptr<TraceWriter> writer_;
  MachineInterfaceSink calls_;
};

}  // namespace

std::unique_ptr<TraceSink> make_trace_writer(TraceFormat format, std::FILE* out, const SourceMap& map,
                                             std::string axes) {
  switch (format) {
    case TraceFormat::Text:
      return std::make_unique<WriterSink>(std::make_unique<TextWriter>(out, std::move(axes)), map, true);
    case TraceFormat::Jsonl:
      return std::make_unique<WriterSink>(std::make_unique<JsonlWriter>(out, std::move(axes)), map, true);
    case TraceFormat::Canon:
      return std::make_unique<WriterSink>(std::make_unique<CanonWriter>(out, std::move(axes)), map, false);
  }
  return nullptr;
}

}  // namespace ncc
