"""Inputs shared by the commands: the context a call runs on, orientation
lists and JSON given as files, dicts or results, and a mesh's diagonal.

Each helper takes what the user passed and returns what the extension wants,
or raises the exception of the matching status (BadInputError, FileError)
naming the file and the defect. Cheap: no geometry is computed.
"""
import json
import math
import os

import numpy as np

from . import _fabvdb
from . import _units
from ._fabvdb import BadInputError, FileError, InvalidArgumentError


def context_for(context, threads, max_memory):
    """The Context a call runs on: `context` as given, else a new one."""
    if context is not None:
        if threads or max_memory is not None:
            raise InvalidArgumentError("give threads and max_memory to the Context, not with context=")
        if not isinstance(context, _fabvdb.Context):
            raise InvalidArgumentError("context must be a fabvdb.Context")
        return context
    threads = _units.count(threads, "threads", allow_auto=False)
    if threads < 0:
        raise InvalidArgumentError("threads must be 0 (every core) or more")
    budget = 0
    if max_memory is not None:
        budget = _units.size(max_memory, "max_memory")
        if not budget >= 1:
            raise InvalidArgumentError("max_memory must be positive")
    return _fabvdb.Context(threads, int(budget))


def diagonal(mesh):
    """The length of the mesh's bounding-box diagonal (mm); 0 for no vertices."""
    vertices = mesh.vertices
    if len(vertices) == 0:
        return 0.0
    return float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))


def path_text(value, name):
    """A file path as text, or InvalidArgumentError."""
    if isinstance(value, (str, os.PathLike)):
        return os.fsdecode(value)
    raise InvalidArgumentError(f"{name} must be a path, got {type(value).__name__}")


def orientations(value, name="orientations"):
    """None for "all", else a (k, 3) float array from a file of "x y z" lines or an array-like."""
    if value is None or (isinstance(value, str) and value == "all"):
        return None
    if isinstance(value, (str, os.PathLike)):
        path = os.fsdecode(value)
        rows = []
        try:
            with open(path, encoding="utf-8") as file:
                for number, line in enumerate(file, 1):
                    fields = line.split("#", 1)[0].split()
                    if not fields:
                        continue
                    try:
                        row = [float(x) for x in fields]
                    except ValueError:
                        row = []
                    if len(row) != 3 or not math.hypot(*row) > 0:
                        raise BadInputError(f'{path}:{number}: expected a direction "x y z"')
                    rows.append(row)
        except OSError as error:
            raise FileError(f"{path}: cannot open the orientations file ({error.strerror})") from None
        if not rows:
            raise BadInputError(f"{path}: no orientation in the file")
        return np.asarray(rows, dtype=np.float64)
    array = np.asarray(value, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 3 or len(array) == 0:
        raise InvalidArgumentError(f"{name} must be 'all', a file or a (k, 3) array of directions")
    if not np.all(np.isfinite(array)) or np.any(np.linalg.norm(array, axis=1) == 0):
        raise BadInputError(f"{name}: every direction must be finite and non-zero")
    return array


def json_text(value, name, wrap_list=None):
    """JSON text from a file path, a dict, a list (as {wrap_list: list} when given) or a result with a report."""
    report = getattr(value, "report", None)
    if isinstance(report, dict):
        value = report
    if isinstance(value, (str, os.PathLike)):
        path = os.fsdecode(value)
        try:
            with open(path, encoding="utf-8") as file:
                return file.read()
        except OSError as error:
            raise FileError(f"{path}: cannot open the {name} file ({error.strerror})") from None
    if isinstance(value, list) and wrap_list:
        value = {wrap_list: value}
    if isinstance(value, (dict, list)):
        return json.dumps(value)
    raise InvalidArgumentError(f"{name} must be a JSON file, a dict, a list or a result with a report")


def report(text):
    """A report's JSON text as a dict (None for no report)."""
    return json.loads(text) if text else None
