#pragma once
// The database as a preset library: every page matching some globs (by default every conductor page
// covering the visible range) with every model's derived and fitted parameters, errors and quality
// flags; and the list of the database's pages.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/consensus/consensus.h"
#include "analysis/pipeline/materials.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// `pages [GLOB...]`: every page matched (default '**'), with its book, the database catalog's book
// name and section, class (from the data), coverage of n and k, reference, and status ("ok" or
// why it cannot be read).
Table pages_table(const Context& ctx, const std::vector<std::string>& globs,
                  const std::function<void(int, int)>& progress = {});

// A library covers "a visible range": at least this share (Coverage::both), by default.

// The library's curve fits stop once a step lowers ½ Σ ΔE2000² by less than this share of it
// (StudyOptions::fit_tolerance; reproduce keeps fit::FitOptions' 1e-10, whose fits start the
// rendered fits). Over every database page covering the visible range (2,812) and every model,
// each fit's RMS ΔE2000 ends within 1e-5 of the same fit run to 1e-13 (kLibraryFitRmsBound, held
// by a test on the slowest pages): the printed errors (3 decimals) do not move, and the library
// takes an eighth less time. At 1e-7 two fits (liquid methane, Cook–Torrance) end 0.009 short.
inline constexpr double kLibraryFitTolerance = 1e-8;
inline constexpr double kLibraryFitRmsBound = 5e-5;

struct LibraryOptions {
  std::vector<std::string> globs{"**"};
  std::optional<spectral::MaterialClass> only = spectral::MaterialClass::Metal;
  double min_coverage = kDefaultMinCoverage;
  bool strict = false;  // a page that cannot be read is an error instead of a skip
};

struct Library {
  MaterialSet set;         // the pages in the library and the skipped ones with their reasons
  ConsensusSet consensus;  // per group of metal pages with a bulk measurement (every model)
  // The library's rows: the pages' studies (every model), each group's consensus just before its
  // first page. The consensus's page distances point here, so a library moves, never copies.
  std::vector<MaterialStudy> rows;

  Library() = default;
  Library(const Library&) = delete;
  Library& operator=(const Library&) = delete;
  Library(Library&&) = default;
  Library& operator=(Library&&) = default;
};

// Loads the pages and studies them (every model, derived and fitted). `load_progress` and
// `fit_progress` get (done, total).
Library build_library(const Context& ctx, const LibraryOptions& options,
                      const std::function<void(int, int)>& load_progress = {},
                      const std::function<void(int, int)>& fit_progress = {});

// One row per page: the presets table's columns, then the page's book and catalog section, what
// the data does not cover, every model's derived and fitted RMS ΔE2000, the quality flags
// (extrapolated, each model's fit flags, values out of range) and the reader's warning count.
// With `consensus`, each page's kind, distance from its group's consensus and outlier flag, and
// for a consensus row its uncertainty (the spread of its pages).
Table library_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                    const ConsensusSet* consensus = nullptr);

// The skipped pages with their reasons, and their count by reason (the reason with the file, line
// and numbers taken out).
Table skipped_table(const std::vector<SkippedMaterial>& skipped);
Table skip_reasons_table(const std::vector<SkippedMaterial>& skipped);
// A reason without its "FILE:LINE: " prefix and with every number written as N.
std::string reason_class(const std::string& reason);

}  // namespace fl::analysis
