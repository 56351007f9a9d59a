"""The add-on's progress and Esc, headless (run by run_blender_test.py inside
Debian's blender): a Drain Holes job on a 100 mm ico-sphere is started as
invoke() starts it (a worker thread, a timer), followed by the operator's own
modal() on timer events until the library reports progress, then sent an Esc
press as the window would send it. Checks: the progress reaches the status
bar, one job runs at a time, Esc cancels the library call (CancelledError in
the worker), the operator ends CANCELLED with its warning, and nothing
half-made is left: no new object, mesh, material or panel result, the input
untouched, the job state cleared so the next operator can run.
Arguments after --: ZIP WORK_DIR."""
import sys
import time
import traceback
from types import SimpleNamespace

import bpy

ZIP, WORK = sys.argv[sys.argv.index("--") + 1:]


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what, flush=True)


def run():
    bpy.ops.preferences.addon_install(filepath=ZIP, overwrite=True)
    bpy.ops.preferences.addon_enable(module="fabvdb_blender")
    from fabvdb_blender import fabvdb, jobs, operators

    class DrainProbe(operators.MeshJob):
        """The Drain Holes operator's own steps (prepare, work, finish) and the jobs' start() and modal(),
        on a plain object: Blender makes operator instances only through bpy.ops, which in background mode
        runs execute(), not the modal path Esc takes."""
        bl_label = operators.FABVDB_OT_drain.bl_label
        suffix = operators.FABVDB_OT_drain.suffix
        read_settings = operators.FABVDB_OT_drain.read_settings
        work = operators.FABVDB_OT_drain.work
        finish = operators.FABVDB_OT_drain.finish

        def __init__(self):
            self.reports = []

        def report(self, kinds, message):
            self.reports.append((set(kinds), message))

    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=5, radius=0.05)
    sphere = bpy.context.active_object
    sphere.name = "sphere"
    scene = bpy.context.scene
    scene.fabvdb.wall = 0.002
    scene.fabvdb.hole_count = 2
    vertex_count = len(sphere.data.vertices)
    before = {name: set(getattr(bpy.data, name).keys()) for name in ("objects", "meshes", "materials", "collections")}
    results_before = dict(operators.RESULTS)

    context = bpy.context
    check(DrainProbe.poll(context), "the job may start")
    probe = DrainProbe()
    check(probe.start(context), "started in a worker thread")
    probe._timer = context.window_manager.event_timer_add(0.1, window=context.window)
    check(jobs.STATE["running"] and not DrainProbe.poll(context), "one job at a time")
    timer = SimpleNamespace(type='TIMER', value='NOTHING')
    # Follow the job on timer events, as the window does (each one writes the status bar), until the library
    # reports progress to the job state the panel shows.
    returned = []
    while jobs.STATE["stage"] == "starting" and probe._thread.is_alive():
        returned.append(probe.modal(context, timer))
        time.sleep(0.02)
    check(all(r == {'PASS_THROUGH'} for r in returned), "while it runs, events pass through: the interface is live")
    check(probe._thread.is_alive() and 0.0 <= jobs.STATE["fraction"] <= 1.0,
          f"the library reported progress ({jobs.STATE['stage']}) and is still working")
    check(probe.modal(context, SimpleNamespace(type='ESC', value='PRESS')) == {'RUNNING_MODAL'},
          "Esc is taken by the operator")
    check(jobs.STATE["stage"] == "cancelling", "the panel says cancelling")
    outcome = None
    while outcome is None or outcome == {'PASS_THROUGH'}:
        time.sleep(0.02)
        outcome = probe.modal(context, timer)
    check(outcome == {'CANCELLED'}, "the operator ends CANCELLED")
    check(isinstance(probe._outcome.get("error"), fabvdb.CancelledError) and "result" not in probe._outcome,
          "the library call was cancelled: no result came back")
    check(({'WARNING'}, "fabvdb: cancelled; nothing was made") in probe.reports, "the user is told")
    check(not probe._thread.is_alive(), "the worker has ended")
    after = {name: set(getattr(bpy.data, name).keys()) for name in before}
    check(after == before, f"nothing half-made: no new object, mesh, material or collection ({after})")
    check(operators.RESULTS == results_before, "no result listed in the panel")
    check(len(sphere.data.vertices) == vertex_count and context.active_object == sphere, "the input is untouched")
    check(not jobs.STATE["running"] and DrainProbe.poll(context), "the next job may start")
    bpy.ops.preferences.addon_disable(module="fabvdb_blender")


try:
    run()
except Exception:
    traceback.print_exc()
    sys.exit(1)
print("blender cancel test: all passed")
