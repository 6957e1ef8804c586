"""The measure of the learned rules themselves: per explored antecedent,
the share of its own pours in which every expectation held (how firmly
its rules, each the majority, hold); and the report's section of
Algorithm 1's rules in words, with the exploration's trace."""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np

from pantarhei.bridge.verdicts import verdicts
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import antecedent_words, consequent_words, pct
from pantarhei.bridge.evaluation.inputs import Inputs


def kept_all_stage(ev: Evaluation, inputs: Inputs) -> None:
    """Per explored antecedent, the share of its own pours (of the
    exploration's, those that did not fail) that kept every expectation:
    `ev.kept_all` (None for an antecedent without such a pour)."""
    m = inputs.methods["curiosity"]
    ev.kept_all = []
    for i in range(len(m.antecedents)):
        rows = m.S[m.of == i]
        rows = rows[np.all(np.isfinite(rows), axis=1)]
        ev.kept_all.append(float(verdicts(rows).all(axis=1).mean()) if len(rows) else None)


def rules_table(ev: Evaluation) -> list[str]:
    """One row per explored antecedent: its rules in words and its share
    of pours that kept every expectation."""
    lines = ["| antecedent | when (in words) | then | its pours that kept every expectation |",
             "|---|---|---|---|"]
    rows = ev.explored_consequents if ev.explored_consequents is not None else []
    kept = list(ev.kept_all) + [None] * (len(ev.explored) - len(ev.kept_all))
    for i, (a, row, k) in enumerate(zip(ev.explored, rows, kept), start=1):
        lines.append(f"| a{i} | {antecedent_words(a)} | {consequent_words(row)} | {pct(k)} |")
    return lines


def learned_rules_section(ev: Evaluation, out: Path) -> list[str]:
    """Algorithm 1's rules in words, and the exploration's trace (its plot,
    written beside the theory, copied into the report when there)."""
    trace = Path(ev.theory).with_suffix(".trace.png")
    if trace.exists():
        shutil.copyfile(trace, out / "exploration.png")
    L = ["", "## The learned rules", "",
         "One row per explored antecedent (its nine rules): what fails, in words, and the share "
         "of the pours sampled for it in which every expectation held (a rule states the "
         "majority; the share shows how firmly).", ""]
    L += rules_table(ev)
    if (out / "exploration.png").exists():
        L += ["", "## The exploration", "", "![exploration trace](exploration.png)"]
    return L
