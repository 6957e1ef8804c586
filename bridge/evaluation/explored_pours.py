"""What a learned theory says of the exploration behind it: its settings,
the antecedents it explored, and their pours drawn again with the
exploration's seeds, in the order it simulated them (the evaluation
simulates them again through its store: bridge/evaluation/pipeline.py).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from pantarhei.oracle.generative import sample

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.simulation import batch_seed
from pantarhei.bridge.theories import loading
from pantarhei.bridge.theories.model import Theory, antecedent_id, antecedent_index, literal_text


@dataclass
class Learned:
    """A theory written by `pantarhei explore`, with what it says of the
    exploration behind it."""
    path: Path
    theory: Theory
    settings: dict[str, list[Any]]
    antecedents: list[tuple[str, ...]]      # explored, in order: a1, a2, ...
    #: Batches of `samples` pours of each explored antecedent (more than one
    #: where the discovering curiosity sampled an undecided antecedent again).
    batches: list[int] = field(default_factory=list)
    #: The candidates set aside after their probe: iteration -> attempt -> antecedent.
    set_aside: dict[int, dict[int, tuple[str, ...]]] = field(default_factory=dict)
    #: The learning curiosity's: the explored antecedent (index into
    #: `antecedents`) of each iteration, in order, from its trace.
    steps: list[int] = field(default_factory=list)

    @property
    def one_layer(self) -> bool:
        """Whether the theory is the learning curiosity's one layer."""
        return bool(self.steps)

    def setting(self, key: str, default: Any = None) -> Any:
        values = self.settings.get(key)
        return values[0] if values else default


def read_learned(path: Path | str) -> Learned:
    """Read a learned theory; UserError if the file lacks the exploration's
    settings and provenance (a hand-written theory, say)."""
    from pantarhei.theory import read_facts

    path = Path(path)
    theory = loading.load([path])
    facts = read_facts([path])
    settings = loading.settings(theory)
    of_rule = {literal_text(a[0]): literal_text(a[2]) for a in facts.get("provenance", [])
               if len(a) == 3 and literal_text(a[1]) == "antecedent"}
    if [str(c) for c in settings.get("curiosity", [])] == ["learn"]:
        return _read_one_layer(path, theory, settings)
    if not settings.get("seed") or not settings.get("batch") or not of_rule:
        raise UserError(f"{path}: not a theory written by `pantarhei explore` "
                        f"(no setting/2 and provenance/3 facts to evaluate it by)")
    bodies: dict[int, tuple[str, ...]] = {}
    for r in theory.rules:
        a = of_rule.get(r.id)
        i = antecedent_index(a) if a else None
        if i is not None:
            bodies.setdefault(i, tuple(sorted(r.body)))
    order = sorted(bodies)
    if order != list(range(1, len(order) + 1)):
        raise UserError(f"{path}: the explored antecedents are not a1..a{len(order)}")
    batches: dict[int, int] = {}
    for a in facts.get("provenance", []):
        if len(a) == 3 and literal_text(a[1]) == "batches":
            i = antecedent_index(of_rule.get(literal_text(a[0]), ""))
            if i is not None:
                batches[i] = int(a[2])
    aside: dict[int, dict[int, list[str]]] = {}
    for a in facts.get("set_aside", []):
        aside.setdefault(int(a[0]), {}).setdefault(int(a[1]), []).append(literal_text(a[2]))
    return Learned(path, theory, settings, [bodies[i] for i in order],
                   [batches.get(i, 1) for i in order],
                   {i: {k: tuple(sorted(ps)) for k, ps in by.items()} for i, by in aside.items()})


def _read_one_layer(path: Path, theory: Theory, settings: dict[str, list[Any]]) -> Learned:
    """A theory of the learning curiosity: what it explored, iteration by
    iteration, is its trace (FILE.trace.jsonl, written beside it)."""
    import json

    from pantarhei.bridge.exploration.trace import trace_path

    trace = trace_path(path)
    if not settings.get("seed") or not settings.get("batch"):
        raise UserError(f"{path}: not a theory written by `pantarhei explore` "
                        f"(no setting/2 facts to evaluate it by)")
    try:
        steps = [json.loads(line) for line in trace.read_text(encoding="utf-8").splitlines()]
        ids = [str(t["id"]) for t in steps]
        bodies = {str(t["id"]): tuple(sorted(str(p) for p in t["antecedent"])) for t in steps}
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise UserError(f"{trace}: the trace of the learning curiosity's theory cannot be read "
                        f"({e})") from None
    order = list(dict.fromkeys(ids))
    if order != [antecedent_id(i) for i in range(1, len(order) + 1)]:
        raise UserError(f"{trace}: the explored antecedents are not a1..a{len(order)}")
    return Learned(path, theory, settings, [bodies[a] for a in order],
                   [ids.count(a) for a in order], {}, [order.index(a) for a in ids])


def exploration_draws(learned: Learned) -> tuple[np.ndarray, list[tuple[str, ...]], np.ndarray,
                                                  list[int]]:
    """The exploration's pours drawn again with its seeds, in the order it
    simulated them: per iteration, the probes of its candidates in turn
    (`probe` pours each, the candidates set aside and the one explored),
    then the rest of the explored one's batch (the whole batch where
    nothing was set aside). With the antecedent each pour was drawn from,
    the index of the explored antecedent it belongs to (-1 for a probe set
    aside) and where each explored antecedent's last batch ends."""
    samples, seed = int(learned.setting("batch")), int(learned.setting("seed"))
    if learned.one_layer:
        rows = [sample(list(learned.antecedents[i]), samples, batch_seed(seed, t, 0))
                for t, i in enumerate(learned.steps, start=1)]
        of = np.repeat(learned.steps, samples)
        drawn = [learned.antecedents[i] for i in of]
        ends = [int(np.flatnonzero(of == i)[-1]) + 1 for i in range(len(learned.antecedents))]
        return np.vstack(rows), drawn, of, ends
    m = min(int(learned.setting("probe", 0)), samples)
    rows, drawn, of, ends = [], [], [], []
    iteration = 0
    for i, (a, n) in enumerate(zip(learned.antecedents, learned.batches)):
        for _ in range(n):
            iteration += 1
            aside = learned.set_aside.get(iteration, {})
            chosen = min(set(range(len(aside) + 1)) - set(aside))
            if aside:
                for k in range(len(aside) + 1):
                    b = aside.get(k, a)
                    rows.append(sample(list(b), samples, batch_seed(seed, iteration, k))[:m])
                    drawn += [b] * m
                    of += [i if k == chosen else -1] * m
            P = sample(list(a), samples, batch_seed(seed, iteration, chosen))[m if aside else 0:]
            rows.append(P)
            drawn += [a] * len(P)
            of += [i] * len(P)
        ends.append(len(of))
    return np.vstack(rows), drawn, np.array(of), ends
