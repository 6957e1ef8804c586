"""bridge/evaluation/registry.py: every measure is named once, with its
meaning in docs/evaluation.md; and a measure named in the registry, and
nowhere else, is measured by the evaluation, kept in its JSON, headlined
and reported."""
from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

from pantarhei.bridge.evaluation import registry
from pantarhei.bridge.evaluation.explored_pours import exploration_draws, read_learned
from pantarhei.bridge.evaluation.pipeline import Evaluation, EvaluationOptions, Inputs, evaluate
from pantarhei.bridge.evaluation.registry import Measure, report_order
from pantarhei.bridge.evaluation.report import load, write

DOCS = Path(__file__).resolve().parents[3] / "docs" / "evaluation.md"


def test_every_measure_has_its_meaning_in_the_docs():
    text = DOCS.read_text(encoding="utf-8")
    start = text.index("## The measures\n")
    listed = text[start:text.index("\n## ", start)]
    for m in registry.MEASURES:
        assert re.search(rf"^- \*\*[^*]+\*\* \(`{re.escape(m.name)}`\)\.", listed, re.M), m.name


def test_each_measure_is_named_once_by_its_figures_and_reported_once():
    names = [m.name for m in registry.MEASURES]
    assert len(set(names)) == len(names)
    keys = Evaluation("t", "synthetic", {}, 0).as_dict()
    assert all(name in keys for name in names)
    assert sorted(m.name for m in report_order()) == sorted(names)


# -- a measure added: the exploration's pours, counted ----------------------------

def counted_stage(ev: Evaluation, inputs: Inputs) -> None:
    ev.figures["exploration_pours"] = len(inputs.methods["curiosity"].P)


def counted_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    n = ev.figures["exploration_pours"]
    return [("pours the exploration simulated", str(n), "at most 10000", n <= 10000)]


def counted_section(ev: Evaluation, out: Path) -> list[str]:
    return ["", "## The exploration's pours", "",
            f"The exploration simulated {ev.figures['exploration_pours']} pours."]


def test_a_measure_named_in_the_registry_is_measured_kept_headlined_and_reported(
        learned, tmp_path, monkeypatch):
    theory, store = learned
    shutil.copyfile(store, tmp_path / "s.sqlite")       # the other tests' store stays as it was
    counted = Measure("exploration_pours", counted_stage, counted_section, counted_headline)
    monkeypatch.setattr(registry, "MEASURES", (counted,))
    ev = evaluate(EvaluationOptions(theory=theory, store=tmp_path / "s.sqlite", scenes=5, seed=3,
                                    verify=0, paper_samples=0, executor="inline", progress=False,
                                    baselines=False))
    n = len(exploration_draws(read_learned(theory))[0])
    # the registered stage alone ran, after the pours every measure reads
    assert list(ev.simulations) == ["exploration", "random exploration"]
    text = write(ev, tmp_path / "rep", gifs=False).read_text(encoding="utf-8")
    saved = json.loads((tmp_path / "rep" / "evaluation.json").read_text(encoding="utf-8"))
    assert saved["exploration_pours"] == n
    assert list(saved)[-3:] == ["exploration_pours", "simulations", "seconds"]
    assert load(tmp_path / "rep" / "evaluation.json").figures == {"exploration_pours": n}
    assert f"| pours the exploration simulated | {n} | at most 10000 | yes |" in text
    assert f"## The exploration's pours\n\nThe exploration simulated {n} pours.\n" in text
