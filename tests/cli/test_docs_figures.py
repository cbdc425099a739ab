"""No figure from a run is typed into the pages that render theirs from records: outside fenced blocks
(the records' tables come in through ```{include} generated/records/...```), a page's text holds no
percentage, no dB figure and no number in e-notation, except the inputs, thresholds, tests' bounds,
equations' values and published figures listed here with what they are. A fenced block is not checked
(commands, and the renderer's includes): output quoted in one is listed in bench/figures_inventory.md. Reads the Markdown sources only: well under a second.
The pages and parts of pages not yet converted are listed in bench/figures_inventory.md."""
import re

import pytest

from conftest import SOURCE

# page: (where the checked part ends, or None for the whole page; {figure as written: what it is})
PAGES = {
    "docs/validation/seeds.md": (None, {
        "1e-6": "the bound tests/cli/test_profile_surfaces.py holds seed-method surfaces to",
        "10 %": "the bound tests/cli/test_profile_surfaces.py holds spectral surfaces to",
        "30 %": "the bound tests/cli/test_seed001_chain.py holds beam R above",
        "8 %": "the bound tests/cli/test_seed001_chain.py holds beam S below",
        "5 %": "the engine's threshold for a fit's error and for a run dominated by impacts",
        "6.8e6": "seed 002's published k0",
    }),
    "docs/tutorials/speed.md": (None, {}),
    "docs/validation/contact-filter.md": ("The other figures from here on (run times", {}),
    "docs/howto/profiles-to-table.md": (None, {"5 %": "the threshold beyond which a curve fit's error is flagged"}),
    "docs/validation/benchmarks.md": (None, {"1e-3": "[blocked_force] answer_tolerance the bench script sets (input)"}),
    "docs/validation/accuracy.md": ("## Measured once, not re-run", {"95 %": "the intervals' nominal level"}),
    "docs/validation/pictures.md": (None, {"95 %": "the intervals' nominal level"}),
    "README.md": (None, {"95 %": "the intervals' nominal level", "10 dB": "compare's --noise-margin default"}),
    "docs/tutorials/first-study.md": (None, {"95 %": "the intervals' nominal level"}),
    "docs/tutorials/your-rig.md": (None, {
        "95 %": "the intervals' nominal level", "10 dB": "compare's --noise-margin default",
        "5 %": "the engine's threshold for a run dominated by impacts",
        "6 dB": "20 log10 2: twice the roughness in a linear model", "2e-8": "the stand-in rig's roughness, an input"}),
    "docs/tutorials/compare.md": (None, {
        "10 dB": "compare's --noise-margin default", "0.4 dB": "10 log10(1 + 10^-1): noise at the 10 dB margin",
        "6 dB": "compare's flat-band threshold", "19.8 dB": "20 log10 9.80665: g read as m/s²",
        "60 dB": "20 log10 1000: mm/s² read as m/s²", "3 dB": "a wrong model the bench script tries (input)",
        "10 %": "a wrong model the bench script tries (input)",
        "5 %": "the engine's threshold for a run dominated by impacts"}),
    "docs/tutorials/measurements.md": (None, {"19.8 dB": "20 log10 9.80665: g read as m/s²",
                                              "60 dB": "20 log10 1000: mm/s² read as m/s²"}),
    "docs/howto/roughness.md": (None, {"0.3 dB": "ISO 3095 Eq. 10-11's band integral against the band level (theory)"}),
    "docs/howto/python-module.md": (None, {}),
}
FIGURE = re.compile(r"[+−-]?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?:\s?[–-]\s?\d+(?:\.\d+)?)?\s?(?:%|dB\b)"
                    r"|\b\d+(?:\.\d+)?e[-+]?\d+\b")
FENCE = re.compile(r"^[ \t]*(```+|:::+).*?^[ \t]*\1[ \t]*$", re.M | re.S)


def typed_figures(text, allowed):
    """[(line number, figure)] of the figures in the text outside fenced blocks that are not allowed."""
    kept = FENCE.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    found = []
    for n, line in enumerate(kept.splitlines(), 1):
        for m in FIGURE.finditer(line):
            if m.group(0).strip() not in allowed:
                found.append((n, m.group(0).strip()))
    return found


@pytest.mark.parametrize("page", sorted(PAGES))
def test_no_run_figure_is_typed_outside_the_rendered_records(page):
    stop, allowed = PAGES[page]
    text = (SOURCE / page).read_text(encoding="utf-8")
    if stop is not None:
        assert stop in text, f"{page}: the checked part's end ({stop!r}) is gone: update PAGES"
        text = text[:text.index(stop)]
    found = typed_figures(text, allowed)
    assert not found, (f"{page}: figures typed outside a rendered record (line, figure): {found}; render them "
                       "from a record (bench/bench_record.py) or, for an input or a published figure, list it here")


@pytest.mark.parametrize("page", sorted(PAGES))
def test_every_allowed_figure_is_still_on_its_page(page):
    """The allowed list does not outlive the page's text (a stale exception could hide a typed figure)."""
    stop, allowed = PAGES[page]
    text = (SOURCE / page).read_text(encoding="utf-8")
    text = text if stop is None else text[:text.index(stop)]
    present = {m.group(0).strip() for m in FIGURE.finditer(FENCE.sub("", text))}
    assert set(allowed) <= present, sorted(set(allowed) - present)


@pytest.mark.parametrize("line, figures", [
    ("beam S 2.2–4.0 % of the time", ["2.2–4.0 %"]),
    ("the 800 Hz band is 25.9 dB above", ["25.9 dB"]),
    ("a rise of +8.5 dB at 5 kHz, −1.1 dB below", ["+8.5 dB", "−1.1 dB"]),
    ("k0 = 1.48e7 N/m", ["1.48e7"]),
    ("the 5 kHz band, 100–800 Hz, 25 realisations, Eq. 11–13, 2a = 139 µm", []),
])
def test_the_pattern_finds_typed_run_figures_and_not_frequencies_or_counts(line, figures):
    assert [f for _, f in typed_figures(line, {})] == figures


def test_figures_inside_a_fenced_block_are_the_renderer_s_and_not_flagged():
    text = "a\n```{include} generated/records/x.md\n```\n```text\nrun gives 5.1 %\n```\nb 3.3 dB\n"
    assert typed_figures(text, {}) == [(7, "3.3 dB")]
