// Study loading in-process: defaults echoed, overrides, canonical text independent of formatting.
#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "src/error.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"

using namespace rollspec;

namespace {
std::string write(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/rollspec_test_" + name + ".ini";
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST_CASE("canonical text: defaults filled in, numbers normalised, formatting irrelevant") {
  const auto a = write(
      "a", "[study]\nscene = random-oscillator\nrealisations = 10\nseed = 1\n[oscillator]\nnatural_frequency = 50.0\n");
  const auto b = write("b",
                       "# comment\n[oscillator]\n  natural_frequency=5e1   # Hz\n[study]\nseed = 1\nrealisations = "
                       "10\nscene = random-oscillator\n");
  const auto sa = study::Study::load(a, {}, scenes::schema_for);
  const auto sb = study::Study::load(b, {}, scenes::schema_for);
  CHECK(sa.canonical_text() == sb.canonical_text());
  CHECK(sa.canonical_text().find("damping_ratio = 0.02") != std::string::npos);
  CHECK(scenes::study_result_hash(sa) == scenes::study_result_hash(sb));
  // The realisation count does not enter the checkpoint hash (an ensemble may be extended).
  const auto sc = study::Study::load(a, {"study.realisations=20"}, scenes::schema_for);
  CHECK(scenes::study_result_hash(sa) == scenes::study_result_hash(sc));
  const auto sd = study::Study::load(a, {"oscillator.mass=3"}, scenes::schema_for);
  CHECK(scenes::study_result_hash(sa) != scenes::study_result_hash(sd));
  CHECK(sd.entry("oscillator.mass").origin.line == -1);
  CHECK(sa.entry("oscillator.natural_frequency").origin.line == 6);
  std::remove(a.c_str());
  std::remove(b.c_str());
}
