#pragma once
// [roughness] of scene rolling-pipe: which roughness the tube rolls over, read once.
namespace rollspec::study {

class KeyReader;

struct PipeRoughnessSection {
  bool line = true;  // kind = line (one line texture under every node); else isotropic surfaces

  static PipeRoughnessSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
