#include "src/io/band_levels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "kernels/spectral/covariance_shrinkage.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/io/sweep_point.hpp"

namespace rollspec::io {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

// A sensor is picked by its name, or by the number K of its name sensor_K (1-based, as the names and
// the study's [sensors] positions count): one scheme, whatever the row order.
std::size_t pick_by_name(const Hdf5Reader& r, const std::vector<std::string>& names, const std::string& sensor) {
  if (sensor.empty()) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == "sensor_mean") return i;
    return 0;
  }
  const bool number = sensor.find_first_not_of("0123456789") == std::string::npos && sensor.size() < 10;
  const std::string name = number ? "sensor_" + std::to_string(std::stoul(sensor)) : sensor;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  throw usage_error("--sensor " + sensor.substr(0, 200) + ": " + r.path() + " has the sensors " + join(names) +
                    "; allowed: a name, or the number K of sensor_K");
}

// The sensor nearest x (the first of equally near ones). It must lie within half the smallest
// spacing between the sensors' places: then no other sensor is nearer than the spacing the study
// resolves, and a place between two sensors is not silently read as one of them. With one place
// there is no spacing to judge by: only that place is accepted.
std::size_t pick_by_position(const Hdf5Reader& r, const std::vector<std::string>& names,
                             const std::vector<double>& positions, double x, std::string& note) {
  const std::string option = "--measured-position " + number_text(x) + " m";
  std::vector<std::size_t> placed;
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (std::isfinite(positions[i])) placed.push_back(i);
  if (placed.empty())
    throw usage_error(option + ": " + r.path() +
                      " has no sensor positions (/bands/sensor_position: written since sensor positions are a "
                      "coordinate, by scenes whose sensors have places); allowed: --sensor NAME|K");
  std::vector<double> sorted;
  for (const std::size_t i : placed) sorted.push_back(positions[i]);
  std::sort(sorted.begin(), sorted.end());
  double gap = INFINITY;
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i] > sorted[i - 1]) gap = std::min(gap, sorted[i] - sorted[i - 1]);
  const double tolerance = std::isinf(gap) ? 0.0 : gap / 2.0;
  std::size_t best = placed[0];
  for (const std::size_t i : placed)
    if (std::fabs(positions[i] - x) < std::fabs(positions[best] - x)) best = i;
  const double distance = std::fabs(positions[best] - x);
  const std::string within = number_text(tolerance) + " m of a sensor (" +
                             (std::isinf(gap) ? "one sensor: no spacing to judge a distance by"
                                              : "half the smallest spacing between sensors") +
                             ")";
  if (distance > tolerance) {
    std::string places;
    for (const std::size_t i : placed)
      places += (places.empty() ? "" : ", ") + names[i] + " " + number_text(positions[i]) + " m";
    throw usage_error(option + ": the nearest sensor, " + names[best] + " at " + number_text(positions[best]) +
                      " m, is " + number_text(distance) + " m away; " + r.path() + " has the sensors at " + places +
                      "; allowed: a position within " + within + ", or --sensor NAME|K");
  }
  note = option + ": " + names[best] + " at " + number_text(positions[best]) + " m, the nearest sensor (within " +
         within + ")";
  return best;
}

// The one chooser of a result's row, for compare and fit.
std::size_t pick_row(const Hdf5Reader& r, const std::vector<std::string>& names, const std::vector<double>& positions,
                     const SensorChoice& choice, std::string& note) {
  const SensorChoice c = sensor_choice(choice.name, choice.position);
  return c.position ? pick_by_position(r, names, positions, *c.position, note) : pick_by_name(r, names, c.name);
}

// Well-formed UTF-8 without control characters: a name that is printed and written into JSON.
bool printable_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) return false;
    const int n = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xe ? 2 : (c >> 3) == 0x1e ? 3 : -1;
    if (n < 0 || i + static_cast<std::size_t>(n) >= s.size() + static_cast<std::size_t>(n == 0))
      return false;  // cut sequence
    for (int k = 1; k <= n; ++k)
      if ((static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]) >> 6) != 0x2) return false;
    i += static_cast<std::size_t>(n) + 1;
  }
  return true;
}

// A double's decibels lie within +-3083 dB (10 log10 of the largest and smallest doubles): beyond
// that a level is not a level of any PSD a double holds.
constexpr double kLargestLevelDb = 3100.0;

// The table term of the row (D-31): the sub-table runs' levels, their dof and variance factor, checked
// against the result's shape; or, for a result whose intervals are conditional on a random table, the
// flag that says its verdict cannot carry the table's error.
void read_table_term(const Hdf5Reader& r, const SweepPoint& at, std::size_t row, std::size_t ns, std::size_t nb,
                     BandLevels& b) {
  const std::string& file = r.path();
  const std::string includes =
      r.has_attribute("/bands", "interval_includes") ? r.string_attribute("/bands", "interval_includes") : "";
  if (!r.exists("/bands/table_leave_out_level_db")) {
    b.table_error_missing = includes.find("conditional on") != std::string::npos;
    const auto on = includes.find("conditional on the ");
    if (on != std::string::npos) b.table = includes.substr(on + 19, includes.find(')', on) - on - 19);
    return;
  }
  std::vector<std::size_t> d;
  const auto v = read_at_point(r, at, "/bands/table_leave_out_level_db", 3, &d);
  if (d.size() != 3 || d[1] != ns || d[2] != nb || d[0] < 2)
    throw data_error(file + ": /bands/table_leave_out_level_db is not (sub-tables >= 2) x sensor x band (" +
                     std::to_string(ns) + " x " + std::to_string(nb) + ")");
  b.table_units = d[0];
  for (std::size_t i = 0; i < d[0]; ++i)
    for (std::size_t k = 0; k < nb; ++k) {
      const double x = v[(i * ns + row) * nb + k];
      if (!(std::fabs(x) <= kLargestLevelDb) && !(std::isinf(x) && x < 0.0))
        throw data_error(file + ": /bands/table_leave_out_level_db[" + std::to_string(i) + ", " + std::to_string(row) +
                         ", " + std::to_string(k) + "] = " + number_text(x) +
                         " dB; allowed: -inf (no power) or a level within +-" + number_text(kLargestLevelDb) +
                         " dB (the file was altered or damaged)");
      b.table_levels_db.push_back(x);
    }
  b.table_dof = r.double_attribute("/bands", "table_jackknife_dof");
  b.table_variance_factor = r.double_attribute("/bands", "table_jackknife_variance_factor");
  if (!(b.table_dof > 0.0 && std::isfinite(b.table_dof)) ||
      !(b.table_variance_factor > 0.0 && std::isfinite(b.table_variance_factor)))
    throw data_error(file + ": /bands@table_jackknife_dof = " + number_text(b.table_dof) +
                     ", table_jackknife_variance_factor = " + number_text(b.table_variance_factor) +
                     "; allowed: finite numbers > 0 (the file was altered or damaged)");
  b.table_independent_bands = r.has_attribute("/bands", "table_covariance") &&
                              r.string_attribute("/bands", "table_covariance").rfind("independent", 0) == 0;
  const auto open = includes.find(", ");
  b.table = open == std::string::npos ? "table" : includes.substr(open + 2, includes.find(" (", open) - open - 2);
}

}  // namespace

SensorChoice sensor_choice(const std::string& name, std::optional<double> position) {
  if (position && !std::isfinite(*position))
    throw usage_error("--measured-position " + number_text(*position) + ": allowed: a finite position in m");
  if (position && !name.empty())
    throw usage_error("--sensor " + name.substr(0, 200) + " and --measured-position " + number_text(*position) +
                      " m both given; allowed: one of the two (a sensor by name, or the one nearest a place)");
  return {name, position};
}

BandLevels read_band_levels(const Hdf5Reader& r, const SensorChoice& choice, const std::string& point) {
  const std::string& file = r.path();
  const SweepPoint at = sweep_point(r, point);
  std::vector<std::size_t> dims;
  const auto level = read_at_point(r, at, "/bands/level_db", 2, &dims);
  if (dims.size() != 2) throw data_error(file + ": /bands/level_db is not sensor x band");
  const std::size_t ns = dims[0], nb = dims[1];
  if (ns == 0 || nb == 0)
    throw data_error(file + ": /bands/level_db is empty (" + std::to_string(ns) + " sensors x " + std::to_string(nb) +
                     " bands)");
  const auto names = r.read_strings("/bands/sensor");
  if (names.size() != ns)
    throw data_error(file + ": /bands/sensor has " + std::to_string(names.size()) + " names; expected " +
                     std::to_string(ns) + " (one per row of /bands/level_db)");
  for (std::size_t i = 0; i < ns; ++i)
    if (!printable_utf8(names[i]))
      throw data_error(file + ": /bands/sensor[" + std::to_string(i) +
                       "] is not printable UTF-8 text; allowed: sensor names "
                       "as rollspec writes them (the file was altered or damaged)");
  std::vector<double> positions;  // results written before positions were a coordinate lack them
  if (r.exists("/bands/sensor_position")) {
    positions = r.read("/bands/sensor_position");
    if (positions.size() != ns)
      throw data_error(file + ": /bands/sensor_position has " + std::to_string(positions.size()) +
                       " values; expected " + std::to_string(ns) + " (one per row of /bands/level_db)");
  }
  BandLevels b;
  b.point = at.label;
  const std::size_t row = pick_row(r, names, positions, choice, b.pick_note);
  b.sensor = names[row];
  if (!positions.empty()) b.position = positions[row];
  const double realisations = r.double_attribute("/psd", "realisations");
  if (!(realisations >= 1.0 && realisations <= 9.0e15 && realisations == std::floor(realisations)))
    throw data_error(file + ": /psd@realisations = " + number_text(realisations) +
                     "; allowed: a whole number >= 1 (the file was altered or damaged)");
  b.realisations = static_cast<std::uint64_t>(realisations);
  b.confidence = r.double_attribute("/psd", "confidence_level");
  if (!(b.confidence > 0.0 && b.confidence < 1.0))
    throw data_error(file + ": /psd@confidence_level = " + number_text(b.confidence) +
                     "; allowed: 0 < level < 1 (the file was altered or damaged)");
  b.interval_method = r.string_attribute("/psd", "interval_method");
  // Every band dataset must match /bands/level_db, or the rows below would read past their end.
  const std::string shape = std::to_string(ns) + " x " + std::to_string(nb);
  auto row_of = [&](const char* name, std::vector<double>& out) {
    std::vector<std::size_t> d;
    const auto v = read_at_point(r, at, name, 2, &d);
    if (d != dims) throw data_error(file + ": " + name + " does not have the shape of /bands/level_db (" + shape + ")");
    out.assign(v.begin() + static_cast<std::ptrdiff_t>(row * nb),
               v.begin() + static_cast<std::ptrdiff_t>((row + 1) * nb));
    for (std::size_t k = 0; k < nb; ++k)
      if (std::isnan(out[k]))
        throw data_error(file + ": " + name + "[" + std::to_string(row) + ", " + std::to_string(k) +
                         "] is NaN; allowed: a number (levels in dB may be -inf for a band without power)");
  };
  row_of("/bands/level_db", b.level_db);
  row_of("/bands/ci_lower_db", b.ci_lower_db);
  row_of("/bands/ci_upper_db", b.ci_upper_db);
  row_of("/bands/std", b.std_dev);
  row_of("/bands/log_std", b.log_std);
  for (std::size_t k = 0; k < nb; ++k) {
    const auto where = [&](const char* name) {
      return file + ": " + name + "[" + std::to_string(row) + ", " + std::to_string(k) + "] = ";
    };
    for (const auto& [name, v] :
         {std::pair<const char*, double>{"/bands/std", b.std_dev[k]}, {"/bands/log_std", b.log_std[k]}})
      if (!(v >= 0.0 && std::isfinite(v)))
        throw data_error(where(name) + number_text(v) +
                         "; allowed: a finite spread >= 0 (the file was altered or damaged)");
    // Levels: -inf for a band without power; interval bounds: +-inf where the interval is unbounded.
    for (const auto& [name, v, bounds] :
         {std::tuple<const char*, double, bool>{"/bands/level_db", b.level_db[k], false},
          {"/bands/ci_lower_db", b.ci_lower_db[k], true},
          {"/bands/ci_upper_db", b.ci_upper_db[k], true}})
      if (std::isfinite(v) ? std::fabs(v) > kLargestLevelDb : !bounds && v > 0.0)
        throw data_error(
            where(name) + number_text(v) + " dB; allowed: " + (bounds ? "+-inf (unbounded)" : "-inf (no power)") +
            " or a level within +-" + number_text(kLargestLevelDb) + " dB (the file was altered or damaged)");
    if (b.ci_lower_db[k] > b.ci_upper_db[k])
      throw data_error(file + ": band " + std::to_string(k) + " of sensor " + names[row] + " has ci_lower_db " +
                       number_text(b.ci_lower_db[k]) + " > ci_upper_db " + number_text(b.ci_upper_db[k]) +
                       "; allowed: lower <= upper (the file was altered or damaged)");
  }
  for (const auto& [name, v] : {std::pair<const char*, std::vector<double>*>{"/bands/lower_frequency", &b.lower},
                                {"/bands/upper_frequency", &b.upper},
                                {"/bands/nominal_frequency", &b.nominal}}) {
    *v = r.read(name);
    if (v->size() != nb)
      throw data_error(file + ": " + name + " has " + std::to_string(v->size()) + " values; expected " +
                       std::to_string(nb) + " (one per band of /bands/level_db)");
  }
  for (std::size_t k = 0; k < nb; ++k)
    if (!(std::isfinite(b.lower[k]) && std::isfinite(b.upper[k]) && std::isfinite(b.nominal[k]) && b.lower[k] > 0.0 &&
          b.lower[k] < b.upper[k]))
      throw data_error(
          file + ": band " + std::to_string(k) + " has edges " + number_text(b.lower[k]) + " .. " +
          number_text(b.upper[k]) + " Hz and nominal centre " + number_text(b.nominal[k]) +
          " Hz; allowed: finite, 0 < lower < upper (/bands/lower_frequency, upper_frequency, nominal_frequency)");
  if (r.exists("/bands/log_level_covariance")) {  // D-26; results written before it lack it
    std::vector<std::size_t> d;
    const auto v = read_at_point(r, at, "/bands/log_level_covariance", 3, &d);
    if (d != std::vector<std::size_t>{ns, nb, nb})
      throw data_error(file + ": /bands/log_level_covariance is not sensor x band x band (" + shape + " x " +
                       std::to_string(nb) + ")");
    b.log_covariance.assign(v.begin() + static_cast<std::ptrdiff_t>(row * nb * nb),
                            v.begin() + static_cast<std::ptrdiff_t>((row + 1) * nb * nb));
  }
  if (r.exists("/bands/log_skewness")) {  // D-26d; results written before it lack it
    row_of("/bands/log_skewness", b.log_skewness);
    for (std::size_t k = 0; k < nb; ++k)
      if (!std::isfinite(b.log_skewness[k]))
        throw data_error(file + ": /bands/log_skewness[" + std::to_string(row) + ", " + std::to_string(k) +
                         "] = " + number_text(b.log_skewness[k]) + "; allowed: a finite skewness");
  }
  read_table_term(r, at, row, ns, nb, b);
  return b;
}

std::vector<double> table_log_covariance(const BandLevels& b, const std::vector<std::size_t>& band) {
  const std::size_t n = b.table_units, nb = b.level_db.size(), p = band.size();
  if (n < 2 || b.table_levels_db.size() != n * nb) return {};
  const double to_log = std::log(10.0) / 10.0;
  std::vector<double> mean(p, 0.0), cov(p * p, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < p; ++k) mean[k] += b.table_levels_db[i * nb + band[k]] / static_cast<double>(n);
  const double scale = b.table_variance_factor * static_cast<double>(n - 1) / static_cast<double>(n) * to_log * to_log;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < p; ++k)
      for (std::size_t l = 0; l < p; ++l)
        if (k == l || !b.table_independent_bands)
          cov[k * p + l] +=
              scale * (b.table_levels_db[i * nb + band[k]] - mean[k]) * (b.table_levels_db[i * nb + band[l]] - mean[l]);
  return cov;
}

double table_shrinkage(const BandLevels& b, const std::vector<std::size_t>& band) {
  const std::size_t n = b.table_units, nb = b.level_db.size(), p = band.size();
  if (n < 2 || b.table_levels_db.size() != n * nb || b.table_independent_bands) return 0.0;
  std::vector<double> x(n * p);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < p; ++k) x[i * p + k] = b.table_levels_db[i * nb + band[k]];
  return spectral::shrinkage_intensity(x.data(), n, p);
}

}  // namespace rollspec::io
