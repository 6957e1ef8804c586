"""The evaluation's headline: each headline figure against its target and
whether it is met (rows, and the Markdown table report/README.md opens
with); and how the report writes a share or a number."""
from __future__ import annotations

from pantarhei.bridge.evaluation.pipeline import Evaluation

#: The targets, as fractions.
TARGETS = {"behaviours_ratio": 2.0, "accuracy": 0.90, "coverage": 0.90, "tree_gap": 0.05,
           "plans": 0.90, "general_coverage": 0.95, "model_gap": 0.02,
           "question_accuracy": 0.95, "contrast_accuracy": 0.85, "calibration": 0.08,
           "coherent": 0.95, "rules_per_expectation": 12}


def pct(x: float | None) -> str:
    """A share as a percentage ("n/a" for none)."""
    return "n/a" if x is None else f"{100 * x:.1f}%"


def num(x: float | None) -> str:
    """A number to three decimals ("n/a" for none)."""
    return "n/a" if x is None else f"{x:.3f}"


def headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """(measure, measured, target, met) rows."""
    rows = []
    cur, rnd = ev.behaviours.get("curiosity", 0), ev.behaviours.get("random", 0)
    ratio = cur / rnd if rnd else float("inf")
    rows.append((f"distinct behaviours at {ev.budget} pours: curiosity / random",
                 f"{cur} / {rnd} = {ratio:.2f}x", "at least 2x", ratio >= TARGETS["behaviours_ratio"]))
    for name in ("near", "uniform"):
        h = ev.heldout.get(name)
        if not h:
            continue
        th, tree = h["curiosity_theory"], h["curiosity_tree"]
        what = {"near": "near explored scenes", "uniform": "uniformly random scenes"}[name]
        # an accuracy is None where nothing was decided
        acc, cov, tacc = th["accuracy"], th["coverage"], tree["accuracy"]
        rows.append((f"held-out accuracy where the theory decides ({what}, {h['scenes']} scenes)",
                     pct(acc), "at least 90%", acc is not None and acc >= TARGETS["accuracy"]))
        rows.append((f"held-out coverage ({what})", pct(cov), "at least 90%",
                     cov >= TARGETS["coverage"]))
        gap = None if acc is None or tacc is None else tacc - acc
        rows.append((f"decision tree accuracy, same simulations ({what})",
                     pct(tacc) if gap is None
                     else f"{pct(tacc)} ({'+' if gap >= 0 else ''}{100 * gap:.1f} points)",
                     "theory within 5 points", gap is not None and gap <= TARGETS["tree_gap"]))
    rows += general_headline(ev)
    asked = [r for r in ev.paper_rules if r.get("oracle_majority")]
    if asked:
        agree = sum(bool(r.get("agrees_with_oracle")) for r in asked)
        rows.append(("the paper's three questions answered as the oracle's majority shows",
                     f"{agree} of {len(asked)}", "all", agree == len(asked)))
    rates = [p["met"] / p["simulated"] if p.get("simulated") else 0.0 for p in ev.plans]
    if rates:
        rows.append((f"plans for {len(rates)} goal sets a user would ask, measured on fresh pours: "
                     f"the lowest share meeting the goals",
                     pct(min(rates)), "at least 90% on each",
                     min(rates) >= TARGETS["plans"]))
    return rows


def general_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """The general theory's rows, on the questions a person would type:
    the shipped theory beside the defaults-only theory and gradient
    boosting of the same pours; accuracy on the contrast keys apart."""
    g = ev.general
    if not g:
        return []
    q = g["shipped"]["questions"]
    base = g["curiosity"]["defaults"]["questions"]
    gbm = g["curiosity"]["boosting"]["questions"]
    n = g["curiosity"]["rules_per_expectation"]
    cal, cal_g, cal_b = q["calibration"], gbm["calibration"], base["calibration"]
    return [
        (f"questions ({len(g['questions'])}): coverage of the {q['clear']} clear keys",
         pct(q["coverage"]), "at least 95%", q["coverage"] >= TARGETS["general_coverage"]),
        (f"questions: accuracy on the clear keys (defaults only: {pct(base['accuracy'])})",
         pct(q["accuracy"]), "at least 95%", q["accuracy"] >= TARGETS["question_accuracy"]),
        (f"questions: accuracy on the {q['contrast']} contrast keys, where the defaults-only "
         f"answer is wrong ({pct(q['contrast']/max(q['clear'], 1))} of the clear keys; "
         f"covered {pct(q['contrast_coverage'])})",
         pct(q["contrast_accuracy"]), "at least 85%",
         q["contrast_accuracy"] >= TARGETS["contrast_accuracy"]),
        (f"calibration: mean |likelihood - share of the pours| (boosting on the same pours "
         f"{num(cal_g)}, defaults only {num(cal_b)})", num(cal),
         "at most 0.08, within 0.02 of boosting",
         cal is not None and cal <= TARGETS["calibration"]
         and (cal_g is None or cal - cal_g <= TARGETS["model_gap"])),
        ("coherent answers: the decided verdicts are a behaviour one of the question's pours "
         "shows", pct(q["coherent"]), "at least 95%", q["coherent"] >= TARGETS["coherent"]),
        ("general rules per expectation (from curiosity's pours)", f"{n:.1f}", "at most 12",
         n <= TARGETS["rules_per_expectation"]),
    ]


def headline_markdown(ev: Evaluation) -> str:
    """The headline figures as a Markdown table (report/README.md's)."""
    lines = ["| measure | measured | target | met |", "|---|---|---|---|"]
    for measure, value, target, met in headline(ev):
        lines.append(f"| {measure} | {value} | {target} | {'yes' if met else '**no**'} |")
    return "\n".join(lines) + "\n"
