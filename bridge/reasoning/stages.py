"""The stage each word of a question speaks of: "start", "pour", "end",
"approach" (the move into the pouring pose) or "retreat" (the move out of
it), said by a stage word ("then", "after pouring", "move away" ...:
words.py brings everyday phrases to them). A stage word speaks for its
clause from there on, and for the words of its clause before it (but for
a move named by its noun with its speed before it, as a note says it:
"bottle near rim fast retract" pours near the rim); a clause
without one goes on in the stage before (pouring, at first), but one
that begins by tilting after the start or the move in is the pour's
("move in slowly, tilt it halfway", "come in low and just tilt it"). A pose said
while moving in is the start pose, while moving away the end pose.
"Leave it tilted" and "leave it there" end as the pour was, and "move
in low" (a path in, no "from") pours as low as it came in, unless the
pour's height is said ("come in high and pour low"): same_at_the_end."""
from __future__ import annotations

from pantarhei.bridge.errors import UserError
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
#: Verbs of tilting: a clause they begin, said after the start or the move in with no stage
#: word of its own, is the pour's ("move in over 3 s, tilt 45 deg", "approach 2 s, pitch 110
#: deg": the tilt poured with).
_TILTING = {stem(w) for w in ("tilt", "tip", "incline", "lean", "angle", "turn", "turned", "tilted", "tipped", "pitch",
                              "pitched")}


#: Verbs of keeping a pose, said after "and" once moved in: the pour's ("bring it in fast and keep it low").
_KEEPING = {stem(w) for w in ("keep", "keeps", "hold", "holds")}


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
        first = next((stem(tokens[i].raw.split()[0]) for i in at
                      if tokens[i].word != "and" and tokens[i].word not in _PASSING), "")
        if not marks and stage in ("start", "approach") and first in _TILTING:
            current = "pour"
        marked = set(marks[1:])
        # a move named with its speed before it, as a note says it ("bottle near rim fast retract"): what
        # comes before the speed is said of the stage before, not of the move
        noted = (marks[0] - 1 if marks and tokens[marks[0]].raw in _MOVE_NOUNS
                 and marks[0] - 1 > at[0] and tokens[marks[0] - 1].word in _SPEEDS else None)
        for i in at:
            if noted is not None and i < noted:
                out.append(stage)
                continue
            if i in marked:
                current = _next(tokens[i].word, current)
            elif (current in ("start", "approach") and i > at[0] and _after_and(tokens, i, at[0])
                  and stem(tokens[i].raw.split()[0]) in _TILTING | _KEEPING and not set(marks) & set(range(i, at[-1] + 1))):
                current = "pour"        # "brought in slowly and turned upside down": the pour's tilt ("and keep it low": its height)
            out.append(current)
        stage = current
    return out


#: Speeds said of a move named by its noun ("fast retreat", "slow approach").
_SPEEDS = {stem(w) for w in ("fast", "slowly", "moderate")}
_MOVE_NOUNS = frozenset(("approach", "retreat", "retract", "retraction", "withdrawal"))
#: A word said in passing before a verb of tilting: "and just tip it".
_PASSING = {"just"}


def _after_and(tokens: list[Token], i: int, first: int) -> bool:
    """Whether the word at `i` follows "and", words said in passing between."""
    j = i - 1
    while j > first and tokens[j].word in _PASSING:
        j -= 1
    return tokens[j].word == "and"


def _next(word: str, stage: str) -> str:
    return MARKER_STEMS[word] or _THEN[stage]


#: Words words.py writes for "leave it tilted" and "leave it there": the end
#: pose keeps the pour's tilt, or its whole pose; and for "move in low": the pouring
#: pose is as high as the move in (the start's height), unless the pour's is said.
SAME = {"same_tilt": ("tilt",), "same_pose": ("height", "alignment", "tilt", "roll"),
        "same_height_in": ("height",)}


def same_at_the_end(tokens: list[Token], scene: list[str], vocab) -> list[str]:
    """The propositions that "leave it tilted" and "leave it there" say of
    the end pose (the pour's, of its tilt or of its whole pose; UserError
    when the pour's are not said), and that "move in low" says of the
    pouring pose (the start's height, where the pour's is not said)."""
    out: list[str] = []
    for t in tokens:
        if t.word not in SAME:
            continue
        if t.word == "same_height_in":
            said = {vocab.propositions[n].dimension for n in scene}
            if "pour_height" not in said:
                out += [f"pour_{n.removeprefix('start_')}" for n in scene
                        if vocab.propositions[n].dimension == "start_height"]
            continue
        dims = {f"pour_{d}" for d in SAME[t.word]}
        copied = [f"end_{n.removeprefix('pour_')}" for n in scene
                  if vocab.propositions[n].dimension in dims]
        copied = [n for n in copied if n in vocab.propositions]
        if not copied:
            what = "tilted how far" if t.word == "same_tilt" else "where"
            raise UserError(f"\"{t.raw}\": {what}? say how the source is poured (\"tilted "
                            f"halfway\", \"from the side\") or how it ends (\"end tilted "
                            f"halfway\", \"end to the side\")")
        out += copied
    return out


def ordinary_tilt() -> str:
    """What `ask` says of a tilt said with no amount ("tip the jug over the
    rim"): the ordinary pour's, its range the prior's of the tilt."""
    from pantarhei.theory.lexicon import load_vocabulary

    tilt = next(p for p in load_vocabulary().parameters if p.name == "pour_pitch")
    return f"tilted as the ordinary pour is ({tilt.prior_low} to {tilt.prior_high} degrees from upright)"


def plain_tilts(tokens: list[Token], read: set[int], negated: set[int]) -> frozenset[int]:
    """The positions of a verb of tilting said of the pour with no amount
    and nothing else reading it ("tip the jug right in over the rim", "keep
    it tilted and move it a bit to the left"): pouring is tilting, so it
    says the ordinary pour's tilt, which is what a scene leaves unsaid. A
    tilt negated, said of the start, the end or a move, said with a number
    its clause does not read ("tilt it 3 times"), or one that falls ("does
    the jug tip over?") is not one."""
    stage = stages(tokens)
    counted = {t.clause for k, t in enumerate(tokens) if k not in read and t.word[:1].isdigit()}

    def falls(i: int) -> bool:
        after = [t.word for t in tokens[i + 1:i + 3] if t.clause == tokens[i].clause]
        return after[:1] == ["over"] and after[1:] not in (["the"], ["a"], ["an"], ["it"])
    return frozenset(i for i, t in enumerate(tokens)
                     if t.word == "tilt" and i not in read and i not in negated
                     and stage[i] == "pour" and t.clause not in counted and not falls(i))
