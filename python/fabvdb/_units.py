"""Values with units, read as the ``fabvdb`` command reads them.

Takes a number (millimetres, degrees, bytes) or a string with a unit: lengths
``"3mm"``, ``"0.3cm"``, ``"0.1m"``, ``"0.1in"``, ``"2%"`` (of the bounding-box
diagonal); angles ``"35deg"``, ``"0.6rad"``; sizes ``"512M"``, ``"8G"``.
Returns plain floats; a malformed value raises InvalidArgumentError naming
the option. Costs nothing worth counting.
"""
import math
import re

from ._fabvdb import InvalidArgumentError

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z%]*)\s*$")

_LENGTH_UNITS = {"": 1.0, "mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4}
_ANGLE_UNITS = {"": 1.0, "deg": 1.0, "rad": 180.0 / math.pi}
_SIZE_UNITS = {"": 1.0, "b": 1.0, "k": 1024.0, "kb": 1024.0, "kib": 1024.0, "m": 1024.0 ** 2,
               "mb": 1024.0 ** 2, "mib": 1024.0 ** 2, "g": 1024.0 ** 3, "gb": 1024.0 ** 3, "gib": 1024.0 ** 3}


def _split(value, name, hint):
    if isinstance(value, bool):
        raise InvalidArgumentError(f"{name}: expected {hint}, got {value!r}")
    if isinstance(value, (int, float)):
        number, unit = float(value), ""
    elif isinstance(value, str):
        match = _NUMBER.match(value)
        if not match:
            raise InvalidArgumentError(f"{name}: expected {hint}, got {value!r}")
        number, unit = float(match.group(1)), match.group(2).lower()
    else:
        try:
            number, unit = float(value), ""  # numpy scalars
        except (TypeError, ValueError):
            raise InvalidArgumentError(f"{name}: expected {hint}, got {value!r}") from None
    if not math.isfinite(number):
        raise InvalidArgumentError(f"{name}: expected a finite value, got {value!r}")
    return number, unit


def length(value, name, diagonal):
    """Millimetres from a length: a number (mm) or "3mm", "0.3cm", "0.1m", "0.1in", "2%" (of `diagonal`)."""
    hint = "a length such as 3, '3mm', '0.3cm', '0.1in' or '2%' (of the bounding-box diagonal)"
    number, unit = _split(value, name, hint)
    if unit == "%":
        return number / 100.0 * diagonal
    if unit not in _LENGTH_UNITS:
        raise InvalidArgumentError(f"{name}: unknown unit {unit!r}; expected {hint}")
    return number * _LENGTH_UNITS[unit]


def angle(value, name):
    """Degrees from an angle: a number (degrees) or "35deg", "0.6rad"."""
    hint = "an angle such as 35, '35deg' or '0.6rad'"
    number, unit = _split(value, name, hint)
    if unit not in _ANGLE_UNITS:
        raise InvalidArgumentError(f"{name}: unknown unit {unit!r}; expected {hint}")
    return number * _ANGLE_UNITS[unit]


def size(value, name):
    """Bytes from a size: a number (bytes) or "512M", "8G", "2GiB"."""
    hint = "a size such as 536870912, '512M' or '8G'"
    number, unit = _split(value, name, hint)
    if unit not in _SIZE_UNITS:
        raise InvalidArgumentError(f"{name}: unknown unit {unit!r}; expected {hint}")
    return number * _SIZE_UNITS[unit]


def share(value, name):
    """A fraction in [0, 1) from "1%" or 0.01."""
    number, unit = _split(value, name, "a share such as '1%' or 0.01")
    if unit == "%":
        number /= 100.0
    elif unit:
        raise InvalidArgumentError(f"{name}: expected a share such as '1%' or 0.01, got {value!r}")
    if not 0.0 <= number < 1.0:
        raise InvalidArgumentError(f"{name}: a share must be in [0, 1) (0% to under 100%), got {value!r}")
    return number


def count(value, name, allow_auto=True):
    """An int from a whole number, or 0 for "auto"."""
    if allow_auto and (value is None or value == "auto"):
        return 0
    if isinstance(value, bool):
        raise InvalidArgumentError(f"{name}: expected a whole number{' or auto' if allow_auto else ''}, got {value!r}")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InvalidArgumentError(
            f"{name}: expected a whole number{' or auto' if allow_auto else ''}, got {value!r}") from None
    if not math.isfinite(number) or number != math.floor(number):
        raise InvalidArgumentError(f"{name}: expected a whole number, got {value!r}")
    return int(number)
