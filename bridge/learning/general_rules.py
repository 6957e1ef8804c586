"""The rules the general learner writes, and how they decide a question.

A rule `B => e` (or `B => neg(e)`) carries the share of B's pours that
keep its head (`confidence`) and its evidence (`support`, `kept`): see
`meaning` for what that share is, `generalize` for how rules are chosen.

How a question is decided. A scene (a set of propositions) is decided, for
each expectation, by the highest ranked rule whose body it holds. Rules
rank by body size (more specific first), then by the distance of their
confidence from one half, then by id (`rank`, theory/learned_rules.pl's).
This is exactly standard defeasible logic (theory/defeasible.pl in each of
its eight variants) over the rules and `sup/2` facts: more specific learned
rules beat less specific ones with the complementary head (specificity,
which the engine derives), and every other pair of conflicting rules that
can apply together gets an explicit `sup/2` fact in rank order. The order
is a linear one, so the superiority relation is acyclic, and no conflict
stays undecided. The default's empty body makes every scene decided.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, Sequence

import numpy as np

from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN
from pantarhei.bridge.theories.model import Rule, Theory


def rank(size: int, general: bool, confidence: float | None, rule_id: str) -> tuple:
    """How a learned rule ranks against a conflicting one that can apply in
    the same scene; higher ranks win: the larger body (`size`
    propositions), the general layer's, the surer (`confidence` further
    from one half; None as one half), then the id. This is
    theory/learned_rules.pl's rank_key/2, read here without a call to
    Prolog because the learner compares thousands of rules inside
    explore/1 (tests/bridge/learning/test_general_rules.py keeps the two
    equal)."""
    c = 0.5 if confidence is None else confidence
    return (size, int(general), round(abs(c - 0.5), 9), rule_id)


def verdict(holds, likelihood, band: float):
    """HOLDS or FAILS as concluded (`holds`), or UNKNOWN where the
    likelihood that the expectation holds lies within `band` of one half:
    theory/learned_rules.pl's verdict/4, for a number or arrays of them
    (tests/bridge/learning/test_general_rules.py keeps the two equal)."""
    x = np.asarray(likelihood, dtype=float)
    out = np.where(np.abs(x - 0.5) < band - 1e-9, UNKNOWN, np.where(holds, HOLDS, FAILS))
    return int(out) if out.ndim == 0 else out


def confidence(permille) -> float:
    """A rule's confidence from the permille its provenance records
    (confidence_permille): theory/learned_rules.pl's likelihood/3 of a rule
    whose head holds (tests/bridge/learning/test_general_rules.py keeps the
    two equal)."""
    return int(permille) / 1000


def likelihood(holds: bool, confidence: float) -> float:
    """The likelihood that the expectation holds, for a rule that
    concludes it (`holds`) or its negation with `confidence`: as
    theory/learned_rules.pl's likelihood/3 (tests keep the two equal)."""
    return confidence if holds else 1 - confidence


@dataclass(frozen=True)
class GeneralRule:
    """`body => expectation` (holds) or `body => neg(expectation)`."""
    id: str
    body: tuple[str, ...]
    expectation: str
    holds: bool
    support: int          # explored pours whose description holds the body
    kept: int             # of those, how many keep the head
    confidence: float     # P(head | body): the share of the body's pours that keep the head
    level: int            # 0 default, 1 exception, 2 exception to an exception, ...
    #: why the learner doubted its rules' answer here (doubts.py), "" for
    #: a contrast: unsettled (the rules of its parts disagree, too few of
    #: its pours tell), parts_disagree (they disagree, its pours tell),
    #: pours_contradict, beside_interaction or few_pours_depart (a pair whose
    #: few pours each depart from a sure answer)
    doubt: str = ""
    #: for beside_interaction, the explored pair that interacts
    beside: tuple[str, ...] = ()

    @property
    def head(self) -> str:
        return self.expectation if self.holds else f"neg({self.expectation})"

    @property
    def rank(self) -> tuple:
        return rank(len(self.body), True, self.confidence, self.id)

    @property
    def likelihood(self) -> float:
        """The share of the body's pours in which the expectation holds."""
        return likelihood(self.holds, self.confidence)

    def rule(self) -> Rule:
        return Rule(self.id, "defeasible", self.head, self.body)


def deciding(rules: Sequence[GeneralRule], scene: set[str]) -> int | None:
    """The index of the rule that decides a scene: the highest ranked of
    those whose body it holds (None when none does)."""
    live = [j for j, r in enumerate(rules) if set(r.body) <= scene]
    return max(live, key=lambda j: rules[j].rank) if live else None


@dataclass(frozen=True)
class Sup:
    """`superior` beats `inferior`: by specificity (the engine derives it
    among learned rules) or by rank (an explicit sup/2 fact)."""
    superior: str
    inferior: str
    reason: str           # "specificity" or "rank"


@dataclass
class General:
    """The general rules of every expectation and their superiority."""
    rules: list[GeneralRule] = field(default_factory=list)
    sup: list[Sup] = field(default_factory=list)
    #: answers whose likelihood lies within this of one half are uncertain
    #: (theory/defaults.pl's uncertain_band, which the Prolog answers read)
    band: float = field(default_factory=lambda: float(defaults()["uncertain_band"]))

    def of(self, expectation: str) -> list[GeneralRule]:
        return [r for r in self.rules if r.expectation == expectation]

    def decide(self, scene: Iterable[str]) -> dict[str, tuple[int, str | None]]:
        """Per expectation: HOLDS, FAILS or UNKNOWN (undecided, or uncertain:
        the likelihood within `band` of one half), and the deciding rule's id."""
        return {e: (v, rid) for e, (v, _, rid) in self.answer(scene).items()}

    def answer(self, scene: Iterable[str]) -> dict[str, tuple[int, float, str | None]]:
        """Per expectation: the verdict (as `decide`), the likelihood that it
        holds (NaN where no rule decides), and the deciding rule's id."""
        s = set(scene)
        out: dict[str, tuple[int, float, str | None]] = {}
        for e in load_vocabulary().expectation_names:
            rules = self.of(e)
            j = deciding(rules, s)
            if j is None:
                out[e] = (UNKNOWN, float("nan"), None)
                continue
            p = rules[j].likelihood
            out[e] = (verdict(rules[j].holds, p, self.band), p, rules[j].id)
        return out

    def predict(self, scenes: Sequence[Iterable[str]]) -> np.ndarray:
        """scenes x 9: HOLDS, FAILS or UNKNOWN, as `decide`."""
        names = load_vocabulary().expectation_names
        out = np.full((len(scenes), len(names)), UNKNOWN, dtype=int)
        for i, s in enumerate(scenes):
            d = self.decide(s)
            out[i] = [d[e][0] for e in names]
        return out

    def theory(self, source: str = "<general>") -> Theory:
        """The rules as learned defeasible rules, with the explicit sup/2
        facts (specificity is left to the engines, which derive it)."""
        t = Theory(source=source)
        for r in self.rules:
            t.rules.append(r.rule())
            t.learned.add(r.id)
        t.sup = [(s.superior, s.inferior) for s in self.sup if s.reason == "rank"]
        return t
