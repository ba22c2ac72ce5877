// Sliding bifurcations on forced branches (issue 20, item 3): located points
// against closed forms that share no code with the library.
//  - Grazing-sliding of a pure-slip coulomb orbit on a belt: the steady slip
//    x = mu_k + Re(P e^{i Omega t}), P = A / (1 - Omega^2 + 2 i beta Omega),
//    touches x' = v when Omega |P| = v, a quadratic in Omega^2.
//  - Crossing-sliding of a non-stop coulomb orbit on a floor (v = 0): the
//    half-wave-symmetric orbit from the closed-form pieces (forced_reference),
//    whose reversal reaches the band's edge |x - A cos(Omega t)| = mu_s.
#include <gtest/gtest.h>

#include <cmath>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "forced_trace.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

ForcedBeltParams Coulomb(double mu_s, double mu_k, double v, double beta, double a) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = mu_s, p.base.mu_k = mu_k, p.base.v = v, p.base.beta = beta;
  p.force = a;
  return p;
}

OrbitBranch Trace(ForcedBeltParams p, double from, double to) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = 0.02 * std::abs(to - from);
  return testing_util::TraceOmega(p, from, to, o);
}

std::vector<OrbitRow> WithLabel(const OrbitBranch& b, SpecialKind l) {
  std::vector<OrbitRow> out;
  for (const OrbitRow& r : b.special)
    if (r.label == l) out.push_back(r);
  return out;
}

// Omega |P| = v: v^2 u^2 + (4 beta^2 v^2 - 2 v^2 - A^2) u + v^2 = 0, u = Omega^2.
void GrazingOmegas(Real v, Real beta, Real a, Real out[2]) {
  const Real b = 4 * beta * beta * v * v - 2 * v * v - a * a, c = v * v;
  const Real d = std::sqrt(b * b - 4 * c * c);
  out[0] = std::sqrt((-b - d) / (2 * c));
  out[1] = std::sqrt((-b + d) / (2 * c));
}

// A pure slip below a belt, Filippov's case mu_s = mu_k: GR where the stick
// phase is born at the low Omega and where it dies at the high one; the
// branch goes on through both to Omega = 2.5.
TEST(ForcedSliding, GrazingSlidingMatchesTheSteadySlipClosedForm) {
  Real omegas[2];
  GrazingOmegas(0.2L, 0.05L, 0.3L, omegas);
  const OrbitBranch b = Trace(Coulomb(0.3, 0.3, 0.2, 0.05, 0.3), 0.45, 2.5);
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  EXPECT_EQ(b.rows.back().p, 2.5);
  const auto gr = WithLabel(b, SpecialKind::kGrazing);
  ASSERT_EQ(gr.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(gr[i].p, static_cast<double>(omegas[i]), 1e-10);
    EXPECT_EQ(gr[i].sticks, i == 0 ? 0 : 1);  // the row on the side it was reached from
    EXPECT_NE(gr[i].description.find("grazing-sliding"), std::string::npos);
    std::printf("[ measured ] GR at Omega = %.15g, closed form %.15Lg (%.1e)\n", gr[i].p, omegas[i],
                std::abs(gr[i].p - static_cast<double>(omegas[i])));
  }
}

// With mu_s > mu_k the stick phase born at the graze has a finite length (it
// lasts until the force reaches mu_s): the stroboscopic map jumps, the
// corrector fails there (before: the branch ended with step-too-small). The
// GR is located on the steady slip's closed form, and the branch goes on.
TEST(ForcedSliding, GrazingWithStaticFrictionJumpsAndGoesOn) {
  Real omegas[2];
  GrazingOmegas(0.2L, 0.05L, 0.3L, omegas);
  const OrbitBranch b = Trace(Coulomb(0.4, 0.3, 0.2, 0.05, 0.3), 0.45, 2.5);
  const auto gr = WithLabel(b, SpecialKind::kGrazing);
  ASSERT_GE(gr.size(), 1u);
  EXPECT_NEAR(gr[0].p, static_cast<double>(omegas[0]), 1e-10);
  EXPECT_EQ(gr[0].sticks, 0);
  size_t i = 0;
  while (i < b.rows.size() && b.rows[i].label != SpecialKind::kGrazing) ++i;
  ASSERT_LT(i + 1, b.rows.size()) << "the branch ends at the GR: " << b.message;
  EXPECT_EQ(b.rows[i + 1].sticks, 1);
  std::printf(
      "[ measured ] mu_s > mu_k: GR at Omega = %.15g, closed form %.15Lg (%.1e); "
      "branch %s after %zu rows\n",
      gr[0].p, omegas[0], std::abs(gr[0].p - static_cast<double>(omegas[0])), Name(b.status),
      b.rows.size());
}

// The half-wave-symmetric non-stop orbit on a floor: from a reversal
// (t_r, x_r, 0) a slip with x' < 0 (friction +mu_k) reaches (t_r + pi/Omega,
// -x_r, 0). Two equations in (t_r, x_r), Newton with difference quotients.
bool SymmetricReversal(const ref::Setup& s, Real* t_r, Real* x_r) {
  const Real half = std::acos(Real(-1)) / s.w;
  auto residual = [&](Real t, Real x, Real* f) {
    ref::CoulombPiece piece(s, 1, t, x, 0);
    Real xe, ye;
    piece.At(t + half, xe, ye);
    f[0] = xe + x, f[1] = ye;
  };
  for (int it = 0; it < 50; ++it) {
    Real f[2], ft[2], fx[2];
    const Real h = 1e-9L;
    residual(*t_r, *x_r, f);
    residual(*t_r + h, *x_r, ft);
    residual(*t_r, *x_r + h, fx);
    const Real j00 = (ft[0] - f[0]) / h, j01 = (fx[0] - f[0]) / h;
    const Real j10 = (ft[1] - f[1]) / h, j11 = (fx[1] - f[1]) / h;
    const Real det = j00 * j11 - j01 * j10;
    const Real dt = (f[0] * j11 - f[1] * j01) / det, dx = (j00 * f[1] - j10 * f[0]) / det;
    *t_r -= dt, *x_r -= dx;
    if (std::abs(dt) + std::abs(dx) < 1e-17L) return true;
  }
  return false;
}

// Coulomb on a floor (mu_s 0.4 > mu_k 0.25, beta 0.05, A 0.5): two sticks
// per period below the first CR, a non-stop orbit between, two sticks again
// above the second. Each CR: the reversal on the band's edge, by bisection
// on the closed-form orbit.
TEST(ForcedSliding, CrossingSlidingMatchesTheClosedFormReversal) {
  ForcedBeltParams p = Coulomb(0.4, 0.25, 0, 0.05, 0.5);
  const OrbitBranch b = Trace(p, 0.5, 2.5);
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  const auto cr = WithLabel(b, SpecialKind::kCrossing);
  ASSERT_EQ(cr.size(), 2u);
  for (const OrbitRow& point : cr) {
    // Start Newton from the library's reversal (a crossing with x > 0).
    p.omega = point.p;
    const ForcedBelt m(p);
    std::vector<FlowSwitch> ev;
    FlowRequest rq;
    rq.switches = &ev;
    testing_util::RunForced(m, ForcedStart(m, 0, point.start.z[0], point.start.z[1]), m.period(),
                            rq);
    Real t0 = -1, x0 = 0;
    for (const FlowSwitch& e : ev)
      if (e.z[0] > 0) t0 = e.t, x0 = e.z[0];
    ASSERT_GE(t0, 0);
    auto edge = [&](Real w) {  // |x_r - A cos(Omega t_r)| - mu_s on the closed-form orbit
      ref::Setup s{reference::Law(p.base), 0.05L, 0, 0.5L, w};
      Real t = t0, x = x0;
      EXPECT_TRUE(SymmetricReversal(s, &t, &x));
      return std::abs(x - s.a * std::cos(w * t)) - Real(0.4);
    };
    Real lo = point.p - 1e-6L, hi = point.p + 1e-6L;
    const Real g_lo = edge(lo);
    ASSERT_LT(g_lo * edge(hi), 0) << "no edge within 1e-6 of " << point.p;
    for (int i = 0; i < 80; ++i) {
      const Real mid = (lo + hi) / 2;
      ((edge(mid) > 0) == (g_lo > 0) ? lo : hi) = mid;
    }
    EXPECT_NEAR(point.p, static_cast<double>(lo), 1e-10);
    std::printf("[ measured ] CR at Omega = %.15g, closed form %.15Lg (%.1e): %s\n", point.p, lo,
                std::abs(point.p - static_cast<double>(lo)), point.description.c_str());
  }
}

}  // namespace
}  // namespace stickslip
