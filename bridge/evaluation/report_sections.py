"""The report's parts that are no measure's, in Markdown lines: the
opening (how the theory was learned and measured, and the headline), the
pours drawn, and each stage's time and simulations. Each measure's
section is its own (registry.py)."""
from __future__ import annotations

from pathlib import Path

from pantarhei.bridge.evaluation.explored_pours import one_layer
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import antecedent_words, consequent_words
from pantarhei.bridge.evaluation.headline import headline_markdown


def opening(ev: Evaluation, command: str) -> list[str]:
    """The title, how the theory was learned and measured, the headline."""
    s = ev.settings
    return [f"# Evaluation of `{ev.theory}`", "",
            f"Measured by `{command}` with the {ev.oracle} oracle (version "
            f"{s.get('oracle_version', '?')}). The theory was learned with seed {s.get('seed')}, "
            + (f"{s.get('explored')} explored antecedents in batches of {s.get('batch')} pours "
               f"({ev.budget} pours), curiosity `{s.get('curiosity')}`" if one_layer(s) else
               f"{s.get('explored')} explored antecedents of {s.get('batch')} pours each "
               f"({ev.budget} pours), qualify `{s.get('qualify')}`")
            + ". All numbers below are in `evaluation.json`.", "",
            ("The exploration's own pours, simulated here, give exactly the theory's rules."
             if ev.reproduced else
             "**The exploration's own pours, simulated here, do not give all of the theory's "
             "rules**: the oracle here differs from the one that learned it, or the theory was "
             "edited."), "",
            "## Headline", "", headline_markdown(ev).rstrip("\n")]


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
