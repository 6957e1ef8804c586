"""The measure of curiosity against random exploration: the distinct
behaviours each way of choosing pours finds with the same budget (the
consequents of its rules, and the nine-verdict vectors its pours show),
beside two searches that build no theory: random pours from the prior
and MAP-Elites. Its stage, headline row and report section."""
from __future__ import annotations

from pathlib import Path

from pantarhei.oracle.generative import sample

from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.inputs import Inputs, Simulations, tell
from pantarhei.bridge.evaluation.map_elites import behaviours_seen, map_elites
from pantarhei.bridge.evaluation.plots import plot_behaviours
from pantarhei.bridge.exploration.simulation import iteration_seed

#: Curiosity's distinct behaviours (in its theory, and seen in its pours)
#: over random exploration's, at the least.
RATIO = 1.0


def behaviours_stage(ev: Evaluation, inputs: Inputs) -> None:
    """The behaviours each method's pours show (`ev.behaviours_seen`);
    with the baselines, those of the two searches too."""
    ev.behaviours_seen = {method: behaviours_seen(m.S) for method, m in inputs.methods.items()}
    if inputs.opts.baselines:
        ev.behaviours_seen.update(search_baselines(inputs.opts.seed, ev.budget, inputs.samples,
                                                   inputs.run))


def search_baselines(seed: int, budget: int, samples: int, run: Simulations) -> dict[str, int]:
    """Behaviours seen by two searches that build no theory, with the same
    budget: random pours from the prior, and MAP-Elites (pyribs) over the
    30 parameters with the nine verdicts as its cells."""
    prior = run("random pours", sample([], budget, iteration_seed(seed + 7919, 0)))
    tell(f"MAP-Elites: {budget} pours in batches of {samples}")
    qd = map_elites(lambda P: run("MAP-Elites", P, say=False), budget, seed, batch=samples)
    return {"prior": behaviours_seen(prior), "map_elites": behaviours_seen(qd.S)}


def behaviours_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """Two measures, each named as what it counts: the behaviours in each
    theory (the distinct consequents of its explored antecedents,
    `ev.behaviours`, from the curves) and the behaviours its pours show
    (`ev.behaviours_seen`), curiosity's over random exploration's; the
    second also against MAP-Elites', where it was run."""
    def ratio(a: int, b: int) -> float:
        return a / b if b else float("inf")

    cur, rnd = ev.behaviours.get("curiosity", 0), ev.behaviours.get("random", 0)
    rows = [(f"behaviours in the theory at {ev.budget} pours (distinct consequents of the explored "
             "antecedents): curiosity / random valid antecedents",
             f"{cur} / {rnd} = {ratio(cur, rnd):.2f}x", f"at least {RATIO:g}x",
             ratio(cur, rnd) >= RATIO)]
    seen = ev.behaviours_seen
    if "curiosity" in seen and "random" in seen:
        c, r = seen["curiosity"], seen["random"]
        shown = f"{c} / {r} = {ratio(c, r):.2f}x"
        if seen.get("map_elites"):
            shown += f" (MAP-Elites {seen['map_elites']}: {ratio(c, seen['map_elites']):.2f}x)"
        rows.append((f"behaviours seen at {ev.budget} pours (nine-verdict vectors two pours show): "
                     "curiosity / random valid antecedents", shown, f"at least {RATIO:g}x",
                     ratio(c, r) >= RATIO))
    return rows


def behaviours_section(ev: Evaluation, out: Path) -> list[str]:
    """Curiosity against random exploration (and the other searches), with
    the plot of behaviours over the budget."""
    plot_behaviours(ev, out / "behaviours.png")
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
