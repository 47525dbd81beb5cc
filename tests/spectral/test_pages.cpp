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
    for (const char* page : {"main/Au/nk/Johnson", "main/Au/nk/Babar", "main/Ag/nk/Johnson", "main/Au2O3/nk/X",
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
  const std::vector<std::string> all{"main/Ag/nk/Johnson", "main/Au/nk/Babar", "main/Au/nk/Johnson", "main/Au2O3/nk/X",
                                     "other/alloys/Cu-Zn/nk/Querry-Cu70Zn30", "other/alloys/Cu-Zn/nk/Querry-Cu90Zn10"};
  EXPECT_EQ(list_pages(db_.path()), all);
  EXPECT_EQ(list_pages(db_.path(), "main/Au"), (std::vector<std::string>{"main/Au/nk/Babar", "main/Au/nk/Johnson"}));
  EXPECT_TRUE(list_pages(db_.path(), "main/Pt").empty());
}

TEST_F(PageGlobs, EachGlobNamesTheSamePagesAsOverTheWholeListing) {
  EXPECT_EQ(expand({"main/Au/**"}), (std::vector<std::string>{"main/Au/nk/Babar", "main/Au/nk/Johnson"}));
  EXPECT_EQ(expand({"main/Au*/nk/*"}),
            (std::vector<std::string>{"main/Au/nk/Babar", "main/Au/nk/Johnson", "main/Au2O3/nk/X"}));
  EXPECT_EQ(expand({"other/alloys/Cu-Zn/**-Cu70Zn30", "main/A?/nk/Johnson", "gold"}),
            (std::vector<std::string>{"other/alloys/Cu-Zn/nk/Querry-Cu70Zn30", "main/Ag/nk/Johnson", "main/Au/nk/Johnson",
                                      "gold"}));
  EXPECT_EQ(expand({"*/Ag/**"}), (std::vector<std::string>{"main/Ag/nk/Johnson"}));
  EXPECT_EQ(expand({"**"}).size(), 6u);
  EXPECT_THROW(expand({"../**"}), InputError);
  EXPECT_THROW(expand({"main/Pt/**"}), InputError);
}

}  // namespace
}  // namespace fl::spectral
