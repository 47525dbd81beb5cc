// A CSV table written in parts (to_csv, then to_csv_rows for the rest, as `library` writes its
// models table) reads back as the table written whole: one header, every row once, in order, with
// the CSV's quoting.
#include <gtest/gtest.h>

#include "csv_reader.h"
#include "documents/table_formats.h"

namespace fl {
namespace {

Table table_of(std::vector<std::vector<Cell>> rows) {
  Table t;
  t.name = "parts";
  t.columns = {{"name"}, {"value", 3}, {"count", 0}, {"hidden", 2, false}};
  t.rows = std::move(rows);
  return t;
}

TEST(TableCsv, PartsReadBackAsTheWholeTable) {
  const std::vector<std::vector<Cell>> rows{{std::string("a, quoted \"one\""), 0.12345, 3LL, 9.0},
                                            {std::string("b"), -0.0001, 4LL, 8.0},
                                            {std::string("c"), 2.5, 5LL, 7.0}};
  const std::string parts =
      documents::to_csv(table_of({rows[0]})) + documents::to_csv_rows(table_of({rows[1], rows[2]}));
  const auto records = test::csv_records(parts);
  ASSERT_EQ(records.size(), 3u);
  EXPECT_EQ(records[0].at("name"), "a, quoted \"one\"");
  EXPECT_EQ(records[0].at("value"), "0.123");
  EXPECT_EQ(records[1].at("value"), "0.000");  // -0.000 is printed as 0.000
  EXPECT_EQ(records[2].at("name"), "c");
  EXPECT_EQ(records[2].at("count"), "5");
  EXPECT_EQ(records[2].count("hidden"), 0u);  // Markdown and JSON only
  EXPECT_EQ(documents::to_csv_rows(table_of({})), "");
}

}  // namespace
}  // namespace fl
