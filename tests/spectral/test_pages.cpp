// Page globs over a small database tree written here: which pages each glob names, and the folder
// a glob's listing can be limited to.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "spectral/errors.h"
#include "spectral/material.h"
#include "spectral/pages.h"
#include "test_util.h"

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

TEST(PageCatalog, MissingOrBrokenCatalogIsEmpty) {
  test::TempDir db;
  EXPECT_TRUE(read_page_catalog(db.path()).empty());
  db.file("catalog-nk.yml", "- SHELF: main\n  content: [\n    - BOOK: Au\n");
  EXPECT_TRUE(read_page_catalog(db.path()).empty());
}

}  // namespace
}  // namespace fl::spectral
