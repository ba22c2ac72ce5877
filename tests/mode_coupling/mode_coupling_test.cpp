// The mode-coupling model (systems/mode_coupling/): its flutter threshold
// against the closed form (docs/theory.md, "Mode coupling"), found here by
// the generic steady-sliding eigenvalues (SteadySliding: System::Rest and
// System::Jacobian) and bisection; and the contact's opening as the flow's
// stop status.
#include "mode_coupling/mode_coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/flow.hpp"

namespace stickslip::mode_coupling {
namespace {

// The study's set: beta 0.02, k11 1, k22 1.5, k12 -0.3, gamma 1, v 0.5,
// coulomb mu_s 0.6.
CouplingParams Study(double mu_k) {
  CouplingParams p;
  p.law.law = LawKind::kCoulomb;
  p.law.mu_s = 0.6;
  p.law.mu_k = mu_k;
  return p;
}

TEST(ModeCoupling, FlutterThresholdIsTheClosedForm) {
  const double closed = FlutterMuK(Study(0.3));
  // (0.25 + 0.36 + 8 0.02^2 2.5) / 1.2 = 0.515.
  EXPECT_NEAR(closed, 0.515, 1e-15);
  auto max_real = [](double mu_k) {
    const SteadyState e = SteadySliding(ModeCoupling(Study(mu_k)));
    EXPECT_TRUE(e.found);
    return e.max_real;
  };
  EXPECT_LT(max_real(0.3), 0);
  EXPECT_GT(max_real(0.59), 0);  // mu_k < mu_s: the law's own check
  double lo = 0.3, hi = 0.59;
  for (int i = 0; i < 60; ++i) ((max_real((lo + hi) / 2) < 0) ? lo : hi) = (lo + hi) / 2;
  EXPECT_NEAR((lo + hi) / 2, closed, 1e-12);
  // At the threshold: a pair on the imaginary axis, the other pair damped.
  const SteadyState e = SteadySliding(ModeCoupling(Study(closed)));
  EXPECT_NEAR(e.eigenvalues[0].real(), 0, 1e-12);
  EXPECT_GT(std::abs(e.eigenvalues[0].imag()), 0.5);
}

// Without damping the threshold is where K's eigenvalues merge: the
// discriminant (k11 - k22)^2 + 4 k12 (k12 + gamma mu_k) vanishes.
TEST(ModeCoupling, UndampedThresholdIsTheModesMerging) {
  CouplingParams p = Study(0.3);
  p.beta = 0;
  const double mu = FlutterMuK(p);
  EXPECT_NEAR(0.25 + 4 * p.k12 * (p.k12 + p.gamma * mu), 0, 1e-15);
  p.gamma = 0;
  EXPECT_TRUE(std::isnan(FlutterMuK(p)));
}

// y grows past 1 / gamma: the run stops with kContactOpen where N = 0.
TEST(ModeCoupling, ContactOpeningStopsTheRun) {
  const ModeCoupling s(Study(0.3));
  FlowOptions fo;
  fo.rtol = 1e-13;
  fo.atol = 1e-15;
  Flow flow(s, fo);
  FlowRequest rq;
  rq.t_max = 50;
  const FlowPoint start{0, Eigen::Vector4d(0, 0, 0.5, 2.0), ModeSet(Mode::kSlipBelow)};
  const FlowRun r = flow.Run(start, rq);
  EXPECT_EQ(r.status, FlowStatus::kContactOpen) << r.message;
  EXPECT_EQ(r.opened, 0);
  EXPECT_NEAR(r.end.z[2], 1.0, 1e-13);
  EXPECT_NE(r.message.find("contact 0 opens"), std::string::npos) << r.message;
  // A start with the contact open is refused.
  EXPECT_THROW(flow.Run(FlowPoint{0, Eigen::Vector4d(0, 0, 1.5, 0), ModeSet(Mode::kSlipBelow)}, rq),
               InvalidArgument);
}

// The Taylor field against CVODE on the same system (the field and its
// Jacobian are the model's; the recurrences are checked by a second
// integrator): a stick-slip run with the normal force varying.
TEST(ModeCoupling, TaylorAgreesWithCvode) {
  const ModeCoupling s(Study(0.45));
  FlowOptions ft, fc;
  ft.rtol = 1e-13;
  ft.atol = 1e-15;
  fc.integrator = Integrator::kCvode;
  fc.rtol = 1e-12;
  fc.atol = 1e-14;
  Flow a(s, ft), b(s, fc);
  FlowRequest rq;
  rq.t_max = 30;
  rq.variational = true;
  const FlowPoint start{0, Eigen::Vector4d(1.0, 0, -0.1, 0), ModeSet(Mode::kSlipBelow)};
  const FlowRun ra = a.Run(start, rq), rb = b.Run(start, rq);
  ASSERT_TRUE(ra.ok() && rb.ok()) << ra.message << rb.message;
  ASSERT_GE(ra.sticks, 1);
  EXPECT_EQ(ra.switches, rb.switches);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(ra.end.z[i], rb.end.z[i], 1e-8) << i;
  EXPECT_NEAR((ra.jacobian - rb.jacobian).cwiseAbs().maxCoeff(), 0, 1e-6);
}

}  // namespace
}  // namespace stickslip::mode_coupling
