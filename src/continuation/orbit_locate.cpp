// Special points of an orbit branch between two rows (orbit_locate.hpp).
#include "orbit_locate.hpp"

#include <cmath>
#include <string>

#include "numerics/tolerances.hpp"

namespace stickslip::orbit_detail {

using Eigen::VectorXd;

namespace {

// The chord a -> b's unit direction in Palc's scaled coordinates.
VectorXd ChordTangent(const Palc& palc, const VectorXd& a, const VectorXd& b) {
  const VectorXd& scale = palc.options().scale;
  const VectorXd chord = scale.size() ? VectorXd((b - a).cwiseQuotient(scale)) : VectorXd(b - a);
  return chord.normalized();
}

// A multiplier within d of -1 or +1, or (a complex one) of the unit circle.
bool NearCritical(const OrbitRow& r, double d) {
  for (const std::complex<double>& mu : r.multipliers)
    if (std::abs(mu + 1.0) < d || std::abs(mu - 1.0) < d ||
        (mu.imag() != 0 && std::abs(std::abs(mu) - 1) < d))
      return true;
  return false;
}

bool HasComplex(const OrbitRow& r) {
  for (const auto& mu : r.multipliers)
    if (mu.imag() != 0) return true;
  return false;
}

const SpecialKind kKinds[3] = {SpecialKind::kFold, SpecialKind::kPeriodDoubling,
                               SpecialKind::kTorus};
const char* const kWhat[3] = {"fold: a multiplier at +1", "period doubling: a multiplier at -1",
                              "Neimark-Sacker: a complex pair on the unit circle"};

}  // namespace

bool Locate(Palc& palc, OrbitProblem& problem, const VectorXd& a, const VectorXd& b,
            const std::function<double()>& test, double tol, Bracket* out, bool fail_is_hi) {
  const VectorXd t = ChordTangent(palc, a, b);
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
  double g = 0;
  if (!at(0.5 * (lo + hi), &g)) {
    if (!fail_is_hi) return false;
    out->mid = out->lo;
    return true;
  }
  out->mid = problem.Row();
  return true;
}

void TestPoints(Palc& palc, OrbitProblem& problem, const BranchPoint& a, const BranchPoint& b,
                double tol, std::vector<OrbitRow>* found, int depth) {
  if (!SameStructure(a.row, b.row)) return;
  const double step = Tolerances::kBranchMultiplierStep;
  const bool far = MultiplierMove(a.row, b.row) > step;
  const bool near = NearCritical(a.row, step) || NearCritical(b.row, step);
  if ((far && depth < Tolerances::kBranchSplitDepth) || (near && depth == 0)) {
    const PalcCorrection c = palc.Correct(0.5 * (a.u + b.u), ChordTangent(palc, a.u, b.u));
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
    if (i == 2 && !(HasComplex(a.row) && HasComplex(b.row))) continue;
    Bracket br;
    auto test = [&] { return RowTest(problem.Row(), i); };
    if (!Locate(palc, problem, a.u, b.u, test, tol, &br)) continue;
    if (!SameStructure(br.mid, a.row)) continue;
    if (i == 2 && !TorusPair(br.mid, Tolerances::kBranchTorusPair)) continue;
    br.mid.label = kKinds[i];
    br.mid.description = kWhat[i];
    found->push_back(br.mid);
  }
}

namespace {
std::string Change(const char* what, int a, int b) {
  return a == b ? ""
                : std::string(", ") + what + " " + std::to_string(a) + " -> " + std::to_string(b);
}
}  // namespace

std::string SequenceChange(const OrbitRow& a, const OrbitRow& b) {
  return Change("sticks", a.sticks, b.sticks) + Change("exits", a.exits, b.exits) +
         Change("crossings", a.crossings, b.crossings);
}

void Sliding(Palc& palc, OrbitProblem& problem, const BranchPoint& a, const BranchPoint& b,
             double tol, std::vector<OrbitRow>* found,
             std::vector<std::pair<BranchPoint, BranchPoint>>* pieces) {
  BranchPoint piece = a;
  OrbitRow ref = a.row;
  VectorXd from = a.u;
  for (int k = 0; k < Tolerances::kBranchEdges && !SameStructure(ref, b.row); ++k) {
    auto test = [&] { return SameStructure(problem.Row(), ref) ? 1.0 : -1.0; };
    Bracket br;
    // On the chord; where the corrector fails there, the edge of the orbits
    // of ref's sequence (a jump of the map).
    if (!Locate(palc, problem, from, b.u, test, tol, &br) &&
        !Locate(palc, problem, from, b.u, test, tol, &br, true))
      break;
    // Where the branch turns a corner the chord's planes meet it on either
    // side far apart: then the edge is bisected in p (BisectEdge).
    const double gap = std::max(std::abs(br.hi.p - br.lo.p),
                                (br.hi.start.z - br.lo.start.z).lpNorm<Eigen::Infinity>());
    const double size = 1 + std::abs(br.lo.p) + br.lo.start.z.lpNorm<Eigen::Infinity>();
    OrbitRow point = br.lo;
    if (gap > Tolerances::kBranchEdgeGap * tol * size) {
      BisectEdge(problem, br.lo, br.hi, tol, &point);
      br.lo = point;
    }
    point.label = SpecialKind::kSliding;
    point.description = "the switching sequence changes" + SequenceChange(br.lo, br.hi);
    found->push_back(point);
    const BranchPoint lo{problem.Unknowns(br.lo.start, br.lo.p), br.lo};
    const BranchPoint hi{problem.Unknowns(br.hi.start, br.hi.p), br.hi};
    pieces->push_back({piece, lo});
    piece = hi;
    ref = br.hi;
    from = hi.u;
  }
  pieces->push_back({piece, b});
}

}  // namespace stickslip::orbit_detail
