// ss_accuracy: the rows and special points an ss_continue run wrote (DIR/branch.tsv,
// DIR/special_points.tsv) against the independent long-double reference integrator
// (reference/reference_orbit.hpp, RKF78 at 1e-17) and the Hopf condition 2 beta + mu'(v) = 0
// solved in long double. Prints the worst error of each quantity and where.
// Usage: ss_accuracy [--rows] DIR...
//        ss_accuracy --seed_references V...   (the AUTO-07p peer's references, see below)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "reference/reference_orbit.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace {

using stickslip::Params;
using stickslip::reference::Real;
namespace ref = stickslip::reference;

bool g_rows = false;  // --rows: print every pure-slip row's errors

struct Table {
  std::string param;
  Params model;
  std::vector<std::vector<std::string>> rows;
};

std::vector<std::string> Split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string f; std::getline(ss, f, sep);) out.push_back(f);
  return out;
}

bool Read(const std::string& path, Table* t) {
  std::ifstream in(path);
  if (!in) return false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# model:", 0) == 0) {
      for (const std::string& kv : Split(line.substr(9), ' ')) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos) continue;
        const std::string k = kv.substr(0, eq), val = kv.substr(eq + 1);
        if (k == "law")
          t->model.law = stickslip::LawFromName(val);
        else
          stickslip::SetParameter(t->model, k, std::stod(val));
      }
    } else if (line.rfind("# ", 0) == 0 && line.find('\t') != std::string::npos) {
      t->param = Split(line.substr(2), '\t')[0];  // an older header line, "# v\tkind..."
      if (t->param == "label") t->param = Split(line.substr(2), '\t')[1];
    } else if (line.empty() || line[0] == '#') {
      continue;
    } else if (t->param.empty()) {  // the header line: the parameter's column
      const auto cols = Split(line, '\t');
      t->param = cols.size() > 1 && cols[0] == "label" ? cols[1] : cols[0];
    } else {
      t->rows.push_back(Split(line, '\t'));
    }
  }
  return true;
}

struct Worst {
  double err = 0;
  std::string where;
  int n = 0;
  void Add(double e, const std::string& at) {
    ++n;
    if (!(e <= err)) err = e, where = at;  // NaN is worst
  }
};

// The double parameter value in [lo, hi] where f changes sign, by bisection to adjacent doubles.
template <class F>
double Bisect(F f, double lo, double hi) {
  Real flo = f(lo);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const Real fm = f(mid);
    if ((fm > 0) == (flo > 0))
      lo = mid, flo = fm;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// Widens [p - w, p + w] until f changes sign; NaN if it never does.
template <class F>
double Root(F f, double p) {
  for (double w = 1e-9; w < 1e-2; w *= 10) {
    if ((f(p - w) > 0) != (f(p + w) > 0)) return Bisect(f, p - w, p + w);
  }
  return NAN;
}

void Measure(const std::string& dir, std::map<std::string, Worst>* worst) {
  Table branch, special;
  if (!Read(dir + "/branch.tsv", &branch) || !Read(dir + "/special_points.tsv", &special)) {
    std::cerr << dir << ": no branch.tsv / special_points.tsv\n";
    return;
  }
  special.model = branch.model;
  const std::string& name = branch.param;
  auto at = [&](double p) {
    Params q = branch.model;
    stickslip::SetParameter(q, name, p);
    return q;
  };
  auto where = [&](const std::string& what, double p) {
    std::ostringstream os;
    os.precision(10);
    os << dir << " " << what << " " << name << "=" << p;
    return os.str();
  };
  auto rel = [](double a, Real r, Real scale) {
    return static_cast<double>(std::abs(a - r) / scale);
  };
  for (const auto& r : branch.rows) {
    // Equilibria are closed forms; amplitude 0 is the Hopf point itself.
    if (r.size() < 12 || r[1] == "equilibrium" || std::stod(r[11]) == 0) continue;
    const double p = std::stod(r[0]), period = std::stod(r[3]);
    const double x_min = std::stod(r[4]), x_max = std::stod(r[5]);
    const Params q = at(p);
    Real ref_period, ref_min, ref_max;
    if (r[1] == "stick-slip") {
      const ref::StickSlipOrbit o = ref::StickSlip(q);
      if (!o.found) continue;
      ref_period = o.period, ref_min = o.x_min, ref_max = o.x_max;
    } else {
      const ref::PureSlipOrbit o = ref::PureSlip(q, x_max);
      if (!o.found) {
        (*worst)["pure-slip reference failed"].Add(1, where("pure-slip", p));
        continue;
      }
      ref_period = o.period, ref_min = o.x_min, ref_max = o.x_max;
      const Real a = o.x_section - ref::Model(q).law.Mu(q.v);
      (*worst)["pure-slip amplitude (abs)"].Add(rel(std::stod(r[11]), a, 1), where("", p));
      if (g_rows)
        std::printf("%s %.17g a %.6e err_a %.2e err_T %.2e\n", dir.c_str(), p,
                    static_cast<double>(a), static_cast<double>(std::stod(r[11]) - a),
                    static_cast<double>((period - o.period) / o.period));
    }
    const Real scale = std::max(std::abs(ref_min), std::abs(ref_max));
    const std::string kind = r[1] + " ";
    (*worst)[kind + "period (rel)"].Add(rel(period, ref_period, ref_period), where("", p));
    (*worst)[kind + "x_min (rel)"].Add(rel(x_min, ref_min, scale), where("", p));
    (*worst)[kind + "x_max (rel)"].Add(rel(x_max, ref_max, scale), where("", p));
  }
  for (const auto& r : special.rows) {
    if (r.size() < 2) continue;
    const double p = std::stod(r[1]);
    Real exact = NAN;
    if (r[0] == "HB") {
      exact = Root(
          [&](double x) {
            const ref::Model m(at(x));
            return 2 * m.beta + m.law.DMu(m.v);
          },
          p);
    } else if (r[0] == "GR" || r[0] == "LP") {
      // GR, and the non-smooth fold at GR: the first return from the exit point touches x' = v.
      exact = Root(
          [&](double x) {
            const ref::Model m(at(x));
            return ref::FirstReturnMaxXdot(m, 1e-17L) - m.v;
          },
          p);
    } else {
      continue;
    }
    (*worst)[r[0] + " parameter (abs)"].Add(static_cast<double>(std::abs(p - exact)),
                                            where(r[0], p));
  }
}

// --seed_references: for the seed set (seed section 4), the grazing speed GR and, at each
// given v, the period of the pure-slip orbit, from the reference integrator at tol 1e-17, each
// with its spread against tol 1e-15 (an estimate of the reference's own error). Lines
// "GR<TAB>v<TAB>spread" and "T<TAB>v<TAB>period<TAB>spread (rel)"; bench/peers/auto_peer.py
// reads them. Exit 2 on a v that is no number or outside (GR, HB), 1 if an orbit is not found.
int SeedReferences(int n, char** args) {
  const Params seed;
  const Real tols[2] = {1e-17L, 1e-15L};
  double gr[2];
  for (int k = 0; k < 2; ++k) {
    auto gap = [&](double v) {  // > 0 below GR: the first slip overshoots the belt speed
      Params q = seed;
      q.v = v;
      const ref::Model m(q);
      return ref::FirstReturnMaxXdot(m, tols[k]) - m.v;
    };
    if ((gap(0.3) > 0) == (gap(0.44) > 0)) {
      std::cerr << "ss_accuracy: reference GR not bracketed by v = 0.3 and 0.44\n";
      return 1;
    }
    gr[k] = Bisect(gap, 0.3, 0.44);
  }
  const double hb = static_cast<double>(ref::CubicHopfSpeed(seed));  // seed (3.16)
  std::vector<double> vs;
  for (int i = 0; i < n; ++i) {
    char* end = nullptr;
    const double v = std::strtod(args[i], &end);
    if (end == args[i] || *end != '\0' || !(v > gr[0] && v < hb)) {
      std::cerr << "ss_accuracy: v = " << args[i]
                << ": must be a number in the pure-slip range (GR " << gr[0] << ", HB " << hb
                << ")\n";
      return 2;
    }
    vs.push_back(v);
  }
  std::printf("GR\t%.17g\t%.1e\n", gr[0], std::abs(gr[0] - gr[1]));
  for (const double v : vs) {
    Params p = seed;
    p.v = v;
    // Guess: steady sliding + the first-harmonic amplitude (Thomsen & Fidlin 2003).
    const Real k1 = ref::CubicK1(p), k3 = ref::CubicK3(p), vv = v;
    const Real a = 2 * std::sqrt((k1 - 2 * Real(p.beta) - 3 * k3 * vv * vv) / (3 * k3));
    Real period[2];
    for (int k = 0; k < 2; ++k) {
      const ref::PureSlipOrbit o = ref::PureSlip(p, ref::Law(p).Mu(vv) + a, tols[k]);
      if (!o.found) {
        std::fprintf(stderr, "ss_accuracy: reference pure-slip orbit not found at v = %.17g\n", v);
        return 1;
      }
      period[k] = o.period;
    }
    std::printf("T\t%.17g\t%.21Lg\t%.1e\n", v, period[0],
                static_cast<double>(std::abs(period[0] - period[1]) / period[0]));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: ss_accuracy [--rows] DIR...  (ss_continue output directories)\n"
                 "       ss_accuracy --seed_references V...\n";
    return 2;
  }
  if (std::string(argv[1]) == "--seed_references") return SeedReferences(argc - 2, argv + 2);
  std::map<std::string, Worst> worst;
  for (int i = 1; i < argc; ++i) {
    try {
      if (std::string(argv[i]) == "--rows")
        g_rows = true;
      else
        Measure(argv[i], &worst);
    } catch (const std::exception& e) {  // a malformed number or parameter name
      std::cerr << "ss_accuracy: " << argv[i] << ": " << e.what() << "\n";
      return 2;
    }
  }
  std::printf("%-30s %6s %10s  %s\n", "quantity", "n", "worst", "where");
  for (const auto& [k, w] : worst)
    std::printf("%-30s %6d %10.2e  %s\n", k.c_str(), w.n, w.err, w.where.c_str());
  return 0;
}
