"""Choices are enums: a study key's choice value is compared as a string only in src/study/sections/.

The rule, read from the sources:
- every choice key of a section is declared by a table of {enum value, "spelling", "doc"} rows
  (key_spec.hpp's Choice), never by a bare list of strings;
- the spellings of those rows are the choice values; outside src/study/sections/ no string literal
  equal to one of them is compared (==, !=, .compare, .find, .rfind): code there switches on the
  enum the section parsed, so a misspelt value cannot compile and fall through.
A few comparisons outside the sections test text that is not a study key's value but happens to
spell like one (a command's option, a file's column or attribute, the "none" of a path key):
ALLOWED lists each, with its count per file and why, so one more such comparison in that file fails.
`violations` runs on the real tree (none allowed) and on scratch trees that break each rule."""
import collections
import pathlib
import re

from source_scan import ROOT, calls, compared_literals, scratch, sources

SECTIONS = pathlib.PurePosixPath("src/study/sections")
ROW = re.compile(r'\{\s*[\w:\']+\s*,\s*"([^"]*)"\s*,')

# (file, literal): (comparisons in that file, why it is no study choice).
ALLOWED = {
    ("src/cli/compare_command.cpp", "table"): (1, "compare's --format option (table, csv or json)"),
    ("src/compare/measured_spectrum.cpp", "hann"): (2, "a psd result's /psd welch_window attribute (hann or rect)"),
    ("src/compare/measured_spectrum.cpp", "none"): (1, "a psd result's /psd welch_detrend attribute"),
    ("src/io/signal_csv.cpp", "none"): (1, "psd's --time-column none"),
    ("src/io/signal_file.cpp", "none"): (1, "psd's --time-column none"),
    ("src/io/signal_mat.cpp", "none"): (2, "psd's --time-column none"),
    ("src/stiffness/stiffness_table.cpp", "auto"): (1, "[stiffness] table, a text key whose auto names the cache file"),
    ("src/study/key_reader.cpp", "none"): (2, "a path key's none (no file)"),
    ("src/study/study.cpp", "none"): (1, "a path key's none (no file)"),
}


def choice_spellings(root):
    """{spelling: [where]} of every Choice row in the sections, and the bare-string choice_key calls."""
    spellings, bare = collections.defaultdict(list), []
    for rel, text in sources(root):
        if SECTIONS not in rel.parents:
            continue
        for m in ROW.finditer(text):
            spellings[m.group(1)].append(str(rel))
        for args in calls(text, "choice_key"):
            if re.search(r'\{\s*"', args):
                bare.append(f"{rel}: choice_key({args.split(',')[1].strip()} ...) lists its values as bare strings; "
                            "declare a ChoiceTable of {enum value, spelling, doc} rows")
    return spellings, bare


def violations(root, allowed=ALLOWED):
    spellings, found = choice_spellings(root)
    counts = collections.Counter()
    for rel, text in sources(root):
        if SECTIONS in rel.parents:
            continue
        for line_no, line in enumerate(text.splitlines(), 1):
            for value in compared_literals(line):
                if value not in spellings:
                    continue
                counts[(str(rel), value)] += 1
                if (str(rel), value) not in allowed:
                    found.append(f'{rel}:{line_no}: compares "{value}", a choice value of '
                                 f'{", ".join(sorted(set(spellings[value])))}; switch on the section\'s enum')
    for key, (n, why) in allowed.items():
        if counts[key] > n:
            found.append(f'{key[0]}: {counts[key]} comparisons with "{key[1]}", {n} allowed ({why})')
    return found


def test_choice_values_are_compared_only_in_the_sections():
    spellings, _ = choice_spellings(ROOT)
    for value in ("hertz", "self-affine", "linearised", "flying-beam", "clamped-clamped", "dopri5"):
        assert value in spellings, f"the sections' choice tables were not read ({value} missing)"
    assert violations(ROOT) == []


SECTION = {"src/study/sections/law_section.hpp":
           'inline constexpr ChoiceTable<Law, 2> kLaws{{\n  {Law::hertz, "hertz", ""},\n'
           '  {Law::path, "path", "a strip"},\n}};\n'}


def test_a_choice_compared_outside_the_sections_is_found(tmp_path):
    root = scratch(tmp_path, {**SECTION, "src/scenes/use.cpp": 'bool f(const S& s) { return s.law == "path"; }\n'})
    found = violations(root, allowed={})
    assert len(found) == 1 and 'src/scenes/use.cpp:1: compares "path"' in found[0]


def test_each_form_of_comparison_is_found(tmp_path):
    body = ('bool a = "hertz" != law;\nbool b = law.compare("hertz") == 0;\n'
            'bool c = text.find("path") != std::string::npos;\nbool d = text.rfind("path", 0) == 0;\n')
    found = violations(scratch(tmp_path, {**SECTION, "src/cli/use.cpp": body}), allowed={})
    assert [f.split(":")[1] for f in found] == ["1", "2", "3", "4"]


def test_other_literals_comments_and_the_sections_themselves_pass(tmp_path):
    files = {**SECTION,
             "src/study/sections/law_section.cpp": 'bool t = s.text("x.law") == "hertz";\n',
             "src/io/use.cpp": 'bool a = format == "json";  // not law == "hertz"\n/* law == "path" */\n'
                               'const char* m = "law == hertz";\n'}
    assert violations(scratch(tmp_path, files), allowed={}) == []


def test_an_allowed_comparison_counts(tmp_path):
    files = {**SECTION, "src/cli/opt.cpp": 'bool a = w == "hertz";\nbool b = w != "hertz";\n'}
    root = scratch(tmp_path, files)
    assert violations(root, allowed={("src/cli/opt.cpp", "hertz"): (2, "an option")}) == []
    found = violations(root, allowed={("src/cli/opt.cpp", "hertz"): (1, "an option")})
    assert found == ['src/cli/opt.cpp: 2 comparisons with "hertz", 1 allowed (an option)']


def test_a_choice_declared_as_bare_strings_is_found(tmp_path):
    files = {"src/study/sections/old.cpp":
             'auto k = choice_key("a", "b", "doc", std::string("x"), {"x", "y"});\n'}
    found = violations(scratch(tmp_path, files), allowed={})
    assert len(found) == 1 and "bare strings" in found[0]
