// The mode-coupling model's fields, contact and parameters (mode_coupling.hpp).
#include "mode_coupling/mode_coupling.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "stickslip/errors.hpp"

namespace stickslip::mode_coupling {

double FlutterMuK(const CouplingParams& p) {
  if (!(p.gamma * p.k12 < 0)) return std::numeric_limits<double>::quiet_NaN();
  const double d = (p.k11 - p.k22) * (p.k11 - p.k22) + 4 * p.k12 * p.k12;
  return -(d + 8 * p.beta * p.beta * (p.k11 + p.k22)) / (4 * p.gamma * p.k12);
}

ModeCoupling::ModeCoupling(const CouplingParams& p) : p_(p), friction_(p.law) {
  const std::string e = ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
}

bool ModeCoupling::Assign(const System& s) {
  const auto* o = dynamic_cast<const ModeCoupling*>(&s);
  if (o) *this = *o;
  return o != nullptr;
}

std::string ModeCoupling::ValidationError() const {
  const char* names[] = {"beta", "k11", "k22", "k12", "gamma", "v"};
  const double values[] = {p_.beta, p_.k11, p_.k22, p_.k12, p_.gamma, p_.v};
  for (int j = 0; j < 6; ++j)
    if (!std::isfinite(values[j]))
      return std::string("mode_coupling: ") + names[j] + " must be finite";
  if (!(p_.beta >= 0)) return "mode_coupling: beta = " + std::to_string(p_.beta) + " must be >= 0";
  if (!(p_.v > 0)) return "mode_coupling: v = " + std::to_string(p_.v) + " must be > 0";
  if (!(p_.gamma >= 0))
    return "mode_coupling: gamma = " + std::to_string(p_.gamma) + " must be >= 0";
  Params law = p_.law;
  law.v = p_.v;
  law.beta = p_.beta;
  const std::string e = stickslip::ValidationError(law);
  return e.empty() ? "" : "mode_coupling: " + e;
}

std::string ModeCoupling::StateName(int i) const {
  static const char* n[] = {"x", "x'", "y", "y'"};
  return n[i];
}

ContactVelocity ModeCoupling::Contact(int) const {
  ContactVelocity c;
  c.terms[0] = {1, 1.0};
  c.size = 1;
  c.speed = p_.v;
  return c;
}

std::optional<ContactVelocity> ModeCoupling::NormalForce(int) const {
  if (p_.gamma == 0) return std::nullopt;
  ContactVelocity n;  // -gamma y - (-1)
  n.terms[0] = {2, -p_.gamma};
  n.size = 1;
  n.speed = -1;
  return n;
}

void ModeCoupling::StickForceGradient(const ModeSet&, int, ConstState, StateOut g) const {
  g.setZero();
  g[0] = p_.k11;
  g[2] = p_.k12;
}

void ModeCoupling::StaticLimitGradient(int, ConstState, StateOut g) const {
  g.setZero();
  g[2] = -p_.law.mu_s * p_.gamma;
}

void ModeCoupling::ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const {
  if (p_.k11 == 0) return System::ProjectOnExit(m, i, bound, z);
  z[0] += (bound - StickForce(m, i, z)) / p_.k11;
}

double ModeCoupling::SlipForce(Mode m, double xd) const {
  return m == Mode::kSlipBelow ? friction_.Mu(p_.v - xd) : -friction_.Mu(xd - p_.v);
}

double ModeCoupling::SlipForceSlope(Mode m, double xd) const {
  return m == Mode::kSlipBelow ? -friction_.DMu(p_.v - xd) : -friction_.DMu(xd - p_.v);
}

void ModeCoupling::Field(const ModeSet& m, ConstState z, StateOut f) const {
  const double tb = 2 * p_.beta;
  if (m.sticks(0)) {
    f[0] = p_.v, f[1] = 0;
  } else {
    f[0] = z[1];
    f[1] =
        -tb * z[1] - p_.k11 * z[0] - p_.k12 * z[2] + (1 - p_.gamma * z[2]) * SlipForce(m[0], z[1]);
  }
  f[2] = z[3];
  f[3] = -tb * z[3] - p_.k12 * z[0] - p_.k22 * z[2];
}

void ModeCoupling::Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const {
  const double tb = 2 * p_.beta;
  J.setZero();
  if (!m.sticks(0)) {
    J(0, 1) = 1;
    J(1, 0) = -p_.k11;
    J(1, 1) = -tb + (1 - p_.gamma * z[2]) * SlipForceSlope(m[0], z[1]);
    J(1, 2) = -p_.k12 - p_.gamma * SlipForce(m[0], z[1]);
  }
  J(2, 3) = 1;
  J(3, 0) = -p_.k12;
  J(3, 2) = -p_.k22;
  J(3, 3) = -tb;
}

bool ModeCoupling::Rest(const ModeSet& m, StateOut z, bool* stable) const {
  if (m[0] != Mode::kSlipBelow) return false;
  const double mu = friction_.Mu(p_.v);
  Eigen::Matrix2d K;
  K << p_.k11, p_.k12 + p_.gamma * mu, p_.k12, p_.k22;
  if (!(std::abs(K.determinant()) > 0)) return false;
  const Eigen::Vector2d xy = K.inverse() * Eigen::Vector2d(mu, 0);
  z << xy[0], 0, xy[1], 0;
  Eigen::Matrix4d J;
  Jacobian(m, z, J);
  const Eigen::EigenSolver<Eigen::Matrix4d> es(J, false);
  *stable = es.eigenvalues().real().maxCoeff() < 0;
  return true;
}

std::string ModeCoupling::ParameterName(int j) const {
  static const char* n[] = {"beta", "k11", "k22", "k12", "gamma", "v", "mu_s", "mu_k"};
  return n[j];
}

double* ModeCoupling::Member(int j) {
  double* m[] = {&p_.beta, &p_.k11, &p_.k22, &p_.k12, &p_.gamma, &p_.v, &p_.law.mu_s, &p_.law.mu_k};
  return m[j];
}

double ModeCoupling::ParameterValue(int j) const {
  return *const_cast<ModeCoupling*>(this)->Member(j);
}

void ModeCoupling::SetParameterValue(int j, double value) {
  *Member(j) = value;
  friction_ = Friction(p_.law);
}

}  // namespace stickslip::mode_coupling
