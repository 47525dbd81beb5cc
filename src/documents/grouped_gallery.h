#pragma once
// A gallery too large to load at once (a library of every database page): cards grouped by
// element under a heading each, the first groups in the page and every other group's cards in a
// script beside it (GROUPS/NNN.js), loaded when its place nears the screen or a search matches
// it. The page holds a search index of every card (id, group, gallery_search_text), so the search
// counts and finds cards that have not been loaded yet.
#include <string>
#include <utility>
#include <vector>

#include "documents/html.h"

namespace fl::documents {

struct GroupedGallery {
  std::string html;    // the gallery section's content, for HtmlReport::gallery_fragment
  std::string script;  // for HtmlReport::gallery_script
  std::vector<std::pair<std::string, std::string>> files;  // (path beside the page, bytes)
};

// Groups in order of first appearance in `entries` (each entry's `group`); groups are set in the
// page until at least `eager_cards` cards are, the others in `folder`/NNN.js (NNN from 001).
GroupedGallery grouped_gallery(const std::vector<GalleryEntry>& entries, size_t eager_cards,
                               const std::string& folder);

}  // namespace fl::documents
