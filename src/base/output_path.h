// Checks made before any work: that the files a command will write can be written. A
// render that runs for minutes and then cannot save its image is wasted, so each command
// checks its output paths (the folder exists, is a folder, accepts a new file; the path is
// not itself a folder) before its first pixel, and creates a missing folder only when the
// user asked for it (`--mkdir`, or a command whose output is a folder, such as `compare`).
#pragma once

#include <string>

namespace sg {

// Checks that a file can be created at `path`. A missing folder is created when
// `create_folder` is true (the return value then says it was), else it is an error whose
// message ends with `hint` (e.g. " (--mkdir creates it)"). Throws sg::Error naming `path`.
bool check_output_file(const std::string& path, bool create_folder, const std::string& hint = "");

// Creates the folder `dir` if missing and checks that it accepts new files. Throws sg::Error
// naming `what` (a flag such as "--out") and the folder.
void prepare_output_folder(const std::string& dir, const std::string& what);

// Checks, without creating anything, that the folder `dir` exists and accepts new files or
// can be created (its nearest existing ancestor is a folder that accepts new files).
void check_output_folder(const std::string& dir, const std::string& what);

}  // namespace sg
