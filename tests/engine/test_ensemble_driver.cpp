// The ensemble driver: the pairwise tree, chunk-size invariance, NaN detection, --only.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "src/ensemble/ensemble_driver.hpp"
#include "src/ensemble/pairwise_tree.hpp"
#include "src/error.hpp"

using namespace rollspec;
using namespace rollspec::ensemble;

namespace {
// Values whose sums depend on the order of addition (large and small magnitudes).
void values_of(std::uint64_t id, int, double* v) {
  v[0] = 1e16 * std::sin(static_cast<double>(id) * 1.7) + 1.0 / (1.0 + static_cast<double>(id));
  v[1] = std::cos(static_cast<double>(id));
}

std::vector<double> bits(const EnsembleSums& s) {
  std::vector<double> out = s.sum;
  out.insert(out.end(), s.sum_sq.begin(), s.sum_sq.end());
  return out;
}
}  // namespace

TEST_CASE("every aligned chunk is a node of the pairwise tree, so chunk size never changes the bits") {
  for (std::uint64_t K : {1u, 2u, 7u, 13u, 64u, 100u}) {
    EnsembleConfig cfg;
    cfg.realisations = K;
    cfg.quiet = true;
    std::vector<std::vector<double>> results;
    for (std::uint64_t C : {1u, 2u, 4u, 16u, 128u}) {
      cfg.chunk_size = C;
      results.push_back(bits(run_ensemble(cfg, 2, values_of)));
    }
    for (const auto& r : results) CHECK(std::memcmp(r.data(), results[0].data(), r.size() * sizeof(double)) == 0);
    // And the tree sum equals a plain pairwise recursion over the realisations.
    const auto direct = tree_sum(0, K, [](std::uint64_t a, std::uint64_t b) {
      std::vector<double> v;
      if (b - a == 1) {
        v.resize(2);
        values_of(a, 0, v.data());
      }
      return v;
    });
    CHECK(direct[0] == results[0][0]);
  }
}

TEST_CASE("a realisation producing NaN stops the run naming its id and the seed") {
  EnsembleConfig cfg;
  cfg.realisations = 20;
  cfg.chunk_size = 4;
  cfg.seed = 77;
  cfg.quiet = true;
  auto bad = [](std::uint64_t id, int, double* v) { v[0] = id == 13 ? std::nan("") : 1.0; };
  try {
    run_ensemble(cfg, 1, bad);
    FAIL("no error");
  } catch (const UserError& e) {
    const std::string m = e.what();
    CHECK(m.find("realisation 13") != std::string::npos);
    CHECK(m.find("seed 77") != std::string::npos);
    CHECK(m.find("--only 13") != std::string::npos);
    CHECK(e.exit_code() == 65);
  }
  cfg.only = 13;
  CHECK_THROWS_AS(run_ensemble(cfg, 1, bad), UserError);
  cfg.only = 12;
  const auto s = run_ensemble(cfg, 1, bad);
  CHECK(s.count == 1);
  CHECK(s.sum[0] == 1.0);
  cfg.only = 20;
  CHECK_THROWS_AS(run_ensemble(cfg, 1, bad), UserError);
}

TEST_CASE("chunk sums reduced as they complete keep few nodes and the tree's bits, for any contiguous range") {
  const auto leaves = [](std::uint64_t a, std::uint64_t b) {
    std::vector<double> v;
    if (b - a == 1) v.resize(2), values_of(a, 0, v.data());
    return v;
  };
  for (std::uint64_t K : {1u, 13u, 100u, 1000u, 4097u})
    for (std::uint64_t C : {1u, 4u, 64u})
      for (std::uint64_t ranks : {1u, 3u}) {
        // Ranges as ranks get them: [first, last) of chunk indices, aligned to nothing.
        const std::uint64_t chunks = (K + C - 1) / C;
        std::map<std::uint64_t, TreeAccumulator::Node> nodes;
        std::size_t most = 0;
        for (std::uint64_t r = 0; r < ranks; ++r) {
          TreeAccumulator acc;
          for (std::uint64_t i = chunks * r / ranks; i < chunks * (r + 1) / ranks; ++i) {
            const std::uint64_t lo = i * C, hi = std::min(lo + C, K);
            acc.push(lo, hi, tree_sum(lo, hi, leaves));
            most = std::max(most, acc.size());
          }
          for (const auto& n : acc.nodes()) nodes[n.lo] = n;
        }
        CHECK(static_cast<double>(most) <= 2.0 * std::log2(static_cast<double>(chunks) + 1.0) + 1.0);
        const auto reduced = tree_sum(0, K, [&](std::uint64_t a, std::uint64_t b) {
          const auto it = nodes.find(a);
          return it != nodes.end() && it->second.hi == b ? it->second.values : std::vector<double>();
        });
        const auto direct = tree_sum(0, K, leaves);
        CHECK(std::memcmp(reduced.data(), direct.data(), direct.size() * sizeof(double)) == 0);
      }
}
