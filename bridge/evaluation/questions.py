"""One-phrase questions a person would type ("pour from the side", "a
heavy liquid into a light bowl", ...), each with the propositions whose
glosses say it (questions.json beside this file). A question's key is the
majority verdict of the pours that `pantarhei simulate --antecedent`
samples for it: the question's one meaning, unsaid parameters from the
priors."""
from __future__ import annotations

import json
from dataclasses import dataclass
from importlib import resources

import numpy as np

from pantarhei.bridge.exploration.simulation import iteration_seed
from pantarhei.oracle.generative import sample

#: Pours sampled per question for its key.
KEY_POURS = 20


@dataclass(frozen=True)
class Question:
    text: str
    antecedent: tuple[str, ...]


def questions() -> list[Question]:
    """The questions, in file order."""
    data = json.loads(resources.files("pantarhei.bridge.evaluation")
                      .joinpath("questions.json").read_text(encoding="utf-8"))
    return [Question(q["text"], tuple(sorted(q["antecedent"]))) for q in data["questions"]]


def question_pours(asked: list[Question], seed: int, n: int = KEY_POURS) -> tuple[np.ndarray, np.ndarray]:
    """n pours of each question (seeded per question), and for each pour the
    index of its question."""
    P = np.vstack([sample(list(q.antecedent), n, iteration_seed(seed, 400_000 + i))
                   for i, q in enumerate(asked)])
    return P, np.repeat(np.arange(len(asked)), n)
