// rollspec modes: the modal frequencies of a ball-on-beam study's beam, mode by mode.
#include <cstdio>

#include "kernels/beam/modal_beam.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/run/run_phases.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::cli {

using run::resolve_study;

int modes_command(const Args& args) {
  const std::string usage =
      "usage: rollspec modes STUDY.ini [--set section.key=value ...]\n"
      "\n"
      "Prints the beam's undamped modal frequencies (Hz), damping ratios and the effective length of a\n"
      "ball-on-beam study. Nothing is computed beyond the eigenvalues.";
  StudyCommandOptions cl;
  if (!cl.parse(args, usage)) return 0;
  const study::Study s = resolve_study(cl.study);
  const auto has_beam = [](const scenes::SceneInfo& i) { return static_cast<bool>(i.modal_beam); };
  const scenes::SceneInfo& scene = scenes::find_scene(s.scene());
  if (!has_beam(scene)) {
    const auto study_keys = study::StudySection::parse(s);
    study_keys.origin(study_keys.scene).refuse("rollspec modes needs a " + scenes::scenes_with(has_beam) + " study");
  }
  const beam::ModalBeam b = scene.modal_beam(s);
  const bool clamped = b.properties().support == beam::Support::clamped_clamped;
  std::printf("# %s beam, span %.6g m, effective length %.6g m, EI %.6g N m^2, rho A %.6g kg/m\n",
              clamped ? "clamped-clamped" : "simply-supported", b.properties().length, b.effective_length(),
              b.bending_stiffness(), b.mass_per_length());
  std::printf("%6s %16s %12s\n", "mode", "frequency_hz", "damping");
  for (int i = 0; i < b.modes(); ++i) std::printf("%6d %16.6f %12.6g\n", i + 1, b.frequency(i), b.zeta(i));
  return 0;
}

}  // namespace rollspec::cli
