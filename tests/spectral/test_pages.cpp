// Page globs over a small database tree written here: which pages each glob names, and the folder
// a glob's listing can be limited to.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "spectral/material.h"
#include "spectral/pages.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

std::vector<std::string> specs_of(const std::vector<MaterialRequest>& requests) {
  std::vector<std::string> out;
  for (const auto& r : requests) out.push_back(r.spec);
  return out;
}

class PageGlobs : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* page :
         {"main/Au/nk/Johnson", "main/Au/nk/Babar", "main/Ag/nk/Johnson", "main/Au2O3/nk/X",
          "other/alloys/Cu-Zn/nk/Querry-Cu70Zn30", "other/alloys/Cu-Zn/nk/Querry-Cu90Zn10"})
      db_.file(std::string("data/") + page + ".yml", "DATA:\n");
    db_.file("data/main/Au/about.yml", "");
    db_.file("catalog-nk.yml", "");  // beside data/: never a page
  }
  std::vector<std::string> expand(const std::vector<std::string>& specs) const {
    return specs_of(expand_materials(specs, DataPaths{db_.path(), ""}));
  }
  test::TempDir db_;
};

TEST_F(PageGlobs, FolderIsTheSegmentsBeforeTheFirstWildcard) {
  EXPECT_EQ(glob_folder("main/Au/**"), "main/Au");
  EXPECT_EQ(glob_folder("main/Au*/nk/*"), "main");
  EXPECT_EQ(glob_folder("other/alloys/Cu-Zn/**-Cu70Zn30"), "other/alloys/Cu-Zn");
  EXPECT_EQ(glob_folder("main/?u/nk/*"), "main");
  EXPECT_EQ(glob_folder("**"), "");
  EXPECT_EQ(glob_folder("*/Au/nk/Johnson"), "");
  EXPECT_EQ(glob_folder("../data/main/**"), "");
  EXPECT_EQ(glob_folder("main/../../**"), "");
}

TEST_F(PageGlobs, ListingUnderAFolderHoldsItsPagesOnly) {
  const std::vector<std::string> all{"main/Ag/nk/Johnson",
                                     "main/Au/nk/Babar",
                                     "main/Au/nk/Johnson",
                                     "main/Au2O3/nk/X",
                                     "other/alloys/Cu-Zn/nk/Querry-Cu70Zn30",
                                     "other/alloys/Cu-Zn/nk/Querry-Cu90Zn10"};
  EXPECT_EQ(list_pages(db_.path()), all);
  EXPECT_EQ(list_pages(db_.path(), "main/Au"),
            (std::vector<std::string>{"main/Au/nk/Babar", "main/Au/nk/Johnson"}));
  EXPECT_TRUE(list_pages(db_.path(), "main/Pt").empty());
}

TEST_F(PageGlobs, EachGlobNamesTheSamePagesAsOverTheWholeListing) {
  EXPECT_EQ(expand({"main/Au/**"}),
            (std::vector<std::string>{"main/Au/nk/Babar", "main/Au/nk/Johnson"}));
  EXPECT_EQ(
      expand({"main/Au*/nk/*"}),
      (std::vector<std::string>{"main/Au/nk/Babar", "main/Au/nk/Johnson", "main/Au2O3/nk/X"}));
  EXPECT_EQ(expand({"other/alloys/Cu-Zn/**-Cu70Zn30", "main/A?/nk/Johnson", "gold"}),
            (std::vector<std::string>{"other/alloys/Cu-Zn/nk/Querry-Cu70Zn30", "main/Ag/nk/Johnson",
                                      "main/Au/nk/Johnson", "gold"}));
  EXPECT_EQ(expand({"*/Ag/**"}), (std::vector<std::string>{"main/Ag/nk/Johnson"}));
  EXPECT_EQ(expand({"**"}).size(), 6u);
  EXPECT_THROW(expand({"../**"}), InputError);
  EXPECT_THROW(expand({"main/Pt/**"}), InputError);
}

// The catalog's entries from a small catalog-nk.yml in the database's layout: shelves of books,
// dividers naming the section of the pages below them, pages whose data is not a .yml file, and
// the YAML forms the real catalog uses (quoted and plain scalars, UTF-8, an empty value).
TEST(PageCatalog, EntriesFromShelvesBooksAndDividers) {
  test::TempDir db;
  db.file("catalog-nk.yml",
          "# comment\n"
          "- DIVIDER: \"Research data\"\n"
          "- SHELF: main\n"
          "  name: \"MAIN - simple inorganic materials\"\n"
          "  content:\n"
          "    - DIVIDER: \"Au - Gold\"\n"
          "    - BOOK: Au\n"
          "      name: \"Au (Gold)\"\n"
          "      content:\n"
          "        - PAGE: Olmon\n"
          "          name: \"Olmon et al. 2012: n,k 0.3\u20132 \u00b5m\"\n"
          "          data: main/Au/nk/Olmon.yml\n"
          "        - DIVIDER: \"Experimental data: thin film\"\n"
          "        - PAGE: Yakubovsky\n"
          "          name: Yakubovsky et al. 2017\n"
          "          data: main/Au/nk/Yakubovsky.yml\n"
          "        - PAGE: NoData\n"
          "          name: no data file\n"
          "          data:\n"
          "        - PAGE: Csv\n"
          "          name: not a page\n"
          "          data: main/Au/nk/table.csv\n"
          "    - BOOK: Ag\n"
          "      name: \"Ag (Silver)\"\n"
          "      content:\n"
          "        - PAGE: Johnson\n"
          "          name: 'Johnson and Christy 1972'\n"
          "          data: main/Ag/nk/Johnson.yml\n"
          "- SHELF: other\n"
          "  content:\n"
          "    - BOOK: Cu-Zn\n"
          "      content:\n"
          "        - DIVIDER: Brass\n"
          "        - PAGE: Querry\n"
          "          data: other/alloys/Cu-Zn/nk/Querry-Cu70Zn30.yml\n");
  const auto catalog = read_page_catalog(db.path());
  ASSERT_EQ(catalog.size(), 4u);
  const auto& olmon = catalog.at("main/Au/nk/Olmon");
  EXPECT_EQ(olmon.book, "Au");
  EXPECT_EQ(olmon.book_name, "Au (Gold)");
  EXPECT_EQ(olmon.page_name, "Olmon et al. 2012: n,k 0.3\u20132 \u00b5m");
  EXPECT_EQ(olmon.section, "");
  EXPECT_TRUE(is_bulk_measurement(&olmon));
  const auto& yak = catalog.at("main/Au/nk/Yakubovsky");
  EXPECT_EQ(yak.page_name, "Yakubovsky et al. 2017");
  EXPECT_EQ(yak.section, "Experimental data: thin film");
  EXPECT_FALSE(is_bulk_measurement(&yak));
  EXPECT_EQ(catalog.at("main/Ag/nk/Johnson").book_name, "Ag (Silver)");
  EXPECT_EQ(catalog.at("main/Ag/nk/Johnson").section, "");  // a divider holds within its book only
  const auto& brass = catalog.at("other/alloys/Cu-Zn/nk/Querry-Cu70Zn30");
  EXPECT_EQ(brass.book, "Cu-Zn");
  EXPECT_EQ(brass.book_name, "");
  EXPECT_EQ(brass.section, "Brass");
}

// A database without catalog-nk.yml names nothing; a broken one is an error naming the file and
// the line, from read_page_catalog and from every use of a PageCatalog.
TEST(PageCatalog, MissingCatalogIsEmptyBrokenCatalogIsAnError) {
  test::TempDir db;
  EXPECT_TRUE(read_page_catalog(db.path()).empty());
  EXPECT_EQ(PageCatalog(db.path()).find("main/Au/nk/Johnson"), nullptr);
  db.file("catalog-nk.yml", "- SHELF: main\n  content: [\n    - BOOK: Au\n");
  const std::string file = db.path() + "/catalog-nk.yml:";
  try {
    read_page_catalog(db.path());
    ADD_FAILURE() << "a broken catalog was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file, 0), 0u) << e.what();
  }
  const PageCatalog catalog(db.path());
  EXPECT_THROW(catalog.find("main/Au/nk/Johnson"), InputError);
  EXPECT_THROW(catalog.entries(), InputError);  // not swallowed on a second use either
}

}  // namespace
}  // namespace fl::spectral

namespace fl::spectral {
namespace {

// Page kinds from a hand-written catalog in the database's layout: each rule of classify_page once,
// with the pages of the real catalog's patterns (sections, thicknesses, temperatures, DFT).
TEST(PageKinds, EachRuleFromSectionAndPageName) {
  test::TempDir db;
  db.file("catalog-nk.yml",
          "- SHELF: main\n"
          "  content:\n"
          "    - BOOK: Au\n"
          "      name: \"Au (Gold)\"\n"
          "      content:\n"
          "        - DIVIDER: \"Experimental data: bulk, thick film\"\n"
          "        - PAGE: J\n"
          "          name: \"Johnson and Christy 1972: n,k 0.2066\u20131.937 \u00b5m\"\n"
          "          data: main/Au/nk/J.yml\n"
          "        - PAGE: M25\n"
          "          name: \"Magnozzi et al. 2019: n,k 0.252\u20131.45 \u00b5m; 25 \u00b0C\"\n"
          "          data: main/Au/nk/M25.yml\n"
          "        - PAGE: M225\n"
          "          name: \"Magnozzi et al. 2019: n,k 0.252\u20131.45 \u00b5m; 225 \u00b0C\"\n"
          "          data: main/Au/nk/M225.yml\n"
          "        - PAGE: F404\n"
          "          name: \"Ferrera et al. 2019: n,k 0.245\u20131.45 \u00b5m; 404 K\"\n"
          "          data: main/Au/nk/F404.yml\n"
          "        - PAGE: P\n"
          "          name: \"Someone 2001: n 0.4\u20130.7 \u00b5m; 3.2 GPa\"\n"
          "          data: main/Au/nk/P.yml\n"
          "        - DIVIDER: \"Experimental data: thin film\"\n"
          "        - PAGE: Y\n"
          "          name: \"Yakubovsky et al. 2017: 25-nm film; n,k 0.30\u20132.0 \u00b5m\"\n"
          "          data: main/Au/nk/Y.yml\n"
          "        - DIVIDER: \"Experimental data: nanoparticles\"\n"
          "        - PAGE: K\n"
          "          name: \"Klinavi\u010dius 2025: R=7.2 nm; n,k 0.4\u20130.9 \u00b5m\"\n"
          "          data: main/Au/nk/K.yml\n"
          "        - DIVIDER: \"Models and simulations\"\n"
          "        - PAGE: BB\n"
          "          name: \"Raki\u0107 et al. 1998: Brendel-Bormann model; n,k 0.248\u20136.20 "
          "\u00b5m\"\n"
          "          data: main/Au/nk/BB.yml\n"
          "        - PAGE: DFT\n"
          "          name: \"Werner et al. 2009: DFT calculations; n,k 0.0176\u20132.48 \u00b5m\"\n"
          "          data: main/Au/nk/DFT.yml\n"
          "    - BOOK: Cr\n"
          "      content:\n"
          "        - DIVIDER: \"Experimental data\"\n"
          "        - PAGE: S\n"
          "          name: \"Sytchkova et al. 2021: 12 nm film; n,k 0.262\u20132.50 \u00b5m\"\n"
          "          data: main/Cr/nk/S.yml\n"
          "        - PAGE: Flakes\n"
          "          name: \"Someone 2020: islands on glass\"\n"
          "          data: main/Cr/nk/I.yml\n");
  const auto catalog = read_page_catalog(db.path());
  const auto kind = [&](const std::string& page) { return classify_page(&catalog.at(page)); };
  const auto j = kind("main/Au/nk/J");
  EXPECT_EQ(j.kind, PageKind::Bulk);
  EXPECT_EQ(j.year, 1972);  // not 2066 from "0.2066"
  EXPECT_EQ(j.detail, "");
  EXPECT_EQ(kind("main/Au/nk/M25").kind, PageKind::Bulk);  // room temperature
  EXPECT_EQ(kind("main/Au/nk/M25").detail, "25 \u00b0C");
  EXPECT_EQ(kind("main/Au/nk/M225").kind, PageKind::Variant);
  EXPECT_EQ(kind("main/Au/nk/F404").kind, PageKind::Variant);
  EXPECT_EQ(kind("main/Au/nk/F404").detail, "404 K");
  EXPECT_EQ(kind("main/Au/nk/P").kind, PageKind::Variant);
  EXPECT_EQ(kind("main/Au/nk/Y").kind, PageKind::ThinFilm);
  EXPECT_EQ(kind("main/Au/nk/Y").detail, "25 nm");
  EXPECT_EQ(kind("main/Au/nk/K").kind, PageKind::Nanostructure);
  EXPECT_EQ(kind("main/Au/nk/K").detail, "R=7.2 nm");
  EXPECT_EQ(kind("main/Au/nk/BB").kind, PageKind::Model);
  EXPECT_EQ(kind("main/Au/nk/DFT").kind, PageKind::Computed);  // listed under models: DFT first
  // A film's thickness in the page name makes it a thin film whatever its section says.
  EXPECT_EQ(kind("main/Cr/nk/S").kind, PageKind::ThinFilm);
  EXPECT_EQ(kind("main/Cr/nk/S").detail, "12 nm");
  EXPECT_EQ(kind("main/Cr/nk/I").kind, PageKind::Nanostructure);
  EXPECT_EQ(classify_page(nullptr).kind, PageKind::Unlisted);
  EXPECT_FALSE(is_bulk_measurement(nullptr));
  EXPECT_TRUE(is_bulk_measurement(&catalog.at("main/Au/nk/M25")));
  EXPECT_FALSE(is_bulk_measurement(&catalog.at("main/Au/nk/F404")));
  EXPECT_STREQ(to_string(PageKind::ThinFilm), "thin film");
}

}  // namespace
}  // namespace fl::spectral
