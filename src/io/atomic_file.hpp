// Writing a file so that it is never seen half-written: a temporary file in the same folder,
// flushed and fsync'd, then renamed over the old one (the folder fsync'd too), keeping the last
// few versions as FILE.1, FILE.2, ... A crash or a kill at any moment leaves either the old file
// or the new one whole.
#pragma once
#include <filesystem>
#include <string_view>

namespace s4d {

// Throws s4d::Error naming the file and the reason when it cannot write; the old file is then
// untouched. `keep` older versions are kept (FILE.1 the newest of them).
void write_file_atomically(const std::filesystem::path& path, std::string_view text, int keep = 0);

// Removes the temporaries (FILE.tmp-PID) that writers killed mid-write left beside `path`, those of
// processes no longer running; returns how many. Never throws (what cannot be removed stays).
int remove_stale_temporaries(const std::filesystem::path& path);

}  // namespace s4d
