#pragma once
// The texture cache's housekeeping files: temp files of writers (write_file_atomic)
// and per-entry lock files ("<key>.ktx2.lock").
#include <filesystem>
#include <string_view>

namespace sherpa::tex {

// A temp file nobody will finish: its writer (the PID in its name) is gone and it
// has not changed for a minute (a writer in another PID namespace keeps writing), or
// it is an hour old whoever wrote it.
bool abandoned_temp_file(std::string_view filename, std::filesystem::file_time_type::duration age);

// The lock file of a cache entry.
std::filesystem::path lock_file_for(const std::filesystem::path& entry);

// Removes the lock file of an evicted entry unless someone holds it (a holder is
// making the entry again; its lock must stay what others wait on).
void remove_unused_lock(const std::filesystem::path& entry);
// The same for a lock file's own path.
void remove_lock_if_unused(const std::filesystem::path& lock);

} // namespace sherpa::tex
