// The consistent mode of contacts that switch at one instant (switching.hpp;
// docs/theory.md, "Modes as sets"): enumerate stick, slip-below and
// slip-above for each, keep the candidates whose sticking contacts hold
// within their static limits and whose slipping ones could not (Filippov's
// rule contact by contact, all at once; the enumeration Acary & Brogliato
// 2008, ch. 12, describe before the relay/LCP form), and beyond a few
// contacts least-index pivoting on the same conditions (PivotedMode).
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>

#include "flow/engine.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/flow.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {

namespace {
// The mode the side of lambda gives a released contact.
Mode Released(double lambda) { return lambda > 0 ? Mode::kSlipBelow : Mode::kSlipAbove; }

// Whether contact i's mode in m is consistent at z.
bool Consistent(const System& s, const ModeSet& m, int i, ConstState z) {
  const double limit = s.StaticLimit(i, z);
  if (m.sticks(i)) return std::abs(s.StickForce(m, i, z)) <= limit;
  ModeSet held = m;
  held.set(i, Mode::kStick);
  const double lambda = s.StickForce(held, i, z);
  return std::abs(lambda) > limit && Released(lambda) == m[i];
}

// The contact-order rule: each contact of `on` in turn, the others as set.
ModeSet ContactOrder(const System& s, ModeSet m, const std::vector<int>& on, ConstState z) {
  for (int i : on) {
    ModeSet stick = m;
    stick.set(i, Mode::kStick);
    const double lambda = s.StickForce(stick, i, z);
    m = std::abs(lambda) <= s.StaticLimit(i, z) ? stick : m;
    if (!m.sticks(i)) m.set(i, Released(lambda));
  }
  return m;
}

// Every candidate over `on` (3^|on|, in base 3): how many are consistent,
// the first of them in *first.
int Enumerate(const System& s, const ModeSet& base, const std::vector<int>& on, ConstState z,
              ModeSet* first) {
  static constexpr Mode kModes[] = {Mode::kStick, Mode::kSlipBelow, Mode::kSlipAbove};
  const int q = static_cast<int>(on.size());
  long total = 1;
  for (int j = 0; j < q; ++j) total *= 3;
  int found = 0;
  ModeSet m = base;
  for (long code = 0; code < total; ++code) {
    long c = code;
    for (int j = 0; j < q; ++j, c /= 3) m.set(on[j], kModes[c % 3]);
    bool ok = true;
    for (int j = 0; ok && j < q; ++j) ok = Consistent(s, m, on[j], z);
    if (!ok) continue;
    if (found++ == 0) *first = m;
  }
  return found;
}

// The mode a contact of `on` that is not consistent in m takes: stuck past
// its limit it slips the way lambda points; slipping, it sticks where held
// within its limit, else slips the way the held force points.
Mode Flipped(const System& s, const ModeSet& m, int j, ConstState z) {
  if (m.sticks(j)) return Released(s.StickForce(m, j, z));
  ModeSet held = m;
  held.set(j, Mode::kStick);
  const double lambda = s.StickForce(held, j, z);
  return std::abs(lambda) <= s.StaticLimit(j, z) ? Mode::kStick : Released(lambda);
}
}  // namespace

ModeChoiceResult PivotedMode(const System& s, const ModeSet& base, const std::vector<int>& on,
                             ConstState z) {
  ModeChoiceResult r;
  r.candidates = static_cast<int>(on.size());
  r.mode = base;
  for (int c : on) r.mode.set(c, Mode::kStick);
  const long q = r.candidates, cap = 3 * q * q + 3;
  std::unordered_set<std::string> seen;
  std::string key(on.size(), ' ');
  for (long flips = 0; flips <= cap; ++flips) {
    const auto bad =
        std::find_if(on.begin(), on.end(), [&](int c) { return !Consistent(s, r.mode, c, z); });
    if (bad == on.end()) {
      r.choice = ModeChoice::kPivoted;
      r.consistent = 1;
      return r;
    }
    for (size_t k = 0; k < on.size(); ++k) key[k] = static_cast<char>(r.mode[on[k]]);
    if (!seen.insert(key).second) break;  // a cycle
    r.mode.set(*bad, Flipped(s, r.mode, *bad, z));
  }
  r.choice = ModeChoice::kTooMany;
  return r;
}

ModeChoiceResult ConsistentMode(const System& s, const ModeSet& base, std::vector<int> on,
                                ConstState z) {
  ModeChoiceResult r;
  std::sort(on.begin(), on.end());
  on.erase(std::unique(on.begin(), on.end()), on.end());
  bool pivoted = false;
  for (;;) {
    const int q = static_cast<int>(on.size());
    pivoted = false;
    if (q > kMaxEnumeratedContacts) {  // pivoting; where it cycles, enumeration up to 12
      r = PivotedMode(s, base, on, z);
      pivoted = r.choice == ModeChoice::kPivoted;
      if (!pivoted && q > kMaxEnumeratedAfterCycle) {
        r.mode = ContactOrder(s, base, on, z);
        return r;
      }
    }
    if (!pivoted) {
      r.candidates = q;
      r.consistent = Enumerate(s, base, on, z, &r.mode);
    }
    if (r.consistent != 1) {
      r.choice = r.consistent == 0 ? ModeChoice::kInconsistent : ModeChoice::kAmbiguous;
      r.mode = ContactOrder(s, base, on, z);
      return r;
    }
    // A sticking contact the new mode pushes past its limit joins them.
    bool grew = false;
    for (int c = 0; c < s.contacts(); ++c) {
      if (!r.mode.sticks(c) || std::binary_search(on.begin(), on.end(), c)) continue;
      if (Consistent(s, r.mode, c, z)) continue;
      on.insert(std::upper_bound(on.begin(), on.end(), c), c);
      grew = true;
    }
    if (!grew) break;
  }
  r.choice = pivoted ? ModeChoice::kPivoted : ModeChoice::kUnique;
  return r;
}

ModeChoiceResult ModeChoiceOf(const System& s, const Eigen::VectorXd& z) {
  ModeSet base;
  std::vector<int> on;
  for (int i = 0; i < s.contacts(); ++i) {
    const double h = s.Contact(i).At(z.data());
    if (h > 0) base.set(i, Mode::kSlipAbove);
    if (h == 0) on.push_back(i);
  }
  if (on.empty()) {
    ModeChoiceResult r;
    r.mode = base;
    return r;
  }
  return ConsistentMode(s, base, on, z);
}

ModeSet ModeOf(const System& s, const Eigen::VectorXd& z) { return ModeChoiceOf(s, z).mode; }

namespace {
// Whether sticking contact i is not inside its static limit by the start's
// slack (at the edge, or NaN), with its stick force.
bool AtEdge(const System& s, const ModeSet& m, int i, ConstState z, double* lambda) {
  *lambda = s.StickForce(m, i, z);
  const double limit = s.StaticLimit(i, z);
  return !(std::abs(*lambda) < limit - Tolerances::StickStart(s.Contact(i).speed, limit));
}

// ReleasedAtEdge from the first sticking contact at its edge on (out of
// line: every flow's start runs ReleasedAtEdge, and most start in slip).
[[gnu::noinline]] ModeSet ReleaseFrom(const System& s, ModeSet m, ConstState z, int first) {
  const int n = s.dimension();
  Eigen::VectorXd f(n), g(n), gl(n);
  const ModeSet held = m;  // every contact's edge judged in the start's own field
  s.Field(held, z, f);
  for (int i = first; i < s.contacts(); ++i) {
    double lambda;
    if (!held.sticks(i) || !AtEdge(s, held, i, z, &lambda)) continue;
    s.StickForceGradient(held, i, z, g);
    s.StaticLimitGradient(i, z, gl);
    if ((lambda > 0 ? 1 : -1) * g.dot(f) - gl.dot(f) > 0) m.set(i, Released(lambda));
  }
  return m;
}
}  // namespace

ModeSet ReleasedAtEdge(const System& s, ModeSet m, ConstState z) {
  double lambda;
  for (int i = 0; i < s.contacts(); ++i)
    if (m.sticks(i) && AtEdge(s, m, i, z, &lambda)) return ReleaseFrom(s, m, z, i);
  return m;
}

namespace flow_detail {

void CheckStart(const System& s, const FlowPoint& p) {
  for (int i = 0; i < s.contacts(); ++i) {
    if (!p.mode.sticks(i)) continue;
    const ContactVelocity c = s.Contact(i);
    const double h = c.At(p.z.data()), lambda = s.StickForce(p.mode, i, p.z);
    const double limit = s.StaticLimit(i, p.z);
    const double slack = Tolerances::StickStart(c.speed, limit);
    if (!(std::abs(h) <= slack) || !(std::abs(lambda) <= limit + slack))
      throw InvalidArgument("Flow::Run: stick mode requested off the stick set (contact " +
                            std::to_string(i) + ")");
  }
}

}  // namespace flow_detail
}  // namespace stickslip
