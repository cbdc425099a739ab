#include "src/ensemble/mpi_context.hpp"

#ifdef ROLLSPEC_WITH_MPI
#include <mpi.h>
#endif

#include <vector>

namespace rollspec::ensemble {

#ifdef ROLLSPEC_WITH_MPI

MpiSession::MpiSession(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
}
MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

bool mpi_enabled() {
  int init = 0;
  MPI_Initialized(&init);
  return init != 0;
}
int mpi_rank() {
  int r = 0;
  if (mpi_enabled()) MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}
int mpi_size() {
  int s = 1;
  if (mpi_enabled()) MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}
void mpi_barrier() {
  if (mpi_enabled()) MPI_Barrier(MPI_COMM_WORLD);
}
bool any_rank(bool flag) {
  if (!mpi_enabled()) return flag;
  int in = flag ? 1 : 0, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out != 0;
}

std::uint64_t sum_over_ranks(std::uint64_t v) {
  if (!mpi_enabled()) return v;
  unsigned long long in = v, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return out;
}

std::map<std::uint64_t, ChunkSums> gather_chunks(const std::map<std::uint64_t, ChunkSums>& mine, std::size_t n_values) {
  if (mpi_size() == 1) return mine;
  // Each chunk travels as [lo, hi, values...] in doubles (ids < 2^53 are exact).
  const std::size_t record = 2 + n_values;
  std::vector<double> send;
  for (const auto& [lo, c] : mine) {
    send.push_back(static_cast<double>(c.lo));
    send.push_back(static_cast<double>(c.hi));
    send.insert(send.end(), c.values.begin(), c.values.end());
  }
  const int size = mpi_size(), rank = mpi_rank();
  int count = static_cast<int>(send.size());
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size));
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> recv;
  if (rank == 0) {
    int total = 0;
    for (int r = 0; r < size; ++r)
      displs[static_cast<std::size_t>(r)] = total, total += counts[static_cast<std::size_t>(r)];
    recv.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(send.data(), count, MPI_DOUBLE, recv.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  std::map<std::uint64_t, ChunkSums> all;
  for (std::size_t off = 0; off + record <= recv.size(); off += record) {
    ChunkSums c;
    c.lo = static_cast<std::uint64_t>(recv[off]);
    c.hi = static_cast<std::uint64_t>(recv[off + 1]);
    c.values.assign(recv.begin() + static_cast<std::ptrdiff_t>(off + 2),
                    recv.begin() + static_cast<std::ptrdiff_t>(off + record));
    all[c.lo] = std::move(c);
  }
  return all;
}

std::map<std::uint64_t, std::vector<double>> allgather_rows(const std::map<std::uint64_t, std::vector<double>>& mine,
                                                            std::size_t row_size) {
  if (mpi_size() == 1) return mine;
  std::vector<double> send;
  for (const auto& [id, row] : mine) {
    send.push_back(static_cast<double>(id));
    send.insert(send.end(), row.begin(), row.end());
  }
  const int size = mpi_size();
  int count = static_cast<int>(send.size());
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size));
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < size; ++r)
    displs[static_cast<std::size_t>(r)] = total, total += counts[static_cast<std::size_t>(r)];
  std::vector<double> recv(static_cast<std::size_t>(total));
  MPI_Allgatherv(send.data(), count, MPI_DOUBLE, recv.data(), counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  std::map<std::uint64_t, std::vector<double>> all;
  for (std::size_t off = 0; off + row_size + 1 <= recv.size(); off += row_size + 1)
    all[static_cast<std::uint64_t>(recv[off])].assign(recv.begin() + static_cast<std::ptrdiff_t>(off + 1),
                                                      recv.begin() + static_cast<std::ptrdiff_t>(off + 1 + row_size));
  return all;
}

#else

std::map<std::uint64_t, std::vector<double>> allgather_rows(const std::map<std::uint64_t, std::vector<double>>& mine,
                                                            std::size_t) {
  return mine;
}

MpiSession::MpiSession(int*, char***) {}
MpiSession::~MpiSession() = default;
bool mpi_enabled() { return false; }
int mpi_rank() { return 0; }
int mpi_size() { return 1; }
void mpi_barrier() {}
bool any_rank(bool flag) { return flag; }
std::uint64_t sum_over_ranks(std::uint64_t v) { return v; }
std::map<std::uint64_t, ChunkSums> gather_chunks(const std::map<std::uint64_t, ChunkSums>& mine, std::size_t) {
  return mine;
}

#endif

std::string rank_prefix() {
  return mpi_size() > 1 ? "[rank " + std::to_string(mpi_rank()) + "/" + std::to_string(mpi_size()) + "] " : "";
}

}  // namespace rollspec::ensemble
