"""Running Algorithm 1 from Python: the options of one exploration and
`explore(options)`, which asks theory/curiosity.pl to explore and returns
what it did. Defaults come from theory/defaults.pl."""
from __future__ import annotations

import json
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Sequence

from pantarhei.bridge.engines.swipl import prolog_quote, text
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.session import error_text, install
from pantarhei.bridge.theories.loading import DEFAULT_THEORY
from pantarhei.oracle.store import DEFAULT_STORE
from pantarhei.theory import defaults


def _default(key: str) -> Any:
    return field(default_factory=lambda: defaults()[key])


@dataclass
class Options:
    """The options of one exploration (see explore/1 in theory/curiosity.pl)."""
    oracle: str = _default("oracle")
    #: "discover" (candidates ranked by predicted novelty) or "paper".
    curiosity: str = _default("curiosity")
    max_rules: int = _default("max_rules")
    samples: int | None = None
    #: discover: the significance level; paper: the slope (None: the mode's default).
    threshold: float | None = None
    permutations: int = _default("permutations")
    #: discover: more batches of an antecedent whose planes are undecided.
    resample: int = _default("resample")
    #: discover: the novelty a candidate needs to be queued, scaled by the
    #: probes' mean score so far (bridge/exploration/novelty.py).
    novelty: float = _default("novelty")
    #: discover: how many of the most novel candidates A_new keeps.
    queue: int = _default("queue")
    #: discover: uniformly random valid antecedents drawn as candidates each step.
    jumps: int = _default("jumps")
    #: discover: pours of a candidate's probe (0: none) and candidates probed a step.
    probe: int = _default("probe")
    probe_attempts: int = _default("probe_attempts")
    #: discover: the last probe of a step goes where fewer than this many pours
    #: hold the candidate's rarest proposition, the fewest (0: never).
    cover: int = _default("cover")
    #: discover: 1 to explore the priors (the empty antecedent) right after a_0.
    prior: int = _default("prior")
    ridge: float = _default("ridge")
    seed: int = _default("seed")
    initial: Sequence[str] | None = None
    breadth: int = _default("breadth")
    qualify: str = _default("qualify")
    out: Path = DEFAULT_THEORY
    store: Path = DEFAULT_STORE
    resume: bool = False
    executor: str = "local"
    workers: int | None = None
    ray_address: str | None = None
    progress: bool = True
    #: Keyword arguments of the oracle's constructor (JSON values).
    oracle_options: dict | None = None
    #: Learn the general rules from every pour and add them to the theory.
    general: bool = _default("general")

    def prolog(self) -> str:
        items = [f"curiosity({prolog_quote(self.curiosity)})",
                 f"oracle({prolog_quote(self.oracle)})", f"max_rules({int(self.max_rules)})",
                 f"permutations({int(self.permutations)})", f"resample({int(self.resample)})",
                 f"novelty({float(self.novelty)!r})", f"queue({int(self.queue)})",
                 f"jumps({int(self.jumps)})", f"probe({int(self.probe)})",
                 f"probe_attempts({int(self.probe_attempts)})", f"cover({int(self.cover)})",
                 f"prior({int(self.prior)})",
                 f"seed({int(self.seed)})",
                 f"breadth({int(self.breadth)})", f"ridge({float(self.ridge)!r})", f"qualify({prolog_quote(self.qualify)})",
                 f"out({prolog_quote(str(Path(self.out).absolute()))})",
                 f"store({prolog_quote(str(Path(self.store).absolute()))})",
                 f"resume({prolog_quote(bool(self.resume))})", f"executor({prolog_quote(self.executor)})",
                 f"progress({prolog_quote(bool(self.progress))})"]
        if self.threshold is not None:
            items.append(f"threshold({float(self.threshold)!r})")
        if self.samples is not None:
            items.append(f"samples({int(self.samples)})")
        if self.initial is not None:
            items.append(f"initial({prolog_quote(list(self.initial))})")
        if self.workers is not None:
            items.append(f"workers({int(self.workers)})")
        if self.ray_address:
            items.append(f"ray_address({prolog_quote(self.ray_address)})")
        if self.oracle_options:
            items.append(f"oracle_options({prolog_quote(json.dumps(self.oracle_options))})")
        return "[" + ", ".join(items) + "]"


def explore(options: Options) -> dict:
    """Run an exploration to the end and return what it did: the output
    files, why it stopped, the number of rules and simulations, and where
    the time went. UserError for bad options; an interruption is raised
    again as KeyboardInterrupt once the state is saved."""
    eng = install()
    host = eng.exploration_host
    host.take_error()
    host.result.clear()
    try:
        goal = (f"curiosity:explore_result({options.prolog()}, R0), "
                "(R0 == ok -> R = ok ; R0 = error(T), text_to_string(T, R))")
        result = eng.once(goal)["R"]
    finally:
        if host.session is not None:
            host.end({"aborted": True})
    if result not in ("ok", b"ok"):
        e = host.take_error()
        if e is not None:
            if isinstance(e, (UserError, KeyboardInterrupt)):
                raise e
            raise UserError(error_text(e)) from e
        raise UserError(_result_text(result))
    out = dict(host.result)
    if options.general:
        from pantarhei.bridge.learning.layers import add_general_rules

        from pantarhei.bridge.exploration.simulation import open_simulator

        P, S = out["pours"]
        t = time.monotonic()
        simulator = open_simulator(options.oracle, options.executor, options.workers,
                                   options.store, options.ray_address, options.oracle_options)
        try:
            general = add_general_rules(options.out, P, S, options.seed,
                                        lambda X: simulator.simulate(X, progress=options.progress))
        finally:
            simulator.close()
        out["general_rules"] = len(general.rules)
        out.setdefault("timings", {})["generalize"] = time.monotonic() - t
    return out


def budget_text(curiosity: str, max_rules: int) -> str:
    """What max_rules counts: explored antecedents for the paper's
    curiosity; for the discovering one, the pours of as many batches (its
    batches and probes)."""
    return f"{max_rules} rules" if curiosity == "paper" else f"the pours of {max_rules} batches"


def stop_text(result: dict, curiosity: str, max_rules: int) -> str:
    """Why an exploration stopped, in words."""
    stopped = str(result.get("stopped", ""))
    return {"a_new_empty": "A_new is empty",
            "max_rules": budget_text(curiosity, max_rules)}.get(stopped, stopped)


def _result_text(result: Any) -> str:
    from pantarhei.bridge.engines.swipl import text

    s = text(result)
    return s.splitlines()[0] if s else "exploration failed"
