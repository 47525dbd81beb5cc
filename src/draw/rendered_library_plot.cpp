#include "draw/rendered_library_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "draw/labels.h"
#include "draw/plot.h"

namespace fl::draw {
namespace {

using analysis::Lighting;
using analysis::RenderedLibraryRow;

constexpr int kWidth = 1520, kHeight = 560;
constexpr double kTop = 60, kPanelHeight = 380, kPanelWidth = 380;
constexpr double kLeftPanel = 80, kMetalsPanel = 580, kDielectricsPanel = 1080;
constexpr double kFloorDe = 5e-3, kCeilingDe = 20;  // the error axis: log10 of these ends
const io::Rgb8 kGrid{225, 225, 225}, kFrame{60, 60, 60};

// One colour per (class, lighting) on the left, per shader on the right.
struct Series {
  const char* page_class;
  Lighting lighting;
  io::Rgb8 colour;
  const char* label;
};
const Series kSeries[] = {{"metal", Lighting::Ibl, {200, 90, 0}, "metals, IBL"},
                          {"metal", Lighting::Area, {250, 170, 80}, "metals, area"},
                          {"dielectric", Lighting::Ibl, {20, 80, 170}, "dielectrics, IBL"},
                          {"dielectric", Lighting::Area, {110, 160, 230}, "dielectrics, area"}};

// Axes whose y is log10 of the error.
Axes panel(double left, double x_min, double x_max) {
  return {left,  kTop,  kPanelWidth,          kPanelHeight,
          x_min, x_max, std::log10(kFloorDe), std::log10(kCeilingDe)};
}

Point at(const Axes& a, double x, double de) {
  return a.map(x, std::log10(std::clamp(de, kFloorDe, kCeilingDe)));
}

void add_panel(Drawing& d, const Axes& a, const std::vector<double>& x_ticks,
               const std::string& title, const std::string& x_label) {
  for (double x : x_ticks) {
    const double px = pixel_centre(a.map(x, 0).x);
    d.add(hairline({px, a.top}, {px, a.top + a.height}, kGrid));
    d.add(Text{px, a.top + a.height + 18, fmt::format("{:g}", x), 12, kInk, Align::Center});
  }
  for (double e : {0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0}) {
    const double py = pixel_centre(at(a, 0, e).y);
    d.add(hairline({a.left, py}, {a.left + a.width, py}, kGrid));
    d.add(Text{a.left - 8, py + 4, fmt::format("{:g}", e), 12, kInk, Align::Right});
  }
  d.add(Polyline{{{a.left, a.top},
                  {a.left, a.top + a.height},
                  {a.left + a.width, a.top + a.height},
                  {a.left + a.width, a.top},
                  {a.left, a.top}},
                 kFrame,
                 1.0,
                 {}});
  d.add(Text{a.left + a.width / 2, a.top - 14, title, 14, kInk, Align::Center});
  d.add(Text{a.left + a.width / 2, a.top + a.height + 40, x_label, 13, kInk, Align::Center});
  d.add(Text{a.left - 50, a.top + a.height / 2, "page RMS ΔE2000 (log scale)", 13, kInk,
             Align::Center, true});
}

const RenderedLibraryRow* find(const std::vector<RenderedLibraryRow>& rows, const std::string& name,
                               Lighting l, const char* cls) {
  for (const auto& r : rows)
    if (r.shader->name == name && r.lighting == l && r.page_class == cls) return &r;
  return nullptr;
}

void add_against_k(Drawing& d, const std::vector<RenderedLibraryRow>& rows) {
  const Axes a = panel(kLeftPanel, 1.8, 5.2);
  add_panel(d, a, {2, 3, 4, 5}, "Basis projections against K", "K, table terms (basis2 … basis5)");
  double legend_y = a.top + a.height + 62;
  for (const auto& s : kSeries) {
    Polyline median{{}, s.colour, 2.0, {}}, p99{{}, s.colour, 1.5, {5, 4}};
    for (int k = 2; k <= 5; ++k)
      if (const auto* r = find(rows, fmt::format("basis{}", k), s.lighting, s.page_class)) {
        median.points.push_back(at(a, k, r->median));
        p99.points.push_back(at(a, k, r->p99));
        d.add(Circle{median.points.back().x, median.points.back().y, 3.5, s.colour, 0});
      }
    d.add(std::move(median));
    d.add(std::move(p99));
    const double lx = a.left + (&s - kSeries) % 2 * 190;
    if ((&s - kSeries) % 2 == 0 && &s != kSeries) legend_y += 20;
    d.add(Polyline{{{lx, legend_y - 4}, {lx + 24, legend_y - 4}}, s.colour, 2.0, {}});
    d.add(Text{lx + 30, legend_y, s.label, 12, kInk});
  }
  d.add(Text{a.left, legend_y + 20, "solid: median over the pages; dashed: p99", 12, kGreyInk});
}

// Every shader's IBL (filled) and area (hollow) marker over the pages of `cls` in its qualitative
// colour, named beside its IBL marker (its area marker when it has no IBL cost).
void add_cost_points(Drawing& d, const Axes& a, const std::vector<RenderedLibraryRow>& rows,
                     const char* cls, const LabelFont& font) {
  const auto& shaders = analysis::library_shaders();
  std::vector<Box> markers;
  std::vector<PointLabel> labels;
  std::vector<bool> named(shaders.size(), false);
  for (const bool ibl_pass : {true, false})
    for (const auto& r : rows) {
      if (r.page_class != cls || !r.gpu || (r.lighting == Lighting::Ibl) != ibl_pass) continue;
      const auto k = static_cast<size_t>(r.shader - shaders.data());
      const Point p = at(a, r.gpu->instructions, r.median);
      d.add(Circle{p.x, p.y, 6, qualitative_colour(k), ibl_pass ? 0.0 : 2.0});
      markers.push_back({p.x - 6, p.y - 6, 12, 12});
      if (!named[k]) labels.push_back({p, r.shader->name, qualitative_colour(k)});
      named[k] = true;
    }
  for (auto& shape :
       place_labels(labels, markers, {a.left + 2, a.top + 2, a.width - 4, a.height - 4}, 12, font))
    d.shapes.push_back(std::move(shape));
}

void add_against_cost(Drawing& d, const std::vector<RenderedLibraryRow>& rows, const char* cls,
                      double left, const std::string& title, const LabelFont& font) {
  const Axes a = panel(left, 0, 25);
  add_panel(d, a, {0, 5, 10, 15, 20, 25}, title, "SPIR-V instructions (bench/gpu_costs.csv)");
  add_cost_points(d, a, rows, cls, font);
  const double y = a.top + a.height + 62;
  d.add(Circle{a.left + 6, y - 4, 6, kGreyInk, 0});
  d.add(Text{a.left + 18, y, "IBL (split-sum DFG)", 12, kInk});
  d.add(Circle{a.left + 186, y - 4, 6, kGreyInk, 2.0});
  d.add(Text{a.left + 198, y, "area lights (LTC moments)", 12, kInk});
  d.add(Text{a.left, y + 20, fmt::format("median over the {} pages", cls), 12, kGreyInk});
}

}  // namespace

Drawing rendered_library_plot(const std::vector<RenderedLibraryRow>& rows, const LabelFont& font) {
  Drawing d;
  d.width = kWidth;
  d.height = kHeight;
  add_against_k(d, rows);
  add_against_cost(d, rows, "metal", kMetalsPanel, "Every shader against its GPU cost: metals",
                   font);
  add_against_cost(d, rows, "dielectric", kDielectricsPanel,
                   "Every shader against its GPU cost: dielectrics", font);
  return d;
}

}  // namespace fl::draw
