"""The exploration's trace: one JSON line per explored antecedent (what it
added to A_new, the steepest plane, ...), and its plot. Timings are kept
apart from the trace (see loop.explore), so that the same run writes the
same trace; its numbers keep DIGITS significant digits, so that it is the
same on every machine (`rounded`)."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Mapping, Sequence

from pantarhei.bridge.files import pyplot, save_figure, write_text


#: Significant digits of the trace's numbers. Machines whose linear algebra
#: takes other code paths differ in a float's last bits (a plane's component
#: was 0.2897128232031609 on one and 0.28971282320316083 on another).
DIGITS = 10


def rounded(value: Any) -> Any:
    """`value` with every float in it (in lists and dicts too) rounded to
    DIGITS significant digits."""
    if isinstance(value, float):
        return float(f"{value:.{DIGITS}g}")
    if isinstance(value, dict):
        return {k: rounded(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [rounded(v) for v in value]
    return value


def explored_whole(entry: Mapping[str, Any]) -> bool:
    """Whether a trace line's antecedent was explored as a whole (the
    learning curiosity's `whole_every`), so that it is no rule's body
    (theory/curiosity/writer.pl)."""
    return entry.get("via") == "whole"


def trace_path(out: Path) -> Path:
    return out.with_suffix(".trace.jsonl")


def plot_path(out: Path) -> Path:
    return out.with_suffix(".trace.png")


def require_distinct_outputs(store: Path, out: Path, dfl: bool = False,
                             names: tuple[str, str] = ("--store", "--out")) -> None:
    """UserError when the store, the learned theory, its trace, the trace's
    plot (or, with `dfl`, the theory's DFL twin) would be the same file:
    one would overwrite another. Checked before anything is written, by
    explore and demo (`names`: their flags) and by explore/1 at the Prolog
    prompt (its options) alike."""
    from pantarhei.bridge.files import require_distinct

    s, o = names
    roles = {s: store, o: out, f"{o}'s trace": trace_path(out), f"{o}'s trace plot": plot_path(out)}
    if dfl:
        roles[f"{o}'s DFL version"] = out.with_suffix(".dfl")
    require_distinct(roles)


def append_trace(out: Path, entry: dict) -> None:
    with open(trace_path(out), "a", encoding="utf-8") as f:
        f.write(json.dumps(entry, sort_keys=True) + "\n")


def write_trace(path: Path, trace: Sequence[dict]) -> None:
    """The whole trace as JSON lines, written atomically."""
    write_text(path, "".join(json.dumps(entry, sort_keys=True) + "\n" for entry in trace))


def probe_means(trace: Sequence[dict]) -> list[float | None]:
    """After each iteration, the mean score of the candidates probed so far
    (each the chance that its batch gives a new, reproducible consequent);
    None before the first probe."""
    out: list[float | None] = []
    found, probed = 0.0, 0
    for t in trace:
        probes = t.get("probes") or []
        probed += len(probes)
        found += sum(float(p["score"]) for p in probes)
        out.append(found / probed if probed else None)
    return out


def plot_trace(path: Path, trace: Sequence[dict], oracle: str | None = None,
               seed: int | None = None) -> None:
    """|A_new| after each iteration and the antecedents each added (PNG);
    for a run with probes also their mean score so far, the evidence that
    something new is still to be found. The title names the run's oracle
    and seed when given."""
    plt = pyplot()
    it = [t["iteration"] for t in trace]
    added = [len(t["added"]) for t in trace]
    size = [t["a_new"] for t in trace]
    fig, ax = plt.subplots(figsize=(7, 3.6), dpi=120)
    bars = ax.bar(it, added, color="#8fb3d9", label="new antecedents")
    (line,) = ax.plot(it, size, color="#c0392b", marker="o", markersize=3, label="|A_new|")
    handles = [bars, line]
    ax.xaxis.get_major_locator().set_params(integer=True)
    ax.set_xlabel("iteration (explored antecedent)")
    ax.set_ylabel("antecedents")
    share = probe_means(trace)
    if any(v is not None for v in share):
        right = ax.twinx()
        (probes,) = right.plot(it, [float("nan") if v is None else v for v in share],
                               color="#27ae60", linestyle="--",
                               label="probes' mean score so far (right)")
        # room above the lines for the legend, on both axes alike
        ax.set_ylim(0, 1.45 * max(size + added + [1]))
        right.set_ylim(0, 1.45)
        right.set_yticks([0, 0.25, 0.5, 0.75, 1])
        right.set_ylabel("mean probe score")
        handles.append(probes)
    title = "Curiosity-driven exploration"
    if oracle is not None:
        title += f" ({oracle} oracle, seed {seed})"
    ax.set_title(title)
    ax.legend(handles=handles, loc="upper right", fontsize="small")
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    save_figure(fig, path)
