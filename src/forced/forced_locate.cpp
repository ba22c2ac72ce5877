#include "forced_locate.hpp"

#include <algorithm>
#include <cmath>

#include "forced_sliding.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip::forced_detail {

using Eigen::VectorXd;

bool Locate(Palc& palc, StrobeProblem& problem, const VectorXd& a, const VectorXd& b,
            const std::function<double()>& test, double tol, Bracket* out, bool fail_is_hi) {
  const VectorXd chord =
      (b - a).cwiseQuotient(palc.options().scale.size() ? palc.options().scale : VectorXd::Ones(3));
  const VectorXd t = chord.normalized();
  auto at = [&](double s, double* g) {
    const PalcCorrection c = palc.Correct(a + s * (b - a), t);
    if (!c.ok) return false;
    *g = test();
    return true;
  };
  double lo = 0, hi = 1, g_lo = 0, g_hi = 0;
  if (!at(hi, &g_hi)) return false;
  out->hi = problem.Row();
  if (!at(lo, &g_lo) || (g_lo > 0) == (g_hi > 0)) return false;
  out->lo = problem.Row();
  for (int it = 0; it < Tolerances::kBranchBisectionCap && hi - lo > tol; ++it) {
    const double mid = 0.5 * (lo + hi);
    double g = 0;
    if (!at(mid, &g)) {
      if (!fail_is_hi) return false;
      hi = mid;
      continue;
    }
    const bool low = (g > 0) == (g_lo > 0);
    (low ? lo : hi) = mid;
    (low ? out->lo : out->hi) = problem.Row();
  }
  out->p_hi = (a + hi * (b - a))[2];
  if (fail_is_hi) return true;
  double g = 0;
  if (!at(0.5 * (lo + hi), &g)) return false;
  out->mid = problem.Row();
  return true;
}

double RowTest(const ForcedBranchRow& r, int i) {
  const std::complex<double> a = r.multipliers[0], b = r.multipliers[1];
  switch (i) {
    case 0:
      return ((a - 1.0) * (b - 1.0)).real();
    case 1:
      return ((a + 1.0) * (b + 1.0)).real();
    default:
      return (a * b).real() - 1;
  }
}

bool TorusPair(const ForcedBranchRow& r, double tol) {
  const std::complex<double> a = r.multipliers[0], b = r.multipliers[1];
  return a.imag() != 0 && std::abs(a - std::conj(b)) <= tol * std::abs(a) &&
         std::abs(std::abs(a) - 1) <= tol;
}

double MultiplierMove(const ForcedBranchRow& a, const ForcedBranchRow& b) {
  const auto& p = a.multipliers;
  const auto& q = b.multipliers;
  const double straight = std::max(std::abs(p[0] - q[0]), std::abs(p[1] - q[1]));
  const double crossed = std::max(std::abs(p[0] - q[1]), std::abs(p[1] - q[0]));
  return std::min(straight, crossed);
}

namespace {

// A multiplier within d of -1 or +1, or (a complex pair) of the unit circle.
bool NearCritical(const ForcedBranchRow& r, double d) {
  for (const std::complex<double>& mu : r.multipliers)
    if (std::abs(mu + 1.0) < d || std::abs(mu - 1.0) < d ||
        (mu.imag() != 0 && std::abs(std::abs(mu) - 1) < d))
      return true;
  return false;
}

const ForcedLabel kLabels[3] = {ForcedLabel::kLP, ForcedLabel::kPD, ForcedLabel::kNS};
const char* const kWhat[3] = {"fold: a multiplier at +1", "period doubling: a multiplier at -1",
                              "Neimark-Sacker: a complex pair on the unit circle"};

}  // namespace

void TestPoints(Palc& palc, StrobeProblem& problem, const BranchPoint& a, const BranchPoint& b,
                double tol, std::vector<ForcedBranchRow>* found, int depth) {
  if (!SameStructure(a.row, b.row)) return;
  const double step = Tolerances::kBranchMultiplierStep;
  const bool far = MultiplierMove(a.row, b.row) > step;
  const bool near = NearCritical(a.row, step) || NearCritical(b.row, step);
  if ((far && depth < Tolerances::kBranchSplitDepth) || (near && depth == 0)) {
    const VectorXd chord = (b.u - a.u).cwiseQuotient(
        palc.options().scale.size() ? palc.options().scale : VectorXd::Ones(3));
    const PalcCorrection c = palc.Correct(0.5 * (a.u + b.u), chord.normalized());
    if (c.ok) {
      const BranchPoint mid{c.u, problem.Row()};
      TestPoints(palc, problem, a, mid, tol, found, depth + 1);
      TestPoints(palc, problem, mid, b, tol, found, depth + 1);
      return;
    }
  }
  for (int i = 0; i < 3; ++i) {
    if ((RowTest(a.row, i) > 0) == (RowTest(b.row, i) > 0)) continue;
    // NS: a complex pair at both ends (a real pair's product crossing 1 is none).
    if (i == 2 && !(a.row.multipliers[0].imag() != 0 && b.row.multipliers[0].imag() != 0)) continue;
    Bracket br;
    auto test = [&] { return RowTest(problem.Row(), i); };
    if (!Locate(palc, problem, a.u, b.u, test, tol, &br)) continue;
    if (!SameStructure(br.mid, a.row)) continue;
    if (i == 2 && !TorusPair(br.mid, Tolerances::kBranchTorusPair)) continue;
    br.mid.label = kLabels[i];
    br.mid.description = kWhat[i];
    found->push_back(br.mid);
  }
}

}  // namespace stickslip::forced_detail
