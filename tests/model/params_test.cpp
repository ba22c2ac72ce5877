// Parameters: validation messages, names, the seed's scaling (section 3).
#include "stickslip/systems/belt/params.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {
namespace {

// True if text contains part; the failure message shows both.
::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

Params SeedParams() { return Params{}; }

// The message of a rejected parameter set; empty if it was accepted.
std::string Rejection(const Params& p) {
  const std::string msg = ValidationError(p);
  if (msg.empty()) {
    EXPECT_NO_THROW(Validate(p));
  } else {
    EXPECT_THROW(Validate(p), InvalidArgument);
  }
  return msg;
}

TEST(Params, SeedSetIsValid) { EXPECT_EQ(ValidationError(SeedParams()), ""); }

TEST(Params, SeedSetCubicCoefficients) {
  // Seed section 4: k1 = 0.45, k3 = 0.6.
  const Params p = SeedParams();
  EXPECT_NEAR(p.k1(), 0.45, 1e-15);
  EXPECT_NEAR(p.k3(), 0.6, 1e-15);
  EXPECT_EQ(p.law, LawKind::kCubic);
}

TEST(Params, RejectsMuMAtOrAboveMuS) {
  Params p = SeedParams();
  p.mu_m = 0.5;
  EXPECT_TRUE(Contains(Rejection(p), "mu_m = 0.5"));
  p.mu_m = 0.4;  // equal is not allowed either
  EXPECT_TRUE(Contains(Rejection(p), "mu_m = 0.4"));
}

TEST(Params, RejectsNonPositiveVm) {
  Params p = SeedParams();
  p.v_m = 0;
  EXPECT_TRUE(Contains(Rejection(p), "v_m = 0"));
  p.v_m = -0.5;
  EXPECT_TRUE(Contains(Rejection(p), "v_m = -0.5"));
}

TEST(Params, RejectsNegativeBeta) {
  Params p = SeedParams();
  p.beta = -0.1;
  EXPECT_TRUE(Contains(Rejection(p), "beta = -0.1"));
  p.beta = 0;  // undamped is fine
  EXPECT_EQ(Rejection(p), "");
  // A damping ratio, not a scale: any small beta >= 0 is a model too.
  for (double beta : {1e-7, 9.99e-7, 1e-300, 4.9e-324}) {
    p.beta = beta;
    EXPECT_EQ(Rejection(p), "") << "beta = " << beta;
  }
}

TEST(Params, RejectsNonPositiveBeltSpeed) {
  Params p = SeedParams();
  p.v = 0;
  EXPECT_TRUE(Contains(Rejection(p), "v = 0"));
  p.v = -0.25;
  EXPECT_TRUE(Contains(Rejection(p), "v = -0.25"));
}

TEST(Params, RejectsMuKAtOrAboveMuS) {
  for (LawKind law : {LawKind::kCoulomb, LawKind::kStribeck}) {
    Params p = SeedParams();
    p.law = law;
    EXPECT_EQ(Rejection(p), "");
    p.mu_k = 0.45;
    EXPECT_TRUE(Contains(Rejection(p), "mu_k = 0.45")) << Name(law);
  }
}

TEST(Params, QuinticTermValidated) {
  Params p = SeedParams();
  p.k5 = -0.1;
  EXPECT_TRUE(Contains(Rejection(p), "k5 = -0.1 must be >= 0"));
  // mu(v) = 0.4 - 0.45 v + 0.6 v^3 - k5 v^5 at v = 1: 0.55 - k5, so k5 = 0.55 is the limit.
  p.v = 1.0;
  p.k5 = 0.549;
  EXPECT_EQ(Rejection(p), "");
  p.k5 = 0.551;
  EXPECT_TRUE(Contains(Rejection(p), "k5 = 0.551 makes mu(v)"));
  p.law = LawKind::kStribeck;  // other laws ignore k5
  EXPECT_EQ(Rejection(p), "");
}

TEST(Params, RejectsNanAndInfinity) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const std::string& name : ParameterNames(LawKind::kCubic)) {
    Params p = SeedParams();
    SetParameter(p, name, nan);
    EXPECT_TRUE(Contains(Rejection(p), name + " = nan")) << name;
    SetParameter(p, name, inf);
    EXPECT_TRUE(Contains(Rejection(p), name + " = inf")) << name;
  }
}

TEST(Params, IgnoresParametersOfOtherLaws) {
  Params p = SeedParams();
  p.mu_k = 0.9;                                        // coulomb / stribeck only
  p.delta = std::numeric_limits<double>::quiet_NaN();  // leine only
  EXPECT_EQ(ValidationError(p), "");
}

TEST(Params, UnknownNameThrows) {
  Params p = SeedParams();
  EXPECT_THROW(GetParameter(p, "gamma"), InvalidArgument);
  EXPECT_THROW(SetParameter(p, "gamma", 1.0), InvalidArgument);
  EXPECT_THROW(GetParameter(p, ""), InvalidArgument);
  EXPECT_FALSE(IsParameterName("gamma"));
  try {
    GetParameter(p, "gamma");
  } catch (const InvalidArgument& e) {
    EXPECT_TRUE(Contains(std::string(e.what()), "gamma"));
  }
}

TEST(Params, GetAndSetByName) {
  Params p = SeedParams();
  for (const auto& name : AllParameterNames()) {
    EXPECT_TRUE(IsParameterName(name));
    SetParameter(p, name, 0.125);
    EXPECT_EQ(GetParameter(p, name), 0.125) << name;
  }
}

TEST(Params, LawNamesRoundTrip) {
  for (LawKind law : {LawKind::kCubic, LawKind::kCoulomb, LawKind::kStribeck, LawKind::kLeine})
    EXPECT_EQ(LawFromName(Name(law)), law);
  EXPECT_THROW(LawFromName("viscous"), InvalidArgument);
  EXPECT_THROW(LawFromName("Cubic"), InvalidArgument);
}

TEST(Params, ParameterNamesPerLaw) {
  using V = std::vector<std::string>;
  EXPECT_EQ(ParameterNames(LawKind::kCubic), (V{"beta", "v", "mu_s", "mu_m", "v_m", "k5"}));
  EXPECT_EQ(ParameterNames(LawKind::kCoulomb), (V{"beta", "v", "mu_s", "mu_k"}));
  EXPECT_EQ(ParameterNames(LawKind::kStribeck), (V{"beta", "v", "mu_s", "mu_k", "v_s"}));
  EXPECT_EQ(ParameterNames(LawKind::kLeine), (V{"beta", "v", "mu_s", "delta"}));
}

TEST(Params, HandComputedConversion) {
  // M = 2 kg, K = 8 N/m, g = 10 m/s^2: L = M g / K = 2.5 m, omega0 = 2 1/s,
  // t0 = 0.5 s, speed scale L / t0 = 5 m/s. C = 0.8: 2 beta = C / sqrt(K M)
  // = 0.2. V = 1 m/s: v = 0.2. V_m = 0.5 m/s: v_m = 0.1. delta 3 s/m: 15.
  PhysicalParams phys;
  phys.mass = 2;
  phys.stiffness = 8;
  phys.gravity = 10;
  phys.damping = 0.8;
  phys.belt_speed = 1;
  phys.speed_m = 0.5;
  phys.speed_s = 2.5;
  phys.delta = 3;
  phys.mu_s = 0.3;
  phys.mu_m = 0.2;
  phys.mu_k = 0.1;
  EXPECT_DOUBLE_EQ(LengthScale(2, 8, 10), 2.5);
  EXPECT_DOUBLE_EQ(TimeScale(2, 8), 0.5);
  const Params p = ToDimensionless(phys);
  EXPECT_DOUBLE_EQ(p.beta, 0.1);
  EXPECT_DOUBLE_EQ(p.v, 0.2);
  EXPECT_DOUBLE_EQ(p.v_m, 0.1);
  EXPECT_DOUBLE_EQ(p.v_s, 0.5);
  EXPECT_DOUBLE_EQ(p.delta, 15);
  EXPECT_EQ(p.mu_s, 0.3);  // friction coefficients are unchanged
  EXPECT_EQ(p.mu_m, 0.2);
  EXPECT_EQ(p.mu_k, 0.1);
}

TEST(Params, SeedSetIsItsOwnPhysicalImageAtUnitScales) {
  // M = K = g = 1 makes L = t0 = 1: the physical numbers are the dimensionless ones.
  const PhysicalParams phys = ToPhysical(SeedParams(), 1, 1, 1);
  EXPECT_DOUBLE_EQ(phys.damping, 0.1);
  EXPECT_DOUBLE_EQ(phys.belt_speed, 0.25);
  EXPECT_DOUBLE_EQ(phys.speed_m, 0.5);
}

TEST(Params, PhysicalDimensionlessRoundTrip) {
  PhysicalParams phys;
  phys.law = LawKind::kStribeck;
  phys.mass = 3.7;
  phys.stiffness = 120;
  phys.gravity = 9.81;
  phys.damping = 1.3;
  phys.belt_speed = 0.07;
  phys.speed_m = 0.11;
  phys.speed_s = 0.02;
  phys.delta = 40;
  phys.mu_s = 0.5;
  phys.mu_m = 0.3;
  phys.mu_k = 0.35;
  const PhysicalParams back =
      ToPhysical(ToDimensionless(phys), phys.mass, phys.stiffness, phys.gravity);
  EXPECT_EQ(back.law, phys.law);
  EXPECT_NEAR(back.damping, phys.damping, 1e-14 * phys.damping);
  EXPECT_NEAR(back.belt_speed, phys.belt_speed, 1e-14 * phys.belt_speed);
  EXPECT_NEAR(back.speed_m, phys.speed_m, 1e-14 * phys.speed_m);
  EXPECT_NEAR(back.speed_s, phys.speed_s, 1e-14 * phys.speed_s);
  EXPECT_NEAR(back.delta, phys.delta, 1e-14 * phys.delta);
  EXPECT_EQ(back.mu_s, phys.mu_s);
  EXPECT_EQ(back.mu_m, phys.mu_m);
  EXPECT_EQ(back.mu_k, phys.mu_k);

  // And the other way round.
  const Params p = SeedParams();
  const Params again = ToDimensionless(ToPhysical(p, 0.5, 20, 9.81));
  for (const auto& name : AllParameterNames())
    EXPECT_NEAR(GetParameter(again, name), GetParameter(p, name), 1e-14) << name;
}

TEST(Params, PhysicalInputsMustBePositive) {
  for (const char* field : {"mass", "stiffness", "gravity"}) {
    PhysicalParams phys;
    double& x = std::string(field) == "mass"        ? phys.mass
                : std::string(field) == "stiffness" ? phys.stiffness
                                                    : phys.gravity;
    x = 0;
    try {
      ToDimensionless(phys);
      ADD_FAILURE() << field << " = 0 accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_TRUE(Contains(std::string(e.what()), std::string(field) + " = 0"));
    }
    x = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(ToDimensionless(phys), InvalidArgument) << field;
  }
  PhysicalParams phys;
  phys.damping = -1;
  EXPECT_THROW(ToDimensionless(phys), InvalidArgument);
}

// Every parameter of every law has a default range that is valid at both ends
// for the law's defaults, and the seed's Hopf point lies inside v's range.
TEST(Params, DefaultRangesAreValidAtBothEnds) {
  for (LawKind law : {LawKind::kCubic, LawKind::kCoulomb, LawKind::kStribeck, LawKind::kLeine}) {
    Params base;
    base.law = law;
    for (const auto& name : ParameterNames(law)) {
      const ParameterRange r = DefaultRange(base, ParameterAxis(name));
      EXPECT_LT(r.from, r.to) << name;
      for (double x : {r.from, r.to}) {
        Params q = base;
        SetParameter(q, name, x);
        EXPECT_EQ(ValidationError(q), "") << Name(law) << " " << name << " = " << x;
      }
    }
  }
  const ParameterRange v = DefaultRange(SeedParams(), Parameter::kV);
  const double hopf =
      std::sqrt((SeedParams().k1() - 2 * SeedParams().beta) / (3 * SeedParams().k3()));  // (3.16)
  EXPECT_LT(v.from, hopf);
  EXPECT_GT(v.to, hopf);
  EXPECT_THROW(DefaultRange(SeedParams(), ParameterAxis("gamma")), InvalidArgument);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

TEST(ParameterAxis, NamesTheSameMemberAsGetAndSet) {
  Params base;
  double x = 0.125;
  for (const std::string& name : AllParameterNames()) {
    const ParameterAxis axis(name);
    const Params q = axis.At(base, x);
    EXPECT_EQ(GetParameter(q, name), x) << name;
    EXPECT_EQ(axis.Get(q), x) << name;
    Params r = base;
    SetParameter(r, name, x);
    EXPECT_EQ(axis.Get(r), x) << name;
    x += 0.5;
  }
  EXPECT_THROW(ParameterAxis("gamma"), InvalidArgument);
  EXPECT_EQ(ParameterNameList(), "beta, v, mu_s, mu_m, v_m, mu_k, v_s, delta or k5");
}

}  // namespace
}  // namespace stickslip
