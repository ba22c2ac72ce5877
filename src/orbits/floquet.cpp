// The Floquet multipliers of DP (floquet.hpp): a 2 x 2 block in closed
// form, larger ones by Eigen's EigenSolver; an event section's 0 deflated by
// a Householder reflection.
#include "orbits/floquet.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "numerics/max_abs.hpp"

namespace stickslip::floquet_detail {

// The eigenvalues of M by modulus, the largest first (2 x 2 in closed form:
// lambda^2 - tr lambda + det = 0).
std::vector<std::complex<double>> Eigenvalues(Eigen::Ref<const Eigen::MatrixXd> M) {
  std::vector<std::complex<double>> e;
  if (M.rows() == 2) {
    // det as Eigen's partial-pivoting LU gives it, to the bit, without its
    // dynamic-size code: rows swapped when |m10| > |m00|, then -+ u00 u11
    // (no division where u00 = 0, as the LU's).
    const bool swap = std::abs(M(1, 0)) > std::abs(M(0, 0));
    const double u00 = swap ? M(1, 0) : M(0, 0);
    const double u11 =
        (swap ? M(0, 1) : M(1, 1)) - (swap ? M(0, 0) : M(1, 0)) / u00 * (swap ? M(1, 1) : M(0, 1));
    const double tr = M(0, 0) + M(1, 1);
    const double det =
        u00 == 0 ? u00 * (M(1, 1) - M(1, 0) * M(0, 1)) : (swap ? -(u00 * u11) : u00 * u11);
    const std::complex<double> disc = std::sqrt(std::complex<double>(tr * tr / 4 - det));
    e = {tr / 2 + disc, tr / 2 - disc};
  } else if (M.rows() == 1) {
    e = {M(0, 0)};
  } else if (M.rows() > 2) {
    const Eigen::EigenSolver<Eigen::MatrixXd> es(M, false);
    e.assign(es.eigenvalues().data(), es.eigenvalues().data() + M.rows());
  }
  auto larger = [](const std::complex<double>& a, const std::complex<double>& b) {
    return std::abs(a) > std::abs(b);
  };
  if (e.size() == 2) {  // stable_sort's buffer comes from the heap
    if (larger(e[1], e[0])) std::swap(e[0], e[1]);
  } else if (e.size() > 2) {
    std::stable_sort(e.begin(), e.end(), larger);
  }
  return e;
}

// An event section's DP = (I - f g^T / (g . f)) Phi has g^T DP = 0: its
// multiplier 0 is the flow's direction, not the orbit's. With the
// reflection H = I - c v v^T taking g to a multiple of e_1, B = H DP H has
// a first row of 0, and the rest of the spectrum is its trailing block's
// (deflation by a Householder reflection; Golub & Van Loan 2013, ch. 7).
// g is scaled by its largest entry first (as LAPACK's dlarfg), so that its
// squares neither under- nor overflow. By loops into kept buffers (v, w: n
// each): no temporaries on the heap.
[[gnu::noinline]] void Deflate(const Eigen::MatrixXd& DP, const Eigen::VectorXd& g,
                               Eigen::MatrixXd* B, Eigen::VectorXd* v, Eigen::VectorXd* w) {
  const int n = static_cast<int>(DP.rows());
  B->resize(n, n);
  v->resize(n);
  w->resize(n);
  const double* m = DP.data();
  double *b = B->data(), *vd = v->data(), *wd = w->data();
  const double scale = MaxAbs(g);
  double gg = 0;
  for (int k = 0; k < n; ++k) {
    vd[k] = g[k] / scale;
    gg += vd[k] * vd[k];
  }
  vd[0] += std::copysign(std::sqrt(gg), vd[0]);
  double vv = 0;
  for (int k = 0; k < n; ++k) vv += vd[k] * vd[k];
  const double c = 2 / vv;
  for (int i = 0; i < n; ++i) {  // w = c DP v
    double sum = 0;
    for (int k = 0; k < n; ++k) sum += m[i + k * n] * vd[k];
    wd[i] = c * sum;
  }
  for (int j = 0; j < n; ++j)  // B = DP H
    for (int i = 0; i < n; ++i) b[i + j * n] = m[i + j * n] - wd[i] * vd[j];
  for (int j = 0; j < n; ++j) {  // B = H B
    double sum = 0;
    for (int k = 0; k < n; ++k) sum += vd[k] * b[k + j * n];
    for (int i = 0; i < n; ++i) b[i + j * n] -= c * sum * vd[i];
  }
}

}  // namespace stickslip::floquet_detail
