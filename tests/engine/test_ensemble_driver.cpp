// The ensemble driver: the pairwise tree, chunk-size invariance, NaN detection, --only.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
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
  auto bad = [](std::uint64_t id, int, double* v) {
    v[0] = id == 13 ? std::nan("") : 1.0;
  };
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
