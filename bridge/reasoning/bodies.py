"""Everyday phrases for the bodies of a pour, the liquid and how much of it,
read as the vocabulary's words: part of words.py's PHRASES, applied in
order at their place there ("a lightweight paper bowl" is light, "a
non-stick pan" slippery, "pour a lot" much liquid, "a hand width" 7 to 10
cm, "a quarter turn" 90 degrees).
"""
from __future__ import annotations

BODIES: tuple[tuple, ...] = (
    # the bodies and the liquid
    ("dull", ("[does|do|will] not bounce",)),
    ("full", ("filled", "brimming", "full up")),
    ("much", ("a lot of", "lots of", "plenty of")),
    # an amount said with no liquid after it: "pour a lot", "with a lot in it"
    ("pour much liquid", (r"re:\bpour(?:s|ed|ing)?(?: out)? (?:a lot|lots|loads|plenty|tons|heaps)\b"
                          r"(?! (?:of|more|higher|lower|further|closer)\b)",)),
    ("much liquid", (r"re:\b(?:a lot|lots|loads|plenty)(?= (?:in|inside) (?:it|the \w+)\b)",)),
    ("slowly", (r"re:\b(?:tak(?:e|es|ing)|took) (?:your|its|my|our|their|the|his|her) time\b",)),
    # lengths by hand: a finger's width, a hand's width (a range, read only where one
    # proposition holds all of it; "a few cm" is numerals.py's)
    # (said "up", above: "a hand's width up", as "20 cm up")
    ("1.5 to 2 cm above", ("a finger width up", "a finger breadth up", "one finger width up")),
    ("7 to 10 cm above", ("a hand width up", "a hand breadth up", "a handbreadth up", "a palm width up",
                          "one hand width up")),
    ("1.5 to 2 cm", ("a finger width", "a finger breadth", "a fingerbreadth", "one finger width")),
    ("7 to 10 cm", ("a hand width", "a hand breadth", "a handbreadth", "a palm width",
                    "one hand width")),
    # a turn of the source said in turns: a quarter turn is 90 degrees
    ("90 degrees", (r"re:\b(?:by |through )?(?:a )?quarter(?: of a)?(?: |-)?turn\b",)),
    ("180 degrees", (r"re:\b(?:by |through )?(?:a half|half a)(?: |-)?turn\b",)),

    ("little", ("a few drops of", "a few drops", "a drop of", "a drop")),
    # a weight said as a compound: "a lightweight paper bowl", "a hefty jug"; or as next to
    # nothing
    ("is light", (r"re:\bweigh(?:s|ed|ing)? (?:(?:hedge|basically|pretty much|like|just) )?(?:(?:next to|almost|practically"
                  r"|virtually|hardly|barely) (?:nothing|anything)|nothing)\b",)),
    ("is heavy", (r"re:\bweigh(?:s|ed|ing)? (?:a lot|a ton|tons|loads|plenty)\b",)),
    # surfaces that grip or do not: a non-stick pan is slippery, a non-slip bowl grippy
    ("slippery", (r"re:\bnon ?stick\b", "teflon")),
    ("grippy", (r"re:\b(?:non|anti) ?(?:slip|skid)\b",)),
    ("heavy", (r"re:\bdense\b(?! (?:plastic|glass|wood|metal|ceramic|material))",)),
    ("light", ("lightweight", "light weight", "featherweight", "feather light", "featherlight", "paper light", "light as paper", "light as a feather", "flimsy")),
    ("heavy", ("heavyweight", "heavy weight", "hefty", "weighty", r"re:\bheavy(?: |-)?bottomed\b")),
    ("slippery", ("slick", r"re:\bslippy\b(?! slidey)", "smooth", "greasy")),
    ("halfway", ("partway", "part way", "part of the way")),
    ("grippy", ("rough",)),
    # a thin bowl is a light one, of whatever it is made (thin is said of the liquid otherwise: runny)
    ("light", (r"re:\bthin(?= (?:(?:material|glass) )?(?:(?!(?:into|in|to|onto|the|a|an|of|from|and|or|over|at|on)\b)[a-z]+ )?"
               r"(?:bowls?|dish|dishes|basins?)\b)",)),
    ("runny", ("thin", "watery")),
    ("sticky", ("viscous", "thick", "thickened", "syrupy", "gooey")),
    ("bouncy", ("springy", "elastic")),
)
