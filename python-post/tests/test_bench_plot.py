"""`python3 -m rollspec_post bench`: work-precision plot from a small CSV; malformed CSVs refused."""
from conftest import is_png_with_content, post

CSV = """# work_precision: comment lines are skipped
method,parameter,value,seconds,error_db
exact_step,substeps,1,0.010,0.8
exact_step,substeps,4,0.035,0.05
exact_step,substeps,16,0.130,0.003
dopri5,rtol,1e-4,0.050,0.4
dopri5,rtol,1e-6,0.110,0.02
dopri5,rtol,1e-8,0.300,0.0009
"""


def test_bench_plot(tmp_path):
    csv = tmp_path / "wp.csv"
    csv.write_text(CSV)
    out = tmp_path / "wp.png"
    r = post("bench", csv, "--out", out)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)
    from rollspec_post.bench_plot import read_bench
    series, name = read_bench(str(csv))
    assert name == "error_db" and list(series) == ["exact_step", "dopri5"] and len(series["dopri5"]) == 3


def test_bench_clear_errors(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("integrator,seconds\nx,1\n")
    r = post("bench", bad, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "error_db or error" in r.stderr
    bad.write_text("method,seconds,error\nx,fast,1\n")
    r = post("bench", bad, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "bad.csv:2" in r.stderr
    r = post("bench", tmp_path / "missing.csv", "--out", tmp_path / "x.png")
    assert r.returncode == 66 and "no such file" in r.stderr
    assert not (tmp_path / "x.png").exists()
