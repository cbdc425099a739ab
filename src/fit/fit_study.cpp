#include "src/fit/fit_study.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "src/compare/measured_psd.hpp"
#include "src/error.hpp"
#include "src/fit/fit_journal.hpp"
#include "src/fit/fit_model.hpp"
#include "src/fit/fit_search.hpp"
#include "src/io/band_levels.hpp"
#include "src/io/number_text.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::fit {

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
    p.measurement = compare::read_measurement(p.path, col, -1, "fit");
    if (i + 1 == files.size()) column = col;
    points.push_back(std::move(p));
  }
  return points;
}

// The runs' own warnings (loss of contact, a band's heavy tail, a suspect key) gathered over the fit:
// how many runs gave any, and those of the run at the estimate, once each.
std::vector<std::string> run_warnings(const FitModel& model, const FitInputs& in) {
  std::vector<std::string> out;
  if (model.warned_runs() == 0) return out;
  bool at_estimate = false;
  for (std::size_t i = 0; i < in.points.size(); ++i) at_estimate = at_estimate || !model.last_warnings(i).empty();
  out.push_back("rollspec fit: " + std::to_string(model.warned_runs()) + " of " + std::to_string(model.runs()) +
                " runs of the study warned; " +
                (at_estimate ? "the run at the estimate warned:" : "the run at the estimate did not"));
  for (std::size_t i = 0; i < in.points.size(); ++i)
    for (const std::string& line : model.last_warnings(i))
      out.push_back("  " + (in.points[i].at.empty() ? std::string() : "(at " + in.points[i].at + ") ") + line);
  return out;
}

}  // namespace

FitOutcome fit_study(const FitRequest& q) {
  compare::check_frequency_range(q.fmin, q.fmax);
  FitInputs in;
  in.sensor = io::sensor_choice(q.sensor, q.measured_position);
  if (q.vary.empty()) throw usage_error("no --vary; allowed: section.key=lo:hi[:log], 1 to 3 times");
  if (q.vary.size() > 3)
    throw usage_error("--vary given " + std::to_string(q.vary.size()) + " times; allowed: 1 to 3 keys");
  for (const auto& s : q.vary) {
    in.vary.push_back(parse_vary(s));
    for (std::size_t i = 0; i + 1 < in.vary.size(); ++i)
      if (in.vary[i].key == in.vary.back().key) throw usage_error("--vary " + in.vary.back().key + " given twice");
  }
  for (const auto& s : q.sets)
    for (const auto& v : in.vary)
      if (s.rfind(v.key + "=", 0) == 0)
        throw usage_error("--set " + clip(s) + ": " + v.key + " is varied by --vary; allowed: one of the two");
  if (!std::filesystem::exists(q.study)) throw missing_input(q.study + ": no such study file");
  in.study = q.study, in.sets = q.sets, in.fmin = q.fmin, in.fmax = q.fmax;
  in.same_surface = q.same_surface;
  FitOutcome answer;
  answer.column = q.column;
  in.points = fit_points(q.measurements, q.ats, q.averages, in, answer.column);
  check_fit_keys(in);

  const TempDir temp;
  std::unique_ptr<FitJournal> journal;
  if (!q.journal.empty()) journal = std::make_unique<FitJournal>(q.journal, fit_journal_key(in, answer.column));
  FitModel model(in, temp.path, journal.get());
  try {
    answer.report = fit_search(model, in);
  } catch (const UserError& e) {
    if (e.exit_code() != kExitInterrupted) throw;
    // The ensemble's message names a checkpoint in the temporary directory, which is gone now.
    throw UserError(kExitInterrupted,
                    "interrupted after " + std::to_string(model.runs()) + " study runs; " +
                        (q.journal.empty() ? "nothing was kept: give --journal FILE to keep the evaluations "
                                             "of a fit that may be interrupted"
                                           : "the finished evaluations are in " + q.journal +
                                                 ": the same command with the same --journal goes on from them"));
  }
  answer.warnings = run_warnings(model, in);
  return answer;
}

}  // namespace rollspec::fit
