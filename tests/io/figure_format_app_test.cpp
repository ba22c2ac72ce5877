// The figures' format (issue 22 item 4): --format png|pdf|svg in every app
// that draws, each format's whole-file check (PDF: %PDF- ... %%EOF; SVG: ...
// </svg>), a bad value refused naming --format, and the shared style's titles.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "cli/gnuplot.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/io/branch_report.hpp"
#include "stickslip/io/figure_style.hpp"
#include "test_paths.hpp"

namespace stickslip {
namespace {

using testing_util::Exists;
using testing_util::ReadFile;
using testing_util::WriteFile;

using stickslip::testing_util::HaveGnuplot;

class FigureFormatTest : public testing_util::AppTest {
 protected:
  int Run(const std::string& app, const std::string& args) { return RunApp(kBin, app, args); }
};

TEST_F(FigureFormatTest, PdfAndSvgChecksAcceptOnlyWholeFiles) {
  const std::string pdf = "%PDF-1.5\n" + std::string(300, 'p') + "\n%%EOF\n";
  const std::string svg = "<?xml version=\"1.0\"?>\n<svg>" + std::string(300, 's') + "</svg>\n\n";
  WriteFile(dir_ + "/whole.pdf", pdf);
  WriteFile(dir_ + "/cut.pdf", pdf.substr(0, 200));
  WriteFile(dir_ + "/text.pdf", std::string(200, 't') + "%%EOF");
  WriteFile(dir_ + "/empty.pdf", "");
  WriteFile(dir_ + "/whole.svg", svg);
  WriteFile(dir_ + "/cut.svg", svg.substr(0, 200));
  WriteFile(dir_ + "/text.svg", "hello</svg>");
  WriteFile(dir_ + "/pdf.png", pdf);  // a PDF named .png is checked as a PNG
  EXPECT_EQ(cli::FigureError(dir_ + "/whole.pdf"), "");
  EXPECT_NE(cli::FigureError(dir_ + "/cut.pdf").find("truncated PDF"), std::string::npos);
  EXPECT_NE(cli::FigureError(dir_ + "/text.pdf").find("not a PDF"), std::string::npos);
  EXPECT_NE(cli::FigureError(dir_ + "/empty.pdf").find("empty"), std::string::npos);
  EXPECT_NE(cli::FigureError(dir_ + "/missing.pdf"), "");
  EXPECT_EQ(cli::FigureError(dir_ + "/whole.svg"), "");
  EXPECT_NE(cli::FigureError(dir_ + "/cut.svg").find("truncated SVG"), std::string::npos);
  EXPECT_NE(cli::FigureError(dir_ + "/text.svg").find("not an SVG"), std::string::npos);
  EXPECT_NE(cli::FigureError(dir_ + "/pdf.png").find("not a PNG"), std::string::npos);
}

TEST(FigureStyle, FormatNamesAndTitles) {
  FigureFormat f = FigureFormat::kPng;
  EXPECT_TRUE(ParseFigureFormat("svg", &f));
  EXPECT_EQ(f, FigureFormat::kSvg);
  EXPECT_FALSE(ParseFigureFormat("PDF", &f));
  EXPECT_FALSE(ParseFigureFormat("jpg", &f));
  EXPECT_EQ(FigureFile("basins", FigureFormat::kPdf), "basins.pdf");
  // The axis parameter's range is left out; names become symbols.
  // Only the law's own parameters: k5 = 0 (the cubic law without its quintic
  // term) and another law's parameter (mu_m for Stribeck) are left out.
  EXPECT_EQ(FigureTitle("law=cubic beta=0.05 v=[0.05, 0.5] mu_s=0.4 k5=0 (partial)", {"v"}),
            "cubic law: β = 0.05, μ_s = 0.4 (partial)");
  EXPECT_EQ(FigureTitle("law=cubic mu_s=0.4 k5=0.24", {}), "cubic law: μ_s = 0.4, k_5 = 0.24");
  EXPECT_EQ(FigureTitle("law=stribeck mu_k=0.25 mu_m=0.25 v_s=0.5 force=0.5", {}),
            "Stribeck law: μ_k = 0.25, v_s = 0.5, A = 0.5");
  EXPECT_EQ(EnhancedText("a_b^c"), "a\\\\_b\\\\^c");  // escaped for a double-quoted string
  // The forced oscillator's parameters as the issue writes them: A cos(Ω t).
  EXPECT_EQ(FigureTitle("law=coulomb beta=0 force=1 omega=[0.75, 2.5]", {"omega"}),
            "Coulomb law: β = 0, A = 1");
  // A system's line: the bracketed (axes, continued) left out, names as symbols.
  EXPECT_EQ(SystemFigureTitle("chain: v=[axis] kc=0.2 beta=0.05 mu_s=0.4 k1=[continued]"),
            "chain: kc = 0.2, β = 0.05, μ_s = 0.4");
  EXPECT_EQ(SystemFigureTitle("kc=0.2"), "kc = 0.2");  // no name: no leading blank
  // A system's k5 (a chain's block-5 stiffness) is not the cubic law's k_5.
  EXPECT_EQ(SystemFigureTitle("chain: k4=1 k5=1"), "chain: k4 = 1, k5 = 1");
  EXPECT_EQ(EnhancedText("c5=0.1 k5=1", false), "c5=0.1 k5=1");
  EXPECT_EQ(EnhancedText("k5=1"), "k_5=1");
  EXPECT_EQ(ParameterAxisLabel(Parameter::kForce), "force amplitude A");
  EXPECT_EQ(ParameterAxisLabel(Parameter::kBeta), "damping ratio β");
  EXPECT_NE(FigurePreamble(FigureFormat::kPdf, 1000, 700).find("pdfcairo size 10in,7in"),
            std::string::npos);
}

// Every drawing app writes each format whole under the right names, and
// refuses any other value with exit 2 naming --format, creating nothing.
TEST_F(FigureFormatTest, EveryAppDrawsEachFormatWhole) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string seed = " --study " + kStudies + "/seed.ini";
  for (FigureFormat f : {FigureFormat::kPdf, FigureFormat::kSvg}) {
    const std::string ext = Name(f), out = dir_ + "/" + ext;
    ASSERT_EQ(::mkdir(out.c_str(), 0755), 0);
    ASSERT_EQ(Run("ss_continue", seed + " --format " + ext + " --out " + out + "/c"), 0) << err_;
    for (const std::string& fig : BifurcationFigures(true, f)) {
      EXPECT_EQ(cli::FigureError(out + "/c/" + fig), "") << fig;
      EXPECT_EQ(fig.substr(fig.size() - 4), "." + ext);
    }
    EXPECT_FALSE(Exists(out + "/c/period.png"));
    ASSERT_EQ(
        Run("ss_basin", "--study " + kStudies + "/stribeck_basin.ini --nx 9 --ny 9 --format " +
                            ext + " --out " + out + "/b"),
        0)
        << err_;
    EXPECT_EQ(cli::FigureError(out + "/b/basins." + ext), "");
    ASSERT_EQ(Run("ss_basin", "--study " + kStudies +
                                  "/stribeck_basin_stability.ini --from 0.56 --to 0.64 --n 3 " +
                                  "--format " + ext + " --out " + out + "/bs"),
              0)
        << err_;
    EXPECT_EQ(cli::FigureError(out + "/bs/basin_stability." + ext), "");
    EXPECT_FALSE(Exists(out + "/bs/basin_stability.png"));
    ASSERT_EQ(Run("ss_simulate", seed + " --t_end 20 --format " + ext + " --out " + out + "/s"), 0)
        << err_;
    EXPECT_EQ(cli::FigureError(out + "/s/trajectory." + ext), "");
    ASSERT_EQ(Run("ss_chart", "--study " + kStudies + "/seed_chart.ini --format " + ext +
                                  " --out " + out + "/h"),
              0)
        << err_;
    EXPECT_EQ(cli::FigureError(out + "/h/chart." + ext), "");
  }
  // A real gnuplot PDF cut short fails the check.
  const std::string whole = ReadFile(dir_ + "/pdf/c/period.pdf");
  WriteFile(dir_ + "/cut.pdf", whole.substr(0, whole.size() - 20));
  EXPECT_NE(cli::FigureError(dir_ + "/cut.pdf").find("truncated"), std::string::npos);
}

// Every forced study draws its figure (bifurcation.png) whole. floor_static has one
// special point: its figure once crashed gnuplot 5.4 (a labels plot with no
// defined point), and the run exited 1.
TEST_F(FigureFormatTest, ForcedStudiesDrawTheirResonanceFigure) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  for (const char* study : {"den_hartog", "floor_static", "seed_forced", "stribeck_forced"}) {
    const std::string out = dir_ + "/" + study;
    ASSERT_EQ(Run("ss_continue", "--study " + kStudies + "/" + study + ".ini --out " + out), 0)
        << study << ": " << err_;
    EXPECT_EQ(cli::FigureError(out + "/bifurcation.png"), "") << study;
  }
}

TEST_F(FigureFormatTest, BadFormatExits2NamingTheOption) {
  const std::string seed = " --study " + kStudies + "/seed.ini";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"ss_continue", seed + " --out " + dir_ + "/o"},
      {"ss_basin", seed + " --out " + dir_ + "/o"},
      {"ss_basin", "--study " + kStudies + "/stribeck_basin_stability.ini --out " + dir_ + "/o"},
      {"ss_simulate", seed + " --out " + dir_ + "/o"},
      {"ss_chart", "--study " + kStudies + "/seed_chart.ini --out " + dir_ + "/o"}};
  for (const auto& [app, args] : runs) {
    EXPECT_EQ(Run(app, args + " --format jpg"), 2) << app;
    EXPECT_NE(err_.find("--format"), std::string::npos) << app << ": " << err_;
    EXPECT_NE(err_.find("jpg"), std::string::npos) << app << ": " << err_;
    EXPECT_FALSE(Exists(dir_ + "/o")) << app;
    EXPECT_FALSE(Exists(dir_ + "/o.tsv")) << app;
  }
}

}  // namespace
}  // namespace stickslip
