"""Defeasible theories as Python values, and the native format they are
written in.

The native format is ground facts that SWI-Prolog and clingo both read:

    fact(L).  rule(Id, Kind, Head).  body(Id, L).  sup(R1, R2).  learned(Id).

Literals are kept as their native text (`bird(tweety)`, `neg(flies(tweety))`),
which is also how both engines print them: a name, or a name with names and
integers as arguments, or neg(L). A learned theory adds `setting(Key, V)`
and `provenance(Id, Key, V)`; facts of any other predicate (`set_aside/3`,
...) are kept aside in `extra` and written back (quoted text quoted and
escaped). What a file may hold is checked by `well_formed` (and by
theory/theory_files.pl, with the same messages); `native` reads a file.
The superiority a theory's rules have (sup/2 and the specificity of learned
rules) is asked of the theory here; whether it is acyclic, of theory/ask.pl
(`check_acyclic`).
"""
from __future__ import annotations

from collections import deque
from dataclasses import dataclass, field
from itertools import combinations
from typing import Iterable

from pantarhei.bridge.theories.facts import term_text
from pantarhei.bridge.theories.well_formed import KINDS, NAME, RULE_NAME, check_literal, value_text
from pantarhei.theory import TheoryFileError, check_message


@dataclass(frozen=True)
class Rule:
    id: str
    kind: str
    head: str
    body: tuple[str, ...] = ()


@dataclass
class Theory:
    """A defeasible theory. `source` names the file it came from."""
    facts: list[str] = field(default_factory=list)
    rules: list[Rule] = field(default_factory=list)
    sup: list[tuple[str, str]] = field(default_factory=list)
    learned: set[str] = field(default_factory=set)
    extra: list[str] = field(default_factory=list)
    source: str = "<theory>"
    #: `setting(Key, Value)` facts of a learned theory (what its exploration
    #: was run with), values in file order; str or int.
    settings: dict[str, list] = field(default_factory=dict)
    #: `provenance(Rule, Key, Value)` facts of a learned theory (where each
    #: rule comes from), in file order; values str or int.
    provenance: list[tuple[str, str, str | int]] = field(default_factory=list)
    #: The line of each rule's `rule/3` fact (or DFL rule) in `source`.
    lines: dict[str, int] = field(default_factory=dict, compare=False, repr=False)
    #: The line of each `body(Id, L)` fact, by (Id, L); of `fact(L)`, by ("", L).
    body_lines: dict[tuple[str, str], int] = field(default_factory=dict, compare=False, repr=False)
    #: DFL rules with variables, grounded when read: (`file:line`, label).
    schemas: list[tuple[str, str]] = field(default_factory=list, compare=False, repr=False)
    #: The first line of each `sup(A, B)` fact (or DFL `A > B`), by ("sup",
    #: A, B); of each `provenance(Id, Key, V)` fact, by ("provenance", Id, Key).
    fact_lines: dict[tuple[str, str, str], int] = field(default_factory=dict, compare=False,
                                                       repr=False)

    def confidences(self) -> dict[str, int]:
        """Each rule's confidence in permille, P(head | body), for the rules
        whose provenance records one (`provenance(R, confidence_permille,
        C)`); theory/learned_rules.pl gives the likelihood, rank and
        verdict that follow from it."""
        return {str(r): int(v) for r, k, v in self.provenance if k == "confidence_permille"}

    def rule(self, rule_id: str) -> Rule:
        for r in self.rules:
            if r.id == rule_id:
                return r
        raise KeyError(rule_id)

    def where(self, rule_id: str) -> str:
        """`file:line` of a rule (line 0 when not known)."""
        return f"{self.source}:{self.lines.get(rule_id, 0)}"

    def literals(self) -> set[str]:
        """The literals of facts, heads and bodies."""
        out = set(self.facts)
        for r in self.rules:
            out.add(r.head)
            out.update(r.body)
        return out

    def with_facts(self, facts: Iterable[str]) -> "Theory":
        """A copy with more facts."""
        extra = [f for f in facts if f not in self.facts]
        return Theory(self.facts + extra, list(self.rules), list(self.sup), set(self.learned),
                      list(self.extra), self.source,
                      {k: list(v) for k, v in self.settings.items()}, list(self.provenance),
                      dict(self.lines), dict(self.body_lines), list(self.schemas),
                      dict(self.fact_lines))

    def native(self) -> str:
        """The theory in the native format: everything it holds (settings
        first, each rule's provenance after it)."""
        lines = [f"setting({k}, {value_text(v)})." for k, vs in self.settings.items() for v in vs]
        lines += [f"fact({f})." for f in self.facts]
        of_rule: dict[str, list[tuple[str, str | int]]] = {}
        for rid, key, value in self.provenance:
            of_rule.setdefault(rid, []).append((key, value))
        for r in self.rules:
            lines.append(f"rule({r.id}, {r.kind}, {r.head}).")
            lines.extend(f"body({r.id}, {b})." for b in r.body)
            if r.id in self.learned:
                lines.append(f"learned({r.id}).")
            lines.extend(f"provenance({r.id}, {k}, {value_text(v)})." for k, v in of_rule.pop(r.id, ()))
        lines.extend(f"sup({a}, {b})." for a, b in self.sup)
        rules = {r.id for r in self.rules}
        lines.extend(f"learned({x})." for x in sorted(self.learned - rules))
        lines.extend(f"provenance({rid}, {k}, {value_text(v)})." for rid, kvs in of_rule.items() for k, v in kvs)
        lines.extend(self.extra)
        return "\n".join(lines) + "\n"

    def encoded(self) -> str:
        """The theory as clingo's encodings read it: its facts, rules,
        superiority, learned rules and their provenance, and nothing else:
        not its settings nor the facts kept aside, which an encoding would
        take for its own (`changed.`, `superior(r2, r1).`, `concl(...)`)."""
        return Theory(self.facts, self.rules, self.sup, self.learned,
                      provenance=self.provenance).native()

    def specificity(self) -> list[tuple[str, str]]:
        """The superiority that specificity gives over learned rules: a rule
        R (learned or written by hand) beats a learned rule S when their
        heads conflict, S's body is strictly inside R's, and sup/2 does not
        say S beats R (as theory/superiority.pl)."""
        explicit = set(self.sup)
        learned = [r for r in self.rules if r.id in self.learned]
        by_head: dict[str, list[Rule]] = {}
        by_body: dict[tuple[str, frozenset], list[Rule]] = {}
        for r in learned:
            by_head.setdefault(r.head, []).append(r)
            by_body.setdefault((r.head, frozenset(r.body)), []).append(r)
        out = []
        for r in self.rules:
            rb = frozenset(r.body)
            against = complement(r.head)
            rivals = by_head.get(against, ())
            if len(rb) < 20 and 2 ** len(rb) < len(rivals):
                # fewer strict subsets of the body than rules against it
                found = [s for sub in _strict_subsets(sorted(rb))
                         for s in by_body.get((against, sub), ())]
                found.sort(key=lambda s: rivals.index(s) if len(rivals) < 64 else 0)
            else:
                found = [s for s in rivals if set(s.body) < rb]
            out.extend((r.id, s.id) for s in found
                       if (s.id, r.id) not in explicit and (r.id, s.id) not in explicit)
        return out

    def acyclic(self) -> bool:
        """No literal depends on itself through the rules for it or for
        its complement (literals and their negations count as one)."""
        def atom(lit: str) -> str:
            return complement(lit) if lit.startswith("neg(") else lit
        edges: dict[str, set[str]] = {}
        for r in self.rules:
            edges.setdefault(atom(r.head), set()).update(atom(b) for b in r.body)
        state: dict[str, int] = {}
        for start in edges:
            if state.get(start):
                continue
            stack = [(start, iter(edges.get(start, ())))]
            state[start] = 1
            while stack:
                node, it = stack[-1]
                nxt = next(it, None)
                if nxt is None:
                    state[node] = 2
                    stack.pop()
                elif state.get(nxt) == 1:
                    return False
                elif not state.get(nxt):
                    state[nxt] = 1
                    stack.append((nxt, iter(edges.get(nxt, ()))))
        return True

    def validate(self) -> None:
        """Raise TheoryFileError (`file:line: what`) for what the engines
        cannot read: bad rule names or kinds, a second rule of a name,
        literals that are not names or terms of names and integers..."""
        ids: set[str] = set()
        for r in self.rules:
            where = self.where(r.id)
            if not NAME.match(r.id):
                raise TheoryFileError(f"{where}: " + RULE_NAME.format(r.id))
            if r.kind not in KINDS:
                raise TheoryFileError(f"{where}: " + check_message("kind", r.id, r.kind))
            if r.id in ids:
                raise TheoryFileError(f"{where}: " + check_message("second_rule", r.id))
            ids.add(r.id)
            for lit in (r.head, *r.body):
                check_literal(lit, where)
        for f in self.facts:
            check_literal(f, f"{self.source}:0")

    def check_acyclic(self) -> None:
        """Raise TheoryFileError if the superiority relation (sup/2 with
        specificity) has a cycle: a rule could then beat itself, and a
        literal and its complement both be concluded. The check is
        theory/ask.pl's (bridge/theories/prolog_checks.py, which also
        checks the general rules), its error naming the line that says the
        cycle's first pair (`source: what` where no line is known)."""
        if not self.sup:
            return
        from pantarhei.bridge.theories.prolog_checks import check

        check([self])

    def _specific_successors(self):
        """rule id -> the learned rules it beats by specificity (sup/2 not
        saying otherwise), computed when asked."""
        explicit = set(self.sup)
        rules = {r.id: r for r in self.rules}
        by_head: dict[str, list[Rule]] = {}
        for r in self.rules:
            if r.id in self.learned:
                by_head.setdefault(r.head, []).append(r)

        def successors(rid: str) -> list[str]:
            r = rules.get(rid)
            if r is None:
                return []
            rb = set(r.body)
            return [s.id for s in by_head.get(complement(r.head), ())
                    if set(s.body) < rb and (s.id, r.id) not in explicit and (r.id, s.id) not in explicit]
        return successors


def antecedent_id(i: int) -> str:
    """The id of the i-th explored antecedent in provenance facts and the
    trace: `a<i>`, as theory/learned_rules.pl's antecedent_id/2 writes it
    (tests/bridge/theories/test_model.py keeps the two equal)."""
    return f"a{int(i)}"


def antecedent_index(aid: str) -> int | None:
    """i for an antecedent id `a<i>` (i in the digits 0 to 9), None for
    anything else (`none`): as antecedent_id/2 reads it."""
    digits = aid[1:]
    return int(digits) if aid[:1] == "a" and digits.isascii() and digits.isdigit() else None



def superiority_cycle(pairs: Iterable[tuple[str, str]], more=None) -> list[str] | None:
    """A shortest cycle [r, ..., r] of the relation `pairs` through the
    first rule (in sorted order) that lies on one; None if it is acyclic.
    Not a check of a theory (that is theory/ask.pl's, `check_acyclic`):
    plan's search asks it of the pairs it would add, many times a plan.
    `more(r)`, if given, lists further successors of r (a relation too
    large to list whole); then only cycles through `pairs` are looked for.
    Linear in the rules and pairs: the rules on a cycle are those of the
    relation's strongly connected components (Tarjan's, without recursion),
    and one breadth-first search from the first of them gives the cycle."""
    succ: dict[str, list[str]] = {}
    for a, b in pairs:
        succ.setdefault(a, []).append(b)
    cache: dict[str, list[str]] = {}

    def following(node: str) -> list[str]:
        if more is None:
            return succ.get(node, [])
        if node not in cache:
            cache[node] = succ.get(node, []) + more(node)
        return cache[node]
    component = _components(sorted(succ), following)
    start = next((r for r in sorted(succ)
                  if any(component[b] == component[r] for b in succ[r])), None)
    if start is None:
        return None
    parent: dict[str, str] = {}
    queue = deque()
    for b in succ[start]:
        if b not in parent:
            parent[b] = start
            queue.append(b)
    while queue:
        node = queue.popleft()
        if node == start:
            path = [start]
            node = parent[start]
            while node != start:
                path.append(node)
                node = parent[node]
            path.append(start)
            return path[::-1]
        for nxt in following(node):
            if nxt not in parent:
                parent[nxt] = node
                queue.append(nxt)
    return None


def _components(roots: list[str], following) -> dict[str, int]:
    """The strongly connected component of each node reachable from `roots`
    in the relation `following` (Tarjan's, iteratively): two nodes lie on
    a cycle together when they have the same."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    component: dict[str, int] = {}
    for root in roots:
        if root in index:
            continue
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        work = [(root, iter(following(root)))]
        while work:
            node, edges = work[-1]
            pushed = False
            for nxt in edges:
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(following(nxt))))
                    pushed = True
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            if pushed:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                while True:
                    x = stack.pop()
                    on_stack.discard(x)
                    component[x] = index[node]
                    if x == node:
                        break
    return component


def _strict_subsets(items: list[str]):
    for k in range(len(items)):
        for c in combinations(items, k):
            yield frozenset(c)


def literal_text(value) -> str:
    """A value of a theory file (str, int, `Text` or tuple) as native text:
    quoted text stays quoted and escaped."""
    return term_text(value)


def complement(lit: str) -> str:
    return lit[4:-1] if lit.startswith("neg(") and lit.endswith(")") else f"neg({lit})"


