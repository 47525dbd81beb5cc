// Direct labels: the speed plot and the GPU-cost figure name every model beside its marker in a
// qualitative colour of its own, and no label covers another label or a marker, measured on the
// pixels each label paints (not on the placer's own boxes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>

#include "draw/drawing.h"
#include "draw/labels.h"
#include "draw/rendered_library_plot.h"
#include "draw/speed_plot.h"
#include "fresnel/registered_models.h"

namespace fl {
namespace {

using draw::Box;

// The box of the pixels `t` inks when set alone on white at the figure's size (PNG output).
Box ink_box(const draw::Text& t, int width, int height, const draw::LabelFont& font) {
  draw::Drawing d;
  d.width = width;
  d.height = height;
  d.add(t);
  const auto img = draw::rasterize(d, font);
  int x0 = width, y0 = height, x1 = -1, y1 = -1;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (const auto p = img.at(x, y); p.r < 250 || p.g < 250 || p.b < 250)
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  return {double(x0), double(y0), double(x1 - x0 + 1), double(y1 - y0 + 1)};
}

struct Measured {
  std::vector<std::pair<std::string, Box>> labels;
  std::vector<Box> markers;
};

// The ink boxes of the texts named in `names` and the boxes of every marker (circle).
Measured measure(const draw::Drawing& d, const std::set<std::string>& names,
                 const draw::LabelFont& font) {
  Measured m;
  for (const auto& shape : d.shapes) {
    if (const auto* t = std::get_if<draw::Text>(&shape); t && names.count(t->utf8))
      m.labels.emplace_back(t->utf8, ink_box(*t, d.width, d.height, font));
    if (const auto* c = std::get_if<draw::Circle>(&shape))
      m.markers.push_back(
          {c->cx - c->radius_px, c->cy - c->radius_px, 2 * c->radius_px, 2 * c->radius_px});
  }
  return m;
}

void expect_no_overlap(const Measured& m) {
  for (size_t i = 0; i < m.labels.size(); ++i) {
    for (size_t j = i + 1; j < m.labels.size(); ++j)
      EXPECT_FALSE(m.labels[i].second.overlaps(m.labels[j].second))
          << m.labels[i].first << " covers " << m.labels[j].first;
    for (const auto& b : m.markers)
      EXPECT_FALSE(m.labels[i].second.overlaps(b))
          << m.labels[i].first << " covers a marker at " << b.x << ", " << b.y;
  }
}

// Ten models crowded within a factor 1.5 in cost and error: every one named once, no overlap.
TEST(DirectLabels, SpeedPlotNamesEveryModelWithoutOverlap) {
  const draw::LabelFont font;
  std::vector<analysis::SpeedRow> rows;
  std::set<std::string> names;
  for (const auto& s : fresnel::model_specs()) {
    const double k = s.model.index();
    rows.push_back({s.model, false, 1.0 + 0.05 * k, 1.0 + 0.04 * k, 2.0, false});
    rows.push_back({s.model, true, 1.0 + 0.05 * k, 0.8 + 0.03 * k, 2.0, k == 0});
    names.insert(s.name);
  }
  const auto m = measure(draw::speed_plot(rows, font), names, font);
  EXPECT_EQ(m.labels.size(), names.size());
  EXPECT_EQ(m.markers.size(), rows.size() + 2);  // and the legend's fitted and derived markers
  expect_no_overlap(m);
}

// The GPU-cost panels (metals, dielectrics): f82, "f82 rendered" and basis3 at the same cost and
// nearly the same error (as in the report) are each named, apart, once in each class's panel.
TEST(DirectLabels, GpuCostFigureNamesEveryShaderWithoutOverlap) {
  const draw::LabelFont font;
  std::vector<analysis::RenderedLibraryRow> rows;
  std::set<std::string> names;
  const auto& shaders = analysis::library_shaders();
  for (size_t k = 0; k < shaders.size(); ++k) {
    const int cost =
        shaders[k].name.rfind("f82", 0) == 0 || shaders[k].name == "basis3" ? 9 : 4 + 3 * int(k);
    for (const char* cls : {"metal", "dielectric", "all"})
      for (const auto l : {analysis::Lighting::Ibl, analysis::Lighting::Area}) {
        analysis::RenderedLibraryRow r;
        r.shader = &shaders[k];
        r.lighting = l;
        r.page_class = cls;
        r.gpu = analysis::GpuCost{fresnel::model_specs()[0].model, l, cost, cost, 0, 1};
        r.median = 0.3 + 0.01 * double(k) + (l == analysis::Lighting::Area ? 0.05 : 0);
        rows.push_back(r);
      }
    names.insert(shaders[k].name);
  }
  const auto m = measure(draw::rendered_library_plot(rows, font), names, font);
  EXPECT_EQ(m.labels.size(), 2 * names.size());  // the rows over every page are not drawn
  expect_no_overlap(m);
}

// The palette: ten colours, no two within 60 (of 441) of each other in RGB codes, and none too pale
// to read as text once darkened for a label (Rec.709 luma of the codes at most 160 of 255).
TEST(DirectLabels, QualitativePaletteIsDistinct) {
  for (size_t i = 0; i < draw::kQualitativeColours; ++i) {
    const auto a = draw::qualitative_colour(i);
    const auto ink = draw::label_ink(a);
    EXPECT_LE(0.2126 * ink.r + 0.7152 * ink.g + 0.0722 * ink.b, 160) << i;
    for (size_t j = i + 1; j < draw::kQualitativeColours; ++j) {
      const auto b = draw::qualitative_colour(j);
      const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
      EXPECT_GT(std::sqrt(dr * dr + dg * dg + db * db), 60) << i << ", " << j;
    }
  }
  // An eleventh series (a model added to the registry) repeats the first colour, named by its
  // label.
  const auto first = draw::qualitative_colour(0),
             eleventh = draw::qualitative_colour(draw::kQualitativeColours);
  EXPECT_EQ(first.r, eleventh.r);
  EXPECT_EQ(first.g, eleventh.g);
  EXPECT_EQ(first.b, eleventh.b);
}

}  // namespace
}  // namespace fl
