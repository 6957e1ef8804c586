% The 86 scene propositions, grouped into dimensions.
%
% Read by SWI-Prolog and by clingo alike: ground facts only (see parameters.pl).
%
% dimension(Dim, Aspect, ImageSchema, Gloss): the values of one dimension are
%   mutually exclusive and ordered by rank.
% proposition(Name, Dim, Rank, Gloss): ranks start at 1 and increase with the
%   value of the parameter that the proposition constrains.
% model(Name, Param, uniform(Low, High)): the proposition draws Param
%   uniformly from [Low, High] (in the parameter's unit).
% model(Name, Param, relative(Base, Low, High)): the proposition draws Param
%   as Base + d, d uniform in [Low, High], clipped to Param's bounds (the pour
%   pose is the anchor: start and end poses move relative to it).

dimension(start_height, verticality, verticality, "height of the source above the destination's rim at the start").
dimension(pour_height, verticality, verticality, "height of the source above the destination's rim when pouring").
dimension(end_height, verticality, verticality, "height of the source above the destination's rim at the end").
dimension(start_alignment, containment, containment, "where the source is relative to the destination's opening at the start").
dimension(pour_alignment, containment, containment, "where the source is relative to the destination's opening when pouring").
dimension(end_alignment, containment, containment, "where the source is relative to the destination's opening at the end").
dimension(pour_lateral, alignment, alignment, "sideways offset of the source from the line of pouring").
dimension(start_tilt, orientation, verticality, "how far and which way the source is tilted at the start").
dimension(pour_tilt, orientation, verticality, "how far and which way the source is tilted when pouring").
dimension(end_tilt, orientation, verticality, "how far and which way the source is tilted at the end").
dimension(pour_roll, orientation, balance, "sideways roll of the source when pouring").
dimension(end_roll, orientation, balance, "sideways roll of the source at the end").
dimension(approach_horizontal, relative_movement, near_far, "horizontal movement from the start pose to the pouring pose").
dimension(approach_vertical, relative_movement, verticality, "vertical movement from the start pose to the pouring pose").
dimension(retreat_horizontal, relative_movement, near_far, "horizontal movement from the pouring pose to the end pose").
dimension(retreat_vertical, relative_movement, verticality, "vertical movement from the pouring pose to the end pose").
dimension(approach_speed, speed, path, "how fast the source moves into the pouring pose").
dimension(retreat_speed, speed, path, "how fast the source moves out of the pouring pose").
dimension(source_weight, material, force, "mass of the source bowl").
dimension(destination_weight, material, force, "mass of the destination bowl").
dimension(liquid_weight, material, force, "mass of the liquid's particles").
dimension(source_friction, material, force, "friction of the source").
dimension(destination_friction, material, force, "friction of the destination").
dimension(liquid_friction, material, force, "friction of the liquid's particles").
dimension(source_bounciness, material, force, "bounciness of the source bowl").
dimension(destination_bounciness, material, force, "bounciness of the destination bowl").
dimension(liquid_bounciness, material, force, "bounciness of the liquid").
dimension(liquid_amount, amount, mass_count, "how much liquid is in the source").

proposition(start_below_rim, start_height, 1, "start below the destination's rim").
proposition(start_low, start_height, 2, "start low above the destination").
proposition(start_mid_height, start_height, 3, "start at medium height above the destination").
proposition(start_high, start_height, 4, "start high above the destination").
proposition(start_very_high, start_height, 5, "start very high above the destination").
proposition(pour_below_rim, pour_height, 1, "pour below the destination's rim").
proposition(pour_low, pour_height, 2, "pour low above the destination").
proposition(pour_mid_height, pour_height, 3, "pour at medium height above the destination").
proposition(pour_high, pour_height, 4, "pour high above the destination").
proposition(pour_very_high, pour_height, 5, "pour very high above the destination").
proposition(end_below_rim, end_height, 1, "end below the destination's rim").
proposition(end_low, end_height, 2, "end low above the destination").
proposition(end_mid_height, end_height, 3, "end at medium height above the destination").
proposition(end_high, end_height, 4, "end high above the destination").
proposition(end_very_high, end_height, 5, "end very high above the destination").
proposition(start_centred, start_alignment, 1, "start centred over the destination").
proposition(start_near_rim, start_alignment, 2, "start near the destination's rim").
proposition(start_to_side, start_alignment, 3, "start to the side").
proposition(start_far_away, start_alignment, 4, "start far from the destination").
proposition(pour_centred, pour_alignment, 1, "pour centred over the destination").
proposition(pour_near_rim, pour_alignment, 2, "pour near the destination's rim").
proposition(pour_to_side, pour_alignment, 3, "pour from the side").
proposition(pour_far_away, pour_alignment, 4, "pour far from the destination").
proposition(end_centred, end_alignment, 1, "end centred over the destination").
proposition(end_near_rim, end_alignment, 2, "end near the destination's rim").
proposition(end_to_side, end_alignment, 3, "end to the side").
proposition(end_far_away, end_alignment, 4, "end far from the destination").
proposition(pour_in_line, pour_lateral, 1, "pour in line with the destination").
proposition(pour_offset_sideways, pour_lateral, 2, "pour offset sideways").
proposition(start_tilted_back, start_tilt, 1, "start with the source tilted away from the destination").
proposition(start_upright, start_tilt, 2, "start with the source upright").
proposition(start_slightly_tilted, start_tilt, 3, "start with the source slightly tilted").
proposition(pour_tilted_back, pour_tilt, 1, "pour with the source tilted away from the destination").
proposition(pour_upright, pour_tilt, 2, "pour with the source upright").
proposition(pour_slightly_tilted, pour_tilt, 3, "pour with the source slightly tilted").
proposition(pour_half_tilted, pour_tilt, 4, "pour with the source tilted halfway").
proposition(pour_steeply_tilted, pour_tilt, 5, "pour with the source steeply tilted").
proposition(pour_upside_down, pour_tilt, 6, "pour with the source upside down").
proposition(end_tilted_back, end_tilt, 1, "end with the source tilted away from the destination").
proposition(end_upright, end_tilt, 2, "right the source up at the end").
proposition(end_slightly_tilted, end_tilt, 3, "end with the source slightly tilted").
proposition(end_half_tilted, end_tilt, 4, "end with the source tilted halfway").
proposition(end_steeply_tilted, end_tilt, 5, "end with the source steeply tilted").
proposition(end_upside_down, end_tilt, 6, "end with the source upside down").
proposition(pour_level, pour_roll, 1, "pour with the source level sideways").
proposition(pour_rolled, pour_roll, 2, "pour with the source rolled sideways").
proposition(end_level, end_roll, 1, "end with the source level sideways").
proposition(end_rolled, end_roll, 2, "end with the source rolled sideways").
proposition(approach_moving_away, approach_horizontal, 1, "move away from the destination before pouring").
proposition(approach_moving_closer, approach_horizontal, 2, "move closer to the destination before pouring").
proposition(approach_raising, approach_vertical, 1, "raise the source before pouring").
proposition(approach_lowering, approach_vertical, 2, "lower the source before pouring").
proposition(retreat_moving_closer, retreat_horizontal, 1, "move closer to the destination after pouring").
proposition(retreat_moving_away, retreat_horizontal, 2, "move away from the destination after pouring").
proposition(retreat_lowering, retreat_vertical, 1, "lower the source after pouring").
proposition(retreat_raising, retreat_vertical, 2, "lift the source after pouring").
proposition(fast_approach, approach_speed, 1, "move to the pouring pose fast").
proposition(moderate_approach, approach_speed, 2, "move to the pouring pose at a moderate speed").
proposition(slow_approach, approach_speed, 3, "move to the pouring pose slowly").
proposition(fast_retreat, retreat_speed, 1, "move away after pouring fast").
proposition(moderate_retreat, retreat_speed, 2, "move away after pouring at a moderate speed").
proposition(slow_retreat, retreat_speed, 3, "move away after pouring slowly").
proposition(light_source, source_weight, 1, "a light source bowl").
proposition(heavy_source, source_weight, 2, "a heavy source bowl").
proposition(light_destination, destination_weight, 1, "a light destination bowl").
proposition(medium_destination, destination_weight, 2, "a destination bowl of medium weight").
proposition(heavy_destination, destination_weight, 3, "a heavy destination bowl").
proposition(light_liquid, liquid_weight, 1, "a light liquid").
proposition(medium_liquid, liquid_weight, 2, "a liquid of medium weight").
proposition(heavy_liquid, liquid_weight, 3, "a heavy liquid").
proposition(slippery_source, source_friction, 1, "a slippery source bowl").
proposition(grippy_source, source_friction, 2, "a grippy source bowl").
proposition(slippery_destination, destination_friction, 1, "a slippery destination bowl").
proposition(grippy_destination, destination_friction, 2, "a grippy destination bowl").
proposition(runny_liquid, liquid_friction, 1, "a runny liquid").
proposition(sticky_liquid, liquid_friction, 2, "a sticky liquid").
proposition(dull_source, source_bounciness, 1, "a dull source bowl that does not bounce").
proposition(bouncy_source, source_bounciness, 2, "a bouncy source bowl").
proposition(dull_destination, destination_bounciness, 1, "a dull destination bowl that does not bounce").
proposition(bouncy_destination, destination_bounciness, 2, "a bouncy destination bowl").
proposition(dull_liquid, liquid_bounciness, 1, "a dull liquid that does not bounce").
proposition(bouncy_liquid, liquid_bounciness, 2, "a bouncy liquid").
proposition(little_liquid, liquid_amount, 1, "a little liquid").
proposition(some_liquid, liquid_amount, 2, "some liquid").
proposition(much_liquid, liquid_amount, 3, "much liquid").
proposition(very_much_liquid, liquid_amount, 4, "a source full of liquid").

model(start_below_rim, start_z, uniform(-40, 0)).
model(start_low, start_z, uniform(0, 60)).
model(start_mid_height, start_z, uniform(60, 140)).
model(start_high, start_z, uniform(140, 250)).
model(start_very_high, start_z, uniform(250, 400)).
model(pour_below_rim, pour_z, uniform(-40, 0)).
model(pour_low, pour_z, uniform(0, 60)).
model(pour_mid_height, pour_z, uniform(60, 140)).
model(pour_high, pour_z, uniform(140, 250)).
model(pour_very_high, pour_z, uniform(250, 400)).
model(end_below_rim, end_z, uniform(-40, 0)).
model(end_low, end_z, uniform(0, 60)).
model(end_mid_height, end_z, uniform(60, 140)).
model(end_high, end_z, uniform(140, 250)).
model(end_very_high, end_z, uniform(250, 400)).
model(start_centred, start_x, uniform(-20, 20)).
model(start_near_rim, start_x, uniform(40, 95)).
model(start_to_side, start_x, uniform(105, 165)).
model(start_far_away, start_x, uniform(175, 250)).
model(pour_centred, pour_x, uniform(-20, 20)).
model(pour_near_rim, pour_x, uniform(40, 95)).
model(pour_to_side, pour_x, uniform(105, 165)).
model(pour_far_away, pour_x, uniform(175, 250)).
model(end_centred, end_x, uniform(-20, 20)).
model(end_near_rim, end_x, uniform(40, 95)).
model(end_to_side, end_x, uniform(105, 165)).
model(end_far_away, end_x, uniform(175, 250)).
model(pour_in_line, pour_y, uniform(-20, 20)).
model(pour_offset_sideways, pour_y, uniform(40, 120)).
model(start_tilted_back, start_pitch, uniform(-30, -5)).
model(start_upright, start_pitch, uniform(-5, 5)).
model(start_slightly_tilted, start_pitch, uniform(5, 40)).
model(pour_tilted_back, pour_pitch, uniform(-30, -5)).
model(pour_upright, pour_pitch, uniform(-5, 5)).
model(pour_slightly_tilted, pour_pitch, uniform(5, 40)).
model(pour_half_tilted, pour_pitch, uniform(40, 80)).
model(pour_steeply_tilted, pour_pitch, uniform(80, 120)).
model(pour_upside_down, pour_pitch, uniform(120, 180)).
model(end_tilted_back, end_pitch, uniform(-30, -5)).
model(end_upright, end_pitch, uniform(-5, 5)).
model(end_slightly_tilted, end_pitch, uniform(5, 40)).
model(end_half_tilted, end_pitch, uniform(40, 80)).
model(end_steeply_tilted, end_pitch, uniform(80, 120)).
model(end_upside_down, end_pitch, uniform(120, 180)).
model(pour_level, pour_roll, uniform(-5, 5)).
model(pour_rolled, pour_roll, uniform(10, 30)).
model(end_level, end_roll, uniform(-5, 5)).
model(end_rolled, end_roll, uniform(10, 30)).
model(approach_moving_away, start_x, relative(pour_x, -150, -20)).
model(approach_moving_closer, start_x, relative(pour_x, 20, 150)).
model(approach_raising, start_z, relative(pour_z, -150, -20)).
model(approach_lowering, start_z, relative(pour_z, 20, 150)).
model(retreat_moving_closer, end_x, relative(pour_x, -150, -20)).
model(retreat_moving_away, end_x, relative(pour_x, 20, 150)).
model(retreat_lowering, end_z, relative(pour_z, -150, -20)).
model(retreat_raising, end_z, relative(pour_z, 20, 150)).
model(fast_approach, approach_duration, uniform(300, 900)).
model(moderate_approach, approach_duration, uniform(1000, 2000)).
model(slow_approach, approach_duration, uniform(2200, 4000)).
model(fast_retreat, retreat_duration, uniform(300, 900)).
model(moderate_retreat, retreat_duration, uniform(1000, 2000)).
model(slow_retreat, retreat_duration, uniform(2200, 4000)).
model(light_source, source_mass, uniform(100, 400)).
model(heavy_source, source_mass, uniform(800, 2000)).
model(light_destination, destination_mass, uniform(20, 100)).
model(medium_destination, destination_mass, uniform(200, 600)).
model(heavy_destination, destination_mass, uniform(1000, 3000)).
model(light_liquid, particle_mass, uniform(100, 800)).
model(medium_liquid, particle_mass, uniform(1500, 3000)).
model(heavy_liquid, particle_mass, uniform(5000, 10000)).
model(slippery_source, source_friction, uniform(0, 200)).
model(grippy_source, source_friction, uniform(800, 1500)).
model(slippery_destination, destination_friction, uniform(0, 200)).
model(grippy_destination, destination_friction, uniform(800, 1500)).
model(runny_liquid, particle_friction, uniform(0, 200)).
model(sticky_liquid, particle_friction, uniform(800, 1500)).
model(dull_source, source_restitution, uniform(0, 150)).
model(bouncy_source, source_restitution, uniform(600, 950)).
model(dull_destination, destination_restitution, uniform(0, 150)).
model(bouncy_destination, destination_restitution, uniform(600, 950)).
model(dull_liquid, particle_restitution, uniform(0, 150)).
model(bouncy_liquid, particle_restitution, uniform(600, 950)).
model(little_liquid, particle_count, uniform(10, 30)).
model(some_liquid, particle_count, uniform(40, 80)).
model(much_liquid, particle_count, uniform(90, 140)).
model(very_much_liquid, particle_count, uniform(150, 200)).

% role(Dim, Role): manner (how the source is moved: poses, tilt, movement,
%   speed) or context (the bodies and the liquid, given by the situation).
role(start_height, manner).
role(pour_height, manner).
role(end_height, manner).
role(start_alignment, manner).
role(pour_alignment, manner).
role(end_alignment, manner).
role(pour_lateral, manner).
role(start_tilt, manner).
role(pour_tilt, manner).
role(end_tilt, manner).
role(pour_roll, manner).
role(end_roll, manner).
role(approach_horizontal, manner).
role(approach_vertical, manner).
role(retreat_horizontal, manner).
role(retreat_vertical, manner).
role(approach_speed, manner).
role(retreat_speed, manner).
role(source_weight, context).
role(destination_weight, context).
role(liquid_weight, context).
role(source_friction, context).
role(destination_friction, context).
role(liquid_friction, context).
role(source_bounciness, context).
role(destination_bounciness, context).
role(liquid_bounciness, context).
role(liquid_amount, context).
