#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {

std::string ValidationError(const ForcedBeltParams& p) {
  if (!std::isfinite(p.force) || p.force < 0)
    return "force = " + Num(p.force, 12) + " must be a finite number >= 0";
  if (!std::isfinite(p.omega) || p.omega <= 0)
    return "omega = " + Num(p.omega, 12) + " must be a finite number > 0";
  // The range's text only on failure: this runs for every model a branch
  // step builds, where formatting it was 38 % of a forced run (callgrind).
  auto range = [] { return "[" + Num(kMinScale) + ", " + Num(kMaxScale) + "]"; };
  // Each blamed on its own name; a force below kMinScale (a denormal 4.9e-324
  // too) is no forcing the flow resolves: 0 or within the range.
  if (p.force != 0 && (p.force < kMinScale || p.force > kMaxScale))
    return "force = " + Num(p.force, 12) + " must be 0 or lie in " + range();
  if (p.omega < kMinScale || p.omega > kMaxScale)
    return "omega = " + Num(p.omega, 12) + " must lie in " + range();
  if (!(p.base.v >= 0)) return "v = " + Num(p.base.v, 12) + " must be >= 0";
  // The belt's checks, with v = 0 and (coulomb) mu_k = mu_s admitted here.
  Params q = p.base;
  if (q.v == 0) q.v = 1;
  if (q.law == LawKind::kCoulomb && q.mu_k == q.mu_s) q.mu_k = 0.5 * q.mu_s;
  return ValidationError(q);
}

namespace {
const ForcedBeltParams& Checked(const ForcedBeltParams& p) {
  const std::string e = ValidationError(p);
  if (!e.empty()) throw InvalidArgument(e);
  return p;
}
}  // namespace

ForcedBelt::ForcedBelt(const ForcedBeltParams& p)
    : p_(Checked(p)), friction_(p.base), two_beta_(2 * p.base.beta) {}

Mat2 ForcedBelt::Jacobian(Mode m, double /*t*/, const Vec2& z) const {
  Mat2 J = Mat2::Zero();
  if (m == Mode::kStick) return J;
  const double slope =
      m == Mode::kSlipBelow ? -friction_.DMu(v() - z[1]) : -friction_.DMu(z[1] - v());
  J << 0.0, 1.0, -1.0, -two_beta_ + slope;
  return J;
}

std::array<double, 2> ForcedBelt::SearchBox() const {
  const double w = omega(), b = beta();
  const double r = force() / std::max({std::abs(1 - w * w), 2 * b * w, 0.2}) + static_limit() + v();
  return {r, r * std::max(1.0, w)};
}

Mode ForcedBelt::ModeAfterArrival(Mode from, double t, double x) const {
  const double f = StickForce(t, x);
  if (std::abs(f) <= p_.base.mu_s) return Mode::kStick;
  (void)from;
  return f > 0 ? Mode::kSlipBelow : Mode::kSlipAbove;
}

Mat2 ForcedBelt::SaltationCrossing(Mode before, Mode after, double t, double x) const {
  // h = x' - v, grad h = (0, 1), dh/dt = 0: S = I + (f+ - f-) (0, 1) / a-.
  const Vec2 z(x, v());
  const Vec2 df = Field(after, t, z) - Field(before, t, z);
  Mat2 S = Mat2::Identity();
  S.col(1) += df / Field(before, t, z)[1];
  return S;
}

Mat2 ForcedBelt::SaltationStickOut(Mode after, double t, double x) const {
  // h = StickForce(t, x) -+ mu_s, grad h = (1, 0), grad h . f_stick + dh/dt = StickForceRate.
  const Vec2 z(x, v());
  const Vec2 df = Field(after, t, z) - Field(Mode::kStick, t, z);
  Mat2 S = Mat2::Identity();
  S.col(0) += df / StickForceRate(t);
  return S;
}

}  // namespace stickslip

// --- The system interface: state (x, x', theta), theta' = Omega ---
namespace stickslip {

bool ForcedBelt::Assign(const System& s) {
  const auto* m = dynamic_cast<const ForcedBelt*>(&s);
  if (m) *this = *m;
  return m != nullptr;
}

std::string ForcedBelt::StateName(int i) const { return i == 0 ? "x" : i == 1 ? "x'" : "theta"; }

ContactVelocity ForcedBelt::Contact(int) const {
  ContactVelocity c;
  c.terms[0] = {1, 1.0};
  c.size = 1;
  c.speed = v();
  return c;
}

double ForcedBelt::StickForce(const ModeSet&, int, ConstState z) const {
  return z[0] + two_beta_ * v() - p_.force * std::cos(z[2]);
}

void ForcedBelt::StickForceGradient(const ModeSet&, int, ConstState z, StateOut g) const {
  g << 1.0, 0.0, p_.force * std::sin(z[2]);
}

void ForcedBelt::ProjectOnExit(const ModeSet&, int, double bound, StateOut z) const {
  z[0] = bound - two_beta_ * v() + p_.force * std::cos(z[2]);
}

void ForcedBelt::Field(const ModeSet& m, ConstState z, StateOut f) const {
  if (m[0] == Mode::kStick) {
    f << v(), 0.0, p_.omega;
    return;
  }
  f << z[1], -z[0] - two_beta_ * z[1] + SlipForce(m[0], z[1]) + p_.force * std::cos(z[2]), p_.omega;
}

void ForcedBelt::Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const {
  J = Jacobian(m[0], 0.0, Vec2(z[0], z[1]));
}

bool ForcedBelt::Rest(const ModeSet& m, StateOut z, bool* stable) const {
  if (p_.force != 0 || m[0] != Mode::kSlipBelow || !(v() > 0)) return false;
  z << friction_.Mu(v()), 0.0, 0.0;  // steady sliding, as Model::SteadySliding
  *stable = two_beta_ + friction_.DMu(v()) > 0;
  return true;
}

bool ForcedBelt::SupportsParameterColumn(int j) const {
  if (j == kForceIndex || j == kOmegaIndex) return true;
  return j >= 0 && j < kForceIndex &&
         ParameterColumnSupported(p_.base.law, ParameterAxis(static_cast<Parameter>(j)));
}

ContactSensitivity ForcedBelt::ContactParameterDerivative(const ModeSet&, int, int j,
                                                          ConstState z) const {
  if (j == kForceIndex) return {0, -std::cos(z[2]), 0};
  return j < kForceIndex ? BeltContactDerivative(p_.base, j) : ContactSensitivity{};
}

int ForcedBelt::parameters() const { return kOmegaIndex + 1; }

std::string ForcedBelt::ParameterName(int j) const { return Name(static_cast<Parameter>(j)); }

std::string ForcedBelt::ParameterError(int j) const {
  return AxisError(ParameterAxis(static_cast<Parameter>(j)), p_.base.law, true);
}

double ForcedBelt::ParameterValue(int j) const {
  return ParameterAxis(static_cast<Parameter>(j)).Get(p_);
}

void ForcedBelt::SetParameterValue(int j, double value) {
  const ParameterAxis axis(static_cast<Parameter>(j));
  axis.Set(p_, value);
  if (axis.forcing()) return;
  friction_ = Friction(p_.base);
  two_beta_ = 2 * p_.base.beta;
}

}  // namespace stickslip
