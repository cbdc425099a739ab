"""src/README.md's "to add a scene" and its list of typed sections are kept true by reading the sources:
every field of SceneInfo (src/scenes/scene.hpp) is named in the README (a new field is a new place a
scene must fill), and every header of src/study/sections/ that declares a section struct is listed.
`missing` runs on the real tree (nothing missing) and on scratch trees that leave each out."""
import re

from source_scan import ROOT, scratch

FIELD = re.compile(r"^\s+(?:std::[\w:<>(),&\s*]+?|\w+)\s+(\w+)\s*(?:=[^;]*)?;", re.M)
SECTION_STRUCT = re.compile(r"^struct \w*Section\b", re.M)


def scene_info_fields(root):
    text = (root / "src/scenes/scene.hpp").read_text()
    body = text[text.index("struct SceneInfo {"):]
    return FIELD.findall(body[:body.index("\n};")])


def missing(root):
    readme = (root / "src/README.md").read_text()
    out = [f"src/README.md: SceneInfo field `{f}` (src/scenes/scene.hpp) is not named in \"to add a scene\""
           for f in scene_info_fields(root) if f"`{f}`" not in readme]
    for h in sorted((root / "src/study/sections").glob("*.hpp")):
        if SECTION_STRUCT.search(h.read_text()) and f"`{h.stem}`" not in readme:
            out.append(f"src/README.md: the sections header {h.name} is not in the list of typed sections")
    return out


def test_the_readme_names_every_scene_field_and_section():
    fields = scene_info_fields(ROOT)
    assert {"name", "memory", "first_keys", "relations"} <= set(fields), fields
    assert missing(ROOT) == []


SCENE_HPP = "struct SceneInfo {\n  std::string name;\n  SceneKind kind;  // what\n  std::function<int(int)> memory;\n};\n"


def test_a_field_or_section_left_out_is_found(tmp_path):
    files = {"src/scenes/scene.hpp": SCENE_HPP, "src/study/sections/ball_section.hpp": "struct BallSection {\n};\n",
             "src/study/sections/vector_keys.hpp": "double x;\n", "src/README.md": "`name`, `kind` and `ball_section`\n"}
    assert missing(scratch(tmp_path, files)) == [
        'src/README.md: SceneInfo field `memory` (src/scenes/scene.hpp) is not named in "to add a scene"']
    files["src/README.md"] = "`name`, `kind`, `memory`\n"
    assert missing(scratch(tmp_path, files)) == [
        "src/README.md: the sections header ball_section.hpp is not in the list of typed sections"]
