#include "gfield/file_read.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>

namespace gfield {

std::string file_problem(const std::string& filename) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(filename, ec);
  if (ec && ec.value() == ELOOP)
    return "a symbolic link loop";
  if (status.type() == fs::file_type::not_found) {
    std::error_code link_ec;
    return fs::is_symlink(fs::symlink_status(filename, link_ec)) ? "a dangling symbolic link"
                                                                 : "no such file";
  }
  if (ec)
    return ec.message();
  switch (status.type()) {
    case fs::file_type::regular:
      return "";
    case fs::file_type::fifo:
      return "a FIFO, not a regular file";
    case fs::file_type::directory:
      return "a folder, not a file";
    default:
      return "not a regular file";
  }
}

bool read_file(const std::string& filename, std::uint64_t max_bytes, std::string& data,
               std::string& error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (const std::string problem = file_problem(filename); !problem.empty()) {
    error = filename + ": " + problem;
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
