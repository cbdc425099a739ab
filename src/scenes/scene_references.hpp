#pragma once
// The papers and theory-note equations (io/references.hpp) a study's run uses. Each scene's registry row
// (SceneInfo::references, in its package folder) lists its own from the study's parsed choices, with the
// groups below that several scenes share.
#include <string>
#include <vector>

namespace rollspec::study {
class KeyReader;
enum class SurfaceMethod;
}  // namespace rollspec::study

namespace rollspec::scenes {

using ReferenceIds = std::vector<std::string>;
void add_references(ReferenceIds& to, const ReferenceIds& more);
// An ensemble's sensor spectra: Welch PSDs, their degrees of freedom, third-octave bands and, with enough
// realisations for one, the interval of the ensemble mean.
ReferenceIds ensemble_spectra_references(const study::KeyReader& s);
// An isotropic rough surface from [surface] method: seed 001's line sums or the 2D Fourier filter.
ReferenceIds isotropic_surface_references(study::SurfaceMethod m);
// The elastic-plastic half-space solver of the contact tables.
ReferenceIds contact_solver_references();

// `rollspec texture` with --count: `surfaces` isotropic surfaces, whatever [surface] count says.
ReferenceIds texture_surface_references(const study::KeyReader& s, long long surfaces);

// The references of `s`'s scene (its registry row's function).
ReferenceIds study_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
