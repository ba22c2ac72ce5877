// The energy bound Model::NoPeriodicOrbit (proof in src/model.cpp): where it
// starts against closed forms, that no orbit exists where it holds against the
// independent long-double reference integrator, and that the continuation
// skips the (stiff) orbit search there: issue 23, "the stiff cliff".
#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference_orbit.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/orbits/orbit_scan.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {
namespace {

Params With(LawKind law, double beta, double v, double mu_s = 0.4) {
  Params p;
  p.law = law;
  p.beta = beta;
  p.v = v;
  p.mu_s = mu_s;
  return p;
}

bool Holds(const Params& p) { return Model(p).NoPeriodicOrbit(); }

TEST(EnergyBound, StartsWherePsiOfVReachesMuS) {
  // Cubic law: psi(v) = mu(v) + 2 beta v = mu_s at v* = sqrt((k1 - 2 beta) / k3),
  // and there psi'(v*) = 2 (k1 - 2 beta) > 0. Seed set: v* = 0.7638.
  const Params seed;
  const double v_cubic = std::sqrt((seed.k1() - 2 * seed.beta) / seed.k3());
  EXPECT_FALSE(Holds(With(LawKind::kCubic, 0.05, v_cubic * (1 - 1e-6))));
  EXPECT_TRUE(Holds(With(LawKind::kCubic, 0.05, v_cubic * (1 + 1e-6))));
  // Coulomb law: psi(v) = mu_k + 2 beta v = mu_s at v* = (mu_s - mu_k) / (2 beta).
  const double v_coulomb = (0.4 - 0.25) / (2 * 0.1);
  EXPECT_FALSE(Holds(With(LawKind::kCoulomb, 0.1, v_coulomb * (1 - 1e-6))));
  EXPECT_TRUE(Holds(With(LawKind::kCoulomb, 0.1, v_coulomb * (1 + 1e-6))));
  // Undamped coulomb (a center) and a quintic term (mu not convex): never.
  EXPECT_FALSE(Holds(With(LawKind::kCoulomb, 0, 1e3)));
  Params quintic = With(LawKind::kCubic, 0.05, 1.0);
  EXPECT_TRUE(Holds(quintic));
  quintic.k5 = 1e-3;
  EXPECT_FALSE(Holds(quintic));
}

TEST(EnergyBound, TheReferenceFindsNoOrbitWhereItHolds) {
  // Just past the onset (least margin) for each law with a known onset.
  const Params cases[] = {With(LawKind::kCubic, 0.05, 0.8), With(LawKind::kStribeck, 0.05, 1.6),
                          With(LawKind::kLeine, 0.05, 10, 1.0), With(LawKind::kCoulomb, 0.1, 0.8)};
  for (const Params& p : cases) {
    SCOPED_TRACE(std::string(Name(p.law)) + " v = " + std::to_string(p.v));
    ASSERT_TRUE(Holds(p));
    // The slip phase from the exit point never reaches the stick set again ...
    EXPECT_FALSE(reference::StickSlip(p, 1e-14L, 200).found);
    // ... and every return to the section x' = 0 that stays below the belt
    // (the reference's smooth field ignores the switch) comes back closer to xbar.
    const reference::Model m(p);
    const reference::Real xbar = m.law.Mu(m.v);
    int below = 0;
    for (int i = 1; i <= 20; ++i) {
      const reference::Real a = (p.mu_s + p.v) * i / 10;
      const reference::SectionReturn r = reference::ReturnToSection(m, xbar + a, 1e-14L, 200);
      if (!r.ok || r.e.xdot_max >= m.v) continue;
      ++below;
      EXPECT_LT(std::abs(r.x - xbar), a) << "a = " << static_cast<double>(a);
    }
    EXPECT_GE(below, 3);
    const PeriodicOrbits found = FindPeriodicOrbits(Model(p), OrbitScanOptions());
    EXPECT_TRUE(found.ok());
    EXPECT_FALSE(found.has_stick_slip);
    EXPECT_TRUE(found.pure_slip.empty());
    EXPECT_TRUE(found.steady.stable());
  }
}

TEST(EnergyBound, AWideRangeCostsNoMoreThanANarrowOne) {
  // Issue 23: the seed branch --to 100 took 12.9 M Taylor steps and --to 5
  // 0.22 M (integrator_steps in ss_continue's branch.tsv), nearly all of them
  // searching for stick-slip orbits where the energy bound excludes them; with
  // the bound 2571 and 2762.
  auto run = [](double to) {
    ContinuationOptions o;
    o.from = 0.05;
    o.to = to;
    return Continue(Params(), o);
  };
  const ContinuationResult narrow = run(5), wide = run(100);
  ASSERT_EQ(narrow.status, ContinuationStatus::kOk) << narrow.message;
  ASSERT_EQ(wide.status, ContinuationStatus::kOk) << wide.message;
  EXPECT_LE(wide.counts.integrator_steps, 2 * narrow.counts.integrator_steps);
  ASSERT_EQ(wide.special.size(), narrow.special.size());
  for (size_t i = 0; i < wide.special.size(); ++i) {
    EXPECT_EQ(wide.special[i].kind, narrow.special[i].kind);
    EXPECT_NEAR(wide.special[i].p, narrow.special[i].p, 1e-12);
  }
}

}  // namespace
}  // namespace stickslip
