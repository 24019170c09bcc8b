#pragma once
// An asset published as one unit (docs/formats.md, "Publishing"). The asset DIR/NAME is four
// files, DIR/NAME.{gimage.exr,gimage.obj,gfield.exr,report.json}; each is a symbolic link into
// DIR/NAME.builds/current/, and `current` is a link to the build folder that holds one complete
// set. A build writes its files into a folder of its own, DIR/NAME.builds/b-PID-N/ (locked while
// its builder lives), and publishes them by one rename: a new link over `current`. Whatever
// fails or kills the build at any instruction, a reader finds the whole old set or the whole new
// one. Under the asset's lock (DIR/NAME.builds/.lock) the publisher renames its folder to
// p-PID-N, turns an asset of the older layout (four plain files) into links to a folder holding
// the same files (each step leaves the same set visible), switches `current`, and removes the
// superseded folders. Builds killed before publishing leave a folder that the next builder or
// `gfield batch` of the same folder removes (remove_stale_staging).

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gfield/atomic_file.hpp"
#include "preprocess/asset_files.hpp"

namespace gfield {

class AssetStaging {
 public:
  AssetStaging() = default;
  /// Removes the build folder and what it holds unless it was published.
  ~AssetStaging();
  AssetStaging(const AssetStaging&) = delete;
  AssetStaging& operator=(const AssetStaging&) = delete;

  /// Creates and locks the build folder of asset `name` (DIR/NAME). False with an error naming
  /// the folder that could not be made.
  bool open(const std::string& name, std::string& error);
  /// Where the build writes: the asset's four files inside its build folder.
  const AssetFiles& staged() const { return staged_; }
  /// Publishes the staged files as the asset (see above). False with an error naming the asset
  /// file or folder that could not be changed; the old asset is then what readers still find.
  bool publish(std::string& error);

 private:
  void remove_folder();

  std::string name_;
  AssetFiles staged_;
  std::filesystem::path folder_;
  int lock_fd_ = -1;
  std::vector<std::unique_ptr<RemovedOnSignal>> on_signal_;
};

/// The folder of asset `name`'s builds: DIR/NAME.builds.
std::filesystem::path builds_folder(const std::string& name);

/// Removes what killed builds left in `dir`: in each DIR/NAME.builds, the build folders whose
/// builder is gone (lock free; without a lock file once a minute old), published folders that
/// are no longer `current`, and temporary links; and staging folders DIR/NAME.tmp-PID-N of the
/// older layout. Returns how many folders were removed.
size_t remove_stale_staging(const std::string& dir);

}  // namespace gfield
