// --format svg keeps the space after a subscript: gnuplot's svg terminal puts
// the text after "x_{max}" or "μ_s" in a tspan of its own that starts with the
// space, and renderers drop such a space unless the root says
// xml:space="preserve" ("μs= 0.4" instead of "μs = 0.4").
#include <gtest/gtest.h>

#include <string>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class SvgFigureApp : public tu::AppTest {};

TEST_F(SvgFigureApp, SpaceAfterASubscriptIsPreserved) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_continue", dir,
             {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/stribeck_forced.ini",
              "--from", "0.7", "--to", "0.65", "--format", "svg"},
             true);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string svg = tu::ReadFile(dir + "/out/bifurcation.svg");
  const auto root = svg.find("<svg");
  ASSERT_NE(root, std::string::npos);
  const std::string tag = svg.substr(root, svg.find('>', root) - root);
  EXPECT_TRUE(tu::Contains(tag, "xml:space=\"preserve\"")) << tag;
  // The title's "μ_s = 0.4": the text after the subscript keeps its space.
  EXPECT_TRUE(tu::Contains(svg, "dy=\"-3.60px\"> = 0.4, μ</tspan>"));
}

}  // namespace
