// rollspec compare: simulated third-octave band levels against a measured PSD (design §7).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "kernels/spectral/third_octave_bands.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/provenance.hpp"

namespace rollspec::cli {

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
}  // namespace

int compare_command(const Args& args) {
  const std::string usage =
      "usage: rollspec compare RESULT.h5 MEASUREMENT.csv [--sensor K] [--fmin HZ] [--fmax HZ] [--format table|csv]\n"
      "\n"
      "MEASUREMENT.csv holds frequency_hz,psd (one-sided, (m/s^2)^2/Hz). For every third-octave band of\n"
      "the result inside [fmin, fmax] that the measurement covers, prints the simulated and measured\n"
      "band levels (dB re 1 (m/s^2)^2/Hz), their difference, and whether the measured level lies in the\n"
      "simulated confidence interval; the last line is `rms_db_error: X  inside_ci: Y/Z`.";
  po::options_description opts("options");
  std::string result, measurement, format = "table";
  long long sensor = 0;
  double fmin = 0.0, fmax = 1e12;
  opts.add_options()("result", po::value(&result)->required(), "result file (HDF5)")(
      "measurement", po::value(&measurement)->required(), "measured PSD (CSV)")(
      "sensor", po::value(&sensor)->default_value(0), "sensor index in the result")(
      "fmin", po::value(&fmin)->default_value(0.0), "lowest band edge (Hz)")(
      "fmax", po::value(&fmax)->default_value(1e12), "highest band edge (Hz)")(
      "format", po::value(&format)->default_value("table"), "table or csv");
  po::positional_options_description pos;
  pos.add("result", 1).add("measurement", 1);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  if (format != "table" && format != "csv") throw usage_error("--format " + format + ": allowed: table or csv");

  const io::Hdf5Reader r(result);
  io::check_filetype(r, io::kResultFileType, io::kResultSchemaMajor);
  std::vector<std::size_t> dims, dims_lower, dims_upper;
  const auto level = r.read("/bands/level_db", &dims);
  const auto lower_db = r.read("/bands/ci_lower_db", &dims_lower);
  const auto upper_db = r.read("/bands/ci_upper_db", &dims_upper);
  const auto lo = r.read("/bands/lower_frequency"), hi = r.read("/bands/upper_frequency");
  const auto centre = r.read("/bands/nominal_frequency");
  if (dims.size() != 2) throw data_error(result + ": /bands/level_db is not sensor x band");
  const std::size_t ns = dims[0], nb = dims[1];
  if (ns == 0 || nb == 0)
    throw data_error(result + ": /bands/level_db is empty (" + std::to_string(ns) + " sensors x " + std::to_string(nb) +
                     " bands)");
  // Every band dataset must match /bands/level_db, or the loop below would read past its end.
  const std::string shape = std::to_string(ns) + " x " + std::to_string(nb);
  if (dims_lower != dims) throw data_error(result + ": /bands/ci_lower_db does not have the shape of /bands/level_db (" + shape + ")");
  if (dims_upper != dims) throw data_error(result + ": /bands/ci_upper_db does not have the shape of /bands/level_db (" + shape + ")");
  for (const auto& [name, v] : {std::pair<const char*, const std::vector<double>*>{"/bands/lower_frequency", &lo},
                                {"/bands/upper_frequency", &hi},
                                {"/bands/nominal_frequency", &centre}})
    if (v->size() != nb)
      throw data_error(result + ": " + name + " has " + std::to_string(v->size()) + " values; expected " + std::to_string(nb) +
                       " (one per band of /bands/level_db)");
  for (std::size_t b = 0; b < nb; ++b)
    if (!(std::isfinite(lo[b]) && std::isfinite(hi[b]) && lo[b] > 0.0 && lo[b] < hi[b]))
      throw data_error(result + ": band " + std::to_string(b) + " has edges " + number(lo[b]) + " .. " + number(hi[b]) +
                       " Hz in /bands/lower_frequency, /bands/upper_frequency; allowed: finite, 0 < lower < upper");
  if (sensor < 0 || static_cast<std::size_t>(sensor) >= ns)
    throw usage_error("--sensor " + std::to_string(sensor) + ": the result has sensors 0.." + std::to_string(ns - 1));
  const std::size_t off = static_cast<std::size_t>(sensor) * nb;
  for (const auto& [name, v] : {std::pair<const char*, const std::vector<double>*>{"/bands/level_db", &level},
                                {"/bands/ci_lower_db", &lower_db},
                                {"/bands/ci_upper_db", &upper_db}})
    for (std::size_t b = 0; b < nb; ++b)
      if (std::isnan((*v)[off + b]))
        throw data_error(result + ": " + name + "[" + std::to_string(sensor) + ", " + std::to_string(b) +
                         "] is NaN; allowed: a level in dB (or -inf for a band without power)");

  const io::CsvTable m = io::read_csv(measurement);
  const auto& mf = m.column("frequency_hz");
  const auto& mp = m.column("psd");
  io::require_increasing(m, m.column_index("frequency_hz"));
  for (std::size_t i = 0; i < mf.size(); ++i)
    if (mf[i] < 0.0)
      throw data_error(m.where(i) + ": frequency_hz value " + number(mf[i]) + " is negative; allowed: >= 0 (one-sided PSD)");
  for (std::size_t i = 0; i < mp.size(); ++i)
    if (mp[i] < 0.0) throw data_error(m.where(i) + ": psd value " + number(mp[i]) + " is negative; allowed: >= 0");

  // The table is printed only once every band is computed: a refused input leaves no partial output.
  std::string text;
  char buf[256];
  if (format == "csv")
    text += "centre_hz,simulated_db,measured_db,delta_db,ci_lower_db,ci_upper_db,inside_ci\n";
  else {
    std::snprintf(buf, sizeof buf, "%10s %12s %12s %8s %10s\n", "centre_Hz", "simulated_dB", "measured_dB", "delta_dB",
                  "inside_CI");
    text += buf;
  }
  double sq = 0.0;
  int inside = 0, count = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    if (lo[b] < fmin || hi[b] > fmax) continue;
    if (mf.size() < 2 || mf.front() > lo[b] || mf.back() < hi[b]) continue;  // the measurement does not cover the band
    const double meas = spectral::band_average_irregular(mf.data(), mp.data(), mf.size(), lo[b], hi[b]);
    if (!std::isfinite(meas))
      throw data_error(measurement + ": the measured PSD averaged over the band " + number(lo[b]) + " .. " + number(hi[b]) +
                       " Hz is not finite (overflow); allowed: psd values whose band average is a finite double");
    if (meas <= 0.0) continue;
    const double mdb = 10.0 * std::log10(meas), sdb = level[off + b];
    const double d = sdb - mdb;
    const bool in = mdb >= lower_db[off + b] && mdb <= upper_db[off + b];
    sq += d * d;
    inside += in;
    ++count;
    if (format == "csv")
      std::snprintf(buf, sizeof buf, "%g,%.4f,%.4f,%.4f,%.4f,%.4f,%s\n", centre[b], sdb, mdb, d, lower_db[off + b],
                    upper_db[off + b], in ? "yes" : "no");
    else
      std::snprintf(buf, sizeof buf, "%10g %12.2f %12.2f %8.2f %10s\n", centre[b], sdb, mdb, d, in ? "yes" : "no");
    text += buf;
  }
  if (count == 0) throw data_error(measurement + ": covers none of the result's bands inside [fmin, fmax]");
  std::snprintf(buf, sizeof buf, "rms_db_error: %.3f  inside_ci: %d/%d\n", std::sqrt(sq / count), inside, count);
  text += buf;
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace rollspec::cli
