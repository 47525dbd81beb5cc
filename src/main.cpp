// fresnel-lab: the command-line entry point. Exceptions are caught here, once.
#include <fmt/format.h>

#include <exception>

#include "cli/app.h"
#include "util/errors.h"

int main(int argc, char** argv) {
  try {
    return fl::cli::run(argc, argv);
  } catch (const fl::InputError& e) {
    fmt::print(stderr, "fresnel-lab: error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "fresnel-lab: failure: {}\n", e.what());
    return 1;
  }
}
