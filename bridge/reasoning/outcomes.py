"""What a question asks, heard apart from the scene it describes.

A clause that asks about the outcome ("will it spill?", "does the bowl
slide?", "is it messy", "does anything come out", "is it safe", "does it
all go in") names the expectations it asks about: the answer puts them
first, and the clause is taken out of the scene's words, its subject left
in ("will a light bowl tip over?" still says a light bowl), but not how
much of the liquid it asks of ("does most of it go in"), nor how much it
happens ("does it shift a little"); a bowl that strikes another is the
source ("does a heavy pot hit the bowl"), and a phase named asks of it
(phases.py: "when the cup comes in"). "What if the bowl moves?" asks what
follows an outcome, which the vocabulary cannot say: it is refused. A
clause about what the person or the robot does ("do I tip the cup"), or
how the source is held ("if the jug is tipped"), is no outcome; one
supposed of a bowl ("if the bowl is moving") is refused. A goal said with the scene
("without spilling", "so that the cup does not touch the bowl") is what the person wants:
an expectation that should hold (or, rarely, fail), for the answer to say whether the
theory expects it and to point to `plan` for how; a clause joined to a goal by "but" or "and" is
wanted too, with its own negation ("so nothing spills and the bowl stays put": the bowl still).

`hear(text)` takes normalised text (wording.normalised) and gives the
expectations asked, the goals as literals ("no_spill", "neg(no_spill)"), the phrases heard and the text left for the scene.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.acting import acts, around, staying
from pantarhei.bridge.reasoning.asked_without import without_asked
from pantarhei.bridge.reasoning.cued import Cued
from pantarhei.bridge.reasoning.earlier_pour import liquid_named
from pantarhei.bridge.reasoning.elsewhere import instead_of_the_bowl
from pantarhei.bridge.reasoning.nouns import poured_from
from pantarhei.bridge.reasoning.outcome_verbs import ALL_IN as _ALL_IN, OUTCOMES
from pantarhei.bridge.reasoning.flow_rates import rates, refuse_alone
from pantarhei.bridge.reasoning.frames import CONTACT, asked_plainly
from pantarhei.bridge.reasoning.likely import likely
from pantarhei.bridge.reasoning.phases import STILL, during, moving
from pantarhei.bridge.reasoning.seeking import reaches, sought, wanting
from pantarhei.bridge.reasoning.strikers import containers, striker
from pantarhei.bridge.reasoning.worries import worried
from pantarhei.bridge.reasoning.supposed_never import never_as_not
from pantarhei.bridge.reasoning.what_follows import FOLLOWS
from pantarhei.bridge.reasoning.vessels import destinations, filled, in_the_source, liquids, out_of_the_source
from pantarhei.theory.lexicon import load_vocabulary

#: Words that ask: an auxiliary before its subject ("will it spill"), or a
#: quantifier that needs none ("anything come out", "how much spills").
_MODALS = r"will|would|does|do|did|could|can|might|may|should|shall"
_AUX = rf"{_MODALS}|is|are|was|were"
#: Where a clause starts: before "is" in "if the jug is heavy and tipped", how the source is held.
_CLAUSE = re.compile(r"[,;:.!?]|\b(?:if|when|while|and|but|so|or|then|what|whether)\b")
_WHOLE = {*"nothing none no every each drop drops droplet droplets bit single last whole shot lot some any most much half".split()}
#: How little of the liquid a goal excludes: "without a single drop spilling", "any droplets".
_DROPS = r"(?:drop|droplet|bit|speck|trace|splash)s? "   # a goal's how much: not the scene's
#: The words that may follow an outcome's verb and are heard with it ("drip on the
#: table", "spill out of the cup", "go into the bowl"): the scene's words stay the scene's.
_REST = ("each other|one another|at all times|all the time|the whole time|at any point|at any time|throughout|on|onto|over|out|of|in(?! one go\\b)|into|inside|outside|the|a|an|table|tablecloth|floor|counter|countertop|worktop|bench|stove|tray|top|"
         # on the one pouring: "splash onto my shirt"
         "(?:my|your|our) (?:shirt|shirts|clothes|apron|sleeves?|hands?|arms?|feet|shoes|face|lap|legs?)|"
         "ground|place|everywhere|anywhere|at|all|any|anything|it|its|liquid|water|bowl|cup|glass|"
         "destination|source|target|container|rim|edge|sides?|middle|centre|center|drop|drops|much|too|even|ever|really|very|"
         "up|down|off|away|again|then|across|along|around|against|between|"
         # said to happen ("how much spillage occurs")
         "occurs?|happens?|takes place|results|"
         # how much it happens ("does it shift a little"): the outcome's, not an amount of liquid
         "little|bit|lot|slightly|tiny|millimetre|millimeter|hair|smidge|inch|as much(?! as)|as bad(?:ly)?(?! as)|"
         # or more or less of it, against the ordinary pour ("does it spill more if tilted?")
         "more(?! than)|less(?! than)|better(?! than)|worse(?! than)|"
         # or as it did with the ordinary pour ("does it still go into the bowl the same")
         "same(?! (?:way|angle|tilt|height|as)\\b)")
#: How much of the liquid an outcome is asked of ("does most of it spill"), or its odds ("is
#: the risk of spilling high"): the outcome's words, not the scene's ("some of it" is no
#: some_liquid).
_PART_OF = re.compile(r"\b(?:most|all|any|some|much|half|none|part|a lot|a bit|a little|little|"
                      r"the rest|each|the last (?:bit|drops?|few drops|little bit)) of\b|\b(?:the |a )?(?:chance|chances|probability|likelihood|"
                      r"odds|risk)(?: of| that)?\b")
#: Quantifiers that begin the subject of an outcome asked ("does much stay in", "will some
#: spill"): the outcome's words, not an amount of liquid in the scene.
_QUANTIFIERS = {*"much most some any all little none nothing no half lots plenty less more every each last drop drops".split()}
#: Once the pour is done, said between two outcomes asked: "... once it's poured or ...", "once I stop pouring",
#: "after the pouring stops".
_ONCE = (r"(?: (?:once|after|when) (?:(?:it is |it has been |it has |it )?(?:already )?(?:gone )?(?:poured|done|finished|in)"
         r"|(?:i|we|you) (?:stop|finish|am done|are done)(?: pouring| tipping| tilting|(?! (?:pouring|tipping|tilting)\b))"
         r"|the pour(?:ing)?(?: (?:stops|ends|is done|is over|is finished))?))?")
#: What joins a second outcome to the one before: "spill or overflow", "go in but then bounce back out".
_JOINED = r"(?:, or|, and|,|or|and|nor|but then|and then|but|then|instead of|rather than)"
#: A second outcome said as what happens in place of the first: "dribble down the outside instead of going in".
_CONTRARY = re.compile(r"^outcome ?,? (?:instead of|rather than)\b")
#: How much of the liquid, asked: "what fraction of the liquid spills".
_SHARE = r"(?:what|which) (?:fraction|proportion|share|percentage|part|amount)(?: of (?:it|the \w+))?"


#: What happens, asked of the pour and of nothing in it ("what happens if I pour from high?", not "what
#: happens to the bowl"), or the worst of it ("what's the worst that can happen"): every expectation is asked.
_WHAT_HAPPENS = re.compile(r"\bwhat (?:happens|would happen|will happen|is going to happen|is gonna happen|could happen)"
                           r"(?! to\b| with\b)|\bworst (?:that (?:can|could|might|would|will) happen|case)\b")
#: ... or what happens to the liquid ("what happens to the water if I tip the cup upside down"): the liquid's.
_TO_THE_LIQUID = r"\bwhat (?:happens|would happen|will happen|is going to happen) to (?:the |my |all the |all of the )?"
#: Words that say nothing of a pour beside it ("so what happens then?": no pour asked of).
_NOTHING_ELSE = frozenset(("so", "then", "now", "next", "here", "there", "and", "well", "ok", "okay", "if", "i", "we",
                           "you", "it", "this", "that", "what", "hey", "hi"))


@dataclass(frozen=True)
class Heard:
    asked: tuple[str, ...]      # the expectations asked about, in the order said
    goals: tuple[str, ...]      # literals wanted: "no_spill", or "neg(no_spill)"
    phrases: tuple[str, ...]    # the phrases heard, as written (normalised)
    scene: str                  # the text left for the scene
    bowl: bool = False          # whether the bowl is named in what is asked ("... end up in the bowl")
    notes: tuple[str, ...] = ()  # what is said back of what is heard and not asked ("come out slower")


@lru_cache(maxsize=None)
def _patterns() -> tuple[re.Pattern, ...]:
    # "go into the mug", "pour out of the jug"
    end = rf"(?P<rest>(?: (?:{_REST}|{destinations()}|{'|'.join(sorted(poured_from(), key=lambda w: (-len(w), w)))})\b)*)"
    verbs = "|".join(f"(?P<v{k}>{filled(v)})" for k, (v, _, _) in enumerate(OUTCOMES))
    # (not holding another auxiliary: "do you think it will spill" asks "will it spill")
    subject = rf"(?P<subject>(?: (?!(?:if|when|while|not|{_MODALS})\b)(?:[a-z]+|[0-9][0-9.]*)){{0,16}}?)"
    # the odds of an outcome: "what is the chance the bowl tips", "the risk of spilling"
    chance = r"(?P<chance>(?:chance|chances|probability|likelihood|odds|risk)(?: of| that)?)"
    asked = re.compile(
        rf"(?<!that )(?<!which )(?!(?:(?<=\bi )|(?<=\bwe )|(?<=\bhe )|(?<=\bshe )|(?<=\bthey ))did not (?:tip|tilt|turn)\b)\b(?:(?:(?!can\b)|(?<!\bwatering )(?<!\bjerry )(?<!\btin )(?<!\bpaint )(?<!\bthe )(?<!\ba )(?<!\bmy ))(?P<aux>{_AUX})(?P<neg> not)?{subject}|(?P<quant>how much(?: of (?:it|the [a-z]\w*))?(?: [a-z]\w*)?"
        rf"|{_SHARE}|anything|something|everything|nothing|any (?:liquid|water)|it all"
        rf"|(?:all|any|some|none|most|much|half|a lot) of (?:it|them|the [a-z]+)|(?:any|some|much)(?= (?:left|leftover)\b))"
        rf"|{chance}{subject.replace('<subject>', '<csubject>')})"
        rf" (?:(?:all|any|ever|even|still|not) ){{0,2}}(?:(?:end|ends|ended) up )?(?:{verbs})\b{end}"
        rf"(?P<odds> (?:very |really |quite |too )?(?:high|low|big|small|great|likely|unlikely)\b)?"
        rf"(?: or not\b| or (?:it |they )?(?:stay|stays)(?= *[?.!]* *$))?")      # ("is the bowl moving on the table or it stay?")
    # (or said alone: "splashes?", "drip everywhere?")
    nominal = re.compile(r"\b(?:(?:is|will) there (?:be )?)?(?:any|a|no|some) (?:little |small |big |trail of |line of )?(?P<v1>spill(?:s|age)?"
                         r"|splash(?:es)?|mess|drips?|puddles?|(?<=any )(?:spilling|splashing|dripping))\b(?! of\b)|\b(?:any|some) (?:spilled|spilt)(?= *[?.!]* *$)"
                         # the bowl moving, named last: "bowl on a slippery tray, any sliding"
                         r"|\bany (?P<moved>sliding|slipping|wobbling|wobble|movement|moving|shifting|rocking)(?= *[?.!]* *$)"
                         # "all go in the bowl or some outside?": landing outside, a spill
                         r"|(?<=\bor )(?:(?:some|any)(?: of it)? )?(?:outside|on the (?:table|counter|floor))(?= *[?.!]* *$)"
                         r"|\b(?:more|less)(?: or (?:more|less))? (?:spill(?:s|age|ing)?|splash(?:es|ing)?|mess)(?: or (?:more|less))?"
                         r"(?= *[?.!]* *$)"
                         r"|(?:^|(?<=[,:;.?!\u2013\u2014] )|(?<= - )|(?<=[,:;\u2013\u2014]))"
                         r"(?:(?:spill(?:s|age)?|splash(?:es)?)(?: (?:everywhere|over))?|(?:drips?|leaks?)(?: (?:everywhere|out|over))?)"
                         r"(?= *[?.!]* *$)"
                         # named as a measure: "the spill outcome", "what is the spillage rate"
                         r"|(?:^|(?<=[,:;.?!] ))(?:a |any )?mess(?: (?:on|onto|all over) (?:the )?"   # "mess on the table?"
                         r"(?:table|counter|floor|worktop|bench))?(?= *[?.!]* *$)"
                         r"|\b(?:the |any |a )?(?:spill(?:s|age)?|splash(?:es|ing)?|drips?|mess)"
                         r" (?:outcome|result|risk|rate|amount|chance|probability|likelihood)s?\b")
    goal = Cued(       # (goal and more compiled only where they may match: their verbs cost ask's start-up)
        rf"\b(?:without (?:(?:getting|having|causing) (?=any\b|a\b)|(?:letting|allowing) (?=(?:it|them|the [a-z]+|anything|any)\b))?(?P<gneg>(?:(?:so much as |even )?(?:any|a single|one single|a|one) )?{_DROPS}(?:of (?:it|them|the [a-z]+) )?"
        rf"|(?:any|some) (?:of (?:it|them|the [a-z]+) )?|a |making (?:a |any )?)?(?P<gwho>(?:it|them|the [a-z]+|anything) )?(?:ever |even )?"
        rf"(?:getting |being |to )?"
        # a goal said as the state wanted: "pour neatly with nothing dribbling down the outside"
        rf"|with (?P<gwith>nothing|none(?: of it)?|no (?:liquid|water|drops?|droplets?)) (?:ever |even )?"
        # the most that can be done before an outcome: "the fastest I can tip it before it starts splashing"
        rf"|before (?P<gbef>(?:it|they|the [a-z]+|anything|any of it) )(?:ever |even )?(?:starts?|begins?) (?:to )?"
        # (not "so does it slide": "so" starting a question, as "then")
        rf"|so(?! (?:does|do|did|will|would|is|are|was|were|can|could|should)\b)(?: that| as)?(?P<gsub>(?: (?!not\b|without\b)"
        rf"[a-z]+){{0,5}}?)(?P<gnot> not| never)? (?:(?:to|will|does|do|would|can|could|all|"
        rf"any) )?)(?:{verbs})\b{end}", None)
    # what is asked, or wanted, next to it: "will it spill or overflow?", "without spilling or
    # tipping the bowl over"
    # ("does it stay in there once it's poured or slosh back out": after the pour, when it is judged)
    more = Cued(rf"\boutcome{_ONCE} ?{_JOINED}? ?(?:(?:will|does|do|would|even|just|only|mostly|mainly|largely|partly|never|not|all|eventually|finally|later|then|kinda|sorta) ){{0,2}}(?:kind of |sort of )?(?:it |the (?:whole |entire )?\w+ |some |any |much )?"
                rf"(?:{verbs})\b{end}", ("outcome",))
    # an outcome said first, with no word that asks: "spills when poured from high?", "sloshing
    # over the rim if tilted steeply?", "pour high, spill or not", "spill or no?"; or ending a note
    # after the pour or the rim it is near ("oil into bowl high pour splash", "jug near the rim spill")
    bare = re.compile(rf"(?:^|(?<=[,:;.?!\u2013\u2014] )|(?<= - )|(?<=[,:;\u2013\u2014])|(?<=\bpour )|(?<=\brim )|(?=[a-z]+ or (?:not|no) *[?.!]* *$))(?:(?P<v0>{filled(OUTCOMES[0][0])})|(?P<v1>spill\w*|spilt|splash\w*|drip\w*"
                      rf"|leak\w*|slosh\w*|dribbl\w*)){end}(?: or not| or no)?(?: expected| likely)?(?= (?:if|when|while)\b| *[?.!,]* *$)")
    return asked, nominal, goal, more, bare


def _which(m: re.Match) -> tuple[tuple[str, ...], bool]:
    k = next(k for k in range(len(OUTCOMES)) if m.groupdict().get(f"v{k}"))
    # (dripping over the edge runs down the outside, as "drip down the side": a spill, not thrown out of the bowl)
    if k == 0 and (out_of_the_source(m.string, m.end("v0")) or re.match(r"(?:drip|dribbl)\w* over\b", m.group("v0"))):
        return OUTCOMES[1][1], OUTCOMES[1][2]
    clung = re.match(r" (?:(?:in|inside|to|on|onto) )?(?:the |a |an |its |my |your )?(?:[a-z]+ (?!(?:after|before|when|if|as|and"
                     r"|or|but|while)\b))?(?!(?:the|a|an|in|to|after|before|when|if)\b)([a-z]+)", m.string[m.end(f"v{k}"):])
    if OUTCOMES[k][1] == ("liquid_leaves_source",) and OUTCOMES[k][2] and clung and re.search(
            rf"\binto (?:the |a |an |my )?(?:\w+ )?{clung.group(1)}\b", m.string):
        return (*_ALL_IN, "liquid_remains_in_destination"), False      # clinging to the bowl poured into
    bowl = m.group(f"v{k}").split()[-1]        # "yogurt from a tub ... stick in the tub": the tub poured from
    from_it = re.fullmatch(destinations(), bowl) and re.search(rf"\b(?:from|out of) (?:the |a |an |my )?(?:\w+ )?{bowl}\b", m.string)
    if OUTCOMES[k][1] == (*_ALL_IN, "liquid_remains_in_destination") and (
            in_the_source(m.group(f"v{k}"), m.string) or from_it or _sits(m, k)):
        return ("liquid_leaves_source",), True       # staying in the source: not leaving it
    return OUTCOMES[k][1], OUTCOMES[k][2]


#: Words that start a clause, not a container named after "stay inside".
_CLAUSE_WORDS = frozenset(("if", "when", "while", "and", "or", "but", "after", "before", "as", "once", "so", "because", "then"))


def _sits(m: re.Match, k: int) -> bool:
    """Whether liquid said to stay in a container not the bowl stays where it was: "just" sitting
    there ("does the stuff just stay in the cup"), never coming out ("sits in the mug and never
    comes out"), in the one said tilted ("if it's tilted a little, does anything stay in the cup"),
    or the amount kept ("how much stays in the pot"), of a container not poured into nor from."""
    said = re.match(r"\w+ in(?:side)?(?: (?:the |a |an |my |your |this |that )?([a-z]+)(?: (?!(?:if|when|while|and|or|but|after"
                    r"|before|as|once|so|because|then|until|for)\b)([a-z]+))?)?", m.string[m.start(f"v{k}"):])
    bowl = (said.group(2) if said.group(1) not in ("bowl", "bowls") else None) or said.group(1) if said else None
    if bowl in ("bowl", "bowls", "destination", "target") or (bowl and re.search(
            rf"\b(?:into|to) (?:the |a |an |my )?(?:\w+ )?{bowl}\b", m.string)):
        return False
    if (bowl is None or bowl in _CLAUSE_WORDS) and re.search(r"\b(?:tilt|tip)\w* (?:the|my|a|your) (?!bowl\b)[a-z]+", m.string) \
            and not re.search(r"\b(?:bowls?|destination|into)\b", m.string):
        return True       # "if I don't tilt the bottle past horizontal, will some stay inside?": inside the one tilted
    before = m.string[:m.start(f"v{k}")]         # ("go in and just stay there": the bowl's)
    tilted = re.search(r"\bit (?:is |gets )?(?:\w+ ){0,3}?(?:tilted|tipped|turned|upside)\b", before)
    if tilted and bowl and not re.search(r"\b(?:into|from)\b", m.string) and not re.search(r"\boutcome (?:and |then |but )+$", before):
        return True       # (not "go in and stay in the cup": the bowl's)
    return (before.endswith("just ") and not re.search(r"\b(?:and|then|but|or) just $", before)) or re.match(
        r"(?: \w+){0,4}? and (?:never|not|does not|do not|will not|would not) (?:come|comes|pour|pours|get|gets|flow|flows) out\b",
        m.string[m.end(f"v{k}"):]) is not None or bool(bowl and re.search(   # "how much soup is staying in the pot"
            r"\bhow much (?:of (?:the |it )?)?(?:[a-z]+ )?(?:is |will |would |does |do |did )?$", before))


def _state(m: re.Match) -> bool:
    """Whether an asked clause says how full the source is, or how it is
    held, not what happens: "the jug is almost empty", "if the jug is
    tipped steeply", "will tipping the jug halfway make the bowl tip" (the
    scene's), not "will it empty", "is the bowl tipped over"."""
    verb = next((v for g, v in m.groupdict().items() if g[0] == "v" and v), "")
    state, bare = m.group("aux") in ("is", "are", "was", "were"), not (m.group("subject") or "").strip()
    doing = bare and m.group("aux") in _MODALS.split("|") and bool(re.match(
        r"tipping (?:it|them|the|a|an|my|your|this|that)\b", m.string[m.start() + len(m.group("aux")) + 1:]))
    return doing or state and (verb.startswith("empt") or (verb in ("tipped", "tilted") and bare))


def hear(text: str) -> Heard:
    """The expectations `text` asks about and the goals it says (see the
    module's docstring)."""
    asked: list[str] = []
    goals: list[str] = []
    phrases: list[str] = []
    negations: list[bool] = []          # whether each goal said was negated ("without ...")
    pattern, nominal, goal, more, bare = _patterns()
    # words joined by a hyphen, and an aside in brackets, are words of the clause they stand
    # in ("does a high-restitution (bouncy) liquid splash?"), as the scene reads them
    text = re.sub(r"[()\[\]]", " ", re.sub(r"(?<=[a-z])-(?=[a-z])", " ", text))
    last: list[str] = []                # the subject of the outcome asked before
    clauses: list[tuple[str, ...]] = []  # what each clause asked, in order
    bowl: list[str] = []                # per outcome asked: whether it names the bowl, or is asked of a container

    def take(m: re.Match, keep: str = "") -> str:
        phrases.append(m.group(0).strip())
        return f" {keep} outcome " if keep else " outcome "

    def as_goal(m: re.Match) -> str:
        subject = (m.group("gsub") or m.group("gwho") or m.group("gbef") or m.group("gwith") or "").split()
        names, bad = _which(m)
        verb = next(v for g, v in m.groupdict().items() if g[0] == "v" and v)
        names = staying(names, verb, subject)
        last[:] = subject
        if acts(subject, names, m):
            return m.group(0)
        negated = (m.group(0).startswith(("without", "before")) or bool(m.group("gnot"))
                   or any(w in ("nothing", "none", "no", "never") for w in subject))
        holds = (not bad) != negated
        if names == ("liquid_leaves_source",) and not holds and re.match(r"(?:go|goes|going|get|gets) out\b(?! of)", verb):
            names, holds = ("liquid_remains_in_destination", "no_spill"), True     # wanted not to go out: of the bowl
        negations.append(negated)
        goals.extend(n if holds else f"neg({n})" for n in names if n not in
                     {g.removeprefix("neg(").rstrip(")") for g in goals})
        # "so nothing spills": its "nothing" is the goal's, not the scene's
        return take(m, " ".join(w for w in subject if w not in _WHOLE))

    def as_asked(m: re.Match) -> str:
        subject = likely((m.group("subject") or m.group("csubject") or "").split())[0]   # "be less likely to"
        names = staying(_which(m)[0], next(v for g, v in m.groupdict().items() if g[0] == "v" and v), subject,
                         "liquid_leaves_source" in asked)
        last[:] = subject
        # "the table is wobbly": the subject before its verb, not the scene's
        before = m.string[:m.start()].split()[-3:] if not subject else []
        # "don't tip it out": an imperative, not a question
        imperative = bool(m.group("neg")) and not subject and m.group("aux") == "do" and not re.search(
            r"\b(?:bowl|it|they|[a-z]+s)\s*$", _CLAUSE.split(m.string[:m.start()])[-1])    # ("the bowls do not tip": said)
        lead = _CLAUSE.split(m.string[:m.start()])[-1].split() if m.group("aux") in ("is", "are", "was", "were") else []
        tipped = names == ("destination_upright",) and containers().spans(lead) and not {"bowl", "destination"} & {*lead}
        manner = re.search(r"\bby (?:just |simply |only )?$", m.string[:next(m.start(g) for g, v in m.groupdict().items()
                                                                      if g[0] == "v" and v)])    # "doable by just tipping it"
        if acts(lead + subject, names, m) or around().spans(before) or _state(m) or imperative or tipped or manner:
            return m.group(0)
        if lead and not subject and re.search(rf"\bif {re.escape(' '.join(lead))} *$", m.string[:m.start()]):
            raise UserError(f'"if {" ".join(lead)} {m.group(0).strip()}" {FOLLOWS}')    # "if the bowl is moving"
        # "if the cup is bouncy and it hits the bowl, what happens": the copula is the scene's, the
        # outcome a clause of its own after "and", supposed with it as a condition of what is
        # asked: what follows an outcome ("what if the bowl is light and the jug hits it" asks it)
        if lead and re.search(r"\b(?:and|n|but)\b", " ".join(subject)) and re.search(
                rf"(?<!\bwhat )\b(?:if|when|once) {re.escape(' '.join(lead))} *$", m.string[:m.start()]):
            raise UserError(f'"{" ".join(lead)} {m.group(0).strip()}" {FOLLOWS}')
        asked.extend(n for n in names if n not in asked)
        clauses.append(names)
        # "does much stay in the jug", "will some milk spill": how much of the liquid the
        # outcome is asked of, not how much the source holds
        while subject and subject[0] in _QUANTIFIERS | {"there", "be", "gonna", "going", "to", "still"}:     # ("is there gonna be some left")
            subject = subject[1:]
        kept = " ".join(striker(subject, names, m, m.group("aux") in _MODALS.split("|"))) if m.group("aux") or m.group("chance") else ""
        # "is the chance of spilling high": the odds, heard; "does it splash high": the scene's
        odds = m.group("odds") or ""
        said_odds = bool(m.group("chance") or _PART_OF.search(kept))
        # the bowl named in what is asked ("how much ends up in the bowl") is still the bowl poured
        # into: another container named beside it is poured from ("with a slippery cup")
        # (not where a container is what the outcome is asked of: "does a light cup slide")
        bowl.append("of a container" if containers().spans(subject) else
                    "named" if re.search(r"\b(?:bowl|destination)\b", m.group("rest") or "") else "")
        return take(m, _PART_OF.sub("", kept)) + ("" if said_odds else odds)

    def as_nominal(m: re.Match) -> str:
        asked.extend(n for n in (STILL if m.group("moved") else ("no_spill",)) if n not in asked)
        return take(m)

    def as_contact(m: re.Match) -> str:
        asked.extend(n for n in ("source_clear",) if n not in asked)
        return take(m)

    def as_more(m: re.Match) -> str:
        names, bad = _which(m)
        said = re.sub(rf"^outcome{_ONCE} ?{_JOINED}? ?(?:(?:will|does|do|would|even) )?", "", m.group(0))
        own = re.match(r"(?:it|the \w+) ", said)
        names = staying(names, said[own.end():] if own else said, own.group(0).split() if own else last,
                         not was_goal and "liquid_leaves_source" in asked)
        if was_goal:                  # wanted as the one before it: "without spilling or tipping"
            # ("so that it goes in instead of spilling": not as the one before; "and never tips": negated)
            negated = negations[-1] != bool(_CONTRARY.match(m.group(0))) or re.search(
                rf"^outcome{_ONCE} ?{_JOINED}? ?(?:never|not) ", m.group(0)) is not None
            holds = (not bad) != negated
            goals.extend(n if holds else f"neg({n})" for n in names if n not in goals)
        else:
            asked.extend(n for n in names if n not in asked)
        clauses.append(names)
        return take(m)

    was_goal = True
    said = text
    text, never = never_as_not(text)
    text, wants = wanting(text)
    phrases.extend((*never, *wants))
    text, framed = asked_plainly(text)
    text, rate, rate_notes = rates(text)     # "will it come out slower": no expectation's (flow_rates.py)
    text, without = without_asked(text)      # "will it go in without any spilling": both asked
    phrases.extend((*framed, *rate, *without))
    text = _spaced(goal.pattern.sub(as_goal, text) if re.search(r"\b(?:without|with|before|so)\b", text) else text)
    if goals:
        # "so it pours out but the bowl does not tip", "so nothing spills and the bowl stays
        # put", "so it stays in and doesn't slosh out": a clause of its own after "but" or "and"
        # is wanted too, with its own negation
        before = ""
        while before != text:       # (each clause wanted makes the next one's "outcome and")
            before = text
            for m in reversed(list(re.finditer(r"\boutcome (?:but (?:also )?|(?:, ?)?and (?:also )?(?=(?:"
                                               r"the|it|nothing|none|no|everything|all|does not|do not|will not|never)\b))", text))):
                trial = f"{text[:m.start()]}outcome so that {text[m.end():]}"
                wanted_too = _spaced(goal.pattern.sub(as_goal, trial))
                text = wanted_too if wanted_too != trial else text
        text = _repeat(more, as_more, text)
        goals[:] = moving(text, goals)     # "move away without the bowl sliding": as it moves away
        text, seeking = sought(text)        # "how high should I hold it": a plan's to find
        phrases.extend(seeking)
    was_goal = False
    text, elsewhere = instead_of_the_bowl(_spaced(pattern.sub(as_asked, text)))   # "on the floor, not in the bowl"
    text = _repeat(more, as_more, text)
    text = nominal.sub(as_nominal, text)
    text = CONTACT.pattern.sub(as_contact, text) if CONTACT.cued(text) else text
    text = _spaced(bare.sub(as_more, text))
    text, asked, when = during(text, asked)         # "does the bowl slide when the cup comes in"
    text, goals, wanted_when = during(text, goals)
    phrases.extend((*elsewhere, *when, *wanted_when))
    if goals and reaches(said):         # "I want nothing on the counter. Is pouring from 20 cm ok?"
        wanted = [g.removeprefix("neg(").removesuffix(")") for g in goals]
        asked = [n for n in asked if n not in OUTCOMES[-1][1] or n in wanted] + [n for n in wanted if n not in asked]
    asked = worried(said, asked, clauses, OUTCOMES[-1][1])     # "is it ok ... or will the bowl tip over"
    if not asked and not goals and _WHAT_HAPPENS.search(said) and set(re.findall(r"[a-z]+", _WHAT_HAPPENS.sub(
            " ", said))) - _NOTHING_ELSE:                        # "upside down bottle over bowl. what happens"
        asked = [e.name for e in load_vocabulary().expectations]
    elif not asked and not goals and liquid_named(_TO_THE_LIQUID).search(said):
        asked = [e.name for e in load_vocabulary().expectations if e.name.startswith("liquid_") or e.name == "no_spill"]
    refuse_alone(rate, tuple(asked), tuple(goals))
    return Heard(tuple(asked), tuple(goals), tuple(phrases), text,
                 "named" in bowl and "of a container" not in bowl, rate_notes)


def _repeat(pattern: Cued, replace, text: str) -> str:
    """`text` with `pattern` replaced until it no longer matches (each
    replacement takes words away, so this ends)."""
    while pattern.cued(text):
        new = _spaced(pattern.pattern.sub(replace, text, count=1))
        if new == text:
            return new
        text = new
    return _spaced(text)


def _spaced(text: str) -> str:
    return re.sub(r" {2,}", " ", text)
