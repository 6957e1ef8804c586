"""The measures of `pantarhei evaluate`, each named here.

A measure is its figures' name (their key in `Evaluation` and
evaluation.json), the stage that measures them, its headline rows (each
figure against its target, which lives beside the rows) and its section
of the report. `pipeline.evaluate` runs every stage in the order of
`MEASURES`, `headline.headline` gives every measure's rows in that order
and `report.write` every section in it too (a measure may name the
measure its section comes before instead). Adding a measure is a module
with its stage, rows and section (as `paper_rules.py`), named in
`MEASURES`, and its meaning in docs/evaluation.md.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from pantarhei.bridge.evaluation import (behaviours, beyond, general_answers, heldout_accuracy,
                                         paper_rules, plan_checks, report_general, rule_table)
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.inputs import Inputs

#: A headline row: the measure in words, what was measured, the target, whether it is met.
Row = tuple[str, str, str, bool]


def no_rows(ev: Evaluation) -> list[Row]:
    """The headline rows of a measure without a target: none."""
    return []


@dataclass(frozen=True)
class Measure:
    """One measure of the evaluation. `stage(ev, inputs)` measures it and
    puts its figures into `ev`; it may read what the stages before it put
    there. `headline(ev)` and `section(ev, out)` are read after every
    stage: its headline rows, and its section of report/README.md as
    Markdown lines (drawing its plots into the report's folder `out`)."""
    name: str
    stage: Callable[[Evaluation, Inputs], None]
    section: Callable[[Evaluation, Path], list[str]]
    headline: Callable[[Evaluation], list[Row]] = no_rows
    #: The measure whose section this one's comes before in the report
    #: ("": in the order of `MEASURES`).
    report_before: str = ""


#: Every measure, in the order they are measured and headlined.
MEASURES = (
    Measure("behaviours_seen", behaviours.behaviours_stage, behaviours.behaviours_section,
            behaviours.behaviours_headline),
    Measure("heldout", heldout_accuracy.heldout_stage, heldout_accuracy.heldout_section,
            heldout_accuracy.heldout_headline),
    Measure("general", general_answers.general_stage, report_general.general_section,
            general_answers.general_headline, report_before="heldout"),
    Measure("beyond", beyond.beyond_stage, beyond.beyond_section, beyond.beyond_headline,
            report_before="heldout"),
    Measure("paper_rules", paper_rules.paper_rules_stage, paper_rules.paper_rules_section,
            paper_rules.paper_rules_headline),
    Measure("plans", plan_checks.plans_stage, plan_checks.plans_section,
            plan_checks.plans_headline),
    Measure("kept_all", rule_table.kept_all_stage, rule_table.learned_rules_section),
)


def report_order() -> list[Measure]:
    """The measures in the order the report shows their sections."""
    out = [m for m in MEASURES if not m.report_before]
    for m in MEASURES:
        if m.report_before:
            out.insert([x.name for x in out].index(m.report_before), m)
    return out
