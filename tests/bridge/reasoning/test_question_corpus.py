"""Questions as people type them, read as meant or refused: never read as
another question. A corpus of everyday phrasing, coordination, negation,
numbers with units and vague or impossible requests, each with the
propositions it means or None where it must be refused (contradictory,
vague, said of a body it cannot qualify, or beyond the vocabulary). Grow
it with every misreading found."""
from __future__ import annotations

import re

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.reading import read_question, understand
from pantarhei.bridge.reasoning.words import FILLERS
from pantarhei.theory.lexicon import load_vocabulary

#: question -> the propositions it means, sorted
READ = {
    'what if the cup is only half full?': ['much_liquid'],
    'Does the liquid spill when the source is held high above a light destination?': ['light_destination', 'pour_high'],
    'What happens if the pouring container is tilted 90 degrees?': ['pour_steeply_tilted'],
    'Will liquid remain in the destination if the destination is bouncy?': ['bouncy_destination'],
    'Pour with a heavy source container and a light receiving container.': ['heavy_source', 'light_destination'],
    'Is the source clear of the destination when pouring from below the rim?': ['pour_below_rim'],
    'What if the liquid particles are heavy?': ['heavy_liquid'],
    'What if the particles are bouncy?': ['bouncy_liquid'],
    'pour near the bowl': ['pour_low'],
    'pour at an angle': [],
    'what if the bowl is on a slippery counter?': ['slippery_destination'],
    'the table is slippery, will the bowl slide?': ['slippery_destination'],
    'The robot pours water from a cup into a bowl from high above.': ['pour_high'],
    'The robot approaches quickly and pours from the side.': ['fast_approach', 'pour_to_side'],
    'With the source held 5 cm above the rim, tilt it to 100 degrees.': ['pour_low', 'pour_steeply_tilted'],
    'Approach in 1 second, pour, then retreat in 3 seconds.': ['moderate_approach', 'slow_retreat'],
    'The destination weighs 50 g.': ['light_destination'],
    'The source weighs 1.5 kg.': ['heavy_source'],
    'Use 20 particles.': ['little_liquid'],
    'What if the target is very light?': ['light_destination'],
    'pour into a heavy, grippy bowl from a light, slippery cup': ['grippy_destination', 'heavy_destination', 'light_source', 'slippery_source'],
    'pour into the bowl from a heavy jug': ['heavy_source'],
    'start upright, pour steeply tilted, end upright': ['end_upright', 'pour_steeply_tilted', 'start_upright'],
    'pour and then lift the cup quickly': ['fast_retreat', 'retreat_raising'],
    'pour, then lower the cup slowly': ['retreat_lowering', 'slow_retreat'],
    'pour from a cup that is upside down': ['pour_upside_down'],
    'move the cup in from the side': ['start_to_side'],
    'retreat to the side': ['end_to_side'],
    'move away slowly after pouring from the side': ['pour_to_side', 'slow_retreat'],
    'move in fast before pouring from high up': ['fast_approach', 'pour_high'],
    'move away after pouring and lift it': ['retreat_raising'],
    'what if the source is light but the liquid is heavy?': ['heavy_liquid', 'light_source'],
    'pour heavy liquid from a light cup into a heavy bowl': ['heavy_destination', 'heavy_liquid', 'light_source'],
    'start far away and move closer before pouring': ['approach_moving_closer', 'start_far_away'],
    'pour from mid height': ['pour_mid_height'],
    'tilt the cup half way': ['pour_half_tilted'],
    'keep the cup level': ['pour_level'],
    'the liquid is not sticky': ['runny_liquid'],
    'a slippery source and a grippy destination': ['grippy_destination', 'slippery_source'],
    'slowly move in and then pour from the side': ['pour_to_side', 'slow_approach'],
    'approach slowly from far away': ['slow_approach', 'start_far_away'],
    'end far from the bowl, upright': ['end_far_away', 'end_upright'],
    'pour above the bowl': [],
    'pour over the bowl': [],
    '30 cm above the bowl': ['pour_very_high'],
    '50 particles of liquid': ['some_liquid'],
    'I pour honey into a glass': ['sticky_liquid'],
    'a 2 kg bowl': ['heavy_destination'],
    'a 200 g destination': ['medium_destination'],
    'a full jug of water': ['very_much_liquid'],
    'a light source and destination': ['light_destination', 'light_source'],
    'a source bowl of 300 g': ['light_source'],
    'a source weighing 2 kg': ['heavy_source'],
    'a very heavy liquid': ['heavy_liquid'],
    'an extremely light bowl': ['light_destination'],
    'approach fast': ['fast_approach'],
    'both bowls are light': ['light_destination', 'light_source'],
    'bring the cup in slowly': ['slow_approach'],
    'does it spill if I pour from the side?': ['pour_to_side'],
    'end at 10 degrees': ['end_slightly_tilted'],
    'finish upright': ['end_upright'],
    'finish with the source upside down': ['end_upside_down'],
    'hold the cup 40 cm above the bowl': ['pour_very_high'],
    'hold the cup upside down over the bowl': ['pour_upside_down'],
    'lift the cup after pouring': ['retreat_raising'],
    'lower the cup before pouring': ['approach_lowering'],
    'move away in 500 ms': ['fast_retreat'],
    'move in over 3 seconds': ['slow_approach'],
    'move the cup in quickly and pour': ['fast_approach'],
    'move the source closer before pouring': ['approach_moving_closer'],
    'only a few drops': ['little_liquid'],
    'pour': [],
    'pour 0 cm above the rim': ['pour_low'],
    'pour 1 foot above the bowl': ['pour_very_high'],
    'pour 2 cm below the rim': ['pour_below_rim'],
    'pour 20 cm to the side': ['pour_far_away'],
    'pour 3 inches above the bowl': ['pour_mid_height'],
    'pour 30cm above the destination, tilted at 60 degrees': ['pour_half_tilted', 'pour_very_high'],
    'pour 5 cm sideways': ['pour_offset_sideways'],
    'pour 70 mm above the bowl': ['pour_mid_height'],
    'pour a heavy liquid': ['heavy_liquid'],
    'pour a heavy liquid from 45 degrees': ['heavy_liquid', 'pour_half_tilted'],
    'pour a heavy liquid into a light bowl, steeply tilted': ['heavy_liquid', 'light_destination', 'pour_steeply_tilted'],
    'pour about 30 cm above the bowl': ['pour_very_high'],
    'pour at 90 degrees': ['pour_steeply_tilted'],
    'pour at a steep angle': ['pour_steeply_tilted'],
    'pour at roughly 45 degrees': ['pour_half_tilted'],
    'pour from 5 cm above the rim': ['pour_low'],
    'pour from a distance': ['pour_far_away'],
    'pour from a heavy cup into a light cup': ['heavy_source', 'light_destination'],
    'pour from a height of 20 cm': ['pour_high'],
    'pour from far away': ['pour_far_away'],
    'pour from the edge of the bowl': ['pour_near_rim'],
    'pour from the right side': ['pour_to_side'],
    'pour from the side, not from far away': ['pour_to_side'],
    'pour high then lower it': ['pour_high', 'retreat_lowering'],
    'pour in line with the bowl': ['pour_in_line'],
    'pour it steeply into a heavy mug and then lift it': ['heavy_destination', 'pour_steeply_tilted', 'retreat_raising'],
    'pour just a little water': ['little_liquid'],
    'pour low then raise the cup': ['pour_low', 'retreat_raising'],
    'pour off to one side': ['pour_to_side'],
    'pour offset to the side': ['pour_offset_sideways'],
    'pour right over the middle of the bowl': ['pour_centred'],
    'pour some liquid': ['some_liquid'],
    'pour steeply': ['pour_steeply_tilted'],
    'pour syrup into a light cup': ['light_destination', 'sticky_liquid'],
    'pour the water from a great height': ['pour_very_high'],
    'pour upside down': ['pour_upside_down'],
    'pour upside-down': ['pour_upside_down'],
    'pour with the source rolled 20 degrees': ['pour_rolled'],
    'pull the cup back fast': ['fast_retreat'],
    'put it down far away': ['end_far_away'],
    'put the source back upright': ['end_upright'],
    'raise it high after pouring': ['end_high', 'retreat_raising'],
    'roll the cup while pouring': ['pour_rolled'],
    'start high and pour low': ['pour_low', 'start_high'],
    'start tilted back': ['start_tilted_back'],
    'start upright and end upside down': ['end_upside_down', 'start_upright'],
    'take 4 seconds to move in': ['slow_approach'],
    'the bowl is rough': ['grippy_destination'],
    'the cup starts upright': ['start_upright'],
    'the destination bowl is heavy and grippy': ['grippy_destination', 'heavy_destination'],
    'the liquid is neither heavy nor light': ['medium_liquid'],
    'the liquid is thin': ['runny_liquid'],
    'the source and the destination are both heavy': ['heavy_destination', 'heavy_source'],
    'the source is heavy and the destination is light': ['heavy_source', 'light_destination'],
    'the source is not heavy and the destination is heavy': ['heavy_destination', 'light_source'],
    'tilt 45 degrees then end upright': ['end_upright', 'pour_half_tilted'],
    'tilt it 30 degrees sideways': ['pour_rolled'],
    'tilt it steeply': ['pour_steeply_tilted'],
    'tilt the jug a bit': ['pour_slightly_tilted'],
    'tilt the jug to 120 degrees': ['pour_upside_down'],
    'tilt the source 100° when pouring': ['pour_steeply_tilted'],
    'tilt the source sideways while pouring': ['pour_rolled'],
    'tilted at 45 degrees': ['pour_half_tilted'],
    'use a heavy glass as the source': ['heavy_source'],
    'what happens to the liquid if the destination is slippery?': ['slippery_destination'],
    'what happens when I pour from very high?': ['pour_very_high'],
    'what if I move away quickly after pouring?': ['fast_retreat'],
    'what if I pour below the rim?': ['pour_below_rim'],
    'what if the bowl is very light?': ['light_destination'],
    'what if the receiving bowl is light and slippery?': ['light_destination', 'slippery_destination'],
    "what if there's lots of water?": ['much_liquid'],
    "will the bowl tip over if it's light and I pour a heavy liquid?": ['heavy_liquid', 'light_destination'],
    'with 150 particles': ['very_much_liquid'],
    'not a heavy liquid but a light one': ['light_liquid'],
    "don't pour from the middle": ['pour_near_rim'],        # the nearest place off it, said back
    'pour from the left': ['pour_to_side'],
    'pour from the side but not too far left': ['pour_to_side'],     # a side named, no length: from the side, said back
    'pour straight down': [],        # the way the stream falls from every pour, said back
}

#: questions to refuse in one line
REFUSED = [
    'If I pour slowly from a low height, does the destination stay upright?',
    "don't pour at medium height",
    'never pour upside down',
    'pour more liquid than the bowl holds',
    'fill the bowl',
    'end with the bowl upside down',
    'pour with the cup level',
    'move it straight down',
    'a liquid that is neither runny nor sticky nor medium',
    'pour the liquid slowly into a slippery bowl',
    'lift the cup high',
    'pour alongside the bowl',
    'pour a little to the side',
    'a bouncy ball',
    'a heavier liquid than water in the jug',
    'an empty cup',
    'either pour from the side or from far away',
    'move in slow then pour fast',
    'pour 10 to 20 cm above',
    'pour a 1 kg liquid',
    'pour a medium amount of liquid',
    'pour carefully',
    'pour for 3 seconds',
    'pour from the front',
    'pour from the side and from above',
    'pour gently',
    'pour half the liquid',
    'pour high or low',
    'pour inside the bowl',
    'pour low and slow',
    'pour quickly',
    'pour slowly',
    'pour up side down',
    'the destination is full',
    'the destination is not light, not heavy',
    'the source bumps into the destination',
    'the source is heavier than the destination',
    'what if I pour really slowly?',
    'what if the bowl moves?',
    'with 100 drops',
]


@pytest.mark.parametrize("question", sorted(READ))
def test_read_as_meant(question):
    assert understand(question) == READ[question]


@pytest.mark.parametrize("question", REFUSED)
def test_refused_in_one_line(question):
    with pytest.raises(UserError) as e:
        understand(question)
    assert "\n" not in str(e.value)


#: Questions as people type them, by kind (issue wordings): question -> (scene,
#: the expectations asked, the goals wanted)
HEARD = {
    # outcome clauses: which expectations are asked, never blocking the scene
    'does it splash?': ([], ['no_spill'], []),
    'will it drip on the table?': ([], ['no_spill'], []),
    'is it messy if I pour really high': (['pour_high'], ['no_spill'], []),
    'will the bowl slide?': ([], ['destination_still_approach', 'destination_still_retreat',
                                  'destination_still_settle'], []),
    'will it overflow?': ([], ['liquid_remains_in_destination', 'no_spill'], []),
    'anything come out?': ([], ['liquid_leaves_source'], []),
    'does anything come out if I pour upside down?': (['pour_upside_down'],
                                                       ['liquid_leaves_source'], []),
    'is it safe to pour honey from high up?': (['pour_high', 'sticky_liquid'],
                                               ['no_spill', 'destination_upright', 'source_clear'], []),
    'does it all go in?': ([], ['liquid_enters_destination'], []),
    'will a light bowl tip over?': (['light_destination'], ['destination_upright'], []),
    'will it make a mess if I pour from the side?': (['pour_to_side'], ['no_spill'], []),
    'does the cup hit the bowl when I pour low?': (['pour_low'], ['source_clear'], []),
    # goals said with the scene: what is wanted
    'pour without spilling': ([], [], ['no_spill']),
    'pour from the side so that it all goes in': (['pour_to_side'], [], ['liquid_enters_destination']),
    'pour so that the cup does not touch the bowl': ([], [], ['source_clear']),
    'pour from high up without spilling or tipping the bowl over': (
        ['pour_high'], [], ['no_spill', 'destination_upright']),
    'does the source bump into the bowl?': ([], ['source_clear'], []),
    # everyday outcome verbs, and subjects of everyday words
    'will the milk splash if I pour it from high up?': (['pour_high'], ['no_spill'], []),
    'does any soup end up on the stove?': ([], ['no_spill'], []),
    # "end up" says where an outcome leads, never the end pose raised
    'pour below the rim: does the source end up hitting the bowl?': (['pour_below_rim'],
                                                                     ['source_clear'], []),
    'will the soup slop over the edge of the bowl?': ([], ['liquid_remains_in_destination', 'no_spill'], []),
    'will the liquid bounce out of the bowl?': ([], ['liquid_remains_in_destination', 'no_spill'], []),
    'will the mug fall over if I pour cream into it?': ([], ['destination_upright'], []),
    'will the jug knock the bowl over?': ([], ['destination_upright'], []),
    'will the jug knock the bowl?': ([], ['source_clear'], []),
    'will the saucepan tip if it is light?': (['light_destination'], ['destination_upright'], []),
    'will the cup go wiggly?': ([], ['destination_still_approach', 'destination_still_retreat',
                                     'destination_still_settle'], []),
    'will the receiving vessel remain stationary?': ([], ['destination_still_approach',
                                                         'destination_still_retreat',
                                                         'destination_still_settle'], []),
    'will the target container translate during pouring?': (
        [], ['destination_still_approach', 'destination_still_retreat', 'destination_still_settle'], []),
    'does the jar bonk the bowl?': ([], ['source_clear'], []),
    'do the cup and the bowl collide?': ([], ['source_clear'], []),
    'does the source intersect the destination?': ([], ['source_clear'], []),
    'is the source clear of the destination at all times?': ([], ['source_clear'], []),
    'does it reach the bowl?': ([], ['liquid_enters_destination'], []),
    'does the juice make it into the glass?': ([], ['liquid_enters_destination'], []),
    'what fraction of the liquid reaches the destination?': ([], ['liquid_enters_destination'], []),
    'does the coffee end up in the cup?': ([], ['liquid_enters_destination',
                                                 'liquid_remains_in_destination'], []),
    'does the liquid exit the source?': ([], ['liquid_leaves_source'], []),
    'does the milk leave the carton?': ([], ['liquid_leaves_source'], []),
    'does yogurt come out if I hold the carton upside down?': (
        ['pour_upside_down', 'sticky_liquid'], ['liquid_leaves_source'], []),
    'is it ok to pour from high up?': (['pour_high'], ['no_spill', 'destination_upright',
                                                      'source_clear'], []),
    'will it make a big mess?': ([], ['no_spill'], []),
    'is it a good idea to pour from high up?': (['pour_high'], ['no_spill', 'destination_upright',
                                                               'source_clear'], []),
    'is it risky to pour upside down?': (['pour_upside_down'], ['no_spill', 'destination_upright',
                                                               'source_clear'], []),
    'do you think it will spill?': ([], ['no_spill'], []),
    'will some of the milk spill?': ([], ['no_spill'], []),
    'is it going to splash all over the place?': ([], ['no_spill'], []),
    'will the juice go splat?': ([], ['no_spill'], []),
    'does the liquid enter the target?': ([], ['liquid_enters_destination'], []),
    'does the robot arm hit the bowl when it moves in?': ([], ['source_clear'], []),
    'can the robot pour without the cup getting knocked?': ([], ['source_clear'], ['source_clear']),
    "what's the chance the bowl tips if the bowl weighs 30 grams?": (
        ['light_destination'], ['destination_upright'], []),
    'is the chance of spilling high if I pour from the side?': (['pour_to_side'], ['no_spill'], []),
    'what is the probability of spilling at 90 degrees?': (['pour_steeply_tilted'], ['no_spill'], []),
    'can I pour cream without it dripping down the side?': ([], [], ['no_spill']),
    "pour milk into the cup but don't let it overflow": (
        [], [], ['liquid_remains_in_destination', 'no_spill']),
    'keep the mug still while pouring': ([], [], ['destination_still_approach',
                                                  'destination_still_retreat',
                                                  'destination_still_settle']),
    "make sure it doesn't spill when I pour from high up": (['pour_high'], [], ['no_spill']),
    # a clause about what is done is no outcome
    'does the source move in fast?': (['fast_approach'], [], []),
    'pour so the cup is upright at the end': (['end_upright'], [], []),
}

#: Wordings of the scene (issue wordings), read as meant
READ_TOO = {
    # signs kept: ASCII and Unicode minus
    'tilted at -10 degrees': ['pour_tilted_back'],
    'tilted at \u221210 degrees': ['pour_tilted_back'],
    'pour -3 cm above the rim': ['pour_below_rim'],
    'pour \u22123 cm above the rim': ['pour_below_rim'],
    'pour minus 2 cm above the rim': ['pour_below_rim'],
    'start tilted at -20 degrees': ['start_tilted_back'],
    # nothing dropped: each stage keeps its words
    'tilt the source halfway and end with the source tilted halfway': ['end_half_tilted', 'pour_half_tilted'],
    'tilt the jug halfway and leave it there': ['end_half_tilted', 'pour_half_tilted'],
    'pour from the side, steeply tilted, and leave it tilted': ['end_steeply_tilted', 'pour_steeply_tilted', 'pour_to_side'],
    # everyday words
    'pour milk into a light plastic cup': ['light_destination'],
    'pour oil from high up': ['pour_high'],
    'a liquid like honey': ['sticky_liquid'],
    'pour into a heavy ceramic bowl': ['heavy_destination'],
    'a light glass bowl': ['light_destination'],
    'a completely full jug': ['very_much_liquid'],
    'tilt it barely': ['pour_slightly_tilted'],
    # liquids by name, containers with their materials and colours, what is around
    'pour soup from a heavy pot into a light bowl': ['heavy_source', 'light_destination'],
    'pour gravy into the gravy boat': [],
    'pour batter into a cake tin': ['sticky_liquid'],
    'pour mercury into a glass beaker': ['heavy_liquid'],
    'pour heavy cream into a bowl': [],
    'pour milk from a plastic jug into a ceramic mug': [],
    'pour from a jug made of steel': [],
    'pour from a light plastic cup': ['light_source'],
    'pour red wine from a heavy red jug': ['heavy_source'],
    'pour from the honey jar into a cereal bowl': ['sticky_liquid'],
    'pour from a heavy thermos': ['heavy_source'],
    'pour from the spout of a heavy jug': ['heavy_source'],
    'pour milk into a light bowl on the kitchen table': ['light_destination'],
    'in the kitchen, pour milk into a mug': [],
    'pour milk into a bowl full of cereal': [],
    'pour into a bowl on the counter from a light jug': ['light_source'],
    'pour into a greasy bowl': ['slippery_destination'],
    'pour into a light bowl from a full jug': ['light_destination', 'very_much_liquid'],
    'pour milk from the carton into a glass; the carton is light': ['light_source'],
    'pour into a cup from a jug; the jug is light': ['light_source'],
    # degree phrases and hedges
    'pour a tiny bit of water': ['little_liquid'],
    'pour a splash of milk': ['little_liquid'],
    'pour from a nearly empty jug': ['little_liquid'],
    'pour loads of milk': ['much_liquid'],
    'pour from a jug filled to the brim': ['very_much_liquid'],
    'tip it a bit': ['pour_slightly_tilted'],
    'hold the jug at a slight angle': ['pour_slightly_tilted'],
    'pour with the jug tilted only a little': ['pour_slightly_tilted'],     # a jug is poured from
    'what if the jug is really heavy?': ['heavy_source'],
    'will the bowl tip if the pitcher is heavy?': ['heavy_source'],
    'pour water into a heavy jug': ['heavy_destination'],
    'pour the olive oil from the bottle, just a tiny bit tilted': ['pour_slightly_tilted'],
    'what if the cup is tilted just a little': ['pour_slightly_tilted'],
    'okay so actually pour from high up': ['pour_high'],
    "I'm gonna pour from the side": ['pour_to_side'],
    # a property by its parameter's name and a level: never a height
    'friction of the destination is low': ['slippery_destination'],
    'low friction destination': ['slippery_destination'],
    'a high friction bowl': ['grippy_destination'],
    'bounciness of the liquid is high': ['bouncy_liquid'],
    'a high-restitution liquid': ['bouncy_liquid'],
    'the cup has a low mass': ['light_destination'],
    'the coefficient of friction of the bowl is very low': ['slippery_destination'],
    'pour a low viscosity liquid from high up': ['pour_high', 'runny_liquid'],
    'the weight of the liquid is high and pour low': ['heavy_liquid', 'pour_low'],
    # ... or by its name and a number, read as the proposition whose range holds it
    'a destination with a friction of 0.1': ['slippery_destination'],
    'restitution 0.9 for the liquid': ['bouncy_liquid'],
    "the source's coefficient of friction is 1.0": ['grippy_source'],
    'particle count 120': ['much_liquid'],
    'particle mass 2 g': ['medium_liquid'],
    'the particles weigh 0.5 g each': ['light_liquid'],
    'pour from x = 120 mm, z = 100 mm': ['pour_mid_height', 'pour_to_side'],
    'the end effector tilts 45 degrees': ['pour_half_tilted'],
    # everyday verbs and phrasings of the scene
    'tilt it forward 30 degrees': ['pour_slightly_tilted'],
    'pour from directly above the bowl': ['pour_centred'],
    'empty the jug into the bowl': [],
    'bring it over quickly and pour': ['fast_approach'],
    'a lateral offset of 5 cm': ['pour_offset_sideways'],
    'approach duration 2.5 s, retreat duration 0.4 s': ['fast_retreat', 'slow_approach'],
    # negation, contrast, reference
    'not tilted at all': ['pour_upright'],
    "don't tilt the cup at all": ['pour_upright'],
    'pour without tilting': ['pour_upright'],
    'pour near the edge instead of the middle': ['pour_near_rim'],
    'pour from the side rather than far away': ['pour_to_side'],
    'pour just above the rim': ['pour_low'],
    'offset 10 cm from the centre': ['pour_offset_sideways'],
    "pour offset 10 cm from the bowl's centre": ['pour_offset_sideways'],
    # numbers bound to the words next to them
    'pour from the side at 10 cm height': ['pour_mid_height', 'pour_to_side'],
    'pour at a height of 20 cm from the side': ['pour_high', 'pour_to_side'],
    # an amount with no liquid after it; tipped all the way over
    'pour a lot': ['much_liquid'],
    'what if I tip the cup all the way over?': ['pour_upside_down'],
    # a tilt with no amount is the ordinary pour's (pouring is tilting); a lot is steeply,
    # all the way upside down, not much slightly
    'if I tip the cup, will it spill?': [],
    'Pour viscous liquid from a tilted source.': ['sticky_liquid'],
    'tip the jug near the rim of the bowl': ['pour_near_rim'],
    'tip it and pour from the side': ['pour_to_side'],
    'pour from the side, tilted': ['pour_to_side'],
    'will it spill if the cup is tipped a lot': ['pour_steeply_tilted'],
    'tilt the jug all the way, does any stay in the bowl': ['pour_upside_down'],
    'tip it right over': ['pour_upside_down'],
    'without tilting it much': ['pour_slightly_tilted'],
    "don't tilt the cup too much": ['pour_slightly_tilted'],
    # not one extreme, where the ordinary pour holds one value: that value, said back
    "if the bowl isn't heavy, does it tip over": ['light_destination'],
    "don't move in fast": ['moderate_approach'],
    # moving fast or slowly with no way said: both moves
    'what if I move fast': ['fast_approach', 'fast_retreat'],
    'the arm moves slowly, does it spill': ['slow_approach', 'slow_retreat'],
    # poured from a length: its height
    'pour from 40 cm': ['pour_very_high'],
}

#: Refused in one line, naming what would be read: question -> words the refusal holds
REFUSED_SAYING = {
    # where nothing can be negative
    'a destination bowl of -500 g': 'cannot be negative',
    'take -2 seconds to move in': 'cannot be negative',
    'with -50 particles': 'cannot be negative',
    'with \u221250 particles': 'cannot be negative',
    # below the rim, but deeper than any proposition's range: the ranges named
    'pour -5 cm above the bowl': 'which no proposition holds (pour_below_rim -40 to 0 mm',
    'pour -5 cm below the rim': 'not both a minus and below',
    # a quantity no proposition takes, named
    'move in at 0.5 m/s': 'is a speed',
    'pour 100 grams of water': 'counts the liquid in particles',
    'pour 200 ml of milk': 'counts the liquid in particles',
    # near a proposition but not it: the phrasing that would be read
    'pour slowly': 'move in slowly',
    'pour fast': 'move in slowly',
    'pour it gently': 'move in slowly',
    'leave it tilted': 'tilted how far?',
    'start tilted and pour low': 'tilted how far?',
    'pour it all the way': 'all the way: tilted how far?',
    # what the vocabulary cannot say stays refused, naming why
    'pour hot milk': 'how hot or cold the liquid is',
    'pour milk at 80 degrees celsius': 'how hot or cold the liquid is',
    'pour 80\u00b0C milk': 'how hot or cold the liquid is',
    'pour honey with a viscosity of 2000': 'a viscosity is not a number',
    'pour a litre of water': 'counts the liquid in particles',
    'pour from a big jug': 'all of one size',
    'pour into a small cup': 'all of one size',
    'pour at 90%': 'a percentage of what?',
    'pour with the lid on': 'no lid',
    'pour milk into the coffee': 'the destination is empty',
    'pour water on the stove': 'the vocabulary pours into a bowl',
    'pour the milk into the sink': 'the vocabulary pours into a bowl',
    'the floor is slippery, will the bowl slide?': 'could not place "slippery"',
    'what if the bowl is on a sticky counter?': 'could not place "sticky"',
    'pour batter slowly into a pan': 'pouring has no speed of its own',
    'what if the jug slides into the bowl?': 'asks what follows an outcome',
    'what if the milk spills?': 'asks what follows an outcome',
    'what if the milk ends up on the floor?': 'could not place "ends up"',
    'does the source end up over the bowl?': 'could not place "end up"',
    'will the beer foam?': 'could not place "foam"',
    'a bowl with a friction of 2': 'which no proposition holds',
    'friction of 0.1': 'the friction of which?',
    'pour with a yaw of 30 degrees': 'no proposition of it',
    'turn the cup 30 degrees': 'no proposition of it',
    'a destination with a restitution of -0.2': 'cannot be negative',
    'pour syrup onto a plate': 'could not place "plate"',
    'pour into a full cup': 'could not place "full"',           # the destination is empty
    # asks for a value: a plan's to find, not a scene
    'how high should I hold the jug?': 'asks for a value',
    'how fast can I move in?': 'asks for a value',
    'how far away can I pour from?': 'asks for a value',
    'pour milk into a cup full of milk': 'could not place "full"',       # a plate holds no pour
}


@pytest.mark.parametrize("question", sorted(HEARD))
def test_the_question_is_heard_as_well_as_the_scene(question):
    r = read_question(question)
    scene, asked, goals = HEARD[question]
    assert (list(r.scene), sorted(r.asked), list(r.goals)) == (scene, sorted(asked), goals)


@pytest.mark.parametrize("question", sorted(READ_TOO))
def test_issue_wordings_read_as_meant(question):
    assert understand(question) == READ_TOO[question]


@pytest.mark.parametrize("question", sorted(REFUSED_SAYING))
def test_refused_naming_what_would_be_read(question):
    with pytest.raises(UserError) as e:
        understand(question)
    assert REFUSED_SAYING[question] in str(e.value) and "\n" not in str(e.value)


def test_everyday_words_are_said_back():
    r = read_question("pour milk into a light plastic cup")
    assert any(n.startswith("milk: read as an ordinary liquid") for n in r.notes)
    assert any(n.startswith("plastic: ignored") for n in r.notes)


def test_what_stands_for_the_ordinary_pour_is_said_back():
    tilt = next(p for p in load_vocabulary().parameters if p.name == "pour_pitch")
    r = read_question("tip the jug over the bowl")
    assert r.scene == () and f"tip: tilted as the ordinary pour is ({tilt.prior_low} to " \
        f"{tilt.prior_high} degrees from upright)" in r.notes
    r = read_question("if I don't come in fast")
    assert r.scene == ("moderate_approach",)
    assert "not fast_approach: moderate_approach, as in the ordinary pour" in r.notes


def test_a_body_said_not_to_be_one_end_of_its_scale_is_the_other():
    """"isn't heavy" of a bowl is a light one, said back, as "not heavy at
    all" is; "not too heavy" is the ordinary pour's weight; a manner said
    so ("don't come in fast") is the ordinary pour's."""
    r = read_question("if the bowl isn't heavy, does it slide?")
    assert r.scene == ("light_destination",) and "not heavy_destination: light_destination" in r.notes
    assert read_question("the bowl is not too heavy, does it slide?").scene == ("medium_destination",)
    assert read_question("the liquid isn't light, does it splash?").scene == ("heavy_liquid",)


@pytest.mark.parametrize("question", sorted({*READ, *READ_TOO, *HEARD}))
def test_no_word_is_dropped_silently(question):
    """Every word of a question read is read, heard as what it asks, said
    back, shown as ignored, or a word of a question's frame ("what", "if",
    "the"): none is lost without a word."""
    r = read_question(question)
    accounted = {w for phrase in (*r.heard, *r.ignored) for w in re.findall(r"[a-z]+", phrase.lower())}
    accounted |= {n.split(":")[0] for n in r.notes}
    frame = set(FILLERS) | {"s", "minus"}          # what's; minus: read as its number's sign
    said = re.sub(r"n't\b", " not", question.lower().replace("\u2019", "'"))
    lost = [w for w in re.findall(r"[a-z]+", said)
            if w not in accounted and w not in frame]
    assert lost == []


def _middles(param: str) -> list[tuple[float, str]]:
    """(the middle of its range, the proposition) for each proposition of `param`."""
    from pantarhei.theory.lexicon import load_vocabulary

    return [((p.model.low + p.model.high) / 2, n)
            for n, p in load_vocabulary().propositions.items()
            if p.model.kind == "uniform" and p.model.param == param]


@pytest.mark.parametrize("minus", ["-", "\u2212", "minus "])
@pytest.mark.parametrize("template,param,scale", [
    ("pour with the source tilted at {} degrees", "pour_pitch", 1),
    ("end tilted at {} degrees", "end_pitch", 1),
    ("pour {} cm above the rim", "pour_z", 10),
    ("start {} mm above the rim", "start_z", 1),
])
def test_a_number_is_read_with_its_sign_as_the_proposition_whose_range_holds_it(
        template, param, scale, minus):
    """Whatever the vocabulary's ranges, the middle of each, negative or
    not, written with any minus, is read as its proposition."""
    for value, name in _middles(param):
        number = f"{abs(value) / scale:g}"
        said = template.format(f"{minus}{number}" if value < 0 else number)
        assert understand(said) == [name], said


@pytest.mark.parametrize("minus", ["-", "\u2212"])
@pytest.mark.parametrize("question", ["a source bowl of {}300 g", "move in over {}2 seconds",
                                      "with {}50 particles", "pour {}100 ml of water"])
def test_nothing_that_cannot_be_negative_is_read_negative(question, minus):
    with pytest.raises(UserError, match="cannot be negative"):
        understand(question.format(minus))
