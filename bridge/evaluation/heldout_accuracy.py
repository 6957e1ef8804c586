"""The measure of held-out prediction: how well each method's theory
predicts the held-out scenes, along the budget and at its end, beside a
decision tree of the same simulations (computed by heldout.py). Its
stage, headline rows and report section."""
from __future__ import annotations

import time
from pathlib import Path

from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import pct
from pantarhei.bridge.evaluation.heldout import heldout_curves, heldout_theories
from pantarhei.bridge.evaluation.inputs import Inputs, tell
from pantarhei.bridge.evaluation.plots import plot_expectations, plot_heldout

#: The theory's accuracy where it decides, and how often it decides, at the least.
ACCURACY, COVERAGE = 0.90, 0.90
#: How far the decision tree's accuracy may be ahead of the theory's, at most.
TREE_GAP = 0.05


def heldout_stage(ev: Evaluation, inputs: Inputs) -> None:
    """The curves over the budget (`ev.curves`, `ev.behaviours`) and each
    theory and decision tree on the held-out scenes (`ev.heldout`)."""
    held = inputs.held
    t = time.monotonic()
    tell("predicting the held-out scenes with every theory along the budget")
    mode = inputs.learned.qualify
    heldout_curves(ev, inputs.methods, held, inputs.samples, mode)
    heldout_theories(ev, inputs.learned.theory, inputs.methods, held, inputs.samples, mode,
                     inputs.opts.seed)
    ev.seconds["predicting"] = round(time.monotonic() - t, 1)


def heldout_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """Per held-out set near explored scenes and uniformly random ones:
    the theory's accuracy and coverage, and the decision tree's accuracy."""
    rows = []
    for name in ("near", "uniform"):
        h = ev.heldout.get(name)
        if not h:
            continue
        th, tree = h["curiosity_theory"], h["curiosity_tree"]
        what = {"near": "near explored scenes", "uniform": "uniformly random scenes"}[name]
        # an accuracy is None where nothing was decided
        acc, cov, tacc = th["accuracy"], th["coverage"], tree["accuracy"]
        rows.append((f"held-out accuracy where the theory decides ({what}, {h['scenes']} scenes)",
                     pct(acc), "at least 90%", acc is not None and acc >= ACCURACY))
        rows.append((f"held-out coverage ({what})", pct(cov), "at least 90%", cov >= COVERAGE))
        gap = None if acc is None or tacc is None else tacc - acc
        rows.append((f"decision tree accuracy, same simulations ({what})",
                     pct(tacc) if gap is None
                     else f"{pct(tacc)} ({'+' if gap >= 0 else ''}{100 * gap:.1f} points)",
                     "theory within 5 points", gap is not None and gap <= TREE_GAP))
    return rows


def heldout_section(ev: Evaluation, out: Path) -> list[str]:
    """The held-out scenes: the theories and the decision trees, with the
    plots over the budget and per expectation."""
    plot_heldout(ev, out / "heldout.png")
    if "near" in ev.heldout and ev.heldout["near"]["scenes"]:
        plot_expectations(ev, out / "expectations.png")
    L = ["## Held-out scenes", "",
         "Each held-out scene is a valid antecedent that neither exploration explored, "
         "sampled once and simulated. *uniform*: drawn uniformly from all valid antecedents. "
         "*near*: an antecedent explored by curiosity with one or two propositions added; "
         "*near_random*: the same around random exploration's antecedents. The theory "
         "decides an expectation when SWI-Prolog concludes it or its negation; the decision "
         "tree (scikit-learn, trained on the same simulations, one-hot antecedents as "
         "features) always decides.", ""]
    L += ["| scenes | propositions per scene | theory: accuracy | theory: coverage | "
          "tree: accuracy | random theory: accuracy | random theory: coverage | random tree: accuracy |",
          "|---|---|---|---|---|---|---|---|"]
    for name, h in ev.heldout.items():
        L.append(f"| {name} ({h['scenes']}) | {h['mean_propositions']:.1f} | "
                 f"{pct(h['curiosity_theory']['accuracy'])} | {pct(h['curiosity_theory']['coverage'])} | "
                 f"{pct(h['curiosity_tree']['accuracy'])} | {pct(h['random_theory']['accuracy'])} | "
                 f"{pct(h['random_theory']['coverage'])} | {pct(h['random_tree']['accuracy'])} |")
    L += ["", "![held-out accuracy and coverage over the budget](heldout.png)", ""]
    if (out / "expectations.png").exists():
        L += ["![per expectation](expectations.png)", ""]
    return L
