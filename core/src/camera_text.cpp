#include "gfield/camera_text.hpp"

#include "gfield/printable.hpp"

#include <cmath>
#include <cstdlib>
#include <vector>

namespace gfield {

std::string camera_problem(const Camera& camera, std::string* key) {
  std::string unused;
  std::string& at = key != nullptr ? *key : unused;
  at = "fov";
  if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f))
    return "vertical field of view must be in (0, 180) degrees";
  at = "";
  const glm::vec3 forward = camera.target - camera.position;
  if (glm::length(forward) <= 0.0f)
    return "camera position and target coincide";
  at = "up";
  if (glm::length(glm::cross(forward, camera.up)) <=
      1e-6f * glm::length(forward) * glm::length(camera.up))
    return "up is zero or parallel to the view direction";
  at = "";
  return "";
}

bool parse_camera_text(const std::string& text, Camera& camera, std::string& error) {
  const char* const expected =
      "expected EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ[,FOV]]: 6, 9 or 10 finite numbers";
  std::vector<float> numbers;
  for (const char* p = text.c_str();; ++p) {  // a number, then ',' and another, or the end
    char* end = nullptr;
    const float v = std::strtof(p, &end);
    if (end == p || !std::isfinite(v) || (*end != ',' && *end != '\0') || numbers.size() == 10) {
      error = expected;
      return false;
    }
    numbers.push_back(v);
    if (*end == '\0')
      break;
    p = end;
  }
  if (numbers.size() != 6 && numbers.size() != 9 && numbers.size() != 10) {
    error = expected;
    return false;
  }
  Camera c = camera;
  c.position = {numbers[0], numbers[1], numbers[2]};
  c.target = {numbers[3], numbers[4], numbers[5]};
  if (numbers.size() >= 9)
    c.up = {numbers[6], numbers[7], numbers[8]};
  if (numbers.size() == 10)
    c.fov_degrees = numbers[9];
  error = camera_problem(c);
  if (!error.empty())
    return false;
  camera = c;
  return true;
}

std::string camera_text(const Camera& camera) {
  const float v[10] = {camera.position.x, camera.position.y, camera.position.z, camera.target.x,
                       camera.target.y,   camera.target.z,   camera.up.x,       camera.up.y,
                       camera.up.z,       camera.fov_degrees};
  std::string text;
  for (float x : v) {
    if (!text.empty())
      text += ',';
    text += float_text(x);
  }
  return text;
}

}  // namespace gfield
