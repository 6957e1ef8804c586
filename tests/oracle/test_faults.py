"""oracle/faults.py: the test-only oracle that really crashes (in a child
process here, so that it is this test's process that survives), and scores
every other pour instantly by its first 9 parameters."""
from __future__ import annotations

import signal
import subprocess
import sys

import numpy as np

from pantarhei.oracle.faults import FaultyOracle
from pantarhei.oracle.generative import normalise

from .pours import pour, with_counts

FLAKY = """
import sys
import numpy as np
from pantarhei.oracle.faults import FaultyOracle
out = FaultyOracle(flaky=[15], marker_dir=sys.argv[1]).score(np.array(eval(sys.argv[2])))
print(out.record["particle_count"])
"""


def no_core() -> None:
    import resource
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def run(code: str, *args: str, cwd) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                          cwd=cwd, preexec_fn=no_core, timeout=120)


def test_other_pours_score_their_first_nine_parameters_scaled():
    o = FaultyOracle(crash=[13, 11], hang=[12], flaky=[14])
    assert o.settings() == {"crash": [11, 13], "hang": [12], "flaky": [14]}
    p = pour(particle_count=20, pour_x=-250, start_x=0)
    out = o.score(p)
    assert out.record == {"particle_count": 20}
    assert np.array_equal(out.scores, normalise(p[None])[0, :9])
    assert out.scores[0] == 0.5 and out.scores[6] == 0.0


def test_a_crash_is_a_real_segmentation_fault(tmp_path):
    r = run("from pantarhei.oracle.faults import segfault; segfault(); print('alive')",
            cwd=tmp_path)
    assert r.returncode == -signal.SIGSEGV and "alive" not in r.stdout


def test_a_flaky_pour_crashes_its_first_time_only(tmp_path):
    p = repr(with_counts([15])[0].tolist())
    first = run(FLAKY, str(tmp_path), p, cwd=tmp_path)
    assert first.returncode == -signal.SIGSEGV
    assert len(list(tmp_path.iterdir())) == 1          # its mark
    second = run(FLAKY, str(tmp_path), p, cwd=tmp_path)
    assert second.returncode == 0 and second.stdout.strip() == "15", second.stderr
    other = repr(with_counts([15], seed=8)[0].tolist())      # another pour: its own first time
    assert run(FLAKY, str(tmp_path), other, cwd=tmp_path).returncode == -signal.SIGSEGV
