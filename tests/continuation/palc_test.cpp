// The physics-free PALC on curves known in closed form: an ellipse (two folds
// in each unknown, closed), a circle in R^3 cut from a sphere by a plane
// (two equations), a domain boundary, and misuse.
#include "stickslip/continuation/palc.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "numerics/stall.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

VectorXd V(double a, double b) { return Eigen::Vector2d(a, b); }
VectorXd V(double a, double b, double c) { return Eigen::Vector3d(a, b, c); }

// x^2 / A^2 + y^2 / B^2 - 1 = 0.
class Ellipse : public PalcProblem {
 public:
  Ellipse(double a, double b) : a_(a), b_(b) {}
  int unknowns() const override { return 2; }
  bool Evaluate(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string*) override {
    f->resize(1);
    (*f)[0] = u[0] * u[0] / (a_ * a_) + u[1] * u[1] / (b_ * b_) - 1;
    jac->resize(1, 2);
    (*jac)(0, 0) = 2 * u[0] / (a_ * a_);
    (*jac)(0, 1) = 2 * u[1] / (b_ * b_);
    return true;
  }
  double a_, b_;
};

TEST(Palc, EllipseClosesWithTwoFoldsInEachUnknown) {
  Ellipse e(2.0, 0.5);
  PalcOptions o;
  o.ds = 0.01;
  o.ds_max = 0.05;
  o.tol = 1e-13;
  Palc palc(e, o);
  // Start off the curve at (2.1, 0), corrected with y = 0 held.
  const PalcResult r = palc.Trace(V(2.1, 0.0), 1, V(0.0, 1.0), nullptr);
  ASSERT_EQ(r.status, PalcStatus::kClosed) << r.message;
  EXPECT_NEAR(r.points.front().u[0], 2.0, 1e-13);
  int folds_x = 0, folds_y = 0;
  double length = 0;
  for (size_t i = 0; i < r.points.size(); ++i) {
    const VectorXd& u = r.points[i].u;
    EXPECT_NEAR(u[0] * u[0] / 4 + u[1] * u[1] / 0.25, 1.0, 1e-12);
    for (int k : r.points[i].folds) {
      // A fold in x (vertical tangent) lies between points on either side
      // of y = 0, a fold in y between points on either side of x = 0.
      const VectorXd& w = r.points[i - 1].u;
      if (k == 0) {
        ++folds_x;
        EXPECT_LE(w[1] * u[1], 0.0);
      } else {
        ++folds_y;
        EXPECT_LE(w[0] * u[0], 0.0);
      }
    }
    if (i > 0) length += (u - r.points[i - 1].u).norm();
  }
  // x folds at (-2, 0) and on closing through (2, 0); y folds at (0, +-0.5).
  EXPECT_EQ(folds_x, 2);
  EXPECT_EQ(folds_y, 2);
  // Ramanujan's perimeter of the ellipse; the last chord ends past the start.
  const double a = 2, b = 0.5, h = std::pow((a - b) / (a + b), 2);
  const double perimeter = M_PI * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
  const double overshoot = (r.points.back().u - r.points.front().u).norm();
  // Chords are shorter than arcs: by sum h^3 kappa^2 / 24, < 5e-3 here.
  EXPECT_LT(length - overshoot, perimeter);
  EXPECT_GT(length - overshoot, perimeter - 5e-3);
  EXPECT_GT(r.points[1].u[1], 0.0);  // went the way it was asked to
}

// Sphere |u| = 2 cut by the plane u0 + u1 + u2 = 1: a circle about (1,1,1)/3.
class SpherePlane : public PalcProblem {
 public:
  int unknowns() const override { return 3; }
  bool Evaluate(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string*) override {
    f->resize(2);
    (*f)[0] = u.squaredNorm() - 4;
    (*f)[1] = u.sum() - 1;
    jac->resize(2, 3);
    jac->row(0) = 2 * u.transpose();
    jac->row(1).setOnes();
    return true;
  }
};

TEST(Palc, CircleInThreeUnknownsStaysOnBothSurfaces) {
  SpherePlane sp;
  PalcOptions o;
  o.ds_max = 0.1;
  Palc palc(sp, o);
  int seen = 0;
  const PalcResult r =
      palc.Trace(V(1.5, 0.0, -0.5), 1, V(0, 1, -1),
                 [&](const std::vector<PalcPoint>& c) { return ++seen < 100000 && !c.empty(); });
  ASSERT_EQ(r.status, PalcStatus::kClosed) << r.message;
  EXPECT_EQ(seen, static_cast<int>(r.points.size()));
  const VectorXd centre = VectorXd::Constant(3, 1.0 / 3);
  const double radius = std::sqrt(4 - 1.0 / 3);
  for (const PalcPoint& p : r.points) {
    EXPECT_NEAR((p.u - centre).norm(), radius, 1e-10);
    EXPECT_NEAR(p.u.sum(), 1.0, 1e-12);
    EXPECT_NEAR(p.tangent.norm(), 1.0, 1e-14);
  }
}

// y = x^2 evaluated only for x < 1: the curve ends at the domain boundary.
class HalfParabola : public PalcProblem {
 public:
  int unknowns() const override { return 2; }
  bool Evaluate(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string* why) override {
    if (u[0] >= 1) {
      *why = "x >= 1";
      return false;
    }
    f->resize(1);
    (*f)[0] = u[1] - u[0] * u[0];
    jac->resize(1, 2);
    (*jac)(0, 0) = -2 * u[0];
    (*jac)(0, 1) = 1;
    return true;
  }
};

TEST(Palc, EndsWithStatusAndReasonAtTheDomainBoundary) {
  HalfParabola hp;
  PalcOptions o;
  o.ds_min = 1e-6;
  Palc palc(hp, o);
  const PalcResult r = palc.Trace(V(0.0, 0.3), 0, V(1, 0), nullptr);
  ASSERT_EQ(r.status, PalcStatus::kStepTooSmall);
  EXPECT_EQ(r.message, "x >= 1");
  EXPECT_GT(r.points.back().u[0], 1 - 1e-5);
  EXPECT_NEAR(r.points.front().u[1], 0.0, 1e-14);  // start corrected at x = 0
  EXPECT_GT(r.rejected_steps, 0);
  // The monitor stops a curve.
  const PalcResult s = palc.Trace(V(0.0, 0.0), 0, V(1, 0),
                                  [](const std::vector<PalcPoint>& c) { return c.size() < 5; });
  EXPECT_EQ(s.status, PalcStatus::kStopped);
  EXPECT_EQ(s.points.size(), 5u);
}

TEST(Palc, MisuseIsAnException) {
  Ellipse e(1, 1);
  PalcOptions o;
  o.ds_min = 1;
  o.ds = 0.1;
  EXPECT_THROW(Palc(e, o), InvalidArgument);
  o = PalcOptions();
  o.scale = VectorXd::Ones(3);
  EXPECT_THROW(Palc(e, o), InvalidArgument);
  Palc palc(e, PalcOptions());
  EXPECT_THROW(palc.CorrectFixed(V(1, 0), 2), InvalidArgument);
}

// Hooks on the unit circle (an ellipse with A = B = 1), from (1, 0)
// counter-clockwise: a loose corrector tolerance, an extra corrector step that
// projects every point onto the circle (the polish), and an end on x = 0
// where the step would cross it (the range end), with the step landing there.
class CircleHooks : public PalcHooks {
 public:
  PalcAction Predicted(const PalcPoint& last, const VectorXd& pred, double* ds) override {
    ++predicted;
    if (pred[0] >= 0) return PalcAction::kGoOn;
    if (*ds > 1e-9 && last.u[0] > 1e-9) {
      *ds = std::min(0.5 * *ds, last.u[0]);  // shorter steps towards x = 0
      return PalcAction::kRetry;
    }
    landed = last.u;
    return PalcAction::kEnd;
  }
  PalcAction Converged(const PalcPoint&, const PalcCorrection& c, PalcPoint* next,
                       double*) override {
    loose = std::max(loose, std::abs(c.u.norm() - 1));
    next->u = c.u / c.u.norm();
    return PalcAction::kGoOn;
  }
  int predicted = 0;
  double loose = 0;
  VectorXd landed;
};

TEST(Palc, HooksPolishEveryPointAndEndTheCurve) {
  Ellipse circle(1.0, 1.0);
  PalcOptions o;
  o.ds = o.ds_max = 0.1;
  o.tol = 1e-3;  // loose: the corrector alone leaves points off the circle
  Palc palc(circle, o);
  CircleHooks hooks;
  const PalcPoint first{V(1.0, 0.0), V(0.0, 1.0), 0, false, {}};
  const PalcResult r = palc.Continue(first, 0.1, hooks);
  ASSERT_EQ(r.status, PalcStatus::kStopped) << r.message;
  EXPECT_GT(hooks.loose, 1e-12);  // the polish had something to do
  for (const PalcPoint& p : r.points) EXPECT_NEAR(p.u.norm(), 1.0, 1e-15);
  // Landed within 1e-9 of (0, 1), a quarter of the circle on.
  ASSERT_EQ(hooks.landed.size(), 2);
  EXPECT_NEAR(hooks.landed[0], 0.0, 1e-8);
  EXPECT_NEAR(hooks.landed[1], 1.0, 1e-15);
  EXPECT_GE(hooks.predicted, static_cast<int>(r.points.size()));
}

TEST(Palc, NewtonStallTest) {
  bool stalled = false;
  EXPECT_TRUE(NewtonConverged(1e-12, 1.0, 1, 1e-11, &stalled));
  EXPECT_FALSE(stalled);
  EXPECT_FALSE(NewtonConverged(5e-9, 6e-9, 2, 1e-11, &stalled));  // too early
  EXPECT_TRUE(NewtonConverged(5e-9, 6e-9, 3, 1e-11, &stalled));
  EXPECT_TRUE(stalled);
  EXPECT_FALSE(NewtonConverged(5e-9, 2e-8, 3, 1e-11, &stalled));  // still halving
}

}  // namespace
}  // namespace stickslip
