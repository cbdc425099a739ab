"""bench/engine/bench_table_verdict.py's intervals over the tables (a pigeonhole bootstrap, Owen 2007), on
simulated verdicts whose share rejected is known: every model table meets every other table's measurement, and
each table moves all its comparisons (a model effect a_t and a measurement effect b_u, each half the variance of
a comparison's own draw), as tables do in the bench. Over 100 such benches of 16 tables, at a true size of 0.05,
the interval over the tables holds 0.05 about as often as its 95 % says, while a binomial interval that counts
the 240 comparisons as independent holds it far less often: the reason the records give the former. About 6 s,
no rollspec run."""
import sys

import numpy as np
from scipy import stats

from conftest import SOURCE

sys.path.insert(0, str(SOURCE / "bench" / "engine"))
import bench_table_verdict  # noqa: E402


def simulated_bench(stream, tables=16, size=0.05):
    """{(t, u): (p, share inside)}: rejected (p = 0.01) where a_t + b_u + e_tu exceeds the level that makes
    the marginal share `size`, else p = 0.5."""
    a, b = stream.normal(0.0, np.sqrt(0.5), tables), stream.normal(0.0, np.sqrt(0.5), tables)
    cut = stats.norm.ppf(1.0 - size) * np.sqrt(2.0)
    return {(t, u): (0.01 if a[t] + b[u] + stream.normal() > cut else 0.5, 1.0)
            for t in range(tables) for u in range(tables) if t != u}


def test_the_interval_over_the_tables_holds_the_true_size_as_often_as_it_says():
    stream = np.random.Generator(np.random.Philox(key=2026))
    benches, held, held_binomial = 100, 0, 0
    for _ in range(benches):
        found = simulated_bench(stream)
        share, _, (low, high) = bench_table_verdict.rejections(found)
        assert low <= share <= high
        held += low <= 0.05 <= high
        half = 1.96 * np.sqrt(share * (1.0 - share) / len(found))
        held_binomial += share - half <= 0.05 <= share + half
    assert 0.88 <= held / benches <= 1.0, held
    assert held_binomial / benches < 0.85, held_binomial
    assert held_binomial < held
