"""Conformance with silkie (mpomarlan/silkie), the DFL reasoner of the
method's first author, as its proof theory documents it (src/silkie/README.md:
+D, -D, and +d, -d under ambiguity blocking with and without team defeat),
on small DFL theories with defeasible facts (`=> a`), strict facts (`-> a`),
defeaters and superiority, in both engines.

Each expectation is worked out by hand from the definitions; the comments
give the reasoning where it is not immediate. Literals are those of the
theory and their complements. Where silkie's code departs from the
definition (docs/theory-formats.md, "Panta Rhei and silkie"), the expectation follows the
definition and says so.

What is tested is the logic of both engines (bridge/reasoning/logic.py:
theory/defeasible.pl and theory/derivability.lp) on theories read by
bridge/theories/dfl.py: a conformance suite no single module owns, which
docs/theory-formats.md names by this file's path.
"""
from __future__ import annotations

import pytest

from pantarhei.bridge.theories.dfl import parse_dfl
from pantarhei.bridge.reasoning.logic import Semantics, conclusions

BLOCKING = Semantics()
INDIVIDUAL = Semantics(team_defeat=False)
PROPAGATION = Semantics("propagation")


def native(lits: str) -> list[str]:
    return sorted(f"neg({x[1:]})" if x.startswith("-") else x for x in lits.split())


# (name, DFL theory, semantics, +D, -D, +d, -d)
CASES = [
    ("strict fact", "-> a", BLOCKING, "a", "-a", "a", "-a"),
    ("defeasible fact", "=> a", BLOCKING, "", "a -a", "a", "-a"),
    ("SPINdle fact", ">> a", BLOCKING, "a", "-a", "a", "-a"),
    # r1 is strict but its body only +d: it proves b defeasibly, not definitely
    ("strict rule over a defeasible fact", "=> a\nr1: a -> b", BLOCKING,
     "", "a -a b -b", "a b", "-a -b"),
    ("strict chain", "-> a\nr1: a -> b", BLOCKING, "a b", "-a -b", "a b", "-a -b"),
    # +D -a: the rule for a is not applicable against a definite complement
    ("defeasible fact against a strict fact", "=> a\n-> -a", BLOCKING, "-a", "a", "-a", "a"),
    # each fact is an applicable attacker of the other, and neither is superior
    ("conflicting defeasible facts", "=> a\n=> -a", BLOCKING, "", "a -a", "", "a -a"),
    ("conflicting defeasible facts, one superior", "f1: => a\nf2: => -a\nf1 > f2", BLOCKING,
     "", "a -a", "a", "-a"),
    # d1 attacks a, and no rule for a is superior to it; a defeater supports nothing
    ("defeasible fact and a defeater", "=> a\n-> b\nd1: b ~> -a", BLOCKING,
     "b", "a -a -b", "b", "a -a -b"),
    ("defeater beaten by superiority", "f1: => a\n-> b\nd1: b ~> -a\nf1 > d1", BLOCKING,
     "b", "a -a -b", "a b", "-a -b"),
    # b has no rule: -d b, so d1 is not applicable and a stands
    ("defeater that does not apply", "=> a\nd1: b ~> -a", BLOCKING,
     "", "a -a b -b", "a", "-a b -b"),
    ("defeater alone", "-> b\nd1: b ~> a", BLOCKING, "b", "a -a -b", "b", "a -a -b"),
    ("defeaters cannot beat a strict fact", "-> a\n-> b\nd1: b ~> -a", BLOCKING,
     "a b", "-a -b", "a b", "-a -b"),
    ("tweety", "-> bird\n-> penguin\nr1: bird => flies\nr2: penguin => -flies\nr2 > r1", BLOCKING,
     "bird penguin", "-bird -penguin flies -flies", "bird penguin -flies", "-bird -penguin flies"),
    ("tweety without superiority", "-> bird\n-> penguin\nr1: bird => flies\nr2: penguin => -flies",
     BLOCKING, "bird penguin", "-bird -penguin flies -flies", "bird penguin", "-bird -penguin flies -flies"),
    # +D b through the strict rule; r2 cannot win against it, superiority or not
    ("strict beats defeasible whatever the superiority", "-> a\nr1: a -> b\nr2: a => -b\nr2 > r1",
     BLOCKING, "a b", "-a -b", "a b", "-a -b"),
    # team defeat: r3 is beaten by r1 and r4 by r2, so p; -p has unbeaten attackers
    ("team defeat", "-> a\n-> b\nr1: a => p\nr2: b => p\nr3: a => -p\nr4: b => -p\nr1 > r3\nr2 > r4",
     BLOCKING, "a b", "-a -b p -p", "a b p", "-a -b -p"),
    # without team defeat no single rule for p beats both r3 and r4
    ("no team defeat", "-> a\n-> b\nr1: a => p\nr2: b => p\nr3: a => -p\nr4: b => -p\nr1 > r3\nr2 > r4",
     INDIVIDUAL, "a b", "-a -b p -p", "a b", "-a -b p -p"),
    # silkie's README example: pacifist is ambiguous; blocking then lets r4 decide war
    ("nixon, ambiguity blocking",
     "-> quaker\n-> republican\nr1: quaker => pacifist\nr2: republican => -pacifist\n"
     "r3: pacifist => -war\nr4: republican => war", BLOCKING,
     "quaker republican", "-quaker -republican pacifist -pacifist war -war",
     "quaker republican war", "-quaker -republican pacifist -pacifist -war"),
    # ... and propagation does not: r3 is supported, so it still blocks war
    ("nixon, ambiguity propagation",
     "-> quaker\n-> republican\nr1: quaker => pacifist\nr2: republican => -pacifist\n"
     "r3: pacifist => -war\nr4: republican => war", PROPAGATION,
     "quaker republican", "-quaker -republican pacifist -pacifist war -war",
     "quaker republican", "-quaker -republican pacifist -pacifist war -war"),
    ("a defeated defeasible fact blocks a chain", "f1: => a\nf2: => -a\nf2 > f1\nr1: a => b", BLOCKING,
     "", "a -a b -b", "-a", "a b -b"),
    # the well-founded semantics: a and b only support each other, so both fail
    ("positive loop", "r1: a => b\nr2: b => a", BLOCKING, "", "a -a b -b", "", "a -a b -b"),
    # -a is beaten by f1 > f2, but d1 (not beaten) still keeps a from +d: neither
    ("superior fact against a team with a defeater", "f1: => a\nf2: => -a\nd1: ~> -a\nf1 > f2",
     BLOCKING, "", "a -a", "", "a -a"),
    ("negated strict fact", ">> -a\nr1: -a => b", BLOCKING, "-a", "a b -b", "-a b", "a -b"),
    # The definition, where silkie's code departs from it (README):
    # a strict fact wins however often and in whatever order the literal is
    # also a defeasible fact; silkie keeps the first form it reads
    ("the same literal as defeasible and strict fact", "=> a\n-> a", BLOCKING, "a", "-a", "a", "-a"),
    # +d p holds iff d1, whose body is p, is not applicable: an odd loop through
    # negation, which the well-founded semantics leaves undecided (silkie: +d p)
    ("odd loop through a defeater", "=> p\nd1: p ~> -p", BLOCKING, "", "p -p", "", "-p"),
    # r1 > d1 makes the defeater harmless (silkie ignores superiority over defeaters)
    ("superiority over a defeater", "-> b\nr1: b => a\nd1: b ~> -a\nr1 > d1", BLOCKING,
     "b", "a -a -b", "a b", "-a -b"),
]


@pytest.mark.parametrize("engine", ["prolog", "asp"])
@pytest.mark.parametrize("name,text,sem,pD,mD,pd,md", CASES, ids=[c[0] for c in CASES])
def test_conclusions_as_silkie_documents_them(engine, name, text, sem, pD, mD, pd, md) -> None:
    expected = {"+D": native(pD), "-D": native(mD), "+d": native(pd), "-d": native(md)}
    assert conclusions(parse_dfl(text + "\n", name), sem, engine) == expected


def test_enough_cases() -> None:
    assert len(CASES) >= 20
