// Special points of an orbit branch between two rows (orbit_locate.hpp).
#include "orbit_locate.hpp"

#include <algorithm>
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
  const VectorXd& scale = palc.options().scale;
  const VectorXd w = scale.size() ? VectorXd(t.cwiseQuotient(scale)) : t;
  // Each point polished as a row is (OrbitProblem::Polish), also where its
  // switching counts change: the corrector's last point lies up to its last
  // update (1e-11) off the branch, and the test's sign on the branch decides
  // the bisection (near a sliding point, the side).
  auto at = [&](double s, double* g) {
    PalcCorrection c = palc.Correct(a + s * (b - a), t);
    if (!c.ok) return false;
    problem.Polish(&w, &c.u, false);
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

void TestPoints(Palc& palc, OrbitProblem& problem, const TracePoint& a, const TracePoint& b,
                double tol, std::vector<OrbitRow>* found, int depth) {
  if (!SameStructure(a.row, b.row)) return;
  const double step = Tolerances::kBranchMultiplierStep;
  const bool far = MultiplierMove(a.row, b.row) > step;
  const bool near = NearCritical(a.row, step) || NearCritical(b.row, step);
  if ((far && depth < Tolerances::kBranchSplitDepth) || (near && depth == 0)) {
    const PalcCorrection c = palc.Correct(0.5 * (a.u + b.u), ChordTangent(palc, a.u, b.u));
    if (c.ok) {
      const TracePoint mid{c.u, problem.Row()};
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

namespace {

// The edge behind a failed or far-apart chord bracket br (span: the chord's
// parameter span; range: the branch's): along the chord, or behind a corner
// of the branch (two branches meeting at the edge), so both ways; b_row is
// the chord's far end.
Bracket AcrossEdge(OrbitProblem& problem, const Bracket& br, bool chord, double span,
                   const OrbitRow& b_row, const double range[2], double tol) {
  Bracket out = br, fine;
  const double step = std::max(std::abs(span) / Tolerances::kBranchEdgeSteps,
                               Tolerances::kBranchEdgeStep * (1 + std::abs(out.lo.p)));
  bool found_edge = false, edge_only = false;
  for (const double sign : {1.0, -1.0}) {
    if (found_edge || edge_only) break;
    const double d = sign * (span > 0 ? 1 : -1);
    // Never past the branch's range (validated; beyond it the system may not be).
    const double limit =
        std::clamp(out.lo.p + d * Tolerances::kBranchEdgeReach * step, range[0], range[1]);
    std::string why;
    found_edge = JumpAcross(problem, out.lo, d, step, limit, tol, &fine.lo, &fine.hi, &why);
    // The edge bisected with no orbit of the same period just beyond (the
    // branch went on to one far away): the edge is the point, b the far side.
    edge_only = !found_edge && std::isfinite(fine.lo.p);
  }
  if (found_edge) {
    out = fine;
  } else if (edge_only) {
    out.lo = fine.lo, out.hi = b_row;
  } else if (!chord) {
    out.hi = b_row;
  }
  return out;
}

}  // namespace

bool Sliding(Palc& palc, OrbitProblem& problem, const TracePoint& a, const TracePoint& b,
             const double range[2], double tol, std::vector<OrbitRow>* found,
             std::vector<std::pair<TracePoint, TracePoint>>* pieces) {
  const int k_p = problem.parameter_index();
  const double edge_gap = Tolerances::kBranchEdgeGap * tol;
  TracePoint piece = a;
  OrbitRow ref = a.row, first_lo;
  VectorXd from = a.u;
  bool jumped = false;
  const std::size_t first = found->size();
  for (int k = 0; k < Tolerances::kBranchEdges && !SameStructure(ref, b.row); ++k) {
    auto test = [&] { return SameStructure(problem.Row(), ref) ? 1.0 : -1.0; };
    Bracket br;
    // On the chord; where the corrector fails there, the edge of the orbits
    // of ref's sequence (a jump of the map).
    const bool chord = Locate(palc, problem, from, b.u, test, tol, &br);
    if (!chord && !Locate(palc, problem, from, b.u, test, tol, &br, true)) break;
    // Where the map jumps or the branch turns a corner, the chord's planes
    // meet it short of the edge or either side of it far apart: the edge is
    // found by natural steps from the last orbit of ref's sequence.
    const double gap = std::max(std::abs(br.hi.p - br.lo.p),
                                (br.hi.start.z - br.lo.start.z).lpNorm<Eigen::Infinity>());
    const double size = 1 + std::abs(br.lo.p) + br.lo.start.z.lpNorm<Eigen::Infinity>();
    if (!chord || gap > edge_gap * size) {
      br = AcrossEdge(problem, br, chord, b.u[k_p] - from[k_p], b.row, range, tol);
      jumped = true;
    }
    // Edges within the tolerance are one point (the two halves of a
    // symmetric orbit on a floor reach the static limit together).
    const bool same = found->size() > first &&
                      std::abs(br.lo.p - found->back().p) <= edge_gap * (1 + std::abs(br.lo.p));
    if (same) found->pop_back();
    if (!same) first_lo = br.lo;
    OrbitRow point = first_lo;
    ClassifySliding(problem, first_lo, br.hi, &point);
    found->push_back(point);
    pieces->push_back({piece, {problem.Unknowns(br.lo.start, br.lo.p), br.lo}});
    piece = {problem.Unknowns(br.hi.start, br.hi.p), br.hi};
    if (SameStructure(br.hi, ref)) break;
    ref = br.hi;
    from = piece.u;
  }
  pieces->push_back({piece, b});
  return jumped;
}

}  // namespace stickslip::orbit_detail
