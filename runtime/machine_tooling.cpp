// The NC-110 tool table and probe as a program changes them (§2.13.8-2.13.10):
// correctors requalified (RQU, RQP), tools declared unusable (TOF) and replaced by
// their sisters when selected, the measuring cycles' distances and speed (DPT).
#include <cmath>
#include <utility>

#include "machine.h"
#include "support/text.h"

namespace ncc {

namespace {

constexpr double kMaxLength = 9999.999;   // a corrector's length, ± (§1.1.17)
constexpr double kMaxDiameter = 999.999;  // its diameter K

}  // namespace

std::optional<int> Machine::whole_operand(int i, int lo, int hi, const char* what) {
  auto v = slot_if(operand_slot(i));
  if (!v) return std::nullopt;
  const std::optional<int> n = whole_in(*v, lo, hi);
  if (!n)
    report_slot(DiagId::OperandValue, operand_slot(i), what, shortest(*v),
                fmt::format("a whole number from {} to {}", lo, hi));
  return n;
}

void Machine::select_offset(int n, OffsetUse use) {
  auto it = tool_offsets_.find(n);
  const OffsetEntry entry = it == tool_offsets_.end() ? OffsetEntry{} : it->second;
  if (use != OffsetUse::Length) {
    offset_number_ = n;
    offset_ = entry;
  }
  if (use != OffsetUse::Radius) {
    length_number_ = n;
    length_offset_ = entry;
  }
}

int Machine::usable_tool(int tool) {
  auto why = unusable_.find(tool);
  if (why == unusable_.end()) return tool;
  // Tool life management takes the first sister still usable (§2.13.8, §2.15.2.2.2).
  if (auto entry = config_.tools.find(tool); entry != config_.tools.end())
    for (int sister : entry->second.sisters)
      if (!unusable_.count(sister)) {
        text_event(EventKind::Tooling, fmt::format("tool {} replaced by sister {}", tool, sister), source(),
                   kToolingUnusable);
        return sister;
      }
  if (!std::exchange(why->second.reported, true)) report(DiagId::ToolUnusable, 'T', tool, why->second.why);
  return tool;
}

bool Machine::tooling_function(FnCall call) {
  switch (call.fn) {
    case Fn::CorrectorRequalify:
    case Fn::CorrectorModify: {
      auto tool = whole_operand(0, 1, 9999, "the tool");
      auto n = whole_operand(1, 1, 9999, "the corrector");
      if (!tool || !n) break;
      auto it = tool_offsets_.find(*n);
      if (it == tool_offsets_.end()) {
        report_slot(DiagId::OffsetUnknown, operand_slot(1), "corrector", *n, config_.profile,
                    number_ranges(tool_offsets_));
        break;
      }
      if (!config_.tools.count(*tool))
        report_slot(DiagId::ToolUnknown, operand_slot(0), *tool, config_.profile, number_ranges(config_.tools));
      const std::string code = block_.code_name;
      OffsetEntry e = it->second;
      // The length's increment, on the axis the corrector's length applies to; a
      // diametral axis's is halved. K is the diameter's. SCF scales neither.
      const char own = e.axis ? e.axis : conv_.tool_offset_axes.empty() ? 'Z' : conv_.tool_offset_axes[0];
      double length = 0;
      for (char letter : conv_.axes) {
        if (!has(letter)) continue;
        if (letter != own) {
          report(DiagId::CorrectorValue, letter,
                 fmt::format("{} adds to corrector {}'s length, which applies to {}: write {}, not {}", code, *n, own,
                             own, letter));
          return true;
        }
        const int a = axis_index(letter);
        length = length_units(word(letter));
        if (config_.axes[static_cast<size_t>(a)].diameter) length /= 2;
      }
      const double diameter = has('K') ? length_units(word('K')) : 0;
      e.length += length;
      e.radius += diameter / 2;
      auto beyond = [&](char word, const char* what, double value, double lo, double hi) {
        if (value >= lo && value <= hi) return false;
        report(DiagId::CorrectorValue, word,
               fmt::format("{} would make corrector {}'s {} {}: it lies between {} and {}", code, *n, what,
                           four_decimals(to_program(value)), four_decimals(to_program(lo)),
                           four_decimals(to_program(hi))));
        return true;
      };
      if (beyond(own, "length", e.length, -kMaxLength, kMaxLength) ||
          beyond('K', "diameter", 2 * e.radius, 0, kMaxDiameter))
        break;
      // RQU adds up the wear a corrector keeps; beyond its maximum the tool is unusable.
      const bool wear = call.fn == Fn::CorrectorRequalify && (e.max_wear_length || e.max_wear_diameter);
      if (wear) {
        e.wear_length += length;
        e.wear_diameter += diameter;
      }
      it->second = e;
      std::string text = fmt::format("corrector {} tool {} length {} radius {}", *n, *tool,
                                     four_decimals(to_program(e.length)), four_decimals(to_program(e.radius)));
      if (wear)
        text += fmt::format(" wear {} {}", four_decimals(to_program(e.wear_length)),
                            four_decimals(to_program(e.wear_diameter)));
      text_event(EventKind::Tooling, text, source(), kToolingCorrector);
      if (!wear) break;
      std::string why;
      if (e.max_wear_length && std::fabs(e.wear_length) > *e.max_wear_length + 1e-9)
        why = fmt::format("corrector {}'s length wear {} is beyond {}", *n, four_decimals(to_program(e.wear_length)),
                          four_decimals(to_program(*e.max_wear_length)));
      else if (e.max_wear_diameter && std::fabs(e.wear_diameter) > *e.max_wear_diameter + 1e-9)
        why = fmt::format("corrector {}'s diameter wear {} is beyond {}", *n,
                          four_decimals(to_program(e.wear_diameter)), four_decimals(to_program(*e.max_wear_diameter)));
      if (why.empty()) break;
      unusable_.emplace(*tool, Unusable{"RQU: " + why});
      text_event(EventKind::Tooling, fmt::format("tool {} unusable (RQU: {})", *tool, why), source(), kToolingUnusable);
      break;
    }
    case Fn::ToolUnusable: {
      auto tool = whole_operand(0, 1, 9999, "the tool");
      if (!tool) break;
      if (!config_.tools.count(*tool))
        report_slot(DiagId::ToolUnknown, operand_slot(0), *tool, config_.profile, number_ranges(config_.tools));
      unusable_.emplace(*tool, Unusable{"TOF"});
      text_event(EventKind::Tooling, fmt::format("tool {} unusable (TOF)", *tool), source(), kToolingUnusable);
      break;
    }
    case Fn::ProbeSettings: {
      // mm and mm/min whatever G70/G71 say (§2.13.9).
      double values[3];
      static constexpr const char* kWhat[] = {"the approach distance Qa", "the safety distance Qs",
                                              "the measuring speed Vm"};
      for (int i = 0; i < 3; ++i) {
        values[i] = slot_if(operand_slot(i)).value_or(0);
        const double lo = i < 2 ? 0.001 : 1, hi = i < 2 ? 9999.999 : 99999;
        if (!(values[i] >= lo && values[i] <= hi)) {
          report_slot(DiagId::OperandValue, operand_slot(i), kWhat[i], shortest(values[i]),
                      fmt::format("from {} to {}", shortest(lo), shortest(hi)));
          return true;
        }
      }
      probe_.approach = values[0];
      probe_.safety = values[1];
      probe_.feed = values[2];
      text_event(EventKind::Tooling,
                 fmt::format("probe approach {} safety {} feed {}", shortest(values[0]), shortest(values[1]),
                             shortest(values[2])),
                 source(), kToolingProbe);
      break;
    }
    default: return false;
  }
  return true;
}

}  // namespace ncc
