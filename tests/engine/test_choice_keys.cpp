// Choice keys from their tables (key_spec.hpp's Choice, src/study/sections/choice_read.hpp): the
// allowed values, default and documentation come from the one table, and every spelling reads back
// as its own enum value.
#include <doctest/doctest.h>

#include <string>

#include "src/error.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/rolling_body_sections.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "tests/engine/study_from_text.hpp"

using namespace rollspec;
using test::message_of;

namespace {
enum class Fruit { apple, pear, plum };
constexpr study::ChoiceTable<Fruit, 3> kFruits{{
    {Fruit::apple, "apple", "round"},
    {Fruit::pear, "pear", ""},
    {Fruit::plum, "plum", "a stone fruit"},
}};
constexpr study::ChoiceTable<Fruit, 2> kPlainFruits{{{Fruit::apple, "apple", ""}, {Fruit::pear, "pear", ""}}};

study::Study ball_on_beam(const std::vector<std::string>& overrides) {
  return test::study_from_text("/tmp/rollspec_choices.ini",
                               "[study]\nscene = ball-on-beam\nrealisations = 2\nseed = 1\n", overrides);
}
}  // namespace

TEST_CASE("a choice key's values, default and doc come from its table") {
  const study::KeySpec k = study::choice_key("tree", "fruit", "what grows", Fruit::pear, kFruits);
  CHECK(k.type == study::KeyType::choice);
  CHECK(k.choices == std::vector<std::string>{"apple", "pear", "plum"});
  REQUIRE(k.default_value);
  CHECK(*k.default_value == "pear");
  CHECK(k.doc == "what grows: apple (round), pear or plum (a stone fruit)");
  CHECK(k.allowed() == "one of apple, pear, plum");
  // No value with a doc of its own: the lead alone.
  CHECK(study::choice_key("tree", "fruit", "what grows", Fruit::apple, kPlainFruits).doc == "what grows");
  CHECK(study::spelling_of(kFruits, Fruit::plum) == "plum");
}

TEST_CASE("every contact law and body kind reads back as its own enum value") {
  for (const auto& c : study::kContactLaws) {
    const auto s = ball_on_beam({std::string("contact.law=") + c.spelling});
    CHECK(study::ContactSection::parse(s).law == c.value);
    CHECK(study::spelling_of(study::kContactLaws, c.value) == c.spelling);
  }
  for (const auto& c : study::kContactFilters) {
    const auto s = ball_on_beam({std::string("contact.filter=") + c.spelling});
    CHECK(study::ContactSection::parse(s).filter == c.value);
  }
  for (const auto& c : study::kBodyKinds) {
    const auto s = test::study_from_text(
        "/tmp/rollspec_choices.ini",
        "[study]\nscene = rolling-beam\nseed = 1\nrealisations = 1\n[body]\nkind = " + std::string(c.spelling) + "\n");
    CHECK(study::BodySection::parse(s).kind == c.value);
  }
}

TEST_CASE("a misspelt choice is refused with file, line, key, value and the table's values (exit 78)") {
  const auto text = "[study]\nscene = ball-on-beam\nrealisations = 2\n[contact]\nlaw = tabel\n";
  const std::string m = message_of([&] { test::study_from_text("/tmp/rollspec_choices.ini", text); });
  CHECK(m.find("/tmp/rollspec_choices.ini:5") != std::string::npos);
  CHECK(m.find("law") != std::string::npos);
  CHECK(m.find("tabel") != std::string::npos);
  CHECK(m.find("one of hertz, table, literal, linearised, path") != std::string::npos);
  try {
    test::study_from_text("/tmp/rollspec_choices.ini", text);
    FAIL("not refused");
  } catch (const UserError& e) {
    CHECK(e.exit_code() == 78);
  }
}

TEST_CASE("the --set texts the engine derives (closed contact, sub-tables) read back as the value they name") {
  for (const auto& c : study::kContactLosses) {
    const std::string set = study::ContactSection::loss_setting(c.value);
    CHECK(set == std::string("contact.loss=") + c.spelling);
    // closed is the linearised law's counterfactual: allowed with it only
    CHECK(study::ContactSection::parse(ball_on_beam({"contact.law=linearised", set})).loss == c.value);
  }
  for (const auto& c : study::kTableErrors) {
    const std::string set = study::StiffnessSection::table_error_setting(c.value);
    CHECK(set == std::string("stiffness.table_error=") + c.spelling);
    const study::StiffnessSection s = study::StiffnessSection::parse(ball_on_beam({set}));
    CHECK(s.table_jackknife == (c.value == study::TableError::jackknife));
    CHECK(s.table_error_auto == (c.value == study::TableError::automatic));
  }
}
