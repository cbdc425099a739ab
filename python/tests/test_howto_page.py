"""The example of docs/howto/python-module.md runs as it is written, from the source tree (its recording is
studies/data/example-signal.csv), and the figures it prints are the module's."""
import os
import re
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PAGE = os.path.join(SOURCE, "docs", "howto", "python-module.md")


def test_the_page_example_runs():
    with open(PAGE, encoding="utf-8") as f:
        blocks = re.findall(r"^```python\n(.*?)^```", f.read(), re.M | re.S)
    assert len(blocks) == 1
    r = subprocess.run([sys.executable, "-c", blocks[0]], cwd=SOURCE, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    lines = r.stdout.splitlines()
    assert lines[0].startswith("['sensor_1', 'sensor_3', 'sensor_5']") and "time column" in lines[0]
    assert lines[-1].endswith("True")  # the contact solve converged
