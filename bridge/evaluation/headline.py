"""The evaluation's headline: each headline figure against its target and
whether it is met (rows, and the Markdown table report/README.md opens
with). The rows and their targets are each measure's (registry.py)."""
from __future__ import annotations

from pantarhei.bridge.evaluation import registry
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.registry import Row


def headline(ev: Evaluation) -> list[Row]:
    """(measure, measured, target, met) rows: every measure's, in the
    order of `registry.MEASURES`."""
    return [row for measure in registry.MEASURES for row in measure.headline(ev)]


def headline_markdown(ev: Evaluation) -> str:
    """The headline figures as a Markdown table (report/README.md's)."""
    lines = ["| measure | measured | target | met |", "|---|---|---|---|"]
    for measure, value, target, met in headline(ev):
        lines.append(f"| {measure} | {value} | {target} | {'yes' if met else '**no**'} |")
    return "\n".join(lines) + "\n"
