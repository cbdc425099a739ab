#pragma once
// A number in rollspec's JSON (compare's verdict, fit's answer): the value, or null where it is not
// finite (JSON has no NaN or infinity).
#include <cmath>
#include <nlohmann/json.hpp>

namespace rollspec::io {

inline nlohmann::ordered_json json_number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace rollspec::io
