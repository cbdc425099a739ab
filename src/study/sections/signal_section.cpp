#include "src/study/sections/signal_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> SignalSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      real_key("signal", "sample_rate", "Hz", "output sample rate of accelerations and forces", std::string("25600"),
               0.0, inf, false),
      integer_key("signal", "substeps", "integration steps per output sample (exact-step integrator)", std::string("4"),
                  1, 1000),
      choice_key("signal", "hold", "modal force over a step", beam::ForceHold::quadratic, kForceHolds),
      choice_key("signal", "integrator", "integrator", SignalIntegrator::exact, kSignalIntegrators),
      real_key("signal", "rtol", "-", "relative tolerance of the dopri5 reference", std::string("1e-8"), 1e-14, 1e-2),
  };
}

SignalSection SignalSection::parse(const KeyReader& s) {
  SignalSection p;
  p.sample_rate = s.real("signal.sample_rate");
  p.substeps = s.integer("signal.substeps");
  p.hold = read_choice(s, "signal.hold", kForceHolds);
  p.integrator = read_choice(s, "signal.integrator", kSignalIntegrators);
  p.rtol = s.real("signal.rtol");
  p.substeps_origin = {s.where("signal.substeps")};
  p.sample_rate_origin = {s.where("signal.sample_rate")};
  return p;
}

}  // namespace rollspec::study
