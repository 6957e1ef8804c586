"""The scalable benchmark theories of defeasible logic, with known answers.

After Maher, Rock, Antoniou, Billington and Miller, "Efficient defeasible
reasoning systems" (2001). Each generator returns the theory and the
literals it must conclude (+d), refute (-d) or leave undecided, under the
default semantics (ambiguity blocking, team defeat, well-founded) unless
it says otherwise.

- chain(n): a0 is a fact; ri: a(i-1) => ai. Every ai is +d.
- circle(n): ri: ai => a((i+1) mod n), no facts. Every ai loops: -d under
  the well-founded semantics, undecided under Kunen's.
- levels(n): ri: => ai and si: a(i+1) => -ai for i < n, rn: => an.
  A cascade of disputes: ai is +d when n - i is even, -d otherwise.
- teams(d): a tree of depth d of disputed literals; each inner literal ai
  has two rules for it (bodies are its children 4i+1, 4i+2) superior one
  each to the two rules against it (children 4i+3, 4i+4); leaves are
  unconditional. With team defeat every ai is +d; without it every inner
  ai is -d.
- tree(d, k): a k-branching tree of depth d: each inner literal has one
  rule whose body is its k children; leaves are facts. Every ai is +d.
- dag(d, k): ai has one rule with body a(i+1) ... a(i+k) for i < d*k;
  a(d*k+1) ... a(d*k+k) are facts: each literal occurs k times. Every
  literal is +d.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from pantarhei.bridge.theories.model import Rule, Theory

NAMES = ("chain", "circle", "levels", "teams", "tree", "dag")


@dataclass
class Benchmark:
    name: str
    theory: Theory
    proved: set[str] = field(default_factory=set)       # +d
    refuted: set[str] = field(default_factory=set)      # -d
    undecided: set[str] = field(default_factory=set)    # neither

    @property
    def size(self) -> int:
        return len(self.theory.rules)


def _a(i: int) -> str:
    return f"a{i}"


def chain(n: int) -> Benchmark:
    t = Theory(facts=[_a(0)], source=f"chain({n})")
    t.rules = [Rule(f"r{i}", "defeasible", _a(i), (_a(i - 1),)) for i in range(1, n + 1)]
    return Benchmark("chain", t, proved={_a(i) for i in range(n + 1)})


def circle(n: int, well_founded: bool = True) -> Benchmark:
    t = Theory(source=f"circle({n})")
    t.rules = [Rule(f"r{i}", "defeasible", _a((i + 1) % n), (_a(i),)) for i in range(n)]
    lits = {_a(i) for i in range(n)}
    return Benchmark("circle", t, refuted=lits if well_founded else set(),
                     undecided=set() if well_founded else lits)


def levels(n: int) -> Benchmark:
    t = Theory(source=f"levels({n})")
    for i in range(n + 1):
        t.rules.append(Rule(f"r{i}", "defeasible", _a(i)))
        if i < n:
            t.rules.append(Rule(f"s{i}", "defeasible", f"neg({_a(i)})", (_a(i + 1),)))
    return Benchmark("levels", t, proved={_a(i) for i in range(n + 1) if (n - i) % 2 == 0},
                     refuted={_a(i) for i in range(n + 1) if (n - i) % 2 == 1})


def teams(depth: int, team_defeat: bool = True) -> Benchmark:
    t = Theory(source=f"teams({depth})")
    inner = (4 ** depth - 1) // 3           # literals with children
    total = (4 ** (depth + 1) - 1) // 3
    for i in range(inner):
        c = [4 * i + j for j in (1, 2, 3, 4)]
        t.rules += [Rule(f"r{i}_1", "defeasible", _a(i), (_a(c[0]),)),
                    Rule(f"r{i}_2", "defeasible", _a(i), (_a(c[1]),)),
                    Rule(f"r{i}_3", "defeasible", f"neg({_a(i)})", (_a(c[2]),)),
                    Rule(f"r{i}_4", "defeasible", f"neg({_a(i)})", (_a(c[3]),))]
        t.sup += [(f"r{i}_1", f"r{i}_3"), (f"r{i}_2", f"r{i}_4")]
    t.rules += [Rule(f"l{i}", "defeasible", _a(i)) for i in range(inner, total)]
    leaves = {_a(i) for i in range(inner, total)}
    inner_lits = {_a(i) for i in range(inner)}
    if team_defeat:
        return Benchmark("teams", t, proved=leaves | inner_lits)
    return Benchmark("teams", t, proved=leaves, refuted=inner_lits)


def tree(depth: int, k: int = 3) -> Benchmark:
    t = Theory(source=f"tree({depth},{k})")
    inner = (k ** depth - 1) // (k - 1)
    total = (k ** (depth + 1) - 1) // (k - 1)
    for i in range(inner):
        t.rules.append(Rule(f"r{i}", "defeasible", _a(i),
                            tuple(_a(k * i + j) for j in range(1, k + 1))))
    t.facts = [_a(i) for i in range(inner, total)]
    return Benchmark("tree", t, proved={_a(i) for i in range(total)})


def dag(depth: int, k: int = 3) -> Benchmark:
    t = Theory(source=f"dag({depth},{k})")
    n = depth * k
    t.rules = [Rule(f"r{i}", "defeasible", _a(i), tuple(_a(i + j) for j in range(1, k + 1)))
               for i in range(n + 1)]
    t.facts = [_a(i) for i in range(n + 1, n + k + 1)]
    return Benchmark("dag", t, proved={_a(i) for i in range(n + k + 1)})


def of_size(name: str, rules: int) -> Benchmark:
    """The benchmark `name` with about `rules` rules (at most, for the trees)."""
    if name == "chain":
        return chain(rules)
    if name == "circle":
        return circle(rules)
    if name == "levels":
        return levels(max(1, (rules - 1) // 2))
    if name == "dag":
        return dag(max(1, rules // 3 - 1), 3)
    if name == "teams":
        d = 1
        while _teams_rules(d + 1) <= rules:
            d += 1
        return teams(d)
    if name == "tree":
        d = 1
        while (3 ** (d + 1) - 1) // 2 <= rules:
            d += 1
        return tree(d, 3)
    raise ValueError(f"unknown benchmark {name} (one of {', '.join(NAMES)})")


def _teams_rules(depth: int) -> int:
    inner = (4 ** depth - 1) // 3
    total = (4 ** (depth + 1) - 1) // 3
    return 4 * inner + (total - inner)


def pouring(rules: int, seed: int = 0) -> Theory:
    """A random learned theory of pouring with `rules` rules: bodies of 1-4
    propositions from distinct dimensions, heads expectations or their
    negations; superiority by specificity (all rules learned)."""
    import random

    from pantarhei.theory.lexicon import load_vocabulary

    rng = random.Random(seed)
    vocab = load_vocabulary()
    dims = sorted(vocab.dimensions)
    expectations = vocab.expectation_names
    t = Theory(source=f"pouring({rules}, seed={seed})")
    for i in range(rules):
        chosen = rng.sample(dims, rng.randint(1, 4))
        body = tuple(sorted(rng.choice(vocab.dimensions[d].values) for d in chosen))
        e = rng.choice(expectations)
        t.rules.append(Rule(f"r{i}", "defeasible", e if rng.random() < 0.5 else f"neg({e})", body))
        t.learned.add(f"r{i}")
    return t
