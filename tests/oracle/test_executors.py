"""oracle/executors.py: the executors by name (`make_executor`)."""
from __future__ import annotations

import os

import pytest

from pantarhei.oracle.executors import EXECUTORS, make_executor
from pantarhei.oracle.inline_executor import InlineExecutor
from pantarhei.oracle.local_executor import LocalExecutor


def test_executors_by_name():
    ex = make_executor("local", workers=3)
    assert isinstance(ex, LocalExecutor) and ex.name == "local" and ex.workers == 3
    assert make_executor("local").workers == (os.cpu_count() or 1)
    inline = make_executor("inline", workers=5)
    assert isinstance(inline, InlineExecutor) and inline.workers == 1
    assert set(EXECUTORS) == {"local", "ray", "inline"}


def test_an_unknown_executor_names_the_choices():
    with pytest.raises(ValueError, match=r"unknown executor 'gpu' \(choose local, ray, inline\)"):
        make_executor("gpu")
