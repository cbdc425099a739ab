// rollspec keys: the documented study keys of a scene (unit, allowed values, default).
#include <iostream>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/cli/section_order.hpp"
#include "src/scenes/scene.hpp"

namespace rollspec::cli {

int keys_command(const Args& args) {
  const std::string usage =
      "usage: rollspec keys [SCENE]\n\nLists every study key of SCENE (or the scenes, without one).";
  po::options_description opts("options");
  std::string scene;
  opts.add_options()("scene", po::value(&scene), "scene name");
  po::variables_map vm;
  if (!parse_scene_options(args, usage, opts, scene, vm)) return 0;
  // A scene adds keys to common sections ([spectrum]): each section is printed once, with all of them.
  bool first = true;
  for (const auto& group : group_by_section(scenes::schema_for(scene))) {
    std::cout << (first ? "" : "\n") << "[" << group.section << "]\n";
    first = false;
    for (const auto& k : group.keys)
      std::cout << "  " << k.key << " = " << (k.default_value ? *k.default_value : "(required)") << "\n      " << k.doc
                << "\n      allowed: " << k.allowed() << "\n";
  }
  return 0;
}

}  // namespace rollspec::cli
