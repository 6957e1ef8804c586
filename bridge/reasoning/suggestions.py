"""What a refusal offers for a word it could not read: the phrasings that
would be read (HINTS: "pour slowly" is "move in slowly"), and the
vocabulary's word it is close to ("tilded": "tilted"), as the glosses, the
everyday phrases of words.py and the everyday word list (everyday.txt)
write them."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import UNCLEAR, alternation, names, sections
from pantarhei.bridge.reasoning.fullness import HOLDS_LIQUID
from pantarhei.bridge.reasoning.name_words import names_part
from pantarhei.bridge.reasoning.outcome_verbs import outcome_verb
from pantarhei.bridge.reasoning.spelling import english
from pantarhei.bridge.reasoning.wording import Token
from pantarhei.bridge.reasoning.words import PHRASES
from pantarhei.theory.lexicon import load_vocabulary


@lru_cache(maxsize=None)
def _spelt() -> tuple[str, ...]:
    """The words of four letters or more of the glosses and the phrases."""
    texts = [p.gloss for p in load_vocabulary().propositions.values()] + [
        " ".join(re.findall(r"[a-z]+", p)) for ps in (*(ps for _, ps, *_ in PHRASES), *(s.phrases for s in sections()))
        for p in ps if not p.startswith("re:")]
    return tuple(sorted({w for t in texts for w in re.findall(r"[a-z]{4,}", t.lower())}))


def misspelt(words: list[str]) -> list[str]:
    """One "did you mean" for those of `words` close to one of the
    vocabulary's (and neither one of them nor an English word), or none."""
    import difflib

    # spelt right, a number, a verb of an outcome ("slide" is no "side") or an English word
    # ("helped" is no "held", "ask" no "cask"): not misspelt
    near = {w: difflib.get_close_matches(w.lower(), _spelt(), n=1, cutoff=0.8) for w in words
            if w.lower() not in _spelt() and not re.search(r"\d", w) and not outcome_verb(w.lower())
            and not english(w.lower())}
    return [f'did you mean {", ".join(f"{m[0]!r} for {w!r}" for w, m in near.items() if m)}?'
            ] if any(near.values()) else []


#: Phrasings that would be read, for words that could not be placed: (pattern
#: of the words as written, what to say).
HINTS: tuple[tuple[str, str], ...] = (
    (r"\bpour\w*\b.*\b(?:slow|fast|quick|gentl|careful|rapid|speed|velocity|pace)|\b(?:speed|rate|pace|velocity)\b.*\bpour"
     r"|^(?:what |which )?(?:[a-z]+ (?:and|or|n) )?(?:speed|rate|pace|velocity)$",
     'pouring has no speed of its own: say how fast the source moves in or away ("move in '
     'slowly", "move away fast")'),
    (r"\b(?:not|without)\b.*\b(?:tilt|tip|lean)",
     'not tilted much: say "slightly tilted" or "upright"'),
    (r"\b(?:tilt|tip|rotat|turn|pour)\w* (?:rate|speed|velocity)\b|\b(?:slow|fast|quick|gradual|rapid|steadi)"
     r"\w* (?:tilt|tip)|\b(?:tilt|tip|rotat|turn)\w*(?: \w+)*? (?:slow|fast|quick|gradual|rapid|steadi"
     r"|speed|velocity|pace)",
     'the vocabulary has no speed of tilting: it says how far the source is tilted ("tilted '
     'halfway") and how fast it moves in or away ("move in slowly", "move away fast")'),
    *((rf"\b(?:{words})\b", f'{said}: than what? the vocabulary says values, not changes: say '
       + (f'{value}, a number ("10 cm above the rim") or the rim ("{said} than the rim")'
          if said in ("higher", "lower") else f'{value}'))
      for words, said, value in (
          ("higher", "higher", '"pour high"'), ("lower", "lower", '"pour low"'),
          ("heavier|lighter", "heavier or lighter", '"a heavy bowl" or "a light bowl"'),
          ("faster|quicker|slower", "faster or slower", '"move in fast" or "move in slowly"'),
          ("steeper", "steeper", '"steeply tilted"'),
          ("closer|nearer|further|farther", "closer or further",
           '"centred over the bowl", "near the rim", "from the side" or "far from the bowl"'),
          ("stickier|thicker|runnier|thinner", "thicker or thinner",
           '"a sticky liquid" or "a runny liquid"'),
          ("bouncier|grippier|slipperier", "bouncier, grippier or slipperier",
           '"a bouncy bowl", "a grippy bowl" or "a slippery bowl"'),
          ("fuller|emptier", "fuller or emptier", '"a full cup" or "a little liquid"'))),
    (r"\b(?:more|less|fewer) than\b|\bat (?:least|most)\b|^(?:past|beyond|up to)$",
     'a bound leaves the value open: say the value ("tilted halfway", "pour high") or a range '
     'with both ends ("10 to 20 cm above the rim", "30 to 40 degrees")'),
    (r"^how ", 'asks for a value: say one ("pour high", "tilted halfway") and `ask` answers '
               'what happens, or give `pantarhei plan` the outcome wanted and it finds a pour'),
    (r"^(?:at|level with|even with) (?:the )?(?:\w+ )?(?:rim|edge|lip) (?:height|level)$",
     'at the rim\'s height: just above it or just below it? say "just above the rim" or "just below the rim"'),
    (r"^(?:none|nothing|no \w+)(?: of it)? (?:on|onto|in|into|over|all over|outside) ",
     'none on the table: wanted, or asked? say "so that nothing spills" or "does any spill?"'),
    (r"^(?:the |its )?(?:far|opposite) (?:side|edge|rim|lip)",
     'the far side of the bowl: the vocabulary\'s places lie on the side the source comes from: say "near the rim", '
     '"centred" or "from the side"'),
    (r"^from above$|^overhead$|^from the top$",
     'above: how high, or where? say "high above the bowl" or "centred over the bowl"'),
    (r"^all the way$", 'all the way: tilted how far? say "steeply tilted" (about 90 degrees) or '
                       '"upside down"'),
    (r"\bempty$", 'empty: the source holds liquid (say "a little liquid" or "almost empty"), and '
                   'the destination is empty before every pour ("into an empty bowl")'),
    (r"^already ", HOLDS_LIQUID),
    (r"^while ", 'the vocabulary pours from one pose: say where the source moves before pouring '
                 '("move in from the side") or after it ("move away fast")'),
    (r"^(?:(?:away )?from|off) (?:the )?(?:\w+ )?(?:rim|edge|lip|brim)$", 'measured from the rim: inside it or outside? say how far from '
                                  'the centre ("5 cm from the centre"), "near the rim" or "to the side"'),
    (r"\b(?:close|next) to|\bbeside\b|\balongside\b", 'close to the bowl: say "just above the rim", "low above the bowl" or '
                             '"near the rim"'),
    (r"^(?:(?:very )?(?:low|high)|(?:high|low|tall|short) ?(?:sided|walled|rimmed|edged))$",
     'the vocabulary\'s bowls are all of one size: a height is where the source is ("pour low", '
     '"pour high above the bowl")'),
    (r"^(?:way|far|well) (?:up )?(?:above|over)$", 'how high above? say "high above the '
                                                            'bowl", "very high" or a height ("20 cm above")'),
    (r"^off(?: |-)?cent", 'off centre: how far? say "near the rim", "from the side" or "offset '
                          'sideways"'),
    (r"\b(?:left|right)", 'left or right: the vocabulary\'s offset names no side: say "offset '
                           'sideways", "from the side" or "in line with the bowl"'),
    (r"^(?:tilt|tip|angl|inclin|lean)\w*(?: \w+)*? (?:too |so |that |very )?far$",
     'tilted too far: how far? say "steeply tilted" or "upside down"'),
    (r"^(?:tilt|tip|angl|inclin|lean)\w*(?: \w+)*? too much$",
     'tilted too much: how far? say "steeply tilted" or "upside down"'),
    (r"horizontal$", 'measured from the horizontal: say the tilt from upright ("tilted 60 degrees", '
                      '"tilted 110 degrees"), or "steeply tilted" for about level'),
    (r"^(?:sideways|laterally|lateral|sidewise)$",
     'sideways: offset or rolled? say "offset sideways" or "tilted sideways"; a move in or out '
     'goes to or from the side: say "move in from the side" or "end to the side"'),
    (r"side(?: ?,)? (?:just )?a (?:little |tiny )?bit$", 'a little to one side: how far? say "near the '
                                                   'rim", "from the side" or "offset sideways"'),
    (r"^a (?:little|bit|tad)$", 'a little: of what? say "a little liquid", "slightly tilted", or '
                               'where ("near the rim", "from the side", "offset sideways")'),
    (r"^(?:drop(?:s|ped|ping)?|let(?:s|ting)?)$|^(?:drop|let)\w* (?:it|the|go)", 'dropping: the source is held throughout the pour; the vocabulary says '
                       'nothing of letting it go'),
    (r"^(?:hit|hits|hitting|touch\w*|bump\w*|strikes?|striking|knock\w*)$",
     'hitting: contact is asked of the source ("does the cup hit the bowl?"); the liquid landing '
     'is asked as "does it go in?" or "does it splash?"'),
    (r"^(?:tilt|tilted|tip|tipped|tipping)$", 'tilted how far? say "slightly tilted", "tilted halfway", '
                                  '"steeply tilted" or "upside down"'),
)


@lru_cache(maxsize=None)
def hints() -> tuple[tuple[str, str], ...]:
    """HINTS and, for each word the everyday list refuses, why and what
    would be read; and for a pour into a place or into a liquid, why not."""
    onto = r"^(?:\w+ )*(?:on|onto|into|in|over|down) (?:the |a |my |our |some )?"
    return HINTS + tuple((rf"^(?:{alternation(s.phrases)})$", s.said_back)
                         for s in sections() if s.words == UNCLEAR) + (
        (rf"{onto}(?:{alternation(names('context'))})$",
         'the vocabulary pours into a bowl: say "into a bowl" (where the bowl stands is not '
         'read: "a bowl on the table")'),
        (rf"^(?:above|over|off|from) (?:the |a |my |our )?(?:{alternation(names('context'))})$",
         'heights are measured from the rim of the destination: say "12 cm above the rim"'),
        (rf"{onto}(?:{alternation(names('liquid'))})$",
         "the destination is empty before the pour: the vocabulary says nothing of pouring "
         "into a liquid"))


#: What a refusal says where no phrasing fits the words it names.
DESCRIBE = "describe the scene with the words of `pantarhei vocab`, or give --props P1,P2"


def hinted(words) -> list[str]:
    """The hints (hints()) for any of `words`, each once, in hints()'s order."""
    return list(dict.fromkeys(h for pattern, h in hints() if any(re.search(pattern, w) for w in words)))


def refuse_unplaced(question: str, tokens: list[Token], read: set[int], lex) -> None:
    """UserError naming the words of the question that were not read: value
    words that fit nothing said ("pour light": the light what?) and, when
    something else was read, words the vocabulary does not know (a question
    with nothing read is read_question's to answer as the ordinary pour or
    to refuse); with the phrasings that would be read, where there are some.
    A word the reader does not know that is part of the name of the bowl
    or liquid after it ("a martini glass") is not refused: `ask` shows it
    as ignored. `read`: the positions read; `lex`: reading.py's lexicon."""
    words: dict[str, None] = {}           # in order, each once
    value_words: dict[str, None] = {}
    for i, t in enumerate(tokens):
        if i not in read and t.word not in lex.known and names_part(tokens, i, lex.placeable):
            continue
        if i not in read and (t.word in lex.placeable or (read and t.word not in lex.known)):
            words.setdefault(t.raw)
            if t.word in lex.saying:
                value_words.setdefault(t.word)
    if not words:
        return
    said = ", ".join(f'"{w}"' for w in words)
    offered = hinted(words)
    if not offered and value_words:
        glosses = list(dict.fromkeys(g for w in value_words for g in lex.saying[w]))
        if len(glosses) <= 4:
            offered = ["would be read: " + ", ".join(f'"{g}"' for g in glosses)]
    offered += misspelt([t.raw for t in tokens if t.word not in lex.known])
    hint = "; ".join(offered) if offered else DESCRIBE
    raise UserError(f"could not place {said} in \"{question}\": {hint}")
