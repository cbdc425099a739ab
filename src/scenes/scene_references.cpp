#include "src/scenes/scene_references.hpp"

#include <cstdint>

#include "kernels/spectral/ensemble_interval.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_section.hpp"

namespace rollspec::scenes {

void add_references(ReferenceIds& to, const ReferenceIds& more) { to.insert(to.end(), more.begin(), more.end()); }

// With enough realisations for one (io/psd_result.cpp interval_method), the interval of the ensemble mean.
ReferenceIds ensemble_spectra_references(const study::KeyReader& s) {
  ReferenceIds ids = {"Welch 1967", "D-15", "D-16", "D-17"};
  if (static_cast<std::uint64_t>(study::StudySection::parse(s).realisations) >= spectral::kMinRealisationsForInterval)
    ids.push_back("D-21");
  return ids;
}

ReferenceIds isotropic_surface_references(study::SurfaceMethod m) {
  return m == study::SurfaceMethod::seed ? ReferenceIds{"seed 001", "D-4"} : ReferenceIds{"D-5"};
}

ReferenceIds contact_solver_references() { return {"Polonsky-Keer 1999", "D-6", "D-7"}; }

ReferenceIds texture_surface_references(const study::KeyReader& s, long long surfaces) {
  ReferenceIds ids = {"D-3"};
  if (surfaces > 0) add_references(ids, isotropic_surface_references(study::SurfaceSection::parse(s).method));
  return ids;
}

ReferenceIds study_references(const study::KeyReader& s) { return find_scene(s.scene()).references(s); }

}  // namespace rollspec::scenes
