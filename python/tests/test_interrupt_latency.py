"""Ctrl-C in `bouncelab.batch` and `bouncelab.impacts` on 10⁷ elements (issue 54 item 6: 9.4 s
and 3.1 s to answer; aim ≤ 0.5 s), measured in a subprocess sent SIGINT as a terminal sends it:
the call raises KeyboardInterrupt, and soon. The latency is printed (pytest -s); the bound
asserted, 5 s, only tells a hang from an answer (speed is measured, not asserted: BRIEF)."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

HANG = 5.0


def interrupted(script: str, delay: float):
    """Run `script` (which prints "go" right before its long call, and "interrupted
    <time.monotonic()>" where KeyboardInterrupt reaches it) in a child Python; SIGINT it
    `delay` s after "go". The seconds from the signal to the KeyboardInterrupt."""
    child = subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(script)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=os.environ,
    )
    try:
        assert child.stdout.readline().strip() == "go", child.stderr.read()
        time.sleep(delay)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=HANG + 30)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    lines = out.split()
    assert "interrupted" in lines, f"no KeyboardInterrupt: {out!r} {err[-2000:]!r}"
    at = float(lines[lines.index("interrupted") + 1])
    return at - sent


def test_ctrl_c_stops_impacts_on_ten_million_elements():
    late = interrupted(
        """
        import time, numpy as np, bouncelab
        c = np.linspace(0.5, 5.0, 10**7)
        print("go", flush=True)
        t0 = time.monotonic()
        try:
            for _ in range(20):
                bouncelab.impacts(m=0.0577, k_p=1.2e5, c=c, k_r=2e5, v0=3.0)
            print("finished", time.monotonic() - t0, flush=True)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic(), flush=True)
        """,
        delay=0.8,
    )
    print(f"impacts: KeyboardInterrupt {late * 1e3:.0f} ms after SIGINT")
    assert 0 <= late < HANG


def test_ctrl_c_stops_a_batch(tmp_path):
    lot = tmp_path / "lot.csv"
    rows = ["id,drop_height_m,rebound_height_m"]
    # the most balls a batch takes (`analysis::batch::MAX_BALLS`), run again until the signal
    rows += [f"B{i},2.54,{1.35 + 0.0001 * (i % 500):.4f}" for i in range(10_000)]
    lot.write_text("\n".join(rows) + "\n")
    late = interrupted(
        f"""
        import time, bouncelab
        print("go", flush=True)
        try:
            for _ in range(20):
                bouncelab.batch({str(lot)!r}, preset="tennis")
            print("finished", flush=True)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic(), flush=True)
        """,
        delay=1.0,
    )
    print(f"batch: KeyboardInterrupt {late * 1e3:.0f} ms after SIGINT")
    assert 0 <= late < HANG
