// Output files are written whole: the bytes go to a temporary file beside the target,
// which is renamed over it only when complete. A crash, a full disk or an exception
// leaves either the old file or none, never a partial one.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace sg {

// Writes `bytes` to `path` through a temporary file and a rename. Throws sg::Error
// naming `path` on failure.
void write_file_atomic(const std::string& path, std::string_view bytes);

// For writers that need a file name (OpenEXR): `write(tmp)` writes to a temporary path
// beside `path`; on success it is renamed to `path`, on any exception it is removed.
void write_file_atomic_with(const std::string& path,
                            const std::function<void(const std::string& tmp)>& write);

// Reads a whole file of at most `max_bytes`; throws sg::Error naming `path` when it is
// missing, not a regular file (a folder, a device such as /dev/zero, a fifo: checked
// before opening, so nothing blocks or runs forever) or larger.
std::string read_file(const std::string& path, std::uintmax_t max_bytes = UINTMAX_MAX);

// Throws the errors of read_file for `path` without reading it; returns its size.
std::uintmax_t check_readable_file(const std::string& path, std::uintmax_t max_bytes = UINTMAX_MAX);

}  // namespace sg
