"""A mishap told in the speaker's own words before the question, with no
time said ("the soup went in but then sloshed back out over the edge. what
should I change?", "my bowl keeps sliding when I pour, any tips?", "it
splashed when I poured from high up. why?"): its outcomes are heard with
the verbs of outcomes.py (outcome_verbs.OUTCOMES), and what is asked after
it is read against them:

- a remedy ("what should I change", "how do I stop that", "any tips"), or a
  value with no goal ("how far should I tilt it"): the outcomes told not
  happening are the goal, the pour told not read ("how should I pour so
  that it stays in the bowl and nothing spills");
- a cause ("why?", "what went wrong"): the outcomes told are asked of the
  pour told, its clauses that tell no outcome read as the scene ("if I
  poured from high up, does it spill?");
- a scene said to help ("would a heavier bowl have stayed put?", "would
  pouring over the centre fix it?"): the outcomes told are asked of it.

Anything else asked after it leaves the question as written. Each question is read alone: what the mishap tells is never the
scene of the answer but where a cause is asked of it. Mishaps told after
a time ("last time ...", "yesterday ...") are earlier_pour.py's; an
outcome told in the present with a value asked to avoid it is
avoided.py's."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.earlier_pour import CAUSE, HELPS, REMEDY, WHEN, liquid_named, says_a_liquid
from pantarhei.bridge.reasoning.everyday import alternation, names, refused
from pantarhei.bridge.reasoning.outcome_verbs import OUTCOMES
from pantarhei.bridge.reasoning.phases import STILL
from pantarhei.bridge.reasoning.rim_strikers import source_names
from pantarhei.bridge.reasoning.vessels import filled

#: What each expectation (or group told together) failing is asked as, and wanted not to as.
_ASKED = {("liquid_remains_in_destination", "no_spill"): "does it splash out", "no_spill": "does it spill", "liquid_remains_in_destination": "does it stay in the bowl",
          "liquid_enters_destination": "does it go in", "liquid_leaves_source": "does it come out",
          "destination_upright": "does the bowl tip over", "source_clear": "does the jug hit the bowl",
          STILL: "does the bowl move"}
_WANTED = {("liquid_remains_in_destination", "no_spill"): "nothing splashes out", "no_spill": "nothing spills", "liquid_remains_in_destination": "it stays in the bowl",
           "liquid_enters_destination": "it all goes in", "liquid_leaves_source": "it all comes out",
           "destination_upright": "the bowl does not tip over", "source_clear": "the jug does not hit the bowl",
           STILL: "the bowl does not move"}
#: The question after the mishap starts at a sentence's end, or at a comma before a word that asks.
_ASKS = (r"why|how|what|whats|which|would|will|could|should|can|is|does|do|did|was|were|any|so|but why|and how|where"
         r"|am (?:i|we) doing (?:it|something|anything) wrong"
         r"|if|should|shall|tips|advice|help")
_BREAK = re.compile(rf"(?:[.!?;]+|,|\.\.\.|\s-)\s+(?=(?:{_ASKS})\b)|\s(?=(?:why|how come|what happened|what went wrong|what did (?:i|we) do wrong|what (?:am i|are we) doing wrong|why (?:did|does|would) (?:that|this|it) happen|why did (?:it|the bowl) do that) *[?.!]* *$)"    # "... poured fast why"
                    r"|\s(?=(?:is|will|would|does) (?:that|this) (?:gonna |going to )?happen\b)")   # "... when i poured is that gonna happen"
#: Whether what was told happens again: asked as a cause is, of the pour told ("is that gonna happen every time?").
_AGAIN = re.compile(r"^(?:so )?(?:is|will|would|does|do) (?:that|this|it) (?:gonna |going to |always |usually )?(?:happen|keep happening)"
                    r"(?: (?:again|every time|each time|always|all the time|often|a lot))?"
                    # with a scene said ("... every time when you come in fast?"): of that scene too
                    r"(?P<when> (?:when|if) (?:i|you|we|it|they|the \w+) [a-z0-9 ]+?)?[?.! ]*$")
#: An outcome told as it happened, or as what keeps happening: its verb in the past ("slid",
#: "went over"), or after "keeps", "always", "is" ("the bowl is jumping").
_TOLD_TENSE = re.compile(r"^(?:[a-z]{2,}[^e]ed|[a-z]+ied|went|ran|fell|slid|came|got|kept|spilt|stuck|flew|threw|shook|sprang"
                         r"|stayed|left|overflowed|tipped|dripped|slipped|flipped|skidded|hit|spun|swung|shot)\b")
_HABIT = re.compile(r"\b(?:keeps|kept|keep|always|every time|each time|just)(?: [a-z]+)? $")
_GOING_ON = re.compile(r"\b(?:is|was|were|are) $")
#: A value asked: "how far should I tilt it", "what height should I use", "how heavy does the bowl need to be".
_VALUE_ASKED = (r"^(?:so )?(?:how (?:far|high|low|much|close|steep|steeply|fast|slow|slowly|quickly|heavy|light)|what "
                r"(?:height|tilt|angle|speed|position|distance|setting)|which (?:height|tilt|angle|speed|position|way))\b")
#: ... with no goal, or with the outcome it is wanted for said in it ("... so it doesn't tip?").
_VALUE = re.compile(rf"{_VALUE_ASKED}(?!.*\b(?:so|without)\b)")
_VALUE_WANTED = re.compile(rf"{_VALUE_ASKED}.*\b(?:so|without)\b")
#: A scene supposed, then whether it helps: "if I come in from higher up next time, would that stop it?".
_IF_HELPS = re.compile(r"^(?:so )?(?:if|what if) (?P<scene>[^,?]+?),? (?:would|will|could|does|do|might) (?:that|this|it) "
                       r"(?:help|work|stop (?:it|that|this)|fix (?:it|that|this)|prevent (?:it|that|this)|solve (?:it|that|this)"
                       r"|be better)[?.! ]*$")
#: What should have been done, asked after a mishap: "should I have pulled away slower?".
_SHOULD_HAVE = re.compile(r"^(?:so )?(?:should|could|would) (?P<who>i|we|he|she|they) (?:have|of) (?P<scene>(?:[a-z]+ed|held|brought"
                          r"|kept|put|gone|come|used|swung|set|stood)\b[^?,]*?)[?.! ]*$")
#: A cause put as a yes or no of a scene: "is the bowl just too light?", "was it too high?".
_TOO = re.compile(r"^(?:so )?(?:is|was|am|were) (?:it|that|i|we|you|he|she|they|the (?P<noun>[a-z]+)) (?:just |simply |maybe )?"
                  r"(?:(?:holding|pouring) (?:it |the \w+ )?(?:from )?|(?:going|moving|coming in|moving (?:it|the \w+)(?: in| away)?"
                  r"|bringing (?:it|the \w+) in|pulling (?:it|the \w+) away) )?(?:too |because (?:(?:it|he|she|they|i|we|you) (?:is|was|are|were|am) |hes |shes |theyre )(?:too )?)"
                  r"(?P<value>light|heavy|slippery|bouncy|high|low|sticky|runny|full|fast|quick|slow|far (?:off )?to (?:one|the) side"
                  r"|far away|close)(?: or (?:something|what))?[?.! ]*$")
#: A cause noted after the mishap ("it went everywhere. too high?"): asked as "was it too high?".
_TOO_NOTED = re.compile(r"(?<=[.,;!?] )too (?=[a-z ]+\?+\s*$)")
#: A speed other than the one told, asked to help: "would slower have helped?", "would going slower fix it".
_SPEED_HELPS = re.compile(r"^(?:so )?(?:would|will|could|does|do|might) (?:(?P<how>going|moving|coming in|pulling (?:it )?away|bringing it in"
                          r"|doing it|pouring|a) )?(?P<speed>slower|more slowly|faster|quicker)(?P<move> approach| retreat)? (?:have )?"
                          r"(?:help(?:ed)?|fix(?:ed)?|stop(?:ped)?|prevent(?:ed)?|work(?:ed)?|save(?:d)?|been better|be better)"
                          r"(?: (?:it|that|this))?[?.! ]*$")
#: The move a speed asked as a cause is of, by the phase the mishap is told in: "when I moved it in ... was I going too fast?".
_SPEED_OF = {" as the jug comes in": "move in", " as the jug moves away": "move away"}
#: What splits the narrative's clauses, for the scene a cause is asked of.
#: (Not a pair said as one: "rocked back and forth", "round and round", "to and fro".)
_CLAUSES = re.compile(r",? (?:and then|but then|(?<!\bback )(?<!\bround )(?<!\bto )and(?! forth\b| round\b| fro\b)|but|then|so|until"
                      r"|because) |, | (?=(?:when|while|after|as soon as|even though"
                      r"|although|though) )")
#: A goal said, not a mishap told: "I want to ...", "I'm trying to ...".
_WANTS = re.compile(r"\b(?:i|we) (?:want|need|would like|d like|am trying|are trying|m trying|re trying|wish) to\b|\bgoal\b")
#: The source's moves told: (the phase they are said as, the words).
_WHO_MOVED = r"(?:\b(?:when|as|while|once) |^)(?:(?:i|we|you|he|she|they|it|the \w+) (?:was |were )?)?"     # (no one, in a note)
_MOVES_TOLD = (
    (" as the jug moves away", re.compile(rf"{_WHO_MOVED}(?:pull|mov|tak|took|drew|draw|lift|yank)\w*(?: it| (?:the|my|a) \w+)? (?:away|back|out|off)\b"
                                          r"|\bon (?:the|its|my) way (?:out|back|away)\b")),      # ("hit the bowl on the way out")
    (" as the jug comes in", re.compile(rf"{_WHO_MOVED}(?:(?:brought|bringing|lowered|lowering)\b|(?:mov|cam|com|swung|swing|carri)\w*"
                                         r"(?: it| (?:the|my|a) \w+)? (?:in|over|closer|down|toward|towards)\b)|\bon (?:the|its|my) way (?:in|down)\b")),
)
#: The bowl said as where a spill told should have gone: it did not all go in ("ran down the
#: outside instead of going in the bowl", "went on the floor and not in the tub").
_NOT_IN = re.compile(r"\b(?:instead of|rather than|and not|not|except(?: for)?|but(?= in\b| into\b)) (?:going |landing |getting |ending up )?(?:(?:(?:in|into|inside|in to) )?"
                     r"(?:the |a |an |my |our )?(?:bowl|dish|destination|basin|tub|pot|pan|glass|mug|cup|bucket)s?\b"
                     r"|(?:in|inside|in there)(?= *(?:[,.;:!?]|$)))")      # ("ran down the pot instead of going in")
#: A cause asked before the mishap it is asked of: "what went wrong here, I turned the cup upside down ...".
_CAUSE_FIRST = re.compile(r"^(?P<cause>what went wrong|what happened|what did (?:i|we) do wrong)(?: here| there)?(?: ?[,:;.?!])+ *"
                          r"(?P<told>(?:i|we|he|she|they|it|the|my)\b[^?]+?)[ .!]*$")
#: The liquid said where it ended up, with no verb ("water everywhere", "milk all over the counter"): spilt.
_EVERYWHERE = re.compile(r"^(?:and |so )?(?:now )?(?:there is |there's |theres |there was )?(?:(?:hot|cold|warm|sticky|the|my|some) )*(?:[a-z]+ )?(?:water|liquid|milk|juice|oil|soup"
                         r"|broth|tea|coffee|syrup|honey|stuff|mess)(?: (?:just|all|went|was|got))? (?:everywhere|all over"
                         r"(?: (?:the|my) (?:table|counter|floor|place|worktop|bench))?)[ .!]*$")
#: What a spill lands on.
_UNDER_WORDS = "table|counter|countertop|worktop|floor|bench|stove|cloth|tablecloth|tray"
_UNDER = rf"(?:{_UNDER_WORDS})"
#: Where the liquid went, said after the verb of the clause before ("... down the jug and onto the table"): spilt.
_ONTO = re.compile(rf"^(?:then |and )?(?:onto|on to|all over|over) (?:the |my |his |her |their |our )?(?:{_UNDER_WORDS}|hands?|shirt|lap)\b")
#: What was left outside, told as a thing: "there was a line of drips all over the table", "a puddle on the counter".
_TRAIL = re.compile(rf"\b(?:there (?:was|were) )?(?:a |an |some )?(?:big |little |long |sticky )?(?:trail|line|puddle|pool|ring|string|stream)"
                    rf" of (?:drips|drops|liquid|water|milk|juice|oil|syrup|soup|it)(?: (?:all over|on|across|everywhere|onto)"
                    rf"(?: (?:the |my )?{_UNDER})?)?"
                    rf"|\b(?:there (?:was|were) )?(?:a |an )?(?:big |little )?puddle (?:on|all over|across) (?:the |my )?{_UNDER}\b")
#: A negation before an outcome told: it did not happen ("nothing came out").
_NOT = re.compile(r"\b(?:nothing|none|not|never|no|zero)\b")


@lru_cache(maxsize=None)
def _outcomes() -> tuple[tuple[re.Pattern, tuple[str, ...], bool], ...]:
    return tuple((re.compile(rf"\b(?:{filled(v)})\b"), names, bad) for v, names, bad in OUTCOMES)


@lru_cache(maxsize=None)
def _liquid_before() -> re.Pattern:
    """The liquid, or its stream, said last before a verb: "the stream hit the rim"."""
    return re.compile(rf"\b(?:stream|jet|flow|pour|liquid|drops?|{alternation(names('liquid'))})(?: just| then)? $")


@lru_cache(maxsize=None)
def _held_tipped() -> re.Pattern:
    """Something held tipped, said last before a verb of tipping: "the bottle already", "the jug was", or a note's
    source alone ("jug tipped too far")."""
    return re.compile(r"\b(?:already )$|\b(?:the|my|a) (?!(?:bowl|dish|basin|tub|trough|destination)\b)[a-z]+ (?:already |was |is |got )*$"
                      rf"|^(?:{alternation(source_names())}) $")


@lru_cache(maxsize=None)
def _sized() -> re.Pattern:
    """A container told by its size ("my big pitcher kept hitting the rim"), which the vocabulary cannot say:
    the cause of such a mishap asked is left as written, for the reader to refuse (what to do next time is
    asked of another pour, and read)."""
    return re.compile(rf"\b(?:{alternation(refused('all of one size').phrases)}) (?:[a-z]+ )?(?:{alternation(names('bowl'))})\b")


@lru_cache(maxsize=None)
def _landing() -> re.Pattern:
    """The liquid landing in the bowl, told with nothing else: "the syrup hit the bowl", "it landed in the bowl"."""
    return re.compile(rf"(?:the |my )?(?:it|stream|jet|pour|liquid|{alternation(names('liquid'))}) (?:hit|hits|landed|lands)"
                      r"(?: in| into| on)? (?:the |my )?(?:bowl|dish|destination|basin)")


def _told(clause: str, present: bool = True) -> list[tuple[tuple[str, ...], bool]]:
    """The outcomes a clause tells as having happened, each group with
    whether it failed ("it slid": the bowl moved; "nothing came out": it did
    not leave the source; "it went in fine": it held)."""
    if _NOT_IN.fullmatch(clause.strip(" ,")):
        return [(("liquid_enters_destination",), True)]         # "it went all over the floor and not in the bowl"
    out: list[tuple[tuple[str, ...], bool]] = []
    # a spill told with no verb of its own: "hot broth everywhere", "there was a line of drips all over the table",
    # "(it went down the jug) and onto the table" (the verb before's)
    spilt = next((p for p in (_EVERYWHERE, _TRAIL, _ONTO) if p.search(clause)), None)
    if spilt is not None:
        out.append((("no_spill",), True))
        clause = spilt.sub(" ", clause)
    for pattern, names, bad in _outcomes()[:-1]:     # (the last is "safe", "fine": no outcome told)
        m = next((m for m in pattern.finditer(clause) if _happened(m, names, present)), None)    # ("drips landed": not "drips")
        if m is None:
            continue
        before = clause[:m.start()]
        group = STILL if names == STILL else names
        failed = bad != (_NOT.search(before) is not None)
        if (group, failed) not in out:
            out.append((group, failed))
        if names == ("destination_upright",) and m.group(0).startswith("knock") and not _liquid_before().search(before):
            out.append((("source_clear",), failed))    # knocked over: struck by the source ("the pitcher knocked the bowl over")
        clause = clause[:m.start()] + " " + clause[m.end():]
    if (("no_spill",), True) in out or (("liquid_remains_in_destination", "no_spill"), True) in out:
        if _NOT_IN.search(clause) and not any("liquid_enters_destination" in g for g, _ in out):
            out.append((("liquid_enters_destination",), True))     # "ran down the bottle instead of into the bowl"
    return out


def _happened(m: re.Match, names: tuple[str, ...], present: bool = True) -> bool:
    """Whether the outcome `m` (of the expectations `names`) is told as having happened to the bowls or the liquid
    (in the present after its subject too, where `present`)."""
    before = m.string[:m.start()]
    if re.search(r"\b(?:before|until|till|unless|in case) (?:it|they|the \w+) $", before):
        return False        # what is to be stopped before it happens ("stop before it overflows"), not told
    if re.search(r"\b(?:i|we|you|he|she|they)(?: just)? $", before) and "source_clear" not in names:
        return False        # what the one pouring did ("i tipped the jug"), not an outcome
    if names == STILL and m.group(0).startswith("mov") and re.match(
            r" (?:the|my|a|an|his|her|their|it)\b(?! (?:bowl|dish|destination|whole|way|lot|bit|little|few|couple)\b)", m.string[m.end():]):
        return False        # someone moving something ("my grandson moved the jug"), not the bowl moving
    if names == ("source_clear",) and _liquid_before().search(before):
        return False        # the liquid striking the bowl ("the stream hit the rim and sprayed"): no contact of the source
    if names == ("destination_upright",) and not re.match(r"(?:knock|push|shov)", m.group(0)) and (re.match(r" (?:the|a|an|my|his|her|their|it)\b(?! (?:bowl|dish|basin|whole thing)\b)(?!(?: \w+)? over\b)",
                                   m.string[m.end():]) or _held_tipped().search(before)):
        return False        # tipping something, or something held tipped: the source ("she keeps tipping the jug",
        #                     "i started with the bottle already tipped", a note's "jug tipped too far"); not the
        #                     bowl ("... and tipped the whole thing")
    # (not told as having happened: "need to empty it without knocking it over")
    # going on: "the bowl is jumping", or its subject alone before it ("bowl wobbling. why.")
    going_on = _GOING_ON.search(before) or re.fullmatch(
        r"(?:the |my )?(?:bowl|dish|cup|jug|bottle|pitcher|glass|mug|water|liquid|milk|juice|oil|soup) ", before)
    # what keeps happening, said in the present after its subject ("it dribbles down the side")
    now = present and re.match(r"[a-z]+[^s]s\b", m.group(0)) and re.search(r"(?:^|\b(?:it|the \w+|my \w+|our \w+) )$", before)
    asked_why = re.search(r"^why did (?:it|they|the \w+|my \w+) $", before)        # "why did it miss the bowl"
    return bool(_TOLD_TENSE.match(m.group(0)) or _HABIT.search(before) or (going_on and re.match(r"[a-z]+ing\b", m.group(0)))
                or now or asked_why)


def _said(words: dict, groups: list[tuple[str, ...]], when: str = "") -> str:
    """The groups of expectations told failed, in `words` (_ASKED or _WANTED), each said once;
    the bowl's moving in the phase told (`when`: " as the jug comes in")."""
    words = {**words, STILL: words[STILL] + when}
    said = []
    for group in groups:
        still = group not in words and set(STILL) <= set(group)       # "knocked it sideways": hit, and moved
        said += [words[group]] if group in words else \
            [words[n] for n in group if not (still and n in STILL)] + ([words[STILL]] if still else [])
    # the phase said last, so that what follows it is not read as of the phase ("... as the jug comes in and ...")
    return " and ".join(sorted(dict.fromkeys(said), key=lambda w: bool(when) and w == words[STILL]))


def _phase_told(told: str) -> str:
    """The move a mishap is told in, said as a phase: "as I brought it in" (the move in),
    "when I pulled the jug away" (the move away); "" for none."""
    for when, move in _MOVES_TOLD:
        if move.search(told):
            return when
    return ""


def mishap(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with a mishap told before its question read as
    the module says, and what is said back; `text` as it is otherwise. The
    question is taken from the last break in the text back, the first that
    asks in one of the ways the module reads; a cause asked first ("what went wrong here, I turned
    the cup upside down ...") is asked after the mishap."""
    if (noted := _TOO_NOTED.sub("was it too ", text)) != text and (read := mishap(noted))[1]:
        return read
    first = _CAUSE_FIRST.match(text)
    if first is not None:
        text = f"{first.group('told')}. {first.group('cause')}?"
    for cut in reversed(list(_BREAK.finditer(text))):
        told, asked = text[:cut.start()].strip(), text[cut.end():].strip()
        if re.match(rf"(?:{_ASKS})\b", re.sub(r"^(?:ok |okay |well )?so (?=i|we|my|the)\b", "", told)) or _WANTS.search(told):
            return text, ()          # a question first, or a goal ("i want to get it all out without any left inside")
        read = _read(told, asked)
        if read is not None:
            return read
    if not re.search(r"[?]", text) and not re.match(rf"(?:{_ASKS})\b", text) and re.search(
            r"^(?:tried|poured|the|my|our|his|her|their|it|after)\b|\b(?:i|we|he|she|they)\b"
            # (or a source told first in a note, with what was done with it, then what went wrong: "jug tilted too
            # far, milk went over the rim")
            rf"|^(?:[a-z]+ )?(?:{alternation(source_names())}) (?:[a-z]+ed|held)\b.*(?:,| and) (?:the |my |some |all |half )?(?:of (?:it|the \w+) )?"
            r"[a-z]+ (?:went|ran|spilled|spilt|splashed|slid|fell|flipped|overflowed|dripped|missed)\b", text) and not re.search(
            r"\b(?:whether|wonder|know|tell|if|would|should|could|can|will|how|what|why|which|please)\b", text):
        # a mishap told with nothing asked after it ("I pulled the pitcher away too fast and a trail of
        # drips went across the table."): what went wrong, asked of the pour told, as "why?" asks it
        read = _read(text.strip(" .!"), "why?", present=bool(re.search(r"\b(?:every|each) time\b|\bwhenever\b", text)))
        if read is not None:
            return read[0], (read[1][0], "nothing asked after it: read as what went wrong, asked of the pour told")
    return text, ()         # anything else asked: the question as written


#: Another bowl or source said to help, the pour told kept: "would a heavier bowl stay up".
_OTHER_BODY = re.compile(r"(?:a|an|the|my) (?:[a-z]+ )?(?:heavier|lighter|heavy|light|slippier|grippier|bouncier)"
                         r" (?:[a-z]+ )?(?:bowl|dish|basin|jug|pitcher|bottle|cup|mug|one)$")


def _scene_told(clauses: list[str], tells: dict, poured: str) -> list[str]:
    """The clauses of a mishap told that tell nothing gone wrong: those with no outcome, and those saying when
    it went wrong ("when i emptied the heavy saucepan into it"), the liquid told first."""
    scene = [re.sub(rf"^(?:{WHEN},? |as soon as (?=\w+ start))", "", c) for c in clauses if not any(bad for _, bad in tells[c]) and (
        re.match(r"(?:when|while|as|after|once|even though|although|though) ", c) or not tells[c])
        and not _landing().fullmatch(c)]       # "the syrup hit the bowl": the pour landing, told with no scene in it
    if poured and not any(poured.strip() in c for c in scene):     # the liquid told is the pour's
        scene.insert(0, f"pouring{poured}")
    return scene


#: A property of the bowl or of the source told, which the one asking has and keeps: "my bowl is very light".
_PROPERTY = r"(light|heavy|slippery|slick|bouncy|grippy)"
_BOWL_TOLD = re.compile(rf"\b(?:bowl|dish|basin)s? (?:is|was|are|were) (?:(?:very|really|quite|so|super|too) )?{_PROPERTY}\b"
                        rf"|\b{_PROPERTY} (?:[a-z]+ )?(?:bowl|dish|basin)\b")
_SOURCE_TOLD = re.compile(rf"\b(?:jug|pitcher|bottle|cup|mug|pot|kettle|carton)s? (?:is|was) (?:(?:very|really|quite|so|super|too) )?"
                          rf"{_PROPERTY}\b|\b{_PROPERTY} (?:[a-z]+ )?(?:jug|pitcher|bottle|cup|mug|pot|kettle|carton)\b")


def _bodies_told(told: str) -> str:
    """The bowl's and the source's properties told, said as the pour asked of them: " into a light bowl"."""
    bowl, source = _BOWL_TOLD.search(told), _SOURCE_TOLD.search(told)
    return (f" from a {source.group(1) or source.group(2)} jug" if source else "") + (
        f" into a {bowl.group(1) or bowl.group(2)} bowl" if bowl else "")


def _read(told: str, asked: str, present: bool = True) -> tuple[str, tuple[str, ...]] | None:
    """The question `asked` after the mishap `told`, read (mishap's), or None; an outcome told in the present
    after its subject is told as having happened where `present` (something asked of it, or "every time" said)."""
    if should := _SHOULD_HAVE.match(asked):       # "should I have pulled away slower?": would that have helped
        put = f"if {should.group('who')} {should.group('scene')}, would that help"
        read = _read(told, f"{put}?", present)
        return None if read is None else (read[0], tuple(n.replace(f"{put}:", f"{asked.strip(' ?.!')}:", 1) for n in read[1]))
    clauses = [c for c in _CLAUSES.split(re.sub(r"[.!?;]+ +", ", ", told)) if c]
    tells = {c: _told(c, present) for c in clauses}          # each clause's outcomes, found once
    failed = list(dict.fromkeys(g for c in clauses for g, bad in tells[c] if bad))
    if not failed:
        return None
    told_why = asked
    if re.match(r"(?:so |and |but )?why did (?:it|they|the \w+|my \w+) [a-z]", asked):     # an outcome named in the cause asked:
        named = [g for g, bad in _told(re.split(r" (?:if|when|while|like|because|after|before)\b", re.sub(
            r"^(?:so |and |but )", "", asked.strip(" ?.!")))[0]) if bad]     # asked too ("why" asks the cause)
        if named:
            failed, asked = list(dict.fromkeys([*failed, *named])), "why?"
    said = f"{told}: read as nothing: a pour told, with what went wrong; the answer is for the one asked"
    when = _phase_told(told)
    wanted, question = _said(_WANTED, failed, when), _said(_ASKED, failed, when)
    poured = liquid_named().search(told)    # the liquid told stays
    poured = f" {poured.group(0)}" if poured else ""
    bodies = _bodies_told(told)      # "my bowl is very light ...": the bowls stay as told, the pour is asked
    if REMEDY.match(asked):
        rest = f"how should i pour{poured}{bodies} so that {wanted}?"
        return rest, (said, f"{asked.strip(' ?.!')}: read as {rest.strip(' ?')}, as the pour told did not")
    if _VALUE_WANTED.match(asked):          # "how heavy does the bowl need to be so it doesn't tip?": its own goal
        return f"{f'pouring{poured}{bodies}, ' if poured or bodies else ''}{asked}", (said,)
    if _VALUE.match(asked):
        rest = f"{asked.strip(' ?.!')} pouring{poured}{bodies} so that {wanted}?" if poured or bodies else \
            f"{asked.strip(' ?.!')} so that {wanted}?"
        return rest, (said, f"{asked.strip(' ?.!')}: read as asked so that {wanted}, as the pour told did not")
    if m := _SPEED_HELPS.match(asked):      # "would slower have helped?": the move told, at the other speed
        move = {" approach": "move in", " retreat": "move away", "coming in": "move in", "bringing it in": "move in"}.get(
            m.group("move") or m.group("how") or "", "move away" if (m.group("how") or "").startswith("pulling") else _SPEED_OF.get(when))
        if move is not None:        # (none told: a speed of pouring itself, which has none)
            rest = f"if i {move} {'slowly' if m.group('speed') in ('slower', 'more slowly') else 'fast'}, {question}?"
            return rest, (said, f"{asked.strip(' ?.!')}: read as {rest.strip(' ?')}, as the pour told did")
    for helps, how in ((HELPS, "with"), (_IF_HELPS, "if")):
        m = helps.match(re.sub(r"^so ", "", asked))
        if m is not None and re.fullmatch(r"(?: (?:it|that|this))?[?.! ]*", m.string[m.end():]):
            kept = f"pouring{poured}, " if poured and not says_a_liquid(m.group("scene")) else ""   # unless another is said
            if _OTHER_BODY.match(m.group("scene")):     # another bowl or source: the pour told kept ("would a heavier bowl ..."),
                body = m.group("scene").split()[-1]     # not what it told of that body ("my bowl is really light")
                kept = "".join(f"{c}, " for c in _scene_told(clauses, tells, poured) if not re.search(rf"\b{body}\b", c))
            rest = f"{kept}{how} {m.group('scene')}, {question}?"
            return rest, (said, f"{asked.strip(' ?.!')}: read as {rest.strip(' ?')}, as the pour told did")
    m = _TOO.match(asked)
    if m is not None and m.group("value") in ("fast", "quick", "slow"):
        if when not in _SPEED_OF:
            return None         # a speed with no move told: of pouring itself, which has none
        rest = f"if i {_SPEED_OF[when]} {'slowly' if m.group('value') == 'slow' else 'fast'}, {question}?"
        return rest, (said, f"{asked.strip(' ?.!')}: read as {rest.strip(' ?')}, as the pour told did")
    if m is not None:
        rest = f"if the {m.group('noun')} is {m.group('value')}, {question}?" if m.group("noun") else (
            f"if i pour {m.group('value')}, {question}?")
        return rest, (said, f"{asked.strip(' ?.!')}: read as {rest.strip(' ?')}, as the pour told did")
    if CAUSE.match(asked) or _AGAIN.match(asked):
        if _sized().search(told):
            return None         # the cause of a pour told with a size, which the answer would leave out
        # the clauses that tell nothing gone wrong: those with no outcome, and those saying when it went wrong
        # ("when i emptied the heavy saucepan into it")
        scene = _scene_told(clauses, tells, poured)
        if (again := _AGAIN.match(asked)) and again.group("when"):
            scene.append(again.group("when").strip())
        rest = f"{', '.join(scene)}, {question}?" if scene else f"{question}?"
        return rest, (f"{told}: read as {rest.strip(' ?')}", f"{told_why.strip(' ?.!')}: read as asked of the pour told")
    return None
