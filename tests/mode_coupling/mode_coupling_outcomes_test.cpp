// What a run of the brake model (systems/mode_coupling) reaches when it
// never settles on an attractor (chaos/lyapunov.hpp, basin/attractors.hpp):
//  - a start with the contact already open (1 - gamma y <= 0) is outside the
//    model: contact-lost at once, with where;
//  - with k12 = 1 the block sticks for good while y runs off: no return to
//    the section comes, and the run is unbounded, not undecided;
//  - next to the flutter threshold the returns spiral slowly onto steady
//    sliding: settling, at the rate of its eigenvalues' real part.
#include <gtest/gtest.h>

#include <cmath>

#include "mode_coupling/mode_coupling.hpp"
#include "stickslip/basin/attractors.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/systems/belt/friction.hpp"

namespace stickslip::mode_coupling {
namespace {

CouplingParams CoulombBrake(double mu_k) {
  CouplingParams p;
  p.law.law = LawKind::kCoulomb;
  p.law.mu_s = 0.8, p.law.mu_k = mu_k;
  return p;
}

SectionRun IterateMaxima(const System& s, const FlowPoint& start, int transient, int keep) {
  LyapunovOptions o;
  o.transient = transient, o.keep = keep, o.align = 10;
  PoincareSection section;
  section.kind = SectionKind::kSurface;
  section.surface = MaximaSection(s);
  return IterateSection(s, start, section, o, {}, 50);
}

TEST(ModeCouplingOutcomes, StartWithTheContactOpenIsContactLost) {
  const ModeCoupling s(CoulombBrake(0.52));
  FlowPoint start = BeltStart(s);
  start.z[2] = 1.2;  // y: the normal force 1 - gamma y = -0.2
  const SectionRun r = IterateMaxima(s, start, 10, 20);
  EXPECT_EQ(r.status, LyapunovStatus::kContactOpen);
  EXPECT_NE(r.message.find("open at the start (normal force -0.2"), std::string::npos) << r.message;
  EXPECT_EQ(ClassifyAttractor(s, r, AttractorOptions()).kind, AttractorKind::kContactLost);
}

TEST(ModeCouplingOutcomes, StuckDriftWithoutReturnsIsUnbounded) {
  CouplingParams p = CoulombBrake(0.52);
  p.k12 = 1;  // k11 k22 - k12^2 > 0 still, but the follower force drives y off
  const ModeCoupling s(p);
  const SectionRun r = IterateMaxima(s, BeltStart(s), 10, 20);
  EXPECT_EQ(r.status, LyapunovStatus::kDiverged) << Name(r.status) << ": " << r.message;
  EXPECT_EQ(ClassifyAttractor(s, r, AttractorOptions()).kind, AttractorKind::kUnbounded);
}

// Just below mu_k* steady sliding is a slowly damped focus: its maxima fall
// by exp(Re lambda T) per return, so the kept returns fall monotonically and
// their exponent is Re lambda (SteadySliding's eigen-solve, another method).
TEST(ModeCouplingOutcomes, SlowSpiralOntoSteadySlidingIsSettling) {
  CouplingParams p = CoulombBrake(0.5);
  p.law.mu_k = FlutterMuK(p) - 0.002;
  const ModeCoupling s(p);
  const SteadyState eq = SteadySliding(s);
  ASSERT_TRUE(eq.found && eq.stable());
  FlowPoint start{0, eq.z, ModeSet()};
  start.z[0] += 0.01;
  start.mode = ModeOf(s, start.z);
  const SectionRun r = IterateMaxima(s, start, 50, 400);
  ASSERT_EQ(r.status, LyapunovStatus::kDone) << r.message;
  const Attractor a = ClassifyAttractor(s, r, AttractorOptions());
  EXPECT_EQ(a.kind, AttractorKind::kSettling) << Name(a.kind);
  EXPECT_NEAR(r.lyapunov, eq.max_real, 1e-2 * std::abs(eq.max_real) + 3 * r.lyapunov_err);
  std::printf("[ measured ] exponent %.6g +- %.2g, steady sliding's Re lambda %.6g\n", r.lyapunov,
              r.lyapunov_err, eq.max_real);
}

}  // namespace
}  // namespace stickslip::mode_coupling
