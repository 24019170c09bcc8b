#version 450
// The geometry-field tracing pass as a full-screen fragment pass: one fragment per pixel
// (lib/field_trace.glsl), into the frame's colour and hit attachments.
#include "lib/field_trace.glsl"

layout(location = 0) out vec4 o_color;  // linear radiance, alpha 1
layout(location = 1) out vec4 o_hits;   // first hit object, secondary rays traced, 0, 0

void main() {
  trace_pixel(ivec2(gl_FragCoord.xy), o_color, o_hits);
}
