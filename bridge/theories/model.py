"""Defeasible theories as Python values: read and write the native format.

The native format is ground facts that SWI-Prolog and clingo both read:

    fact(L).  rule(Id, Kind, Head).  body(Id, L).  sup(R1, R2).  learned(Id).

Literals are kept as their native text (`bird(tweety)`, `neg(flies(tweety))`),
which is also how both engines print them. Facts of other predicates
(provenance, settings) are kept aside and written back unchanged.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable

from pantarhei.theory import TheoryFileError, read_facts

KINDS = ("strict", "defeasible", "defeater")
_NAME = re.compile(r"^[a-z][A-Za-z0-9_]*$")


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

    def rule(self, rule_id: str) -> Rule:
        for r in self.rules:
            if r.id == rule_id:
                return r
        raise KeyError(rule_id)

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
                      {k: list(v) for k, v in self.settings.items()}, list(self.provenance))

    def native(self) -> str:
        """The theory in the native format: everything it holds (settings
        first, each rule's provenance after it)."""
        lines = [f"setting({k}, {_value_text(v)})." for k, vs in self.settings.items() for v in vs]
        lines += [f"fact({f})." for f in self.facts]
        of_rule: dict[str, list[tuple[str, str | int]]] = {}
        for rid, key, value in self.provenance:
            of_rule.setdefault(rid, []).append((key, value))
        for r in self.rules:
            lines.append(f"rule({r.id}, {r.kind}, {r.head}).")
            lines.extend(f"body({r.id}, {b})." for b in r.body)
            if r.id in self.learned:
                lines.append(f"learned({r.id}).")
            lines.extend(f"provenance({r.id}, {k}, {_value_text(v)})." for k, v in of_rule.pop(r.id, ()))
        lines.extend(f"sup({a}, {b})." for a, b in self.sup)
        lines.extend(f"provenance({rid}, {k}, {_value_text(v)})." for rid, kvs in of_rule.items() for k, v in kvs)
        lines.extend(self.extra)
        return "\n".join(lines) + "\n"

    def specificity(self) -> list[tuple[str, str]]:
        """The superiority that specificity gives among learned rules: R
        beats S when their heads conflict, S's body is strictly inside R's,
        and sup/2 does not say S beats R (as theory/defeasible.pl)."""
        explicit = set(self.sup)
        learned = [r for r in self.rules if r.id in self.learned]
        by_head: dict[str, list[Rule]] = {}
        for r in learned:
            by_head.setdefault(r.head, []).append(r)
        out = []
        for r in learned:
            rb = set(r.body)
            for s in by_head.get(complement(r.head), ()):
                if set(s.body) < rb and (s.id, r.id) not in explicit and (r.id, s.id) not in explicit:
                    out.append((r.id, s.id))
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
        cannot read: unknown kinds, dangling bodies, double negation..."""
        text = _text_of(self.source)
        ids: dict[str, Rule] = {}
        for r in self.rules:
            where = _line(text, rf"rule\(\s*{re.escape(r.id)}\s*,", self.source)
            if not _NAME.match(r.id):
                raise TheoryFileError(f"{where}: a rule name in lower case letters, digits and _, not '{r.id}'")
            if r.kind not in KINDS:
                raise TheoryFileError(f"{where}: rule {r.id}: kind strict, defeasible or defeater, not {r.kind}")
            if r.id in ids:
                raise TheoryFileError(f"{where}: a second rule named {r.id}")
            ids[r.id] = r
            for lit in (r.head, *r.body):
                _check_literal(lit, where)
        for f in self.facts:
            _check_literal(f, _line(text, rf"fact\(\s*{re.escape(f)}", self.source))

    def check_acyclic(self) -> None:
        """Raise TheoryFileError if the superiority relation (sup/2 with
        specificity) has a cycle: a rule could then beat itself, and a
        literal and its complement both be concluded."""
        cycle = superiority_cycle(self.sup + self.specificity())
        if cycle:
            a, b = cycle[0], cycle[1]
            where = _line(_text_of(self.source), rf"sup\(\s*{re.escape(a)}\s*,\s*{re.escape(b)}\s*\)"
                                                 rf"|\b{re.escape(a)}\s*>\s*{re.escape(b)}\b", self.source)
            raise TheoryFileError(f"{where.removesuffix(':0')}: the superiority relation has a cycle, "
                                  f"{' > '.join(cycle)}: it must be acyclic")

    def check_superiority(self) -> None:
        """Raise TheoryFileError if sup/2 names a rule that does not exist."""
        text = _text_of(self.source)
        ids = {r.id for r in self.rules}
        for a, b in self.sup:
            for x in (a, b):
                if x not in ids:
                    where = _line(text, rf"sup\(\s*{re.escape(a)}\s*,\s*{re.escape(b)}\b"
                                        rf"|\b{re.escape(a)}\s*>\s*{re.escape(b)}\b", self.source)
                    raise TheoryFileError(f"{where}: sup({a}, {b}) names {x}, which is not a rule")


def rule_id(antecedent: int, expectation: str) -> str:
    """The id of Algorithm 1's rule for the i-th explored antecedent and an
    expectation (theory/curiosity.pl makes the same ids): `r<i>_<E>`."""
    return f"r{int(antecedent)}_{expectation}"


def antecedent_id(i: int) -> str:
    """The id of the i-th explored antecedent in provenance facts: `a<i>`."""
    return f"a{int(i)}"


def antecedent_index(aid: str) -> int | None:
    """i for an antecedent id `a<i>`, None for anything else (`none`)."""
    return int(aid[1:]) if len(aid) > 1 and aid[0] == "a" and aid[1:].isdigit() else None


def _value_text(value) -> str:
    """A setting's or provenance's value as native text: integers and atoms
    as they are, anything else quoted."""
    if isinstance(value, int) or (isinstance(value, str) and _NAME.match(value)):
        return str(value)
    if isinstance(value, str) and re.match(r"^[a-z][A-Za-z0-9_]*\(.*\)$", value):
        return value
    return '"' + str(value).replace("\\", "\\\\").replace('"', '\\"') + '"'


def superiority_cycle(pairs: Iterable[tuple[str, str]]) -> list[str] | None:
    """A shortest cycle [r, ..., r] of the relation `pairs` through the
    first rule (in sorted order) that lies on one; None if it is acyclic."""
    succ: dict[str, list[str]] = {}
    for a, b in pairs:
        succ.setdefault(a, []).append(b)
    for start in sorted(succ):
        paths = {b: [start, b] for b in succ[start]}
        queue = list(paths)
        while queue:
            node = queue.pop(0)
            if node == start:
                return paths[node]
            for nxt in succ.get(node, ()):
                if nxt not in paths:
                    paths[nxt] = paths[node] + [nxt]
                    queue.append(nxt)
    return None


def literal_text(value) -> str:
    """A value of `read_facts` (str, int or tuple) as native text."""
    if isinstance(value, tuple):
        return f"{value[0]}({','.join(literal_text(v) for v in value[1:])})"
    return str(value)


def complement(lit: str) -> str:
    return lit[4:-1] if lit.startswith("neg(") and lit.endswith(")") else f"neg({lit})"


def _check_literal(lit: str, where: str) -> None:
    inner = complement(lit) if lit.startswith("neg(") else lit
    if inner.startswith("neg("):
        raise TheoryFileError(f"{where}: a literal or its negation neg(L), not a double negation {lit}")
    name = inner.split("(", 1)[0]
    if not _NAME.match(name):
        raise TheoryFileError(f"{where}: a literal such as p or bird(tweety), not {lit}")


def _text_of(source: str) -> str:
    try:
        return Path(source).read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""


def _line(text: str, pattern: str, source: str) -> str:
    m = re.search(pattern, text)
    line = text.count("\n", 0, m.start()) + 1 if m else 0
    return f"{source}:{line}"


def read_native(path: Path | str) -> Theory:
    """Read a native theory file; TheoryFileError names file and line."""
    path = Path(path)
    facts = read_facts([path])
    t = Theory(source=str(path))
    t.facts = [literal_text(f[0]) for f in facts.get("fact", []) if len(f) == 1]
    bodies: dict[str, list[str]] = {}
    for args in facts.get("body", []):
        if len(args) == 2:
            bodies.setdefault(literal_text(args[0]), []).append(literal_text(args[1]))
    rule_ids = set()
    for args in facts.get("rule", []):
        if len(args) != 3:
            continue
        rid, kind, head = (literal_text(a) for a in args)
        rule_ids.add(rid)
        t.rules.append(Rule(rid, kind, head, tuple(dict.fromkeys(bodies.get(rid, ())))))
    text = _text_of(str(path))
    for rid in bodies:
        if rid not in rule_ids:
            where = _line(text, rf"body\(\s*{re.escape(rid)}\s*,", str(path))
            raise TheoryFileError(f"{where}: body({rid}, _) of a rule {rid} that has no rule({rid}, Kind, Head) fact")
    t.sup = [(literal_text(a), literal_text(b)) for a, b in
             (x for x in facts.get("sup", []) if len(x) == 2)]
    t.learned = {literal_text(x[0]) for x in facts.get("learned", []) if len(x) == 1}
    for args in facts.get("setting", []):
        if len(args) == 2:
            value = args[1] if isinstance(args[1], (str, int)) else literal_text(args[1])
            t.settings.setdefault(literal_text(args[0]), []).append(value)
    for args in facts.get("provenance", []):
        if len(args) == 3:
            value = args[2] if isinstance(args[2], (str, int)) else literal_text(args[2])
            t.provenance.append((literal_text(args[0]), literal_text(args[1]), value))
    t.validate()
    return t


def merge(theories: list[Theory]) -> Theory:
    """One theory from several files (a learned theory and rules added by
    hand); rule names must be distinct, sup/2 may cross files."""
    if len(theories) == 1:
        return theories[0]
    out = Theory(source=" + ".join(t.source for t in theories))
    owner: dict[str, str] = {}
    for t in theories:
        for f in t.facts:
            if f not in out.facts:
                out.facts.append(f)
        for r in t.rules:
            if r.id in owner:
                where = _line(_text_of(t.source), rf"{re.escape(r.id)}\b", t.source)
                raise TheoryFileError(f"{where}: rule {r.id} is already defined in {owner[r.id]}")
            owner[r.id] = t.source
            out.rules.append(r)
        out.sup.extend(t.sup)
        out.learned |= t.learned
        for k, values in t.settings.items():
            have = out.settings.setdefault(k, [])
            have.extend(v for v in values if v not in have)
        out.provenance.extend(t.provenance)
    return out
