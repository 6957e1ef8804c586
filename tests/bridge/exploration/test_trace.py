"""The exploration's trace (bridge/exploration/trace.py): its numbers
rounded alike on every machine, written whole or a line at a time as the
same JSON lines, the probes' running mean, and its plot."""
from __future__ import annotations

import json

from pantarhei.bridge.exploration.trace import (append_trace, plot_path, plot_trace,
                                                probe_means, rounded, trace_path, write_trace)

TRACE = [{"iteration": 1, "a_new": 3, "added": [["pour_low"]], "probes": []},
         {"iteration": 2, "a_new": 4, "added": [], "probes": [{"score": 0.5}, {"score": 0.25}]},
         {"iteration": 3, "a_new": 2, "added": []},
         {"iteration": 4, "a_new": 0, "added": [], "probes": [{"score": 1.0}]}]


def test_floats_are_rounded_to_ten_digits_wherever_they_are():
    assert rounded(0.2897128232031609) == rounded(0.28971282320316083) == 0.2897128232
    assert rounded({"a": [1.23456789012345, (2, "x")], "n": 3}) == \
        {"a": [1.23456789, [2, "x"]], "n": 3}


def test_the_trace_written_whole_or_line_by_line_is_the_same_file(tmp_path):
    out = tmp_path / "theory.pl"
    assert trace_path(out).name == "theory.trace.jsonl"
    assert plot_path(out).name == "theory.trace.png"
    for entry in TRACE:
        append_trace(out, entry)
    by_line = trace_path(out).read_bytes()
    write_trace(trace_path(out), TRACE)
    assert trace_path(out).read_bytes() == by_line
    assert [json.loads(x) for x in by_line.decode().splitlines()] == TRACE


def test_probe_means_run_over_every_probe_so_far():
    assert probe_means(TRACE) == [None, 0.375, 0.375, 1.75 / 3]


def test_the_plot_is_a_png(tmp_path):
    path = tmp_path / "t.trace.png"
    plot_trace(path, TRACE, "synthetic", 3)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
