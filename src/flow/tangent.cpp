// The tangent block of a run (engine.hpp): M = dz/dz0 and the column C =
// dz/dp at the start, across each segment, and across each switch by its
// saltation matrix (Leine & Nijmeijer 2004, section 7.3; di Bernardo et al.
// 2008, section 2.5).
#include <Eigen/Dense>

#include "flow/engine.hpp"

namespace stickslip::flow_detail {

// A start in stick has no direction off its surface: Phi projected on it.
void Engine::ProjectStartTangent() {
  for (int i = 0; i < k_; ++i) {
    if (!mode_.sticks(i)) continue;
    const ContactVelocity& c = contacts_[i];
    Eigen::VectorXd& g = grad_;  // scratch (no temporary per start)
    g.setZero(nt_);
    for (int t = 0; t < c.size; ++t)
      if (c.terms[t].index < nt_) g[c.terms[t].index] += c.terms[t].weight;
    const double g2 = g.squaredNorm();
    if (!(g2 > 0)) continue;
    row_.noalias() = g.transpose() * M_;
    for (int col = 0; col < nt_; ++col)
      for (int r = 0; r < nt_; ++r) M_(r, col) -= g[r] * row_[col] / g2;
    // And the start moved onto the surface as the parameter moves it (h = g z - s(p)).
    if (column_) C_ -= g * (ArrivalDp(i) / g2);
  }
}

// M <- Phi M and, with the column, C <- Phi C + the segment's own column.
// nt = 2 (the belt, the forced oscillator) on fixed sizes: no dynamic-size
// product kernels per segment, and the same sums of two products.
void Engine::AdvanceTangent(const double* y, const TaylorLayout& layout) {
  if (nt_ == 2) {
    const Eigen::Map<const Eigen::Matrix2d> phi(y + n_);
    Eigen::Map<Eigen::Matrix2d> M(M_.data());
    const Eigen::Matrix2d pm = phi * M;
    M = pm;
    if (column_) {
      Eigen::Map<Eigen::Vector2d> C(C_.data());
      const Eigen::Vector2d pc = phi * C;
      C = pc + Eigen::Map<const Eigen::Vector2d>(y + layout.param());
    }
    return;
  }
  Eigen::Map<const Eigen::MatrixXd> phi(y + n_, nt_, nt_);
  tmp_.noalias() = phi * M_;
  M_.swap(tmp_);
  if (column_) {
    ctmp_.noalias() = phi * C_;
    C_ = ctmp_ + Eigen::Map<const Eigen::VectorXd>(y + layout.param(), nt_);
  }
}

void Engine::Saltation(const ModeSet& before, const ModeSet& after, const Eigen::VectorXd& grad,
                       double g_p) {
  if (!variational_) return;
  f_before_.resize(n_);
  f_after_.resize(n_);
  s_->Field(before, z_, f_before_);
  s_->Field(after, z_, f_after_);
  const double den = grad.dot(f_before_);
  if (den == 0) return;  // a tangential event: no finite saltation (measure zero)
  // M <- S M = M + ((f+ - f-) / den) (grad^T M), on the tangent block.
  jump_ = (f_after_ - f_before_).head(nt_) / den;
  if (nt_ == 2) {  // fixed sizes, as AdvanceTangent
    Eigen::Map<Eigen::Matrix2d> M(M_.data());
    const Eigen::RowVector2d row = grad.head<2>().transpose() * M;
    M.noalias() += jump_.head<2>() * row;
  } else {
    row_.noalias() = grad.head(nt_).transpose() * M_;
    M_.noalias() += jump_ * row_;
  }
  if (!column_) return;
  // The parameter as a state of rate 0: the event time moves by -(grad .
  // dz/dp + g_p) / den, and the column by (f+ - f-) times minus that (the
  // clocks' column is (t - t0) d omega / dp).
  double q = grad.head(nt_).dot(C_) + g_p;
  for (int j = 0; j < n_ - nt_; ++j) q += grad[nt_ + j] * (t_ - t_start_) * clock_drate_[j];
  C_ += jump_ * q;
}

}  // namespace stickslip::flow_detail
