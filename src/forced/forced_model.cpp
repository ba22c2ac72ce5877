#include <cmath>

#include "stickslip/errors.hpp"
#include "stickslip/model/forced.hpp"
#include "numerics/numbers.hpp"

namespace stickslip {

std::string ValidationError(const ForcedParams& p) {
  if (!std::isfinite(p.force) || p.force < 0)
    return "force = " + Num(p.force, 12) + " must be a finite number >= 0";
  if (!std::isfinite(p.omega) || p.omega <= 0)
    return "omega = " + Num(p.omega, 12) + " must be a finite number > 0";
  if (p.force > kMaxScale || (p.omega != 0 && (p.omega < kMinScale || p.omega > kMaxScale)))
    return "force or omega is outside [" + Num(kMinScale) + ", " + Num(kMaxScale) + "]";
  if (!(p.base.v >= 0)) return "v = " + Num(p.base.v, 12) + " must be >= 0";
  // The belt's checks, with v = 0 and (coulomb) mu_k = mu_s admitted here.
  Params q = p.base;
  if (q.v == 0) q.v = 1;
  if (q.law == LawKind::kCoulomb && q.mu_k == q.mu_s) q.mu_k = 0.5 * q.mu_s;
  return ValidationError(q);
}

namespace {
const ForcedParams& Checked(const ForcedParams& p) {
  const std::string e = ValidationError(p);
  if (!e.empty()) throw InvalidArgument(e);
  return p;
}
}  // namespace

ForcedModel::ForcedModel(const ForcedParams& p)
    : p_(Checked(p)), friction_(p.base), two_beta_(2 * p.base.beta) {}

Mat2 ForcedModel::Jacobian(Mode m, double /*t*/, const Vec2& z) const {
  Mat2 J = Mat2::Zero();
  if (m == Mode::kStick) return J;
  const double slope =
      m == Mode::kSlipBelow ? -friction_.DMu(v() - z[1]) : -friction_.DMu(z[1] - v());
  J << 0.0, 1.0, -1.0, -two_beta_ + slope;
  return J;
}

Mode ForcedModel::ModeAfterArrival(Mode from, double t, double x) const {
  const double f = StickForce(t, x);
  if (std::abs(f) <= p_.base.mu_s) return Mode::kStick;
  (void)from;
  return f > 0 ? Mode::kSlipBelow : Mode::kSlipAbove;
}

Mat2 ForcedModel::SaltationCrossing(Mode before, Mode after, double t, double x) const {
  // h = x' - v, grad h = (0, 1), dh/dt = 0: S = I + (f+ - f-) (0, 1) / a-.
  const Vec2 z(x, v());
  const Vec2 df = Field(after, t, z) - Field(before, t, z);
  Mat2 S = Mat2::Identity();
  S.col(1) += df / Field(before, t, z)[1];
  return S;
}

Mat2 ForcedModel::SaltationStickOut(Mode after, double t, double x) const {
  // h = StickForce(t, x) -+ mu_s, grad h = (1, 0), grad h . f_stick + dh/dt = StickForceRate.
  const Vec2 z(x, v());
  const Vec2 df = Field(after, t, z) - Field(Mode::kStick, t, z);
  Mat2 S = Mat2::Identity();
  S.col(0) += df / StickForceRate(t);
  return S;
}

}  // namespace stickslip
