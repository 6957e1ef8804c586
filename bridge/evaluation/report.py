"""The evaluation report: Markdown with PNG plots and GIFs of pours.

`write(evaluation, out_dir)` writes `README.md` (headline figures against
their targets, the curves, the held-out tables, the paper's three rules, the
plans, the learned rules in words), `evaluation.json`, the plots, the
exploration trace plot and, for the PyBullet oracle, GIFs of the pours
behind three rules.
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Sequence


from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.evaluation.measures import question_misses
from pantarhei.bridge.evaluation.pipeline import Evaluation
from pantarhei.bridge.evaluation.plots import (SET_NAMES, plot_behaviours, plot_expectations,
                                               plot_heldout)
from pantarhei.bridge.files import write_text

#: The targets, as fractions.
TARGETS = {"behaviours_ratio": 2.0, "accuracy": 0.90, "coverage": 0.90, "tree_gap": 0.05,
           "plans": 0.90, "general_coverage": 0.95, "model_gap": 0.02,
           "question_accuracy": 0.95, "contrast_accuracy": 0.85, "calibration": 0.08,
           "coherent": 0.95, "rules_per_expectation": 12}


def _pct(x: float | None) -> str:
    return "n/a" if x is None else f"{100 * x:.1f}%"


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
                     _pct(acc), "at least 90%", acc is not None and acc >= TARGETS["accuracy"]))
        rows.append((f"held-out coverage ({what})", _pct(cov), "at least 90%",
                     cov >= TARGETS["coverage"]))
        gap = None if acc is None or tacc is None else tacc - acc
        rows.append((f"decision tree accuracy, same simulations ({what})",
                     _pct(tacc) if gap is None
                     else f"{_pct(tacc)} ({'+' if gap >= 0 else ''}{100 * gap:.1f} points)",
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
                     _pct(min(rates)), "at least 90% on each",
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
         _pct(q["coverage"]), "at least 95%", q["coverage"] >= TARGETS["general_coverage"]),
        (f"questions: accuracy on the clear keys (defaults only: {_pct(base['accuracy'])})",
         _pct(q["accuracy"]), "at least 95%", q["accuracy"] >= TARGETS["question_accuracy"]),
        (f"questions: accuracy on the {q['contrast']} contrast keys, where the defaults-only "
         f"answer is wrong ({_pct(q['contrast']/max(q['clear'], 1))} of the clear keys; "
         f"covered {_pct(q['contrast_coverage'])})",
         _pct(q["contrast_accuracy"]), "at least 85%",
         q["contrast_accuracy"] >= TARGETS["contrast_accuracy"]),
        (f"calibration: mean |likelihood - share of the pours| (boosting on the same pours "
         f"{_num(cal_g)}, defaults only {_num(cal_b)})", _num(cal),
         "at most 0.08, within 0.02 of boosting",
         cal is not None and cal <= TARGETS["calibration"]
         and (cal_g is None or cal - cal_g <= TARGETS["model_gap"])),
        ("coherent answers: the decided verdicts are a behaviour one of the question's pours "
         "shows", _pct(q["coherent"]), "at least 95%", q["coherent"] >= TARGETS["coherent"]),
        ("general rules per expectation (from curiosity's pours)", f"{n:.1f}", "at most 12",
         n <= TARGETS["rules_per_expectation"]),
    ]


def _num(x: float | None) -> str:
    return "n/a" if x is None else f"{x:.3f}"


def general_section(ev: Evaluation) -> list[str]:
    """The report's section on the general theory."""
    g = ev.general
    if not g:
        return []
    names = load_vocabulary().expectation_names
    L = ["## The general theory, asked what a person would ask", "",
         "General rules are learned from every pour of the exploration and from the learner's "
         "own pours for the ordinary pour and each proposition alone (`bridge/learning/`): a "
         "default per expectation and the contrasts that move it, each with the likelihood of "
         "its head. The shipped theory holds them beside Algorithm 1's rules. Each theory or "
         "model below is asked the questions of `bridge/evaluation/questions.json` "
         f"({len(g['questions'])}: one-phrase questions, then real pours that vary one or two "
         "aspects of the ordinary pour), whose key is the majority of 20 pours sampled for the "
         "question. *clear*: keys where at least 75% of the pours agree. *contrast*: the clear "
         "keys where the defaults-only theory (one verdict per expectation, the majority of all "
         "pours learned from) is wrong. *calibration*: the mean absolute difference between "
         "the likelihood stated and the share of the question's pours, over every key. "
         "*coherent*: the questions whose decided verdicts, taken together, one of their own "
         "pours shows. *boosting*: gradient boosting of the same pours on the 30 parameters, "
         "averaged over each question's meaning: the ceiling of what the pours support. "
         "*uniform*: uniformly random held-out scenes, one pour each.", "",
         "| theory or model | pours | clear: coverage | clear: accuracy | contrast: accuracy "
         "(coverage) | calibration | coherent | uniform: accuracy (coverage) |",
         "|---|---|---|---|---|---|---|---|"]

    def row(label: str, pours: str, e: dict) -> str:
        q, u = e["questions"], e.get("uniform")
        held = f"{_pct(u['accuracy'])} ({_pct(u['coverage'])})" if u else "-"
        return (f"| {label} | {pours} | {_pct(q['coverage'])} | {_pct(q['accuracy'])} | "
                f"{_pct(q['contrast_accuracy'])} ({_pct(q['contrast_coverage'])}) | "
                f"{_num(q['calibration'])} | {_pct(q['coherent'])} | {held} |")

    L.append(row(f"the shipped theory (both layers, {g['shipped']['general_rules']} general rules)",
                 "curiosity", g["shipped"]))
    for method in ("curiosity", "random"):
        e = g[method]
        L.append(row(f"general rules alone ({e['rules_per_expectation']:.1f} per expectation)",
                     f"{method} ({e['pours']})", e))
        L.append(row("gradient boosting", method, e["boosting"]))
        L.append(row("defaults only", method, e["defaults"]))
    q = g["shipped"]["questions"]
    L += ["", f"{q['contrast']} of the {q['clear']} clear keys are contrast keys.", "",
          "The questions, as the shipped theory answers them (the clear keys it gets wrong or "
          "leaves open are named; a contrast key is marked *):", "",
          "| question | clear | contrast | wrong | undecided |", "|---|---|---|---|---|"]
    ans, key, clear = g["shipped"]["answers"], g["key"], g["clear"]
    contrast = g.get("contrast", [[0] * len(names)] * len(clear))

    def named(ks: list[int], i: int) -> str:
        return ", ".join(names[k] + ("*" if contrast[i][k] else "") for k in ks) or "-"

    for i, (qq, (wrong, open_)) in enumerate(zip(g["questions"], question_misses(ans, key, clear))):
        L.append(f"| {qq['text']} | {sum(clear[i])} | {sum(contrast[i])} | {named(wrong, i)} | "
                 f"{named(open_, i)} |")
    L += ["", "The general rules learned from curiosity's pours (likelihood: the share of the "
          "body's pours, the rest an ordinary pour, in which the expectation holds; seen: of "
          "the pours learned from that could have been drawn for the body, how many kept the "
          "head):", "",
          "| rule | when | then | likelihood | seen |", "|---|---|---|---|---|"]
    for r in g["curiosity"]["rules"]:
        when = antecedent_words(r["body"]) if r["body"] else "(an ordinary pour)"
        holds = not r["head"].startswith("neg(")
        lik = r["confidence"] if holds else 1 - r["confidence"]
        L.append(f"| `{r['id']}` | {when} | `{r['head']}` | {lik:.2f} | "
                 f"{r['kept']} of {r['support']} |")
    return L + [""]


def headline_markdown(ev: Evaluation) -> str:
    """The headline figures as a Markdown table (report/README.md's)."""
    lines = ["| measure | measured | target | met |", "|---|---|---|---|"]
    for measure, value, target, met in headline(ev):
        lines.append(f"| {measure} | {value} | {target} | {'yes' if met else '**no**'} |")
    return "\n".join(lines) + "\n"


def load(path: Path | str) -> Evaluation:
    """An evaluation as `write` saved it (evaluation.json)."""
    return Evaluation(**json.loads(Path(path).read_text(encoding="utf-8")))


# -- words ---------------------------------------------------------------------

def antecedent_words(props: Sequence[str]) -> str:
    v = load_vocabulary()
    return "; ".join(v.propositions[p].gloss for p in props)


def consequent_words(row: Sequence[bool]) -> str:
    v = load_vocabulary()
    failing = [e.name.replace("_", " ") for e, holds in zip(v.expectations, row) if not holds]
    if not failing:
        return "everything as expected"
    return "not: " + ", ".join(failing)


def rules_table(ev: Evaluation) -> list[str]:
    lines = ["| antecedent | when (in words) | then | its pours that kept every expectation |",
             "|---|---|---|---|"]
    rows = ev.explored_consequents if ev.explored_consequents is not None else []
    kept = list(ev.kept_all) + [None] * (len(ev.explored) - len(ev.kept_all))
    for i, (a, row, k) in enumerate(zip(ev.explored, rows, kept), start=1):
        lines.append(f"| a{i} | {antecedent_words(a)} | {consequent_words(row)} | {_pct(k)} |")
    return lines


def gif_choices(ev: Evaluation, k: int = 3) -> list[int]:
    """Indices of explored antecedents whose pours to draw: the first of
    each distinct behaviour, then the earliest others."""
    rows = ev.explored_consequents
    if rows is None or not len(rows):
        return []
    picked, seen = [], set()
    for i, r in enumerate(rows):
        if tuple(r) not in seen:
            seen.add(tuple(r))
            picked.append(i)
    picked += [i for i in range(len(rows)) if i not in picked]
    return picked[:k]


def render_gifs(ev: Evaluation, out: Path, k: int = 3) -> list[tuple[int, Path]]:
    from pantarhei.oracle.render import render

    done = []
    for i in gif_choices(ev, k):
        path = out / f"pour_a{i + 1}.gif"
        render(ev.best_samples[i], path, fps=10, width=320, height=240)
        done.append((i, path))
    return done


# -- the report ----------------------------------------------------------------

def write(ev: Evaluation, out: Path, gifs: bool = True, command: str = "make evaluate") -> Path:
    out.mkdir(parents=True, exist_ok=True)
    write_text(out / "evaluation.json", json.dumps(ev.as_dict(), indent=1) + "\n")
    plot_behaviours(ev, out / "behaviours.png")
    plot_heldout(ev, out / "heldout.png")
    if "near" in ev.heldout and ev.heldout["near"]["scenes"]:
        plot_expectations(ev, out / "expectations.png")
    trace = Path(ev.theory).with_suffix(".trace.png")
    if trace.exists():
        shutil.copyfile(trace, out / "exploration.png")
    drawn = render_gifs(ev, out) if gifs and ev.oracle == "pybullet" else []

    s = ev.settings
    L = [f"# Evaluation of `{ev.theory}`", "",
         f"Measured by `{command}` with the {ev.oracle} oracle (version "
         f"{s.get('oracle_version', '?')}). The theory was learned with seed {s.get('seed')}, "
         f"{s.get('explored')} explored antecedents of {s.get('samples')} pours each "
         f"({ev.budget} pours), qualify `{s.get('qualify')}`. All numbers below are in "
         "`evaluation.json`.", "",
         ("The exploration's own pours, simulated here, give exactly the theory's rules."
          if ev.reproduced else
          "**The exploration's own pours, simulated here, do not give all of the theory's "
          "rules**: the oracle here differs from the one that learned it, or the theory was "
          "edited."), "",
         "## Headline", "", headline_markdown(ev).rstrip("\n")]
    L += ["", "## Curiosity against random exploration", "",
          f"Random exploration spends the same budget ({ev.budget} pours) on "
          f"{len(ev.explored)} uniformly random valid antecedents, and builds rules the same way "
          "(equation (1), then qualify). A behaviour is a distinct consequent: the vector of "
          "the nine verdicts.", "", "![distinct behaviours](behaviours.png)", ""]
    if ev.behaviours_seen:
        names = {"curiosity": "curiosity", "random": "random valid antecedents",
                 "prior": "random pours from the prior", "map_elites": "MAP-Elites (pyribs)"}
        L += ["Behaviours seen: distinct nine-verdict vectors among each method's "
              f"{ev.budget} pours, each shown by at least two pours. MAP-Elites searches the "
              "30 parameters (normalised) with a Gaussian emitter and keeps one pour per "
              "verdict vector (pyribs' `CategoricalArchive`); it builds no theory.", "",
              "| method | behaviours seen |", "|---|---|"]
        L += [f"| {names.get(k, k)} | {v} |" for k, v in ev.behaviours_seen.items()]
        L += [""]
    L += general_section(ev)
    L += ["## Held-out scenes", "",
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
                 f"{_pct(h['curiosity_theory']['accuracy'])} | {_pct(h['curiosity_theory']['coverage'])} | "
                 f"{_pct(h['curiosity_tree']['accuracy'])} | {_pct(h['random_theory']['accuracy'])} | "
                 f"{_pct(h['random_theory']['coverage'])} | {_pct(h['random_tree']['accuracy'])} |")
    L += ["", "![held-out accuracy and coverage over the budget](heldout.png)", ""]
    if (out / "expectations.png").exists():
        L += ["![per expectation](expectations.png)", ""]
    L += ["## The paper's three example rules", "",
          "Each scene is asked of the theory as `pantarhei ask` asks it (as given, nothing "
          "assumed), and simulated.", "",
          "A learned rule matches when it concludes the paper's literal from an antecedent that "
          "holds the paper's propositions; what else it needs is listed.", "",
          "| the paper | learned rules for it | the theory says | the oracle: share of pours where the paper's rule holds | the oracle's majority | theory agrees with the oracle |",
          "|---|---|---|---|---|---|"]
    for r in ev.paper_rules:
        scene = ", ".join(f"`{p}`" for p in r["scene"])
        learned = "; ".join(f"`{x['rule']}` (with {', '.join(x['also_needs']) or 'nothing else'})"
                            for x in r["learned"]) or "no rule"
        share = (f"{_pct(r['oracle_share'])} of {r['simulated']}"
                 if r.get("oracle_share") is not None else "not simulated")
        majority = f"`{r['oracle_majority']}`" if r.get("oracle_majority") else "n/a"
        if r.get("oracle_majority") and r["oracle_majority"] != r["literal"]:
            majority += " (the oracle disagrees with the paper)"
        L.append(f"| {r['paper']}: {scene} → `{r['literal']}` | {learned} | "
                 f"`{r['theory_says']}` | {share} | {majority} | "
                 f"{'yes' if r.get('agrees_with_oracle') else '**no**'} |")
    L += ["", "## Plans", "",
          "For each goal set a user would ask, the plan `pantarhei plan` prints: the first of "
          "the theory's plans whose goals were met in at least 90% of the pours that verify "
          "it; then measured again on twice as many fresh pours.", "",
          "| goals | plan (manners chosen) | fresh pours meeting the goals |", "|---|---|---|"]
    for p in ev.plans:
        if "plan" not in p:
            L.append(f"| {p['words']} | none found: {p.get('none', '')} | - |")
            continue
        met = f"{p['met']} of {p['simulated']}" if "simulated" in p else "not simulated"
        L.append(f"| {p['words']} | {', '.join(p['plan']) or '(an ordinary pour)'} | {met} |")
    if not ev.plans:
        L.append("| (not verified) | | |")
    L += ["", "## The learned rules", "",
          "One row per explored antecedent (its nine rules): what fails, in words, and the share "
          "of the pours sampled for it in which every expectation held (a rule states the "
          "majority; the share shows how firmly).", ""]
    L += rules_table(ev)
    if (out / "exploration.png").exists():
        L += ["", "## The exploration", "", "![exploration trace](exploration.png)"]
    if drawn:
        L += ["", "## Pours behind three rules", "",
              "The simulation with the largest weight for each antecedent, rendered by "
              "PyBullet's software renderer.", ""]
        for i, path in drawn:
            L += [f"**a{i + 1}**: {antecedent_words(ev.explored[i])}. Then: "
                  f"{consequent_words(ev.explored_consequents[i])}.", "",
                  f"![pour a{i + 1}]({path.name})", ""]
    L += ["", "## Time and simulations", "", "| stage | pours simulated (not in the store) | seconds |",
          "|---|---|---|"]
    for k, sec in ev.seconds.items():
        L.append(f"| {k} | {ev.simulations.get(k, '')} | {sec} |")
    write_text(out / "README.md", "\n".join(L) + "\n")
    return out / "README.md"
