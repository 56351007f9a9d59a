# jobs.py — how the add-on's operators run fabvdb: read the inputs from bpy
# on the main thread (prepare), run the fabvdb call in a worker thread with
# its own fabvdb.Context (work: no bpy there), then make the results on the
# main thread (finish). Invoked from the interface the operator is modal: the
# interface stays live, progress shows in the status bar and the sidebar, Esc
# cancels (Context.cancel(); nothing is made). Executed (scripts, background
# mode) the same steps run at once; start() and modal() are also what the
# headless cancel test drives (tests/blender/cancel_test.py).
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
import threading

import bpy

from . import fabvdb

# The job running now (one at a time): its stage and fraction, for the panel.
STATE = {"running": False, "stage": "", "fraction": 0.0, "label": ""}


def _redraw(context):
    for area in context.screen.areas if context.screen else ():
        if area.type == 'VIEW_3D':
            area.tag_redraw()


class FabvdbJob:
    """Mixin of the fabvdb operators: subclasses define prepare(context) -> inputs, work(inputs, ctx,
    progress) -> result (any thread, no bpy), finish(context, inputs, result)."""

    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return not STATE["running"] and obj is not None and obj.type == 'MESH'

    def job_context(self, inputs):
        """The fabvdb.Context the work runs on (Esc cancels it): a new one unless a subclass has its own."""
        return fabvdb.Context()

    def execute(self, context):
        try:
            inputs = self.prepare(context)
            result = self.work(inputs, self.job_context(inputs), None)
            self.finish(context, inputs, result)
        except fabvdb.Error as error:
            self.report({'ERROR'}, f"fabvdb: {error}")
            return {'CANCELLED'}
        return {'FINISHED'}

    def invoke(self, context, event):
        if bpy.app.background:
            return self.execute(context)
        if not self.start(context):
            return {'CANCELLED'}
        manager = context.window_manager
        self._timer = manager.event_timer_add(0.1, window=context.window)
        manager.modal_handler_add(self)
        return {'RUNNING_MODAL'}

    def start(self, context):
        """Reads the inputs and starts the work in a worker thread; False (reported) when the inputs fail.
        modal() then follows it on each timer event and cancels it on Esc."""
        try:
            self._inputs = self.prepare(context)
        except fabvdb.Error as error:
            self.report({'ERROR'}, f"fabvdb: {error}")
            return False
        self._ctx = self.job_context(self._inputs)
        self._outcome = {}
        STATE.update(running=True, stage="starting", fraction=0.0, label=self.bl_label)

        def progress(stage, fraction):
            STATE["stage"], STATE["fraction"] = stage, fraction

        # The thread sees plain Python objects only, never the operator (bpy is main-thread only).
        work, inputs, ctx, outcome = self.work, self._inputs, self._ctx, self._outcome

        def run():
            try:
                outcome["result"] = work(inputs, ctx, progress)
            except BaseException as error:  # handed to the main thread
                outcome["error"] = error

        self._thread = threading.Thread(target=run, daemon=True)
        self._thread.start()
        return True

    def modal(self, context, event):
        if event.type == 'ESC' and event.value == 'PRESS':
            self._ctx.cancel()
            STATE["stage"] = "cancelling"
            return {'RUNNING_MODAL'}
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        context.workspace.status_text_set(
            f"fabvdb {self.bl_label}: {STATE['stage']} {100 * STATE['fraction']:.0f}%  (Esc cancels)")
        _redraw(context)
        if self._thread.is_alive():
            return {'PASS_THROUGH'}
        context.window_manager.event_timer_remove(self._timer)
        context.workspace.status_text_set(None)
        STATE.update(running=False, stage="", fraction=0.0)
        _redraw(context)
        error = self._outcome.get("error")
        if isinstance(error, fabvdb.CancelledError):
            self.report({'WARNING'}, "fabvdb: cancelled; nothing was made")
            return {'CANCELLED'}
        if error is not None:
            self.report({'ERROR'}, f"fabvdb: {error}")
            return {'CANCELLED'}
        try:
            self.finish(context, self._inputs, self._outcome["result"])
        except fabvdb.Error as failure:
            self.report({'ERROR'}, f"fabvdb: {failure}")
            return {'CANCELLED'}
        return {'FINISHED'}
