// How a branch of periodic orbits ended: one status for every system's
// branches (orbit_branch.hpp).
#pragma once

#include "stickslip/names.hpp"

namespace stickslip {

enum class BranchStatus {
  kReachedEnd,    ///< the last row is at p = to
  kUnbounded,     ///< the orbit passed max_amplitude (a resonance without damping)
  kStepTooSmall,  ///< the corrector failed below ds_min (message says why and where)
  kStartFailed,   ///< no orbit at p = from near the guess
  kMaxPoints,
  kClosed,     ///< the branch came back to its start, or to a special point it had located
  kCancelled,  ///< palc.cancelled() returned true (a signal, a time limit)
  kLeftRange,  ///< the branch turned back and passed p = from
  /// A contact's normal force reached 0 (labelled CL): beyond, the contact
  /// opens and the system is another one (issue 32).
  kContactLost,
  /// The orbit's switching sequence ends at a located and classified
  /// nonsmooth point (GR, SL, AD, CR: the last row) and no periodic orbit of
  /// the same period exists beyond: the branch's natural end on its section.
  kSequenceEnded,
};
template <>
struct EnumNames<BranchStatus> {
  static constexpr NamedValue<BranchStatus> kTable[] = {
      {BranchStatus::kReachedEnd, "reached-end"},
      {BranchStatus::kUnbounded, "unbounded"},
      {BranchStatus::kStepTooSmall, "step-too-small"},
      {BranchStatus::kStartFailed, "start-failed"},
      {BranchStatus::kMaxPoints, "max-points"},
      {BranchStatus::kClosed, "closed"},
      {BranchStatus::kCancelled, "cancelled"},
      {BranchStatus::kLeftRange, "left-range"},
      {BranchStatus::kContactLost, "contact-lost"},
      {BranchStatus::kSequenceEnded, "sequence-ended"},
  };
};

/// Whether a branch ended where it should: at its end, closed, at CL, or
/// where its switching sequence ends; anything else was cut short (a branch
/// that turned back past its start, left-range, has not been traced beyond).
inline bool Complete(BranchStatus s) {
  return s == BranchStatus::kReachedEnd || s == BranchStatus::kClosed ||
         s == BranchStatus::kContactLost || s == BranchStatus::kSequenceEnded;
}

}  // namespace stickslip
