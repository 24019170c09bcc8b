// Diffuse albedo of the scene's textures as gfield::texture_albedo (core/src/scene.cpp) computes
// it: plain colour, checker (squares along u and v in checker0.w / checker1.w) or the 6 x 4
// colour chart (sRGB patches on black gaps, returned linear). Texture codes TEXTURE_* are the
// contract's. And the base colour a mesh's own vertex carries (runtime/gpu_assets.hpp).

#include "lib/contract.glsl"

// The meshes' own textures: linear colour, a layer each, GL_LINEAR and GL_REPEAT, t = v.
layout(binding = UNIT_MESH_TEXTURES) uniform sampler2DArray u_mesh_textures;

// The base colour of a mesh's surface at texture coordinates uv, from its vertices' `base`
// (rgb: material colour x vertex colour; a: the texture's layer, -1 none): as
// gfield::base_color_at (geometry/mesh_appearance.cpp), the texture looked up bilinearly.
vec3 mesh_base_color(vec4 base, vec2 uv) {
  if (base.a < -0.5f) return base.rgb;
  return base.rgb * texture(u_mesh_textures, vec3(uv, base.a)).rgb;
}

vec3 texture_albedo(int texture_type, vec3 color, vec4 checker0, vec4 checker1, vec2 uv) {
  if (texture_type == TEXTURE_CHECKER) {
    int cu = int(floor(uv.x * checker0.w));
    int cv = int(floor(uv.y * checker1.w));
    return ((cu + cv) & 1) == 0 ? checker0.rgb : checker1.rgb;
  }
  if (texture_type == TEXTURE_COLOR_CHART) {
    const vec3 patches[24] = vec3[](
        vec3(115, 82, 68), vec3(194, 150, 130), vec3(98, 122, 157), vec3(87, 108, 67),
        vec3(133, 128, 177), vec3(103, 189, 170), vec3(214, 126, 44), vec3(80, 91, 166),
        vec3(193, 90, 99), vec3(94, 60, 108), vec3(157, 188, 64), vec3(224, 163, 46),
        vec3(56, 61, 150), vec3(70, 148, 73), vec3(175, 54, 60), vec3(231, 199, 31),
        vec3(187, 86, 149), vec3(8, 133, 161), vec3(243, 243, 242), vec3(200, 200, 200),
        vec3(160, 160, 160), vec3(122, 122, 121), vec3(85, 85, 85), vec3(52, 52, 52));
    float u = clamp(uv.x, 0.0f, 1.0f) * 6.0f;
    float v = clamp(1.0f - uv.y, 0.0f, 1.0f) * 4.0f;
    int column = min(int(u), 5);
    int row = min(int(v), 3);
    float fu = u - float(column);
    float fv = v - float(row);
    const float gap = 0.08f;
    if (fu < gap || fu > 1.0f - gap || fv < gap || fv > 1.0f - gap) return vec3(0.01f);
    vec3 c = patches[row * 6 + column] / 255.0f;
    // sRGB -> linear (IEC 61966-2-1)
    return mix(c / 12.92f, pow((c + 0.055f) / 1.055f, vec3(2.4f)), greaterThan(c, vec3(0.04045f)));
  }
  return color;
}
