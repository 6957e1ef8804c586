"""From a question in words to the scene it describes and what it asks.

`read_question("will it spill if I pour milk from the side?")` hears the question in five steps:

1. A clause that asks about the outcome ("will it spill?") or says a goal ("without
   spilling") is heard apart (outcomes.py): what it asks or wants; the rest is the scene.
2. Everyday phrases become the vocabulary's words (words.py, everyday.txt,
   properties.py: "a full cup", milk an ordinary liquid, plastic ignored,
   "low friction" slippery), and a number with its unit, its sign kept,
   the proposition whose range holds it (quantities.py: "-3 cm above").
3. Each word gets the stage it speaks of (stages.py).
4. Each proposition is said by its value words: the words of its gloss
   or of its name, without its stage or body ("far" for `pour_far_away`,
   "tilted halfway" or "half tilted" for `pour_half_tilted`), found close
   together in one clause, in the stage of the proposition; the readings
   with the most words first, each word read once. A word said of the bodies
   ("light", "slippery") belongs to the noun it qualifies (nouns.py). A name said
   outright (`pour_to_side`) is read as it is; "leave it there" ends where the pour
   was, "leave it tilted" as tilted as it was.
5. Negation ("not", "never", "no", "without", "don't", "instead of" ...) covers the rest
   of its clause (negation.py): a proposition said there is excluded, and its dimension is
   read as its other value when one is left (or another value is said), or the question is
   refused naming the values left. Two values of one dimension ("a light and heavy
   liquid") are refused as contradictory, as is a choice of two liquids read as different
   values with no goal ("honey or water?", choices.py), a scene set against the first that
   the vocabulary cannot say (set_against.py), and a question with a word that cannot be
   placed ("pour light": the light what?), naming the phrasings that would be read where there are some ("pour slowly": "move in slowly"). A refusal is a UserError:
   one line. A question of pouring, or of an outcome, that names no proposition ("what
   happens if I pour?", "does it splash?") reads as no propositions: the ordinary pour; a
   question that says nothing of a pour is refused.

A word mistyped is read as the one word it is near (spelling.py: "hihg" is high) and said
back, as is a contraction typed without its apostrophe (wording.py: "im" is I'm). Nothing is
dropped silently: an everyday word is said back with how it was read (`Reading.notes`), any
other word read as nothing is in `Reading.ignored`, for `ask`'s `understood:` line.
"""
from __future__ import annotations

import re
from bisect import bisect_left
from dataclasses import dataclass
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.chatter import chatter
from pantarhei.bridge.reasoning.choices import read_choice
from pantarhei.bridge.reasoning.drips_after import refuse_drips_after
from pantarhei.bridge.reasoning.mishaps import mishap
from pantarhei.bridge.reasoning.aux_dropped import aux_restored
from pantarhei.bridge.reasoning.claims import claim_asked
from pantarhei.bridge.reasoning.carried import liquid_carried
from pantarhei.bridge.reasoning.set_against import refuse_unsayable
from pantarhei.bridge.reasoning.ages import ages_said
from pantarhei.bridge.reasoning.causes import causes_weighed
from pantarhei.bridge.reasoning.lexicon_cache import cached_lexicon
from pantarhei.bridge.reasoning.negation import (NEGATION_STEMS, covered, opposite, or_list, ordinary_left,
                                                 scope, scope_ends, still_between)
from pantarhei.bridge.reasoning.occurrences import closest, occurrences
from pantarhei.bridge.reasoning.outright import first_compared, outright
from pantarhei.bridge.reasoning.nouns import ARTICLES, BOWL, CONTEXT, OBJECT_STEMS, Nouns, roles
from pantarhei.bridge.reasoning.outcomes import hear
from pantarhei.bridge.reasoning.what_follows import FOLLOWS, follows
from pantarhei.bridge.reasoning.quantities import read_numbers
from pantarhei.bridge.reasoning.seeking import if_it_can
from pantarhei.bridge.reasoning.spelling import corrected
from pantarhei.bridge.reasoning.stages import (MARKER_STEMS, MOVE, POSE, SAME, ordinary_tilt, plain_tilts,
                                               same_at_the_end, stages)
from pantarhei.bridge.reasoning.wording import Token, names_written, normalising, stem, tokens as words_of
from pantarhei.bridge.reasoning.suggestions import DESCRIBE, hinted, misspelt, names_part, refuse_unplaced
from pantarhei.bridge.reasoning.unnamed import containers_named, liquids_unnamed
from pantarhei.bridge.reasoning.who_asks import asker_said
from pantarhei.bridge.reasoning.words import FILLERS, UNCLEAR, rewrites
from pantarhei.theory.lexicon import load_vocabulary

_IGNORED = {stem(w) for w in FILLERS}
#: Words the everyday word list reads as nothing, said back with the reason
#: ("plastic", "table", "spout"): a question may hold them and ask of the ordinary pour.
_SAID_AS_NOTHING = frozenset({"material", "context", "part"})
#: The words of a negation's scope that say nothing of the scene: the bowls, an outcome heard, the frame.
_BARE = frozenset({BOWL, "outcome", *ARTICLES, *_IGNORED} - {stem(w) for w in ("without", "with", "any", "all")})


@dataclass(frozen=True)
class Reading:
    """What a question was heard to say."""
    scene: tuple[str, ...]          # the propositions, sorted (none: the ordinary pour)
    asked: tuple[str, ...] = ()     # the expectations it asks about, in the order said
    goals: tuple[str, ...] = ()     # the literals it wants: "no_spill", "neg(no_spill)"
    notes: tuple[str, ...] = ()     # everyday words said back: "milk: read as an ordinary liquid"
    ignored: tuple[str, ...] = ()   # words read as nothing, as written
    heard: tuple[str, ...] = ()     # every phrase read (the scene's, the outcome's), as written


@dataclass(frozen=True)
class _Lexicon:
    phrases: dict[tuple[str, ...], frozenset[str]]   # value words -> the propositions they say
    slots: dict[str, tuple[str, str]]                # proposition -> ("stage"|"object", which)
    placeable: frozenset[str]                        # words a question must place
    known: frozenset[str]
    amounts: frozenset[str]                          # propositions of how much liquid the source holds
    asking: frozenset[str]                           # words of a question of the ordinary pour
    saying: dict[str, tuple[str, ...]]               # a value word -> glosses that would read it


@lru_cache(maxsize=None)
def lexicon() -> _Lexicon:
    return cached_lexicon(_built_lexicon, _Lexicon)         # kept between questions (lexicon_cache.py)


def _built_lexicon() -> _Lexicon:
    vocab = load_vocabulary()
    props = vocab.propositions
    slot_words = set(MARKER_STEMS) | set(OBJECT_STEMS) | {BOWL}
    phrases: dict[tuple[str, ...], set[str]] = {}
    slots = {}
    for n, p in props.items():
        # said by its gloss, read as a question is, or by its name word by word
        for words in ({t.word for t in words_of(p.gloss)}, {stem(w) for w in n.split("_")}):
            phrases.setdefault(tuple(sorted(words - _IGNORED - slot_words)), set()).add(n)
        first, last = n.split("_")[0], n.split("_")[-1]      # pour_low, fast_approach, light_liquid
        slots[n] = ("stage", first) if first in POSE else (
            ("stage", last) if last in POSE else ("object", last))
    placeable = set().union(*phrases) - {"very"}
    # the expectations' words, by their names ("does the liquid spill?"); the
    # clauses that ask about them are outcomes.py's
    asked = {stem(w) for e in vocab.expectations for w in e.name.split("_")}
    texts = [*(p.gloss for p in props.values()), *(d.gloss for d in vocab.dimensions.values()),
             *(p.gloss for p in vocab.parameters)]
    known = {stem(w) for t in texts for w in re.findall(r"[a-z]+", t.lower())} | asked
    known |= {stem(w) for _, words, _ in rewrites() for w in words}
    known |= _IGNORED | slot_words | NEGATION_STEMS | {"very"} | set(SAME)
    # the dimension whose gloss says the liquid is in the source: its values
    # may be said of the source ("a full cup")
    amounts = {n for n, p in props.items() if slots[n] == ("object", "liquid")
               and "source" in vocab.dimensions[p.dimension].gloss}
    # what a question of the ordinary pour may hold: its frame, the bodies,
    # pouring and the expectations it asks of ("does the liquid spill?"), after a stage of it
    # ("after pulling the cup back, does the bowl move?")
    asking = _IGNORED | set(OBJECT_STEMS) | {BOWL, "pour", "after"} | asked | _SAID_AS_NOTHING
    saying: dict[str, list[str]] = {}
    for words, names in phrases.items():
        for w in words:
            saying.setdefault(w, []).extend(props[n].gloss for n in sorted(names))
    return _Lexicon({k: frozenset(v) for k, v in phrases.items()}, slots,
                    frozenset(placeable | {UNCLEAR}), frozenset(known), frozenset(amounts),
                    frozenset(asking), {w: tuple(g) for w, g in saying.items()})


class Scene(list):
    """The propositions of a question, sorted, as a list; `reading` holds
    what else it said (what it asks, its goals, the words said back or
    ignored), for `ask` to print beside the answers."""

    def __init__(self, reading: Reading) -> None:
        super().__init__(reading.scene)
        self.reading = reading


def understand(question: str) -> Scene:
    """The propositions the question names, sorted (none: the ordinary
    pour), with its whole reading; UserError as read_question's."""
    return Scene(read_question(question))


def read_question(question: str) -> Reading:
    """What the question says of the scene and asks of it (see the
    module's docstring); UserError for a question that negates or
    contradicts itself in a way not understood, holds a word that cannot
    be placed or a number no proposition holds, or says nothing of a pour.
    A question refused is read again with its mistyped words read as the
    words meant (spelling.py), if it has any; refused again, the first
    refusal stands."""
    text, respelt = normalising(question)
    lex = lexicon()                         # "It is for science.": chatter (chatter.py)
    text, chat = chatter(text, words_of, lex.known, frozenset(_IGNORED), NEGATION_STEMS, lex.placeable)
    text, asker = asker_said(text)          # "I'm a potter and ...": who asks (who_asks.py)
    text, claimed = claim_asked(text)       # "my mum says ..., is that true": the claim asked (claims.py)
    text, restored = aux_restored(text)     # "it fall down?": does it (aux_dropped.py)
    refuse_drips_after(text)                # "drip down the bottle after pouring" (drips_after.py)
    text, told = mishap(text)               # "it slid off the tray. how do i stop that?" (mishaps.py)
    text, alike = read_choice(text)         # "honey or water?": two questions; "water vs oil": one (choices.py)
    respelt += chat + asker + claimed + restored + told + alike
    refuse_unsayable(text, lex.known, lex.placeable)  # "60 degrees vs 90 with 200 ml" (set_against.py)
    try:
        return _read_text(question, text, respelt)
    except UserError:
        fixed, typed = corrected(text)
        if not typed:
            raise
        try:
            return _read_text(question, fixed, respelt + typed)
        except UserError:
            pass
        raise


def _read_text(question: str, text: str, typed: tuple[str, ...]) -> Reading:
    """read_question's reading of `question`, normalised as `text`, with
    the words read as others said back (`typed`)."""
    vocab = load_vocabulary()
    props = vocab.propositions
    lex = lexicon()
    text, named = names_written(text)
    text, unnamed = containers_named(text)          # "pour from a growler": a container
    text, carried = liquid_carried(text)            # "bring the jug of honey in": with honey (carried.py)
    text, aged = ages_said(text)                    # "my 6 year old": who pours
    text, weighed = causes_weighed(text)            # "... - is it too full or not tilted enough?"
    typed += unnamed + carried + aged + weighed
    outcome = hear(text)
    tokens = read_numbers(words_of(outcome.scene), lex.placeable)
    accepted = _read(tokens, lex, outcome.bowl)
    cues = [i for i, t in enumerate(tokens) if t.word in NEGATION_STEMS]
    ends = scope_ends(tokens)
    # per position: how many words before it say something (neither filler
    # nor negation); the positions read, negations left out
    saying = [0]
    for t in tokens:
        saying.append(saying[-1] + (t.word not in _IGNORED and t.word not in NEGATION_STEMS))
    read = sorted(j for _, positions in accepted for j in positions
                  if tokens[j].word not in NEGATION_STEMS)
    for i in cues:
        k = bisect_left(read, i + 1)
        if (saying[ends[i]] > saying[i + 1] and not (k < len(read) and read[k] < ends[i])
                and not (read and _bare(tokens, scope(tokens, i, ends)))):
            phrase = " ".join(tokens[j].raw for j in (i, *sorted(scope(tokens, i, ends))))
            said = [t.raw for t in tokens if t.word == UNCLEAR] + [phrase]     # "instead of fast, pour slowly"
            hint = next(iter(hinted(said)), DESCRIBE)
            raise UserError(f"understood nothing that \"{phrase}\" excludes: {hint}")
    negated_at = covered(tokens, cues, ends)
    words = [t.word for t in tokens]        # "not heavy at all", "not at all heavy": the dimensions
    at_all = {props[n].dimension for n, p in accepted if p & negated_at and ["at", "all"] in (
        words[max(p) + 1:max(p) + 3], words[max(0, min(p) - 2):min(p)])}
    said: dict[str, list[str]] = {}
    negated: dict[str, list[str]] = {}
    for name, positions in accepted:
        target = negated if positions & negated_at else said
        names = target.setdefault(props[name].dimension, [])
        if name not in names:
            names.append(name)

    out, spoken, comparing = [], [], set()
    for dim, names in said.items():
        names = outright(names, accepted, tokens, vocab)      # "lower than last time, 2 cm below the rim"
        names, against, at = first_compared(names, accepted, tokens, text)
        spoken += against                                  # "is it messier from high up or just above?"
        comparing |= at
        if len(names) > 1:
            a, b = sorted(names)[:2]
            raise UserError(f"\"{question}\" says both {a} ({props[a].gloss}) and {b} "
                            f"({props[b].gloss}), two values of {dim}: ask about one of them")
        out.append(names[0])
    for dim, names in negated.items():
        if dim in said:
            continue                  # "never from the side, centred over it": the one said
        others = [v for v in vocab.dimensions[dim].values if v not in names]
        if len(others) == 1 and still_between(names[0], others[0], props):
            raise UserError(f"not {names[0]}: {others[0]} ({props[others[0]].gloss}), or no move "
                            f"of {dim} at all, which is said by saying none: say which")
        if len(others) == 1:
            out.append(others[0])
            continue
        # "not heavy at all", and a body's plain "isn't heavy" (not "too", "very"): the other end, said back
        plain = vocab.dimensions[dim].role == "context" and not {"too", "veri", "that", "so", "overli"} & {
            w for n, p in accepted if n in names for w in words[max(0, min(p) - 2):min(p)]}
        far = (dim in at_all or plain) and opposite(names, vocab.dimensions[dim].values)
        if far:
            out.append(far)
            spoken.append(f"not {names[0]}{' at all' if dim in at_all else ''}: {far}")
            continue
        ordinary = ordinary_left(names, others, vocab)
        if ordinary:                             # "isn't heavy": the ordinary pour's bowl, said back
            out += [ordinary[0]] if ordinary[0] else []
            spoken.append(ordinary[1])
            continue
        raise UserError(f"not {', '.join(names)} leaves {or_list(others)}: say which one (or give "
                        f"--props P1,P2)" if others
                        else f"\"{question}\" excludes every value of {dim}")
    read_at = set().union(*(p for _, p in accepted))
    plain = plain_tilts(tokens, read_at, negated_at)
    liquid_at, liquid = liquids_unnamed(tokens, read_at | plain, lex.known)   # "pour the merlot" (unnamed.py)
    taken = read_at | plain | liquid_at | comparing
    refuse_unplaced(question, tokens, taken, lex)
    out += same_at_the_end(tokens, out, vocab)
    if not accepted and not plain and not _ordinary(tokens, lex, bool(outcome.asked or outcome.goals), liquid_at):
        unknown = list(dict.fromkeys(t.raw for t in tokens if t.word not in lex.known))
        hint = ([FOLLOWS] if follows(text) else []) + hinted(unknown) + misspelt(unknown)
        said = ("could not place " + ", ".join(f'"{w}"' for w in unknown) + ": ") if unknown else ""
        raise UserError(f"understood none of \"{question}\": {said}" + (hint[0] if hint else DESCRIBE))
    structural = _IGNORED | NEGATION_STEMS | set(OBJECT_STEMS) | {BOWL} | set(MARKER_STEMS)
    ignored = [t.raw for i, t in enumerate(tokens) if i not in taken and t.word not in structural
               and t.word not in SAME]
    heard = [t.raw for t in tokens if t.raw not in ignored or t.said_back]    # said back: heard
    tilted = ordinary_tilt() if plain else ""
    notes = typed + tuple(dict.fromkeys([*(f"{t.raw}: {t.said_back}" for t in tokens if t.said_back),
                                         *(f"{tokens[i].raw}: {tilted}" for i in sorted(plain)),
                                         *spoken, *liquid, *outcome.notes]))
    noted = {t.raw for t in tokens if t.said_back}
    manners = any(vocab.dimensions[props[n].dimension].role == "manner" for n in out)
    can, goals = if_it_can(text, outcome.goals, manners)     # "can I pour high without spilling?"
    return Reading(tuple(sorted(set(out))), tuple(dict.fromkeys((*named, *outcome.asked, *can))),
                   goals, notes, tuple(dict.fromkeys(w for w in ignored if w not in noted)),
                   tuple([*heard, *outcome.phrases, *named]))


def _bare(tokens: list[Token], positions) -> bool:
    """Whether the words at `positions`, a negation's scope, say nothing but
    the bowls and an outcome heard ("will not make the bowl move", "never
    bring the bottle over the bowl"): with something else read, such a
    negation excludes nothing of the scene, and its words are shown as
    ignored (a place, a liquid or a word of the vocabulary in it is no bare one)."""
    return all(tokens[j].word in _BARE for j in positions)


def _ordinary(tokens: list[Token], lex: _Lexicon, asks: bool, liquid: set[int]) -> bool:
    """Whether a question that names no proposition asks of the ordinary pour: it says pouring
    ("what happens if I pour water into a cup?"), or asks about an outcome ("does it
    splash?"), in words the vocabulary knows, and nothing else (but the name of a liquid
    it does not know, at the positions `liquid`)."""
    return ((asks or any(t.word == "pour" for t in tokens))
            and all(t.word in lex.asking or i in liquid
                    or (t.word not in lex.known and names_part(tokens, i, lex.placeable))
                    for i, t in enumerate(tokens)))


def _read(tokens: list[Token], lex: _Lexicon, bowl: bool = False) -> list[tuple[str, frozenset[int]]]:
    """Each proposition said, with the positions of the words that say it:
    names given outright, then the readings with the most words, then the
    closest together, each word read once (`bowl`: named in what is asked)."""
    stage = stages(tokens)
    noun = Nouns(tokens, roles(tokens, lex.placeable, bowl), lex.placeable)
    found = [(t.word, frozenset({i})) for i, t in enumerate(tokens) if t.word in lex.slots]
    claimed = set().union(*(p for _, p in found))
    for words, positions in sorted(occurrences(tokens, lex.phrases), key=closest):
        if positions & claimed:
            continue
        name = _resolve(lex.phrases[words], positions, stage, noun, lex)
        if name is not None:
            found.append((name, positions))
            claimed |= positions
            found += [(n, positions) for n in _shared(name, words, positions, noun, lex)]
    return found


def _shared(name: str, words: tuple[str, ...], positions: frozenset[int], noun: Nouns,
            lex: _Lexicon) -> list[str]:
    """The same value said of the other bodies its noun is coordinated with
    ("the source and the destination are heavy", "a light source and
    destination", "both bowls are light"): their propositions of `words`."""
    kind, body = lex.slots[name]
    at = noun.at(min(positions), max(positions))
    if kind != "object" or at is None:
        return []
    others = noun.partners(at) - {body}
    return sorted(n for n in lex.phrases[words] if lex.slots[n][0] == "object"
                  and lex.slots[n][1] in others)


def _resolve(names: frozenset[str], positions: frozenset[int], stage_of: list[str],
             noun: Nouns, lex: _Lexicon) -> str | None:
    """The one proposition of `names` that the words at `positions` say in
    their stage and of their noun, or None."""
    stage = stage_of[min(positions)]
    fits = [n for n in names if lex.slots[n][0] == "stage" and lex.slots[n][1] in
            (POSE[stage], MOVE[stage])]
    of_bodies = sorted(n for n in names if lex.slots[n][0] == "object")
    if len(of_bodies) > 1:
        body = noun(min(positions), max(positions))
        of_bodies = [n for n in of_bodies if lex.slots[n][1] == body]
    fits += of_bodies
    if len(fits) != 1:
        return None
    return fits[0] if _agrees(fits[0], min(positions), max(positions), noun, lex) else None


def _agrees(name: str, first: int, last: int, noun: Nouns, lex: _Lexicon) -> bool:
    """Whether the proposition `name`, said by the words from `first` to
    `last`, fits the noun they qualify: a property of the liquid said of a
    bowl ("a sticky bowl"), how full the source is said of the destination
    ("the destination is full", "into a full cup"), or a pose of the source said of the
    destination ("with the cup upside down": a bowl is the destination) is
    no reading, and the words are refused as not placed."""
    kind, which = lex.slots[name]
    at = noun.at(first, last)
    if at is None:
        return True
    body = noun.roles[at]
    if body == CONTEXT:             # "a sticky counter", "the table is high": of no body of the scene
        return kind == "stage" and not noun.said_of(at, first, last)
    if kind == "stage":             # only "with the <destination> ..." says it of the destination
        t = noun.tokens
        said_with = at == first - 1 and any(
            k >= 0 and t[k].word == "with" and all(t[m].word in ARTICLES for m in range(k + 1, at))
            for k in (at - 1, at - 2))
        return not (said_with and body == "destination")
    if body == which:
        return True
    # how much liquid there is, said of the source: "a full cup", "a source full of liquid"
    return (which == "liquid" and name in lex.amounts and not noun.names_destination(at)
            and not noun.poured_into(at))

