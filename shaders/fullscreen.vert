#version 450
// A triangle covering the viewport; v_ndc is the normalised device position.
layout(location = 0) out vec2 v_ndc;
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0f - 1.0f;
  v_ndc = p;
  gl_Position = vec4(p, 0.0f, 1.0f);
}
