#include "stickslip/systems/belt/model.hpp"

#include <cmath>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

Model::Model(const Params& p) : p_(p), friction_((Validate(p), p)), two_beta_(2.0 * p.beta) {}

Mat2 Model::Jacobian(Mode m, const Vec2& z) const {
  Mat2 J;
  if (m == Mode::kStick) {
    J.setZero();
    return J;
  }
  J << 0.0, 1.0, -1.0, -two_beta_ + SlipForceSlope(m, z[1]);
  return J;
}

bool Model::Assign(const System& s) {
  const auto* m = dynamic_cast<const Model*>(&s);
  if (m) *this = *m;
  return m != nullptr;
}

bool ParameterColumnSupported(LawKind law, const ParameterAxis& axis) {
  const Parameter p = axis.id();
  return !((p == Parameter::kVM && law == LawKind::kCubic) ||
           (p == Parameter::kVS && law == LawKind::kStribeck) ||
           (p == Parameter::kDelta && law == LawKind::kLeine));
}

ContactSensitivity BeltContactDerivative(const Params& p, int j) {
  ContactSensitivity d;
  if (j == static_cast<int>(Parameter::kV)) d.speed = 1, d.stick_force = 2 * p.beta;
  if (j == static_cast<int>(Parameter::kBeta)) d.stick_force = 2 * p.v;
  if (j == static_cast<int>(Parameter::kMuS)) d.static_limit = 1;
  return d;
}

bool Model::SupportsParameterColumn(const ParameterAxis& axis) const {
  return ParameterColumnSupported(p_.law, axis);
}

bool Model::SupportsParameterColumn(int j) const {
  return j >= 0 && j < parameters() &&
         SupportsParameterColumn(ParameterAxis(static_cast<Parameter>(j)));
}

int Model::parameters() const { return kBeltParameters; }

std::string Model::ParameterName(int j) const { return Name(static_cast<Parameter>(j)); }

std::string Model::ParameterError(int j) const {
  return AxisError(ParameterAxis(static_cast<Parameter>(j)), p_.law);
}

double Model::ParameterValue(int j) const {
  return ParameterAxis(static_cast<Parameter>(j)).Get(p_);
}

void Model::SetParameterValue(int j, double value) {
  ParameterAxis(static_cast<Parameter>(j)).Set(p_, value);
  friction_ = Friction(p_);
  two_beta_ = 2.0 * p_.beta;
}

Equilibrium Model::SteadySliding() const {
  Equilibrium e;
  e.x = friction_.Mu(p_.v);
  e.damping = two_beta_ + friction_.DMu(p_.v);
  const double b = e.damping, d = b * b - 4.0;
  if (d < 0) {  // complex pair: no cancellation
    const double im = 0.5 * std::sqrt(-d);
    e.lambda1 = {-0.5 * b, im};
    e.lambda2 = {-0.5 * b, -im};
    return e;
  }
  // Real roots of lambda^2 + b lambda + 1 = 0 in the stable form (Press et al.,
  // Numerical Recipes, eq. 5.6.4): q = -(b + sgn(b) sqrt(b^2 - 4)) / 2, roots q
  // and 1 / q. -b/2 + sqrt(...)/2 cancels to 0 for large b (v_m = 1e-6).
  // lambda1 is the larger.
  const double q = -0.5 * (b + std::copysign(std::sqrt(d), b));
  e.lambda1 = b > 0 ? 1.0 / q : q;
  e.lambda2 = b > 0 ? q : 1.0 / q;
  return e;
}

// The energy bound. With y = x - mu(v), w = x' and psi(s) = mu(s) + 2 beta s,
// seed eq. (3.5) gives for E = (y^2 + w^2) / 2 in each mode:
//   slip below, s = v - w > 0:  E' = -w (psi(v) - psi(s)),
//   slip above, u = w - v > 0:  E' = -w (mu(v) + 2 beta w + mu(u)),
//   stick, w = v:               E' = v y, and y <= mu_s - psi(v) there.
// If mu is convex and positive on s > 0, psi(v) > mu_s >= mu(0+) and
// psi'(v) = 2 beta + mu'(v) > 0, convexity gives psi(s) < psi(v) for s < v and
// psi(s) > psi(v) for s > v, so E' < 0 except at isolated instants (w = 0, off
// the equilibrium). E is continuous across switches, so it strictly decreases
// along every trajectory: no closed orbit, and by LaSalle's invariance
// principle (Khalil, Nonlinear Systems, 3rd ed., thm. 4.4) every trajectory
// tends to steady sliding. mu is convex and positive for every law but the
// cubic one with k5 > 0 (mu'' = 6 k3 s - 20 k5 s^3 turns negative). For the
// seed set the bound holds from v = sqrt((k1 - 2 beta) / k3) = 0.764 on.
bool Model::NoPeriodicOrbit() const {
  if (p_.law == LawKind::kCubic && p_.k5 != 0) return false;
  const double psi_v = friction_.Mu(p_.v) + two_beta_ * p_.v;
  const double damping = two_beta_ + friction_.DMu(p_.v);
  // Margins well above rounding: the bound is only used to skip searches.
  return psi_v - p_.mu_s > Tolerances::kNoOrbitMargin * psi_v &&
         damping > Tolerances::kNoOrbitMargin;
}

}  // namespace stickslip
