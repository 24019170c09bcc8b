#include "geometry/gltf_meshopt.hpp"

#include <meshoptimizer.h>

#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"

namespace gfield {
namespace {

using nlohmann::json;

/// The extension's members as read; mode and filter as given.
struct MeshoptView {
  std::uint64_t buffer = 0, offset = 0, length = 0, stride = 0, count = 0;
  std::string mode, filter = "NONE";
};

/// An unsigned member `key` of `ext` up to kMaxMeshFileBytes (required unless `fallback` >= 0).
bool member(const json& ext, const char* key, std::int64_t fallback, std::uint64_t& value) {
  if (!ext.contains(key)) {
    value = std::uint64_t(fallback);
    return fallback >= 0;
  }
  if (!ext[key].is_number_integer() || ext[key].get<std::int64_t>() < 0 ||
      ext[key].get<std::uint64_t>() > kMaxMeshFileBytes)
    return false;
  value = ext[key].get<std::uint64_t>();
  return true;
}

/// What is wrong with the extension's claims ("" when nothing is).
std::string meshopt_problem(const MeshoptView& m, std::uint64_t view_length,
                            const std::vector<GltfBufferBytes>& buffers) {
  const bool attributes = m.mode == "ATTRIBUTES";
  if (!attributes && m.mode != "TRIANGLES" && m.mode != "INDICES")
    return "mode \"" + m.mode + "\" (expected ATTRIBUTES, TRIANGLES or INDICES)";
  if (attributes ? m.stride == 0 || m.stride % 4 != 0 || m.stride > 256
                 : m.stride != 2 && m.stride != 4)
    return "byteStride " + std::to_string(m.stride) + " does not fit mode " + m.mode;
  if (m.mode == "TRIANGLES" && m.count % 3 != 0)
    return "count " + std::to_string(m.count) + " of TRIANGLES is not a multiple of 3";
  const bool filter_fits =
      m.filter == "NONE" ||
      (attributes && m.filter == "OCTAHEDRAL" && (m.stride == 4 || m.stride == 8)) ||
      (attributes && m.filter == "QUATERNION" && m.stride == 8) ||
      (attributes && m.filter == "EXPONENTIAL");
  if (!filter_fits)
    return "filter \"" + m.filter + "\" does not fit mode " + m.mode + " and byteStride " +
           std::to_string(m.stride);
  if (m.buffer >= buffers.size() || buffers[m.buffer].fallback ||
      m.offset + m.length > buffers[m.buffer].bytes.size())
    return "the compressed bytes " + std::to_string(m.offset) + " to " +
           std::to_string(m.offset + m.length) + " are not within a buffer that has data";
  if (m.count * m.stride != view_length)
    return "count " + std::to_string(m.count) + " x byteStride " + std::to_string(m.stride) +
           " is not the buffer view's byteLength " + std::to_string(view_length);
  return "";
}

/// Runs meshoptimizer's decoder and filter of `m` on `source` into `out` (sized).
int run_decoder(const MeshoptView& m, const unsigned char* source, std::string& out) {
  void* data = out.data();
  if (m.mode == "TRIANGLES")
    return meshopt_decodeIndexBuffer(data, m.count, m.stride, source, m.length);
  if (m.mode == "INDICES")
    return meshopt_decodeIndexSequence(data, m.count, m.stride, source, m.length);
  const int status = meshopt_decodeVertexBuffer(data, m.count, m.stride, source, m.length);
  if (status == 0 && m.filter == "OCTAHEDRAL")
    meshopt_decodeFilterOct(data, m.count, m.stride);
  if (status == 0 && m.filter == "QUATERNION")
    meshopt_decodeFilterQuat(data, m.count, m.stride);
  if (status == 0 && m.filter == "EXPONENTIAL")
    meshopt_decodeFilterExp(data, m.count, m.stride);
  return status;
}

}  // namespace

bool decode_meshopt_view(const json& document, size_t index,
                         const std::vector<GltfBufferBytes>& buffers, std::string& decoded,
                         JsonFailure& failure) {
  const json& view = document["bufferViews"][index];
  const std::string pointer = json_pointer_child(
      json_pointer_child(json_pointer_child("/bufferViews", index), "extensions"),
      "EXT_meshopt_compression");
  const json& ext = view["extensions"]["EXT_meshopt_compression"];
  MeshoptView m;
  const bool strings = ext.is_object() && ext.value("mode", json()).is_string() &&
                       ext.value("filter", json("NONE")).is_string();
  if (!strings || !member(ext, "buffer", -1, m.buffer) || !member(ext, "byteOffset", 0, m.offset) ||
      !member(ext, "byteLength", -1, m.length) || !member(ext, "byteStride", -1, m.stride) ||
      !member(ext, "count", -1, m.count)) {
    failure = {pointer,
               "needs buffer, byteLength, byteStride and count (integers in [0, 2^31]) and a mode"};
    return false;
  }
  m.mode = ext["mode"].get<std::string>();
  m.filter = ext.value("filter", std::string("NONE"));
  const std::uint64_t view_length = view["byteLength"].get<std::uint64_t>();
  if (const std::string problem = meshopt_problem(m, view_length, buffers); !problem.empty()) {
    failure = {pointer, problem};
    return false;
  }
  decoded.assign(view_length, '\0');
  const auto* source =
      reinterpret_cast<const unsigned char*>(buffers[m.buffer].bytes.data()) + m.offset;
  if (const int status = run_decoder(m, source, decoded); status != 0) {
    failure = {pointer, "meshoptimizer cannot decode the compressed bytes (error " +
                            std::to_string(status) + ": corrupt or truncated)"};
    return false;
  }
  return true;
}

}  // namespace gfield
