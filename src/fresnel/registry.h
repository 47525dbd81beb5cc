#pragma once
// The registry: every Fresnel model Fresnel Lab compares, in report order. A new model is one
// file in models/ and one entry in `Registry`; every entry must be a ModelUnit (unit.h), checked
// below, and every generic test runs over this list.
#include <type_traits>

#include "fresnel/models/basis.h"
#include "fresnel/models/cook_torrance.h"
#include "fresnel/models/f82.h"
#include "fresnel/models/fresnel_rgb.h"
#include "fresnel/models/generalized_schlick.h"
#include "fresnel/models/gulbrandsen.h"
#include "fresnel/models/lazanyi.h"
#include "fresnel/models/schlick.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

template <class... Units>
struct ModelList {
  static constexpr int kSize = sizeof...(Units);
};

using Registry = ModelList<models::Schlick, models::GeneralizedSchlick, models::CookTorrance,
                           models::Lazanyi, models::F82, models::Gulbrandsen, models::FresnelRgb,
                           models::Basis<3>, models::Basis<4>, models::Basis<5>>;

namespace detail {
template <class... Units>
constexpr bool all_units(ModelList<Units...>) {
  return (check_unit<Units>() && ...);
}
}  // namespace detail
static_assert(detail::all_units(Registry{}), "every registry entry must be a ModelUnit (unit.h)");

namespace detail {
template <class Unit, class... Units>
constexpr int index_in(ModelList<Units...>) {
  int i = 0, found = -1;
  ((std::is_same_v<Unit, Units> ? (found = i, ++i) : ++i), ...);
  return found;
}
template <class F, class... Units>
void visit_in(int index, F& f, ModelList<Units...>) {
  int i = 0;
  ((i++ == index ? (f(Units{}), 0) : 0), ...);
}
}  // namespace detail

// The handle of unit `Unit`: model_of<models::F82>.
template <class Unit>
inline constexpr Model model_of{detail::index_in<Unit>(Registry{})};

// Calls f(Unit{}) with the unit of model m, so generic code can use its compile-time kernel.
template <class F>
void visit_model(Model m, F&& f) {
  detail::visit_in(m.index(), f, Registry{});
}

}  // namespace fl::fresnel
