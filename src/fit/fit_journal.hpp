#pragma once
// rollspec fit --journal FILE: every evaluation's key (the parameter vector, and for a run with its own
// seed that run's index) and what the fit read from it (-ln L; or, where common random numbers do not
// hold, the run's band logs and covariance, kernels/spectral D-27i), so a fit interrupted (SIGINT) and
// run again with the same --journal reruns no finished evaluation. The search is deterministic, so the
// rerun asks for the same evaluations in the same order and finds them here. The file starts with a key
// of everything the values depend on, so the journal of another fit is refused, never reused. It is made
// whole (a temporary renamed onto it), then each evaluation is appended as one line "key ; values" by one
// write and synced; a last line without its newline (a crash or a full disk mid-write) is torn and
// discarded, and the file is rewritten without it before anything is appended.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "src/fit/fit_model.hpp"

namespace rollspec::fit {

// FNV-1a over the study's text, each measurement file's bytes, every --set/--at/--vary, the sensor,
// the band range, M, the question (--same-surface) and the build (io::code_identity): a different input
// or build gives another key.
std::uint64_t fit_journal_key(const FitInputs& in, const std::string& column);

class FitJournal {
 public:
  // Reads `path` if it exists: refused (exit 73) at once if it is not a regular file (a FIFO would
  // block, a device never end) or is not a fit journal or has another key.
  FitJournal(std::string path, std::uint64_t key);
  bool find(const std::vector<double>& key, std::vector<double>& values) const;
  void record(const std::vector<double>& key, const std::vector<double>& values);
  std::size_t size() const { return entries_.size(); }

 private:
  std::string path_;
  std::uint64_t key_;
  std::vector<std::pair<std::vector<double>, std::vector<double>>> order_;  // as evaluated
  std::map<std::vector<double>, std::vector<double>> entries_;
  bool whole_ = false;  // the file holds exactly the header and order_ (else it is rewritten first)

  void rewrite();
  void append(const std::string& line);
};

}  // namespace rollspec::fit
