"""The paper's three example rules (section 3.2), asked of a learned theory
and simulated: does the theory say what the paper says, and what does the
oracle do? The measure's stage, headline row and report section."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import numpy as np

from pantarhei.oracle.generative import sample

from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import pct
from pantarhei.bridge.evaluation.inputs import Inputs
from pantarhei.bridge.exploration.simulation import iteration_seed
from pantarhei.bridge.reasoning import answers
from pantarhei.bridge.theories.model import Theory, complement

#: The paper's three example rules (section 3.2): the scene, the literal it
#: concludes, and the paper's words.
PAPER_RULES = (
    (("pour_to_side",), "neg(no_spill)", "pouring from the side will result in spillage"),
    (("light_liquid",), "neg(liquid_leaves_source)",
     "too light a liquid will not entirely leave the source"),
    (("light_liquid", "end_upright", "end_low"), "neg(liquid_remains_in_destination)",
     "when pouring a lightweight liquid and then righting up the source while low above the "
     "destination, the liquid does not remain in the destination"),
)


def paper_rules(theory: Theory, simulate: Callable[[np.ndarray], np.ndarray], n: int,
                seed: int) -> list[dict[str, Any]]:
    """The paper's three rules asked of the theory as `ask` asks them, the
    learned rules that conclude them, and (with `n` > 0) n pours of each
    scene simulated: the share where the paper's literal holds and whether
    the theory's answer is the oracle's majority."""
    from pantarhei.bridge.reasoning.planning import goals_met

    out, scenes = [], []
    for props, literal, words in PAPER_RULES:
        # learned rules for the literal whose antecedent holds the scene's propositions
        # (and perhaps more: what else each needs is kept)
        rules = [{"rule": r.id, "also_needs": sorted(set(r.body) - set(props))}
                 for r in theory.rules if r.id in theory.learned and r.head == literal
                 and set(props) <= set(r.body)]
        scene = sorted(props)
        said = {o.expectation: o for o in answers.what_happens(theory, scene)}
        expectation = complement(literal) if literal.startswith("neg(") else literal
        o = said[expectation]
        says = {"holds": expectation, "fails": f"neg({expectation})"}.get(o.value, "unknown")
        out.append({"scene": list(props), "literal": literal, "paper_words": words,
                    "learned": rules, "theory_says": says, "rule": o.rule, "reason": o.reason})
        scenes.append(scene)
    if n:
        P = np.vstack([sample(s, n, iteration_seed(seed, 200_000 + i))
                       for i, s in enumerate(scenes)])
        S = simulate(P)
        for i, entry in enumerate(out):
            rows = S[i * n:(i + 1) * n]
            rows = rows[np.all(np.isfinite(rows), axis=1)]
            share = float(goals_met(rows, [entry["literal"]]).mean()) if len(rows) else None
            majority = None if share is None else (entry["literal"] if share >= 0.5
                                                   else complement(entry["literal"]))
            entry.update(simulated=int(len(rows)), oracle_share=share, oracle_majority=majority,
                         agrees_with_oracle=majority is not None and entry["theory_says"] == majority)
    return out


def paper_rules_stage(ev: Evaluation, inputs: Inputs) -> None:
    """The paper's rules asked of the learned theory, `--paper-samples`
    pours of each simulated: `ev.paper_rules`."""
    ev.paper_rules = paper_rules(inputs.learned.theory,
                                 lambda X: inputs.run("the paper's rules", X),
                                 inputs.opts.paper_samples, inputs.opts.seed)


def paper_rules_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """Whether the theory says what the oracle's majority shows, for every
    one of the paper's rules simulated (no row when none was)."""
    asked = [r for r in ev.paper_rules if r.get("oracle_majority")]
    if not asked:
        return []
    agree = sum(bool(r.get("agrees_with_oracle")) for r in asked)
    return [("the paper's three questions answered as the oracle's majority shows",
             f"{agree} of {len(asked)}", "all", agree == len(asked))]


def paper_rules_section(ev: Evaluation, out: Path) -> list[str]:
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
        L.append(f"| {r['paper_words']}: {scene} → `{r['literal']}` | {learned} | "
                 f"`{r['theory_says']}` | {share} | {majority} | "
                 f"{'yes' if r.get('agrees_with_oracle') else '**no**'} |")
    return L
