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
#include "stickslip/io/resonance_report.hpp"

namespace stickslip::cli {

// How much the run log says.
enum class LogDetail { kSpecialPoints, kEveryPoint };

// The belt's branch: with kEveryPoint a table of every point, then the
// special points ("  GR1  pt 88  v = ...  period ...  x in [...]  description").
void PrintBranchLog(std::ostream& os, const ContinuationResult& r, LogDetail detail,
                    const std::optional<Scales>& scales);

// The forced branch (its pieces in branch.tsv's order, pt counted over them).
void PrintForcedLog(std::ostream& os, const std::vector<OrbitBranch>& pieces, const ForcedParams& p,
                    ParameterAxis axis, LogDetail detail);

}  // namespace stickslip::cli
