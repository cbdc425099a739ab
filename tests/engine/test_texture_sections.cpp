// Typed [texture], [surface], [lines] and [study] sections: the values and file:line messages of the
// string reads they replace, and the grid errors of texture generators in study keys.
#include <doctest/doctest.h>

#include <functional>
#include <string>

#include "src/error.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/sections/lines_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "tests/engine/study_from_text.hpp"
#include "src/texture/texture_keys.hpp"

using namespace rollspec;
using test::message_of;

namespace {
const test::SceneStudies texture_study{"/tmp/rollspec_texture_sections/s.ini", "texture", 1, 7};

}  // namespace

TEST_CASE("texture section: values, profile paths beside the study file, origins") {
  const auto s = texture_study("[texture]\nsource = profiles\nprofiles = a.csv, /abs/b.csv\nhurst = 0.6\n");
  const auto t = study::TextureSection::parse(s);
  CHECK(t.present);
  CHECK(t.source == study::TextureSource::profiles);
  CHECK(t.hurst == 0.6);
  CHECK(t.value_text(t.table_path) == "none");
  CHECK_FALSE(t.has_table);
  CHECK(t.table_extension == texture::Extension::error);
  CHECK(t.profile_paths == std::vector<std::string>{"/tmp/rollspec_texture_sections/a.csv", "/abs/b.csv"});
  CHECK(texture_io::profile_files(t) == t.profile_paths);
  CHECK(t.origin(t.profile_paths).where == s.where("texture.profiles"));
  CHECK(t.origin(t.source).where == "/tmp/rollspec_texture_sections/s.ini:6: [texture] source = profiles");
  // A key that cannot act on measured profiles is refused where it is set, before any file is read.
  CHECK(message_of([&] { texture_io::study_psd(t); }) ==
        "/tmp/rollspec_texture_sections/s.ini:8: [texture] hurst = 0.6: does not act on measured profiles ([texture] "
        "source = profiles); allowed with profiles: profiles, median_filter, table_extension, short_wavelength (cuts "
        "the measured PSD) and amplitudes; remove it");
  CHECK(t.was_set(t.hurst));
  CHECK_FALSE(t.was_set(t.rms));
  // One scan is enough (each is used whole); none is refused at [texture] profiles.
  const auto none = study::TextureSection::parse(texture_study("[texture]\nsource = profiles\nprofiles = ,\n"));
  CHECK(message_of([&] { texture_io::study_psd(none); }) ==
        "/tmp/rollspec_texture_sections/s.ini:7: [texture] profiles = ,: names no profile file; allowed: one or more "
        "comma-separated CSV files (position_m,height_m), each a whole scan");
}

TEST_CASE("texture section: the PSD from the section is the PSD from the study") {
  const auto s = texture_study("[texture]\nrms = 2e-7\nshort_wavelength = 2e-5\n");
  const auto a = texture_io::study_psd(s), b = texture_io::study_psd(study::TextureSection::parse(s));
  CHECK(a.description == b.description);
  CHECK(a.support_max == b.support_max);
  for (double k : {1e3, 1e4, 2e5}) CHECK(a(k) == b(k));
  const auto bad = study::TextureSection::parse(texture_study("[texture]\nshort_wavelength = 2e-3\n"));
  CHECK(message_of([&] { texture_io::study_psd(bad); }) ==
        "/tmp/rollspec_texture_sections/s.ini:6: [texture] short_wavelength = 0.002: must be shorter than the roll-off "
        "wavelength");
}

TEST_CASE("texture section: a scene without [texture] parses to present = false") {
  const auto s = test::study_from_text("/tmp/rollspec_texture_sections/o.ini",
                                       "[study]\nscene = random-oscillator\nrealisations = 1\nseed = 1\n"
                                       "[oscillator]\nmass = 2\nnatural_frequency = 50\ndamping_ratio = 0.05\n",
                                       {});
  const auto t = study::TextureSection::parse(s);
  CHECK_FALSE(t.present);
  CHECK(texture_io::profile_files(t).empty());
  CHECK_FALSE(study::SurfaceSection::parse(s).present);
}

TEST_CASE("surface section: which seed-method keys take the measured profiles' values") {
  const auto s = texture_study("[texture]\nsource = profiles\nprofiles = a.csv, b.csv\n[surface]\nmethod = seed\n",
                               {"surface.sigma=1e-7"});
  const auto f = study::SurfaceSection::parse(s);
  CHECK(f.method == study::SurfaceMethod::seed);
  CHECK(f.sigma == 1e-7);
  CHECK_FALSE(f.sigma_default);
  CHECK(f.correlation_x_default);
  const auto keys = texture_io::profile_derived_surface_keys(study::TextureSection::parse(s), f);
  CHECK(keys == std::vector<std::string>{"correlation_x", "correlation_y"});
  CHECK(keys == texture_io::profile_derived_surface_keys(s));
}

TEST_CASE("surface section: an odd grid is refused at [surface] nx") {
  const auto s = texture_study("[surface]\nnx = 17\n");
  const auto t = study::TextureSection::parse(s);
  const auto f = study::SurfaceSection::parse(s);
  CHECK(f.count == 0);
  CHECK(message_of([&] { texture_io::surface_generator(t, f, texture_io::study_psd(t)); }) ==
        "/tmp/rollspec_texture_sections/s.ini:6: [surface] nx = 17: must be even");
}

TEST_CASE("lines and study sections: values and origins") {
  const auto s = texture_study("[lines]\ncount = 3\nlength = 2e-3\nspacing = 4e-6\n");
  const auto l = study::LinesSection::parse(s);
  CHECK(l.count == 3);
  CHECK(l.length == 2e-3);
  CHECK(l.spacing == 4e-6);
  CHECK(l.origin(l.spacing).where == "/tmp/rollspec_texture_sections/s.ini:8: [lines] spacing = 4e-06");
  const auto st = study::StudySection::parse(s);
  CHECK(st.scene == "texture");
  CHECK(st.seed == 7);
  CHECK(st.origin(st.scene).where == s.where("study.scene"));
}

TEST_CASE("line generator: a spacing coarser than the PSD names the keys that fix it") {
  // k_max = 2 pi / 1e-5 m: pi / k_max = 5e-6 m; the spacing 1e-5 m needs short_wavelength >= 2e-5 m.
  const auto s = texture_study("[lines]\nspacing = 1e-5\n");
  const auto t = study::TextureSection::parse(s);
  const auto l = study::LinesSection::parse(s);
  const auto keys = texture_io::LineGeneratorKeys::of(t, l.origin(l.spacing), "[lines] spacing");
  const std::string m =
      message_of([&] { texture_io::line_generator(keys, texture_io::study_psd(t), l.spacing, 100, false); });
  CHECK(m.find("/tmp/rollspec_texture_sections/s.ini:6: [lines] spacing = 1e-05: sampling dx") == 0);
  CHECK(m.find("; allowed: [lines] spacing at most 5e-06 m, or [texture] short_wavelength at least 2e-05 m") !=
        std::string::npos);
  CHECK(m.find("truncation") == std::string::npos);
  // Truncation allowed (the scenes' band-limited lines): no error.
  CHECK(texture_io::line_generator(keys, texture_io::study_psd(t), l.spacing, 100, true) != nullptr);
}
