#pragma once
// What gfield-view shows, without a window: the GPU scene, one instance of every registered
// method (loaded on first use, all drawing from the one scene), the method shown and an optional
// second one on the right half, and an optional error heat map against a reference picture. The
// interactive viewer (runtime/viewer.cpp) and the headless path (runtime/headless.cpp) both
// drive a session; tests drive it headless.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gfield/image.hpp"
#include "gfield/image_metrics.hpp"
#include "gfield/scene.hpp"
#include "runtime/framebuffer.hpp"
#include "runtime/gpu_scene.hpp"
#include "runtime/method.hpp"

namespace gfield {

class ViewSession {
 public:
  /// One instance of every method of the registry, in its order (none loaded: their options can
  /// be bound before a GL context exists).
  ViewSession();

  /// Uploads `scene` (no method loaded yet). Needs a current GL 4.5 context.
  bool load(const Scene& scene, const std::filesystem::path& shader_dir, std::string& error);

  int method_count() const { return int(methods_.size()); }
  Method& method(int index) { return *methods_[size_t(index)]; }
  /// Index of the method named `name`, -1 if none.
  int find(const std::string& name) const;
  /// Shows method `index`, loading it on first use. False with the method's error when it cannot
  /// draw the scene (the method shown stays).
  bool select(int index, std::string& error);
  /// Shows method `index` on the right half too (-1: off), loading it on first use.
  bool select_compare(int index, std::string& error);
  int current() const { return current_; }
  int compare() const { return compare_; }
  /// Whether method `index` was loaded.
  bool loaded(int index) const { return loaded_[size_t(index)]; }

  GpuScene& scene() { return scene_; }
  /// After editing scene().scene(): refills the scene's buffers and tells every loaded method.
  void scene_changed();

  /// Draws one frame of `camera` into `frame`: the current method, the compare method over the
  /// right half, and, when a reference of the frame's size is set and `difference` is on, the
  /// error heat map instead (difference_message() then holds the PSNR).
  void draw(const Camera& camera, Framebuffer& frame, FrameStats* stats = nullptr);
  /// Rebuilds the shaders of the loaded methods whose files changed.
  bool reload_shaders_if_changed(std::string& error);
  /// Deletes every GL object of the session while its context is still current: the scene and
  /// the methods (replaced by new, unloaded instances with their default settings).
  void release();

  /// The reference picture for the difference (rows top to bottom), read from `file`: radiance
  /// (EXR, HDR), or a display picture (PNG, JPEG), against which the frame is compared as a PNG
  /// of it would be (match_metric_scale).
  void set_reference(Image reference, const std::string& file) {
    reference_ = std::move(reference);
    reference_file_ = file;
    ++revision_;
  }
  /// Counts the changes a picture depends on that its methods' options do not show: scene
  /// edits, a new reference, rebuilt shaders.
  int revision() const { return revision_; }
  bool difference = false;
  float difference_scale = 0.25f;  ///< error shown white
  const std::string& difference_message() const { return difference_message_; }

 private:
  bool ensure_loaded(int index, std::string& error);
  void draw_difference(Framebuffer& frame);

  std::vector<std::unique_ptr<Method>> methods_;
  std::vector<bool> loaded_;
  std::filesystem::path shader_dir_;
  GpuScene scene_;
  int current_ = -1;
  int compare_ = -1;
  Framebuffer second_;
  Image reference_;
  std::string reference_file_;  // the reference's file: its type decides the metric scale
  std::string difference_message_;
  int revision_ = 0;
};

}  // namespace gfield
