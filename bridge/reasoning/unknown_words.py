"""Words a question holds that the vocabulary does not know, judged by the
part they play in it, for reading.py: one that bears on how the pour is
made is refused naming why, one that does not is shown as ignored.

A word the vocabulary does not know is refused when:

- it is close to one of the vocabulary's words ("tilded": "tilted"), a
  word mistyped;
- it is a number no unit came with, or stands right after a number (a
  unit not known: "5 tablespoons");
- it stands right after a negation ("not jerkily", "without the lid"):
  what it excludes cannot be placed;
- it compares or grades: a comparative or superlative of a word the
  vocabulary knows or of an adjective ("heavier", "steeper", "bigger",
  "the tallest"), any word before "than", or a closed-class word of degree
  ("more", "less", "enough", "best");
- it says a manner: an adverb made with -ly, -wise or -ward(s)
  ("jerkily", "clockwise", "upwards"), or one of the adverbs English makes
  without a suffix ("hard", "steady", "sharp": `FLAT`), whatever it
  modifies ("pour jerkily", "tilt it hard");
- it is the question's action: a verb where English puts one, after who
  acts ("I drizzle", "the robot shakes"), after an infinitive's "to" (a
  noun after the preposition "to" takes an article: "to the spout"), an
  -ing form after "while", "when", "by", "before" or "after" ("while
  stirring"), first in its clause before an article or a pronoun
  ("drizzle the honey") or alone in it, after "then" ("then stir"), or
  after "and" before an article or a pronoun ("pour and stir it");
- it is what is poured ("pour batter", "pour the cereal"): a substance
  the vocabulary does not know, which may pour as no liquid it says;
- it begins or ends with a value word of five letters or more and is no
  compound read ("overweight", "lightish"): it says something of the
  value the vocabulary does not place;
- it is an amount, a number in words or a unit without a number
  (`AMOUNTS`: "a couple of drops", "ten cm", "degrees");
- it names a measure (`MEASURES`: "at an angle", "the temperature"):
  what is measured, without its value;
- it is one of the core adjectives of size, shape, colour, age and
  physical property (`ADJECTIVES`: "a tiny cup", "a small amount"), or
  it is said of a body (before its noun: "a wobbly bowl", or after it
  and a copula: "the bowl is wobbly") and has an adjective's suffix (-y,
  -ous, -ful, -less, -ive, -able, -ible, -ish, -ent, -ant, -ed): a
  property that the vocabulary may say otherwise ("greasy" is
  slippery?) or not at all.

Any other word the vocabulary does not know plays the part of a noun, or
is a closed-class word of the question's frame (`CLOSED`: "okay",
"please", "actually", "I wonder"): a food ("onto my cereal"), a part of a
container ("the spout"), a noun said before a bowl ("a cereal bowl", "a
mixing bowl"). It does not change the pour the vocabulary describes, and
is shown as ignored on `ask`'s `understood:` line.

A compound of a value word and a word the vocabulary knows is read as the
value word ("lightweight", "heavyweight": `compound`).
"""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.negation import NEGATION_STEMS
from pantarhei.bridge.reasoning.quantities import UNITS
from pantarhei.bridge.reasoning.nouns import BOWL, OBJECT_STEMS
from pantarhei.bridge.reasoning.suggestions import misspelt
from pantarhei.bridge.reasoning.wording import NUMBER, Token, stem

#: Closed-class words of a question's frame that the fillers do not hold:
#: interjections and politeness, stance and discourse adverbs, pronouns and
#: determiners, and the verbs that frame a question ("I wonder if ...").
CLOSED = frozenset("""
    ok okay alright hi hello hey thanks thank yes yeah yep nope well um uh hmm oh ah sure
    maybe perhaps probably possibly actually basically honestly seriously literally generally
    usually normally typically certainly definitely hopefully exactly simply obviously
    apparently presumably likely necessarily ordinarily
    he she him them us his their theirs mine yours ours myself yourself itself someone
    somebody anyone anybody everyone everybody whatever whenever
    wonder think know want wanna need guess mean wish hope expect plan intend going gonna
    trying tried wondering curious question ask asking got gotten
""".split())
#: Nouns of measure: a word that names what is measured bears on the pour
#: unless its value is said (and a value said with it is read with it).
MEASURES = frozenset("""angle size amount volume temperature pressure force rate flow velocity
    pace degree position direction orientation width depth length viscosity thickness
    quantity level""".split())
#: Amounts, numbers in words and units said without a number: how much,
#: how far or how long, in words the vocabulary does not read.
AMOUNTS = frozenset("""couple few several handful splash dash drop drops drip drips glug bunch
    load loads ton tons heap pinch trickle stream quarter third double twice triple zero two three
    four five six seven eight nine ten eleven twelve fifteen twenty thirty forty fifty sixty
    seventy eighty ninety hundred thousand dozen""".split())
#: Prepositions of place the vocabulary does not read: each says where.
PLACES = frozenset("""next beside besides behind across through along outside against past
    beyond within between among alongside atop upon inside opposite front top bottom left
    corner""".split())
#: Words of degree and comparison, a closed class: they grade a value the
#: question does not say.
DEGREE = frozenset("""more less most least enough extra ultra kinda sorta mega better best worse
    worst than further farther""".split())
#: Adverbs English makes without a suffix (flat adverbs): each says a manner.
FLAT = frozenset("""hard soft steady sharp tight loose firm direct flat deep late early sudden
    abrupt careful gentle smooth rough even straight fine""".split())
#: Core adjectives of dimension, shape, age, colour and physical property
#: (the small closed-ish classes of English adjectives): said of a body,
#: a property the vocabulary may say otherwise or not at all.
ADJECTIVES = frozenset("""big small large tiny huge little tall short wide narrow long deep
    shallow thick thin broad round square flat oval new old clean dirty wet dry hot cold warm cool
    empty hollow solid soft hard firm stiff loose tight fragile sturdy strong weak rigid
    brittle cracked broken chipped open closed black white red green yellow blue brown purple
    pink orange grey gray""".split())
#: General nouns for what a source holds: what is poured, named by no kind.
_CONTENTS = {"content", "contents", "stuff", "rest", "remainder"}
#: What `judged` says of a word close to one of the vocabulary's: the refusal
#: says "did you mean" for all of them at once (suggestions.py).
MISTYPED = "mistyped"
_MANNER = ('"{}": a manner the vocabulary does not say (it says the pose, the tilt, and how '
           'fast the source moves in and away)')
_UNITS = ('"{}": a unit the vocabulary does not read (mm, cm, m, inches, feet, degrees, '
          'seconds, grams, kg, particles)')
_ADJECTIVE_SUFFIXES = ("ous", "ful", "less", "ive", "able", "ible", "ish", "ent", "ant", "ed")
_DETERMINERS = {"a", "an", "the", "my", "your", "our", "their", "his", "her", "its", "this",
                "that", "these", "those", "some", "any", "each", "every"}
_ACTORS = {"i", "we", "you", "he", "she", "they", "robot", "arm", "gripper", "someone",
           "somebody"}
_COPULAS = {stem(w) for w in ("is", "are", "was", "were", "be", "been", "being", "seems",
                              "looks", "feels", "gets", "becomes", "stays", "remains")}
_GRADING = {"very", "really", "quite", "too", "so", "pretty", "fairly", "rather", "somewhat",
            "not"}
_BEFORE_ACTION = {"while", "when", "by", "before", "after", "whil"}


def compound(word: str, values: frozenset[str], known: frozenset[str]) -> str | None:
    """The value word that `word` (as written) is a compound of with a
    word the vocabulary knows ("lightweight": "light"), or None."""
    for k in range(3, len(word) - 2):
        head, rest = word[:k], word[k:]
        if stem(head) in values and stem(rest) in known:
            return head
    return None


def unknown(t: Token, known: frozenset[str], values: frozenset[str]) -> bool:
    """Whether the vocabulary does not know the word of `t` (it knows a
    proposition's name, and a number read with its unit)."""
    return t.word not in known and t.word not in values and "_" not in t.word


def compounds(tokens: list[Token], values: frozenset[str], known: frozenset[str]) -> list[Token]:
    """The tokens with each compound of a value word read as the value word."""
    return [Token(stem(head), t.raw, t.clause) if unknown(t, known, values)
            and (head := compound(t.raw.lower(), values, known)) else t for t in tokens]


def judged(tokens: list[Token], i: int, known: frozenset[str], values: frozenset[str]) -> str | None:
    """Why the word at `i`, which the vocabulary does not know, bears on
    the pour (the refusal's words), or None if it is ignored (see the
    module's docstring). `values` are the vocabulary's value words."""
    t = tokens[i]
    w = t.raw.lower()
    before = tokens[i - 1] if i > 0 and tokens[i - 1].clause == t.clause else None
    after = tokens[i + 1] if i + 1 < len(tokens) and tokens[i + 1].clause == t.clause else None
    if re.fullmatch(NUMBER, t.word):
        return _UNITS.format(t.raw + (f" {after.raw}" if after is not None else ""))
    if before is not None and re.fullmatch(NUMBER, before.word):
        return _UNITS.format(f"{before.raw} {t.raw}")
    if w in CLOSED:
        return None
    if w in DEGREE or _compares(w, values) or (after is not None and after.word == "than"):
        return f'"{t.raw}": a comparison; say the value itself (see `pantarhei vocab`)'
    near = misspelt([w])
    if near and f"{w!r} for {w!r}" not in near[0]:
        return MISTYPED
    k = i - 1
    while k >= 0 and tokens[k].clause == t.clause and tokens[k].word in _DETERMINERS:
        k -= 1
    if k >= 0 and tokens[k].clause == t.clause and tokens[k].word in NEGATION_STEMS:
        return f'"{tokens[k].raw} ... {t.raw}": what it excludes is not in the vocabulary'
    if w in AMOUNTS or w in UNITS:
        return f'"{t.raw}": an amount, a number or a unit the vocabulary does not read so; ' \
               'write the number in digits with its unit ("45 degrees", "5 cm above", "50 ' \
               'particles"), or say "a little liquid", "some liquid", "much liquid"'
    if w in MEASURES:
        return f'"{t.raw}": a measure without its value; say the value (see `pantarhei vocab`)'
    if w in PLACES:
        return f'"{t.raw}": a place the vocabulary does not say (it says the height above the '\
               'rim, centred, near the rim, to the side, far away, offset sideways)'
    body = _of_body(tokens, i)
    if w in FLAT and body is None:
        return _MANNER.format(t.raw)
    if w in ADJECTIVES:
        return f'"{t.raw}": a property the vocabulary does not say (it says a bowl\'s ' \
               f'{_properties("bowl")}, and a liquid\'s {_properties("liquid")})'
    determined = before is not None and before.word in _DETERMINERS
    if (re.search(r"(?:..ly|wise|wards?)$", w) and len(w) > 4 and not re.search(r"[eio]lly$", w)
            and not determined):
        return _MANNER.format(t.raw)
    held = next((v for v in sorted(values) if len(v) > 4 and (w.startswith(v) or w.endswith(v))),
                None)
    if held is not None:
        return f'"{t.raw}": holds "{held}", and is not a phrasing the vocabulary reads'
    k = i - 1
    while k >= 0 and tokens[k].clause == t.clause and tokens[k].word in _DETERMINERS:
        k -= 1
    if k >= 0 and tokens[k].clause == t.clause and tokens[k].word == "pour" and w not in _CONTENTS:
        return f'"{t.raw}": what is poured, which the vocabulary does not know (it says a ' \
               'liquid\'s weight, stickiness and bounce: "a sticky liquid"; water, milk, oil, honey ' \
               'are read)'
    if _acts(tokens, i, before, after):
        return f'"{t.raw}": an action the vocabulary does not say (it says pouring, tilting, ' \
               'moving in and away, raising and lowering)'
    if body is not None and (w.endswith(_ADJECTIVE_SUFFIXES) or re.search(r"[^aeiou]y$", w)):
        if body not in _NOUNS.values():
            return f'"{t.raw}": a state the vocabulary does not say'
        return f'"{t.raw}": a property of the {body} that the vocabulary does not say ' \
               f'(it says its {_properties(body)})'
    return None


def _compares(w: str, values: frozenset[str]) -> bool:
    """Whether `w` is a comparative or superlative of a value word or a core adjective."""
    m = re.fullmatch(r"(\w{2,}?)(?:i?er|i?est)", w)
    if not m or len(w) < 5:
        return False
    base = m.group(1)
    bases = {base, base + "e", base + "y", base[:-1] if len(base) > 2 and base[-1] == base[-2] else base}
    return any(b in ADJECTIVES or stem(b) in values for b in bases)


def _acts(tokens: list[Token], i: int, before: Token | None, after: Token | None) -> bool:
    """Whether the word at `i` stands where English puts the question's verb."""
    objected = after is not None and (after.word in _DETERMINERS or after.word in ("it", "them"))
    if before is None:              # first in its clause, alone or before its object ("then stir")
        return after is None or objected
    if before.word in ("and", "or") and objected or before.word == "then" and (
            after is None or objected):                 # "pour and stir it", "then stir"
        return True
    if before.word in _ACTORS or (before.word == "to" and i > 1 and tokens[i - 2].word not in
                                  ("next", "clos", "close", "clo")):
        return True
    return tokens[i].raw.endswith("ing") and before.word in _BEFORE_ACTION


def _of_body(tokens: list[Token], i: int) -> str | None:
    """The body the word at `i` is said of, as an adjective: before its
    noun ("a wobbly, light bowl"), or after it and a copula ("the bowl is
    very wobbly"); None if neither."""
    clause = tokens[i].clause
    j = i + 1
    while j < len(tokens) and tokens[j].clause == clause and (
            tokens[j].word in ("and", "or", "material") or tokens[j].word not in _NOUNS
            and tokens[j].word not in _STOPS):
        j += 1
    if j < len(tokens) and tokens[j].clause == clause and tokens[j].word in _NOUNS:
        return _NOUNS[tokens[j].word]
    j = i - 1
    while j >= 0 and tokens[j].clause == clause and tokens[j].word in _GRADING:
        j -= 1
    if j >= 1 and tokens[j].word in _COPULAS and tokens[j].clause == clause:
        return _NOUNS.get(tokens[j - 1].word, tokens[j - 1].raw)
    return None


#: The nouns of the bodies, by their stems: a bowl is the destination by default.
_NOUNS = {**OBJECT_STEMS, BOWL: "bowl"}
#: Words that end the search for the noun an adjective stands before.
_STOPS = {stem(w) for w in ("of", "to", "into", "onto", "from", "with", "at", "in", "on", "over",
                            "above", "below", "by", "for", "if", "when", "then", "is", "are",
                            "it", "pour", "will", "does", "do", "what", "how", "than", "not",
                            "no", "without")}


@lru_cache(maxsize=None)
def _properties(body: str) -> str:
    """What the vocabulary says of `body`, from its dimensions' glosses."""
    from pantarhei.theory.lexicon import load_vocabulary

    bodies = ("source", "destination") if body == "bowl" else (body,)
    said = list(dict.fromkeys(
        d.gloss.split(" of ")[0] for d in load_vocabulary().dimensions.values()
        if " of " in d.gloss and any(v.endswith(f"_{b}") for v in d.values for b in bodies)))
    return ", ".join(said[:-1]) + " and " + said[-1] if len(said) > 1 else "".join(said)
