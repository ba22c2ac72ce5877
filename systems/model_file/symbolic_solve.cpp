// A mode's sticking forces (compiler.hpp): h_c' = sum_j A_cj F_j + b_c = 0
// for the sticking contacts c, solved by Cramer's rule (at most 4 of them),
// without GiNaC's lsolve, whose normal() expands powers of sums and whose
// choice of pivots followed GiNaC's run-to-run term order. And a law's
// smoothness where every slip starts, s = 0.
#include <ginac/ginac.h>

#include <cmath>

#include "model_file/compiler.hpp"

namespace stickslip::model_file {

using GiNaC::ex;

namespace {

using Matrix = std::vector<std::vector<ex>>;

// Laplace's expansion along the first row (q <= 4: at most 24 products).
ex Det(const Matrix& a) {
  const std::size_t q = a.size();
  if (q == 1) return a[0][0];
  ex sum = 0;
  for (std::size_t j = 0; j < q; ++j) {
    Matrix minor;
    for (std::size_t r = 1; r < q; ++r) {
      std::vector<ex> row;
      for (std::size_t c = 0; c < q; ++c)
        if (c != j) row.push_back(a[r][c]);
      minor.push_back(row);
    }
    sum += (j % 2 ? -1 : 1) * a[0][j] * Det(minor);
  }
  return sum;
}

}  // namespace

void Compiler::Solve(const std::vector<ex>& rates, const std::vector<int>& sticking,
                     std::vector<ex>* lambdas, bool* consistent) const {
  *consistent = true;
  const std::size_t q = sticking.size();
  if (q == 0) return;
  GiNaC::exmap none;
  for (int c : sticking) none[forces_[c]] = 0;
  Matrix a(q, std::vector<ex>(q));
  std::vector<ex> b(q);
  for (std::size_t r = 0; r < q; ++r) {
    for (std::size_t j = 0; j < q; ++j) a[r][j] = rates[r].diff(forces_[sticking[j]]);
    b[r] = rates[r].subs(none);
  }
  const ex det = Det(a);
  // Singular where the determinant vanishes at the defaults on three states
  // (the origin and two others): the set's forces are then not determined.
  bool regular = false;
  for (double scale : {0.0, 0.37, -0.61}) {
    std::vector<double> z(state_.size());
    for (std::size_t t = 0; t < z.size(); ++t) z[t] = scale * (1 + 0.3 * static_cast<double>(t));
    const double d = At(det, z);
    regular = regular || (std::isfinite(d) && d != 0);
  }
  if (!regular) {
    *consistent = false;
    return;
  }
  for (std::size_t j = 0; j < q; ++j) {
    Matrix aj = a;
    for (std::size_t r = 0; r < q; ++r) aj[r][j] = -b[r];
    lambdas->push_back(Det(aj) / det);
  }
}

void Compiler::CheckLaw(std::size_t c) {
  const ContactSpec& spec = spec_.contacts[c];
  const std::vector<double> zero(state_.size(), 0.0);
  // A power of something that vanishes with s needs a whole exponent >= 0:
  // s^3.5 has finite derivatives up to order 3, yet its recurrence divides by s.
  for (auto it = law_[c].preorder_begin(); it != law_[c].preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::power>(*it) || !it->op(0).has(s_)) continue;
    const ex q = it->op(1);
    const bool whole =
        GiNaC::is_a<GiNaC::numeric>(q) && GiNaC::ex_to<GiNaC::numeric>(q).is_nonneg_integer();
    const bool base_vanishes = std::abs(At(it->op(0).subs(s_ == 0), zero)) == 0;
    if (!whole && base_vanishes)
      Fail(spec_.source, spec.law.line,
           "law " + spec.name + " = '" + spec.law.text +
               "' is not smooth at s = 0: a power of s needs a numeric whole exponent >= 0 "
               "(every slip starts at s = 0)");
  }
  ex d = law_[c];
  for (int k = 0; k <= 3; ++k, d = d.diff(s_)) {
    double v = NAN;
    try {
      v = At(d.subs(s_ == 0), zero);
    } catch (const std::exception&) {
    }
    if (!std::isfinite(v))
      Fail(spec_.source, spec.law.line,
           "law " + spec.name + " = '" + spec.law.text + "' is not smooth at s = 0 (its " +
               (k ? "derivative of order " + std::to_string(k) : std::string("value")) +
               " there is not finite at the parameters given): every slip starts at s = 0, "
               "and a power s^a needs a whole a >= 0");
  }
}

}  // namespace stickslip::model_file
