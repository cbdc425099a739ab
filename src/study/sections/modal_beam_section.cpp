#include "src/study/sections/modal_beam_section.hpp"

#include <exception>
#include <limits>
#include <string>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> ModalBeamSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      choice_key("beam", "support", "boundary conditions", beam::Support::clamped_clamped, kBeamSupports),
      real_key("beam", "length", "m", "physical span l between the supports", std::string("0.4"), 0.0, inf, false),
      real_key("beam", "effective_length", "m", "modal length l_eff >= l (clamp rotation, seed 002: l + 30 mm); 0: l",
               std::string("0"), 0.0, inf),
      real_key("beam", "width", "m", "section width", std::string("0.05"), 0.0, inf, false),
      real_key("beam", "thickness", "m", "section thickness (bending direction)", std::string("0.0068"), 0.0, inf,
               false),
      real_key("beam", "youngs_modulus", "Pa", "Young's modulus E", std::string("210e9"), 0.0, inf, false),
      real_key("beam", "poisson", "-", "Poisson's ratio (contact modulus)", std::string("0.3"), -1.0, 0.5, false,
               false),
      real_key("beam", "density", "kg/m^3", "density rho", std::string("7850"), 0.0, inf, false),
      integer_key("beam", "modes", "number of modes (0: all up to max_frequency)", std::string("0"), 0, 5000),
      real_key("beam", "max_frequency", "Hz", "highest modal frequency kept when modes = 0", std::string("20000"), 0.0,
               inf),
      real_key("beam", "loss_factor", "-", "modal loss factor eta (zeta = eta/2)", std::string("0.01"), 0.0, 2.0),
      bool_key("beam", "static_correction", "residual flexibility of the truncated modes", std::string("true")),
  };
}

ModalBeamSection ModalBeamSection::parse(const KeyReader& s) {
  ModalBeamSection b;
  beam::BeamProperties& p = b.properties;
  p.support = read_choice(s, "beam.support", kBeamSupports);
  p.youngs_modulus = s.real("beam.youngs_modulus");
  p.density = s.real("beam.density");
  p.width = s.real("beam.width");
  p.thickness = s.real("beam.thickness");
  p.length = s.real("beam.length");
  p.effective_length = s.real("beam.effective_length");
  b.selection.count = static_cast<int>(s.integer("beam.modes"));
  b.selection.max_frequency = s.real("beam.max_frequency");
  b.damping.loss_factor = s.real("beam.loss_factor");
  b.static_correction = s.boolean("beam.static_correction");
  b.poisson = s.real("beam.poisson");
  b.effective_length_origin = {s.where("beam.effective_length")};
  b.modes_origin = {s.where("beam.modes")};
  b.thickness_origin = {s.where("beam.thickness")};
  b.max_frequency_origin = {s.where("beam.max_frequency")};
  return b;
}

beam::ModalBeam ModalBeamSection::modal_beam() const {
  if (properties.effective_length > 0.0 && properties.effective_length < properties.length)
    effective_length_origin.refuse("is shorter than [beam] length; allowed: 0 or >= length");
  if (selection.count == 0 && selection.max_frequency <= 0.0)
    max_frequency_origin.refuse("must be > 0 when [beam] modes = 0");
  try {
    return beam::ModalBeam(properties, selection, damping, static_correction);
  } catch (const std::exception& e) {
    modes_origin.refuse(e.what());
  }
}

}  // namespace rollspec::study
