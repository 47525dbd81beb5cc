#pragma once
// The database's pages: listing, globs over their paths, and where each sits in the database's own
// catalog (catalog-nk.yml: book and page names).
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace fl::spectral {

// Every data file under DATABASE/data/ except the books' about.yml, as page paths relative to data/
// without ".yml" ("main/Au/nk/Johnson"), sorted. With `folder` ("main/Au"), only the pages under
// DATABASE/data/FOLDER/.
std::vector<std::string> list_pages(const std::string& database, const std::string& folder = "");

// A page path glob: `*` matches any run of characters within one path segment, `?` one character
// other than '/', `**` any run including '/' (so 'main/**' is every page of the main shelf and '**'
// every page). Everything else matches itself.
bool glob_match(std::string_view pattern, std::string_view path);
bool is_glob(std::string_view spec);  // contains '*' or '?'

// The pages matching `pattern`, sorted.
std::vector<std::string> match_pages(const std::vector<std::string>& pages,
                                     const std::string& pattern);
// The folder every match of `pattern` lies in: its segments before the first one holding a
// wildcard ("main/Au/**" → "main/Au", "**" → ""); empty for a folder outside data/ ("../x/*").
std::string glob_folder(std::string_view pattern);

// A page's place in the database's catalog.
struct PageEntry {
  std::string book;       // the book's folder name ("Au"); from the path when the catalog lacks it
  std::string book_name;  // "Au (Gold)" (empty when the catalog lacks the page)
  std::string page_name;  // "Johnson and Christy 1972: n,k 0.188–1.94 µm"
  std::string section;    // the catalog divider above the page ("Experimental data: thin film")
};
// catalog-nk.yml's entries by page path; empty when the database has no catalog-nk.yml (the
// catalog only names things: pages are listed from data/ either way). A catalog that cannot be
// read (a directory, empty, binary, invalid YAML) is an InputError naming the file and line.
std::map<std::string, PageEntry> read_page_catalog(const std::string& database);

// One database's catalog-nk.yml, read on first use and kept: owned by whoever runs a command (the
// analysis context), so nothing is cached for the process. Thread-safe. When reading fails, every
// use throws that InputError (the file is read again: nothing is swallowed).
class PageCatalog {
 public:
  explicit PageCatalog(std::string database) : database_(std::move(database)) {}
  PageCatalog(const PageCatalog&) = delete;
  PageCatalog& operator=(const PageCatalog&) = delete;

  const std::string& database() const { return database_; }
  // Every entry by page path.
  const std::map<std::string, PageEntry>& entries() const;
  // The entry for `page`; nullptr when the catalog lacks the page.
  const PageEntry* find(const std::string& page) const;

 private:
  std::string database_;
  mutable std::once_flag read_;
  mutable std::map<std::string, PageEntry> entries_;
};

// What a page holds, from its catalog section and page name (classify_page).
enum class PageKind {
  Bulk,           // a measurement of the bulk material (or a thick film), at room temperature
  ThinFilm,       // a film thin enough that its thickness is part of the result
  Nanostructure,  // nanoparticles, islands, flakes, 2D structures
  Model,          // a dispersion model fitted to measurements (Drude, Lorentz, Brendel-Bormann...)
  Computed,       // DFT or other computed (ab initio) data
  Variant,        // measured away from room temperature, or under pressure
  Unlisted        // not in the catalog
};
const char* to_string(PageKind kind);

struct PageClass {
  PageKind kind = PageKind::Unlisted;
  std::string detail;  // "12 nm" (film), "404 K" (temperature), "R=7.2 nm"; empty when none
  int year = 0;        // the first 19xx/20xx in the page name (0: none)
};
// The rule, first match wins, over the section and page name (case-insensitive):
// 1. no entry: Unlisted;
// 2. "dft", "ab initio", "first-principles", "calculation", "computed": Computed;
// 3. "model" or "simulation": Model;
// 4. "nanoparticle", "island", "flake", "2d structure": Nanostructure;
// 5. "thin film", or a page name holding a thickness ("25-nm film", "12 nm film"): ThinFilm;
// 6. a temperature outside 288-303 K (15-30 °C) or a pressure (GPa, MPa, kbar) in the page name:
//    Variant (a room-temperature page is Bulk, its temperature in `detail`);
// 7. otherwise Bulk (books without sections hold measurements).
PageClass classify_page(const PageEntry* entry);
// classify_page(entry).kind == PageKind::Bulk.
bool is_bulk_measurement(const PageEntry* entry);
// The book folder of a page path: the folder above the page's own ("main/Au/nk/Johnson" → "Au").
std::string book_of(const std::string& page);

}  // namespace fl::spectral
