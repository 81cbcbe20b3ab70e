"""The boundary between Python and the native module, where its errors become Python's.

- A panic of the native code (a bug: every numeric path is meant to end in a typed error)
  reaches Python as PyO3's ``PanicException``, a ``BaseException`` that ``except Exception``
  misses: it is raised again as ``RuntimeError`` with its message.
- A number Python cannot hand to the native code (``samples=-1``, ``bounces=10**30``,
  ``v0=10**400``) raises PyO3's ``OverflowError``, whose message does not say which argument:
  it is raised again naming it, as the command line's errors do ("invalid samples: -1 …").

(python/tests/test_boundary.py)
"""

import functools
import re

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


def guard(f):
    """`f` with the native module's panics and overflows raised as Python errors."""
    names = _parameters(f)

    @functools.wraps(f)
    def call(*args, **kwargs):
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
