"""The Monte Carlo from Python against the command line (BOUNCELAB_BIN), against closed forms,
and on a real Dask cluster against the single-process call (docs/scale.md)."""

import json
import pickle
from pathlib import Path

import numpy as np
import pytest
from cli_binary import as_package, cli

import bouncelab


def answer(out):
    """The command line's JSON, every key (its `ball` object and `conditions` included), as the
    package holds it."""
    return as_package(json.loads(out))


ROOT = Path(__file__).resolve().parents[2]
VARY = {"k_p": 0.05, "c": 0.05, "k_r": 0.05}


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))


@pytest.mark.parametrize("dist", ["normal", "uniform", "lognormal"])
def test_the_same_numbers_as_the_command_line(dist):
    code, out, err = cli(
        "mc", "--preset", "golf", "--vary", "k_p=5%,c=5%,k_r=5%", "--dist", dist,
        "--samples", "3000", "--seed", "17", "--format", "json",
    )
    assert code == 0, err
    # json.loads reads each number back exactly (shortest round-trip text): equality is exact
    assert bouncelab.monte_carlo(
        preset="golf", vary=VARY, samples=3000, seed=17, dist=dist
    ) == answer(out)


def test_vary_as_the_command_line_writes_it():
    a = bouncelab.monte_carlo(preset="tennis", vary="k_r=10%,v0=0.02", samples=50, seed=2)
    b = bouncelab.monte_carlo(preset="tennis", vary={"v0": 0.02, "k_r": 0.1}, samples=50, seed=2)
    assert a == b and list(a["vary"]) == ["k_r", "v0"]


def test_samples_give_the_quantiles_numpy_computes():
    r = bouncelab.monte_carlo(preset="golf", vary=VARY, samples=2001, seed=3, return_samples=True)
    v = r["values"]
    assert set(v) == {"k_p", "c", "k_r", "cor", "max_force", "contact_time"}
    assert all(a.shape == (2001,) for a in v.values())
    for key in ["cor", "max_force", "contact_time"]:
        st = r["stats"][key]
        assert st["mean"] == pytest.approx(np.mean(v[key]), rel=1e-14)
        assert st["sd"] == pytest.approx(np.std(v[key], ddof=1), rel=1e-12)
        assert (st["min"], st["max"]) == (v[key].min(), v[key].max())
        for p, q in st["q"].items():
            # numpy's default method is type 7, as bouncelab's
            assert q == pytest.approx(np.quantile(v[key], float(p) / 100), rel=1e-15)
    # the inputs' spread: sd 5 % of the nominal value (2001 samples: within 5 standard errors)
    k_p = bouncelab.run(preset="golf").k_p
    assert np.std(v["k_p"], ddof=1) / k_p == pytest.approx(0.05, rel=5 / np.sqrt(2 * 2001))


def test_each_estimate_carries_its_95_percent_interval():
    # the quantiles' ends are samples (order statistics), around the estimate; the mean's is
    # Student's t over s/√n; 200 samples leave the 1 % and 99 % quantiles an open end (None,
    # the JSON's null), which the warnings name (src/analysis/mc_interval.rs)
    r = bouncelab.monte_carlo(preset="golf", vary=VARY, samples=200, seed=7, return_samples=True)
    v = r["values"]["cor"]
    st = r["stats"]["cor"]
    assert st["mean_se"] == pytest.approx(np.std(v, ddof=1) / np.sqrt(200), rel=1e-12)
    lo, hi = st["mean_ci"]
    assert lo < st["mean"] < hi and hi - st["mean"] == pytest.approx(1.971957 * st["mean_se"])
    for p, (a, b) in st["q_ci"].items():
        assert all(x in v for x in (a, b) if x is not None), p
        below, above = (-np.inf if a is None else a), (np.inf if b is None else b)
        assert below <= st["q"][p] <= above, p
    assert st["q_ci"]["1"][0] is None and st["q_ci"]["99"][1] is None
    assert None not in st["q_ci"]["2.5"]
    assert len(r["warnings"]) == 1 and "1 %, 99 %" in r["warnings"][0]
    assert bouncelab.monte_carlo(preset="golf", vary=VARY, samples=400, seed=7)["warnings"] == []


def test_open_ends_are_the_json_nulls():
    # 200 samples: the 1 % and 99 % quantiles' intervals have an open end — None here, null in
    # the command line's JSON, so the two dicts are equal
    code, out, err = cli(
        "mc", "--preset", "golf", "--vary", "k_p=5%,c=5%,k_r=5%", "--samples", "200",
        "--seed", "7", "--format", "json",
    )
    assert code == 0, err
    assert bouncelab.monte_carlo(preset="golf", vary=VARY, samples=200, seed=7) == answer(out)


def test_zero_spread_is_the_impact_of_run():
    r = bouncelab.monte_carlo(preset="golf", vary={"k_r": 0.0}, samples=5, seed=1)
    assert r["stats"]["cor"]["mean"] == pytest.approx(bouncelab.run(preset="golf").cor, abs=1e-12)
    assert r["stats"]["cor"]["sd"] == 0.0


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"vary": {"k_q": 0.05}}, "invalid vary: unknown parameter 'k_q'"),
        ({"vary": {"k_p": -0.05}}, "invalid vary k_p: -0.05"),
        ({"vary": VARY, "samples": 0}, "invalid samples: 0 (must be at least 1)"),
        ({"vary": VARY, "dist": "cauchy"}, "invalid dist: 'cauchy'"),
    ],
)
def test_bad_input_raises_the_command_lines_message(kwargs, message):
    with pytest.raises(ValueError) as e:
        bouncelab.monte_carlo(preset="golf", **kwargs)
    assert str(e.value).startswith(message)


def test_the_results_pickle():
    r = bouncelab.monte_carlo(preset="golf", vary=VARY, samples=20, seed=1, return_samples=True)
    back = pickle.loads(pickle.dumps(r))
    assert back["stats"] == r["stats"]
    assert np.array_equal(back["values"]["cor"], r["values"]["cor"])


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as c:
        yield c


def test_dask_gives_the_single_process_answer(client):
    import bouncelab.dask

    kw = dict(preset="golf", vary=VARY, samples=10_007, seed=23)
    one = bouncelab.monte_carlo(**kw)
    # uneven chunks, on two worker processes
    on_cluster = bouncelab.dask.monte_carlo(client, **kw, chunk=3_000)
    assert on_cluster == one
    assert pickle.loads(pickle.dumps(on_cluster)) == one
    # another seed, another answer
    assert bouncelab.dask.monte_carlo(client, **{**kw, "seed": 24}, chunk=5_000) != one


def test_hertz_samples_of_a_tabulated_ball_count_as_cheap_ones(client, tmp_path):
    """Under Hertz the work limit counts a sample of a ball the Hertz table answers as 1/40 of
    an impact (docs/scale.md): golf's 30 000 run, in one call and through Dask, whose client
    checks a chunk as its worker does; a ball whose cell is outside the table (baseball's K_r
    × 10⁶, a user preset: λ̂ past the grid; baseball itself is in the table since its kink
    band was split) counts a whole impact a sample, and 30 000 (more than 25 000) are
    refused."""
    import bouncelab.dask

    kw = dict(preset="golf", vary=VARY, samples=30_000, seed=5, law="hertz")
    one = bouncelab.monte_carlo(**kw)
    assert bouncelab.dask.monte_carlo(client, **kw, chunk=30_000) == one
    presets = tmp_path / "config" / "bouncelab" / "presets"
    presets.mkdir(parents=True)
    baseball = (ROOT / "presets" / "baseball.toml").read_text()
    off_table = baseball.replace('name = "baseball"', 'name = "off-table"')
    off_table = off_table.replace("k_r = 4.2e5", "k_r = 4.2e11")
    (presets / "off-table.toml").write_text(off_table)
    with pytest.raises(ValueError, match="too much work: 30000 samples is 30000 hertz-law"):
        bouncelab.monte_carlo(**{**kw, "preset": "off-table"})


def close_but_the_sums(streamed, one):
    """The streaming merge's answer against the single call's: every number the same bits
    but the mean, sd and the mean's interval (Chan's update against a compensated sum), those
    within 1e-13 (docs/scale.md)."""
    rest = lambda d: {k: v for k, v in d.items() if k != "stats"}  # noqa: E731
    assert rest(streamed) == rest(one)
    for q in ("cor", "max_force", "contact_time"):
        a, b = streamed["stats"][q], one["stats"][q]
        for k in ("n", "min", "max", "q", "q_ci"):
            assert a[k] == b[k], (q, k)
        for k in ("mean", "sd", "mean_se"):
            assert a[k] == pytest.approx(b[k], rel=1e-13, nan_ok=True), (q, k)
        assert a["mean_ci"] == pytest.approx(b["mean_ci"], rel=1e-13, nan_ok=True), q


def test_dask_streams_the_merge_with_the_single_process_quantiles(client):
    """Issue 54 item 1: beyond `exact_below` the values stay on the workers; the client merges
    per-task moments (Chan) and finds the exact order statistics by refined histograms. Few
    bins and a small cap force several refining passes."""
    import bouncelab.dask

    kw = dict(preset="golf", vary=VARY, samples=200_003, seed=7, dist="lognormal")
    one = bouncelab.monte_carlo(**kw)
    streamed = bouncelab.dask.monte_carlo(
        client, **kw, chunk=40_000, exact_below=0, bins=16, cap=300
    )
    close_but_the_sums(streamed, one)


def test_the_streaming_merge_is_exact_with_ties_and_missing_values(monkeypatch):
    """Order statistics through bins that cannot be split (every value equal) and many ties,
    with NaN contact times (no rebound), against the gathered merge of the same values."""
    pytest.importorskip("dask")
    import dask

    import bouncelab.dask

    def fake(options, start, count):
        i = np.arange(start, start + count)
        cor = np.round(np.sin(i * 0.37) * 0.2 + 0.5, 2)
        force = np.full(count, 5.0)
        time = np.where(i % 7 == 0, np.nan, 1e-3 + (i % 13) * 1e-5)
        return cor, force, time

    monkeypatch.setattr(bouncelab.dask, "_chunk", fake)
    kw = dict(preset="golf", vary=VARY, samples=50_001, seed=1, chunk=7_000)
    with dask.config.set(scheduler="threads"):
        gathered = bouncelab.dask.monte_carlo(None, **kw)
        streamed = bouncelab.dask.monte_carlo(None, **kw, exact_below=0, bins=8, cap=50)
    assert streamed["no_rebound"] == gathered["no_rebound"] == 7_143
    close_but_the_sums(streamed, gathered)


def test_the_streaming_merge_holds_no_samples_at_the_client(client):
    """The client's memory does not grow with the samples: the peak of what Python allocated
    while merging 4·10⁵ samples stays below their 9.6 MB (the gathered merge's cost, twice:
    the tasks' arrays and their concatenation) and does not grow with the samples."""
    import tracemalloc

    import bouncelab.dask

    kw = dict(preset="golf", vary=VARY, seed=3, chunk=25_000, exact_below=0)
    peaks = []
    for samples in (100_000, 400_000):
        tracemalloc.start()
        bouncelab.dask.monte_carlo(client, **kw, samples=samples)
        peaks.append(tracemalloc.get_traced_memory()[1])
        tracemalloc.stop()
    print(f"client peaks {peaks[0] / 1e6:.2f} MB, {peaks[1] / 1e6:.2f} MB")
    assert peaks[1] < 5e6
    assert peaks[1] < 1.5 * peaks[0] + 1e6


def test_dask_refuses_a_run_beyond_its_bound_before_any_task(client):
    """Issue 54 item 9: samples=10**12 had no bound on the whole run."""
    import bouncelab.dask

    with pytest.raises(ValueError, match="invalid samples: 1000000000000 is beyond"):
        bouncelab.dask.monte_carlo(client, preset="golf", vary=VARY, samples=10**12, chunk=10**7)


def test_dask_without_a_client_uses_dasks_own_scheduler():
    pytest.importorskip("dask")
    import dask

    import bouncelab.dask

    kw = dict(preset="tennis", vary="k_r=5%,c=2%", samples=2_500, seed=4, dist="lognormal")
    one = bouncelab.monte_carlo(**kw)
    with dask.config.set(scheduler="threads"):
        assert bouncelab.dask.monte_carlo(None, **kw, chunk=1_000) == one


def test_dask_refuses_bad_input_on_the_client(client):
    import bouncelab.dask

    with pytest.raises(ValueError, match="invalid vary: unknown parameter 'spin'"):
        bouncelab.dask.monte_carlo(client, preset="golf", vary={"spin": 0.1}, samples=10)
    with pytest.raises(ValueError, match="invalid chunk: 0"):
        bouncelab.dask.monte_carlo(client, preset="golf", vary=VARY, samples=10, chunk=0)
    with pytest.raises(ValueError, match="too much work: 20000000 samples"):
        bouncelab.dask.monte_carlo(client, preset="golf", vary=VARY, samples=10**8, chunk=2 * 10**7)


def test_dask_names_a_number_out_of_range_as_monte_carlo_does():
    # checked on the client, before any task: no cluster needed. Before, the check called the
    # native module past the boundary's guard, and a samples=-1 raised OverflowError "can't
    # convert negative int to unsigned", naming nothing
    import bouncelab.dask

    # (a negative count is a ValueError, test_argument_types.py)
    for kw, kind in [
        (dict(samples=-1), ValueError),
        (dict(samples=10, seed=-1), ValueError),
        (dict(samples=10**30), OverflowError),
    ]:
        with pytest.raises(kind) as want:
            bouncelab.monte_carlo(preset="golf", vary=VARY, **kw)
        with pytest.raises(kind) as got:
            bouncelab.dask.monte_carlo(None, preset="golf", vary=VARY, **kw)
        assert str(got.value) == str(want.value) and str(want.value).startswith("invalid ")


def test_correlated_samples_as_the_command_line():
    """`correlate` (a dict or the command line's text) gives `mc --correlate`'s numbers, and the
    varied parameters the correlation asked for."""
    corr = {"k_p:c": 0.5}
    r = bouncelab.monte_carlo(
        preset="golf", vary=VARY, samples=4000, seed=2, correlate=corr, return_samples=True
    )
    assert r["correlate"] == corr
    text = bouncelab.monte_carlo(preset="golf", vary=VARY, samples=4000, seed=2, correlate="k_p:c=0.5")
    assert text["stats"] == {k: r["stats"][k] for k in r["stats"]}
    rho = np.corrcoef(r["values"]["k_p"], r["values"]["c"])[0, 1]
    assert abs(rho - 0.5) < 4 * 0.75 / np.sqrt(4000)
    code, out, err = cli(
        "mc", "--preset", "golf", "--vary", "k_p=5%,c=5%,k_r=5%", "--correlate", "k_p:c=0.5",
        "--samples", "4000", "--seed", "2", "--format", "json",
    )
    assert code == 0, err
    assert json.loads(out)["stats"]["cor"]["q"]["50"] == r["stats"]["cor"]["q"]["50"]
    with pytest.raises(ValueError, match="not positive definite"):
        bouncelab.monte_carlo(
            preset="golf", vary=VARY, samples=10,
            correlate={"k_p:c": 0.9, "k_p:k_r": 0.9, "c:k_r": -0.9},
        )
    with pytest.raises(ValueError, match="invalid vary fit: golf"):
        bouncelab.monte_carlo(preset="golf", vary="fit", samples=10)


def test_correlated_chunks_merge_to_the_single_call():
    """Dask's path carries `correlate` to every task and to the merge: the same numbers."""
    pytest.importorskip("dask")
    corr = {"k_p:c": 0.5, "c:k_r": -0.3}
    one = bouncelab.monte_carlo(preset="golf", vary=VARY, samples=3000, seed=4, correlate=corr)
    split = bouncelab.dask.monte_carlo(
        None, preset="golf", vary=VARY, samples=3000, seed=4, chunk=700, correlate=corr
    )
    assert split == one
