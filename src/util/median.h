#pragma once
// The median of a set of numbers.
#include <vector>

namespace fl {

// The middle value of `values` in sorted order; for an even count, the mean of the two middle
// values. An empty input has no median: the result is NaN (tables print it as n/a).
double median(std::vector<double> values);

}  // namespace fl
