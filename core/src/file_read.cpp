#include "gfield/file_read.hpp"

#include <filesystem>
#include <fstream>

namespace gfield {

bool read_file(const std::string& filename, std::uint64_t max_bytes, std::string& data,
               std::string& error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(filename, ec)) {
    error = filename + ": no such file";
    return false;
  }
  if (!fs::is_regular_file(filename, ec)) {
    error = filename + ": not a regular file";
    return false;
  }
  const std::uintmax_t size = fs::file_size(filename, ec);
  std::ifstream in(filename, std::ios::binary);
  if (ec || !in) {
    error = filename + ": cannot open (permission denied?)";
    return false;
  }
  if (size == 0) {
    error = filename + ": empty file";
    return false;
  }
  if (size > max_bytes) {
    error = filename + ": " + std::to_string(size) + " bytes, more than the limit of " +
            std::to_string(max_bytes) + " for this kind of file";
    return false;
  }
  data.resize(size_t(size));
  if (!in.read(data.data(), std::streamsize(size)) || size_t(in.gcount()) != size) {
    error = filename + ": cannot read";
    return false;
  }
  return true;
}

}  // namespace gfield
