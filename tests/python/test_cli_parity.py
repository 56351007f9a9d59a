"""The same command from Python and from the `fabvdb` tool on the same input
gives the same output file, byte for byte, and the same figures."""
import json
import os
import subprocess

import numpy as np
import pytest

import fabvdb
from conftest import CLI, SOURCE, signed_volume

pytestmark = pytest.mark.skipif(not CLI or not os.path.exists(CLI), reason="FABVDB_CLI (the fabvdb tool) not given")


def cli(*args):
    subprocess.run([CLI, *map(str, args), "--quiet"], check=True, stdout=subprocess.DEVNULL)


@pytest.fixture(scope="module")
def spot():
    return os.path.join(SOURCE, "data", "spot.obj")


def same_bytes(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def test_repair(tmp_path, spot):
    cli("repair", spot, "-o", tmp_path / "cli.stl", "--volumetric", "--resolution", 80)
    fabvdb.repair(spot, volumetric=True, resolution=80, output=tmp_path / "py.stl")
    assert same_bytes(tmp_path / "cli.stl", tmp_path / "py.stl")


def test_hollow(tmp_path, spot):
    cli("hollow", spot, "-o", tmp_path / "cli.stl", "--wall", "2%", "--report", tmp_path / "cli.json")
    _, report = fabvdb.hollow(spot, wall="2%", output=tmp_path / "py.stl")
    assert same_bytes(tmp_path / "cli.stl", tmp_path / "py.stl")
    expected = json.loads((tmp_path / "cli.json").read_text())
    for key in ("volume_solid", "volume_shell", "cavity_count", "voxel_size", "wall"):
        assert report[key] == expected[key]


def test_inspect(tmp_path, spot):
    cli("info", spot, "--report", tmp_path / "cli.json")
    expected = json.loads((tmp_path / "cli.json").read_text())
    report = fabvdb.inspect(spot)
    del report["timings"], expected["timings"]
    assert report == expected


def test_drain(tmp_path, sphere_path):
    cli("drain", sphere_path, "--scale", 20, "-o", tmp_path / "cli.stl", "--holes", 2, "--patches", 300,
        "--report", tmp_path / "cli.json")
    result = fabvdb.drain(fabvdb.read(sphere_path, scale=20), holes=2, patches=300, output=tmp_path / "py.stl")
    assert same_bytes(tmp_path / "cli.stl", tmp_path / "py.stl")
    expected = json.loads((tmp_path / "cli.json").read_text())
    assert result.holes == expected["holes"]
    assert result.report["predicted_residual_fraction"] == expected["predicted_residual_fraction"]


def read_heat_ply(path):
    """(positions, colours, values, faces) of a heat-map PLY as `fabvdb drain --heatmap` writes it."""
    data = path.read_bytes()
    body = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:body].decode("ascii").splitlines()
    count = {line.split()[1]: int(line.split()[2]) for line in header if line.startswith("element")}
    vertex = np.dtype([("p", "<f4", (3,)), ("rgb", "u1", (3,)), ("q", "<f4")])
    face = np.dtype([("n", "u1"), ("i", "<i4", (3,))])
    vertices = np.frombuffer(data, vertex, count["vertex"], body)
    faces = np.frombuffer(data, face, count["face"], body + vertices.nbytes)
    assert len(data) == body + vertices.nbytes + faces.nbytes and np.all(faces["n"] == 3)
    return vertices["p"], vertices["rgb"], vertices["q"], faces["i"]


def test_drain_heatmap(tmp_path, sphere_path):
    cli("drain", sphere_path, "--scale", 20, "-o", tmp_path / "cli.stl", "--holes", 2, "--patches", 300,
        "--heatmap", tmp_path / "cli.ply")
    sphere = fabvdb.read(sphere_path, scale=20)
    heat = fabvdb.drain(sphere, holes=2, patches=300, heatmap=True).heatmap
    # The arrays hold what the tool's files hold (positions and values there as floats).
    points, rgb, drains, faces = read_heat_ply(tmp_path / "cli.ply")
    assert np.array_equal(np.asarray(heat.surface.vertices, dtype=np.float32), points)
    assert np.array_equal(np.asarray(heat.surface.triangles, dtype=np.int64), faces)
    assert np.array_equal(heat.colours, rgb)
    assert np.array_equal(heat.drains.astype(np.float32), drains)
    left_points, _, left, left_faces = read_heat_ply(tmp_path / "cli_left.ply")
    assert np.array_equal(left_points, points) and np.array_equal(left_faces, faces)
    assert np.array_equal(heat.left.astype(np.float32), left)
    # With a path, the same files as the tool's, byte for byte.
    fabvdb.drain(sphere, holes=2, patches=300, heatmap=tmp_path / "py.ply")
    for cli_name, py_name in (("cli.ply", "py.ply"), ("cli_left.ply", "py_left.ply"), ("cli.png", "py.png"),
                              ("cli_left.png", "py_left.png")):
        assert same_bytes(tmp_path / cli_name, tmp_path / py_name), py_name


def test_powder_sim(tmp_path, sphere_path):
    cli("drain", sphere_path, "--scale", 20, "-o", tmp_path / "drained.stl", "--holes", 2, "--patches", 300,
        "--report", tmp_path / "drain.json")
    cli("powder-sim", tmp_path / "drained.stl", "--holes-from", tmp_path / "drain.json", "--turns", 3, "--voxel", "1mm",
        "--report", tmp_path / "cli.json")
    report = fabvdb.powder_sim(tmp_path / "drained.stl", holes_from=tmp_path / "drain.json", turns=3, voxel="1mm")
    expected = json.loads((tmp_path / "cli.json").read_text())
    for key in ("initial_volume", "residual_volume", "residual_fraction", "routine", "voxel_size"):
        assert report[key] == expected[key]


def test_decompose_and_mold(tmp_path, sphere_path):
    options = ["--shell", "3mm", "--parts", 2, "--low-res", 1500]
    cli("decompose", sphere_path, "--scale", 20, "-o", tmp_path / "cli_d", *options)
    sphere = fabvdb.read(sphere_path, scale=20)
    fabvdb.decompose(sphere, shell="3mm", parts=2, low_res=1500, output=tmp_path / "py_d")
    for name in ("decomposition.json", "decomposition.ply", "deformation.ply"):
        assert same_bytes(tmp_path / "cli_d" / name, tmp_path / "py_d" / name), name
    cli("mold", sphere_path, "--scale", 20, "-o", tmp_path / "cli_m", "--decomposition",
        tmp_path / "cli_d" / "decomposition.json", "--mold-margin", "6mm", "--voxel", "0.8mm")
    result = fabvdb.mold(sphere, decomposition=tmp_path / "py_d" / "decomposition.json", mold_margin="6mm",
                         voxel="0.8mm", output=tmp_path / "py_m")
    for name in ("parts/part_00.stl", "parts/part_01.stl"):
        assert same_bytes(tmp_path / "cli_m" / name, tmp_path / "py_m" / name), name
    # The mold pieces are not byte-identical, nor are two runs of the tool's own: the same vertices, but
    # their triangles come in another order. The same measured figures instead.
    assert len(result.parts) == 2 and len(result.molds) == 2
    for part, pieces in enumerate(result.molds):
        for side, piece in zip(("top", "bottom"), pieces):
            expected = fabvdb.read(tmp_path / "cli_m" / "molds" / f"part_{part:02d}_{side}.stl")
            assert piece.triangle_count == expected.triangle_count
            assert signed_volume(piece) == pytest.approx(signed_volume(expected), rel=1e-9)
            np.testing.assert_allclose(np.sort(piece.vertices, axis=0), np.sort(expected.vertices, axis=0),
                                       atol=0)
