// fresnel-lab: the command-line entry point. Exceptions are caught here, once; so is a failed
// write to standard output (a full disk, a closed pipe's file): exit status 1, never 0. An error
// line is cut to kMaxErrorLine bytes (util/truncated.h).
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>

#include "cli/app.h"
#include "util/errors.h"
#include "util/truncated.h"

namespace {

// Exit status 1 with a message when standard output could not be written (its buffer is flushed
// here, so a write that failed late is seen too); `status` otherwise.
int checked_stdout(int status) {
  errno = 0;
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return status;
  fmt::print(stderr, "fresnel-lab: failure: standard output: write failed{}\n",
             errno ? fmt::format(": {}", std::strerror(errno)) : "");
  return status != 0 ? status : 1;
}

}  // namespace

int main(int argc, char** argv) {
  int status = 1;
  try {
    status = fl::cli::run(argc, argv);
  } catch (const fl::InputError& e) {
    fmt::print(stderr, "fresnel-lab: error: {}\n", fl::truncated(e.what(), fl::kMaxErrorLine));
    status = 2;
  } catch (const std::exception& e) {
    if (std::ferror(stdout)) return checked_stdout(1);
    fmt::print(stderr, "fresnel-lab: failure: {}\n", fl::truncated(e.what(), fl::kMaxErrorLine));
    status = 1;
  }
  return checked_stdout(status);
}
