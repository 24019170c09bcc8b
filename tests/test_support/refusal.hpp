#pragma once
// The contract for bad input, checked on a command's run: exit 2, one line on stderr naming
// what the user must see, nothing on stdout.

#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <string>

#include "test_support/cli_run.hpp"

namespace gfield::test {

/// `run` refused its input: exit 2, one stderr line holding each of `parts` (the file, the
/// place, the value), nothing on stdout. `label` names the case in failure messages.
inline void expect_refused(const CliRun& run, std::initializer_list<std::string> parts,
                           const std::string& label = "") {
  EXPECT_EQ(run.exit_code, 2) << label << "\n" << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << label << "\n" << run.err;
  for (const std::string& part : parts)
    EXPECT_NE(run.err.find(part), std::string::npos) << label << ": must name " << part << "\n"
                                                     << run.err;
  EXPECT_TRUE(run.out.empty()) << label << "\n" << run.out;
}

}  // namespace gfield::test
