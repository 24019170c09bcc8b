#include "runtime/view_session.hpp"

#include <cstdio>

#include "gfield/image_metrics.hpp"
#include "gfield/printable.hpp"
#include "runtime/method_registry.hpp"

namespace gfield {

ViewSession::ViewSession() {
  for (const MethodEntry& entry : method_registry())
    methods_.push_back(entry.make());
  loaded_.assign(methods_.size(), false);
}

bool ViewSession::load(const Scene& scene, const std::filesystem::path& shader_dir,
                       std::string& error) {
  shader_dir_ = shader_dir;
  loaded_.assign(methods_.size(), false);
  current_ = compare_ = -1;
  return scene_.load(scene, error);
}

int ViewSession::find(const std::string& name) const {
  for (size_t k = 0; k < methods_.size(); ++k)
    if (methods_[k]->info().name == name)
      return int(k);
  return -1;
}

bool ViewSession::ensure_loaded(int index, std::string& error) {
  if (index < 0 || index >= method_count()) {
    error = "no method " + std::to_string(index);
    return false;
  }
  if (!loaded_[size_t(index)]) {
    if (!methods_[size_t(index)]->load(scene_, shader_dir_, error))
      return false;
    for (const std::string& note : methods_[size_t(index)]->notes())
      std::fprintf(stderr, "gfield-view: note: %s\n", printable(note).c_str());
    loaded_[size_t(index)] = true;
  }
  return true;
}

bool ViewSession::select(int index, std::string& error) {
  if (!ensure_loaded(index, error))
    return false;
  current_ = index;
  return true;
}

bool ViewSession::select_compare(int index, std::string& error) {
  if (index >= 0 && !ensure_loaded(index, error))
    return false;
  compare_ = index;
  return true;
}

void ViewSession::scene_changed() {
  ++revision_;
  scene_.update();
  for (size_t k = 0; k < methods_.size(); ++k)
    if (loaded_[k])
      methods_[k]->scene_changed();
}

void ViewSession::draw(const Camera& camera, Framebuffer& frame, FrameStats* stats) {
  if (current_ < 0)
    return;
  methods_[size_t(current_)]->render(camera, frame, glm::vec2(0.0f), stats);
  if (compare_ >= 0) {
    second_.resize(frame.width(), frame.height());
    methods_[size_t(compare_)]->render(camera, second_, glm::vec2(0.0f), nullptr);
    const int half = frame.width() / 2;
    glBlitNamedFramebuffer(second_.framebuffer(), frame.framebuffer(), half, 0, frame.width(),
                           frame.height(), half, 0, frame.width(), frame.height(),
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  if (difference)
    draw_difference(frame);
}

void ViewSession::draw_difference(Framebuffer& frame) {
  if (reference_.width != frame.width() || reference_.height != frame.height()) {
    difference_message_ = "difference: load a reference of " + std::to_string(frame.width()) + "x" +
                          std::to_string(frame.height()) + " (e.g. gfield render SCENE --size WxH)";
    return;
  }
  Image image = frame.read_image();
  Image reference = reference_;
  const MetricScale scale = match_metric_scale(image, "", reference, reference_file_);
  const ImageComparison c = compare_images(image, reference);
  char text[128];
  std::snprintf(text, sizeof(text), "PSNR %.2f dB, SSIM %.4f against the reference (%s)", c.psnr,
                c.ssim, metric_scale_name(scale));
  difference_message_ = text;
  const Image heat = error_heatmap(image, reference, difference_scale);
  // Bottom row first (the frame's layout), over the frame.
  std::vector<glm::vec4> rows(heat.pixels.size());
  for (int y = 0; y < heat.height; ++y)
    for (int x = 0; x < heat.width; ++x)
      rows[size_t(heat.height - 1 - y) * size_t(heat.width) + size_t(x)] =
          glm::vec4(heat.at(x, y), 1.0f);
  glTextureSubImage2D(frame.color_texture(), 0, 0, 0, heat.width, heat.height, GL_RGBA, GL_FLOAT,
                      rows.data());
}

bool ViewSession::reload_shaders_if_changed(std::string& error) {
  bool rebuilt = false;
  error.clear();
  for (size_t k = 0; k < methods_.size(); ++k) {
    if (!loaded_[k])
      continue;
    std::string method_error;
    rebuilt |= methods_[k]->reload_shaders_if_changed(method_error);
    error += method_error;
  }
  if (rebuilt)
    ++revision_;
  return rebuilt && error.empty();
}

void ViewSession::release() {
  for (size_t k = 0; k < methods_.size(); ++k)
    methods_[k] = method_registry()[k].make();
  loaded_.assign(methods_.size(), false);
  current_ = compare_ = -1;
  scene_ = GpuScene();
  second_ = Framebuffer();
}

}  // namespace gfield
