#pragma once
// The one percentile rule of every summary (docs/conventions.md): nearest rank.
#include <string>
#include <vector>

namespace fl {

// The q-quantile (0 ≤ q ≤ 1) by nearest rank (Hyndman & Fan 1996, definition 1): the value of
// rank ⌈q·n⌉ in ascending order (rank 1 for q = 0). A value of the set, never an interpolation:
// p99 over 385 pages is the 382nd smallest (⌈3.81⌉ = 4th largest). NaN for an empty set (tables
// print it as n/a).
double quantile(std::vector<double> values, double q);

// The median as every summary reports it: quantile(values, 0.5), the value of rank ⌈n/2⌉ (for an
// even count the lower of the two middle values).
double median(std::vector<double> values);

// The sample median as an estimator (not a reported percentile): the middle value, for an even
// count the mean of the two middle values. The consensus presets use it.
double sample_median(std::vector<double> values);

// The `count` largest values' indices, largest first (ties: the lower index first).
std::vector<std::size_t> largest_indices(const std::vector<double>& values, std::size_t count);

}  // namespace fl
