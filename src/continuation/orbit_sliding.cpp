// The sliding bifurcations of an orbit branch (special_kind.hpp): GR, AD and
// CR read off the change of the switching counts across a located change of
// the sequence and the switches of one period on either side, the
// classification of di Bernardo, Kowalczyk & Nordmark (Physica D 170, 2002,
// section 3) as Kowalczyk & Piiroinen (Physica D 237, 2008) find it in a
// forced dry-friction oscillator.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "numerics/tolerances.hpp"
#include "orbit_locate.hpp"

namespace stickslip::orbit_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// How close an arrival on a contact's surface (a crossing, or a stick entry)
// comes to its static limit: min | |lambda_i| - mu_s N_i | over the arrivals
// (inf: none). Crossing-sliding is an arrival at the limit, from either side.
double ArrivalToLimit(const System& s, const std::vector<FlowSwitch>& sw) {
  double best = kInf;
  for (const FlowSwitch& e : sw) {
    if (e.kind != SwitchKind::kCrossing && e.kind != SwitchKind::kStickIn) continue;
    ModeSet m = e.before;
    m.set(e.contact, Mode::kStick);
    best = std::min(
        best, std::abs(std::abs(s.StickForce(m, e.contact, e.z)) - s.StaticLimit(e.contact, e.z)));
  }
  return best;
}

// The shortest slip of a contact from its stick exit to its next stick entry
// (touches aside) over one period (the switches wrap around it).
double ShortestSlipBetweenSticks(const std::vector<FlowSwitch>& sw, double period) {
  double best = kInf;
  const std::size_t n = sw.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (sw[i].kind != SwitchKind::kStickOut) continue;
    for (std::size_t k = 1; k <= n; ++k) {
      const FlowSwitch& e = sw[(i + k) % n];
      if (e.contact != sw[i].contact || e.kind == SwitchKind::kTouch) continue;
      if (e.kind == SwitchKind::kStickIn)
        best = std::min(best, e.t - sw[i].t + (i + k >= n ? period : 0));
      break;
    }
  }
  return best;
}

// The largest extent of the orbit's displacements (tangent components no
// other one is the rate of: x, not x').
double Width(const System& s, const OrbitRow& r) {
  const std::vector<bool> displacement = Displacements(s);
  double w = 0;
  for (int i = 0; i < static_cast<int>(displacement.size()) && i < r.lo.size() && i < r.hi.size();
       ++i)
    if (displacement[i]) w = std::max(w, r.hi[i] - r.lo[i]);
  return w;
}

const char* Crossing(int ds, int dc) {
  return ds > 0   ? "a crossing of the contact's surface reaches its static limit and becomes a "
                    "stick phase"
         : ds < 0 ? "a stick phase shrinks to a crossing at the static limit"
         : dc < 0 ? "a crossing of the contact's surface reaches its static limit and is lost"
                  : "a crossing of the contact's surface is born at its static limit";
}

}  // namespace

bool ClassifySliding(OrbitProblem& problem, const OrbitRow& before, const OrbitRow& after,
                     OrbitRow* point) {
  const int ds = after.sticks - before.sticks, dc = after.crossings - before.crossings;
  const std::string change = SequenceChange(before, after);
  point->label = SpecialKind::kSliding;
  point->description = "the switching sequence changes" + change;
  const Tolerances tol = Tolerances::From(problem.shooting().options().flow.rtol,
                                          problem.shooting().options().flow.atol);
  std::vector<FlowSwitch> sb, sa;
  const System* s = problem.Switches(before, &sb);
  if (!s) return false;  // unclassified: the system is invalid there
  const double near = ArrivalToLimit(*s, sb);
  const double width = Width(*s, before);
  s = problem.Switches(after, &sa);
  if (!s) return false;
  const double far = ArrivalToLimit(*s, sa);
  // A crossing is born or lost only where an arrival passes the static limit,
  // never by a tangency (outside the limit the surface is crossed
  // transversally: docs/theory.md, "Why no SW").
  const bool at_limit = std::min(near, far) <= tol.BandEdge() * (1 + width);
  if ((ds != 0 && dc == -ds) || (dc != 0 && (at_limit || ds == 0))) {
    point->label = SpecialKind::kCrossing;
    point->description = std::string("crossing-sliding: ") + Crossing(ds, dc) + change;
  } else if (ds != 0 && dc == 0) {
    // Adding-sliding leaves a vanishing slip between two sticks; grazing a
    // stick phase born from a tangency.
    const OrbitRow& more = ds > 0 ? after : before;
    const double slip = ShortestSlipBetweenSticks(ds > 0 ? sa : sb, more.period);
    if (slip <= tol.VanishingPhase() * more.period) {
      point->label = SpecialKind::kAdding;
      point->description = std::string("adding-sliding: ") +
                           (ds > 0 ? "a stick phase splits around a short slip"
                                   : "two stick phases merge as the slip between them vanishes") +
                           change;
    } else {
      point->label = SpecialKind::kGrazing;
      point->description =
          std::string(
              "grazing-sliding: a slip phase touches the contact's surface tangentially "
              "within its static limit, ") +
          (ds > 0 ? "a stick phase is born" : "a stick phase vanishes") + change;
    }
  }
  return true;
}

}  // namespace stickslip::orbit_detail
