#include "runtime/methods/trace_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gfield/check.hpp"

namespace gfield {
namespace {

size_t slot(TracePass pass) {
  GF_CHECK(pass != TracePass::kAuto, "a trial times the compute or the fragment pass");
  return pass == TracePass::kCompute ? 0 : 1;
}

/// The fastest timed frame of a pass (its warm-up frame left out).
double fastest(const std::vector<double>& ms) {
  return *std::min_element(ms.begin() + 1, ms.end());
}

}  // namespace

const char* trace_pass_name(TracePass pass) {
  switch (pass) {
    case TracePass::kAuto:
      return "auto";
    case TracePass::kCompute:
      return "compute";
    case TracePass::kFragment:
      return "fragment";
  }
  return "?";
}

void restart_pass_trial(PassTrial& trial, const std::string& key) {
  if (trial.key == key)
    return;
  trial = {};
  trial.key = key;
}

bool pass_trial_done(const PassTrial& trial) {
  return std::all_of(trial.ms.begin(), trial.ms.end(), [](const std::vector<double>& ms) {
    return int(ms.size()) >= 1 + kPassTrialFrames;
  });
}

TracePass next_trace_pass(const PassTrial& trial) {
  if (!pass_trial_done(trial))
    return trial.ms[0].size() <= trial.ms[1].size() ? TracePass::kCompute : TracePass::kFragment;
  return fastest(trial.ms[0]) <= fastest(trial.ms[1]) ? TracePass::kCompute : TracePass::kFragment;
}

void record_trace_pass(PassTrial& trial, TracePass pass, double gpu_ms) {
  std::vector<double>& ms = trial.ms[slot(pass)];
  if (int(ms.size()) < 1 + kPassTrialFrames)
    ms.push_back(gpu_ms);
}

std::string describe_pass_trial(const PassTrial& trial) {
  const TracePass pass = next_trace_pass(trial);
  if (!pass_trial_done(trial))
    return std::string(trace_pass_name(pass)) + " (auto: measuring)";
  const TracePass other = pass == TracePass::kCompute ? TracePass::kFragment : TracePass::kCompute;
  char text[160];
  if (std::isinf(fastest(trial.ms[slot(other)])))
    std::snprintf(text, sizeof(text), "%s (auto: %s did not build)", trace_pass_name(pass),
                  trace_pass_name(other));
  else
    std::snprintf(text, sizeof(text), "%s (auto: %.1f ms against %s %.1f ms)",
                  trace_pass_name(pass), fastest(trial.ms[slot(pass)]), trace_pass_name(other),
                  fastest(trial.ms[slot(other)]));
  return text;
}

}  // namespace gfield
