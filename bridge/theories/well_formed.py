"""What a theory file may hold, and where it goes wrong: rule names, kinds
and literals as the native format and both engines read them, the checks of
what they cannot read (their messages theory/check_messages.pl's, as
SWI-Prolog's),
how a setting's or provenance's value is written so that it reads back as
one value."""
from __future__ import annotations

import re

from pantarhei.bridge.theories import facts as theory_facts
from pantarhei.bridge.theories.facts import Text, term_text
from pantarhei.theory import TheoryFileError, check_message

KINDS = ("strict", "defeasible", "defeater")
NAME = re.compile(r"^[a-z][A-Za-z0-9_]*$")
_ARG = r"(?:[a-z][A-Za-z0-9_]*|-?[0-9]+)"
_ATOM = rf"[a-z][A-Za-z0-9_]*(?:\({_ARG}(?:,{_ARG})*\))?"
_LITERAL = re.compile(rf"^(?:{_ATOM}|neg\({_ATOM}\))$")

# The messages of the checks both readers make are theory/check_messages.pl's
# (pantarhei.theory.check_message); this one is Python's alone (a rule
# named by a DFL file or by code, which the fact reader cannot give).
RULE_NAME = "a rule name in lower case letters, digits and _, not '{}'"


def is_literal(lit: str) -> bool:
    """A literal: a name, a name with names and integers as arguments, or
    neg(L) of one."""
    return bool(_LITERAL.match(lit))


def check_literal(lit: str, where: str) -> None:
    """TheoryFileError (`where: what`) unless `lit` is a literal."""
    if lit.startswith("neg(neg("):
        raise TheoryFileError(f"{where}: " + check_message("double_negation", lit))
    if not _LITERAL.match(lit):
        raise TheoryFileError(f"{where}: " + check_message("literal", lit))


def value_text(value) -> str:
    """A setting's or provenance's value as native text: integers, names
    and terms as they are, anything else (`Text`, or str that is not a
    term) quoted and escaped, so that no value can be read as more facts."""
    if isinstance(value, bool) or not isinstance(value, (int, str)):
        value = str(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, Text):
        return theory_facts.quote(value)
    if NAME.match(value):
        return value
    if "(" in value and value[:1].islower():
        try:
            (f,) = theory_facts.parse(f"v({value}).")
            if len(f.args) == 1 and term_text(f.args[0]) == value:
                return value
        except (TheoryFileError, ValueError):
            pass
    return theory_facts.quote(value)
