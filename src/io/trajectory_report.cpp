// A trajectory's tables and figures (trajectory_report.hpp).
#include "stickslip/io/trajectory_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip {

namespace {

// The forcing periods the time series shows: the last few, not the whole run
// (thousands of oscillations drawn in 700 pixels are a block of colour).
constexpr double kShownPeriods = 8;
constexpr const char* kGray = "lc rgb '#b0b0b0'";

std::string Q(const std::string& s) { return GnuplotQuoted(s); }
std::string Col(const System& s, int i) { return "column('" + StateColumn(s, i) + "')"; }
// The value of column i where t is before (early) or from (late) t_split, else NaN.
std::string Split(const System& s, int i, const std::string& t_split, bool early) {
  return "(column('t') " + std::string(early ? "< " : ">= ") + t_split + " ? " + Col(s, i) +
         " : NaN)";
}

// The phase portrait of components 0 and 1, the transient in gray.
void Portrait(std::ostringstream& os, const System& s, const std::string& ts,
              const std::string& early, const std::string& late) {
  const std::string u = "column('" + StateColumn(s, 0) + "')";
  os << "set xlabel " << Q(EnhancedText(s.StateName(0))) << "\nset ylabel "
     << Q(EnhancedText(s.StateName(1))) << "\nset title 'phase portrait'\n"
     << "plot 'trajectory.tsv' using (" << u << "):" << Split(s, 1, ts, true) << " with lines lw 1 "
     << kGray << " title " << early << ", \\\n"
     << "     'trajectory.tsv' using (" << u << "):" << Split(s, 1, ts, false)
     << " with lines ls 1 lw 1.5 title " << late << ", \\\n"
     << "     'trajectory.tsv' using (" << u << "):(substr(strcol('mode'), 1, 5) eq 'stick' ? "
     << Col(s, 1) << " : NaN) with lines ls 9 title "
     << Q(s.contacts() > 1 ? "contact 1 sticking" : "sticking") << "\n";
}

// The displacements and first-order states against t (one displacement
// alone: it and its rate), over the last kShownPeriods periods of a clock.
void TimeSeries(std::ostringstream& os, const System& s, const TrajectoryFigure& f) {
  const int nt = s.tangent_dimension();
  std::vector<bool> rate(static_cast<std::size_t>(nt), false);
  for (int i = 0; i < nt; ++i)
    if (const int d = s.DerivativeOf(i); d >= 0 && d < nt) rate[static_cast<std::size_t>(d)] = true;
  std::vector<int> shown;
  bool states = false;  // a first-order state among them
  for (int i = 0; i < nt; ++i)
    if (!rate[static_cast<std::size_t>(i)]) {
      shown.push_back(i);
      states = states || s.DerivativeOf(i) < 0;
    }
  const bool one = shown.size() == 1 && !states;
  if (one) shown.push_back(s.DerivativeOf(shown[0]));
  os << "set xlabel 'time t'\nset ylabel "
     << Q(one      ? EnhancedText(s.StateName(shown[0]) + ", " + s.StateName(shown[1]))
          : states ? "states"
                   : "displacements")
     << "\n";
  // Without a clock: the last kShownPeriods periods 2 pi of the dimensionless
  // oscillator (unit natural frequency).
  const double period = f.period > 0 ? f.period : 2 * M_PI;
  const double from = std::max(0.0, f.t_end - kShownPeriods * period);
  if (from == 0)
    os << "set title 'time series'\n";
  else if (f.period > 0)
    os << "set title "
       << Q("time series: the last " + Num(std::min(kShownPeriods, f.t_end / f.period), 3) +
            " forcing periods");
  else
    os << "set title " << Q("time series: the last " + Num(f.t_end - from, 3) + " time units");
  if (from > 0)
    os << "\nset xrange [" << FormatNumber(from) << ":" << FormatNumber(f.t_end) << "]\n";
  os << "plot ";
  for (size_t k = 0; k < shown.size(); ++k) {
    const int i = shown[k];
    const bool velocity = one && k == 1;
    os << (k ? ", \\\n     " : "") << "'trajectory.tsv' using 't':'" << StateColumn(s, i)
       << "' with lines lw 1.5 lc rgb '" << SeriesColor(k) << "' title "
       << Q(EnhancedText((velocity                 ? "velocity "
                          : s.DerivativeOf(i) >= 0 ? "displacement "
                                                   : "") +
                         s.StateName(i)));
  }
  os << "\nunset multiplot\nset autoscale x\n";
}

// The section's figure: strobe, component 1 against 0; exit, the return map
// of the first clock's phase (else of component 0).
void SectionFigure(std::ostringstream& os, const System& s, const TrajectoryFigure& f,
                   const std::string& ts, const std::string& early, const std::string& late) {
  os << "set bmargin 7\n"
     << FigureTerminal(f.format, 950, 750) << "set output " << Q(FigureFile("section", f.format))
     << "\n";
  const std::string title = Q(f.title);
  if (f.section == SimulationSection::kStrobe) {
    os << "set title \"stroboscopic section (every forcing period)\\n\" . " << title << "\n"
       << "set xlabel " << Q(EnhancedText(s.StateName(0))) << "\nset ylabel "
       << Q(EnhancedText(s.StateName(1))) << "\n"
       << "set offsets graph 0.04, graph 0.04, graph 0.04, graph 0.04\n"  // no point on the frame
       << "plot 'section.tsv' using (" << Col(s, 0) << "):" << Split(s, 1, ts, true)
       << " with points pt 6 ps 0.6 " << kGray << " title " << early << ", \\\n"
       << "     'section.tsv' using (" << Col(s, 0) << "):" << Split(s, 1, ts, false)
       << " with points pt 7 ps 0.8 lc rgb '#0072b2' title " << late << "\n";
    return;
  }
  const bool clock = s.clocks() > 0;
  const int c = clock ? s.tangent_dimension() : 0;
  const std::string what = clock ? "forcing phase" : s.StateName(0);
  os << "set title \"" << (clock ? "exit-phase map" : "exit map") << " (stick exits)\\n\" . "
     << title << "\n"
     << "set xlabel " << Q(EnhancedText(what + " at stick exit n" + (clock ? " [rad]" : "")))
     << "\nset ylabel " << Q(EnhancedText(what + " at stick exit n+1" + (clock ? " [rad]" : "")))
     << "\n";
  if (clock) os << "set xrange [0:2*pi]\nset yrange [0:2*pi]\n";
  os << "set size square\nprev = NaN\nplot x with lines lc rgb '#aaaaaa' dt 2 notitle, \\\n"
     << "     'section.tsv' using (q = prev, prev = " << Col(s, c)
     << ", q):" << Split(s, c, ts, true) << " with points pt 6 ps 0.6 " << kGray << " title "
     << early << ", \\\n"
     << "     prev = NaN, 'section.tsv' using (q = prev, prev = " << Col(s, c)
     << ", q):" << Split(s, c, ts, false) << " with points pt 7 ps 0.8 lc rgb '#0072b2' title "
     << late << "\n";
}

}  // namespace

double ClockPhase(double theta) {
  double p = std::fmod(theta, 2 * M_PI);
  if (p < 0) p += 2 * M_PI;
  const double slack = Tolerances::kPhaseRounding * (1 + std::abs(theta)) * Tolerances::kPhaseUlps;
  return 2 * M_PI - p <= slack ? 0 : p;
}

std::vector<std::string> TrajectoryColumns(const System& s) {
  std::vector<std::string> c = {"t"};
  for (int i = 0; i < s.dimension(); ++i) c.push_back(StateColumn(s, i));
  c.push_back("mode");
  return c;
}

std::vector<std::string> SectionColumns(const System& s) {
  std::vector<std::string> c = TrajectoryColumns(s);
  c.insert(c.begin(), "n");
  return c;
}

std::vector<TsvTable::Cell> TrajectoryRow(const System& s, long n, double t, const double* z,
                                          const ModeSet& mode) {
  std::vector<TsvTable::Cell> row;
  if (n >= 0) row.emplace_back(n);
  row.emplace_back(t);
  for (int i = 0; i < s.dimension(); ++i)
    row.emplace_back(i < s.tangent_dimension() ? z[i] : ClockPhase(z[i]));
  row.emplace_back(ModeSetName(mode, s.contacts()));
  return row;
}

std::string TrajectoryScript(const System& s, const TrajectoryFigure& f) {
  const std::string ts = FormatNumber(f.t_end / 2);
  const std::string late = Q("after the transient (t ≥ " + Num(f.t_end / 2, 4) + ")");
  const std::string early = Q("transient (t < " + Num(f.t_end / 2, 4) + ")");
  std::ostringstream os;
  os << FigurePreamble(f.format, 1400, 650) << "set output "
     << Q(FigureFile("trajectory", f.format)) << "\n"
     << "set bmargin 9\n"  // the portrait's key takes three rows under its axis label
     << "set multiplot layout 1,2 title " << Q(f.title) << "\n";
  os << "set offsets 0, 0, graph 0.04, graph 0.04\n";  // the stick line off the frame
  Portrait(os, s, ts, early, late);
  os << "set offsets 0, 0, 0, 0\n";
  TimeSeries(os, s, f);
  if (f.section != SimulationSection::kNone) SectionFigure(os, s, f, ts, early, late);
  return os.str();
}

}  // namespace stickslip
