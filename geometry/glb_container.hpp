#pragma once
// The binary glTF container (.glb, glTF 2.0 section 4.4): a 12-byte header ("glTF", version 2,
// the file's length), a JSON chunk and an optional BIN chunk, each an 8-byte header (length,
// type) and its bytes, lengths little-endian and padded to 4 bytes.

#include <cstdint>
#include <string>

namespace gfield {

/// Splits `data` (a whole .glb file) into its JSON chunk `json` and the offset and length of its
/// BIN chunk's bytes in `data` (`bin_bytes` 0: no BIN chunk). False with `what` (no file name)
/// for a container that the file's bytes contradict: no magic, version other than 2, a length
/// that is not the file's, a first chunk that is not JSON, a second that is not BIN or leaves the
/// file.
bool read_glb_container(const std::string& data, std::string& json, std::uint64_t& bin_offset,
                        std::int64_t& bin_bytes, std::string& what);

/// The bytes of a .glb file holding `json` (padded with spaces) and, when not empty, `bin`
/// (padded with zeros). Both together must stay below 4 GiB (the header's lengths are 32 bits).
std::string glb_bytes(std::string json, std::string bin);

}  // namespace gfield
