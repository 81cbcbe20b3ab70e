"""A preset ball with some of its parameters replaced, as the command line's `--mass`,
`--radius`, `--k-p`, `--damping`, `--k-r`, `--z-p` replace them: `run`, `drop`, `oblique` and
`collide` take them as keyword arguments (SI units) and answer as the command line does."""

import pytest

import bouncelab
from test_bouncelab import cli_error, cli_json, no_user_presets, same  # noqa: F401

# a tennis ball with a stiffer recoil spring, a softer dashpot and a heavier core
SET = {"k_r": 20000.0, "damping": 180.0, "mass": 0.06}
FLAGS = ["--k-r", "20000", "--damping", "180", "--mass", "0.06"]


def test_run_takes_the_overrides_as_the_command_line():
    r = bouncelab.run(preset="tennis", **SET)
    want = cli_json("run", "--preset", "tennis", *FLAGS, "--format", "json")
    # the project's parity: numbers to 1e-12 relative (test_bouncelab.same)
    same(r.to_dict(), want)
    assert (r.k_r, r.c, r.mass) == (2e4, 180.0, 0.06)
    # and they move the answer: the preset's own ball differs
    assert bouncelab.run(preset="tennis").cor != r.cor


def test_drop_judges_the_overridden_ball_against_its_standard():
    d = bouncelab.drop(preset="tennis", standard="itf", **SET)
    want = cli_json("drop", "--preset", "tennis", "--standard", "itf", *FLAGS, "--format", "json")
    same(d["standard"], want["standard"])
    same(list(d["bounces"]["cor"]), [b["cor"] for b in want["bounces"]])
    assert d["standard"] != bouncelab.drop(preset="tennis", standard="itf")["standard"]


def test_oblique_and_collide_take_the_overrides_as_the_command_line():
    o = bouncelab.oblique("tennis", angle=30.0, friction=0.5, radius=0.034, **SET)
    want = cli_json("oblique", "--preset", "tennis", "--angle", "30", "--friction", "0.5",
                    "--radius", "0.034", *FLAGS, "--format", "json")
    same(o.to_dict(), want)
    c = bouncelab.collide(preset="tennis", target_mass=0.3, z_p=0.004, **SET)
    want = cli_json("collide", "--preset", "tennis", "--target-mass", "0.3", "--z-p", "0.004",
                    *FLAGS, "--format", "json")
    same(c.to_dict(), want)


@pytest.mark.parametrize("name", ["mass", "radius", "k_p", "damping", "k_r", "z_p"])
def test_a_bad_override_is_named_as_the_command_line_names_it(name):
    flag = "--" + name.replace("_", "-")
    want = cli_error("run", "--preset", "tennis", flag, "-1")
    with pytest.raises(ValueError) as e:
        bouncelab.run(preset="tennis", **{name: -1.0})
    assert str(e.value) == want


def test_one_parameter_set_twice_is_refused():
    with pytest.raises(ValueError, match="k_r and lambda_ both set K_r"):
        bouncelab.run(preset="tennis", k_r=2e4, lambda_=0.5)
    with pytest.raises(ValueError, match="damping and zeta both set c"):
        bouncelab.run(preset="tennis", damping=180.0, zeta=0.1)
    # either alone answers
    assert bouncelab.run(preset="tennis", lambda_=0.5).cor > 0
    assert bouncelab.run(preset="tennis", zeta=0.1).cor > 0


def test_monte_carlo_spreads_the_overridden_ball_as_the_command_line():
    kw = dict(preset="tennis", vary={"k_p": 0.05, "c": 0.05}, samples=2000, seed=5)
    m = bouncelab.monte_carlo(**kw, **SET)
    want = cli_json("mc", "--preset", "tennis", "--vary", "k_p=5%,c=5%", "--samples", "2000",
                    "--seed", "5", *FLAGS, "--format", "json")
    same(m, want)
    assert m["stats"]["cor"]["mean"] != bouncelab.monte_carlo(**kw)["stats"]["cor"]["mean"]


def test_dask_spreads_the_overridden_ball_as_the_single_call():
    distributed = pytest.importorskip("distributed")
    import bouncelab.dask

    kw = dict(preset="tennis", vary={"k_p": 0.05}, samples=5_003, seed=9, **SET)
    one = bouncelab.monte_carlo(**kw)
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        assert bouncelab.dask.monte_carlo(client, **kw, chunk=2_000) == one
