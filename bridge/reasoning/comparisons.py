"""A comparison said against an earlier or the usual pour, part of words.py's
PHRASES (applied before its comparatives, which refuse a comparison with
nothing): each question is read alone, so against the ordinary pour
("slower than the previous pour" is slowly, "not as high as last time"
low, "not tilting as far as before" slightly tilted, "twice as much
water" much liquid, "twice as high as usual" high), said back; and
"more high", "more thick like honey", as learners of English say them,
are the value itself. A comparative said of nothing is read against the
ordinary pour too ("a bouncier bowl", "if I tilt more": upside down, past
its 100 to 140 degrees), and one negated ("without moving the cup closer")
as no change from it. A scene compared with another said as "one" ("stay
put better than a glass one"), or with another liquid ("does syrup spill
less than water"), is the scene said first, the other said back as not
read, as is one said "compared to" ("compared to a full jug, would a
nearly empty one spill less?"). A comparative said of a liquid given with
an example ("a thicker liquid such as custard") is the value it names.
More toward a place ("more at the rim", "more to the side") is no
comparison: the place.
"""
from __future__ import annotations

from pantarhei.bridge.reasoning.outright import AGAINST

#: The words that set another scene against the one asked about, which is not read (the
#: hedges below) and must say nothing the vocabulary cannot (set_against.py): "vs" ...
VERSUS = r"vs|versus"
#: ... and "compared to" and its like.
COMPARED = r"compared (?:to|with)|as opposed to|in comparison (?:to|with)"
#: Degree words before a comparative: "a bit lower".
DEGREE = r"(?:just|only|slightly|barely|a (?:little |tiny )?bit|a little|a tad|somewhat)"
#: Comparatives of the vocabulary's values, said of nothing they are measured from.
COMPARATIVES = ("higher|heavier|lighter|faster|quicker|slower|steeper|stickier|runnier|thicker|"
                 "thinner|bouncier|grippier|slipperier|fuller|emptier")
#: Words after "more" or "less" that make it an amount, not a comparative: "less water".
_VALUED = "liquid|water|of|than|and|often|time|times|likely"
#: An earlier or the usual pour, as a comparison is made to it: "than the previous pour",
#: "than last time", "than usual"; and after "as high as": "last time" ("as before" is a hedge
#: of the everyday list by then).
_BEFORE = (r"than (?:(?:the|my|our|a|that|your) )?(?:(?:previous|last|earlier|first|other|usual|normal|ordinary"
           r"|regular|standard|old) (?:pour|time|one|try|attempt|go|run)|before|usual|normal|last time|previously"
           r"|earlier)\b")
_AS_BEFORE = (r"(?:(?:the|my|our|that) )?(?:(?:previous|last|earlier|first|usual|normal) (?:pour|time|one|try|attempt)"
              r"|last time|before|usual|normal)\b")

COMPARISONS: tuple[tuple, ...] = (
    # more toward a place, said after the middle is refused: the place ("not over the middle, more at the rim";
    # "more to the edge" is nearness.py's)
    ("hedge", (r"re(more):\bmore(?= (?:at|near|over) (?:the|its) (?:side|edge|rim|lip)\b| (?:to|towards?) (?:the|one) side\b)",),
     "ignored: more toward a place is the place"),
    # a comparison with an earlier or the usual pour: each question is read alone, so against
    # the ordinary pour ("slower than the previous pour" is slowly; "not as high as last time" low)
    *((value, (rf"re({comparative}):\b(?:{DEGREE} |much |even |far |a lot )?(?:{comparative}) {_BEFORE}",
               rf"re( as ):\b(?:not|never) (?:(?:held|poured|tilted|moved|brought|tipped|quite|nearly|so|as) )*?as (?:{plain})"
               rf" (?:as {_AS_BEFORE}|hedge\b)") if plain else
       (rf"re({comparative}):\b(?:{DEGREE} |much |even |far |a lot )?(?:{comparative}) {_BEFORE}",),
       AGAINST)
      for comparative, value, plain in (
          ("higher", "high", "low|short"), ("lower", "low", "high"), ("slower", "slowly", "fast|quick|quickly"),
          ("faster|quicker", "fast", "slow|slowly"), ("heavier", "heavy", "light"), ("lighter", "light", "heavy"),
          ("steeper", "steeply tilted", ""), ("stickier|thicker", "sticky", "runny|thin"),
          ("runnier|thinner", "runny", "sticky|thick"))),
    ("slightly tilted", (rf"re( as ):\b(?:not|never) (?:tilt|tip)\w* (?:it |the \w+ )?as (?:far|much)"
                         rf" (?:as {_AS_BEFORE}|hedge\b)",
                         rf"re(less tilted):\bless tilted {_BEFORE}"), AGAINST),
    # twice as much, twice as high (as usual): read against the ordinary pour, its value
    *((value, (rf"re(twice|double|two times|three times):\b(?:twice|double|two times|three times) as (?:{said})"
               rf"(?: as (?:{_AS_BEFORE}))?(?![^,;:.?!]*\bas\b)",), AGAINST)
      for said, value in (("much", "much"), ("high", "high"), ("heavy", "heavy"), ("fast|quick|quickly", "fast"),
                          ("slow|slowly", "slowly"), ("far", "far"), ("thick|sticky", "sticky"))),
    # whether it matters ("less liquid = less spill?? or doesnt matter", "does less water make any difference"):
    # whether the outcome happens
    ("hedge", (r"re(matter):\b(?:or )?(?:(?:does|do|would|will) (?:it |that |this )?)?(?:not )?(?:really )?matters?\b(?: but\b)?",
               r"re(difference):\b(?:make|makes|made|making) (?:any|a|much of a|no) difference\b",
               # "A vs B - what's the difference in how much goes in?": whether it goes in
               r"re(difference):\b(?:what is|whats|what) the difference in\b"),
     "ignored: whether it matters is whether the outcome happens with what is said"),
    # poured the same way, tipped to the same angle (as the scene compared with): the one said
    ("hedge", ("[in] the same way", "same way", "the same angle", "same angle", "the same tilt", "same tilt",
               r"re(same bowl|identical bowl):\b(?:the )?(?:same|identical) bowls?\b"),
     "ignored: each question is read alone, with nothing of the one before"),
    # a scene compared with ("compared to a full jug, would a nearly empty one ...", "... spill less
    # compared with pouring from high up"): not read, up to where its clause ends
    ("hedge", (rf"re(compared|as opposed|in comparison):\b(?:{COMPARED})"
               r" [^,;:.!?]+?(?= [,;:.!?]|$)",),
     "read as nothing: the scene compared with is not read, the answer is for the one said"),
    # a scene set against another with "vs" ("silicone bowl vs enamel bowl", "at 30 cm vs 5 cm"):
    # the other not read, up to where its clause ends
    # (nor past an outcome asked, or the clause that says when: "... be less likely to slide when I
    # pour the water in quickly" is the scene's, said of both)
    ("hedge", (rf"re(vs|versus):\b(?:{VERSUS})\b" r"\.? [^,;:.!?]+?(?= *(?:[,;:.!?]| - )|$| outcome\b| (?:when|while|once|if) (?:i|we|you|the|it)\b"
               r"| (?:it|they) (?:does|do|did)\b)",),     # (nor into a goal's words: "... so it does not go out")
     "read as nothing: the scene compared with is not read, the answer is for the one said first"),
    # not too high (or low): the height next to it toward the middle of the scale, as "neither too
    # high nor too low" is (words.py); not too fast or heavy is already the ordinary pour's
    ("at medium height", (r"re(too):\b(?:not|never|nor) (?:held |poured |hold(?: it| the \w+)? |pour(?: it)? )?(?:too|overly)"
                          r" (?:high|low)\b(?! than\b)",),
     "read as at medium height: the height next to it, toward the middle"),
    # a comparative negated, said of nothing ("without moving the cup closer", "not faster"): no
    # change from the ordinary pour, read as nothing (a value said beside it stands)
    ("hedge", (rf"re(closer|nearer|further|farther|{COMPARATIVES}|more|less):\b(?:not|never|without|no)\b"
               rf"(?: (?!and\b|or\b|but\b)[a-z]+){{0,3}}? (?:any )?(?:closer|nearer|further|farther|{COMPARATIVES}"
               rf"|more|less)\b(?! than\b)(?! (?:{_VALUED})\b)",),
     "read as nothing: no change from the ordinary pour, against which a comparative with nothing is read"),
    # a comparative said of nothing ("a bouncier bowl", "pour a bit lower", "if I tilt more"): against
    # the ordinary pour, as against the usual one, the value that way (not after a number: "2 cm higher")
    *((value, (rf"re({said if cue is None else cue}):(?<!\d )(?<!cm )(?<!mm )(?<!inches )(?<!degrees )\b(?:{DEGREE} |much |even |far |a lot "
               rf"|way )?(?:{said})\b(?!(?: [a-z]+)? than\b)" + after,),
       f"{AGAINST}, with nothing before it")
      for said, value, after, cue in (
          ("higher", "high", "", None), ("lower", "low", r"(?! (?:the|it|them|(?:the|a|an|my) \w+)\b)", None),
          ("slower", "slowly", "", None), ("faster|quicker", "fast", "", None), ("heavier", "heavy", "", None),
          ("lighter", "light", "", None), ("steeper", "steeply tilted", "", None),
          ("stickier|thicker", "sticky", "", None), ("runnier|thinner", "runny", r"(?! (?:into|onto|from|out of)\b)", None),     # (not "pouring thinner into a bucket")
          ("bouncier", "bouncy", "", None), ("grippier", "grippy", "", None), ("slipperier", "slippery", "", None),
          # tilted more than the ordinary pour's 100 to 140 degrees: upside down; less: slightly
          (r"tilt(?:s|ed|ing)? (?:(?:it|the \w+) )?more|tip(?:s|ped|ping)? (?:(?:it|the \w+) )?more|more tilt(?:ed)?",
           "tilted upside down", "", "more"),
          (r"tilt(?:s|ed|ing)? (?:(?:it|the \w+) )?less|less tilt(?:ed)?", "slightly tilted", "", "less"),
          # less liquid than the ordinary pour's 40 to 140 particles: a little; more: very much
          (r"(?:less|fewer) (?:liquid|particles?)", "little liquid", "", "less|fewer"),
          (r"more (?:liquid|particles?)", "very much liquid", "", "more"))),
    # a scene compared with another said as "one" ("stay put better than a glass one", "spill more
    # than a half-full one"): the scene said first is read, the other one is not, said back
    ("hedge", (r"re(than):\b(?:(?:much |a (?:little |lot )?(?:bit )?)?(?:better|more|less|worse) )?than"
               r" (?:a|an|the|that|this) (?:[a-z-]+ ){0,3}?ones?\b",
               # a liquid compared with ("does syrup spill less than water")
               r"re(than):\b(?:much |a (?:little |lot )?(?:bit )?)?(?:more|less|worse) than (?:a |an |the |plain |regular"
               r" |normal |ordinary )?(?:(?:sticky|runny|heavy|light|bouncy) )?liquid\b",
               # ... or as much as it ("does honey splash as much as water": no amount of liquid)
               r"re(as much as):\bas much as (?:pouring |when pouring |with )?(?:a |an |the |plain |regular |normal |ordinary )?"
               r"(?:(?:sticky|runny|heavy|light|bouncy) )?liquid\b"),
     "read as nothing: the scene compared with is not read, the answer is for the one said first"),
    # a comparative said of a liquid with an example of it ("a thicker liquid such as custard"):
    # the value the example has, as it is said
    *((value, (rf"re({said}):\b(?:{said})(?= liquids?(?: ?,)? (?:such as|like|for example|for instance|e g|say|hedge)\b)",),
       "read as the value of the liquid given as its example") for said, value in (
        ("thicker|stickier", "sticky"), ("thinner|runnier", "runny"), ("heavier|denser", "heavy"), ("lighter", "light"))),
    # "more high", "more thick like honey", as learners of English say them: the value itself
    *((value, (rf"re(more ):\bmore (?:{said})\b(?! than\b)",)) for said, value in (
        ("high", "high"), ("low", "low"), ("thick", "sticky"), ("thin", "runny"), ("heavy", "heavy"),
        ("light", "light"), ("fast|quick", "fast"), ("slow", "slowly"), ("sticky", "sticky"), ("runny", "runny"))),
)
