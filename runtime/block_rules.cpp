// ISO/Fanuc's block rules (§8.4, §8.8-§8.31; E-08..E-27): what scaling, rotation,
// incremental positioning and cutter compensation forbid a block, and the dwell after
// a move; NC-110's (§2.8.7): what a compensated path may hold. The plain rules (GOST
// 20999, pp) are the base's.
#include "block_rules.h"

namespace ncc {

class Machine::IsoBlockRules final : public BlockRules {
 public:
  using BlockRules::BlockRules;
  bool may_run_scaled_or_rotated() override;
  bool may_change_coordinates() override;
  bool may_change_plane(const Plane& plane) override;
  bool may_use_machine_coordinates() override;
  void check_arc() override;
  bool dwells_after_move() const override { return true; }  // §8.4
  // §8.12: an arc by R keeps its shape, R scaled by the larger factor (decision 26);
  // by I J K its end point leaves the circle (E-01).
  bool scales_arcs_unequally() const override { return true; }

 private:
  void refuse(const char* because);  // the code being applied, under what forbids it
};

class Machine::Nc110BlockRules final : public BlockRules {
 public:
  using BlockRules::BlockRules;
  bool may_stand_in_compensated_path() override;
  bool joins_path_corners() const override { return true; }  // §2.8.7: r, b in a block of their own
};

std::unique_ptr<Machine::BlockRules> Machine::BlockRules::make(Machine& m, const Conventions& conv) {
  if (conv.fanuc_rules) return std::make_unique<IsoBlockRules>(m);
  if (conv.cutter == CutterStyle::Nc110) return std::make_unique<Nc110BlockRules>(m);
  return std::make_unique<BlockRules>(m);
}

// §2.8.7 rule 2: no M, H, S or T inside a compensated profile.
bool Machine::Nc110BlockRules::may_stand_in_compensated_path() {
  for (char l : {'M', 'H', 'S', 'T'})
    if (m_.has(l)) {
      m_.report(DiagId::CompPath, l,
                fmt::format("{} stands outside the compensated profile: between G41/G42 and G40 no "
                            "block has M, H, S or T (§2.8.7)",
                            l));
      return false;
    }
  return true;
}

void Machine::IsoBlockRules::refuse(const char* because) {
  m_.report_code(DiagId::PlaneState, m_.block_.code_name, because);
}

// §8.8-§8.31 (E-08, E-09, E-19, E-21, E-22, E-26, E-27).
bool Machine::IsoBlockRules::may_run_scaled_or_rotated() {
  if (!m_.modal_.scaling && !m_.modal_.rotation) return true;
  refuse(m_.modal_.scaling ? "scaling (G51)" : "coordinate rotation (G68)");
  return false;
}

// The offset path is made in the work coordinates of its moves: a change of units or
// of the frame would put two moves of it in different ones (§8.10).
bool Machine::IsoBlockRules::may_change_coordinates() {
  if (m_.modal_.comp == 0) return true;
  refuse("cutter radius compensation");
  return false;
}

// §8.10 (E-10): the plane stays while cutter compensation is on, unless G40 in the
// same block (in any word order) ends it.
bool Machine::IsoBlockRules::may_change_plane(const Plane& plane) {
  if (m_.modal_.comp == 0 || !m_.block_.request || m_.modal_.plane == plane || m_.block_has(Fn::CompOff)) return true;
  refuse("cutter radius compensation");
  return false;
}

// §8.14 (E-20): machine coordinates are absolute (a G90 of the block counts).
bool Machine::IsoBlockRules::may_use_machine_coordinates() {
  if (m_.modal_.absolute || m_.block_has(Fn::DistanceAbsolute)) return true;
  refuse("incremental positioning (G91)");
  return false;
}

void Machine::IsoBlockRules::check_arc() {
  const Modal& modal = m_.modal_;
  const BlockState& block = m_.block_;
  // §8.11 (E-15): the length offset does not change on a helix.
  if (modal.plane.w >= 0 && m_.has(kAxisLetters[modal.plane.w]) && m_.compensation().length != block.length_before)
    m_.report(DiagId::ArcForm, 0,
              "the tool length offset cannot change in a helical move (E-15): change it on a straight move");
  // §8.10: compensation starts and ends on a straight move (E-11, E-13; the path checks
  // the first move after a G41/G42/G40 of a block of its own), and changes side or
  // radius only there (E-14).
  const char* what = nullptr;
  if (block.comp_before == 0 && modal.comp != 0)
    what = "cutter radius compensation cannot start on an arc (E-11)";
  else if (block.comp_before != 0 && modal.comp == 0)
    what = "cutter radius compensation cannot end on an arc (E-13)";
  else if (block.comp_before != 0 &&
           (modal.comp != block.comp_before || m_.compensation().radius != block.radius_before))
    what = "cutter radius compensation changes side or radius only on a straight move (E-14)";
  if (what) m_.report(DiagId::ArcForm, 0, std::string(what) + ": use a G00 or G01 move");
}

}  // namespace ncc
