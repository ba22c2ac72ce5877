// The chain's fields, contacts and parameters (chain.hpp); its Taylor
// recurrences are chain_taylor.cpp.
#include "chain/chain.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "stickslip/errors.hpp"

namespace stickslip::chain {

ChainParams Uniform(int n, const Params& p, double kc) {
  ChainParams c;
  c.v = p.v;
  c.kc = kc;
  Block b;
  b.m = 1;
  b.c = 2 * p.beta;
  b.k = 1;
  b.law = p;
  c.blocks.assign(n > 0 ? n : 0, b);
  return c;
}

Chain::Chain(const ChainParams& p) : p_(p) {
  const std::string e = ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  Rebuild();
}

void Chain::Rebuild() {
  friction_.clear();
  for (const Block& b : p_.blocks) friction_.emplace_back(b.law);
}

bool Chain::Assign(const System& s) {
  const auto* o = dynamic_cast<const Chain*>(&s);
  if (!o) return false;
  const bool same = o->blocks() == blocks();
  p_ = o->p_;
  if (same) {
    for (int i = 0; i < blocks(); ++i) friction_[i] = o->friction_[i];
  } else {
    friction_ = o->friction_;
  }
  return true;
}

std::string Chain::ValidationError() const {
  const int n = blocks();
  if (n < 1 || n > ModeSet::kMaxContacts)
    return "chain: blocks = " + std::to_string(n) + " must lie in [1, " +
           std::to_string(ModeSet::kMaxContacts) + "]";
  if (!(p_.v > 0 && std::isfinite(p_.v)))
    return "chain: v = " + std::to_string(p_.v) + " must be > 0";
  if (!(p_.kc >= 0 && std::isfinite(p_.kc)))
    return "chain: kc = " + std::to_string(p_.kc) + " must be >= 0";
  for (int i = 0; i < n; ++i) {
    const Block& b = p_.blocks[i];
    const std::string at = "chain: block " + std::to_string(i + 1) + ": ";
    if (!(b.m > 0 && std::isfinite(b.m))) return at + "m = " + std::to_string(b.m) + " must be > 0";
    if (!(b.c >= 0 && std::isfinite(b.c)))
      return at + "c = " + std::to_string(b.c) + " must be >= 0";
    if (!(b.k >= 0 && std::isfinite(b.k)))
      return at + "k = " + std::to_string(b.k) + " must be >= 0";
    Params law = b.law;  // the law's own checks, at the chain's speed
    law.v = p_.v;
    law.beta = b.c / 2;
    const std::string e = stickslip::ValidationError(law);
    if (!e.empty()) return at + e;
  }
  return "";
}

std::string Chain::StateName(int i) const {
  return "x" + std::to_string(i / 2 + 1) + (i % 2 ? "'" : "");
}

double Chain::Spring(int i, const double* z) const {
  const Block& b = p_.blocks[i];
  double f = b.k * z[2 * i];
  if (i > 0) f += p_.kc * (z[2 * i] - z[2 * i - 2]);
  if (i + 1 < blocks()) f += p_.kc * (z[2 * i] - z[2 * i + 2]);
  return f;
}

ContactVelocity Chain::Contact(int i) const {
  ContactVelocity c;
  c.terms[0] = {2 * i + 1, 1.0};
  c.size = 1;
  c.speed = p_.v;
  return c;
}

void Chain::StickForceGradient(const ModeSet&, int i, ConstState, StateOut g) const {
  g.setZero();
  g[2 * i] = Stiffness(i);
  if (i > 0) g[2 * i - 2] = -p_.kc;
  if (i + 1 < blocks()) g[2 * i + 2] = -p_.kc;
}

void Chain::ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const {
  const double k = Stiffness(i);
  if (!(k > 0)) return System::ProjectOnExit(m, i, bound, z);
  z[2 * i] += (bound - HoldingForce(i, z.data())) / k;
}

double Chain::SlipForce(int i, Mode m, double xd) const {
  const Friction& f = friction_[i];
  return m == Mode::kSlipBelow ? f.Mu(p_.v - xd) : -f.Mu(xd - p_.v);
}

double Chain::SlipForceSlope(int i, Mode m, double xd) const {
  const Friction& f = friction_[i];
  return m == Mode::kSlipBelow ? -f.DMu(p_.v - xd) : -f.DMu(xd - p_.v);
}

void Chain::Field(const ModeSet& m, ConstState z, StateOut f) const {
  for (int i = 0; i < blocks(); ++i) {
    if (m.sticks(i)) {
      f[2 * i] = p_.v;
      f[2 * i + 1] = 0;
      continue;
    }
    const Block& b = p_.blocks[i];
    const double xd = z[2 * i + 1];
    f[2 * i] = xd;
    f[2 * i + 1] = (-b.c * xd - Spring(i, z.data()) + SlipForce(i, m[i], xd)) / b.m;
  }
}

void Chain::Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const {
  J.setZero();
  for (int i = 0; i < blocks(); ++i) {
    if (m.sticks(i)) continue;
    const Block& b = p_.blocks[i];
    J(2 * i, 2 * i + 1) = 1;
    J(2 * i + 1, 2 * i) = -Stiffness(i) / b.m;
    if (i > 0) J(2 * i + 1, 2 * i - 2) = p_.kc / b.m;
    if (i + 1 < blocks()) J(2 * i + 1, 2 * i + 2) = p_.kc / b.m;
    J(2 * i + 1, 2 * i + 1) = (-b.c + SlipForceSlope(i, m[i], z[2 * i + 1])) / b.m;
  }
}

bool Chain::RestPositions(double* x) const {
  const int n = blocks();
  std::vector<double> cp(n);  // the eliminated super-diagonal
  double prev = 0;
  for (int i = 0; i < n; ++i) {
    const double lower = i > 0 ? -p_.kc : 0.0;
    const double den = Stiffness(i) - lower * (i > 0 ? cp[i - 1] : 0.0);
    if (!(std::abs(den) > 0)) return false;
    cp[i] = (i + 1 < n ? -p_.kc : 0.0) / den;
    x[i] = (friction_[i].Mu(p_.v) - lower * prev) / den;
    prev = x[i];
  }
  for (int i = n - 2; i >= 0; --i) x[i] -= cp[i] * x[i + 1];
  return true;
}

bool Chain::Rest(const ModeSet& m, StateOut z, bool* stable) const {
  const int n = blocks();
  for (int i = 0; i < n; ++i)
    if (m[i] != Mode::kSlipBelow) return false;
  std::vector<double> x(n);
  if (!RestPositions(x.data())) return false;
  for (int i = 0; i < n; ++i) z[2 * i] = x[i], z[2 * i + 1] = 0;
  Eigen::MatrixXd J(2 * n, 2 * n);
  Jacobian(m, z, J);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, false);
  *stable = es.eigenvalues().real().maxCoeff() < 0;
  return true;
}

std::string Chain::ParameterName(int j) const {
  static const char* kGlobal[] = {"v", "kc", "beta"};
  static const char* kBlock[] = {"m", "c", "k", "mu_s"};
  if (j < 3) return kGlobal[j];
  return std::string(kBlock[(j - 3) % 4]) + std::to_string((j - 3) / 4 + 1);
}

std::string Chain::ParameterError(int j) const {
  if (j == 1 && blocks() == 1) return "'kc' does not apply to a chain of one block (no coupling)";
  return "";
}

double Chain::ParameterValue(int j) const {
  if (j == 0) return p_.v;
  if (j == 1) return p_.kc;
  if (j == 2) return p_.blocks[0].c / 2;
  const Block& b = p_.blocks[(j - 3) / 4];
  const double v[] = {b.m, b.c, b.k, b.law.mu_s};
  return v[(j - 3) % 4];
}

void Chain::SetParameterValue(int j, double value) {
  if (j == 0) {
    p_.v = value;
  } else if (j == 1) {
    p_.kc = value;
  } else if (j == 2) {
    for (Block& b : p_.blocks) b.c = 2 * value;
  } else {
    Block& b = p_.blocks[(j - 3) / 4];
    double* v[] = {&b.m, &b.c, &b.k, &b.law.mu_s};
    *v[(j - 3) % 4] = value;
  }
  Rebuild();
}

}  // namespace stickslip::chain
