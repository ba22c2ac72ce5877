// Continue() on a worker thread, for an app: cancellation by signals and
// --max_time (cli::RunControl), progress lines, and a grace period after which
// the app goes on without a library call that does not return.
#pragma once

#include "cli/run_control.hpp"
#include "stickslip/continuation.hpp"

namespace stickslip::cli {

// Runs the continuation with cancellation and progress; an InvalidArgument
// escaping the library after validation is a numerical failure (Error, exit 1).
// *abandoned: the worker is still running (the caller must then end the
// process without running destructors under it).
ContinuationResult RunContinuation(const Params& base, ContinuationOptions opts, RunControl& run,
                                   bool* abandoned);

}  // namespace stickslip::cli
