#include "stickslip/continuation/palc.hpp"

#include <cmath>
#include <sstream>

#include "numerics/stall.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

using Eigen::MatrixXd;
using Eigen::VectorXd;

std::string PalcOptions::ValidationError(int unknowns) const {
  std::ostringstream os;
  if (unknowns < 2) {
    os << "unknowns = " << unknowns << " must be >= 2";
  } else if (!(ds_min > 0 && ds_min <= ds && ds <= ds_max && std::isfinite(ds_max))) {
    os << "steps must satisfy 0 < ds_min <= ds <= ds_max: ds_min = " << ds_min << ", ds = " << ds
       << ", ds_max = " << ds_max;
  } else if (!(grow >= 1 && std::isfinite(grow))) {
    os << "grow = " << grow << " must be >= 1";
  } else if (max_newton < 1) {
    os << "max_newton = " << max_newton << " must be >= 1";
  } else if (!(tol > 0 && std::isfinite(tol))) {
    os << "tol = " << tol << " must be > 0";
  } else if (max_points < 1) {
    os << "max_points = " << max_points << " must be >= 1";
  } else if (scale.size() != 0 && scale.size() != unknowns) {
    os << "scale has " << scale.size() << " entries, need " << unknowns;
  } else if (scale.size() != 0 && !((scale.array() > 0).all() && scale.allFinite())) {
    os << "scale entries must be finite and > 0";
  }
  return os.str();
}

Palc::Palc(PalcProblem& problem, const PalcOptions& options)
    : problem_(problem), options_(options) {
  const int m = problem.unknowns();
  const std::string err = options.ValidationError(m);
  if (!err.empty()) throw InvalidArgument("Palc: " + err);
  scale_ = options.scale.size() == 0 ? VectorXd::Ones(m) : options.scale;
}

bool Palc::Eval(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string* why) {
  ++evaluations_;
  const int m = problem_.unknowns();
  if (!problem_.Evaluate(u, f, jac, why)) return false;
  if (f->size() != m - 1 || jac->rows() != m - 1 || jac->cols() != m)
    throw InvalidArgument("PalcProblem::Evaluate: F or its Jacobian has the wrong size");
  if (!f->allFinite() || !jac->allFinite()) {
    *why = "F or its Jacobian is not finite";
    return false;
  }
  return true;
}

VectorXd Palc::Tangent(const MatrixXd& jac, const VectorXd& along) const {
  const int m = static_cast<int>(scale_.size());
  const MatrixXd js = jac * scale_.asDiagonal();
  VectorXd t(m);
  if (m == 2) {
    // One equation: the null vector of (j1, j2) is (-j2, j1).
    const double n = std::hypot(js(0, 0), js(0, 1));
    t << -js(0, 1) / n, js(0, 0) / n;
  } else {
    // The last column of Q in J_s^T = Q R spans the null space of J_s.
    const Eigen::HouseholderQR<MatrixXd> qr(js.transpose());
    t = qr.householderQ() * VectorXd::Unit(m, m - 1);
    t.normalize();
  }
  if (along.size() == m && t.dot(along) < 0) t = -t;
  return t;
}

namespace {
// Solves a x = rhs; false if a is singular. 2 x 2 by Cramer's rule, larger by LU.
bool SolveBordered(const MatrixXd& a, const VectorXd& rhs, VectorXd* x) {
  if (a.rows() == 2) {
    const double det = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
    if (det == 0 || !std::isfinite(det)) return false;
    x->resize(2);
    *x << (rhs[0] * a(1, 1) - a(0, 1) * rhs[1]) / det, (a(0, 0) * rhs[1] - a(1, 0) * rhs[0]) / det;
    return true;
  }
  const Eigen::PartialPivLU<MatrixXd> lu(a);
  const double det = lu.determinant();
  if (det == 0 || !std::isfinite(det)) return false;
  *x = lu.solve(rhs);
  return true;
}
}  // namespace

PalcCorrection Palc::Correct(const VectorXd& pred, const VectorXd& tangent) {
  const int m = static_cast<int>(scale_.size());
  problem_.BeginCorrection();
  PalcCorrection c;
  VectorXd u = pred;
  double last_step = HUGE_VAL;
  MatrixXd a(m, m);
  VectorXd rhs(m);
  for (int it = 1; it <= options_.max_newton; ++it) {
    c.iterations = it;
    c.u = u;
    if (!Eval(u, &c.f, &c.jac, &c.why)) return c;
    // Bordered system [J_s; t^T] du_s = -[F; t . (u_s - pred_s)] (Keller 1977).
    a.topRows(m - 1) = c.jac * scale_.asDiagonal();
    a.row(m - 1) = tangent.transpose();
    rhs.head(m - 1) = -c.f;
    rhs[m - 1] = -tangent.dot((u - pred).cwiseQuotient(scale_));
    VectorXd du_s;
    if (!SolveBordered(a, rhs, &du_s)) {
      c.why = "singular corrector";
      return c;
    }
    u += du_s.cwiseProduct(scale_);
    const double step = du_s.lpNorm<1>();
    if (NewtonConverged(step, last_step, it, options_.tol, &c.stalled)) {
      c.ok = true;
      return c;
    }
    last_step = step;
    c.why = problem_.DomainError(u);
    if (!c.why.empty()) return c;
  }
  c.why = "corrector did not converge in " + std::to_string(options_.max_newton) + " iterations";
  return c;
}

PalcCorrection Palc::CorrectFixed(const VectorXd& pred, int k) {
  const int m = static_cast<int>(scale_.size());
  if (k < 0 || k >= m) throw InvalidArgument("Palc::CorrectFixed: no unknown " + std::to_string(k));
  return Correct(pred, VectorXd::Unit(m, k));
}

namespace {
// The plain loop's hooks: the monitor sees every accepted point.
class MonitorHooks : public PalcHooks {
 public:
  explicit MonitorHooks(const PalcMonitor& monitor) : monitor_(monitor) {}
  bool Accepted(const std::vector<PalcPoint>& curve) override {
    return !monitor_ || monitor_(curve);
  }

 private:
  const PalcMonitor& monitor_;
};
}  // namespace

PalcResult Palc::Trace(const VectorXd& u0, int fixed, const VectorXd& direction,
                       const PalcMonitor& monitor) {
  const int before = evaluations_;
  const PalcCorrection c = CorrectFixed(u0, fixed);
  PalcResult r;
  if (c.ok) {
    const PalcPoint first{c.u, Tangent(c.jac, direction), c.iterations, c.stalled, {}};
    if (monitor && !monitor({first})) {
      r.points.push_back(first);
      r.status = PalcStatus::kStopped;
    } else {
      MonitorHooks hooks(monitor);
      r = Continue(first, options_.ds, hooks);
    }
  } else {
    r.status = PalcStatus::kStartFailed;
    r.message = c.why;
  }
  r.newton_iterations += c.iterations;
  r.evaluations = evaluations_ - before;
  return r;
}

PalcResult Palc::Continue(const PalcPoint& first, double ds, PalcHooks& hooks) {
  PalcResult r;
  const int before = evaluations_;
  auto finish = [&](PalcStatus s, const std::string& message) {
    r.status = s;
    r.message = message;
    r.evaluations = evaluations_ - before;
    return r;
  };
  r.points.push_back(first);
  const VectorXd first_s = first.u.cwiseQuotient(scale_);
  double travelled = 0;
  while (static_cast<int>(r.points.size()) < options_.max_points) {
    if (options_.cancelled && options_.cancelled())
      return finish(PalcStatus::kStopped, "cancelled");
    const PalcPoint& last = r.points.back();
    const VectorXd pred = hooks.Predict(last, ds, scale_);
    PalcAction act = hooks.Predicted(last, pred, &ds);
    if (act == PalcAction::kEnd) return finish(PalcStatus::kStopped, "");
    if (act == PalcAction::kRetry) continue;
    const PalcCorrection c = Correct(pred, last.tangent);
    r.newton_iterations += c.iterations;
    if (!c.ok) {
      act = hooks.Rejected(last, c, pred, &ds);
      if (act == PalcAction::kEnd) return finish(PalcStatus::kStopped, "");
      if (act == PalcAction::kRetry) continue;
      ++r.rejected_steps;
      ds *= 0.5;
      if (ds < options_.ds_min) return finish(PalcStatus::kStepTooSmall, c.why);
      continue;
    }
    PalcPoint next{c.u, Tangent(c.jac, last.tangent), c.iterations, c.stalled, {}};
    for (int k = 0; k < next.tangent.size(); ++k)
      if (next.tangent[k] * last.tangent[k] < 0) next.folds.push_back(k);
    act = hooks.Converged(last, c, &next, &ds);
    if (act == PalcAction::kEnd) return finish(PalcStatus::kStopped, "");
    if (act == PalcAction::kRetry) continue;
    const VectorXd a = last.u.cwiseQuotient(scale_), d = next.u.cwiseQuotient(scale_) - a;
    const double step = d.norm();
    travelled += step;
    r.points.push_back(std::move(next));
    if (!hooks.Accepted(r.points)) return finish(PalcStatus::kStopped, "");
    // The last chord passes through the first point, moving the same way: a
    // closed curve.
    const double s = (first_s - a).dot(d) / d.squaredNorm();
    if (options_.closed_curves && travelled > 3 * step && s >= 0 && s <= 1 &&
        (a + s * d - first_s).norm() < Tolerances::kClosedCurveGap * step &&
        r.points.back().tangent.dot(r.points.front().tangent) > 0)
      return finish(PalcStatus::kClosed, "");
    if (c.iterations <= options_.fast_iterations)
      ds = std::min(ds * options_.grow, options_.ds_max);
  }
  return finish(PalcStatus::kMaxPoints,
                "more than max_points = " + std::to_string(options_.max_points) + " points");
}

}  // namespace stickslip
