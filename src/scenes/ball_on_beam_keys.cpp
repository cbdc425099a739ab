// Study keys of scene `ball-on-beam` and the modal beam they describe (ball_on_beam.hpp).
#include <limits>
#include <string>

#include "kernels/beam/modal_beam.hpp"
#include "src/scenes/ball_on_beam.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/stiffness/path_table.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/path_table_section.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/study.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

namespace {
const double inf = std::numeric_limits<double>::infinity();
}  // namespace

std::vector<KeySpec> ball_on_beam_keys() {
  // [beam] and [ball] first, then the scene's other keys, in the order `rollspec keys` lists them.
  std::vector<KeySpec> k = ModalBeamSection::keys();
  for (auto& t : BallSection::keys()) k.push_back(t);
  const std::vector<KeySpec> rest = {
      choice_key("contact", "law",
                 "contact law: hertz (smooth Hertz P(delta)), table (rough-surface P(delta) from the stiffness stage), "
                 "literal (seed 001 Eq. 7: k_c(delta) delta from the same table), linearised (seed 002: blocked "
                 "force F0 and contact stiffness k0) or path (P(delta, xi) of one rough strip from a cached table of "
                 "contact solves along the ball's path, kernels/beam B41-B46; the strip is the roughness)",
                 std::string("hertz"), {"hertz", "table", "literal", "linearised", "path"}),
      real_key("contact", "damping", "N s/m", "contact damping c_c (c0 for the linearised law)", std::string("100"), 0.0, inf),
      choice_key("contact", "loss", "force during loss of contact: damping_only (seed 001 Eq. 8) or zero",
                 std::string("damping_only"), {"damping_only", "zero"}),
      real_key("contact", "k0", "N/m", "linearised contact stiffness k0", std::string("6.8e6"), 0.0, inf, false),
      choice_key("contact", "blocked_force",
                 "linearised law's F0(t): spring (W + k0 h_patch(v t), k0 from [contact]) or solver (the contact "
                 "solver's blocked force along a rough strip, seed 002 §4.2: k0, d0 and the F0 PSD from a cached table)",
                 std::string("spring"), {"spring", "solver"}),
      choice_key("contact", "filter",
                 "what the contact does to the roughness (Hertz radius a at the weight): none (point contact), patch "
                 "(1D average over 2a along the path, B35), iso2d (line synthesised from G_eq, the path PSD a Hertz "
                 "disc sees on an isotropic surface, kernels/texture Eq. 38) or solver (line synthesised from the PSD "
                 "of the equivalent roughness h_eq of half-space solves at the weight on [equivalent_roughness] strips "
                 "rough strips, kernels/contact ER-1..ER-7, a cached table; point laws only)",
                 std::string("patch"), {"none", "patch", "iso2d", "solver"}),
      real_key("roughness", "spacing", "m",
               "sample spacing of the beam's line texture (harmonics above pi/dx dropped); 0: one sample per integration "
               "step, v / (sample_rate x substeps)",
               std::string("0"), 0.0, inf),
      choice_key("roughness", "band_limit",
                 "roughness the ball sees: output (wavelengths shorter than v / (sample_rate / 2) dropped, an ideal "
                 "anti-alias filter on the linear response; kernels/beam B40) or step (up to the sampling's pi/dx: the "
                 "response above sample_rate / 2 aliases into the bands)",
                 std::string("output"), {"output", "step"}),
      real_key("signal", "sample_rate", "Hz", "output sample rate of accelerations and forces", std::string("25600"), 0.0,
               inf, false),
      integer_key("signal", "substeps", "integration steps per output sample (exact-step integrator)", std::string("4"), 1,
                  1000),
      choice_key("signal", "hold",
                 "modal force over a step: quadratic (order 3, default) or linear (order 2)",
                 std::string("quadratic"), {"quadratic", "linear"}),
      choice_key("signal", "integrator", "exact (exact modal step, implicit contact) or dopri5 (reference)",
                 std::string("exact"), {"exact", "dopri5"}),
      real_key("signal", "rtol", "-", "relative tolerance of the dopri5 reference", std::string("1e-8"), 1e-14, 1e-2),
      text_key("sensors", "positions", "accelerometer positions along the beam, m, comma-separated", std::string("0.2")),
      bool_key("sensors", "average", "add the mean PSD over sensors (seed 002 averages 5 sensors x 25 rolls)",
               std::string("true")),
      real_key("spectrum", "skip_start", "s",
               "time at the start of each record left out of the PSDs (start-up of the random response)", std::string("0"),
               0.0, inf),
      integer_key("output", "time_histories", "store time histories of realisations 0..n-1", std::string("0"), 0, 1000),
      bool_key("output", "reference",
               "linearised law: also write the frequency-domain reference (/reference: expected Welch PSD and the "
               "range that holds the ensemble mean), computed once after the ensemble",
               std::string("true")),
  };
  for (auto& t : rest) k.push_back(t);
  for (auto& t : texture_io::psd_keys()) k.push_back(t);
  for (auto& t : texture_io::surface_keys()) {
    // The solver's blocked force derives its strip from the contact radius unless the study sets these.
    if (t.key == "ny") t.doc += "; blocked_force = solver: strip width, the window's by default";
    if (t.key == "spacing") t.doc += "; blocked_force = solver: derived from the contact radius and the texture unless set";
    k.push_back(t);
  }
  for (auto& t : study::StiffnessSection::keys()) k.push_back(t);
  for (auto& t : BlockedForceSection::keys()) k.push_back(t);
  for (auto& t : PathTableSection::keys()) k.push_back(t);
  for (auto& t : stiffness::equivalent_roughness_keys()) k.push_back(t);
  return k;
}

beam::ModalBeam study_modal_beam(const Study& s) { return ModalBeamSection::parse(s).modal_beam(); }

}  // namespace rollspec::scenes
