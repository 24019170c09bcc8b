#include "runtime/method.hpp"

#include <utility>

#include "gfield/printable.hpp"
#include "runtime/supersample.hpp"

namespace gfield {

namespace {

MethodOption described(MethodOption::Kind kind, std::string name, std::string label,
                       std::string help) {
  MethodOption o;
  o.kind = kind;
  o.name = std::move(name);
  o.label = std::move(label);
  o.help = std::move(help);
  return o;
}

}  // namespace

MethodOption int_option(std::string name, std::string label, std::string help, int* value, int min,
                        int max) {
  MethodOption o =
      described(MethodOption::Kind::kInt, std::move(name), std::move(label), std::move(help));
  o.int_value = value;
  o.min = min;
  o.max = max;
  return o;
}

MethodOption float_option(std::string name, std::string label, std::string help, float* value,
                          float min, float max) {
  MethodOption o =
      described(MethodOption::Kind::kFloat, std::move(name), std::move(label), std::move(help));
  o.float_value = value;
  o.min = min;
  o.max = max;
  return o;
}

MethodOption flag_option(std::string name, std::string label, std::string help, bool* value,
                         bool sets) {
  MethodOption o =
      described(MethodOption::Kind::kFlag, std::move(name), std::move(label), std::move(help));
  o.flag_value = value;
  o.flag_sets = sets;
  return o;
}

namespace {
void add_named(std::vector<std::pair<std::string, double>>& list, const std::string& name,
               double value) {
  for (auto& [n, v] : list) {
    if (n == name) {
      v += value;
      return;
    }
  }
  list.emplace_back(name, value);
}

double named_value(const std::vector<std::pair<std::string, double>>& list,
                   const std::string& name) {
  for (const auto& [n, v] : list)
    if (n == name)
      return v;
  return 0.0;
}
}  // namespace

void FrameStats::add_part(const std::string& name, double ms) {
  add_named(parts_ms, name, ms);
}

void FrameStats::add_gpu_part(const std::string& name, double ms) {
  add_named(gpu_parts_ms, name, ms);
}

void FrameStats::add_count(const std::string& name, double count) {
  add_named(counts, name, count);
}

double FrameStats::part_ms(const std::string& name) const {
  return named_value(parts_ms, name);
}

double FrameStats::gpu_part_ms(const std::string& name) const {
  return named_value(gpu_parts_ms, name);
}

double FrameStats::count(const std::string& name) const {
  return named_value(counts, name);
}

Image render_image(Method& method, const Camera& camera, int width, int height, int spp,
                   FrameStats* stats) {
  return render_supersampled(width, height, spp, [&](Framebuffer& target, glm::vec2 jitter) {
    method.render(camera, target, jitter, stats);
  });
}

void add_frame_time(FrameStats* stats, PassClock& clock, const std::string& part, double part_ms,
                    double part_gpu_ms) {
  if (stats == nullptr)
    return;
  stats->milliseconds += clock.read();
  stats->gpu_milliseconds += clock.gpu_ms(clock.readings() - 1);
  stats->add_part(part, part_ms);
  stats->add_gpu_part(part, part_gpu_ms);
}

std::string option_value_text(const MethodOption& o) {
  switch (o.kind) {
    case MethodOption::Kind::kInt:
      return std::to_string(*o.int_value);
    case MethodOption::Kind::kFloat:
      return float_text(*o.float_value);
    case MethodOption::Kind::kFlag:
      return *o.flag_value == o.flag_sets ? "on" : "off";
    case MethodOption::Kind::kChoice:
      return o.choices[size_t(o.get_choice())];
  }
  return "";
}

std::string option_arguments(Method& method) {
  std::string words;
  for (const MethodOption& o : method.options()) {
    const std::string value = option_value_text(o);
    if (o.kind == MethodOption::Kind::kFlag && value == "off")
      continue;
    words += (words.empty() ? "--" : " --") + o.name;
    if (o.kind != MethodOption::Kind::kFlag)
      words += " " + value;
  }
  return words;
}

bool reload_programs_if_changed(const std::vector<ShaderProgram*>& programs, std::string& error) {
  bool rebuilt = false;
  error.clear();
  for (ShaderProgram* program : programs) {
    std::string program_error;
    rebuilt |= program->reload_if_changed(program_error);
    error += program_error;
  }
  return rebuilt && error.empty();
}

}  // namespace gfield
