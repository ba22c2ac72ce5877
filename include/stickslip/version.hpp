// The tool's version and where it was built from, for file headers and
// --version.
#pragma once

namespace stickslip {

/// The release, "MAJOR.MINOR.PATCH" (CMake's project version).
const char* Version();
/// The git commit the build was configured from ("" if not a checkout).
const char* GitCommit();
/// "0.1.0" or "0.1.0 (git 0123456789ab)".
const char* VersionString();

}  // namespace stickslip
