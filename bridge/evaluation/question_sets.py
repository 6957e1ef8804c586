"""Question sets beyond the one-phrase questions, each keyed by the pours
`pantarhei simulate --antecedent` samples for it (20 a scene): pairs of
pose propositions that may interact (interactions.json beside this
module), and uniformly random valid scenes of several propositions. A
key departs from the usual one (a contrast key) where it is clear and
differs from the ordinary pour's verdict (the majority of the empty
antecedent's pours); an answer is a confident error where it states a
likelihood of 0.8 or more on the side a clear key contradicts."""
from __future__ import annotations

import json
from dataclasses import dataclass
from importlib import resources
from typing import Callable, Sequence

import numpy as np

from pantarhei.bridge.evaluation.measures import question_key, question_measures, question_shares
from pantarhei.bridge.verdicts import verdicts
from pantarhei.bridge.evaluation.questions import KEY_POURS, Question, question_pours

#: The likelihood, on the side a key contradicts, of a confident error.
CONFIDENT = 0.8
#: The random scenes: how many, their sizes, and the seed they are drawn with.
RANDOM_SCENES, RANDOM_SIZES, RANDOM_SEED = 40, (5, 8), 20261204


def interaction_questions() -> list[Question]:
    """The pairs of pose propositions of interactions.json, in file order."""
    data = json.loads(resources.files("pantarhei.bridge.evaluation")
                      .joinpath("interactions.json").read_text(encoding="utf-8"))
    return [Question(q["text"], tuple(sorted(q["antecedent"]))) for q in data["questions"]]


def random_scenes(n: int = RANDOM_SCENES, sizes: tuple[int, int] = RANDOM_SIZES,
                  seed: int = RANDOM_SEED) -> list[Question]:
    """n valid scenes of sizes[0] to sizes[1] propositions, each of a
    different dimension, drawn uniformly with `seed`."""
    from pantarhei.bridge.learning.askable import valid
    from pantarhei.theory.lexicon import load_vocabulary

    dims: dict[str, list[str]] = {}
    for name, p in sorted(load_vocabulary().propositions.items()):
        dims.setdefault(p.dimension, []).append(name)
    order = sorted(dims)
    rng = np.random.default_rng(seed)
    out: list[Question] = []
    while len(out) < n:
        k = int(rng.integers(sizes[0], sizes[1] + 1))
        chosen = [order[i] for i in rng.choice(len(order), k, replace=False)]
        scene = tuple(sorted(dims[d][int(rng.integers(len(dims[d])))] for d in chosen))
        if valid(scene) and scene not in {q.antecedent for q in out}:
            out.append(Question(", ".join(scene), scene))
    return out


@dataclass(frozen=True)
class Keyed:
    """A question set with the keys of its pours: per scene and
    expectation the majority verdict, whether it is clear, the share of
    pours that hold, and whether it departs from the ordinary pour's."""
    name: str
    scenes: list[tuple[str, ...]]
    key: np.ndarray
    clear: np.ndarray
    share: np.ndarray
    contrast: np.ndarray
    V: np.ndarray
    of: np.ndarray

    def measures(self, predictions: np.ndarray, likelihood: np.ndarray) -> dict:
        """The question measures of answers to the set, with the confident
        errors counted."""
        out = question_measures(predictions, likelihood, self.share, self.key, self.clear,
                                self.contrast, self.V, self.of)
        out["confident_errors"] = confident_errors(likelihood, self.key, self.clear)
        return out


def confident_errors(likelihood: np.ndarray, key: np.ndarray, clear: np.ndarray) -> int:
    """Clear keys answered with a likelihood of CONFIDENT or more on the
    side the key contradicts."""
    lik = np.asarray(likelihood, dtype=float)
    with np.errstate(invalid="ignore"):
        wrong = np.where(key, lik <= 1 - CONFIDENT, lik >= CONFIDENT)
    return int((wrong & clear & np.isfinite(lik)).sum())


def keyed(name: str, asked: Sequence[Question], run: Callable[[np.ndarray], np.ndarray],
          seed: int = 1, n: int = KEY_POURS) -> Keyed:
    """The set keyed by n pours a scene (seeded as the evaluation draws
    them), and the ordinary pour keyed by 2n, simulated with `run`."""
    scenes = [q.antecedent for q in asked]
    P, of = question_pours([*asked, Question("an ordinary pour", ())], seed, n)
    P = np.vstack([P, question_pours([Question("", ())], seed + 1, n)[0]])
    of = np.concatenate([of, np.full(n, len(asked))])
    S = np.asarray(run(P), dtype=float)
    ok = np.all(np.isfinite(S), axis=1)
    S, of = S[ok], of[ok]
    key, clear = question_key(S, of, len(asked) + 1)
    share = question_shares(S, of, len(asked) + 1)
    inside = of < len(asked)
    contrast = clear[:-1] & (key[:-1] != key[-1])
    return Keyed(name, scenes, key[:-1], clear[:-1], share[:-1], contrast,
                 verdicts(S[inside]), of[inside])


def answers(theory, scenes: Sequence[tuple[str, ...]]) -> tuple[np.ndarray, np.ndarray]:
    """A learned theory's (general_rules.General) verdicts and likelihoods
    for the scenes (NaN where nothing decides)."""
    from pantarhei.theory.lexicon import load_vocabulary

    names = load_vocabulary().expectation_names
    lik = np.array([[theory.answer(s)[e][1] for e in names] for s in scenes], dtype=float)
    return theory.predict(scenes), lik


def theory_behaviours(theory) -> int:
    """The distinct nine-verdict answers, every verdict decided, that a
    learned theory gives for the bodies of its rules (the empty one
    included): the behaviours in the theory."""
    from pantarhei.bridge.verdicts import UNKNOWN

    bodies = list(dict.fromkeys([()] + [tuple(sorted(r.body)) for r in theory.rules]))
    rows = theory.predict(bodies)
    return len({tuple(r) for r in rows if (r != UNKNOWN).all()})

