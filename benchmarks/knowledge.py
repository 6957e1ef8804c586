"""Knowledge per pour: what a theory learned from the pours each method
chooses knows, at the same total of pours, every pour counted.

    python -m benchmarks knowledge                        # PyBullet, seeds 101-105 (make bench)
    python -m benchmarks.knowledge --oracle synthetic --seeds 101,102 --budgets 40,80

The methods, each spending the same budget on pours of its own choice and
learning the same kind of theory from its own pours only (no pours of the
learner's own; `--learner`, by default bridge/learning/generalize.py,
likelihoods from every pour pooled):

* `curiosity`: the learning curiosity (`explore --curiosity learn`); the
  rules' bodies are the antecedents it explored;
* `random`: the ordinary pour, then uniformly random antecedents of what a
  question says (a proposition or a valid pair, the antecedents the
  curiosity chooses among), a batch of the curiosity's size each; the
  rules' bodies are those antecedents;
* `random_valid`: uniformly random valid antecedents of the whole
  vocabulary, a batch of the curiosity's size each (random exploration,
  as `pantarhei evaluate` runs it); the rules' bodies are those
  antecedents;
* `designed`: the one-at-a-time experiment: the ordinary pour and each
  proposition alone, one pour each in turn, round after round; the rules'
  bodies are those;
* `uncertainty`: uncertainty sampling on a boosting model of the pours so
  far: from pours of the ordinary pour, each batch the pours (among 256
  drawn for random propositions and pairs) whose nine verdicts the model
  is least sure of; the rules' bodies are every askable one;
* `map_elites`: MAP-Elites' pours (pyribs, bridge/evaluation/map_elites.py);
  the rules' bodies are every askable one.

Each method's pours are one sequence, and the theory at a budget is learned
from its first pours (for the curiosity: the pours of the steps that fit,
as a run with that budget explores them). The theories are asked the
questions of bridge/evaluation/questions.json, keyed by 20 pours each (seed
1, as `pantarhei evaluate` draws them): accuracy on the clear keys, on the
contrast keys (the clear keys where the defaults-only answer, the majority
of the questions' pours, is wrong), calibration and coherence; beside them
the distinct behaviours each method's pours show (nine-verdict vectors at
least two pours show), and gradient boosting of the same pours, the
ceiling of what they support. Medians over the seeds with their range; a
table, the curiosity's targets (benchmarks/knowledge_targets.py) and a
plot of the learning curves go to `--report` (report/), and every
row measured to `knowledge-ORACLE.json` beside them, after each seed: a
later run measures only the methods, seeds and budgets that file lacks
(`--fresh`: this run's again, the others kept), so an interrupted run
loses nothing. Every pour goes through the store (pantarhei.sqlite), so a
second run simulates nothing.
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Callable, Sequence

import numpy as np

from benchmarks.knowledge_targets import targets
from benchmarks.knowledge_methods import (METHODS, Chosen, curiosity, designed, map_elites_pours,
                                          random_bodies, random_valid, uncertainty)

MEASURES = (("contrast_accuracy", "contrast accuracy"), ("accuracy", "clear accuracy"),
            ("calibration", "calibration"), ("coherent", "coherent"),
            ("askable_contrast_accuracy", "contrast accuracy, every askable body"),
            ("interaction_contrast_accuracy", "interactions: contrast accuracy"),
            ("interaction_calibration", "interactions: calibration"),
            ("interaction_confident_errors", "interactions: confident errors"),
            ("askable_interaction_contrast_accuracy",
             "interactions: contrast accuracy, every askable body"),
            ("random_contrast_accuracy", "random scenes: contrast accuracy"),
            ("random_calibration", "random scenes: calibration"),
            ("boosting_contrast_accuracy", "boosting on the same pours: contrast accuracy"),
            ("boosting_calibration", "boosting on the same pours: calibration"),
            ("theory_behaviours", "behaviours in the theory"))
#: The measures that are counts.
COUNTS = ("behaviours", "theory_behaviours", "interaction_confident_errors")
#: The measures printed as each row is measured.
SHOWN = (("contrast_accuracy", "contrast"), ("calibration", "calibration"),
         ("interaction_contrast_accuracy", "interactions"),
         ("interaction_confident_errors", "confident errors"),
         ("random_contrast_accuracy", "random scenes"), ("behaviours", "behaviours seen"),
         ("theory_behaviours", "in the theory"))


def measure(oracle: str, seeds: Sequence[int], budgets: Sequence[int], store: Path,
            methods: Sequence[str] = METHODS,
            done: Callable[[list[dict]], None] | None = None,
            known: Sequence[dict] = (), settings: dict | None = None,
            executor: dict | None = None, learner: str | None = None) -> list[dict]:
    """One row per method, seed and budget: the measures of its theory on
    the questions, and the behaviours its pours show; the rows of `known`
    are kept and not measured again; `done` is given the rows so far after
    each seed; `settings` are the curiosity's options other than their
    defaults; `executor` the executor options of every pour (executor,
    workers, ray_address: as explore's); `learner` the learner every
    method's theory is learned by (None: the option table's default)."""
    from pantarhei.bridge.evaluation.measures import (contrast_keys, defaults_only, question_key,
                                                      question_shares)
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.evaluation.question_sets import (Keyed, interaction_questions, keyed,
                                                           random_scenes)
    from pantarhei.bridge.evaluation.questions import question_pours, questions
    from pantarhei.bridge.exploration.simulation import open_simulator
    from pantarhei.theory import defaults

    asked = questions()
    how = {k: v for k, v in (executor or {}).items() if v is not None}
    sim = open_simulator(oracle, how.get("executor", defaults()["executor"]), how.get("workers"),
                         store.absolute(), how.get("ray_address"))
    settings = {**how, **(settings or {})}
    run = lambda P: np.asarray(sim.simulate(P, progress=False), dtype=float)  # noqa: E731
    rows = list(known)
    have = {(r["method"], r["seed"], r["pours"]) for r in rows}
    try:
        P_q, of = question_pours(asked, 1)
        S_q = run(P_q)
        ok = np.all(np.isfinite(S_q), axis=1)
        key, clear = question_key(S_q[ok], of[ok], len(asked))
        share = question_shares(S_q[ok], of[ok], len(asked))
        V, of_ok = verdicts(S_q[ok]), of[ok]
        project = Keyed("questions", [q.antecedent for q in asked], key, clear, share,
                        contrast_keys(key, clear, defaults_only(V, len(asked))[0]), V, of_ok)
        sets = {"": project,
                "interaction_": keyed("interactions", interaction_questions(), run),
                "random_": keyed("random scenes", random_scenes(), run)}
        top = max(budgets)
        for seed in seeds:
            for method in methods:
                wanted = [n for n in budgets if (method, seed, n) not in have]
                if not wanted:
                    continue
                if method == "curiosity":
                    chosen = curiosity(seed, top, oracle, store, run, settings)
                else:
                    make = {"random": random_bodies, "random_valid": random_valid,
                            "designed": designed,
                            "uncertainty": uncertainty, "map_elites": map_elites_pours}[method]
                    chosen = make(seed, top, run)
                for n in wanted:
                    row = {"method": method, "seed": seed, "pours": n,
                           **theory_row(chosen, n, seed, sets, learner)}
                    rows.append(row)
                    print(f"{method:11} seed {seed} {n:4} pours: " + ", ".join(
                        f"{label} {_num(row.get(k))}" for k, label in SHOWN), flush=True)
            if done is not None:
                done(rows)
    finally:
        sim.close()
    return rows


def theory_row(chosen: Chosen, n: int, seed: int, sets: dict,
               learner: str | None = None) -> dict:
    """The measures of the theories learned by `learner` (learners.py;
    None: the option table's default) from a method's first n pours:
    over its own bodies (unprefixed) and over every askable body
    (`askable_`; the same for a method whose own bodies are every askable
    one), each on every question set (`sets`: prefix -> Keyed), with the
    behaviours its pours show and those its theory gives; and gradient
    boosting of the same pours (`boosting_`, as `pantarhei evaluate` fits
    it: averaged over each scene's meaning), the ceiling of what they
    support."""
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.bridge.evaluation.question_sets import answers, theory_behaviours
    from pantarhei.bridge.learning.generalize import Settings
    from pantarhei.bridge.learning.learners import learner as named
    from pantarhei.bridge.learning.meaning import Meaning
    from pantarhei.bridge.verdicts import verdicts

    learn = named(learner)
    P, S = chosen.P[:n], chosen.S[:n]
    good = np.all(np.isfinite(S), axis=1)
    own = chosen.bodies(n)
    theories = {"": learn(P[good], S[good], seed, own)}
    theories["askable_"] = (theories[""] if own is None else
                            learn(P[good], S[good], seed, None))
    row: dict = {"behaviours": behaviours_seen(S)}
    for tag, g in theories.items():
        row[f"{tag}theory_behaviours"] = theory_behaviours(g)
        for prefix, ks in sets.items():
            m = ks.measures(*answers(g, ks.scenes))
            row.update({f"{tag}{prefix}{k}": v for k, v in m.items()})
    model, band = Meaning(P[good], verdicts(S[good]), Settings(seed=seed)), Settings()
    for prefix, ks in sets.items():
        lik = model([tuple(s) for s in ks.scenes])
        row.update({f"boosting_{prefix}{k}": v
                    for k, v in ks.measures(band.verdict(lik), lik).items()})
    return row


def _num(x) -> str:
    return "n/a" if x is None else f"{x:.3f}"


def summary(rows: list[dict], key: str, method: str, pours: int) -> tuple[float, float, float] | None:
    """Median, lowest and highest of a measure over the seeds."""
    v = [r[key] for r in rows if r["method"] == method and r["pours"] == pours
         and r.get(key) is not None]
    return (float(np.median(v)), float(min(v)), float(max(v))) if v else None


def table(rows: list[dict], oracle: str, seeds: Sequence[int], note: str = "") -> str:
    """The report: one row per method and budget, medians [range]; `note`
    a paragraph after the opening."""
    budgets = sorted({r["pours"] for r in rows})
    methods = [m for m in METHODS if any(r["method"] == m for r in rows)]
    cols = [*MEASURES, ("behaviours", "behaviours seen")]
    out = [f"# Knowledge per pour ({oracle} oracle)", "",
           f"Written by `python -m benchmarks knowledge --oracle {oracle}`; seeds "
           f"{', '.join(map(str, seeds))}, medians [lowest-highest]. Each method learns the "
           "same kind of theory from its own pours only, every pour counted "
           "(benchmarks/knowledge.py says how each chooses): over its own bodies (the "
           "antecedents it explored; every askable body for uncertainty sampling and "
           "MAP-Elites) and, so that the choice of pours is compared apart from the choice of "
           "bodies, over every askable body (*every askable body*). The questions are those of "
           "bridge/evaluation/questions.json (contrast keys: where the defaults-only answer is "
           "wrong); *interactions* are the 64 pairs of pose propositions of "
           "bridge/evaluation/interactions.json and *random scenes* 40 uniformly random valid "
           "scenes of 5 to 8 propositions, each keyed by the majority of 20 pours (contrast "
           "keys: clear keys that depart from the ordinary pour's verdict). A confident error "
           "states a likelihood of 80% or more on the side a clear key contradicts. Behaviours "
           "seen: distinct nine-verdict vectors that two or more of the method's pours show; "
           "in the theory: distinct nine-verdict answers, all decided, for its rules' bodies.",
           "", *([note, ""] if note else []),
           "| method | pours | " + " | ".join(label for _, label in cols) + " |",
           "|---|---|" + "---|" * len(cols)]
    for n in budgets:
        for m in methods:
            cells = []
            for k, _ in cols:
                s = summary(rows, k, m, n)
                fmt = "{:.0f}" if k in COUNTS else "{:.3f}"
                cells.append("n/a" if s is None else
                             f"{fmt.format(s[0])} [{fmt.format(s[1])}-{fmt.format(s[2])}]")
            out.append(f"| {m} | {n} | " + " | ".join(cells) + " |")
    return "\n".join([*out, *targets(rows, summary)]) + "\n"


def plot(rows: list[dict], path: Path) -> None:
    """Learning curves: each measure against the pours, the median of the
    seeds with their range shaded."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    budgets = sorted({r["pours"] for r in rows})
    methods = [m for m in METHODS if any(r["method"] == m for r in rows)]
    cols = 4
    rows_ = -(-len(MEASURES) // cols)
    fig, grid = plt.subplots(rows_, cols, figsize=(4 * cols, 3.2 * rows_))
    axes = grid.ravel()
    for ax in axes[len(MEASURES):]:
        ax.set_visible(False)
    for ax, (k, label) in zip(axes, MEASURES):
        for m in methods:
            s = [summary(rows, k, m, n) for n in budgets]
            xs = [n for n, v in zip(budgets, s) if v]
            if not xs:
                continue
            med = [v[0] for v in s if v]
            ax.plot(xs, med, marker="o", label=m)
            ax.fill_between(xs, [v[1] for v in s if v], [v[2] for v in s if v], alpha=0.15)
        ax.set_xlabel("pours simulated")
        ax.set_title(label, fontsize=9)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def _order(row: dict) -> tuple:
    return (row["seed"], METHODS.index(row["method"]), row["pours"])


def _rows(path: Path) -> list[dict]:
    """The rows measured before, from `path` (none if it does not exist)."""
    if not path.exists():
        return []
    try:
        rows = json.loads(path.read_text(encoding="utf-8"))
        if not all({"method", "seed", "pours"} <= set(r) for r in rows):
            raise ValueError("a row without its method, seed or pours")
    except (ValueError, TypeError, AttributeError) as e:
        raise SystemExit(f"{path}: not the rows of the knowledge benchmark ({e}); "
                         "move it aside to start a new one") from None
    return rows


def _numbers(text: str) -> list[int]:
    out = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            out += list(range(int(a), int(b) + 1))
        elif part.strip():
            out.append(int(part))
    return out


def main(argv: Sequence[str] = ()) -> None:
    """The benchmark with the options `argv` (none: its defaults, as `make
    bench` runs it)."""
    from pantarhei.bridge.commands.options import choices
    from pantarhei.oracle.store import DEFAULT_STORE
    from pantarhei.theory import defaults

    p = argparse.ArgumentParser(prog="python -m benchmarks knowledge", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--oracle", default=defaults()["oracle"])
    p.add_argument("--seeds", default="101-105", help="seeds, e.g. 101-105 or 101,103")
    p.add_argument("--budgets", default="200,400,775", help="total pours, e.g. 200,400,775")
    p.add_argument("--methods", default=",".join(METHODS))
    p.add_argument("--store", default=DEFAULT_STORE)
    p.add_argument("--report", default="report",
                   help="folder for knowledge-ORACLE.md, .png and .json")
    p.add_argument("--fresh", action="store_true",
                   help="measure this run's rows again (default: keep the rows of "
                        "knowledge-ORACLE.json; the others are kept either way)")
    p.add_argument("--executor", choices=choices("executor"), default=defaults()["executor"],
                   help="where the pours are simulated, as explore's --executor (ray: a cluster)")
    p.add_argument("--workers", type=int, default=None, help="worker processes (default: one per core)")
    p.add_argument("--ray-address", default=None, metavar="ADDR",
                   help="Ray cluster to join (with --executor ray)")
    p.add_argument("--learner", choices=choices("learner"), default=defaults()["learner"],
                   help="the learner of every method's theory, as explore's --learner")
    p.add_argument("--explore", default="", metavar="NAME=VALUE,...",
                   help="the curiosity's options other than their defaults, e.g. doubt=0,reach=0")
    args = p.parse_args(list(argv))
    seeds, budgets = _numbers(args.seeds), sorted(_numbers(args.budgets))
    methods = [m for m in args.methods.split(",") if m]
    unknown = sorted(set(methods) - set(METHODS))
    if unknown or not seeds or not budgets or min(budgets) < 1:
        raise SystemExit(f"unknown method {', '.join(unknown)} (choose among {', '.join(METHODS)})"
                         if unknown else "give seeds and budgets of at least 1 pour")
    folder = Path(args.report)
    folder.mkdir(parents=True, exist_ok=True)
    md, png, data = (folder / f"knowledge-{args.oracle}.{x}" for x in ("md", "png", "json"))

    def ours(r: dict) -> bool:                  # a row of this run's methods, seeds, budgets
        return r["method"] in methods and r["seed"] in seeds and r["pours"] in budgets

    def this_run(rows: list[dict]) -> list[dict]:
        return [r for r in rows if ours(r)]

    known = [r for r in _rows(data) if not (args.fresh and ours(r))]   # --fresh: ours again

    def write(rows: list[dict]) -> None:        # after each seed: what is measured is kept
        data.write_text(json.dumps(sorted(rows, key=_order), indent=1) + "\n", encoding="utf-8")
        shown = this_run(rows)
        md.write_text(table(shown, args.oracle, sorted({r["seed"] for r in shown})),
                      encoding="utf-8")
        plot(shown, png)

    try:
        settings = {k.strip(): float(v) if "." in v else int(v)
                    for k, v in (x.split("=") for x in args.explore.split(",") if x.strip())}
    except ValueError:
        raise SystemExit(f"--explore: not NAME=VALUE,...: {args.explore!r}") from None
    executor = {"executor": args.executor, "workers": args.workers, "ray_address": args.ray_address}
    rows = measure(args.oracle, seeds, budgets, Path(args.store), methods, write, known, settings,
                   executor, args.learner)
    write(rows)
    print(table(this_run(rows), args.oracle, seeds))
    print(f"written: {md}, {png}, {data}")


if __name__ == "__main__":
    import sys

    main(sys.argv[1:])
