#include "src/io/band_levels.hpp"

#include <cmath>
#include <cstdio>

#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::io {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + std::to_string(i) + " = " + names[i];
  return s;
}

std::size_t pick_row(const Hdf5Reader& r, const std::vector<std::string>& names, const std::string& sensor) {
  if (sensor.empty()) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == "sensor_mean") return i;
    return 0;
  }
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == sensor) return i;
  if (sensor.find_first_not_of("0123456789") == std::string::npos && sensor.size() < 10) {
    const std::size_t i = std::stoul(sensor);
    if (i < names.size()) return i;
  }
  throw usage_error("--sensor " + sensor.substr(0, 200) + ": " + r.path() + " has the sensors " + join(names) +
                    "; allowed: a name or an index");
}

}  // namespace

BandLevels read_band_levels(const Hdf5Reader& r, const std::string& sensor) {
  const std::string& file = r.path();
  std::vector<std::size_t> dims;
  const auto level = r.read("/bands/level_db", &dims);
  if (dims.size() != 2) throw data_error(file + ": /bands/level_db is not sensor x band");
  const std::size_t ns = dims[0], nb = dims[1];
  if (ns == 0 || nb == 0)
    throw data_error(file + ": /bands/level_db is empty (" + std::to_string(ns) + " sensors x " + std::to_string(nb) + " bands)");
  const auto names = r.read_strings("/bands/sensor");
  if (names.size() != ns)
    throw data_error(file + ": /bands/sensor has " + std::to_string(names.size()) + " names; expected " + std::to_string(ns) +
                     " (one per row of /bands/level_db)");
  const std::size_t row = pick_row(r, names, sensor);

  BandLevels b;
  b.sensor = names[row];
  b.realisations = static_cast<std::uint64_t>(r.double_attribute("/psd", "realisations"));
  b.confidence = r.double_attribute("/psd", "confidence_level");
  b.interval_method = r.string_attribute("/psd", "interval_method");
  // Every band dataset must match /bands/level_db, or the rows below would read past their end.
  const std::string shape = std::to_string(ns) + " x " + std::to_string(nb);
  auto row_of = [&](const char* name, std::vector<double>& out) {
    std::vector<std::size_t> d;
    const auto v = r.read(name, &d);
    if (d != dims) throw data_error(file + ": " + name + " does not have the shape of /bands/level_db (" + shape + ")");
    out.assign(v.begin() + static_cast<std::ptrdiff_t>(row * nb), v.begin() + static_cast<std::ptrdiff_t>((row + 1) * nb));
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
  for (const auto& [name, v] : {std::pair<const char*, std::vector<double>*>{"/bands/lower_frequency", &b.lower},
                                {"/bands/upper_frequency", &b.upper},
                                {"/bands/nominal_frequency", &b.nominal}}) {
    *v = r.read(name);
    if (v->size() != nb)
      throw data_error(file + ": " + name + " has " + std::to_string(v->size()) + " values; expected " + std::to_string(nb) +
                       " (one per band of /bands/level_db)");
  }
  for (std::size_t k = 0; k < nb; ++k)
    if (!(std::isfinite(b.lower[k]) && std::isfinite(b.upper[k]) && std::isfinite(b.nominal[k]) && b.lower[k] > 0.0 &&
          b.lower[k] < b.upper[k]))
      throw data_error(file + ": band " + std::to_string(k) + " has edges " + number_text(b.lower[k]) + " .. " + number_text(b.upper[k]) +
                       " Hz and nominal centre " + number_text(b.nominal[k]) +
                       " Hz; allowed: finite, 0 < lower < upper (/bands/lower_frequency, upper_frequency, nominal_frequency)");
  return b;
}

}  // namespace rollspec::io
