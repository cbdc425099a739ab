// rollspec compare: simulated third-octave band levels against a measured PSD (design §7).
#include <cmath>
#include <cstdio>
#include <iostream>

#include "kernels/spectral/third_octave_bands.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/provenance.hpp"

namespace rollspec::cli {

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
  std::vector<std::size_t> dims;
  const auto level = r.read("/bands/level_db", &dims);
  const auto lower_db = r.read("/bands/ci_lower_db");
  const auto upper_db = r.read("/bands/ci_upper_db");
  const auto lo = r.read("/bands/lower_frequency"), hi = r.read("/bands/upper_frequency");
  const auto centre = r.read("/bands/nominal_frequency");
  if (dims.size() != 2) throw data_error(result + ": /bands/level_db is not sensor x band");
  const std::size_t ns = dims[0], nb = dims[1];
  if (sensor < 0 || static_cast<std::size_t>(sensor) >= ns)
    throw usage_error("--sensor " + std::to_string(sensor) + ": the result has sensors 0.." + std::to_string(ns - 1));

  const io::CsvTable m = io::read_csv(measurement);
  const auto& mf = m.column("frequency_hz");
  const auto& mp = m.column("psd");
  io::require_increasing(m, m.column_index("frequency_hz"));
  for (std::size_t i = 0; i < mp.size(); ++i)
    if (mp[i] < 0.0) throw data_error(m.where(i) + ": psd value " + std::to_string(mp[i]) + " is negative; allowed: >= 0");

  if (format == "csv")
    std::printf("centre_hz,simulated_db,measured_db,delta_db,ci_lower_db,ci_upper_db,inside_ci\n");
  else
    std::printf("%10s %12s %12s %8s %10s\n", "centre_Hz", "simulated_dB", "measured_dB", "delta_dB", "inside_CI");
  double sq = 0.0;
  int inside = 0, count = 0;
  const std::size_t off = static_cast<std::size_t>(sensor) * nb;
  for (std::size_t b = 0; b < nb; ++b) {
    if (lo[b] < fmin || hi[b] > fmax) continue;
    const double meas = spectral::band_average_irregular(mf.data(), mp.data(), mf.size(), lo[b], hi[b]);
    if (std::isnan(meas) || meas <= 0.0) continue;
    const double mdb = 10.0 * std::log10(meas), sdb = level[off + b];
    const double d = sdb - mdb;
    const bool in = mdb >= lower_db[off + b] && mdb <= upper_db[off + b];
    sq += d * d;
    inside += in;
    ++count;
    if (format == "csv")
      std::printf("%g,%.4f,%.4f,%.4f,%.4f,%.4f,%s\n", centre[b], sdb, mdb, d, lower_db[off + b], upper_db[off + b],
                  in ? "yes" : "no");
    else
      std::printf("%10g %12.2f %12.2f %8.2f %10s\n", centre[b], sdb, mdb, d, in ? "yes" : "no");
  }
  if (count == 0) throw data_error(measurement + ": covers none of the result's bands inside [fmin, fmax]");
  std::printf("rms_db_error: %.3f  inside_ci: %d/%d\n", std::sqrt(sq / count), inside, count);
  return 0;
}

}  // namespace rollspec::cli
