// TsvTable's layout (report.hpp): "# key: value" lines, then the header line
// without '#', then the rows; what pandas (comment='#') and csv.DictReader read.
#include "stickslip/report.hpp"

#include <gtest/gtest.h>

#include "stickslip/errors.hpp"

namespace ss = stickslip;

TEST(Report, TableStartsWithMetadataThenAHeaderWithoutHash) {
  ss::TsvTable t({"v", "kind"});
  t.AddMeta("status", "complete");
  t.AddRow({0.25, "stick-slip"});
  t.PrependMeta({{"tool", "ss_continue 0.1.0"}, {"beta", "0.05"}});
  EXPECT_EQ(t.str(),
            "# tool: ss_continue 0.1.0\n# beta: 0.05\n# status: complete\n"
            "v\tkind\n0.25\tstick-slip\n");
}

TEST(Report, MetadataKeyWithColonOrLineBreakIsRejected) {
  ss::TsvTable t({"v"});
  EXPECT_THROW(t.AddMeta("a:b", "1"), ss::InvalidArgument);
  EXPECT_THROW(t.AddMeta("", "1"), ss::InvalidArgument);
  EXPECT_THROW(t.AddMeta("key", "two\nlines"), ss::InvalidArgument);
}
