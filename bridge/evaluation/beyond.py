"""The shipped theory beyond the ordinary pour's neighbourhood: the pairs of
pose propositions that may interact (interactions.json) and uniformly
random valid scenes of 5 to 8 propositions (question_sets.py), each keyed
by the majority of 20 pours, asked of SWI-Prolog. Contrast keys are the
clear keys that depart from the ordinary pour's verdict; a confident
error states 80% or more on the side a clear key contradicts. Its stage,
headline rows and report section."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import numpy as np

from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import num, pct
from pantarhei.bridge.evaluation.inputs import Inputs
from pantarhei.bridge.evaluation.question_sets import (interaction_questions, keyed,
                                                       random_scenes)
from pantarhei.bridge.evaluation.rule_building import answer_matrix
from pantarhei.bridge.theories.model import Theory

#: The targets: on the interaction questions, contrast accuracy at least,
#: calibration at most, and no confident error; on the random scenes,
#: contrast accuracy at least and calibration at most.
INTERACTION_CONTRAST, INTERACTION_CALIBRATION = 0.90, 0.06
RANDOM_CONTRAST, RANDOM_CALIBRATION = 0.95, 0.05
SETS = {"interactions": "pairs of pose propositions that may interact",
        "random": "uniformly random valid scenes of 5 to 8 propositions"}


def beyond_stage(ev: Evaluation, inputs: Inputs) -> None:
    """`ev.beyond`: the shipped theory's measures on both sets."""
    ev.beyond = beyond_figures(inputs.learned.theory, inputs.run, inputs.opts.seed)


def beyond_figures(theory: Theory, run: Callable[..., np.ndarray], seed: int) -> dict[str, Any]:
    """The measures of `theory`'s answers on each set, its pours simulated
    with `run(label, P)` (keys drawn with `seed`)."""
    out: dict[str, Any] = {}
    for name, asked in (("interactions", interaction_questions()), ("random", random_scenes())):
        ks = keyed(name, asked, lambda P, name=name: run(f"{name} keys", P), seed)
        pred, lik = answer_matrix(theory, ks.scenes)
        m = ks.measures(pred, lik)
        out[name] = {"scenes": len(asked), **{k: (float(v) if isinstance(v, (float, np.floating))
                                                 else v) for k, v in m.items()}}
    return out


def beyond_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    f = ev.beyond
    if not f:
        return []
    i, r = f["interactions"], f["random"]
    rows = _rows(f"interactions ({i['scenes']} pairs of pose propositions)", "interactions", i,
                 INTERACTION_CONTRAST, INTERACTION_CALIBRATION)
    rows.insert(2, ("interactions: confident errors (80% or more on the side the pours "
                    "contradict)", str(i["confident_errors"]), "none", i["confident_errors"] == 0))
    return rows + _rows(f"random scenes ({r['scenes']}, 5 to 8 propositions, 20 pours each)",
                        "random scenes", r, RANDOM_CONTRAST, RANDOM_CALIBRATION)


def _rows(title: str, short: str, m: dict, contrast: float,
          calibration: float) -> list[tuple[str, str, str, bool]]:
    """A set's accuracy on the keys that depart from the ordinary pour and
    its calibration, against their targets."""
    cal = m["calibration"]
    return [(f"{title}: accuracy on the {m['contrast']} keys that depart from the ordinary pour "
             f"(covered {pct(m['contrast_coverage'])})", pct(m["contrast_accuracy"]),
             f"at least {100 * contrast:.0f}%", m["contrast_accuracy"] >= contrast),
            (f"{short}: calibration", num(cal), f"at most {calibration:g}",
             cal is not None and cal <= calibration)]


def beyond_section(ev: Evaluation, out: Path) -> list[str]:
    f = ev.beyond
    if not f:
        return []
    L = ["", "## Beyond the ordinary pour", "",
         "The shipped theory (SWI-Prolog's answers) on two sets kept beside the questions: "
         "pairs of pose propositions that may interact (`bridge/evaluation/interactions.json`) "
         "and uniformly random valid scenes, each keyed by the majority of 20 pours. *depart*: "
         "the clear keys whose verdict is not the ordinary pour's. *confident errors*: answers "
         "of 80% or more on the side a clear key contradicts.", "",
         "| set | scenes | clear: coverage | clear: accuracy | depart: accuracy (coverage) | "
         "calibration | confident errors |", "|---|---|---|---|---|---|---|"]
    for name, what in SETS.items():
        m = f[name]
        L.append(f"| {what} | {m['scenes']} | {pct(m['coverage'])} | {pct(m['accuracy'])} | "
                 f"{pct(m['contrast_accuracy'])} ({pct(m['contrast_coverage'])} of "
                 f"{m['contrast']}) | {num(m['calibration'])} | {m['confident_errors']} |")
    return L
