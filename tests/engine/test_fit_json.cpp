// fit --format json (src/fit/fit_json.cpp), written by nlohmann-json: what a program reading it gets back,
// for text a user gave (a path with a quote, a backslash, a control character, a byte that is not UTF-8)
// and for numbers JSON cannot hold (NaN: null) or must keep whole (every digit of a double).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "src/fit/fit_json.hpp"

using namespace rollspec;

TEST_CASE("fit's JSON reads back as written: user text, full-precision numbers, null for NaN") {
  fit::FitReport r;
  r.parameters.push_back({"force.level", 0.1 + 0.2, NAN, NAN, false, false});
  r.parameters.push_back({"oscillator.damping_ratio", 1.0 / 3.0, 0.25, 0.5, false, true});
  r.correlation = {1.0, -0.125, -0.125, 1.0};
  fit::FitPointReport p;
  p.measurement = "rig \"A\"\\roll\t1\x01.csv";
  p.at = "oscillator.natural_frequency=50";
  p.records = 25.0;
  p.bands = 9;
  r.points.push_back(p);
  r.log_likelihood = -12.345678901234567;
  r.realisations = 40;
  r.verdict = "not rejected";
  const auto j = nlohmann::json::parse(fit::fit_json(r));
  CHECK(j["points"][0]["measurement"] == p.measurement);
  CHECK(j["points"][0]["measured_averages"] == 25.0);
  CHECK(j["parameters"]["force.level"]["estimate"].get<double>() == 0.1 + 0.2);  // not rounded to 10 digits
  CHECK(j["parameters"]["force.level"]["interval"][0].is_null());
  CHECK(j["parameters"]["oscillator.damping_ratio"]["interval_at_range_end"][1] == true);
  CHECK(j["correlation"][1][0].get<double>() == -0.125);
  CHECK(j["log_likelihood"].get<double>() == -12.345678901234567);
  CHECK(j["realisations"] == 40);
  CHECK(j["p_value"].is_null());  // r.test_defined is false
  // A path that is not UTF-8 is written with U+FFFD in place of the bad byte, not refused.
  r.points[0].measurement = "roll\xff.csv";
  CHECK(nlohmann::json::parse(fit::fit_json(r))["points"][0]["measurement"] == "roll\xef\xbf\xbd.csv");
}
