"""COR against ζ for several λ — the paper's Fig. 2 — drawn with matplotlib.

    pip install ./python matplotlib
    python python/examples/cor_vs_zeta.py [out.png]

Without an output file the figure opens in a window (or, with no display, is written to
cor_vs_zeta.png). matplotlib is needed here only, not by the package or its tests.
"""

import sys

import numpy as np

import bouncelab


def main(out=None):
    import matplotlib

    if out is not None:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lambdas = [0.0, 0.1, 0.4, 1.0, 4.0]
    zetas = np.logspace(-2, 2, 400)
    d = bouncelab.sweep_zeta(lambdas, zetas)  # one call, all λ; the GIL is released meanwhile
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for lam in lambdas:
        rows = d["lambda"] == lam
        ax.semilogx(d["zeta"][rows], d["cor"][rows], label=f"λ = {lam:g}")
    # the three balls of the paper, at their adopted λ and ζ
    for p in bouncelab.presets()[:3]:
        r = bouncelab.run(preset=p["name"])
        ax.plot(r.zeta, r.cor, "o", color="black")
        ax.annotate(p["name"], (r.zeta, r.cor), textcoords="offset points", xytext=(6, -12))
    ax.set_xlabel("damping factor ζ = √(m K_p) / (2c)")
    ax.set_ylabel("coefficient of restitution e")
    ax.set_ylim(0, 1.02)
    ax.set_title("COR against ζ, linear law, no flattening (Christoforou & Yigit, Fig. 2)")
    ax.legend(loc="lower left")
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    if out is None and matplotlib.get_backend().lower() == "agg":
        out = "cor_vs_zeta.png"
    if out is None:
        plt.show()
    else:
        fig.savefig(out, dpi=120)
        print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else None)
