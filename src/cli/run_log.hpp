// ss_continue's run log, printed from the result (the library never prints):
// the special points with their labels (GR1, HB1, PD1) and point numbers,
// which `--restart DIR --point` takes, and with --verbose one line per point
// as AUTO-07p prints its steps (pt, kind, parameter, period, x range,
// multiplier, stability, label). With physical inputs the SI values stand
// beside the dimensionless ones.
#pragma once

#include <optional>
#include <ostream>
#include <vector>

#include "cli/physical.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip::cli {

// How much the run log says.
enum class LogDetail { kSpecialPoints, kEveryPoint };

// The belt's branch: with kEveryPoint a table of every point, then the
// special points ("  GR1  pt 88  v = ...  period ...  x in [...]  description").
void PrintBranchLog(std::ostream& os, const ContinuationResult& r, LogDetail detail,
                    const std::optional<Scales>& scales);

// A system's run (ss_continue --system, --model, --force): the same, pt and
// labels counted as branch.tsv and special_points.tsv count them (steady
// sliding's rows, then each piece's); an orbit's m is its section's turns
// (a clock) or returns, steady sliding's |mu|max its largest real part.
void PrintSystemLog(std::ostream& os, const System& s, const SystemRun& r, LogDetail detail);

}  // namespace stickslip::cli
