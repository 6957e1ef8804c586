"""Literals as people type them: an expectation E, its negation as -E,
~E, "not E" or neg(E); checked against the vocabulary's expectations."""
from __future__ import annotations

from pantarhei.bridge.errors import UserError
from pantarhei.theory.lexicon import load_vocabulary


def parse_goal(goal: str) -> str:
    """`spill`, `-spill`, `neg(spill)`, `not spill` -> native literal text."""
    g = goal.strip()
    for prefix in ("-", "~", "not "):
        if g.startswith(prefix):
            return f"neg({g[len(prefix):].strip()})"
    return g


def goal_literal(goal: str) -> str:
    """The native literal of `goal`; UserError for one that names no
    expectation, with the closest ones."""
    lit = parse_goal(goal)
    name = lit[4:-1] if lit.startswith("neg(") and lit.endswith(")") else lit
    known = load_vocabulary().expectation_names
    if name not in known:
        import difflib

        close = difflib.get_close_matches(name, known, n=3, cutoff=0.5)
        hint = f" (did you mean {', '.join(close)}?)" if close else ""
        where = f" in '{goal}'" if goal.strip() != name else ""
        raise UserError(f"unknown expectation '{name}'{where}{hint}")
    return lit
