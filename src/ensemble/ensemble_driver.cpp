#include "src/ensemble/ensemble_driver.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <map>
#include <sstream>

#include "src/ensemble/checkpoint.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/rank_failure.hpp"
#include "src/ensemble/pairwise_tree.hpp"
#include "src/ensemble/progress.hpp"
#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::ensemble {

int ensemble_threads() { return omp_get_max_threads(); }

namespace {

void check_finite(const double* v, std::size_t n, std::uint64_t id, std::uint64_t seed) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) {
      std::ostringstream s;
      s << "realisation " << id << " (seed " << seed << ") produced a non-finite value (entry " << i
        << "); rerun it alone with --only " << id << " to investigate";
      throw data_error(s.str());
    }
}

// Runs realisations [lo, hi) in parallel and returns the chunk's [sum, sum of squares].
ChunkSums run_chunk(std::uint64_t lo, std::uint64_t hi, std::size_t n_values, const RealisationFn& realisation,
                    std::uint64_t seed, Progress& progress) {
  const auto count = static_cast<std::int64_t>(hi - lo);
  std::vector<double> rows(static_cast<std::size_t>(count) * n_values);
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t r = 0; r < count; ++r) {
    if (failure || stop_requested()) continue;
    try {
      double* row = rows.data() + static_cast<std::size_t>(r) * n_values;
      realisation(lo + static_cast<std::uint64_t>(r), omp_get_thread_num(), row);
      check_finite(row, n_values, lo + static_cast<std::uint64_t>(r), seed);
      progress.advance();
    } catch (...) {
#pragma omp critical(rollspec_ensemble_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  ChunkSums c;
  c.lo = lo;
  c.hi = hi;
  if (stop_requested()) return c;  // empty: not complete
  c.values = tree_sum(lo, hi, [&](std::uint64_t a, std::uint64_t b) {
    std::vector<double> v;
    if (b - a != 1) return v;
    const double* row = rows.data() + (a - lo) * n_values;
    v.resize(2 * n_values);
    for (std::size_t i = 0; i < n_values; ++i) {
      v[i] = row[i];
      v[n_values + i] = row[i] * row[i];
    }
    return v;
  });
  return c;
}

}  // namespace

EnsembleSums run_ensemble(const EnsembleConfig& cfg, std::size_t n_values, const RealisationFn& realisation) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t K = cfg.realisations, C = cfg.chunk_size;
  if (K == 0 || C == 0 || (C & (C - 1)) != 0)
    throw std::invalid_argument("ensemble needs K > 0 and a power-of-two chunk size");
  const auto rank = static_cast<std::uint64_t>(mpi_rank()), ranks = static_cast<std::uint64_t>(mpi_size());
  if (cfg.only >= 0) {
    const auto id = static_cast<std::uint64_t>(cfg.only);
    if (id >= K)
      throw usage_error("--only " + std::to_string(id) + ": the study has realisations 0.." + std::to_string(K - 1));
    EnsembleSums out;
    std::vector<double> v(n_values);
    if (rank == 0) {
      realisation(id, 0, v.data());
      check_finite(v.data(), n_values, id, cfg.seed);
    }
    out.sum = v;
    out.sum_sq.resize(n_values);
    for (std::size_t i = 0; i < n_values; ++i) out.sum_sq[i] = v[i] * v[i];
    out.count = out.computed = 1;
    out.only = cfg.only;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  }

  // This rank's chunks: a contiguous range [first, last) of chunk indices, so that its sums reduce
  // as they complete (TreeAccumulator) and memory does not grow with the number of chunks.
  const std::uint64_t n_chunks = (K + C - 1) / C;
  const auto chunk_start = [&](std::uint64_t r) { return n_chunks / ranks * r + std::min(r, n_chunks % ranks); };
  const std::uint64_t first = chunk_start(rank), last = chunk_start(rank + 1);
  const auto chunk_hi = [&](std::uint64_t lo) { return std::min(lo + C, K); };
  CheckpointStore store(cfg.checkpoint_dir, cfg.study_hash);
  std::uint64_t mine = 0, reused = 0;
  for (std::uint64_t i = first; i < last; ++i) mine += chunk_hi(i * C) - i * C;
  if (!cfg.checkpoint_dir.empty()) {
    // Every chunk file is checked now (a damaged one is refused before any work) but read only
    // when the reduction reaches it. Chunks of another size or count are recomputed.
    if (cfg.resume)
      store.scan(2 * n_values, [&](std::uint64_t lo, std::uint64_t hi) {
        if (lo % C == 0 && hi == chunk_hi(lo) && lo / C >= first && lo / C < last) reused += hi - lo;
      });
    mpi_barrier();
  }

  Progress progress("realisations", mine - reused, cfg.quiet, cfg.log_prefix);
  EnsembleSums out;
  TreeAccumulator acc;
  std::exception_ptr failure;
  try {
    for (std::uint64_t i = first; i < last; ++i) {
      const std::uint64_t lo = i * C, hi = chunk_hi(lo);
      if (cfg.resume && !cfg.checkpoint_dir.empty() && store.has(lo, hi)) {
        try {
          acc.push(lo, hi, store.read(lo, hi, 2 * n_values).values);
          continue;
        } catch (const DamagedChunk& e) {  // computed again (the same bits) and written over
          std::cerr << cfg.log_prefix << "rollspec: warning: " << e.what() << "; computing it again\n";
          reused -= hi - lo;
        }
      }
      ChunkSums c = run_chunk(lo, hi, n_values, realisation, cfg.seed, progress);
      if (c.values.empty()) break;  // stopped
      if (!cfg.checkpoint_dir.empty()) store.write(c);
      out.computed += hi - lo;
      acc.push(lo, hi, std::move(c.values));
    }
  } catch (...) {
    failure = std::current_exception();
  }
  rethrow_on_every_rank(failure, cfg.log_prefix + "stopped because another rank failed (see its message)");
  out.computed = sum_over_ranks(out.computed);
  if (any_rank(stop_requested())) {
    std::ostringstream s;
    const auto complete = sum_over_ranks(reused) + out.computed;
    s << cfg.log_prefix << "interrupted: " << complete << " of " << io::counted(K, "realisation")
      << (complete == 1 ? " is" : " are") << " complete";
    if (!cfg.checkpoint_dir.empty()) s << " and checkpointed in " << cfg.checkpoint_dir << "; finish with --resume";
    throw UserError(kExitInterrupted, s.str());
  }
  progress.finish();

  const auto reduce_start = std::chrono::steady_clock::now();
  std::map<std::uint64_t, ChunkSums> nodes;
  for (const auto& n : acc.nodes()) nodes[n.lo] = ChunkSums{n.lo, n.hi, n.values};
  const std::map<std::uint64_t, ChunkSums> all = gather_chunks(nodes, 2 * n_values);
  out.count = K;
  if (rank == 0) {
    const std::vector<double> total = tree_sum(0, K, [&](std::uint64_t a, std::uint64_t b) {
      const auto it = all.find(a);
      if (it != all.end() && it->second.hi == b) return it->second.values;
      return std::vector<double>();
    });
    out.sum.assign(total.begin(), total.begin() + static_cast<std::ptrdiff_t>(n_values));
    out.sum_sq.assign(total.begin() + static_cast<std::ptrdiff_t>(n_values), total.end());
  }
  out.reduce_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - reduce_start).count();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rollspec::ensemble
