// NC-110 virtual axes, UAV (§2.17-2.19): the program moves virtual axes in place of
// real ones. The trace keeps the programmed (virtual) coordinates, as LinuxCNC's canon
// keeps world coordinates whatever the kinematics; a `virtual` event says how the
// real axes follow, and gives their positions when the virtual axes are cancelled.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine.h"
#include "support/text.h"

namespace ncc {

namespace {

constexpr double kPi = std::numbers::pi;

// UAV's axis lists travel packed, an axis a hex digit (its index + 1), the first lowest;
// empty when that is not what they hold (a bytecode file written by hand).
std::vector<int> unpack_axes(double packed) {
  std::vector<int> axes;
  for (uint32_t n = whole_in<uint32_t>(packed, 1, 0xFFFF).value_or(0); n; n >>= 4) {
    const int a = static_cast<int>(n & 15) - 1;
    if (a < 0 || a >= kAxisCount || std::find(axes.begin(), axes.end(), a) != axes.end()) return {};
    axes.push_back(a);
  }
  return axes;
}

// "X Y Z"
std::string letters(const std::vector<int>& axes) {
  std::string s;
  for (int a : axes) s += (s.empty() ? "" : " ") + std::string(1, kAxisLetters[static_cast<size_t>(a)]);
  return s;
}

// The distance from the origin to the segment p..q.
double distance_to_segment(double px, double py, double qx, double qy) {
  const double dx = qx - px, dy = qy - py, length2 = dx * dx + dy * dy;
  const double t = length2 > 0 ? std::clamp(-(px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(px + t * dx, py + t * dy);
}

}  // namespace

bool Machine::virtual_function(FnCall call) {
  if (call.fn != Fn::VirtualAxes) return false;
  VirtualAxes& va = virtual_axes_;
  const auto mode = whole_operand(0, 0, 4, "the mode");
  if (!mode) return true;
  // The path's coordinates change under it: compensation and a GTL profile end first.
  if (modal_.comp != 0) {
    report_code(DiagId::VirtualAxes, "UAV changes the axes the path is compensated in: G40 comes first");
    return true;
  }
  if (gtl_open()) {
    report_code(DiagId::VirtualAxes, "UAV changes the axes of the open GTL profile: G20 ends it first");
    return true;
  }
  if (*mode == 0) {
    if (va.mode == 0)
      report_code(DiagId::VirtualAxes, "(UAV,0) cancels virtual axes; none are active");
    else
      virtual_off();
    return true;
  }
  if (va.mode != 0) {
    report_code(DiagId::VirtualAxes, "virtual axes are active already: (UAV,0) cancels them first");
    return true;
  }
  const std::vector<int> real = unpack_axes(slot_value(operand_slot(1)));
  const std::vector<int> virt = unpack_axes(slot_value(operand_slot(2)));
  auto value = [&](int i) { return slot_value(operand_slot(3 + i)); };
  auto kind = [&](int a) { return config_.axes[static_cast<size_t>(a)].kind; };
  auto fail = [&](const std::string& why) {
    report_code(DiagId::VirtualAxes, why);
    return true;
  };
  auto program = [&](int a) { return kernel_.position()[a] - kernel_.origin(a); };
  // The lists' lengths the mode takes (the compiler checked them).
  const auto m = static_cast<size_t>(*mode);
  const VirtualForm& form = kVirtualForms[m];
  if (real.size() < form.real_lo || real.size() > form.real_hi || virt.size() < form.virt_lo ||
      virt.size() > form.virt_hi)
    return fail(fmt::format("mode {} does not take the axes {} and {}", m, letters(real), letters(virt)));
  for (int a : virt)
    if (std::find(real.begin(), real.end(), a) != real.end())
      return fail(fmt::format("{} stands in both lists", kAxisLetters[a]));
  // The axes UAV joins cannot be mirrored, scaled or rotated: the mapping is between
  // plain coordinates.
  for (const std::vector<int>* list : {&real, &virt})
    for (int a : *list)
      if (kernel_.frame().mirror[a] || kernel_.frame().scale[a] != 1 ||
          (kernel_.frame().rotation != 0 && (a == modal_.plane.u || a == modal_.plane.v)))
        return fail(
            fmt::format("{} is mirrored, scaled or rotated (MIR, SCF, URT): cancel that before UAV", kAxisLetters[a]));
  for (int a : virt)
    if (kind(a) != AxisKind::Linear || config_.axes[static_cast<size_t>(a)].diameter)
      return fail(fmt::format("the virtual axis {} is a linear axis, not a rotary or diametral one", kAxisLetters[a]));

  if (kernel_.path()) kernel_.path()->leave();
  VirtualAxes next;
  next.mode = *mode;
  next.real = real;
  next.virt = virt;
  next.saved = kernel_.position();
  next.zero = kernel_.origins();
  std::string text;
  switch (*mode) {
    case 1:
    case 2: {
      // Polar (§2.17.1): X C as U V, r the radius the tool must stay outside.
      // Cylinder (§2.17.2): B as V, the developed circumference of radius n.
      const int rotary = *mode == 1 ? real[1] : real[0];
      if (*mode == 1 && kind(real[0]) != AxisKind::Linear)
        return fail(fmt::format("{} is the linear axis of the polar pair: it must be linear", kAxisLetters[real[0]]));
      if (kind(rotary) != AxisKind::Rotary) return fail(fmt::format("{} must be a rotary axis", kAxisLetters[rotary]));
      next.value = length_units(value(0));
      if (*mode == 1 && next.value < 0)
        return fail(fmt::format("the minimum radius {} is negative", shortest(value(0))));
      if (*mode == 2 && !(next.value > 0))
        return fail(fmt::format("the cylinder's radius {} must be greater than 0", shortest(value(0))));
      // "The rotary axis is positioned at zero" when they are activated.
      if (std::fabs(program(rotary)) > 1e-9) {
        AxisValues t = kernel_.position();
        t[rotary] = kernel_.origin(rotary);
        rapid(t);
      }
      next.saved = kernel_.position();
      if (*mode == 1) {
        // C is the polar angle of U V, counter-clockwise; a tool on X's negative side
        // starts half a turn round.
        const double x = program(real[0]);
        next.sign[0] = x < 0 ? -1 : 1;
        next.angle = x < 0 ? kPi : 0;
        kernel_.place(virt[0], next.zero[virt[0]] + x);
        kernel_.place(virt[1], next.zero[virt[1]]);
        text = fmt::format("polar {} as {} min radius {}", letters(real), letters(virt),
                           four_decimals(to_program(next.value)));
      } else {
        kernel_.place(virt[0], next.zero[virt[0]]);
        text = fmt::format("cylinder {} as {} radius {}", kAxisLetters[rotary], kAxisLetters[virt[0]],
                           four_decimals(to_program(next.value)));
      }
      break;
    }
    case 3: {
      // Parallel axes (§2.18): each slave follows its master, mirrored or not.
      for (int a : real)
        if (std::fabs(program(a)) > 1e-9)
          return fail(fmt::format("the slave {} is not at 0: masters and slaves start at 0", kAxisLetters[a]));
      for (int a : virt)
        if (std::fabs(program(a)) > 1e-9)
          return fail(fmt::format("the master {} is not at 0: masters and slaves start at 0", kAxisLetters[a]));
      uint32_t map = whole_in<uint32_t>(value(0), 1, 999).value_or(0),
               mirror = whole_in<uint32_t>(value(1), 1, 999).value_or(0);
      text = "parallel";
      for (size_t k = real.size(); k-- > 0; map /= 10, mirror /= 10) {
        if (map % 10 < 1 || map % 10 > virt.size() || mirror % 10 < 1 || mirror % 10 > 2)
          return fail("each slave has a master's place in the list and a mirror, 1 or 2");
        next.master[k] = virt[map % 10 - 1];
        next.sign[k] = mirror % 10 == 2 ? -1 : 1;
      }
      for (size_t k = 0; k < real.size(); ++k)
        text +=
            fmt::format(" {}={}{}", kAxisLetters[real[k]], next.sign[k] < 0 ? "-" : "", kAxisLetters[next.master[k]]);
      break;
    }
    case 4: {
      // Rotation in space (§2.19): real = Rz(a3) Ry(a2) Rx(a1) virtual, about the origin.
      for (int a : real)
        if (kind(a) != AxisKind::Linear) return fail(fmt::format("{} must be a linear axis", kAxisLetters[a]));
      double r[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      for (int k = 0; k < 3; ++k) {
        const double a = angle_degrees(value(k)) * kPi / 180, c = std::cos(a), s = std::sin(a);
        const int i = (k + 1) % 3, j = (k + 2) % 3;  // the plane the rotation about axis k turns
        double next_r[3][3];
        for (int col = 0; col < 3; ++col) {
          next_r[k][col] = r[k][col];
          next_r[i][col] = c * r[i][col] - s * r[j][col];
          next_r[j][col] = s * r[i][col] + c * r[j][col];
        }
        std::copy(&next_r[0][0], &next_r[0][0] + 9, &r[0][0]);
      }
      std::copy(&r[0][0], &r[0][0] + 9, next.rotation.begin());
      for (int i = 0; i < 3; ++i) {  // virtual = R^T real
        double v = 0;
        for (int k = 0; k < 3; ++k) v += r[k][i] * program(real[static_cast<size_t>(k)]);
        kernel_.place(virt[static_cast<size_t>(i)], next.zero[virt[static_cast<size_t>(i)]] + v);
      }
      text = fmt::format("rotation {} as {} angles {} {} {}", letters(real), letters(virt), shortest(value(0)),
                         shortest(value(1)), shortest(value(2)));
      break;
    }
    default: break;
  }
  va = next;
  virtual_event(text);
  return true;
}

void Machine::virtual_event(const std::string& what) {
  // The positions of the axes it joins, program coordinates.
  std::string text = what + " at";
  const VirtualAxes& va = virtual_axes_;
  for (const std::vector<int>* list : {&va.virt, &va.real})
    for (int a : *list)
      text += fmt::format(" {}{}", kAxisLetters[a],
                          four_decimals(program_axis(a, kernel_.position()[a] - kernel_.origin(a))));
  text_event(EventKind::Virtual, text, source());
}

void Machine::virtual_off() {
  VirtualAxes& va = virtual_axes_;
  if (va.mode == 0) return;
  if (kernel_.path()) kernel_.path()->leave();  // NC-110's G40 leaves with the next move: this is it
  const AxisValues now = kernel_.position();
  AxisValues to = now;
  auto virtual_at = [&](size_t k) { return now[va.virt[k]] - va.zero[va.virt[k]]; };
  switch (va.mode) {
    case 1: {
      to[va.real[0]] = va.zero[va.real[0]] + va.sign[0] * std::hypot(virtual_at(0), virtual_at(1));
      to[va.real[1]] = va.zero[va.real[1]] + (va.angle - (va.sign[0] < 0 ? kPi : 0)) * 180 / kPi;
      break;
    }
    case 2: to[va.real[0]] = va.zero[va.real[0]] + virtual_at(0) / va.value * 180 / kPi; break;
    case 3:
      for (size_t k = 0; k < va.real.size(); ++k)
        to[va.real[k]] = va.saved[va.real[k]] + va.sign[k] * (now[va.master[k]] - va.saved[va.master[k]]);
      break;
    case 4:
      for (size_t i = 0; i < 3; ++i) {
        double v = 0;
        for (size_t k = 0; k < 3; ++k) v += va.rotation[i * 3 + k] * virtual_at(k);
        to[va.real[i]] = va.zero[va.real[i]] + v;
      }
      break;
    default: return;
  }
  // The virtual axes' letters are the real axes' again, where those were (modes 1, 2, 4).
  if (va.mode != 3)
    for (int a : va.virt) to[a] = va.saved[a];
  kernel_.move_to(to);
  virtual_event("off");
  va = VirtualAxes{};
}

bool Machine::virtual_axes_programmed() {
  const VirtualAxes& va = virtual_axes_;
  // Mode 3: the masters are programmed, the slaves follow; otherwise the virtual axes
  // are programmed and the real ones follow.
  const std::vector<int>& driven = va.real;
  for (int a : driven)
    if (has(kAxisLetters[static_cast<size_t>(a)])) {
      report(DiagId::VirtualAxes, kAxisLetters[static_cast<size_t>(a)],
             fmt::format("{} follows {} (UAV mode {}): program {}, or cancel with (UAV,0)",
                         kAxisLetters[static_cast<size_t>(a)], va.mode == 3 ? "its master" : "the virtual axes",
                         va.mode, va.mode == 3 ? "the master" : letters(va.virt)));
      return true;
    }
  return false;
}

bool Machine::virtual_path(const std::vector<AxisValues>& path) {
  // Mode 1: the tool stays outside the minimum radius about the rotary axis, and C
  // turns as the path goes round it (the angle unwrapped point by point: no segment
  // of a line, nor chord of an arc, turns half a turn about a centre it keeps away from).
  VirtualAxes& va = virtual_axes_;
  if (va.mode != 1) return true;
  const int u = va.virt[0], v = va.virt[1];
  for (size_t i = 0; i < path.size(); ++i) {
    const double x = path[i][u] - va.zero[u], y = path[i][v] - va.zero[v];
    if (i > 0) {
      const double px = path[i - 1][u] - va.zero[u], py = path[i - 1][v] - va.zero[v];
      const double d = distance_to_segment(px, py, x, y);
      if (d < va.value - kChord) {
        report(
            DiagId::VirtualAxes, 0,
            fmt::format("the path passes {} from {}'s centre, inside the minimum radius {} (UAV)",
                        four_decimals(to_program(d)), kAxisLetters[va.real[1]], four_decimals(to_program(va.value))));
        return false;
      }
    }
    if (x != 0 || y != 0) va.angle += std::remainder(std::atan2(y, x) - va.angle, 2 * kPi);
  }
  return true;
}

}  // namespace ncc
