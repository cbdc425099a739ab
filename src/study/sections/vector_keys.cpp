#include "src/study/sections/vector_keys.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

Eigen::Vector3d vector3(const KeyReader& s, const std::string& key) {
  const auto v = s.numbers(key, 3);
  return {v[0], v[1], v[2]};
}

std::vector<Eigen::Vector3d> triples(const KeyReader& s, const std::string& key) {
  std::vector<Eigen::Vector3d> out;
  std::istringstream in(s.text(key));
  std::string item;
  while (std::getline(in, item, ';')) {
    std::vector<double> v;
    std::istringstream parts(item);
    std::string part;
    while (std::getline(parts, part, ',')) {
      char* end = nullptr;
      const double x = std::strtod(part.c_str(), &end);
      while (end && (*end == ' ' || *end == '\t')) ++end;
      if (end == part.c_str() || *end != '\0' || !std::isfinite(x))
        s.refuse(key, "'" + part + "' is not a finite number");
      v.push_back(x);
    }
    if (v.size() != 3) s.refuse(key, "'" + item + "' is not x,y,z; allowed: x,y,z triples separated by ';'");
    out.emplace_back(v[0], v[1], v[2]);
  }
  return out;
}

}  // namespace rollspec::study
