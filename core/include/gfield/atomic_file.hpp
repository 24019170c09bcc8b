#pragma once
// Output files appear whole or not at all: write to a temporary path beside the target, then
// rename. The temporary file is removed if the writer fails, the object goes out of scope
// without commit(), or the process is interrupted by SIGINT/SIGTERM/SIGHUP.

#include <filesystem>
#include <string>

namespace gfield {

/// Leaves SIGINT, SIGTERM and SIGHUP to the process that loaded the library: RemovedOnSignal and
/// SignalsDeferred then install no handlers. For a host with signal handling of its own, before
/// anything is written: the Python module, where Ctrl-C is Python's KeyboardInterrupt and stops a
/// build through its JobControl, whose files are then removed on the way out.
void leave_signals_to_host();

/// Registers `path` for removal if SIGINT, SIGTERM or SIGHUP ends the process while this object
/// lives: files are unlinked first, then folders (removed when empty by then). The handlers are
/// installed on first use (unless leave_signals_to_host was called), process-wide.
class RemovedOnSignal {
 public:
  explicit RemovedOnSignal(const std::filesystem::path& path);
  ~RemovedOnSignal();
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

 private:
  int slot_ = -1;
};

/// While this object lives, SIGINT, SIGTERM and SIGHUP wait: the first one that arrives is raised
/// again when it goes out of scope (a group of renames that must not stop half-way).
class SignalsDeferred {
 public:
  SignalsDeferred();
  ~SignalsDeferred();
  SignalsDeferred(const SignalsDeferred&) = delete;
  SignalsDeferred& operator=(const SignalsDeferred&) = delete;
};

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
  /// `text` (a writer's error) with the temporary file's name replaced by the target's.
  std::string as_target(std::string text) const;

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  RemovedOnSignal on_signal_;
  bool committed_ = false;
};

/// Writes `contents` to `filename` atomically (temporary file + rename).
bool write_text_file(const std::string& filename, const std::string& contents, std::string& error);

}  // namespace gfield
