"""DFL, the theory format of SPINdle and silkie, read and written.

    r1: bird(tweety), -penguin(tweety) => flies(tweety)   % defeasible
    r2: penguin(X) -> bird(X)        strict (with silkie's ?x variables)
    r3: broken_wing ~> -flies(tweety)                      defeater
    r3 > r1                                                superiority
    >> bird(tweety)                                        a fact (SPINdle)
    -> bird(tweety)                                        a strict fact
    => bird(tweety)                                        a defeasible fact

A fact `>> a` or `-> a` is definite (+D a). A defeasible fact `=> a` is a
defeasible rule with an empty body, as in silkie and in defeasible logic:
it gives +d a but never +D a, and a rule for -a that beats it, a defeater
for -a or a definite -a defeats it. It is named like any rule without a
label. A labelled `f: -> a` / `f: => a` is a strict / defeasible
rule with an empty body (a strict one proves +D a like a fact).

`-` (or `¬`) negates a literal; comments start with `#`, `%` or `//`.
The superiority relation (`r1 > r2`, with the specificity of learned
rules) must be acyclic: a cycle, or a rule superior to itself, is an
error naming its rules and the line of its first pair (theory/ask.pl's
check, made when the file is loaded: bridge/theories/prolog_checks.py).

Rules with variables (`?x`, or a name starting with an upper-case letter
inside an argument list) are grounded over the facts: every instance whose
body literals all occur among the facts or the heads of other instances.
Rules without a label get `r<line>` (`line<line>` if another rule is
labelled `r<line>`).

What DFL has no form for (`learned/1`, `setting/2`, `provenance/3` and any
other fact of a native theory) is written as a comment that holds the
native fact, `# pantarhei: learned(r1).`, read back as in a native file
(SPINdle and silkie skip it). The superiority that specificity gives
over learned rules is written out too (`r4 > r3 # specificity`), so that
those tools conclude the same; it is read back as specificity again when
the rule beaten is learned.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Sequence

from pantarhei.theory import TheoryFileError

from pantarhei.bridge.theories import facts as theory_facts
from pantarhei.bridge.errors import quoted
from pantarhei.bridge.files import is_dfl  # noqa: F401  (the format's test, with the format)
from pantarhei.bridge.theories.model import Rule, Theory, complement
from pantarhei.bridge.theories.native import from_facts
from pantarhei.bridge.theories.well_formed import value_text

#: The most rule instances grounding a file's rules with variables may give,
#: and the most partial bindings it may try on the way (all rounds of its
#: fixpoint together): past either, the file is refused at the rule's line,
#: so that a small file cannot ask for |facts|^variables instances.
GROUND_AT_MOST = 20_000
GROUND_STEPS_AT_MOST = 2_000_000

#: A comment holding a native fact DFL has no form for.
ANNOTATION = "# pantarhei: "
#: The native predicates DFL has a form for, which no such comment holds.
_DFL_FORMS = {"fact", "rule", "body", "sup"}
_ANNOTATION = re.compile(r"^\s*#\s*pantarhei:\s?(.*)$")
_DERIVED = re.compile(r"^\s*([a-z][A-Za-z0-9_]*)\s*>\s*([a-z][A-Za-z0-9_]*)\s*#\s*specificity\s*$")

_ARROWS = (("->", "strict"), ("=>", "defeasible"), ("~>", "defeater"))
_TERM = re.compile(r"^[a-z][A-Za-z0-9_]*(\((.*)\))?$")
_ARG = re.compile(r"^(\?[A-Za-z_][A-Za-z0-9_]*|[A-Z][A-Za-z0-9_]*|[a-z][A-Za-z0-9_]*|-?[0-9]+)$")


def read_dfl(path: Path | str) -> Theory:
    path = Path(path)
    if not path.is_file():
        raise TheoryFileError(f"{path}: no such file")
    return parse_dfl(path.read_text(encoding="utf-8", errors="replace"), str(path))


def parse_dfl(text: str, source: str = "<dfl>") -> Theory:
    """A theory from DFL text; TheoryFileError names source and line."""
    t = Theory(source=source)
    raws = text.splitlines()
    annotations, derived = _annotations(raws, source)
    lines = [re.split(r"#|%|//", raw, maxsplit=1)[0].strip() for raw in raws]
    schemas, sups = _statements(lines, source, t)
    t.rules, origin = _ground(schemas, t.facts, source)
    _add_superiority(t, sups, schemas, origin, source)
    seen: dict[str, int] = {}
    for r, n in schemas:
        if r.id in seen:
            raise TheoryFileError(f"{source}:{n}: a second rule labelled {r.id} (line {seen[r.id]})")
        seen[r.id] = n
        if _variables(r.head) or any(map(_variables, r.body)):
            t.schemas.append((f"{source}:{n}", r.id))
    for r in t.rules:
        t.lines[r.id] = seen.get(origin[r.id], 0)
    if annotations:
        from_facts(annotations, source, t)
        t.sup = [p for p in t.sup if not (p in derived and p[1] in t.learned)]
    return t


def _annotations(raws: list[str], source: str) -> tuple[list, set[tuple[str, str]]]:
    """The native facts the comments hold (`# pantarhei: ...`), and the
    superiority pairs written as specificity's (`r4 > r3 # specificity`)."""
    annotations = []
    derived = set()
    for n, raw in enumerate(raws, start=1):
        m = _ANNOTATION.match(raw)
        if m:
            held = theory_facts.parse(m.group(1), source, n)
            for f in held:
                if f.name in _DFL_FORMS:      # a comment carries no rules
                    raise TheoryFileError(
                        f"{source}:{n}: {ANNOTATION.strip()} comments hold what DFL has no form "
                        f"for, not {f.name}/{len(f.args)}: write rules, facts and superiority "
                        f"as DFL")
            annotations.extend(held)
        m = _DERIVED.match(raw)
        if m:
            derived.add((m.group(1), m.group(2)))
    return annotations, derived


def _statements(lines: list[str], source: str,
                t: Theory) -> tuple[list[tuple[Rule, int]], list[tuple[str, str, int]]]:
    """The rules (with variables, and their lines) and superiority pairs
    (with their lines) of the lines without comments; facts go into `t`."""
    schemas: list[tuple[Rule, int]] = []
    sups: list[tuple[str, str, int]] = []
    labels = {m.group(1) for m in (re.match(r"^([A-Za-z0-9_]+)\s*:(?!-)", x) for x in lines) if m}
    for n, line in enumerate(lines, start=1):
        if not line:
            continue
        where = f"{source}:{n}"
        if line.startswith(">>"):
            t.facts.append(_literal(line[2:].strip(), where, ground=True))
            continue
        arrow = next(((a, k) for a, k in _ARROWS if a in line), None)
        if arrow is None:
            m = re.fullmatch(r"([A-Za-z0-9_]+)\s*>\s*([A-Za-z0-9_]+)", line)
            if not m:
                raise TheoryFileError(f"{where}: expected a rule 'label: a, b => c', "
                                      f"a superiority 'r1 > r2' or a fact '>> a'")
            sups.append((m.group(1), m.group(2), n))
            continue
        rule = _rule(line, arrow, n, labels, where)
        if isinstance(rule, str):
            t.facts.append(rule)
        else:
            schemas.append((rule, n))
    return schemas, sups


def _rule(line: str, arrow: tuple[str, str], n: int, labels: set[str], where: str) -> Rule | str:
    """The rule of a line with an arrow, or the literal of a strict fact
    (`-> a`)."""
    label, rest = None, line
    m = re.match(r"^([A-Za-z0-9_]+)\s*:(?!-)\s*(.*)$", line)
    if m:
        label, rest = m.group(1), m.group(2)
    body_text, head_text = rest.split(arrow[0], 1)
    body = tuple(_literal(b, where) for b in _split(body_text, where))
    head = _literal(head_text.strip(), where)
    if not body and label is None and arrow[1] != "defeater":
        if _variables(head):
            raise TheoryFileError(f"{where}: a fact without variables, not {head_text.strip()}")
        if arrow[1] == "strict":
            return head
    rid = label if label is not None else f"r{n}" if f"r{n}" not in labels else f"line{n}"
    if not re.fullmatch(r"[a-z][A-Za-z0-9_]*", rid):
        raise TheoryFileError(f"{where}: a rule label in lower case letters, digits and _, not '{rid}'")
    return Rule(rid, arrow[1], head, body)


def _add_superiority(t: Theory, sups: list[tuple[str, str, int]], schemas: list[tuple[Rule, int]],
                     origin: dict[str, str], source: str) -> None:
    """The superiority pairs, between the instances of rules with variables."""
    ids = {r.id for r in t.rules} | {r.id for r, _ in schemas}
    instances: dict[str, list[str]] = {}
    for r in t.rules:
        instances.setdefault(origin[r.id], []).append(r.id)
    for a, b, n in sups:
        for x in (a, b):
            if not re.fullmatch(r"[a-z][A-Za-z0-9_]*", x):
                raise TheoryFileError(f"{source}:{n}: a rule label in lower case letters, digits and _, not '{x}'")
        # a label not defined here may name a rule of another file (merge)
        left = instances.get(a) or ([] if a in ids else [a])
        right = instances.get(b) or ([] if b in ids else [b])
        for pair in ((x, y) for x in left for y in right):
            t.sup.append(pair)
            t.fact_lines.setdefault(("sup", *pair), n)


def _split(text: str, where: str) -> list[str]:
    parts, depth, cur = [], 0, ""
    for c in text:
        if c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
        if c == "," and depth == 0:
            parts.append(cur.strip())
            cur = ""
        else:
            cur += c
    if cur.strip():
        parts.append(cur.strip())
    if any(not p for p in parts):
        raise TheoryFileError(f"{where}: expected literals separated by commas")
    return parts


def _literal(text: str, where: str, ground: bool = False) -> str:
    """DFL literal text -> native text (variables kept as `?x`)."""
    s = text.strip()
    negated = False
    if s[:1] in ("-", "¬", "~"):
        negated, s = True, s[1:].strip()
    m = _TERM.match(s.replace(" ", ""))
    if not m or re.search(r"[A-Za-z0-9_)]\s+[A-Za-z0-9_(?]", s):
        raise TheoryFileError(f"{where}: expected a literal such as p, -p or bird(tweety), "
                              f"not {quoted(text.strip())}")
    s = s.replace(" ", "")
    if s.split("(", 1)[0] == "not":
        raise TheoryFileError(f"{where}: " + theory_facts.check_message("not_name"))
    if m.group(1):
        args = _split(m.group(2), where)
        for a in args:
            if not _ARG.match(a):
                raise TheoryFileError(f"{where}: expected a constant or a variable ?x as argument, "
                                      f"not {quoted(a)}")
            if a == "not":
                raise TheoryFileError(f"{where}: " + theory_facts.check_message("not_name"))
            if a[0] in "-0123456789" and (problem := theory_facts.integer_problem(a)):
                raise TheoryFileError(f"{where}: {problem}")     # clingo would wrap it
            if ground and _is_var(a):
                raise TheoryFileError(f"{where}: a fact without variables, not '{text.strip()}'")
        s = f"{s.split('(', 1)[0]}({','.join('?' + a.lstrip('?') if _is_var(a) else a for a in args)})"
    return f"neg({s})" if negated else s


def _is_var(arg: str) -> bool:
    return arg.startswith("?") or arg[:1].isupper()


def _variables(lit: str) -> set[str]:
    return set(re.findall(r"\?[A-Za-z0-9_]+", lit))


def _args(lit: str) -> tuple[str, tuple[str, ...]]:
    core = complement(lit) if lit.startswith("neg(") else lit
    sign = "-" if lit.startswith("neg(") else "+"
    if "(" not in core:
        return f"{sign}{core}", ()
    name, inner = core.split("(", 1)
    return f"{sign}{name}/{inner.count(',') + 1}", tuple(inner[:-1].split(","))


def _subst(lit: str, binding: dict[str, str]) -> str:
    return re.sub(r"\?[A-Za-z0-9_]+", lambda m: binding[m.group(0)], lit)


def _ground(schemas: list[tuple[Rule, int]], facts: list[str],
            source: str) -> tuple[list[Rule], dict[str, str]]:
    """Ground rules with variables: instances whose body literals are all
    known (facts, or heads of instances found so far), up to a fixpoint."""
    rules: list[Rule] = []
    origin: dict[str, str] = {}
    open_rules = []
    lines: dict[str, int] = {}
    for r, n in schemas:
        vars_ = set().union(*(_variables(x) for x in (r.head, *r.body)))
        if not vars_:
            rules.append(r)
            origin[r.id] = r.id
            continue
        if not _variables(r.head) <= set().union(*(_variables(b) for b in r.body), set()):
            raise TheoryFileError(f"{source}:{n}: every variable of the head must occur in the body")
        open_rules.append(r)
        lines[r.id] = n
    known = set(facts) | {r.head for r in rules}
    budget = [GROUND_STEPS_AT_MOST]
    done: set[str] = set()
    changed = True
    while changed and open_rules:
        changed = False
        index: dict[str, list[tuple[str, ...]]] = {}
        for lit in known:
            key, args = _args(lit)
            index.setdefault(key, []).append(args)
        for r in open_rules:
            for binding in _matches(r.body, index, budget):
                if budget[0] < 0 or len(rules) >= GROUND_AT_MOST:
                    raise TheoryFileError(
                        f"{source}:{lines[r.id]}: grounding the rules with variables over the "
                        f"facts passes {GROUND_AT_MOST:,} instances or {GROUND_STEPS_AT_MOST:,} "
                        f"bindings tried (at rule {r.id}): write fewer variables or facts, or "
                        f"the instances themselves")
                inst = Rule(f"{r.id}_{'_'.join(binding[v] for v in sorted(binding))}".replace("-", "m"),
                            r.kind, _subst(r.head, binding), tuple(_subst(b, binding) for b in r.body))
                if inst.id not in done:
                    done.add(inst.id)
                    origin[inst.id] = r.id
                    rules.append(inst)
                    if inst.head not in known:
                        known.add(inst.head)
                        changed = True
    return rules, origin


def _matches(body: tuple[str, ...], index: dict[str, list[tuple[str, ...]]], budget: list[int]):
    """The bindings of the body's variables that make every body literal
    one of `index`; every binding tried takes one from budget[0], and when
    it runs out one more binding is given, for the caller to refuse."""
    def go(i: int, binding: dict[str, str]):
        if i == len(body):
            yield dict(binding)
            return
        key, pattern = _args(body[i])
        for args in index.get(key, ()):
            budget[0] -= 1
            if budget[0] < 0:
                yield binding
                return
            b = dict(binding)
            if all(_bind(p, a, b) for p, a in zip(pattern, args)):
                yield from go(i + 1, b)
    yield from go(0, {})


def _bind(p: str, a: str, b: dict[str, str]) -> bool:
    if p.startswith("?"):
        if b.setdefault(p, a) != a:
            return False
        return True
    return p == a


def dfl_literal(lit: str) -> str:
    """Native literal text -> DFL (`neg(p(a))` -> `-p(a)`)."""
    return f"-{complement(lit)}" if lit.startswith("neg(") else lit


def write_dfl(theory: Theory, header: Sequence[str] = ()) -> str:
    """The theory in DFL: facts, rules, then superiority, including the
    superiority that specificity gives learned rules, so that the DFL
    theory has the same conclusions in SPINdle and silkie; every other fact
    as an annotation (`# pantarhei: learned(r1).`), so that nothing is
    lost. `header` lines go first, as comments."""
    arrows = {k: a for a, k in _ARROWS}
    lines = [f"# {h}" for h in header]
    lines += [f"{ANNOTATION}setting({k}, {value_text(v)})." for k, vs in theory.settings.items() for v in vs]
    lines += [f">> {dfl_literal(f)}" for f in theory.facts]
    of_rule: dict[str, list[str]] = {}
    for rid, key, value in theory.provenance:
        of_rule.setdefault(rid, []).append(f"{ANNOTATION}provenance({rid}, {key}, {value_text(value)}).")
    for r in theory.rules:
        body = ", ".join(dfl_literal(b) for b in r.body)
        lines.append(f"{r.id}: {body}{' ' if body else ''}{arrows[r.kind]} {dfl_literal(r.head)}")
        if r.id in theory.learned:
            lines.append(f"{ANNOTATION}learned({r.id}).")
        lines.extend(of_rule.pop(r.id, ()))
    lines.extend(f"{a} > {b}" for a, b in theory.sup)
    rules = {r.id for r in theory.rules}
    lines.extend(f"{ANNOTATION}learned({x})." for x in sorted(theory.learned - rules))
    lines.extend(x for xs in of_rule.values() for x in xs)
    lines.extend(ANNOTATION + x for x in theory.extra)
    derived = theory.specificity()
    if derived:
        lines.append("# superiority of learned rules by specificity")
        lines.extend(f"{a} > {b} # specificity" for a, b in derived)
    return "\n".join(lines) + "\n"
