#pragma once
// The writer's staging: names of the temporaries, recovery of those dead processes left, the
// folder lock, checked writes and the termination handler (io/writer.h describes the protocol).
#include <filesystem>
#include <string>

namespace fl::io::staging {

namespace fs = std::filesystem;

// "NAME.PID.N": a set being written (`kStaging`) or one complete and being moved in (`kCommitted`).
inline constexpr const char* kStaging = ".fresnel-lab-staging.";
inline constexpr const char* kCommitted = ".fresnel-lab-commit.";
// A fresh name for this process: kStaging or kCommitted + "PID.N".
std::string unique_suffix();

// An exclusive lock (flock) on a folder, released when the object goes or the process dies.
class FolderLock {
 public:
  explicit FolderLock(const fs::path& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

// Recovers, in `folder`, the staging of processes no longer running: uncommitted sets and
// folders removed, committed ones moved into place, FOLDER.old.PID removed once FOLDER is in
// place (or put back when the new one never came). Call with the folder's lock held.
void recover(const fs::path& folder);

// Renames every file under `committed` to the same relative path under `folder` (creating its
// subfolders), then removes `committed`.
void move_in(const fs::path& committed, const fs::path& folder);

// Writes `bytes` to `path`, every write checked; std::runtime_error naming `user_path` (the
// user's name for the file) and the system's reason on failure.
void write_checked(const fs::path& path, const std::string& bytes, const std::string& user_path);

// While an object lives, termination signals are held (install_termination_handler); the last to
// go lets a held signal end the process.
class HoldSignals {
 public:
  HoldSignals();
  ~HoldSignals();
  HoldSignals(const HoldSignals&) = delete;
  HoldSignals& operator=(const HoldSignals&) = delete;
};

}  // namespace fl::io::staging
