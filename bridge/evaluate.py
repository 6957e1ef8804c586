"""`pantarhei evaluate`: a learned theory against the oracle it was learned
from, on scenes exploration never explored.

Everything is simulated by the same oracle, through the same store, so a
second run simulates nothing:

* the exploration's own simulations, drawn again with the seeds the
  exploration used (all found in the store when it is the same store);
* held-out scenes: random valid antecedents, one pour each, in three sets:
  `uniform` (uniformly random valid antecedents), `near` (an explored
  antecedent with one or two propositions added: where the theory speaks)
  and `near_random` (the same around the random exploration's antecedents);
* random exploration: the same budget spent on uniformly random valid
  antecedents, and the same rule building (equation (1) and qualify);
* the paper's three example rules, asked of the theory and simulated;
* plans for the goals the theory can reach, sampled and simulated.

The numbers go into an `Evaluation` (and JSON); `bridge/report.py` writes
them up.
"""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from pantarhei.oracle.generative import sample
from pantarhei.oracle.vocabulary import load_vocabulary

from . import reasoning
from .errors import UserError
from .evaluation import (FAILS, HOLDS, UNKNOWN, accuracy, distinct_behaviours,
                         tree_predictions, verdicts)
from .exploration import iteration_seed, outcome
from .theories import Rule, Theory, complement, literal_text
from .weights import log_densities, weights

#: The paper's three example rules (section 3.2): the scene, the literal it
#: concludes, and the paper's words.
PAPER_RULES = (
    (("pour_to_side",), "neg(no_spill)", "pouring from the side will result in spillage"),
    (("light_liquid",), "neg(liquid_leaves_source)",
     "too light a liquid will not entirely leave the source"),
    (("light_liquid", "end_upright", "end_low"), "neg(liquid_remains_in_destination)",
     "when pouring a lightweight liquid and then righting up the source while low above the "
     "destination, the liquid does not remain in the destination"),
)


@dataclass
class Learned:
    """A theory written by `pantarhei explore`, with what it says of the
    exploration behind it."""
    path: Path
    theory: Theory
    settings: dict[str, list[Any]]
    antecedents: list[tuple[str, ...]]      # explored, in order: a1, a2, ...

    def setting(self, key: str, default: Any = None) -> Any:
        values = self.settings.get(key)
        return values[0] if values else default


def read_learned(path: Path | str) -> Learned:
    """Read a learned theory; UserError if the file lacks the exploration's
    settings and provenance (a hand-written theory, say)."""
    from pantarhei.theory import read_facts

    path = Path(path)
    theory = reasoning.load([path])
    facts = read_facts([path])
    settings = reasoning.settings(theory)
    of_rule = {literal_text(a[0]): literal_text(a[2]) for a in facts.get("provenance", [])
               if len(a) == 3 and literal_text(a[1]) == "antecedent"}
    if not settings.get("seed") or not settings.get("samples") or not of_rule:
        raise UserError(f"{path}: not a theory written by `pantarhei explore` "
                        f"(no setting/2 and provenance/3 facts to evaluate it by)")
    bodies: dict[int, tuple[str, ...]] = {}
    for r in theory.rules:
        a = of_rule.get(r.id)
        if a and a[1:].isdigit():
            bodies.setdefault(int(a[1:]), tuple(sorted(r.body)))
    order = sorted(bodies)
    if order != list(range(1, len(order) + 1)):
        raise UserError(f"{path}: the explored antecedents are not a1..a{len(order)}")
    return Learned(path, theory, settings, [bodies[i] for i in order])


# -- rule building -------------------------------------------------------------

def consequents(antecedents: Sequence[Sequence[str]], P: np.ndarray, S: np.ndarray,
                mode: str = "weighted") -> np.ndarray:
    """The consequent (verdict per expectation) of each antecedent, from
    all simulations (P, S) weighted by equation (1) over these antecedents,
    as Algorithm 1's last loop builds them."""
    ok = np.all(np.isfinite(S), axis=1)
    W = weights(log_densities(P[ok], [list(a) for a in antecedents]))
    return np.array([[o["holds"] for o in outcome(S[ok], W[i], mode)["outcomes"]]
                     for i in range(len(antecedents))], dtype=bool).reshape(len(antecedents), -1)


def theory_of(antecedents: Sequence[Sequence[str]], heads: np.ndarray, source: str) -> Theory:
    """A learned theory: for each antecedent, one defeasible rule per
    expectation, concluding it or its negation."""
    names = load_vocabulary().expectation_names
    t = Theory(source=source)
    for i, (a, row) in enumerate(zip(antecedents, heads), start=1):
        for e, holds in zip(names, row):
            rid = f"r{i}_{e}"
            t.rules.append(Rule(rid, "defeasible", e if holds else f"neg({e})", tuple(sorted(a))))
            t.learned.add(rid)
    return t


def predict(theory: Theory, scenes: Sequence[Sequence[str]]) -> np.ndarray:
    """What SWI-Prolog concludes in each scene (scenes x 9): HOLDS, FAILS or
    UNKNOWN, by `queries:what_happens/3`."""
    names = load_vocabulary().expectation_names
    out = np.full((len(scenes), len(names)), UNKNOWN, dtype=int)
    if not scenes:
        return out
    e = reasoning.prolog_load(theory)
    e.use_module("queries")
    code = {"holds": HOLDS, "fails": FAILS}
    for i, scene in enumerate(scenes):
        r = e.once(f"queries:what_happens([{', '.join(scene)}], [], Os), "
                   "findall(S, (member(outcome(E, V, _), Os), format(atom(S), '~w=~w', [E, V])), Ss)")
        for pair in r["Ss"]:
            name, value = reasoning.prolog_text(pair).split("=", 1)
            out[i, names.index(name)] = code.get(value, UNKNOWN)
    return out


# -- scenes --------------------------------------------------------------------

def random_antecedents(seed: int, n: int) -> list[tuple[str, ...]]:
    """n antecedents drawn uniformly from the valid ones (by Prolog)."""
    from .prolog import engine

    r = engine().once(f"validity:random_antecedents({int(seed)}, {int(n)}, As)")
    return [tuple(str(p) for p in a) for a in r["As"]]


def random_exploration(seed: int, count: int, samples: int) -> tuple[list[tuple[str, ...]], np.ndarray]:
    """The random baseline's exploration at a budget: `count` uniformly random
    valid antecedents, `samples` pours of each (seeded as exploration seeds its
    iterations, so the same store serves every reader)."""
    ants = random_antecedents(seed + 7919, count)
    P = np.vstack([sample(list(a), samples, iteration_seed(seed + 7919, i))
                   for i, a in enumerate(ants, start=1)])
    return ants, P


def uniform_scenes(seed: int, n: int, exclude: set[tuple[str, ...]]) -> list[tuple[str, ...]]:
    """n distinct uniformly random valid antecedents, none in `exclude`."""
    out = [a for a in random_antecedents(seed, 2 * n) if a not in exclude]
    return list(dict.fromkeys(out))[:n]


def scene_pours(scenes: Sequence[Sequence[str]], seed: int) -> np.ndarray:
    """One pour of each held-out scene, shape (len(scenes), 30)."""
    if not scenes:
        return np.empty((0, len(load_vocabulary().parameters)))
    return np.vstack([sample(list(a), 1, iteration_seed(seed, 100_000 + j))
                      for j, a in enumerate(scenes)])


def near_antecedents(explored: Sequence[Sequence[str]], n: int, seed: int,
                     exclude: set[tuple[str, ...]]) -> list[tuple[str, ...]]:
    """n valid antecedents, each an explored antecedent with one or two
    propositions of dimensions it leaves open added; none in `exclude`."""
    from .validity import violations

    v = load_vocabulary()
    rng = np.random.default_rng(seed)
    out: list[tuple[str, ...]] = []
    seen = set(exclude)
    for _ in range(200 * n):
        if len(out) == n:
            break
        base = list(explored[rng.integers(len(explored))])
        used = {v.propositions[p].dimension for p in base}
        free = sorted(p for p, d in v.propositions.items() if d.dimension not in used)
        k = int(rng.integers(1, 3))
        extra = [free[j] for j in rng.choice(len(free), size=k, replace=False)]
        cand = tuple(sorted(set(base) | set(extra)))
        if cand in seen or len({v.propositions[p].dimension for p in cand}) != len(cand):
            continue
        if violations(cand):
            continue
        seen.add(cand)
        out.append(cand)
    return out


# -- the run -------------------------------------------------------------------

@dataclass
class Options:
    theory: Path
    store: Path
    scenes: int = 150
    seed: int = 1
    verify: int = 10
    paper_samples: int = 20
    executor: str = "local"
    workers: int | None = None
    ray_address: str | None = None
    progress: bool = True


@dataclass
class Evaluation:
    """Every figure of an evaluation, JSON-ready (`as_dict`)."""
    theory: str
    oracle: str
    settings: dict[str, Any]
    budget: int
    #: Whether the exploration's pours, simulated here, give the theory's rules.
    reproduced: bool = True
    #: Per explored antecedent: the share of its own pours that kept every expectation.
    kept_all: list[float | None] = field(default_factory=list)
    heldout: dict[str, Any] = field(default_factory=dict)
    curves: dict[str, Any] = field(default_factory=dict)
    behaviours: dict[str, int] = field(default_factory=dict)
    paper_rules: list[dict[str, Any]] = field(default_factory=list)
    plans: list[dict[str, Any]] = field(default_factory=list)
    simulations: dict[str, int] = field(default_factory=dict)
    seconds: dict[str, float] = field(default_factory=dict)
    #: Not in the JSON: what the report draws from.
    explored: list[tuple[str, ...]] = field(default_factory=list, repr=False)
    explored_consequents: np.ndarray | None = field(default=None, repr=False)
    best_samples: list[np.ndarray] = field(default_factory=list, repr=False)

    def as_dict(self) -> dict[str, Any]:
        return {k: getattr(self, k) for k in
                ("theory", "oracle", "settings", "budget", "reproduced", "kept_all", "heldout", "curves", "behaviours",
                 "paper_rules", "plans", "simulations", "seconds")}

    @property
    def plan_rate(self) -> float | None:
        """The share of the plans' pours that met their goals (None: none simulated)."""
        met = sum(p["met"] for p in self.plans if "met" in p)
        done = sum(p["simulated"] for p in self.plans if "simulated" in p)
        return met / done if done else None


def _shown(path: Path) -> str:
    """A path as the report shows it: relative to here when inside it."""
    try:
        return str(Path(path).resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(path)


def _say(text: str) -> None:
    print(f"pantarhei evaluate: {text}", file=sys.stderr, flush=True)


def evaluate(opts: Options) -> Evaluation:
    learned = read_learned(opts.theory)
    oracle = str(learned.setting("oracle", "pybullet"))
    samples = int(learned.setting("samples"))
    seed = int(learned.setting("seed"))
    mode = str(learned.setting("qualify", "weighted"))
    explored = learned.antecedents
    R = len(explored)
    if opts.scenes < 1 or opts.verify < 0 or opts.paper_samples < 0:
        raise UserError("--scenes must be at least 1, --verify and --paper-samples at least 0")
    ev = Evaluation(theory=_shown(opts.theory), oracle=oracle,
                    settings={k: (v if len(v) > 1 else v[0]) for k, v in learned.settings.items()},
                    budget=R * samples, explored=list(explored))
    from .exploration import open_simulator, oracle_identity

    version, _ = oracle_identity(oracle)
    if str(learned.setting("oracle_version", version)) != version:
        _say(f"the theory was learned with {oracle} version {learned.setting('oracle_version')}, "
             f"the oracle here is version {version}: its simulations are not reused")
    sim = open_simulator(oracle, opts.executor, opts.workers, opts.store, opts.ray_address)
    names = load_vocabulary().expectation_names
    try:
        def run(label: str, P: np.ndarray) -> np.ndarray:
            t = time.monotonic()
            if len(P):
                _say(f"{label}: {len(P)} pours")
            S = np.asarray(sim.simulate(P, progress=opts.progress and len(P) > 0), dtype=float) \
                if len(P) else np.empty((0, len(names)))
            ev.simulations[label] = int(sim.last_simulated) if len(P) else 0
            ev.seconds[label] = round(time.monotonic() - t, 1)
            return S

        # 1. the exploration's simulations, drawn again
        P_cur = np.vstack([sample(list(a), samples, iteration_seed(seed, i))
                           for i, a in enumerate(explored, start=1)])
        S_cur = run("exploration", P_cur)
        ev.explored_consequents = consequents(explored, P_cur, S_cur, mode)
        ok = np.all(np.isfinite(S_cur), axis=1)
        W = weights(log_densities(P_cur[ok], [list(a) for a in explored]))
        ev.best_samples = [P_cur[ok][int(np.argmax(W[i]))] for i in range(R)]
        ev.kept_all = []
        for i in range(R):      # of the pours sampled for a_i: the share that kept every expectation
            rows = S_cur[i * samples:(i + 1) * samples]
            rows = rows[np.all(np.isfinite(rows), axis=1)]
            ev.kept_all.append(float((rows > 0.5).all(axis=1).mean()) if len(rows) else None)
        differ = _differing_rules(learned.theory, ev.explored_consequents)
        ev.reproduced = not differ
        if differ:
            _say(f"{len(differ)} rules of the theory differ from those its own pours give here "
                 f"(first: {differ[0]}): another oracle build, or a theory edited by hand")

        # 2. random exploration with the same budget
        random_ants, P_rnd = random_exploration(opts.seed, R, samples)
        S_rnd = run("random exploration", P_rnd)

        # 3. held-out scenes, one pour each, never explored by either
        known = set(explored) | set(random_ants)
        uniform = uniform_scenes(opts.seed, opts.scenes, known)
        near = near_antecedents(explored, opts.scenes, opts.seed, known | set(uniform))
        near_random = near_antecedents(random_ants, opts.scenes, opts.seed + 1,
                                       known | set(uniform) | set(near))
        sets = {"uniform": uniform, "near": near, "near_random": near_random}
        P_held = {k: scene_pours(v, opts.seed) for k, v in sets.items()}
        S_held = {k: run(f"held-out ({k})", P_held[k]) for k in sets}

        t = time.monotonic()
        _say("predicting the held-out scenes with every theory along the budget")
        held = {}    # per set: the scenes whose pour did not fail, and their verdicts
        for name, scenes in sets.items():
            ok = np.all(np.isfinite(S_held[name]), axis=1)
            held[name] = ([s for s, kept in zip(scenes, ok) if kept], verdicts(S_held[name][ok]))
        curves: dict[str, Any] = {"budget": [k * samples for k in range(1, R + 1)]}
        for method, ants, P, S in (("curiosity", explored, P_cur, S_cur),
                                   ("random", random_ants, P_rnd, S_rnd)):
            beh, cov, acc = [], {k: [] for k in sets}, {k: [] for k in sets}
            for k in range(1, R + 1):
                heads = consequents(ants[:k], P[:k * samples], S[:k * samples], mode)
                beh.append(distinct_behaviours(heads))
                th = theory_of(ants[:k], heads, f"{method}@{k}")
                for name, (sel, y) in held.items():
                    a = accuracy(predict(th, sel), y)
                    cov[name].append(a.overall_coverage)
                    acc[name].append(None if np.isnan(a.overall_accuracy) else a.overall_accuracy)
            curves[method] = {"behaviours": beh, "coverage": cov, "accuracy": acc}
            ev.behaviours[method] = beh[-1]
        ev.curves = curves

        # the final theories and the decision trees, per held-out set
        final = {"curiosity": learned.theory,
                 "random": theory_of(random_ants,
                                     consequents(random_ants, P_rnd, S_rnd, mode), "random")}
        train = {"curiosity": ([a for a in explored for _ in range(samples)], S_cur),
                 "random": ([a for a in random_ants for _ in range(samples)], S_rnd)}
        for name, (sel, y) in held.items():
            out: dict[str, Any] = {"scenes": len(sel),
                                   "mean_propositions": float(np.mean([len(s) for s in sel]))
                                   if sel else 0.0}
            for label, th in final.items():
                out[f"{label}_theory"] = accuracy(predict(th, sel), y).as_dict()
            for label, (X, S) in train.items():
                okr = np.all(np.isfinite(S), axis=1)
                Xk = [x for x, o in zip(X, okr) if o]
                out[f"{label}_tree"] = accuracy(
                    tree_predictions(Xk, verdicts(S[okr]), sel, opts.seed), y).as_dict()
            ev.heldout[name] = out
        ev.seconds["predicting"] = round(time.monotonic() - t, 1)

        # 4. the paper's three rules
        ev.paper_rules = _paper_rules(learned.theory, run, opts)

        # 5. plans
        ev.plans = _plans(learned.theory, run, opts)
    finally:
        sim.close()
    return ev


def _differing_rules(theory: Theory, heads: np.ndarray) -> list[str]:
    """The learned rules rI_E whose head is not the consequent rebuilt from
    the exploration's pours (none when the theory is reproduced)."""
    names = load_vocabulary().expectation_names
    have = {r.id: r.head for r in theory.rules}
    out = []
    for i, row in enumerate(heads, start=1):
        for e, holds in zip(names, row):
            rid = f"r{i}_{e}"
            if have.get(rid) != (e if holds else f"neg({e})"):
                out.append(rid)
    return out


def _paper_rules(theory: Theory, run, opts: Options) -> list[dict[str, Any]]:
    from .planning import goals_met

    out, scenes = [], []
    for props, literal, words in PAPER_RULES:
        # learned rules for the literal whose antecedent holds the scene's propositions
        # (and perhaps more: what else each needs is kept)
        rules = [{"rule": r.id, "also_needs": sorted(set(r.body) - set(props))}
                 for r in theory.rules if r.id in theory.learned and r.head == literal
                 and set(props) <= set(r.body)]
        assumed = reasoning.assumptions(theory, list(props))
        scene = sorted(set(props) | set(assumed))
        said = {o.expectation: o for o in reasoning.what_happens(theory, scene)}
        expectation = complement(literal) if literal.startswith("neg(") else literal
        o = said[expectation]
        says = {"holds": expectation, "fails": f"neg({expectation})"}.get(o.value, "unknown")
        out.append({"scene": list(props), "assumed": assumed, "literal": literal, "paper": words,
                    "learned": rules, "theory_says": says, "rule": o.rule, "reason": o.reason})
        scenes.append(scene)
    if opts.paper_samples:
        P = np.vstack([sample(s, opts.paper_samples, iteration_seed(opts.seed, 200_000 + i))
                       for i, s in enumerate(scenes)])
        S = run("the paper's rules", P)
        for i, entry in enumerate(out):
            rows = S[i * opts.paper_samples:(i + 1) * opts.paper_samples]
            rows = rows[np.all(np.isfinite(rows), axis=1)]
            share = float(goals_met(rows, [entry["literal"]]).mean()) if len(rows) else None
            entry.update(simulated=int(len(rows)), oracle_share=share)
    return out


#: The goals tried for plans: each expectation, its negation, and a clean pour.
def goal_sets() -> list[list[str]]:
    names = load_vocabulary().expectation_names
    return [list(names)] + [[e] for e in names] + [[f"neg({e})"] for e in names]


def _plans(theory: Theory, run, opts: Options) -> list[dict[str, Any]]:
    from .planning import goals_met, plan

    out = []
    for goals in goal_sets():
        try:
            (p,) = plan(theory, goals, [], 0)
        except UserError:
            continue
        out.append({"goals": goals, "plan": list(p.chosen), "antecedent": list(p.antecedent)})
    if opts.verify and out:
        P = np.vstack([sample(e["antecedent"], opts.verify, iteration_seed(opts.seed, 300_000 + i))
                       for i, e in enumerate(out)])
        S = run("plans", P)
        for i, e in enumerate(out):
            rows = S[i * opts.verify:(i + 1) * opts.verify]
            rows = rows[np.all(np.isfinite(rows), axis=1)]
            met = goals_met(rows, e["goals"])
            e.update(simulated=int(len(rows)), met=int(met.sum()))
    return out
