// pipeline/atomic_file.cpp — files and folders that appear whole or not at all (files.hpp); the signal
// handler that removes a staging folder is in staging_signals.cpp.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>
#include <stdexcept>
#include <system_error>

#include <csignal>  // kill
#include <fcntl.h>  // renameat2 (stdio.h), AT_FDCWD
#include <unistd.h>

#include "pipeline/files.hpp"
#include "pipeline/staging_signals.hpp"

namespace gsdot3::pipeline {

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw std::runtime_error(file.string() + ": cannot write");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(file.string() + ": cannot rename the written file into place: " + ec.message());
  }
}

namespace {

namespace fs = std::filesystem;

constexpr const char* out_mark = ".gsdot3-out";  // in every staged folder: "a gsdot3 output, may be replaced"

// TARGET as a name in its parent folder: "out/" and "a/./out" are "out" in "a".
fs::path normalised(const fs::path& target) {
  fs::path p = fs::absolute(target).lexically_normal();
  return p.has_filename() ? p : p.parent_path();
}

// A sibling of `base` that does not exist yet: BASE.KIND-PID-N.
fs::path fresh_sibling(const fs::path& base, const char* kind) {
  for (int n = 0;; ++n) {
    std::string suffix = ".";  // appended piecewise: g++ 12 warns falsely (-Wrestrict) on a chain of +
    suffix.append(kind).append("-").append(std::to_string(::getpid())).append("-").append(std::to_string(n));
    fs::path p = base;
    p += suffix;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(p, ec))) return p;
  }
}

// Removes BASE.partial-PID-... of processes that are gone (kill(PID, 0) fails with ESRCH): what a run
// ended by a crash or SIGKILL left. A live process's (another run into the same folder) stays.
void remove_stale_siblings(const fs::path& base) {
  const std::string prefix = base.filename().string() + ".partial-";
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(base.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::size_t digits = name.find_first_not_of("0123456789", prefix.size());
    if (digits == prefix.size() || digits == std::string::npos || name[digits] != '-' || digits - prefix.size() > 9)
      continue;
    const long pid = std::stol(name.substr(prefix.size(), digits - prefix.size()));
    if (pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) stale.push_back(it->path());
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

}  // namespace

staged_directory::staged_directory(fs::path target, const std::string& mark) : target_(std::move(target)) {
  std::error_code ec;
  const fs::path base = normalised(target_);
  if (fs::exists(base, ec) && !fs::is_directory(base, ec))
    throw std::runtime_error(target_.string() + ": exists and is not a directory");
  if (fs::is_directory(base, ec)) {  // fail now, not after minutes of work
    if (!fs::is_empty(base, ec) && !fs::exists(base / out_mark, ec) && !fs::exists(base / mark, ec))
      throw std::runtime_error(target_.string() + ": holds files but no " + mark +
                               ", so is not a previous output this run may replace; give a new or empty folder");
    if (::access(base.c_str(), W_OK) != 0)  // its files could not be removed when it is replaced
      throw std::runtime_error(target_.string() + ": the output directory is not writable");
  }
  if (!fs::is_directory(base.parent_path(), ec)) {
    fs::create_directories(base.parent_path(), ec);
    if (ec) throw std::runtime_error(target_.string() + ": cannot create the output directory (" + ec.message() + ")");
  }
  remove_stale_siblings(base);
  staging_ = fresh_sibling(base, "partial");
  slot_ = track_staging(staging_);  // before the folder exists: a signal never finds it untracked
  if (!fs::create_directory(staging_, ec) || ec || !std::ofstream(staging_ / out_mark)) {
    const std::string why = ec ? ec.message() : std::string("cannot write into it");
    fs::remove_all(staging_, ec);
    untrack_staging(slot_);
    throw std::runtime_error(target_.string() + ": cannot create the output directory beside it (" + why + ")");
  }
}

staged_directory::~staged_directory() {
  if (!committed_) {
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
  }
  untrack_staging(slot_);
}

std::string staged_directory::as_target(std::string message) const {
  const std::string from = staging_.string(), to = target_.string();
  for (std::size_t at = 0; (at = message.find(from, at)) != std::string::npos; at += to.size())
    message.replace(at, from.size(), to);
  return message;
}

void staged_directory::commit() {
  const fs::path base = normalised(target_);
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(target_.string() + ": cannot put the output in place (" + why + ")");
  };
  std::error_code ec;
  if (!fs::exists(base, ec)) {
    fs::rename(staging_, base, ec);
    if (ec) fail(ec.message());
  } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, base.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(staging_, ec);  // now the previous output; a signal meanwhile removes it too
  } else if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP) {  // a filesystem without the exchange
    const fs::path old = fresh_sibling(base, "old");
    fs::rename(base, old, ec);
    if (ec) fail(ec.message());
    fs::rename(staging_, base, ec);
    if (ec) {
      std::error_code ignored;
      fs::rename(old, base, ignored);
      fail(ec.message());
    }
    fs::remove_all(old, ec);
  } else {
    fail(std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace gsdot3::pipeline
