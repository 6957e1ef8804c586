"""The verb phrases of outcomes: each with the expectations it speaks of
and whether it happening makes them fail ("spill": no_spill fails; "stay
upright": destination_upright holds). outcomes.py hears them in the
clauses that ask about the outcome or say a goal."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.phases import STILL
from pantarhei.bridge.reasoning.vessels import CONTAINER, OUT_OF, SAFE, filled

ALL_IN = ("liquid_enters_destination",)

#: How much a pour leaves in the source, said of it: "leaves more behind", "leave a film in the jug".
_KEPT = (r"(?:more|less|much|some|any|anything|something|a lot|a bit|nothing|stuff|(?:any |some |a )?residue"
         r"|(?:a|any) (?:film|layer|coat|coating|skin|trace))")

#: Slopping, said in any form ("slops", "slopped", "sloppy"), never a slope ("on a slope", "sloping").
_SLOP = r"slop(?!e|ing\b)\w*"

#: Verbs of liquid thrown about: thrown over the rim or out of the destination, it entered
#: and did not stay ("splash out of the bowl": liquid_remains_in_destination and no_spill).
_THROWN = (rf"spill\w*|spilt|splash\w*|splatter\w*|splat\w*|{_SLOP}|slosh\w*|spray\w*|spurt\w*"
           r"|squirt\w*|escap\w*|spew\w*|gush\w*|leak\w*|drip\w*|dribbl\w*|trickl\w*")

#: What a bowl stands on, which it slides, flies or falls off.
_STANDS_ON = r"(?:table|counter|countertop|worktop|bench|tray|shelf|stool|desk|board|cart|placemat|mat)"

#: (verb phrase, the expectations it speaks of, whether it happening makes them fail)
OUTCOMES: tuple[tuple[str, tuple[str, ...], bool], ...] = (
    (rf"(?:{_THROWN}) (?:(?:back|right|straight|all|up|and) )*(?:over|past|out of|out over|from)(?= (?:the |a |an |my "
     rf"|your |its |their |this |that )?(?!source\b)(?:[a-z]+ )?{OUT_OF}\b)"
     rf"|escap\w*(?= (?:the |a |an |my |your |its )?(?!source\b)(?:[a-z]+ )?{OUT_OF}\b)"
     # leaving the bowl poured into: not staying in it ("will any liquid leave the bowl")
     r"|leav(?:e|es|ing)(?= the (?:bowl|dish|basin|destination)\b)"
     # gone out of the bowl it went into: "for the oil not going out of the bowl"
     r"|(?:go|goes|going|went|get|gets|getting|got) out of(?= (?:the |a |an |my )?(?:[a-z]+ )?(?:bowl|destination)\b)"
     # thrown out, no bowl said: out of the destination, as people who pour read it ("splash out")
     rf"|(?:splash\w*|splatter\w*|slosh\w*|{_SLOP})(?: back)?(?: up(?: and)?)? out\b(?! of\b| over\b)"
     # (spilled out onto the table: where it lands, a spill; splashed out onto it was thrown out of the bowl)
     r"|(?:spill\w*|spilt)(?: back)? out\b(?! of\b| over\b| (?:on|onto|all over) (?:the |a |my )?"
     r"(?:table|counter|countertop|worktop|floor|bench|tablecloth|ground)\b)"
     # thrown outside it: "splash outside the bowl", "make splash outside" (landing or dripping outside is a spill)
     rf"|(?:makes? (?:a |any |big |much )*)?(?:splash\w*|splatter\w*|slosh\w*|{_SLOP}) outside\b"
     # thrown back up out of the bowl: "splash back", "splash-back expected?"
     r"|(?:splash|splatter)(?:es|ed|ing)? ?back\b(?! (?:in|into|out)\b| up\b(?! (?:at|toward|towards|onto|on)\b))|splashbacks?\b"
     # (not foaming or boiling over: the vocabulary's liquid does neither, everyday.txt refuses it)
     rf"|overflow\w*|(?:run|runs|running|ran|spill\w*|slosh\w*|{_SLOP}|splash\w*|splatter\w*) over"
     r"(?: the (?:rim|edge|top|side)s?)?"
     r"|(?:(?:come|comes|came|coming|go|goes|went|going) )?(?:bounc|jump|leap|hop|climb|fly|flies|flew|flying)\w* (?:right |straight )?(?:back )?(?:up )?(?:and )?(?:over|out(?: of)?)|flood\w*"
     r"|(?:go|goes|going|went|get|gets|come|comes|came) (?:right |straight )?over(?= the (?:far |near |other |opposite |back |front )?"
     r"(?:rim|edge|top|side|brim|lip)s?\b)", ("liquid_remains_in_destination", "no_spill"), True),
    # (sloshing around in the bowl is no spill: everyday.txt says it back)
    # along the source itself, said first for the plain verbs to leave it whole: "drip back down along the spout", "run down the jug"
    (r"(?:run|runs|running|ran|drip\w*|dribbl\w*|trickl\w*|creep\w*) (?:back )?(?:down |under )?(?:along )?(?:the |its )?"
     r"(?:underside of (?:the |its )?)?(?:(?:jug|jar|bottle|pitcher|carton|kettle) )?"
     r"(?:spout|neck|lip|jug|jar|bottle|pitcher|carton|kettle)\b(?! (?:in|into)\b)"
     r"|spill\w*|spilt|splash\w*|splatter\w*|spatter\w*|spray(?:s|ed|ing)?|spurt\w*|slosh\w*(?! (?:around|about)\b)|drip\w*|dribbl\w*|leak\w*|mess(?:y|es)?"
     r"|(?:makes?|(?<=up )making) (?:(?:a|any) )?(?:big |huge |bit of a |real |total )?mess"
     r"|(?:makes?|making|made) (?:a |any )?(?:big |huge |massive |giant |real |bit of a )splash\b"
     r"|(?:makes?|making|made) (?:the |any |big |many |lots of |a lot of )?(?:splashes|spills|drips)\b|(?:go|goes|going|went|get|gets|getting|got|glug|glugs|glugged|glugging)(?: out)? everywhere"
     r"|(?:fling|flings|flung|flinging|fly|flies|flew|flying|spray|sprays|sprayed|spraying|shoot|shoots|shot|shooting)(?: out)? everywhere"
     r"|(?:get|gets|getting|got) (?:it|them|liquid|(?:the )?[a-z]+) (?:everywhere|all over(?: the place)?)\b"
     # lost over the rim or on the counter: "do I lose any on the counter", "do i lose broth over the rim"
     r"|los(?:e|es|ing|t) (?:any|some|much|a lot|a bit|a drop)(?: of it)?(?= (?:on|onto|over|all over)\b)"
     r"|los(?:e|es|ing|t)(?= [a-z]+ (?:on|onto|over|all over) (?:the |my )?(?:rim|edge|side|table|counter|floor|worktop|bench)\b)"
     rf"|{_SLOP}|splat\w*|(?:end|ends|ended|ending) up (?:on|onto|all over|everywhere|outside)|(?:end|ends|ended|ending) up (?:somewhere )?where (?:it|they) (?:should not|must not|is not supposed to|are not supposed to|was not supposed to)\b|(?:get|gets|got|getting) (?:any|some|much|a drop)(?: of it)?(?= on\b| onto\b)"
     r"|(?:run|runs|running|ran|roll\w*|stream\w*|drip\w*|dribbl\w*|trickl\w*|go|goes|going|went) (?:(?:back|straight|right|just) )?down the (?:outside|side)(?! of (?:the |a )?(?:bowl|dish|destination))"
     # what is left behind outside: "does it leave a trail of drips", "leaving a sticky ring on the counter"
     r"|leav(?:e|es|ing) (?:a |any )?(?:sticky |little |wet |big )?(?:trail|line|ring|puddle)s?\b"
     # where drips went: "a trail of drips went right across the table"
     r"|(?:go|goes|going|went) (?:right |straight )?across (?:the )?(?:table|counter|countertop|worktop|bench|floor)\b"
     # out, then where it lands: "or go out to the table", "went out onto the counter"
     r"|(?:go|goes|going|went|come|comes|coming|came) out (?:to|on|onto|over) (?:the |my )?(?:table|counter|countertop|worktop|bench|floor|stove|tablecloth)\b"
     # the place under it wet: "will my counter get wet"
     r"|(?:table|counter|countertop|floor|worktop|bench|tablecloth) (?:get|gets|got|getting|be|become|becomes) (?:all )?wet\b"
     # finding its way onto the tablecloth, dropping on the table
     r"|(?:find|finds|found|make|makes|made) (?:its|their) way (?:onto|on to|on) "
     r"|(?:is |are )?drop(?:s|ped|ping)? (?:on|onto) (?:the )?(?:table|floor|counter|countertop|worktop|bench|tablecloth)\b"
     # the liquid touching what is under it: "without any of it touching the table"
     r"|(?:touch\w*|reach\w*) (?:the )?(?:table|floor|counter|countertop|worktop|bench|tablecloth|tray)\b"
     r"|hit\w* (?:the )?(?:table|floor|counter|countertop|worktop|bench|bar mat|bar top|bar|mat|tray|stove|tablecloth|ground)\b|(?:go|goes|going|went|get|gets|got|land|lands|landed|landing|fall|falls|fell) (?:on(?!(?:to)? (?:its|their) sides?\b)|onto(?! (?:its|their) sides?\b)|all over"
     r"|outside)",
     ("no_spill",), True),
    # down the outside of the bowl, not into it: "it all ran down the outside of the bowl instead of in"
    (r"(?:run|runs|running|ran|drip\w*|dribbl\w*|trickl\w*|go|goes|going|went) (?:(?:back|straight|right|just) )?down the (?:outside|sides?)"
     r" of (?:the |a |my )?(?:bowl|dish|destination)\b", (*ALL_IN, "no_spill"), True),
    # in, and none of it outside: "will it glob on the rim or go in clean", "does it stay clean"
    (r"(?:go|goes|going|went|get|gets|land|lands) (?:in|into)(?: the \w+)? clean(?:ly)?\b", (*ALL_IN, "no_spill"), False),
    (r"(?:stay|stays|staying|stayed|keep|keeps|remain|remains) (?:nice and )?clean\b", ("no_spill",), False),
    (r"(?:stay|stays|remain|remains|keep|keeps) (?:upright|standing|up(?= *(?:[?.!,;]|$| (?:if|when|while|or|and)\b)))"
     r"|be (?:still )?(?:upright|standing)\b",       # "will the bowl still be upright" (of the source, held so: acting.py)
     ("destination_upright",), False),
    # tipped or fallen off what it stands on: moved, and fallen ("the bowl just flipped off the counter")
    (r"(?:flip(?:s|ped|ping)?|tip(?:s|ped|ping)?(?: over)?|toppl\w*|tumbl\w*|fall|falls|falling|fell) off"
     rf"(?= (?:the |my |our )?{_STANDS_ON}\b)", (*STILL, "destination_upright"), True),
    (r"tip(?:s|ped|ping)?(?: over)?(?! (?:(?:it|them|the \w+) )?(?:(?:past|beyond)\b|(?:to|by|at|up to|no more than|more than"
     r"|less than|at most|at least|under|about) -?\d))"
     # (not the source tipped by whoever pours: "without tipping the pitcher much")
     r"(?! (?:the|my|a|this|that) (?:jug|pitcher|bottle|cup|carton|kettle|jar|mug|can|teapot|flask|beaker|source)\b)|toppl\w*|(?:fall|falls|falling|fell) (?:over|down)|(?:knock|push|shov)\w*(?: it| the \w+)? over"
     r"|turn\w* over|flip\w*|capsiz\w*|overturn\w*|keel\w* over|tumbl(?:e|es|ed|ing)\b"
     # gone over, nothing after it: "the bowl went over" (not "went over the rim": out of the bowl)
     r"|(?:go|goes|went|gone) over(?= *[,.;!?]| *$| (?:and|when|if|as|while|because)\b"
     r"| on (?:the |my |our )?(?:table|counter|countertop|worktop|bench|floor|tray)\b)"   # ("went over on the counter")
     r"|(?:fall|falls|fell)\b(?! (?:in|into|inside|out|off|on|onto)\b)"
     # on its side: "does the bowl end up going over on its side"
     r"|(?:(?:go|goes|going|went|gone|fall|falls|falling|fell|tip\w*|roll\w*) (?:over )?)?on(?:to)? (?:its|their) sides?\b"
     # upside down at the end, said of the bowl: "will the bowl end up upside down" (the source's end pose otherwise)
     r"|(?:(?<=bowl )|(?<=bowls )|(?<=dish )|(?<=basin ))(?:end|ends|ended|ending) up (?:upside down|flipped|overturned)\b",
     ("destination_upright",), True),
    (r"(?:stay|stays|remain|remains|keep|keeps|be|is|hold|holds) (?:(?:completely|totally|perfectly|absolutely|entirely|fully|really|dead"
     r"|quite|nice and|nicely) )?(?:still|put|in place|steady|stable|stationary"
     r"|(?:exactly |right )?where (?:it|they) (?:is|was|are|were|stands|stood|started)"
     r"|(?:exactly |right )?where (?:i|you|we|they) (?:put|placed|set|left) (?:it|them))"
     r"|(?:sit|sits|sitting|stand|stands|standing|stay|stays|staying|remain|remains|rest|rests|resting|be)"
     r" (?:still )?(?:in|at) the same (?:spot|place|position|location)", STILL, False),
    # sent off what it stands on: moved, and fallen ("the bowl went flying off the counter")
    (rf"(?:go|goes|going|went|gone|sent) flying off(?= (?:the |my |our )?{_STANDS_ON}\b)",
     (*STILL, "destination_upright"), True),
    # flown or walked off what it stands on, said of the bowl: moved ("will the bowl fly off the table", "or does it walk off")
    (rf"(?:fly|flies|flew|flying) off(?= (?:the |my |our )?{_STANDS_ON}\b)"
     r"|(?:(?<=bowl )|(?<=it ))(?:walk|walks|walked|walking) off(?= *(?:[?.!,;]|$))", STILL, True),
    # the way it moves said after it is the moving's ("the bowl scoots sideways", "slides to one side")
    # somewhere else at the end: "does the bowl end up in a different spot than where it started"
    (r"(?:end|ends|ended|ending) up (?:in|at|on) (?:a )?(?:different|another|new) (?:spot|place|position|location)"
     r"(?: (?:than|from) where (?:it|they) (?:started|was|were|began|stood))?|(?:end|ends|ended) up somewhere else", STILL, True),
    # dancing where it stands, as children say a bowl wobbling: "does the bowl do a little dance"
    (r"(?:do|does|did|doing|done) (?:a |that |this |the )?(?:little |bit of a |small )?(?:wobble |wobbly |jiggle |wiggle |rocking )?dance\b"
     r"|danc(?:e|es|ed|ing)\b(?: (?:a)?round| about)?"
     # "does the bowl do that little wobble thing", "that wobbly spinny thing"; "go for a walk", "zoom away"
     r"|(?:do|does|did|doing|done) (?:a |that |this |the )?(?:little |bit of a |small |weird )?"
     r"(?:(?:wobble|wobbly|jiggle|wiggle|rocking|spinny|shaky|spinning) ){1,2}thing\b"
     # "will the bowl do a little wobble" (no little liquid), "did a wiggle"
     r"|(?:do|does|did|doing|done) (?:a |that |this |the )?(?:little |bit of a |small |weird |tiny )?(?:wobble|jiggle|wiggle|shimmy|spin|skid|hop)\b"
     r"|(?:go|goes|going|went|gone) (?:for a walk|walkabout)\b|zoom(?:s|ed|ing)? (?:away|off|across|around|about)\b", STILL, True),
    # (not the source slipping from a hand: "will it slip out of my hand", a drop the vocabulary does not say)
    (r"(?:slid\w*|slip(?:s|ped|ping)?\b(?! (?:out of|outta|from) (?:my|his|her|their|your|our|the|its|a) (?:\w+ )?(?:hand|hands|grip|grasp|fingers|gripper|gloves?)\b)|shift\w*|budg\w*|wobbl\w*|shimm(?:y|ies|ied|ying)\b|jitter\w*|judder\w*|teeter\w*|trembl\w*|quiver\w*|skid\w*|skat(?:e|es|ed|ing)\b|wiggl\w*|jiggl\w*"
     r"|jostl\w*|walk(?:s|ed|ing)? (?:across|along|around|about)\b|rock(?:s|ed|ing)?|(?:shak(?:e|es|ing)|shook)(?! (?:it|them)\b)|translat\w*|drift\w*|creep\w*|scoot\w*"
     # turning where it stands ("can a bowl spin around"), not a source turned ("spin the bottle")
     r"|(?:spin|spins|spinning|spun|swivel\w*)(?! (?:it|them|the \w+)\b)(?: (?:a)?round| about)?"
     # the bowl pushed by the stream, said with where it goes ("will the stream push them across the table"), or last ("push it?")
     r"|(?:push|shov)(?:es|e|ed|ing)? (?:it|them|the (?:bowl|bowls|destination|dish|container))(?: (?:across|along|around|about|sideways|aside|away)\b| *(?=[?.!,;]|$))"
     # sent flying, itself: "does the bowl go flying" (not "go flying out of the bowl": thrown out)
     r"|(?:go|goes|going|went|gone) flying\b(?! (?:out|off|over)\b)|(?:go|goes|going|went|gone) (?:sliding|skidding|skating|scooting)\b"
     r"|(?:shot|shoot|shoots|shooting) (?:sideways|across|off)\b"
     r"|(?:(?:get|gets|got|getting) )?sent (?:across|flying|sliding|skidding)|displac\w*|(?:(?:get|gets|got|getting|be|being) )?(?:pushed|shoved)\b(?! (?:in|back|away|out|over)\b)|(?:go|goes|going|went|get|gets|getting) (?:wiggly|wobbly|shaky|jiggly|wonky|(?:slippy |slip |slippery )?slidey)"
     r"|mov(?:e|es|ed|ing)\b(?! (?:(?:it|them|the \w+) )?(?:in|away|closer|nearer|further|farther|to|out|back|up"
     r"|down|over|into|off|towards?)\b)|bounc\w* (?:around|about))(?: sideways| (?:off |over )?to (?:the|one) side| back and forth| to and fro)?"
     # and how, likened: "go all wobbly like jelly" (no sticky liquid), "rock like a boat", "wobbled like crazy"
     r"(?: like (?:a |an )?(?:jelly|jello|boat|leaf|crazy|mad))?\b",
     STILL, True),       # "move the cup closer": the source's move
    # the bowl moving away or sideways, said of it ("will the bowl move away?", "the bowl just went
    # sideways"; the source moving away is its retreat)
    (r"(?:(?<=bowl )|(?<=bowls )|(?<=dish )|(?<=basin )|(?<=destination )|(?<=bowl just )|(?<=bowl kind of ))(?:mov(?:e|es|ed|ing)|go|goes|going|went|slid\w*|slip\w*)"
     r" away\b|(?:(?<=bowl )|(?<=bowl just ))(?:go|goes|going|went) sideways\b"
     # jumping where it stands: "the pitcher clinked the rim and the bowl jumped" (not liquid jumping out)
     r"|(?:(?<=bowl )|(?<=bowl just ))(?:jump|jumps|jumped|jumping|hop|hops|hopped|hopping)\b(?! (?:out|over|up|back|off)\b)"
     # or away from who pours ("it can move away from me?")
     r"|(?:mov(?:e|es|ed|ing)|slid\w*|slip\w*|go|goes|going|went) away from (?:me|us|you|him|her|them)\b", STILL, True),
    # struck and moved: "the bowl gets knocked sideways", "it banged into the bowl and knocked it aside", "knocked around",
    # or knocked after the bump told ("the spout bumped the bowl and knocked it")
    (r"(?:(?<=\band )|^)knock(?:s|ed)? (?:it|them)(?= *(?:[,.;!?]|$))", ("source_clear", *STILL), True),
    (r"(?:knock|bump|nudg|bash|bang)\w*(?: it| them| the \w+)? (?:sideways|aside|across|along|out of place)\b", ("source_clear", *STILL), True),
    # knocked about, by whatever knocks it (the stream too): moved
    (r"knock\w*(?: it| them| the \w+)? (?:around|about)\b", STILL, True),
    (r"(?:giv(?:e|es|ing)|gave) (?:a |any |some )?(?:hit|knock|bump|bang|touch)s?(?: to)?(?= (?:the|a|an|my|its|it)\b)"   # "giving a hit to the bowl"
     r"|bump\w*|hit(?:s|ting)?|touch\w*|collid\w*|crash\w*|knock\w*|clip(?:s|ped)?|strike\w*"
     r"|bonk\w*|bang\w*|intersect\w*|clash\w*|graz(?:e|es|ed|ing)|scrap(?:e|es|ed|ing)|nudg\w*|clink\w*|clang\w*|clonk\w*|clunk\w*|clank\w*|slam\w*(?! *(?:[,.;!?]|$|tonight\b))"
     r"|smash\w*|whack\w*|smack\w*|(?:run|runs|ran|running) into|(?:come|comes|came) into contact|(?:make|makes|made|making) contact with|bounc\w* (?:off|against)"
     r"|make contact|makes contact|(?:any|some) contact|contact (?:occur|occurs|happen|happens)"
     r"|(?<=there )(?:any |some )?contact|(?<=there be )(?:any |some )?contact",   # "is there contact"
     ("source_clear",), True),
    (r"(?:stay|stays|keep|keeps|be|is)? ?clear(?: of)?", ("source_clear",), False),
    # emptied into the bowl: it leaves the source and goes in ("does the carton empty into the bowl")
    (r"(?:empt(?:y|ies|ied)|drain(?:s|ed|ing)?)(?: out)?(?= into\b)"
     # so is coming out into it: "will anything even come out into the bowl"
     r"|(?:come|comes|coming|came) out(?= (?:in|into) (?:the |a |my )?(?:[a-z]+ )?(?:bowl|destination)\b)",
     ("liquid_leaves_source", *ALL_IN), False),
    (r"(?:come|comes|coming|came|get|gets|pour|pours|flow|flows|run|runs|drain\w*|make it|makes it|made it) out"
     # the liquid pouring, said of it ("does anything pour at that angle"), not of who pours
     r"|(?:(?<=anything )|(?<=something )|(?<=nothing )|(?<=any liquid )|(?<=any water ))pour(?:s|ed)?\b(?! (?:it|them|the|from|into|in)\b)"
     r"|(?:go|goes|going|went) out\b(?! of (?:the |a |an |my )?(?!source\b)(?:[a-z]+ )?(?:bowl|destination)\b)"
     r"|glug(?:s|ged|ging)? out\b"          # "it glugged out" (not "so it doesn't glug": how it flows)
     r"|glugged(?= *(?:[,.;!?]|$))"          # told: "the milk glugged, and ..." (it came out)
     # (not how full the source is: "a nearly empty jug", "an empty cup")
     r"|(?<!nearly )(?<!almost )(?<!mostly )(?<!practically )(?<!all but )(?<!half )(?<!\ban )(?<!\ba )(?<!\bthe )"
     r"empt(?:y|ies|ied)(?: out)?|(?:(?:end|ends) up|becomes?|gets?) (?:totally |completely |fully )?empty(?: (?:completely|fully|totally))?|leav(?:e|es|ing) (?:the|it)\b(?! (?:bowl|dish|basin|destination)\b)|exit\w*", ("liquid_leaves_source",), False),
    # sitting at the source's lip: kept in it ("or does it just sit at the lip")
    (r"(?:sit|sits|sitting|sat|hang|hangs|hanging|hung) (?:at|on|in) (?:the|its) (?:lip|spout|mouth|neck)\b",
     ("liquid_leaves_source",), True),
    # stayed inside, no bowl said: kept in the source ("a bit of the oil stayed inside", "it just sat in the jar")
    (r"(?:stayed|remained|stuck|(?:just )?sat) (?:inside|behind|in (?:the|my|a|its) (?!(?:[a-z]+ )?(?:bowl|destination)s?\b)(?:[a-z]+ )?[a-z]+)\b"
     r"(?! (?:the |a |an |my )?(?:[a-z]+ )?(?:bowl|destination)s?\b)",
     ("liquid_leaves_source",), True),
    # left inside, no bowl said: kept in the source ("there was still a bit left inside at the end")
    (r"left (?:over |stuck |clinging |sitting )?inside\b(?! (?:the |a |an |my )?(?:[a-z]+ )?(?:bowl|destination)s?\b)"
     # at the bottom of a container not the bowl: "a little puddle left at the bottom of the jug"
     r"|left (?:over |stuck |sitting )?(?:at|in|on) the (?:bottom|base) of (?:the |my |a )?(?!(?:[a-z]+ )?(?:bowl|destination)s?\b)[a-z]+\b",
     ("liquid_leaves_source",), True),
    # left in the source: kept in it ("is anything left in the jug afterwards")
    (r"(?:(?<=\bsome )|(?<=\bany )|(?<=\bnone )|(?<=\bnothing )|(?<=\bmuch ))?(?:left|leftover) (?:over |stuck |clinging |sitting )?in(?= (?:(?:the |a |an |my |your )(?:[a-z]+ )?)?(?!(?:bowl|destination)s?\b)[a-z]+\b)"
     r"(?! (?:the |a |an |my |your )(?:[a-z]+ )?(?:bowl|destination)s?\b)",
     ("liquid_leaves_source",), True),
    # left behind in the source: kept in it ("with nothing left behind")
    (r"(?:left|stay(?:s|ed|ing)?|remain(?:s|ed|ing)?) behind\b"
     # what is left in it, said of the pour: "which one leaves more behind in the cup"
     rf"|leav(?:e|es|ing) (?:{_KEPT} )?behind\b"
     # what is left in it, said of the pour, in the bowl poured from: "a pour that doesn't leave anything in the bottle"
     rf"|leav(?:e|es|ing) (?:{_KEPT}|a drop)(?: of it)? in"
     r"(?= (?:the |a |an |my |your )(?:[a-z]+ )?(?!(?:bowl|destination)s?\b)[a-z]+\b)(?! (?:the |a |an |my |your )(?:[a-z]+ )?(?:bowl|destination)s?\b)"
     # some of it remaining, said after it left: "shall all of it leave it, or will some remain?"
     r"|(?:(?<=some )|(?<=any )|(?<=bit )|(?<=little ))remain(?:s)?\b(?! in (?:the )?(?:bowl|destination)\b)",
     ("liquid_leaves_source",), True),
    # clinging to a container not the bowl: kept in the source ("make it into the bowl or cling to the jar")
    (r"(?:stick|sticks|sticking|stuck|cling|clings|clinging|clung) to"
     r"(?!(?: [a-z]+){0,2}? (?:bowl|bowls|destination|target|rim|edge|top|sides?|walls?|brim|lip|bottom|surface|it|them)\b)"
     rf"(?= (?:the |a |an |its |my |your )?(?:insides? of (?:the |a |an |its |my |your )?(?!(?:[a-z]+ )?(?:bowl|dish|destination)s?\b))?(?:[a-z]+ )?{CONTAINER}\b)",
     ("liquid_leaves_source",), True),
    # stuck inside, no bowl named: kept in the source ("will the last bit stay stuck inside?")
    (r"(?:(?:stay|stays|remain|remains|get|gets|be|is) )?stuck in(?:side)?(?: (?:the |a |my )?(?!bowl\b|destination\b)[a-z]+)?"
     r"(?! (?:the |a |my )?(?:bowl|destination)\b)"
     r"|(?:stay|stays|remain|remains|get|gets) stuck\b(?! (?:in|to|on|at)\b)",      # "come out or just stay stuck"
     ("liquid_leaves_source",), True),
    # (where in the bowl it lands is no outcome: "go in the middle of the bowl" is refused, everyday.txt)
    (r"(?:end|ends|ended|ending) up (?:more |less |mostly )?in(?:side)?(?! the (?:middle|centre|center)\b)", (*ALL_IN, "liquid_remains_in_destination"), False),
    # what stays in the bowl entered it: "remains" alone holds also when none enters
    (r"(?:stay|stays|remain|remains) (?:in )?there\b"
     rf"|(?:stay|stays|staying|remain|remains|remaining|stop|stops|stick|sticks|stuck|cling|clings|clung|sit|sits|sitting) (?:in(?:side)?|within)(?: the (?:bottom|base) of)?(?: the \w+| (?:my |a |its )?{CONTAINER}\b)?",
     (*ALL_IN, "liquid_remains_in_destination"), False),
    (r"(?:go|goes|going|went|get|gets|land|lands|plop|plops|plopped|make it|makes it|fall|falls|transfer\w*|arrive\w*|finds? (?:its|their) way) (?:more |mostly |all )?(?:in|into|inside)\b(?! the way\b)(?! the (?:middle|centre|center)\b)|reach\w*|make it (?:to|into)|enter\w*|get (?:the |all (?:the )?)?(?:water|liquid|milk|it|everything) (?:in|into)\b"
     r"|(?<=\bit all )in(?= (?:the |my )?(?:bowl|dish|basin|destination)\b)",         # "or is it all in the bowl"
     ALL_IN, False),
    # what misses the bowl lands outside it: not all of it goes in, and it spills
    (r"miss(?:es|ed|ing)?|overshoot\w*|undershoot\w*|fall\w* short"
     # gone past it: "it went straight past the bowl", "the stream landed past the rim"
     r"|(?:land|lands|landed|landing|go|goes|going|went|gone|fly|flies|flying|flew|shoot|shoots|shooting|shot)"
     r" (?:right |just |straight )?(?:past|beyond) (?:it|them|the (?:bowl|destination|rim|edge))\b", (*ALL_IN, "no_spill"), True),
    # (safe: not what a liquid does, "is this bleach safe to pour", vessels.filled's)
    (rf"{SAFE}|(?:be |is )?(?:fine|ok|okay|alright|all right)\b|(?:a )?(?:good|bad) idea|risky|bad(?= *[?.!]* *$)"
     r"|(?:be )?(?:a )?(?:disaster|catastrophe|nightmare|fiasco)\b"
     r"|(?:go|goes|going|went) wrong"
     r"|dangerous|(?:a )?problem|(?:bad|good|wise|unwise|smart|sensible|better|safer|wiser)(?= to\b)",
     ("no_spill", "destination_upright", "source_clear"), False),
)


@lru_cache(maxsize=None)
def outcome_verb(word: str) -> bool:
    """Whether `word` is a verb of an outcome ("slide", "spills", "leaking")."""
    return any(re.fullmatch(filled(verb), word) for verb, _, _ in OUTCOMES)
