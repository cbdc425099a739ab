"""How the generated fault suite (test_program_faults.py) runs each program of the repository so that it
reaches its output check at once: a recipe per script, keyed by its path. Tokens: OUT (the output a
hostile target replaces), IN (an input the script reads), BIN (rollspec), STUDY (a shipped study), PY
(Debian's Python), S (the script itself). `out`: "file", "folder" or None (it prints only); `fixed`: the
outputs it writes at paths of its own (relative to a copy of the repository, `tree`); `help`: the
arguments of a run that only prints (None: none is cheap); `binary`: the argv position of a binary the
script runs (a missing one must be one line too)."""

PY_FILE = {"help": ["--help"]}
# A bench script that runs BIN and writes its record to OUT (`--bin BIN --record OUT`); the recipes are only read.
RECORDS_WITH_BIN = {"argv": ["PY", "S", "--bin", "BIN", "--record", "OUT"], "out": "file", "help": ["--help"], "binary": 3}

RECIPES = {
    # docs/
    "docs/build.sh": {"argv": ["bash", "S", "OUT"], "out": "folder", "help": None, "env": {"ROLLSPEC_BIN": "BIN"}},
    "docs/generate_reference.py": {"argv": ["PY", "S", "--bin", "BIN", "--out", "OUT"], "out": "folder",
                                   "help": ["--help"]},
    "docs/check_links.py": {"argv": ["PY", "S", "IN"], "in": "folder", "help": ["EMPTY"]},
    # the module rollspec in-process on the repository's data ($ROLLSPEC_SOURCE): no binary, no output file
    "docs/examples/plot_measured_map_contact.py": {"argv": ["PY", "S"], "help": None, "in": "folder",
                                                   "env": {"ROLLSPEC_SOURCE": "IN"}},
    "docs/examples/plot_sensor_bands.py": {"argv": ["PY", "S"], "help": None, "env": {"ROLLSPEC_BIN": "BIN"},
                                           "binary": "env"},
    "docs/examples/plot_speed_comparison.py": {"argv": ["PY", "S"], "help": None, "env": {"ROLLSPEC_BIN": "BIN"},
                                               "binary": "env"},
    "docs/examples/plot_speed_sweep.py": {"argv": ["PY", "S"], "help": None, "env": {"ROLLSPEC_BIN": "BIN"},
                                          "binary": "env"},
    "docs/examples/plot_your_rig.py": {"argv": ["PY", "S"], "help": None, "env": {"ROLLSPEC_BIN": "BIN"},
                                       "binary": "env"},
    # python/: BUILD is the folder it configures and builds into
    "python/tests/sanitized.sh": {"argv": ["bash", "S"], "out": "folder", "help": None, "env": {"BUILD": "OUT"}},
    # bench/
    "bench/bench_goals.py": {"argv": ["PY", "S", "measure", "--goals", "1", "--bin", "BINDIR"], "help": ["--help"],
                             "fixed": ["bench/goals.json"], "tree": ["bench", "python-post/rollspec_post"]},
    "bench/record_versions.py": {"argv": ["PY", "S", "accept", "engine"], "help": ["--help"],
                                 "fixed": ["bench/record_versions.json"],
                                 "tree": ["bench", "src", "kernels", "python-post/rollspec_post"]},
    "bench/record_csv.py": {"argv": ["PY", "S", "--record", "OUT", "--title", "t", "--describe", "d", "--", "true"],
                            "out": "file", "help": ["--help"]},
    "bench/contact/bench_answer_tables.py": RECORDS_WITH_BIN,
    "bench/contact/bench_contact_goals.py": {"argv": ["PY", "S", "--base", "BINDIR", "--new", "BINDIR"],
                                             "help": ["--help"], "binary": 3},
    "bench/contact/bench_plan_estimates.py": {"argv": ["PY", "S", "--binary", "BIN", "--json", "OUT"], "out": "file",
                                              "help": ["--help"], "binary": 3},
    "bench/contact/bench_sides_threads.py": {"argv": ["PY", "S", "--reference", "BIN", "--current", "BIN"],
                                             "help": ["--help"], "binary": 3},
    "bench/contact/bench_tables.py": {"argv": ["PY", "S", "--reference", "BIN", "--current", "BIN", "--json", "OUT"],
                                      "out": "file", "help": ["--help"], "binary": 3},
    "bench/contact/table_jackknife.py": {"argv": ["PY", "S", "BIN", "STUDY", "--work", "OUT"], "out": "folder",
                                         "help": ["--help"], "binary": 2},
    "bench/contact/table_uncertainty.py": {"argv": ["PY", "S", "BIN", "STUDY", "--work", "OUT"], "out": "folder",
                                           "help": ["--help"], "binary": 2},
    "bench/engine/bench_compare_power.py": {"argv": ["PY", "S", "--binary", "BIN", "--trials", "1", "--record", "OUT"],
                                            "out": "file", "help": ["--help"], "binary": 3},
    "bench/engine/bench_table_verdict.py": {"argv": ["PY", "S", "BIN", "--scene", "beam-s", "--tables", "2",
                                                    "--work", "OUT"], "out": "folder", "help": ["--help"],
                                           "binary": 2},
    "bench/engine/bench_common_random_numbers.py": {"argv": ["PY", "S", "--binary", "BIN"], "help": ["--help"],
                                                    "fixed": ["bench/records/common-random-numbers.json",
                                                              "docs/howto/sweeps.md"],
                                                    "tree": ["bench", "docs/howto", "python-post/rollspec_post"],
                                                    "binary": 3},
    "bench/engine/bench_default_accuracy.py": {"argv": ["PY", "S", "--bin", "BIN"], "help": ["--help"], "binary": 3},
    "bench/engine/bench_fit_coverage.py": {"argv": ["PY", "S", "--binary", "BIN", "--experiments", "1", "--log", "OUT"],
                                           "out": "file", "help": ["--help"], "binary": 3,
                                           "in_argv": ["PY", "S", "--summarise", "IN"], "in": "file"},
    "bench/engine/bench_memory_estimate.py": {"argv": ["PY", "S", "--bin", "BIN"], "help": ["--help"], "binary": 3},
    "bench/engine/bench_python_module.py": {"argv": ["PY", "S", "--bin", "BIN", "--rounds", "1", "--realisations", "2",
                                                     "--contact-threads", "1", "--record", "OUT"], "out": "file",
                                            "help": ["--help"], "binary": 3},
    "bench/engine/bench_recording_verdict.py": RECORDS_WITH_BIN,
    "bench/engine/bench_scaling.py": {"argv": ["PY", "S", "STUDY", "--release", "BIN"], "help": ["--help"],
                                      "binary": 4},
    "bench/engine/bench_tail_check.py": {"argv": ["PY", "S", "scene", "BIN", "STUDY", "10", "2", "10"], "help": None,
                                         "binary": 3},
    "bench/engine/bench_whole_run.py": {"argv": ["PY", "S", "--bin", "BIN"], "help": ["--help"], "binary": 3},
    "bench/engine/compare_results.py": {"argv": ["PY", "S", "IN", "IN"], "in": "folder", "help": None},
    "bench/engine/fit_factor_check.py": {"argv": ["PY", "S", "--save-rig", "OUT", "IN", "IN", "IN"], "out": "file",
                                         "in": "file", "help": ["--help"]},
    "bench/engine/fit_seed002_offline.py": {"argv": ["PY", "S", "--binary", "BIN", "--seeds", "1", "--keep", "OUT"],
                                            "out": "folder", "help": ["--help"], "binary": 3},
    "bench/engine/fit_seed002_roughness.py": {"argv": ["PY", "S", "--binary", "BIN", "--log", "OUT"], "out": "file",
                                              "help": ["--help"], "binary": 3, "fixed": ["docs/howto/fit.md"],
                                              "tree": ["bench", "docs/howto", "python-post/rollspec_post"]},
    "bench/engine/accuracy_checks.py": RECORDS_WITH_BIN,
    "bench/engine/seed000_examples.py": RECORDS_WITH_BIN,
    "bench/engine/seed001_loss_of_contact.py": RECORDS_WITH_BIN,
    "bench/engine/seed001_contrast.py": RECORDS_WITH_BIN,
    "bench/engine/seed002_modes.py": RECORDS_WITH_BIN,
    "bench/engine/seed002_routes.py": RECORDS_WITH_BIN,
    "bench/rolling/bench_rolling_pipe.py": {"argv": ["PY", "S", "--bin", "BIN", "--baseline", "BIN"],
                                            "help": ["--help"], "binary": 3},
    # studies/
    "studies/contact_filter_levels.py": {"argv": ["PY", "S", "--keep", "OUT"], "out": "folder", "help": ["--help"],
                                         "env": {"ROLLSPEC_BIN": "BIN"}},
    "studies/data/make_example_data.py": {"argv": ["PY", "S", "BIN"], "help": None, "binary": 2,
                                          "fixed": ["studies/data/example-signal.csv", "studies/data/measured-psd.csv"],
                                          "tree": ["studies/data/make_example_data.py", "python-post/rollspec_post"]},
    "studies/data/make_seed001_profiles.py": {"argv": ["PY", "S", "BIN"], "help": None, "binary": 2,
                                              "fixed": ["studies/data/seed001-profiles/beam-r-01.csv"],
                                              "tree": ["studies/data/make_seed001_profiles.py",
                                                       "studies/data/seed001-profiles", "python-post/rollspec_post"]},
    "studies/data/measured-profiles/make_measured_profiles.py": {
        "argv": ["PY", "S", "SRCDIR"], "help": None,
        "fixed": ["studies/data/measured-profiles/dektak-1-a.csv"],
        "tree": ["studies/data/measured-profiles", "python-post/rollspec_post"]},
    # tests/ (programs beside the tests: the format check prints only)
    "tests/engine/check_format.py": {"argv": ["PY", "S", "IN"], "in": "folder", "help": None},
    # python-post/ (its command: python-post/tests/test_post_faults.py runs every subcommand against every target)
    "python-post/rollspec_post/__main__.py": {"delegated": "python-post/tests/test_post_faults.py"},
    "python-post/docs/make_readme_pictures.sh": {"argv": ["bash", "S"], "help": None, "binary": "tree",
                                                 "fixed": ["python-post/docs/seed002-rig-psd.png"],
                                                 "tree": ["python-post/docs", "python-post/rollspec_post"]},
}
