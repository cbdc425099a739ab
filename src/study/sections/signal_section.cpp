#include "src/study/sections/signal_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<SignalSection> SignalSection::declare() {
  using T = SignalSection;
  return SectionKeys<T>("signal")
      .real("sample_rate", &T::sample_rate, "Hz", "output sample rate of accelerations and forces", "25600", above(0.0))
      .integer("substeps", &T::substeps, "integration steps per output sample (exact-step integrator)", "4", 1, 1000)
      .choice("hold", &T::hold, "modal force over a step", beam::ForceHold::quadratic, kForceHolds)
      .choice("integrator", &T::integrator, "integrator", SignalIntegrator::exact, kSignalIntegrators)
      .real("rtol", &T::rtol, "-", "relative tolerance of the dopri5 reference", "1e-8", within(1e-14, 1e-2));
}
template struct DeclaredSection<SignalSection>;

}  // namespace rollspec::study
