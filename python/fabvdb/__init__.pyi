# Type stub of the fabvdb package (python/fabvdb); docstrings from fabvdb.h.
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
import os
from typing import Any, Callable, NamedTuple, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

Length = Union[float, int, str]
"""Millimetres, or a string with a unit: "3mm", "0.3cm", "0.1m", "0.1in", "2%" (of the bounding-box diagonal)."""
Angle = Union[float, int, str]
"""Degrees, or "35deg", "0.6rad"."""
Size = Union[float, int, str]
"""Bytes, or "512M", "8G", "2GiB"."""
Path = Union[str, os.PathLike]
Progress = Optional[Callable[[str, float], Any]]
"""Called with the stage's name and the fraction of it done in [0, 1]; a truthy return cancels (CancelledError)."""
MeshLike = Union["Mesh", Path, Any]
"""A Mesh, a mesh file's path, or an object with vertices and faces arrays (a trimesh)."""


class Error(Exception):
    """A fabvdb call failed. str(error) is the library's message; error.status is its fabvdb_status code."""
    status: int
class InvalidArgumentError(Error, ValueError):
    """A parameter is out of its range, or an array has the wrong shape (FABVDB_ERR_INVALID_ARGUMENT)."""
class FileError(Error):
    """A file could not be opened, read, written or renamed (FABVDB_ERR_IO)."""
class BadInputError(Error, ValueError):
    """The input is malformed or cannot be processed; the message names the defect (FABVDB_ERR_BAD_INPUT)."""
class OutOfBudgetError(Error):
    """The operation would exceed the context's memory budget; the message proposes what fits."""
class OutOfMemoryError(Error, MemoryError):
    """Memory allocation failed."""
class CancelledError(Error):
    """The progress callback or Context.cancel() cancelled the call; no result was made."""
class InternalError(Error):
    """A bug or an unexpected library failure (also: a solid that fails the check before writing)."""
class NotFoundError(Error, LookupError):
    """A key or item asked for does not exist."""


class Context:
    """A library context: worker threads (0: every core), memory budget in bytes (0: half the physical memory).
    One call at a time runs on a context (others wait); cancel() is safe from any thread."""
    def __init__(self, threads: int = 0, memory_budget: int = 0) -> None: ...
    def cancel(self) -> None:
        """Cancels the call running on this context (or the next one started); it raises CancelledError."""
    @property
    def memory_budget(self) -> int: ...
    @property
    def threads(self) -> int: ...


class Mesh:
    """An immutable triangle mesh: vertex positions (mm) and triangles of three 0-based vertex indices."""
    def __init__(self, vertices: npt.ArrayLike, triangles: npt.ArrayLike) -> None:
        """From an (n, 3) array of positions (any float or integer dtype) and an (m, 3) array of vertex
        indices (any integer dtype), converted once and copied. Raises InvalidArgumentError (shape, dtype)
        or BadInputError (an index out of range, a non-finite coordinate)."""
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """(n, 3) positions, a read-only view (no copy)."""
    @property
    def triangles(self) -> npt.NDArray[np.uint32]:
        """(m, 3) vertex indices, a read-only view (no copy)."""
    @property
    def vertex_count(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...
    @staticmethod
    def read(path: Path, *, scale: Optional[float] = None, fit: Optional[Length] = None, progress: Progress = None,
             context: Optional[Context] = None, threads: int = 0, max_memory: Optional[Size] = None) -> "Mesh":
        """As fabvdb.read()."""
    def write(self, path: Path, *, context: Optional[Context] = None) -> None:
        """Writes .stl (binary), .ply, .obj, .off or .3mf atomically; a solid fabvdb made is checked first."""


class Volume:
    """A solid as a sparse narrow-band signed distance field (OpenVDB, negative inside, mm)."""
    @property
    def voxel_size(self) -> float: ...
    @staticmethod
    def read(path: Path, *, context: Optional[Context] = None) -> "Volume":
        """Reads the first float level set of an OpenVDB file (.vdb)."""
    def write(self, path: Path, *, context: Optional[Context] = None) -> None:
        """Writes an OpenVDB file (.vdb), atomically."""
    def to_mesh(self, *, adaptivity: float = 0.0, progress: Progress = None,
                context: Optional[Context] = None) -> Mesh:
        """Extracts the zero surface: closed, 2-manifold, outward-oriented."""


class Result(NamedTuple):
    """A mesh a command made, and its report (a dict of every figure computed)."""
    mesh: Mesh
    report: Optional[dict]

class VolumeResult(NamedTuple):
    volume: Volume
    report: Optional[dict]

class HeatMap(NamedTuple):
    """The cavity surface (triangles facing the powder), per vertex the share of the powder resting there
    that drains (0..1) and the powder left (mm^3/mm^2), the viridis colours of the share (n, 3) uint8, and
    the report's heatmap entry (ranges, mean; with a .ply path, the files). Taken from the library as
    arrays (fabvdb_mesh_drain_heatmap): no file is written unless heatmap is a path."""
    surface: Mesh
    drains: npt.NDArray[np.float64]
    left: npt.NDArray[np.float64]
    colours: npt.NDArray[np.uint8]
    report: dict

class DrainResult(NamedTuple):
    mesh: Mesh
    report: dict
    holes: list
    routine: list
    heatmap: Optional[HeatMap]

class DecomposeResult(NamedTuple):
    report: dict
    decomposition: dict
    output: Optional[str]

class MoldResult(NamedTuple):
    parts: list
    molds: list
    report: dict
    output: Optional[str]


def read(path: Path, *, scale: Optional[float] = None, fit: Optional[Length] = None, progress: Progress = None,
         context: Optional[Context] = None, threads: int = 0, max_memory: Optional[Size] = None) -> Mesh:
    """Reads a mesh file (.stl .obj .ply .off .3mf); scale multiplies the coordinates, fit scales the longest
    side to a length. Raises FileError or BadInputError (the message names the file and the defect)."""

def write(mesh: Mesh, path: Path, *, context: Optional[Context] = None) -> None:
    """Writes a mesh atomically (format from the extension)."""

def inspect(mesh: MeshLike, *, report: Optional[Path] = None, progress: Progress = None,
            context: Optional[Context] = None, threads: int = 0, max_memory: Optional[Size] = None) -> dict:
    """Counts, topology, defects, volume, genus, bbox (fabvdb info; docs/info.md). Defects are data."""

def check(mesh: MeshLike, *, process: Union[str, Path] = "sla", up: Union[str, Sequence[float]] = "+z",
          build_volume: Union[None, str, Sequence[Length]] = None, voxel: Optional[Length] = None,
          resolution: int = 400, thickness_map: Optional[Path] = None, report: Optional[Path] = None,
          progress: Progress = None, context: Optional[Context] = None, threads: int = 0,
          max_memory: Optional[Size] = None) -> dict:
    """Will it print in this process as it is (fabvdb check; docs/check.md): verdict "pass", "warn" or "fail"
    and every check with its figures in mm. A part that fails is a finding, never an error."""

def repair(mesh: MeshLike, *, voxel: Optional[Length] = None, resolution: int = 400, adaptivity: float = 0.0,
           volumetric: bool = False, no_snap: bool = False, min_shell_volume: float = 0.0,
           thicken: Optional[Length] = None, output: Optional[Path] = None, report: Union[bool, Path] = True,
           progress: Progress = None, context: Optional[Context] = None, threads: int = 0,
           max_memory: Optional[Size] = None) -> Result:
    """A clean watertight solid of a dirty mesh, changing no more than it must (fabvdb repair; docs/repair.md).
    output ending in .vdb returns a VolumeResult with the level set instead."""

def to_volume(mesh: MeshLike, *, voxel: Optional[Length] = None, resolution: int = 400, half_band: int = 3,
              min_shell_volume: float = 0.0, thicken: Optional[Length] = None, progress: Progress = None,
              context: Optional[Context] = None, threads: int = 0,
              max_memory: Optional[Size] = None) -> VolumeResult:
    """The robust signed distance field of a mesh (generalized winding number), whatever its defects."""

def hollow(mesh: Union[MeshLike, Volume], *, wall: Length = "3mm", closing: Length = "0mm",
           voxel: Optional[Length] = None, resolution: Optional[int] = None, adaptivity: float = 0.0,
           min_cavity: float = 0.0, infill: Optional[str] = None, cell: Optional[Length] = None,
           strut: Optional[Length] = None, output: Optional[Path] = None, report: Optional[Path] = None,
           progress: Progress = None, context: Optional[Context] = None, threads: int = 0,
           max_memory: Optional[Size] = None) -> Result:
    """Hollows a part: a wall of `wall` under the outer surface, the rest emptied (fabvdb hollow;
    docs/hollow.md). infill="gyroid" adds a strut lattice (cell, strut). A Volume input, or output ending
    in .vdb, returns a VolumeResult."""

def drain(mesh: MeshLike, *, wall: Length = "3mm", holes: Union[str, int] = "auto", hole_diameter: Length = "4mm",
          repose: Angle = "35deg", orientations: Union[str, Path, npt.ArrayLike] = "all", effort: float = 0.9,
          target: Union[str, float] = "1%", keep_out: Optional[Path] = None,
          heatmap: Union[None, bool, Path] = None, voxel: Optional[Length] = None, patches: int = 2000,
          output: Optional[Path] = None, report: Optional[Path] = None, progress: Progress = None,
          context: Optional[Context] = None, threads: int = 0, max_memory: Optional[Size] = None) -> DrainResult:
    """Places and drills drain holes so trapped powder escapes (fabvdb drain; docs/drain.md), with the
    cleaning routine and, with heatmap (True, or a .ply path that also receives the files), the
    drainability heat map of the cavity as arrays (None when the part has no cavity)."""

def powder_sim(mesh: MeshLike, *, holes_from: Union[Path, dict, list, DrainResult],
               orientations: Union[str, Path, npt.ArrayLike] = "all", turns: Optional[int] = None,
               seed: Optional[int] = None, repose: Angle = "35deg", voxel: Optional[Length] = None,
               routine: Union[None, Path, dict, list, DrainResult] = None, report: Optional[Path] = None,
               progress: Progress = None, context: Optional[Context] = None, threads: int = 0,
               max_memory: Optional[Size] = None) -> dict:
    """The reference sand-pile powder simulation through an operator's routine (fabvdb powder-sim)."""

def decompose(mesh: MeshLike, *, output: Optional[Path] = None, shell: Optional[Length] = None, solid: bool = False,
              gamma: float = 0.05, parts: Union[str, int] = "auto", max_parts: int = 16, draft: Angle = "1deg",
              low_res: int = 10000, smoothing: int = 10, smoothness: float = 1.0,
              edits: Union[None, Path, list, dict] = None, report: Optional[Path] = None,
              progress: Progress = None, context: Optional[Context] = None, threads: int = 0,
              max_memory: Optional[Size] = None) -> DecomposeResult:
    """Cuts an object into parts that each cast in a two-piece rigid mold (fabvdb decompose; thesis ch. 3)."""

def mold(mesh: MeshLike, *, output: Optional[Path] = None,
         decomposition: Union[None, Path, DecomposeResult, "Decomposition"] = None, common_mold: bool = False,
         mold_margin: Length = "10mm", voxel: Optional[Length] = None, grid_step: Optional[Length] = None,
         density: float = 1.1, shell: Optional[Length] = None, solid: bool = False, gamma: float = 0.05,
         parts: int = 0, low_res: int = 10000, report: Optional[Path] = None, progress: Progress = None,
         context: Optional[Context] = None, threads: int = 0, max_memory: Optional[Size] = None) -> MoldResult:
    """Cast-ready parts and two-piece molds with gate, runner, sprue, vents and keys (fabvdb mold)."""


class Decomposition:
    """A mold decomposition being edited, as the studio does it: four edits, re-runs, undo/redo."""
    context: Context
    progress: Progress
    def __init__(self, mesh: MeshLike, *, shell: Optional[Length] = None, solid: bool = False, gamma: float = 0.05,
                 parts: Union[str, int] = "auto", max_parts: int = 16, draft: Angle = "1deg", low_res: int = 10000,
                 smoothing: int = 10, smoothness: float = 1.0, progress: Progress = None,
                 context: Optional[Context] = None, threads: int = 0, max_memory: Optional[Size] = None) -> None: ...
    @classmethod
    def read(cls, mesh: MeshLike, path: Path, *, progress: Progress = None, context: Optional[Context] = None,
             threads: int = 0, max_memory: Optional[Size] = None) -> "Decomposition":
        """A session from a decomposition.json of this mesh (or its folder)."""
    def no_cut(self, points: npt.ArrayLike, radius: Length, *, progress: Progress = None) -> None:
        """The surface within radius of the points ends up in one part."""
    def cut(self, points: npt.ArrayLike, *, closed: bool = False, progress: Progress = None) -> None:
        """A cut through click-placed points (at least two)."""
    def merge(self, a: Sequence[float], b: Sequence[float], *, progress: Progress = None) -> None:
        """The neighbouring parts under points a and b become one."""
    def smooth(self, points: npt.ArrayLike, radius: Length, *, progress: Progress = None) -> None:
        """Part boundaries within radius of the points are smoothed."""
    def apply(self, edit: Union[dict, str], *, progress: Progress = None) -> None:
        """One edit as in the edits file."""
    def rerun(self, *, gamma: Optional[float] = None, parts: Union[None, str, int] = None,
              max_parts: Optional[int] = None, draft: Optional[Angle] = None, smoothing: Optional[int] = None,
              smoothness: Optional[float] = None, progress: Progress = None) -> None:
        """The automatic decomposition again with these options; one undoable step."""
    def undo(self) -> bool: ...
    def redo(self) -> bool: ...
    @property
    def info(self) -> dict: ...
    @property
    def options(self) -> dict: ...
    @property
    def part_count(self) -> int: ...
    @property
    def parts(self) -> list: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def triangles(self) -> npt.NDArray[np.uint32]: ...
    @property
    def surface(self) -> Mesh: ...
    @property
    def labels(self) -> npt.NDArray[np.int32]: ...
    @property
    def sides(self) -> npt.NDArray[np.uint8]: ...
    @property
    def deformation(self) -> npt.NDArray[np.float32]: ...
    def draft_map(self, direction: Sequence[float], draft: Angle = "1deg") -> npt.NDArray[np.uint8]: ...
    def parting_lines(self) -> list: ...
    def boundaries(self) -> list: ...
    def write(self, output: Path) -> None: ...
    def write_edits(self, path: Path) -> None: ...
