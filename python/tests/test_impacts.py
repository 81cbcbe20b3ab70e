"""`bouncelab.impacts`: numpy arrays broadcast as a ufunc's arguments, each element the answer
`run_params` gives for its values (issue 30 item 5)."""

import re

import numpy as np
import pytest

import bouncelab

KEYS = ["cor", "max_force", "contact_time", "max_indentation", "permanent_indentation"]


def same_as_run_params(out, index, rel=1e-12, **kw):
    r = bouncelab.run_params(**kw)
    for k in KEYS:
        want = getattr(r, k)
        got = out[k][index]
        if want is None:  # no rebound: no contact time
            assert np.isnan(got), (k, index)
        else:
            assert got == pytest.approx(want, rel=rel, abs=1e-300), (k, index, kw)
    assert bool(out["rebound"][index]) == r.rebound


def test_arrays_broadcast_like_a_ufunc():
    k_p = np.array([[2e4], [5e4], [2e5]])  # (3, 1)
    c = np.array([2.0, 10.0, 40.0, 150.0])  # (4,)
    out = bouncelab.impacts(m=0.05, k_p=k_p, c=c, k_r=7e4, v0=3.0, z_p=2e-3)
    assert set(out) == set(KEYS) | {"rebound"}
    for k in out:
        assert out[k].shape == (3, 4), k
    assert out["rebound"].dtype == np.bool_
    for i in range(3):
        for j in range(4):
            same_as_run_params(
                out, (i, j), m=0.05, k_p=k_p[i, 0], c=c[j], k_r=7e4, v0=3.0, z_p=2e-3
            )


def test_scalars_give_zero_dimensional_arrays():
    out = bouncelab.impacts(m=0.0495, k_p=5.45e4, c=10.0, k_r=7.08e4, v0=3.12)
    assert out["cor"].shape == ()
    same_as_run_params(out, (), m=0.0495, k_p=5.45e4, c=10.0, k_r=7.08e4, v0=3.12)


def test_every_law_and_flattening_agree_with_run_params():
    """Hertz rows come from the Hertz table (docs/numerics.md): within 1e-10 of its reference
    and 1e-9 of `run`'s adaptive solver (not stiff here), not `run`'s bits; elastic-plastic
    rows from the same table below yield and the Taylor steps past it, to 1e-9 of `run`; the
    linear law's rows are `run`'s answers to 1e-12."""
    v0 = np.linspace(0.5, 30.0, 7)
    for law in ["linear", "hertz", "elastic-plastic"]:
        out = bouncelab.impacts(m=0.0456, k_p=5.6e5, c=1200.0, k_r=5.6e5, v0=v0, z_p=3e-3, law=law)
        rel = 1e-12 if law == "linear" else 1e-9
        for i, v in enumerate(v0):
            same_as_run_params(
                out, i, rel, m=0.0456, k_p=5.6e5, c=1200.0, k_r=5.6e5, v0=v, z_p=3e-3, law=law
            )
    # the fast speeds flatten the golf ball: some permanent indentation
    assert (out["permanent_indentation"] > 0).any()


def test_bad_input_names_the_element_or_is_numpys():
    with pytest.raises(ValueError, match=r"element 2: invalid k_p: -1"):
        bouncelab.impacts(m=0.05, k_p=[1e5, 2e5, -1.0], c=10.0, k_r=7e4, v0=3.0)
    with pytest.raises(ValueError, match="shape"):
        bouncelab.impacts(m=0.05, k_p=np.ones(3), c=np.ones(4), k_r=7e4, v0=3.0)
    with pytest.raises(ValueError, match="law"):
        bouncelab.impacts(m=0.05, k_p=1e5, c=10.0, k_r=7e4, v0=3.0, law="plastic")
    # the work limit holds here too, before any copy (a broadcast view of 10⁹ elements)
    many = np.broadcast_to(3.0, (10**9,))
    with pytest.raises(ValueError, match="limit"):
        bouncelab.impacts(m=0.05, k_p=1e5, c=10.0, k_r=7e4, v0=many)


def test_a_k_h_given_as_nan_is_refused_as_run_params_refuses_it():
    # k_h left out is Eq. 16's, element by element; a NaN given (a computation upstream gone
    # wrong) is not "left out": it was taken for the default without a word
    kw = dict(m=0.05, k_p=1e5, c=10.0, k_r=7e4, v0=3.0, law="hertz")
    with pytest.raises(ValueError) as e:
        bouncelab.run_params(**kw, k_h=float("nan"))
    with pytest.raises(ValueError, match=f"^element 1: {re.escape(str(e.value))}$"):
        bouncelab.impacts(**kw, k_h=[5e6, np.nan])
    with pytest.raises(ValueError, match="^element 0: invalid k_h: NaN"):
        bouncelab.impacts(**{**kw, "law": "linear"}, k_h=np.nan)
    # the Hertz table's answers: within the adaptive solver's 1e-9 of run_params (library.md)
    out = bouncelab.impacts(**kw, k_h=[5e6, 6e6])
    same_as_run_params(out, 1, rel=1e-9, **kw, k_h=6e6)
    same_as_run_params(bouncelab.impacts(**kw), (), rel=1e-9, **kw)


def test_empty_arrays_give_empty_answers():
    out = bouncelab.impacts(m=0.05, k_p=np.ones(0), c=10.0, k_r=7e4, v0=3.0)
    assert out["cor"].shape == (0,)


def test_elastic_plastic_rows_yield_and_meet_run_params():
    """Past yield an elastic-plastic row is the Taylor steps' answer (docs/numerics.md): its
    permanent indentation z_f > 0 and every number within 1e-9 of `run`'s adaptive solver, z_f
    to 1e-9 of z_m (its rounding scale, Eqs. 18-19); below yield z_f is 0, as `run`'s."""
    kw = dict(m=0.0374, k_p=5.45e4, c=10.0, k_r=7.08e4, z_p=2e-3)
    v0 = np.array([0.5, 3.12, 9.4, 20.0])
    out = bouncelab.impacts(v0=v0, law="elastic-plastic", **kw)
    yielded = 0
    for i, v in enumerate(v0):
        r = bouncelab.run_params(v0=v, law="elastic-plastic", **kw)
        assert bool(out["rebound"][i]) == r.rebound
        for k in ["cor", "max_force", "contact_time", "max_indentation"]:
            assert out[k][i] == pytest.approx(getattr(r, k), rel=1e-9), (k, v)
        z_f = out["permanent_indentation"][i]
        assert abs(z_f - r.permanent_indentation) <= 1e-9 * r.max_indentation, v
        yielded += z_f > 0
    assert yielded >= 2


def test_the_work_limit_counts_elements_the_hertz_table_holds_as_cheap_ones():
    """Under Hertz an element the Hertz table holds counts 1/40 of an impact, under the
    elastic-plastic law 1/40 below yield and 1/20 past it, one outside the table a whole impact
    (docs/guarantees.md):
    100 000 golf-like elements run under both laws (beyond the 25 000 whole impacts the limit
    allows), 30 000 balls outside the table (K_r 10⁶ times larger) are refused by count."""
    ball = dict(m=0.0456, k_p=5.6e5, c=1200.0, k_r=5.6e5, z_p=3e-3)
    v0 = np.linspace(1.0, 30.0, 100_000)
    for law in ["hertz", "elastic-plastic"]:
        out = bouncelab.impacts(v0=v0, law=law, **ball)
        assert out["cor"].shape == (100_000,)
        for i in [0, 54_321, 99_999]:
            same_as_run_params(out, i, 1e-9, v0=v0[i], law=law, **ball)
    outside = dict(ball, k_r=5.6e11)
    with pytest.raises(
        ValueError,
        match=r"^too much work: 30000 elements \(30000 of them outside the Hertz table, a whole "
        r"impact each; 40 of the others count as one impact\) is 30000 hertz-law impacts",
    ):
        bouncelab.impacts(v0=np.linspace(1.0, 30.0, 30_000), law="hertz", **outside)
    with pytest.raises(ValueError, match=r"^too much work: 1000001 elements \(40 elements the"):
        bouncelab.impacts(v0=np.linspace(1.0, 30.0, 1_000_001), law="hertz", **ball)


GOLF = dict(m=0.0456, k_p=5.6e5, c=1200.0, k_r=5.6e5, z_p=3e-3)


def test_a_million_elastic_plastic_elements_below_yield_run_in_one_call():
    """Below yield an elastic-plastic element is the Hertz table's answer and counts as one
    (1/40 of an impact): 10⁶ of them run in one call (refused on ce671d8's wheel, which counted
    each 1/20: 'too much work: 1000000 elements (20 elements the Hertz table holds count as one
    impact) is 50000 elastic-plastic-law impacts'); one more is refused before any copy."""
    v0 = np.linspace(0.5, 3.0, 1_000_000)
    out = bouncelab.impacts(v0=v0, law="elastic-plastic", **GOLF)
    assert out["cor"].shape == (1_000_000,)
    # all below yield: no permanent indentation, z_m below z_p
    assert (out["permanent_indentation"] == 0.0).all()
    assert (out["max_indentation"] < GOLF["z_p"]).all()
    for i in [0, 123_456, 999_999]:
        same_as_run_params(out, i, 1e-9, v0=v0[i], law="elastic-plastic", **GOLF)
    with pytest.raises(
        ValueError,
        match=r"^too much work: 1000001 elements \(40 elements the Hertz table holds below "
        r"yield count as one impact\) is 25001 elastic-plastic-law impacts",
    ):
        bouncelab.impacts(v0=np.linspace(0.5, 3.0, 1_000_001), law="elastic-plastic", **GOLF)


def test_elastic_plastic_elements_past_yield_count_a_twentieth():
    """Past yield an element takes the Taylor steps and counts 1/20 of an impact: 500 001 of
    them are refused after the table's pass, by their count, before any step runs; with
    500 000 below yield beside 30 000 past it the call is within the limit (12 500 + 1 500
    impacts' worth of the 25 000), and runs."""
    fast = np.full(500_001, 30.0)
    with pytest.raises(
        ValueError,
        match=r"^too much work: 500001 elements \(500001 past yield, 20 to an impact; 40 of "
        r"the others count as one impact\) is 25001 elastic-plastic-law impacts",
    ):
        bouncelab.impacts(v0=fast, law="elastic-plastic", **GOLF)
    v0 = np.concatenate([np.linspace(0.5, 3.0, 500_000), np.linspace(25.0, 30.0, 30_000)])
    out = bouncelab.impacts(v0=v0, law="elastic-plastic", **GOLF)
    assert (out["permanent_indentation"][:500_000] == 0.0).all()
    assert (out["permanent_indentation"][500_000:] > 0.0).all()
    for i in [499_999, 500_000, 529_999]:
        same_as_run_params(out, i, 1e-9, v0=v0[i], law="elastic-plastic", **GOLF)
