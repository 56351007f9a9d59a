"""The same command from Python and from the `fabvdb` tool on the same input
gives the same output file, byte for byte, and the same figures."""
import json
import os
import subprocess

import pytest

import fabvdb
from conftest import CLI, SOURCE

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
