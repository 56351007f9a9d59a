# fabvdb for Blender — a sidebar panel (3D view > Sidebar > fabvdb) whose
# operators prepare the active mesh object for fabrication through the fabvdb
# Python package: inspect, repair, hollow, drain holes with the drainability
# heat map, mold decomposition with edits and undo, molds. Results go into new
# objects and attributes; the user's mesh is never changed. Long work runs in
# a thread with progress in the status bar; Esc cancels.
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
bl_info = {
    "name": "fabvdb",
    "author": "the fabvdb developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > fabvdb",
    "description": "Prepare models for fabrication: repair, hollow, drain holes, mold decomposition and molds",
    "doc_url": "https://github.com/fabvdb/fabvdb/blob/main/docs/blender.md",
    "category": "Mesh",
}

import importlib
import os
import sys


def _load_fabvdb():
    """The fabvdb package: the installed one, else the copy packed in this add-on (vendor/)."""
    try:
        return importlib.import_module("fabvdb")
    except ImportError:
        vendor = os.path.join(os.path.dirname(__file__), "vendor")
        if os.path.isdir(vendor) and vendor not in sys.path:
            sys.path.insert(0, vendor)
        return importlib.import_module("fabvdb")


fabvdb = _load_fabvdb()

from . import operators, panel  # noqa: E402  (after fabvdb is importable)

_modules = (panel, operators)


def register():
    for module in _modules:
        module.register()


def unregister():
    for module in reversed(_modules):
        module.unregister()
