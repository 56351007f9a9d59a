"""The Decomposition class: a mold decomposition being edited, as the studio
does it (thesis section 3.5), from a script or Blender.

Made once from a mesh (pre-computation, automatic decomposition, smoothing)
or read from a decomposition.json, then changed one step at a time: the four
edits in world coordinates (no_cut, cut, merge, smooth), re-runs with another
gamma, part count or draft, undo and redo. Every step is atomic: it succeeds
whole or leaves the session as it was. Arrays come back as copies. A session
is used by one thread at a time; long steps release the GIL.
"""
import json
import os

import numpy as np

from . import _commands, _fabvdb, _inputs, _units
from ._fabvdb import InvalidArgumentError, NotFoundError

PARTING = 0
BOUNDARY = 1
DRAFT_CLASSES = ("positive", "negative", "needed", "undercut")


class Decomposition:
    """A mold decomposition being edited (fabvdb studio's session).

    Decomposition(mesh, shell=None, solid=False, gamma=0.05, parts="auto", max_parts=16, draft="1deg",
    low_res=10000, smoothing=10, smoothness=1.0, progress=None, context=None) runs the automatic
    decomposition (options as fabvdb.decompose()); Decomposition.read(mesh, path) opens a decomposition.json.
    progress given here is used by every later step unless a step is given its own."""

    def __init__(self, mesh, *, shell=None, solid=False, gamma=0.05, parts="auto", max_parts=16, draft="1deg",
                 low_res=10000, smoothing=10, smoothness=1.0, progress=None, context=None, threads=0,
                 max_memory=None, _session=None):
        self.context = _inputs.context_for(context, threads, max_memory)
        self.progress = progress
        if _session is not None:
            self._session = _session
            return
        mesh = _commands._mesh(mesh, self.context, progress)
        options = _commands.decompose_options(mesh, shell, solid, gamma, parts, max_parts, draft, low_res, smoothing,
                                              smoothness)
        self._session = _fabvdb._Decomposition(self.context, mesh, options, progress)

    @classmethod
    def read(cls, mesh, path, *, progress=None, context=None, threads=0, max_memory=None):
        """A session from a decomposition.json (of this mesh at this scale) or the folder holding it."""
        context = _inputs.context_for(context, threads, max_memory)
        path = _inputs.path_text(path, "path")
        if os.path.isdir(path):
            path = os.path.join(path, "decomposition.json")
        mesh = _commands._mesh(mesh, context, progress)
        session = _fabvdb._Decomposition.read(context, mesh, path, progress)
        return cls(None, context=context, progress=progress, _session=session)

    def _progress(self, progress):
        return self.progress if progress is None else progress

    # --- edits -------------------------------------------------------------
    def no_cut(self, points, radius, *, progress=None):
        """A brush stroke: the surface within `radius` (mm or "3mm") of the points ends up in one part."""
        self._session.apply(0, _points(points), _units.length(radius, "radius", 0.0), False, self._progress(progress))

    def cut(self, points, *, closed=False, progress=None):
        """A cut through click-placed points (at least two; closed joins the last to the first)."""
        self._session.apply(1, _points(points), 0.0, bool(closed), self._progress(progress))

    def merge(self, a, b, *, progress=None):
        """The (neighbouring) parts under points a and b become one."""
        self._session.apply(2, _points([a, b]), 0.0, False, self._progress(progress))

    def smooth(self, points, radius, *, progress=None):
        """A brush stroke: part boundaries within `radius` of the points are smoothed (snakes)."""
        self._session.apply(3, _points(points), _units.length(radius, "radius", 0.0), False, self._progress(progress))

    def apply(self, edit, *, progress=None):
        """One edit as a dict or JSON text, as in the edits file: {"type": "cut", "points": [...], ...}."""
        text = edit if isinstance(edit, str) else json.dumps(edit)
        self._session.apply_json(text, self._progress(progress))

    def rerun(self, *, gamma=None, parts=None, max_parts=None, draft=None, smoothing=None, smoothness=None,
              progress=None):
        """Runs the automatic decomposition again with the options given (the others stay); one undoable step."""
        options = self._session.options()
        keep = {key: options[key] for key in ("gamma", "parts", "max_parts", "draft_degrees", "w_overhang",
                                              "w_overlap", "w_coarse_overlap", "smoothing_iterations", "w_smooth")}
        if gamma is not None:
            keep["gamma"] = float(gamma)
        if parts is not None:
            keep["parts"] = _units.count(parts, "parts")
        if max_parts is not None:
            keep["max_parts"] = _units.count(max_parts, "max_parts", allow_auto=False)
        if draft is not None:
            keep["draft_degrees"] = _units.angle(draft, "draft")
        if smoothing is not None:
            keep["smoothing_iterations"] = _units.count(smoothing, "smoothing", allow_auto=False)
        if smoothness is not None:
            keep["w_smooth"] = float(smoothness)
        self._session.rerun(keep, self._progress(progress))

    def undo(self):
        """Steps back; False (and nothing changes) when there is no step to undo."""
        try:
            self._session.undo()
            return True
        except NotFoundError:
            return False

    def redo(self):
        """Steps forward again; False when nothing was undone."""
        try:
            self._session.redo()
            return True
        except NotFoundError:
            return False

    # --- the current step --------------------------------------------------
    @property
    def info(self):
        """part_count, total_energy, gamma, over_gamma, draft_degrees, undo_steps, redo_steps, edit_count,
        last_step_seconds."""
        return self._session.info()

    @property
    def options(self):
        """The options of the current step (C field names: gamma, parts, draft_degrees, ...)."""
        return self._session.options()

    @property
    def part_count(self):
        return self._session.info()["part_count"]

    @property
    def parts(self):
        """Per part: direction (unit parting direction), energy, overhang_energy, overlap_energy, area (mm^2),
        triangle_count."""
        return [self._session.part(i) for i in range(self.part_count)]

    @property
    def vertices(self):
        """S_low's (n, 3) positions (mm); smoothing moves them."""
        return self._session.vertices()

    @property
    def triangles(self):
        """S_low's (m, 3) triangles (uint32); they never change within a session."""
        return self._session.triangles()

    @property
    def surface(self):
        """S_low as a Mesh."""
        return _fabvdb.Mesh(self._session.vertices(), self._session.triangles())

    @property
    def labels(self):
        """Per S_low triangle, its part (int32)."""
        return self._session.labels()

    @property
    def sides(self):
        """Per S_low triangle, 1 if in M+ (the half pulled along +d of its part), else 0 (uint8)."""
        return self._session.sides()

    @property
    def deformation(self):
        """Per S_low triangle, the estimated deformation (the thesis' heat map, float32 >= 0)."""
        return self._session.deformation()

    def draft_map(self, direction, draft="1deg"):
        """Per S_low triangle, its class for pulling along `direction`: 0 positive, 1 negative, 2 needs draft,
        3 undercut (names in DRAFT_CLASSES)."""
        d = np.asarray(direction, dtype=np.float64).reshape(3)
        return self._session.draft_map(float(d[0]), float(d[1]), float(d[2]), _units.angle(draft, "draft"))

    def parting_lines(self):
        """The parting lines: a list of (part, (k, 3) points); a closed loop repeats its first point."""
        return _lines(self._session.lines(PARTING))

    def boundaries(self):
        """The boundaries between parts (each seen from both parts): a list of (part, (k, 3) points)."""
        return _lines(self._session.lines(BOUNDARY))

    def write(self, output):
        """Writes decomposition.json, decomposition.ply, deformation.ply into the folder (atomically)."""
        self._session.write(_inputs.path_text(output, "output"))

    def write_edits(self, path):
        """Writes the edits since the last automatic decomposition as an edits file (decompose(edits=))."""
        self._session.write_edits(_inputs.path_text(path, "path"))

    def __repr__(self):
        info = self.info
        return (f"<fabvdb.Decomposition: {info['part_count']} parts, energy {info['total_energy']:.5f} "
                f"(gamma {info['gamma']}), {info['edit_count']} edits>")


def _points(points):
    array = np.asarray(points, dtype=np.float64)
    if array.ndim == 1 and array.size == 3:
        array = array.reshape(1, 3)
    if array.ndim != 2 or array.shape[1] != 3:
        raise InvalidArgumentError("points must be an (k, 3) array of positions (mm)")
    return array


def _lines(triple):
    points, starts, parts = triple
    return [(int(parts[i]), points[starts[i]:starts[i + 1]]) for i in range(len(parts))]
