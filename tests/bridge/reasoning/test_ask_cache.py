"""ask's cache of compiled Prolog (bridge/reasoning/asking.py, under
$XDG_CACHE_HOME/pantarhei): a state that is cut short or overwritten is
removed and compiled again, and a cache that is no folder is no cache;
ask answers either way."""
from __future__ import annotations

import shutil
import time

import pytest

from pantarhei.bridge.reasoning.asking import compiled_state

from tests.conftest import run_cli

SWIPL = shutil.which("swipl")


def _ask(cache) -> None:
    r = run_cli("ask", "pour from the side", env={"XDG_CACHE_HOME": str(cache)})
    assert r.code == 0 and "understood: pour_to_side" in r.out and not r.err, r.err


@pytest.mark.skipif(SWIPL is None, reason="needs swipl")
def test_a_damaged_state_is_compiled_again(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    state = compiled_state(SWIPL)
    state.parent.mkdir(parents=True)
    state.write_bytes(b"not a ZIP file")
    _ask(tmp_path)                        # from the sources, compiling again meanwhile
    for _ in range(120):
        if state.is_file() and state.read_bytes()[:2] != b"no":
            break
        time.sleep(0.5)
    assert state.read_bytes() != b"not a ZIP file"
    _ask(tmp_path)


@pytest.mark.skipif(SWIPL is None, reason="needs swipl")
def test_a_cache_that_is_no_folder_is_no_cache(tmp_path):
    (tmp_path / "pantarhei").write_text("a file where the folder would be")
    _ask(tmp_path)
    assert (tmp_path / "pantarhei").read_text() == "a file where the folder would be"
