#include "src/study/sections/lines_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> LinesSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      integer_key("lines", "count", "line textures to generate", std::string("10"), 0, 1e6),
      real_key("lines", "length", "m", "length of each line texture", std::string("0.4"), 0.0, inf, false),
      real_key("lines", "spacing", "m", "sample spacing dx of the lines (dx <= pi / k_max)", std::string("1e-5"), 0.0,
               inf, false),
  };
}

LinesSection LinesSection::parse(const KeyReader& s) {
  LinesSection l;
  l.count = s.integer("lines.count");
  l.length = s.real("lines.length");
  l.spacing = s.real("lines.spacing");
  l.length_origin = {s.where("lines.length")};
  l.spacing_origin = {s.where("lines.spacing")};
  return l;
}

}  // namespace rollspec::study
