// Newton on the Poincare map of any section (shooting.hpp); the map itself,
// its Jacobian and the orbit's Floquet data are in poincare_map.cpp.
#include "stickslip/orbits/shooting.hpp"

#include <cmath>

#include "numerics/max_abs.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::string ShootingOptions::ValidationError() const {
  std::string err = flow.ValidationError();
  if (!err.empty()) return err;
  if (max_newton < 1) return "max_newton = " + std::to_string(max_newton) + " must be >= 1";
  if (!(tol > 0 && tol < 1)) return "tol = " + Num(tol) + " must be in (0, 1)";
  if (!(max_return_time > 0) || !std::isfinite(max_return_time))
    return "max_return_time = " + Num(max_return_time) + " must be a finite number > 0";
  if (max_steps < 1) return "max_steps = " + std::to_string(max_steps) + " must be >= 1";
  return "";
}

PoincareSection PoincareSection::Stroboscopic(const System& s, const Eigen::VectorXd& z, int m) {
  if (s.clocks() != 1)
    throw InvalidArgument("a stroboscopic section needs a system with one clock, not " +
                          std::to_string(s.clocks()));
  if (m < 1) throw InvalidArgument("m = " + std::to_string(m) + " must be >= 1");
  Eigen::VectorXd f(s.dimension());
  s.Field(ModeOf(s, z), z, f);
  PoincareSection p;
  p.kind = SectionKind::kTime;
  p.time = m * (2 * M_PI / f[s.dimension() - 1]);  // m periods of theta' = Omega
  p.turns = m;
  return p;
}

PoincareSection PoincareSection::StickExit(int contact, int returns, int turns) {
  PoincareSection p;
  p.kind = SectionKind::kStickExit;
  p.contact = contact;
  p.returns = returns;
  p.turns = turns;
  return p;
}

namespace {
const ShootingOptions& Checked(const ShootingOptions& o) {
  const std::string err = o.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  return o;
}
}  // namespace

Shooting::Shooting(const System& system, const ShootingOptions& options)
    : options_(Checked(options)), flow_(system, options.flow) {}

void Shooting::set_max_return_time(double t) {
  if (!(t > 0) || !std::isfinite(t))
    throw InvalidArgument("max_return_time = " + Num(t) + " must be a finite number > 0");
  options_.max_return_time = t;
}

void Shooting::set_max_newton(int n) {
  if (n < 1) throw InvalidArgument("max_newton = " + std::to_string(n) + " must be >= 1");
  options_.max_newton = n;
}

void Shooting::Check(const PoincareSection& p) const {
  const System& s = system();
  if (p.kind == SectionKind::kTime) {
    if (!(p.time > 0) || !std::isfinite(p.time))
      throw InvalidArgument("section time = " + Num(p.time) + " must be a finite number > 0");
    return;
  }
  if (p.returns < 1)
    throw InvalidArgument("returns = " + std::to_string(p.returns) + " must be >= 1");
  if (s.clocks() > 1)
    throw InvalidArgument("an event section needs a system with at most one clock, not " +
                          std::to_string(s.clocks()));
  if (s.clocks() == 1 && p.turns < 1)
    throw InvalidArgument("turns = " + std::to_string(p.turns) +
                          ": the clock turns at least once per period");
  if (p.kind == SectionKind::kStickExit && (p.contact < 0 || p.contact >= s.contacts()))
    throw InvalidArgument("contact = " + std::to_string(p.contact) + " is not one of the " +
                          std::to_string(s.contacts()) + " contacts");
  if (p.kind == SectionKind::kSurface) {
    if (p.surface.derivative || p.surface.g.size < 1 || p.returns != 1)
      throw InvalidArgument("a surface section is a plain hyperplane crossed once per period");
    for (int t = 0; t < p.surface.g.size; ++t)
      if (p.surface.g.terms[t].index < 0 || p.surface.g.terms[t].index >= s.tangent_dimension())
        throw InvalidArgument("a surface section reads state " +
                              std::to_string(p.surface.g.terms[t].index) + ", not a tangent one");
  }
}

namespace {
bool Singular(double det, double max_abs) {
  return std::abs(det) <= Tolerances::kSingularShooting * (1 + max_abs);
}

// dz = -A^-1 r at a fixed size: no heap and no blocked code for the belt's 2
// and the forced oscillator's 3 unknowns. From 3 on the fixed solve rounds
// otherwise than the dynamic one; at 4 that alone turns chain2_asym's branch 2
// back at a fold instead of ending it at a sequence change (docs/benchmarks.md),
// so 4 and more keep the dynamic solve.
template <int N>
bool SolveFixed(const Eigen::MatrixXd& A, const Eigen::VectorXd& r, Eigen::VectorXd* dz) {
  const Eigen::Matrix<double, N, N> a = A;
  const Eigen::PartialPivLU<Eigen::Matrix<double, N, N>> lu(a);
  if (Singular(lu.determinant(), a.cwiseAbs().maxCoeff())) return false;
  *dz = -lu.solve(Eigen::Matrix<double, N, 1>(r));
  return true;
}
}  // namespace

// dz = -(DP - I)^-1 r by partial pivoting; false where DP - I is singular.
bool Shooting::NewtonStep() {
  const Eigen::Index n = dp_.rows();
  if (n == 1) return SolveFixed<1>(dp_, r_, &dz_);
  if (n == 2) return SolveFixed<2>(dp_, r_, &dz_);
  if (n == 3) return SolveFixed<3>(dp_, r_, &dz_);
  lu_.compute(dp_);  // what dp_.determinant() computes, once for the solve too
  if (Singular(lu_.determinant(), dp_.cwiseAbs().maxCoeff())) return false;
  dz_ = lu_.solve(r_);
  dz_ = -dz_;
  return true;
}

PeriodicOrbit Shooting::Find(const FlowPoint& guess, const PoincareSection& section) {
  Check(section);
  const System& s = system();
  if (guess.z.size() != s.dimension())
    throw InvalidArgument("the guess has " + std::to_string(guess.z.size()) +
                          " components, the system " + std::to_string(s.dimension()));
  const bool timed = section.kind == SectionKind::kTime;
  const int nu = timed ? s.tangent_dimension() : s.dimension();  // unknowns
  const int nt = s.tangent_dimension();
  PeriodicOrbit o;
  FlowPoint z = guess;
  if (timed) z.mode = ModeOf(s, z.z);
  Prepare(z, section);  // Newton in z only: no parameter column
  // The extremes are the converged evaluation's alone: Newton's iterates
  // hold them back (the same steps, to the bit, without their roots) until
  // an update is small enough that convergence is near, and a converged
  // evaluation that held them back is run again for them. A held run that
  // fails is run again seeking them (a segment's step cap counts from the
  // last root passed, extrema's included). (CVODE's are its step ends.)
  bool& held = request_.hold_extrema;
  held = !request_.extrema.empty() && request_.extrema_in_steps;
  for (o.iterations = 1; o.iterations <= options_.max_newton; ++o.iterations) {
    if (!Evaluate(z, section, &o)) {
      if (!held) return o;
      held = false;
      if (!Evaluate(z, section, &o)) return o;
    }
    if (!dp_.allFinite() || !r_.allFinite()) {  // g . f = 0: a tangential arrival
      o.status = OrbitStatus::kSingular;
      o.message = "the map's Jacobian is not finite (a tangential arrival on the section) at t = " +
                  Num(run_.end.t);
      return o;
    }
    dp_.diagonal().array() -= 1.0;  // DP - I
    if (!NewtonStep()) {
      o.status = OrbitStatus::kSingular;
      o.message = "DP - I is singular (a multiplier at 1) at t = " + Num(z.t);
      return o;
    }
    Eigen::VectorXd& dz = dz_;
    const double size = 1 + MaxAbs(z.z.head(nu));
    // A long step is cut (damped Newton): the state's by a share of its size,
    // a clock's to a quarter turn.
    const double norm = MaxAbs(dz.head(nt)), cap = Tolerances::kNewtonCap * size;
    if (norm > cap) dz.head(nt) *= cap / norm;
    if (nu > nt && std::abs(dz[nt]) > M_PI / 2) dz[nt] = std::copysign(M_PI / 2, dz[nt]);
    o.update = MaxAbs(dz);
    dp_.diagonal().array() += 1.0;
    if (o.update <= options_.tol * size) {
      if (held) {  // once more, for the extremes
        held = false;
        if (!Evaluate(z, section, &o)) return o;
        // DP as the Newton step leaves it, (DP - I) + I: the bits of an
        // evaluation that sought them.
        dp_.diagonal().array() -= 1.0;
        dp_.diagonal().array() += 1.0;
      }
      Describe(z, section, &o);
      o.status = OrbitStatus::kOk;
      return o;
    }
    // Quadratic convergence: within about two more evaluations.
    if (o.update <= Tolerances::kSeekExtrema * std::sqrt(options_.tol) * size) held = false;
    for (int i = 0; i < nu; ++i) z.z[i] += dz[i];
    OntoSection(section, &z);
  }
  o.status = OrbitStatus::kNotConverged;
  o.message = "no convergence in " + std::to_string(options_.max_newton) + " Newton iterations";
  return o;
}

}  // namespace stickslip
