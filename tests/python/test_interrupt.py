"""Ctrl-C during hrspace.design: the run stops at the end of its iteration
and KeyboardInterrupt carries the best design so far (`design` attribute)."""

import os
import signal
import threading
import time

import pytest

import hrspace
from conftest import BEDROOM


@pytest.mark.parametrize("send", [
    lambda: signal.raise_signal(signal.SIGINT),
    lambda: os.kill(os.getpid(), signal.SIGINT),
], ids=["raise_signal", "kill"])
def test_ctrl_c_stops_the_design_with_the_best_layout(tmp_path, send):
    steps = []
    timer = threading.Timer(1.5, send)
    timer.start()
    t0 = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt) as e:
            hrspace.design(hrspace.Scene(BEDROOM), iterations=100_000, planner="proposed",
                           threads=2, progress=steps.append)
    finally:
        timer.cancel()
    elapsed = time.monotonic() - t0
    assert elapsed < 60, elapsed
    best = e.value.design
    assert isinstance(best, hrspace.Design)
    assert best.stopped and best.valid
    assert 0 < len(best.report["trace"]) < 100_000
    # progress saw every finished iteration of chain 0 (perhaps but the last, when
    # Ctrl-C came first); the other chain of the default two stopped too.
    restarts = best.report["restarts"]
    assert best.cost == min(c["cost"] for c in restarts["tried"])
    if restarts["kept_seed"] == 1:
        assert len(best.report["trace"]) - 1 <= len(steps) <= len(best.report["trace"])
    else:
        assert 0 < len(steps) < 100_000
    best.layout.validate()
    assert best.cost <= best.initial_cost
    best.save(tmp_path)
    assert (tmp_path / "layout.json").exists()


def test_the_gil_is_released_during_a_design():
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        hrspace.design(hrspace.Scene(BEDROOM), iterations=60, planner="proposed", threads=1)
    finally:
        stop.set()
        thread.join()
    assert len(ticks) > 10
