#include "draw/plan_plot.h"

#include <fmt/format.h>

#include <algorithm>

#include "draw/plot.h"

namespace fl::draw {
namespace {

constexpr int kWidth = 960, kHeight = 560;
constexpr double kLeft = 90, kTop = 50, kPanelW = 600, kPanelH = 430, kRadius = 5;
const io::Rgb8 kFrontColour{31, 119, 180}, kDominated{170, 170, 170}, kChosen{214, 39, 40},
    kBudget{44, 160, 44};

Axes plan_axes(const analysis::Plan& p) {
  double x_max = 1, y_max = 0;
  for (const auto& o : p.scene_options) {
    if (!o.cost.gpu_instructions) continue;
    x_max = std::max(x_max, static_cast<double>(*o.cost.gpu_instructions));
    y_max = std::max(y_max, o.worst_de00);
  }
  y_max = std::min(std::max(y_max, p.scene.max_de00), 4 * p.scene.max_de00);
  return {kLeft, kTop, kPanelW, kPanelH, 0, nice_ceiling(1.05 * x_max), 0, nice_ceiling(y_max)};
}

Point at(const Axes& a, int instructions, double de) {
  return a.map(instructions, std::min(de, a.y_max));
}

// The front of cost against worst error, cheapest first, as a staircase.
void add_front(Drawing& d, const Axes& a, const analysis::Plan& p) {
  std::vector<const analysis::SceneOption*> front;
  for (const auto& o : p.scene_options)
    if (!o.dominated_by && o.cost.gpu_instructions) front.push_back(&o);
  std::sort(front.begin(), front.end(), [](const auto* x, const auto* y) {
    return analysis::scene_cost_less(x->cost, y->cost);
  });
  Polyline line{{}, kFrontColour, 1.5, {}};
  for (const auto* o : front) {
    const Point q = at(a, *o->cost.gpu_instructions, o->worst_de00);
    if (!line.points.empty()) line.points.push_back({q.x, line.points.back().y});
    line.points.push_back(q);
    d.add(Text{q.x + 8, q.y - 6, o->name, 11, kInk});
  }
  if (line.points.size() > 1) d.add(std::move(line));
}

void add_legend(Drawing& d) {
  const double x = kLeft + kPanelW + 30;
  double y = kTop + 10;
  const auto entry = [&](Shape s, const std::string& label) {
    d.add(std::move(s));
    d.add(Text{x + 18, y + 4, label, 13, kInk});
    y += 24;
  };
  entry(Circle{x + 6, y, kRadius, kFrontColour, 0}, "worst, on the front");
  entry(Circle{x + 6, y, kRadius, kDominated, 0}, "worst, dominated");
  entry(Circle{x + 6, y, kRadius - 1, kInk, 1.5}, "median");
  entry(Circle{x + 6, y, kRadius + 4, kChosen, 2}, "chosen");
  entry(Polyline{{{x - 1, y}, {x + 13, y}}, kBudget, 1.5, {5, 3}}, "budget");
}

}  // namespace

Drawing plan_plot(const analysis::Plan& p) {
  Drawing d;
  d.width = kWidth;
  d.height = kHeight;
  const Axes a = plan_axes(p);
  add_axes(d, a, nice_ticks(a.x_min, a.x_max), nice_ticks(a.y_min, a.y_max),
           "GPU instructions per draw (the dearest shader variant)", "rendered RMS ΔE2000", 0,
           tick_decimals(nice_ticks(a.y_min, a.y_max)));
  d.add(
      Text{kLeft + 0.5 * kPanelW, 28, "Shader sets for " + p.scene.path, 15, kInk, Align::Center});
  d.add(
      data_line(a, {a.x_min, a.x_max}, {p.scene.max_de00, p.scene.max_de00}, kBudget, 1.5, {5, 3}));
  add_front(d, a, p);
  for (bool front : {false, true})  // the front over the dominated
    for (const auto& o : p.scene_options) {
      if (!o.cost.gpu_instructions || front == o.dominated_by.has_value()) continue;
      const Point w = at(a, *o.cost.gpu_instructions, o.worst_de00);
      const Point m = at(a, *o.cost.gpu_instructions, o.median_de00);
      d.add(Circle{m.x, m.y, kRadius - 1, kInk, 1.5});
      d.add(Circle{w.x, w.y, kRadius, front ? kFrontColour : kDominated, 0});
    }
  const auto& c = p.scene_choice();
  if (c.cost.gpu_instructions) {
    const Point w = at(a, *c.cost.gpu_instructions, c.worst_de00);
    d.add(Circle{w.x, w.y, kRadius + 4, kChosen, 2});
  }
  add_legend(d);
  return d;
}

}  // namespace fl::draw
