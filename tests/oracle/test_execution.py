"""oracle/execution.py: how a failed simulation is worded (`error_line`,
`died`)."""
from __future__ import annotations

import signal

from pantarhei.oracle.execution import died, error_line


def test_an_error_is_one_line_of_at_most_500_characters():
    assert error_line(ValueError("pour 3 is bad\nTraceback ...")) == "ValueError: pour 3 is bad"
    assert error_line(KeyError("pour_x")) == "KeyError: 'pour_x'"
    long = error_line(RuntimeError("x" * 2000))
    assert len(long) == 500 and long.startswith("RuntimeError: xxx")


def test_a_dead_worker_is_named_by_its_signal_or_exit_code():
    assert died(-signal.SIGSEGV) == "the worker died (SIGSEGV)"
    assert died(-signal.SIGKILL) == "the worker died (SIGKILL)"
    assert died(3) == "the worker died (exit code 3)"
    assert died(-200) == "the worker died (exit code -200)"      # no such signal
    assert died(None) == "the worker died (exit code None)"
