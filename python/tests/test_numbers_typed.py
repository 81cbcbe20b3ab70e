"""Issue 54 item 7: a spread is a number. `vary={'k_p': True}` was read as 100 % (a bool is an
int to Python); now it is refused, naming the parameter, as any value that is not a number."""

import pytest

import bouncelab


@pytest.mark.parametrize("bad", [True, False, "5%", None, [0.05]])
def test_a_spread_that_is_no_number_is_refused(bad):
    with pytest.raises(ValueError, match=r"invalid vary k_p: .* is not a number"):
        bouncelab.monte_carlo(preset="golf", vary={"k_p": bad}, samples=10)


def test_a_number_still_reads():
    r = bouncelab.monte_carlo(preset="golf", vary={"k_p": 0.05}, samples=10)
    assert list(r["vary"]) == ["k_p"]
