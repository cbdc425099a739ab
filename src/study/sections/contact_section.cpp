#include "src/study/sections/contact_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> ContactSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      choice_key("contact", "law", "contact law", ContactLaw::hertz, kContactLaws),
      real_key("contact", "damping", "N s/m", "contact damping c_c (c0 for the linearised law)", std::string("100"),
               0.0, inf),
      choice_key("contact", "loss", "force during loss of contact", ContactLoss::damping_only, kContactLosses),
      real_key("contact", "k0", "N/m", "linearised contact stiffness k0", std::string("6.8e6"), 0.0, inf, false),
      choice_key("contact", "blocked_force", "linearised law's F0(t)", BlockedForceSource::spring,
                 kBlockedForceSources),
      choice_key("contact", "filter", "what the contact does to the roughness (Hertz radius a at the weight)",
                 ContactFilter::patch, kContactFilters),
  };
}

std::string ContactSection::loss_setting(ContactLoss v) { return choice_setting("contact.loss", kContactLosses, v); }

ContactSection ContactSection::parse(const KeyReader& s) {
  ContactSection p;
  p.law = read_choice(s, "contact.law", kContactLaws);
  p.damping = s.real("contact.damping");
  p.loss = read_choice(s, "contact.loss", kContactLosses);
  p.k0 = s.real("contact.k0");
  p.blocked_force = read_choice(s, "contact.blocked_force", kBlockedForceSources);
  p.filter = read_choice(s, "contact.filter", kContactFilters);
  p.filter_origin = {s.where("contact.filter")};
  p.filter_set = s.is_set("contact.filter");
  if (p.loss == ContactLoss::closed && p.law != ContactLaw::linearised)
    KeyOrigin{s.where("contact.loss")}.refuse(
        "a contact that never opens is the linear law's counterfactual; "
        "allowed with [contact] law = " +
        spelling_of(kContactLaws, p.law) + ": damping_only or zero");
  return p;
}

}  // namespace rollspec::study
