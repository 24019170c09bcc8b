#pragma once
// An asset published as one unit (docs/formats.md, "Build id"). A build writes its four files
// into a private staging folder beside the asset, DIR/NAME.tmp-PID-N/, and renames them into DIR
// only when all are complete: under an exclusive lock on DIR/.gfield-publish.lock (concurrent
// builders of one folder publish one after the other, never interleaved), with SIGINT, SIGTERM
// and SIGHUP deferred until the last rename, in the order parameterised mesh, geometry image,
// geometry field, report. Until then the old asset is untouched. A staging folder holds a lock
// (OFD lock on its .lock file) while its builder lives; one whose lock is free was left by a
// killed builder and is removed by remove_stale_staging, on any host sharing the folder.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gfield/atomic_file.hpp"
#include "preprocess/asset_files.hpp"

namespace gfield {

/// The lock file that serialises the publishing of assets in one folder (it stays there).
inline constexpr const char* kPublishLockFile = ".gfield-publish.lock";

class AssetStaging {
 public:
  AssetStaging() = default;
  /// Removes the staging folder and what it holds unless published.
  ~AssetStaging();
  AssetStaging(const AssetStaging&) = delete;
  AssetStaging& operator=(const AssetStaging&) = delete;

  /// Creates and locks the staging folder of asset `name` (DIR/NAME). False with an error naming
  /// the folder that could not be made.
  bool open(const std::string& name, std::string& error);
  /// Where the build writes: the asset's four files inside the staging folder.
  const AssetFiles& staged() const { return staged_; }
  /// Renames the staged files onto the asset's (see above) and removes the staging folder. False
  /// with an error naming the file that could not be renamed.
  bool publish(std::string& error);

 private:
  void remove_folder();

  AssetFiles target_;
  AssetFiles staged_;
  std::filesystem::path folder_;
  int lock_fd_ = -1;
  std::vector<std::unique_ptr<RemovedOnSignal>> on_signal_;
};

/// Removes the staging folders in `dir` whose builder is gone (lock free; a folder without a
/// lock file once it is a minute old). Returns how many were removed.
size_t remove_stale_staging(const std::string& dir);

}  // namespace gfield
