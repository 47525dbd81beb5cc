#include "util/median.h"

#include <algorithm>
#include <cmath>

namespace fl {

double median(std::vector<double> values) {
  const std::size_t n = values.size();
  if (n == 0) return std::nan("");
  std::sort(values.begin(), values.end());
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace fl
