"""Helpers of the store's tests: pours simulated by the synthetic oracle
in this process into a store file."""
from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np

from pantarhei.oracle.generative import sample
from pantarhei.oracle.simulator import make_simulator


def low_pours(n: int, seed: int = 1) -> np.ndarray:
    return sample(["pour_low"], n, seed)


def simulate(store: Path, P: np.ndarray, **kw) -> tuple[np.ndarray, object]:
    """The scores of P, and the simulator (closed) to ask what it did."""
    with make_simulator("synthetic", executor="inline", store=str(store), **kw) as sim:
        return sim.simulate(P), sim


#: A script simulating the pours of the file argv[2] into the store argv[1] in
#: one local worker; the pour of 43 particles hangs, for a test to kill it.
HANGING_RUN = textwrap.dedent("""
    import sys
    import numpy as np
    from pantarhei.oracle.simulator import make_simulator
    P = np.load(sys.argv[2])
    with make_simulator("faulty", executor="local", workers=1, store=sys.argv[1],
                        timeout=600, hang=[43]) as sim:
        sim.simulate(P)
""")
