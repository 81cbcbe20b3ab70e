"""Issue 54 item 9: an array of more dimensions than numpy broadcasts (64) came out of
`impacts` as a RuntimeError (the boundary's word for a native failure); it is the argument's
fault: ValueError naming it. A bad `Collision` pickle raised KeyError: a ValueError naming the
key, as `Impact`'s."""

import numpy as np
import pytest

import bouncelab


@pytest.mark.parametrize("ndim", [33, 64])
def test_an_array_of_too_many_dimensions_is_named(ndim):
    a = np.ones((1,) * ndim)
    with pytest.raises(ValueError, match=rf"invalid m: an array of {ndim} dimensions"):
        bouncelab.impacts(m=a, k_p=1e4, c=1.0, k_r=1e5, v0=1.0)


def test_thirty_two_dimensions_still_broadcast():
    a = np.ones((1,) * 32)
    r = bouncelab.impacts(m=a, k_p=1e4, c=1.0, k_r=1e5, v0=1.0)
    assert r["cor"].shape == a.shape


@pytest.mark.parametrize("state", [{}, {"target": {}}])
def test_a_bad_collision_state_is_a_value_error(state):
    # a state missing its keys raised KeyError (Impact's raises ValueError naming the key)
    c = bouncelab.collide("golf", target_mass=1.0)
    rebuild, _ = c.__reduce__()
    with pytest.raises(ValueError, match=r"Collision state without '"):
        rebuild(state)
