#include "src/study/sections/path_table_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> PathTableSection::keys() {
  return {
      integer_key("path_table", "approaches",
                  "law = path: approaches J of the table P(delta, xi) (kernels/beam B43), 2 or more", std::string("8"),
                  2, 64),
      integer_key(
          "path_table", "step",
          "law = path: path step in cells between tabulated positions; 0: at most a quarter of the contact radius",
          std::string("0"), 0, 1000),
      real_key("path_table", "strip_length", "m",
               "law = path: length of the rough strip; 0: the ball's path in the run ((end - start) + one step) plus "
               "the solver window",
               std::string("0"), 0.0, std::numeric_limits<double>::infinity()),
  };
}

PathTableSection PathTableSection::parse(const KeyReader& s) {
  PathTableSection p;
  p.approaches = s.integer("path_table.approaches");
  p.step = s.integer("path_table.step");
  p.strip_length = s.real("path_table.strip_length");
  p.strip_length_origin = {s.where("path_table.strip_length")};
  return p;
}

}  // namespace rollspec::study
