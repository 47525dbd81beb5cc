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

struct LibraryOptions {
  std::vector<std::string> globs{"**"};
  std::optional<spectral::MaterialClass> only = spectral::MaterialClass::Metal;
  double min_coverage = kDefaultMinCoverage;
  bool strict = false;  // a page that cannot be read is an error instead of a skip
};

struct Library {
  MaterialSet set;  // the pages in the library and the skipped ones with their reasons
  std::vector<MaterialStudy> studies;
  ConsensusSet consensus;  // per group of metal pages with a bulk measurement (every model)
  // The library's rows: the pages, each group's consensus just before its first page.
  std::vector<MaterialStudy> rows;
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
