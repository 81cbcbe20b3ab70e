"""Arguments as a new user gives them (the qa10 pass): every function through the boundary,
arrays that are not numbers refused naming the argument, the command line's refusals kept,
rows counted as the arrays count them, and the warnings the command line's JSON carries."""

import inspect

import numpy as np
import pytest

import bouncelab
from cli_binary import reach
from test_bouncelab import cli_json, no_user_presets  # noqa: F401


# ---- every function through the boundary (bouncelab/_boundary.py)


def test_every_function_is_guarded():
    # `oblique` and `impacts` were not: samples=-1 raised "can't convert negative int to
    # unsigned", naming no argument, and a panic would have been a PanicException
    for name in bouncelab.__all__:
        f = getattr(bouncelab, name)
        if inspect.isclass(f):
            continue
        assert getattr(f, "__wrapped__", None) is not None, name


@pytest.mark.parametrize(
    "call, name, kind",
    [
        # a negative count is a ValueError (test_argument_types.py)
        (
            lambda: bouncelab.oblique(angle=30, friction=0.5, history=True, samples=-1),
            "samples",
            ValueError,
        ),
        (lambda: bouncelab.oblique(angle=30, friction=0.5, v0=10**400), "v0", OverflowError),
        (lambda: bouncelab.impacts(m=1, k_p=1, c=1, k_r=1, v0=10**400), "v0", OverflowError),
    ],
)
def test_a_number_out_of_range_names_its_argument(call, name, kind):
    with pytest.raises(kind) as e:
        call()
    assert str(e.value).startswith(f"invalid {name}:"), str(e.value)
    assert str(e.value).count("invalid") == 1, str(e.value)


# ---- arrays of numbers, and nothing else


def test_impacts_refuses_arrays_that_are_not_numbers():
    # a complex array lost its imaginary part with a ComplexWarning; a string array was
    # read as numbers
    ok = dict(m=1.0, k_p=1.0, c=1.0, k_r=1.0, v0=1.0)
    with pytest.raises(TypeError, match=r"^invalid m: an array of complex128 \(expected real"):
        bouncelab.impacts(**{**ok, "m": np.array([1 + 1j])})
    with pytest.raises(TypeError, match=r"^invalid v0: an array of <U1 \(expected real"):
        bouncelab.impacts(**{**ok, "v0": ["3"]})
    with pytest.raises(ValueError, match=r"^invalid k_r: could not convert string"):
        bouncelab.impacts(**{**ok, "k_r": np.array([1.0, "a"], dtype=object)})
    # what numpy takes as numbers still goes: ints, objects holding floats; bools do not
    # (test_a_bool_is_no_number)
    d = bouncelab.impacts(**{**ok, "m": np.array([1, 2]), "c": np.array([1.0], dtype=object)})
    assert d["cor"].shape == (2,)
    with pytest.raises(TypeError, match=r"^invalid m: an array of bool \(expected a number"):
        bouncelab.impacts(**{**ok, "m": np.array([True, False])})


def _numeric_parameters():
    """(function name, parameter) for every parameter of the package's functions that takes
    numbers: not a flag (default True or False), not a name or text."""
    from bouncelab._boundary import _TEXT, _flags, _parameters

    for name in bouncelab.__all__:
        f = getattr(bouncelab, name)
        native = getattr(f, "__wrapped__", None)
        if native is None:
            continue
        for p in _parameters(native):
            if p not in _flags(native) and p not in _TEXT:
                yield name, p


def test_every_function_has_numeric_parameters_listed():
    found = set(_numeric_parameters())
    # a sample the list must hold, and a flag and a name it must not
    assert {("run", "v0"), ("sweep_zeta", "zetas"), ("drop", "bounces")} <= found
    assert ("run", "history") not in found and ("run", "preset") not in found


@pytest.mark.parametrize("function, name", sorted(_numeric_parameters()))
def test_a_bool_is_no_number(function, name):
    # run(v0=True) ran at 1.0 m/s: Python's True is the integer 1
    f = getattr(bouncelab, function)
    whole = f"^invalid {name}: True \\(expected a number, not a bool\\)$"
    with pytest.raises(TypeError, match=whole):
        f(**{name: True})
    with pytest.raises(TypeError, match=f"^invalid {name}\\[1\\]: False \\(expected a number"):
        f(**{name: [1.0, False]})


def test_flags_still_take_bools():
    assert bouncelab.run(preset="golf", history=True).t.size > 0
    assert bouncelab.drop(preset="tennis", bounces=1, drag=False)["drag"] is False


def test_sweep_zeta_names_a_bad_value_by_its_index():
    # it said "invalid zeta: -1", naming neither the argument nor the element, where
    # sweep_velocity says "speeds[1]: invalid v0: …"
    with pytest.raises(ValueError, match=r"^zetas\[2\]: invalid zeta: -1 \(must not be negative"):
        bouncelab.sweep_zeta([0.4], [0.5, 1.0, -1.0])
    with pytest.raises(ValueError, match=r"^lambdas\[1\]: invalid lambda: 2000000 \(above 1e6"):
        bouncelab.sweep_zeta([0.4, 2e6], [0.5])
    with pytest.raises(ValueError, match=r"^speeds\[1\]: invalid v0: -3"):
        bouncelab.sweep_velocity("golf", [3.0, -3.0])


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda a: bouncelab.sweep_zeta(a, [1.0]), "lambdas"),
        (lambda a: bouncelab.sweep_zeta([0.4], a), "zetas"),
        (lambda a: bouncelab.sweep_velocity("golf", a), "speeds"),
        (lambda a: bouncelab.fit_trace(a, [0.0, 1.0]), "time"),
        (lambda a: bouncelab.fit_cor_table([1.0, 2.0], a), "cor"),
        (lambda a: bouncelab.fit_cor_table([1.0], [0.7], cor_sd=a), "cor_sd"),
        (lambda a: bouncelab.fit_drops(a, [0.5]), "drop_heights"),
        (
            lambda a: bouncelab.fit_oblique(
                v0=[20.0], angle_deg=a, spin_in=[0.0], vx_out=[15.0], vy_out=[5.0]
            ),
            "angle_deg",
        ),
    ],
)
@pytest.mark.parametrize("bad", [np.ones((2, 2)), "abc"])
def test_a_list_argument_that_is_not_one_names_it(call, name, bad):
    # PyO3's own "only 0-dimensional arrays can be converted to Python scalars" named none
    with pytest.raises(TypeError, match=f"^invalid {name}: .*expected one number, a sequence"):
        call(bad)


def test_empty_arrays_are_refused_naming_the_first():
    # the readers said "row 1: no data rows after the header" of the text made of them
    with pytest.raises(ValueError, match="^invalid time: no value given$"):
        bouncelab.fit_trace([], [])
    with pytest.raises(ValueError, match="^invalid v0: no value given$"):
        bouncelab.fit_cor_table([], [])
    with pytest.raises(ValueError, match="^invalid drop_heights: no value given$"):
        bouncelab.fit_drops([], [])
    with pytest.raises(ValueError, match="^invalid v0: no value given$"):
        bouncelab.fit_oblique(v0=[], angle_deg=[], spin_in=[], vx_out=[], vy_out=[])


def test_free_takes_the_command_lines_text_as_batch_does():
    v, e = [1.0, 2.0, 3.0, 4.0], [0.75, 0.74, 0.73, 0.72]
    a = bouncelab.fit_cor_table(v, e, free="k_r,z_p")
    b = bouncelab.fit_cor_table(v, e, free=["k_r", "z_p"])
    assert a["free"] == b["free"] == ["k_r", "z_p"]
    assert a["fitted"]["z_p"]["value"] == b["fitted"]["z_p"]["value"]
    for bad in (1, [1]):
        with pytest.raises(TypeError, match="^invalid free: .*expected a list of names"):
            bouncelab.fit_cor_table(v, e, free=bad)
        with pytest.raises(TypeError, match="^invalid free: "):
            bouncelab.batch("lot.csv", preset="tennis", free=bad)


# ---- the rows of the arrays, counted as the arrays count them


def test_the_rows_of_a_fits_arrays_count_from_zero():
    # "COR table row 2" named cor[1], where impacts says "element 1" and fit_oblique
    # "oblique row 1" for the same index
    with pytest.raises(ValueError, match=r"^COR table row 1: COR 1.5"):
        bouncelab.fit_cor_table([1.0, 2.0], [0.5, 1.5])
    with pytest.raises(ValueError, match=r"^trace row 2: force 'NaN'"):
        bouncelab.fit_trace([0.0, 1.0, 2.0], [0.0, 1.0, np.nan])
    with pytest.raises(ValueError, match=r"^oblique row 1, angle_deg"):
        bouncelab.fit_oblique(
            v0=[20.0, 20.0], angle_deg=[30.0, 95.0], spin_in=[0.0, 0.0],
            vx_out=[15.0, 15.0], vy_out=[5.0, 5.0],
        )
    with pytest.raises(ValueError, match=r"^element 1: invalid mass"):
        bouncelab.impacts(m=[1.0, -1.0], k_p=1.0, c=1.0, k_r=1.0, v0=1.0)


def test_a_trace_without_a_pulse_names_its_row_not_a_line_and_column():
    # it was "2:5: empty pulse …": the line and column of the text the arrays were turned into
    with pytest.raises(ValueError) as e:
        bouncelab.fit_trace(np.linspace(0.0, 3e-3, 50), np.zeros(50))
    assert str(e.value).startswith("trace row 0: empty pulse"), str(e.value)


# ---- refused as the command line refuses


def test_oblique_samples_follow_runs_rule():
    # samples=0 with a history gave no history, without a word; samples without history
    # were ignored (the command line's --samples needs --history)
    with pytest.raises(ValueError, match=r"^invalid samples: 0 \(must lie in 2"):
        bouncelab.oblique(angle=30, friction=0.5, history=True, samples=0)
    with pytest.raises(ValueError, match=r"^invalid samples: 1 \(must lie in 2"):
        bouncelab.oblique(angle=30, friction=0.5, history=True, samples=1)
    with pytest.raises(ValueError, match="history"):
        bouncelab.oblique(angle=30, friction=0.5, samples=5)
    assert len(bouncelab.oblique(angle=30, friction=0.5, history=True).t) == 400
    assert len(bouncelab.oblique(angle=30, friction=0.5, history=True, samples=7).t) == 7


def test_target_damping_needs_a_target_stiffness():
    # a dashpot beside a rigid surface was ignored; collide --target-damping requires
    # --target-stiffness
    with pytest.raises(ValueError, match=r"^invalid target_damping: 5 \(it needs target_stiff"):
        bouncelab.collide(target_mass=1.0, target_damping=5.0)
    c = bouncelab.collide(target_mass=1.0, target_stiffness=4e4, target_damping=5.0)
    assert c.target_damping == 5.0
    assert bouncelab.collide(target_mass=1.0, target_damping=0.0).target_damping == 0.0


# ---- the warnings the command line's JSON carries


def test_sweep_velocity_carries_each_rows_warnings():
    # `sweep velocity --format json` warns at 45 m/s (a 31 mm indentation in a 21.55 mm
    # ball); the dict had neither the warning nor max_indentation
    d = bouncelab.sweep_velocity("superball", [3.0, 45.0])
    assert reach(d["warnings"][0]) == []
    assert reach(d["warnings"][1]) == [
        "peak indentation 31.05 mm exceeds the ball's radius 21.55 mm: outside the model's "
        "range (the contact laws assume a deformation small against the ball)"
    ]
    assert d["max_indentation"][1] == pytest.approx(bouncelab.run(v0=45.0).max_indentation, 1e-12)
    rows = cli_json(
        "sweep", "velocity", "--from", "3", "--to", "45", "--points", "2", "--format", "json"
    )["rows"]
    assert d["warnings"] == [r["warnings"] for r in rows]
    assert list(d["max_indentation"]) == pytest.approx([r["max_indentation"] for r in rows])


def test_sweep_velocity_warns_of_the_centre_as_the_cli_does():
    # the softball swept to 300 m/s: from about 175 m/s its centre passes the radius while its
    # indentation does not; the dict's warnings say so as the command line's rows do
    rows = cli_json(
        "sweep", "velocity", "--preset", "softball", "--to", "300", "--format", "json"
    )["rows"]
    d = bouncelab.sweep_velocity("softball", speeds=[r["v0"] for r in rows])
    assert d["warnings"] == [r["warnings"] for r in rows]
    centre = "peak displacement of the ball's centre"
    assert any(centre in w for ws in d["warnings"] for w in ws), d["warnings"]


def test_collide_oblique_and_monte_carlo_carry_the_command_lines_warnings():
    # a table-tennis ball at 100 m/s: 23 mm into a 20 mm ball; the objects had no warnings
    beyond = "exceeds the ball's radius 20.00 mm"
    c = bouncelab.collide(preset="table-tennis", v0=100.0, target_mass=1.0)
    want = cli_json("collide", "--preset", "table-tennis", "--v0", "100", "--target-mass", "1",
                    "--format", "json")["warnings"]
    assert c.warnings == want and beyond in c.warnings[0]
    o = bouncelab.oblique("table-tennis", v0=100.0, angle=80.0, friction=0.5)
    want = cli_json("oblique", "--preset", "table-tennis", "--v0", "100", "--angle", "80",
                    "--friction", "0.5", "--format", "json")["warnings"]
    assert o.warnings == want and beyond in o.warnings[0]
    m = bouncelab.monte_carlo(preset="table-tennis", v0=100.0, vary={"k_p": 0.05},
                              samples=400, seed=1)
    want = cli_json("mc", "--preset", "table-tennis", "--v0", "100", "--vary", "k_p=5%",
                    "--samples", "400", "--seed", "1", "--format", "json")["warnings"]
    assert m["warnings"] == want and m["warnings"][0].startswith("at the nominal parameters: ")
    # within the radius: none
    assert reach(bouncelab.collide(preset="table-tennis", target_mass=1.0).warnings) == []
    assert reach(bouncelab.oblique("table-tennis", angle=80.0, friction=0.5).warnings) == []
