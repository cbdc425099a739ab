// rollspec psd: Welch PSD (D-15) of a measured time series (CSV/text, sound file or .mat; src/io/signal_file.hpp), CSV
// out.
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
#include "src/io/psd_options.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/number_text.hpp"
#include "src/io/psd_csv.hpp"
#include "src/io/signal_file.hpp"
#include "src/version.hpp"

namespace rollspec::cli {

namespace {
const char* const kPsdUsage =
    "usage: rollspec psd SIGNAL [--fs HZ] [--column NAME]... [--unit UNIT] [--scale X] [--segment N]\n"
    "                    [--overlap F] [--window hann|rectangular] [--time-column NAME|none] [--skip-rows N]\n"
    "                    [--out FILE.csv] [--force] [--quiet]\n"
    "\n"
    "One-sided Welch PSD of each channel of a measured signal, in (m/s^2)^2/Hz: segments mean-detrended and\n"
    "windowed, density scaling. Output: a CSV that pandas.read_csv and numpy.genfromtxt(names=True) read\n"
    "as it is, frequency_hz,<channel> [(m/s^2)^2/Hz],... (the channel without its own unit: 'Acc (g)' gives\n"
    "'Acc [(m/s^2)^2/Hz]'; ',', ';', tab, '\"' and '#' in a name become '_'); to stdout without --out. With\n"
    "--out, FILE.csv-metadata.json beside it (W3C CSVW) records the PSD unit, segment, overlap, window,\n"
    "detrending, segments averaged and their equivalent degrees of freedom, the sample rate, the source\n"
    "file and its SHA-256, the version and the CSV's own SHA-256. An existing --out (or metadata file) is\n"
    "replaced only if psd wrote it and it was not edited since (its metadata records its SHA-256; or it\n"
    "starts with the older marker line '# rollspec-psd-csv'), or with --force.\n"
    "\n"
    "SIGNAL is read by its content, else by its extension:\n"
    "  CSV/text  a header line naming the columns, then one sample per row. Delimiter ',', ';' or tab, from\n"
    "            the data rows; with ';' or tab a decimal comma is accepted (0,125;1,5), one decimal mark per\n"
    "            file; one column with a decimal comma (0,0123 per row) is read as such. UTF-8 (with or\n"
    "            without a byte-order mark) or UTF-16 with a byte-order mark. Preamble lines before the header\n"
    "            (logger, date, a calibration table) are skipped: the header is the line followed by the most\n"
    "            rows of numbers of its width in the file (--skip-rows N: the header follows the first N\n"
    "            lines). A units row next to the header ([s], [m/s²], g, ... or empty cells) gives units.\n"
    "            The time column is named t, time or zeit, alone (seconds) or with a unit s, ms, us (µs) or ns\n"
    "            written _ms, [ms], (ms), /ms (time_s, Time (s), t [ms], zeit_ms, t [µs]), or has a time unit\n"
    "            in brackets or the units row (case and spaces ignored; a bare capital T is no time: a\n"
    "            temperature or tension). It is never a channel and gives the sample rate (--time-column NAME\n"
    "            picks another, in the unit its name or the units row gives, else seconds; --time-column none:\n"
    "            no time column; several time columns are read if they agree). Its stamps must increase, each\n"
    "            within 0.1 sample interval of the uniform grid through the first and last stamps, or within\n"
    "            the rounding of its printed digits; stamps printed so coarsely that a missing sample would not\n"
    "            show (1 ms at 1 kHz) are read only if every step is the same. --fs overrides it.\n"
    "  WAV, FLAC, AIFF, AU, CAF, Ogg (libsndfile)  rate from the header, channels channel_1..channel_N.\n"
    "            Integer PCM is a fraction of full scale (within +-1: a 16-bit sample / 32768) and needs\n"
    "            --scale (the recorder's full scale in --unit); float data are read as stored.\n"
    "  .mat      MATLAB v4, v5 (scipy.io.savemat) or v7.3: each real numeric vector is a channel named by\n"
    "            its variable; an N x C matrix M holds channels M_1..M_C (one per column, a sample per row;\n"
    "            --column M picks them all); a scalar fs (fs_hz, sample_rate, sampling_rate) or a time\n"
    "            vector t, time, time_s, ... gives the rate. Complex, logical, char, struct and cell\n"
    "            variables are not channels.\n"
    "--fs is needed when the file gives no rate; it overrides a CSV time column; a sound file's or .mat\n"
    "file's own rate it must match within 0.1 %.\n"
    "Units: each channel's from its name (Acc (g), a [m/s²], acc [mm/s^2], acc_g, a/(m/s^2)) or the units\n"
    "row: g (9.80665 m/s^2), m/s^2 (m/s², m/s2, m s^-2), cm/s^2, mm/s^2, um/s^2 (µm/s²), in/s^2, ft/s^2;\n"
    "a channel named in another unit (V, N, ...) is refused. Without one (a bare name, a sound file, a .mat\n"
    "variable) values are taken as m/s^2, and said so. --unit UNIT overrides the file: one unit for all\n"
    "channels, or one per channel in output order (--unit g,m/s2).\n"
    "--scale X multiplies every value: the physical value (in the channel's unit) of one file unit, or for\n"
    "integer PCM of full scale (a recorder whose full scale is 50 g: --scale 50 --unit g).\n"
    "Each choice made from the file (encoding, delimiter, decimal comma, header and units row, time column,\n"
    "sample rate, each channel's unit) is said in one line on stderr (not with --quiet).";
}  // namespace

int psd_command(const Args& args) {
  const std::string usage = kPsdUsage;
  po::options_description opts("options");
  std::string input, out;
  io::WelchOptions welch;
  io::SignalOptions signal;
  opts.add_options()("signal", po::value(&input)->required(), "input signal (CSV/text, WAV/FLAC/..., .mat)")(
      "fs", po::value<double>(), "sample rate (Hz); default: from the file")(
      "column", po::value(&signal.columns)->composing(),
      "channel(s) to analyse, repeatable or comma-separated (default: all)")(
      "unit", po::value(&signal.unit),
      "unit of the values (g, m/s2, mm/s2, ...), or one per channel (g,m/s2); default: from the file, else m/s2")(
      "scale", po::value<double>(),
      "physical units per file unit, or per full scale (integer PCM; needed there); default 1")(
      "time-column", po::value<std::string>(),
      "CSV column of time stamps, or none (default: the column named like a time)")(
      "skip-rows", po::value<long long>(), "CSV lines before the header (default: found from the data)")(
      "quiet,q", "do not say the choices made from the file")(
      "segment", po::value(&welch.segment)->default_value(1024, "1024"), "segment length (samples)")(
      "overlap", po::value(&welch.overlap)->default_value(0.5, "0.5"),
      "overlap as a fraction of the segment, in [0, 0.95]")(
      "window", po::value(&welch.window)->default_value("hann", "hann"),
      "hann or rectangular (rect), the spellings of the study key spectrum.window")("out,o", po::value(&out),
                                                                                    "output CSV")(
      "force", "replace an existing --out (and its metadata file) even if psd did not write it");
  po::positional_options_description pos;
  pos.add("signal", 1);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  if (vm.count("fs")) signal.fs = vm["fs"].as<double>();
  if (vm.count("scale")) signal.scale = vm["scale"].as<double>();
  if (vm.count("time-column")) signal.time_column = vm["time-column"].as<std::string>();
  if (vm.count("skip-rows")) signal.skip_rows = vm["skip-rows"].as<long long>();
  const io::SignalRequest request = io::signal_request(signal, io::OptionSpelling::command);
  spectral::WelchConfig cfg = io::welch_options(welch, io::OptionSpelling::command);

  if (!out.empty()) {  // an output that is the input is refused before the input is read
    std::error_code ec;
    if (std::filesystem::exists(out, ec) && std::filesystem::equivalent(out, input, ec))
      throw usage_error("--out " + out + " is also the input signal ('" + input +
                        "'); refusing to overwrite an input; choose another --out");
  }
  const io::SignalTable t = io::prepare_signal(input, request);
  if (!vm.count("quiet"))
    for (const auto& note : t.notes) std::cerr << "rollspec psd: " << note << "\n";
  if (t.samples() < cfg.segment)
    throw data_error(input + ": " + std::to_string(t.samples()) + " samples, fewer than one segment (--segment " +
                     std::to_string(cfg.segment) + ")");
  cfg.sample_rate = t.sample_rate;
  const spectral::WelchPlan plan(cfg);
  spectral::WelchWorkspace ws(cfg.segment);
  std::vector<std::vector<double>> psd(t.channels.size(), std::vector<double>(plan.n_freq()));
  for (std::size_t c = 0; c < t.channels.size(); ++c) {
    plan.psd(t.values[c].data(), t.samples(), psd[c].data(), ws);
    for (std::size_t k = 0; k < psd[c].size(); ++k)
      if (!std::isfinite(psd[c][k])) {
        double peak = 0.0;
        for (double v : t.values[c]) peak = std::max(peak, std::fabs(v));
        throw data_error(
            input + ": column '" + t.channels[c] + "': the PSD overflows a double (largest |value| " +
            io::number_text(peak) +
            " m/s^2); allowed: samples whose squares stay finite, e.g. |value| < 1e100 (rescale the unit)");
      }
  }

  const std::vector<std::string> titles = io::psd_column_titles(t.channels);
  std::ostringstream s;
  s << "frequency_hz";
  for (const auto& title : titles) s << "," << title;
  s << "\n";
  const auto f = plan.frequencies();
  std::string buf;
  for (std::size_t k = 0; k < f.size(); ++k) {
    buf = io::formatted("%.17g", f[k]);
    s << buf;
    for (const auto& col : psd) {
      buf = io::formatted("%.17g", col[k]);
      s << "," << buf;
    }
    s << "\n";
  }
  if (out.empty()) {
    std::cout << s.str();
    return 0;
  }
  io::PsdCsvMetadata m;
  m.sample_rate = t.sample_rate;
  m.rate_source = t.rate_source;
  m.segment = cfg.segment;
  m.overlap = cfg.overlap;
  m.window = cfg.window == spectral::Window::hann ? "hann" : "rect";  // the metadata's spelling (psd_csv.hpp)
  m.detrend = "mean";
  m.samples = t.samples();
  m.segments = plan.segments(t.samples());
  m.edof = plan.equivalent_dof(t.samples());
  m.scale = t.scale;
  m.source = input;
  m.source_hash = io::sha256_file(input);
  m.version = std::string(kVersion) + " (" + kGitSha + ")";
  std::vector<io::PsdColumnMetadata> columns;
  for (std::size_t c = 0; c < t.channels.size(); ++c) {
    const std::string title = titles[c];
    columns.push_back({title, title.substr(0, title.rfind(" [")), t.channels[c], t.units[c].text, t.units[c].where});
  }
  io::write_psd_csv(out, vm.count("force") > 0, {input}, s.str(), m, columns);
  return 0;
}

}  // namespace rollspec::cli
