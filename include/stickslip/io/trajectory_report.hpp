// A trajectory of any system as files (ss_simulate for the forced oscillator
// and --system; docs/formats.md, "trajectory.tsv and section.tsv"): its rows
// and Poincare section points (flow/simulate.hpp) as TSV tables, columns
// named from the system, and the figures as one gnuplot script. The library
// writes text only.
#pragma once

#include <string>
#include <vector>

#include "stickslip/flow/simulate.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/system/system.hpp"

namespace stickslip {

/// A clock's phase theta mod 2 pi in [0, 2 pi); within rounding of 2 pi
/// (a stroboscopic point reached from below) it is 0.
double ClockPhase(double theta);

/// trajectory.tsv's columns: t, every state component (StateColumn; a
/// clock's as its phase, ClockPhase), mode (ModeSetName).
std::vector<std::string> TrajectoryColumns(const System& s);
/// section.tsv's columns: n (from 0), then TrajectoryColumns.
std::vector<std::string> SectionColumns(const System& s);
/// One row of either table (n < 0: a trajectory row).
std::vector<TsvTable::Cell> TrajectoryRow(const System& s, long n, double t, const double* z,
                                          const ModeSet& mode);

/// What the figures show.
struct TrajectoryFigure {
  std::string title;  ///< as drawn (FigureTitle, SystemFigureTitle: enhanced text)
  FigureFormat format = FigureFormat::kPng;
  SimulationSection section = SimulationSection::kNone;  ///< kNone: no section figure
  double t_end = 0;   ///< the last row's t: t < t_end / 2 is drawn as the transient
  double period = 0;  ///< a clock's period (0: none): the time series shows the last 8
};

/// trajectory.gp. Figure "trajectory": the phase portrait of components 0
/// and 1 (the transient in gray, the first contact's stick rows marked) and
/// the time series (one displacement: it and its rate; else every
/// displacement). Figure "section", if a section was taken: strobe, component
/// 1 against 0; exit, the first clock's phase (else component 0) at exit n+1
/// against exit n; the transient apart in gray.
std::string TrajectoryScript(const System& s, const TrajectoryFigure& f);

}  // namespace stickslip
