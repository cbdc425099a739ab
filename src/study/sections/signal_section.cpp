#include "src/study/sections/signal_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
const SectionKeys<SignalSection>& declared() {
  using T = SignalSection;
  static const auto k =
      SectionKeys<T>("signal")
          .real("sample_rate", &T::sample_rate, "Hz", "output sample rate of accelerations and forces", "25600",
                above(0.0))
          .integer("substeps", &T::substeps, "integration steps per output sample (exact-step integrator)", "4", 1,
                   1000)
          .choice("hold", &T::hold, "modal force over a step", beam::ForceHold::quadratic, kForceHolds)
          .choice("integrator", &T::integrator, "integrator", SignalIntegrator::exact, kSignalIntegrators)
          .real("rtol", &T::rtol, "-", "relative tolerance of the dopri5 reference", "1e-8", within(1e-14, 1e-2));
  return k;
}
}  // namespace

std::vector<KeySpec> SignalSection::keys() { return declared().keys(); }
SignalSection SignalSection::parse(const KeyReader& s) { return declared().read(s); }

}  // namespace rollspec::study
