"""Shared fixtures of the Python package's tests (ctest runs pytest with
PYTHONPATH=build/python, FABVDB_SOURCE, FABVDB_SHARED_DATA, FABVDB_CLI set):
the small shapes every test measures, and the measurements themselves, done
here with numpy, never read from a report."""
import os

import numpy as np
import pytest

import fabvdb

SOURCE = os.environ.get("FABVDB_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
SHARED = os.environ.get("FABVDB_SHARED_DATA", os.path.join(SOURCE, "..", "shared", "data"))
CLI = os.environ.get("FABVDB_CLI", "")


def box_arrays(size=40.0):
    """A closed, outward-oriented box with a corner at the origin: 8 vertices, 12 triangles."""
    v = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=np.float64) * size
    t = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]], dtype=np.int64)
    return v, t


def signed_volume(mesh):
    """Σ det(a, b, c) / 6 over the triangles: the enclosed volume of a closed, outward-oriented mesh."""
    v = np.asarray(mesh.vertices)
    t = np.asarray(mesh.triangles, dtype=np.int64)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def is_closed(mesh):
    """Every directed edge appears once and its opposite once: closed, 2-manifold along edges, oriented."""
    t = np.asarray(mesh.triangles, dtype=np.int64)
    if len(t) == 0:
        return False
    edges = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    n = int(t.max()) + 1
    forward = edges[:, 0] * n + edges[:, 1]
    backward = edges[:, 1] * n + edges[:, 0]
    if len(np.unique(forward)) != len(forward):
        return False
    return bool(np.all(np.isin(forward, backward)))


def components(mesh):
    """Connected components of the triangles (through shared vertices)."""
    t = np.asarray(mesh.triangles, dtype=np.int64)
    parent = np.arange(len(mesh.vertices))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b, c in t:
        ra, rb, rc = find(a), find(b), find(c)
        parent[rb] = ra
        parent[find(rc)] = ra
    used = np.unique(t)
    return len({find(int(i)) for i in used})


@pytest.fixture(scope="session")
def box():
    v, t = box_arrays()
    return fabvdb.Mesh(v, t)


@pytest.fixture(scope="session")
def sphere():
    """The project's unit sphere scaled to 40 mm across (642 vertices)."""
    return fabvdb.read(os.path.join(SOURCE, "data", "sphere.obj"), scale=20.0)


@pytest.fixture(scope="session")
def sphere_path():
    return os.path.join(SOURCE, "data", "sphere.obj")
