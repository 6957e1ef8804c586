"""The figures of an evaluation (`Evaluation`): what every measure's stage
puts in, what the headline, the report and evaluation.json read. Imports
nothing of the evaluation, so that every measure's module, the stages
that run them (pipeline.py) and the report read it without importing one
another."""
from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np


@dataclass
class Evaluation:
    """Every figure of an evaluation, JSON-ready (`as_dict`)."""
    theory: str
    oracle: str
    settings: dict[str, Any]
    budget: int
    #: Whether the exploration's pours, simulated here, give the theory's rules.
    reproduced: bool = True
    #: Per explored antecedent: the share of its own pours that kept every expectation.
    kept_all: list[float | None] = field(default_factory=list)
    heldout: dict[str, Any] = field(default_factory=dict)
    curves: dict[str, Any] = field(default_factory=dict)
    behaviours: dict[str, int] = field(default_factory=dict)
    #: The general theory (both layers as shipped, and the general rules alone)
    #: against the models, per method's pours: held-out and one-phrase questions.
    general: dict[str, Any] = field(default_factory=dict)
    #: The shipped theory on interaction questions and random scenes (beyond.py).
    beyond: dict[str, Any] = field(default_factory=dict)
    #: Per search method: distinct nine-verdict vectors among its pours, each seen twice.
    behaviours_seen: dict[str, int] = field(default_factory=dict)
    paper_rules: list[dict[str, Any]] = field(default_factory=list)
    plans: list[dict[str, Any]] = field(default_factory=list)
    simulations: dict[str, int] = field(default_factory=dict)
    seconds: dict[str, float] = field(default_factory=dict)
    #: The figures of a measure without a field of its own, by its name
    #: (in the JSON after the plans).
    figures: dict[str, Any] = field(default_factory=dict)
    #: Not in the JSON: what the report draws from.
    explored: list[tuple[str, ...]] = field(default_factory=list, repr=False)
    explored_consequents: np.ndarray | None = field(default=None, repr=False)
    best_samples: list[np.ndarray] = field(default_factory=list, repr=False)

    def as_dict(self) -> dict[str, Any]:
        return {**{k: getattr(self, k) for k in
                   ("theory", "oracle", "settings", "budget", "reproduced", "kept_all", "heldout",
                    "curves", "behaviours", "behaviours_seen", "general", "beyond", "paper_rules",
                    "plans")},
                **self.figures, "simulations": self.simulations, "seconds": self.seconds}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Evaluation:
        """An evaluation from its `as_dict`."""
        own = {f.name for f in fields(cls)}
        return cls(**{k: v for k, v in d.items() if k in own},
                   figures={k: v for k, v in d.items() if k not in own})

    @property
    def plan_rate(self) -> float | None:
        """The share of the plans' pours that met their goals (None: none simulated)."""
        met = sum(p["met"] for p in self.plans if "met" in p)
        done = sum(p["simulated"] for p in self.plans if "simulated" in p)
        return met / done if done else None
