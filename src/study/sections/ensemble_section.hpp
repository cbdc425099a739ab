#pragma once
// [ensemble] (every scene): how the realisations are chunked for checkpoints, read once. Its key is in
// the common table of every scene (scenes/scene_registry).
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

struct EnsembleSection : DeclaredSection<EnsembleSection> {
  long long chunk_size = 0;  // realisations per checkpointed chunk

  static SectionKeys<EnsembleSection> declare();
};

}  // namespace rollspec::study
