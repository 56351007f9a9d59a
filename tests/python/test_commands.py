"""Every command as a function, on small shapes, checked by measurement
(volumes, closedness, distances computed here with numpy), not by the report."""
import json
import os

import numpy as np
import pytest

import fabvdb
from conftest import box_arrays, components, is_closed, signed_volume


def test_inspect_box(box, tmp_path):
    report = fabvdb.inspect(box, report=tmp_path / "r.json")
    assert report["closed"] and report["triangles"] == 12 and report["boundary_edges"] == 0
    assert report["volume"] == pytest.approx(signed_volume(box))
    assert json.loads((tmp_path / "r.json").read_text())["triangles"] == 12


def test_inspect_finds_a_hole(box):
    v, t = box_arrays()
    open_box = fabvdb.Mesh(v, t[2:])
    report = fabvdb.inspect(open_box)
    assert not is_closed(open_box)
    assert not report["closed"] and report["boundary_loops"] == 1 and report["volume"] is None


def test_check_finds_a_plate_too_thin_for_resin(tmp_path):
    # A plate 0.3 mm thick, under resin's 0.5 mm minimum wall; a 20 mm
    # block is nowhere thin. The figures come from the shapes' sides.
    v, t = box_arrays(1.0)
    plate = fabvdb.Mesh(v * np.array([30.0, 30.0, 0.3]), t)
    report = fabvdb.check(plate, process="sla", report=tmp_path / "r.json")
    wall = report["checks"]["wall_thickness"]
    assert report["verdict"] == "fail" and wall["status"] == "fail"
    assert json.loads((tmp_path / "r.json").read_text())["verdict"] == "fail"
    block = fabvdb.check(fabvdb.Mesh(v * 20.0, t), process="sla", build_volume="25x25x25mm")
    assert block["checks"]["wall_thickness"]["status"] == "pass"
    assert block["checks"]["build_volume"]["status"] == "pass"
    small = fabvdb.check(fabvdb.Mesh(v * 20.0, t), process="sla", build_volume=(10, 10, "1cm"))
    assert small["checks"]["build_volume"]["status"] == "fail"


def test_check_refuses_bad_options():
    v, t = box_arrays(20.0)
    block = fabvdb.Mesh(v, t)
    with pytest.raises(fabvdb.InvalidArgumentError):
        fabvdb.check(block, up="sideways")
    with pytest.raises(fabvdb.InvalidArgumentError):
        fabvdb.check(block, build_volume="250x210")
    with pytest.raises(fabvdb.Error):
        fabvdb.check(block, process="no-such-process")


def test_repair_closes_a_hole():
    v, t = box_arrays()
    mesh, report = fabvdb.repair(fabvdb.Mesh(v, t[2:]), resolution=60)
    assert is_closed(mesh)
    assert signed_volume(mesh) == pytest.approx(40.0 ** 3, rel=0.03)
    assert report["path"] in ("mesh", "mixed", "volumetric")


def test_repair_of_a_clean_solid_keeps_it(box):
    mesh, report = fabvdb.repair(box, report=False)
    assert report is None
    np.testing.assert_array_equal(np.sort(mesh.vertices, axis=0), np.sort(box.vertices, axis=0))


def test_repair_volumetric_with_units(sphere):
    mesh, report = fabvdb.repair(sphere, volumetric=True, voxel="1%")
    diagonal = np.linalg.norm(sphere.vertices.max(0) - sphere.vertices.min(0))
    assert report["voxel_size"] == pytest.approx(0.01 * diagonal)
    assert is_closed(mesh)
    radius = np.linalg.norm(mesh.vertices, axis=1)
    assert np.all(np.abs(radius - 20.0) < 2 * report["voxel_size"])


def test_repair_to_a_level_set(sphere, tmp_path):
    result = fabvdb.repair(sphere, output=tmp_path / "s.vdb", resolution=50)
    assert isinstance(result, fabvdb.VolumeResult)
    volume = fabvdb.Volume.read(tmp_path / "s.vdb")
    assert volume.voxel_size == pytest.approx(result.volume.voxel_size)
    surface = volume.to_mesh()
    assert is_closed(surface)
    assert signed_volume(surface) == pytest.approx(signed_volume(sphere), rel=0.03)


def test_hollow_box_wall_thickness(box, tmp_path):
    shell, report = fabvdb.hollow(box, wall="4mm", output=tmp_path / "h.stl")
    assert is_closed(shell) and components(shell) == 2
    # The cavity is the box inset by the wall: 40^3 - 32^3 of material.
    assert signed_volume(shell) == pytest.approx(40.0 ** 3 - 32.0 ** 3, rel=0.02)
    cavity = shell.vertices[np.all((shell.vertices > 1) & (shell.vertices < 39), axis=1)]
    assert len(cavity) > 0
    distance_to_outside = np.minimum(cavity, 40.0 - cavity).min(axis=1)
    assert np.allclose(distance_to_outside, 4.0, atol=0.05)
    assert os.path.getsize(tmp_path / "h.stl") > 0


def test_hollow_accepts_units(box):
    a, _ = fabvdb.hollow(box, wall=4)
    b, _ = fabvdb.hollow(box, wall="0.4cm")
    np.testing.assert_array_equal(a.vertices, b.vertices)
    inches, _ = fabvdb.hollow(box, wall="0.15748in")  # 3.99999 mm
    percent, _ = fabvdb.hollow(box, wall=f"{400.0 / (40.0 * np.sqrt(3.0))}%")  # of the diagonal
    for other in (inches, percent):
        assert signed_volume(other) == pytest.approx(signed_volume(a), rel=0.01)


def test_hollow_too_thin_stays_solid(box):
    shell, report = fabvdb.hollow(box, wall=25)
    assert components(shell) == 1
    assert signed_volume(shell) == pytest.approx(40.0 ** 3)


def test_hollow_bad_parameters():
    v, t = box_arrays()
    with pytest.raises(fabvdb.InvalidArgumentError):
        fabvdb.hollow(fabvdb.Mesh(v, t), wall=-1)
    with pytest.raises(fabvdb.InvalidArgumentError, match="unknown unit"):
        fabvdb.hollow(fabvdb.Mesh(v, t), wall="3 furlongs")
    with pytest.raises(fabvdb.InvalidArgumentError, match="cell and strut need"):
        fabvdb.hollow(fabvdb.Mesh(v, t), cell="5mm")
    with pytest.raises(TypeError):
        fabvdb.hollow(fabvdb.Mesh(v, t), thickness="3mm")  # not an option: Python says so


def test_hollow_volume_in_and_out(sphere):
    solid, _ = fabvdb.to_volume(sphere, resolution=60)
    shell, report = fabvdb.hollow(solid, wall="5mm")
    assert isinstance(shell, fabvdb.Volume)
    surface = shell.to_mesh()
    assert is_closed(surface) and components(surface) == 2
    expected = 4.0 / 3.0 * np.pi * (20.0 ** 3 - 15.0 ** 3)
    assert signed_volume(surface) == pytest.approx(expected, rel=0.05)


@pytest.fixture(scope="module")
def drained(sphere):
    return fabvdb.drain(sphere, wall="3mm", holes=2, patches=300, heatmap=True)


def test_drain_drills_holes_through_the_wall(drained):
    mesh, report, holes, routine, heat = drained
    assert len(holes) == 2 and len(routine) >= 1
    assert is_closed(mesh)
    # The holes join cavity and outside: one shell, less material than the undrilled shell.
    assert components(mesh) == 1
    shell = 4.0 / 3.0 * np.pi * (20.0 ** 3 - 17.0 ** 3)
    assert signed_volume(mesh) < shell
    assert signed_volume(mesh) == pytest.approx(shell, rel=0.05)
    for hole in holes:
        assert np.linalg.norm(hole["center"]) == pytest.approx(18.5, abs=2.0)


def test_drain_heatmap_per_vertex(drained):
    heat = drained.heatmap
    assert heat is not None
    n = heat.surface.vertex_count
    assert heat.drains.shape == (n,) and heat.left.shape == (n,) and heat.colours.shape == (n, 3)
    assert heat.colours.dtype == np.uint8
    assert np.all((heat.drains >= 0) & (heat.drains <= 1)) and np.all(heat.left >= 0)
    # The cavity surface lies at the wall's depth and faces the powder (inward: a negative volume).
    radius = np.linalg.norm(heat.surface.vertices, axis=1)
    assert np.all(np.abs(radius - 17.0) < 1.0)
    assert is_closed(heat.surface)
    assert signed_volume(heat.surface) == pytest.approx(-4.0 / 3.0 * np.pi * 17.0 ** 3, rel=0.05)
    assert heat.report["drained_share"]["max"] == 1.0 and "path" not in heat.report["drained_share"]
    assert heat.report["powder_left"]["max"] == pytest.approx(max(heat.left.max(), 0) or 1.0)


def box_surface_distance(points, lo, hi):
    """Distance of each point to the surface of the box [lo, hi]^3."""
    below, above = lo - points, points - hi
    outside = np.linalg.norm(np.maximum(np.maximum(below, above), 0.0), axis=1)
    inside = np.min(np.minimum(-below, -above), axis=1)
    return np.where(outside > 0, outside, inside)


def test_drain_heatmap_on_a_box_cavity(box, tmp_path):
    # A 40 mm box with a 3 mm wall: the cavity is the box [3, 37]^3, the voxel wall / 4 = 0.75 mm.
    path = tmp_path / "heat.ply"
    result = fabvdb.drain(box, wall="3mm", holes=2, patches=300, heatmap=path)
    heat = result.heatmap
    assert np.max(box_surface_distance(np.asarray(heat.surface.vertices), 3.0, 37.0)) < 0.75
    assert signed_volume(heat.surface) == pytest.approx(-34.0 ** 3, rel=0.05)
    assert np.all((heat.drains >= 0) & (heat.drains <= 1)) and np.all(heat.left >= 0)
    # A path also writes the files, and the report names them.
    assert set(os.listdir(tmp_path)) == {"heat.ply", "heat.png", "heat_left.ply", "heat_left.png"}
    assert heat.report["drained_share"]["path"] == str(path)


def test_drain_heatmap_of_no_cavity(tmp_path):
    # A plate thinner than two walls stays solid: no holes, no heat map, no temporary files.
    v, t = box_arrays(1.0)
    plate = fabvdb.Mesh(v * np.array([40.0, 40.0, 4.0]), t)
    result = fabvdb.drain(plate, wall="3mm", heatmap=True)
    assert result.heatmap is None and result.holes == []


def test_powder_sim_from_a_drain_result(drained):
    report = fabvdb.powder_sim(drained.mesh, holes_from=drained, routine=drained, voxel="1mm")
    assert 0.0 <= report["residual_fraction"] <= 1.0
    cavity = 4.0 / 3.0 * np.pi * 17.0 ** 3
    assert report["initial_volume"] == pytest.approx(cavity, rel=0.1)
    with pytest.raises(fabvdb.InvalidArgumentError, match="routine replays"):
        fabvdb.powder_sim(drained.mesh, holes_from=drained, routine=drained, turns=3)


def test_powder_sim_bad_holes(drained):
    with pytest.raises(fabvdb.BadInputError):
        fabvdb.powder_sim(drained.mesh, holes_from={"nothing": []})


DECOMPOSE = dict(shell="3mm", parts=2, low_res=1500)


def test_decompose_parts(sphere, tmp_path):
    result = fabvdb.decompose(sphere, output=tmp_path / "d", **DECOMPOSE)
    assert result.report["part_count"] == 2
    assert os.path.exists(tmp_path / "d" / "decomposition.json")
    assert isinstance(result.decomposition, dict)


def test_mold_parts_and_pieces(sphere, tmp_path):
    decomposed = fabvdb.decompose(sphere, output=tmp_path / "d", **DECOMPOSE)
    result = fabvdb.mold(sphere, decomposition=decomposed, mold_margin="6mm", voxel="0.8mm")
    assert len(result.parts) == 2 and len(result.molds) == 2
    total = 0.0
    for part in result.parts:
        assert is_closed(part)
        total += signed_volume(part)
    # The parts are the 3 mm shell of the sphere (swept, so a little more).
    shell = 4.0 / 3.0 * np.pi * (20.0 ** 3 - 17.0 ** 3)
    assert shell * 0.9 < total < shell * 1.6
    for top, bottom in result.molds:
        assert is_closed(top) and is_closed(bottom)
        assert signed_volume(top) > 0 and signed_volume(bottom) > 0
    assert result.output is None
