#include "cli/figure_layout.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "stickslip/io/report.hpp"

namespace stickslip::cli {
namespace {

constexpr double kSingleColumn = 3.5, kDoubleColumn = 7.2;  // inches
constexpr double kMinInches = 1, kMaxInches = 20;
constexpr double kMinPoints = 4, kMaxPoints = 30;
constexpr double kPngDpi = 150, kSvgDpi = 96;
constexpr double kScreenPoints = 12;  // the scripts' own font size (figure_style.cpp)
constexpr double kLineWidth = 0.8;    // x the scripts' widths: 0.8 pt for their lw 2
constexpr double kPointSize = 0.5;    // x the scripts' point sizes

bool ParseDouble(const std::string& text, double* x) {
  std::size_t used = 0;
  try {
    *x = std::stod(text, &used);
  } catch (...) {
    return false;
  }
  return used == text.size() && std::isfinite(*x);
}

// Each `key` + number of the script scaled: "font ',N'" (labels) from the
// screen's 12 pt to pt, " ps N" (point sizes) by kPointSize.
std::string ScaleAfter(std::string s, const std::string& key, char end, double factor) {
  for (auto at = s.find(key); at != std::string::npos; at = s.find(key, at + 1)) {
    const auto from = at + key.size();
    auto to = s.find(end, from);
    if (end == ' ') to = s.find_first_not_of("0123456789.", from);
    double n = 0;
    if (to == std::string::npos || to == from || !ParseDouble(s.substr(from, to - from), &n))
      continue;
    s.replace(from, to - from, FormatNumber(std::round(n * factor * 100) / 100));
  }
  return s;
}

// "set title '...'" lines over 60 characters (the model's description) become
// "set title ''"; the panels' short titles stay.
std::string DropLongTitles(const std::string& s) {
  std::istringstream in(s);
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind("set title ", 0) == 0 && line.size() > 60) line = "set title ''";
    out += line + "\n";
  }
  if (!s.empty() && s.back() != '\n') out.pop_back();
  return out;
}

}  // namespace

std::optional<FigureLayout> FigureLayoutOf(const Arguments& args) {
  if (!args.Given("size") && !args.Given("font")) return std::nullopt;
  FigureLayout l;
  const std::string size = args.Text("size", "double");
  const auto bad_size = [&] {
    return UsageError("invalid value '" + size + "' for " + args.Source("size") +
                      ": must be single, double or WxH in inches (e.g. 3.5x2.6), each in [1, 20]");
  };
  if (size == "single") {
    l.width_in = kSingleColumn;
  } else if (size == "double") {
    l.width_in = kDoubleColumn;
  } else {
    const auto x = size.find('x');
    if (x == std::string::npos || !ParseDouble(size.substr(0, x), &l.width_in) ||
        !ParseDouble(size.substr(x + 1), &l.height_in))
      throw bad_size();
    if (l.height_in < kMinInches || l.height_in > kMaxInches) throw bad_size();
  }
  if (l.width_in < kMinInches || l.width_in > kMaxInches) throw bad_size();
  const std::string font = args.Text("font", l.width_in < 5 ? "Sans,7" : "Sans,9");
  const auto comma = font.rfind(',');
  double pt = 0;
  if (!ParseDouble(comma == std::string::npos ? font : font.substr(comma + 1), &pt) ||
      pt < kMinPoints || pt > kMaxPoints || (comma != std::string::npos && comma == 0))
    throw UsageError("invalid value '" + font + "' for " + args.Source("font") +
                     ": must be NAME,PT or PT with PT in [4, 30] (e.g. Sans,8)");
  l.font = comma == std::string::npos ? "Sans," + font : font;
  return l;
}

std::string ApplyFigureLayout(const std::string& script, const FigureLayout& l) {
  const auto at = script.find("set terminal ");
  if (at == std::string::npos) return script;
  const auto end = script.find('\n', at);
  const std::string line = script.substr(at, end - at);
  std::istringstream words(line.substr(13));
  std::string terminal, word, size;
  words >> terminal;
  while (words >> word)
    if (word == "size" && words >> size) break;
  double w = 0, h = 0;
  const auto comma = size.find(',');
  auto inches = [](std::string s) {  // "10in" or "1000"
    if (s.size() > 2 && s.compare(s.size() - 2, 2, "in") == 0) s.resize(s.size() - 2);
    return s;
  };
  if (comma == std::string::npos || !ParseDouble(inches(size.substr(0, comma)), &w) ||
      !ParseDouble(inches(size.substr(comma + 1)), &h) || w <= 0 || h <= 0)
    return script;
  const double wi = l.width_in, hi = l.height_in > 0 ? l.height_in : wi * h / w;
  const std::string font = "font '" + l.font + "'";
  double pt = kScreenPoints;
  ParseDouble(l.font.substr(l.font.rfind(',') + 1), &pt);
  // Cairo sizes text for 96 dpi (pdfcairo's fontscale 0.75 makes PT points);
  // a line width unit is half a point.
  const std::string name = l.font.substr(0, l.font.rfind(','));
  std::string t;
  if (terminal == "pdfcairo") {
    t = "set terminal pdfcairo size " + FormatNumber(wi) + "in," + FormatNumber(hi) +
        "in enhanced " + font + " fontscale 0.75 linewidth " + FormatNumber(kLineWidth) +
        " dashlength 1.5";
  } else if (terminal == "svg") {  // 96 units an inch, the font in units
    t = "set terminal svg size " + FormatNumber(std::round(wi * kSvgDpi)) + "," +
        FormatNumber(std::round(hi * kSvgDpi)) + " enhanced font '" + name + "," +
        FormatNumber(std::round(pt * kSvgDpi / 72 * 10) / 10) + "' linewidth " +
        FormatNumber(kLineWidth * kSvgDpi / 144) + " dashlength 1.5 background '#ffffff'";
  } else {
    t = "set terminal pngcairo size " + FormatNumber(std::round(wi * kPngDpi)) + "," +
        FormatNumber(std::round(hi * kPngDpi)) + " enhanced " + font + " fontscale " +
        FormatNumber(kPngDpi / kSvgDpi) + " linewidth " + FormatNumber(kLineWidth * kPngDpi / 144) +
        " dashlength 1.5";
  }
  std::string rest = ScaleAfter(script.substr(end), "font ',", '\'', pt / kScreenPoints);
  rest = ScaleAfter(rest, " ps ", ' ', kPointSize);
  // Below 5 in the model's line is wider than the figure: the caption says it.
  if (wi < 5) rest = DropLongTitles(rest);
  return script.substr(0, at) + t + rest;
}

}  // namespace stickslip::cli
