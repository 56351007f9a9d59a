"""fabvdb — prepares 3D models for fabrication: repair, hollow, drain holes,
mold decomposition and molds. The Python face of the C library (fabvdb.h).

Meshes are numpy arrays in and out::

    import fabvdb, numpy as np
    part = fabvdb.read("part.stl")                  # or fabvdb.Mesh(vertices, triangles)
    shell, report = fabvdb.hollow(part, wall="2mm")  # lengths in mm or "3mm", "0.1in", "2%"
    shell.vertices, shell.triangles                 # (n, 3) float64, (m, 3) uint32, no copy
    shell.write("shell.stl")

Every command of the ``fabvdb`` tool is a function with its options as
keyword arguments: inspect, check, repair, hollow, drain, powder_sim, decompose,
mold (and to_volume for level sets). Decomposition is the interactive
session. Errors are fabvdb.Error subclasses; Ctrl-C cancels a running call.
See docs/python.md.
"""
from . import _fabvdb
from ._fabvdb import (BadInputError, CancelledError, Context, Error, FileError, InternalError, InvalidArgumentError,
                      Mesh, NotFoundError, OutOfBudgetError, OutOfMemoryError, Volume)
from ._commands import (DecomposeResult, DrainResult, HeatMap, MoldResult, Result, VolumeResult, check, decompose,
                        drain, hollow, inspect, mold, powder_sim, read, repair, to_volume, write)
from ._session import Decomposition

__version__ = _fabvdb.version


def _mesh_write(self, path, *, context=None):
    """Writes the mesh (.stl binary, .ply, .obj, .off, .3mf) atomically; a solid fabvdb made is checked first."""
    write(self, path, context=context)


def _mesh_repr(self):
    return f"<fabvdb.Mesh: {self.vertex_count} vertices, {self.triangle_count} triangles>"


def _volume_read(path, *, context=None):
    """Reads the first float level set of an OpenVDB file (.vdb)."""
    return _fabvdb._read_volume(context or Context(), str(path))


def _volume_write(self, path, *, context=None):
    """Writes the level set as an OpenVDB file (.vdb), atomically."""
    _fabvdb._write_volume(context or Context(), self, str(path))


def _volume_to_mesh(self, *, adaptivity=0.0, progress=None, context=None):
    """Extracts the zero surface: closed, 2-manifold, outward-oriented."""
    return _fabvdb._volume_to_mesh(context or Context(), self, float(adaptivity), progress)


Mesh.read = staticmethod(read)
Mesh.write = _mesh_write
Mesh.__repr__ = _mesh_repr
Volume.read = staticmethod(_volume_read)
Volume.write = _volume_write
Volume.to_mesh = _volume_to_mesh

__all__ = ["BadInputError", "CancelledError", "Context", "DecomposeResult", "Decomposition", "DrainResult",
           "Error", "FileError", "HeatMap", "InternalError", "InvalidArgumentError", "Mesh", "MoldResult",
           "NotFoundError", "OutOfBudgetError", "OutOfMemoryError", "Result", "Volume", "VolumeResult",
           "check", "decompose", "drain", "hollow", "inspect", "mold", "powder_sim", "read", "repair", "to_volume",
           "write"]
