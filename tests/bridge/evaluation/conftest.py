"""What the evaluation's tests share: a theory learned from the synthetic
oracle (with its store), small enough that an evaluation of it runs in
seconds."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import run_cli


@pytest.fixture(scope="session")
def learned(tmp_path_factory) -> tuple[Path, Path]:
    d = tmp_path_factory.mktemp("learned")
    # without the priors' batch: with it, this small run's last antecedent ends
    # past the last whole batch both methods are compared at
    # (prior_batch(0): an option of explore/1 alone, at the Prolog prompt)
    r = run_cli("prolog", "-g", f"explore([oracle(synthetic), executor(inline), progress(false), "
                f"curiosity(discover), prior_batch(0), budget(6), batch(12), "
                f"out('{d / 't.pl'}'), store('{d / 's.sqlite'}')])")
    assert r.code == 0, r.err
    return d / "t.pl", d / "s.sqlite"
