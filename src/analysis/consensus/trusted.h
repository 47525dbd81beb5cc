#pragma once
// Short names ("gold", "Ti") resolve to the element's trusted value: the consensus of its bulk
// pages where enough of them agree, else the recommended page; a page named on its own is checked
// against its element's consensus (docs/consensus.md, "Short names").
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/consensus/consensus.h"

namespace fl::analysis {

// The consensus is trusted when at least kTrustedMinPages bulk pages make it and their median F0
// and F82 distances from it are within kTrustedMaxMedianDe00 (the outlier rule's floor: a
// difference one sees side by side).
inline constexpr int kTrustedMinPages = 3;
inline constexpr double kTrustedMaxMedianDe00 = kOutlierMinDe00;

// What a short name stands for: a book of the main shelf ("main/Au"), and when the name is a
// catalog entry its key, display name and page (the talk's).
struct ShortName {
  std::string book, key, name, catalog_page;
};
// A catalog name of a metal whose data is a page of the main shelf, or an element's symbol or
// common name in the database's catalog; nullopt for a page, a glob, a file, anything else.
std::optional<ShortName> short_name(const spectral::DataPaths& paths, const std::string& spec);

struct TrustedMaterial {
  LoadedMaterial material;  // the consensus or the recommended page, named as the short name
  bool consensus = false;
  double catalog_f0_de00 = NAN, catalog_f82_de00 = NAN;  // the catalog page from the consensus
  std::string reason;                                    // which and why (also material.resolved)
};
// InputError when the book has no consensus (no bulk metal page covering the visible range).
TrustedMaterial trusted_material(const Context& ctx, const std::string& spec, const ShortName& s,
                                 const std::function<void(int, int)>& progress = {});

// "warning: …" when `page` (main/X/…) is an outlier of its book's consensus, with its distances;
// empty otherwise (not an outlier, no consensus, not a page of the main shelf).
std::string outlier_warning(const Context& ctx, const std::string& page);

// `specs` as `presets` reads them: short names through trusted_material, every other argument
// through `load` (consecutive ones together), in argument order; `notes` say what each short name
// became and warn of named outlier pages. No specs: load({}) (the catalog, the talk's pages).
struct NamedMaterials {
  std::vector<LoadedMaterial> materials;
  std::vector<std::string> notes;
};
using Loader = std::function<std::vector<LoadedMaterial>(const std::vector<std::string>&)>;
NamedMaterials named_materials(const Context& ctx, const std::vector<std::string>& specs,
                               const Loader& load);

}  // namespace fl::analysis
