"""Ctrl-C in a Python session, for the module's tests: SIGINT sent to this process by a thread once a
condition holds (a checkpoint's first chunk, a journal's evaluations), as a user's Ctrl-C arrives
while a long call runs."""
import os
import signal
import threading
import time


class SigintWhen:
    """Starts watching at once: ready() polled every 2 ms, SIGINT sent the first time it holds."""

    def __init__(self, ready, timeout=60.0):
        self.sent = None  # time.monotonic() of the signal; None: ready() never held within the timeout
        self._thread = threading.Thread(target=self._watch, args=(ready, timeout))
        self._thread.start()

    def _watch(self, ready, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if ready():
                self.sent = time.monotonic()
                os.kill(os.getpid(), signal.SIGINT)
                return
            time.sleep(0.002)

    def join(self):
        self._thread.join()
        return self


def has_chunk(checkpoint):
    """A run's checkpoint folder holds a completed chunk."""
    return checkpoint.is_dir() and any(p.name.startswith("chunk") for p in checkpoint.iterdir())
