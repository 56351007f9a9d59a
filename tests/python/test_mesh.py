"""fabvdb.Mesh and files: numpy arrays in and out, converted once, views
without copies, bad arrays refused with a clear exception, files round trip."""
import os

import numpy as np
import pytest

import fabvdb
from conftest import box_arrays, is_closed, signed_volume


@pytest.mark.parametrize("vdtype", [np.float64, np.float32, np.int32, np.int64])
@pytest.mark.parametrize("tdtype", [np.uint32, np.int32, np.int64, np.uint64, np.int16])
def test_any_dtype_round_trips(vdtype, tdtype):
    v, t = box_arrays()
    mesh = fabvdb.Mesh(v.astype(vdtype), t.astype(tdtype))
    assert mesh.vertices.dtype == np.float64 and mesh.vertices.shape == (8, 3)
    assert mesh.triangles.dtype == np.uint32 and mesh.triangles.shape == (12, 3)
    np.testing.assert_array_equal(mesh.vertices, v)
    np.testing.assert_array_equal(mesh.triangles, t)
    assert signed_volume(mesh) == pytest.approx(40.0 ** 3)


def test_views_share_memory_and_are_read_only(box):
    a, b = box.vertices, box.vertices
    assert np.shares_memory(a, b)  # no copy per access
    assert not a.flags.writeable and not box.triangles.flags.writeable
    with pytest.raises(ValueError):
        a[0, 0] = 1.0
    del box  # the view keeps the mesh alive
    assert a.sum() > 0


def test_non_contiguous_input_is_converted():
    v, t = box_arrays()
    wide = np.zeros((8, 6))
    wide[:, ::2] = v
    mesh = fabvdb.Mesh(wide[:, ::2], np.asfortranarray(t))
    np.testing.assert_array_equal(mesh.vertices, v)
    np.testing.assert_array_equal(mesh.triangles, t)


def test_lists_are_accepted():
    mesh = fabvdb.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    assert mesh.vertex_count == 3 and mesh.triangle_count == 1


def test_empty_mesh():
    mesh = fabvdb.Mesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int32))
    assert mesh.vertices.shape == (0, 3) and mesh.triangles.shape == (0, 3)


def test_wrong_shapes_are_refused():
    v, t = box_arrays()
    with pytest.raises(fabvdb.InvalidArgumentError, match=r"vertices must have shape \(n, 3\), got \(8, 2\)"):
        fabvdb.Mesh(v[:, :2], t)
    with pytest.raises(fabvdb.InvalidArgumentError, match="triangles must have shape"):
        fabvdb.Mesh(v, t.reshape(-1))
    with pytest.raises(ValueError):  # InvalidArgumentError is a ValueError too
        fabvdb.Mesh(v.reshape(2, 4, 3), t)


def test_wrong_dtypes_are_refused():
    v, t = box_arrays()
    with pytest.raises(fabvdb.InvalidArgumentError, match="integer dtype"):
        fabvdb.Mesh(v, t.astype(np.float64))
    with pytest.raises(fabvdb.InvalidArgumentError, match="vertices must be numbers"):
        fabvdb.Mesh(v.astype(str), t)


def test_nan_is_refused():
    v, t = box_arrays()
    v[3, 1] = np.nan
    with pytest.raises(fabvdb.BadInputError) as error:
        fabvdb.Mesh(v, t)
    assert error.value.status == 3 and str(error.value)
    v[3, 1] = np.inf
    with pytest.raises(fabvdb.BadInputError):
        fabvdb.Mesh(v, t)


@pytest.mark.parametrize("bad", [-1, 8, 2 ** 40])
def test_out_of_range_indices_are_refused(bad):
    v, t = box_arrays()
    t[5, 2] = bad
    with pytest.raises(fabvdb.BadInputError, match="triangle 5 refers to vertex"):
        fabvdb.Mesh(v, t)


def test_out_of_range_uint32_is_refused():
    v, t = box_arrays()
    t = t.astype(np.uint32)
    t[0, 0] = 99
    with pytest.raises(fabvdb.BadInputError):
        fabvdb.Mesh(v, t)


def test_huge_uint64_is_refused():
    v, t = box_arrays()
    t = t.astype(np.uint64)
    t[0, 0] = np.uint64(2 ** 63 + 1)
    with pytest.raises(fabvdb.BadInputError):
        fabvdb.Mesh(v, t)


@pytest.mark.parametrize("extension", [".stl", ".ply", ".obj", ".off", ".3mf"])
def test_files_round_trip(tmp_path, box, extension):
    path = tmp_path / ("box" + extension)
    box.write(path)
    again = fabvdb.read(path)
    assert again.triangle_count == 12 and is_closed(again)
    assert signed_volume(again) == pytest.approx(40.0 ** 3)


def test_read_scale_and_fit(sphere_path):
    unit = fabvdb.read(sphere_path)
    assert fabvdb.read(sphere_path, scale=20.0).vertices.max() == pytest.approx(20.0 * unit.vertices.max())
    fitted = fabvdb.read(sphere_path, fit="5cm")
    extent = fitted.vertices.max(axis=0) - fitted.vertices.min(axis=0)
    assert extent.max() == pytest.approx(50.0)


def test_read_errors_name_the_file(tmp_path):
    with pytest.raises(fabvdb.FileError, match="missing.stl"):
        fabvdb.read(tmp_path / "missing.stl")
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nf 1 2 3\n")
    with pytest.raises(fabvdb.BadInputError, match="bad.obj"):
        fabvdb.read(bad)
    with pytest.raises(fabvdb.Error):
        fabvdb.read(tmp_path / "x.unknown")


def test_write_is_atomic_on_failure(tmp_path, box):
    with pytest.raises(fabvdb.Error):
        box.write(tmp_path / "nowhere" / "box.stl")
    assert not os.path.exists(tmp_path / "nowhere")


def test_trimesh_like_objects_are_accepted(box):
    class Like:
        vertices = np.asarray(box.vertices)
        faces = np.asarray(box.triangles, dtype=np.int64)
    report = fabvdb.inspect(Like())
    assert report["triangles"] == 12 and report["closed"]
