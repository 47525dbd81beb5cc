#include "cli/app.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>

#include "analysis/pipeline/materials.h"
#include "color/rgb_space.h"
#include "fresnel_lab_version.h"
#include "util/errors.h"
#include "util/suggest.h"
#include "util/truncated.h"

namespace fl::cli {

void progress(const GlobalOptions& g, const std::string& message) {
  if (!g.quiet) fmt::print(stderr, "{}\n", message);
}

void print_warnings(const GlobalOptions& g, const std::vector<analysis::LoadedMaterial>& ms) {
  for (const auto& m : ms)
    for (const auto& w : m.warnings) progress(g, "warning: " + w);
}

const char* const kMaterialsHelp =
    "catalog names (gold), database pages (main/Au/nk/Johnson), page globs ('main/*/nk/*', '**') "
    "or files "
    "(refractiveindex.info .yml, CSV/text tables, SOPRA .nk, WVASE .mat, NAME.eta.spd + "
    "NAME.k.spd)";

std::vector<analysis::LoadedMaterial> load_many(const GlobalOptions& g,
                                                const analysis::Context& ctx,
                                                const std::vector<std::string>& specs,
                                                std::vector<std::string>* skipped,
                                                bool allow_empty) {
  analysis::LoadPolicy policy;
  policy.min_coverage = g.min_coverage >= 0 ? g.min_coverage : analysis::kDefaultMinCoverage;
  policy.skip_named = g.skip_unusable;
  auto set = analysis::load_materials(ctx, specs, policy);
  print_warnings(g, set.materials);
  for (const auto& s : set.skipped) {
    progress(g, fmt::format("skipped {}: {}", s.spec, s.reason));
    if (skipped) skipped->push_back(s.spec + ": " + s.reason);
  }
  if (!set.skipped.empty())
    progress(g, fmt::format("skipped {} of {} materials", set.skipped.size(), set.requested));
  if (set.materials.empty() && !allow_empty)
    throw InputError("no material left to work on (every one was skipped)");
  return std::move(set.materials);
}

std::function<void(int, int)> study_progress(const GlobalOptions& g, const std::string& what) {
  const bool tty = ::isatty(STDERR_FILENO);
  return [&g, what, tty](int done, int total) {
    if (g.quiet || (!tty && done != total)) return;
    fmt::print(stderr, "{}{}{}/{} materials{}", tty ? "\r" : "", what, done, total,
               done == total ? "\n" : "");
  };
}

std::function<void(int, int)> periodic_progress(const GlobalOptions& g, const std::string& what,
                                                double seconds) {
  const bool tty = ::isatty(STDERR_FILENO);
  const auto t0 = std::chrono::steady_clock::now();
  auto last = std::make_shared<std::pair<int, double>>(
      0, 0.0);  // (tenths reported, seconds at the last line)
  return [&g, what, tty, t0, last, seconds](int done, int total) {
    if (g.quiet || total <= 0) return;
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (tty) {
      fmt::print(stderr, "\r{}{}/{}{}", what, done, total, done == total ? "\n" : "");
      return;
    }
    const int tenth = static_cast<int>(10LL * done / total);
    if (done != total && tenth <= last->first && t - last->second < seconds) return;
    last->first = std::max(last->first, tenth);
    last->second = t;
    fmt::print(stderr, "{}{}/{} ({:.0f} s)\n", what, done, total, t);
  };
}

CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& s) { return s.empty() ? std::string("is empty") : std::string(); }, "TEXT",
      "non-empty");
}

CLI::Validator finite_range(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        double x = 0;
        if (!CLI::detail::lexical_cast(s, x) || !std::isfinite(x) || x < lo || x > hi)
          return fmt::format("'{}' is not a number from {:g} to {:g}", s, lo, hi);
        return {};
      },
      fmt::format("[{:g} - {:g}]", lo, hi), "finite range");
}

CLI::Validator output_location() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        if (path.empty()) return "is empty: name the output";
        try {
          require_output_folder(path);
        } catch (const InputError& e) {
          return e.what();
        }
        return {};
      },
      "PATH", "output location");
}

void emit(const GlobalOptions& g, const std::string& out, const std::string& text) {
  if (out.empty()) {
    fmt::print("{}", text);
    return;
  }
  require_output_folder(out);
  io::write_file_atomic(out, text);
  progress(g, "wrote " + out);
}

int write_output(const GlobalOptions& g, const io::Output& out) {
  io::write_files_atomic(out.files);
  for (const auto& m : out.messages) progress(g, m);
  return 0;
}

spectral::DataFile given_or(const std::string& option, const spectral::DataFile& fallback) {
  return option.empty() ? fallback : spectral::DataFile{option, option};
}

analysis::Context make_context(const GlobalOptions& g) {
  const std::string& db = g.settings.paths.database;
  if (db.empty())
    throw InputError("no refractiveindex.info database given: use --db DIR or set $FRESNEL_LAB_DB");
  std::error_code ec;
  if (!std::filesystem::is_directory(db + "/data", ec))
    throw InputError(db, 0, database_missing_message(g.locations));
  return analysis::Context(g.settings);
}

namespace {

std::string version_text() {
  return fmt::format("fresnel-lab {} (commit {})", FRESNEL_LAB_VERSION, FRESNEL_LAB_COMMIT);
}

// Where the command line points in the command tree: the commands it names, outermost first
// (`fresnel-lab`, `lut`, `dfg`), and an "unknown ... command" message with the nearest name when a
// word stands where a subcommand is required.
struct CommandPath {
  std::vector<const CLI::App*> apps;
  std::optional<std::string> unknown;
};

// Whether `arg` (an option) takes the next word as its value, in `app` or the program.
bool takes_value(const CLI::App& app, const CLI::App& program, const std::string& arg) {
  if (arg.find('=') != std::string::npos) return false;          // --name=value
  if (arg.rfind("--", 0) != 0 && arg.size() != 2) return false;  // -abc: flags or -xVALUE
  for (const CLI::App* a : {&app, &program})
    if (const auto* opt = a->get_option_no_throw(arg)) return opt->get_type_size_min() > 0;
  return false;
}

CommandPath command_path(const CLI::App& program, int argc, char** argv) {
  CommandPath path{{&program}, std::nullopt};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const CLI::App& here = *path.apps.back();
    if (a.rfind("-", 0) == 0) {
      if (takes_value(here, program, a)) ++i;
      continue;
    }
    const auto subs = here.get_subcommands([](const CLI::App*) { return true; });
    if (subs.empty()) break;  // a leaf command: the rest are its arguments
    const auto it = std::find_if(subs.begin(), subs.end(),
                                 [&](const CLI::App* s) { return s->get_name() == a; });
    if (it != subs.end()) {
      path.apps.push_back(*it);
      continue;
    }
    if (here.get_require_subcommand_min() == 0) break;
    std::vector<NameChoice> choices;
    for (const auto* s : subs) choices.push_back({s->get_name(), {}});
    const std::string what = path.apps.size() == 1 ? "command" : here.get_name() + " command";
    path.unknown = unknown_name_message(what, a, choices);
    break;
  }
  return path;
}

// "fresnel-lab lut dfg": the commands of a path.
std::string command_words(const CommandPath& path) {
  std::string words;
  for (const auto* a : path.apps) words += (words.empty() ? "" : " ") + a->get_name();
  return words;
}

// The help footer of every subcommand: the program's options, which every command accepts.
std::string global_options_footer(const CLI::App& program) {
  std::string text = "Global options (before or after the command; fresnel-lab --help):\n";
  for (const auto* opt : program.get_options()) {
    const std::string name = opt->get_name(false, true);
    if (name.find("help") != std::string::npos || name.find("version") != std::string::npos)
      continue;
    text += fmt::format("  {:<22}{}\n", name, opt->get_description());
  }
  return text;
}

void add_footer(CLI::App& app, const std::string& footer) {
  for (auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    sub->footer(footer);
    add_footer(*sub, footer);
  }
}

// The options every command shares, into g (whose defaults are set).
// The display and views of every picture.
void add_picture_options(CLI::App& app, analysis::Settings& s) {
  app.add_option("--display", s.view.display,
                 "OpenColorIO display of every picture (default: sRGB; with --ocio-config, any the "
                 "config has)")
      ->check(non_empty());
  app.add_option("--view", s.view.view,
                 "OpenColorIO view of renders, flips and contact sheets (default: ACES 1.0 - SDR "
                 "Video, or with --ocio-config the config's default view of the display; without "
                 "a config also Un-tone-mapped)")
      ->check(non_empty());
  app.add_option("--reflectance-view", s.reflectance_view,
                 "OpenColorIO view of reflectance colours: strips and swatches (default: "
                 "Un-tone-mapped, reflectance 1 as display white)")
      ->check(non_empty());
  app.add_option("--exposure", s.view.exposure_ev,
                 "stops applied to renders before the view (EXRs, tables and every ΔE2000 stay "
                 "scene-linear)")
      ->capture_default_str();
}

void add_global_options(CLI::App& app, GlobalOptions& g) {
  auto& s = g.settings;
  app.add_option(
         "--db", s.paths.database,
         "refractiveindex.info database root (the folder holding data/); default $FRESNEL_LAB_DB")
      ->capture_default_str();
  app.add_option("--materials", s.paths.materials, "material catalog folder")
      ->capture_default_str();
  app.add_option("--space", s.space,
                 "working space: acescg, lin_rec709, aces2065-1, lin_rec2020, lin_p3d65 (or a "
                 "space of --ocio-config)")
      ->capture_default_str()
      ->check(non_empty());
  app.add_option(
         "--illuminant", s.illuminant,
         "D50, D55, D60, D65, D75, A, E, or Dnnnn (daylight at nnnn K); default: the working "
         "space's "
         "reference "
         "white (D60 for acescg and aces2065-1, D65 for lin_rec709, lin_rec2020, lin_p3d65)")
      ->check(non_empty());
  app.add_option("--angles", s.angles, "incidence-angle samples over [0°, 90°]")
      ->capture_default_str();
  app.add_option("--adaptation", s.adaptation, "chromatic adaptation: bradford, cat02, none")
      ->capture_default_str()
      ->check(non_empty());
  app.add_option("--step-nm", s.step_nm, "spectral step, 5 or 1 nm (360-830 nm)")
      ->capture_default_str();
  app.add_option("--ocio-config", s.ocio_config,
                 "an OpenColorIO config whose colour-space names --space takes (default $OCIO; "
                 "empty: built-in spaces)");
  app.add_option("--ocio-xyz", s.ocio_xyz,
                 "the config's CIE XYZ D65 space (default: role cie_xyz_d65_interchange)");
  app.add_option("--ocio-white", s.ocio_white,
                 "white of the --space colour space of the config: ACES or an illuminant name "
                 "(default: the built-in "
                 "space whose matrix it has, else D65)");
  add_picture_options(app, s);
  app.add_flag("-q,--quiet", g.quiet, "no progress or warnings on stderr");
  app.add_option("--min-coverage", g.min_coverage,
                 "refuse materials named explicitly, skip pages matched by a glob, whose data "
                 "covers less than this share of the visible range, weighted by the illuminant x "
                 "ybar (0-1; default 0.99: a material measured over part of the visible is mostly "
                 "extrapolation)")
      ->check(finite_range(0.0, 1.0));
  app.add_flag("--skip-unusable", g.skip_unusable,
               "skip (with the reason) a material named explicitly that cannot be read or is "
               "below --min-coverage, instead of refusing the command");
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{
      "Fresnel Lab: spectral ground truth, Fresnel approximations and their parameters, in "
      "CIEDE2000."};
  app.name("fresnel-lab");
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text(), "print the version and the git commit");
  GlobalOptions g;
  auto& s = g.settings;
  g.locations = find_locations(std::filesystem::path(executable_path()).parent_path().string());
  s.paths = default_paths(g.locations);
  s.ocio_config = default_ocio_config();
  g.label_font = label_font_file();
  io::install_termination_handler();

  add_global_options(app, g);

  // Global options are accepted after the command as well as before it: a subcommand passes the
  // options it does not know to the program (CLI11's fallthrough, inherited by every subcommand).
  app.fallthrough();
  Runner selected;
  for (const auto& c : commands()) c.add(app, g, selected);
  add_footer(app, global_options_footer(app));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const auto path = command_path(app, argc, argv);
    fmt::print(stderr, "fresnel-lab: error: {} (see {} --help)\n",
               truncated(path.unknown.value_or(e.what()), kMaxErrorLine), command_words(path));
    return 2;
  }
  if (!selected) throw InputError("no command given (see --help)");
  // A built-in space under any of its accepted names is known by its canonical one from here on.
  if (s.ocio_config.empty())
    if (const auto canonical = color::builtin_space_name(s.space)) s.space = *canonical;
  return selected();
}

}  // namespace fl::cli
