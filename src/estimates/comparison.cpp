#include "stickslip/estimates/comparison.hpp"

#include <cmath>

#include "numerics/numbers.hpp"
#include "stickslip/estimates/estimates.hpp"

namespace stickslip {

namespace {

void Track(const EstimateCell& c, double p, double* max_err, double* p_at, int* count) {
  if (!c.applies) return;
  ++*count;
  if (std::abs(c.error) > *max_err) {
    *max_err = std::abs(c.error);
    *p_at = p;
  }
}
// Why the estimates do not apply to this model, or empty.
std::string NotApplicable(const Params& base, const ParameterAxis& param) {
  if (base.law != LawKind::kCubic)
    return std::string("the estimates are for the cubic law, not ") + Name(base.law);
  const bool k5 = param.id() == Parameter::kK5;
  if (base.k5 != 0 || k5)
    return std::string("the estimates are for the cubic law without the quintic term (k5 = 0)") +
           (k5 ? ", and k5 is the continued parameter" : "");
  return "";
}

// The closed forms at the branch's special points (GR and HB in v, HB in beta).
void AddSpecialEstimates(const Params& base, const ContinuationResult& r,
                         EstimateComparison* out_) {
  EstimateComparison& out = *out_;
  const Parameter param = r.param.id();
  for (const SpecialPoint& s : r.special) {
    const Params at = r.param.At(base, s.p);
    const AveragingEstimate avg0 = EstimateAveraging(at);
    if (s.kind == SpecialKind::kGrazing && param == Parameter::kV)
      out.special.push_back(
          {"GR", "averaging: a_ps = v, 2 sqrt((k1 - 2 beta)/(15 k3))", s.p, avg0.grazing_speed});
    if (s.kind == SpecialKind::kHopf && param == Parameter::kV)
      out.special.push_back({"HB", "seed (3.16): sqrt((k1 - 2 beta)/(3 k3))", s.p, SeedVMax(at)});
    if (s.kind == SpecialKind::kHopf && param == Parameter::kBeta)
      out.special.push_back({"HB", "(k1 - 3 k3 v^2) / 2", s.p, avg0.hopf_beta});
  }
}
}  // namespace

EstimateComparison CompareEstimates(const Params& base, const ContinuationResult& r,
                                    int check_points, const std::function<bool()>& cancelled) {
  EstimateComparison out;
  out.reason = NotApplicable(base, r.param);
  if (!out.reason.empty()) return out;
  out.applies = true;
  const size_t n = r.points.size();
  ExtraColumn r1{"r1", std::vector<double>(n, kNan)};
  ExtraColumn err_r1{"err_r1", std::vector<double>(n, kNan)};
  ExtraColumn a_ps{"a_ps", std::vector<double>(n, kNan)};
  ExtraColumn err_a_ps{"err_a_ps", std::vector<double>(n, kNan)};
  ExtraColumn xb_lo{"x_bound_min", std::vector<double>(n, kNan)};
  ExtraColumn xb_hi{"x_bound_max", std::vector<double>(n, kNan)};
  ExtraColumn xb_ok{"x_bound_holds", std::vector<double>(n, kNan)};
  SeedEstimateOptions seed_opts;
  seed_opts.bounds.check_points = check_points;
  for (size_t i = 0; i < n; ++i) {
    const BranchPoint& pt = r.points[i];
    // Steady sliding, and the zero-amplitude end of a pure-slip branch at HB,
    // are not orbits to compare with.
    if (pt.kind == PointKind::kEquilibrium || pt.extrema.x_max == pt.extrema.x_min) continue;
    if (cancelled && cancelled()) {
      out.cancelled = true;
      break;
    }
    const Params q = r.param.At(base, pt.p);
    ComparisonRow row;
    row.p = pt.p;
    row.kind = pt.kind;
    row.xdot_min = pt.extrema.xdot_min;
    // The seed: r1 estimates the smallest slip velocity x'_min (section 4).
    const SeedEstimate seed = EstimateSeed(q, seed_opts);
    if (seed.bounds.roots.applies) {
      row.r1 = {true, seed.velocity_amplitude, pt.extrema.xdot_min,
                seed.velocity_amplitude - pt.extrema.xdot_min, ""};
      r1.values[i] = row.r1.estimate;
      err_r1.values[i] = row.r1.error;
    } else {
      row.r1.note = "n/a: " + seed.bounds.roots.reason;
    }
    if (std::isfinite(seed.x_max_bound)) {
      const bool holds =
          pt.extrema.x_max <= seed.x_max_bound && pt.extrema.x_min >= seed.x_min_bound;
      row.x_max_bound = {true, seed.x_max_bound, pt.extrema.x_max,
                         seed.x_max_bound - pt.extrema.x_max, holds ? "holds" : "violated"};
      xb_lo.values[i] = seed.x_min_bound;
      xb_hi.values[i] = seed.x_max_bound;
      xb_ok.values[i] = holds ? 1 : 0;
      (holds ? out.bound_holds : out.bound_fails)++;
    } else {
      row.x_max_bound.note = "n/a";
    }
    // Averaging: x' ~ a_ps cos t on a pure-slip orbit, so x'_min ~ -a_ps.
    const AveragingEstimate avg = EstimateAveraging(q);
    if (std::isfinite(avg.amplitude)) a_ps.values[i] = avg.amplitude;
    if (avg.applies && pt.kind == PointKind::kPureSlip) {
      row.a_ps = {true, -avg.amplitude, pt.extrema.xdot_min, -avg.amplitude - pt.extrema.xdot_min,
                  ""};
      err_a_ps.values[i] = row.a_ps.error;
    } else {
      row.a_ps.note = pt.kind == PointKind::kStickSlip
                          ? "n/a: averaging assumes pure slip; this orbit sticks"
                          : "n/a: " + avg.reason;
    }
    Track(row.r1, pt.p, &out.max_err_r1, &out.p_max_err_r1, &out.r1_applies);
    Track(row.a_ps, pt.p, &out.max_err_a_ps, &out.p_max_err_a_ps, &out.a_ps_applies);
    out.rows.push_back(row);
  }
  out.columns = {r1, err_r1, a_ps, err_a_ps, xb_lo, xb_hi, xb_ok};
  if (out.cancelled) return out;

  AddSpecialEstimates(base, r, &out);
  return out;
}

}  // namespace stickslip
