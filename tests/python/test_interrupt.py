"""Ctrl-C (SIGINT) stops a running compute or generate with KeyboardInterrupt (docs/python.md,
"Interrupts"), well before the work would have ended (S(Q) to Q w = 120 at N = 5000 takes about
50 s on 2 threads; 3000 spheres to P = 1e12 minutes), the random start of a large N included."""
import os
import signal
import subprocess
import sys
import time

import pytest

from conftest import DATA

SCRIPTS = {
    "analysis": "import sbpack; p = sbpack.Packing.read(%r); print('started', flush=True); "
                "sbpack.StructureFactor(qmax=120, threads=2).compute(p); print('finished')"
                % os.path.join(DATA, "mrj-spheres-5000.h5"),
    "generate": "import sbpack; print('started', flush=True); "
                "sbpack.generate(n=3000, seed=1); print('finished')",
    # issue 65 item 3: the random start of 3e5 superballs takes about 9 s, its first window a
    # minute; neither polled Ctrl-C before
    "generate set-up": "import sbpack; print('started', flush=True); "
                       "sbpack.generate(n=300000, p=1.5, seed=1); print('finished')",
}


@pytest.mark.parametrize("work", SCRIPTS)
def test_sigint_raises_keyboard_interrupt(work):
    child = subprocess.Popen([sys.executable, "-c", SCRIPTS[work]], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ)
    assert child.stdout.readline().strip() == "started"
    time.sleep(1.0)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=30)
    assert time.monotonic() - sent < 5.0
    assert "KeyboardInterrupt" in err and "finished" not in out
