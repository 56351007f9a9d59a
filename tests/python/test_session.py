"""fabvdb.Decomposition: the studio's session from Python — edits, re-runs,
undo/redo, accessors, save and load — checked on the labels themselves."""
import json

import numpy as np
import pytest

import fabvdb


@pytest.fixture(scope="module")
def session(sphere):
    return fabvdb.Decomposition(sphere, shell="3mm", parts=2, low_res=1500)


def part_areas(session):
    v, t, labels = session.vertices, session.triangles.astype(np.int64), session.labels
    area = 0.5 * np.linalg.norm(np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]]), axis=1)
    return np.bincount(labels, weights=area)


def test_a_new_session(session):
    info = session.info
    assert info["part_count"] == 2 and info["undo_steps"] == 0
    n = len(session.triangles)
    assert session.labels.shape == (n,) and set(np.unique(session.labels)) == {0, 1}
    assert session.sides.shape == (n,) and session.deformation.shape == (n,)
    radius = np.linalg.norm(session.vertices, axis=1)
    assert np.all((radius > 19.0) & (radius < 21.0))
    for part in session.parts:
        assert np.linalg.norm(part["direction"]) == pytest.approx(1.0)
    areas = part_areas(session)
    assert areas.sum() == pytest.approx(4 * np.pi * 20.0 ** 2, rel=0.05)
    lines = session.parting_lines()
    assert lines and all(points.shape[1] == 3 for _, points in lines)
    assert session.surface.triangle_count == n
    classes = session.draft_map([0, 0, 1], "1deg")
    assert classes.shape == (n,) and classes.max() <= 3


def test_edits_undo_redo(session):
    labels = session.labels.copy()
    # A cut all round the sphere's equator in the plane x = 0 (a closed loop).
    angles = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    loop = np.stack([np.zeros_like(angles), 20 * np.cos(angles), 20 * np.sin(angles)], axis=1)
    session.cut(loop, closed=True)
    assert session.part_count >= 3 and session.info["undo_steps"] == 1
    assert session.undo()
    np.testing.assert_array_equal(session.labels, labels)
    assert session.redo()
    assert session.part_count >= 3
    assert session.undo()
    assert session.info["redo_steps"] == 1 and session.part_count == 2


def test_refused_edit_leaves_the_session(session):
    labels = session.labels.copy()
    with pytest.raises(fabvdb.BadInputError):
        session.cut([[0, 0, 20]])  # fewer than two points
    np.testing.assert_array_equal(session.labels, labels)


def test_rerun_and_save_load(session, sphere, tmp_path):
    session.rerun(parts=3)
    assert session.part_count == 3 and session.options["parts"] == 3
    session.write(tmp_path / "d")
    again = fabvdb.Decomposition.read(sphere, tmp_path / "d")
    np.testing.assert_array_equal(again.labels, session.labels)
    assert session.undo() and session.part_count == 2
    session.no_cut([[0, 0, 20], [0, 5, 19]], "4mm")
    session.write_edits(tmp_path / "edits.json")
    edits = json.loads((tmp_path / "edits.json").read_text())
    assert edits["edits"][0]["type"] == "no_cut"
