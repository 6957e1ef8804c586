"""Where a negation reaches in a question: "not", "never", "no",
"without", "don't" ... cover the rest of their clause, up to the next
"and", "or", "yet"; a question asked negatively ("can't I pour from
high?") and what not to do ("what should I not do with a heavy jug")
negate nothing. Not one of two moves the other way is not the other
("don't lift it" may leave it where it is): still_between says so."""
from __future__ import annotations

from pantarhei.bridge.reasoning.wording import CLAUSE_ENDS, SO_BEFORE, Token, stem

#: Words that end the scope of a negation within a clause.
_SCOPE_ENDS = CLAUSE_ENDS | {"and", "or", "yet", "if", "when", "unless", "because"}
#: Words that negate what follows them in their clause.
NEGATIONS = {"not", "never", "no", "without", "nor", "neither", "cannot", "none", "nothing"}
NEGATION_STEMS = {stem(w) for w in NEGATIONS}


#: "none", "nothing", "no liquid" said of a place ("none on the table"): how much liquid is there, up to the
#: place's noun, not a negation of the rest of the clause ("... when pouring a heavy liquid").
_PLACED = {stem(w) for w in ("none", "nothing")}
_AT = {"on", "onto", "in", "into", "over", "outside", "all"}
_BEFORE_NOUN = {"the", "a", "an", "my", "our", "your", "its", "over", "of", "it"}


#: An auxiliary, "not" and its subject, in that order, ask a question negatively: "can't I", "isn't it".
_AUX = {*"can could would should will do does did is are was were has have must might may shall".split()}
_SUBJECTS = {*"i we you it they he she".split()}


def scope_ends(tokens: list[Token]) -> list[int]:
    """For each position i, where the scope of a negation at i ends: the
    end of its clause, or the next "and", "or", "yet"... after it (for
    "none" or "nothing" said of a place, the place's noun)."""
    ends = [len(tokens)] * len(tokens)
    for j in range(len(tokens) - 2, -1, -1):
        nxt = tokens[j + 1]
        so_much = nxt.raw == "so" and j + 2 < len(tokens) and tokens[j + 2].raw in SO_BEFORE    # "not so high"
        ends[j] = j + 1 if nxt.clause != tokens[j].clause or (nxt.word in _SCOPE_ENDS and not so_much) else ends[j + 1]
    for j in range(1, len(tokens) - 1):      # a question asked negatively ("can't I pour from high?") negates nothing
        if tokens[j].word == "not" and tokens[j - 1].raw in _AUX and tokens[j + 1].raw in _SUBJECTS:
            ends[j] = j + 1
    for j in range(len(tokens) - 1):         # what not to do ("what should I not do with a heavy jug") negates the doing
        if tokens[j].raw in ("not", "never") and (tokens[j + 1].raw == "do" or (
                tokens[j + 1].raw == "to" and j + 2 < len(tokens) and tokens[j + 2].raw == "do")):
            ends[j] = j + 1
    for j, t in enumerate(tokens[:-2]):
        at = j + 1 + (t.word == "no" and tokens[j + 1].word == "liquid")      # "no liquid on the table"
        if (t.word in _PLACED or at > j + 1) and tokens[at].word in _AT:
            noun = next((k for k in range(at + 1, ends[j]) if tokens[k].word not in _BEFORE_NOUN), ends[j] - 1)
            ends[j] = min(ends[j], noun + 1)
    return ends


def scope(tokens: list[Token], i: int, ends: list[int]) -> set[int]:
    """The positions a negation at i covers: the rest of its clause, up to
    the next "and", "or", "yet"..., its negations left out."""
    return {j for j in range(i + 1, ends[i]) if tokens[j].word not in NEGATION_STEMS}


def covered(tokens: list[Token], cues: list[int], ends: list[int]) -> set[int]:
    """The positions the negations at `cues` cover, together (each position
    is looked at once: a scope that starts inside another ends with it)."""
    out: set[int] = set()
    reach = 0
    for i in cues:                            # in order
        for j in range(max(i + 1, reach), ends[i]):
            if tokens[j].word not in NEGATION_STEMS:
                out.add(j)
        reach = max(reach, ends[i])
    return out


def still_between(a: str, b: str, props) -> bool:
    """Whether two moves go opposite ways with no move between them left
    out ("don't lift it after pouring" is not lowering it: it may stay)."""
    ra, rb = (props[n].model for n in (a, b))
    return (all(hasattr(r, "low") and hasattr(r, "high") for r in (ra, rb))
            and min(ra.high, rb.high) < 0 < max(ra.low, rb.low))


def ordinary_left(negated: list[str], others: list[str], vocab) -> tuple[str, str] | None:
    """What a negation that leaves several values (`others`) is read as, and
    what is said back: the one of them that says what the ordinary pour does
    (its range the prior of its parameter: "not heavy" leaves a light bowl or
    one of medium weight, and the ordinary pour's bowl is of medium weight);
    or, where no value says it but the ordinary pour lies wholly outside the
    values negated ("not from high": it pours at 50 to 120 mm), the ordinary
    pour itself (""); None otherwise. Not over the middle, how far off it not
    said ("not from center", "if I don't hold it right over the bowl"), is
    the nearest place off it, near the rim, as "off centre" is."""
    for n in negated if len(negated) == 1 else ():
        near = n.replace("_centred", "_near_rim")
        if n.endswith("_centred") and near in others:
            return near, (f"not {n}: {near}, the nearest place off the middle (say \"from the side\" or "
                          f"\"offset sideways\" for others)")
    props = vocab.propositions
    priors = {p.name: (p.prior_low, p.prior_high) for p in vocab.parameters}
    models = [props[n].model for n in (*negated, *others)]
    if not all(m.kind == "uniform" for m in models):
        return None
    found = [n for n in others if (props[n].model.low, props[n].model.high) == priors[props[n].model.param]]
    if len(found) == 1:
        return found[0], f"not {', '.join(negated)}: {found[0]}, as in the ordinary pour"
    param = next(p for p in vocab.parameters if p.name == models[0].param)
    low, high = param.prior_low, param.prior_high
    if not found and all(props[n].model.high <= low or high <= props[n].model.low for n in negated):
        return "", (f"not {', '.join(negated)}: the ordinary pour, which lies outside it ({low:g} to {high:g} "
                    f"{param.unit} of {param.name})")
    return None


def opposite(negated: list[str], values: tuple[str, ...]) -> str | None:
    """The value at the other end of a scale of three (`values`, in order)
    from the one `negated` "at all": "not heavy at all" is light, not the
    ordinary pour's medium weight; None for any other negation."""
    if len(negated) != 1 or len(values) != 3 or negated[0] == values[1]:
        return None
    return values[2] if negated[0] == values[0] else values[0]


def or_list(names: list[str]) -> str:
    """Names as a refusal lists them: "a, b or c"."""
    return ", ".join(names[:-1]) + " or " + names[-1] if len(names) > 1 else names[0]
