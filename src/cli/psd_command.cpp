// rollspec psd: Welch PSD (D-15) of a measured time series, CSV in, CSV out.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "kernels/spectral/welch.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/output_target.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::cli {

int psd_command(const Args& args) {
  const std::string usage =
      "usage: rollspec psd SIGNAL.csv --fs HZ [--segment N] [--overlap F] [--window hann|rect] [--out FILE.csv]\n"
      "\n"
      "One-sided Welch PSD of each column of SIGNAL.csv (a header line naming the channels, then one\n"
      "sample per row). Segments are mean-detrended and windowed; density scaling (unit^2/Hz).\n"
      "Output CSV: frequency_hz,<channel>,... (to stdout without --out).";
  po::options_description opts("options");
  std::string input, out, window = "hann";
  double fs = 0.0, overlap = 0.5;
  long long segment = 1024;
  opts.add_options()("signal", po::value(&input)->required(), "input CSV")(
      "fs", po::value(&fs)->required(), "sample rate (Hz)")("segment", po::value(&segment)->default_value(1024),
                                                           "segment length (samples)")(
      "overlap", po::value(&overlap)->default_value(0.5), "overlap as a fraction of the segment, in [0, 0.95]")(
      "window", po::value(&window)->default_value("hann"), "hann or rect")("out,o", po::value(&out), "output CSV")(
      "force", "replace an existing --out file even if it is not a PSD written by rollspec psd");
  po::positional_options_description pos;
  pos.add("signal", 1);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  if (!(fs > 0.0) || !std::isfinite(fs)) throw usage_error("--fs " + std::to_string(fs) + ": allowed: a finite number > 0 (Hz)");
  if (segment < 4) throw usage_error("--segment " + std::to_string(segment) + ": allowed: a whole number >= 4");
  if (!(overlap >= 0.0 && overlap <= 0.95)) throw usage_error("--overlap " + std::to_string(overlap) + ": allowed: a fraction in [0, 0.95]");
  if (window != "hann" && window != "rect") throw usage_error("--window " + window + ": allowed: hann or rect");

  if (!out.empty()) {  // an output that is the input is refused before the input is read
    std::error_code ec;
    if (std::filesystem::exists(out, ec) && std::filesystem::equivalent(out, input, ec))
      throw usage_error("--out " + out + " is also the input signal ('" + input +
                        "'); refusing to overwrite an input; choose another --out");
  }
  const io::CsvTable t = io::read_csv(input);
  if (t.rows() < static_cast<std::size_t>(segment))
    throw data_error(input + ": " + std::to_string(t.rows()) + " samples, fewer than one segment (--segment " +
                     std::to_string(segment) + ")");
  spectral::WelchConfig cfg;
  cfg.sample_rate = fs;
  cfg.segment = static_cast<std::size_t>(segment);
  cfg.overlap = static_cast<std::size_t>(std::floor(overlap * static_cast<double>(segment)));
  cfg.window = window == "hann" ? spectral::Window::hann : spectral::Window::rectangular;
  const spectral::WelchPlan plan(cfg);
  spectral::WelchWorkspace ws(cfg.segment);
  std::vector<std::vector<double>> psd(t.columns.size(), std::vector<double>(plan.n_freq()));
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    plan.psd(t.values[c].data(), t.rows(), psd[c].data(), ws);
    for (std::size_t k = 0; k < psd[c].size(); ++k)
      if (!std::isfinite(psd[c][k])) {
        double peak = 0.0;
        for (double v : t.values[c]) peak = std::max(peak, std::fabs(v));
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", peak);
        throw data_error(input + ": column '" + t.columns[c] + "': the PSD overflows a double (largest |value| " + buf +
                         "); allowed: samples whose squares stay finite, e.g. |value| < 1e100 (rescale the unit)");
      }
  }

  std::ostringstream s;
  s << "frequency_hz";
  for (const auto& c : t.columns) s << "," << c;
  s << "\n";
  const auto f = plan.frequencies();
  char buf[32];
  for (std::size_t k = 0; k < f.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.17g", f[k]);
    s << buf;
    for (const auto& col : psd) {
      std::snprintf(buf, sizeof buf, "%.17g", col[k]);
      s << "," << buf;
    }
    s << "\n";
  }
  if (out.empty()) {
    std::cout << s.str();
    return 0;
  }
  // Written beside the output and renamed onto it: an existing file is replaced whole or not at all,
  // and the temporary file never outlives a failure.
  io::OutputTarget target{out, io::kPsdCsvKind};
  target.force = vm.count("force") > 0;
  target.inputs = {input};
  const std::string write_path = io::check_output_target(target);
  const std::string tmp = io::temp_name(write_path);
  io::register_temp(tmp);
  const auto fail = [&](const std::string& what, int err) {
    std::remove(tmp.c_str());
    io::unregister_temp(tmp);
    return cannot_create(what + " (writing " + tmp + ": " +
                         (err == ENOSPC ? std::string("no space left on device") : std::string(std::strerror(err))) + ")");
  };
  {
    errno = 0;
    std::ofstream o(tmp, std::ios::trunc);
    if (!o) throw fail("cannot create output file '" + out + "'", errno ? errno : EIO);
    o << s.str();
    o.close();
    if (!o) throw fail("cannot write output file '" + out + "'", errno ? errno : EIO);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, write_path, ec);
  if (ec) throw fail("cannot create output file '" + out + "': " + ec.message(), ec.value());
  io::unregister_temp(tmp);
  return 0;
}

}  // namespace rollspec::cli
