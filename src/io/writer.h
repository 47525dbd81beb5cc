#pragma once
// The one file writer: sets of files replaced as a whole, and the names of output files.
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace fl::io {

// Files to write together: (path, bytes).
using Files = std::vector<std::pair<std::string, std::string>>;

// The one rule for where outputs go: the folder that holds `path` (a file, or an output folder)
// must exist and be writable; outputs never create it. InputError otherwise, naming `path`; the
// writer checks it, and commands check it again before their work.
void require_output_folder(const std::string& path);

// The one file writer. A set of files, replaced as a whole or not at all:
//  1. every file is written, each write checked, into a hidden staging folder
//     `.fresnel-lab-staging.PID.N` in the folder that holds the set (the deepest folder common to
//     the files, or `out_folder` when given: an output folder, created if missing, whose parent
//     must exist);
//  2. the complete staging folder is renamed `.fresnel-lab-commit.PID.N`: the commit point;
//  3. its files are renamed into place, and it is removed.
// A failure before 2 removes the staging folder and leaves the previous files as they were; the
// error names the user's path, never the staging one. Termination signals (INT, TERM, HUP) that
// arrive while a set is written take effect once it is in place (install_termination_handler).
// Every write first recovers what dead processes left in that folder: an uncommitted staging
// folder is removed, a committed one's files are moved into place (so a set killed in step 3 is
// completed by the next write), and the temporaries of replace_folder_atomic are resolved the same
// way. Moving in and recovering hold an exclusive lock on the folder, so concurrent runs never
// interleave their sets.
void write_files_atomic(const Files& path_and_content, const std::string& out_folder = "");
void write_file_atomic(const std::string& path, const std::string& content);  // one file

// A folder of outputs replaced as a whole: `files` (paths relative to `folder`) plus an empty
// `marker` file are written to `FOLDER.new.PID` beside it, renamed `FOLDER.ready.PID` once
// complete (the commit point), which then takes the place of `folder` (the previous one moved to
// `FOLDER.old.PID` and removed), so a rerun leaves no stale file of the previous one and a failure
// leaves the previous one intact; the staging of dead processes is recovered as above. An existing
// `folder` must be empty or hold `marker` (a folder this writer made): anything else is an
// InputError, checked by require_replaceable_folder before the work (with require_output_folder).
void replace_folder_atomic(const std::string& folder, const Files& files,
                           const std::string& marker);
void require_replaceable_folder(const std::string& folder, const std::string& marker);

// Installs the handler of SIGINT, SIGTERM and SIGHUP that holds them while a set is being written
// (then the process ends by the signal, its outputs complete); at any other time the signal's
// default action is taken at once. Called once by the command line.
void install_termination_handler();

// What a command produces: its files, and the lines to show on stderr once they are written.
struct Output {
  Files files;
  std::vector<std::string> messages;
};
// The paths of `files` for a message: "a", "a and b", "a, b and c".
std::string file_list(const Files& files);

// The lower-case extension of `path` (".exr"; empty if none).
std::string lower_extension(const std::string& path);
// lower_extension(path), which must be one of `allowed`; otherwise an InputError naming the path
// and the expected types.
std::string output_extension(const std::string& path, std::initializer_list<const char*> allowed);

}  // namespace fl::io
