// A GTL profile (§2.11.8-2.11.9): the elements a program calls between G21 and G20,
// joined where they meet, by a fillet `r` or a chamfer `b`, turned into the pieces
// of the tool's path. With compensation the tool runs on the elements moved by its
// radius to one side (§2.8.7 as GTL applies it): lines shifted, circles grown or
// shrunk, consecutive ones meeting where their offsets meet; `r0` rolls the tool
// round an outside corner instead, as it does where the offsets do not meet.
//
// An element's end depends on the element after it, so each call waits for the next
// one: the pieces come out one element late, each tagged with the caller's tag of
// the block it belongs to, with the blocks that move only other axes in their order.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gtl.h"

namespace ncc::gtl {

// A piece of the path in the plane: a line or an arc to `to` (of its tag's block), or
// a held block whose own axes outside the plane move now (`in_plane` false).
struct Piece {
  size_t tag = 0;
  bool in_plane = true;
  bool arc = false;
  Vec to{0, 0};
  Vec centre{0, 0};
  bool ccw = false;
};

// An element as the profile names it: "l3".
using ElementId = std::pair<Kind, int>;
std::string element_name(ElementId id);

class Profile {
 public:
  // G21: side +1 puts the tool left of the path (G41), -1 right (G42), 0 on it; radius
  // is the tool's, stock allowance included.
  void open_at(const Vec& start, size_t tag, int side, double radius, Tolerance tol);
  // A closed profile names its last element first; s2: where it meets the first.
  void open_closed(const Element& last, ElementId id, bool s2, size_t tag, int side, double radius, Tolerance tol);
  // The next element; s2: where it meets the one after it.
  void element(const Element& e, ElementId id, bool s2, size_t tag);
  void fillet(double r, size_t tag);
  void chamfer(double b, size_t tag);
  // A block that moves only axes outside the plane: after the moves before it.
  void hold(size_t tag);
  // G20: an open profile ends at a point, a closed one names its first element again.
  void close_at(const Vec& end, size_t tag);
  void close_with(ElementId first, size_t tag);

  bool active() const { return active_; }
  // No more pieces until the profile closes (a block of it failed elsewhere).
  void abandon() { failed_ = true; }
  bool failed() const { return active_ && failed_; }
  // The pieces ready to go, in order.
  std::vector<Piece> take() { return std::exchange(ready_, {}); }
  // The first problem, with the tag of its block; the profile then makes no more
  // pieces until it is closed.
  struct Problem {
    size_t tag = 0;
    std::string what;
    bool warning = false;  // the profile goes on
  };
  [[nodiscard]] std::optional<Problem> take_problem() { return std::exchange(problem_, std::nullopt); }

 private:
  struct Call {
    Element nominal, path;  // as defined, and as the tool's centre follows it
    ElementId id;
    bool s2 = false;
    size_t tag = 0;
    Vec entry_nominal{0, 0}, entry{0, 0};
  };
  // Where one element ends and the next begins, and the pieces between them.
  struct Junction {
    Vec exit_nominal{0, 0}, exit{0, 0}, entry_nominal{0, 0}, entry{0, 0};
    std::optional<Piece> between;
  };
  struct Connector {
    enum class Kind { None, Fillet, Chamfer } kind = Kind::None;
    double size = 0;
    size_t tag = 0;
    size_t queued = 0;  // the held blocks before it
  };

  bool fail(size_t tag, std::string what);
  [[nodiscard]] std::optional<Call> call(const Element& e, ElementId id, bool s2, size_t tag);
  [[nodiscard]] std::optional<Junction> join(const Call& a, const Call& b, const Connector& c);
  bool on(const Element& e, const Vec& p) const;
  Vec beside(const Element& e, const Vec& p) const { return p + side_ * radius_ * left(tangent(e, p)); }
  void move(const Call& c, const Vec& exit_nominal, const Vec& exit);
  void flush(size_t from, size_t to);
  void reset();

  bool active_ = false, failed_ = false, closed_ = false;
  int side_ = 0;
  double radius_ = 0;
  Tolerance tol_;
  size_t open_tag_ = 0;
  Vec start_{0, 0};
  std::optional<Call> last_;         // a closed profile's last element, as G21 names it
  std::optional<Junction> closing_;  // ... where it meets the first
  ElementId first_id_{Kind::Line, -1};
  std::optional<Call> current_;  // the element waiting for the next
  Connector connector_;
  std::vector<size_t> held_;  // blocks waiting for the current element's move
  std::vector<Piece> ready_;
  std::optional<Problem> problem_;
};

}  // namespace ncc::gtl
