"""The oracle at the Prolog prompt (`pantarhei prolog`): the handlers of
`oracle_sample`, `oracle_simulate` and `oracle_describe`, which
bridge/exploration/session.py registers beside the exploration's."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.simulation import open_simulator, oracle_identity
from pantarhei.oracle.generative import InvalidAntecedent, sample
from pantarhei.oracle.store import DEFAULT_STORE
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary


def oracle_sample(request: dict) -> dict:
    """n rows drawn from the antecedent's generative model with a seed."""
    props = [str(p) for p in request["antecedent"]]
    try:
        P = sample(props, int(request["n"]), int(request["seed"]))
    except (InvalidAntecedent, ValueError) as e:
        raise UserError(str(e)) from None
    return {"rows": P.tolist()}


def oracle_simulate(request: dict) -> dict:
    """The oracle's scores of the rows given (failed ones as "nan")."""
    oracle = str(request.get("oracle", defaults()["oracle"]))
    oracle_identity(oracle)
    P = np.asarray(request["rows"], dtype=float)
    n = len(load_vocabulary().parameters)
    if P.ndim != 2 or P.shape[1] != n:
        raise UserError(f"expected rows of {n} numbers")
    workers = request.get("workers")
    sim = open_simulator(oracle, str(request.get("executor", defaults()["executor"])),
                         int(workers) if workers is not None else None,
                         Path(str(request.get("store") or DEFAULT_STORE)).absolute())
    try:
        S = np.asarray(sim.simulate(P, progress=False), dtype=float)
    finally:
        sim.close()
    return {"scores": [[float(x) if np.isfinite(x) else "nan" for x in row] for row in S]}


def oracle_describe(request: dict) -> dict:
    """The propositions whose generative models hold each row (describe)."""
    from pantarhei.oracle.generative import describe

    P = np.asarray(request["rows"], dtype=float)
    n = len(load_vocabulary().parameters)
    if P.ndim != 2 or P.shape[1] != n or not np.all(np.isfinite(P)):
        raise UserError(f"expected rows of {n} numbers")
    return {"props": [list(d) for d in describe(P)]}
