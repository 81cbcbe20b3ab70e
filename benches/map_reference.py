"""40-digit reference of one linear-law impact without flattening, summary only (issue 21).

The normalized ball (m = K_p = v0 = 1, docs/model.md §5): the indentation z̄ obeys
z̄''' + 2ζ(1+λ) z̄'' + z̄' + 2ζλ z̄ = 0 with z̄(0) = 0, z̄'(0) = 1, z̄''(0) = -2ζ; while z̄ > 0
the force is F̄ = z̄ on loading and unloading alike (no flattening), so one flow holds from
first touch to separation. Its modes are the roots of the cubic, at 60 digits (roots that
nearly coincide, where the complex pair turns real, are apart by ~1e-8 and still carry 40+
digits); the coefficients solve the Vandermonde system. τ_m is the first zero of z̄', F̄_m =
z̄(τ_m); τ_f the first zero of z̄ after it; e = -ᾱ'(τ_f), ᾱ' = 1 - ∫ z̄ dτ (ᾱ'' = -F̄).

Run: python3 benches/map_reference.py   (mpmath 1.3); prints the rows of
tests/physics/map_precision.rs's REFERENCE table: λ, ζ (the doubles' exact values), e, F̄_m, τ_f.
"""
from mpmath import mp, mpf, polyroots, matrix, lu_solve, exp, findroot, re, nstr

mp.dps = 60

POINTS = [
    (0.02, 1.7861026411617908),  # the complex pair turns real here (issue 21)
    (0.05, 0.9044760255043721),  # and here
    (1.0, 0.1),
    (0.4, 0.3),
    (5.0, 20.0),
    (100.0, 0.01),
    (0.01, 0.01),
    (0.3, 3.0),
]


def flow(lam, zeta):
    a2, a1, a0 = 2 * zeta * (1 + lam), mpf(1), 2 * zeta * lam
    r = polyroots([1, a2, a1, a0], maxsteps=500, extraprec=400)
    v = matrix([[1, 1, 1], [r[0], r[1], r[2]], [r[0] ** 2, r[1] ** 2, r[2] ** 2]])
    c = lu_solve(v, matrix([0, 1, -2 * zeta]))
    z = lambda t: re(sum(c[i] * exp(r[i] * t) for i in range(3)))
    dz = lambda t: re(sum(c[i] * r[i] * exp(r[i] * t) for i in range(3)))
    # ᾱ'(τ) = 1 - ∫0^τ z̄ = 1 - Σ c_i (e^{r_i τ} - 1)/r_i
    v_end = lambda t: re(1 - sum(c[i] * (exp(r[i] * t) - 1) / r[i] for i in range(3)))
    return z, dz, v_end


def first_zero(f, t0, step, falling):
    """The first sign change of f after t0 (in the direction asked), polished by findroot."""
    a, fa = t0, f(t0)
    for _ in range(200000):
        b = a + step
        fb = f(b)
        if (fa > 0 and fb <= 0) if falling else (fa < 0 and fb >= 0):
            return findroot(f, (a, b), solver="anderson")
        a, fa = b, fb
        step *= 1.02
    raise RuntimeError("no zero")


def reference(lam_f, zeta_f):
    lam, zeta = mpf(lam_f), mpf(zeta_f)  # the doubles' exact binary values
    z, dz, v_end = flow(lam, zeta)
    tau_m = first_zero(dz, mpf("1e-9"), mpf("0.01"), True)
    tau_f = first_zero(z, tau_m, mpf("0.01"), True)
    return -v_end(tau_f), z(tau_m), tau_f


for lam, zeta in POINTS:
    e, f, t = reference(lam, zeta)
    print(f"    ({lam!r}, {zeta!r}, {nstr(e, 40)}, {nstr(f, 40)}, {nstr(t, 40)}),")
