"""The stage each word of a question speaks of: "start", "pour", "end",
"approach" (the move into the pouring pose) or "retreat" (the move out of
it), said by a stage word ("then", "after pouring", "move away" ...:
words.py brings everyday phrases to them). A stage word speaks for its
clause from there on, and for the words of its clause before it; a clause
without one goes on in the stage before (pouring, at first). A pose said
while moving in is the start pose, while moving away the end pose."""
from __future__ import annotations

from pantarhei.bridge.reasoning.wording import Token, stem

#: Stage words, and where "then" goes on to from each stage.
MARKERS = {"start": "start", "pour": "pour", "end": "end", "finally": "end", "final": "end",
           "approach": "approach", "retreat": "retreat", "then": None}
_THEN = {"start": "pour", "approach": "pour", "pour": "end", "retreat": "end", "end": "end"}
#: The pose and the movement a stage speaks of: "move in from low down" is start_low.
POSE = {"start": "start", "approach": "start", "pour": "pour", "retreat": "end", "end": "end"}
MOVE = {"start": "approach", "approach": "approach", "pour": None, "retreat": "retreat",
        "end": "retreat"}
MARKER_STEMS = {stem(w): s for w, s in MARKERS.items()}


def stages(tokens: list[Token]) -> list[str]:
    """The stage each word speaks of (see the module's docstring)."""
    out: list[str] = []
    stage = "pour"
    clauses: dict[int, list[int]] = {}          # clause -> its positions, in order
    for i, t in enumerate(tokens):
        clauses.setdefault(t.clause, []).append(i)
    for clause in sorted(clauses):
        at = clauses[clause]
        marks = [i for i in at if tokens[i].word in MARKER_STEMS]
        current = _next(tokens[marks[0]].word, stage) if marks else stage
        marked = set(marks[1:])
        for i in at:
            if i in marked:
                current = _next(tokens[i].word, current)
            out.append(current)
        stage = current
    return out


def _next(word: str, stage: str) -> str:
    return MARKER_STEMS[word] or _THEN[stage]
