"""A test-only oracle that really fails: it segfaults, hangs, or crashes
only the first time, for parameterizations with given particle counts.

For any other parameterization it scores instantly and deterministically
(the first 9 parameters scaled to [0, 1] by their bounds), so that tests of
the executors and the store need no physics.
"""
from __future__ import annotations

import ctypes
import hashlib
import time
from pathlib import Path
from typing import Any, Iterable, Optional

import numpy as np

from pantarhei.oracle.base import Oracle, Outcome
from pantarhei.oracle.generative import normalise
from pantarhei.theory.lexicon import load_vocabulary



def segfault() -> None:
    """Crash this process with a real segmentation fault."""
    ctypes.string_at(0)


class FaultyOracle(Oracle):
    name = "faulty"
    version = "1"

    def __init__(self, crash: Iterable[int] = (), hang: Iterable[int] = (),
                 flaky: Iterable[int] = (), marker_dir: Optional[str] = None):
        self.crash = sorted(int(c) for c in crash)
        self.hang = sorted(int(c) for c in hang)
        self.flaky = sorted(int(c) for c in flaky)
        self.marker_dir = marker_dir

    def settings(self) -> dict[str, Any]:
        return {"crash": self.crash, "hang": self.hang, "flaky": self.flaky}

    def score(self, p: np.ndarray) -> Outcome:
        count = int(round(float(p[load_vocabulary().parameter('particle_count').index])))
        if count in self.crash:
            segfault()
        if count in self.hang:
            while True:
                time.sleep(0.05)
        if count in self.flaky and self.marker_dir:
            mark = Path(self.marker_dir) / hashlib.sha256(np.asarray(p, float).tobytes()).hexdigest()
            if not mark.exists():
                mark.write_text("crashed once\n")
                segfault()
        s = np.clip(normalise(np.asarray(p, dtype=float)[None])[0, :9], 0.0, 1.0)
        return Outcome(s, {"particle_count": count})
