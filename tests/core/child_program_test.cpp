// Running another of gfield's programs (gfield/child_program.hpp): where it is looked for, and
// the wait status of one that exits, one that a signal kills and one that cannot be started.

#include "gfield/child_program.hpp"

#include <sys/wait.h>

#include <cstdlib>

#include <gtest/gtest.h>

namespace gfield {
namespace {

TEST(ChildProgram, ExitCodesAndSignalsComeBackAndAMissingProgramIsFalse) {
  int status = 0;
  ASSERT_TRUE(run_child({"/bin/sh", "-c", "exit 3"}, false, status));
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(child_exit_code(status), 3);
  ASSERT_TRUE(run_child({"/bin/sh", "-c", "kill -9 $$"}, true, status));
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(child_exit_code(status), 128 + 9);
  EXPECT_FALSE(run_child({"/nonexistent/program"}, false, status));
}

TEST(ChildProgram, TheEnvironmentFirstThenTheBuildTreeThenThePath) {
  ::setenv("GFIELD_CHILD_TEST", "/somewhere/tool", 1);
  EXPECT_EQ(sibling_executable("GFIELD_CHILD_TEST", "no-such-tool", "/bin/sh"), "/somewhere/tool");
  ::setenv("GFIELD_CHILD_TEST", "", 1);
  EXPECT_EQ(sibling_executable("GFIELD_CHILD_TEST", "no-such-tool", "/bin/sh"), "/bin/sh");
  EXPECT_EQ(sibling_executable("GFIELD_CHILD_TEST", "no-such-tool", "/nonexistent/tool"),
            "no-such-tool");
  ::unsetenv("GFIELD_CHILD_TEST");
}

}  // namespace
}  // namespace gfield
