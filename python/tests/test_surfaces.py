"""surface= (issue 53, docs/surfaces.md, docs/python.md): run, drop, oblique and collide on a
surface named or given by its numbers, each answer carrying the command line's `surface`
object and the command line's numbers."""

import copy
import json
import math
import pickle
import subprocess

import pytest
from cli_binary import binary

import bouncelab


@pytest.fixture(autouse=True)
def no_user_files(tmp_path, monkeypatch):
    """Both the binary and the package read $XDG_CONFIG_HOME/bouncelab: an empty one."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    return tmp_path / "config" / "bouncelab"


def cli_json(*args):
    out = subprocess.run([binary(), *args, "--format", "json"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def close(a, b, path="$"):
    """The package's value `a` is the JSON's `b`: the same keys, numbers to 1e-12 (inf for
    the JSON's null)."""
    if isinstance(b, dict):
        assert set(a) == set(b), (path, set(a) ^ set(b))
        for k in b:
            close(a[k], b[k], f"{path}.{k}")
    elif isinstance(b, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            close(x, y, f"{path}[{i}]")
    elif b is None:
        assert a is None or math.isinf(a), (path, a)
    elif isinstance(b, (bool, str)):
        assert a == b, (path, a, b)
    else:
        assert abs(float(a) - b) <= 1e-12 * max(abs(b), 1e-300), (path, a, b)


def test_every_answer_names_the_rigid_plate_by_default():
    want = {"name": "steel-plate", "origin": "embedded", "stiffness": math.inf, "damping": 0.0,
            "mass": math.inf, "friction": None, "tangential_stiffness": None,
            "tangential_damping": None, "overrides": []}
    assert bouncelab.run(preset="tennis").surface == want
    # target_mass given: an override, as --target-mass
    c = bouncelab.collide("tennis", target_mass=math.inf)
    assert c.surface == dict(want, overrides=["target_mass"])
    assert bouncelab.drop("tennis", bounces=1)["surface"] == want
    o = bouncelab.oblique("tennis", angle=30.0, friction=0.5)
    # the surface object holds what was given (K_t: Mindlin's, not given, stays None there);
    # μ given is an override, as `oblique --friction` (tests/cli/court_assumed.rs)
    assert o.surface == dict(want, friction=0.5, overrides=["friction"])


def test_the_rigid_plate_is_the_same_dict_in_every_answer():
    # the answers that take no surface ran on the rigid plate: its infinite K_s and M are inf
    # in each, as in run's (batch, monte_carlo and fit_oblique gave None, their dicts read
    # from the command line's JSON, where ∞ is null); inf, a number, also goes back in as
    # surface= (None is refused there)
    from test_batch import LOT7
    from test_fit_oblique import bounces

    plate = bouncelab.run(preset="tennis").surface
    answers = {
        "static": bouncelab.static("tennis", load_kg=8.165),
        "fit": bouncelab.fit(0.5, preset="baseball", v0=30.0),
        "sweep_velocity": bouncelab.sweep_velocity("tennis", speeds=[2.0, 5.0]),
        "batch": bouncelab.batch(LOT7, preset="tennis"),
        "monte_carlo": bouncelab.monte_carlo(preset="golf", vary="k_p=5%", samples=50),
        "fit_oblique": bouncelab.fit_oblique(preset="tennis", **bounces()),
    }
    for name, answer in answers.items():
        assert answer["surface"] == plate, (name, answer["surface"])
    again = {k: answers["batch"]["surface"][k] for k in ("stiffness", "mass")}
    assert bouncelab.run(preset="tennis", surface=again).cor == bouncelab.run(preset="tennis").cor


def test_run_on_a_surface_that_gives_is_the_command_lines():
    # before: run() had no surface= (a TypeError), and its answer no surface
    r = bouncelab.run(preset="tennis", surface={"stiffness": 1e6, "damping": 20.0})
    cli = cli_json("run", "--preset", "tennis", "--surface-stiffness", "1e6",
                   "--surface-damping", "20")
    close(r.to_dict(), cli)
    assert r.surface["overrides"] == ["stiffness", "damping"]
    # another answer than the rigid plate's (the surface in series with the ball's chain)
    assert r.cor != bouncelab.run(preset="tennis").cor
    assert r.energy is None


def test_run_on_a_moving_surface_with_a_history():
    kw = {"surface": {"name": "concrete", "stiffness": 5e5, "mass": 2.0}, "history": True,
          "samples": 50}
    r = bouncelab.run(preset="golf", **kw)
    cli = cli_json("run", "--preset", "golf", "--surface", "concrete", "--surface-stiffness",
                   "5e5", "--surface-mass", "2", "--history", "--samples", "50")
    close(r.to_dict(), cli)
    # numbers given over concrete: named for what it is (docs/surfaces.md §1, "The name")
    assert r.surface["name"] == "concrete-modified" and r.surface["mass"] == 2.0


def test_oblique_on_a_surface_that_gives_with_a_tangential_dashpot():
    kw = {"angle": 30.0, "friction": 0.6, "tangential_damping": 2.0,
          "surface": {"name": "hard-court", "stiffness": 2e6, "damping": 30.0}}
    o = bouncelab.oblique("tennis", **kw)
    cli = cli_json("oblique", "--preset", "tennis", "--angle", "30", "--friction", "0.6",
                   "--tangential-damping", "2", "--surface", "hard-court",
                   "--surface-stiffness", "2e6", "--surface-damping", "30")
    close(o.to_dict(), cli)
    assert list(o.to_dict()) == list(cli) and list(o.energy) == list(cli["energy"])
    assert o.tangential_damping == 2.0 and o.surface["tangential_damping"] == 2.0
    # the same numbers given inside surface=: the same answer
    inside = dict(kw["surface"], friction=0.6, tangential_damping=2.0)
    assert bouncelab.oblique("tennis", angle=30.0, surface=inside) == o


def test_oblique_needs_a_friction_where_the_surface_has_none():
    with pytest.raises(ValueError, match="friction"):
        bouncelab.oblique("tennis", angle=30.0, surface="clay")
    with pytest.raises(ValueError, match="friction given twice"):
        bouncelab.oblique("tennis", angle=30.0, friction=0.5, surface={"friction": 0.4})


def test_collide_on_a_surface_is_the_command_lines():
    c = bouncelab.collide("tennis", surface={"stiffness": 1e6, "damping": 10.0, "mass": 3.0})
    cli = cli_json("collide", "--preset", "tennis", "--surface-stiffness", "1e6",
                   "--surface-damping", "10", "--surface-mass", "3")
    close(c.to_dict(), cli)
    # target_mass over the surface's mass, as --target-mass
    c = bouncelab.collide("tennis", target_mass=5.0, surface="concrete")
    cli = cli_json("collide", "--preset", "tennis", "--target-mass", "5", "--surface",
                   "concrete")
    close(c.to_dict(), cli)
    with pytest.raises(ValueError, match="target_mass, target_preset and surface"):
        bouncelab.collide("tennis")


def test_drop_on_a_surface_is_the_command_lines():
    d = bouncelab.drop("tennis", bounces=2, surface={"stiffness": 2e6, "damping": 40.0})
    cli = cli_json("drop", "--preset", "tennis", "--bounces", "2", "--surface-stiffness", "2e6",
                   "--surface-damping", "40")
    close(d["surface"], cli["surface"])
    for i, b in enumerate(cli["bounces"]):
        for k in ("v_in", "v_out", "cor", "contact_time", "max_force"):
            close(d["bounces"][k][i], b[k], f"bounces[{i}].{k}")
    assert d["bounces"]["cor"][0] != bouncelab.drop("tennis", bounces=1)["bounces"]["cor"][0]
    assert "cor_ci95_lo" not in d["bounces"]


def test_a_user_surface_file_is_found(no_user_files):
    folder = no_user_files / "surfaces"
    folder.mkdir(parents=True)
    (folder / "gym.toml").write_text(
        'name = "gym"\ndescription = "a test floor"\n'
        '[normal]\nstiffness = 3e6\ndamping = 25.0\n'
        '[tangential]\nfriction = 0.5\n'
        + "".join(f'[[sources]]\nquantity = "{q}"\nsource = "a test"\n'
                  for q in ("stiffness", "damping", "friction")))
    r = bouncelab.run(preset="tennis", surface="gym")
    cli = cli_json("run", "--preset", "tennis", "--surface", "gym")
    close(r.to_dict(), cli)
    o = bouncelab.oblique("tennis", angle=20.0, surface="gym")
    assert o.friction == 0.5 and o.surface["origin"].endswith("gym.toml")


@pytest.mark.parametrize("surface,message", [
    ("no-such-court", "no-such-court"),
    ({"stiffnes": 1e6}, "unknown key"),
    ({"damping": 5.0}, "rigid"),
    ({"stiffness": -1.0}, "stiffness"),
    ({"mass": "heavy"}, "mass"),
    (3.0, "surface"),
])
def test_bad_surfaces_are_named(surface, message):
    with pytest.raises(ValueError, match=message):
        bouncelab.run(preset="tennis", surface=surface)


@pytest.mark.parametrize("key", ["friction", "tangential_stiffness", "tangential_damping"])
@pytest.mark.parametrize("call", [
    lambda s: bouncelab.run(preset="tennis", surface=s),
    lambda s: bouncelab.collide("tennis", surface=s),
    lambda s: bouncelab.drop("tennis", bounces=1, surface=s),
], ids=["run", "collide", "drop"])
def test_a_normal_impact_refuses_tangential_numbers(call, key):
    # the command line refuses `run --friction` (exit 2): a number the impact cannot use is
    # refused, not silently dropped from the answer
    with pytest.raises(ValueError, match=f"invalid surface {key}: .*normal impact"):
        call({"name": "hard-court", key: 0.6})


def test_answers_on_a_surface_pickle_and_copy():
    s = {"stiffness": 1e6, "damping": 20.0}
    for r in (bouncelab.run(preset="tennis", surface=s),
              bouncelab.oblique("tennis", angle=40.0, friction=0.5, surface=s,
                                tangential_damping=1.0),
              bouncelab.collide("tennis", surface=dict(s, mass=4.0))):
        back = pickle.loads(pickle.dumps(r))
        assert back == r and back.surface == r.surface
        assert copy.deepcopy(r) == r
    # the surface read is a new dict: changing it changes no answer
    r = bouncelab.run(preset="tennis", surface=s)
    r.surface["stiffness"] = 1.0
    assert r.surface["stiffness"] == 1e6
