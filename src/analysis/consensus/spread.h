#pragma once
// How much measurements of the same material disagree: for every element or alloy with several
// database pages, the spread between its pages' F0 and F82 colours (ΔE2000) and Schlick errors.
#include <string>
#include <vector>

#include "analysis/pipeline/materials.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// The material a page measures: its book ("main/Au/nk/Johnson" → "main/Au"); on the alloys shelf
// (other/alloys/) the page name after its first '-' names the composition and joins the book
// ("other/alloys/Cu-Zn/nk/Querry-Cu70Zn30" → "other/alloys/Cu-Zn Cu70Zn30"). Empty for a path
// that is not a page.
std::string spread_group(const std::string& page);

// Pages and their studies (derived parameters only), loaded together so that the studies' pointers
// stay valid.
struct PageStudies {
  MaterialSet set;
  std::vector<MaterialStudy> studies;
};
// Loads and studies (no fits) the conductor pages of `globs` that cover the visible range
// (kSpreadMinCoverage); pages that cannot be read are skipped.
PageStudies study_pages(const Context& ctx, const std::vector<std::string>& globs,
                        const std::function<void(int, int)>& progress = {});
// The pages a spread uses cover at least this share of the visible range.
constexpr double kSpreadMinCoverage = 0.99;

// The group a studied material joins in a spread or a consensus: a database page of a metal
// covering kSpreadMinCoverage of the visible range; empty for any other material.
std::string spread_group_of(const LoadedMaterial& m);

// One row per group with at least two pages (conductor pages among `pages` covering at least
// kSpreadMinCoverage; the others are left out), for its bulk measurements and for all its pages:
// pairwise ΔE2000 between the pages' F0 colours and between their F82 colours (largest and median),
// the range of their Schlick RMS ΔE2000, and the pages at the ends.
Table spread_table(const Context& ctx, const std::vector<MaterialStudy>& pages);

// The page globs of the groups of the metals among `materials` that come from pages ("main/Au/**"),
// for spread_table over every page of their groups.
std::vector<std::string> group_globs(const std::vector<LoadedMaterial>& materials);

// Every catalog material whose Schlick RMS ΔE2000 misses the talk's value by more than
// kTalkMissTolerance, against the spread of its group's pages: whether the talk's value lies
// within the range the database's measurements give, and the page closest to it.
constexpr double kTalkMissTolerance = 0.10;
Table talk_misses_table(const Context& ctx, const std::vector<LoadedMaterial>& catalog,
                        const std::vector<MaterialStudy>& pages);

}  // namespace fl::analysis
