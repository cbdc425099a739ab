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
extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx_gallery.gen_gallery"]
# docs/examples/plot_*.py are run on every build (a failing example fails the build) and their
# figures and printed lines shown in the gallery.
sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "gallery",
    "filename_pattern": "/plot_",
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "download_all_examples": False,
    "remove_config_comments": True,
}
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}  # .rst: the gallery's generated pages
myst_enable_extensions = ["colon_fence", "dollarmath"]
myst_heading_anchors = 3
exclude_patterns = ["_repo", "_repo/**", "build.sh", "**/README.md", "examples/**", "validation/generated/goals-table.md",
                    "validation/generated/validation-records.md", "validation/generated/records/**",
                    "howto/generated/**"]
html_theme = "furo"
html_title = "rollspec"
# Wide tables and long usage lines wrap inside the page's column instead of being cut off (1280 px).
html_static_path = ["_static"]
html_css_files = ["rollspec.css"]
autodoc_member_order = "bysource"
autodoc_mock_imports = []
# The kernel notes are written for GitHub: they start at '##' under the page title and skip levels.
suppress_warnings = ["myst.header"]
