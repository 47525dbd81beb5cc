#pragma once
// The command line: a table of subcommands, each returning an exit code.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>

#include "analysis/pipeline/context.h"
#include "analysis/tables/media_tables.h"
#include "report/writer.h"

namespace fl::cli {

struct GlobalOptions {
  analysis::Settings settings;
  bool quiet = false;  // no progress or warnings on stderr
  analysis::BlendOptions blend;  // `table blend` options
};

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
// MATERIAL (a catalog name, database page or file) loaded, its warnings printed.
analysis::LoadedMaterial load_one(const GlobalOptions& g, const analysis::Context& ctx, const std::string& material);
// Study progress "<what>done/total materials": a live counter on a terminal, one line when stderr
// is a log, nothing with --quiet.
std::function<void(int, int)> study_progress(const GlobalOptions& g, const std::string& what);
// Writes out.files (all or nothing), then prints out.messages; returns exit status 0.
int write_output(const GlobalOptions& g, const report::Output& out);

}  // namespace fl::cli
