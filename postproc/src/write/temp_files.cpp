// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/write/temp_files.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <mutex>

namespace ncpost {
namespace {

// Fixed storage, so that the handler touches no heap: a slot's path is valid while its state is 1.
constexpr std::size_t kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 holds a path to remove, 2 being filled
  char path[kPathBytes];
};
std::array<Slot, kSlots> g_slots;
std::mutex g_mutex;  // registration only
bool g_installed = false;

void remove_and_die(int sig) {
  for (auto& slot : g_slots)
    if (slot.state.load() == 1) ::unlink(slot.path);  // async-signal-safe
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);  // ends the process with the signal's own status
}

void install_handlers() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    ::sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // nohup, or a shell that ignores SIGINT: keep it so
    struct sigaction sa {};
    sa.sa_handler = remove_and_die;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    sigaddset(&sa.sa_mask, SIGHUP);
    ::sigaction(sig, &sa, nullptr);
  }
}

}  // namespace

void remember_temp_file(const std::string& path) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (!g_installed) {
    install_handlers();
    g_installed = true;
  }
  if (path.size() >= kPathBytes) throw FileError("'" + path + "': path too long for a temporary file");
  for (auto& slot : g_slots)
    if (slot.state.load() == 0) {
      slot.state.store(2);
      std::memcpy(slot.path, path.c_str(), path.size() + 1);
      slot.state.store(1);
      return;
    }
  throw std::runtime_error("more than 64 temporary files at once");
}

void forget_temp_file(const std::string& path) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (auto& slot : g_slots)
    if (slot.state.load() == 1 && path == slot.path) {
      slot.state.store(0);
      return;
    }
}

}  // namespace ncpost
