#include "io/staging.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <vector>

#include "io/writer.h"

namespace fl::io {
namespace staging {
namespace {

std::atomic<int> g_holding{0};      // HoldSignals objects alive
std::atomic<int> g_held_signal{0};  // a termination signal that arrived meanwhile
const int kTerminationSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void on_termination(int sig) {
  if (g_holding.load() > 0) {
    g_held_signal.store(sig);
    return;
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

bool process_alive(long pid) {
  if (pid <= 0 || pid == static_cast<long>(::getpid())) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

// The digits of `s` as a number (nullopt unless all are digits).
std::optional<long> digits(std::string_view s) {
  if (s.empty() || s.size() > 10 || !std::all_of(s.begin(), s.end(), ::isdigit))
    return std::nullopt;
  return std::stol(std::string(s));
}

enum class Kind { Staging, Committed, New, Ready, Old, Tmp };

struct Leftover {
  Kind kind;
  fs::path path;
  std::string base;  // New, Ready, Old, Tmp: the name of what they stand in for
  long pid;
};

// A name the writer gives its temporaries, with the process that made it.
std::optional<Leftover> leftover(const fs::path& p) {
  const std::string name = p.filename().string();
  for (const auto& [prefix, kind] :
       {std::pair{kStaging, Kind::Staging}, std::pair{kCommitted, Kind::Committed}})
    if (name.rfind(prefix, 0) == 0) {
      const std::string rest = name.substr(std::strlen(prefix));
      const auto pid = digits(rest.substr(0, rest.find('.')));
      if (pid) return Leftover{kind, p, "", *pid};
    }
  const auto dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0) return std::nullopt;
  const auto pid = digits(std::string_view(name).substr(dot + 1));
  const auto dot2 = name.rfind('.', dot - 1);
  if (!pid || dot2 == std::string::npos || dot2 == 0) return std::nullopt;
  const std::string tag = name.substr(dot2 + 1, dot - dot2 - 1), base = name.substr(0, dot2);
  for (const auto& [t, kind] : {std::pair{"new", Kind::New}, std::pair{"ready", Kind::Ready},
                                std::pair{"old", Kind::Old}, std::pair{"tmp", Kind::Tmp}})
    if (tag == t) return Leftover{kind, p, base, *pid};
  return std::nullopt;
}

// A dead process's FOLDER.ready.PID: put in place of FOLDER as replace_folder_atomic would have.
void finish_ready(const Leftover& l, const fs::path& folder) {
  std::error_code ec;
  const fs::path target = folder / l.base, old = folder / fmt::format("{}.old.{}", l.base, l.pid);
  if (fs::exists(target, ec) && !fs::exists(old, ec)) fs::rename(target, old, ec);
  if (!fs::exists(target, ec)) fs::rename(l.path, target, ec);
  if (!ec) fs::remove_all(old, ec);
}

}  // namespace

std::string unique_suffix() {
  static std::atomic<int> n{0};
  return fmt::format("{}.{}", static_cast<long>(::getpid()), n++);
}

FolderLock::FolderLock(const fs::path& folder) {
  fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ >= 0)
    while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

void move_in(const fs::path& committed, const fs::path& folder) {
  std::error_code ec;
  std::vector<fs::path> files;
  for (auto it = fs::recursive_directory_iterator(committed, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (!it->is_directory(ec)) files.push_back(fs::relative(it->path(), committed, ec));
  std::sort(files.begin(), files.end());
  for (const auto& rel : files) {
    const fs::path to = folder / rel;
    if (rel.has_parent_path()) fs::create_directories(to.parent_path(), ec);
    fs::rename(committed / rel, to, ec);
    if (ec)
      throw std::runtime_error(fmt::format("{}: cannot move the finished file into place: {}",
                                           to.string(), ec.message()));
  }
  fs::remove_all(committed, ec);
}

void recover(const fs::path& folder) {
  std::error_code ec;
  std::vector<Leftover> found;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator();
       it.increment(ec))
    if (auto l = leftover(it->path());
        l && !process_alive(l->pid) && (l->kind == Kind::Tmp) != it->is_directory(ec))
      found.push_back(*l);  // FOLDER.new/ready/old.PID are folders, FILE.tmp.PID a file
  // Sets and folders completed first; what they replaced is removed after.
  std::stable_sort(found.begin(), found.end(), [](const Leftover& a, const Leftover& b) {
    return (a.kind == Kind::Old) < (b.kind == Kind::Old);
  });
  for (const auto& l : found) {
    std::error_code e;
    if (l.kind == Kind::Committed) {
      move_in(l.path, folder);
    } else if (l.kind == Kind::Ready) {
      finish_ready(l, folder);
    } else if (l.kind == Kind::Old) {
      if (!fs::exists(l.path, e)) continue;  // removed with its ready folder
      if (fs::exists(folder / l.base, e))
        fs::remove_all(l.path, e);
      else
        fs::rename(l.path, folder / l.base, e);  // the new one never came: the old one back
    } else {
      fs::remove_all(l.path, e);
    }
  }
}

void write_checked(const fs::path& path, const std::string& bytes, const std::string& user_path) {
  const auto fail = [&](int err) {
    return std::runtime_error(fmt::format("{}: write failed: {}", user_path, std::strerror(err)));
  };
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw fail(errno);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw fail(err);
    }
    done += static_cast<size_t>(n);
  }
  if (::close(fd) != 0) throw fail(errno);
}

HoldSignals::HoldSignals() {
  ++g_holding;
}

HoldSignals::~HoldSignals() {
  if (--g_holding > 0) return;
  if (const int sig = g_held_signal.exchange(0)) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
}

}  // namespace staging

void install_termination_handler() {
  struct sigaction sa {};
  sa.sa_handler = staging::on_termination;
  sigemptyset(&sa.sa_mask);
  for (const int sig : staging::kTerminationSignals) {
    struct sigaction current {};
    // A signal the parent had ignored (a background job's SIGINT, nohup's SIGHUP) stays ignored.
    if (::sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &sa, nullptr);
  }
}

}  // namespace fl::io
