"""The knowledge report's targets for the curiosity: each set against the
figure the seeds give (medians, with their range), and whether it is met.

The curiosity is set against random exploration (uniformly random valid
antecedents, `random_valid`), MAP-Elites and uncertainty sampling on the
same seeds, and its theory against gradient boosting of its very pours.
A target whose rows are missing is said to be unmeasured, never met.
"""
from __future__ import annotations

from statistics import median
from typing import Callable, Optional, Sequence

#: The budget of the paper, where every target but knowledge per pour is set.
FULL = 775
#: Knowledge per pour is set at each of these budgets.
BUDGETS = (200, 400, 775)

Summary = Callable[[list[dict], str, str, int], Optional[tuple[float, float, float]]]


def _fig(s: Optional[tuple[float, float, float]], count: bool = False) -> str:
    if s is None:
        return "n/a"
    f = "{:.0f}" if count else "{:.3f}"
    return f"{f.format(s[0])} [{f.format(s[1])}-{f.format(s[2])}]"


def _met(ok: Optional[bool]) -> str:
    return "not measured" if ok is None else ("yes" if ok else "**no**")


def targets(rows: Sequence[dict], summary: Summary) -> list[str]:
    """The section of the report: a heading, a sentence and a table, one
    row per target; none when no row of the curiosity at FULL pours."""
    rows = list(rows)

    def s(key: str, method: str = "curiosity", n: int = FULL):
        return summary(rows, key, method, n)

    if s("contrast_accuracy") is None:
        return []
    out = ["", "## Targets", "",
           f"The curiosity at {FULL} pours unless a budget is named, medians over the seeds "
           "[lowest-highest], each against what is set; a target is met when its median is.",
           "", "| target | curiosity | set against | met |", "|---|---|---|---|"]

    def at_least(label: str, key: str, other: str, count: bool = False, n: int = FULL):
        mine, theirs = s(key, n=n), s(key, other, n)
        ok = None if mine is None or theirs is None else mine[0] >= theirs[0]
        ratio = f" ({mine[0] / theirs[0]:.2f}x)" if mine and theirs and theirs[0] else ""
        out.append(f"| {label} | {_fig(mine, count)} | {other}: {_fig(theirs, count)}{ratio} "
                   f"| {_met(ok)} |")

    def bound(label: str, key: str, limit: float, most: bool, count: bool = False):
        mine = s(key)
        ok = None if mine is None else (mine[0] <= limit if most else mine[0] >= limit)
        out.append(f"| {label} | {_fig(mine, count)} | {'at most' if most else 'at least'} "
                   f"{limit:g} | {_met(ok)} |")

    at_least("behaviours seen", "behaviours", "random_valid", count=True)
    elites = s("behaviours", "map_elites")
    if elites and s("behaviours"):
        out.append(f"| behaviours seen, on the way to MAP-Elites' | {_fig(s('behaviours'), True)} "
                   f"| map_elites: {_fig(elites, True)} "
                   f"({s('behaviours')[0] / elites[0]:.2f}x) | the ratio |")
    at_least("behaviours in the theory", "theory_behaviours", "random_valid", count=True)
    bound("interactions: contrast accuracy", "interaction_contrast_accuracy", 0.90, most=False)
    bound("interactions: calibration", "interaction_calibration", 0.06, most=True)
    bound("interactions: confident errors", "interaction_confident_errors", 0, most=True,
          count=True)
    bound("random scenes: contrast accuracy", "random_contrast_accuracy", 0.95, most=False)
    bound("random scenes: calibration", "random_calibration", 0.05, most=True)
    bound("questions: contrast accuracy", "contrast_accuracy", 0.95, most=False)
    bound("questions: calibration", "calibration", 0.05, most=True)
    gap = [r["calibration"] - r["boosting_calibration"] for r in rows
           if r["method"] == "curiosity" and r["pours"] == FULL
           and r.get("calibration") is not None and r.get("boosting_calibration") is not None]
    if gap:
        mid = median(gap)
        out.append(f"| questions: calibration beside boosting on the same pours (the theory's "
                   f"less boosting's, per seed) | {mid:+.3f} [{min(gap):+.3f} to {max(gap):+.3f}] "
                   f"| boosting: {_fig(s('boosting_calibration'))}; at most +0.01 "
                   f"| {_met(mid <= 0.01)} |")
    else:
        out.append("| questions: calibration beside boosting on the same pours | n/a | at most "
                   "+0.01 | not measured |")
    for n in BUDGETS:
        for key, what in (("askable_contrast_accuracy", "questions"),
                          ("askable_interaction_contrast_accuracy", "interactions")):
            at_least(f"knowledge per pour at {n} pours, every askable body: {what}' contrast "
                     "accuracy", key, "uncertainty", n=n)
    return out
