#pragma once
// The ensemble driver: runs realisations 0..K-1 of a scene in OpenMP threads, chunk by chunk,
// and sums their per-realisation values (and squares) along the fixed pairwise tree of
// pairwise_tree.hpp. Each realisation draws only from Philox streams keyed by (seed, id), so
// the sums are bitwise identical for any thread count, schedule, chunk placement or restart.
// Chunk sums are added as chunks complete (TreeAccumulator: at most about 2 log2(chunks) partial
// sums are kept, on a run and on --resume alike). Completed chunks are checkpointed;
// SIGINT/SIGTERM stop cleanly with exit 130 and --resume recomputes only missing chunks. A realisation that produces
// NaN/Inf stops the run, naming its id and the seed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rollspec::ensemble {

struct EnsembleConfig {
  std::uint64_t realisations = 1;
  std::uint64_t chunk_size = 16;  // a power of two
  std::uint64_t seed = 0;
  std::string checkpoint_dir;  // empty: no checkpoints
  std::uint64_t study_hash = 0;
  bool resume = false;
  bool quiet = false;
  std::string log_prefix;  // e.g. "[rank 1] "
  std::int64_t only = -1;  // >= 0: run just this realisation (no checkpoints), to investigate it
};

struct EnsembleSums {
  std::vector<double> sum, sum_sq;  // over realisations, per value (on rank 0 only under MPI)
  std::uint64_t count = 0;
  std::uint64_t computed = 0;  // realisations computed in this run (the rest came from checkpoints)
  double seconds = 0.0;
  double reduce_seconds = 0.0;  // gathering chunk sums to rank 0 and adding them (part of `seconds`)
  std::int64_t only = -1;       // >= 0: the one realisation these sums hold (--only)

  // Ensemble mean of value i, and the standard deviation of one realisation's value (K - 1).
  double mean(std::size_t i) const { return sum[i] / static_cast<double>(count); }
  double std_dev(std::size_t i) const {
    const double K = static_cast<double>(count), m = mean(i);
    return count > 1 ? std::sqrt(std::max(0.0, (sum_sq[i] - K * m * m) / (K - 1.0))) : 0.0;
  }
};

// Fills values[0..n_values) for realisation `id` using the workspace of thread `thread`.
using RealisationFn = std::function<void(std::uint64_t id, int thread, double* values)>;

// Threads available to realisations (one workspace each).
int ensemble_threads();

EnsembleSums run_ensemble(const EnsembleConfig& config, std::size_t n_values, const RealisationFn& realisation);

}  // namespace rollspec::ensemble
