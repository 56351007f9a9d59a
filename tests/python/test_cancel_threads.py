"""Progress, cancellation (callback, Context.cancel() from another thread,
Ctrl-C) and several threads calling at once; the GIL is released meanwhile."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import fabvdb
from conftest import signed_volume


def test_progress_is_reported(sphere):
    seen = []
    fabvdb.repair(sphere, volumetric=True, resolution=80, progress=lambda stage, f: seen.append((stage, f)))
    assert seen and all(isinstance(s, str) and 0.0 <= f <= 1.0 for s, f in seen)


def test_progress_return_cancels(sphere):
    with pytest.raises(fabvdb.CancelledError) as error:
        fabvdb.repair(sphere, volumetric=True, resolution=80, progress=lambda stage, f: True)
    assert error.value.status == 6


def test_progress_exception_propagates(sphere):
    def boom(stage, fraction):
        raise RuntimeError("from the callback")
    with pytest.raises(RuntimeError, match="from the callback"):
        fabvdb.hollow(sphere, wall="3mm", progress=boom)


def test_context_cancel_from_another_thread(sphere):
    context = fabvdb.Context()
    started = threading.Event()

    def progress(stage, fraction):
        started.set()

    def cancel_soon():
        started.wait(30)
        context.cancel()

    canceller = threading.Thread(target=cancel_soon)
    canceller.start()
    try:
        with pytest.raises(fabvdb.CancelledError):
            fabvdb.drain(sphere, holes=2, patches=300, context=context, progress=progress)
    finally:
        canceller.join()
    # The context is usable again.
    mesh, _ = fabvdb.hollow(sphere, wall="3mm", context=context)
    assert signed_volume(mesh) > 0


def test_ctrl_c_cancels_with_keyboard_interrupt(sphere):
    # SIGINT arrives from another thread while the library works without the
    # GIL; Python's own handler (default_int_handler) runs at the next
    # progress report, the call stops and KeyboardInterrupt comes out of it.
    started, done = threading.Event(), threading.Event()

    def interrupt_once_started():
        started.wait(60)
        if not done.is_set():
            os.kill(os.getpid(), signal.SIGINT)

    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    killer = threading.Thread(target=interrupt_once_started)
    killer.start()
    result = None
    try:
        with pytest.raises(KeyboardInterrupt):
            result = fabvdb.drain(sphere, holes=2, patches=300,
                                  progress=lambda stage, fraction: started.set())
    finally:
        done.set()
        started.set()
        killer.join()
    assert result is None


def test_threads_call_at_once(sphere):
    results, errors = {}, []
    busy = [0, 0]
    lock = threading.Lock()

    def work(i):
        try:
            def progress(stage, fraction):
                with lock:
                    busy[0] += 1
            results[i] = fabvdb.hollow(sphere, wall=f"{2 + i}mm", threads=1, progress=progress).mesh
        except Exception as error:  # reported below
            errors.append(error)

    workers = [threading.Thread(target=work, args=(i,)) for i in range(3)]
    for w in workers:
        w.start()
    # The main thread keeps running Python while they work (the GIL is free).
    while any(w.is_alive() for w in workers):
        busy[1] += 1
        time.sleep(0.001)
    for w in workers:
        w.join()
    assert not errors
    for i in range(3):
        expected = 4.0 / 3.0 * np.pi * (20.0 ** 3 - (18.0 - i) ** 3)
        assert signed_volume(results[i]) == pytest.approx(expected, rel=0.05)
    assert busy[0] > 0 and busy[1] > 0
