"""The evaluation's plots (PNG): behaviours over the budget, held-out
coverage and accuracy over the budget, and accuracy per expectation."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.files import pyplot, save_figure

#: How the report names the held-out sets.
SET_NAMES = {"near": "near curiosity's antecedents", "near_random": "near random's antecedents",
             "uniform": "uniformly random"}


def plotted(values) -> list[float]:
    """Values with None (nothing decided) as NaN, which a plot leaves out."""
    return [float("nan") if v is None else v for v in values]


def plot_behaviours(ev: Evaluation, path: Path) -> None:
    plt = pyplot()
    c = ev.curves
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=120)
    ax.plot(c["budget"], c["curiosity"]["behaviours"], marker="o", markersize=3,
            label="curiosity (Algorithm 1)", color="#c0392b")
    ax.plot(c["budget"], c["random"]["behaviours"], marker="s", markersize=3,
            label="random valid antecedents", color="#2c7fb8")
    ax.set_xlabel("simulation budget (pours)")
    ax.set_ylabel("distinct behaviours")
    ax.set_title("Distinct consequents discovered")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    save_figure(fig, path)


def plot_heldout(ev: Evaluation, path: Path) -> None:
    plt = pyplot()
    c = ev.curves
    sets = [k for k in ("near", "near_random", "uniform") if k in ev.heldout]
    fig, axes = plt.subplots(1, len(sets), figsize=(4.4 * len(sets), 3.8), dpi=120, squeeze=False)
    for ax, name in zip(axes[0], sets):
        for method, colour in (("curiosity", "#c0392b"), ("random", "#2c7fb8")):
            acc = plotted(c[method]["accuracy"][name])
            ax.plot(c["budget"], acc, color=colour, label=f"{method}: accuracy where decided")
            ax.plot(c["budget"], c[method]["coverage"][name], color=colour, linestyle="--",
                    label=f"{method}: coverage")
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel("simulation budget (pours)")
        ax.set_title(f"held-out, {SET_NAMES[name]} ({ev.heldout[name]['scenes']})", fontsize=9)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    save_figure(fig, path)


def plot_expectations(ev: Evaluation, path: Path, name: str = "near") -> None:
    plt = pyplot()
    h = ev.heldout[name]
    exps = list(h["curiosity_theory"]["per_expectation"])
    x = np.arange(len(exps))
    th = h["curiosity_theory"]["per_expectation"]
    tree = h["curiosity_tree"]["per_expectation"]
    fig, ax = plt.subplots(figsize=(8, 3.8), dpi=120)
    ax.bar(x - 0.27, plotted(th[e]["accuracy"] for e in exps), 0.27, label="theory: accuracy where decided",
           color="#c0392b")
    ax.bar(x, [th[e]["coverage"] for e in exps], 0.27, label="theory: coverage", color="#f4a582")
    ax.bar(x + 0.27, plotted(tree[e]["accuracy"] for e in exps), 0.27, label="decision tree: accuracy",
           color="#2c7fb8")
    ax.set_xticks(x, [e.replace("_", " ") for e in exps], rotation=35, ha="right", fontsize=7)
    ax.set_ylim(0, 1.05)
    ax.set_title(f"per expectation, held-out {name} scenes")
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    save_figure(fig, path)
