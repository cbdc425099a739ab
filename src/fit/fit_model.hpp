#pragma once
// rollspec fit's model: the study run at a point of the parameters' box, at each operating point (its
// --at keys set), its band levels read back, and ln L of each point's measured band levels under the
// prediction-interval law (kernels/spectral D-27), summed over the points (independent measurements).
// The runs at the start point say whether common random numbers hold (D-27i): if they do, every run
// keeps the study's seed, realisation i draws the same numbers at every parameter value and ln L is
// smooth in the parameters; if not, the fit runs replicates with seeds of their own and smooths them
// (fit_surface.hpp). A random contact table's error (D-31) is estimated once, by the start point's run,
// and held for the whole fit; every later run leaves it out ([stiffness] table_error = none).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "src/compare/combined_test.hpp"
#include "src/compare/measured_psd.hpp"
#include "src/io/band_levels.hpp"

namespace rollspec::fit {

using compare::chosen_bands;
using compare::ChosenBands;
using compare::combined_test;
using compare::CombinedTest;
using compare::Measurement;

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
  bool same_surface = false;  // --same-surface: the table's own surface (no table term, D-31)
  io::SensorChoice sensor;
  std::vector<std::string> sets;  // --set passed on to every run
  std::vector<VaryRange> vary;
  std::vector<FitPoint> points;
  double fmin = 0.0, fmax = std::numeric_limits<double>::infinity();  // the command's defaults: every band
};

// Refuses, before the first run, a study or --at point that does not load, and a --vary range outside
// its key's type or range or whose ends the study refuses (fit_keys.cpp).
void check_fit_keys(const FitInputs& in);

// Lookup of evaluations already made (a resumed fit's journal); null: none.
class FitJournal;

// One point's run as the likelihood reads it: its compared bands only.
struct PointRun {
  std::vector<double> log_mean;  // ln of the model's mean band power
  std::vector<double> cov;       // S: the realisations' covariance of the band logs, p x p
  std::uint64_t realisations = 0;
};

// The largest share of independent runs' variance the probe's second difference may have for the fit to
// take ln L of the study's seed as smooth (D-27i a): above it the noise of -ln L between neighbouring
// evaluations is a sizeable part of the 1.92 that bounds a profile interval.
constexpr double kCoherenceLimit = 0.05;
// The probe's step in u (each key's range is [0, 1]).
constexpr double kCoherenceStep = 0.01;

// Whether common random numbers hold (D-27i a): each point's band logs at the start u0 and u0 +- h (every
// key moved), their second difference against its variance between independent runs.
struct Coherence {
  double step = 0.0;
  double incoherent_share = 0.0;  // the largest over the points
  bool holds = true;
};

// The table term of one point (D-31): what the fit asks, and c_T Sigma_T of its compared bands.
struct PointTable {
  bool random = false;             // the study's contact table is random (its error can be estimated)
  double factor = 0.0;             // c_T: 2 (another surface), 0 (--same-surface, or not estimated)
  std::vector<double> covariance;  // c_T Sigma_T, p x p, natural log squared (empty: none)
  io::BandLevels held;             // the start point's run, whose table fields every verdict carries
  std::string question;            // one sentence: the question asked, and how the term was had
};

class FitModel {
 public:
  FitModel(const FitInputs& in, std::string temp_dir, FitJournal* journal = nullptr);
  // The start point's runs: each point's bands, its table term, and whether common random numbers
  // hold (three runs per point, never journalled: a resumed fit makes them again).
  Coherence probe(const std::vector<double>& start, double step);
  // -ln L at u with the study's seed, summed over the points (cached, and journalled).
  double negative_log_likelihood(const std::vector<double>& u);
  // ln m of each point's compared bands at u with the study's seed (cached with -ln L's runs).
  std::vector<std::vector<double>> log_means(const std::vector<double>& u);
  // Each point's run at u with a seed of its own, the index-th of the fit (journalled).
  std::vector<PointRun> replicate(const std::vector<double>& u, std::uint64_t index);
  // ln L of one point's run (D-27a with the terms of band_test.hpp's LikelihoodTerms; the point's table
  // term is added here). Throws std::invalid_argument where the model has no power in a band.
  double point_log_likelihood(std::size_t point, const PointRun& run, double mean_share, double dof) const;
  // The run of each point at u with the study's seed, its table fields those held from the start.
  std::vector<io::BandLevels> runs_at(const std::vector<double>& u);
  const PointTable& table(std::size_t point) const { return table_[point]; }
  const std::vector<std::size_t>& band(std::size_t point) const { return band_[point]; }
  const std::vector<double>& measured_db(std::size_t point) const { return measured_db_[point]; }
  int runs() const { return runs_; }
  int reused() const { return reused_; }  // evaluations taken from the journal
  std::size_t bands() const;              // over all points
  std::size_t bands(std::size_t point) const { return band_[point].size(); }
  std::uint64_t realisations() const { return realisations_; }
  // The warnings of the point's latest run (after runs_at(u): the run at u), and how many runs warned.
  const std::vector<std::string>& last_warnings(std::size_t point) const { return last_warnings_[point]; }
  int warned_runs() const { return warned_runs_; }

 private:
  // psd, df: the row's mean PSD and bin width, read from this run's result (the start's, for the band rules).
  io::BandLevels run_at(std::size_t point, const std::vector<double>& u, const std::vector<std::string>& extra,
                        std::vector<double>* psd = nullptr, double* df = nullptr);
  io::BandLevels first_run(std::size_t point, const std::vector<double>& u);
  std::vector<std::string> later_sets(std::size_t point) const;
  PointRun point_run(std::size_t point, const io::BandLevels& b) const;
  std::vector<PointRun> crn_runs(const std::vector<double>& u);
  void hold_table(std::size_t point, const io::BandLevels& b, const std::string& refused);
  void choose_bands(std::size_t point, const io::BandLevels& b);
  void check_band_rules(std::size_t point, const io::BandLevels& b, const std::vector<double>& psd, double df) const;

  const FitInputs& in_;
  std::string temp_dir_;
  FitJournal* journal_;
  std::map<std::vector<double>, double> cache_;
  std::map<std::vector<double>, std::vector<PointRun>> crn_;  // the study seed's runs, by u
  std::vector<std::vector<std::size_t>> band_;                // per point: indices of the compared bands in the result
  std::vector<std::vector<double>> measured_db_;              // per point: their measured levels
  std::vector<PointTable> table_;                             // per point
  std::vector<std::vector<std::string>> last_warnings_;       // per point
  std::uint64_t realisations_ = 0, seed_ = 0;                 // seed_: the study's, from the start point's result
  int runs_ = 0, reused_ = 0, warned_runs_ = 0;
};

}  // namespace rollspec::fit
