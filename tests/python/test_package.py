"""The package as a user meets it: help() teaches, the .pyi stub lists what
the package exports with the same parameters, errors form one hierarchy."""
import inspect
import os
import pydoc

import fabvdb


def test_help_teaches():
    text = pydoc.render_doc(fabvdb.hollow, renderer=pydoc.plaintext)
    for word in ("wall", "closing", "infill", "Returns", "3mm"):
        assert word in text


def test_every_status_has_an_exception():
    classes = [fabvdb.InvalidArgumentError, fabvdb.FileError, fabvdb.BadInputError, fabvdb.OutOfBudgetError,
               fabvdb.OutOfMemoryError, fabvdb.CancelledError, fabvdb.InternalError, fabvdb.NotFoundError]
    assert all(issubclass(c, fabvdb.Error) for c in classes)
    assert issubclass(fabvdb.InvalidArgumentError, ValueError)


def test_stub_matches_the_package():
    stub_path = os.path.join(os.path.dirname(fabvdb.__file__), "__init__.pyi")
    stub = {}
    exec(compile(open(stub_path).read(), stub_path, "exec"), stub)
    for name in fabvdb.__all__:
        assert name in stub, f"{name} missing from the stub"
    for name in ("read", "inspect", "repair", "to_volume", "hollow", "drain", "powder_sim", "decompose", "mold"):
        real = list(inspect.signature(getattr(fabvdb, name)).parameters)
        typed = list(inspect.signature(stub[name]).parameters)
        assert real == typed, name
    real = list(inspect.signature(fabvdb.Decomposition.__init__).parameters)
    typed = list(inspect.signature(stub["Decomposition"].__init__).parameters)
    assert [p for p in real if not p.startswith("_")] == typed


def test_version():
    assert fabvdb.__version__.count(".") == 2
