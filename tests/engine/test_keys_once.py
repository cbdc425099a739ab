"""Keys bound once: a study key's name appears in one line of the section code, the line declaring it.

A key is declared by a section's SectionKeys (src/study/sections/section_keys.hpp:
`SectionKeys<S>("ball").real("radius", ...)`), which gives its KeySpec, its parsing and its origin, or,
not yet converted, by a KeySpec builder (`real_key("ball", "radius", ...)`). A declaration's key appears in
a line of section code (src/study/sections/ and the declaring file's .hpp/.cpp pair) that
- declares it;
- holds the literal "section.key" (a string read, or a --set text "section.key=value");
- holds the literal "key" or the identifier key_origin (a hand-kept origin field) in the declaring file's
  pair, other than a line declaring a key or a ChoiceTable row (whose spelling may be a key's name).
More than one such line is a key written twice. PENDING lists the keys of the sections not converted yet,
each still written more than once; ELSEWHERE counts, per file, the lines outside the section code that name
a key as "section.key". Both can only shrink: a PENDING key now written once, or a file below its count,
fails until the list is lowered. `violations` runs on the real tree and on scratch trees that break each rule."""
import collections
import re

from source_scan import ROOT, TOKENS, scratch, sources

BUILDER = re.compile(r'\b(?:real|integer|choice|text|path|bool)_key\s*\(\s*"(\w+)"\s*,\s*"(\w+)"')
BINDER = re.compile(r'\bSectionKeys<[\w:]+>\s*\(\s*"(\w+)"\s*\)')
BOUND = re.compile(r'\.\s*(?:real|integer|boolean|text|path|choice)\s*\(\s*"')
# A row of a ChoiceTable ({value, "spelling", "doc"}): its spelling is a value, not a key, even where they agree.
CHOICE_ROW = re.compile(r'^\s*\{\s*[\w:\']+\s*,\s*"')
LITERAL = re.compile(r'"((?:\\.|[^"\\\n])*)"')

# section.key: why it is still written more than once (the sections that keep a hand-written parse). Every
# section declares its keys once now: the list stays, empty, for the checks below.
PENDING = {}


# Lines outside the section code that name a study key as "section.key", per file: the scenes' first keys
# of the templates and their dimension-plausibility relations (which name keys by text), --set texts the
# engine writes, the init template's [study] lines and the loader's own handling of study.scene. Not yet
# reached through the sections' declarations; each count can only shrink.
ELSEWHERE = {
    "src/fit/fit_model.cpp": 1,
}


def masked(text):
    """The text with each string or char literal's contents blanked (quotes and length kept), so that a ';' or
    '(' inside a doc does not end a statement."""
    def blank(m):
        q = m.group(0)[0]
        return q + " " * (len(m.group(0)) - 2) + q if q in "\"'" else m.group(0)
    return TOKENS.sub(blank, text)


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def declarations(files):
    """[(file, line, section, key)] of every key declaration."""
    out = []
    for rel, text in files.items():
        for m in BUILDER.finditer(text):
            out.append((rel, line_of(text, m.start(2)), m.group(1), m.group(2)))
        blank = masked(text)
        for m in BINDER.finditer(text):
            end = blank.find(";", m.end())
            for b in BOUND.finditer(blank, m.end(), end if end >= 0 else len(blank)):
                key = LITERAL.match(text, b.end() - 1).group(1)
                out.append((rel, line_of(text, b.end()), m.group(1), key))
    return out


def pair(rel):
    stem = rel.rsplit(".", 1)[0]
    return {stem + ".cpp", stem + ".hpp"}


SECTIONS = "src/study/sections/"


def appearances(files, decl, declaring_lines):
    """The lines of section code (src/study/sections/ and the declaring file's pair) naming the key."""
    rel, line, section, key = decl
    found = {(rel, line)}
    full = section + "." + key
    for f, text in files.items():
        own = f in pair(rel)
        if not (own or f.startswith(SECTIONS)):
            continue
        for n, code in enumerate(text.splitlines(), 1):
            literals = LITERAL.findall(code)
            if any(v == full or v.startswith(full + "=") for v in literals):
                found.add((f, n))
            elif (own and (f, n) not in declaring_lines and not CHOICE_ROW.match(code)
                  and (key in literals or re.search(rf"\b{key}_origin\b", code))):
                found.add((f, n))
    return found


def named_elsewhere(files, decls):
    """{file: lines} outside the section code that name a key by its full name ("section.key")."""
    names = {s + "." + k for _, _, s, k in decls}
    out = collections.Counter()
    for f, text in files.items():
        if f.startswith(SECTIONS):
            continue
        for code in text.splitlines():
            if any(v in names or v.split("=")[0] in names for v in LITERAL.findall(code)):
                out[f] += 1
    return out


def violations(root, pending=PENDING, elsewhere=ELSEWHERE):
    files = {str(rel): text for rel, text in sources(root)}
    decls = declarations(files)
    declaring_lines = {(f, n) for f, n, _, _ in decls}
    out, twice = [], set()
    for decl in decls:
        full = decl[2] + "." + decl[3]
        lines = sorted(appearances(files, decl, declaring_lines))
        if len(lines) > 1:
            twice.add(full)
            if full not in pending:
                out.append(f"{decl[0]}:{decl[1]}: key {full} appears in {len(lines)} lines of section code ("
                           + ", ".join(f"{f}:{n}" for f, n in lines) + "); declare it once (SectionKeys)")
    for full in sorted(set(pending) - twice):
        out.append(f"PENDING lists {full}, which now appears once (or is gone): remove it from the list")
    named = named_elsewhere(files, decls)
    for f in sorted(set(named) | set(elsewhere)):
        if named[f] != elsewhere.get(f, 0):
            out.append(f"{f}: {named[f]} lines name a study key as \"section.key\", ELSEWHERE allows "
                       f"{elsewhere.get(f, 0)}" + (" (lower it: it can only shrink)" if named[f] < elsewhere.get(f, 0)
                                                  else "; reach the key through its section (SectionKeys)"))
    return out, decls


def test_every_key_name_is_in_one_line_of_src():
    found, decls = violations(ROOT)
    keys = {(s, k) for _, _, s, k in decls}
    assert {("ball", "radius"), ("beam", "effective_length"), ("texture", "hurst"), ("study", "seed"),
            ("spectrum", "skip_start"), ("imposed", "times")} <= keys, "the key declarations were not read"
    assert len(keys) >= 150, len(keys)
    assert found == []


BOUND_SECTION = ('inline constexpr ChoiceTable<Shape, 1> kShapes{{\n    {Shape::end, "end", "a value spelt as a key"},\n'
                 '}};\nSectionKeys<BallSection> BallSection::declare() {\n  return SectionKeys<B>("ball")\n'
                 '      .real("radius", &B::radius, "m", "radius; not (a) doc", "0.02", above(0.0))\n'
                 '      .path("end", &B::end, "end", "none");\n}\ntemplate struct DeclaredSection<BallSection>;\n')


def test_a_key_written_once_passes(tmp_path):
    files = {"src/study/sections/ball_section.cpp": BOUND_SECTION + 'void f(const B& b) { b.origin(b.end); }\n',
             "src/scenes/other.cpp": 'const char* a = "end";\n'}
    found, decls = violations(scratch(tmp_path, files), pending={}, elsewhere={})
    assert found == [] and [d[3] for d in decls] == ["radius", "end"]


def test_a_key_read_again_or_kept_by_hand_is_found(tmp_path):
    files = {"src/study/sections/ball_section.cpp": BOUND_SECTION + 'double r = s.real("ball.radius");\n',
             "src/study/sections/ball_section.hpp": "struct B : KeyedSection {\n  KeyOrigin end_origin;\n};\n"}
    found, _ = violations(scratch(tmp_path, files), pending={}, elsewhere={})
    assert len(found) == 2
    assert "key ball.radius appears in 2 lines" in found[0] and "ball_section.cpp:10" in found[0]
    assert "key ball.end appears in 2 lines" in found[1] and "ball_section.hpp:2" in found[1]


def test_a_key_named_outside_the_sections_counts_against_its_file(tmp_path):
    files = {"src/study/sections/ball_section.cpp": BOUND_SECTION,
             "src/cli/set.cpp": 'auto t = std::string("ball.end=") + v;\nauto u = "ball.radius";\nauto w = "ball.x";\n'}
    root = scratch(tmp_path, files)
    assert violations(root, pending={}, elsewhere={"src/cli/set.cpp": 2})[0] == []
    assert violations(root, pending={}, elsewhere={"src/cli/set.cpp": 1})[0] == [
        'src/cli/set.cpp: 2 lines name a study key as "section.key", ELSEWHERE allows 1; reach the key through its '
        "section (SectionKeys)"]
    assert violations(root, pending={}, elsewhere={"src/cli/set.cpp": 3})[0] == [
        'src/cli/set.cpp: 2 lines name a study key as "section.key", ELSEWHERE allows 3 (lower it: it can only '
        "shrink)"]


def test_a_builder_key_parsed_by_hand_is_found_and_pending_only_shrinks(tmp_path):
    files = {"src/study/sections/flat_section.cpp":
             'auto k = real_key("flat", "poisson", "-", "doc", std::string("0.3"), -1.0, 0.5);\n'
             'auto k2 = real_key(\n    "flat", "e", "Pa", "doc", std::string("1"), 0.0, inf);\n'
             'double p = s.real("flat.poisson");\n'}
    root = scratch(tmp_path, files)
    found, _ = violations(root, pending={}, elsewhere={})
    assert len(found) == 1 and found[0].startswith("src/study/sections/flat_section.cpp:1: key flat.poisson")
    assert violations(root, pending={"flat.poisson": "not yet"}, elsewhere={})[0] == []
    assert violations(root, pending={"flat.poisson": "", "flat.e": ""}, elsewhere={})[0] == [
        "PENDING lists flat.e, which now appears once (or is gone): remove it from the list"]
