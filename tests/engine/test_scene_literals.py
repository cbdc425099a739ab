"""A scene is a package known by its registry row, never by its name: outside src/scenes/scene_registry.cpp
(its row) and the scene's own package folder, src/scenes/<name with _ for ->/ (what the row names), no code
spells a registered scene's name.

The rule, read from the sources:
- the scene names are the rows of scene_registry() (`{"name", "description", ...}`);
- a string literal equal to a scene name is compared nowhere else (==, !=, .compare, .find): code asks
  the row (scenes::find_scene) what the scene has (its command, memory model, plausibility relations,
  contact, beam, first keys) instead of testing which scene it is;
- a scene name that is no other name (ball-on-beam, ...) appears as a literal nowhere else at all (a
  table keyed by scene names is a second registry). Names also spelt by a section (`texture`,
  `stiffness`: [texture] keys, the `texture` stage and command) are checked by comparison alone.
`violations` runs on the real tree (none allowed) and on scratch trees that break each rule."""
import pathlib
import re

from source_scan import ROOT, compared_literals, scratch, sources

REGISTRY = pathlib.PurePosixPath("src/scenes/scene_registry.cpp")
ROW = re.compile(r'\{\s*"([^"\\]+)"\s*,\s*"')  # a row's name, then its description
SECTION_KEY = re.compile(r'\b\w+_key\s*\(\s*"(\w+)"\s*,\s*"')  # a key declared in [section]
SECTION_KEYS = re.compile(r'\bSectionKeys<[\w:]+>\s*\(\s*"(\w+)"\s*\)')  # a section's key declarations
LITERAL = re.compile(r'"((?:\\.|[^"\\\n])*)"')


def scene_names(root):
    text = dict(sources(root)).get(REGISTRY, "")
    body = text[text.find("scene_registry() {"):]
    return ROW.findall(body[:body.find("return scenes;")])


def section_names(root):
    return {m.group(1) for _, text in sources(root) for r in (SECTION_KEY, SECTION_KEYS) for m in r.finditer(text)}


def own_file(rel, name):
    """The registry, or a file of the scene's own package folder."""
    return rel == REGISTRY or pathlib.PurePosixPath("src/scenes", name.replace("-", "_")) in rel.parents


def violations(root):
    names = scene_names(root)
    shared = set(names) & section_names(root)
    found = []
    for rel, text in sources(root):
        for line_no, line in enumerate(text.splitlines(), 1):
            compared = set(compared_literals(line))
            for m in LITERAL.finditer(line):
                name = m.group(1)
                if name not in names or own_file(rel, name):
                    continue
                if name in compared:
                    found.append(f'{rel}:{line_no}: compares the scene name "{name}"; ask its registry row '
                                 "(scenes::find_scene) what the scene has instead")
                elif name not in shared:
                    found.append(f'{rel}:{line_no}: spells the scene name "{name}"; it belongs in the scene\'s '
                                 "registry row (src/scenes/scene_registry.cpp)")
    return found


def test_scene_names_are_spelt_only_in_the_registry():
    names = scene_names(ROOT)
    for name in ("ball-on-beam", "random-oscillator", "rolling-pipe", "rolling-beam", "stiffness", "texture"):
        assert name in names, f"the registry's rows were not read ({name} missing from {names})"
    assert violations(ROOT) == []


REGISTRY_TEXT = {str(REGISTRY): 'const std::vector<SceneInfo>& scene_registry() {\n  static const std::vector<SceneInfo> '
                 'scenes = {\n      {"ball-on-beam", "a ball on a beam", SceneKind::ensemble},\n'
                 '      {"texture", "roughness only", SceneKind::stages_only},\n  };\n  return scenes;\n}\n',
                 "src/study/sections/texture_section.cpp": 'auto k = real_key("texture", "rms", "m", "rms");\n'}


def test_a_compared_scene_name_is_found_with_file_and_line(tmp_path):
    body = '// scene == "texture" in a comment\nbool a = s.scene() == "texture";\nbool b = "ball-on-beam" != s.scene();\n'
    found = violations(scratch(tmp_path, {**REGISTRY_TEXT, "src/cli/use.cpp": body}))
    assert found == ['src/cli/use.cpp:2: compares the scene name "texture"; ask its registry row '
                     "(scenes::find_scene) what the scene has instead",
                     'src/cli/use.cpp:3: compares the scene name "ball-on-beam"; ask its registry row '
                     "(scenes::find_scene) what the scene has instead"]


def test_a_table_keyed_by_a_scene_name_is_found(tmp_path):
    body = 'const std::map<std::string, int> rows = {\n    {"ball-on-beam", 13},\n};\n'
    found = violations(scratch(tmp_path, {**REGISTRY_TEXT, "src/cli/first_keys.cpp": body}))
    assert len(found) == 1 and found[0].startswith('src/cli/first_keys.cpp:2: spells the scene name "ball-on-beam"')


def test_a_section_spelt_like_a_scene_the_registry_and_the_package_folder_pass(tmp_path):
    files = {**REGISTRY_TEXT,
             "src/texture/keys.cpp": 'auto t = key_text("texture", "rms", x);\nStagePlan p{"texture", run, ""};\n',
             "src/scenes/ball_on_beam/stages.cpp": 'bool a = name == "ball-on-beam";\n',
             "src/io/message.cpp": 'const char* m = "needs a ball-on-beam study";\n'}
    assert violations(scratch(tmp_path, files)) == []
