"""Verdicts (bridge/verdicts.py): a score holds above the threshold of
theory/defaults.pl, and the answer codes are three distinct values; the
learning package, which reads both, depends on nothing of the evaluation."""
from __future__ import annotations

import ast
from pathlib import Path

import numpy as np

from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN, verdicts
from pantarhei.theory import defaults

BRIDGE = Path(__file__).resolve().parents[2] / "bridge"


def imported_modules(path: Path) -> set[str]:
    """The modules a Python file imports (at any depth: inside functions too)."""
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module:
            out.add(node.module)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return out


def test_a_score_holds_above_the_threshold_of_the_defaults():
    t = float(defaults()["verdict_threshold"])
    v = verdicts(np.array([[t + 0.01, t, t - 0.01, np.nan]]))
    assert v.tolist() == [[True, False, False, False]]


def test_the_answer_codes_are_distinct():
    assert len({HOLDS, FAILS, UNKNOWN}) == 3


def test_the_learning_package_imports_nothing_of_the_evaluation():
    found = {p.name: sorted(m for m in imported_modules(p)
                            if m.startswith("pantarhei.bridge.evaluation"))
             for p in sorted((BRIDGE / "learning").glob("*.py"))}
    assert {k: v for k, v in found.items() if v} == {}


def test_an_import_of_the_evaluation_is_found_inside_a_function(tmp_path):
    f = tmp_path / "m.py"
    f.write_text("def g():\n    from pantarhei.bridge.evaluation.measures import verdicts\n")
    assert "pantarhei.bridge.evaluation.measures" in imported_modules(f)
