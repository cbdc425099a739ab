#include "src/scenes/scene_references.hpp"

#include <cstdint>

#include "kernels/spectral/ensemble_interval.hpp"
#include "src/scenes/ball_on_beam_sections.hpp"
#include "src/scenes/ball_on_beam_settings.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_section.hpp"

namespace rollspec::scenes {

namespace {
using Ids = std::vector<std::string>;

void add(Ids& to, const Ids& more) { to.insert(to.end(), more.begin(), more.end()); }

// An ensemble's sensor spectra: Welch PSDs, their degrees of freedom, third-octave bands and, with
// enough realisations for one (io/psd_result.cpp interval_method), the interval of the ensemble mean.
Ids ensemble_spectra(const study::KeyReader& s) {
  Ids ids = {"Welch 1967", "D-15", "D-16", "D-17"};
  if (static_cast<std::uint64_t>(study::StudySection::parse(s).realisations) >= spectral::kMinRealisationsForInterval)
    ids.push_back("D-21");
  return ids;
}

// An isotropic rough surface from [surface] method: seed 001's line sums or the 2D Fourier filter.
Ids isotropic_surface(study::SurfaceMethod m) {
  return m == study::SurfaceMethod::seed ? Ids{"seed 001", "D-4"} : Ids{"D-5"};
}

// The elastic-plastic half-space solver of the contact tables.
Ids contact_solver() { return {"Polonsky-Keer 1999", "D-6", "D-7"}; }
}  // namespace

std::vector<std::string> random_oscillator_references(const study::KeyReader& s) {
  Ids ids = {"D-3", "D-18", "D-19"};
  add(ids, ensemble_spectra(s));
  return ids;
}

std::vector<std::string> ball_on_beam_references(const study::KeyReader& s) {
  const BallOnBeamSections sections = BallOnBeamSections::parse(s);
  const BallOnBeamSettings b = read_ball_on_beam_settings(sections);
  Ids ids = {"seed 001", "D-1", "D-3", "D-8", "D-9"};
  switch (b.contact) {
    case ContactModel::hertz:
      add(ids, {"D-10", "Johnson 1985"});
      break;
    case ContactModel::table:
    case ContactModel::literal:
      add(ids, {"D-10"});
      add(ids, contact_solver());
      if (sections.stiffness.rough) add(ids, isotropic_surface(sections.surface.method));
      break;
    case ContactModel::linearised_spring:
      add(ids, {"seed 002", "D-11"});
      break;
    case ContactModel::linearised_solver:
      add(ids, {"seed 002", "D-11", "BF-1..BF-7"});
      add(ids, contact_solver());
      break;
    case ContactModel::path:
      add(ids, {"D-10", "B41..B46"});
      add(ids, contact_solver());
      break;
  }
  const bool filtered = b.filter_applied == b.filter_name;  // a patch filter is not applied on a strip law
  if (filtered && b.filter == ContactFilter::patch) add(ids, {"B35", "Johnson 1985"});
  if (b.filter == ContactFilter::iso2d) add(ids, {"texture Eq. 36-40", "Johnson 1985"});
  if (b.filter == ContactFilter::solver) {
    add(ids, {"ER-1..ER-7"});
    add(ids, contact_solver());
  }
  add(ids, ensemble_spectra(s));
  return ids;
}

std::vector<std::string> rolling_beam_references(const study::KeyReader&) { return {"seed 000", "D-12..D-14"}; }

std::vector<std::string> rolling_pipe_references(const study::KeyReader& s) {
  Ids ids = {"seed 000", "D-12..D-14"};
  if (study::PipeRoughnessSection::parse(s).line)
    add(ids, {"D-3"});
  else
    add(ids, isotropic_surface(study::SurfaceSection::parse(s).method));
  add(ids, ensemble_spectra(s));
  return ids;
}

std::vector<std::string> stiffness_references(const study::KeyReader& s) {
  Ids ids = contact_solver();
  if (study::StiffnessSection::parse(s).rough) add(ids, isotropic_surface(study::SurfaceSection::parse(s).method));
  return ids;
}

std::vector<std::string> texture_surface_references(const study::KeyReader& s, long long surfaces) {
  Ids ids = {"D-3"};
  if (surfaces > 0) add(ids, isotropic_surface(study::SurfaceSection::parse(s).method));
  return ids;
}

std::vector<std::string> texture_references(const study::KeyReader& s) {
  return texture_surface_references(s, study::SurfaceSection::parse(s).count);
}

std::vector<std::string> study_references(const study::KeyReader& s) { return find_scene(s.scene()).references(s); }

}  // namespace rollspec::scenes
