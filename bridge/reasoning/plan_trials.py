"""A plan tried in the simulation (`Trial`) and its batches of pours
(`Batch`): what the plan search (plan_search.py) records of each plan it
verifies, and what the order of its candidates (plan_order.py) reads of
the plans tried so far.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from pantarhei.bridge.reasoning.planning import Plan


@dataclass
class Trial:
    """A plan verified in the simulation: where it came from (the theory
    or the search), the round, its pours and how many met every goal, and
    each goal's count."""
    plan: Plan
    origin: str
    round: int
    simulated: int = 0
    failed: int = 0
    met: int = 0
    per_goal: dict[str, int] = field(default_factory=dict)
    verified: bool = False
    #: what the theory of its round said of each goal in its scene (plan_numbers.Support)
    said: list = field(default_factory=list)
    #: per batch (the first, then the confirming one): its pours and how many met every goal
    batches: list[Batch] = field(default_factory=list)
    #: passed its first batch, and the budget held too few pours to confirm it
    short: bool = False

    @property
    def rate(self) -> float:
        return self.met / self.simulated if self.simulated else 0.0

    @property
    def shares(self) -> dict[str, float]:
        """Each goal's share of every verifying pour (both batches)."""
        return {g: n / self.simulated if self.simulated else 0.0 for g, n in self.per_goal.items()}

    @property
    def unconfirmed(self) -> bool:
        """Passed its first batch and failed the confirming one."""
        return len(self.batches) > 1 and not self.verified

    def as_dict(self) -> dict:
        return {"chosen": list(self.plan.chosen), "antecedent": list(self.plan.antecedent),
                "origin": self.origin, "round": self.round, "simulated": self.simulated,
                "failed": self.failed, "met": self.met, "rate": round(self.rate, 3),
                "per_goal": dict(self.per_goal),
                "per_goal_share": {g: round(x, 3) for g, x in self.shares.items()},
                "batches": [b.as_dict() for b in self.batches], "verified": self.verified,
                "unconfirmed_for_budget": self.short,
                "rests_on": [x.as_dict() for x in self.said]}


@dataclass(frozen=True)
class Batch:
    """A batch of a plan's verifying pours: `first` (chosen on it) or
    `confirming` (fresh pours after); the pours that finished, and how many
    met every goal."""
    kind: str
    simulated: int
    met: int

    def as_dict(self) -> dict:
        return {"batch": self.kind, "simulated": self.simulated, "met": self.met}
