#pragma once
// The fixture of the GL tests: one headless OpenGL 4.5 context (EGL; llvmpipe in CI) for a test
// suite, made before its first test and destroyed after its last. A suite that prepares more
// (assets built by the CLI, a reference picture) defines its own SetUpTestSuite: make_context()
// first, then its preparation with ASSERTs, then `ready_ = true`; one that keeps more state
// defines TearDownTestSuite and calls GlSuite::TearDownTestSuite() last.

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "runtime/gl_context.hpp"

namespace gfield::test {

class GlSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { ready_ = make_context(); }
  static void TearDownTestSuite() {
    context_.reset();
    ready_ = false;
  }
  /// A failed suite set-up fails every test instead of letting it use what is missing.
  void SetUp() override { ASSERT_TRUE(ready_) << "the test suite's set-up failed (see above)"; }

  /// Makes the suite's context current; false, with a test failure naming the reason, when there
  /// is none.
  static bool make_context() {
    std::string error;
    context_ = GlContext::create_headless(error);
    if (context_ == nullptr) {
      ADD_FAILURE() << "no headless OpenGL 4.5 context: " << error;
    }
    return context_ != nullptr;
  }

  static inline std::unique_ptr<GlContext> context_;
  static inline bool ready_ = false;  ///< the suite's set-up finished
};

}  // namespace gfield::test
