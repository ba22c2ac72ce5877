// The apps' model compiler is a module loaded when a model file is read
// (systems/model_file/compile_loaded.cpp): an app that reads none does not
// load GiNaC, one that reads one does, and an app without the module next to
// it (nor where `cmake --install` puts it) refuses a model file in one line
// and still runs a built-in system.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;

const std::string kBelt = STICKSLIP_SOURCE_DIR "/studies/models/belt.ini";
const std::string kRun = "--t_end 20 --no_plots --out ";

class ModelModuleApp : public tu::AppTest {
 protected:
  // RunApp under LD_DEBUG=files: the dynamic loader names each object it
  // loads on stderr.
  int RunTraced(const std::string& bin_dir, const std::string& args) {
    ::setenv("LD_DEBUG", "files", 1);
    const int code = RunApp(bin_dir, "ss_simulate", args);
    ::unsetenv("LD_DEBUG");
    return code;
  }
};

TEST_F(ModelModuleApp, GiNaCIsLoadedOnlyForAModelFile) {
  const std::string bin = STICKSLIP_BIN_DIR;
  ASSERT_EQ(RunTraced(bin, kRun + tu::ShellQuoted(NewDir())), 0) << err_;
  EXPECT_FALSE(tu::Contains(err_, "libginac")) << "a built-in system loaded GiNaC";
  EXPECT_FALSE(tu::Contains(err_, "libstickslip_model_compiler")) << err_;
  ASSERT_EQ(RunTraced(bin, "--model " + tu::ShellQuoted(kBelt) + " " + kRun +
                               tu::ShellQuoted(NewDir())),
            0)
      << err_;
  EXPECT_TRUE(tu::Contains(err_, "libstickslip_model_compiler.so"));
  EXPECT_TRUE(tu::Contains(err_, "libginac"));
}

TEST_F(ModelModuleApp, WithoutTheModuleAModelFileIsRefusedInOneLine) {
  const std::string bin = NewDir();
  ASSERT_EQ(std::system(("cp " + tu::ShellQuoted(std::string(STICKSLIP_BIN_DIR) + "/ss_simulate") +
                         " " + tu::ShellQuoted(bin))
                            .c_str()),
            0);
  const std::string out = NewDir() + "/out";
  EXPECT_EQ(RunApp(bin, "ss_simulate", "--model " + tu::ShellQuoted(kBelt) + " " + kRun +
                                           tu::ShellQuoted(out)),
            2)
      << err_;
  EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
  EXPECT_TRUE(tu::Contains(err_, "--model " + kBelt + ": cannot load the model compiler: "));
  EXPECT_TRUE(tu::Contains(err_, bin + "/libstickslip_model_compiler.so"));
  EXPECT_FALSE(tu::Exists(out)) << err_;
  // The app itself needs no module: the built-in belt runs.
  EXPECT_EQ(RunApp(bin, "ss_simulate", kRun + tu::ShellQuoted(out)), 0) << err_;
  EXPECT_TRUE(tu::Exists(out + "/trajectory.tsv"));
}

}  // namespace
