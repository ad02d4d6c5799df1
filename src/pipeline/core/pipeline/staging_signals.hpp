// pipeline/staging_signals.hpp — the staging folders of live staged_directory objects (files.hpp), kept
// where a SIGINT / SIGTERM handler can remove them: preformatted C strings in a fixed table, and a
// recursive removal that calls only async-signal-safe functions (POSIX.1-2017 2.4.3, plus Linux's
// getdents64, a bare system call).
#pragma once

#include <filesystem>

namespace gsdot3::pipeline {

// Registers `staging` for removal on a signal; returns its slot, or -1 when the table (64 slots per
// process, never reused) is full or the path too long: such a folder is left to the next run's stale
// clean-up (staged_directory's constructor).
int track_staging(const std::filesystem::path& staging);
void untrack_staging(int slot) noexcept;

// Removes `path` and everything under it, not following symbolic links; async-signal-safe. Returns
// false when something could not be removed (path missing counts as removed).
bool remove_tree_signal_safe(const char* path) noexcept;

}  // namespace gsdot3::pipeline
