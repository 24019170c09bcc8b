#pragma once
// A camera as one command-line word, so that a view seen in the viewer can be rendered again
// headless or by the reference tracer: "EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ[,FOV]]" (eye position,
// target, up, vertical field of view in degrees; world units). gfield-view and gfield render
// take it as --camera; the viewer prints it with each screenshot.

#include <string>

#include "gfield/scene.hpp"

namespace gfield {

/// What is wrong with `camera` (as a scene file's camera is checked), "" when nothing is; `key`
/// (if given) gets the camera key at fault: "fov", "up", or "" (position and target coincide).
std::string camera_problem(const Camera& camera, std::string* key = nullptr);

/// Reads `text` over `camera`: 6, 9 or 10 comma-separated finite numbers; what is not given
/// (up, field of view) keeps the value `camera` has. False with `error` ("expected ...") when the
/// text or the camera it makes is bad; `camera` is then unchanged.
bool parse_camera_text(const std::string& text, Camera& camera, std::string& error);

/// The 10-number text of `camera` that parse_camera_text reads back exactly (float_text).
std::string camera_text(const Camera& camera);

}  // namespace gfield
