"""Well-kept libraries do their jobs, not hand-written copies: JSON is written by nlohmann-json, and
content is hashed by one function (src/io/content_hash: FNV-1a 64, the hash the stored tables' names and
checkpoints carry).

The rules, read from the C++ of src/, kernels/ and python/ (comments blanked, literals kept):
- no JSON escaping by hand: no literal that writes an escaped quote ("\\\"") or a \\u00XX escape, and
  no function named json_string, json_escape, json_quote or escape_json (compare's and fit's JSON
  once had both);
- FNV's offset basis and prime appear only in src/io/content_hash.hpp/.cpp (a second copy once sat in
  the checkpoint, the table text and fit's journal);
- the engine's text is formatted by one function, io::formatted (src/io/number_text.hpp): no other
  snprintf or sprintf in src/ or python/ (56 calls into fixed buffers, which cut a long message short, once
  sat in 32 files). The kernels keep their own (their error messages; they include nothing of src/).
`violations` runs on the real tree and on scratch trees that break each rule, so the test can fail."""
import re

from source_scan import ROOT, code_only, scratch

ESCAPE_LITERAL = re.compile(r'"\\\\\\""|"[^"\n]*\\\\u00[0-9A-Fa-f]{2}')
ESCAPE_FUNCTION = re.compile(r"\b(json_string|json_escape|json_quote|escape_json)\s*\(")
FNV = re.compile(r"\b(1099511628211|0x100000001b3|14695981039346656037|0xcbf29ce484222325)(ull|ULL|u|U)?\b",
                 re.I)
HASH_HOME = {"src/io/content_hash.hpp", "src/io/content_hash.cpp"}
PRINTF_INTO = re.compile(r"\b(?:std::)?v?s(?:n)?printf\s*\(")
FORMAT_HOME = "src/io/number_text.hpp"


def cpp_files(root):
    for top in ("src", "kernels", "python"):
        for f in sorted((root / top).rglob("*")):
            if f.suffix in (".cpp", ".hpp", ".h") and f.is_file():
                yield f.relative_to(root).as_posix(), code_only(f.read_text(errors="replace"))


def violations(root):
    found = []
    for rel, code in cpp_files(root):
        for n, line in enumerate(code.splitlines(), 1):
            if ESCAPE_LITERAL.search(line) or ESCAPE_FUNCTION.search(line):
                found.append(f"{rel}:{n}: JSON escaped by hand; build a nlohmann::json and dump() it")
            if FNV.search(line) and rel not in HASH_HOME:
                found.append(f"{rel}:{n}: FNV-1a written again; call io::content_hash (src/io/content_hash.hpp)")
            if PRINTF_INTO.search(line) and rel != FORMAT_HOME and not rel.startswith("kernels/"):
                found.append(f"{rel}:{n}: text formatted into a buffer by hand; call io::formatted "
                             "(src/io/number_text.hpp)")
    return found


def test_the_tree_leaves_json_and_hashing_to_their_one_place():
    assert violations(ROOT) == []


def test_a_hand_written_json_escape_is_found(tmp_path):
    tree = scratch(tmp_path, {
        "src/cli/report.cpp": 'std::string q(char c) { return c == \'"\' ? "\\\\\\"" : std::string(1, c); }\n',
        "src/fit/journal.cpp": "std::string json_string(const std::string& s) { return s; }\n",
        "python/x.cpp": 'const char* u = "\\\\u0001";\n',
    })
    found = violations(tree)
    assert sorted(f.split(":")[0] for f in found) == ["python/x.cpp", "src/cli/report.cpp", "src/fit/journal.cpp"], found


def test_a_second_fnv_is_found_but_not_in_its_home_or_a_comment(tmp_path):
    tree = scratch(tmp_path, {
        "src/io/content_hash.cpp": "h *= 1099511628211ull;\n",
        "src/ensemble/checkpoint.cpp": "std::uint64_t h = 14695981039346656037ULL;\n",
        "kernels/contact/x.hpp": "// FNV's prime 0x100000001b3, in a comment only\n",
    })
    assert violations(tree) == ["src/ensemble/checkpoint.cpp:1: FNV-1a written again; call io::content_hash "
                                "(src/io/content_hash.hpp)"]


def test_a_second_formatter_is_found_but_not_in_its_home_or_the_kernels(tmp_path):
    tree = scratch(tmp_path, {
        "src/io/number_text.hpp": "std::vsnprintf(nullptr, 0, format, args);\n",
        "src/cli/plan.cpp": "char buf[32];\nstd::snprintf(buf, sizeof buf, \"%g\", x);\n",
        "python/y.cpp": "sprintf(buf, \"%d\", n);\n",
        "kernels/texture/psd.cpp": "std::snprintf(buf, sizeof buf, \"%g\", x);\n",
    })
    assert sorted(violations(tree)) == [
        "python/y.cpp:1: text formatted into a buffer by hand; call io::formatted (src/io/number_text.hpp)",
        "src/cli/plan.cpp:2: text formatted into a buffer by hand; call io::formatted (src/io/number_text.hpp)"]
