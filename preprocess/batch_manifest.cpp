#include "preprocess/batch_manifest.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>

namespace gfield {

std::string manifest_path(const std::string& dir, const Shard& shard) {
  return (std::filesystem::path(dir) / ("manifest-" + std::to_string(shard.index) + "-of-" +
                                        std::to_string(shard.count) + ".jsonl"))
      .string();
}

std::string utc_timestamp(std::chrono::system_clock::time_point time) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(time.time_since_epoch());
  const std::time_t seconds = std::time_t(ms.count() / 1000);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[40];
  const size_t n = std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%S", &utc);
  std::snprintf(text + n, sizeof(text) - n, ".%03dZ", int(ms.count() % 1000));
  return text;
}

nlohmann::json manifest_accuracy(const AssetReport& report) {
  if (!report.accuracy) {
    return nlohmann::json::object();
  }
  const ReferenceAccuracy& described = report.accuracy->described();
  const AccuracyStats& refined = described.families.at("box_rays").at("refined");
  return {{"table_hit_miss", described.table.hit_agreement()},
          {"refined_hit_miss", refined.hit_agreement()},
          {"refined_median_percent", refined.position_median},
          {"refined_p95_percent", refined.position_p95}};
}

bool append_manifest_line(const std::string& path, const nlohmann::json& record,
                          std::string& error) {
  const std::string line = record.dump() + "\n";
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = path + ": cannot open the manifest (" + std::strerror(errno) + ")";
    return false;
  }
  const ssize_t written = ::write(fd, line.data(), line.size());
  const int write_errno = errno;
  if (::close(fd) != 0 || written != ssize_t(line.size())) {
    error = path + ": cannot append to the manifest (" +
            std::strerror(written < 0 ? write_errno : EIO) + ")";
    return false;
  }
  return true;
}

}  // namespace gfield
