"""Reads the drainability heat maps `fabvdb drain` writes (binary PLY: the
cavity surface with a viridis colour and a `quality` value per vertex).

Takes the path; returns the surface as a Mesh and the values as a float array,
with numpy (no per-element Python loop). Raises BadInputError for any other
PLY layout.
"""
import numpy as np

from . import _fabvdb
from ._fabvdb import BadInputError

_VERTEX = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("r", "u1"), ("g", "u1"), ("b", "u1"),
                    ("quality", "<f4")])
_FACE = np.dtype([("n", "u1"), ("i", "<i4", (3,))])
_PROPERTIES = ["property float x", "property float y", "property float z", "property uchar red",
               "property uchar green", "property uchar blue", "property float quality"]


def read(path):
    """(surface Mesh, per-vertex values, per-vertex colours (n, 3) uint8) of a heat-map PLY."""
    with open(path, "rb") as file:
        data = file.read()
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        raise BadInputError(f"{path}: not a PLY heat map")
    header = data[:end].decode("ascii", "replace").splitlines()
    lines = [line for line in header if not line.startswith("comment")]
    try:
        vertex_count = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
        face_count = int(next(l for l in lines if l.startswith("element face")).split()[2])
    except (StopIteration, IndexError, ValueError):
        raise BadInputError(f"{path}: a heat map needs vertex and face elements") from None
    if "format binary_little_endian 1.0" not in lines or [l for l in lines if l.startswith("property float") or
                                                           l.startswith("property uchar")] != _PROPERTIES:
        raise BadInputError(f"{path}: not a heat map as fabvdb writes it")
    body = end + len(b"end_header\n")
    vertices = np.frombuffer(data, _VERTEX, vertex_count, body)
    faces = np.frombuffer(data, _FACE, face_count, body + vertex_count * _VERTEX.itemsize)
    if face_count and not np.all(faces["n"] == 3):
        raise BadInputError(f"{path}: a heat map has triangles only")
    points = np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1)
    surface = _fabvdb.Mesh(points, faces["i"])
    colours = np.stack([vertices["r"], vertices["g"], vertices["b"]], axis=1)
    return surface, vertices["quality"].astype(np.float64), colours
