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

constexpr const char* kLockName = ".lock";

/// An exclusive OFD lock on the whole of `fd` (waiting for it with `wait`). 0 on success, else the
/// errno: EAGAIN when another open file holds it, ENOLCK/EINVAL when the file system has none.
int lock_whole_file(int fd, bool wait) {
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  return ::fcntl(fd, wait ? F_OFD_SETLKW : F_OFD_SETLK, &lock) == 0 ? 0 : errno;
}

fs::path folder_of(const std::string& name) {
  const fs::path dir = fs::path(name).parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

/// True for NAME.tmp-PID-N.
bool is_staging_name(const std::string& file) {
  static const std::regex pattern(R"(.+\.tmp-[0-9]+-[0-9]+)");
  return std::regex_match(file, pattern);
}

/// Removes the staging folder `folder` when it has no living builder: its lock is free (taken
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

/// Makes and locks the staging folder `folder` (its .lock file). 0 on success, else the errno:
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

}  // namespace

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
  const fs::path dir = folder_of(name);
  const std::string stem = fs::path(name).filename().string();
  target_ = asset_files(name);
  // A signal between creating the folder and registering it for removal would leave it behind:
  // it waits until the end of open(), then removes what is registered.
  const SignalsDeferred deferred;
  for (int n = 0;; ++n) {
    const fs::path folder =
        dir / (stem + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(n));
    const int result = make_locked_folder(folder, lock_fd_);
    if (result == 0) {
      folder_ = folder;
      break;
    }
    if (result != EEXIST && result != EAGAIN) {
      error =
          folder.string() + ": cannot create the staging folder (" + std::strerror(result) + ")";
      std::error_code ec;
      fs::remove_all(folder, ec);
      return false;
    }
  }
  on_signal_.push_back(std::make_unique<RemovedOnSignal>(folder_));
  on_signal_.push_back(std::make_unique<RemovedOnSignal>(folder_ / kLockName));
  staged_ = asset_files((folder_ / stem).string());
  for (const std::string* file :
       {&staged_.parameterized_mesh, &staged_.image, &staged_.field, &staged_.report}) {
    on_signal_.push_back(std::make_unique<RemovedOnSignal>(*file));
  }
  return true;
}

bool AssetStaging::publish(std::string& error) {
  const fs::path lock = folder_of(target_.image) / kPublishLockFile;
  const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = lock.string() + ": cannot open the publishing lock (" + std::strerror(errno) + ")";
    return false;
  }
  lock_whole_file(fd, true);  // no lock support: publish unlocked
  bool ok = true;
  {
    const SignalsDeferred deferred;
    const std::pair<const std::string*, const std::string*> order[] = {
        {&staged_.parameterized_mesh, &target_.parameterized_mesh},
        {&staged_.image, &target_.image},
        {&staged_.field, &target_.field},
        {&staged_.report, &target_.report}};
    for (const auto& [from, to] : order) {
      if (ok && ::rename(from->c_str(), to->c_str()) != 0) {
        error = *to + ": cannot write (" + std::strerror(errno) + ")";
        ok = false;
      }
    }
  }
  ::close(fd);
  remove_folder();
  return ok;
}

size_t remove_stale_staging(const std::string& dir) {
  size_t removed = 0;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    std::error_code entry_ec;
    if (entry.is_directory(entry_ec) && !entry.is_symlink(entry_ec) &&
        is_staging_name(entry.path().filename().string()) && remove_if_stale(entry.path())) {
      ++removed;
    }
  }
  return removed;
}

}  // namespace gfield
