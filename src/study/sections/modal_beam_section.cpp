#include "src/study/sections/modal_beam_section.hpp"

#include <exception>
#include <string>

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
using T = ModalBeamSection;
using P = beam::BeamProperties;

}  // namespace

SectionKeys<ModalBeamSection> ModalBeamSection::declare() {
  return SectionKeys<T>("beam")
      .choice("support", nested(&T::properties, &P::support), "boundary conditions", beam::Support::clamped_clamped,
              kBeamSupports)
      .real("length", nested(&T::properties, &P::length), "m", "physical span l between the supports", "0.4",
            above(0.0))
      .real("effective_length", nested(&T::properties, &P::effective_length), "m",
            "modal length l_eff >= l (clamp rotation, seed 002: l + 30 mm); 0: l", "0", at_least(0.0))
      .real("width", nested(&T::properties, &P::width), "m", "section width", "0.05", above(0.0))
      .real("thickness", nested(&T::properties, &P::thickness), "m", "section thickness (bending direction)", "0.0068",
            above(0.0))
      .real("youngs_modulus", nested(&T::properties, &P::youngs_modulus), "Pa", "Young's modulus E", "210e9",
            above(0.0))
      .real("poisson", &T::poisson, "-", "Poisson's ratio (contact modulus)", "0.3", {-1.0, 0.5, false, false})
      .real("density", nested(&T::properties, &P::density), "kg/m^3", "density rho", "7850", above(0.0))
      .integer("modes", nested(&T::selection, &beam::ModeSelection::count),
               "number of modes (0: all up to max_frequency)", "0", 0, 5000)
      .real("max_frequency", nested(&T::selection, &beam::ModeSelection::max_frequency), "Hz",
            "highest modal frequency kept when modes = 0", "20000", at_least(0.0))
      .real("loss_factor", nested(&T::damping, &beam::ModalDamping::loss_factor), "-",
            "modal loss factor eta (zeta = eta/2)", "0.01", within(0.0, 2.0))
      .boolean("static_correction", &T::static_correction, "residual flexibility of the truncated modes", "true");
}
template struct DeclaredSection<ModalBeamSection>;

beam::ModalBeam ModalBeamSection::modal_beam() const {
  if (properties.effective_length > 0.0 && properties.effective_length < properties.length)
    origin(properties.effective_length).refuse("is shorter than [beam] length; allowed: 0 or >= length");
  if (selection.count == 0 && selection.max_frequency <= 0.0)
    origin(selection.max_frequency).refuse("must be > 0 when [beam] modes = 0");
  try {
    return beam::ModalBeam(properties, selection, damping, static_correction);
  } catch (const std::exception& e) {
    origin(selection.count).refuse(e.what());
  }
}

}  // namespace rollspec::study
