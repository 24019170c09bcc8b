#pragma once
// One rendering method of gfield-view behind one interface: the geometry field (Li et al. 2006),
// cube-map refraction and reflection (Hurley; Blinn & Newell), image-space refraction (Wyman
// 2005; Davis & Wyman 2007) and glass by vertex displacement (Mukai et al. 2013). A method is
// made by name from the registry (runtime/method_registry.hpp), draws from the one GpuScene,
// renders a frame of a camera into a Framebuffer, reports its statistics and describes its
// options once (MethodOption: the command line and the viewer's panel are made from it).
// Adding a method: one file pair under runtime/methods/ and one line in method_registry.cpp.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/framebuffer.hpp"
#include "runtime/gpu_scene.hpp"
#include "runtime/pass_clock.hpp"

namespace gfield {

/// One setting of a method, bound to the variable it sets. The same description becomes a
/// command-line option `--NAME` and a control in the viewer's panel.
struct MethodOption {
  enum class Kind {
    kInt,     ///< *int_value in [min, max]
    kFloat,   ///< *float_value in [min, max]
    kFlag,    ///< `--NAME` sets *flag_value = flag_sets (the panel shows the variable itself)
    kChoice,  ///< get_choice()/set_choice(): index of the value in `choices`
  };
  Kind kind = Kind::kInt;
  std::string name;   ///< the long option name without "--" (e.g. "bounces")
  std::string label;  ///< the panel's label
  std::string help;   ///< one line
  int* int_value = nullptr;
  float* float_value = nullptr;
  bool* flag_value = nullptr;
  bool flag_sets = true;
  double min = 0.0;
  double max = 0.0;
  std::vector<std::string> choices;
  std::function<int()> get_choice;
  std::function<void(int)> set_choice;
};

MethodOption int_option(std::string name, std::string label, std::string help, int* value, int min,
                        int max);
MethodOption float_option(std::string name, std::string label, std::string help, float* value,
                          float min, float max);
/// A flag: `--NAME` sets *value = sets; the panel shows a checkbox of *value.
MethodOption flag_option(std::string name, std::string label, std::string help, bool* value,
                         bool sets = true);
/// A choice among `choices`, the i-th meaning the value T(i) (an enum or an int).
template <class T>
MethodOption choice_option(std::string name, std::string label, std::string help, T* value,
                           std::vector<std::string> choices) {
  MethodOption o;
  o.kind = MethodOption::Kind::kChoice;
  o.name = std::move(name);
  o.label = std::move(label);
  o.help = std::move(help);
  o.choices = std::move(choices);
  o.get_choice = [value] { return int(*value); };
  o.set_choice = [value](int index) { *value = T(index); };
  return o;
}

/// One frame's figures, summed over the frames rendered into the same stats.
struct FrameStats {
  double milliseconds = 0.0;      ///< wall time (glFinish), all samples
  double gpu_milliseconds = 0.0;  ///< GPU time (GL_TIMESTAMP queries: pass_clock.hpp)
  /// Named parts of the frame time (e.g. "G-buffer", "tracing"), by the wall clock and by the
  /// GPU's, and named counts (e.g. "traced pixels"), in the order the method reports them.
  std::vector<std::pair<std::string, double>> parts_ms;
  std::vector<std::pair<std::string, double>> gpu_parts_ms;
  std::vector<std::pair<std::string, double>> counts;

  void add_part(const std::string& name, double ms);
  void add_gpu_part(const std::string& name, double ms);
  void add_count(const std::string& name, double count);
  /// The part (wall or GPU time) or count called `name` (0 when not reported).
  double part_ms(const std::string& name) const;
  double gpu_part_ms(const std::string& name) const;
  double count(const std::string& name) const;
};

/// Name and one-line description of a method.
struct MethodInfo {
  std::string name;   ///< the --method name (e.g. "davis-wyman")
  std::string title;  ///< the panel's name with its paper (e.g. "davis-wyman (Davis & Wyman 2007)")
};

class Method {
 public:
  virtual ~Method() = default;
  virtual MethodInfo info() const = 0;
  /// The method's settings, bound to its own variables (valid as long as the method lives).
  virtual std::vector<MethodOption> options() = 0;
  /// Prepares to draw `scene` (it outlives the method): loads the assets it needs through
  /// scene.require(), builds its shaders from `shader_dir`, checks that it can draw the scene.
  /// Needs a current GL 4.5 context. False with "FILE: problem" or FILE:LINE for shaders.
  virtual bool load(GpuScene& scene, const std::filesystem::path& shader_dir,
                    std::string& error) = 0;
  /// Objects, materials or lights of the scene changed (its buffers are already refilled).
  virtual void scene_changed() {}
  /// Renders one frame of `camera` into `target` (its size) with a sample offset `jitter` in
  /// pixels (x right, y down) from the pixel centres. With `stats`, waits for the GPU and adds
  /// the frame's figures.
  virtual void render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                      FrameStats* stats) = 0;
  /// Rebuilds the shaders whose files changed. True when any was rebuilt; `error` on failure
  /// (the old programs stay).
  virtual bool reload_shaders_if_changed(std::string& error) = 0;
  /// Figures derived from one sample's stats for --bench (e.g. ns per ray), one line or "".
  virtual std::string summary(const FrameStats& per_sample) const {
    (void)per_sample;
    return "";
  }
  /// What the method does with this scene that the user should know (shown in the panel and by
  /// --bench), a line per fact or "".
  virtual std::string status() const { return ""; }
  /// True while the method times itself on frames of an unchanged picture (the field method's
  /// --pass auto trial): a viewer that draws only on change draws it again.
  virtual bool measuring() const { return false; }
  /// What the method falls back on for this scene, one line each (e.g. a mesh without a geometry
  /// field, traced through its BVH): gfield-view prints them on stderr once it has loaded it.
  virtual std::vector<std::string> notes() const { return {}; }
};

/// Renders `width` x `height` of `camera` with `spp` stratified samples per pixel (the strata
/// centres, as the reference tracer's --strata-centres), averaged, and reads it back (linear
/// radiance, rows top to bottom).
Image render_image(Method& method, const Camera& camera, int width, int height, int spp,
                   FrameStats* stats = nullptr);

/// With `stats`: reads `clock` (the frame's end) and adds the frame's wall and GPU time since it
/// started, and its named part `part` of `part_ms` wall and `part_gpu_ms` GPU milliseconds.
void add_frame_time(FrameStats* stats, PassClock& clock, const std::string& part, double part_ms,
                    double part_gpu_ms);

/// The current value of option `o` as a command-line word ("refined", "4", "0.005"); for a flag,
/// "on" when `--NAME` is in effect, else "off".
std::string option_value_text(const MethodOption& o);
/// The command-line words that set `method`'s options to their current values (e.g. "--mode
/// refined --depth 4 --min-weight 0.005"; a flag only where it is in effect).
std::string option_arguments(Method& method);

/// Rebuilds every program in `programs` whose files changed (the Method contract).
bool reload_programs_if_changed(const std::vector<ShaderProgram*>& programs, std::string& error);

}  // namespace gfield
