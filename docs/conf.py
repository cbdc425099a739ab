"""Sphinx configuration of the rollspec documentation. Built by `bash docs/build.sh [BUILD_DIR]`, which
copies docs/ into BUILD_DIR/src, links the repository as `_repo` beside it, writes the generated
reference into reference/generated/ and runs sphinx-build -W."""
import inspect
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


def module_docstring_as_help_shows_it(app, what, name, obj, options, lines):
    """The module rollspec's docstrings are written for help(): the reference shows them as they read
    there (a literal block), not parsed as reStructuredText. Runs after napoleon (priority 900), from
    the object's own docstring; a pybind11 function's first line, its signature, is autodoc's."""
    if not (name == "rollspec" or name.startswith("rollspec.")):
        return
    text = inspect.getdoc(obj) or ""
    short = name.rsplit(".", 1)[-1]
    if text.startswith(short + "("):  # pybind11's signature line, which autodoc shows as the signature
        text = text.split("\n", 1)[1] if "\n" in text else ""
    body = text.strip("\n").splitlines()
    lines[:] = ["::", ""] + ["    " + line for line in body] + [""] if body else []


def setup(app):
    app.connect("autodoc-process-docstring", module_docstring_as_help_shows_it, priority=900)
