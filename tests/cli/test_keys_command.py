"""rollspec keys SCENE lists each section once, in the order sections first appear in the key table, with
every key of the table (a scene's own keys in a common section, [spectrum] skip_start, under that section)."""
import re

import pytest

from conftest import run

SCENES = [line.split(":")[0] for line in run(["keys"]).stdout.splitlines()]


@pytest.mark.parametrize("scene", SCENES)
def test_each_section_once(scene):
    r = run(["keys", scene])
    assert r.returncode == 0, r.stderr
    sections = re.findall(r"^\[(.+)\]$", r.stdout, re.M)
    assert len(sections) == len(set(sections)), sections
    assert sections[:3] == ["study", "ensemble", "spectrum"]
    # Keys are unique within their section and blocks are separated by one blank line.
    for block in r.stdout.split("\n\n"):
        keys = re.findall(r"^  (\w+) = ", block, re.M)
        assert len(keys) == len(set(keys)), block[:200]
        assert block.startswith("["), block[:200]


def test_scene_keys_join_the_common_section():
    text = run(["keys", "ball-on-beam"]).stdout
    spectrum = text.split("[spectrum]\n")[1].split("\n\n")[0]
    assert re.findall(r"^  (\w+) = ", spectrum, re.M) == ["segment", "overlap", "window", "band_min", "band_max",
                                                          "confidence", "skip_start"]
