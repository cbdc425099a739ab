// rollspec fit: the study parameters named by --vary estimated from a measured PSD by maximum
// likelihood of its band levels under compare's prediction-interval law (kernels/spectral D-27),
// with profile-likelihood intervals, the parameters' correlation and the fit's combined test.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "kernels/spectral/fit_search.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/fit_report.hpp"
#include "src/fit/fit_journal.hpp"
#include "src/fit/fit_model.hpp"
#include "src/fit/fit_search.hpp"
#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::cli {

using compare::read_measurement;
using fit::check_fit_keys;
using fit::fit_journal_key;
using fit::fit_search;
using fit::FitInputs;
using fit::FitJournal;
using fit::FitModel;
using fit::FitPoint;
using fit::parse_at;
using fit::parse_vary;

namespace {

using io::number_text;

// A directory for the runs' result files, removed with everything in it when the fit ends.
struct TempDir {
  std::string path;
  TempDir() {
    // $TMPDIR as POSIX reads it (unset or empty: /tmp), checked here: the library's lookup throws
    // on a $TMPDIR that is not a directory, which would end in an internal error.
    const char* env = std::getenv("TMPDIR");
    const std::string base = env && *env ? env : "/tmp";
    std::error_code ec;
    if (!std::filesystem::is_directory(base, ec))
      throw cannot_create("TMPDIR = " + base + " is not a directory (" +
                          (std::filesystem::exists(std::filesystem::symlink_status(base, ec)) ? "another kind of file"
                                                                                              : "it does not exist") +
                          "); allowed: a writable directory for the fit's temporary results");
    std::string pattern = (std::filesystem::path(base) / "rollspec-fit-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw cannot_create("cannot create a temporary directory under " + base + " (set TMPDIR)");
    path = pattern;
    io::register_temp_dir(path);  // an interrupt (which ends the process without unwinding) removes it too
  }
  ~TempDir() {
    io::unregister_temp_dir(path);
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

// The measurements and their operating points: MEASUREMENT / --measurement FILE (repeatable, in order),
// each paired with the --at of the same rank; --measured-averages once for all or once per measurement.
std::vector<FitPoint> fit_points(const std::vector<std::string>& files, const std::vector<std::string>& ats,
                                 const std::vector<double>& averages, const FitInputs& in, std::string& column) {
  if (files.empty()) throw usage_error("no measurement; allowed: MEASUREMENT.csv or --measurement FILE --at KEYS");
  if (!(ats.empty() && files.size() == 1) && ats.size() != files.size())
    throw usage_error(std::to_string(files.size()) + " measurements and " + std::to_string(ats.size()) +
                      " --at; allowed: one --at per measurement, in the same order (none for a single measurement)");
  if (averages.size() != 1 && averages.size() != files.size())
    throw usage_error("--measured-averages given " + std::to_string(averages.size()) + " times for " +
                      std::to_string(files.size()) + " measurements; allowed: once for all, or once per measurement");
  std::vector<FitPoint> points;
  for (std::size_t i = 0; i < files.size(); ++i) {
    FitPoint p;
    p.path = files[i];
    p.records = averages[averages.size() == 1 ? 0 : i];
    if (!(p.records >= 1.0 && std::isfinite(p.records)))
      throw usage_error("--measured-averages " + number_text(p.records) +
                        ": allowed: a finite count >= 1 of independent records");
    if (!ats.empty()) p.at = ats[i], p.sets = parse_at(ats[i]);
    for (const auto& kv : p.sets) {
      const std::string key = kv.substr(0, kv.find('='));
      for (const auto& v : in.vary)
        if (key == v.key)
          throw usage_error("--at " + clip(p.at) + ": " + key + " is varied by --vary; allowed: one of the two");
      for (const auto& s : in.sets)
        if (s.substr(0, s.find('=')) == key)
          throw usage_error("--at " + clip(p.at) + ": " + key + " is also given by --set " + clip(s) +
                            "; allowed: one of the two");
    }
    for (std::size_t j = 0; j < i; ++j)
      if (points[j].at == p.at && points[j].path == p.path)
        throw usage_error("--measurement " + clip(p.path) + " given twice at the same point");
    std::string col = column;
    p.measurement = read_measurement(p.path, col, -1, "fit");
    if (i + 1 == files.size()) column = col;
    points.push_back(std::move(p));
  }
  return points;
}

// The runs' own warnings (loss of contact, a band's heavy tail, a suspect key) gathered over the fit:
// how many runs gave any, and those of the run at the estimate, once each.
void say_run_warnings(const FitModel& model, const FitInputs& in) {
  if (model.warned_runs() == 0) return;
  bool at_estimate = false;
  for (std::size_t i = 0; i < in.points.size(); ++i) at_estimate = at_estimate || !model.last_warnings(i).empty();
  std::fprintf(stderr, "rollspec fit: %d of %d runs of the study warned; %s\n", model.warned_runs(), model.runs(),
               at_estimate ? "the run at the estimate warned:" : "the run at the estimate did not");
  for (std::size_t i = 0; i < in.points.size(); ++i)
    for (const std::string& line : model.last_warnings(i))
      std::fprintf(stderr, "  %s%s\n", in.points[i].at.empty() ? "" : ("(at " + in.points[i].at + ") ").c_str(),
                   line.c_str());
}

}  // namespace

const char* const kFitUsage =
    "usage: rollspec fit STUDY.ini MEASUREMENT.csv --vary section.key=lo:hi[:log] [--vary ...] --measured-averages M\n"
    "       rollspec fit STUDY.ini --measurement M1.csv --at section.key=value[,...] --measurement M2.csv --at ...\n"
    "                    --vary ... --measured-averages M [--measured-averages M2 ...]\n"
    "                    [--set section.key=value ...] [--sensor NAME|K | --measured-position X] [--same-surface]\n"
    "                    [--column NAME] [--fmin HZ] [--fmax HZ] [--journal FILE] [--format text|json]\n"
    "\n"
    "Estimates the 1 to 3 study keys named by --vary (each searched in [lo, hi], `log`: on a log scale) from\n"
    "a measured PSD (as `rollspec compare` reads it) that averages M independent records: the values that\n"
    "maximise the likelihood of the measured third-octave band levels under compare's prediction law\n"
    "(kernels/spectral D-27). Several measurements, each taken at its operating point (--at: the keys set\n"
    "in its runs only, e.g. ball.speed=3), are fitted jointly: the varied keys are shared and ln L is the\n"
    "sum over the points. Three runs at the start say whether common random numbers hold (D-27i): if they\n"
    "do, every evaluation runs the study with its own seed and ln L is smooth; if not (impacts make the\n"
    "runs chaotic in the keys), runs with seeds of their own are smoothed by a quadratic response surface,\n"
    "and where no surface holds the interval the estimate is given without one, with the reason. A random\n"
    "contact table's error enters the likelihood (V = G S G + 2 Sigma_T: a rig with another surface, D-31;\n"
    "--same-surface: the table's own surface), estimated once at the start and held.\n"
    "Prints each key's estimate and 95 % profile-likelihood interval, the keys' correlation (from the\n"
    "Hessian of ln L), the combined test of the best fit corrected for the fitted keys (D-27j; several\n"
    "points: each point's and Fisher's combination of them), compare's uncorrected test, and the number of\n"
    "study runs. A key the measurements cannot identify (its likelihood flat over its range) is refused,\n"
    "named. --journal FILE records every evaluation: a fit interrupted and run again with the same\n"
    "--journal reruns none it finished (a journal of another study, measurement, option or build is\n"
    "refused).";

int fit_command(const Args& args) {
  po::options_description opts("options");
  std::string study, format = "text", sensor, column, journal_path;
  std::vector<std::string> vary_specs, sets, files, ats;
  std::vector<double> averages;
  double fmin = 0.0, fmax = INFINITY, measured_position = NAN;
  opts.add_options()("study", po::value(&study)->required(), "study (INI)")(
      "measurement", po::value(&files), "measured PSD (CSV); repeatable, each with its --at")(
      "at", po::value(&ats), "section.key=value[,...]: the operating point of the measurement of the same rank")(
      "vary", po::value(&vary_specs)->required(), "section.key=lo:hi[:log], 1 to 3 times")(
      "measured-averages", po::value(&averages)->required(),
      "independent records averaged into the measurement (once, or once per measurement)")(
      "set", po::value(&sets), "section.key=value for every run")(
      "sensor", po::value(&sensor),
      "sensor name, or the number K of sensor_K (1-based; default: sensor_mean if present, else the first)")(
      "measured-position", po::value(&measured_position),
      "where the measurement was taken (m): the sensor nearest it, as compare picks it")(
      "column", po::value(&column), "PSD column of the measurement CSV")(
      "fmin", po::value(&fmin)->default_value(0.0, "0"), "lowest band edge (Hz)")(
      "fmax", po::value(&fmax)->default_value(INFINITY, "inf"), "highest band edge (Hz)")(
      "journal", po::value(&journal_path), "record evaluations here; reuse those of an interrupted identical fit")(
      "same-surface", "the measurement was taken on the very surface the model's table was built on (D-31)")(
      "format", po::value(&format)->default_value("text", "text"), "text or json");
  po::positional_options_description pos;
  pos.add("study", 1).add("measurement", 1);
  po::variables_map vm;
  if (!parse_options(args, kFitUsage, opts, pos, vm)) return 0;
  if (format != "text" && format != "json") throw usage_error("--format " + clip(format) + ": allowed: text or json");
  if (!(fmin >= 0.0) || std::isinf(fmin))
    throw usage_error("--fmin " + number_text(fmin) + ": allowed: a finite frequency >= 0 Hz");
  if (!(fmax > fmin))
    throw usage_error("--fmax " + number_text(fmax) + ": allowed: a frequency above --fmin (" + number_text(fmin) +
                      " Hz)");
  FitInputs in;
  in.sensor = io::sensor_choice(
      sensor, vm.count("measured-position") ? std::optional<double>(measured_position) : std::nullopt);
  if (vary_specs.size() > 3)
    throw usage_error("--vary given " + std::to_string(vary_specs.size()) + " times; allowed: 1 to 3 keys");
  for (const auto& s : vary_specs) {
    in.vary.push_back(parse_vary(s));
    for (std::size_t i = 0; i + 1 < in.vary.size(); ++i)
      if (in.vary[i].key == in.vary.back().key) throw usage_error("--vary " + in.vary.back().key + " given twice");
  }
  for (const auto& s : sets)
    for (const auto& v : in.vary)
      if (s.rfind(v.key + "=", 0) == 0)
        throw usage_error("--set " + clip(s) + ": " + v.key + " is varied by --vary; allowed: one of the two");
  if (!std::filesystem::exists(study)) throw missing_input(study + ": no such study file");
  in.study = study, in.sets = sets, in.fmin = fmin, in.fmax = fmax;
  in.same_surface = vm.count("same-surface") > 0;
  in.points = fit_points(files, ats, averages, in, column);
  check_fit_keys(in);

  const TempDir temp;
  std::unique_ptr<FitJournal> journal;
  if (!journal_path.empty()) journal = std::make_unique<FitJournal>(journal_path, fit_journal_key(in, column));
  FitModel model(in, temp.path, journal.get());
  FitReport report;
  try {
    report = fit_search(model, in);
  } catch (const UserError& e) {
    if (e.exit_code() != kExitInterrupted) throw;
    // The ensemble's message names a checkpoint in the temporary directory, which is gone now.
    throw UserError(kExitInterrupted,
                    "interrupted after " + std::to_string(model.runs()) + " study runs; " +
                        (journal_path.empty() ? "nothing was kept: give --journal FILE to keep the evaluations "
                                                "of a fit that may be interrupted"
                                              : "the finished evaluations are in " + journal_path +
                                                    ": the same command with the same --journal goes on from them"));
  }
  say_run_warnings(model, in);
  std::fputs((format == "json" ? fit_json(report) : fit_text(report)).c_str(), stdout);
  return 0;
}

}  // namespace rollspec::cli
