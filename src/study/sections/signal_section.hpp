#pragma once
// [signal] (scene ball-on-beam): output sample rate, integration substeps and hold, the integrator
// and the dopri5 reference's tolerance, read once.
#include <string>
#include <vector>

#include "kernels/beam/exact_step_integrator.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class SignalIntegrator { exact, dopri5 };

inline constexpr ChoiceTable<beam::ForceHold, 2> kForceHolds{{
    {beam::ForceHold::quadratic, "quadratic", "order 3, default"},
    {beam::ForceHold::linear, "linear", "order 2"},
}};
inline constexpr ChoiceTable<SignalIntegrator, 2> kSignalIntegrators{{
    {SignalIntegrator::exact, "exact", "exact modal step, implicit contact"},
    {SignalIntegrator::dopri5, "dopri5", "reference"},
}};

struct SignalSection : DeclaredSection<SignalSection> {
  double sample_rate = 0.0, rtol = 0.0;
  long long substeps = 0;
  beam::ForceHold hold = beam::ForceHold::quadratic;
  SignalIntegrator integrator = SignalIntegrator::exact;

  static SectionKeys<SignalSection> declare();
};

}  // namespace rollspec::study
