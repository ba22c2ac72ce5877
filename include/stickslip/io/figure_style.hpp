// The one figure style of every gnuplot script the library and the apps write
// (issue 22 item 4): the terminal per format, the font, line styles and
// colours for stable/unstable and for each kind of solution, the key below the
// plot. The library only writes script text; running gnuplot is the apps'.
//
// A script writer starts with FigurePreamble(format, w, h) and draws with the
// line styles below (`with lines ls kStyleStickSlip`); titles and labels go
// through EnhancedText so names like beta and mu_s print as symbols.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "stickslip/names.hpp"

namespace stickslip {

class ParameterAxis;

enum class FigureFormat { kPng, kPdf, kSvg };
template <>
struct EnumNames<FigureFormat> {
  static constexpr NamedValue<FigureFormat> kTable[] = {
      {FigureFormat::kPng, "png"},
      {FigureFormat::kPdf, "pdf"},
      {FigureFormat::kSvg, "svg"},
  };
};
/// False if text is none of the names above.
bool ParseFigureFormat(const std::string& text, FigureFormat* f);
/// stem + "." + the extension.
std::string FigureFile(const std::string& stem, FigureFormat f);

/// Line styles FigurePreamble defines. Stable solid, unstable dashed; colour by
/// kind (stick-slip blue, pure-slip vermillion, steady sliding gray: the
/// Okabe-Ito colour-blind-safe palette).
enum FigureLineStyle : int {
  kStyleStickSlip = 1,
  kStyleStickSlipUnstable = 2,
  kStylePureSlip = 3,
  kStylePureSlipUnstable = 4,
  kStyleEquilibrium = 5,
  kStyleEquilibriumUnstable = 6,
  kStyleThreshold = 7,   // a stability threshold: thin black dotted
  kStyleSpecial = 8,     // special points: black filled circles
  kStyleReference = 9,   // a computed reference curve: thick black
  kStyleEstimate1 = 10,  // estimates: green dashed, purple dash-dot
  kStyleEstimate2 = 11,
  kStyleBound = 12,  // a bound (the seed's x range): orange dash-dot-dot
};
/// Region fills (basins, charts), as gnuplot colour strings.
extern const char* const kFillStickSlip;
extern const char* const kFillPureSlip;
extern const char* const kFillEquilibrium;
extern const char* const kFillUndecided;
extern const char* const kFillContactLost;  ///< AttractorKind::kContactLost
extern const char* const kFillSettling;     ///< AttractorKind::kSettling
/// Colours of series that are not kinds (methods of a benchmark), in order.
const char* SeriesColor(int i);

/// The terminal line: pngcairo at width x height pixels, pdfcairo at the same
/// size in inches at 100 px per inch, svg at width x height; utf-8, enhanced.
std::string FigureTerminal(FigureFormat f, int width, int height);
/// The terminal, encoding, tab-separated data with column headers, grid,
/// the line styles above and the key outside below the plot.
std::string FigurePreamble(FigureFormat f, int width, int height);
/// Text for gnuplot's enhanced mode: parameter names as symbols (beta -> β,
/// mu_s -> μ with subscript s, delta -> δ, k5 -> k_5), other special
/// characters (_ ^ { } @ & ~) escaped. law false: a system's names, where k5
/// is not the cubic law's quintic term (a chain's block-5 stiffness) but text.
std::string EnhancedText(const std::string& plain, bool law = true);
/// A title from a model line "law=cubic beta=0.05 v=[0.05, 0.5] ... (partial)":
/// "cubic law: β = 0.05, ... (partial)" in enhanced text, leaving out the
/// parameters on the axes (their values are the axes).
std::string FigureTitle(const std::string& description, const std::vector<std::string>& axes);
/// A title line's length in characters, about: wider lines break (a model
/// file's twelve parameters overflowed the figures' width).
inline constexpr std::size_t kTitleWidth = 110;
/// A title from a system's line "chain: v=[axis] kc=0.2 beta=0.05 ...":
/// "chain: kc = 0.2, β = 0.05, ..." in enhanced text, leaving out the
/// parameters whose value is bracketed (the axes, the continued one),
/// broken into lines of about kTitleWidth.
std::string SystemFigureTitle(const std::string& description);
/// The words of `text` in lines of at most `width` characters (a longer word
/// alone), joined by newlines.
std::string WrapWords(const std::string& text, std::size_t width);
/// A double-quoted gnuplot string holding `text` (backslashes and quotes escaped).
std::string GnuplotQuoted(const std::string& text);
/// The axis words for a parameter: "belt speed v", "damping ratio β", ...
std::string ParameterAxisLabel(const ParameterAxis& param);

/// A parameter axis as drawn: value on the axis = factor x dimensionless value.
struct FigureAxis {
  double factor = 1;
  std::string label;  // words, symbol and unit; empty: ParameterAxisLabel
};
/// A figure's units. The data are dimensionless; a physical run (seed
/// section 3 scaling, L = M g / K, t0 = sqrt(M / K)) draws lengths in m,
/// times in s, speeds in m/s and its parameter axes in physical form. A
/// script multiplies each column by its factor: the gnuplot variables ul
/// (length), ut (time), uv (speed), up and up2 (the parameter axes) of
/// FigureUnitVariables.
struct FigureUnits {
  bool si = false;
  double length = 1, time = 1;  // L [m], t0 [s]
  FigureAxis p1, p2;
  /// " [m]", " [s]", " [m/s]"; " (dimensionless)" when not si.
  std::string LengthUnit() const;
  std::string TimeUnit() const;
  std::string SpeedUnit() const;
  /// p1's (p2's) label; without one, ParameterAxisLabel(param) and, for a
  /// parameter that has units in a physical run, " (dimensionless)".
  std::string P1Label(const ParameterAxis& param) const;
  std::string P2Label(const ParameterAxis& param) const;
};
/// "ul = ...\nut = ...\nuv = ...\nup = ...\nup2 = ...\n" for a script.
std::string FigureUnitVariables(const FigureUnits& u);

}  // namespace stickslip
