// The preset-format registry is the one list: every entry is reachable by its --format name, and
// `library` writes every entry, each readable as its kind (a table with one row per page, a
// MaterialX document with one material per page, glTF 2.0 JSON with one material per page), each
// linked from the library's README and HTML page. A format added to the registry is checked here
// without a new test (a new kind fails until it has its own check).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "csv_reader.h"
#include "documents/preset_formats.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::documents {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PresetRegistry, EveryEntryIsSelectedByItsName) {
  for (const auto& f : preset_formats()) {
    const std::string shader = f.kind == PresetKind::MaterialX ? to_string(f.shader) : "";
    EXPECT_EQ(&preset_format(f.name, false, shader), &f) << f.name << f.suffix;
    if (f.alias) EXPECT_EQ(preset_format_name(f.alias), f.name);
  }
  EXPECT_THROW(preset_format_name("usdz"), InputError);
}

// Two gold pages (main/Au/nk/Johnson and main/Au/nk/Jiang...): what `library` writes per format.
TEST(PresetRegistry, LibraryWritesEveryFormatReadableAndLinked) {
  test::TempDir tmp;
  const std::string out = tmp.path() + "/lib";
  const auto r = test::run_command(test::cli() +
                                   " -q library 'main/Au/nk/J*' --no-gallery --out '" + out + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string readme = test::read_text_file(out + "/README.md"),
                    index = test::read_text_file(out + "/index.html");
  const auto table = test::csv_records(test::read_text_file(out + "/library.csv"));
  const int pages = static_cast<int>(table.size());
  ASSERT_GE(pages, 2);
  for (const auto& f : preset_file_names("library")) {
    SCOPED_TRACE(f.path);
    const std::string text = test::read_text_file(out + "/" + f.path);
    ASSERT_FALSE(text.empty());
    EXPECT_NE(readme.find("[" + f.path + "](" + f.path + ")"), std::string::npos);
    EXPECT_NE(index.find("href=\"" + f.path + "\""), std::string::npos);
  }
  for (const auto& f : preset_formats()) {
    const std::string path = out + "/library" + f.suffix + "." + f.extension;
    const std::string text = test::read_text_file(path);
    SCOPED_TRACE(path);
    switch (f.kind) {
      case PresetKind::Table:
        if (f.table_format == Format::Csv) EXPECT_EQ(test::csv_records(text).size(), table.size());
        if (f.table_format == Format::Json)
          EXPECT_EQ(nlohmann::json::parse(text)["rows"].size(), table.size());
        if (f.table_format == Format::Markdown) EXPECT_GE(count(text, "\n| "), pages + 1);
        break;
      case PresetKind::MaterialX:
        EXPECT_EQ(count(text, "<materialx"), 1);
        EXPECT_EQ(count(text, "<surfacematerial"), pages);
        break;
      case PresetKind::Gltf:
        EXPECT_EQ(nlohmann::json::parse(text)["materials"].size(), static_cast<size_t>(pages));
        break;
    }
  }
}

}  // namespace
}  // namespace fl::documents
