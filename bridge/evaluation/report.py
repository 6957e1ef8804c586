"""The evaluation report: Markdown with PNG plots and GIFs of pours.

`write(evaluation, out_dir)` writes `README.md` (headline figures against
their targets, the curves, the held-out tables, the paper's three rules, the
plans, the learned rules in words), `evaluation.json`, the plots, the
exploration trace plot and, for the PyBullet oracle, GIFs of the pours
behind three rules. The headline is `headline`'s; each measure writes its
section (and its plots), in the report's order of `registry`; the opening,
the pours drawn and the time are `report_sections`'. `load` reads an
evaluation.json back, so that a report can be written again without
measuring.
"""
from __future__ import annotations

import json
from pathlib import Path

from pantarhei.bridge.evaluation import report_sections as sections
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.registry import report_order
from pantarhei.bridge.files import write_text
from pantarhei.oracle.base import REAL_ORACLES


def load(path: Path | str) -> Evaluation:
    """An evaluation as `write` saved it (evaluation.json)."""
    return Evaluation.from_dict(json.loads(Path(path).read_text(encoding="utf-8")))


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


#: The files the report writes into its folder, besides its pours' GIFs
#: (pour_a<i>.gif, i an explored antecedent's number).
FILES = ("README.md", "evaluation.json", "behaviours.png", "heldout.png", "expectations.png",
         "exploration.png")


def render_gifs(ev: Evaluation, out: Path, k: int = 3) -> list[tuple[int, Path]]:
    """Render the pours of `gif_choices` as GIFs in `out`: (index, path) each."""
    from pantarhei.oracle.render import render

    done = []
    for i in gif_choices(ev, k):
        path = out / f"pour_a{i + 1}.gif"
        render(ev.best_samples[i], path, fps=10, width=320, height=240)
        done.append((i, path))
    return done


def write(ev: Evaluation, out: Path, gifs: bool = True, command: str = "make evaluate") -> Path:
    """Write the report into `out`: evaluation.json, the GIFs, README.md
    and each measure's plots; returns README.md's path."""
    out.mkdir(parents=True, exist_ok=True)
    write_text(out / "evaluation.json", json.dumps(ev.as_dict(), indent=1) + "\n")
    drawn = render_gifs(ev, out) if gifs and ev.oracle in REAL_ORACLES else []
    L = sections.opening(ev, command)
    for measure in report_order():
        L += measure.section(ev, out)
    L += sections.pours_section(ev, drawn) + sections.time_section(ev)
    write_text(out / "README.md", "\n".join(L) + "\n")
    return out / "README.md"
