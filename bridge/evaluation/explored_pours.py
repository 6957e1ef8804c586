"""What a learned theory says of the exploration behind it: its settings
(the theory's setting/2 facts), and from its trace (FILE.trace.jsonl,
written beside it) the antecedents it explored and every pour it
simulated, drawn again in the order it simulated them (the evaluation
simulates them again through its store: bridge/evaluation/pipeline.py).
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from pantarhei.theory import defaults

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.simulation import Draw, drawn_pours, trace_draws
from pantarhei.bridge.exploration.trace import explored_whole, trace_path
from pantarhei.bridge.reasoning.written_theory import as_written
from pantarhei.bridge.theories import loading
from pantarhei.bridge.theories.model import Theory, antecedent_id


@dataclass
class Learned:
    """A theory written by `pantarhei explore`, with what its trace says
    of the exploration behind it."""
    path: Path
    theory: Theory
    settings: dict[str, list[Any]]
    antecedents: list[tuple[str, ...]]      # explored, in order: a1, a2, ...
    #: The explored antecedent (index into `antecedents`) of each
    #: iteration, in order: more than one iteration where an antecedent
    #: was sampled again.
    steps: list[int]
    #: Every pour of the exploration, as the trace's draws record them.
    draws: list[Draw]
    #: The explored antecedents (indices into `antecedents`) explored as
    #: wholes: no rule's body (theory/curiosity/learn.pl).
    wholes: frozenset[int] = frozenset()

    @property
    def rule_bodies(self) -> list[tuple[str, ...]]:
        """The explored antecedents that are rules' bodies: all but the
        wholes, in order."""
        return [a for i, a in enumerate(self.antecedents) if i not in self.wholes]

    @property
    def one_layer(self) -> bool:
        """Whether the theory is one layer, as its curiosity lays it out
        (`one_layer`)."""
        return one_layer(self.settings)

    @property
    def qualify(self) -> str:
        """How the exploration qualified its explored antecedents (its
        setting, else the default of theory/defaults.pl)."""
        return str(self.setting("qualify", defaults()["qualify"]))

    @property
    def learner(self) -> str:
        """The learner that wrote the theory's general rules (its setting,
        else the default of theory/defaults.pl): the one the evaluation
        learns with again."""
        from pantarhei.bridge.learning.learners import recorded_learner

        return recorded_learner(self.settings)

    @property
    def batches(self) -> list[int]:
        """Per explored antecedent, how many iterations explored it."""
        return [self.steps.count(i) for i in range(len(self.antecedents))]

    def setting(self, key: str, default: Any = None) -> Any:
        values = self.settings.get(key)
        return values[0] if values else default


def one_layer(settings: Mapping[str, Any]) -> bool:
    """Whether a theory of `settings` (its setting/2 facts, a value or the
    list of a key's values) is one layer: the module of the curiosity it
    records lays its theory out without Algorithm 1's rules (its
    theory_layout's `rules` false, theory/curiosity/interface.pl), so that
    its rules are the learned layer alone. A theory that records no
    curiosity, or one without a module loaded, is not."""
    from pantarhei.bridge.engines.swipl import engine

    recorded = settings.get("curiosity")
    if isinstance(recorded, (list, tuple)):
        if len(recorded) != 1:
            return False
        recorded = recorded[0]
    if recorded is None:
        return False
    eng = engine()
    eng.use_module("curiosity")
    return eng.succeeds("curiosity_interface:by_curiosity(_{curiosity:C}, theory_layout(L)), "
                        "get_dict(rules, L, false)", C=str(recorded))


def read_learned(path: Path | str) -> Learned:
    """Read a learned theory and its trace; UserError if the file lacks
    the exploration's settings (a hand-written theory, say) or its trace
    cannot be read. SWI-Prolog is given the file as written
    (written_theory.as_written), as long as the theory is unchanged."""
    from pantarhei.bridge.learning.learners import known_recorded_learner

    path = Path(path)
    theory = as_written(loading.load([path]), [path])
    settings = loading.settings(theory)
    if not settings.get("seed") or not settings.get("batch"):
        raise UserError(f"{path}: not a theory written by `pantarhei explore` "
                        f"(no setting/2 facts to evaluate it by)")
    known_recorded_learner(settings, path)
    trace = trace_path(path)
    try:
        lines = [json.loads(line) for line in trace.read_text(encoding="utf-8").splitlines()]
        ids = [str(t["id"]) for t in lines]
        bodies = {str(t["id"]): tuple(sorted(str(p) for p in t["antecedent"])) for t in lines}
        whole = {str(t["id"]) for t in lines if explored_whole(t)}
        draws = trace_draws(lines)
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise UserError(f"{trace}: the trace of the theory cannot be read ({e})") from None
    order = list(dict.fromkeys(ids))
    if order != [antecedent_id(i) for i in range(1, len(order) + 1)]:
        raise UserError(f"{trace}: the explored antecedents are not a1..a{len(order)}")
    return Learned(path, theory, settings, [bodies[a] for a in order],
                   [order.index(a) for a in ids], draws,
                   frozenset(i for i, a in enumerate(order) if a in whole))


def exploration_draws(learned: Learned) -> tuple[np.ndarray, list[tuple[str, ...]], np.ndarray,
                                                  list[int]]:
    """The exploration's pours drawn again as its trace records them, in
    the order it simulated them; with the antecedent each pour was drawn
    from, the index of the explored antecedent it belongs to (-1 for a
    probe of a candidate set aside) and where each explored antecedent's
    last pour ends."""
    draws = learned.draws
    P = drawn_pours(draws, int(learned.setting("seed")), int(learned.setting("batch")))
    drawn = [tuple(sorted(d.antecedent)) for d in draws for _ in range(d.last - d.first)]
    of = np.array([learned.steps[d.step] if d.explored else -1
                   for d in draws for _ in range(d.last - d.first)], dtype=int)
    ends = [int(np.flatnonzero(of == i)[-1]) + 1 for i in range(len(learned.antecedents))]
    return P, drawn, of, ends
