#pragma once
// The command line: a table of subcommands, each returning an exit code.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "analysis/pipeline/context.h"
#include "analysis/tables/media_tables.h"
#include "cli/locations.h"
#include "io/writer.h"

namespace fl::cli {

struct GlobalOptions {
  analysis::Settings settings;
  bool quiet = false;            // no progress or warnings on stderr
  analysis::BlendOptions blend;  // `table blend` options
  double min_coverage = -1;      // --min-coverage (negative: not given)
  bool skip_unusable = false;    // --skip-unusable: skip explicitly named unusable materials
  Locations locations;           // where the tool's data were found (cli/locations.h)
  // The label font's file ($FRESNEL_LAB_FONT; empty: DejaVu Sans). A command that draws text
  // loads it into the draw::LabelFont it passes to the drawing.
  std::string label_font;
};

// `option` (a file given on the command line, named by its path), else `fallback`.
spectral::DataFile given_or(const std::string& option, const spectral::DataFile& fallback);

using Runner = std::function<int()>;

// A command adds its subcommand (options and help) to `app`; when the user picks it, `selected`
// is set to what runs it. `g` is complete (parsed) by the time the runner is called.
struct Command {
  const char* name;
  void (*add)(CLI::App& app, GlobalOptions& g, Runner& selected);
};

// Fresnel Lab's command table (cli/commands.cpp).
const std::vector<Command>& commands();

// Parses the command line and runs the chosen command. Throws InputError for bad input; the
// caller (main) maps exceptions to exit codes.
int run(int argc, char** argv);

// Progress / warnings on stderr unless --quiet.
void progress(const GlobalOptions& g, const std::string& message);
// The context for the run, with material warnings printed once.
analysis::Context make_context(const GlobalOptions& g);
void print_warnings(const GlobalOptions& g, const std::vector<analysis::LoadedMaterial>& ms);
// MATERIALS (catalog names, database pages, page globs, files; none: the catalog) loaded under
// --min-coverage, their warnings and the skipped ones printed.
// `skipped` (if given) collects "SPEC: reason" of each skipped material, for a document's
// provenance. InputError when every material is skipped, unless allow_empty (a caller loading in
// parts checks the whole).
std::vector<analysis::LoadedMaterial> load_many(const GlobalOptions& g,
                                                const analysis::Context& ctx,
                                                const std::vector<std::string>& specs,
                                                std::vector<std::string>* skipped = nullptr,
                                                bool allow_empty = false);
// The help text of a MATERIALS argument.
extern const char* const kMaterialsHelp;
// Study progress "<what>done/total materials": a live counter on a terminal, one line when stderr
// is a log, nothing with --quiet.
std::function<void(int, int)> study_progress(const GlobalOptions& g, const std::string& what);
// Progress for long runs: a live counter on a terminal; when stderr is not a terminal, a line at
// every tenth of the work (and at least every `seconds`), with the elapsed time.
std::function<void(int, int)> periodic_progress(const GlobalOptions& g, const std::string& what,
                                                double seconds = 30);
// `text` on standard output when `out` is empty, else written to the file `out` atomically
// (complete or not at all; InputError when its folder does not exist).
void emit(const GlobalOptions& g, const std::string& out, const std::string& text);
// The writer's rule for where outputs go (io/writer.h): the folder that holds `path` exists and
// is writable.
using io::require_output_folder;
// The check of every --out and --plot option, run while the command line is parsed (before any
// work): not empty, and require_output_folder.
CLI::Validator output_location();
// A number option's check: finite (NaN and infinities refused) and in [lo, hi].
CLI::Validator finite_range(double lo, double hi);
// A text option's check: not empty.
CLI::Validator non_empty();
// Writes out.files (all or nothing), then prints out.messages; returns exit status 0.
int write_output(const GlobalOptions& g, const io::Output& out);

}  // namespace fl::cli
