// The system interface's own parts (system.hpp, mode.hpp): names, parameter
// lookup and the generic projection onto a stick exit.
#include "stickslip/system/system.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "numerics/numbers.hpp"

namespace stickslip {

std::string ModeSetName(const ModeSet& m, int contacts) {
  if (contacts <= 1) return Name(m[0]);
  std::string s;
  for (int i = 0; i < contacts; ++i) {
    if (i) s += ',';
    s += Name(m[i]);
  }
  return s;
}

int System::ParameterIndex(const std::string& name) const {
  for (int j = 0; j < parameters(); ++j)
    if (ParameterName(j) == name) return j;
  return -1;
}

std::string ContactVelocityError(const System& s) {
  const int tangent = s.dimension() - s.clocks();
  for (int c = 0; c < s.contacts(); ++c) {
    const ContactVelocity h = s.Contact(c);
    // The name only on failure: this runs for each system a flow is given.
    auto name = [c] { return "contact " + std::to_string(c) + "'s velocity"; };
    if (h.size < 1 || h.size > ContactVelocity::kMaxTerms)
      return name() + " has " + std::to_string(h.size) + " terms, not 1 to " +
             std::to_string(ContactVelocity::kMaxTerms);
    for (int t = 0; t < h.size; ++t)
      if (h.terms[t].index < 0 || h.terms[t].index >= tangent ||
          !(std::isfinite(h.terms[t].weight) && h.terms[t].weight != 0))
        return name() + "'s term " + std::to_string(t) + " (component " +
               std::to_string(h.terms[t].index) + ", weight " + Num(h.terms[t].weight) +
               ") must be a state component with a finite nonzero weight";
  }
  return "";
}

// One Newton step on r(z) = lambda_i(z) - bound along the gradient of r,
// restricted to the components no sticking contact's velocity reads and no
// clock: exact where lambda is linear in them (a spring force).
void System::ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const {
  const int n = dimension(), nt = tangent_dimension();
  std::vector<bool> free(n, false);
  for (int j = 0; j < nt; ++j) free[j] = true;
  for (int c = 0; c < contacts(); ++c) {
    if (!m.sticks(c)) continue;
    const ContactVelocity v = Contact(c);
    for (int t = 0; t < v.size; ++t) free[v.terms[t].index] = false;
  }
  Eigen::VectorXd g(n), gl(n);
  StickForceGradient(m, i, z, g);
  for (int j = 0; j < n; ++j)
    if (!free[j]) g[j] = 0;
  const double norm2 = g.squaredNorm();
  if (!(norm2 > 0)) return;
  const double r = StickForce(m, i, z) - bound;
  z -= (r / norm2) * g;
}

}  // namespace stickslip
