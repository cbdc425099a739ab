// rollspec fit: the study parameters named by --vary estimated from a measured PSD by maximum
// likelihood of its band levels under compare's prediction-interval law (kernels/spectral D-27),
// with profile-likelihood intervals, the parameters' correlation and the fit's combined test; the
// work is src/fit/fit_study's, this file reads the options and prints.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "src/cli/commands.hpp"
#include "src/cli/fit_report.hpp"
#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/fit/fit_json.hpp"
#include "src/fit/fit_study.hpp"

namespace rollspec::cli {

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
  fit::FitRequest q;
  q.study = study, q.measurements = files, q.ats = ats, q.vary = vary_specs, q.averages = averages, q.sets = sets;
  q.sensor = sensor, q.column = column, q.journal = journal_path, q.fmin = fmin, q.fmax = fmax;
  if (vm.count("measured-position")) q.measured_position = measured_position;
  q.same_surface = vm.count("same-surface") > 0;
  const fit::FitOutcome answer = fit::fit_study(q);
  for (const std::string& line : answer.warnings) std::fprintf(stderr, "%s\n", line.c_str());
  std::fputs((format == "json" ? fit::fit_json(answer.report) : fit_text(answer.report)).c_str(), stdout);
  return 0;
}

}  // namespace rollspec::cli
