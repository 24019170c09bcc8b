#include "geometry/glb_container.hpp"

namespace gfield {
namespace {

std::uint32_t little_endian_u32(const std::string& data, size_t offset) {
  const auto* b = reinterpret_cast<const unsigned char*>(data.data() + offset);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

void append_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k)
    out += char((v >> (8 * k)) & 0xFF);
}

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au, kBinChunk = 0x004E4942u;

}  // namespace

bool read_glb_container(const std::string& data, std::string& json, std::uint64_t& bin_offset,
                        std::int64_t& bin_bytes, std::string& what) {
  if (data.size() < 20 || data.compare(0, 4, "glTF") != 0) {
    what = data.size() < 20 ? "truncated .glb (" + std::to_string(data.size()) +
                                  " bytes; a header and a JSON chunk need at least 20)"
                            : "not a binary glTF file (no \"glTF\" magic)";
    return false;
  }
  const std::uint32_t version = little_endian_u32(data, 4), length = little_endian_u32(data, 8);
  const std::uint32_t json_length = little_endian_u32(data, 12);
  if (version != 2 || length != data.size() || little_endian_u32(data, 16) != kJsonChunk ||
      json_length == 0 || json_length % 4 != 0 || std::uint64_t(json_length) + 20 > data.size()) {
    what = version != 2 ? "binary glTF version " + std::to_string(version) + " (expected 2)"
           : length != data.size()
               ? "the header says " + std::to_string(length) + " bytes, the file has " +
                     std::to_string(data.size()) + " (truncated or padded)"
               : "the first chunk is not a JSON chunk within the file, padded to 4 bytes";
    return false;
  }
  json = data.substr(20, json_length);
  const std::uint64_t bin = 20 + std::uint64_t(json_length);
  bin_bytes = 0;
  bin_offset = 0;
  if (bin + 8 <= data.size()) {
    const std::uint64_t bin_length = little_endian_u32(data, size_t(bin));
    if (little_endian_u32(data, size_t(bin) + 4) != kBinChunk ||
        bin + 8 + bin_length > data.size()) {
      what = "the second chunk is not a BIN chunk within the file (truncated?)";
      return false;
    }
    bin_offset = bin + 8;
    bin_bytes = std::int64_t(bin_length);
  }
  return true;
}

std::string glb_bytes(std::string json, std::string bin) {
  while (json.size() % 4 != 0)
    json += ' ';
  while (bin.size() % 4 != 0)
    bin += '\0';
  std::string out = "glTF";
  append_u32(out, 2);
  append_u32(out, std::uint32_t(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  append_u32(out, std::uint32_t(json.size()));
  append_u32(out, kJsonChunk);
  out += json;
  if (!bin.empty()) {
    append_u32(out, std::uint32_t(bin.size()));
    append_u32(out, kBinChunk);
    out += bin;
  }
  return out;
}

}  // namespace gfield
