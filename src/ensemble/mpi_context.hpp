#pragma once
// MPI for ensembles (optional build, -DROLLSPEC_MPI=ON). Each rank runs a contiguous range of
// chunks and reduces it as chunks complete (TreeAccumulator); each rank sends those few sums to rank 0, which adds them
// along the same pairwise tree as a single process (pairwise_tree.hpp), so the result data are bitwise identical for
// any rank count. Without MPI every function here is the one-process identity.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "src/ensemble/checkpoint.hpp"

namespace rollspec::ensemble {

class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

int mpi_rank();
int mpi_size();
bool mpi_enabled();
void mpi_barrier();
bool any_rank(bool flag);  // logical OR over ranks
std::uint64_t sum_over_ranks(std::uint64_t v);
// Rank 0 receives every rank's chunks (its own included); other ranks get an empty map.
std::map<std::uint64_t, ChunkSums> gather_chunks(const std::map<std::uint64_t, ChunkSums>& mine, std::size_t n_values);
// Every rank receives every rank's rows (keyed by id, all of length row_size).
std::map<std::uint64_t, std::vector<double>> allgather_rows(const std::map<std::uint64_t, std::vector<double>>& mine,
                                                            std::size_t row_size);
std::string rank_prefix();  // "[rank r/n] " under MPI with n > 1, else ""

}  // namespace rollspec::ensemble
