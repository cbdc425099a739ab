#include "src/study/sections/contact_section.hpp"

#include <string>

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<ContactSection> ContactSection::declare() {
  using T = ContactSection;
  return SectionKeys<T>("contact")
      .choice("law", &T::law, "contact law", ContactLaw::hertz, kContactLaws)
      .real("damping", &T::damping, "N s/m", "contact damping c_c (c0 for the linearised law)", "100", at_least(0.0))
      .choice("loss", &T::loss, "force during loss of contact", ContactLoss::damping_only, kContactLosses)
      .real("k0", &T::k0, "N/m", "linearised contact stiffness k0", "6.8e6", above(0.0))
      .choice("blocked_force", &T::blocked_force, "linearised law's F0(t)", BlockedForceSource::spring,
              kBlockedForceSources)
      .choice("filter", &T::filter, "what the contact does to the roughness (Hertz radius a at the weight)",
              ContactFilter::patch, kContactFilters);
}
template struct DeclaredSection<ContactSection>;

std::string ContactSection::loss_setting(ContactLoss v) {
  return choice_setting(declared().full_name(&ContactSection::loss), kContactLosses, v);
}

void ContactSection::finish() {
  if (loss == ContactLoss::closed && law != ContactLaw::linearised)
    origin(loss).refuse(
        "a contact that never opens is the linear law's counterfactual; "
        "allowed with [contact] law = " +
        spelling_of(kContactLaws, law) + ": damping_only or zero");
}

}  // namespace rollspec::study
