// Continue() on a worker thread, for an app: cancellation by signals and
// --max_time (cli::RunControl) and progress lines. The worker is joined
// before the call returns (a cancelled library returns within a step) and
// its failures come back as the result's status, never as an exception.
#pragma once

#include "cli/run_control.hpp"
#include "stickslip/continuation/continuation.hpp"

namespace stickslip::cli {

// Runs the continuation with cancellation and progress. A numerical failure,
// an exception escaping the library included, is status kFailed with where
// it happened in the message; the points so far are kept.
ContinuationResult RunContinuation(const Params& base, ContinuationOptions opts, RunControl& run);

}  // namespace stickslip::cli
