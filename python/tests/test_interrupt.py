"""Ctrl-C in a long call raises KeyboardInterrupt, as in pure Python: the
call runs with the GIL released, and the library's loops see the request
(python/src/interruptible.hpp). Each case runs in a child interpreter that
is sent SIGINT while the call runs; the call alone would take minutes."""
import os
import signal
import subprocess
import sys
import textwrap

import pytest

import stratum

CASES = {
    "measure": "stratum.measure(np.random.default_rng(1).random((400000, 4)), 'l2-star', algorithm='warnock')",
    "study": "stratum.study_dimension(dims='1:10', n='16:16777216', runs=64)",
    "converge": "stratum.converge('genz-gaussian', ['random', 'sobol:owen'], n='1024:16777216:4', runs=256, d=8)",
}
if hasattr(stratum, "comparisons"):  # built with the renderer
    CASES["render"] = "stratum.render(width=64, height=64, spp=2**22, passes=1)"


def interrupt_child(call, tmp_path):
    code = textwrap.dedent(f"""
        import sys
        import numpy as np
        import stratum
        print("calling", flush=True)
        try:
            {call}
        except KeyboardInterrupt:
            print("KeyboardInterrupt", flush=True)
            # The request is spent: the next call runs to its end.
            value = stratum.measure(np.random.default_rng(2).random((64, 2)), "l2-star")["value"]
            print("then", value > 0, flush=True)
            sys.exit(3)
        print("finished", flush=True)
    """)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    # SIGINT at its default in the child even when this run inherited it ignored
    # (a background job): Python installs KeyboardInterrupt only over SIG_DFL.
    child = subprocess.Popen([sys.executable, "-c", code], cwd=tmp_path, env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True,
                             preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        assert child.stdout.readline().strip() == "calling"
        try:
            child.wait(timeout=1.5)  # the call has begun (it must not end on its own)
        except subprocess.TimeoutExpired:
            pass
        assert child.poll() is None, child.communicate()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=20)  # a hang fails here
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    return child.returncode, out, err


@pytest.mark.parametrize("name", sorted(CASES))
def test_sigint_raises_keyboard_interrupt(name, tmp_path):
    code, out, err = interrupt_child(CASES[name], tmp_path)
    assert code == 3 and "KeyboardInterrupt" in out, (code, out, err)
    assert "finished" not in out

    assert "then True" in out  # a call after the interrupt is not stopped by it
