// A user's own law in a model file against an independent integrator: the
// belt with mu(s) = mu_k + (mu_s - mu_k) / (1 + (s / v_s)^2) (no built-in law
// has this form). Its stick-slip orbit from the stick exit (mu_s - 2 beta v,
// v): the slip phase integrated by Boost.Odeint's Dormand-Prince 5(4) with
// dense output in long double at 1e-18, the return to x' = v found by
// bisection on the dense output, then the stick phase in closed form,
// x = x_a + v t until x + 2 beta v = mu_s. Shares no code with the library.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop

#include "model_file/model_file.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip::model_file {
namespace {

using LReal = long double;
using State = std::array<LReal, 2>;

constexpr LReal kBeta = 0.05L, kV = 0.3L, kMuS = 0.4L, kMuK = 0.25L, kVs = 0.3L;

const char* kModel =
    "name = lorentzian belt\n"
    "coordinates = x\n"
    "parameter beta = 0.05\nparameter v = 0.3\nparameter mu_s = 0.4\n"
    "parameter mu_k = 0.25\nparameter v_s = 0.3\n"
    "x'' = -2*beta*x' - x + F\n"
    "contact F = x' - v\n"
    "law F = mu_k + (mu_s - mu_k)/(1 + (s/v_s)^2)\n";

// The period of the orbit through the stick exit, independently.
LReal ReferencePeriod() {
  namespace odeint = boost::numeric::odeint;
  auto field = [](const State& z, State& dz, LReal) {
    const LReal s = kV - z[1];  // slipping below the belt
    const LReal mu = kMuK + (kMuS - kMuK) / (1 + (s / kVs) * (s / kVs));
    dz[0] = z[1];
    dz[1] = -2 * kBeta * z[1] - z[0] + mu;
  };
  const LReal x_exit = kMuS - 2 * kBeta * kV;
  auto stepper = odeint::make_dense_output(LReal(1e-18), LReal(1e-18),
                                           odeint::runge_kutta_dopri5<State, LReal>());
  stepper.initialize(State{x_exit, kV}, 0, LReal(1e-4));
  stepper.do_step(field);  // off the surface, below it
  while (stepper.current_state()[1] < kV) stepper.do_step(field);
  LReal lo = stepper.previous_time(), hi = stepper.current_time();
  State z{};
  for (int i = 0; i < 200 && hi - lo > 1e-19L * hi; ++i) {  // x' = v on the dense output
    const LReal mid = (lo + hi) / 2;
    stepper.calc_state(mid, z);
    (z[1] < kV ? lo : hi) = mid;
  }
  stepper.calc_state(hi, z);
  EXPECT_LE(std::abs(z[0] + 2 * kBeta * kV), kMuS);  // it sticks there
  return hi + (x_exit - z[0]) / kV;                  // then rides the belt to the exit
}

TEST(ModelFileLaw, AUsersLawMatchesAnIndependentIntegrator) {
  const std::unique_ptr<System> s = ParseModel(kModel, "lorentzian.ini");
  ShootingOptions o;
  o.flow.rtol = o.flow.atol = 1e-13;
  const FlowPoint exit{0, Eigen::Vector2d(0.4 - 2 * 0.05 * 0.3, 0.3), ModeSet(Mode::kSlipBelow)};
  const PeriodicOrbit orbit = Shooting(*s, o).Find(exit, PoincareSection::StickExit(0));
  ASSERT_TRUE(orbit.ok()) << orbit.message;
  EXPECT_EQ(orbit.sticks, 1);
  EXPECT_NEAR(orbit.period, static_cast<double>(ReferencePeriod()), 1e-12);  // 1.8e-15 measured
}

}  // namespace
}  // namespace stickslip::model_file
