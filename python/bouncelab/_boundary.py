"""The boundary between Python and the native module, where its errors become Python's.

- A panic of the native code (a bug: every numeric path is meant to end in a typed error)
  reaches Python as PyO3's ``PanicException``, a ``BaseException`` that ``except Exception``
  misses: it is raised again as ``RuntimeError`` with its message.
- A number Python cannot hand to the native code (``samples=-1``, ``bounces=10**30``,
  ``v0=10**400``) raises PyO3's ``OverflowError``, whose message does not say which argument:
  it is raised again naming it, as the command line's errors do ("invalid samples: -1 …").
- A bool where a number is meant (``run(v0=True)``, ``speeds=[3.0, True]``, an array of
  bools) is refused with a ``TypeError`` naming the argument (and the element): Python's
  ``True`` is the integer 1, and the native code read it as 1.0. The flags (a parameter whose
  default is ``True`` or ``False``) take bools, and the parameters that take names or text
  (``_TEXT``) are left to the native code's own checks.

(python/tests/test_boundary.py, python/tests/test_arguments.py)
"""

import functools
import re

import numpy as np

_PROCESSING = re.compile(r"while processing '([^']+)'")


def _shown(value):
    """A number for a message: whole up to 30 digits, else its size."""
    if isinstance(value, int) and not isinstance(value, bool):
        digits = len(str(abs(value)))
        if digits > 30:
            sign = "-" if value < 0 else ""
            return f"{sign}an integer of {digits} digits"
    return repr(value)


def _argument(error, args, kwargs, names):
    """The argument an extraction error was about, and its value (``None`` if unknown)."""
    for note in getattr(error, "__notes__", ()):
        m = _PROCESSING.search(note)
        if m:
            name = m.group(1)
            if name in kwargs:
                return name, kwargs[name]
            if name in names and names.index(name) < len(args):
                return name, args[names.index(name)]
            return name, None
    # before Python 3.11 there are no notes: the one integer out of every native range
    huge = [
        (k, v)
        for k, v in kwargs.items()
        if isinstance(v, int) and not isinstance(v, bool) and (v < 0 or v >= 2**63)
    ]
    return huge[0] if len(huge) == 1 else (None, None)


def visible(text):
    """`text` with control and format characters (ESC, BEL, NUL, zero-width …) escaped."""
    return "".join(
        c if c.isprintable() or c == " " else c.encode("unicode_escape").decode("ascii")
        for c in str(text)
    )


def _parameters(f):
    """The names of `f`'s parameters, in order, from its text signature."""
    sig = getattr(f, "__text_signature__", None) or ""
    return [p.split("=")[0].strip(" */") for p in sig.strip("()").split(",") if p.strip()]


# the parameters that take names, text or mappings, not numbers: a bool there is the native
# code's to refuse
_TEXT = {
    "correlate",
    "dist",
    "file",
    "free",
    "law",
    "params",
    "preset",
    "standard",
    "target_preset",
    "vary",
}


def _flags(f):
    """The names of `f`'s parameters whose default is ``True`` or ``False``: bools."""
    sig = getattr(f, "__text_signature__", None) or ""
    parts = [p.strip(" */").split("=") for p in sig.strip("()").split(",")]
    return {p[0].strip() for p in parts if len(p) == 2 and p[1].strip() in ("True", "False")}


def _is_bool(x):
    return isinstance(x, (bool, np.bool_))


def _refuse_bools(name, value):
    """A ``TypeError`` naming `name` (and the element) when `value` is a bool or holds one."""
    why = "(expected a number, not a bool)"
    if _is_bool(value):
        raise TypeError(f"invalid {name}: {value!r} {why}")
    if isinstance(value, np.ndarray) and value.dtype == np.bool_:
        raise TypeError(f"invalid {name}: an array of bool {why}")
    if isinstance(value, (list, tuple)) or (
        isinstance(value, np.ndarray) and value.dtype == object and value.ndim == 1
    ):
        for i, x in enumerate(value):
            if _is_bool(x):
                raise TypeError(f"invalid {name}[{i}]: {x!r} {why}")


def guard(f):
    """`f` with the native module's panics and overflows raised as Python errors, and bools
    refused where a number is meant."""
    names = _parameters(f)
    numeric = set(names) - _flags(f) - _TEXT

    @functools.wraps(f)
    def call(*args, **kwargs):
        for name, value in [*zip(names, args), *kwargs.items()]:
            if name in numeric:
                _refuse_bools(name, value)
        try:
            return f(*args, **kwargs)
        except OverflowError as e:
            name, value = _argument(e, args, kwargs, names)
            if name is None:
                raise
            shown = "" if value is None else f" {_shown(value)}"
            raise OverflowError(f"invalid {name}:{shown} ({e})") from None
        except BaseException as e:
            if type(e).__name__ != "PanicException":
                raise
            raise RuntimeError(
                f"internal error in bouncelab (a bug; please report it): {visible(e)}"
            ) from None

    call.__module__ = "bouncelab"
    return call
