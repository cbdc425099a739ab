// rollspec init: a commented study of a scene to start from (study_template.hpp).
#include <fstream>
#include <iostream>
#include <sstream>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/cli/study_template.hpp"
#include "src/error.hpp"
#include "src/io/output_target.hpp"
#include "src/io/text_output.hpp"
#include "src/scenes/scene.hpp"

namespace rollspec::cli {

namespace {

std::string scene_names() {
  std::string names;
  for (const auto& s : scenes::scene_registry()) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// An existing file is the user's work (a study they edited, a template or not): it is replaced
// only with --force, or when it already holds exactly this text.
void refuse_existing(const std::string& out, const std::string& write_path, const std::string& text) {
  std::ifstream probe(write_path, std::ios::binary);
  if (!probe) return;
  const std::string old = file_text(write_path);
  if (old == text) return;
  const std::string what = old.rfind(kStudyTemplateMarker, 0) == 0
                               ? "a study written by rollspec init, edited since or for another scene or version"
                               : "not a study written by rollspec init";
  throw cannot_create("output file '" + out + "' (--out) exists and is " + what +
                      "; refusing to replace it; choose another --out, or add --force to replace it");
}

}  // namespace

int init_command(const Args& args) {
  const std::string usage =
      "usage: rollspec init [SCENE] [--out FILE.ini] [--force]\n\n"
      "Writes a commented study of SCENE that loads, plans and runs as it stands: first the keys to set\n"
      "for your own rig, each with its meaning, unit, allowed values and default, then every other key\n"
      "commented out at its default. Without --out the study goes to standard output; without SCENE\n"
      "the scenes are listed.";
  po::options_description opts("options");
  std::string scene, out;
  opts.add_options()("scene", po::value(&scene), "scene name")("out,o", po::value(&out),
                                                               "study file to write (default: standard output)")(
      "force", "replace an existing --out file (without it, a file that is not this very template is kept)");
  po::variables_map vm;
  if (!parse_scene_options(args, usage, opts, scene, vm)) return 0;
  bool known = false;
  for (const auto& s : scenes::scene_registry()) known = known || s.name == scene;
  if (!known) throw usage_error("unknown scene '" + clip(scene) + "'; allowed: one of " + scene_names());
  const std::string text = study_template(scene);
  if (out.empty() && vm.count("out"))
    throw usage_error("--out is empty; allowed: the path of the study file to write (or no --out: standard output)");
  if (out.empty()) {
    std::cout << text;
    return 0;
  }
  io::OutputTarget target{out, "rollspec-study-template"};
  target.check_kind = false;  // a text file: refuse_existing() decides on its contents
  const std::string write_path = io::check_output_target(target);
  if (!vm.count("force")) refuse_existing(out, write_path, text);
  io::write_text_file(write_path, out, text);
  std::cerr << "rollspec init: wrote " << out << " (" << scene << "); check it with: rollspec plan " << out << "\n";
  return 0;
}

}  // namespace rollspec::cli
