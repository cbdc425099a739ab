#include "src/scenes/result_shape.hpp"

#include <cstdio>

#include "src/scenes/psd_rows.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::scenes {

namespace {

std::string span(const std::vector<double>& lo, const std::vector<double>& hi) {
  if (lo.empty()) return "";
  return io::formatted(" (%.6g .. %.6g Hz)", lo.front(), hi.back());
}

}  // namespace

bool ResultShape::operator==(const ResultShape& o) const {
  return rows == o.rows && frequency == o.frequency && band_lower == o.band_lower && band_upper == o.band_upper;
}

std::string ResultShape::text() const {
  const std::string r = std::to_string(rows.size()) + " x ";
  return "/psd/mean " + r + std::to_string(frequency.size()) + span(frequency, frequency) + ", /bands/level_db " + r +
         std::to_string(band_lower.size()) + span(band_lower, band_upper);
}

ResultShape psd_result_shape(std::vector<std::string> sensors, bool sensor_mean, const spectral::WelchConfig& welch,
                             double band_min, double band_max) {
  const spectral::WelchPlan plan(welch);
  return PsdRows(std::move(sensors), sensor_mean, plan.frequencies(), band_min, band_max, 0).shape();
}

std::vector<std::string> numbered_sensors(std::size_t n) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < n; ++k) names.push_back("sensor_" + std::to_string(k + 1));
  return names;
}

}  // namespace rollspec::scenes
