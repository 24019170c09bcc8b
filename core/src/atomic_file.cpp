#include "gfield/atomic_file.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <mutex>
#include <system_error>

namespace gfield {

namespace {

// Temporary files alive in this process, so that SIGINT/SIGTERM can remove them. Fixed-size
// buffers: the signal handler may only call async-signal-safe functions (unlink, raise).
constexpr int kSlots = 64;
constexpr size_t kPathBytes = 4096;
struct Slot {
  std::atomic<bool> used{false};
  char path[kPathBytes];
};
std::array<Slot, kSlots> g_slots;
std::atomic<unsigned> g_counter{0};
std::once_flag g_handlers_installed;
std::atomic<bool> g_host_signals{false};  ///< leave_signals_to_host: no handlers
std::atomic<bool> g_deferring{false};     ///< SignalsDeferred alive
std::atomic<int> g_deferred{0};           ///< the signal that arrived meanwhile

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  if (g_deferring.load()) {
    int none = 0;
    g_deferred.compare_exchange_strong(none, signal_number);
    return;
  }
  for (Slot& slot : g_slots) {
    if (slot.used.load()) {
      ::unlink(slot.path);
    }
  }
  for (Slot& slot : g_slots) {
    if (slot.used.load()) {
      ::rmdir(slot.path);
    }
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void install_handlers() {
  if (g_host_signals.load()) {
    return;
  }
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) {
    if (std::signal(s, remove_temporaries_and_reraise) == SIG_IGN) {
      std::signal(s, SIG_IGN);  // keep an inherited "ignore" (e.g. nohup)
    }
  }
}

int register_slot(const std::filesystem::path& p) {
  const std::string s = p.string();
  if (s.size() >= kPathBytes) {
    return -1;
  }
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (g_slots[i].used.compare_exchange_strong(expected, true)) {
      g_slots[i].used.store(false);
      std::memcpy(g_slots[i].path, s.c_str(), s.size() + 1);
      g_slots[i].used.store(true);
      return i;
    }
  }
  return -1;
}

std::filesystem::path temporary_name(const std::filesystem::path& target) {
  std::filesystem::path path = target;
  path += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(g_counter++);
  return path;
}

}  // namespace

void leave_signals_to_host() {
  g_host_signals.store(true);
}

RemovedOnSignal::RemovedOnSignal(const std::filesystem::path& path) {
  std::call_once(g_handlers_installed, install_handlers);
  slot_ = register_slot(path);
}

RemovedOnSignal::~RemovedOnSignal() {
  if (slot_ >= 0) {
    g_slots[slot_].used.store(false);
  }
}

SignalsDeferred::SignalsDeferred() {
  std::call_once(g_handlers_installed, install_handlers);
  g_deferring.store(true);
}

SignalsDeferred::~SignalsDeferred() {
  g_deferring.store(false);
  if (const int s = g_deferred.exchange(0); s != 0) {
    std::raise(s);
  }
}

TemporaryFile::TemporaryFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporary_name(target_)), on_signal_(temporary_) {}

TemporaryFile::~TemporaryFile() {
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

bool TemporaryFile::commit(std::string& error) {
  std::error_code ec;
  std::filesystem::rename(temporary_, target_, ec);
  if (ec) {
    error = target_.string() + ": cannot write (" + ec.message() + ")";
    return false;
  }
  committed_ = true;
  return true;
}

std::string TemporaryFile::as_target(std::string text) const {
  const std::string from = temporary_.string(), to = target_.string();
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

bool write_text_file(const std::string& filename, const std::string& contents, std::string& error) {
  TemporaryFile tmp(filename);
  {
    errno = 0;
    std::ofstream out(tmp.path(), std::ios::binary);
    out << contents;
    out.flush();
    if (!out) {  // the failed open or write set errno
      error = filename + ": cannot write" +
              (errno != 0 ? " (" + std::string(std::strerror(errno)) + ")" : std::string());
      return false;
    }
  }
  return tmp.commit(error);
}

}  // namespace gfield
