// Steady sliding along a parameter, with its HB and LP points (steady_branch.hpp).
#include "stickslip/equilibria/steady_branch.hpp"

#include <cmath>
#include <memory>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

// Where the rest point at p is no sliding state: the first contact whose
// normal force there is not positive, else -1.
int OpenContact(const System& s, const SteadyState& st, double* normal) {
  for (int i = 0; i < s.contacts(); ++i)
    if (const auto n = s.NormalForce(i)) {
      *normal = n->At(st.z.data());
      if (!(*normal > 0)) return i;
    }
  return -1;
}

// The point between rows a and b (max_real of opposite signs), bisected in p
// (at least once: a point is never a copy of a row); false, with mid.p,
// where a midpoint has no rest point.
bool Locate(System& s, int j, const SteadyRow& a, const SteadyRow& b, const SteadyBranchOptions& o,
            SteadyRow* out) {
  double lo = a.p, hi = b.p;
  const bool lo_negative = a.state.max_real < 0;
  SteadyRow& mid = *out;
  mid = a;
  for (int i = 0; i < Tolerances::kBranchBisectionCap; ++i) {
    mid.p = 0.5 * (lo + hi);
    s.SetParameterValue(j, mid.p);
    mid.state = SteadySliding(s, a.state);
    if (!mid.state.found || mid.state.eigenvalues.empty()) return false;
    ((mid.state.max_real < 0) == lo_negative ? lo : hi) = mid.p;
    if (std::abs(hi - lo) <= o.locate_tol * (1 + std::abs(lo))) break;
    if (o.cancelled && o.cancelled()) break;
  }
  const std::complex<double> e = mid.state.eigenvalues.front();
  const bool pair = std::abs(e.imag()) > Tolerances::kSteadyRealPair * (1 + std::abs(e));
  const std::string turn = lo_negative ? "loses" : "gains";
  mid.label = pair ? SpecialKind::kHopf : SpecialKind::kFold;
  mid.description =
      pair ? "Hopf: a complex pair crosses the imaginary axis at +-i w, w = " +
                 Num(std::abs(e.imag()), 12) +
                 " (2 pi / w = " + Num(2 * M_PI / std::abs(e.imag()), 12) + "); steady sliding " +
                 turn + " stability"
           : "a real eigenvalue crosses 0 (a fold or branch point of steady sliding); it " + turn +
                 " stability";
  return true;
}

}  // namespace

std::string SteadyBranchOptions::ValidationError() const {
  if (points < 2 || points > kMaxPoints) return IntRangeError("points", points, 2, kMaxPoints);
  if (!(locate_tol > 0) || !std::isfinite(locate_tol))
    return "locate_tol = " + Num(locate_tol) + " must be a finite number > 0";
  return "";
}

SteadyBranch ContinueSteadySliding(const System& system, int parameter, double to,
                                   const SteadyBranchOptions& options) {
  std::string e = system.ValidationError();
  if (e.empty()) e = options.ValidationError();
  if (e.empty() && (parameter < 0 || parameter >= system.parameters()))
    e = "parameter = " + std::to_string(parameter) + " is not one of the system's " +
        std::to_string(system.parameters());
  if (e.empty()) e = system.ParameterError(parameter);  // a flat branch otherwise
  const double from = e.empty() ? system.ParameterValue(parameter) : 0;
  if (e.empty() && (!std::isfinite(to) || to == from))
    e = "to = " + Num(to) + " must be finite and differ from " + system.ParameterName(parameter) +
        " = " + Num(from);
  if (!e.empty()) throw InvalidArgument(e);
  std::unique_ptr<System> s = system.Clone();
  const std::string name = system.ParameterName(parameter);
  SteadyBranch out;
  out.status = BranchStatus::kReachedEnd;
  for (int i = 0; i < options.points; ++i) {
    if (options.cancelled && options.cancelled()) {
      out.status = BranchStatus::kCancelled, out.message = "cancelled";
      break;
    }
    SteadyRow row;
    row.p = i + 1 == options.points ? to : from + (to - from) * i / (options.points - 1);
    s->SetParameterValue(parameter, row.p);
    if (const std::string invalid = s->ValidationError(); !invalid.empty()) {
      out.status = i == 0 ? BranchStatus::kStartFailed : BranchStatus::kStepTooSmall;
      out.message = "at " + name + " = " + Num(row.p, 12) + ": " + invalid;
      break;
    }
    row.state = out.rows.empty() ? SteadySliding(*s) : SteadySliding(*s, out.rows.back().state);
    double normal = 0;
    const int open = row.state.found ? OpenContact(*s, row.state, &normal) : -1;
    if (!row.state.found || open >= 0) {
      out.status = i == 0            ? BranchStatus::kStartFailed
                   : row.state.found ? BranchStatus::kContactLost
                                     : BranchStatus::kStepTooSmall;
      out.message = row.state.found ? "contact " + std::to_string(open) +
                                          "'s normal force at steady sliding is " + Num(normal) +
                                          " <= 0 at " + name + " = " + Num(row.p, 12)
                                    : "no steady sliding at " + name + " = " + Num(row.p, 12);
      break;
    }
    if (!out.rows.empty() && (out.rows.back().state.max_real < 0) != (row.state.max_real < 0)) {
      SteadyRow point;
      if (!Locate(*s, parameter, out.rows.back(), row, options, &point)) {
        out.status = BranchStatus::kStepTooSmall;
        out.message = "no steady sliding at " + name + " = " + Num(point.p, 12) +
                      ", between two rows where it exists";
        break;
      }
      if (options.cancelled && options.cancelled()) {  // not located: no point
        out.status = BranchStatus::kCancelled, out.message = "cancelled";
        break;
      }
      out.special.push_back(point);
      out.rows.push_back(std::move(point));
    }
    out.rows.push_back(std::move(row));
  }
  return out;
}

}  // namespace stickslip
