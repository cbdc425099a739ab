#include "src/study/sections/ensemble_section.hpp"

#include "src/study/key_reader.hpp"

namespace rollspec::study {

EnsembleSection EnsembleSection::parse(const KeyReader& s) {
  EnsembleSection e;
  e.chunk_size = s.integer("ensemble.chunk_size");
  return e;
}

}  // namespace rollspec::study
