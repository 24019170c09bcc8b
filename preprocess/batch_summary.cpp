#include "preprocess/batch_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "gfield/file_read.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// One manifest file: shard I of N and its lines in order.
struct Manifest {
  std::string path;
  int index = 0;
  int count = 0;
  std::vector<json> records;
};

bool read_manifests(const std::string& dir, std::vector<Manifest>& manifests,
                    std::vector<std::string>& skipped, std::string& error) {
  static const std::regex pattern(R"(manifest-([0-9]+)-of-([0-9]+)\.jsonl)");
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (!std::regex_match(file, m, pattern)) {
      continue;
    }
    Manifest manifest{entry.path().string(), std::stoi(m[1]), std::stoi(m[2]), {}};
    std::ifstream in(entry.path());
    size_t line_number = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      json record = json::parse(line, nullptr, false);
      if (record.is_object() && record.contains("asset") && record["asset"].is_string()) {
        manifest.records.push_back(std::move(record));
      } else {
        skipped.push_back(manifest.path + ":" + std::to_string(line_number));
      }
    }
    manifests.push_back(std::move(manifest));
  }
  if (ec || manifests.empty()) {
    error = dir + ": no manifest-I-of-N.jsonl files (not the output folder of a gfield batch?)";
    return false;
  }
  std::sort(manifests.begin(), manifests.end(),
            [](const Manifest& a, const Manifest& b) { return a.path < b.path; });
  return true;
}

std::string text_of(const json& record, const char* key) {
  const auto it = record.find(key);
  return it != record.end() && it->is_string() ? it->get<std::string>() : std::string();
}

double number_of(const json& record, const char* key) {
  const auto it = record.find(key);
  return it != record.end() && it->is_number() ? it->get<double>() : 0.0;
}

/// The latest record of every asset.
std::map<std::string, json> latest_records(const std::vector<Manifest>& manifests) {
  std::map<std::string, json> latest;
  for (const Manifest& manifest : manifests) {
    for (const json& record : manifest.records) {
      const std::string asset = record["asset"].get<std::string>();
      const auto it = latest.find(asset);
      if (it == latest.end() || text_of(record, "finished") >= text_of(it->second, "finished")) {
        latest[asset] = record;
      }
    }
  }
  return latest;
}

std::string format(const char* pattern, const std::string& a, const std::string& b, double c,
                   const std::string& d, const std::string& e) {
  char line[512];
  std::snprintf(line, sizeof(line), pattern, a.c_str(), b.c_str(), c, d.c_str(), e.c_str());
  return line;
}

/// One row per asset: name, status, seconds, refined hit/miss, shard.
std::string table(const std::map<std::string, json>& latest) {
  const char* row = "%-28s %-11s %8.2f %12s %7s\n";
  std::string text = "asset                        status       seconds refined h/m   shard\n";
  for (const auto& [asset, r] : latest) {
    std::string hit_miss = "-";
    if (r.contains("accuracy") && r["accuracy"].contains("refined_hit_miss")) {
      char value[32];
      std::snprintf(value, sizeof(value), "%.3f%%",
                    100.0 * r["accuracy"]["refined_hit_miss"].get<double>());
      hit_miss = value;
    }
    text += format(row, fs::path(asset).filename().string(), text_of(r, "status"),
                   number_of(r, "seconds"), hit_miss, text_of(r, "shard"));
  }
  return text;
}

/// Counts, time per built mesh, the slowest meshes and the failures with their errors.
std::string totals(const std::map<std::string, json>& latest, const BatchSummary& s) {
  std::map<std::string, size_t> counts;
  std::vector<std::pair<double, std::string>> built;
  std::string failures;
  for (const auto& [asset, r] : latest) {
    const std::string status = text_of(r, "status");
    ++counts[status];
    if (status == "built") {
      built.emplace_back(number_of(r, "seconds"), fs::path(asset).filename().string());
    } else if (status == "failed") {
      failures += "  " + text_of(r, "mesh") + ": " + text_of(r, "error") + "\n";
    }
  }
  char line[512];
  std::snprintf(line, sizeof(line),
                "%zu meshes: %zu built, %zu up to date, %zu failed, %zu without a line\n", s.meshes,
                counts["built"], counts["up to date"], counts["failed"], s.missing);
  std::string text = line;
  if (!built.empty()) {
    std::sort(built.rbegin(), built.rend());
    double total = 0.0;
    for (const auto& b : built) {
      total += b.first;
    }
    std::snprintf(line, sizeof(line),
                  "time per built mesh: mean %.2f s, median %.2f s, max %.2f s (%.1f s in all)\n",
                  total / double(built.size()), built[built.size() / 2].first, built[0].first,
                  total);
    text += line;
    text += "slowest:";
    for (size_t i = 0; i < std::min<size_t>(5, built.size()); ++i) {
      std::snprintf(line, sizeof(line), "%s %s %.2f s", i ? "," : "", built[i].second.c_str(),
                    built[i].first);
      text += line;
    }
    text += "\n";
  }
  return failures.empty() ? text : text + "failed:\n" + failures;
}

/// Shards (of `count`) with a failed asset or fewer assets than they hold: shard i of `meshes`
/// meshes (the input as its newest run saw it) holds meshes i, i + count, ...
std::vector<int> shards_to_rerun(const std::vector<Manifest>& manifests,
                                 const std::map<std::string, json>& latest, size_t meshes,
                                 int count) {
  std::vector<std::set<std::string>> seen(static_cast<size_t>(count));
  std::set<int> rerun;
  for (const Manifest& m : manifests) {
    if (m.count != count || m.index >= count) {
      continue;
    }
    for (const json& r : m.records) {
      const std::string asset = r["asset"].get<std::string>();
      const auto it = latest.find(asset);
      // A line of a run over another input (a mesh since added or gone: the shards held other
      // meshes then), or of a mesh gone from the input, says nothing of the shards now.
      if (it == latest.end() || size_t(number_of(r, "meshes")) != meshes) {
        continue;
      }
      seen[size_t(m.index)].insert(asset);
      if (text_of(it->second, "status") == "failed") {
        rerun.insert(m.index);
      }
    }
  }
  for (size_t i = 0; i < size_t(count); ++i) {
    const size_t holds = meshes > i ? (meshes - i + size_t(count) - 1) / size_t(count) : 0;
    if (seen[i].size() < holds) {
      rerun.insert(int(i));
    }
  }
  return {rerun.begin(), rerun.end()};
}

}  // namespace

bool summarize_batch(const std::string& dir, BatchSummary& summary, std::string& error) {
  std::vector<Manifest> manifests;
  std::vector<std::string> skipped;
  if (!read_manifests(dir, manifests, skipped, error)) {
    return false;
  }
  std::map<std::string, json> latest = latest_records(manifests);
  // An asset whose mesh has left the input since its line was written is no longer the batch's:
  // listed, not counted (the batch's size is what its newest run saw).
  std::string vanished;
  for (auto it = latest.begin(); it != latest.end();) {
    if (file_problem(text_of(it->second, "mesh")) == "no such file") {
      vanished += "  " + text_of(it->second, "mesh") + "\n";
      it = latest.erase(it);
    } else {
      ++it;
    }
  }
  BatchSummary s;
  std::string newest;
  for (const auto& [asset, r] : latest) {
    s.failed += text_of(r, "status") == "failed" ? 1 : 0;
    if (text_of(r, "finished") >= newest) {
      newest = text_of(r, "finished");
      s.shard_count = std::max(1, int(number_of(r, "shard_count")));
      s.meshes = size_t(number_of(r, "meshes"));
    }
  }
  s.missing = s.meshes > latest.size() ? s.meshes - latest.size() : 0;
  s.shards_to_rerun = shards_to_rerun(manifests, latest, s.meshes, s.shard_count);
  s.text = "batch " + dir + ": " + std::to_string(manifests.size()) + " manifests\n" +
           table(latest) + totals(latest, s) +
           (vanished.empty() ? "" : "meshes gone from the input since their lines:\n" + vanished);
  for (const std::string& where : skipped) {
    s.text += "skipped an unreadable line: " + where + "\n";
  }
  summary = std::move(s);
  return true;
}

}  // namespace gfield
