#pragma once
// SHA-256 (FIPS 180-4) of bytes and files: the content hashes behind asset build ids
// (docs/formats.md, "Build id").

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace gfield {

/// Incremental SHA-256: update() any number of times, then hex() once.
class Sha256 {
 public:
  Sha256();
  void update(const void* data, size_t bytes);
  void update(std::string_view text) { update(text.data(), text.size()); }
  /// The digest as 64 lowercase hex digits. Ends the hash: call update() no more.
  std::string hex();

 private:
  void block(const uint8_t* p);
  std::array<uint32_t, 8> state_;
  std::array<uint8_t, 64> buffer_{};
  size_t buffered_ = 0;
  uint64_t length_ = 0;  ///< bytes hashed so far
};

/// SHA-256 of `bytes` as 64 hex digits.
std::string sha256_hex(std::string_view bytes);

/// SHA-256 of the contents of `filename` as 64 hex digits. False with an error "FILE: problem".
bool sha256_file(const std::string& filename, std::string& hex, std::string& error);

}  // namespace gfield
