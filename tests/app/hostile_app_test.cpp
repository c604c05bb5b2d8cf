// CLI helpers on hostile input (issue 19, findings 9 and 10): the directory of "/name" is "/",
// not "", and `rcache diff` does not call an image of NaNs identical to anything.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "app/cli_args.h"
#include "app/diff_command.h"
#include "app/output_checks.h"
#include "core/error.h"
#include "render/image_io.h"

namespace rc {
namespace {

TEST(OutputChecks, ParentDirectory) {
  EXPECT_EQ(parentDirectory("/s.json"), "/");
  EXPECT_EQ(parentDirectory("s.json"), ".");
  EXPECT_EQ(parentDirectory("a/b/s.json"), "a/b");
  EXPECT_EQ(parentDirectory("/tmp/s.json"), "/tmp");
}

TEST(OutputChecks, StatsAtTheRootIsNotAnEmptyDirectory) {
  RenderArgs args;
  args.statsPath = "/rc_hostile_never_written.json";
  const std::string image = "/tmp/rc_hostile_" + std::to_string(getpid()) + ".exr";
  // Whatever the permissions, the message must not name an empty directory.
  try {
    checkOutputs(args, image);
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find("directory ''"), std::string::npos) << e.what();
  }
}

TEST(Diff, NonFinitePixelsAreAnError) {
  const std::string a = "/tmp/rc_diff_nan_" + std::to_string(getpid()) + ".exr";
  const std::string b = "/tmp/rc_diff_ok_" + std::to_string(getpid()) + ".exr";
  Image nan, ok;
  nan.width = ok.width = 4;
  nan.height = ok.height = 4;
  nan.pixels.assign(16, Color(NAN));
  ok.pixels.assign(16, Color(0.5f));
  writeImage(nan, a);
  writeImage(ok, b);
  DiffArgs d;
  d.a = a;
  d.b = b;
  d.json = true;
  std::ostringstream out;
  try {
    runDiff(d, out);
    ADD_FAILURE() << "diff against an all-NaN image succeeded: " << out.str();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("16 pixel(s) are NaN or infinite"), std::string::npos) << e.what();
  }
  EXPECT_NE(out.str().find("\"non_finite\": 16"), std::string::npos) << out.str();
  d.a = b;
  std::ostringstream same;
  EXPECT_EQ(runDiff(d, same), 0);
  std::remove(a.c_str());
  std::remove(b.c_str());
}

}  // namespace
}  // namespace rc
