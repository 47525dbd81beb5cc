// The report's summary lines read their values from the tables they are given.
#include <gtest/gtest.h>

#include "jobs/report_summary.h"

namespace fl::jobs {
namespace {

Table table(std::string name, std::vector<std::string> columns,
            std::vector<std::vector<Cell>> rows) {
  Table t;
  t.name = std::move(name);
  for (auto& c : columns) t.columns.push_back({std::move(c)});
  t.rows = std::move(rows);
  return t;
}

TEST(ReportSummary, CountsTheTalksMissesAndNamesThem) {
  const auto lines =
      report_summary({table("talk_spread", {"material", "ours", "talk", "misses"},
                            {{std::string("Silver"), 0.281, 0.270, std::string("no")},
                             {std::string("Gold"), 0.812, 0.690, std::string("yes")}})});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("1 of 2 metals"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("Gold (ours 0.812, the talk's 0.690)"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[0].find("Silver"), std::string::npos) << lines[0];
}

TEST(ReportSummary, BestRenderedModelIsTheLowestClassMean) {
  // metal: a averages (1 + 3) / 2 = 2, b averages (2.5 + 2.5) / 2 = 2.5; dielectric: only b.
  const auto lines = report_summary(
      {table("lut-accuracy", {"class", "model", "parameters", "ibl_rms_de00"},
             {{std::string("metal"), std::string("a"), std::string("fitted"), 1.0},
              {std::string("metal"), std::string("a"), std::string("fitted"), 3.0},
              {std::string("metal"), std::string("b"), std::string("fitted"), 2.5},
              {std::string("metal"), std::string("b"), std::string("fitted"), 2.5},
              {std::string("dielectric"), std::string("b"), std::string("rendered"), 0.5}})});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("dielectric: b (rendered) 0.500; metal: a (fitted) 2.000"),
            std::string::npos)
      << lines[0];
}

TEST(ReportSummary, ParetoFrontListsFlaggedModelsByCost) {
  const auto lines =
      report_summary({table("speed",
                            {"model", "parameters", "cpu_ns_per_eval", "gpu_instructions",
                             "median_rms_de00", "pareto_cpu", "pareto_gpu"},
                            {{std::string("slow"), std::string("fitted"), 70.0, 60LL, 0.004,
                              std::string("yes"), std::string("no")},
                             {std::string("fast"), std::string("fitted"), 0.5, 7LL, 1.3,
                              std::string("yes"), std::string("yes")},
                             {std::string("worse"), std::string("derived"), 1.0, 9LL, 2.0,
                              std::string("no"), std::string("no")}})});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("fast (fitted) 0.5 ns → 1.300, slow (fitted) 70 ns → 0.004."),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[1].find("fast (fitted) 7 instructions → 1.300."), std::string::npos) << lines[1];
  EXPECT_EQ(lines[0].find("worse"), std::string::npos);
}

}  // namespace
}  // namespace fl::jobs
