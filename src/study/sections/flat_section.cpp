#include "src/study/sections/flat_section.hpp"

#include "src/study/key_reader.hpp"

namespace rollspec::study {

FlatSection FlatSection::parse(const KeyReader& s) {
  FlatSection f;
  f.youngs_modulus = s.real("flat.youngs_modulus");
  f.poisson = s.real("flat.poisson");
  return f;
}

}  // namespace rollspec::study
