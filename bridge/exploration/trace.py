"""The exploration's trace: one JSON line per explored antecedent (what it
added to A_new, the steepest plane, ...), and its plot. Timings are kept
apart from the trace (see loop.explore), so that the same run writes the
same trace."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Sequence

from pantarhei.bridge.files import pyplot, save_figure, write_text


def trace_path(out: Path) -> Path:
    return out.with_suffix(".trace.jsonl")


def plot_path(out: Path) -> Path:
    return out.with_suffix(".trace.png")


def append_trace(out: Path, entry: dict) -> None:
    with open(trace_path(out), "a", encoding="utf-8") as f:
        f.write(json.dumps(entry, sort_keys=True) + "\n")


def write_trace(path: Path, trace: Sequence[dict]) -> None:
    """The whole trace as JSON lines, written atomically."""
    write_text(path, "".join(json.dumps(entry, sort_keys=True) + "\n" for entry in trace))


def plot_trace(path: Path, trace: Sequence[dict], settings: dict | None = None) -> None:
    """|A_new| after each iteration, and the antecedents each added (PNG)."""
    plt = pyplot()
    it = [t["iteration"] for t in trace]
    added = [len(t["added"]) for t in trace]
    size = [t["a_new"] for t in trace]
    fig, ax = plt.subplots(figsize=(7, 3.6), dpi=120)
    ax.bar(it, added, color="#8fb3d9", label="new antecedents")
    ax.plot(it, size, color="#c0392b", marker="o", markersize=3, label="|A_new|")
    ax.set_xlabel("iteration (explored antecedent)")
    ax.set_ylabel("antecedents")
    title = "Curiosity-driven exploration"
    if settings:
        title += f" ({settings.get('oracle')} oracle, seed {settings.get('seed')})"
    ax.set_title(title)
    ax.legend(loc="upper right")
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    save_figure(fig, path)
