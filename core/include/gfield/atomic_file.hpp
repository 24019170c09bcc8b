#pragma once
// Output files appear whole or not at all: write to a temporary path beside the target, then
// rename. The temporary file is removed if the writer fails, the object goes out of scope
// without commit(), or the process is interrupted by SIGINT/SIGTERM.

#include <filesystem>
#include <string>

namespace gfield {

class TemporaryFile {
 public:
  /// Reserves "<target>.tmp-<pid>-<n>" beside `target` (nothing is created yet).
  explicit TemporaryFile(std::filesystem::path target);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  /// Where the writer should write.
  const std::filesystem::path& path() const { return temporary_; }
  /// Renames the temporary file onto the target. False with an error naming the target.
  bool commit(std::string& error);

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int slot_ = -1;
  bool committed_ = false;
};

/// Writes `contents` to `filename` atomically (temporary file + rename).
bool write_text_file(const std::string& filename, const std::string& contents, std::string& error);

}  // namespace gfield
