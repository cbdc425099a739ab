"""Issue 16, items 9 and 10 under resource limits (CTest label `fault`: an address-space limit
(ulimit -v) cannot be combined with AddressSanitizer's shadow memory, so the sanitizer pass skips
these). Each case: a clear refusal before any allocation, never an abort, a signal or silently
dropped data."""
import resource
import subprocess

from conftest import BIN, EX_CONFIG, EX_DATAERR, SOURCE, assert_refused, oscillator_study, run

RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"




# --- item 10: a read error is an error, never the end of the file -----------------------------------

def test_a_line_longer_than_memory_is_an_error_not_the_end(tmp_path):
    sig = tmp_path / "sig.csv"
    with open(sig, "w") as f:
        f.write("a\n" + "".join(f"{i % 5}\n" for i in range(64)))
        f.write("1" * 300_000_000 + "\n")
        f.write("".join(f"{i % 3}\n" for i in range(64)))

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (400 << 20, 400 << 20))
    r = subprocess.run([BIN, "psd", str(sig), "--fs", "100", "--segment", "16"], capture_output=True, text=True,
                       preexec_fn=limit)
    assert_refused(r, EX_DATAERR, ["sig.csv:66: cannot read this line", "the data after it were not read"])
    assert r.stdout == ""


# --- item 9: resources estimated up front; no allocation failure reaches FFTW or std::bad_alloc ------

def limited(gib):
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (gib << 30, gib << 30))
    return limit


def run_limited(args, gib=2):
    return subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, preexec_fn=limited(gib), timeout=60)


def test_memory_estimate_refuses_before_any_allocation(tmp_path):
    s = oscillator_study(tmp_path)
    out = tmp_path / "r.h5"
    big = ["--set", "signal.sample_rate=1e6", "--set", "signal.duration=200", "--set", "spectrum.band_max=1e5"]
    r = run_limited(["run", s, "--out", out, "--quiet", *big])
    assert_refused(r, EX_CONFIG, ["needs an estimated", "[signal] sample_rate = 1e+06", "[signal] duration = 200",
                           "is available", "--force"])
    assert not out.exists() and not (tmp_path / "r.h5.checkpoint").exists()
    r = run_limited(["plan", s, *big])
    assert r.returncode == 0, r.stderr
    assert "memory: estimated peak" in r.stdout and "rollspec run refuses it" in r.stdout
    r = run(["plan", s])
    assert r.returncode == 0 and "memory: estimated peak" in r.stdout and "checkpoint disk: 1 chunk of" in r.stdout
    assert "run time" not in r.stdout  # plan computes nothing unless asked
    r = run(["plan", s, "--probe"])
    assert r.returncode == 0 and "s per realisation (probe of realisation 0); the ensemble of 4 on" in r.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.ini"], "plan writes no file"


def test_documented_maximum_surface_grid_is_refused_not_crashed(tmp_path):
    t = tmp_path / "t.ini"
    t.write_text((SOURCE / "studies" / "texture-demo.ini").read_text())
    r = run_limited(["texture", t, "--out", tmp_path / "t.h5", "--set", "surface.nx=16384", "--set", "surface.ny=16384"])
    assert_refused(r, EX_CONFIG, ["[surface] nx = 16384", "[surface] ny = 16384", "--force"])
    h = tmp_path / "h.ini"
    h.write_text((SOURCE / "studies" / "hertz.ini").read_text())
    r = run_limited(["stiffness", h, "--quiet", "--set", "surface.nx=16384", "--set", "surface.ny=16384"])
    assert_refused(r, EX_CONFIG, ["contact solver grid", "[surface] nx = 16384"])
    assert not (tmp_path / "tables").exists()


def test_blocked_force_window_at_its_maximum_is_refused(tmp_path):
    r = run_limited(["run", RIG, "--out", tmp_path / "r.h5", "--quiet", "--set", "contact.law=linearised",
                     "--set", "contact.blocked_force=solver", "--set", "blocked_force.window=4096",
                     "--set", "surface.ny=4096"])
    assert_refused(r, EX_CONFIG, ["blocked-force contact window", "[blocked_force] window = 4096", "[surface] ny = 4096"])


def test_a_dataset_larger_than_memory_is_refused_by_compare(tmp_path):
    import h5py
    big = tmp_path / "big.h5"
    s = oscillator_study(tmp_path)
    assert run(["run", s, "--out", big, "--quiet"]).returncode == 0
    with h5py.File(big, "r+") as f:
        del f["/bands/level_db"]
        f.create_dataset("/bands/level_db", shape=(1_000_000, 1_000_000), dtype="f8", chunks=(1, 1024))
    m = tmp_path / "m.csv"
    m.write_text("frequency_hz,psd\n1,1e-3\n300,2e-3\n500,1e-3\n")
    r = run_limited(["compare", big, m])
    assert_refused(r, EX_DATAERR, ["/bands/level_db holds 1000000000000 values", "more than the memory available"])
