#include "runtime/web_export.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

#include <unistd.h>
#include <zlib.h>
#include <nlohmann/json.hpp>

#include "gfield/gpu_contract.hpp"
#include "gfield/printable.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/glsl_es.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// WebGL2's guaranteed limits are lower (2048 texels, 256 layers); these are what the browsers
// gfield is tested on offer (SwiftShader, desktop GPUs), checked again by the player.
constexpr int kWebMaxTextureSize = 8192;
constexpr int kWebMaxLayers = 256;

// The stages the player runs (web/player/gfield-player.js).
const char* const kWebStages[] = {"fullscreen.vert", "gbuffer.vert", "gbuffer.frag",
                                  "field_trace.frag", "present.frag"};
const char* const kPlayerFiles[] = {"index.html", "gfield-player.js", "gfield-three-mesh-bvh.js"};

// The player's three-mesh-bvh method (web/player/gfield-three-mesh-bvh.js) imports these npm
// files, which the page's import map finds under vendor/: a file of node_modules and its name
// there. three.core.js holds every class three-mesh-bvh imports from "three".
struct VendorFile {
  const char* from;
  const char* to;
};
const VendorFile kVendorFiles[] = {
    {"three/build/three.core.js", "three.core.js"},
    {"three/LICENSE", "three.LICENSE"},
    {"three-mesh-bvh/build/index.module.js", "three-mesh-bvh.js"},
    {"three-mesh-bvh/LICENSE", "three-mesh-bvh.LICENSE"},
};

// scene.bin: blocks one after another, each at a multiple of 16 bytes (typed-array views).
struct Blob {
  std::vector<uint8_t> bytes;
  json add(const void* data, size_t size) {
    const size_t offset = (bytes.size() + 15) / 16 * 16;
    bytes.resize(offset + size);
    if (size > 0)
      std::memcpy(bytes.data() + offset, data, size);
    return json{{"offset", offset}, {"bytes", size}};
  }
};

std::vector<uint8_t> read_buffer(GLuint buffer) {
  GLint64 size = 0;
  if (buffer != 0)
    glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &size);
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  if (size > 0)
    glGetNamedBufferSubData(buffer, 0, size, bytes.data());
  return bytes;
}

// A texture's bytes into `blob`, and its entry in scene.json's "textures".
json texture_json(Blob& blob, const std::vector<uint8_t>& bytes, int width, int height, int layers,
                  const char* web_format) {
  json t = blob.add(bytes.data(), bytes.size());
  t["width"] = width;
  t["height"] = height;
  t["layers"] = layers;
  t["format"] = web_format;
  return t;
}

// A 2D array texture read back whole as `format`/`type` (texel_bytes each); a texture never
// made becomes one zero texel.
json add_texture(Blob& blob, GLuint texture, GLenum format, GLenum type, int texel_bytes,
                 const char* web_format, const std::string& what, std::string& error) {
  GLint w = 1, h = 1, layers = 1;
  std::vector<uint8_t> bytes(size_t(texel_bytes), 0);
  if (texture != 0) {
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
    bytes.assign(size_t(w) * size_t(h) * size_t(layers) * size_t(texel_bytes), 0);
    glGetTextureImage(texture, 0, format, type, GLsizei(bytes.size()), bytes.data());
  }
  if (w > kWebMaxTextureSize || h > kWebMaxTextureSize || layers > kWebMaxLayers)
    error = what + " is " + std::to_string(w) + " x " + std::to_string(h) + " x " +
            std::to_string(layers) + " texels, beyond the web player's " +
            std::to_string(kWebMaxTextureSize) + " x " + std::to_string(kWebMaxTextureSize) +
            " x " + std::to_string(kWebMaxLayers);
  return texture_json(blob, bytes, w, h, layers, web_format);
}

// A storage buffer as a 2D texture of rows of WEB_TEXEL_ROW texels of `texel_bytes`, the last
// row padded with zeros: the fields' line words (BUFFER_FIELD_LINES, r32ui) and the BVHs'
// buffers (rgba32f).
json add_rows(Blob& blob, GLuint buffer, int texel_bytes, const char* web_format,
              const std::string& what, std::string& error) {
  std::vector<uint8_t> bytes = read_buffer(buffer);
  const size_t row = size_t(gpu::WEB_TEXEL_ROW) * size_t(texel_bytes);
  const size_t rows = std::max<size_t>(1, (bytes.size() + row - 1) / row);
  bytes.resize(rows * row, 0);
  if (rows > size_t(kWebMaxTextureSize))
    error = what + " need " + std::to_string(rows) + " rows of " +
            std::to_string(gpu::WEB_TEXEL_ROW) + " texels, beyond the web player's " +
            std::to_string(kWebMaxTextureSize);
  return texture_json(blob, bytes, gpu::WEB_TEXEL_ROW, int(rows), 1, web_format);
}

json add_mesh(Blob& blob, const GpuMesh& mesh, int bvh_root, bool field) {
  const std::vector<uint8_t> vertices = read_buffer(mesh.vertices.id());
  const std::vector<uint8_t> indices = read_buffer(mesh.indices.id());
  return json{{"vertices", blob.add(vertices.data(), vertices.size())},
              {"indices", blob.add(indices.data(), indices.size())},
              {"index_count", mesh.index_count},
              {"vertex_bytes", sizeof(GpuVertex)},
              {"bvh_root", bvh_root},
              {"field", field}};
}

template <typename M>
json numbers(const M& m, int count) {
  const float* p = &m[0][0];
  return std::vector<float>(p, p + count);
}
json vec3_json(const glm::vec3& v) {
  return {v.x, v.y, v.z};
}

json objects_json(const GpuScene& gpu) {
  json objects = json::array();
  for (int k = 0; k < int(gpu.scene().objects.size()); ++k) {
    const GpuScene::ObjectUniforms u = gpu.object_uniforms(k);
    glm::vec3 lo, hi;
    gpu.object_world_bounds(k, lo, hi);
    objects.push_back(
        {{"name", gpu.scene().objects[size_t(k)].name},
         {"to_world", numbers(u.to_world, 16)},
         {"to_object", numbers(u.to_object, 16)},
         {"shape", u.shape},
         {"shape_params", {u.shape_params.x, u.shape_params.y, u.shape_params.z, 0.0f}},
         {"shape_size", vec3_json(u.shape_size)},
         {"proxy_half", vec3_json(u.proxy_half)},
         {"mesh", u.mesh},
         {"world_bounds", {vec3_json(lo), vec3_json(hi)}}});
  }
  return objects;
}

json scene_json(const GpuScene& gpu, const WebExportOptions& options) {
  const Scene& scene = gpu.scene();
  return {{"format", "gfield-web"},
          {"version", kWebSceneVersion},
          {"name", options.scene_name},
          {"size", {options.width, options.height}},
          {"camera",
           {{"position", vec3_json(scene.camera.position)},
            {"target", vec3_json(scene.camera.target)},
            {"up", vec3_json(scene.camera.up)},
            {"fov", scene.camera.fov_degrees}}},
          {"uniforms",
           {{"object_count", scene.objects.size()},
            {"light_count", scene.lights.size()},
            {"ambient", vec3_json(scene.ambient)},
            {"scene_extent", gpu.extent()},
            {"env_type", int(scene.environment.type)},
            {"env_color", vec3_json(scene.environment.color)},
            {"env_intensity", scene.environment.intensity}}},
          {"objects", objects_json(gpu)}};
}

// The scene's bytes into `blob` and where each lies into `manifest`.
bool add_gpu_data(const GpuScene& gpu, Blob& blob, json& manifest, std::string& error) {
  const GpuAssets& a = gpu.assets();
  const std::vector<uint8_t> objects = read_buffer(gpu.objects_buffer());
  const std::vector<uint8_t> lights = read_buffer(gpu.lights_buffer());
  manifest["blocks"] = {{"objects", blob.add(objects.data(), objects.size())},
                        {"lights", blob.add(lights.data(), lights.size())}};
  json& t = manifest["textures"];
  t["gi_positions"] = add_texture(blob, a.positions(), GL_RGBA, GL_FLOAT, 16, "rgba32f",
                                  "the geometry images", error);
  t["gi_normals"] = add_texture(blob, a.normals(), GL_RGBA, GL_FLOAT, 16, "rgba32f",
                                "the geometry images' normals", error);
  t["fields"] = add_texture(blob, a.fields(), GL_RG, GL_UNSIGNED_BYTE, 2, "rg8",
                            "the fields' nearest-hit tables", error);
  t["field_words"] = add_rows(blob, a.field_lines(), 4, "r32ui", "the fields' line tables", error);
  t["bvh_nodes"] = add_rows(blob, a.bvhs().nodes(), 16, "rgba32f", "the BVHs' nodes", error);
  t["bvh_triangles"] =
      add_rows(blob, a.bvhs().triangles(), 16, "rgba32f", "the BVHs' triangles", error);
  t["bvh_shading"] = add_rows(blob, a.bvhs().shading(), 16, "rgba32f", "the BVHs' shading", error);
  t["gi_albedo"] = add_texture(blob, a.albedo(), GL_RGBA, GL_HALF_FLOAT, 8, "rgba16f",
                               "the geometry images' albedo", error);
  t["mesh_textures"] = add_texture(blob, a.mesh_textures(), GL_RGBA, GL_HALF_FLOAT, 8, "rgba16f",
                                   "the meshes' textures", error);
  t["environment"] = add_texture(blob, gpu.environment_texture(), GL_RGBA, GL_FLOAT, 16, "rgba32f",
                                 "the environment", error);
  json meshes = json::array();
  for (const GpuAsset& asset : a.assets())
    meshes.push_back(add_mesh(blob, asset.source, asset.bvh_root, asset.samples_per_side > 0));
  manifest["meshes"] = meshes;
  manifest["proxy_cube"] = add_mesh(blob, gpu.proxy_cube(), -1, false);
  return error.empty();
}

bool write_gzip(const fs::path& path, const std::vector<uint8_t>& bytes, std::string& error) {
  gzFile file = gzopen(path.c_str(), "wb6");
  bool ok = file != nullptr;
  for (size_t at = 0; ok && at < bytes.size();) {
    const unsigned chunk = unsigned(std::min<size_t>(bytes.size() - at, size_t(1) << 30));
    ok = gzwrite(file, bytes.data() + at, chunk) == int(chunk);
    at += chunk;
  }
  if (file != nullptr && gzclose(file) != Z_OK)
    ok = false;
  if (!ok)
    error = path.string() + ": cannot write";
  return ok;
}

bool write_text(const fs::path& path, const std::string& text, std::string& error) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) {
    error = path.string() + ": cannot write";
    return false;
  }
  return true;
}

// Copies file `from` to `to`; false with "FROM: cannot copy to TO: why".
bool copy_into(const fs::path& from, const fs::path& to, std::string& error) {
  std::error_code ec;
  fs::copy_file(from, to, ec);
  if (ec)
    error = from.string() + ": cannot copy to " + to.string() + ": " + ec.message();
  return !ec;
}

// Whether `node_modules` holds every vendor file; then `version` is three-mesh-bvh's (false with
// `error` when its package.json names none).
bool vendor_version(const fs::path& node_modules, std::string& version, std::string& error) {
  std::error_code ec;
  for (const VendorFile& file : kVendorFiles)
    if (!fs::is_regular_file(node_modules / file.from, ec))
      return true;
  const fs::path package = node_modules / "three-mesh-bvh" / "package.json";
  std::ifstream in(package);
  const json j = json::parse(in, nullptr, false);
  version = j.is_object() && j.contains("version") && j["version"].is_string()
                ? j["version"].get<std::string>()
                : "";
  if (version.empty())
    error =
        package.string() + ": no version (a damaged npm install: run scripts/install-web-deps.sh)";
  return !version.empty();
}

// The vendor files into dir/vendor, and scene.json's "peers" (three-mesh-bvh's version); none
// when `node_modules` lacks them (the page then offers no three-mesh-bvh method).
bool add_vendor(const fs::path& node_modules, const fs::path& dir, json& manifest,
                std::string& error) {
  manifest["peers"] = json::object();
  std::string version;
  if (!vendor_version(node_modules, version, error))
    return false;
  if (version.empty())
    return true;
  std::error_code ec;
  if (!fs::create_directories(dir / "vendor", ec)) {
    error = (dir / "vendor").string() + ": cannot create: " + ec.message();
    return false;
  }
  for (const VendorFile& file : kVendorFiles)
    if (!copy_into(node_modules / file.from, dir / "vendor" / file.to, error))
      return false;
  manifest["peers"]["three-mesh-bvh"] = version;
  return true;
}

// Everything of the export into the empty folder `dir`.
bool write_folder(const GpuScene& gpu, const fs::path& dir, const WebExportOptions& options,
                  std::string& error) {
  json manifest = scene_json(gpu, options);
  Blob blob;
  if (!add_gpu_data(gpu, blob, manifest, error)) {
    error = gpu.scene().filename + ": " + error;
    return false;
  }
  manifest["bin"] = {{"file", "scene.bin.gz"}, {"bytes", blob.bytes.size()}};
  fs::create_directories(dir / "shaders");
  for (const char* stage : kWebStages) {
    std::string text;
    if (!glsl_es_source(options.shader_dir, stage, text, error) ||
        !write_text(dir / "shaders" / stage, text, error))
      return false;
  }
  for (const char* file : kPlayerFiles)
    if (!copy_into(options.player_dir / file, dir / file, error))
      return false;
  return add_vendor(options.node_modules, dir, manifest, error) &&
         write_gzip(dir / "scene.bin.gz", blob.bytes, error) &&
         write_text(dir / "scene.json", manifest.dump(1) + "\n", error);
}

bool is_earlier_export(const fs::path& dir) {
  std::ifstream in(dir / "scene.json");
  const json j = json::parse(in, nullptr, false);
  return j.is_object() && j.value("format", "") == "gfield-web";
}

}  // namespace

bool export_web(const GpuScene& gpu, const fs::path& out, const WebExportOptions& options,
                std::string& error) {
  std::error_code ec;
  if (gpu.scene().objects.size() > size_t(gpu::WEB_MAX_OBJECTS) ||
      gpu.scene().lights.size() > size_t(gpu::WEB_MAX_LIGHTS)) {
    error = gpu.scene().filename + ": the web player draws at most " +
            std::to_string(gpu::WEB_MAX_OBJECTS) + " objects and " +
            std::to_string(gpu::WEB_MAX_LIGHTS) + " lights";
    return false;
  }
  const bool replace = fs::exists(out, ec);
  if (replace &&
      !(fs::is_directory(out, ec) && (fs::is_empty(out, ec) || is_earlier_export(out)))) {
    error = out.string() + ": exists and is not an earlier web export; choose another folder";
    return false;
  }
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::string name = ".";
  name.append(out.filename().string()).append(".tmp-").append(std::to_string(::getpid()));
  const fs::path staging = parent / name;
  const fs::path old = parent / name.replace(name.rfind(".tmp-"), 5, ".old-");
  fs::remove_all(staging, ec);
  if (!fs::create_directories(staging, ec)) {
    error = out.string() + ": cannot create the folder: " + ec.message();
    return false;
  }
  if (!write_folder(gpu, staging, options, error)) {
    fs::remove_all(staging, ec);
    return false;
  }
  if (replace)
    fs::rename(out, old, ec);
  if (!ec)
    fs::rename(staging, out, ec);
  if (ec) {
    error = out.string() + ": cannot put the export in place: " + ec.message();
    if (replace && !fs::exists(out))
      fs::rename(old, out, ec);
    fs::remove_all(staging, ec);
    return false;
  }
  fs::remove_all(old, ec);
  return true;
}

namespace {

/// The bytes of the files under `folder` (a file that cannot be sized counts 0).
std::uintmax_t folder_bytes(const fs::path& folder) {
  std::uintmax_t bytes = 0;
  std::error_code ec, file_ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::uintmax_t size = it->is_regular_file(file_ec) ? it->file_size(file_ec) : 0;
    bytes += file_ec ? 0 : size;
  }
  return bytes;
}

}  // namespace

int run_export_web(const Scene& scene, const fs::path& out, const WebExportOptions& options,
                   std::string& error) {
  auto context = GlContext::create_headless(error);
  if (!context)
    return kExitNoOpenGL;
  GpuScene gpu;
  AssetNeeds needs;
  needs.fields = true;
  // A mesh without its assets is traced by its BVH, as gfield-view does.
  needs.optional_fields = true;
  needs.field_bits = 8;
  needs.source_meshes = true;
  needs.bvhs = true;  // the page's BVH mode
  if (!gpu.load(scene, error) || !gpu.require(needs, error))
    return 2;
  const std::vector<GpuAsset>& assets = gpu.assets().assets();
  for (size_t m = 0; m < scene.meshes.size() && m < assets.size(); ++m)
    if (assets[m].samples_per_side == 0)
      std::fprintf(
          stderr, "gfield-view: note: %s: traced through its BVH in the web player\n",
          missing_asset_message(scene.meshes[m], scene.filename, "geometry field").c_str());
  if (!export_web(gpu, out, options, error))
    return 2;
  const double bytes = double(folder_bytes(out));
  std::printf(
      "wrote %s: %.1f MB, %zu meshes; serve it (python3 -m http.server --directory %s) "
      "and open its index.html\n",
      printable(out.string()).c_str(), bytes / 1e6, scene.meshes.size(),
      printable(out.string()).c_str());
  return 0;
}

}  // namespace gfield
