// --size and --font: the figures at the size they are printed, so that text,
// line widths and dash lengths are what the page shows (a 10 in figure reduced
// to a 3.5 in column has 4 pt text and dashes that look like dots). The app
// rewrites the `set terminal` line of its staged script before gnuplot runs;
// the script in --out then redraws the same figure.
#pragma once

#include <optional>
#include <string>

#include "cli/study.hpp"

namespace stickslip::cli {

struct FigureLayout {
  double width_in = 0;   // the figure's width [in]
  double height_in = 0;  // 0: the script's own aspect ratio
  std::string font;      // "Sans,8"
};

// --size single (3.5 in, one journal column) | double (7.2 in) | WxH (inches,
// e.g. 3.5x2.6) and --font NAME,PT or PT; nothing if neither is given.
// UsageError naming the option on a bad value.
std::optional<FigureLayout> FigureLayoutOf(const Arguments& args);

// The script with its first `set terminal` line set to the layout: pdf at the
// size in inches, svg at 96 units an inch, png at 150 pixels an inch, text in
// points; below 5 in the long title lines (the model) dropped; line widths 0.8 x (lw 2: 0.8 pt),
// dashes 1.5 x the default length and points half size, so that lines stay
// lines and dashes stay dashes at that size; label fonts scaled from 12 pt.
std::string ApplyFigureLayout(const std::string& script, const FigureLayout& layout);

}  // namespace stickslip::cli
