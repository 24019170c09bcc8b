// --camera words (core/camera_text): read back exactly what they print, keep what they do not
// give, and refuse what a scene file's camera would refuse.

#include "gfield/camera_text.hpp"

#include <gtest/gtest.h>

namespace gfield {
namespace {

TEST(CameraText, PrintsWhatItReadsBackExactly) {
  Camera c;
  c.position = {-1.87917745f, 2.8225317f, 7.35945559f};
  c.target = {0.0f, 1.1f, 0.0f};
  c.up = {0.0f, 1.0f, 0.0f};
  c.fov_degrees = 42.0f;
  EXPECT_EQ(camera_text(c), "-1.8791775,2.8225317,7.3594556,0,1.1,0,0,1,0,42");
  Camera back;
  std::string error;
  ASSERT_TRUE(parse_camera_text(camera_text(c), back, error)) << error;
  EXPECT_EQ(back.position, c.position);
  EXPECT_EQ(back.target, c.target);
  EXPECT_EQ(back.up, c.up);
  EXPECT_EQ(back.fov_degrees, c.fov_degrees);
}

TEST(CameraText, SixNumbersKeepUpAndFieldOfView) {
  Camera c;
  c.up = {0.0f, 0.0f, 1.0f};
  c.fov_degrees = 30.0f;
  std::string error;
  ASSERT_TRUE(parse_camera_text("1,2,3,0,0,0", c, error)) << error;
  EXPECT_EQ(c.position, glm::vec3(1, 2, 3));
  EXPECT_EQ(c.up, glm::vec3(0, 0, 1));
  EXPECT_EQ(c.fov_degrees, 30.0f);
}

TEST(CameraText, RefusesBadWordsAndBadCamerasAndKeepsTheCamera) {
  const Camera before;
  for (const char* text : {"", "1,2,3", "1,2,3,4,5,6,7", "1,2,3,4,5,6,7,8,9,10,11", "1,2,3,4,5,x",
                           "1,2,3,4,5,nan", "1,2,3,4,5,1e99", "1,,3,4,5,6", "1,2,3,4,5,6,"}) {
    Camera c = before;
    std::string error;
    EXPECT_FALSE(parse_camera_text(text, c, error)) << text;
    EXPECT_NE(error.find("expected EX,EY,EZ,TX,TY,TZ"), std::string::npos) << text << ": " << error;
    EXPECT_EQ(c.position, before.position);
  }
  Camera c;
  std::string error;
  EXPECT_FALSE(parse_camera_text("1,2,3,1,2,3", c, error));
  EXPECT_EQ(error, "camera position and target coincide");
  EXPECT_FALSE(parse_camera_text("0,0,5,0,0,0,0,0,1", c, error));
  EXPECT_EQ(error, "up is zero or parallel to the view direction");
  EXPECT_FALSE(parse_camera_text("0,0,5,0,0,0,0,1,0,180", c, error));
  EXPECT_EQ(error, "vertical field of view must be in (0, 180) degrees");
}

}  // namespace
}  // namespace gfield
