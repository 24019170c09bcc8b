#include "gfield/printable.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include <nlohmann/json.hpp>

namespace gfield {
namespace {

TEST(Printable, KeepsUtf8AndEscapesTheRest) {
  EXPECT_EQ(printable("spot.obj"), "spot.obj");
  EXPECT_EQ(printable("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"),
            "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");  // é, €, an emoji
  EXPECT_EQ(printable("caf\xE9.obj"), "caf\\xE9.obj");     // Latin-1 é
  EXPECT_EQ(printable("a\nb\rc\td\x01\x7F"), "a\\nb\\rc\\td\\x01\\x7F");
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");                    // overlong '/'
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");           // a surrogate
  EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
  EXPECT_EQ(printable("\xE2\x82"), "\\xE2\\x82");                    // cut short
  EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
}

TEST(Printable, AlwaysGivesOneLineThatJsonCanDump) {
  std::string every_byte;
  for (int c = 0; c < 256; ++c) {
    every_byte += char(c);
  }
  const std::string text = printable(every_byte);
  EXPECT_EQ(text.find('\n'), std::string::npos);
  EXPECT_NO_THROW((void)nlohmann::json(text).dump());
}

TEST(Printable, FloatTextIsTheShortestThatReadsBack) {
  EXPECT_EQ(float_text(0.005f), "0.005");
  EXPECT_EQ(float_text(42.0f), "42");
  EXPECT_EQ(float_text(-0.0f), "-0");
  EXPECT_EQ(float_text(1e-30f), "1e-30");
  for (float v : {3.20000005f, 0.1f, 1.0f / 3.0f, 16777217.0f, 3.4e38f, 1.17549435e-38f}) {
    const std::string text = float_text(v);
    EXPECT_EQ(std::strtof(text.c_str(), nullptr), v) << text;
    EXPECT_LE(text.size(), 15u) << text;
  }
}

}  // namespace
}  // namespace gfield
