// Running gnuplot and checking its figures: the apps' layer (the library only
// writes the data and the script text).
#pragma once

#include <functional>
#include <string>

namespace stickslip::cli {

enum class GnuplotStatus {
  kOk,
  kMissing,    // gnuplot is not on PATH
  kFailed,     // it could not start, or exited non-zero or on a signal
  kCancelled,  // cancelled() returned true; the child was killed
};
struct GnuplotResult {
  GnuplotStatus status = GnuplotStatus::kOk;
  std::string message;  // one line; empty when ok
  bool ok() const { return status == GnuplotStatus::kOk; }
};

/// Runs `gnuplot script_path` with working directory `workdir` (empty: the
/// current one), so relative paths inside the script resolve there; a relative
/// script_path is taken relative to the caller's current directory. The child
/// gets default SIGPIPE handling and no stdin/stdout; its stderr's last line is
/// the reason given on failure. `cancelled` (if set) is polled every 50 ms; when
/// it returns true the child is killed (SIGTERM, then SIGKILL) and reaped.
GnuplotResult RunGnuplot(const std::string& script_path, const std::string& workdir,
                         const std::function<bool()>& cancelled);
/// The same without cancellation: false and *error (if not null) set to the
/// message when the status is not kOk.
bool RunGnuplot(const std::string& script_path, const std::string& workdir, std::string* error);

// Empty if `path` holds a whole PNG image (the PNG signature first, the IEND
// chunk last), else one line saying what is wrong (missing, empty, truncated).
std::string PngError(const std::string& path);
// The same for a whole PDF document ("%PDF-" first, "%%EOF" last but for
// trailing white space) and a whole SVG image (an XML or <svg> start,
// "</svg>" last but for white space).
std::string PdfError(const std::string& path);
std::string SvgError(const std::string& path);
// The check the name's extension calls for: .pdf, .svg, else PNG.
std::string FigureError(const std::string& path);

}  // namespace stickslip::cli
