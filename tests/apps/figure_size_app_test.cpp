// --size and --font: the figure drawn at its printed size. A PDF of
// --size single is 3.5 in wide (252 pt in its MediaBox) at the script's
// aspect ratio, its text in points at the font given; bad values are exit 2
// naming the option, nothing written.
#include <gtest/gtest.h>

#include <string>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class FigureSizeApp : public tu::AppTest {};

TEST_F(FigureSizeApp, SingleColumnPdfIsThreeAndAHalfInchesWide) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_continue", dir,
             {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/seed.ini", "--no_estimates",
              "--format", "pdf", "--size", "single", "--font", "Sans,8"},
             true);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string gp = tu::ReadFile(dir + "/out/bifurcation.gp");
  EXPECT_TRUE(tu::Contains(gp, "set terminal pdfcairo size 3.5in,")) << gp.substr(0, 300);
  EXPECT_TRUE(tu::Contains(gp, "font 'Sans,8' fontscale 0.75"));
  // The page: 3.5 in = 252 pt wide (PDF units are points).
  const std::string pdf = tu::ReadFile(dir + "/out/period.pdf");
  EXPECT_TRUE(tu::Contains(pdf, "/MediaBox [ 0 0 252 ")) << "not 3.5 in wide";
}

TEST_F(FigureSizeApp, BadSizeOrFontIsExitTwoNamingTheOption) {
  for (const auto& [option, value] :
       std::vector<std::pair<std::string, std::string>>{{"--size", "triple"},
                                                        {"--size", "0.5x2"},
                                                        {"--size", "3.5x"},
                                                        {"--font", "Sans,2"},
                                                        {"--font", "Sans,x"}}) {
    const std::string dir = NewDir();
    const auto r = RunOut("ss_continue", dir, {option, value});
    EXPECT_EQ(r.outcome.code, 2) << option << " " << value;
    EXPECT_TRUE(tu::Contains(r.err, option)) << r.err;
    EXPECT_TRUE(tu::Contains(r.err, value)) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << option << " " << value;
  }
}

}  // namespace
