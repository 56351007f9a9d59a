"""The commands of the ``fabvdb`` tool as functions: inspect, repair,
to_volume, hollow, drain, powder_sim, decompose, mold, and reading meshes.

Each takes a mesh (a Mesh, a file path, or an object with ``vertices`` and
``faces`` arrays such as a trimesh) and keyword arguments named like the
command's options (``--hole-diameter`` is ``hole_diameter``; lengths in mm or
as "3mm", "2%" of the bounding-box diagonal), and returns its results with the
report as a dict. ``output=`` and ``report=`` write files as ``-o`` and
``--report`` do. Every call also takes ``progress`` (callable(stage, fraction),
a truthy return cancels), ``context`` (a Context, to cancel from another
thread), or ``threads`` and ``max_memory``. Ctrl-C cancels the call
(KeyboardInterrupt, nothing returned); failures raise fabvdb.Error's
subclasses with the library's message. The GIL is released while the library
works, so calls in several threads run at once.
"""
import json
import os
import re
import tempfile
from typing import NamedTuple, Optional

import numpy as np

from . import _fabvdb, _inputs, _units
from ._fabvdb import InvalidArgumentError, Mesh, Volume


class Result(NamedTuple):
    """A mesh a command made, and its report (a dict of every figure computed)."""
    mesh: Mesh
    report: Optional[dict]


class VolumeResult(NamedTuple):
    """A level set a command made, and its report."""
    volume: Volume
    report: Optional[dict]


class HeatMap(NamedTuple):
    """The drainability heat map of the cavity surface (what ``--heatmap`` writes), as arrays.

    surface: the cavity surface as a Mesh (facing the powder); drains: per
    vertex, the share of the powder resting there at the start that drains
    (0..1); left: per vertex, the powder left at the end (mm^3 per mm^2);
    colours: the viridis colours of ``drains`` as (n, 3) uint8; report: the
    drain report's ``heatmap`` entry (ranges, mean; with a .ply path, the files)."""
    surface: Mesh
    drains: np.ndarray
    left: np.ndarray
    colours: np.ndarray
    report: dict


class DrainResult(NamedTuple):
    """The drilled part, the report, its holes[] and routine[], and the heat map (or None)."""
    mesh: Mesh
    report: dict
    holes: list
    routine: list
    heatmap: Optional[HeatMap]


class DecomposeResult(NamedTuple):
    """The report, decomposition.json as a dict, and the folder it was written to (None: a temporary one, gone)."""
    report: dict
    decomposition: dict
    output: Optional[str]


class MoldResult(NamedTuple):
    """The cast-ready parts, the mold pieces as (top, bottom) pairs (one pair with common_mold), the report and
    the folder written (None: a temporary one, gone)."""
    parts: list
    molds: list
    report: dict
    output: Optional[str]


def _mesh(mesh, context, progress):
    if isinstance(mesh, Mesh):
        return mesh
    if isinstance(mesh, (str, os.PathLike)):
        return _fabvdb._read_mesh(context, os.fsdecode(mesh), progress)
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        return Mesh(np.asarray(mesh.vertices), np.asarray(mesh.faces))
    raise InvalidArgumentError("mesh must be a fabvdb.Mesh, a file path, or have vertices and faces arrays")


def _write_report(report, path):
    if path not in (None, True, False):
        target = _inputs.path_text(path, "report")
        temp = target + ".tmp"
        with open(temp, "w", encoding="utf-8") as file:
            json.dump(report, file, indent=2)
            file.write("\n")
        os.replace(temp, target)


def _is_level_set(path):
    return path is not None and os.fsdecode(path).lower().endswith(".vdb")


def read(path, *, scale=None, fit=None, progress=None, context=None, threads=0, max_memory=None):
    """Reads a mesh file (.stl .obj .ply .off .3mf; STL ASCII or binary sniffed).

    scale: multiply the coordinates by this first (a file in metres: 1000).
    fit: scale uniformly so the longest side is this length ("100mm").
    Raises FileError (missing, unreadable) or BadInputError (unknown
    extension, malformed content: the message names the file and the defect)."""
    context = _inputs.context_for(context, threads, max_memory)
    mesh = _fabvdb._read_mesh(context, _inputs.path_text(path, "path"), progress)
    if scale is not None and fit is not None:
        raise InvalidArgumentError("give scale or fit, not both")
    factor = 1.0
    if scale is not None:
        factor = float(scale)
        if not factor > 0:
            raise InvalidArgumentError("scale must be positive")
    if fit is not None:
        vertices = mesh.vertices
        longest = float((vertices.max(axis=0) - vertices.min(axis=0)).max()) if len(vertices) else 0.0
        target = _units.length(fit, "fit", _inputs.diagonal(mesh))
        if not (longest > 0 and target > 0):
            raise InvalidArgumentError("fit needs a positive length and a model that is not flat to a point")
        factor = target / longest
    return mesh if factor == 1.0 else _fabvdb._scale_mesh(context, mesh, factor)


def write(mesh, path, *, context=None):
    """Writes a mesh (.stl binary, .ply, .obj, .off, .3mf) atomically. A solid fabvdb made is checked first
    (closed, 2-manifold, no degenerate or crossing triangle as stored); else nothing is written (InternalError)."""
    _fabvdb._write_mesh(context or _fabvdb.Context(), mesh, _inputs.path_text(path, "path"))


def inspect(mesh, *, report=None, progress=None, context=None, threads=0, max_memory=None):
    """What a print-file checker reports (fabvdb info): counts, topology, defects, volume, as a dict.

    Keys (docs/info.md): vertices, triangles, components, closed, boundary_edges, boundary_loops,
    non_manifold_edges, non_manifold_vertices, degenerate_triangles, duplicate_triangles,
    self_intersecting_pairs, consistently_oriented, volume (None unless closed), genus, bbox {min, max}.
    Defects are data, never errors. report: also write it to this JSON file."""
    context = _inputs.context_for(context, threads, max_memory)
    result = _inputs.report(_fabvdb._inspect(context, _mesh(mesh, context, progress), progress))
    _write_report(result, report)
    return result


_AXES = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1)}


def check(mesh, *, process="sla", up="+z", build_volume=None, voxel=None, resolution=400, thickness_map=None,
          report=None, progress=None, context=None, threads=0, max_memory=None):
    """Will it print in this process as it is (fabvdb check): the verdict and every check, as a dict.

    process: "sla" (resin), "powder" (SLS, MJF, binder jetting), "fdm", or a JSON profile's path (docs/check.md).
    up: the build direction, "+x" ... "-z" or three numbers. build_volume: the printer's, three lengths or
    "250x210x220mm" (None: not checked). voxel: a length (default: the longest side / resolution, kept
    between the process' minimum wall / 4 and / 2). thickness_map: a .ply path that receives the surface coloured by
    local wall thickness, with its legend beside it. Keys (docs/check.md): verdict ("pass", "warn" or
    "fail"), process, voxel_size, checks {mesh, units, wall_thickness, small_features (pins, fins,
    small pieces), holes, trapped_volumes, cups, overhangs, build_volume}, each with status, message and
    figures in mm. A part that fails is a finding, never an error. report: also write it to this JSON file."""
    context = _inputs.context_for(context, threads, max_memory)
    handle = _mesh(mesh, context, progress)
    options = {"process": _inputs.path_text(process, "process"),
               "resolution": _units.count(resolution, "resolution", allow_auto=False)}
    direction = _AXES.get(up) if isinstance(up, str) else up
    if direction is None:
        raise InvalidArgumentError(f"up: expected one of {', '.join(_AXES)} or three numbers, got {up!r}")
    options["up"] = np.asarray(direction, dtype=float).reshape(1, 3)
    if build_volume is not None:
        if isinstance(build_volume, str):
            # "250x210x220mm": the unit after the last side holds for all three.
            match = re.fullmatch(r"\s*([0-9.]+)\s*x\s*([0-9.]+)\s*x\s*([0-9.]+)\s*([a-z]*)\s*", build_volume.lower())
            sides = [side + match.group(4) for side in match.groups()[:3]] if match else []
        else:
            sides = list(build_volume)
        if len(sides) != 3:
            raise InvalidArgumentError(f"build_volume: expected three lengths such as '250x210x220mm', "
                                       f"got {build_volume!r}")
        sizes = [_units.length(side, "build_volume", 0.0) for side in sides]
        if not all(size > 0 for size in sizes):
            raise InvalidArgumentError("build_volume: every side must be positive")
        options["build_volume"] = np.asarray(sizes, dtype=float).reshape(1, 3)
    if voxel is not None:
        options["voxel_size"] = _units.length(voxel, "voxel", _inputs.diagonal(handle))
        if not options["voxel_size"] > 0:
            raise InvalidArgumentError("voxel must be positive")
    if thickness_map is not None:
        options["thickness_map_path"] = _inputs.path_text(thickness_map, "thickness_map")
    result = _inputs.report(_fabvdb._check(context, handle, options, progress))
    _write_report(result, report)
    return result


def _volume_options(mesh, voxel, resolution, adaptivity, volumetric, no_snap, min_shell_volume, thicken):
    options = {"adaptivity": float(adaptivity), "min_shell_volume": float(min_shell_volume),
               "volumetric": bool(volumetric), "no_snap": bool(no_snap)}
    if resolution is not None:
        options["resolution"] = _units.count(resolution, "resolution", allow_auto=False)
    if voxel is not None:
        options["voxel_size"] = _units.length(voxel, "voxel", _inputs.diagonal(mesh))
        if not options["voxel_size"] > 0:
            raise InvalidArgumentError("voxel must be positive")
    if thicken is not None:
        options["thicken"] = _units.length(thicken, "thicken", _inputs.diagonal(mesh))
        if not options["thicken"] > 0:
            raise InvalidArgumentError("thicken must be positive")
    return options


def repair(mesh, *, voxel=None, resolution=400, adaptivity=0.0, volumetric=False, no_snap=False,
           min_shell_volume=0.0, thicken=None, output=None, report=True, progress=None, context=None, threads=0,
           max_memory=None):
    """Makes a clean watertight solid of a dirty mesh (fabvdb repair), changing no more than it must.

    A clean solid comes back as it is; exactly fixable defects (unwelded points, degenerate or duplicate
    triangles, flipped shells, small holes, crossing shells) are fixed at mesh level keeping the input's
    triangles; anything else (or volumetric=True, thicken, min_shell_volume) goes through a robust level set
    (generalized winding number), whose surface is closed, 2-manifold and free of self-intersections.

    voxel: voxel size ("0.2mm", "0.1%"); overrides resolution (voxels along the longest side, default 400).
    adaptivity: 0..1, fewer triangles on flat regions. no_snap: keep vertices where the voxels put them.
    min_shell_volume: drop shells under this many mm^3. thicken: an open sheet becomes a solid this thick.
    output: also write the mesh there; a path ending in .vdb makes and writes the level set instead and
    returns a VolumeResult. report: True (default) returns the report (path, fixes, input inspection,
    timings: docs/repair.md), False skips it (faster), a path also writes it there.
    Returns Result(mesh, report). Raises BadInputError for an input that encloses no volume (give thicken),
    OutOfBudgetError when the voxel size needs more memory than max_memory."""
    context = _inputs.context_for(context, threads, max_memory)
    mesh = _mesh(mesh, context, progress)
    options = _volume_options(mesh, voxel, resolution, adaptivity, volumetric, no_snap, min_shell_volume, thicken)
    if _is_level_set(output):
        volume, text = _fabvdb._volume_from_mesh(context, mesh, options, progress)
        _fabvdb._write_volume(context, volume, os.fsdecode(output))
        result = VolumeResult(volume, _inputs.report(text))
    else:
        repaired, text = _fabvdb._repair(context, mesh, options, report is not False, progress)
        if output is not None:
            _fabvdb._write_mesh(context, repaired, _inputs.path_text(output, "output"))
        result = Result(repaired, _inputs.report(text))
    _write_report(result.report, report)
    return result


def to_volume(mesh, *, voxel=None, resolution=400, half_band=3, min_shell_volume=0.0, thicken=None, progress=None,
              context=None, threads=0, max_memory=None):
    """The robust signed distance field of a mesh (negative inside), whatever its defects.

    voxel, resolution, min_shell_volume, thicken: as for repair(); half_band: voxels each side (>= 2).
    Returns VolumeResult(volume, report) (voxel_size, active_voxels, volume, shells_kept, timings...)."""
    context = _inputs.context_for(context, threads, max_memory)
    mesh = _mesh(mesh, context, progress)
    options = _volume_options(mesh, voxel, resolution, 0.0, False, False, min_shell_volume, thicken)
    options["half_band_voxels"] = _units.count(half_band, "half_band", allow_auto=False)
    volume, text = _fabvdb._volume_from_mesh(context, mesh, options, progress)
    return VolumeResult(volume, _inputs.report(text))


def _hollow_options(diagonal, wall, closing, voxel, resolution, adaptivity, min_cavity, infill, cell, strut):
    options = {"wall": _units.length(wall, "wall", diagonal), "closing": _units.length(closing, "closing", diagonal),
               "adaptivity": float(adaptivity), "min_cavity_volume": float(min_cavity)}
    if voxel is not None and resolution is not None:
        raise InvalidArgumentError("give voxel or resolution, not both")
    if voxel is not None:
        options["voxel_size"] = _units.length(voxel, "voxel", diagonal)
        if not options["voxel_size"] > 0:
            raise InvalidArgumentError("voxel must be > 0")
    if resolution is not None:
        options["resolution"] = _units.count(resolution, "resolution", allow_auto=False)
        if options["resolution"] < 1:
            raise InvalidArgumentError("resolution must be >= 1")
    if infill is not None:
        if infill != "gyroid":
            raise InvalidArgumentError(f"infill: unknown pattern {infill!r} (known: gyroid)")
        options["infill_cell"] = _units.length("10mm" if cell is None else cell, "cell", diagonal)
        options["infill_strut"] = _units.length("1.2mm" if strut is None else strut, "strut", diagonal)
    elif cell is not None or strut is not None:
        raise InvalidArgumentError("cell and strut need infill='gyroid'")
    return options


def hollow(mesh, *, wall="3mm", closing="0mm", voxel=None, resolution=None, adaptivity=0.0, min_cavity=0.0,
           infill=None, cell=None, strut=None, output=None, report=None, progress=None, context=None, threads=0,
           max_memory=None):
    """Hollows a part for printing (fabvdb hollow): keeps a wall under the outer surface, empties the rest.

    A dirty input goes through the robust signed distance first; a clean closed one keeps its own outer
    triangles. The cavity lies at exactly `wall` from the outer surface (closing 0) or at least at it.
    Regions thinner than 2*wall stay solid; a part that thin everywhere comes back solid (cavity_count 0, a
    warning). The result has the outer shells facing out and the cavity shells facing in, all closed.

    wall: wall thickness (default "3mm"). closing: offset the cavity by -(wall+closing) then +closing,
    rounding it. voxel / resolution: voxel size (default wall/4) or voxels along the longest side.
    adaptivity: 0..1 simplification of the cavity surface. min_cavity: fill voids under this many mm^3.
    infill="gyroid": an open-cell strut lattice in the cavity, cells of `cell` (default "10mm"), struts of
    diameter `strut` (default "1.2mm", at most cell/4).
    mesh may also be a Volume (its zero surface is the outer surface); the shell then comes back as a
    VolumeResult, as it does with output ending in .vdb.
    Returns Result(mesh, report) (volume_solid, volume_shell, material_saved_fraction, cavity_count,
    cavities, min_wall_at_vertices, timings, warnings: docs/hollow.md)."""
    context = _inputs.context_for(context, threads, max_memory)
    if isinstance(mesh, Volume):
        options = _hollow_options(0.0, wall, closing, voxel, resolution, adaptivity, min_cavity, infill, cell, strut)
        options.pop("voxel_size", None)
        options.pop("resolution", None)
        shell, text = _fabvdb._volume_hollow(context, mesh, options, progress)
        result = VolumeResult(shell, _inputs.report(text))
        if output is not None:
            _fabvdb._write_volume(context, shell, _inputs.path_text(output, "output"))
    else:
        mesh = _mesh(mesh, context, progress)
        options = _hollow_options(_inputs.diagonal(mesh), wall, closing, voxel, resolution, adaptivity, min_cavity,
                                  infill, cell, strut)
        if _is_level_set(output):
            shell, text = _fabvdb._hollow_volume(context, mesh, options, progress)
            _fabvdb._write_volume(context, shell, os.fsdecode(output))
            result = VolumeResult(shell, _inputs.report(text))
        else:
            hollowed, text = _fabvdb._hollow(context, mesh, options, progress)
            if output is not None:
                _fabvdb._write_mesh(context, hollowed, _inputs.path_text(output, "output"))
            result = Result(hollowed, _inputs.report(text))
    _write_report(result.report, report)
    return result


def drain(mesh, *, wall="3mm", holes="auto", hole_diameter="4mm", repose="35deg", orientations="all", effort=0.9,
          target="1%", keep_out=None, heatmap=None, voxel=None, patches=2000, output=None, report=None,
          progress=None, context=None, threads=0, max_memory=None):
    """Places and drills drain holes so trapped powder can escape (fabvdb drain, powder printing).

    A solid is hollowed first with `wall`; a hollow shell is used as is. The holes maximise the powder the
    drainability model drains as the operator turns the part; each cavity gets its own.
    holes: "auto" (at least 2 per cavity, more until the predicted residual under the cleaning routine is
    under `target`) or a count. hole_diameter: default "4mm". repose: the powder's angle of repose ("35deg").
    orientations: "all" (162 directions), a file of "x y z" lines, or a (k, 3) array of gravity directions.
    effort: chance the operator turns the part once more. keep_out: a JSON file of spheres or a closed mesh
    file where no hole may open. heatmap: True, or a .ply path (also written there, with HEAT_left.ply and
    PNG legends), to get the drainability heat map of the cavity as arrays (None when there is no cavity). voxel: level-set voxel (default wall/4).
    patches: cavity patches of the model.
    Returns DrainResult(mesh, report, holes, routine, heatmap): holes [{center, axis, diameter, cavity,
    depth}], routine [{gravity, hole_down, tilt_degrees, tilt_axis, instruction}], and in the report the
    predicted residual, the lowest-point baseline, timings and warnings (docs/drain.md)."""
    context = _inputs.context_for(context, threads, max_memory)
    mesh = _mesh(mesh, context, progress)
    diagonal = _inputs.diagonal(mesh)
    hole_count = _units.count(holes, "holes")
    if holes != "auto" and hole_count < 1:
        raise InvalidArgumentError("holes takes 'auto' or a count >= 1")
    options = {"wall": _units.length(wall, "wall", diagonal),
               "hole_count": hole_count,
               "hole_diameter": _units.length(hole_diameter, "hole_diameter", diagonal),
               "repose_degrees": _units.angle(repose, "repose"),
               "effort": float(effort),
               "target_residual": _units.share(target, "target"),
               "orientations": _inputs.orientations(orientations),
               "patch_count": _units.count(patches, "patches", allow_auto=False)}
    if voxel is not None:
        options["voxel_size"] = _units.length(voxel, "voxel", diagonal)
        if not options["voxel_size"] > 0:
            raise InvalidArgumentError("voxel must be positive (leave it out for wall / 4)")
    if keep_out is not None:
        options["keep_out_path"] = _inputs.path_text(keep_out, "keep_out")
    if heatmap not in (None, False, True):
        options["heatmap_path"] = _inputs.path_text(heatmap, "heatmap")
    drilled, text, heat_maps = _fabvdb._drain(context, mesh, options, heatmap not in (None, False), progress)
    result_report = _inputs.report(text)
    heat = None if heat_maps is None else HeatMap(*heat_maps, result_report.get("heatmap", {}))
    if output is not None:
        _fabvdb._write_mesh(context, drilled, _inputs.path_text(output, "output"))
    _write_report(result_report, report)
    return DrainResult(drilled, result_report, result_report.get("holes", []), result_report.get("routine", []),
                       heat)


def powder_sim(mesh, *, holes_from, orientations="all", turns=None, seed=None, repose="35deg", voxel=None, routine=None,
               report=None, progress=None, context=None, threads=0, max_memory=None):
    """The reference powder simulation (fabvdb powder-sim), independent of drain()'s model.

    Fills the cavity of a hollow part with powder, opens the holes, and runs sand-pile rules through an
    operator's routine: first as printed (-z down), then turns-1 (default 10 turns) turns drawn with `seed`
    (default 1) from `orientations`, or exactly `routine` (a drain report's routine[], a DrainResult, or a
    list of gravities). holes_from: a drain report (path, dict or DrainResult) or a list of
    {center, axis, diameter, depth}. voxel: sand-pile cell (default diagonal/150, at most a quarter hole).
    Returns the report as a dict: initial_volume, residual_volume, residual_fraction,
    residual_volume_after_turn, routine, voxel_size, timings (docs/powder-sim.md)."""
    context = _inputs.context_for(context, threads, max_memory)
    mesh = _mesh(mesh, context, progress)
    options = {"repose_degrees": _units.angle(repose, "repose"), "orientations": _inputs.orientations(orientations)}
    if routine is not None:
        if turns is not None or seed is not None:
            raise InvalidArgumentError("routine replays its own turns: turns and seed do not apply")
        options["routine_json"] = _inputs.json_text(routine, "routine")
    else:
        options["turns"] = _units.count(10 if turns is None else turns, "turns", allow_auto=False)
        seed = _units.count(1 if seed is None else seed, "seed", allow_auto=False)
        if seed < 0:
            raise InvalidArgumentError("seed must be >= 0")
        options["seed"] = seed
    if voxel is not None:
        options["voxel_size"] = _units.length(voxel, "voxel", _inputs.diagonal(mesh))
        if not options["voxel_size"] > 0:
            raise InvalidArgumentError("voxel must be a positive length")
    holes_json = _inputs.json_text(holes_from, "holes", wrap_list="holes")
    result = _inputs.report(_fabvdb._powder_simulate(context, mesh, holes_json, options, progress))
    _write_report(result, report)
    return result


def decompose_options(mesh, shell, solid, gamma, parts, max_parts, draft, low_res, smoothing, smoothness):
    """The decomposition's options (C field names) from the CLI's names and units."""
    options = {"solid": bool(solid), "gamma": float(gamma), "parts": _units.count(parts, "parts"),
               "draft_degrees": _units.angle(draft, "draft")}
    if parts not in (None, "auto") and not 1 <= options["parts"] <= 1000:
        raise InvalidArgumentError("parts must be auto or a whole number from 1 to 1000")
    if max_parts is not None:
        options["max_parts"] = _units.count(max_parts, "max_parts", allow_auto=False)
    if low_res is not None:
        options["low_res_triangles"] = _units.count(low_res, "low_res", allow_auto=False)
    if smoothing is not None:
        options["smoothing_iterations"] = _units.count(smoothing, "smoothing", allow_auto=False)
    if smoothness is not None:
        options["w_smooth"] = float(smoothness)
    if shell is not None:
        options["shell_thickness"] = _units.length(shell, "shell", _inputs.diagonal(mesh))
        if not options["shell_thickness"] > 0:
            raise InvalidArgumentError("shell must be positive")
    return options


def _edits_file(edits, folder):
    if edits is None:
        return None
    if isinstance(edits, (str, os.PathLike)):
        return os.fsdecode(edits)
    path = os.path.join(folder, "edits.json")
    with open(path, "w", encoding="utf-8") as file:
        json.dump(edits if isinstance(edits, dict) else {"edits": list(edits)}, file)
    return path


def decompose(mesh, *, output=None, shell=None, solid=False, gamma=0.05, parts="auto", max_parts=16, draft="1deg",
              low_res=10000, smoothing=10, smoothness=1.0, edits=None, report=None, progress=None, context=None,
              threads=0, max_memory=None):
    """Cuts a free-form object into parts that each cast in a two-piece rigid mold (fabvdb decompose).

    The thin shell (thickness `shell`, default 0.03 x the longest side; thin features stay solid; solid=True
    for solid parts) is decomposed by the thesis' method: region growing over 162 parting directions, parts
    added from 2 until the total moldability energy is under `gamma`, graph-cut parting lines, snake
    smoothing (`smoothing` iterations, weight `smoothness`). parts: "auto" or a count; max_parts caps auto.
    draft: draft angle ("1deg"). low_res: triangles of the surface the decomposition runs on.
    edits: a JSON file, a list of edits ({"type": "no_cut"|"cut"|"merge"|"smooth", "points": [[x,y,z],...],
    "radius": r, "closed": bool}) or {"edits": [...]}, applied in order.
    output: the folder for decomposition.json, decomposition.ply, deformation.ply (None: a temporary one).
    For interactive editing use the Decomposition class.
    Returns DecomposeResult(report, decomposition, output) (report keys: docs/decompose.md)."""
    context = _inputs.context_for(context, threads, max_memory)
    mesh = _mesh(mesh, context, progress)
    options = decompose_options(mesh, shell, solid, gamma, parts, max_parts, draft, low_res, smoothing, smoothness)
    with tempfile.TemporaryDirectory(prefix="fabvdb-decompose-") as temp:
        folder = _inputs.path_text(output, "output") if output is not None else os.path.join(temp, "out")
        text = _fabvdb._decompose(context, mesh, options, _edits_file(edits, temp), folder, progress)
        with open(os.path.join(folder, "decomposition.json"), encoding="utf-8") as file:
            document = json.load(file)
    result = DecomposeResult(_inputs.report(text), document, None if output is None else folder)
    _write_report(result.report, report)
    return result


def _read_part_file(context, folder, name):
    path = name if os.path.isabs(name) else os.path.join(folder, name)
    return _fabvdb._read_mesh(context, path, None)


def mold(mesh, *, output=None, decomposition=None, common_mold=False, mold_margin="10mm", voxel=None,
         grid_step=None, density=1.1, shell=None, solid=False, gamma=0.05, parts=0, low_res=10000, report=None,
         progress=None, context=None, threads=0, max_memory=None):
    """Makes cast-ready parts and two-piece rigid molds from a decomposition (fabvdb mold).

    decomposition: a decomposition.json path, a DecomposeResult written to a folder, or a Decomposition
    session; None decomposes first with shell, solid, gamma, parts (0: automatic) and low_res.
    Each part's surface is restored from the input, swept into a double height field along its parting
    direction, and put in a block of `mold_margin` split by a smooth parting surface, with gate, runner,
    sprue, vents and registration keys. common_mold: one pair for all parts in a row. voxel: level-set voxel
    (default diagonal/250). grid_step: parting-surface grid (default margin/8). density: g/cm^3 for weights.
    output: the folder for parts/ and molds/ (None: a temporary one).
    Returns MoldResult(parts, molds, report, output): parts as Meshes, molds as (top, bottom) Mesh pairs."""
    context = _inputs.context_for(context, threads, max_memory)
    mesh = _mesh(mesh, context, progress)
    diagonal = _inputs.diagonal(mesh)
    options = {"common": bool(common_mold), "margin": _units.length(mold_margin, "mold_margin", diagonal),
               "density": float(density)}
    if voxel is not None:
        options["voxel_size"] = _units.length(voxel, "voxel", diagonal)
    if grid_step is not None:
        options["grid_step"] = _units.length(grid_step, "grid_step", diagonal)
    for name in ("margin", "voxel_size", "grid_step"):
        if name in options and not options[name] > 0:
            raise InvalidArgumentError("mold_margin, voxel, grid_step and shell must be positive")
    decompose = {}
    if decomposition is not None:
        if shell is not None or solid or gamma != 0.05 or parts != 0 or low_res != 10000:
            raise InvalidArgumentError("shell, solid, gamma, parts and low_res set up a decomposition; they do "
                                       "not go with decomposition=")
    else:
        decompose = decompose_options(mesh, shell, solid, gamma, parts or "auto", None, "1deg", low_res, None, None)
    with tempfile.TemporaryDirectory(prefix="fabvdb-mold-") as temp:
        path = None
        if decomposition is not None:
            if isinstance(decomposition, DecomposeResult):
                if decomposition.output is None:
                    raise InvalidArgumentError("this DecomposeResult's folder is gone: decompose with output=")
                path = os.path.join(decomposition.output, "decomposition.json")
            elif hasattr(decomposition, "write") and hasattr(decomposition, "undo"):
                decomposition.write(os.path.join(temp, "decomposition"))
                path = os.path.join(temp, "decomposition", "decomposition.json")
            else:
                path = _inputs.path_text(decomposition, "decomposition")
        folder = _inputs.path_text(output, "output") if output is not None else os.path.join(temp, "out")
        text = _fabvdb._mold(context, mesh, path, decompose, options, folder, progress)
        result_report = _inputs.report(text)
        part_meshes = [_read_part_file(context, folder, p["file"]) for p in result_report.get("parts", [])]
        if common_mold:
            common = result_report["common_mold"]
            molds = [(_read_part_file(context, folder, common["top_file"]),
                      _read_part_file(context, folder, common["bottom_file"]))]
        else:
            molds = [(_read_part_file(context, folder, p["top_file"]), _read_part_file(context, folder, p["bottom_file"]))
                     for p in result_report.get("parts", [])]
    _write_report(result_report, report)
    return MoldResult(part_meshes, molds, result_report, None if output is None else folder)
