#include "stickslip/io/figure_style.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {

const char* const kFillStickSlip = "#a6cee3";
const char* const kFillPureSlip = "#fdbf6f";
const char* const kFillEquilibrium = "#d9d9d9";
const char* const kFillUndecided = "#ffffff";
const char* const kFillContactLost = "#ffe066";
const char* const kFillSettling = "#c7eae5";

bool ParseFigureFormat(const std::string& text, FigureFormat* f) { return FromName(text, f); }

std::string FigureFile(const std::string& stem, FigureFormat f) { return stem + "." + Name(f); }

const char* SeriesColor(int i) {
  static const char* const kColors[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                        "#e69f00", "#56b4e9", "#000000", "#f0e442"};
  return kColors[((i % 8) + 8) % 8];
}

std::string FigureTerminal(FigureFormat f, int width, int height) {
  std::ostringstream os;
  switch (f) {
    case FigureFormat::kPng:
      os << "set terminal pngcairo size " << width << "," << height << " enhanced font 'Sans,12'";
      break;
    case FigureFormat::kPdf:
      os << "set terminal pdfcairo size " << width / 100.0 << "in," << height / 100.0
         << "in enhanced font 'Sans,9'";
      break;
    case FigureFormat::kSvg:
      os << "set terminal svg size " << width << "," << height
         << " enhanced font 'Sans,12' background '#ffffff'";
      break;
  }
  return os.str() + "\n";
}

std::string FigurePreamble(FigureFormat f, int width, int height) {
  std::ostringstream os;
  os << FigureTerminal(f, width, height) << "set encoding utf8\n"
     << "set datafile separator '\\t'\nset datafile columnheaders\n"
     << "set grid lc rgb '#e0e0e0' lw 0.5\nset border lw 1\n"
     << "set style line 1 lc rgb '#0072b2' lw 2 dt 1\n"
     << "set style line 2 lc rgb '#0072b2' lw 2 dt 2\n"
     << "set style line 3 lc rgb '#d55e00' lw 2 dt 1\n"
     << "set style line 4 lc rgb '#d55e00' lw 2 dt 2\n"
     << "set style line 5 lc rgb '#606060' lw 2 dt 1\n"
     << "set style line 6 lc rgb '#606060' lw 2 dt 2\n"
     << "set style line 7 lc rgb '#000000' lw 1 dt 3\n"
     << "set style line 8 lc rgb '#000000' pt 7 ps 1.0\n"
     << "set style line 9 lc rgb '#000000' lw 2.5 dt 1\n"
     << "set style line 10 lc rgb '#009e73' lw 2 dt 2\n"
     << "set style line 11 lc rgb '#cc79a7' lw 2 dt 4\n"
     << "set style line 12 lc rgb '#e69f00' lw 2 dt 5\n"
     << "set key outside below center horizontal box lc rgb '#c0c0c0' samplen 3 spacing 1.1 "
        "height 0.5\nset bmargin 7\n"
     << "set style textbox opaque noborder margins 1,1\n";
  return os.str();
}

namespace {
// The symbol of a parameter name, in enhanced text; empty if it has none.
std::string Symbol(const std::string& w) {
  if (w == "beta") return "β";
  if (w == "delta") return "δ";
  if (w == "mu_s" || w == "mu_m" || w == "mu_k") return "μ_" + w.substr(3);
  if (w == "v_m" || w == "v_s") return "v_" + w.substr(2);
  if (w == "k5") return "k_5";
  if (w == "omega") return "Ω";  // the forced oscillator: A cos(Ω t)
  if (w == "force") return "A";
  return "";
}
}  // namespace

std::string EnhancedText(const std::string& plain) {
  std::string out;
  std::size_t i = 0;
  while (i < plain.size()) {
    std::size_t j = i;
    while (j < plain.size() &&
           (std::isalnum(static_cast<unsigned char>(plain[j])) || plain[j] == '_'))
      ++j;
    if (j > i) {
      const std::string word = plain.substr(i, j - i);
      const std::string sym = Symbol(word);
      if (!sym.empty()) {
        out += sym;
      } else {
        for (char c : word) out += c == '_' ? std::string("\\\\_") : std::string(1, c);
      }
      i = j;
      continue;
    }
    const char c = plain[i++];
    if (c == '^' || c == '{' || c == '}' || c == '@' || c == '&' || c == '~') out += "\\\\";
    out += c;
  }
  return out;
}

namespace {
// A model parameter is shown only if the law has it, and the cubic law's
// quintic term only when on (k5 = 0 is seed eq. 3.3 itself).
bool TitleShows(const std::string& key, const std::string& value,
                const std::vector<std::string>& own) {
  if (!IsParameterName(key)) return true;  // A, Ω, ...
  if (std::find(own.begin(), own.end(), key) == own.end()) return false;
  return !(key == "k5" && value == "0");
}
}  // namespace

std::string SystemFigureTitle(const std::string& description) {
  const std::size_t colon = description.find(": ");
  std::istringstream in(colon == std::string::npos ? description : description.substr(colon + 2));
  std::string out =
      colon == std::string::npos ? "" : EnhancedText(description.substr(0, colon)) + ":";
  std::size_t line = out.size();  // the current line's plain length, about
  const char* sep = out.empty() ? "" : " ";
  for (std::string word; in >> word;) {
    const std::size_t eq = word.find('=');
    if (eq == std::string::npos || word.compare(eq + 1, 1, "[") == 0) continue;
    if (line + word.size() + 4 > kTitleWidth) sep = *sep == ',' ? ",\n" : "\n", line = 0;
    out += sep + EnhancedText(word.substr(0, eq)) + " = " + word.substr(eq + 1);
    line += word.size() + 4;
    sep = ", ";
  }
  return out;
}

std::string WrapWords(const std::string& text, std::size_t width) {
  std::istringstream in(text);
  std::string out;
  std::size_t line = 0;
  for (std::string word; in >> word;) {
    if (line > 0 && line + 1 + word.size() > width)
      out += '\n', line = 0;
    else if (line > 0)
      out += ' ', ++line;
    out += word;
    line += word.size();
  }
  return out;
}

std::string FigureTitle(const std::string& description, const std::vector<std::string>& axes) {
  std::vector<std::string> items;  // "key=value" (a value may hold spaces) or "(...)"
  std::istringstream in(description);
  std::string word;
  while (in >> word) {
    if (word.find('=') == std::string::npos && word[0] != '(' && !items.empty())
      items.back() += " " + word;
    else
      items.push_back(word);
  }
  std::string law, out, tail;
  std::vector<std::string> own = AllParameterNames();  // the law's own once law= is read
  for (const std::string& it : items) {
    const std::size_t eq = it.find('=');
    if (eq == std::string::npos) {
      tail += " " + EnhancedText(it);
      continue;
    }
    const std::string key = it.substr(0, eq), value = it.substr(eq + 1);
    if (key == "law") {  // proper names capitalised, as ChartTitle does
      const bool named = value == "stribeck" || value == "leine" || value == "coulomb";
      law = (named ? std::string(1, static_cast<char>(std::toupper(value[0]))) + value.substr(1)
                   : EnhancedText(value)) +
            " law";
      try {
        own = ParameterNames(LawFromName(value));
      } catch (const InvalidArgument&) {  // not a law: every parameter shown
      }
    } else if (!TitleShows(key, value, own) ||
               std::find(axes.begin(), axes.end(), key) != axes.end()) {
      continue;
    } else {
      out += (out.empty() ? "" : ", ") + EnhancedText(key) + " = " + EnhancedText(value);
    }
  }
  return law + (law.empty() || out.empty() ? "" : ": ") + out + tail;
}

std::string GnuplotQuoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"')
      out += "\\\"";
    else if (c == '\n')
      out += "\\n";
    else
      out += c;  // backslashes are already doubled by EnhancedText
  }
  return out + "\"";
}

namespace {
std::string Dimensionless(const ParameterAxis& param, const FigureAxis& a) {
  if (!a.label.empty()) return a.label;
  // The parameters a physical run gives in units (cli/physical.hpp's axes).
  const Parameter id = param.id();
  const bool has_units = id == Parameter::kV || id == Parameter::kBeta || id == Parameter::kVM ||
                         id == Parameter::kVS || id == Parameter::kDelta;
  return ParameterAxisLabel(param) + (has_units ? " (dimensionless)" : "");
}
}  // namespace

std::string FigureUnits::LengthUnit() const { return si ? " [m]" : " (dimensionless)"; }
std::string FigureUnits::TimeUnit() const { return si ? " [s]" : " (dimensionless)"; }
std::string FigureUnits::SpeedUnit() const { return si ? " [m/s]" : " (dimensionless)"; }
std::string FigureUnits::P1Label(const ParameterAxis& param) const {
  return Dimensionless(param, p1);
}
std::string FigureUnits::P2Label(const ParameterAxis& param) const {
  return Dimensionless(param, p2);
}

std::string FigureUnitVariables(const FigureUnits& u) {
  std::ostringstream os;
  os.precision(17);
  os << "ul = " << u.length << "\nut = " << u.time << "\nuv = " << u.length / u.time
     << "\nup = " << u.p1.factor << "\nup2 = " << u.p2.factor << "\n";
  return os.str();
}

std::string ParameterAxisLabel(const ParameterAxis& param) {
  // The words of --help (cli/study.cpp), one set for every figure.
  static constexpr NamedValue<Parameter> kWords[] = {
      {Parameter::kV, "belt speed v"},
      {Parameter::kBeta, "damping ratio β"},
      {Parameter::kMuS, "static friction coefficient μ_s"},
      {Parameter::kMuM, "minimum friction coefficient μ_m"},
      {Parameter::kMuK, "kinetic friction coefficient μ_k"},
      {Parameter::kVM, "speed of minimum friction v_m"},
      {Parameter::kVS, "Stribeck speed v_s"},
      {Parameter::kDelta, "friction decay rate δ"},
      {Parameter::kK5, "quintic coefficient k_5"},
      {Parameter::kOmega, "forcing frequency Ω"},
      {Parameter::kForce, "force amplitude A"},
  };
  for (const auto& w : kWords)
    if (w.value == param.id()) return w.name;
  return EnhancedText(param.name());
}

}  // namespace stickslip
