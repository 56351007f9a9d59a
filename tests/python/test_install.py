"""`cmake --install` puts the package where Debian's python3 imports it, and
the installed extension finds the installed library by its run path (no
LD_LIBRARY_PATH, no build tree on sys.path)."""
import os
import subprocess
import sys

import pytest

BUILD = os.environ.get("FABVDB_BUILD", "")


@pytest.mark.skipif(not BUILD, reason="FABVDB_BUILD (the build folder) not given")
def test_installed_package_imports(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", BUILD, "--prefix", str(prefix)], check=True, stdout=subprocess.DEVNULL)
    found = list(prefix.glob("lib/python3*/dist-packages/fabvdb/__init__.pyi"))
    assert len(found) == 1, found  # lib/python3.11/dist-packages, or lib/python3/dist-packages for /usr
    site = found[0].parent.parent
    env = {key: value for key, value in os.environ.items() if key not in ("PYTHONPATH", "LD_LIBRARY_PATH")}
    env["PYTHONPATH"] = str(site)
    script = ("import fabvdb; m = fabvdb.Mesh([[0,0,0],[9,0,0],[0,9,0],[0,0,9]], [[0,2,1],[0,1,3],[0,3,2],[1,2,3]]);"
              "print(fabvdb.__file__); print(fabvdb.inspect(m)['closed'])")
    out = subprocess.run([sys.executable, "-c", script], check=True, env=env, capture_output=True, text=True,
                         cwd=tmp_path).stdout  # not the build tree's folder, first on sys.path
    path, closed = out.split()
    assert path.startswith(str(site)) and closed == "True"
