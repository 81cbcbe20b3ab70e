"""The boundary between Python and the native module, where its errors become Python's.

- A panic of the native code (a bug: every numeric path is meant to end in a typed error)
  reaches Python as PyO3's ``PanicException``, a ``BaseException`` that ``except Exception``
  misses: it is raised again as ``RuntimeError`` with its message.
- An argument the native code cannot take raises PyO3's error, whose message does not say
  which argument (``TypeError: must be real number, not list``): PyO3 (and the native code,
  for the arguments it reads by hand) puts the name in a note, ``while processing 'v0'``, which
  Python shows only in a traceback. The error is raised again, of its own class, naming the
  argument and its value as the command line's errors do ("invalid v0: [1.0, 2.0] (must be
  real number, not list)"). A negative whole number where a count is meant (``samples=-1``,
  ``seed=-1``) is a ``ValueError`` ("invalid samples: -1 (must not be negative)"), as is
  ``samples=0``; a number too large for the native code (``bounces=10**30``, ``v0=10**400``)
  stays an ``OverflowError``. The notes are Python 3.11's: on 3.9 and 3.10 only an overflow's
  argument is found (the one integer out of every native range).
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
# an argument's value when the call did not give it (a default's error)
_UNSEEN = object()


def _shown(value):
    """A value for a message, on one line: a number whole up to 30 digits, else its size; any
    other value its repr, cut after 40 characters."""
    if isinstance(value, int) and not isinstance(value, bool):
        digits = len(str(abs(value)))
        if digits > 30:
            sign = "-" if value < 0 else ""
            return f"{sign}an integer of {digits} digits"
    try:
        text = " ".join(repr(value).split())
    except Exception:
        text = f"a {type(value).__name__}"
    return visible(text if len(text) <= 40 else text[:39] + "…")


def _negative_count(value):
    """Whether `value` is a negative whole number a float would hold: one a float parameter
    takes, so its overflow is an unsigned parameter's (a count, a seed)."""
    if not isinstance(value, int) or isinstance(value, bool) or value >= 0:
        return False
    try:
        float(value)
    except OverflowError:
        return False
    return True


def _named(error, args, kwargs, names):
    """`error` raised again naming the argument it was about, when one is known."""
    name, value = _argument(error, args, kwargs, names)
    if name is None:
        return error
    shown = "" if value is _UNSEEN else f" {_shown(value)}"
    if isinstance(error, OverflowError) and _negative_count(value):
        return ValueError(f"invalid {name}:{shown} (must not be negative)")
    # the plain class it is one of (a UnicodeEncodeError, a ValueError, takes no one message)
    for kind in (OverflowError, TypeError, ValueError):
        if isinstance(error, kind):
            return kind(f"invalid {name}:{shown} ({visible(error)})")
    return error


def _argument(error, args, kwargs, names):
    """The argument of the call an extraction error was about (``None`` if unknown), and its
    value (``_UNSEEN`` if the call did not give it)."""
    for note in getattr(error, "__notes__", ()):
        m = _PROCESSING.search(note)
        if m and m.group(1) in names:
            name = m.group(1)
            if name in kwargs:
                return name, kwargs[name]
            if names.index(name) < len(args):
                return name, args[names.index(name)]
            return name, _UNSEEN
    if not isinstance(error, OverflowError):
        return None, _UNSEEN
    # before Python 3.11 there are no notes: the one integer out of every native range
    huge = [
        (k, v)
        for k, v in kwargs.items()
        if isinstance(v, int) and not isinstance(v, bool) and (v < 0 or v >= 2**63)
    ]
    return huge[0] if len(huge) == 1 else (None, _UNSEEN)


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
    """`f` with the native module's panics raised as Python errors, its errors about an
    argument naming it, and bools refused where a number is meant."""
    names = _parameters(f)
    numeric = set(names) - _flags(f) - _TEXT

    @functools.wraps(f)
    def call(*args, **kwargs):
        for name, value in [*zip(names, args), *kwargs.items()]:
            if name in numeric:
                _refuse_bools(name, value)
        try:
            return f(*args, **kwargs)
        except Exception as e:
            named = _named(e, args, kwargs, names)
            if named is e:
                raise
            raise named from None
        except BaseException as e:
            if type(e).__name__ != "PanicException":
                raise
            raise RuntimeError(
                f"internal error in bouncelab (a bug; please report it): {visible(e)}"
            ) from None

    call.__module__ = "bouncelab"
    return call
