#pragma once
// rollspec fit's model: the study run at a point of the parameters' box, at each operating point (its
// --at keys set), its band levels read back, and ln L of each point's measured band levels under the
// prediction-interval law (kernels/spectral D-27), summed over the points (independent measurements).
// Every run keeps the study's seed, so realisation i draws the same numbers at every parameter value
// (common random numbers) and ln L is smooth in the parameters.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "src/compare/combined_test.hpp"
#include "src/cli/measured_psd.hpp"
#include "src/io/band_levels.hpp"

namespace rollspec::cli {

using compare::ChosenBands;
using compare::CombinedTest;
using compare::chosen_bands;
using compare::combined_test;

// --vary section.key=lo:hi[:log]: the range searched, mapped onto u in [0, 1] (log: geometric).
struct VaryRange {
  std::string key;
  double lo = 0.0, hi = 1.0;
  bool log = false;
  double value(double u) const;
  double unit(double value) const;
};

// Refuses (exit 64) a malformed spec, lo >= hi, a non-finite end, or log with lo <= 0.
VaryRange parse_vary(const std::string& spec);

// One measurement and the operating point it was taken at (--at keys set in its runs only).
struct FitPoint {
  std::string path, at;           // at: "section.key=value,..." as given ("" for none)
  std::vector<std::string> sets;  // at, split into --set values
  Measurement measurement;
  double records = 1.0;  // M
};

// Refuses (exit 64) an --at that is not section.key=value[,section.key=value ...], or names a key twice.
std::vector<std::string> parse_at(const std::string& at);

struct FitInputs {
  std::string study;
  io::SensorChoice sensor;
  std::vector<std::string> sets;  // --set passed on to every run
  std::vector<VaryRange> vary;
  std::vector<FitPoint> points;
  double fmin = 0.0, fmax = 0.0;
};

// Refuses, before the first run, a study or --at point that does not load, and a --vary range outside
// its key's type or range or whose ends the study refuses (fit_keys.cpp).
void check_fit_keys(const FitInputs& in);

// Lookup of -ln L at parameter values already evaluated (a resumed fit's journal); null: none.
class FitJournal;

class FitModel {
 public:
  FitModel(const FitInputs& in, std::string temp_dir, FitJournal* journal = nullptr);
  // -ln L at u, summed over the points (cached, and journalled: a value already known is not run again).
  double negative_log_likelihood(const std::vector<double>& u);
  // D-26's combined test of each point's measurement against its run at u.
  std::vector<CombinedTest> tests_at(const std::vector<double>& u);
  int runs() const { return runs_; }
  int reused() const { return reused_; }  // values taken from the journal
  std::size_t bands() const;              // over all points
  std::size_t bands(std::size_t point) const { return band_[point].size(); }
  std::uint64_t realisations() const { return realisations_; }
  // The warnings of the point's latest run (after tests_at(u): the run at u), and how many runs warned.
  const std::vector<std::string>& last_warnings(std::size_t point) const { return last_warnings_[point]; }
  int warned_runs() const { return warned_runs_; }

 private:
  io::BandLevels run_at(std::size_t point, const std::vector<double>& u);
  void choose_bands(std::size_t point, const io::BandLevels& b);
  void check_band_rules(std::size_t point, const io::BandLevels& b, const std::vector<double>& psd, double df) const;

  const FitInputs& in_;
  std::string temp_dir_;
  FitJournal* journal_;
  std::map<std::vector<double>, double> cache_;
  std::vector<std::vector<std::size_t>> band_;           // per point: indices of the compared bands in the result
  std::vector<std::vector<double>> measured_db_;         // per point: their measured levels
  std::vector<std::vector<std::string>> last_warnings_;  // per point
  std::uint64_t realisations_ = 0;
  int runs_ = 0, reused_ = 0, warned_runs_ = 0;
};

}  // namespace rollspec::cli
