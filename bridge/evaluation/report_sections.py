"""The report's sections on what the exploration found, in Markdown lines:
how the theory was measured, curiosity against random exploration, the
held-out scenes, the paper's three rules, the plans, the learned rules in
words, the pours drawn, time and simulations; and antecedents and
consequents in words."""
from __future__ import annotations

from pathlib import Path
from typing import Sequence

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.evaluation.headline import headline_markdown, pct
from pantarhei.bridge.evaluation.pipeline import Evaluation


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
        lines.append(f"| a{i} | {antecedent_words(a)} | {consequent_words(row)} | {pct(k)} |")
    return lines


def opening(ev: Evaluation, command: str) -> list[str]:
    """The title, how the theory was learned and measured, the headline."""
    s = ev.settings
    return [f"# Evaluation of `{ev.theory}`", "",
            f"Measured by `{command}` with the {ev.oracle} oracle (version "
            f"{s.get('oracle_version', '?')}). The theory was learned with seed {s.get('seed')}, "
            + (f"{s.get('explored')} explored antecedents in batches of {s.get('batch')} pours "
               f"({ev.budget} pours), curiosity `learn`" if s.get("curiosity") == "learn" else
               f"{s.get('explored')} explored antecedents of {s.get('batch')} pours each "
               f"({ev.budget} pours), qualify `{s.get('qualify')}`")
            + ". All numbers below are in `evaluation.json`.", "",
            ("The exploration's own pours, simulated here, give exactly the theory's rules."
             if ev.reproduced else
             "**The exploration's own pours, simulated here, do not give all of the theory's "
             "rules**: the oracle here differs from the one that learned it, or the theory was "
             "edited."), "",
            "## Headline", "", headline_markdown(ev).rstrip("\n")]


def against_random(ev: Evaluation) -> list[str]:
    """Curiosity against random exploration (and the other searches)."""
    L = ["", "## Curiosity against random exploration", "",
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
    return L


def heldout_section(ev: Evaluation, out: Path) -> list[str]:
    """The held-out scenes: the theories and the decision trees."""
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


def paper_rules_section(ev: Evaluation) -> list[str]:
    """The paper's three example rules: the learned rules for them, the
    theory's answer and the oracle's."""
    L = ["## The paper's three example rules", "",
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
        share = (f"{pct(r['oracle_share'])} of {r['simulated']}"
                 if r.get("oracle_share") is not None else "not simulated")
        majority = f"`{r['oracle_majority']}`" if r.get("oracle_majority") else "n/a"
        if r.get("oracle_majority") and r["oracle_majority"] != r["literal"]:
            majority += " (the oracle disagrees with the paper)"
        L.append(f"| {r['paper']}: {scene} → `{r['literal']}` | {learned} | "
                 f"`{r['theory_says']}` | {share} | {majority} | "
                 f"{'yes' if r.get('agrees_with_oracle') else '**no**'} |")
    return L


def plans_section(ev: Evaluation) -> list[str]:
    """The plans for the goal sets, measured on fresh pours."""
    L = ["", "## Plans", "",
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
    return L


def learned_rules_section(ev: Evaluation, out: Path) -> list[str]:
    """Algorithm 1's rules in words, and the exploration's trace."""
    L = ["", "## The learned rules", "",
         "One row per explored antecedent (its nine rules): what fails, in words, and the share "
         "of the pours sampled for it in which every expectation held (a rule states the "
         "majority; the share shows how firmly).", ""]
    L += rules_table(ev)
    if (out / "exploration.png").exists():
        L += ["", "## The exploration", "", "![exploration trace](exploration.png)"]
    return L


def pours_section(ev: Evaluation, drawn: list[tuple[int, Path]]) -> list[str]:
    """The pours drawn as GIFs, each with its antecedent in words."""
    if not drawn:
        return []
    L = ["", "## Pours behind three rules", "",
         "The simulation with the largest weight for each antecedent, rendered by "
         "PyBullet's software renderer.", ""]
    for i, path in drawn:
        L += [f"**a{i + 1}**: {antecedent_words(ev.explored[i])}. Then: "
              f"{consequent_words(ev.explored_consequents[i])}.", "",
              f"![pour a{i + 1}]({path.name})", ""]
    return L


def time_section(ev: Evaluation) -> list[str]:
    """Each stage's seconds and the pours it simulated."""
    L = ["", "## Time and simulations", "", "| stage | pours simulated (not in the store) | seconds |",
         "|---|---|---|"]
    for k, sec in ev.seconds.items():
        L.append(f"| {k} | {ev.simulations.get(k, '')} | {sec} |")
    return L
