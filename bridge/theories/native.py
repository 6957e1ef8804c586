"""The native theory format read: the facts of a file (`fact/1`,
`rule/3`, `body/2`, `sup/2`, `learned/1`, `setting/2`, `provenance/3`, any
other kept aside) checked against their forms and gathered into a
`Theory`; `explored/2` and `held/4` (the explored antecedents' pours,
which answers cite) are checked and kept aside. `Theory.native()` writes
it back."""
from __future__ import annotations

from pathlib import Path

from pantarhei.bridge.theories import facts as theory_facts
from pantarhei.bridge.theories.facts import Fact, term_text
from pantarhei.bridge.theories.model import Rule, Theory
from pantarhei.bridge.theories.well_formed import KINDS, NAME, check_literal
from pantarhei.theory import TheoryFileError, check_message


def read_native(path: Path | str) -> Theory:
    """Read a native theory file; TheoryFileError names file and line."""
    facts = theory_facts.read(path)
    with theory_facts._no_gc():
        return from_facts(facts, str(path))


#: The predicates of a theory, with the form each is written in.
FORMS = {("fact", 1): "fact(L)", ("rule", 3): "rule(Id, Kind, Head)", ("body", 2): "body(Id, L)",
         ("sup", 2): "sup(R1, R2)", ("learned", 1): "learned(Id)",
         ("setting", 2): "setting(Key, Value)", ("provenance", 3): "provenance(Id, Key, Value)",
         ("explored", 2): "explored(Antecedent, Proposition)",
         ("held", 4): "held(Antecedent, Expectation, Held, Pours)"}
_FORM_OF = {name: form for (name, _), form in FORMS.items()}


_NAMES_AT = {"rule": (0,), "body": (0,), "sup": (0, 1), "learned": (0,), "setting": (0,),
             "provenance": (0, 1), "explored": (0, 1), "held": (0, 1), "fact": ()}
_LITERAL_AT = {"fact": 0, "rule": 2, "body": 1}


def check_fact(f: Fact, source: str, checked: set | None = None) -> None:
    """TheoryFileError (`file:line: what`) if a fact of a theory predicate
    is not of its form (theory_files:check_theory_fact/2 in Prolog).
    `checked` holds literals already found good (a theory repeats them)."""
    form = _FORM_OF.get(f.name)
    if form is None:
        return
    a = f.args
    if (f.name, len(a)) not in FORMS:
        raise TheoryFileError(f"{source}:{f.line}: " + check_message("arity", form, f.name, len(a)))
    for i in _NAMES_AT[f.name]:
        if not (type(a[i]) is str and NAME.match(a[i])):
            raise TheoryFileError(f"{source}:{f.line}: "
                                  + check_message("name_argument", form, term_text(a[i])))
    if f.name == "rule" and a[1] not in KINDS:
        raise TheoryFileError(f"{source}:{f.line}: " + check_message("kind", a[0], term_text(a[1])))
    if f.name == "held" and not (type(a[2]) is int and type(a[3]) is int and 0 <= a[2] <= a[3]):
        raise TheoryFileError(f"{source}:{f.line}: "
                              + check_message("held", a[0], a[1], term_text(a[2]), term_text(a[3])))
    if f.name == "provenance" and a[1] == "confidence_permille" \
            and not (type(a[2]) is int and 1 <= a[2] <= 1000):
        raise TheoryFileError(f"{source}:{f.line}: "
                              + check_message("confidence", a[0], term_text(a[2])))
    i = _LITERAL_AT.get(f.name)
    if i is not None:
        lit = a[i] if type(a[i]) is str else term_text(a[i])
        if checked is None or lit not in checked:
            check_literal(lit, f"{source}:{f.line}")
            if checked is not None:
                checked.add(lit)


def from_facts(facts: list[Fact], source: str, t: Theory | None = None) -> Theory:
    """A theory of the facts of a file (checked: TheoryFileError with
    `file:line: what`); added to `t` if given."""
    t = t if t is not None else Theory(source=source)
    bodies: dict[str, list[str]] = {}
    heads: list[tuple[str, str, str]] = []
    first_body: dict[str, int] = {}
    lines, body_lines = t.lines, t.body_lines
    checked: set[str] = set()
    names: set[str] = set()
    for f in facts:
        name, a = f.name, f.args
        if name == "body" and len(a) == 2:
            rid, lit = a
            if type(lit) is not str:
                lit = term_text(lit)
            if lit not in checked or rid not in names:
                check_fact(f, source, checked)
                names.add(rid)
        else:
            check_fact(f, source, checked)
        if name == "body":
            have = bodies.get(rid)
            if have is None:
                bodies[rid] = [lit]
                first_body[rid] = f.line
            else:
                have.append(lit)
            body_lines.setdefault((rid, lit), f.line)
        elif name == "rule":
            rid = a[0]
            if rid in lines:
                raise TheoryFileError(f"{source}:{f.line}: " + check_message("second_rule", rid))
            lines[rid] = f.line
            heads.append((rid, a[1], a[2] if type(a[2]) is str else term_text(a[2])))
        elif name == "learned":
            t.learned.add(a[0])
        elif name == "fact":
            t.facts.append(term_text(a[0]))
            body_lines.setdefault(("", t.facts[-1]), f.line)
        elif name == "sup":
            t.sup.append((a[0], a[1]))
            t.fact_lines.setdefault(("sup", a[0], a[1]), f.line)
        elif name == "setting":
            t.settings.setdefault(a[0], []).append(_plain(a[1]))
        elif name == "provenance":
            t.provenance.append((a[0], a[1], _plain(a[2])))
            t.fact_lines.setdefault(("provenance", a[0], a[1]), f.line)
        else:
            t.extra.append(f.text + ".")
    for rid, line in first_body.items():
        if rid not in t.lines:
            raise TheoryFileError(f"{source}:{line}: "
                                  + check_message("dangling_body", rid, rid, rid))
    t.rules.extend(Rule(rid, kind, head, tuple(dict.fromkeys(bodies.get(rid, ()))))
                   for rid, kind, head in heads)
    return t


def _plain(value) -> str | int:
    """A setting's or provenance's value: int, name or Text as they are, a
    term as its native text."""
    return value if isinstance(value, (str, int)) else term_text(value)

