"""Runs a Blender test script headless and passes its exit code on:
run_blender_test.py BLENDER SCRIPT ARGS... (BLENDER empty: not installed).
Blender runs with --factory-startup and a user-scripts folder of its own
(ARGS' last one, emptied first), so the user's add-ons and settings are not
touched. Exits 77 (ctest: skipped) with the reason when Blender cannot run
here: not installed (Debian ships it for amd64 and arm64 only) or no Python
in it."""
import os
import shutil
import subprocess
import sys

blender, script, *args = sys.argv[1:]
if not blender:
    print("SKIPPED: Blender is not installed (scripts/setup.sh installs Debian's blender where the architecture "
          "has it); the add-on is not tested here")
    sys.exit(77)
work = args[-1]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, "scripts"))
env = dict(os.environ, BLENDER_USER_SCRIPTS=os.path.join(work, "scripts"),
           BLENDER_USER_CONFIG=os.path.join(work, "config"))
command = [blender, "--background", "--factory-startup", "--python-exit-code", "1", "--python", script, "--", *args]
print(" ".join(command), flush=True)
sys.exit(subprocess.run(command, env=env).returncode)
