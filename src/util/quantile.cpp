#include "util/quantile.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fl {

double quantile(std::vector<double> values, double q) {
  const std::size_t n = values.size();
  if (n == 0) return std::nan("");
  std::sort(values.begin(), values.end());
  // ⌈q·n⌉ with q·n rounded to 1e-9 first, so that 0.29·100 (28.999999999999996 in binary) is
  // rank 29.
  const double at = std::round(q * static_cast<double>(n) * 1e9) / 1e9;
  const auto rank = static_cast<std::size_t>(std::max(1.0, std::ceil(at)));
  return values[std::min(rank, n) - 1];
}

double median(std::vector<double> values) {
  return quantile(std::move(values), 0.5);
}

double sample_median(std::vector<double> values) {
  const std::size_t n = values.size();
  if (n == 0) return std::nan("");
  std::sort(values.begin(), values.end());
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<std::size_t> largest_indices(const std::vector<double>& values, std::size_t count) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] > values[b]; });
  order.resize(std::min(count, order.size()));
  return order;
}

}  // namespace fl
