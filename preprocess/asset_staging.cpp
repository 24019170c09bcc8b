#include "preprocess/asset_staging.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <regex>

namespace gfield {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLockName = ".lock";   ///< in a build folder and in NAME.builds
constexpr const char* kCurrent = "current";  ///< NAME.builds/current -> the published folder

/// An exclusive OFD lock on the whole of `fd` (waiting for it with `wait`). 0 on success, else the
/// errno: EAGAIN when another open file holds it, ENOLCK/EINVAL when the file system has none.
int lock_whole_file(int fd, bool wait) {
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  return ::fcntl(fd, wait ? F_OFD_SETLKW : F_OFD_SETLK, &lock) == 0 ? 0 : errno;
}

std::string reason(int error_number) {
  return std::strerror(error_number);
}

/// b-PID-N: a build folder (being written, or left by a killed builder).
bool is_build_name(const std::string& file) {
  static const std::regex pattern(R"(b-[0-9]+-[0-9]+)");
  return std::regex_match(file, pattern);
}

/// NAME.tmp-PID-N: a staging folder of the older layout, beside the asset.
bool is_old_staging_name(const std::string& file) {
  static const std::regex pattern(R"(.+\.tmp-[0-9]+-[0-9]+)");
  return std::regex_match(file, pattern);
}

/// Removes the build folder `folder` when it has no living builder: its lock is free (taken
/// and held while the folder is removed), or it has no lock file and is over a minute old (its
/// builder was killed between mkdir and creating the lock). True when it was removed.
bool remove_if_stale(const fs::path& folder) {
  std::error_code ec;
  const int fd = ::open((folder / kLockName).c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) {
    const auto age = fs::file_time_type::clock::now() - fs::last_write_time(folder, ec);
    return !ec && age > std::chrono::minutes(1) && fs::remove_all(folder, ec) > 0;
  }
  bool removed = false;
  if (lock_whole_file(fd, false) == 0) {
    removed = fs::remove_all(folder, ec) > 0;  // under the lock: see make_locked_folder
  }
  ::close(fd);
  return removed;
}

/// Makes and locks the build folder `folder` (its .lock file). 0 on success, else the errno:
/// EEXIST when the folder exists, EAGAIN when a cleaner took its lock first. A cleaner that
/// opened the lock file before the builder locked it may win the lock and remove the folder
/// (remove_if_stale): the builder then holds the lock of an unlinked file, and tries again.
int make_locked_folder(const fs::path& folder, int& lock_fd) {
  if (::mkdir(folder.c_str(), 0777) != 0) {
    return errno;
  }
  lock_fd = ::open((folder / kLockName).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd < 0) {
    return errno;
  }
  struct stat lock_file {};
  if (lock_whole_file(lock_fd, false) == EAGAIN ||
      (::fstat(lock_fd, &lock_file) == 0 && lock_file.st_nlink == 0)) {
    ::close(lock_fd);
    lock_fd = -1;
    return EAGAIN;
  }
  return 0;  // locked, or a file system without locks
}

/// The asset's lock (NAME.builds/.lock), held while this lives: publishers and cleaners of one
/// asset take turns.
class AssetLock {
 public:
  /// Waits for the lock with `wait`, else takes it only if it is free (held() says).
  AssetLock(const fs::path& builds, bool wait) {
    fd_ = ::open((builds / kLockName).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    error_ = fd_ < 0 ? errno : lock_whole_file(fd_, wait);
    if (error_ == ENOLCK || error_ == EINVAL)
      error_ = 0;  // a file system without locks: go on unlocked
  }
  ~AssetLock() {
    if (fd_ >= 0)
      ::close(fd_);
  }
  AssetLock(const AssetLock&) = delete;
  AssetLock& operator=(const AssetLock&) = delete;
  bool held() const { return error_ == 0; }
  int error() const { return error_; }

 private:
  int fd_ = -1;
  int error_ = 0;
};

/// The folder name NAME.builds/current links to ("" when there is none).
std::string current_folder(const fs::path& builds) {
  std::error_code ec;
  const fs::path target = fs::read_symlink(builds / kCurrent, ec);
  return ec ? "" : target.filename().string();
}

/// Makes `path` a symbolic link to `target` in one rename (a new link made in `builds`, then
/// renamed over `path`). 0 on success, else the errno.
int replace_with_link(const fs::path& path, const std::string& target, const fs::path& builds) {
  const fs::path link = builds / ("link.tmp-" + std::to_string(::getpid()));
  ::unlink(link.c_str());
  if (::symlink(target.c_str(), link.c_str()) != 0)
    return errno;
  if (::rename(link.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(link.c_str());
    return error;
  }
  return 0;
}

/// The asset's four files, with the link each must be (relative to the asset's folder).
std::vector<std::pair<fs::path, std::string>> asset_links(const std::string& name) {
  const AssetFiles files = asset_files(name);
  const std::string builds = builds_folder(name).filename().string();
  std::vector<std::pair<fs::path, std::string>> links;
  for (const std::string* file :
       {&files.parameterized_mesh, &files.image, &files.field, &files.report}) {
    const fs::path path(*file);
    links.emplace_back(path, builds + "/" + kCurrent + "/" + path.filename().string());
  }
  return links;
}

bool is_link_to(const fs::path& path, const std::string& target) {
  std::error_code ec;
  return fs::is_symlink(fs::symlink_status(path, ec)) && fs::read_symlink(path, ec) == target;
}

/// An asset of the older layout (plain files) becomes links to a published folder holding the
/// same files (hard links): each step leaves the same set visible. False with `error`.
bool adopt_plain_files(const std::string& name, const fs::path& builds, std::string& error) {
  const fs::path folder = builds / ("p-old-" + std::to_string(::getpid()));
  std::error_code ec;
  fs::remove_all(folder, ec);
  if (::mkdir(folder.c_str(), 0777) != 0) {
    error = folder.string() + ": cannot create (" + reason(errno) + ")";
    return false;
  }
  for (const auto& [path, link] : asset_links(name)) {
    if (fs::is_regular_file(fs::symlink_status(path, ec)) &&
        ::link(path.c_str(), (folder / path.filename()).c_str()) != 0) {
      error = path.string() + ": cannot publish over it (" + reason(errno) + ")";
      fs::remove_all(folder, ec);
      return false;
    }
  }
  if (const int e = replace_with_link(builds / kCurrent, folder.filename().string(), builds)) {
    error = (builds / kCurrent).string() + ": cannot publish (" + reason(e) + ")";
    fs::remove_all(folder, ec);
    return false;
  }
  return true;
}

/// Makes each of the asset's four files the link into `current` it must be; an asset of the
/// older layout is adopted first. False with `error` naming the file that could not change.
bool link_asset_files(const std::string& name, const fs::path& builds, std::string& error) {
  const auto links = asset_links(name);
  std::error_code ec;
  bool plain = false;
  for (const auto& [path, link] : links)
    plain = plain || fs::is_regular_file(fs::symlink_status(path, ec));
  if (plain && current_folder(builds).empty() && !adopt_plain_files(name, builds, error))
    return false;
  for (const auto& [path, link] : links) {
    if (is_link_to(path, link))
      continue;
    if (const int e = replace_with_link(path, link, builds)) {
      error = path.string() + ": cannot publish over it (" + reason(e) + ")";
      return false;
    }
  }
  return true;
}

/// With the asset's lock held: removes the folders and links of `builds` that no reader can
/// reach (published folders that are not `current`, build folders of killed builders, temporary
/// links). Returns how many folders were removed.
size_t remove_superseded(const fs::path& builds) {
  const std::string current = current_folder(builds);
  size_t removed = 0;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(builds, ec)) {
    const std::string file = entry.path().filename().string();
    if (file == kCurrent || file == kLockName || file == current)
      continue;
    std::error_code entry_ec;
    if (file.rfind("p-", 0) == 0 && entry.is_directory(entry_ec)) {
      removed += fs::remove_all(entry.path(), entry_ec) > 0;
    } else if (is_build_name(file) && entry.is_directory(entry_ec)) {
      removed += remove_if_stale(entry.path());
    } else if (file.rfind("link.tmp-", 0) == 0) {
      fs::remove(entry.path(), entry_ec);
    }
  }
  return removed;
}

}  // namespace

fs::path builds_folder(const std::string& name) {
  return fs::path(name + ".builds");
}

AssetStaging::~AssetStaging() {
  remove_folder();
}

void AssetStaging::remove_folder() {
  if (!folder_.empty()) {
    std::error_code ec;
    fs::remove_all(folder_, ec);
    folder_.clear();
  }
  if (lock_fd_ >= 0) {
    ::close(lock_fd_);
    lock_fd_ = -1;
  }
  on_signal_.clear();
}

bool AssetStaging::open(const std::string& name, std::string& error) {
  name_ = name;
  const fs::path builds = builds_folder(name);
  std::error_code ec;
  fs::create_directories(builds, ec);
  if (ec || !fs::is_directory(builds, ec)) {
    error = builds.string() + ": cannot create the asset's builds folder (" +
            (ec ? ec.message() : "a file is in the way") + ")";
    return false;
  }
  // A signal between creating the folder and registering it for removal would leave it behind:
  // it waits until the end of open(), then removes what is registered.
  const SignalsDeferred deferred;
  for (int n = 0;; ++n) {
    const std::string id = std::to_string(::getpid()) + "-" + std::to_string(n);
    // p-PID-N published already (by this process, which builds the asset again, or by an earlier
    // one with the same pid): this build could not publish under that name.
    if (fs::exists(builds / ("p-" + id), ec)) {
      continue;
    }
    const fs::path folder = builds / ("b-" + id);
    const int result = make_locked_folder(folder, lock_fd_);
    if (result == 0) {
      folder_ = folder;
      break;
    }
    if (result != EEXIST && result != EAGAIN) {
      error = folder.string() + ": cannot create the build folder (" + reason(result) + ")";
      fs::remove_all(folder, ec);
      return false;
    }
  }
  on_signal_.push_back(std::make_unique<RemovedOnSignal>(folder_));
  on_signal_.push_back(std::make_unique<RemovedOnSignal>(folder_ / kLockName));
  staged_ = asset_files((folder_ / fs::path(name).filename()).string());
  for (const std::string* file :
       {&staged_.parameterized_mesh, &staged_.image, &staged_.field, &staged_.report}) {
    on_signal_.push_back(std::make_unique<RemovedOnSignal>(*file));
  }
  return true;
}

bool AssetStaging::publish(std::string& error) {
  const fs::path builds = builds_folder(name_);
  const AssetLock lock(builds, true);
  if (!lock.held()) {
    error =
        (builds / kLockName).string() + ": cannot lock the asset (" + reason(lock.error()) + ")";
    return false;
  }
  const SignalsDeferred deferred;
  // p-PID-N: complete, so that no cleaner takes it for a killed build once unlocked.
  std::string published_name = folder_.filename().string();
  published_name[0] = 'p';
  const fs::path published = builds / published_name;
  if (::rename(folder_.c_str(), published.c_str()) != 0) {
    error = published.string() + ": cannot publish (" + reason(errno) + ")";
    return false;
  }
  folder_ = published;  // removed by remove_folder() unless published below
  if (!link_asset_files(name_, builds, error))
    return false;
  if (const int e = replace_with_link(builds / kCurrent, published.filename().string(), builds)) {
    error = (builds / kCurrent).string() + ": cannot publish (" + reason(e) + ")";
    return false;
  }
  // Published: from here on, what fails only leaves garbage for the next cleaner.
  ::unlink((published / kLockName).c_str());
  folder_.clear();
  remove_folder();
  remove_superseded(builds);
  return true;
}

size_t remove_stale_staging(const std::string& dir) {
  size_t removed = 0;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    std::error_code entry_ec;
    const std::string file = entry.path().filename().string();
    if (!entry.is_directory(entry_ec) || entry.is_symlink(entry_ec))
      continue;
    if (file.size() > 7 && file.compare(file.size() - 7, 7, ".builds") == 0) {
      const AssetLock lock(entry.path(), false);  // busy: its publisher cleans up
      if (lock.held())
        removed += remove_superseded(entry.path());
    } else if (is_old_staging_name(file)) {
      removed += remove_if_stale(entry.path());
    }
  }
  return removed;
}

}  // namespace gfield
