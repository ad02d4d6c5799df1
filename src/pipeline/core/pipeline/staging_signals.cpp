// pipeline/staging_signals.cpp — see staging_signals.hpp; remove_staging_on_signals is in files.hpp.
//
// The handler may call only async-signal-safe functions: no malloc, no std::filesystem, no opendir /
// readdir / nftw (they allocate). It walks a folder with openat + getdents64 (the system call under
// readdir, a fixed buffer on the stack) and removes with unlinkat; the paths were formatted when the
// folder was made. The folder is first renamed to PATH.gone, so a thread still writing the run (by path)
// cannot add files to it while it is removed.
#include "pipeline/staging_signals.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include "pipeline/files.hpp"

namespace gsdot3::pipeline {
namespace {

constexpr int max_slots = 64;
constexpr std::size_t max_path = 4096;

// Written once before `live` is set (release) and never rewritten, so a handler on any thread that
// reads `live` (acquire) sees whole strings.
struct slot {
  std::atomic<bool> live{false};
  char path[max_path];
  char gone[max_path];  // path + ".gone"
};
slot slots[max_slots];
std::atomic<int> slots_used{0};
std::atomic_flag cleaning = ATOMIC_FLAG_INIT;
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

constexpr int max_depth = 16;  // a staging folder holds files and at most a level or two of folders

bool remove_entries(int dir, int depth) noexcept;

// Removes `name` in `dir` (AT_FDCWD: the working folder): a file or link by unlinkat, a folder after its
// entries.
bool remove_entry(int dir, const char* name, int depth) noexcept {
  if (::unlinkat(dir, name, 0) == 0 || errno == ENOENT) return true;
  if (errno != EISDIR && errno != EPERM) return false;  // Linux says EISDIR for a folder, POSIX allows EPERM
  if (depth == 0) return false;
  const int sub = ::openat(dir, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (sub < 0) return errno == ENOENT;
  const bool emptied = remove_entries(sub, depth - 1);
  ::close(sub);
  return emptied && (::unlinkat(dir, name, AT_REMOVEDIR) == 0 || errno == ENOENT);
}

// Removes every entry of `dir`; reads it again from the start until a pass finds none, since removing
// while reading may make getdents64 skip entries.
bool remove_entries(int dir, int depth) noexcept {
  for (int pass = 0; pass < 8; ++pass) {
    if (::lseek(dir, 0, SEEK_SET) < 0) return false;
    bool found = false;
    alignas(8) char buf[2048];
    for (ssize_t n; (n = ::getdents64(dir, buf, sizeof buf)) != 0;) {
      if (n < 0) return false;
      for (ssize_t at = 0; at < n;) {
        const auto* e = reinterpret_cast<const dirent64*>(buf + at);
        at += e->d_reclen;
        if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
        found = true;
        if (!remove_entry(dir, e->d_name, depth)) return false;
      }
    }
    if (!found) return true;
  }
  return false;
}

void on_signal(int sig) {
  const int saved_errno = errno;
  // One cleaner: a second signal on another thread returns; the first re-raises and ends the process.
  if (!cleaning.test_and_set()) {
    const int n = slots_used.load() < max_slots ? slots_used.load() : max_slots;
    for (int i = 0; i < n; ++i) {
      slot& s = slots[i];
      if (!s.live.load(std::memory_order_acquire)) continue;
      remove_tree_signal_safe(::rename(s.path, s.gone) == 0 ? s.gone : s.path);
    }
    // The default action once this handler returns (the signal is blocked in it): the exit status says
    // which signal ended the process.
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    ::sigaction(sig, &dfl, nullptr);
    ::raise(sig);
  }
  errno = saved_errno;
}

}  // namespace

int track_staging(const std::filesystem::path& staging) {
  std::error_code ec;
  const std::string p = std::filesystem::absolute(staging, ec).string();
  if (ec || p.size() + sizeof ".gone" > max_path) return -1;
  const int i = slots_used.fetch_add(1);
  if (i >= max_slots) return -1;
  std::memcpy(slots[i].path, p.c_str(), p.size() + 1);
  std::memcpy(slots[i].gone, p.c_str(), p.size());
  std::memcpy(slots[i].gone + p.size(), ".gone", sizeof ".gone");
  slots[i].live.store(true, std::memory_order_release);
  return i;
}

void untrack_staging(int slot) noexcept {
  if (slot >= 0) slots[slot].live.store(false, std::memory_order_release);
}

bool remove_tree_signal_safe(const char* path) noexcept { return remove_entry(AT_FDCWD, path, max_depth); }

void remove_staging_on_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, sig);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler != SIG_IGN) ::sigaction(sig, &sa, nullptr);
  }
}

}  // namespace gsdot3::pipeline
