"""Sphinx configuration of the rollspec documentation. Built by `bash docs/build.sh [BUILD_DIR]`, which
copies docs/ into BUILD_DIR/src, links the repository as `_repo` beside it, writes the generated
reference into reference/generated/ and runs sphinx-build -W."""
import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = Path(os.environ.get("ROLLSPEC_SOURCE", HERE / "_repo")).resolve()
sys.path.insert(0, str(REPO / "python-post"))

project = "rollspec"
author = "the rollspec authors"
copyright = "rollspec authors"
extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon"]
source_suffix = {".md": "markdown"}
myst_enable_extensions = ["colon_fence", "dollarmath"]
myst_heading_anchors = 3
exclude_patterns = ["_repo", "_repo/**", "build.sh", "**/README.md", "validation/generated/goals-table.md"]
html_theme = "furo"
html_title = "rollspec"
autodoc_member_order = "bysource"
autodoc_mock_imports = []
# The kernel notes are written for GitHub: they start at '##' under the page title and skip levels.
suppress_warnings = ["myst.header"]
