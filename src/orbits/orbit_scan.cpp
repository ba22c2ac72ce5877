#include "stickslip/orbits/orbit_scan.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "numerics/roots.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::string OrbitScanOptions::ValidationError() const {
  std::string err = orbit.ValidationError();
  if (!err.empty()) return err;
  std::ostringstream os;
  if (samples < 4)
    os << "samples = " << samples << " must be >= 4";
  else if (!(a_min > 0 && a_min < kAMinLimit))
    os << "a_min = " << a_min << " must be in (0, " << kAMinLimit << ")";
  return os.str();
}

namespace {

// The sampled amplitudes: geometric from a_lo (small orbits near a Hopf
// point) merged with uniform (large ones), increasing.
std::vector<double> Grid(double a_lo, double a_hi, int n) {
  std::vector<double> a;
  const int ng = n / 2, nu = n - ng;
  for (int i = 0; i < ng; ++i) a.push_back(a_lo * std::pow(a_hi / a_lo, double(i) / (ng - 1)));
  for (int i = 1; i <= nu; ++i) a.push_back(a_hi * i / nu);
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

class Scan {
 public:
  Scan(const Model& m, const OrbitScanOptions& o, PeriodicOrbits& out)
      : o_(o), finder_(m, o.orbit), out_(out), xbar_(m.SteadySliding().x) {
    if (o.cancelled) finder_.flow().set_cancel(o.cancelled);
  }

  void Run();

 private:
  // G(a) = (P(xbar + a) - xbar - a) / a; kOk, kSticks, kNoReturn or a failure.
  OrbitStatus G(double a, double* g) {
    ++out_.returns;
    ReturnMap map;
    const OrbitStatus s = finder_.Desingularised(a, g, nullptr, &map);
    if (s != OrbitStatus::kOk && s != OrbitStatus::kSticks && s != OrbitStatus::kNoReturn)
      Fail(s, a, map.message);
    return s;
  }
  void Fail(OrbitStatus s, double a, const std::string& why) {
    if (!out_.ok()) return;
    out_.status =
        s == OrbitStatus::kCancelled ? OrbitScanStatus::kCancelled : OrbitScanStatus::kFailed;
    std::ostringstream os;
    os << "orbit scan at section amplitude a = " << a << ": " << why;
    out_.message = os.str();
  }
  // Both ends of a sign change are integration noise: G vanishes identically
  // (a center, as for the coulomb law with beta = 0: a continuum of orbits,
  // none isolated). G's noise is about rtol (|xbar| + a) / a.
  bool Noise(double a0, double g0, double a1, double g1) const {
    const double rtol = o_.orbit.flow.rtol;
    auto noise = [&](double a) {
      return Tolerances::kScanNoise * rtol * (1 + std::abs(xbar_) + a) / a;
    };
    return std::abs(g0) < noise(a0) && std::abs(g1) < noise(a1);
  }
  void Bracket(double a0, double g0, double a1, double g1);
  void LocateSticking(double a_ok, double g_ok, double a_sticks, double* a_last, double* g_last);

  const OrbitScanOptions& o_;
  OrbitFinder finder_;
  PeriodicOrbits& out_;
  double xbar_;
};

// A sign change of G on [a0, a1]: Brent, then Newton for the orbit and its
// multiplier P'(x*). Orbits that stick are not pure-slip orbits.
void Scan::Bracket(double a0, double g0, double a1, double g1) {
  auto f = [&](double a) {
    double g = 0;
    return G(a, &g) == OrbitStatus::kOk ? g : NAN;
  };
  const RootResult root = FindRoot(f, a0, a1, g0, g1, Tolerances::kScanRoot * a1);
  if (!root.ok || !out_.ok()) return;
  const OrbitResult r = finder_.PureSlip(root.x);
  out_.returns += r.iterations;
  if (r.status == OrbitStatus::kCancelled) return Fail(r.status, root.x, r.message);
  if (!r.ok()) return;  // sticks, or no orbit near the bracket
  const double a = r.orbit.start[0] - xbar_;
  for (const Orbit& q : out_.pure_slip)
    if (std::abs(q.start[0] - xbar_ - a) <= Tolerances::kSameOrbit * Tolerances::Scale(a)) return;
  out_.pure_slip.push_back(r.orbit);
}

// Bisection for the smallest amplitude that sticks; *a_last, *g_last: the
// largest amplitude that does not, and G there.
void Scan::LocateSticking(double a_ok, double g_ok, double a_sticks, double* a_last,
                          double* g_last) {
  while (a_sticks - a_ok > Tolerances::kStickingBisection * a_sticks && out_.ok()) {
    const double mid = 0.5 * (a_ok + a_sticks);
    double g = 0;
    const OrbitStatus s = G(mid, &g);
    if (s == OrbitStatus::kOk) {
      a_ok = mid, g_ok = g;
    } else if (s == OrbitStatus::kSticks) {
      a_sticks = mid;
    } else {
      break;
    }
  }
  out_.a_stick = a_sticks;
  *a_last = a_ok;
  *g_last = g_ok;
}

void Scan::Run() {
  const Model& m = finder_.model();
  const double scale = m.params().mu_s + std::abs(m.v());
  out_.a_max = 2 * scale;
  const OrbitResult ss = finder_.StickSlip();
  if (ss.ok()) {
    out_.has_stick_slip = true;
    out_.stick_slip = ss.orbit;
  } else if (ss.status == OrbitStatus::kCancelled || ss.status == OrbitStatus::kIntegratorFailed) {
    return Fail(ss.status, 0, "stick-slip orbit: " + ss.message);
  }
  double a0 = 0, g0 = 0;
  bool have0 = false;
  for (double a1 : Grid(o_.a_min * scale, out_.a_max, o_.samples)) {
    double g1 = 0;
    const OrbitStatus s = G(a1, &g1);
    if (!out_.ok()) return;
    if (s == OrbitStatus::kSticks) {
      // Larger amplitudes reach the belt speed too: the last bracket ends
      // just below the first sticking amplitude.
      if (!have0) break;
      double a_last = a0, g_last = g0;
      LocateSticking(a0, g0, a1, &a_last, &g_last);
      if (out_.ok() && g0 * g_last <= 0 && a_last > a0 && !Noise(a0, g0, a_last, g_last))
        Bracket(a0, g0, a_last, g_last);
      break;
    }
    if (s != OrbitStatus::kOk) {
      have0 = false;  // no return: no value to bracket with
      continue;
    }
    if (have0 && g0 * g1 <= 0 && !Noise(a0, g0, a1, g1)) Bracket(a0, g0, a1, g1);
    if (!out_.ok()) return;
    a0 = a1, g0 = g1, have0 = true;
  }
  std::sort(out_.pure_slip.begin(), out_.pure_slip.end(),
            [](const Orbit& p, const Orbit& q) { return p.start[0] < q.start[0]; });
}

}  // namespace

PeriodicOrbits FindPeriodicOrbits(const Model& model, const OrbitScanOptions& options) {
  const std::string err = options.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  PeriodicOrbits out;
  out.steady = model.SteadySliding();
  // The energy bound excludes every orbit: steady sliding attracts all.
  if (model.NoPeriodicOrbit()) return out;
  Scan(model, options, out).Run();
  return out;
}

}  // namespace stickslip
