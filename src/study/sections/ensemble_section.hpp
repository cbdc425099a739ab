#pragma once
// [ensemble] (every scene): how the realisations are chunked for checkpoints, read once. The key
// itself is in the common table (scenes/scene_registry).
namespace rollspec::study {

class KeyReader;

struct EnsembleSection {
  long long chunk_size = 0;  // realisations per checkpointed chunk

  static EnsembleSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
