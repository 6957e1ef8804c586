% A theory of pouring learned by curiosity-driven exploration
% (pantarhei explore, oracle pybullet, seed 1).
%
% Ground facts, read by SWI-Prolog and clingo alike:
%   rule(Id, defeasible, Head): Head is an expectation, or neg(E) when it fails;
%   body(Id, Prop): a scene proposition of the rule's antecedent;
%   learned(Id): a learned rule (superiority from specificity);
%   provenance(Id, Key, Value): where the rule comes from (antecedent,
%   parent antecedent, simulations with a weight, their weight mass and the
%   verdict's confidence in permille, and the plane, parameter and sign
%   that produced the antecedent);
%   setting(Key, Value): how the exploration ran;
%   set_aside(Iteration, Attempt, Prop): a proposition of a candidate whose
%   probe (the Attempt-th of the Iteration, from 0) set it aside.

setting(oracle, pybullet).
setting(oracle_version, "4").
setting(seed, 1).
setting(batch, 31).
setting(budget, 25).
setting(curiosity, discover).
setting(significance_permille, 50).
setting(permutations, 199).
setting(resample, 2).
setting(novelty_permille, 100).
setting(jumps, 31).
setting(probe, 8).
setting(probe_attempts, 3).
setting(prior_batch, 1).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 18).
setting(simulations, 742).
setting(failed_simulations, 0).
setting(stopped, budget).
setting(a_new_left, 1411).
setting(initial, pour_mid_height).
setting(initial, pour_near_rim).
setting(initial, pour_steeply_tilted).
set_aside(4, 1, dull_destination).
set_aside(4, 1, end_upside_down).
set_aside(4, 1, end_very_high).
set_aside(4, 1, heavy_destination).
set_aside(4, 1, heavy_source).
set_aside(4, 1, light_liquid).
set_aside(4, 1, pour_far_away).
set_aside(4, 1, pour_high).
set_aside(4, 1, pour_upright).
set_aside(4, 1, retreat_moving_away).
set_aside(4, 1, runny_liquid).
set_aside(4, 1, slow_approach).
set_aside(4, 1, some_liquid).
set_aside(4, 1, start_high).
set_aside(4, 1, start_tilted_back).
set_aside(4, 1, start_to_side).
set_aside(4, 2, bouncy_source).
set_aside(4, 2, dull_destination).
set_aside(4, 2, end_half_tilted).
set_aside(4, 2, end_to_side).
set_aside(4, 2, fast_retreat).
set_aside(4, 2, heavy_destination).
set_aside(4, 2, light_liquid).
set_aside(4, 2, pour_far_away).
set_aside(4, 2, pour_in_line).
set_aside(4, 2, pour_low).
set_aside(4, 2, pour_rolled).
set_aside(4, 2, pour_tilted_back).
set_aside(4, 2, retreat_raising).
set_aside(4, 2, runny_liquid).
set_aside(4, 2, slippery_destination).
set_aside(4, 2, slippery_source).
set_aside(4, 2, slow_approach).
set_aside(4, 2, some_liquid).
set_aside(4, 2, start_near_rim).
set_aside(5, 0, approach_lowering).
set_aside(5, 0, dull_source).
set_aside(5, 0, end_slightly_tilted).
set_aside(5, 0, end_to_side).
set_aside(5, 0, fast_approach).
set_aside(5, 0, grippy_source).
set_aside(5, 0, heavy_source).
set_aside(5, 0, light_destination).
set_aside(5, 0, medium_liquid).
set_aside(5, 0, pour_centred).
set_aside(5, 0, pour_high).
set_aside(5, 0, pour_in_line).
set_aside(5, 0, pour_level).
set_aside(5, 0, pour_steeply_tilted).
set_aside(5, 0, runny_liquid).
set_aside(5, 0, slippery_destination).
set_aside(5, 0, some_liquid).
set_aside(5, 0, start_centred).
set_aside(5, 1, approach_moving_away).
set_aside(5, 1, bouncy_liquid).
set_aside(5, 1, dull_destination).
set_aside(5, 1, dull_source).
set_aside(5, 1, end_centred).
set_aside(5, 1, end_high).
set_aside(5, 1, end_level).
set_aside(5, 1, end_slightly_tilted).
set_aside(5, 1, grippy_source).
set_aside(5, 1, heavy_destination).
set_aside(5, 1, heavy_liquid).
set_aside(5, 1, moderate_approach).
set_aside(5, 1, much_liquid).
set_aside(5, 1, pour_in_line).
set_aside(5, 1, pour_level).
set_aside(5, 1, pour_near_rim).
set_aside(5, 1, pour_steeply_tilted).
set_aside(5, 1, runny_liquid).
set_aside(5, 1, slippery_destination).
set_aside(5, 1, start_high).
set_aside(6, 0, approach_moving_closer).
set_aside(6, 0, bouncy_source).
set_aside(6, 0, dull_destination).
set_aside(6, 0, dull_liquid).
set_aside(6, 0, end_half_tilted).
set_aside(6, 0, end_high).
set_aside(6, 0, end_level).
set_aside(6, 0, end_to_side).
set_aside(6, 0, fast_approach).
set_aside(6, 0, fast_retreat).
set_aside(6, 0, grippy_source).
set_aside(6, 0, heavy_liquid).
set_aside(6, 0, heavy_source).
set_aside(6, 0, medium_destination).
set_aside(6, 0, pour_steeply_tilted).
set_aside(6, 0, pour_very_high).
set_aside(6, 0, runny_liquid).
set_aside(6, 0, start_upright).
set_aside(6, 0, start_very_high).
set_aside(6, 0, very_much_liquid).
set_aside(6, 2, bouncy_destination).
set_aside(6, 2, dull_liquid).
set_aside(6, 2, dull_source).
set_aside(6, 2, end_far_away).
set_aside(6, 2, end_rolled).
set_aside(6, 2, end_tilted_back).
set_aside(6, 2, fast_approach).
set_aside(6, 2, grippy_destination).
set_aside(6, 2, heavy_source).
set_aside(6, 2, light_destination).
set_aside(6, 2, little_liquid).
set_aside(6, 2, medium_liquid).
set_aside(6, 2, pour_far_away).
set_aside(6, 2, pour_high).
set_aside(6, 2, pour_in_line).
set_aside(6, 2, pour_rolled).
set_aside(6, 2, pour_steeply_tilted).
set_aside(6, 2, retreat_raising).
set_aside(6, 2, slippery_source).
set_aside(6, 2, slow_retreat).
set_aside(6, 2, start_centred).
set_aside(6, 2, start_slightly_tilted).
set_aside(6, 2, sticky_liquid).
set_aside(7, 0, dull_liquid).
set_aside(7, 0, dull_source).
set_aside(7, 0, end_mid_height).
set_aside(7, 0, end_upright).
set_aside(7, 0, heavy_source).
set_aside(7, 0, light_destination).
set_aside(7, 0, much_liquid).
set_aside(7, 0, pour_high).
set_aside(7, 0, pour_in_line).
set_aside(7, 0, pour_level).
set_aside(7, 0, pour_near_rim).
set_aside(7, 0, pour_steeply_tilted).
set_aside(7, 0, slow_approach).
set_aside(7, 0, start_mid_height).
set_aside(7, 0, start_tilted_back).
set_aside(7, 0, start_to_side).
set_aside(7, 0, sticky_liquid).
set_aside(7, 1, approach_moving_away).
set_aside(7, 1, dull_source).
set_aside(7, 1, end_far_away).
set_aside(7, 1, end_half_tilted).
set_aside(7, 1, end_rolled).
set_aside(7, 1, grippy_destination).
set_aside(7, 1, grippy_source).
set_aside(7, 1, heavy_source).
set_aside(7, 1, light_destination).
set_aside(7, 1, light_liquid).
set_aside(7, 1, much_liquid).
set_aside(7, 1, pour_offset_sideways).
set_aside(7, 1, pour_rolled).
set_aside(7, 1, pour_steeply_tilted).
set_aside(7, 1, pour_to_side).
set_aside(7, 1, retreat_lowering).
set_aside(7, 1, slow_retreat).
set_aside(7, 1, start_low).
set_aside(7, 1, start_upright).
set_aside(7, 1, sticky_liquid).
set_aside(8, 1, approach_moving_closer).
set_aside(8, 1, dull_destination).
set_aside(8, 1, dull_source).
set_aside(8, 1, end_centred).
set_aside(8, 1, end_half_tilted).
set_aside(8, 1, end_level).
set_aside(8, 1, end_low).
set_aside(8, 1, grippy_destination).
set_aside(8, 1, grippy_source).
set_aside(8, 1, heavy_destination).
set_aside(8, 1, heavy_liquid).
set_aside(8, 1, light_source).
set_aside(8, 1, pour_in_line).
set_aside(8, 1, pour_low).
set_aside(8, 1, pour_slightly_tilted).
set_aside(8, 1, runny_liquid).
set_aside(8, 1, slow_approach).
set_aside(8, 1, slow_retreat).
set_aside(8, 1, start_below_rim).
set_aside(8, 1, very_much_liquid).
set_aside(8, 2, approach_moving_closer).
set_aside(8, 2, dull_destination).
set_aside(8, 2, dull_source).
set_aside(8, 2, end_centred).
set_aside(8, 2, end_half_tilted).
set_aside(8, 2, end_level).
set_aside(8, 2, end_low).
set_aside(8, 2, grippy_destination).
set_aside(8, 2, grippy_source).
set_aside(8, 2, heavy_destination).
set_aside(8, 2, heavy_liquid).
set_aside(8, 2, light_source).
set_aside(8, 2, pour_centred).
set_aside(8, 2, pour_in_line).
set_aside(8, 2, pour_slightly_tilted).
set_aside(8, 2, runny_liquid).
set_aside(8, 2, slow_approach).
set_aside(8, 2, slow_retreat).
set_aside(8, 2, start_below_rim).
set_aside(8, 2, very_much_liquid).
set_aside(9, 1, approach_moving_away).
set_aside(9, 1, dull_destination).
set_aside(9, 1, dull_source).
set_aside(9, 1, end_centred).
set_aside(9, 1, end_level).
set_aside(9, 1, end_low).
set_aside(9, 1, end_steeply_tilted).
set_aside(9, 1, grippy_destination).
set_aside(9, 1, grippy_source).
set_aside(9, 1, heavy_destination).
set_aside(9, 1, heavy_liquid).
set_aside(9, 1, light_source).
set_aside(9, 1, pour_in_line).
set_aside(9, 1, pour_slightly_tilted).
set_aside(9, 1, runny_liquid).
set_aside(9, 1, slow_approach).
set_aside(9, 1, slow_retreat).
set_aside(9, 1, start_below_rim).
set_aside(9, 1, very_much_liquid).
set_aside(9, 2, approach_moving_closer).
set_aside(9, 2, dull_destination).
set_aside(9, 2, dull_source).
set_aside(9, 2, end_centred).
set_aside(9, 2, end_half_tilted).
set_aside(9, 2, end_level).
set_aside(9, 2, end_low).
set_aside(9, 2, grippy_destination).
set_aside(9, 2, grippy_source).
set_aside(9, 2, heavy_destination).
set_aside(9, 2, heavy_liquid).
set_aside(9, 2, light_source).
set_aside(9, 2, pour_in_line).
set_aside(9, 2, pour_level).
set_aside(9, 2, pour_slightly_tilted).
set_aside(9, 2, runny_liquid).
set_aside(9, 2, slow_approach).
set_aside(9, 2, slow_retreat).
set_aside(9, 2, start_below_rim).
set_aside(9, 2, very_much_liquid).
set_aside(10, 1, approach_moving_away).
set_aside(10, 1, approach_raising).
set_aside(10, 1, dull_destination).
set_aside(10, 1, dull_source).
set_aside(10, 1, end_low).
set_aside(10, 1, end_rolled).
set_aside(10, 1, end_to_side).
set_aside(10, 1, end_upside_down).
set_aside(10, 1, fast_retreat).
set_aside(10, 1, grippy_source).
set_aside(10, 1, heavy_destination).
set_aside(10, 1, pour_below_rim).
set_aside(10, 1, pour_steeply_tilted).
set_aside(10, 1, runny_liquid).
set_aside(10, 1, slippery_destination).
set_aside(10, 1, slow_approach).
set_aside(10, 1, some_liquid).
set_aside(10, 1, start_tilted_back).
set_aside(10, 2, approach_moving_away).
set_aside(10, 2, dull_destination).
set_aside(10, 2, dull_source).
set_aside(10, 2, end_centred).
set_aside(10, 2, end_half_tilted).
set_aside(10, 2, end_level).
set_aside(10, 2, end_low).
set_aside(10, 2, grippy_destination).
set_aside(10, 2, grippy_source).
set_aside(10, 2, heavy_destination).
set_aside(10, 2, heavy_liquid).
set_aside(10, 2, light_source).
set_aside(10, 2, pour_in_line).
set_aside(10, 2, pour_level).
set_aside(10, 2, pour_slightly_tilted).
set_aside(10, 2, runny_liquid).
set_aside(10, 2, slow_approach).
set_aside(10, 2, slow_retreat).
set_aside(10, 2, start_below_rim).
set_aside(10, 2, very_much_liquid).
set_aside(11, 0, approach_moving_away).
set_aside(11, 0, dull_destination).
set_aside(11, 0, dull_source).
set_aside(11, 0, end_centred).
set_aside(11, 0, end_level).
set_aside(11, 0, end_low).
set_aside(11, 0, end_upside_down).
set_aside(11, 0, grippy_destination).
set_aside(11, 0, grippy_source).
set_aside(11, 0, heavy_destination).
set_aside(11, 0, heavy_liquid).
set_aside(11, 0, light_source).
set_aside(11, 0, moderate_retreat).
set_aside(11, 0, pour_in_line).
set_aside(11, 0, pour_low).
set_aside(11, 0, pour_slightly_tilted).
set_aside(11, 0, runny_liquid).
set_aside(11, 0, slow_approach).
set_aside(11, 0, start_below_rim).
set_aside(11, 0, very_much_liquid).
set_aside(11, 2, approach_moving_away).
set_aside(11, 2, dull_destination).
set_aside(11, 2, dull_source).
set_aside(11, 2, end_centred).
set_aside(11, 2, end_half_tilted).
set_aside(11, 2, end_level).
set_aside(11, 2, end_low).
set_aside(11, 2, grippy_destination).
set_aside(11, 2, grippy_source).
set_aside(11, 2, heavy_destination).
set_aside(11, 2, heavy_liquid).
set_aside(11, 2, light_source).
set_aside(11, 2, pour_centred).
set_aside(11, 2, pour_in_line).
set_aside(11, 2, pour_slightly_tilted).
set_aside(11, 2, runny_liquid).
set_aside(11, 2, slow_approach).
set_aside(11, 2, slow_retreat).
set_aside(11, 2, start_below_rim).
set_aside(11, 2, very_much_liquid).
set_aside(12, 0, approach_moving_away).
set_aside(12, 0, dull_destination).
set_aside(12, 0, dull_source).
set_aside(12, 0, end_centred).
set_aside(12, 0, end_half_tilted).
set_aside(12, 0, end_level).
set_aside(12, 0, end_low).
set_aside(12, 0, grippy_destination).
set_aside(12, 0, grippy_source).
set_aside(12, 0, heavy_destination).
set_aside(12, 0, heavy_liquid).
set_aside(12, 0, light_source).
set_aside(12, 0, pour_in_line).
set_aside(12, 0, pour_upside_down).
set_aside(12, 0, runny_liquid).
set_aside(12, 0, slow_approach).
set_aside(12, 0, slow_retreat).
set_aside(12, 0, start_below_rim).
set_aside(12, 0, very_much_liquid).
set_aside(12, 2, approach_moving_away).
set_aside(12, 2, dull_destination).
set_aside(12, 2, dull_liquid).
set_aside(12, 2, dull_source).
set_aside(12, 2, end_centred).
set_aside(12, 2, end_half_tilted).
set_aside(12, 2, end_level).
set_aside(12, 2, end_low).
set_aside(12, 2, grippy_destination).
set_aside(12, 2, grippy_source).
set_aside(12, 2, heavy_destination).
set_aside(12, 2, heavy_liquid).
set_aside(12, 2, light_source).
set_aside(12, 2, pour_in_line).
set_aside(12, 2, pour_slightly_tilted).
set_aside(12, 2, runny_liquid).
set_aside(12, 2, slow_approach).
set_aside(12, 2, slow_retreat).
set_aside(12, 2, start_below_rim).
set_aside(12, 2, very_much_liquid).
set_aside(13, 0, approach_moving_closer).
set_aside(13, 0, bouncy_source).
set_aside(13, 0, dull_destination).
set_aside(13, 0, end_centred).
set_aside(13, 0, end_half_tilted).
set_aside(13, 0, end_level).
set_aside(13, 0, end_low).
set_aside(13, 0, grippy_destination).
set_aside(13, 0, grippy_source).
set_aside(13, 0, heavy_destination).
set_aside(13, 0, heavy_liquid).
set_aside(13, 0, light_source).
set_aside(13, 0, pour_centred).
set_aside(13, 0, pour_in_line).
set_aside(13, 0, pour_slightly_tilted).
set_aside(13, 0, runny_liquid).
set_aside(13, 0, slow_approach).
set_aside(13, 0, slow_retreat).
set_aside(13, 0, start_below_rim).
set_aside(13, 0, very_much_liquid).
set_aside(13, 1, approach_moving_away).
set_aside(13, 1, dull_destination).
set_aside(13, 1, dull_source).
set_aside(13, 1, end_centred).
set_aside(13, 1, end_half_tilted).
set_aside(13, 1, end_level).
set_aside(13, 1, end_low).
set_aside(13, 1, grippy_destination).
set_aside(13, 1, grippy_source).
set_aside(13, 1, heavy_liquid).
set_aside(13, 1, light_source).
set_aside(13, 1, medium_destination).
set_aside(13, 1, pour_in_line).
set_aside(13, 1, pour_slightly_tilted).
set_aside(13, 1, runny_liquid).
set_aside(13, 1, slow_approach).
set_aside(13, 1, slow_retreat).
set_aside(13, 1, start_below_rim).
set_aside(13, 1, very_much_liquid).
set_aside(15, 0, approach_moving_away).
set_aside(15, 0, bouncy_destination).
set_aside(15, 0, bouncy_source).
set_aside(15, 0, end_centred).
set_aside(15, 0, end_half_tilted).
set_aside(15, 0, end_level).
set_aside(15, 0, end_low).
set_aside(15, 0, grippy_destination).
set_aside(15, 0, grippy_source).
set_aside(15, 0, heavy_destination).
set_aside(15, 0, heavy_liquid).
set_aside(15, 0, light_source).
set_aside(15, 0, pour_in_line).
set_aside(15, 0, pour_slightly_tilted).
set_aside(15, 0, runny_liquid).
set_aside(15, 0, slow_approach).
set_aside(15, 0, slow_retreat).
set_aside(15, 0, some_liquid).
set_aside(15, 0, start_below_rim).
set_aside(16, 0, approach_raising).
set_aside(16, 0, bouncy_destination).
set_aside(16, 0, end_level).
set_aside(16, 0, end_near_rim).
set_aside(16, 0, end_upside_down).
set_aside(16, 0, light_source).
set_aside(16, 0, little_liquid).
set_aside(16, 0, medium_liquid).
set_aside(16, 0, pour_below_rim).
set_aside(16, 0, pour_half_tilted).
set_aside(16, 0, pour_rolled).
set_aside(16, 0, slippery_destination).
set_aside(16, 0, slippery_source).
set_aside(16, 0, slow_retreat).
set_aside(16, 0, start_upright).
set_aside(16, 0, sticky_liquid).
set_aside(16, 1, approach_moving_away).
set_aside(16, 1, bouncy_destination).
set_aside(16, 1, dull_source).
set_aside(16, 1, end_centred).
set_aside(16, 1, end_half_tilted).
set_aside(16, 1, end_level).
set_aside(16, 1, end_low).
set_aside(16, 1, grippy_destination).
set_aside(16, 1, grippy_source).
set_aside(16, 1, heavy_destination).
set_aside(16, 1, heavy_liquid).
set_aside(16, 1, light_source).
set_aside(16, 1, pour_in_line).
set_aside(16, 1, pour_slightly_tilted).
set_aside(16, 1, runny_liquid).
set_aside(16, 1, slow_approach).
set_aside(16, 1, slow_retreat).
set_aside(16, 1, some_liquid).
set_aside(16, 1, start_below_rim).

rule(r1_destination_still_approach, defeasible, destination_still_approach).
body(r1_destination_still_approach, pour_mid_height).
body(r1_destination_still_approach, pour_near_rim).
body(r1_destination_still_approach, pour_steeply_tilted).
learned(r1_destination_still_approach).
provenance(r1_destination_still_approach, antecedent, a1).
provenance(r1_destination_still_approach, parent, none).
provenance(r1_destination_still_approach, simulations, 35).
provenance(r1_destination_still_approach, weight_mass_permille, 28400).
provenance(r1_destination_still_approach, confidence_permille, 1000).
provenance(r1_destination_still_approach, score_permille, 990).
provenance(r1_destination_still_approach, batches, 1).

rule(r1_destination_still_retreat, defeasible, destination_still_retreat).
body(r1_destination_still_retreat, pour_mid_height).
body(r1_destination_still_retreat, pour_near_rim).
body(r1_destination_still_retreat, pour_steeply_tilted).
learned(r1_destination_still_retreat).
provenance(r1_destination_still_retreat, antecedent, a1).
provenance(r1_destination_still_retreat, parent, none).
provenance(r1_destination_still_retreat, simulations, 35).
provenance(r1_destination_still_retreat, weight_mass_permille, 28400).
provenance(r1_destination_still_retreat, confidence_permille, 1000).
provenance(r1_destination_still_retreat, score_permille, 996).
provenance(r1_destination_still_retreat, batches, 1).

rule(r1_destination_still_settle, defeasible, destination_still_settle).
body(r1_destination_still_settle, pour_mid_height).
body(r1_destination_still_settle, pour_near_rim).
body(r1_destination_still_settle, pour_steeply_tilted).
learned(r1_destination_still_settle).
provenance(r1_destination_still_settle, antecedent, a1).
provenance(r1_destination_still_settle, parent, none).
provenance(r1_destination_still_settle, simulations, 35).
provenance(r1_destination_still_settle, weight_mass_permille, 28400).
provenance(r1_destination_still_settle, confidence_permille, 1000).
provenance(r1_destination_still_settle, score_permille, 1000).
provenance(r1_destination_still_settle, batches, 1).

rule(r1_destination_upright, defeasible, destination_upright).
body(r1_destination_upright, pour_mid_height).
body(r1_destination_upright, pour_near_rim).
body(r1_destination_upright, pour_steeply_tilted).
learned(r1_destination_upright).
provenance(r1_destination_upright, antecedent, a1).
provenance(r1_destination_upright, parent, none).
provenance(r1_destination_upright, simulations, 35).
provenance(r1_destination_upright, weight_mass_permille, 28400).
provenance(r1_destination_upright, confidence_permille, 1000).
provenance(r1_destination_upright, score_permille, 1000).
provenance(r1_destination_upright, batches, 1).

rule(r1_source_clear, defeasible, source_clear).
body(r1_source_clear, pour_mid_height).
body(r1_source_clear, pour_near_rim).
body(r1_source_clear, pour_steeply_tilted).
learned(r1_source_clear).
provenance(r1_source_clear, antecedent, a1).
provenance(r1_source_clear, parent, none).
provenance(r1_source_clear, simulations, 35).
provenance(r1_source_clear, weight_mass_permille, 28400).
provenance(r1_source_clear, confidence_permille, 1000).
provenance(r1_source_clear, score_permille, 994).
provenance(r1_source_clear, batches, 1).

rule(r1_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r1_liquid_leaves_source, pour_mid_height).
body(r1_liquid_leaves_source, pour_near_rim).
body(r1_liquid_leaves_source, pour_steeply_tilted).
learned(r1_liquid_leaves_source).
provenance(r1_liquid_leaves_source, antecedent, a1).
provenance(r1_liquid_leaves_source, parent, none).
provenance(r1_liquid_leaves_source, simulations, 35).
provenance(r1_liquid_leaves_source, weight_mass_permille, 28400).
provenance(r1_liquid_leaves_source, confidence_permille, 859).
provenance(r1_liquid_leaves_source, score_permille, 818).
provenance(r1_liquid_leaves_source, batches, 1).

rule(r1_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r1_liquid_enters_destination, pour_mid_height).
body(r1_liquid_enters_destination, pour_near_rim).
body(r1_liquid_enters_destination, pour_steeply_tilted).
learned(r1_liquid_enters_destination).
provenance(r1_liquid_enters_destination, antecedent, a1).
provenance(r1_liquid_enters_destination, parent, none).
provenance(r1_liquid_enters_destination, simulations, 35).
provenance(r1_liquid_enters_destination, weight_mass_permille, 28400).
provenance(r1_liquid_enters_destination, confidence_permille, 824).
provenance(r1_liquid_enters_destination, score_permille, 809).
provenance(r1_liquid_enters_destination, batches, 1).

rule(r1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r1_liquid_remains_in_destination, pour_mid_height).
body(r1_liquid_remains_in_destination, pour_near_rim).
body(r1_liquid_remains_in_destination, pour_steeply_tilted).
learned(r1_liquid_remains_in_destination).
provenance(r1_liquid_remains_in_destination, antecedent, a1).
provenance(r1_liquid_remains_in_destination, parent, none).
provenance(r1_liquid_remains_in_destination, simulations, 35).
provenance(r1_liquid_remains_in_destination, weight_mass_permille, 28400).
provenance(r1_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r1_liquid_remains_in_destination, score_permille, 1000).
provenance(r1_liquid_remains_in_destination, batches, 1).

rule(r1_no_spill, defeasible, no_spill).
body(r1_no_spill, pour_mid_height).
body(r1_no_spill, pour_near_rim).
body(r1_no_spill, pour_steeply_tilted).
learned(r1_no_spill).
provenance(r1_no_spill, antecedent, a1).
provenance(r1_no_spill, parent, none).
provenance(r1_no_spill, simulations, 35).
provenance(r1_no_spill, weight_mass_permille, 28400).
provenance(r1_no_spill, confidence_permille, 1000).
provenance(r1_no_spill, score_permille, 991).
provenance(r1_no_spill, batches, 1).

rule(r2_destination_still_approach, defeasible, destination_still_approach).
body(r2_destination_still_approach, approach_moving_away).
body(r2_destination_still_approach, dull_liquid).
body(r2_destination_still_approach, end_rolled).
body(r2_destination_still_approach, end_steeply_tilted).
body(r2_destination_still_approach, grippy_destination).
body(r2_destination_still_approach, heavy_destination).
body(r2_destination_still_approach, light_liquid).
body(r2_destination_still_approach, much_liquid).
body(r2_destination_still_approach, pour_rolled).
body(r2_destination_still_approach, pour_tilted_back).
body(r2_destination_still_approach, pour_very_high).
body(r2_destination_still_approach, retreat_lowering).
body(r2_destination_still_approach, retreat_moving_closer).
body(r2_destination_still_approach, slippery_source).
body(r2_destination_still_approach, slow_approach).
body(r2_destination_still_approach, slow_retreat).
body(r2_destination_still_approach, start_slightly_tilted).
learned(r2_destination_still_approach).
provenance(r2_destination_still_approach, antecedent, a2).
provenance(r2_destination_still_approach, parent, none).
provenance(r2_destination_still_approach, simulations, 31).
provenance(r2_destination_still_approach, weight_mass_permille, 31000).
provenance(r2_destination_still_approach, confidence_permille, 1000).
provenance(r2_destination_still_approach, score_permille, 993).
provenance(r2_destination_still_approach, batches, 1).

rule(r2_destination_still_retreat, defeasible, destination_still_retreat).
body(r2_destination_still_retreat, approach_moving_away).
body(r2_destination_still_retreat, dull_liquid).
body(r2_destination_still_retreat, end_rolled).
body(r2_destination_still_retreat, end_steeply_tilted).
body(r2_destination_still_retreat, grippy_destination).
body(r2_destination_still_retreat, heavy_destination).
body(r2_destination_still_retreat, light_liquid).
body(r2_destination_still_retreat, much_liquid).
body(r2_destination_still_retreat, pour_rolled).
body(r2_destination_still_retreat, pour_tilted_back).
body(r2_destination_still_retreat, pour_very_high).
body(r2_destination_still_retreat, retreat_lowering).
body(r2_destination_still_retreat, retreat_moving_closer).
body(r2_destination_still_retreat, slippery_source).
body(r2_destination_still_retreat, slow_approach).
body(r2_destination_still_retreat, slow_retreat).
body(r2_destination_still_retreat, start_slightly_tilted).
learned(r2_destination_still_retreat).
provenance(r2_destination_still_retreat, antecedent, a2).
provenance(r2_destination_still_retreat, parent, none).
provenance(r2_destination_still_retreat, simulations, 31).
provenance(r2_destination_still_retreat, weight_mass_permille, 31000).
provenance(r2_destination_still_retreat, confidence_permille, 1000).
provenance(r2_destination_still_retreat, score_permille, 1000).
provenance(r2_destination_still_retreat, batches, 1).

rule(r2_destination_still_settle, defeasible, destination_still_settle).
body(r2_destination_still_settle, approach_moving_away).
body(r2_destination_still_settle, dull_liquid).
body(r2_destination_still_settle, end_rolled).
body(r2_destination_still_settle, end_steeply_tilted).
body(r2_destination_still_settle, grippy_destination).
body(r2_destination_still_settle, heavy_destination).
body(r2_destination_still_settle, light_liquid).
body(r2_destination_still_settle, much_liquid).
body(r2_destination_still_settle, pour_rolled).
body(r2_destination_still_settle, pour_tilted_back).
body(r2_destination_still_settle, pour_very_high).
body(r2_destination_still_settle, retreat_lowering).
body(r2_destination_still_settle, retreat_moving_closer).
body(r2_destination_still_settle, slippery_source).
body(r2_destination_still_settle, slow_approach).
body(r2_destination_still_settle, slow_retreat).
body(r2_destination_still_settle, start_slightly_tilted).
learned(r2_destination_still_settle).
provenance(r2_destination_still_settle, antecedent, a2).
provenance(r2_destination_still_settle, parent, none).
provenance(r2_destination_still_settle, simulations, 31).
provenance(r2_destination_still_settle, weight_mass_permille, 31000).
provenance(r2_destination_still_settle, confidence_permille, 1000).
provenance(r2_destination_still_settle, score_permille, 1000).
provenance(r2_destination_still_settle, batches, 1).

rule(r2_destination_upright, defeasible, destination_upright).
body(r2_destination_upright, approach_moving_away).
body(r2_destination_upright, dull_liquid).
body(r2_destination_upright, end_rolled).
body(r2_destination_upright, end_steeply_tilted).
body(r2_destination_upright, grippy_destination).
body(r2_destination_upright, heavy_destination).
body(r2_destination_upright, light_liquid).
body(r2_destination_upright, much_liquid).
body(r2_destination_upright, pour_rolled).
body(r2_destination_upright, pour_tilted_back).
body(r2_destination_upright, pour_very_high).
body(r2_destination_upright, retreat_lowering).
body(r2_destination_upright, retreat_moving_closer).
body(r2_destination_upright, slippery_source).
body(r2_destination_upright, slow_approach).
body(r2_destination_upright, slow_retreat).
body(r2_destination_upright, start_slightly_tilted).
learned(r2_destination_upright).
provenance(r2_destination_upright, antecedent, a2).
provenance(r2_destination_upright, parent, none).
provenance(r2_destination_upright, simulations, 31).
provenance(r2_destination_upright, weight_mass_permille, 31000).
provenance(r2_destination_upright, confidence_permille, 1000).
provenance(r2_destination_upright, score_permille, 1000).
provenance(r2_destination_upright, batches, 1).

rule(r2_source_clear, defeasible, source_clear).
body(r2_source_clear, approach_moving_away).
body(r2_source_clear, dull_liquid).
body(r2_source_clear, end_rolled).
body(r2_source_clear, end_steeply_tilted).
body(r2_source_clear, grippy_destination).
body(r2_source_clear, heavy_destination).
body(r2_source_clear, light_liquid).
body(r2_source_clear, much_liquid).
body(r2_source_clear, pour_rolled).
body(r2_source_clear, pour_tilted_back).
body(r2_source_clear, pour_very_high).
body(r2_source_clear, retreat_lowering).
body(r2_source_clear, retreat_moving_closer).
body(r2_source_clear, slippery_source).
body(r2_source_clear, slow_approach).
body(r2_source_clear, slow_retreat).
body(r2_source_clear, start_slightly_tilted).
learned(r2_source_clear).
provenance(r2_source_clear, antecedent, a2).
provenance(r2_source_clear, parent, none).
provenance(r2_source_clear, simulations, 31).
provenance(r2_source_clear, weight_mass_permille, 31000).
provenance(r2_source_clear, confidence_permille, 1000).
provenance(r2_source_clear, score_permille, 1000).
provenance(r2_source_clear, batches, 1).

rule(r2_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r2_liquid_leaves_source, approach_moving_away).
body(r2_liquid_leaves_source, dull_liquid).
body(r2_liquid_leaves_source, end_rolled).
body(r2_liquid_leaves_source, end_steeply_tilted).
body(r2_liquid_leaves_source, grippy_destination).
body(r2_liquid_leaves_source, heavy_destination).
body(r2_liquid_leaves_source, light_liquid).
body(r2_liquid_leaves_source, much_liquid).
body(r2_liquid_leaves_source, pour_rolled).
body(r2_liquid_leaves_source, pour_tilted_back).
body(r2_liquid_leaves_source, pour_very_high).
body(r2_liquid_leaves_source, retreat_lowering).
body(r2_liquid_leaves_source, retreat_moving_closer).
body(r2_liquid_leaves_source, slippery_source).
body(r2_liquid_leaves_source, slow_approach).
body(r2_liquid_leaves_source, slow_retreat).
body(r2_liquid_leaves_source, start_slightly_tilted).
learned(r2_liquid_leaves_source).
provenance(r2_liquid_leaves_source, antecedent, a2).
provenance(r2_liquid_leaves_source, parent, none).
provenance(r2_liquid_leaves_source, simulations, 31).
provenance(r2_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r2_liquid_leaves_source, confidence_permille, 968).
provenance(r2_liquid_leaves_source, score_permille, 935).
provenance(r2_liquid_leaves_source, batches, 1).

rule(r2_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r2_liquid_enters_destination, approach_moving_away).
body(r2_liquid_enters_destination, dull_liquid).
body(r2_liquid_enters_destination, end_rolled).
body(r2_liquid_enters_destination, end_steeply_tilted).
body(r2_liquid_enters_destination, grippy_destination).
body(r2_liquid_enters_destination, heavy_destination).
body(r2_liquid_enters_destination, light_liquid).
body(r2_liquid_enters_destination, much_liquid).
body(r2_liquid_enters_destination, pour_rolled).
body(r2_liquid_enters_destination, pour_tilted_back).
body(r2_liquid_enters_destination, pour_very_high).
body(r2_liquid_enters_destination, retreat_lowering).
body(r2_liquid_enters_destination, retreat_moving_closer).
body(r2_liquid_enters_destination, slippery_source).
body(r2_liquid_enters_destination, slow_approach).
body(r2_liquid_enters_destination, slow_retreat).
body(r2_liquid_enters_destination, start_slightly_tilted).
learned(r2_liquid_enters_destination).
provenance(r2_liquid_enters_destination, antecedent, a2).
provenance(r2_liquid_enters_destination, parent, none).
provenance(r2_liquid_enters_destination, simulations, 31).
provenance(r2_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r2_liquid_enters_destination, confidence_permille, 935).
provenance(r2_liquid_enters_destination, score_permille, 87).
provenance(r2_liquid_enters_destination, batches, 1).

rule(r2_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r2_liquid_remains_in_destination, approach_moving_away).
body(r2_liquid_remains_in_destination, dull_liquid).
body(r2_liquid_remains_in_destination, end_rolled).
body(r2_liquid_remains_in_destination, end_steeply_tilted).
body(r2_liquid_remains_in_destination, grippy_destination).
body(r2_liquid_remains_in_destination, heavy_destination).
body(r2_liquid_remains_in_destination, light_liquid).
body(r2_liquid_remains_in_destination, much_liquid).
body(r2_liquid_remains_in_destination, pour_rolled).
body(r2_liquid_remains_in_destination, pour_tilted_back).
body(r2_liquid_remains_in_destination, pour_very_high).
body(r2_liquid_remains_in_destination, retreat_lowering).
body(r2_liquid_remains_in_destination, retreat_moving_closer).
body(r2_liquid_remains_in_destination, slippery_source).
body(r2_liquid_remains_in_destination, slow_approach).
body(r2_liquid_remains_in_destination, slow_retreat).
body(r2_liquid_remains_in_destination, start_slightly_tilted).
learned(r2_liquid_remains_in_destination).
provenance(r2_liquid_remains_in_destination, antecedent, a2).
provenance(r2_liquid_remains_in_destination, parent, none).
provenance(r2_liquid_remains_in_destination, simulations, 31).
provenance(r2_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r2_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r2_liquid_remains_in_destination, score_permille, 1000).
provenance(r2_liquid_remains_in_destination, batches, 1).

rule(r2_no_spill, defeasible, neg(no_spill)).
body(r2_no_spill, approach_moving_away).
body(r2_no_spill, dull_liquid).
body(r2_no_spill, end_rolled).
body(r2_no_spill, end_steeply_tilted).
body(r2_no_spill, grippy_destination).
body(r2_no_spill, heavy_destination).
body(r2_no_spill, light_liquid).
body(r2_no_spill, much_liquid).
body(r2_no_spill, pour_rolled).
body(r2_no_spill, pour_tilted_back).
body(r2_no_spill, pour_very_high).
body(r2_no_spill, retreat_lowering).
body(r2_no_spill, retreat_moving_closer).
body(r2_no_spill, slippery_source).
body(r2_no_spill, slow_approach).
body(r2_no_spill, slow_retreat).
body(r2_no_spill, start_slightly_tilted).
learned(r2_no_spill).
provenance(r2_no_spill, antecedent, a2).
provenance(r2_no_spill, parent, none).
provenance(r2_no_spill, simulations, 31).
provenance(r2_no_spill, weight_mass_permille, 31000).
provenance(r2_no_spill, confidence_permille, 903).
provenance(r2_no_spill, score_permille, 152).
provenance(r2_no_spill, batches, 1).

rule(r3_destination_still_approach, defeasible, destination_still_approach).
body(r3_destination_still_approach, approach_lowering).
body(r3_destination_still_approach, dull_source).
body(r3_destination_still_approach, end_slightly_tilted).
body(r3_destination_still_approach, end_to_side).
body(r3_destination_still_approach, fast_approach).
body(r3_destination_still_approach, grippy_source).
body(r3_destination_still_approach, heavy_source).
body(r3_destination_still_approach, light_destination).
body(r3_destination_still_approach, medium_liquid).
body(r3_destination_still_approach, pour_centred).
body(r3_destination_still_approach, pour_half_tilted).
body(r3_destination_still_approach, pour_high).
body(r3_destination_still_approach, pour_in_line).
body(r3_destination_still_approach, pour_level).
body(r3_destination_still_approach, runny_liquid).
body(r3_destination_still_approach, slippery_destination).
body(r3_destination_still_approach, some_liquid).
body(r3_destination_still_approach, start_centred).
learned(r3_destination_still_approach).
provenance(r3_destination_still_approach, antecedent, a3).
provenance(r3_destination_still_approach, parent, none).
provenance(r3_destination_still_approach, simulations, 31).
provenance(r3_destination_still_approach, weight_mass_permille, 31000).
provenance(r3_destination_still_approach, confidence_permille, 1000).
provenance(r3_destination_still_approach, score_permille, 993).
provenance(r3_destination_still_approach, batches, 1).

rule(r3_destination_still_retreat, defeasible, destination_still_retreat).
body(r3_destination_still_retreat, approach_lowering).
body(r3_destination_still_retreat, dull_source).
body(r3_destination_still_retreat, end_slightly_tilted).
body(r3_destination_still_retreat, end_to_side).
body(r3_destination_still_retreat, fast_approach).
body(r3_destination_still_retreat, grippy_source).
body(r3_destination_still_retreat, heavy_source).
body(r3_destination_still_retreat, light_destination).
body(r3_destination_still_retreat, medium_liquid).
body(r3_destination_still_retreat, pour_centred).
body(r3_destination_still_retreat, pour_half_tilted).
body(r3_destination_still_retreat, pour_high).
body(r3_destination_still_retreat, pour_in_line).
body(r3_destination_still_retreat, pour_level).
body(r3_destination_still_retreat, runny_liquid).
body(r3_destination_still_retreat, slippery_destination).
body(r3_destination_still_retreat, some_liquid).
body(r3_destination_still_retreat, start_centred).
learned(r3_destination_still_retreat).
provenance(r3_destination_still_retreat, antecedent, a3).
provenance(r3_destination_still_retreat, parent, none).
provenance(r3_destination_still_retreat, simulations, 31).
provenance(r3_destination_still_retreat, weight_mass_permille, 31000).
provenance(r3_destination_still_retreat, confidence_permille, 1000).
provenance(r3_destination_still_retreat, score_permille, 1000).
provenance(r3_destination_still_retreat, batches, 1).

rule(r3_destination_still_settle, defeasible, destination_still_settle).
body(r3_destination_still_settle, approach_lowering).
body(r3_destination_still_settle, dull_source).
body(r3_destination_still_settle, end_slightly_tilted).
body(r3_destination_still_settle, end_to_side).
body(r3_destination_still_settle, fast_approach).
body(r3_destination_still_settle, grippy_source).
body(r3_destination_still_settle, heavy_source).
body(r3_destination_still_settle, light_destination).
body(r3_destination_still_settle, medium_liquid).
body(r3_destination_still_settle, pour_centred).
body(r3_destination_still_settle, pour_half_tilted).
body(r3_destination_still_settle, pour_high).
body(r3_destination_still_settle, pour_in_line).
body(r3_destination_still_settle, pour_level).
body(r3_destination_still_settle, runny_liquid).
body(r3_destination_still_settle, slippery_destination).
body(r3_destination_still_settle, some_liquid).
body(r3_destination_still_settle, start_centred).
learned(r3_destination_still_settle).
provenance(r3_destination_still_settle, antecedent, a3).
provenance(r3_destination_still_settle, parent, none).
provenance(r3_destination_still_settle, simulations, 31).
provenance(r3_destination_still_settle, weight_mass_permille, 31000).
provenance(r3_destination_still_settle, confidence_permille, 1000).
provenance(r3_destination_still_settle, score_permille, 1000).
provenance(r3_destination_still_settle, batches, 1).

rule(r3_destination_upright, defeasible, destination_upright).
body(r3_destination_upright, approach_lowering).
body(r3_destination_upright, dull_source).
body(r3_destination_upright, end_slightly_tilted).
body(r3_destination_upright, end_to_side).
body(r3_destination_upright, fast_approach).
body(r3_destination_upright, grippy_source).
body(r3_destination_upright, heavy_source).
body(r3_destination_upright, light_destination).
body(r3_destination_upright, medium_liquid).
body(r3_destination_upright, pour_centred).
body(r3_destination_upright, pour_half_tilted).
body(r3_destination_upright, pour_high).
body(r3_destination_upright, pour_in_line).
body(r3_destination_upright, pour_level).
body(r3_destination_upright, runny_liquid).
body(r3_destination_upright, slippery_destination).
body(r3_destination_upright, some_liquid).
body(r3_destination_upright, start_centred).
learned(r3_destination_upright).
provenance(r3_destination_upright, antecedent, a3).
provenance(r3_destination_upright, parent, none).
provenance(r3_destination_upright, simulations, 31).
provenance(r3_destination_upright, weight_mass_permille, 31000).
provenance(r3_destination_upright, confidence_permille, 1000).
provenance(r3_destination_upright, score_permille, 1000).
provenance(r3_destination_upright, batches, 1).

rule(r3_source_clear, defeasible, source_clear).
body(r3_source_clear, approach_lowering).
body(r3_source_clear, dull_source).
body(r3_source_clear, end_slightly_tilted).
body(r3_source_clear, end_to_side).
body(r3_source_clear, fast_approach).
body(r3_source_clear, grippy_source).
body(r3_source_clear, heavy_source).
body(r3_source_clear, light_destination).
body(r3_source_clear, medium_liquid).
body(r3_source_clear, pour_centred).
body(r3_source_clear, pour_half_tilted).
body(r3_source_clear, pour_high).
body(r3_source_clear, pour_in_line).
body(r3_source_clear, pour_level).
body(r3_source_clear, runny_liquid).
body(r3_source_clear, slippery_destination).
body(r3_source_clear, some_liquid).
body(r3_source_clear, start_centred).
learned(r3_source_clear).
provenance(r3_source_clear, antecedent, a3).
provenance(r3_source_clear, parent, none).
provenance(r3_source_clear, simulations, 31).
provenance(r3_source_clear, weight_mass_permille, 31000).
provenance(r3_source_clear, confidence_permille, 1000).
provenance(r3_source_clear, score_permille, 1000).
provenance(r3_source_clear, batches, 1).

rule(r3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r3_liquid_leaves_source, approach_lowering).
body(r3_liquid_leaves_source, dull_source).
body(r3_liquid_leaves_source, end_slightly_tilted).
body(r3_liquid_leaves_source, end_to_side).
body(r3_liquid_leaves_source, fast_approach).
body(r3_liquid_leaves_source, grippy_source).
body(r3_liquid_leaves_source, heavy_source).
body(r3_liquid_leaves_source, light_destination).
body(r3_liquid_leaves_source, medium_liquid).
body(r3_liquid_leaves_source, pour_centred).
body(r3_liquid_leaves_source, pour_half_tilted).
body(r3_liquid_leaves_source, pour_high).
body(r3_liquid_leaves_source, pour_in_line).
body(r3_liquid_leaves_source, pour_level).
body(r3_liquid_leaves_source, runny_liquid).
body(r3_liquid_leaves_source, slippery_destination).
body(r3_liquid_leaves_source, some_liquid).
body(r3_liquid_leaves_source, start_centred).
learned(r3_liquid_leaves_source).
provenance(r3_liquid_leaves_source, antecedent, a3).
provenance(r3_liquid_leaves_source, parent, none).
provenance(r3_liquid_leaves_source, simulations, 31).
provenance(r3_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r3_liquid_leaves_source, confidence_permille, 1000).
provenance(r3_liquid_leaves_source, score_permille, 1).
provenance(r3_liquid_leaves_source, batches, 1).

rule(r3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r3_liquid_enters_destination, approach_lowering).
body(r3_liquid_enters_destination, dull_source).
body(r3_liquid_enters_destination, end_slightly_tilted).
body(r3_liquid_enters_destination, end_to_side).
body(r3_liquid_enters_destination, fast_approach).
body(r3_liquid_enters_destination, grippy_source).
body(r3_liquid_enters_destination, heavy_source).
body(r3_liquid_enters_destination, light_destination).
body(r3_liquid_enters_destination, medium_liquid).
body(r3_liquid_enters_destination, pour_centred).
body(r3_liquid_enters_destination, pour_half_tilted).
body(r3_liquid_enters_destination, pour_high).
body(r3_liquid_enters_destination, pour_in_line).
body(r3_liquid_enters_destination, pour_level).
body(r3_liquid_enters_destination, runny_liquid).
body(r3_liquid_enters_destination, slippery_destination).
body(r3_liquid_enters_destination, some_liquid).
body(r3_liquid_enters_destination, start_centred).
learned(r3_liquid_enters_destination).
provenance(r3_liquid_enters_destination, antecedent, a3).
provenance(r3_liquid_enters_destination, parent, none).
provenance(r3_liquid_enters_destination, simulations, 31).
provenance(r3_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r3_liquid_enters_destination, confidence_permille, 1000).
provenance(r3_liquid_enters_destination, score_permille, 0).
provenance(r3_liquid_enters_destination, batches, 1).

rule(r3_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r3_liquid_remains_in_destination, approach_lowering).
body(r3_liquid_remains_in_destination, dull_source).
body(r3_liquid_remains_in_destination, end_slightly_tilted).
body(r3_liquid_remains_in_destination, end_to_side).
body(r3_liquid_remains_in_destination, fast_approach).
body(r3_liquid_remains_in_destination, grippy_source).
body(r3_liquid_remains_in_destination, heavy_source).
body(r3_liquid_remains_in_destination, light_destination).
body(r3_liquid_remains_in_destination, medium_liquid).
body(r3_liquid_remains_in_destination, pour_centred).
body(r3_liquid_remains_in_destination, pour_half_tilted).
body(r3_liquid_remains_in_destination, pour_high).
body(r3_liquid_remains_in_destination, pour_in_line).
body(r3_liquid_remains_in_destination, pour_level).
body(r3_liquid_remains_in_destination, runny_liquid).
body(r3_liquid_remains_in_destination, slippery_destination).
body(r3_liquid_remains_in_destination, some_liquid).
body(r3_liquid_remains_in_destination, start_centred).
learned(r3_liquid_remains_in_destination).
provenance(r3_liquid_remains_in_destination, antecedent, a3).
provenance(r3_liquid_remains_in_destination, parent, none).
provenance(r3_liquid_remains_in_destination, simulations, 31).
provenance(r3_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r3_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r3_liquid_remains_in_destination, score_permille, 1000).
provenance(r3_liquid_remains_in_destination, batches, 1).

rule(r3_no_spill, defeasible, no_spill).
body(r3_no_spill, approach_lowering).
body(r3_no_spill, dull_source).
body(r3_no_spill, end_slightly_tilted).
body(r3_no_spill, end_to_side).
body(r3_no_spill, fast_approach).
body(r3_no_spill, grippy_source).
body(r3_no_spill, heavy_source).
body(r3_no_spill, light_destination).
body(r3_no_spill, medium_liquid).
body(r3_no_spill, pour_centred).
body(r3_no_spill, pour_half_tilted).
body(r3_no_spill, pour_high).
body(r3_no_spill, pour_in_line).
body(r3_no_spill, pour_level).
body(r3_no_spill, runny_liquid).
body(r3_no_spill, slippery_destination).
body(r3_no_spill, some_liquid).
body(r3_no_spill, start_centred).
learned(r3_no_spill).
provenance(r3_no_spill, antecedent, a3).
provenance(r3_no_spill, parent, none).
provenance(r3_no_spill, simulations, 31).
provenance(r3_no_spill, weight_mass_permille, 31000).
provenance(r3_no_spill, confidence_permille, 1000).
provenance(r3_no_spill, score_permille, 999).
provenance(r3_no_spill, batches, 1).

rule(r4_destination_still_approach, defeasible, destination_still_approach).
body(r4_destination_still_approach, approach_moving_away).
body(r4_destination_still_approach, bouncy_destination).
body(r4_destination_still_approach, bouncy_liquid).
body(r4_destination_still_approach, end_high).
body(r4_destination_still_approach, end_level).
body(r4_destination_still_approach, end_upside_down).
body(r4_destination_still_approach, grippy_destination).
body(r4_destination_still_approach, grippy_source).
body(r4_destination_still_approach, heavy_source).
body(r4_destination_still_approach, medium_liquid).
body(r4_destination_still_approach, pour_high).
body(r4_destination_still_approach, pour_near_rim).
body(r4_destination_still_approach, pour_offset_sideways).
body(r4_destination_still_approach, pour_upright).
body(r4_destination_still_approach, slow_approach).
body(r4_destination_still_approach, slow_retreat).
body(r4_destination_still_approach, start_high).
body(r4_destination_still_approach, start_upright).
learned(r4_destination_still_approach).
provenance(r4_destination_still_approach, antecedent, a4).
provenance(r4_destination_still_approach, parent, none).
provenance(r4_destination_still_approach, simulations, 31).
provenance(r4_destination_still_approach, weight_mass_permille, 31000).
provenance(r4_destination_still_approach, confidence_permille, 1000).
provenance(r4_destination_still_approach, score_permille, 993).
provenance(r4_destination_still_approach, batches, 1).

rule(r4_destination_still_retreat, defeasible, destination_still_retreat).
body(r4_destination_still_retreat, approach_moving_away).
body(r4_destination_still_retreat, bouncy_destination).
body(r4_destination_still_retreat, bouncy_liquid).
body(r4_destination_still_retreat, end_high).
body(r4_destination_still_retreat, end_level).
body(r4_destination_still_retreat, end_upside_down).
body(r4_destination_still_retreat, grippy_destination).
body(r4_destination_still_retreat, grippy_source).
body(r4_destination_still_retreat, heavy_source).
body(r4_destination_still_retreat, medium_liquid).
body(r4_destination_still_retreat, pour_high).
body(r4_destination_still_retreat, pour_near_rim).
body(r4_destination_still_retreat, pour_offset_sideways).
body(r4_destination_still_retreat, pour_upright).
body(r4_destination_still_retreat, slow_approach).
body(r4_destination_still_retreat, slow_retreat).
body(r4_destination_still_retreat, start_high).
body(r4_destination_still_retreat, start_upright).
learned(r4_destination_still_retreat).
provenance(r4_destination_still_retreat, antecedent, a4).
provenance(r4_destination_still_retreat, parent, none).
provenance(r4_destination_still_retreat, simulations, 31).
provenance(r4_destination_still_retreat, weight_mass_permille, 31000).
provenance(r4_destination_still_retreat, confidence_permille, 1000).
provenance(r4_destination_still_retreat, score_permille, 966).
provenance(r4_destination_still_retreat, batches, 1).

rule(r4_destination_still_settle, defeasible, destination_still_settle).
body(r4_destination_still_settle, approach_moving_away).
body(r4_destination_still_settle, bouncy_destination).
body(r4_destination_still_settle, bouncy_liquid).
body(r4_destination_still_settle, end_high).
body(r4_destination_still_settle, end_level).
body(r4_destination_still_settle, end_upside_down).
body(r4_destination_still_settle, grippy_destination).
body(r4_destination_still_settle, grippy_source).
body(r4_destination_still_settle, heavy_source).
body(r4_destination_still_settle, medium_liquid).
body(r4_destination_still_settle, pour_high).
body(r4_destination_still_settle, pour_near_rim).
body(r4_destination_still_settle, pour_offset_sideways).
body(r4_destination_still_settle, pour_upright).
body(r4_destination_still_settle, slow_approach).
body(r4_destination_still_settle, slow_retreat).
body(r4_destination_still_settle, start_high).
body(r4_destination_still_settle, start_upright).
learned(r4_destination_still_settle).
provenance(r4_destination_still_settle, antecedent, a4).
provenance(r4_destination_still_settle, parent, none).
provenance(r4_destination_still_settle, simulations, 31).
provenance(r4_destination_still_settle, weight_mass_permille, 31000).
provenance(r4_destination_still_settle, confidence_permille, 1000).
provenance(r4_destination_still_settle, score_permille, 996).
provenance(r4_destination_still_settle, batches, 1).

rule(r4_destination_upright, defeasible, destination_upright).
body(r4_destination_upright, approach_moving_away).
body(r4_destination_upright, bouncy_destination).
body(r4_destination_upright, bouncy_liquid).
body(r4_destination_upright, end_high).
body(r4_destination_upright, end_level).
body(r4_destination_upright, end_upside_down).
body(r4_destination_upright, grippy_destination).
body(r4_destination_upright, grippy_source).
body(r4_destination_upright, heavy_source).
body(r4_destination_upright, medium_liquid).
body(r4_destination_upright, pour_high).
body(r4_destination_upright, pour_near_rim).
body(r4_destination_upright, pour_offset_sideways).
body(r4_destination_upright, pour_upright).
body(r4_destination_upright, slow_approach).
body(r4_destination_upright, slow_retreat).
body(r4_destination_upright, start_high).
body(r4_destination_upright, start_upright).
learned(r4_destination_upright).
provenance(r4_destination_upright, antecedent, a4).
provenance(r4_destination_upright, parent, none).
provenance(r4_destination_upright, simulations, 31).
provenance(r4_destination_upright, weight_mass_permille, 31000).
provenance(r4_destination_upright, confidence_permille, 1000).
provenance(r4_destination_upright, score_permille, 1000).
provenance(r4_destination_upright, batches, 1).

rule(r4_source_clear, defeasible, source_clear).
body(r4_source_clear, approach_moving_away).
body(r4_source_clear, bouncy_destination).
body(r4_source_clear, bouncy_liquid).
body(r4_source_clear, end_high).
body(r4_source_clear, end_level).
body(r4_source_clear, end_upside_down).
body(r4_source_clear, grippy_destination).
body(r4_source_clear, grippy_source).
body(r4_source_clear, heavy_source).
body(r4_source_clear, medium_liquid).
body(r4_source_clear, pour_high).
body(r4_source_clear, pour_near_rim).
body(r4_source_clear, pour_offset_sideways).
body(r4_source_clear, pour_upright).
body(r4_source_clear, slow_approach).
body(r4_source_clear, slow_retreat).
body(r4_source_clear, start_high).
body(r4_source_clear, start_upright).
learned(r4_source_clear).
provenance(r4_source_clear, antecedent, a4).
provenance(r4_source_clear, parent, none).
provenance(r4_source_clear, simulations, 31).
provenance(r4_source_clear, weight_mass_permille, 31000).
provenance(r4_source_clear, confidence_permille, 1000).
provenance(r4_source_clear, score_permille, 1000).
provenance(r4_source_clear, batches, 1).

rule(r4_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r4_liquid_leaves_source, approach_moving_away).
body(r4_liquid_leaves_source, bouncy_destination).
body(r4_liquid_leaves_source, bouncy_liquid).
body(r4_liquid_leaves_source, end_high).
body(r4_liquid_leaves_source, end_level).
body(r4_liquid_leaves_source, end_upside_down).
body(r4_liquid_leaves_source, grippy_destination).
body(r4_liquid_leaves_source, grippy_source).
body(r4_liquid_leaves_source, heavy_source).
body(r4_liquid_leaves_source, medium_liquid).
body(r4_liquid_leaves_source, pour_high).
body(r4_liquid_leaves_source, pour_near_rim).
body(r4_liquid_leaves_source, pour_offset_sideways).
body(r4_liquid_leaves_source, pour_upright).
body(r4_liquid_leaves_source, slow_approach).
body(r4_liquid_leaves_source, slow_retreat).
body(r4_liquid_leaves_source, start_high).
body(r4_liquid_leaves_source, start_upright).
learned(r4_liquid_leaves_source).
provenance(r4_liquid_leaves_source, antecedent, a4).
provenance(r4_liquid_leaves_source, parent, none).
provenance(r4_liquid_leaves_source, simulations, 31).
provenance(r4_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r4_liquid_leaves_source, confidence_permille, 1000).
provenance(r4_liquid_leaves_source, score_permille, 1000).
provenance(r4_liquid_leaves_source, batches, 1).

rule(r4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r4_liquid_enters_destination, approach_moving_away).
body(r4_liquid_enters_destination, bouncy_destination).
body(r4_liquid_enters_destination, bouncy_liquid).
body(r4_liquid_enters_destination, end_high).
body(r4_liquid_enters_destination, end_level).
body(r4_liquid_enters_destination, end_upside_down).
body(r4_liquid_enters_destination, grippy_destination).
body(r4_liquid_enters_destination, grippy_source).
body(r4_liquid_enters_destination, heavy_source).
body(r4_liquid_enters_destination, medium_liquid).
body(r4_liquid_enters_destination, pour_high).
body(r4_liquid_enters_destination, pour_near_rim).
body(r4_liquid_enters_destination, pour_offset_sideways).
body(r4_liquid_enters_destination, pour_upright).
body(r4_liquid_enters_destination, slow_approach).
body(r4_liquid_enters_destination, slow_retreat).
body(r4_liquid_enters_destination, start_high).
body(r4_liquid_enters_destination, start_upright).
learned(r4_liquid_enters_destination).
provenance(r4_liquid_enters_destination, antecedent, a4).
provenance(r4_liquid_enters_destination, parent, none).
provenance(r4_liquid_enters_destination, simulations, 31).
provenance(r4_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r4_liquid_enters_destination, confidence_permille, 903).
provenance(r4_liquid_enters_destination, score_permille, 149).
provenance(r4_liquid_enters_destination, batches, 1).

rule(r4_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r4_liquid_remains_in_destination, approach_moving_away).
body(r4_liquid_remains_in_destination, bouncy_destination).
body(r4_liquid_remains_in_destination, bouncy_liquid).
body(r4_liquid_remains_in_destination, end_high).
body(r4_liquid_remains_in_destination, end_level).
body(r4_liquid_remains_in_destination, end_upside_down).
body(r4_liquid_remains_in_destination, grippy_destination).
body(r4_liquid_remains_in_destination, grippy_source).
body(r4_liquid_remains_in_destination, heavy_source).
body(r4_liquid_remains_in_destination, medium_liquid).
body(r4_liquid_remains_in_destination, pour_high).
body(r4_liquid_remains_in_destination, pour_near_rim).
body(r4_liquid_remains_in_destination, pour_offset_sideways).
body(r4_liquid_remains_in_destination, pour_upright).
body(r4_liquid_remains_in_destination, slow_approach).
body(r4_liquid_remains_in_destination, slow_retreat).
body(r4_liquid_remains_in_destination, start_high).
body(r4_liquid_remains_in_destination, start_upright).
learned(r4_liquid_remains_in_destination).
provenance(r4_liquid_remains_in_destination, antecedent, a4).
provenance(r4_liquid_remains_in_destination, parent, none).
provenance(r4_liquid_remains_in_destination, simulations, 31).
provenance(r4_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r4_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r4_liquid_remains_in_destination, score_permille, 948).
provenance(r4_liquid_remains_in_destination, batches, 1).

rule(r4_no_spill, defeasible, neg(no_spill)).
body(r4_no_spill, approach_moving_away).
body(r4_no_spill, bouncy_destination).
body(r4_no_spill, bouncy_liquid).
body(r4_no_spill, end_high).
body(r4_no_spill, end_level).
body(r4_no_spill, end_upside_down).
body(r4_no_spill, grippy_destination).
body(r4_no_spill, grippy_source).
body(r4_no_spill, heavy_source).
body(r4_no_spill, medium_liquid).
body(r4_no_spill, pour_high).
body(r4_no_spill, pour_near_rim).
body(r4_no_spill, pour_offset_sideways).
body(r4_no_spill, pour_upright).
body(r4_no_spill, slow_approach).
body(r4_no_spill, slow_retreat).
body(r4_no_spill, start_high).
body(r4_no_spill, start_upright).
learned(r4_no_spill).
provenance(r4_no_spill, antecedent, a4).
provenance(r4_no_spill, parent, none).
provenance(r4_no_spill, simulations, 31).
provenance(r4_no_spill, weight_mass_permille, 31000).
provenance(r4_no_spill, confidence_permille, 935).
provenance(r4_no_spill, score_permille, 136).
provenance(r4_no_spill, batches, 1).

rule(r5_destination_still_approach, defeasible, destination_still_approach).
body(r5_destination_still_approach, grippy_destination).
body(r5_destination_still_approach, pour_mid_height).
body(r5_destination_still_approach, pour_near_rim).
body(r5_destination_still_approach, pour_steeply_tilted).
learned(r5_destination_still_approach).
provenance(r5_destination_still_approach, antecedent, a5).
provenance(r5_destination_still_approach, parent, a1).
provenance(r5_destination_still_approach, simulations, 31).
provenance(r5_destination_still_approach, weight_mass_permille, 31000).
provenance(r5_destination_still_approach, confidence_permille, 1000).
provenance(r5_destination_still_approach, score_permille, 991).
provenance(r5_destination_still_approach, batches, 1).

rule(r5_destination_still_retreat, defeasible, destination_still_retreat).
body(r5_destination_still_retreat, grippy_destination).
body(r5_destination_still_retreat, pour_mid_height).
body(r5_destination_still_retreat, pour_near_rim).
body(r5_destination_still_retreat, pour_steeply_tilted).
learned(r5_destination_still_retreat).
provenance(r5_destination_still_retreat, antecedent, a5).
provenance(r5_destination_still_retreat, parent, a1).
provenance(r5_destination_still_retreat, simulations, 31).
provenance(r5_destination_still_retreat, weight_mass_permille, 31000).
provenance(r5_destination_still_retreat, confidence_permille, 1000).
provenance(r5_destination_still_retreat, score_permille, 986).
provenance(r5_destination_still_retreat, batches, 1).

rule(r5_destination_still_settle, defeasible, destination_still_settle).
body(r5_destination_still_settle, grippy_destination).
body(r5_destination_still_settle, pour_mid_height).
body(r5_destination_still_settle, pour_near_rim).
body(r5_destination_still_settle, pour_steeply_tilted).
learned(r5_destination_still_settle).
provenance(r5_destination_still_settle, antecedent, a5).
provenance(r5_destination_still_settle, parent, a1).
provenance(r5_destination_still_settle, simulations, 31).
provenance(r5_destination_still_settle, weight_mass_permille, 31000).
provenance(r5_destination_still_settle, confidence_permille, 1000).
provenance(r5_destination_still_settle, score_permille, 1000).
provenance(r5_destination_still_settle, batches, 1).

rule(r5_destination_upright, defeasible, destination_upright).
body(r5_destination_upright, grippy_destination).
body(r5_destination_upright, pour_mid_height).
body(r5_destination_upright, pour_near_rim).
body(r5_destination_upright, pour_steeply_tilted).
learned(r5_destination_upright).
provenance(r5_destination_upright, antecedent, a5).
provenance(r5_destination_upright, parent, a1).
provenance(r5_destination_upright, simulations, 31).
provenance(r5_destination_upright, weight_mass_permille, 31000).
provenance(r5_destination_upright, confidence_permille, 1000).
provenance(r5_destination_upright, score_permille, 1000).
provenance(r5_destination_upright, batches, 1).

rule(r5_source_clear, defeasible, source_clear).
body(r5_source_clear, grippy_destination).
body(r5_source_clear, pour_mid_height).
body(r5_source_clear, pour_near_rim).
body(r5_source_clear, pour_steeply_tilted).
learned(r5_source_clear).
provenance(r5_source_clear, antecedent, a5).
provenance(r5_source_clear, parent, a1).
provenance(r5_source_clear, simulations, 31).
provenance(r5_source_clear, weight_mass_permille, 31000).
provenance(r5_source_clear, confidence_permille, 1000).
provenance(r5_source_clear, score_permille, 1000).
provenance(r5_source_clear, batches, 1).

rule(r5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r5_liquid_leaves_source, grippy_destination).
body(r5_liquid_leaves_source, pour_mid_height).
body(r5_liquid_leaves_source, pour_near_rim).
body(r5_liquid_leaves_source, pour_steeply_tilted).
learned(r5_liquid_leaves_source).
provenance(r5_liquid_leaves_source, antecedent, a5).
provenance(r5_liquid_leaves_source, parent, a1).
provenance(r5_liquid_leaves_source, simulations, 31).
provenance(r5_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r5_liquid_leaves_source, confidence_permille, 839).
provenance(r5_liquid_leaves_source, score_permille, 737).
provenance(r5_liquid_leaves_source, batches, 1).

rule(r5_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r5_liquid_enters_destination, grippy_destination).
body(r5_liquid_enters_destination, pour_mid_height).
body(r5_liquid_enters_destination, pour_near_rim).
body(r5_liquid_enters_destination, pour_steeply_tilted).
learned(r5_liquid_enters_destination).
provenance(r5_liquid_enters_destination, antecedent, a5).
provenance(r5_liquid_enters_destination, parent, a1).
provenance(r5_liquid_enters_destination, simulations, 31).
provenance(r5_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r5_liquid_enters_destination, confidence_permille, 839).
provenance(r5_liquid_enters_destination, score_permille, 732).
provenance(r5_liquid_enters_destination, batches, 1).

rule(r5_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r5_liquid_remains_in_destination, grippy_destination).
body(r5_liquid_remains_in_destination, pour_mid_height).
body(r5_liquid_remains_in_destination, pour_near_rim).
body(r5_liquid_remains_in_destination, pour_steeply_tilted).
learned(r5_liquid_remains_in_destination).
provenance(r5_liquid_remains_in_destination, antecedent, a5).
provenance(r5_liquid_remains_in_destination, parent, a1).
provenance(r5_liquid_remains_in_destination, simulations, 31).
provenance(r5_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r5_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r5_liquid_remains_in_destination, score_permille, 1000).
provenance(r5_liquid_remains_in_destination, batches, 1).

rule(r5_no_spill, defeasible, no_spill).
body(r5_no_spill, grippy_destination).
body(r5_no_spill, pour_mid_height).
body(r5_no_spill, pour_near_rim).
body(r5_no_spill, pour_steeply_tilted).
learned(r5_no_spill).
provenance(r5_no_spill, antecedent, a5).
provenance(r5_no_spill, parent, a1).
provenance(r5_no_spill, simulations, 31).
provenance(r5_no_spill, weight_mass_permille, 31000).
provenance(r5_no_spill, confidence_permille, 1000).
provenance(r5_no_spill, score_permille, 994).
provenance(r5_no_spill, batches, 1).

rule(r6_destination_still_approach, defeasible, destination_still_approach).
body(r6_destination_still_approach, approach_lowering).
body(r6_destination_still_approach, bouncy_destination).
body(r6_destination_still_approach, dull_source).
body(r6_destination_still_approach, end_rolled).
body(r6_destination_still_approach, end_slightly_tilted).
body(r6_destination_still_approach, light_destination).
body(r6_destination_still_approach, moderate_approach).
body(r6_destination_still_approach, pour_centred).
body(r6_destination_still_approach, pour_level).
body(r6_destination_still_approach, pour_mid_height).
body(r6_destination_still_approach, pour_steeply_tilted).
body(r6_destination_still_approach, retreat_moving_closer).
body(r6_destination_still_approach, some_liquid).
body(r6_destination_still_approach, start_centred).
body(r6_destination_still_approach, sticky_liquid).
learned(r6_destination_still_approach).
provenance(r6_destination_still_approach, antecedent, a6).
provenance(r6_destination_still_approach, parent, none).
provenance(r6_destination_still_approach, simulations, 31).
provenance(r6_destination_still_approach, weight_mass_permille, 31000).
provenance(r6_destination_still_approach, confidence_permille, 1000).
provenance(r6_destination_still_approach, score_permille, 961).
provenance(r6_destination_still_approach, batches, 1).

rule(r6_destination_still_retreat, defeasible, destination_still_retreat).
body(r6_destination_still_retreat, approach_lowering).
body(r6_destination_still_retreat, bouncy_destination).
body(r6_destination_still_retreat, dull_source).
body(r6_destination_still_retreat, end_rolled).
body(r6_destination_still_retreat, end_slightly_tilted).
body(r6_destination_still_retreat, light_destination).
body(r6_destination_still_retreat, moderate_approach).
body(r6_destination_still_retreat, pour_centred).
body(r6_destination_still_retreat, pour_level).
body(r6_destination_still_retreat, pour_mid_height).
body(r6_destination_still_retreat, pour_steeply_tilted).
body(r6_destination_still_retreat, retreat_moving_closer).
body(r6_destination_still_retreat, some_liquid).
body(r6_destination_still_retreat, start_centred).
body(r6_destination_still_retreat, sticky_liquid).
learned(r6_destination_still_retreat).
provenance(r6_destination_still_retreat, antecedent, a6).
provenance(r6_destination_still_retreat, parent, none).
provenance(r6_destination_still_retreat, simulations, 31).
provenance(r6_destination_still_retreat, weight_mass_permille, 31000).
provenance(r6_destination_still_retreat, confidence_permille, 1000).
provenance(r6_destination_still_retreat, score_permille, 971).
provenance(r6_destination_still_retreat, batches, 1).

rule(r6_destination_still_settle, defeasible, destination_still_settle).
body(r6_destination_still_settle, approach_lowering).
body(r6_destination_still_settle, bouncy_destination).
body(r6_destination_still_settle, dull_source).
body(r6_destination_still_settle, end_rolled).
body(r6_destination_still_settle, end_slightly_tilted).
body(r6_destination_still_settle, light_destination).
body(r6_destination_still_settle, moderate_approach).
body(r6_destination_still_settle, pour_centred).
body(r6_destination_still_settle, pour_level).
body(r6_destination_still_settle, pour_mid_height).
body(r6_destination_still_settle, pour_steeply_tilted).
body(r6_destination_still_settle, retreat_moving_closer).
body(r6_destination_still_settle, some_liquid).
body(r6_destination_still_settle, start_centred).
body(r6_destination_still_settle, sticky_liquid).
learned(r6_destination_still_settle).
provenance(r6_destination_still_settle, antecedent, a6).
provenance(r6_destination_still_settle, parent, none).
provenance(r6_destination_still_settle, simulations, 31).
provenance(r6_destination_still_settle, weight_mass_permille, 31000).
provenance(r6_destination_still_settle, confidence_permille, 1000).
provenance(r6_destination_still_settle, score_permille, 995).
provenance(r6_destination_still_settle, batches, 1).

rule(r6_destination_upright, defeasible, destination_upright).
body(r6_destination_upright, approach_lowering).
body(r6_destination_upright, bouncy_destination).
body(r6_destination_upright, dull_source).
body(r6_destination_upright, end_rolled).
body(r6_destination_upright, end_slightly_tilted).
body(r6_destination_upright, light_destination).
body(r6_destination_upright, moderate_approach).
body(r6_destination_upright, pour_centred).
body(r6_destination_upright, pour_level).
body(r6_destination_upright, pour_mid_height).
body(r6_destination_upright, pour_steeply_tilted).
body(r6_destination_upright, retreat_moving_closer).
body(r6_destination_upright, some_liquid).
body(r6_destination_upright, start_centred).
body(r6_destination_upright, sticky_liquid).
learned(r6_destination_upright).
provenance(r6_destination_upright, antecedent, a6).
provenance(r6_destination_upright, parent, none).
provenance(r6_destination_upright, simulations, 31).
provenance(r6_destination_upright, weight_mass_permille, 31000).
provenance(r6_destination_upright, confidence_permille, 1000).
provenance(r6_destination_upright, score_permille, 996).
provenance(r6_destination_upright, batches, 1).

rule(r6_source_clear, defeasible, source_clear).
body(r6_source_clear, approach_lowering).
body(r6_source_clear, bouncy_destination).
body(r6_source_clear, dull_source).
body(r6_source_clear, end_rolled).
body(r6_source_clear, end_slightly_tilted).
body(r6_source_clear, light_destination).
body(r6_source_clear, moderate_approach).
body(r6_source_clear, pour_centred).
body(r6_source_clear, pour_level).
body(r6_source_clear, pour_mid_height).
body(r6_source_clear, pour_steeply_tilted).
body(r6_source_clear, retreat_moving_closer).
body(r6_source_clear, some_liquid).
body(r6_source_clear, start_centred).
body(r6_source_clear, sticky_liquid).
learned(r6_source_clear).
provenance(r6_source_clear, antecedent, a6).
provenance(r6_source_clear, parent, none).
provenance(r6_source_clear, simulations, 31).
provenance(r6_source_clear, weight_mass_permille, 31000).
provenance(r6_source_clear, confidence_permille, 1000).
provenance(r6_source_clear, score_permille, 1000).
provenance(r6_source_clear, batches, 1).

rule(r6_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r6_liquid_leaves_source, approach_lowering).
body(r6_liquid_leaves_source, bouncy_destination).
body(r6_liquid_leaves_source, dull_source).
body(r6_liquid_leaves_source, end_rolled).
body(r6_liquid_leaves_source, end_slightly_tilted).
body(r6_liquid_leaves_source, light_destination).
body(r6_liquid_leaves_source, moderate_approach).
body(r6_liquid_leaves_source, pour_centred).
body(r6_liquid_leaves_source, pour_level).
body(r6_liquid_leaves_source, pour_mid_height).
body(r6_liquid_leaves_source, pour_steeply_tilted).
body(r6_liquid_leaves_source, retreat_moving_closer).
body(r6_liquid_leaves_source, some_liquid).
body(r6_liquid_leaves_source, start_centred).
body(r6_liquid_leaves_source, sticky_liquid).
learned(r6_liquid_leaves_source).
provenance(r6_liquid_leaves_source, antecedent, a6).
provenance(r6_liquid_leaves_source, parent, none).
provenance(r6_liquid_leaves_source, simulations, 31).
provenance(r6_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r6_liquid_leaves_source, confidence_permille, 548).
provenance(r6_liquid_leaves_source, score_permille, 415).
provenance(r6_liquid_leaves_source, batches, 1).

rule(r6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r6_liquid_enters_destination, approach_lowering).
body(r6_liquid_enters_destination, bouncy_destination).
body(r6_liquid_enters_destination, dull_source).
body(r6_liquid_enters_destination, end_rolled).
body(r6_liquid_enters_destination, end_slightly_tilted).
body(r6_liquid_enters_destination, light_destination).
body(r6_liquid_enters_destination, moderate_approach).
body(r6_liquid_enters_destination, pour_centred).
body(r6_liquid_enters_destination, pour_level).
body(r6_liquid_enters_destination, pour_mid_height).
body(r6_liquid_enters_destination, pour_steeply_tilted).
body(r6_liquid_enters_destination, retreat_moving_closer).
body(r6_liquid_enters_destination, some_liquid).
body(r6_liquid_enters_destination, start_centred).
body(r6_liquid_enters_destination, sticky_liquid).
learned(r6_liquid_enters_destination).
provenance(r6_liquid_enters_destination, antecedent, a6).
provenance(r6_liquid_enters_destination, parent, none).
provenance(r6_liquid_enters_destination, simulations, 31).
provenance(r6_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r6_liquid_enters_destination, confidence_permille, 774).
provenance(r6_liquid_enters_destination, score_permille, 194).
provenance(r6_liquid_enters_destination, batches, 1).

rule(r6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r6_liquid_remains_in_destination, approach_lowering).
body(r6_liquid_remains_in_destination, bouncy_destination).
body(r6_liquid_remains_in_destination, dull_source).
body(r6_liquid_remains_in_destination, end_rolled).
body(r6_liquid_remains_in_destination, end_slightly_tilted).
body(r6_liquid_remains_in_destination, light_destination).
body(r6_liquid_remains_in_destination, moderate_approach).
body(r6_liquid_remains_in_destination, pour_centred).
body(r6_liquid_remains_in_destination, pour_level).
body(r6_liquid_remains_in_destination, pour_mid_height).
body(r6_liquid_remains_in_destination, pour_steeply_tilted).
body(r6_liquid_remains_in_destination, retreat_moving_closer).
body(r6_liquid_remains_in_destination, some_liquid).
body(r6_liquid_remains_in_destination, start_centred).
body(r6_liquid_remains_in_destination, sticky_liquid).
learned(r6_liquid_remains_in_destination).
provenance(r6_liquid_remains_in_destination, antecedent, a6).
provenance(r6_liquid_remains_in_destination, parent, none).
provenance(r6_liquid_remains_in_destination, simulations, 31).
provenance(r6_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r6_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r6_liquid_remains_in_destination, score_permille, 997).
provenance(r6_liquid_remains_in_destination, batches, 1).

rule(r6_no_spill, defeasible, no_spill).
body(r6_no_spill, approach_lowering).
body(r6_no_spill, bouncy_destination).
body(r6_no_spill, dull_source).
body(r6_no_spill, end_rolled).
body(r6_no_spill, end_slightly_tilted).
body(r6_no_spill, light_destination).
body(r6_no_spill, moderate_approach).
body(r6_no_spill, pour_centred).
body(r6_no_spill, pour_level).
body(r6_no_spill, pour_mid_height).
body(r6_no_spill, pour_steeply_tilted).
body(r6_no_spill, retreat_moving_closer).
body(r6_no_spill, some_liquid).
body(r6_no_spill, start_centred).
body(r6_no_spill, sticky_liquid).
learned(r6_no_spill).
provenance(r6_no_spill, antecedent, a6).
provenance(r6_no_spill, parent, none).
provenance(r6_no_spill, simulations, 31).
provenance(r6_no_spill, weight_mass_permille, 31000).
provenance(r6_no_spill, confidence_permille, 806).
provenance(r6_no_spill, score_permille, 777).
provenance(r6_no_spill, batches, 1).

rule(r7_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r7_destination_still_approach, approach_moving_closer).
body(r7_destination_still_approach, dull_destination).
body(r7_destination_still_approach, dull_source).
body(r7_destination_still_approach, end_centred).
body(r7_destination_still_approach, end_half_tilted).
body(r7_destination_still_approach, end_level).
body(r7_destination_still_approach, end_low).
body(r7_destination_still_approach, grippy_destination).
body(r7_destination_still_approach, grippy_source).
body(r7_destination_still_approach, heavy_destination).
body(r7_destination_still_approach, heavy_liquid).
body(r7_destination_still_approach, light_source).
body(r7_destination_still_approach, pour_in_line).
body(r7_destination_still_approach, pour_slightly_tilted).
body(r7_destination_still_approach, runny_liquid).
body(r7_destination_still_approach, slow_approach).
body(r7_destination_still_approach, slow_retreat).
body(r7_destination_still_approach, start_below_rim).
body(r7_destination_still_approach, very_much_liquid).
learned(r7_destination_still_approach).
provenance(r7_destination_still_approach, antecedent, a7).
provenance(r7_destination_still_approach, parent, none).
provenance(r7_destination_still_approach, simulations, 45).
provenance(r7_destination_still_approach, weight_mass_permille, 45000).
provenance(r7_destination_still_approach, confidence_permille, 511).
provenance(r7_destination_still_approach, score_permille, 478).
provenance(r7_destination_still_approach, batches, 1).

rule(r7_destination_still_retreat, defeasible, destination_still_retreat).
body(r7_destination_still_retreat, approach_moving_closer).
body(r7_destination_still_retreat, dull_destination).
body(r7_destination_still_retreat, dull_source).
body(r7_destination_still_retreat, end_centred).
body(r7_destination_still_retreat, end_half_tilted).
body(r7_destination_still_retreat, end_level).
body(r7_destination_still_retreat, end_low).
body(r7_destination_still_retreat, grippy_destination).
body(r7_destination_still_retreat, grippy_source).
body(r7_destination_still_retreat, heavy_destination).
body(r7_destination_still_retreat, heavy_liquid).
body(r7_destination_still_retreat, light_source).
body(r7_destination_still_retreat, pour_in_line).
body(r7_destination_still_retreat, pour_slightly_tilted).
body(r7_destination_still_retreat, runny_liquid).
body(r7_destination_still_retreat, slow_approach).
body(r7_destination_still_retreat, slow_retreat).
body(r7_destination_still_retreat, start_below_rim).
body(r7_destination_still_retreat, very_much_liquid).
learned(r7_destination_still_retreat).
provenance(r7_destination_still_retreat, antecedent, a7).
provenance(r7_destination_still_retreat, parent, none).
provenance(r7_destination_still_retreat, simulations, 45).
provenance(r7_destination_still_retreat, weight_mass_permille, 45000).
provenance(r7_destination_still_retreat, confidence_permille, 756).
provenance(r7_destination_still_retreat, score_permille, 743).
provenance(r7_destination_still_retreat, batches, 1).

rule(r7_destination_still_settle, defeasible, destination_still_settle).
body(r7_destination_still_settle, approach_moving_closer).
body(r7_destination_still_settle, dull_destination).
body(r7_destination_still_settle, dull_source).
body(r7_destination_still_settle, end_centred).
body(r7_destination_still_settle, end_half_tilted).
body(r7_destination_still_settle, end_level).
body(r7_destination_still_settle, end_low).
body(r7_destination_still_settle, grippy_destination).
body(r7_destination_still_settle, grippy_source).
body(r7_destination_still_settle, heavy_destination).
body(r7_destination_still_settle, heavy_liquid).
body(r7_destination_still_settle, light_source).
body(r7_destination_still_settle, pour_in_line).
body(r7_destination_still_settle, pour_slightly_tilted).
body(r7_destination_still_settle, runny_liquid).
body(r7_destination_still_settle, slow_approach).
body(r7_destination_still_settle, slow_retreat).
body(r7_destination_still_settle, start_below_rim).
body(r7_destination_still_settle, very_much_liquid).
learned(r7_destination_still_settle).
provenance(r7_destination_still_settle, antecedent, a7).
provenance(r7_destination_still_settle, parent, none).
provenance(r7_destination_still_settle, simulations, 45).
provenance(r7_destination_still_settle, weight_mass_permille, 45000).
provenance(r7_destination_still_settle, confidence_permille, 756).
provenance(r7_destination_still_settle, score_permille, 771).
provenance(r7_destination_still_settle, batches, 1).

rule(r7_destination_upright, defeasible, destination_upright).
body(r7_destination_upright, approach_moving_closer).
body(r7_destination_upright, dull_destination).
body(r7_destination_upright, dull_source).
body(r7_destination_upright, end_centred).
body(r7_destination_upright, end_half_tilted).
body(r7_destination_upright, end_level).
body(r7_destination_upright, end_low).
body(r7_destination_upright, grippy_destination).
body(r7_destination_upright, grippy_source).
body(r7_destination_upright, heavy_destination).
body(r7_destination_upright, heavy_liquid).
body(r7_destination_upright, light_source).
body(r7_destination_upright, pour_in_line).
body(r7_destination_upright, pour_slightly_tilted).
body(r7_destination_upright, runny_liquid).
body(r7_destination_upright, slow_approach).
body(r7_destination_upright, slow_retreat).
body(r7_destination_upright, start_below_rim).
body(r7_destination_upright, very_much_liquid).
learned(r7_destination_upright).
provenance(r7_destination_upright, antecedent, a7).
provenance(r7_destination_upright, parent, none).
provenance(r7_destination_upright, simulations, 45).
provenance(r7_destination_upright, weight_mass_permille, 45000).
provenance(r7_destination_upright, confidence_permille, 778).
provenance(r7_destination_upright, score_permille, 778).
provenance(r7_destination_upright, batches, 1).

rule(r7_source_clear, defeasible, neg(source_clear)).
body(r7_source_clear, approach_moving_closer).
body(r7_source_clear, dull_destination).
body(r7_source_clear, dull_source).
body(r7_source_clear, end_centred).
body(r7_source_clear, end_half_tilted).
body(r7_source_clear, end_level).
body(r7_source_clear, end_low).
body(r7_source_clear, grippy_destination).
body(r7_source_clear, grippy_source).
body(r7_source_clear, heavy_destination).
body(r7_source_clear, heavy_liquid).
body(r7_source_clear, light_source).
body(r7_source_clear, pour_in_line).
body(r7_source_clear, pour_slightly_tilted).
body(r7_source_clear, runny_liquid).
body(r7_source_clear, slow_approach).
body(r7_source_clear, slow_retreat).
body(r7_source_clear, start_below_rim).
body(r7_source_clear, very_much_liquid).
learned(r7_source_clear).
provenance(r7_source_clear, antecedent, a7).
provenance(r7_source_clear, parent, none).
provenance(r7_source_clear, simulations, 45).
provenance(r7_source_clear, weight_mass_permille, 45000).
provenance(r7_source_clear, confidence_permille, 689).
provenance(r7_source_clear, score_permille, 229).
provenance(r7_source_clear, batches, 1).

rule(r7_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r7_liquid_leaves_source, approach_moving_closer).
body(r7_liquid_leaves_source, dull_destination).
body(r7_liquid_leaves_source, dull_source).
body(r7_liquid_leaves_source, end_centred).
body(r7_liquid_leaves_source, end_half_tilted).
body(r7_liquid_leaves_source, end_level).
body(r7_liquid_leaves_source, end_low).
body(r7_liquid_leaves_source, grippy_destination).
body(r7_liquid_leaves_source, grippy_source).
body(r7_liquid_leaves_source, heavy_destination).
body(r7_liquid_leaves_source, heavy_liquid).
body(r7_liquid_leaves_source, light_source).
body(r7_liquid_leaves_source, pour_in_line).
body(r7_liquid_leaves_source, pour_slightly_tilted).
body(r7_liquid_leaves_source, runny_liquid).
body(r7_liquid_leaves_source, slow_approach).
body(r7_liquid_leaves_source, slow_retreat).
body(r7_liquid_leaves_source, start_below_rim).
body(r7_liquid_leaves_source, very_much_liquid).
learned(r7_liquid_leaves_source).
provenance(r7_liquid_leaves_source, antecedent, a7).
provenance(r7_liquid_leaves_source, parent, none).
provenance(r7_liquid_leaves_source, simulations, 45).
provenance(r7_liquid_leaves_source, weight_mass_permille, 45000).
provenance(r7_liquid_leaves_source, confidence_permille, 622).
provenance(r7_liquid_leaves_source, score_permille, 574).
provenance(r7_liquid_leaves_source, batches, 1).

rule(r7_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r7_liquid_enters_destination, approach_moving_closer).
body(r7_liquid_enters_destination, dull_destination).
body(r7_liquid_enters_destination, dull_source).
body(r7_liquid_enters_destination, end_centred).
body(r7_liquid_enters_destination, end_half_tilted).
body(r7_liquid_enters_destination, end_level).
body(r7_liquid_enters_destination, end_low).
body(r7_liquid_enters_destination, grippy_destination).
body(r7_liquid_enters_destination, grippy_source).
body(r7_liquid_enters_destination, heavy_destination).
body(r7_liquid_enters_destination, heavy_liquid).
body(r7_liquid_enters_destination, light_source).
body(r7_liquid_enters_destination, pour_in_line).
body(r7_liquid_enters_destination, pour_slightly_tilted).
body(r7_liquid_enters_destination, runny_liquid).
body(r7_liquid_enters_destination, slow_approach).
body(r7_liquid_enters_destination, slow_retreat).
body(r7_liquid_enters_destination, start_below_rim).
body(r7_liquid_enters_destination, very_much_liquid).
learned(r7_liquid_enters_destination).
provenance(r7_liquid_enters_destination, antecedent, a7).
provenance(r7_liquid_enters_destination, parent, none).
provenance(r7_liquid_enters_destination, simulations, 45).
provenance(r7_liquid_enters_destination, weight_mass_permille, 45000).
provenance(r7_liquid_enters_destination, confidence_permille, 644).
provenance(r7_liquid_enters_destination, score_permille, 350).
provenance(r7_liquid_enters_destination, batches, 1).

rule(r7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r7_liquid_remains_in_destination, approach_moving_closer).
body(r7_liquid_remains_in_destination, dull_destination).
body(r7_liquid_remains_in_destination, dull_source).
body(r7_liquid_remains_in_destination, end_centred).
body(r7_liquid_remains_in_destination, end_half_tilted).
body(r7_liquid_remains_in_destination, end_level).
body(r7_liquid_remains_in_destination, end_low).
body(r7_liquid_remains_in_destination, grippy_destination).
body(r7_liquid_remains_in_destination, grippy_source).
body(r7_liquid_remains_in_destination, heavy_destination).
body(r7_liquid_remains_in_destination, heavy_liquid).
body(r7_liquid_remains_in_destination, light_source).
body(r7_liquid_remains_in_destination, pour_in_line).
body(r7_liquid_remains_in_destination, pour_slightly_tilted).
body(r7_liquid_remains_in_destination, runny_liquid).
body(r7_liquid_remains_in_destination, slow_approach).
body(r7_liquid_remains_in_destination, slow_retreat).
body(r7_liquid_remains_in_destination, start_below_rim).
body(r7_liquid_remains_in_destination, very_much_liquid).
learned(r7_liquid_remains_in_destination).
provenance(r7_liquid_remains_in_destination, antecedent, a7).
provenance(r7_liquid_remains_in_destination, parent, none).
provenance(r7_liquid_remains_in_destination, simulations, 45).
provenance(r7_liquid_remains_in_destination, weight_mass_permille, 45000).
provenance(r7_liquid_remains_in_destination, confidence_permille, 800).
provenance(r7_liquid_remains_in_destination, score_permille, 759).
provenance(r7_liquid_remains_in_destination, batches, 1).

rule(r7_no_spill, defeasible, no_spill).
body(r7_no_spill, approach_moving_closer).
body(r7_no_spill, dull_destination).
body(r7_no_spill, dull_source).
body(r7_no_spill, end_centred).
body(r7_no_spill, end_half_tilted).
body(r7_no_spill, end_level).
body(r7_no_spill, end_low).
body(r7_no_spill, grippy_destination).
body(r7_no_spill, grippy_source).
body(r7_no_spill, heavy_destination).
body(r7_no_spill, heavy_liquid).
body(r7_no_spill, light_source).
body(r7_no_spill, pour_in_line).
body(r7_no_spill, pour_slightly_tilted).
body(r7_no_spill, runny_liquid).
body(r7_no_spill, slow_approach).
body(r7_no_spill, slow_retreat).
body(r7_no_spill, start_below_rim).
body(r7_no_spill, very_much_liquid).
learned(r7_no_spill).
provenance(r7_no_spill, antecedent, a7).
provenance(r7_no_spill, parent, none).
provenance(r7_no_spill, simulations, 45).
provenance(r7_no_spill, weight_mass_permille, 45000).
provenance(r7_no_spill, confidence_permille, 733).
provenance(r7_no_spill, score_permille, 680).
provenance(r7_no_spill, batches, 1).

rule(r8_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r8_destination_still_approach, approach_moving_away).
body(r8_destination_still_approach, dull_destination).
body(r8_destination_still_approach, dull_source).
body(r8_destination_still_approach, end_centred).
body(r8_destination_still_approach, end_half_tilted).
body(r8_destination_still_approach, end_level).
body(r8_destination_still_approach, end_low).
body(r8_destination_still_approach, grippy_destination).
body(r8_destination_still_approach, grippy_source).
body(r8_destination_still_approach, heavy_destination).
body(r8_destination_still_approach, heavy_liquid).
body(r8_destination_still_approach, light_source).
body(r8_destination_still_approach, pour_in_line).
body(r8_destination_still_approach, pour_slightly_tilted).
body(r8_destination_still_approach, runny_liquid).
body(r8_destination_still_approach, slow_approach).
body(r8_destination_still_approach, slow_retreat).
body(r8_destination_still_approach, start_below_rim).
body(r8_destination_still_approach, very_much_liquid).
learned(r8_destination_still_approach).
provenance(r8_destination_still_approach, antecedent, a8).
provenance(r8_destination_still_approach, parent, a7).
provenance(r8_destination_still_approach, simulations, 42).
provenance(r8_destination_still_approach, weight_mass_permille, 42000).
provenance(r8_destination_still_approach, confidence_permille, 595).
provenance(r8_destination_still_approach, score_permille, 400).
provenance(r8_destination_still_approach, batches, 1).
provenance(r8_destination_still_approach, followed, liquid_remains_in_destination).
provenance(r8_destination_still_approach, direction, start_x).
provenance(r8_destination_still_approach, sign, down).

rule(r8_destination_still_retreat, defeasible, destination_still_retreat).
body(r8_destination_still_retreat, approach_moving_away).
body(r8_destination_still_retreat, dull_destination).
body(r8_destination_still_retreat, dull_source).
body(r8_destination_still_retreat, end_centred).
body(r8_destination_still_retreat, end_half_tilted).
body(r8_destination_still_retreat, end_level).
body(r8_destination_still_retreat, end_low).
body(r8_destination_still_retreat, grippy_destination).
body(r8_destination_still_retreat, grippy_source).
body(r8_destination_still_retreat, heavy_destination).
body(r8_destination_still_retreat, heavy_liquid).
body(r8_destination_still_retreat, light_source).
body(r8_destination_still_retreat, pour_in_line).
body(r8_destination_still_retreat, pour_slightly_tilted).
body(r8_destination_still_retreat, runny_liquid).
body(r8_destination_still_retreat, slow_approach).
body(r8_destination_still_retreat, slow_retreat).
body(r8_destination_still_retreat, start_below_rim).
body(r8_destination_still_retreat, very_much_liquid).
learned(r8_destination_still_retreat).
provenance(r8_destination_still_retreat, antecedent, a8).
provenance(r8_destination_still_retreat, parent, a7).
provenance(r8_destination_still_retreat, simulations, 42).
provenance(r8_destination_still_retreat, weight_mass_permille, 42000).
provenance(r8_destination_still_retreat, confidence_permille, 738).
provenance(r8_destination_still_retreat, score_permille, 739).
provenance(r8_destination_still_retreat, batches, 1).
provenance(r8_destination_still_retreat, followed, liquid_remains_in_destination).
provenance(r8_destination_still_retreat, direction, start_x).
provenance(r8_destination_still_retreat, sign, down).

rule(r8_destination_still_settle, defeasible, destination_still_settle).
body(r8_destination_still_settle, approach_moving_away).
body(r8_destination_still_settle, dull_destination).
body(r8_destination_still_settle, dull_source).
body(r8_destination_still_settle, end_centred).
body(r8_destination_still_settle, end_half_tilted).
body(r8_destination_still_settle, end_level).
body(r8_destination_still_settle, end_low).
body(r8_destination_still_settle, grippy_destination).
body(r8_destination_still_settle, grippy_source).
body(r8_destination_still_settle, heavy_destination).
body(r8_destination_still_settle, heavy_liquid).
body(r8_destination_still_settle, light_source).
body(r8_destination_still_settle, pour_in_line).
body(r8_destination_still_settle, pour_slightly_tilted).
body(r8_destination_still_settle, runny_liquid).
body(r8_destination_still_settle, slow_approach).
body(r8_destination_still_settle, slow_retreat).
body(r8_destination_still_settle, start_below_rim).
body(r8_destination_still_settle, very_much_liquid).
learned(r8_destination_still_settle).
provenance(r8_destination_still_settle, antecedent, a8).
provenance(r8_destination_still_settle, parent, a7).
provenance(r8_destination_still_settle, simulations, 42).
provenance(r8_destination_still_settle, weight_mass_permille, 42000).
provenance(r8_destination_still_settle, confidence_permille, 857).
provenance(r8_destination_still_settle, score_permille, 851).
provenance(r8_destination_still_settle, batches, 1).
provenance(r8_destination_still_settle, followed, liquid_remains_in_destination).
provenance(r8_destination_still_settle, direction, start_x).
provenance(r8_destination_still_settle, sign, down).

rule(r8_destination_upright, defeasible, destination_upright).
body(r8_destination_upright, approach_moving_away).
body(r8_destination_upright, dull_destination).
body(r8_destination_upright, dull_source).
body(r8_destination_upright, end_centred).
body(r8_destination_upright, end_half_tilted).
body(r8_destination_upright, end_level).
body(r8_destination_upright, end_low).
body(r8_destination_upright, grippy_destination).
body(r8_destination_upright, grippy_source).
body(r8_destination_upright, heavy_destination).
body(r8_destination_upright, heavy_liquid).
body(r8_destination_upright, light_source).
body(r8_destination_upright, pour_in_line).
body(r8_destination_upright, pour_slightly_tilted).
body(r8_destination_upright, runny_liquid).
body(r8_destination_upright, slow_approach).
body(r8_destination_upright, slow_retreat).
body(r8_destination_upright, start_below_rim).
body(r8_destination_upright, very_much_liquid).
learned(r8_destination_upright).
provenance(r8_destination_upright, antecedent, a8).
provenance(r8_destination_upright, parent, a7).
provenance(r8_destination_upright, simulations, 42).
provenance(r8_destination_upright, weight_mass_permille, 42000).
provenance(r8_destination_upright, confidence_permille, 929).
provenance(r8_destination_upright, score_permille, 911).
provenance(r8_destination_upright, batches, 1).
provenance(r8_destination_upright, followed, liquid_remains_in_destination).
provenance(r8_destination_upright, direction, start_x).
provenance(r8_destination_upright, sign, down).

rule(r8_source_clear, defeasible, neg(source_clear)).
body(r8_source_clear, approach_moving_away).
body(r8_source_clear, dull_destination).
body(r8_source_clear, dull_source).
body(r8_source_clear, end_centred).
body(r8_source_clear, end_half_tilted).
body(r8_source_clear, end_level).
body(r8_source_clear, end_low).
body(r8_source_clear, grippy_destination).
body(r8_source_clear, grippy_source).
body(r8_source_clear, heavy_destination).
body(r8_source_clear, heavy_liquid).
body(r8_source_clear, light_source).
body(r8_source_clear, pour_in_line).
body(r8_source_clear, pour_slightly_tilted).
body(r8_source_clear, runny_liquid).
body(r8_source_clear, slow_approach).
body(r8_source_clear, slow_retreat).
body(r8_source_clear, start_below_rim).
body(r8_source_clear, very_much_liquid).
learned(r8_source_clear).
provenance(r8_source_clear, antecedent, a8).
provenance(r8_source_clear, parent, a7).
provenance(r8_source_clear, simulations, 42).
provenance(r8_source_clear, weight_mass_permille, 42000).
provenance(r8_source_clear, confidence_permille, 976).
provenance(r8_source_clear, score_permille, 24).
provenance(r8_source_clear, batches, 1).
provenance(r8_source_clear, followed, liquid_remains_in_destination).
provenance(r8_source_clear, direction, start_x).
provenance(r8_source_clear, sign, down).

rule(r8_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r8_liquid_leaves_source, approach_moving_away).
body(r8_liquid_leaves_source, dull_destination).
body(r8_liquid_leaves_source, dull_source).
body(r8_liquid_leaves_source, end_centred).
body(r8_liquid_leaves_source, end_half_tilted).
body(r8_liquid_leaves_source, end_level).
body(r8_liquid_leaves_source, end_low).
body(r8_liquid_leaves_source, grippy_destination).
body(r8_liquid_leaves_source, grippy_source).
body(r8_liquid_leaves_source, heavy_destination).
body(r8_liquid_leaves_source, heavy_liquid).
body(r8_liquid_leaves_source, light_source).
body(r8_liquid_leaves_source, pour_in_line).
body(r8_liquid_leaves_source, pour_slightly_tilted).
body(r8_liquid_leaves_source, runny_liquid).
body(r8_liquid_leaves_source, slow_approach).
body(r8_liquid_leaves_source, slow_retreat).
body(r8_liquid_leaves_source, start_below_rim).
body(r8_liquid_leaves_source, very_much_liquid).
learned(r8_liquid_leaves_source).
provenance(r8_liquid_leaves_source, antecedent, a8).
provenance(r8_liquid_leaves_source, parent, a7).
provenance(r8_liquid_leaves_source, simulations, 42).
provenance(r8_liquid_leaves_source, weight_mass_permille, 42000).
provenance(r8_liquid_leaves_source, confidence_permille, 571).
provenance(r8_liquid_leaves_source, score_permille, 499).
provenance(r8_liquid_leaves_source, batches, 1).
provenance(r8_liquid_leaves_source, followed, liquid_remains_in_destination).
provenance(r8_liquid_leaves_source, direction, start_x).
provenance(r8_liquid_leaves_source, sign, down).

rule(r8_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r8_liquid_enters_destination, approach_moving_away).
body(r8_liquid_enters_destination, dull_destination).
body(r8_liquid_enters_destination, dull_source).
body(r8_liquid_enters_destination, end_centred).
body(r8_liquid_enters_destination, end_half_tilted).
body(r8_liquid_enters_destination, end_level).
body(r8_liquid_enters_destination, end_low).
body(r8_liquid_enters_destination, grippy_destination).
body(r8_liquid_enters_destination, grippy_source).
body(r8_liquid_enters_destination, heavy_destination).
body(r8_liquid_enters_destination, heavy_liquid).
body(r8_liquid_enters_destination, light_source).
body(r8_liquid_enters_destination, pour_in_line).
body(r8_liquid_enters_destination, pour_slightly_tilted).
body(r8_liquid_enters_destination, runny_liquid).
body(r8_liquid_enters_destination, slow_approach).
body(r8_liquid_enters_destination, slow_retreat).
body(r8_liquid_enters_destination, start_below_rim).
body(r8_liquid_enters_destination, very_much_liquid).
learned(r8_liquid_enters_destination).
provenance(r8_liquid_enters_destination, antecedent, a8).
provenance(r8_liquid_enters_destination, parent, a7).
provenance(r8_liquid_enters_destination, simulations, 42).
provenance(r8_liquid_enters_destination, weight_mass_permille, 42000).
provenance(r8_liquid_enters_destination, confidence_permille, 524).
provenance(r8_liquid_enters_destination, score_permille, 507).
provenance(r8_liquid_enters_destination, batches, 1).
provenance(r8_liquid_enters_destination, followed, liquid_remains_in_destination).
provenance(r8_liquid_enters_destination, direction, start_x).
provenance(r8_liquid_enters_destination, sign, down).

rule(r8_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r8_liquid_remains_in_destination, approach_moving_away).
body(r8_liquid_remains_in_destination, dull_destination).
body(r8_liquid_remains_in_destination, dull_source).
body(r8_liquid_remains_in_destination, end_centred).
body(r8_liquid_remains_in_destination, end_half_tilted).
body(r8_liquid_remains_in_destination, end_level).
body(r8_liquid_remains_in_destination, end_low).
body(r8_liquid_remains_in_destination, grippy_destination).
body(r8_liquid_remains_in_destination, grippy_source).
body(r8_liquid_remains_in_destination, heavy_destination).
body(r8_liquid_remains_in_destination, heavy_liquid).
body(r8_liquid_remains_in_destination, light_source).
body(r8_liquid_remains_in_destination, pour_in_line).
body(r8_liquid_remains_in_destination, pour_slightly_tilted).
body(r8_liquid_remains_in_destination, runny_liquid).
body(r8_liquid_remains_in_destination, slow_approach).
body(r8_liquid_remains_in_destination, slow_retreat).
body(r8_liquid_remains_in_destination, start_below_rim).
body(r8_liquid_remains_in_destination, very_much_liquid).
learned(r8_liquid_remains_in_destination).
provenance(r8_liquid_remains_in_destination, antecedent, a8).
provenance(r8_liquid_remains_in_destination, parent, a7).
provenance(r8_liquid_remains_in_destination, simulations, 42).
provenance(r8_liquid_remains_in_destination, weight_mass_permille, 42000).
provenance(r8_liquid_remains_in_destination, confidence_permille, 524).
provenance(r8_liquid_remains_in_destination, score_permille, 514).
provenance(r8_liquid_remains_in_destination, batches, 1).
provenance(r8_liquid_remains_in_destination, followed, liquid_remains_in_destination).
provenance(r8_liquid_remains_in_destination, direction, start_x).
provenance(r8_liquid_remains_in_destination, sign, down).

rule(r8_no_spill, defeasible, no_spill).
body(r8_no_spill, approach_moving_away).
body(r8_no_spill, dull_destination).
body(r8_no_spill, dull_source).
body(r8_no_spill, end_centred).
body(r8_no_spill, end_half_tilted).
body(r8_no_spill, end_level).
body(r8_no_spill, end_low).
body(r8_no_spill, grippy_destination).
body(r8_no_spill, grippy_source).
body(r8_no_spill, heavy_destination).
body(r8_no_spill, heavy_liquid).
body(r8_no_spill, light_source).
body(r8_no_spill, pour_in_line).
body(r8_no_spill, pour_slightly_tilted).
body(r8_no_spill, runny_liquid).
body(r8_no_spill, slow_approach).
body(r8_no_spill, slow_retreat).
body(r8_no_spill, start_below_rim).
body(r8_no_spill, very_much_liquid).
learned(r8_no_spill).
provenance(r8_no_spill, antecedent, a8).
provenance(r8_no_spill, parent, a7).
provenance(r8_no_spill, simulations, 42).
provenance(r8_no_spill, weight_mass_permille, 42000).
provenance(r8_no_spill, confidence_permille, 857).
provenance(r8_no_spill, score_permille, 713).
provenance(r8_no_spill, batches, 1).
provenance(r8_no_spill, followed, liquid_remains_in_destination).
provenance(r8_no_spill, direction, start_x).
provenance(r8_no_spill, sign, down).

rule(r9_destination_still_approach, defeasible, destination_still_approach).
body(r9_destination_still_approach, approach_moving_away).
body(r9_destination_still_approach, dull_destination).
body(r9_destination_still_approach, dull_source).
body(r9_destination_still_approach, end_centred).
body(r9_destination_still_approach, end_level).
body(r9_destination_still_approach, end_low).
body(r9_destination_still_approach, end_upside_down).
body(r9_destination_still_approach, grippy_destination).
body(r9_destination_still_approach, grippy_source).
body(r9_destination_still_approach, heavy_destination).
body(r9_destination_still_approach, heavy_liquid).
body(r9_destination_still_approach, light_source).
body(r9_destination_still_approach, pour_in_line).
body(r9_destination_still_approach, pour_slightly_tilted).
body(r9_destination_still_approach, runny_liquid).
body(r9_destination_still_approach, slow_approach).
body(r9_destination_still_approach, slow_retreat).
body(r9_destination_still_approach, start_below_rim).
body(r9_destination_still_approach, very_much_liquid).
learned(r9_destination_still_approach).
provenance(r9_destination_still_approach, antecedent, a9).
provenance(r9_destination_still_approach, parent, a8).
provenance(r9_destination_still_approach, simulations, 37).
provenance(r9_destination_still_approach, weight_mass_permille, 31615).
provenance(r9_destination_still_approach, confidence_permille, 533).
provenance(r9_destination_still_approach, score_permille, 518).
provenance(r9_destination_still_approach, batches, 1).
provenance(r9_destination_still_approach, followed, liquid_leaves_source).
provenance(r9_destination_still_approach, direction, end_pitch).
provenance(r9_destination_still_approach, sign, up).

rule(r9_destination_still_retreat, defeasible, destination_still_retreat).
body(r9_destination_still_retreat, approach_moving_away).
body(r9_destination_still_retreat, dull_destination).
body(r9_destination_still_retreat, dull_source).
body(r9_destination_still_retreat, end_centred).
body(r9_destination_still_retreat, end_level).
body(r9_destination_still_retreat, end_low).
body(r9_destination_still_retreat, end_upside_down).
body(r9_destination_still_retreat, grippy_destination).
body(r9_destination_still_retreat, grippy_source).
body(r9_destination_still_retreat, heavy_destination).
body(r9_destination_still_retreat, heavy_liquid).
body(r9_destination_still_retreat, light_source).
body(r9_destination_still_retreat, pour_in_line).
body(r9_destination_still_retreat, pour_slightly_tilted).
body(r9_destination_still_retreat, runny_liquid).
body(r9_destination_still_retreat, slow_approach).
body(r9_destination_still_retreat, slow_retreat).
body(r9_destination_still_retreat, start_below_rim).
body(r9_destination_still_retreat, very_much_liquid).
learned(r9_destination_still_retreat).
provenance(r9_destination_still_retreat, antecedent, a9).
provenance(r9_destination_still_retreat, parent, a8).
provenance(r9_destination_still_retreat, simulations, 37).
provenance(r9_destination_still_retreat, weight_mass_permille, 31615).
provenance(r9_destination_still_retreat, confidence_permille, 720).
provenance(r9_destination_still_retreat, score_permille, 696).
provenance(r9_destination_still_retreat, batches, 1).
provenance(r9_destination_still_retreat, followed, liquid_leaves_source).
provenance(r9_destination_still_retreat, direction, end_pitch).
provenance(r9_destination_still_retreat, sign, up).

rule(r9_destination_still_settle, defeasible, destination_still_settle).
body(r9_destination_still_settle, approach_moving_away).
body(r9_destination_still_settle, dull_destination).
body(r9_destination_still_settle, dull_source).
body(r9_destination_still_settle, end_centred).
body(r9_destination_still_settle, end_level).
body(r9_destination_still_settle, end_low).
body(r9_destination_still_settle, end_upside_down).
body(r9_destination_still_settle, grippy_destination).
body(r9_destination_still_settle, grippy_source).
body(r9_destination_still_settle, heavy_destination).
body(r9_destination_still_settle, heavy_liquid).
body(r9_destination_still_settle, light_source).
body(r9_destination_still_settle, pour_in_line).
body(r9_destination_still_settle, pour_slightly_tilted).
body(r9_destination_still_settle, runny_liquid).
body(r9_destination_still_settle, slow_approach).
body(r9_destination_still_settle, slow_retreat).
body(r9_destination_still_settle, start_below_rim).
body(r9_destination_still_settle, very_much_liquid).
learned(r9_destination_still_settle).
provenance(r9_destination_still_settle, antecedent, a9).
provenance(r9_destination_still_settle, parent, a8).
provenance(r9_destination_still_settle, simulations, 37).
provenance(r9_destination_still_settle, weight_mass_permille, 31615).
provenance(r9_destination_still_settle, confidence_permille, 798).
provenance(r9_destination_still_settle, score_permille, 785).
provenance(r9_destination_still_settle, batches, 1).
provenance(r9_destination_still_settle, followed, liquid_leaves_source).
provenance(r9_destination_still_settle, direction, end_pitch).
provenance(r9_destination_still_settle, sign, up).

rule(r9_destination_upright, defeasible, destination_upright).
body(r9_destination_upright, approach_moving_away).
body(r9_destination_upright, dull_destination).
body(r9_destination_upright, dull_source).
body(r9_destination_upright, end_centred).
body(r9_destination_upright, end_level).
body(r9_destination_upright, end_low).
body(r9_destination_upright, end_upside_down).
body(r9_destination_upright, grippy_destination).
body(r9_destination_upright, grippy_source).
body(r9_destination_upright, heavy_destination).
body(r9_destination_upright, heavy_liquid).
body(r9_destination_upright, light_source).
body(r9_destination_upright, pour_in_line).
body(r9_destination_upright, pour_slightly_tilted).
body(r9_destination_upright, runny_liquid).
body(r9_destination_upright, slow_approach).
body(r9_destination_upright, slow_retreat).
body(r9_destination_upright, start_below_rim).
body(r9_destination_upright, very_much_liquid).
learned(r9_destination_upright).
provenance(r9_destination_upright, antecedent, a9).
provenance(r9_destination_upright, parent, a8).
provenance(r9_destination_upright, simulations, 37).
provenance(r9_destination_upright, weight_mass_permille, 31615).
provenance(r9_destination_upright, confidence_permille, 876).
provenance(r9_destination_upright, score_permille, 861).
provenance(r9_destination_upright, batches, 1).
provenance(r9_destination_upright, followed, liquid_leaves_source).
provenance(r9_destination_upright, direction, end_pitch).
provenance(r9_destination_upright, sign, up).

rule(r9_source_clear, defeasible, neg(source_clear)).
body(r9_source_clear, approach_moving_away).
body(r9_source_clear, dull_destination).
body(r9_source_clear, dull_source).
body(r9_source_clear, end_centred).
body(r9_source_clear, end_level).
body(r9_source_clear, end_low).
body(r9_source_clear, end_upside_down).
body(r9_source_clear, grippy_destination).
body(r9_source_clear, grippy_source).
body(r9_source_clear, heavy_destination).
body(r9_source_clear, heavy_liquid).
body(r9_source_clear, light_source).
body(r9_source_clear, pour_in_line).
body(r9_source_clear, pour_slightly_tilted).
body(r9_source_clear, runny_liquid).
body(r9_source_clear, slow_approach).
body(r9_source_clear, slow_retreat).
body(r9_source_clear, start_below_rim).
body(r9_source_clear, very_much_liquid).
learned(r9_source_clear).
provenance(r9_source_clear, antecedent, a9).
provenance(r9_source_clear, parent, a8).
provenance(r9_source_clear, simulations, 37).
provenance(r9_source_clear, weight_mass_permille, 31615).
provenance(r9_source_clear, confidence_permille, 779).
provenance(r9_source_clear, score_permille, 172).
provenance(r9_source_clear, batches, 1).
provenance(r9_source_clear, followed, liquid_leaves_source).
provenance(r9_source_clear, direction, end_pitch).
provenance(r9_source_clear, sign, up).

rule(r9_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r9_liquid_leaves_source, approach_moving_away).
body(r9_liquid_leaves_source, dull_destination).
body(r9_liquid_leaves_source, dull_source).
body(r9_liquid_leaves_source, end_centred).
body(r9_liquid_leaves_source, end_level).
body(r9_liquid_leaves_source, end_low).
body(r9_liquid_leaves_source, end_upside_down).
body(r9_liquid_leaves_source, grippy_destination).
body(r9_liquid_leaves_source, grippy_source).
body(r9_liquid_leaves_source, heavy_destination).
body(r9_liquid_leaves_source, heavy_liquid).
body(r9_liquid_leaves_source, light_source).
body(r9_liquid_leaves_source, pour_in_line).
body(r9_liquid_leaves_source, pour_slightly_tilted).
body(r9_liquid_leaves_source, runny_liquid).
body(r9_liquid_leaves_source, slow_approach).
body(r9_liquid_leaves_source, slow_retreat).
body(r9_liquid_leaves_source, start_below_rim).
body(r9_liquid_leaves_source, very_much_liquid).
learned(r9_liquid_leaves_source).
provenance(r9_liquid_leaves_source, antecedent, a9).
provenance(r9_liquid_leaves_source, parent, a8).
provenance(r9_liquid_leaves_source, simulations, 37).
provenance(r9_liquid_leaves_source, weight_mass_permille, 31615).
provenance(r9_liquid_leaves_source, confidence_permille, 1000).
provenance(r9_liquid_leaves_source, score_permille, 1000).
provenance(r9_liquid_leaves_source, batches, 1).
provenance(r9_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r9_liquid_leaves_source, direction, end_pitch).
provenance(r9_liquid_leaves_source, sign, up).

rule(r9_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r9_liquid_enters_destination, approach_moving_away).
body(r9_liquid_enters_destination, dull_destination).
body(r9_liquid_enters_destination, dull_source).
body(r9_liquid_enters_destination, end_centred).
body(r9_liquid_enters_destination, end_level).
body(r9_liquid_enters_destination, end_low).
body(r9_liquid_enters_destination, end_upside_down).
body(r9_liquid_enters_destination, grippy_destination).
body(r9_liquid_enters_destination, grippy_source).
body(r9_liquid_enters_destination, heavy_destination).
body(r9_liquid_enters_destination, heavy_liquid).
body(r9_liquid_enters_destination, light_source).
body(r9_liquid_enters_destination, pour_in_line).
body(r9_liquid_enters_destination, pour_slightly_tilted).
body(r9_liquid_enters_destination, runny_liquid).
body(r9_liquid_enters_destination, slow_approach).
body(r9_liquid_enters_destination, slow_retreat).
body(r9_liquid_enters_destination, start_below_rim).
body(r9_liquid_enters_destination, very_much_liquid).
learned(r9_liquid_enters_destination).
provenance(r9_liquid_enters_destination, antecedent, a9).
provenance(r9_liquid_enters_destination, parent, a8).
provenance(r9_liquid_enters_destination, simulations, 37).
provenance(r9_liquid_enters_destination, weight_mass_permille, 31615).
provenance(r9_liquid_enters_destination, confidence_permille, 908).
provenance(r9_liquid_enters_destination, score_permille, 867).
provenance(r9_liquid_enters_destination, batches, 1).
provenance(r9_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r9_liquid_enters_destination, direction, end_pitch).
provenance(r9_liquid_enters_destination, sign, up).

rule(r9_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r9_liquid_remains_in_destination, approach_moving_away).
body(r9_liquid_remains_in_destination, dull_destination).
body(r9_liquid_remains_in_destination, dull_source).
body(r9_liquid_remains_in_destination, end_centred).
body(r9_liquid_remains_in_destination, end_level).
body(r9_liquid_remains_in_destination, end_low).
body(r9_liquid_remains_in_destination, end_upside_down).
body(r9_liquid_remains_in_destination, grippy_destination).
body(r9_liquid_remains_in_destination, grippy_source).
body(r9_liquid_remains_in_destination, heavy_destination).
body(r9_liquid_remains_in_destination, heavy_liquid).
body(r9_liquid_remains_in_destination, light_source).
body(r9_liquid_remains_in_destination, pour_in_line).
body(r9_liquid_remains_in_destination, pour_slightly_tilted).
body(r9_liquid_remains_in_destination, runny_liquid).
body(r9_liquid_remains_in_destination, slow_approach).
body(r9_liquid_remains_in_destination, slow_retreat).
body(r9_liquid_remains_in_destination, start_below_rim).
body(r9_liquid_remains_in_destination, very_much_liquid).
learned(r9_liquid_remains_in_destination).
provenance(r9_liquid_remains_in_destination, antecedent, a9).
provenance(r9_liquid_remains_in_destination, parent, a8).
provenance(r9_liquid_remains_in_destination, simulations, 37).
provenance(r9_liquid_remains_in_destination, weight_mass_permille, 31615).
provenance(r9_liquid_remains_in_destination, confidence_permille, 796).
provenance(r9_liquid_remains_in_destination, score_permille, 778).
provenance(r9_liquid_remains_in_destination, batches, 1).
provenance(r9_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r9_liquid_remains_in_destination, direction, end_pitch).
provenance(r9_liquid_remains_in_destination, sign, up).

rule(r9_no_spill, defeasible, no_spill).
body(r9_no_spill, approach_moving_away).
body(r9_no_spill, dull_destination).
body(r9_no_spill, dull_source).
body(r9_no_spill, end_centred).
body(r9_no_spill, end_level).
body(r9_no_spill, end_low).
body(r9_no_spill, end_upside_down).
body(r9_no_spill, grippy_destination).
body(r9_no_spill, grippy_source).
body(r9_no_spill, heavy_destination).
body(r9_no_spill, heavy_liquid).
body(r9_no_spill, light_source).
body(r9_no_spill, pour_in_line).
body(r9_no_spill, pour_slightly_tilted).
body(r9_no_spill, runny_liquid).
body(r9_no_spill, slow_approach).
body(r9_no_spill, slow_retreat).
body(r9_no_spill, start_below_rim).
body(r9_no_spill, very_much_liquid).
learned(r9_no_spill).
provenance(r9_no_spill, antecedent, a9).
provenance(r9_no_spill, parent, a8).
provenance(r9_no_spill, simulations, 37).
provenance(r9_no_spill, weight_mass_permille, 31615).
provenance(r9_no_spill, confidence_permille, 689).
provenance(r9_no_spill, score_permille, 669).
provenance(r9_no_spill, batches, 1).
provenance(r9_no_spill, followed, liquid_leaves_source).
provenance(r9_no_spill, direction, end_pitch).
provenance(r9_no_spill, sign, up).

rule(r10_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r10_destination_still_approach, approach_moving_away).
body(r10_destination_still_approach, dull_destination).
body(r10_destination_still_approach, dull_source).
body(r10_destination_still_approach, end_centred).
body(r10_destination_still_approach, end_level).
body(r10_destination_still_approach, end_low).
body(r10_destination_still_approach, end_upside_down).
body(r10_destination_still_approach, grippy_destination).
body(r10_destination_still_approach, grippy_source).
body(r10_destination_still_approach, heavy_destination).
body(r10_destination_still_approach, heavy_liquid).
body(r10_destination_still_approach, light_source).
body(r10_destination_still_approach, pour_in_line).
body(r10_destination_still_approach, pour_low).
body(r10_destination_still_approach, pour_slightly_tilted).
body(r10_destination_still_approach, runny_liquid).
body(r10_destination_still_approach, slow_approach).
body(r10_destination_still_approach, slow_retreat).
body(r10_destination_still_approach, start_below_rim).
body(r10_destination_still_approach, very_much_liquid).
learned(r10_destination_still_approach).
provenance(r10_destination_still_approach, antecedent, a10).
provenance(r10_destination_still_approach, parent, a9).
provenance(r10_destination_still_approach, simulations, 35).
provenance(r10_destination_still_approach, weight_mass_permille, 30385).
provenance(r10_destination_still_approach, confidence_permille, 666).
provenance(r10_destination_still_approach, score_permille, 315).
provenance(r10_destination_still_approach, batches, 1).

rule(r10_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r10_destination_still_retreat, approach_moving_away).
body(r10_destination_still_retreat, dull_destination).
body(r10_destination_still_retreat, dull_source).
body(r10_destination_still_retreat, end_centred).
body(r10_destination_still_retreat, end_level).
body(r10_destination_still_retreat, end_low).
body(r10_destination_still_retreat, end_upside_down).
body(r10_destination_still_retreat, grippy_destination).
body(r10_destination_still_retreat, grippy_source).
body(r10_destination_still_retreat, heavy_destination).
body(r10_destination_still_retreat, heavy_liquid).
body(r10_destination_still_retreat, light_source).
body(r10_destination_still_retreat, pour_in_line).
body(r10_destination_still_retreat, pour_low).
body(r10_destination_still_retreat, pour_slightly_tilted).
body(r10_destination_still_retreat, runny_liquid).
body(r10_destination_still_retreat, slow_approach).
body(r10_destination_still_retreat, slow_retreat).
body(r10_destination_still_retreat, start_below_rim).
body(r10_destination_still_retreat, very_much_liquid).
learned(r10_destination_still_retreat).
provenance(r10_destination_still_retreat, antecedent, a10).
provenance(r10_destination_still_retreat, parent, a9).
provenance(r10_destination_still_retreat, simulations, 35).
provenance(r10_destination_still_retreat, weight_mass_permille, 30385).
provenance(r10_destination_still_retreat, confidence_permille, 532).
provenance(r10_destination_still_retreat, score_permille, 466).
provenance(r10_destination_still_retreat, batches, 1).

rule(r10_destination_still_settle, defeasible, destination_still_settle).
body(r10_destination_still_settle, approach_moving_away).
body(r10_destination_still_settle, dull_destination).
body(r10_destination_still_settle, dull_source).
body(r10_destination_still_settle, end_centred).
body(r10_destination_still_settle, end_level).
body(r10_destination_still_settle, end_low).
body(r10_destination_still_settle, end_upside_down).
body(r10_destination_still_settle, grippy_destination).
body(r10_destination_still_settle, grippy_source).
body(r10_destination_still_settle, heavy_destination).
body(r10_destination_still_settle, heavy_liquid).
body(r10_destination_still_settle, light_source).
body(r10_destination_still_settle, pour_in_line).
body(r10_destination_still_settle, pour_low).
body(r10_destination_still_settle, pour_slightly_tilted).
body(r10_destination_still_settle, runny_liquid).
body(r10_destination_still_settle, slow_approach).
body(r10_destination_still_settle, slow_retreat).
body(r10_destination_still_settle, start_below_rim).
body(r10_destination_still_settle, very_much_liquid).
learned(r10_destination_still_settle).
provenance(r10_destination_still_settle, antecedent, a10).
provenance(r10_destination_still_settle, parent, a9).
provenance(r10_destination_still_settle, simulations, 35).
provenance(r10_destination_still_settle, weight_mass_permille, 30385).
provenance(r10_destination_still_settle, confidence_permille, 782).
provenance(r10_destination_still_settle, score_permille, 747).
provenance(r10_destination_still_settle, batches, 1).

rule(r10_destination_upright, defeasible, destination_upright).
body(r10_destination_upright, approach_moving_away).
body(r10_destination_upright, dull_destination).
body(r10_destination_upright, dull_source).
body(r10_destination_upright, end_centred).
body(r10_destination_upright, end_level).
body(r10_destination_upright, end_low).
body(r10_destination_upright, end_upside_down).
body(r10_destination_upright, grippy_destination).
body(r10_destination_upright, grippy_source).
body(r10_destination_upright, heavy_destination).
body(r10_destination_upright, heavy_liquid).
body(r10_destination_upright, light_source).
body(r10_destination_upright, pour_in_line).
body(r10_destination_upright, pour_low).
body(r10_destination_upright, pour_slightly_tilted).
body(r10_destination_upright, runny_liquid).
body(r10_destination_upright, slow_approach).
body(r10_destination_upright, slow_retreat).
body(r10_destination_upright, start_below_rim).
body(r10_destination_upright, very_much_liquid).
learned(r10_destination_upright).
provenance(r10_destination_upright, antecedent, a10).
provenance(r10_destination_upright, parent, a9).
provenance(r10_destination_upright, simulations, 35).
provenance(r10_destination_upright, weight_mass_permille, 30385).
provenance(r10_destination_upright, confidence_permille, 734).
provenance(r10_destination_upright, score_permille, 699).
provenance(r10_destination_upright, batches, 1).

rule(r10_source_clear, defeasible, neg(source_clear)).
body(r10_source_clear, approach_moving_away).
body(r10_source_clear, dull_destination).
body(r10_source_clear, dull_source).
body(r10_source_clear, end_centred).
body(r10_source_clear, end_level).
body(r10_source_clear, end_low).
body(r10_source_clear, end_upside_down).
body(r10_source_clear, grippy_destination).
body(r10_source_clear, grippy_source).
body(r10_source_clear, heavy_destination).
body(r10_source_clear, heavy_liquid).
body(r10_source_clear, light_source).
body(r10_source_clear, pour_in_line).
body(r10_source_clear, pour_low).
body(r10_source_clear, pour_slightly_tilted).
body(r10_source_clear, runny_liquid).
body(r10_source_clear, slow_approach).
body(r10_source_clear, slow_retreat).
body(r10_source_clear, start_below_rim).
body(r10_source_clear, very_much_liquid).
learned(r10_source_clear).
provenance(r10_source_clear, antecedent, a10).
provenance(r10_source_clear, parent, a9).
provenance(r10_source_clear, simulations, 35).
provenance(r10_source_clear, weight_mass_permille, 30385).
provenance(r10_source_clear, confidence_permille, 1000).
provenance(r10_source_clear, score_permille, 0).
provenance(r10_source_clear, batches, 1).

rule(r10_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r10_liquid_leaves_source, approach_moving_away).
body(r10_liquid_leaves_source, dull_destination).
body(r10_liquid_leaves_source, dull_source).
body(r10_liquid_leaves_source, end_centred).
body(r10_liquid_leaves_source, end_level).
body(r10_liquid_leaves_source, end_low).
body(r10_liquid_leaves_source, end_upside_down).
body(r10_liquid_leaves_source, grippy_destination).
body(r10_liquid_leaves_source, grippy_source).
body(r10_liquid_leaves_source, heavy_destination).
body(r10_liquid_leaves_source, heavy_liquid).
body(r10_liquid_leaves_source, light_source).
body(r10_liquid_leaves_source, pour_in_line).
body(r10_liquid_leaves_source, pour_low).
body(r10_liquid_leaves_source, pour_slightly_tilted).
body(r10_liquid_leaves_source, runny_liquid).
body(r10_liquid_leaves_source, slow_approach).
body(r10_liquid_leaves_source, slow_retreat).
body(r10_liquid_leaves_source, start_below_rim).
body(r10_liquid_leaves_source, very_much_liquid).
learned(r10_liquid_leaves_source).
provenance(r10_liquid_leaves_source, antecedent, a10).
provenance(r10_liquid_leaves_source, parent, a9).
provenance(r10_liquid_leaves_source, simulations, 35).
provenance(r10_liquid_leaves_source, weight_mass_permille, 30385).
provenance(r10_liquid_leaves_source, confidence_permille, 1000).
provenance(r10_liquid_leaves_source, score_permille, 999).
provenance(r10_liquid_leaves_source, batches, 1).

rule(r10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r10_liquid_enters_destination, approach_moving_away).
body(r10_liquid_enters_destination, dull_destination).
body(r10_liquid_enters_destination, dull_source).
body(r10_liquid_enters_destination, end_centred).
body(r10_liquid_enters_destination, end_level).
body(r10_liquid_enters_destination, end_low).
body(r10_liquid_enters_destination, end_upside_down).
body(r10_liquid_enters_destination, grippy_destination).
body(r10_liquid_enters_destination, grippy_source).
body(r10_liquid_enters_destination, heavy_destination).
body(r10_liquid_enters_destination, heavy_liquid).
body(r10_liquid_enters_destination, light_source).
body(r10_liquid_enters_destination, pour_in_line).
body(r10_liquid_enters_destination, pour_low).
body(r10_liquid_enters_destination, pour_slightly_tilted).
body(r10_liquid_enters_destination, runny_liquid).
body(r10_liquid_enters_destination, slow_approach).
body(r10_liquid_enters_destination, slow_retreat).
body(r10_liquid_enters_destination, start_below_rim).
body(r10_liquid_enters_destination, very_much_liquid).
learned(r10_liquid_enters_destination).
provenance(r10_liquid_enters_destination, antecedent, a10).
provenance(r10_liquid_enters_destination, parent, a9).
provenance(r10_liquid_enters_destination, simulations, 35).
provenance(r10_liquid_enters_destination, weight_mass_permille, 30385).
provenance(r10_liquid_enters_destination, confidence_permille, 701).
provenance(r10_liquid_enters_destination, score_permille, 655).
provenance(r10_liquid_enters_destination, batches, 1).

rule(r10_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r10_liquid_remains_in_destination, approach_moving_away).
body(r10_liquid_remains_in_destination, dull_destination).
body(r10_liquid_remains_in_destination, dull_source).
body(r10_liquid_remains_in_destination, end_centred).
body(r10_liquid_remains_in_destination, end_level).
body(r10_liquid_remains_in_destination, end_low).
body(r10_liquid_remains_in_destination, end_upside_down).
body(r10_liquid_remains_in_destination, grippy_destination).
body(r10_liquid_remains_in_destination, grippy_source).
body(r10_liquid_remains_in_destination, heavy_destination).
body(r10_liquid_remains_in_destination, heavy_liquid).
body(r10_liquid_remains_in_destination, light_source).
body(r10_liquid_remains_in_destination, pour_in_line).
body(r10_liquid_remains_in_destination, pour_low).
body(r10_liquid_remains_in_destination, pour_slightly_tilted).
body(r10_liquid_remains_in_destination, runny_liquid).
body(r10_liquid_remains_in_destination, slow_approach).
body(r10_liquid_remains_in_destination, slow_retreat).
body(r10_liquid_remains_in_destination, start_below_rim).
body(r10_liquid_remains_in_destination, very_much_liquid).
learned(r10_liquid_remains_in_destination).
provenance(r10_liquid_remains_in_destination, antecedent, a10).
provenance(r10_liquid_remains_in_destination, parent, a9).
provenance(r10_liquid_remains_in_destination, simulations, 35).
provenance(r10_liquid_remains_in_destination, weight_mass_permille, 30385).
provenance(r10_liquid_remains_in_destination, confidence_permille, 851).
provenance(r10_liquid_remains_in_destination, score_permille, 826).
provenance(r10_liquid_remains_in_destination, batches, 1).

rule(r10_no_spill, defeasible, no_spill).
body(r10_no_spill, approach_moving_away).
body(r10_no_spill, dull_destination).
body(r10_no_spill, dull_source).
body(r10_no_spill, end_centred).
body(r10_no_spill, end_level).
body(r10_no_spill, end_low).
body(r10_no_spill, end_upside_down).
body(r10_no_spill, grippy_destination).
body(r10_no_spill, grippy_source).
body(r10_no_spill, heavy_destination).
body(r10_no_spill, heavy_liquid).
body(r10_no_spill, light_source).
body(r10_no_spill, pour_in_line).
body(r10_no_spill, pour_low).
body(r10_no_spill, pour_slightly_tilted).
body(r10_no_spill, runny_liquid).
body(r10_no_spill, slow_approach).
body(r10_no_spill, slow_retreat).
body(r10_no_spill, start_below_rim).
body(r10_no_spill, very_much_liquid).
learned(r10_no_spill).
provenance(r10_no_spill, antecedent, a10).
provenance(r10_no_spill, parent, a9).
provenance(r10_no_spill, simulations, 35).
provenance(r10_no_spill, weight_mass_permille, 30385).
provenance(r10_no_spill, confidence_permille, 534).
provenance(r10_no_spill, score_permille, 534).
provenance(r10_no_spill, batches, 1).

rule(r11_destination_still_approach, defeasible, destination_still_approach).
body(r11_destination_still_approach, approach_moving_closer).
body(r11_destination_still_approach, bouncy_source).
body(r11_destination_still_approach, dull_destination).
body(r11_destination_still_approach, end_centred).
body(r11_destination_still_approach, end_half_tilted).
body(r11_destination_still_approach, end_level).
body(r11_destination_still_approach, end_low).
body(r11_destination_still_approach, grippy_destination).
body(r11_destination_still_approach, grippy_source).
body(r11_destination_still_approach, heavy_destination).
body(r11_destination_still_approach, heavy_liquid).
body(r11_destination_still_approach, light_source).
body(r11_destination_still_approach, pour_in_line).
body(r11_destination_still_approach, pour_slightly_tilted).
body(r11_destination_still_approach, runny_liquid).
body(r11_destination_still_approach, slow_approach).
body(r11_destination_still_approach, slow_retreat).
body(r11_destination_still_approach, start_below_rim).
body(r11_destination_still_approach, very_much_liquid).
learned(r11_destination_still_approach).
provenance(r11_destination_still_approach, antecedent, a11).
provenance(r11_destination_still_approach, parent, a7).
provenance(r11_destination_still_approach, simulations, 35).
provenance(r11_destination_still_approach, weight_mass_permille, 35000).
provenance(r11_destination_still_approach, confidence_permille, 543).
provenance(r11_destination_still_approach, score_permille, 537).
provenance(r11_destination_still_approach, batches, 1).

rule(r11_destination_still_retreat, defeasible, destination_still_retreat).
body(r11_destination_still_retreat, approach_moving_closer).
body(r11_destination_still_retreat, bouncy_source).
body(r11_destination_still_retreat, dull_destination).
body(r11_destination_still_retreat, end_centred).
body(r11_destination_still_retreat, end_half_tilted).
body(r11_destination_still_retreat, end_level).
body(r11_destination_still_retreat, end_low).
body(r11_destination_still_retreat, grippy_destination).
body(r11_destination_still_retreat, grippy_source).
body(r11_destination_still_retreat, heavy_destination).
body(r11_destination_still_retreat, heavy_liquid).
body(r11_destination_still_retreat, light_source).
body(r11_destination_still_retreat, pour_in_line).
body(r11_destination_still_retreat, pour_slightly_tilted).
body(r11_destination_still_retreat, runny_liquid).
body(r11_destination_still_retreat, slow_approach).
body(r11_destination_still_retreat, slow_retreat).
body(r11_destination_still_retreat, start_below_rim).
body(r11_destination_still_retreat, very_much_liquid).
learned(r11_destination_still_retreat).
provenance(r11_destination_still_retreat, antecedent, a11).
provenance(r11_destination_still_retreat, parent, a7).
provenance(r11_destination_still_retreat, simulations, 35).
provenance(r11_destination_still_retreat, weight_mass_permille, 35000).
provenance(r11_destination_still_retreat, confidence_permille, 743).
provenance(r11_destination_still_retreat, score_permille, 747).
provenance(r11_destination_still_retreat, batches, 1).

rule(r11_destination_still_settle, defeasible, destination_still_settle).
body(r11_destination_still_settle, approach_moving_closer).
body(r11_destination_still_settle, bouncy_source).
body(r11_destination_still_settle, dull_destination).
body(r11_destination_still_settle, end_centred).
body(r11_destination_still_settle, end_half_tilted).
body(r11_destination_still_settle, end_level).
body(r11_destination_still_settle, end_low).
body(r11_destination_still_settle, grippy_destination).
body(r11_destination_still_settle, grippy_source).
body(r11_destination_still_settle, heavy_destination).
body(r11_destination_still_settle, heavy_liquid).
body(r11_destination_still_settle, light_source).
body(r11_destination_still_settle, pour_in_line).
body(r11_destination_still_settle, pour_slightly_tilted).
body(r11_destination_still_settle, runny_liquid).
body(r11_destination_still_settle, slow_approach).
body(r11_destination_still_settle, slow_retreat).
body(r11_destination_still_settle, start_below_rim).
body(r11_destination_still_settle, very_much_liquid).
learned(r11_destination_still_settle).
provenance(r11_destination_still_settle, antecedent, a11).
provenance(r11_destination_still_settle, parent, a7).
provenance(r11_destination_still_settle, simulations, 35).
provenance(r11_destination_still_settle, weight_mass_permille, 35000).
provenance(r11_destination_still_settle, confidence_permille, 800).
provenance(r11_destination_still_settle, score_permille, 796).
provenance(r11_destination_still_settle, batches, 1).

rule(r11_destination_upright, defeasible, destination_upright).
body(r11_destination_upright, approach_moving_closer).
body(r11_destination_upright, bouncy_source).
body(r11_destination_upright, dull_destination).
body(r11_destination_upright, end_centred).
body(r11_destination_upright, end_half_tilted).
body(r11_destination_upright, end_level).
body(r11_destination_upright, end_low).
body(r11_destination_upright, grippy_destination).
body(r11_destination_upright, grippy_source).
body(r11_destination_upright, heavy_destination).
body(r11_destination_upright, heavy_liquid).
body(r11_destination_upright, light_source).
body(r11_destination_upright, pour_in_line).
body(r11_destination_upright, pour_slightly_tilted).
body(r11_destination_upright, runny_liquid).
body(r11_destination_upright, slow_approach).
body(r11_destination_upright, slow_retreat).
body(r11_destination_upright, start_below_rim).
body(r11_destination_upright, very_much_liquid).
learned(r11_destination_upright).
provenance(r11_destination_upright, antecedent, a11).
provenance(r11_destination_upright, parent, a7).
provenance(r11_destination_upright, simulations, 35).
provenance(r11_destination_upright, weight_mass_permille, 35000).
provenance(r11_destination_upright, confidence_permille, 943).
provenance(r11_destination_upright, score_permille, 904).
provenance(r11_destination_upright, batches, 1).

rule(r11_source_clear, defeasible, neg(source_clear)).
body(r11_source_clear, approach_moving_closer).
body(r11_source_clear, bouncy_source).
body(r11_source_clear, dull_destination).
body(r11_source_clear, end_centred).
body(r11_source_clear, end_half_tilted).
body(r11_source_clear, end_level).
body(r11_source_clear, end_low).
body(r11_source_clear, grippy_destination).
body(r11_source_clear, grippy_source).
body(r11_source_clear, heavy_destination).
body(r11_source_clear, heavy_liquid).
body(r11_source_clear, light_source).
body(r11_source_clear, pour_in_line).
body(r11_source_clear, pour_slightly_tilted).
body(r11_source_clear, runny_liquid).
body(r11_source_clear, slow_approach).
body(r11_source_clear, slow_retreat).
body(r11_source_clear, start_below_rim).
body(r11_source_clear, very_much_liquid).
learned(r11_source_clear).
provenance(r11_source_clear, antecedent, a11).
provenance(r11_source_clear, parent, a7).
provenance(r11_source_clear, simulations, 35).
provenance(r11_source_clear, weight_mass_permille, 35000).
provenance(r11_source_clear, confidence_permille, 771).
provenance(r11_source_clear, score_permille, 202).
provenance(r11_source_clear, batches, 1).

rule(r11_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r11_liquid_leaves_source, approach_moving_closer).
body(r11_liquid_leaves_source, bouncy_source).
body(r11_liquid_leaves_source, dull_destination).
body(r11_liquid_leaves_source, end_centred).
body(r11_liquid_leaves_source, end_half_tilted).
body(r11_liquid_leaves_source, end_level).
body(r11_liquid_leaves_source, end_low).
body(r11_liquid_leaves_source, grippy_destination).
body(r11_liquid_leaves_source, grippy_source).
body(r11_liquid_leaves_source, heavy_destination).
body(r11_liquid_leaves_source, heavy_liquid).
body(r11_liquid_leaves_source, light_source).
body(r11_liquid_leaves_source, pour_in_line).
body(r11_liquid_leaves_source, pour_slightly_tilted).
body(r11_liquid_leaves_source, runny_liquid).
body(r11_liquid_leaves_source, slow_approach).
body(r11_liquid_leaves_source, slow_retreat).
body(r11_liquid_leaves_source, start_below_rim).
body(r11_liquid_leaves_source, very_much_liquid).
learned(r11_liquid_leaves_source).
provenance(r11_liquid_leaves_source, antecedent, a11).
provenance(r11_liquid_leaves_source, parent, a7).
provenance(r11_liquid_leaves_source, simulations, 35).
provenance(r11_liquid_leaves_source, weight_mass_permille, 35000).
provenance(r11_liquid_leaves_source, confidence_permille, 629).
provenance(r11_liquid_leaves_source, score_permille, 611).
provenance(r11_liquid_leaves_source, batches, 1).

rule(r11_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r11_liquid_enters_destination, approach_moving_closer).
body(r11_liquid_enters_destination, bouncy_source).
body(r11_liquid_enters_destination, dull_destination).
body(r11_liquid_enters_destination, end_centred).
body(r11_liquid_enters_destination, end_half_tilted).
body(r11_liquid_enters_destination, end_level).
body(r11_liquid_enters_destination, end_low).
body(r11_liquid_enters_destination, grippy_destination).
body(r11_liquid_enters_destination, grippy_source).
body(r11_liquid_enters_destination, heavy_destination).
body(r11_liquid_enters_destination, heavy_liquid).
body(r11_liquid_enters_destination, light_source).
body(r11_liquid_enters_destination, pour_in_line).
body(r11_liquid_enters_destination, pour_slightly_tilted).
body(r11_liquid_enters_destination, runny_liquid).
body(r11_liquid_enters_destination, slow_approach).
body(r11_liquid_enters_destination, slow_retreat).
body(r11_liquid_enters_destination, start_below_rim).
body(r11_liquid_enters_destination, very_much_liquid).
learned(r11_liquid_enters_destination).
provenance(r11_liquid_enters_destination, antecedent, a11).
provenance(r11_liquid_enters_destination, parent, a7).
provenance(r11_liquid_enters_destination, simulations, 35).
provenance(r11_liquid_enters_destination, weight_mass_permille, 35000).
provenance(r11_liquid_enters_destination, confidence_permille, 657).
provenance(r11_liquid_enters_destination, score_permille, 387).
provenance(r11_liquid_enters_destination, batches, 1).

rule(r11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r11_liquid_remains_in_destination, approach_moving_closer).
body(r11_liquid_remains_in_destination, bouncy_source).
body(r11_liquid_remains_in_destination, dull_destination).
body(r11_liquid_remains_in_destination, end_centred).
body(r11_liquid_remains_in_destination, end_half_tilted).
body(r11_liquid_remains_in_destination, end_level).
body(r11_liquid_remains_in_destination, end_low).
body(r11_liquid_remains_in_destination, grippy_destination).
body(r11_liquid_remains_in_destination, grippy_source).
body(r11_liquid_remains_in_destination, heavy_destination).
body(r11_liquid_remains_in_destination, heavy_liquid).
body(r11_liquid_remains_in_destination, light_source).
body(r11_liquid_remains_in_destination, pour_in_line).
body(r11_liquid_remains_in_destination, pour_slightly_tilted).
body(r11_liquid_remains_in_destination, runny_liquid).
body(r11_liquid_remains_in_destination, slow_approach).
body(r11_liquid_remains_in_destination, slow_retreat).
body(r11_liquid_remains_in_destination, start_below_rim).
body(r11_liquid_remains_in_destination, very_much_liquid).
learned(r11_liquid_remains_in_destination).
provenance(r11_liquid_remains_in_destination, antecedent, a11).
provenance(r11_liquid_remains_in_destination, parent, a7).
provenance(r11_liquid_remains_in_destination, simulations, 35).
provenance(r11_liquid_remains_in_destination, weight_mass_permille, 35000).
provenance(r11_liquid_remains_in_destination, confidence_permille, 800).
provenance(r11_liquid_remains_in_destination, score_permille, 755).
provenance(r11_liquid_remains_in_destination, batches, 1).

rule(r11_no_spill, defeasible, no_spill).
body(r11_no_spill, approach_moving_closer).
body(r11_no_spill, bouncy_source).
body(r11_no_spill, dull_destination).
body(r11_no_spill, end_centred).
body(r11_no_spill, end_half_tilted).
body(r11_no_spill, end_level).
body(r11_no_spill, end_low).
body(r11_no_spill, grippy_destination).
body(r11_no_spill, grippy_source).
body(r11_no_spill, heavy_destination).
body(r11_no_spill, heavy_liquid).
body(r11_no_spill, light_source).
body(r11_no_spill, pour_in_line).
body(r11_no_spill, pour_slightly_tilted).
body(r11_no_spill, runny_liquid).
body(r11_no_spill, slow_approach).
body(r11_no_spill, slow_retreat).
body(r11_no_spill, start_below_rim).
body(r11_no_spill, very_much_liquid).
learned(r11_no_spill).
provenance(r11_no_spill, antecedent, a11).
provenance(r11_no_spill, parent, a7).
provenance(r11_no_spill, simulations, 35).
provenance(r11_no_spill, weight_mass_permille, 35000).
provenance(r11_no_spill, confidence_permille, 743).
provenance(r11_no_spill, score_permille, 686).
provenance(r11_no_spill, batches, 1).

rule(r12_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r12_destination_still_approach, approach_moving_away).
body(r12_destination_still_approach, bouncy_destination).
body(r12_destination_still_approach, dull_source).
body(r12_destination_still_approach, end_centred).
body(r12_destination_still_approach, end_half_tilted).
body(r12_destination_still_approach, end_level).
body(r12_destination_still_approach, end_low).
body(r12_destination_still_approach, grippy_destination).
body(r12_destination_still_approach, grippy_source).
body(r12_destination_still_approach, heavy_destination).
body(r12_destination_still_approach, heavy_liquid).
body(r12_destination_still_approach, light_source).
body(r12_destination_still_approach, pour_in_line).
body(r12_destination_still_approach, pour_slightly_tilted).
body(r12_destination_still_approach, runny_liquid).
body(r12_destination_still_approach, slow_approach).
body(r12_destination_still_approach, slow_retreat).
body(r12_destination_still_approach, start_below_rim).
body(r12_destination_still_approach, very_much_liquid).
learned(r12_destination_still_approach).
provenance(r12_destination_still_approach, antecedent, a12).
provenance(r12_destination_still_approach, parent, a8).
provenance(r12_destination_still_approach, simulations, 31).
provenance(r12_destination_still_approach, weight_mass_permille, 31000).
provenance(r12_destination_still_approach, confidence_permille, 581).
provenance(r12_destination_still_approach, score_permille, 402).
provenance(r12_destination_still_approach, batches, 1).

rule(r12_destination_still_retreat, defeasible, destination_still_retreat).
body(r12_destination_still_retreat, approach_moving_away).
body(r12_destination_still_retreat, bouncy_destination).
body(r12_destination_still_retreat, dull_source).
body(r12_destination_still_retreat, end_centred).
body(r12_destination_still_retreat, end_half_tilted).
body(r12_destination_still_retreat, end_level).
body(r12_destination_still_retreat, end_low).
body(r12_destination_still_retreat, grippy_destination).
body(r12_destination_still_retreat, grippy_source).
body(r12_destination_still_retreat, heavy_destination).
body(r12_destination_still_retreat, heavy_liquid).
body(r12_destination_still_retreat, light_source).
body(r12_destination_still_retreat, pour_in_line).
body(r12_destination_still_retreat, pour_slightly_tilted).
body(r12_destination_still_retreat, runny_liquid).
body(r12_destination_still_retreat, slow_approach).
body(r12_destination_still_retreat, slow_retreat).
body(r12_destination_still_retreat, start_below_rim).
body(r12_destination_still_retreat, very_much_liquid).
learned(r12_destination_still_retreat).
provenance(r12_destination_still_retreat, antecedent, a12).
provenance(r12_destination_still_retreat, parent, a8).
provenance(r12_destination_still_retreat, simulations, 31).
provenance(r12_destination_still_retreat, weight_mass_permille, 31000).
provenance(r12_destination_still_retreat, confidence_permille, 742).
provenance(r12_destination_still_retreat, score_permille, 722).
provenance(r12_destination_still_retreat, batches, 1).

rule(r12_destination_still_settle, defeasible, destination_still_settle).
body(r12_destination_still_settle, approach_moving_away).
body(r12_destination_still_settle, bouncy_destination).
body(r12_destination_still_settle, dull_source).
body(r12_destination_still_settle, end_centred).
body(r12_destination_still_settle, end_half_tilted).
body(r12_destination_still_settle, end_level).
body(r12_destination_still_settle, end_low).
body(r12_destination_still_settle, grippy_destination).
body(r12_destination_still_settle, grippy_source).
body(r12_destination_still_settle, heavy_destination).
body(r12_destination_still_settle, heavy_liquid).
body(r12_destination_still_settle, light_source).
body(r12_destination_still_settle, pour_in_line).
body(r12_destination_still_settle, pour_slightly_tilted).
body(r12_destination_still_settle, runny_liquid).
body(r12_destination_still_settle, slow_approach).
body(r12_destination_still_settle, slow_retreat).
body(r12_destination_still_settle, start_below_rim).
body(r12_destination_still_settle, very_much_liquid).
learned(r12_destination_still_settle).
provenance(r12_destination_still_settle, antecedent, a12).
provenance(r12_destination_still_settle, parent, a8).
provenance(r12_destination_still_settle, simulations, 31).
provenance(r12_destination_still_settle, weight_mass_permille, 31000).
provenance(r12_destination_still_settle, confidence_permille, 839).
provenance(r12_destination_still_settle, score_permille, 827).
provenance(r12_destination_still_settle, batches, 1).

rule(r12_destination_upright, defeasible, destination_upright).
body(r12_destination_upright, approach_moving_away).
body(r12_destination_upright, bouncy_destination).
body(r12_destination_upright, dull_source).
body(r12_destination_upright, end_centred).
body(r12_destination_upright, end_half_tilted).
body(r12_destination_upright, end_level).
body(r12_destination_upright, end_low).
body(r12_destination_upright, grippy_destination).
body(r12_destination_upright, grippy_source).
body(r12_destination_upright, heavy_destination).
body(r12_destination_upright, heavy_liquid).
body(r12_destination_upright, light_source).
body(r12_destination_upright, pour_in_line).
body(r12_destination_upright, pour_slightly_tilted).
body(r12_destination_upright, runny_liquid).
body(r12_destination_upright, slow_approach).
body(r12_destination_upright, slow_retreat).
body(r12_destination_upright, start_below_rim).
body(r12_destination_upright, very_much_liquid).
learned(r12_destination_upright).
provenance(r12_destination_upright, antecedent, a12).
provenance(r12_destination_upright, parent, a8).
provenance(r12_destination_upright, simulations, 31).
provenance(r12_destination_upright, weight_mass_permille, 31000).
provenance(r12_destination_upright, confidence_permille, 903).
provenance(r12_destination_upright, score_permille, 893).
provenance(r12_destination_upright, batches, 1).

rule(r12_source_clear, defeasible, neg(source_clear)).
body(r12_source_clear, approach_moving_away).
body(r12_source_clear, bouncy_destination).
body(r12_source_clear, dull_source).
body(r12_source_clear, end_centred).
body(r12_source_clear, end_half_tilted).
body(r12_source_clear, end_level).
body(r12_source_clear, end_low).
body(r12_source_clear, grippy_destination).
body(r12_source_clear, grippy_source).
body(r12_source_clear, heavy_destination).
body(r12_source_clear, heavy_liquid).
body(r12_source_clear, light_source).
body(r12_source_clear, pour_in_line).
body(r12_source_clear, pour_slightly_tilted).
body(r12_source_clear, runny_liquid).
body(r12_source_clear, slow_approach).
body(r12_source_clear, slow_retreat).
body(r12_source_clear, start_below_rim).
body(r12_source_clear, very_much_liquid).
learned(r12_source_clear).
provenance(r12_source_clear, antecedent, a12).
provenance(r12_source_clear, parent, a8).
provenance(r12_source_clear, simulations, 31).
provenance(r12_source_clear, weight_mass_permille, 31000).
provenance(r12_source_clear, confidence_permille, 903).
provenance(r12_source_clear, score_permille, 65).
provenance(r12_source_clear, batches, 1).

rule(r12_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r12_liquid_leaves_source, approach_moving_away).
body(r12_liquid_leaves_source, bouncy_destination).
body(r12_liquid_leaves_source, dull_source).
body(r12_liquid_leaves_source, end_centred).
body(r12_liquid_leaves_source, end_half_tilted).
body(r12_liquid_leaves_source, end_level).
body(r12_liquid_leaves_source, end_low).
body(r12_liquid_leaves_source, grippy_destination).
body(r12_liquid_leaves_source, grippy_source).
body(r12_liquid_leaves_source, heavy_destination).
body(r12_liquid_leaves_source, heavy_liquid).
body(r12_liquid_leaves_source, light_source).
body(r12_liquid_leaves_source, pour_in_line).
body(r12_liquid_leaves_source, pour_slightly_tilted).
body(r12_liquid_leaves_source, runny_liquid).
body(r12_liquid_leaves_source, slow_approach).
body(r12_liquid_leaves_source, slow_retreat).
body(r12_liquid_leaves_source, start_below_rim).
body(r12_liquid_leaves_source, very_much_liquid).
learned(r12_liquid_leaves_source).
provenance(r12_liquid_leaves_source, antecedent, a12).
provenance(r12_liquid_leaves_source, parent, a8).
provenance(r12_liquid_leaves_source, simulations, 31).
provenance(r12_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r12_liquid_leaves_source, confidence_permille, 613).
provenance(r12_liquid_leaves_source, score_permille, 472).
provenance(r12_liquid_leaves_source, batches, 1).

rule(r12_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r12_liquid_enters_destination, approach_moving_away).
body(r12_liquid_enters_destination, bouncy_destination).
body(r12_liquid_enters_destination, dull_source).
body(r12_liquid_enters_destination, end_centred).
body(r12_liquid_enters_destination, end_half_tilted).
body(r12_liquid_enters_destination, end_level).
body(r12_liquid_enters_destination, end_low).
body(r12_liquid_enters_destination, grippy_destination).
body(r12_liquid_enters_destination, grippy_source).
body(r12_liquid_enters_destination, heavy_destination).
body(r12_liquid_enters_destination, heavy_liquid).
body(r12_liquid_enters_destination, light_source).
body(r12_liquid_enters_destination, pour_in_line).
body(r12_liquid_enters_destination, pour_slightly_tilted).
body(r12_liquid_enters_destination, runny_liquid).
body(r12_liquid_enters_destination, slow_approach).
body(r12_liquid_enters_destination, slow_retreat).
body(r12_liquid_enters_destination, start_below_rim).
body(r12_liquid_enters_destination, very_much_liquid).
learned(r12_liquid_enters_destination).
provenance(r12_liquid_enters_destination, antecedent, a12).
provenance(r12_liquid_enters_destination, parent, a8).
provenance(r12_liquid_enters_destination, simulations, 31).
provenance(r12_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r12_liquid_enters_destination, confidence_permille, 581).
provenance(r12_liquid_enters_destination, score_permille, 471).
provenance(r12_liquid_enters_destination, batches, 1).

rule(r12_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r12_liquid_remains_in_destination, approach_moving_away).
body(r12_liquid_remains_in_destination, bouncy_destination).
body(r12_liquid_remains_in_destination, dull_source).
body(r12_liquid_remains_in_destination, end_centred).
body(r12_liquid_remains_in_destination, end_half_tilted).
body(r12_liquid_remains_in_destination, end_level).
body(r12_liquid_remains_in_destination, end_low).
body(r12_liquid_remains_in_destination, grippy_destination).
body(r12_liquid_remains_in_destination, grippy_source).
body(r12_liquid_remains_in_destination, heavy_destination).
body(r12_liquid_remains_in_destination, heavy_liquid).
body(r12_liquid_remains_in_destination, light_source).
body(r12_liquid_remains_in_destination, pour_in_line).
body(r12_liquid_remains_in_destination, pour_slightly_tilted).
body(r12_liquid_remains_in_destination, runny_liquid).
body(r12_liquid_remains_in_destination, slow_approach).
body(r12_liquid_remains_in_destination, slow_retreat).
body(r12_liquid_remains_in_destination, start_below_rim).
body(r12_liquid_remains_in_destination, very_much_liquid).
learned(r12_liquid_remains_in_destination).
provenance(r12_liquid_remains_in_destination, antecedent, a12).
provenance(r12_liquid_remains_in_destination, parent, a8).
provenance(r12_liquid_remains_in_destination, simulations, 31).
provenance(r12_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r12_liquid_remains_in_destination, confidence_permille, 613).
provenance(r12_liquid_remains_in_destination, score_permille, 417).
provenance(r12_liquid_remains_in_destination, batches, 1).

rule(r12_no_spill, defeasible, no_spill).
body(r12_no_spill, approach_moving_away).
body(r12_no_spill, bouncy_destination).
body(r12_no_spill, dull_source).
body(r12_no_spill, end_centred).
body(r12_no_spill, end_half_tilted).
body(r12_no_spill, end_level).
body(r12_no_spill, end_low).
body(r12_no_spill, grippy_destination).
body(r12_no_spill, grippy_source).
body(r12_no_spill, heavy_destination).
body(r12_no_spill, heavy_liquid).
body(r12_no_spill, light_source).
body(r12_no_spill, pour_in_line).
body(r12_no_spill, pour_slightly_tilted).
body(r12_no_spill, runny_liquid).
body(r12_no_spill, slow_approach).
body(r12_no_spill, slow_retreat).
body(r12_no_spill, start_below_rim).
body(r12_no_spill, very_much_liquid).
learned(r12_no_spill).
provenance(r12_no_spill, antecedent, a12).
provenance(r12_no_spill, parent, a8).
provenance(r12_no_spill, simulations, 31).
provenance(r12_no_spill, weight_mass_permille, 31000).
provenance(r12_no_spill, confidence_permille, 742).
provenance(r12_no_spill, score_permille, 663).
provenance(r12_no_spill, batches, 1).

rule(r13_destination_still_approach, defeasible, destination_still_approach).
body(r13_destination_still_approach, approach_moving_away).
body(r13_destination_still_approach, bouncy_destination).
body(r13_destination_still_approach, bouncy_source).
body(r13_destination_still_approach, end_centred).
body(r13_destination_still_approach, end_half_tilted).
body(r13_destination_still_approach, end_level).
body(r13_destination_still_approach, end_low).
body(r13_destination_still_approach, grippy_destination).
body(r13_destination_still_approach, grippy_source).
body(r13_destination_still_approach, heavy_destination).
body(r13_destination_still_approach, heavy_liquid).
body(r13_destination_still_approach, light_source).
body(r13_destination_still_approach, pour_in_line).
body(r13_destination_still_approach, pour_slightly_tilted).
body(r13_destination_still_approach, runny_liquid).
body(r13_destination_still_approach, slow_approach).
body(r13_destination_still_approach, slow_retreat).
body(r13_destination_still_approach, start_below_rim).
body(r13_destination_still_approach, very_much_liquid).
learned(r13_destination_still_approach).
provenance(r13_destination_still_approach, antecedent, a13).
provenance(r13_destination_still_approach, parent, a12).
provenance(r13_destination_still_approach, simulations, 31).
provenance(r13_destination_still_approach, weight_mass_permille, 31000).
provenance(r13_destination_still_approach, confidence_permille, 581).
provenance(r13_destination_still_approach, score_permille, 526).
provenance(r13_destination_still_approach, batches, 1).

rule(r13_destination_still_retreat, defeasible, destination_still_retreat).
body(r13_destination_still_retreat, approach_moving_away).
body(r13_destination_still_retreat, bouncy_destination).
body(r13_destination_still_retreat, bouncy_source).
body(r13_destination_still_retreat, end_centred).
body(r13_destination_still_retreat, end_half_tilted).
body(r13_destination_still_retreat, end_level).
body(r13_destination_still_retreat, end_low).
body(r13_destination_still_retreat, grippy_destination).
body(r13_destination_still_retreat, grippy_source).
body(r13_destination_still_retreat, heavy_destination).
body(r13_destination_still_retreat, heavy_liquid).
body(r13_destination_still_retreat, light_source).
body(r13_destination_still_retreat, pour_in_line).
body(r13_destination_still_retreat, pour_slightly_tilted).
body(r13_destination_still_retreat, runny_liquid).
body(r13_destination_still_retreat, slow_approach).
body(r13_destination_still_retreat, slow_retreat).
body(r13_destination_still_retreat, start_below_rim).
body(r13_destination_still_retreat, very_much_liquid).
learned(r13_destination_still_retreat).
provenance(r13_destination_still_retreat, antecedent, a13).
provenance(r13_destination_still_retreat, parent, a12).
provenance(r13_destination_still_retreat, simulations, 31).
provenance(r13_destination_still_retreat, weight_mass_permille, 31000).
provenance(r13_destination_still_retreat, confidence_permille, 806).
provenance(r13_destination_still_retreat, score_permille, 797).
provenance(r13_destination_still_retreat, batches, 1).

rule(r13_destination_still_settle, defeasible, destination_still_settle).
body(r13_destination_still_settle, approach_moving_away).
body(r13_destination_still_settle, bouncy_destination).
body(r13_destination_still_settle, bouncy_source).
body(r13_destination_still_settle, end_centred).
body(r13_destination_still_settle, end_half_tilted).
body(r13_destination_still_settle, end_level).
body(r13_destination_still_settle, end_low).
body(r13_destination_still_settle, grippy_destination).
body(r13_destination_still_settle, grippy_source).
body(r13_destination_still_settle, heavy_destination).
body(r13_destination_still_settle, heavy_liquid).
body(r13_destination_still_settle, light_source).
body(r13_destination_still_settle, pour_in_line).
body(r13_destination_still_settle, pour_slightly_tilted).
body(r13_destination_still_settle, runny_liquid).
body(r13_destination_still_settle, slow_approach).
body(r13_destination_still_settle, slow_retreat).
body(r13_destination_still_settle, start_below_rim).
body(r13_destination_still_settle, very_much_liquid).
learned(r13_destination_still_settle).
provenance(r13_destination_still_settle, antecedent, a13).
provenance(r13_destination_still_settle, parent, a12).
provenance(r13_destination_still_settle, simulations, 31).
provenance(r13_destination_still_settle, weight_mass_permille, 31000).
provenance(r13_destination_still_settle, confidence_permille, 774).
provenance(r13_destination_still_settle, score_permille, 806).
provenance(r13_destination_still_settle, batches, 1).

rule(r13_destination_upright, defeasible, destination_upright).
body(r13_destination_upright, approach_moving_away).
body(r13_destination_upright, bouncy_destination).
body(r13_destination_upright, bouncy_source).
body(r13_destination_upright, end_centred).
body(r13_destination_upright, end_half_tilted).
body(r13_destination_upright, end_level).
body(r13_destination_upright, end_low).
body(r13_destination_upright, grippy_destination).
body(r13_destination_upright, grippy_source).
body(r13_destination_upright, heavy_destination).
body(r13_destination_upright, heavy_liquid).
body(r13_destination_upright, light_source).
body(r13_destination_upright, pour_in_line).
body(r13_destination_upright, pour_slightly_tilted).
body(r13_destination_upright, runny_liquid).
body(r13_destination_upright, slow_approach).
body(r13_destination_upright, slow_retreat).
body(r13_destination_upright, start_below_rim).
body(r13_destination_upright, very_much_liquid).
learned(r13_destination_upright).
provenance(r13_destination_upright, antecedent, a13).
provenance(r13_destination_upright, parent, a12).
provenance(r13_destination_upright, simulations, 31).
provenance(r13_destination_upright, weight_mass_permille, 31000).
provenance(r13_destination_upright, confidence_permille, 968).
provenance(r13_destination_upright, score_permille, 946).
provenance(r13_destination_upright, batches, 1).

rule(r13_source_clear, defeasible, neg(source_clear)).
body(r13_source_clear, approach_moving_away).
body(r13_source_clear, bouncy_destination).
body(r13_source_clear, bouncy_source).
body(r13_source_clear, end_centred).
body(r13_source_clear, end_half_tilted).
body(r13_source_clear, end_level).
body(r13_source_clear, end_low).
body(r13_source_clear, grippy_destination).
body(r13_source_clear, grippy_source).
body(r13_source_clear, heavy_destination).
body(r13_source_clear, heavy_liquid).
body(r13_source_clear, light_source).
body(r13_source_clear, pour_in_line).
body(r13_source_clear, pour_slightly_tilted).
body(r13_source_clear, runny_liquid).
body(r13_source_clear, slow_approach).
body(r13_source_clear, slow_retreat).
body(r13_source_clear, start_below_rim).
body(r13_source_clear, very_much_liquid).
learned(r13_source_clear).
provenance(r13_source_clear, antecedent, a13).
provenance(r13_source_clear, parent, a12).
provenance(r13_source_clear, simulations, 31).
provenance(r13_source_clear, weight_mass_permille, 31000).
provenance(r13_source_clear, confidence_permille, 871).
provenance(r13_source_clear, score_permille, 81).
provenance(r13_source_clear, batches, 1).

rule(r13_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r13_liquid_leaves_source, approach_moving_away).
body(r13_liquid_leaves_source, bouncy_destination).
body(r13_liquid_leaves_source, bouncy_source).
body(r13_liquid_leaves_source, end_centred).
body(r13_liquid_leaves_source, end_half_tilted).
body(r13_liquid_leaves_source, end_level).
body(r13_liquid_leaves_source, end_low).
body(r13_liquid_leaves_source, grippy_destination).
body(r13_liquid_leaves_source, grippy_source).
body(r13_liquid_leaves_source, heavy_destination).
body(r13_liquid_leaves_source, heavy_liquid).
body(r13_liquid_leaves_source, light_source).
body(r13_liquid_leaves_source, pour_in_line).
body(r13_liquid_leaves_source, pour_slightly_tilted).
body(r13_liquid_leaves_source, runny_liquid).
body(r13_liquid_leaves_source, slow_approach).
body(r13_liquid_leaves_source, slow_retreat).
body(r13_liquid_leaves_source, start_below_rim).
body(r13_liquid_leaves_source, very_much_liquid).
learned(r13_liquid_leaves_source).
provenance(r13_liquid_leaves_source, antecedent, a13).
provenance(r13_liquid_leaves_source, parent, a12).
provenance(r13_liquid_leaves_source, simulations, 31).
provenance(r13_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r13_liquid_leaves_source, confidence_permille, 710).
provenance(r13_liquid_leaves_source, score_permille, 703).
provenance(r13_liquid_leaves_source, batches, 1).

rule(r13_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r13_liquid_enters_destination, approach_moving_away).
body(r13_liquid_enters_destination, bouncy_destination).
body(r13_liquid_enters_destination, bouncy_source).
body(r13_liquid_enters_destination, end_centred).
body(r13_liquid_enters_destination, end_half_tilted).
body(r13_liquid_enters_destination, end_level).
body(r13_liquid_enters_destination, end_low).
body(r13_liquid_enters_destination, grippy_destination).
body(r13_liquid_enters_destination, grippy_source).
body(r13_liquid_enters_destination, heavy_destination).
body(r13_liquid_enters_destination, heavy_liquid).
body(r13_liquid_enters_destination, light_source).
body(r13_liquid_enters_destination, pour_in_line).
body(r13_liquid_enters_destination, pour_slightly_tilted).
body(r13_liquid_enters_destination, runny_liquid).
body(r13_liquid_enters_destination, slow_approach).
body(r13_liquid_enters_destination, slow_retreat).
body(r13_liquid_enters_destination, start_below_rim).
body(r13_liquid_enters_destination, very_much_liquid).
learned(r13_liquid_enters_destination).
provenance(r13_liquid_enters_destination, antecedent, a13).
provenance(r13_liquid_enters_destination, parent, a12).
provenance(r13_liquid_enters_destination, simulations, 31).
provenance(r13_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r13_liquid_enters_destination, confidence_permille, 581).
provenance(r13_liquid_enters_destination, score_permille, 563).
provenance(r13_liquid_enters_destination, batches, 1).

rule(r13_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r13_liquid_remains_in_destination, approach_moving_away).
body(r13_liquid_remains_in_destination, bouncy_destination).
body(r13_liquid_remains_in_destination, bouncy_source).
body(r13_liquid_remains_in_destination, end_centred).
body(r13_liquid_remains_in_destination, end_half_tilted).
body(r13_liquid_remains_in_destination, end_level).
body(r13_liquid_remains_in_destination, end_low).
body(r13_liquid_remains_in_destination, grippy_destination).
body(r13_liquid_remains_in_destination, grippy_source).
body(r13_liquid_remains_in_destination, heavy_destination).
body(r13_liquid_remains_in_destination, heavy_liquid).
body(r13_liquid_remains_in_destination, light_source).
body(r13_liquid_remains_in_destination, pour_in_line).
body(r13_liquid_remains_in_destination, pour_slightly_tilted).
body(r13_liquid_remains_in_destination, runny_liquid).
body(r13_liquid_remains_in_destination, slow_approach).
body(r13_liquid_remains_in_destination, slow_retreat).
body(r13_liquid_remains_in_destination, start_below_rim).
body(r13_liquid_remains_in_destination, very_much_liquid).
learned(r13_liquid_remains_in_destination).
provenance(r13_liquid_remains_in_destination, antecedent, a13).
provenance(r13_liquid_remains_in_destination, parent, a12).
provenance(r13_liquid_remains_in_destination, simulations, 31).
provenance(r13_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r13_liquid_remains_in_destination, confidence_permille, 581).
provenance(r13_liquid_remains_in_destination, score_permille, 381).
provenance(r13_liquid_remains_in_destination, batches, 1).

rule(r13_no_spill, defeasible, no_spill).
body(r13_no_spill, approach_moving_away).
body(r13_no_spill, bouncy_destination).
body(r13_no_spill, bouncy_source).
body(r13_no_spill, end_centred).
body(r13_no_spill, end_half_tilted).
body(r13_no_spill, end_level).
body(r13_no_spill, end_low).
body(r13_no_spill, grippy_destination).
body(r13_no_spill, grippy_source).
body(r13_no_spill, heavy_destination).
body(r13_no_spill, heavy_liquid).
body(r13_no_spill, light_source).
body(r13_no_spill, pour_in_line).
body(r13_no_spill, pour_slightly_tilted).
body(r13_no_spill, runny_liquid).
body(r13_no_spill, slow_approach).
body(r13_no_spill, slow_retreat).
body(r13_no_spill, start_below_rim).
body(r13_no_spill, very_much_liquid).
learned(r13_no_spill).
provenance(r13_no_spill, antecedent, a13).
provenance(r13_no_spill, parent, a12).
provenance(r13_no_spill, simulations, 31).
provenance(r13_no_spill, weight_mass_permille, 31000).
provenance(r13_no_spill, confidence_permille, 516).
provenance(r13_no_spill, score_permille, 464).
provenance(r13_no_spill, batches, 1).

rule(r14_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r14_destination_still_approach, approach_raising).
body(r14_destination_still_approach, bouncy_destination).
body(r14_destination_still_approach, dull_source).
body(r14_destination_still_approach, end_near_rim).
body(r14_destination_still_approach, end_rolled).
body(r14_destination_still_approach, end_tilted_back).
body(r14_destination_still_approach, fast_retreat).
body(r14_destination_still_approach, grippy_destination).
body(r14_destination_still_approach, grippy_source).
body(r14_destination_still_approach, heavy_liquid).
body(r14_destination_still_approach, light_source).
body(r14_destination_still_approach, pour_below_rim).
body(r14_destination_still_approach, pour_rolled).
body(r14_destination_still_approach, pour_slightly_tilted).
body(r14_destination_still_approach, retreat_lowering).
body(r14_destination_still_approach, start_centred).
body(r14_destination_still_approach, start_upright).
learned(r14_destination_still_approach).
provenance(r14_destination_still_approach, antecedent, a14).
provenance(r14_destination_still_approach, parent, none).
provenance(r14_destination_still_approach, simulations, 31).
provenance(r14_destination_still_approach, weight_mass_permille, 31000).
provenance(r14_destination_still_approach, confidence_permille, 548).
provenance(r14_destination_still_approach, score_permille, 465).
provenance(r14_destination_still_approach, batches, 1).

rule(r14_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r14_destination_still_retreat, approach_raising).
body(r14_destination_still_retreat, bouncy_destination).
body(r14_destination_still_retreat, dull_source).
body(r14_destination_still_retreat, end_near_rim).
body(r14_destination_still_retreat, end_rolled).
body(r14_destination_still_retreat, end_tilted_back).
body(r14_destination_still_retreat, fast_retreat).
body(r14_destination_still_retreat, grippy_destination).
body(r14_destination_still_retreat, grippy_source).
body(r14_destination_still_retreat, heavy_liquid).
body(r14_destination_still_retreat, light_source).
body(r14_destination_still_retreat, pour_below_rim).
body(r14_destination_still_retreat, pour_rolled).
body(r14_destination_still_retreat, pour_slightly_tilted).
body(r14_destination_still_retreat, retreat_lowering).
body(r14_destination_still_retreat, start_centred).
body(r14_destination_still_retreat, start_upright).
learned(r14_destination_still_retreat).
provenance(r14_destination_still_retreat, antecedent, a14).
provenance(r14_destination_still_retreat, parent, none).
provenance(r14_destination_still_retreat, simulations, 31).
provenance(r14_destination_still_retreat, weight_mass_permille, 31000).
provenance(r14_destination_still_retreat, confidence_permille, 935).
provenance(r14_destination_still_retreat, score_permille, 38).
provenance(r14_destination_still_retreat, batches, 1).

rule(r14_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r14_destination_still_settle, approach_raising).
body(r14_destination_still_settle, bouncy_destination).
body(r14_destination_still_settle, dull_source).
body(r14_destination_still_settle, end_near_rim).
body(r14_destination_still_settle, end_rolled).
body(r14_destination_still_settle, end_tilted_back).
body(r14_destination_still_settle, fast_retreat).
body(r14_destination_still_settle, grippy_destination).
body(r14_destination_still_settle, grippy_source).
body(r14_destination_still_settle, heavy_liquid).
body(r14_destination_still_settle, light_source).
body(r14_destination_still_settle, pour_below_rim).
body(r14_destination_still_settle, pour_rolled).
body(r14_destination_still_settle, pour_slightly_tilted).
body(r14_destination_still_settle, retreat_lowering).
body(r14_destination_still_settle, start_centred).
body(r14_destination_still_settle, start_upright).
learned(r14_destination_still_settle).
provenance(r14_destination_still_settle, antecedent, a14).
provenance(r14_destination_still_settle, parent, none).
provenance(r14_destination_still_settle, simulations, 31).
provenance(r14_destination_still_settle, weight_mass_permille, 31000).
provenance(r14_destination_still_settle, confidence_permille, 548).
provenance(r14_destination_still_settle, score_permille, 454).
provenance(r14_destination_still_settle, batches, 1).

rule(r14_destination_upright, defeasible, destination_upright).
body(r14_destination_upright, approach_raising).
body(r14_destination_upright, bouncy_destination).
body(r14_destination_upright, dull_source).
body(r14_destination_upright, end_near_rim).
body(r14_destination_upright, end_rolled).
body(r14_destination_upright, end_tilted_back).
body(r14_destination_upright, fast_retreat).
body(r14_destination_upright, grippy_destination).
body(r14_destination_upright, grippy_source).
body(r14_destination_upright, heavy_liquid).
body(r14_destination_upright, light_source).
body(r14_destination_upright, pour_below_rim).
body(r14_destination_upright, pour_rolled).
body(r14_destination_upright, pour_slightly_tilted).
body(r14_destination_upright, retreat_lowering).
body(r14_destination_upright, start_centred).
body(r14_destination_upright, start_upright).
learned(r14_destination_upright).
provenance(r14_destination_upright, antecedent, a14).
provenance(r14_destination_upright, parent, none).
provenance(r14_destination_upright, simulations, 31).
provenance(r14_destination_upright, weight_mass_permille, 31000).
provenance(r14_destination_upright, confidence_permille, 871).
provenance(r14_destination_upright, score_permille, 771).
provenance(r14_destination_upright, batches, 1).

rule(r14_source_clear, defeasible, neg(source_clear)).
body(r14_source_clear, approach_raising).
body(r14_source_clear, bouncy_destination).
body(r14_source_clear, dull_source).
body(r14_source_clear, end_near_rim).
body(r14_source_clear, end_rolled).
body(r14_source_clear, end_tilted_back).
body(r14_source_clear, fast_retreat).
body(r14_source_clear, grippy_destination).
body(r14_source_clear, grippy_source).
body(r14_source_clear, heavy_liquid).
body(r14_source_clear, light_source).
body(r14_source_clear, pour_below_rim).
body(r14_source_clear, pour_rolled).
body(r14_source_clear, pour_slightly_tilted).
body(r14_source_clear, retreat_lowering).
body(r14_source_clear, start_centred).
body(r14_source_clear, start_upright).
learned(r14_source_clear).
provenance(r14_source_clear, antecedent, a14).
provenance(r14_source_clear, parent, none).
provenance(r14_source_clear, simulations, 31).
provenance(r14_source_clear, weight_mass_permille, 31000).
provenance(r14_source_clear, confidence_permille, 1000).
provenance(r14_source_clear, score_permille, 0).
provenance(r14_source_clear, batches, 1).

rule(r14_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r14_liquid_leaves_source, approach_raising).
body(r14_liquid_leaves_source, bouncy_destination).
body(r14_liquid_leaves_source, dull_source).
body(r14_liquid_leaves_source, end_near_rim).
body(r14_liquid_leaves_source, end_rolled).
body(r14_liquid_leaves_source, end_tilted_back).
body(r14_liquid_leaves_source, fast_retreat).
body(r14_liquid_leaves_source, grippy_destination).
body(r14_liquid_leaves_source, grippy_source).
body(r14_liquid_leaves_source, heavy_liquid).
body(r14_liquid_leaves_source, light_source).
body(r14_liquid_leaves_source, pour_below_rim).
body(r14_liquid_leaves_source, pour_rolled).
body(r14_liquid_leaves_source, pour_slightly_tilted).
body(r14_liquid_leaves_source, retreat_lowering).
body(r14_liquid_leaves_source, start_centred).
body(r14_liquid_leaves_source, start_upright).
learned(r14_liquid_leaves_source).
provenance(r14_liquid_leaves_source, antecedent, a14).
provenance(r14_liquid_leaves_source, parent, none).
provenance(r14_liquid_leaves_source, simulations, 31).
provenance(r14_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r14_liquid_leaves_source, confidence_permille, 1000).
provenance(r14_liquid_leaves_source, score_permille, 992).
provenance(r14_liquid_leaves_source, batches, 1).

rule(r14_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r14_liquid_enters_destination, approach_raising).
body(r14_liquid_enters_destination, bouncy_destination).
body(r14_liquid_enters_destination, dull_source).
body(r14_liquid_enters_destination, end_near_rim).
body(r14_liquid_enters_destination, end_rolled).
body(r14_liquid_enters_destination, end_tilted_back).
body(r14_liquid_enters_destination, fast_retreat).
body(r14_liquid_enters_destination, grippy_destination).
body(r14_liquid_enters_destination, grippy_source).
body(r14_liquid_enters_destination, heavy_liquid).
body(r14_liquid_enters_destination, light_source).
body(r14_liquid_enters_destination, pour_below_rim).
body(r14_liquid_enters_destination, pour_rolled).
body(r14_liquid_enters_destination, pour_slightly_tilted).
body(r14_liquid_enters_destination, retreat_lowering).
body(r14_liquid_enters_destination, start_centred).
body(r14_liquid_enters_destination, start_upright).
learned(r14_liquid_enters_destination).
provenance(r14_liquid_enters_destination, antecedent, a14).
provenance(r14_liquid_enters_destination, parent, none).
provenance(r14_liquid_enters_destination, simulations, 31).
provenance(r14_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r14_liquid_enters_destination, confidence_permille, 1000).
provenance(r14_liquid_enters_destination, score_permille, 1000).
provenance(r14_liquid_enters_destination, batches, 1).

rule(r14_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r14_liquid_remains_in_destination, approach_raising).
body(r14_liquid_remains_in_destination, bouncy_destination).
body(r14_liquid_remains_in_destination, dull_source).
body(r14_liquid_remains_in_destination, end_near_rim).
body(r14_liquid_remains_in_destination, end_rolled).
body(r14_liquid_remains_in_destination, end_tilted_back).
body(r14_liquid_remains_in_destination, fast_retreat).
body(r14_liquid_remains_in_destination, grippy_destination).
body(r14_liquid_remains_in_destination, grippy_source).
body(r14_liquid_remains_in_destination, heavy_liquid).
body(r14_liquid_remains_in_destination, light_source).
body(r14_liquid_remains_in_destination, pour_below_rim).
body(r14_liquid_remains_in_destination, pour_rolled).
body(r14_liquid_remains_in_destination, pour_slightly_tilted).
body(r14_liquid_remains_in_destination, retreat_lowering).
body(r14_liquid_remains_in_destination, start_centred).
body(r14_liquid_remains_in_destination, start_upright).
learned(r14_liquid_remains_in_destination).
provenance(r14_liquid_remains_in_destination, antecedent, a14).
provenance(r14_liquid_remains_in_destination, parent, none).
provenance(r14_liquid_remains_in_destination, simulations, 31).
provenance(r14_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r14_liquid_remains_in_destination, confidence_permille, 968).
provenance(r14_liquid_remains_in_destination, score_permille, 965).
provenance(r14_liquid_remains_in_destination, batches, 1).

rule(r14_no_spill, defeasible, no_spill).
body(r14_no_spill, approach_raising).
body(r14_no_spill, bouncy_destination).
body(r14_no_spill, dull_source).
body(r14_no_spill, end_near_rim).
body(r14_no_spill, end_rolled).
body(r14_no_spill, end_tilted_back).
body(r14_no_spill, fast_retreat).
body(r14_no_spill, grippy_destination).
body(r14_no_spill, grippy_source).
body(r14_no_spill, heavy_liquid).
body(r14_no_spill, light_source).
body(r14_no_spill, pour_below_rim).
body(r14_no_spill, pour_rolled).
body(r14_no_spill, pour_slightly_tilted).
body(r14_no_spill, retreat_lowering).
body(r14_no_spill, start_centred).
body(r14_no_spill, start_upright).
learned(r14_no_spill).
provenance(r14_no_spill, antecedent, a14).
provenance(r14_no_spill, parent, none).
provenance(r14_no_spill, simulations, 31).
provenance(r14_no_spill, weight_mass_permille, 31000).
provenance(r14_no_spill, confidence_permille, 1000).
provenance(r14_no_spill, score_permille, 973).
provenance(r14_no_spill, batches, 1).

rule(r15_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r15_destination_still_approach, approach_moving_closer).
body(r15_destination_still_approach, bouncy_source).
body(r15_destination_still_approach, dull_destination).
body(r15_destination_still_approach, end_centred).
body(r15_destination_still_approach, end_half_tilted).
body(r15_destination_still_approach, end_high).
body(r15_destination_still_approach, end_level).
body(r15_destination_still_approach, grippy_destination).
body(r15_destination_still_approach, grippy_source).
body(r15_destination_still_approach, heavy_destination).
body(r15_destination_still_approach, heavy_liquid).
body(r15_destination_still_approach, light_source).
body(r15_destination_still_approach, pour_in_line).
body(r15_destination_still_approach, pour_slightly_tilted).
body(r15_destination_still_approach, runny_liquid).
body(r15_destination_still_approach, slow_approach).
body(r15_destination_still_approach, slow_retreat).
body(r15_destination_still_approach, start_below_rim).
body(r15_destination_still_approach, very_much_liquid).
learned(r15_destination_still_approach).
provenance(r15_destination_still_approach, antecedent, a15).
provenance(r15_destination_still_approach, parent, a11).
provenance(r15_destination_still_approach, simulations, 31).
provenance(r15_destination_still_approach, weight_mass_permille, 31000).
provenance(r15_destination_still_approach, confidence_permille, 516).
provenance(r15_destination_still_approach, score_permille, 481).
provenance(r15_destination_still_approach, batches, 1).

rule(r15_destination_still_retreat, defeasible, destination_still_retreat).
body(r15_destination_still_retreat, approach_moving_closer).
body(r15_destination_still_retreat, bouncy_source).
body(r15_destination_still_retreat, dull_destination).
body(r15_destination_still_retreat, end_centred).
body(r15_destination_still_retreat, end_half_tilted).
body(r15_destination_still_retreat, end_high).
body(r15_destination_still_retreat, end_level).
body(r15_destination_still_retreat, grippy_destination).
body(r15_destination_still_retreat, grippy_source).
body(r15_destination_still_retreat, heavy_destination).
body(r15_destination_still_retreat, heavy_liquid).
body(r15_destination_still_retreat, light_source).
body(r15_destination_still_retreat, pour_in_line).
body(r15_destination_still_retreat, pour_slightly_tilted).
body(r15_destination_still_retreat, runny_liquid).
body(r15_destination_still_retreat, slow_approach).
body(r15_destination_still_retreat, slow_retreat).
body(r15_destination_still_retreat, start_below_rim).
body(r15_destination_still_retreat, very_much_liquid).
learned(r15_destination_still_retreat).
provenance(r15_destination_still_retreat, antecedent, a15).
provenance(r15_destination_still_retreat, parent, a11).
provenance(r15_destination_still_retreat, simulations, 31).
provenance(r15_destination_still_retreat, weight_mass_permille, 31000).
provenance(r15_destination_still_retreat, confidence_permille, 774).
provenance(r15_destination_still_retreat, score_permille, 766).
provenance(r15_destination_still_retreat, batches, 1).

rule(r15_destination_still_settle, defeasible, destination_still_settle).
body(r15_destination_still_settle, approach_moving_closer).
body(r15_destination_still_settle, bouncy_source).
body(r15_destination_still_settle, dull_destination).
body(r15_destination_still_settle, end_centred).
body(r15_destination_still_settle, end_half_tilted).
body(r15_destination_still_settle, end_high).
body(r15_destination_still_settle, end_level).
body(r15_destination_still_settle, grippy_destination).
body(r15_destination_still_settle, grippy_source).
body(r15_destination_still_settle, heavy_destination).
body(r15_destination_still_settle, heavy_liquid).
body(r15_destination_still_settle, light_source).
body(r15_destination_still_settle, pour_in_line).
body(r15_destination_still_settle, pour_slightly_tilted).
body(r15_destination_still_settle, runny_liquid).
body(r15_destination_still_settle, slow_approach).
body(r15_destination_still_settle, slow_retreat).
body(r15_destination_still_settle, start_below_rim).
body(r15_destination_still_settle, very_much_liquid).
learned(r15_destination_still_settle).
provenance(r15_destination_still_settle, antecedent, a15).
provenance(r15_destination_still_settle, parent, a11).
provenance(r15_destination_still_settle, simulations, 31).
provenance(r15_destination_still_settle, weight_mass_permille, 31000).
provenance(r15_destination_still_settle, confidence_permille, 968).
provenance(r15_destination_still_settle, score_permille, 967).
provenance(r15_destination_still_settle, batches, 1).

rule(r15_destination_upright, defeasible, destination_upright).
body(r15_destination_upright, approach_moving_closer).
body(r15_destination_upright, bouncy_source).
body(r15_destination_upright, dull_destination).
body(r15_destination_upright, end_centred).
body(r15_destination_upright, end_half_tilted).
body(r15_destination_upright, end_high).
body(r15_destination_upright, end_level).
body(r15_destination_upright, grippy_destination).
body(r15_destination_upright, grippy_source).
body(r15_destination_upright, heavy_destination).
body(r15_destination_upright, heavy_liquid).
body(r15_destination_upright, light_source).
body(r15_destination_upright, pour_in_line).
body(r15_destination_upright, pour_slightly_tilted).
body(r15_destination_upright, runny_liquid).
body(r15_destination_upright, slow_approach).
body(r15_destination_upright, slow_retreat).
body(r15_destination_upright, start_below_rim).
body(r15_destination_upright, very_much_liquid).
learned(r15_destination_upright).
provenance(r15_destination_upright, antecedent, a15).
provenance(r15_destination_upright, parent, a11).
provenance(r15_destination_upright, simulations, 31).
provenance(r15_destination_upright, weight_mass_permille, 31000).
provenance(r15_destination_upright, confidence_permille, 1000).
provenance(r15_destination_upright, score_permille, 1000).
provenance(r15_destination_upright, batches, 1).

rule(r15_source_clear, defeasible, neg(source_clear)).
body(r15_source_clear, approach_moving_closer).
body(r15_source_clear, bouncy_source).
body(r15_source_clear, dull_destination).
body(r15_source_clear, end_centred).
body(r15_source_clear, end_half_tilted).
body(r15_source_clear, end_high).
body(r15_source_clear, end_level).
body(r15_source_clear, grippy_destination).
body(r15_source_clear, grippy_source).
body(r15_source_clear, heavy_destination).
body(r15_source_clear, heavy_liquid).
body(r15_source_clear, light_source).
body(r15_source_clear, pour_in_line).
body(r15_source_clear, pour_slightly_tilted).
body(r15_source_clear, runny_liquid).
body(r15_source_clear, slow_approach).
body(r15_source_clear, slow_retreat).
body(r15_source_clear, start_below_rim).
body(r15_source_clear, very_much_liquid).
learned(r15_source_clear).
provenance(r15_source_clear, antecedent, a15).
provenance(r15_source_clear, parent, a11).
provenance(r15_source_clear, simulations, 31).
provenance(r15_source_clear, weight_mass_permille, 31000).
provenance(r15_source_clear, confidence_permille, 645).
provenance(r15_source_clear, score_permille, 273).
provenance(r15_source_clear, batches, 1).

rule(r15_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r15_liquid_leaves_source, approach_moving_closer).
body(r15_liquid_leaves_source, bouncy_source).
body(r15_liquid_leaves_source, dull_destination).
body(r15_liquid_leaves_source, end_centred).
body(r15_liquid_leaves_source, end_half_tilted).
body(r15_liquid_leaves_source, end_high).
body(r15_liquid_leaves_source, end_level).
body(r15_liquid_leaves_source, grippy_destination).
body(r15_liquid_leaves_source, grippy_source).
body(r15_liquid_leaves_source, heavy_destination).
body(r15_liquid_leaves_source, heavy_liquid).
body(r15_liquid_leaves_source, light_source).
body(r15_liquid_leaves_source, pour_in_line).
body(r15_liquid_leaves_source, pour_slightly_tilted).
body(r15_liquid_leaves_source, runny_liquid).
body(r15_liquid_leaves_source, slow_approach).
body(r15_liquid_leaves_source, slow_retreat).
body(r15_liquid_leaves_source, start_below_rim).
body(r15_liquid_leaves_source, very_much_liquid).
learned(r15_liquid_leaves_source).
provenance(r15_liquid_leaves_source, antecedent, a15).
provenance(r15_liquid_leaves_source, parent, a11).
provenance(r15_liquid_leaves_source, simulations, 31).
provenance(r15_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r15_liquid_leaves_source, confidence_permille, 613).
provenance(r15_liquid_leaves_source, score_permille, 504).
provenance(r15_liquid_leaves_source, batches, 1).

rule(r15_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r15_liquid_enters_destination, approach_moving_closer).
body(r15_liquid_enters_destination, bouncy_source).
body(r15_liquid_enters_destination, dull_destination).
body(r15_liquid_enters_destination, end_centred).
body(r15_liquid_enters_destination, end_half_tilted).
body(r15_liquid_enters_destination, end_high).
body(r15_liquid_enters_destination, end_level).
body(r15_liquid_enters_destination, grippy_destination).
body(r15_liquid_enters_destination, grippy_source).
body(r15_liquid_enters_destination, heavy_destination).
body(r15_liquid_enters_destination, heavy_liquid).
body(r15_liquid_enters_destination, light_source).
body(r15_liquid_enters_destination, pour_in_line).
body(r15_liquid_enters_destination, pour_slightly_tilted).
body(r15_liquid_enters_destination, runny_liquid).
body(r15_liquid_enters_destination, slow_approach).
body(r15_liquid_enters_destination, slow_retreat).
body(r15_liquid_enters_destination, start_below_rim).
body(r15_liquid_enters_destination, very_much_liquid).
learned(r15_liquid_enters_destination).
provenance(r15_liquid_enters_destination, antecedent, a15).
provenance(r15_liquid_enters_destination, parent, a11).
provenance(r15_liquid_enters_destination, simulations, 31).
provenance(r15_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r15_liquid_enters_destination, confidence_permille, 903).
provenance(r15_liquid_enters_destination, score_permille, 129).
provenance(r15_liquid_enters_destination, batches, 1).

rule(r15_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r15_liquid_remains_in_destination, approach_moving_closer).
body(r15_liquid_remains_in_destination, bouncy_source).
body(r15_liquid_remains_in_destination, dull_destination).
body(r15_liquid_remains_in_destination, end_centred).
body(r15_liquid_remains_in_destination, end_half_tilted).
body(r15_liquid_remains_in_destination, end_high).
body(r15_liquid_remains_in_destination, end_level).
body(r15_liquid_remains_in_destination, grippy_destination).
body(r15_liquid_remains_in_destination, grippy_source).
body(r15_liquid_remains_in_destination, heavy_destination).
body(r15_liquid_remains_in_destination, heavy_liquid).
body(r15_liquid_remains_in_destination, light_source).
body(r15_liquid_remains_in_destination, pour_in_line).
body(r15_liquid_remains_in_destination, pour_slightly_tilted).
body(r15_liquid_remains_in_destination, runny_liquid).
body(r15_liquid_remains_in_destination, slow_approach).
body(r15_liquid_remains_in_destination, slow_retreat).
body(r15_liquid_remains_in_destination, start_below_rim).
body(r15_liquid_remains_in_destination, very_much_liquid).
learned(r15_liquid_remains_in_destination).
provenance(r15_liquid_remains_in_destination, antecedent, a15).
provenance(r15_liquid_remains_in_destination, parent, a11).
provenance(r15_liquid_remains_in_destination, simulations, 31).
provenance(r15_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r15_liquid_remains_in_destination, confidence_permille, 774).
provenance(r15_liquid_remains_in_destination, score_permille, 786).
provenance(r15_liquid_remains_in_destination, batches, 1).

rule(r15_no_spill, defeasible, neg(no_spill)).
body(r15_no_spill, approach_moving_closer).
body(r15_no_spill, bouncy_source).
body(r15_no_spill, dull_destination).
body(r15_no_spill, end_centred).
body(r15_no_spill, end_half_tilted).
body(r15_no_spill, end_high).
body(r15_no_spill, end_level).
body(r15_no_spill, grippy_destination).
body(r15_no_spill, grippy_source).
body(r15_no_spill, heavy_destination).
body(r15_no_spill, heavy_liquid).
body(r15_no_spill, light_source).
body(r15_no_spill, pour_in_line).
body(r15_no_spill, pour_slightly_tilted).
body(r15_no_spill, runny_liquid).
body(r15_no_spill, slow_approach).
body(r15_no_spill, slow_retreat).
body(r15_no_spill, start_below_rim).
body(r15_no_spill, very_much_liquid).
learned(r15_no_spill).
provenance(r15_no_spill, antecedent, a15).
provenance(r15_no_spill, parent, a11).
provenance(r15_no_spill, simulations, 31).
provenance(r15_no_spill, weight_mass_permille, 31000).
provenance(r15_no_spill, confidence_permille, 548).
provenance(r15_no_spill, score_permille, 535).
provenance(r15_no_spill, batches, 1).

rule(r16_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r16_destination_still_approach, approach_moving_away).
body(r16_destination_still_approach, bouncy_destination).
body(r16_destination_still_approach, bouncy_source).
body(r16_destination_still_approach, end_far_away).
body(r16_destination_still_approach, end_half_tilted).
body(r16_destination_still_approach, end_level).
body(r16_destination_still_approach, end_low).
body(r16_destination_still_approach, grippy_destination).
body(r16_destination_still_approach, grippy_source).
body(r16_destination_still_approach, heavy_destination).
body(r16_destination_still_approach, heavy_liquid).
body(r16_destination_still_approach, light_source).
body(r16_destination_still_approach, pour_in_line).
body(r16_destination_still_approach, pour_slightly_tilted).
body(r16_destination_still_approach, runny_liquid).
body(r16_destination_still_approach, slow_approach).
body(r16_destination_still_approach, slow_retreat).
body(r16_destination_still_approach, start_below_rim).
body(r16_destination_still_approach, very_much_liquid).
learned(r16_destination_still_approach).
provenance(r16_destination_still_approach, antecedent, a16).
provenance(r16_destination_still_approach, parent, a13).
provenance(r16_destination_still_approach, simulations, 31).
provenance(r16_destination_still_approach, weight_mass_permille, 31000).
provenance(r16_destination_still_approach, confidence_permille, 516).
provenance(r16_destination_still_approach, score_permille, 487).
provenance(r16_destination_still_approach, batches, 1).

rule(r16_destination_still_retreat, defeasible, destination_still_retreat).
body(r16_destination_still_retreat, approach_moving_away).
body(r16_destination_still_retreat, bouncy_destination).
body(r16_destination_still_retreat, bouncy_source).
body(r16_destination_still_retreat, end_far_away).
body(r16_destination_still_retreat, end_half_tilted).
body(r16_destination_still_retreat, end_level).
body(r16_destination_still_retreat, end_low).
body(r16_destination_still_retreat, grippy_destination).
body(r16_destination_still_retreat, grippy_source).
body(r16_destination_still_retreat, heavy_destination).
body(r16_destination_still_retreat, heavy_liquid).
body(r16_destination_still_retreat, light_source).
body(r16_destination_still_retreat, pour_in_line).
body(r16_destination_still_retreat, pour_slightly_tilted).
body(r16_destination_still_retreat, runny_liquid).
body(r16_destination_still_retreat, slow_approach).
body(r16_destination_still_retreat, slow_retreat).
body(r16_destination_still_retreat, start_below_rim).
body(r16_destination_still_retreat, very_much_liquid).
learned(r16_destination_still_retreat).
provenance(r16_destination_still_retreat, antecedent, a16).
provenance(r16_destination_still_retreat, parent, a13).
provenance(r16_destination_still_retreat, simulations, 31).
provenance(r16_destination_still_retreat, weight_mass_permille, 31000).
provenance(r16_destination_still_retreat, confidence_permille, 806).
provenance(r16_destination_still_retreat, score_permille, 838).
provenance(r16_destination_still_retreat, batches, 1).

rule(r16_destination_still_settle, defeasible, destination_still_settle).
body(r16_destination_still_settle, approach_moving_away).
body(r16_destination_still_settle, bouncy_destination).
body(r16_destination_still_settle, bouncy_source).
body(r16_destination_still_settle, end_far_away).
body(r16_destination_still_settle, end_half_tilted).
body(r16_destination_still_settle, end_level).
body(r16_destination_still_settle, end_low).
body(r16_destination_still_settle, grippy_destination).
body(r16_destination_still_settle, grippy_source).
body(r16_destination_still_settle, heavy_destination).
body(r16_destination_still_settle, heavy_liquid).
body(r16_destination_still_settle, light_source).
body(r16_destination_still_settle, pour_in_line).
body(r16_destination_still_settle, pour_slightly_tilted).
body(r16_destination_still_settle, runny_liquid).
body(r16_destination_still_settle, slow_approach).
body(r16_destination_still_settle, slow_retreat).
body(r16_destination_still_settle, start_below_rim).
body(r16_destination_still_settle, very_much_liquid).
learned(r16_destination_still_settle).
provenance(r16_destination_still_settle, antecedent, a16).
provenance(r16_destination_still_settle, parent, a13).
provenance(r16_destination_still_settle, simulations, 31).
provenance(r16_destination_still_settle, weight_mass_permille, 31000).
provenance(r16_destination_still_settle, confidence_permille, 968).
provenance(r16_destination_still_settle, score_permille, 964).
provenance(r16_destination_still_settle, batches, 1).

rule(r16_destination_upright, defeasible, destination_upright).
body(r16_destination_upright, approach_moving_away).
body(r16_destination_upright, bouncy_destination).
body(r16_destination_upright, bouncy_source).
body(r16_destination_upright, end_far_away).
body(r16_destination_upright, end_half_tilted).
body(r16_destination_upright, end_level).
body(r16_destination_upright, end_low).
body(r16_destination_upright, grippy_destination).
body(r16_destination_upright, grippy_source).
body(r16_destination_upright, heavy_destination).
body(r16_destination_upright, heavy_liquid).
body(r16_destination_upright, light_source).
body(r16_destination_upright, pour_in_line).
body(r16_destination_upright, pour_slightly_tilted).
body(r16_destination_upright, runny_liquid).
body(r16_destination_upright, slow_approach).
body(r16_destination_upright, slow_retreat).
body(r16_destination_upright, start_below_rim).
body(r16_destination_upright, very_much_liquid).
learned(r16_destination_upright).
provenance(r16_destination_upright, antecedent, a16).
provenance(r16_destination_upright, parent, a13).
provenance(r16_destination_upright, simulations, 31).
provenance(r16_destination_upright, weight_mass_permille, 31000).
provenance(r16_destination_upright, confidence_permille, 968).
provenance(r16_destination_upright, score_permille, 967).
provenance(r16_destination_upright, batches, 1).

rule(r16_source_clear, defeasible, neg(source_clear)).
body(r16_source_clear, approach_moving_away).
body(r16_source_clear, bouncy_destination).
body(r16_source_clear, bouncy_source).
body(r16_source_clear, end_far_away).
body(r16_source_clear, end_half_tilted).
body(r16_source_clear, end_level).
body(r16_source_clear, end_low).
body(r16_source_clear, grippy_destination).
body(r16_source_clear, grippy_source).
body(r16_source_clear, heavy_destination).
body(r16_source_clear, heavy_liquid).
body(r16_source_clear, light_source).
body(r16_source_clear, pour_in_line).
body(r16_source_clear, pour_slightly_tilted).
body(r16_source_clear, runny_liquid).
body(r16_source_clear, slow_approach).
body(r16_source_clear, slow_retreat).
body(r16_source_clear, start_below_rim).
body(r16_source_clear, very_much_liquid).
learned(r16_source_clear).
provenance(r16_source_clear, antecedent, a16).
provenance(r16_source_clear, parent, a13).
provenance(r16_source_clear, simulations, 31).
provenance(r16_source_clear, weight_mass_permille, 31000).
provenance(r16_source_clear, confidence_permille, 806).
provenance(r16_source_clear, score_permille, 158).
provenance(r16_source_clear, batches, 1).

rule(r16_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r16_liquid_leaves_source, approach_moving_away).
body(r16_liquid_leaves_source, bouncy_destination).
body(r16_liquid_leaves_source, bouncy_source).
body(r16_liquid_leaves_source, end_far_away).
body(r16_liquid_leaves_source, end_half_tilted).
body(r16_liquid_leaves_source, end_level).
body(r16_liquid_leaves_source, end_low).
body(r16_liquid_leaves_source, grippy_destination).
body(r16_liquid_leaves_source, grippy_source).
body(r16_liquid_leaves_source, heavy_destination).
body(r16_liquid_leaves_source, heavy_liquid).
body(r16_liquid_leaves_source, light_source).
body(r16_liquid_leaves_source, pour_in_line).
body(r16_liquid_leaves_source, pour_slightly_tilted).
body(r16_liquid_leaves_source, runny_liquid).
body(r16_liquid_leaves_source, slow_approach).
body(r16_liquid_leaves_source, slow_retreat).
body(r16_liquid_leaves_source, start_below_rim).
body(r16_liquid_leaves_source, very_much_liquid).
learned(r16_liquid_leaves_source).
provenance(r16_liquid_leaves_source, antecedent, a16).
provenance(r16_liquid_leaves_source, parent, a13).
provenance(r16_liquid_leaves_source, simulations, 31).
provenance(r16_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r16_liquid_leaves_source, confidence_permille, 613).
provenance(r16_liquid_leaves_source, score_permille, 587).
provenance(r16_liquid_leaves_source, batches, 1).

rule(r16_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r16_liquid_enters_destination, approach_moving_away).
body(r16_liquid_enters_destination, bouncy_destination).
body(r16_liquid_enters_destination, bouncy_source).
body(r16_liquid_enters_destination, end_far_away).
body(r16_liquid_enters_destination, end_half_tilted).
body(r16_liquid_enters_destination, end_level).
body(r16_liquid_enters_destination, end_low).
body(r16_liquid_enters_destination, grippy_destination).
body(r16_liquid_enters_destination, grippy_source).
body(r16_liquid_enters_destination, heavy_destination).
body(r16_liquid_enters_destination, heavy_liquid).
body(r16_liquid_enters_destination, light_source).
body(r16_liquid_enters_destination, pour_in_line).
body(r16_liquid_enters_destination, pour_slightly_tilted).
body(r16_liquid_enters_destination, runny_liquid).
body(r16_liquid_enters_destination, slow_approach).
body(r16_liquid_enters_destination, slow_retreat).
body(r16_liquid_enters_destination, start_below_rim).
body(r16_liquid_enters_destination, very_much_liquid).
learned(r16_liquid_enters_destination).
provenance(r16_liquid_enters_destination, antecedent, a16).
provenance(r16_liquid_enters_destination, parent, a13).
provenance(r16_liquid_enters_destination, simulations, 31).
provenance(r16_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r16_liquid_enters_destination, confidence_permille, 581).
provenance(r16_liquid_enters_destination, score_permille, 461).
provenance(r16_liquid_enters_destination, batches, 1).

rule(r16_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r16_liquid_remains_in_destination, approach_moving_away).
body(r16_liquid_remains_in_destination, bouncy_destination).
body(r16_liquid_remains_in_destination, bouncy_source).
body(r16_liquid_remains_in_destination, end_far_away).
body(r16_liquid_remains_in_destination, end_half_tilted).
body(r16_liquid_remains_in_destination, end_level).
body(r16_liquid_remains_in_destination, end_low).
body(r16_liquid_remains_in_destination, grippy_destination).
body(r16_liquid_remains_in_destination, grippy_source).
body(r16_liquid_remains_in_destination, heavy_destination).
body(r16_liquid_remains_in_destination, heavy_liquid).
body(r16_liquid_remains_in_destination, light_source).
body(r16_liquid_remains_in_destination, pour_in_line).
body(r16_liquid_remains_in_destination, pour_slightly_tilted).
body(r16_liquid_remains_in_destination, runny_liquid).
body(r16_liquid_remains_in_destination, slow_approach).
body(r16_liquid_remains_in_destination, slow_retreat).
body(r16_liquid_remains_in_destination, start_below_rim).
body(r16_liquid_remains_in_destination, very_much_liquid).
learned(r16_liquid_remains_in_destination).
provenance(r16_liquid_remains_in_destination, antecedent, a16).
provenance(r16_liquid_remains_in_destination, parent, a13).
provenance(r16_liquid_remains_in_destination, simulations, 31).
provenance(r16_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r16_liquid_remains_in_destination, confidence_permille, 645).
provenance(r16_liquid_remains_in_destination, score_permille, 382).
provenance(r16_liquid_remains_in_destination, batches, 1).

rule(r16_no_spill, defeasible, no_spill).
body(r16_no_spill, approach_moving_away).
body(r16_no_spill, bouncy_destination).
body(r16_no_spill, bouncy_source).
body(r16_no_spill, end_far_away).
body(r16_no_spill, end_half_tilted).
body(r16_no_spill, end_level).
body(r16_no_spill, end_low).
body(r16_no_spill, grippy_destination).
body(r16_no_spill, grippy_source).
body(r16_no_spill, heavy_destination).
body(r16_no_spill, heavy_liquid).
body(r16_no_spill, light_source).
body(r16_no_spill, pour_in_line).
body(r16_no_spill, pour_slightly_tilted).
body(r16_no_spill, runny_liquid).
body(r16_no_spill, slow_approach).
body(r16_no_spill, slow_retreat).
body(r16_no_spill, start_below_rim).
body(r16_no_spill, very_much_liquid).
learned(r16_no_spill).
provenance(r16_no_spill, antecedent, a16).
provenance(r16_no_spill, parent, a13).
provenance(r16_no_spill, simulations, 31).
provenance(r16_no_spill, weight_mass_permille, 31000).
provenance(r16_no_spill, confidence_permille, 613).
provenance(r16_no_spill, score_permille, 519).
provenance(r16_no_spill, batches, 1).

rule(r17_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r17_destination_still_approach, approach_moving_away).
body(r17_destination_still_approach, bouncy_destination).
body(r17_destination_still_approach, dull_source).
body(r17_destination_still_approach, end_centred).
body(r17_destination_still_approach, end_half_tilted).
body(r17_destination_still_approach, end_level).
body(r17_destination_still_approach, end_low).
body(r17_destination_still_approach, grippy_destination).
body(r17_destination_still_approach, grippy_source).
body(r17_destination_still_approach, heavy_destination).
body(r17_destination_still_approach, heavy_liquid).
body(r17_destination_still_approach, light_source).
body(r17_destination_still_approach, pour_below_rim).
body(r17_destination_still_approach, pour_in_line).
body(r17_destination_still_approach, pour_slightly_tilted).
body(r17_destination_still_approach, runny_liquid).
body(r17_destination_still_approach, slow_approach).
body(r17_destination_still_approach, slow_retreat).
body(r17_destination_still_approach, start_below_rim).
body(r17_destination_still_approach, very_much_liquid).
learned(r17_destination_still_approach).
provenance(r17_destination_still_approach, antecedent, a17).
provenance(r17_destination_still_approach, parent, a12).
provenance(r17_destination_still_approach, simulations, 31).
provenance(r17_destination_still_approach, weight_mass_permille, 31000).
provenance(r17_destination_still_approach, confidence_permille, 871).
provenance(r17_destination_still_approach, score_permille, 120).
provenance(r17_destination_still_approach, batches, 1).

rule(r17_destination_still_retreat, defeasible, destination_still_retreat).
body(r17_destination_still_retreat, approach_moving_away).
body(r17_destination_still_retreat, bouncy_destination).
body(r17_destination_still_retreat, dull_source).
body(r17_destination_still_retreat, end_centred).
body(r17_destination_still_retreat, end_half_tilted).
body(r17_destination_still_retreat, end_level).
body(r17_destination_still_retreat, end_low).
body(r17_destination_still_retreat, grippy_destination).
body(r17_destination_still_retreat, grippy_source).
body(r17_destination_still_retreat, heavy_destination).
body(r17_destination_still_retreat, heavy_liquid).
body(r17_destination_still_retreat, light_source).
body(r17_destination_still_retreat, pour_below_rim).
body(r17_destination_still_retreat, pour_in_line).
body(r17_destination_still_retreat, pour_slightly_tilted).
body(r17_destination_still_retreat, runny_liquid).
body(r17_destination_still_retreat, slow_approach).
body(r17_destination_still_retreat, slow_retreat).
body(r17_destination_still_retreat, start_below_rim).
body(r17_destination_still_retreat, very_much_liquid).
learned(r17_destination_still_retreat).
provenance(r17_destination_still_retreat, antecedent, a17).
provenance(r17_destination_still_retreat, parent, a12).
provenance(r17_destination_still_retreat, simulations, 31).
provenance(r17_destination_still_retreat, weight_mass_permille, 31000).
provenance(r17_destination_still_retreat, confidence_permille, 516).
provenance(r17_destination_still_retreat, score_permille, 500).
provenance(r17_destination_still_retreat, batches, 1).

rule(r17_destination_still_settle, defeasible, destination_still_settle).
body(r17_destination_still_settle, approach_moving_away).
body(r17_destination_still_settle, bouncy_destination).
body(r17_destination_still_settle, dull_source).
body(r17_destination_still_settle, end_centred).
body(r17_destination_still_settle, end_half_tilted).
body(r17_destination_still_settle, end_level).
body(r17_destination_still_settle, end_low).
body(r17_destination_still_settle, grippy_destination).
body(r17_destination_still_settle, grippy_source).
body(r17_destination_still_settle, heavy_destination).
body(r17_destination_still_settle, heavy_liquid).
body(r17_destination_still_settle, light_source).
body(r17_destination_still_settle, pour_below_rim).
body(r17_destination_still_settle, pour_in_line).
body(r17_destination_still_settle, pour_slightly_tilted).
body(r17_destination_still_settle, runny_liquid).
body(r17_destination_still_settle, slow_approach).
body(r17_destination_still_settle, slow_retreat).
body(r17_destination_still_settle, start_below_rim).
body(r17_destination_still_settle, very_much_liquid).
learned(r17_destination_still_settle).
provenance(r17_destination_still_settle, antecedent, a17).
provenance(r17_destination_still_settle, parent, a12).
provenance(r17_destination_still_settle, simulations, 31).
provenance(r17_destination_still_settle, weight_mass_permille, 31000).
provenance(r17_destination_still_settle, confidence_permille, 871).
provenance(r17_destination_still_settle, score_permille, 872).
provenance(r17_destination_still_settle, batches, 1).

rule(r17_destination_upright, defeasible, destination_upright).
body(r17_destination_upright, approach_moving_away).
body(r17_destination_upright, bouncy_destination).
body(r17_destination_upright, dull_source).
body(r17_destination_upright, end_centred).
body(r17_destination_upright, end_half_tilted).
body(r17_destination_upright, end_level).
body(r17_destination_upright, end_low).
body(r17_destination_upright, grippy_destination).
body(r17_destination_upright, grippy_source).
body(r17_destination_upright, heavy_destination).
body(r17_destination_upright, heavy_liquid).
body(r17_destination_upright, light_source).
body(r17_destination_upright, pour_below_rim).
body(r17_destination_upright, pour_in_line).
body(r17_destination_upright, pour_slightly_tilted).
body(r17_destination_upright, runny_liquid).
body(r17_destination_upright, slow_approach).
body(r17_destination_upright, slow_retreat).
body(r17_destination_upright, start_below_rim).
body(r17_destination_upright, very_much_liquid).
learned(r17_destination_upright).
provenance(r17_destination_upright, antecedent, a17).
provenance(r17_destination_upright, parent, a12).
provenance(r17_destination_upright, simulations, 31).
provenance(r17_destination_upright, weight_mass_permille, 31000).
provenance(r17_destination_upright, confidence_permille, 935).
provenance(r17_destination_upright, score_permille, 946).
provenance(r17_destination_upright, batches, 1).

rule(r17_source_clear, defeasible, neg(source_clear)).
body(r17_source_clear, approach_moving_away).
body(r17_source_clear, bouncy_destination).
body(r17_source_clear, dull_source).
body(r17_source_clear, end_centred).
body(r17_source_clear, end_half_tilted).
body(r17_source_clear, end_level).
body(r17_source_clear, end_low).
body(r17_source_clear, grippy_destination).
body(r17_source_clear, grippy_source).
body(r17_source_clear, heavy_destination).
body(r17_source_clear, heavy_liquid).
body(r17_source_clear, light_source).
body(r17_source_clear, pour_below_rim).
body(r17_source_clear, pour_in_line).
body(r17_source_clear, pour_slightly_tilted).
body(r17_source_clear, runny_liquid).
body(r17_source_clear, slow_approach).
body(r17_source_clear, slow_retreat).
body(r17_source_clear, start_below_rim).
body(r17_source_clear, very_much_liquid).
learned(r17_source_clear).
provenance(r17_source_clear, antecedent, a17).
provenance(r17_source_clear, parent, a12).
provenance(r17_source_clear, simulations, 31).
provenance(r17_source_clear, weight_mass_permille, 31000).
provenance(r17_source_clear, confidence_permille, 1000).
provenance(r17_source_clear, score_permille, 0).
provenance(r17_source_clear, batches, 1).

rule(r17_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r17_liquid_leaves_source, approach_moving_away).
body(r17_liquid_leaves_source, bouncy_destination).
body(r17_liquid_leaves_source, dull_source).
body(r17_liquid_leaves_source, end_centred).
body(r17_liquid_leaves_source, end_half_tilted).
body(r17_liquid_leaves_source, end_level).
body(r17_liquid_leaves_source, end_low).
body(r17_liquid_leaves_source, grippy_destination).
body(r17_liquid_leaves_source, grippy_source).
body(r17_liquid_leaves_source, heavy_destination).
body(r17_liquid_leaves_source, heavy_liquid).
body(r17_liquid_leaves_source, light_source).
body(r17_liquid_leaves_source, pour_below_rim).
body(r17_liquid_leaves_source, pour_in_line).
body(r17_liquid_leaves_source, pour_slightly_tilted).
body(r17_liquid_leaves_source, runny_liquid).
body(r17_liquid_leaves_source, slow_approach).
body(r17_liquid_leaves_source, slow_retreat).
body(r17_liquid_leaves_source, start_below_rim).
body(r17_liquid_leaves_source, very_much_liquid).
learned(r17_liquid_leaves_source).
provenance(r17_liquid_leaves_source, antecedent, a17).
provenance(r17_liquid_leaves_source, parent, a12).
provenance(r17_liquid_leaves_source, simulations, 31).
provenance(r17_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r17_liquid_leaves_source, confidence_permille, 548).
provenance(r17_liquid_leaves_source, score_permille, 559).
provenance(r17_liquid_leaves_source, batches, 1).

rule(r17_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r17_liquid_enters_destination, approach_moving_away).
body(r17_liquid_enters_destination, bouncy_destination).
body(r17_liquid_enters_destination, dull_source).
body(r17_liquid_enters_destination, end_centred).
body(r17_liquid_enters_destination, end_half_tilted).
body(r17_liquid_enters_destination, end_level).
body(r17_liquid_enters_destination, end_low).
body(r17_liquid_enters_destination, grippy_destination).
body(r17_liquid_enters_destination, grippy_source).
body(r17_liquid_enters_destination, heavy_destination).
body(r17_liquid_enters_destination, heavy_liquid).
body(r17_liquid_enters_destination, light_source).
body(r17_liquid_enters_destination, pour_below_rim).
body(r17_liquid_enters_destination, pour_in_line).
body(r17_liquid_enters_destination, pour_slightly_tilted).
body(r17_liquid_enters_destination, runny_liquid).
body(r17_liquid_enters_destination, slow_approach).
body(r17_liquid_enters_destination, slow_retreat).
body(r17_liquid_enters_destination, start_below_rim).
body(r17_liquid_enters_destination, very_much_liquid).
learned(r17_liquid_enters_destination).
provenance(r17_liquid_enters_destination, antecedent, a17).
provenance(r17_liquid_enters_destination, parent, a12).
provenance(r17_liquid_enters_destination, simulations, 31).
provenance(r17_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r17_liquid_enters_destination, confidence_permille, 645).
provenance(r17_liquid_enters_destination, score_permille, 609).
provenance(r17_liquid_enters_destination, batches, 1).

rule(r17_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r17_liquid_remains_in_destination, approach_moving_away).
body(r17_liquid_remains_in_destination, bouncy_destination).
body(r17_liquid_remains_in_destination, dull_source).
body(r17_liquid_remains_in_destination, end_centred).
body(r17_liquid_remains_in_destination, end_half_tilted).
body(r17_liquid_remains_in_destination, end_level).
body(r17_liquid_remains_in_destination, end_low).
body(r17_liquid_remains_in_destination, grippy_destination).
body(r17_liquid_remains_in_destination, grippy_source).
body(r17_liquid_remains_in_destination, heavy_destination).
body(r17_liquid_remains_in_destination, heavy_liquid).
body(r17_liquid_remains_in_destination, light_source).
body(r17_liquid_remains_in_destination, pour_below_rim).
body(r17_liquid_remains_in_destination, pour_in_line).
body(r17_liquid_remains_in_destination, pour_slightly_tilted).
body(r17_liquid_remains_in_destination, runny_liquid).
body(r17_liquid_remains_in_destination, slow_approach).
body(r17_liquid_remains_in_destination, slow_retreat).
body(r17_liquid_remains_in_destination, start_below_rim).
body(r17_liquid_remains_in_destination, very_much_liquid).
learned(r17_liquid_remains_in_destination).
provenance(r17_liquid_remains_in_destination, antecedent, a17).
provenance(r17_liquid_remains_in_destination, parent, a12).
provenance(r17_liquid_remains_in_destination, simulations, 31).
provenance(r17_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r17_liquid_remains_in_destination, confidence_permille, 645).
provenance(r17_liquid_remains_in_destination, score_permille, 401).
provenance(r17_liquid_remains_in_destination, batches, 1).

rule(r17_no_spill, defeasible, no_spill).
body(r17_no_spill, approach_moving_away).
body(r17_no_spill, bouncy_destination).
body(r17_no_spill, dull_source).
body(r17_no_spill, end_centred).
body(r17_no_spill, end_half_tilted).
body(r17_no_spill, end_level).
body(r17_no_spill, end_low).
body(r17_no_spill, grippy_destination).
body(r17_no_spill, grippy_source).
body(r17_no_spill, heavy_destination).
body(r17_no_spill, heavy_liquid).
body(r17_no_spill, light_source).
body(r17_no_spill, pour_below_rim).
body(r17_no_spill, pour_in_line).
body(r17_no_spill, pour_slightly_tilted).
body(r17_no_spill, runny_liquid).
body(r17_no_spill, slow_approach).
body(r17_no_spill, slow_retreat).
body(r17_no_spill, start_below_rim).
body(r17_no_spill, very_much_liquid).
learned(r17_no_spill).
provenance(r17_no_spill, antecedent, a17).
provenance(r17_no_spill, parent, a12).
provenance(r17_no_spill, simulations, 31).
provenance(r17_no_spill, weight_mass_permille, 31000).
provenance(r17_no_spill, confidence_permille, 581).
provenance(r17_no_spill, score_permille, 592).
provenance(r17_no_spill, batches, 1).

rule(r18_destination_still_approach, defeasible, destination_still_approach).
learned(r18_destination_still_approach).
provenance(r18_destination_still_approach, antecedent, a18).
provenance(r18_destination_still_approach, parent, none).
provenance(r18_destination_still_approach, simulations, 42).
provenance(r18_destination_still_approach, weight_mass_permille, 33600).
provenance(r18_destination_still_approach, confidence_permille, 1000).
provenance(r18_destination_still_approach, score_permille, 981).
provenance(r18_destination_still_approach, batches, 1).

rule(r18_destination_still_retreat, defeasible, destination_still_retreat).
learned(r18_destination_still_retreat).
provenance(r18_destination_still_retreat, antecedent, a18).
provenance(r18_destination_still_retreat, parent, none).
provenance(r18_destination_still_retreat, simulations, 42).
provenance(r18_destination_still_retreat, weight_mass_permille, 33600).
provenance(r18_destination_still_retreat, confidence_permille, 1000).
provenance(r18_destination_still_retreat, score_permille, 997).
provenance(r18_destination_still_retreat, batches, 1).

rule(r18_destination_still_settle, defeasible, destination_still_settle).
learned(r18_destination_still_settle).
provenance(r18_destination_still_settle, antecedent, a18).
provenance(r18_destination_still_settle, parent, none).
provenance(r18_destination_still_settle, simulations, 42).
provenance(r18_destination_still_settle, weight_mass_permille, 33600).
provenance(r18_destination_still_settle, confidence_permille, 1000).
provenance(r18_destination_still_settle, score_permille, 1000).
provenance(r18_destination_still_settle, batches, 1).

rule(r18_destination_upright, defeasible, destination_upright).
learned(r18_destination_upright).
provenance(r18_destination_upright, antecedent, a18).
provenance(r18_destination_upright, parent, none).
provenance(r18_destination_upright, simulations, 42).
provenance(r18_destination_upright, weight_mass_permille, 33600).
provenance(r18_destination_upright, confidence_permille, 1000).
provenance(r18_destination_upright, score_permille, 1000).
provenance(r18_destination_upright, batches, 1).

rule(r18_source_clear, defeasible, source_clear).
learned(r18_source_clear).
provenance(r18_source_clear, antecedent, a18).
provenance(r18_source_clear, parent, none).
provenance(r18_source_clear, simulations, 42).
provenance(r18_source_clear, weight_mass_permille, 33600).
provenance(r18_source_clear, confidence_permille, 1000).
provenance(r18_source_clear, score_permille, 987).
provenance(r18_source_clear, batches, 1).

rule(r18_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(r18_liquid_leaves_source).
provenance(r18_liquid_leaves_source, antecedent, a18).
provenance(r18_liquid_leaves_source, parent, none).
provenance(r18_liquid_leaves_source, simulations, 42).
provenance(r18_liquid_leaves_source, weight_mass_permille, 33600).
provenance(r18_liquid_leaves_source, confidence_permille, 1000).
provenance(r18_liquid_leaves_source, score_permille, 996).
provenance(r18_liquid_leaves_source, batches, 1).

rule(r18_liquid_enters_destination, defeasible, liquid_enters_destination).
learned(r18_liquid_enters_destination).
provenance(r18_liquid_enters_destination, antecedent, a18).
provenance(r18_liquid_enters_destination, parent, none).
provenance(r18_liquid_enters_destination, simulations, 42).
provenance(r18_liquid_enters_destination, weight_mass_permille, 33600).
provenance(r18_liquid_enters_destination, confidence_permille, 1000).
provenance(r18_liquid_enters_destination, score_permille, 958).
provenance(r18_liquid_enters_destination, batches, 1).

rule(r18_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(r18_liquid_remains_in_destination).
provenance(r18_liquid_remains_in_destination, antecedent, a18).
provenance(r18_liquid_remains_in_destination, parent, none).
provenance(r18_liquid_remains_in_destination, simulations, 42).
provenance(r18_liquid_remains_in_destination, weight_mass_permille, 33600).
provenance(r18_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r18_liquid_remains_in_destination, score_permille, 1000).
provenance(r18_liquid_remains_in_destination, batches, 1).

rule(r18_no_spill, defeasible, no_spill).
learned(r18_no_spill).
provenance(r18_no_spill, antecedent, a18).
provenance(r18_no_spill, parent, none).
provenance(r18_no_spill, simulations, 42).
provenance(r18_no_spill, weight_mass_permille, 33600).
provenance(r18_no_spill, confidence_permille, 1000).
provenance(r18_no_spill, score_permille, 962).
provenance(r18_no_spill, batches, 1).

% General rules, learned from every pour of the exploration
% and the learner's own pours (bridge/learning/gaps.py), by
% bridge/learning/generalize.py: a default per expectation and the
% contrasts that move it. provenance(Id, support, N): the pours whose
% description holds the body; kept: how many of them keep the head;
% confidence_permille: P(head | body), the share of the pours sampled
% for the body (the rest an ordinary pour) that keep the head.
% sup/2 below orders both layers (see bridge/learning/layers.py).
setting(general_pours, 1422).
setting(general_own_pours, 680).
setting(general_rules, 79).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 48).
provenance(g0_destination_still_approach, kept, 48).
provenance(g0_destination_still_approach, confidence_permille, 996).
rule(g1_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g1_destination_still_approach, pour_below_rim).
learned(g1_destination_still_approach).
provenance(g1_destination_still_approach, layer, general).
provenance(g1_destination_still_approach, level, 1).
provenance(g1_destination_still_approach, support, 12).
provenance(g1_destination_still_approach, kept, 10).
provenance(g1_destination_still_approach, confidence_permille, 731).
rule(g2_destination_still_approach, defeasible, destination_still_approach).
body(g2_destination_still_approach, start_below_rim).
learned(g2_destination_still_approach).
provenance(g2_destination_still_approach, layer, general).
provenance(g2_destination_still_approach, level, 1).
provenance(g2_destination_still_approach, support, 13).
provenance(g2_destination_still_approach, kept, 5).
provenance(g2_destination_still_approach, confidence_permille, 677).
rule(g3_destination_still_approach, defeasible, destination_still_approach).
body(g3_destination_still_approach, approach_raising).
learned(g3_destination_still_approach).
provenance(g3_destination_still_approach, layer, general).
provenance(g3_destination_still_approach, level, 1).
provenance(g3_destination_still_approach, support, 36).
provenance(g3_destination_still_approach, kept, 27).
provenance(g3_destination_still_approach, confidence_permille, 852).
rule(g4_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g4_destination_still_approach, approach_raising).
body(g4_destination_still_approach, pour_below_rim).
learned(g4_destination_still_approach).
provenance(g4_destination_still_approach, layer, general).
provenance(g4_destination_still_approach, level, 2).
provenance(g4_destination_still_approach, support, 0).
provenance(g4_destination_still_approach, kept, 0).
provenance(g4_destination_still_approach, confidence_permille, 876).
rule(g5_destination_still_approach, defeasible, destination_still_approach).
body(g5_destination_still_approach, pour_low).
learned(g5_destination_still_approach).
provenance(g5_destination_still_approach, layer, general).
provenance(g5_destination_still_approach, level, 1).
provenance(g5_destination_still_approach, support, 12).
provenance(g5_destination_still_approach, kept, 11).
provenance(g5_destination_still_approach, confidence_permille, 969).
rule(g6_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g6_destination_still_approach, pour_low).
body(g6_destination_still_approach, start_below_rim).
learned(g6_destination_still_approach).
provenance(g6_destination_still_approach, layer, general).
provenance(g6_destination_still_approach, level, 2).
provenance(g6_destination_still_approach, support, 6).
provenance(g6_destination_still_approach, kept, 6).
provenance(g6_destination_still_approach, confidence_permille, 657).
rule(g7_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g7_destination_still_approach, approach_raising).
body(g7_destination_still_approach, pour_low).
learned(g7_destination_still_approach).
provenance(g7_destination_still_approach, layer, general).
provenance(g7_destination_still_approach, level, 2).
provenance(g7_destination_still_approach, support, 9).
provenance(g7_destination_still_approach, kept, 7).
provenance(g7_destination_still_approach, confidence_permille, 630).
rule(g8_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g8_destination_still_approach, approach_moving_away).
body(g8_destination_still_approach, start_below_rim).
learned(g8_destination_still_approach).
provenance(g8_destination_still_approach, layer, general).
provenance(g8_destination_still_approach, level, 2).
provenance(g8_destination_still_approach, support, 0).
provenance(g8_destination_still_approach, kept, 0).
provenance(g8_destination_still_approach, confidence_permille, 630).
rule(g9_destination_still_approach, defeasible, destination_still_approach).
body(g9_destination_still_approach, pour_below_rim).
body(g9_destination_still_approach, retreat_lowering).
learned(g9_destination_still_approach).
provenance(g9_destination_still_approach, layer, general).
provenance(g9_destination_still_approach, level, 2).
provenance(g9_destination_still_approach, support, 0).
provenance(g9_destination_still_approach, kept, 0).
provenance(g9_destination_still_approach, confidence_permille, 515).
rule(g10_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g10_destination_still_approach, approach_moving_closer).
body(g10_destination_still_approach, start_below_rim).
learned(g10_destination_still_approach).
provenance(g10_destination_still_approach, layer, general).
provenance(g10_destination_still_approach, level, 2).
provenance(g10_destination_still_approach, support, 6).
provenance(g10_destination_still_approach, kept, 5).
provenance(g10_destination_still_approach, confidence_permille, 526).
rule(g11_destination_still_approach, defeasible, destination_still_approach).
body(g11_destination_still_approach, slippery_destination).
body(g11_destination_still_approach, start_below_rim).
learned(g11_destination_still_approach).
provenance(g11_destination_still_approach, layer, general).
provenance(g11_destination_still_approach, level, 1).
provenance(g11_destination_still_approach, support, 0).
provenance(g11_destination_still_approach, kept, 0).
provenance(g11_destination_still_approach, confidence_permille, 558).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 48).
provenance(g0_destination_still_retreat, kept, 48).
provenance(g0_destination_still_retreat, confidence_permille, 996).
rule(g1_destination_still_retreat, defeasible, destination_still_retreat).
body(g1_destination_still_retreat, pour_below_rim).
learned(g1_destination_still_retreat).
provenance(g1_destination_still_retreat, layer, general).
provenance(g1_destination_still_retreat, level, 1).
provenance(g1_destination_still_retreat, support, 12).
provenance(g1_destination_still_retreat, kept, 3).
provenance(g1_destination_still_retreat, confidence_permille, 576).
rule(g2_destination_still_retreat, defeasible, destination_still_retreat).
body(g2_destination_still_retreat, end_below_rim).
learned(g2_destination_still_retreat).
provenance(g2_destination_still_retreat, layer, general).
provenance(g2_destination_still_retreat, level, 1).
provenance(g2_destination_still_retreat, support, 15).
provenance(g2_destination_still_retreat, kept, 7).
provenance(g2_destination_still_retreat, confidence_permille, 803).
rule(g3_destination_still_retreat, defeasible, destination_still_retreat).
body(g3_destination_still_retreat, retreat_lowering).
learned(g3_destination_still_retreat).
provenance(g3_destination_still_retreat, layer, general).
provenance(g3_destination_still_retreat, level, 1).
provenance(g3_destination_still_retreat, support, 34).
provenance(g3_destination_still_retreat, kept, 23).
provenance(g3_destination_still_retreat, confidence_permille, 885).
rule(g4_destination_still_retreat, defeasible, destination_still_retreat).
body(g4_destination_still_retreat, pour_low).
learned(g4_destination_still_retreat).
provenance(g4_destination_still_retreat, layer, general).
provenance(g4_destination_still_retreat, level, 1).
provenance(g4_destination_still_retreat, support, 12).
provenance(g4_destination_still_retreat, kept, 11).
provenance(g4_destination_still_retreat, confidence_permille, 962).
rule(g5_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g5_destination_still_retreat, pour_below_rim).
body(g5_destination_still_retreat, retreat_lowering).
learned(g5_destination_still_retreat).
provenance(g5_destination_still_retreat, layer, general).
provenance(g5_destination_still_retreat, level, 2).
provenance(g5_destination_still_retreat, support, 0).
provenance(g5_destination_still_retreat, kept, 0).
provenance(g5_destination_still_retreat, confidence_permille, 787).
rule(g6_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g6_destination_still_retreat, end_below_rim).
body(g6_destination_still_retreat, pour_below_rim).
learned(g6_destination_still_retreat).
provenance(g6_destination_still_retreat, layer, general).
provenance(g6_destination_still_retreat, level, 2).
provenance(g6_destination_still_retreat, support, 0).
provenance(g6_destination_still_retreat, kept, 0).
provenance(g6_destination_still_retreat, confidence_permille, 757).
rule(g7_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g7_destination_still_retreat, end_below_rim).
body(g7_destination_still_retreat, pour_low).
learned(g7_destination_still_retreat).
provenance(g7_destination_still_retreat, layer, general).
provenance(g7_destination_still_retreat, level, 2).
provenance(g7_destination_still_retreat, support, 4).
provenance(g7_destination_still_retreat, kept, 4).
provenance(g7_destination_still_retreat, confidence_permille, 530).
rule(g8_destination_still_retreat, defeasible, destination_still_retreat).
body(g8_destination_still_retreat, end_low).
learned(g8_destination_still_retreat).
provenance(g8_destination_still_retreat, layer, general).
provenance(g8_destination_still_retreat, level, 1).
provenance(g8_destination_still_retreat, support, 21).
provenance(g8_destination_still_retreat, kept, 18).
provenance(g8_destination_still_retreat, confidence_permille, 960).
rule(g9_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g9_destination_still_retreat, end_low).
body(g9_destination_still_retreat, pour_below_rim).
learned(g9_destination_still_retreat).
provenance(g9_destination_still_retreat, layer, general).
provenance(g9_destination_still_retreat, level, 2).
provenance(g9_destination_still_retreat, support, 0).
provenance(g9_destination_still_retreat, kept, 0).
provenance(g9_destination_still_retreat, confidence_permille, 549).
rule(g10_destination_still_retreat, defeasible, destination_still_retreat).
body(g10_destination_still_retreat, pour_low).
body(g10_destination_still_retreat, retreat_lowering).
learned(g10_destination_still_retreat).
provenance(g10_destination_still_retreat, layer, general).
provenance(g10_destination_still_retreat, level, 1).
provenance(g10_destination_still_retreat, support, 9).
provenance(g10_destination_still_retreat, kept, 2).
provenance(g10_destination_still_retreat, confidence_permille, 526).
rule(g11_destination_still_retreat, defeasible, destination_still_retreat).
body(g11_destination_still_retreat, approach_raising).
body(g11_destination_still_retreat, pour_below_rim).
learned(g11_destination_still_retreat).
provenance(g11_destination_still_retreat, layer, general).
provenance(g11_destination_still_retreat, level, 1).
provenance(g11_destination_still_retreat, support, 0).
provenance(g11_destination_still_retreat, kept, 0).
provenance(g11_destination_still_retreat, confidence_permille, 780).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 48).
provenance(g0_destination_still_settle, kept, 48).
provenance(g0_destination_still_settle, confidence_permille, 1000).
rule(g1_destination_still_settle, defeasible, destination_still_settle).
body(g1_destination_still_settle, end_below_rim).
learned(g1_destination_still_settle).
provenance(g1_destination_still_settle, layer, general).
provenance(g1_destination_still_settle, level, 1).
provenance(g1_destination_still_settle, support, 15).
provenance(g1_destination_still_settle, kept, 14).
provenance(g1_destination_still_settle, confidence_permille, 991).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 48).
provenance(g0_destination_upright, kept, 48).
provenance(g0_destination_upright, confidence_permille, 999).
rule(g1_destination_upright, defeasible, destination_upright).
body(g1_destination_upright, end_below_rim).
learned(g1_destination_upright).
provenance(g1_destination_upright, layer, general).
provenance(g1_destination_upright, level, 1).
provenance(g1_destination_upright, support, 15).
provenance(g1_destination_upright, kept, 11).
provenance(g1_destination_upright, confidence_permille, 953).
rule(g2_destination_upright, defeasible, destination_upright).
body(g2_destination_upright, retreat_lowering).
learned(g2_destination_upright).
provenance(g2_destination_upright, layer, general).
provenance(g2_destination_upright, level, 1).
provenance(g2_destination_upright, support, 34).
provenance(g2_destination_upright, kept, 30).
provenance(g2_destination_upright, confidence_permille, 975).
rule(g3_destination_upright, defeasible, destination_upright).
body(g3_destination_upright, pour_below_rim).
learned(g3_destination_upright).
provenance(g3_destination_upright, layer, general).
provenance(g3_destination_upright, level, 1).
provenance(g3_destination_upright, support, 12).
provenance(g3_destination_upright, kept, 10).
provenance(g3_destination_upright, confidence_permille, 979).
rule(g4_destination_upright, defeasible, destination_upright).
body(g4_destination_upright, end_low).
learned(g4_destination_upright).
provenance(g4_destination_upright, layer, general).
provenance(g4_destination_upright, level, 1).
provenance(g4_destination_upright, support, 21).
provenance(g4_destination_upright, kept, 21).
provenance(g4_destination_upright, confidence_permille, 984).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 48).
provenance(g0_source_clear, kept, 47).
provenance(g0_source_clear, confidence_permille, 974).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, pour_below_rim).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 12).
provenance(g1_source_clear, kept, 12).
provenance(g1_source_clear, confidence_permille, 963).
rule(g2_source_clear, defeasible, neg(source_clear)).
body(g2_source_clear, end_below_rim).
learned(g2_source_clear).
provenance(g2_source_clear, layer, general).
provenance(g2_source_clear, level, 1).
provenance(g2_source_clear, support, 15).
provenance(g2_source_clear, kept, 11).
provenance(g2_source_clear, confidence_permille, 508).
rule(g3_source_clear, defeasible, neg(source_clear)).
body(g3_source_clear, pour_low).
learned(g3_source_clear).
provenance(g3_source_clear, layer, general).
provenance(g3_source_clear, level, 1).
provenance(g3_source_clear, support, 12).
provenance(g3_source_clear, kept, 6).
provenance(g3_source_clear, confidence_permille, 539).
rule(g4_source_clear, defeasible, source_clear).
body(g4_source_clear, start_below_rim).
learned(g4_source_clear).
provenance(g4_source_clear, layer, general).
provenance(g4_source_clear, level, 1).
provenance(g4_source_clear, support, 13).
provenance(g4_source_clear, kept, 4).
provenance(g4_source_clear, confidence_permille, 624).
rule(g5_source_clear, defeasible, source_clear).
body(g5_source_clear, retreat_lowering).
learned(g5_source_clear).
provenance(g5_source_clear, layer, general).
provenance(g5_source_clear, level, 1).
provenance(g5_source_clear, support, 34).
provenance(g5_source_clear, kept, 17).
provenance(g5_source_clear, confidence_permille, 707).
rule(g6_source_clear, defeasible, source_clear).
body(g6_source_clear, approach_raising).
learned(g6_source_clear).
provenance(g6_source_clear, layer, general).
provenance(g6_source_clear, level, 1).
provenance(g6_source_clear, support, 36).
provenance(g6_source_clear, kept, 24).
provenance(g6_source_clear, confidence_permille, 823).
rule(g7_source_clear, defeasible, source_clear).
body(g7_source_clear, end_low).
learned(g7_source_clear).
provenance(g7_source_clear, layer, general).
provenance(g7_source_clear, level, 1).
provenance(g7_source_clear, support, 21).
provenance(g7_source_clear, kept, 14).
provenance(g7_source_clear, confidence_permille, 861).
rule(g8_source_clear, defeasible, source_clear).
body(g8_source_clear, pour_to_side).
learned(g8_source_clear).
provenance(g8_source_clear, layer, general).
provenance(g8_source_clear, level, 1).
provenance(g8_source_clear, support, 12).
provenance(g8_source_clear, kept, 12).
provenance(g8_source_clear, confidence_permille, 986).
rule(g9_source_clear, defeasible, source_clear).
body(g9_source_clear, pour_very_high).
learned(g9_source_clear).
provenance(g9_source_clear, layer, general).
provenance(g9_source_clear, level, 1).
provenance(g9_source_clear, support, 12).
provenance(g9_source_clear, kept, 12).
provenance(g9_source_clear, confidence_permille, 998).
rule(g10_source_clear, defeasible, source_clear).
body(g10_source_clear, pour_high).
learned(g10_source_clear).
provenance(g10_source_clear, layer, general).
provenance(g10_source_clear, level, 1).
provenance(g10_source_clear, support, 12).
provenance(g10_source_clear, kept, 12).
provenance(g10_source_clear, confidence_permille, 998).
rule(g11_source_clear, defeasible, source_clear).
body(g11_source_clear, pour_far_away).
learned(g11_source_clear).
provenance(g11_source_clear, layer, general).
provenance(g11_source_clear, level, 1).
provenance(g11_source_clear, support, 12).
provenance(g11_source_clear, kept, 12).
provenance(g11_source_clear, confidence_permille, 983).
rule(g0_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 48).
provenance(g0_liquid_leaves_source, kept, 48).
provenance(g0_liquid_leaves_source, confidence_permille, 1000).
rule(g1_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g1_liquid_leaves_source, pour_tilted_back).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 12).
provenance(g1_liquid_leaves_source, kept, 12).
provenance(g1_liquid_leaves_source, confidence_permille, 995).
rule(g2_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g2_liquid_leaves_source, pour_upright).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 12).
provenance(g2_liquid_leaves_source, kept, 12).
provenance(g2_liquid_leaves_source, confidence_permille, 995).
rule(g3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g3_liquid_leaves_source, pour_slightly_tilted).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 12).
provenance(g3_liquid_leaves_source, kept, 12).
provenance(g3_liquid_leaves_source, confidence_permille, 987).
rule(g4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g4_liquid_leaves_source, pour_half_tilted).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 12).
provenance(g4_liquid_leaves_source, kept, 12).
provenance(g4_liquid_leaves_source, confidence_permille, 981).
rule(g5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g5_liquid_leaves_source, pour_steeply_tilted).
learned(g5_liquid_leaves_source).
provenance(g5_liquid_leaves_source, layer, general).
provenance(g5_liquid_leaves_source, level, 1).
provenance(g5_liquid_leaves_source, support, 36).
provenance(g5_liquid_leaves_source, kept, 34).
provenance(g5_liquid_leaves_source, confidence_permille, 779).
rule(g6_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g6_liquid_leaves_source, end_upside_down).
learned(g6_liquid_leaves_source).
provenance(g6_liquid_leaves_source, layer, general).
provenance(g6_liquid_leaves_source, level, 1).
provenance(g6_liquid_leaves_source, support, 12).
provenance(g6_liquid_leaves_source, kept, 12).
provenance(g6_liquid_leaves_source, confidence_permille, 1000).
rule(g7_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g7_liquid_leaves_source, end_steeply_tilted).
learned(g7_liquid_leaves_source).
provenance(g7_liquid_leaves_source, layer, general).
provenance(g7_liquid_leaves_source, level, 1).
provenance(g7_liquid_leaves_source, support, 12).
provenance(g7_liquid_leaves_source, kept, 12).
provenance(g7_liquid_leaves_source, confidence_permille, 1000).
rule(g8_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g8_liquid_leaves_source, end_below_rim).
body(g8_liquid_leaves_source, pour_half_tilted).
learned(g8_liquid_leaves_source).
provenance(g8_liquid_leaves_source, layer, general).
provenance(g8_liquid_leaves_source, level, 1).
provenance(g8_liquid_leaves_source, support, 0).
provenance(g8_liquid_leaves_source, kept, 0).
provenance(g8_liquid_leaves_source, confidence_permille, 516).
rule(g9_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g9_liquid_leaves_source, end_below_rim).
body(g9_liquid_leaves_source, pour_slightly_tilted).
learned(g9_liquid_leaves_source).
provenance(g9_liquid_leaves_source, layer, general).
provenance(g9_liquid_leaves_source, level, 1).
provenance(g9_liquid_leaves_source, support, 0).
provenance(g9_liquid_leaves_source, kept, 0).
provenance(g9_liquid_leaves_source, confidence_permille, 585).
rule(g0_liquid_enters_destination, defeasible, liquid_enters_destination).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 48).
provenance(g0_liquid_enters_destination, kept, 48).
provenance(g0_liquid_enters_destination, confidence_permille, 986).
rule(g1_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g1_liquid_enters_destination, pour_far_away).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 12).
provenance(g1_liquid_enters_destination, kept, 12).
provenance(g1_liquid_enters_destination, confidence_permille, 961).
rule(g2_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g2_liquid_enters_destination, pour_tilted_back).
learned(g2_liquid_enters_destination).
provenance(g2_liquid_enters_destination, layer, general).
provenance(g2_liquid_enters_destination, level, 1).
provenance(g2_liquid_enters_destination, support, 12).
provenance(g2_liquid_enters_destination, kept, 12).
provenance(g2_liquid_enters_destination, confidence_permille, 946).
rule(g3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g3_liquid_enters_destination, pour_upright).
learned(g3_liquid_enters_destination).
provenance(g3_liquid_enters_destination, layer, general).
provenance(g3_liquid_enters_destination, level, 1).
provenance(g3_liquid_enters_destination, support, 12).
provenance(g3_liquid_enters_destination, kept, 12).
provenance(g3_liquid_enters_destination, confidence_permille, 932).
rule(g4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g4_liquid_enters_destination, pour_to_side).
learned(g4_liquid_enters_destination).
provenance(g4_liquid_enters_destination, layer, general).
provenance(g4_liquid_enters_destination, level, 1).
provenance(g4_liquid_enters_destination, support, 12).
provenance(g4_liquid_enters_destination, kept, 9).
provenance(g4_liquid_enters_destination, confidence_permille, 851).
rule(g5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g5_liquid_enters_destination, pour_slightly_tilted).
learned(g5_liquid_enters_destination).
provenance(g5_liquid_enters_destination, layer, general).
provenance(g5_liquid_enters_destination, level, 1).
provenance(g5_liquid_enters_destination, support, 12).
provenance(g5_liquid_enters_destination, kept, 12).
provenance(g5_liquid_enters_destination, confidence_permille, 895).
rule(g6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g6_liquid_enters_destination, pour_half_tilted).
learned(g6_liquid_enters_destination).
provenance(g6_liquid_enters_destination, layer, general).
provenance(g6_liquid_enters_destination, level, 1).
provenance(g6_liquid_enters_destination, support, 12).
provenance(g6_liquid_enters_destination, kept, 12).
provenance(g6_liquid_enters_destination, confidence_permille, 891).
rule(g7_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g7_liquid_enters_destination, pour_offset_sideways).
learned(g7_liquid_enters_destination).
provenance(g7_liquid_enters_destination, layer, general).
provenance(g7_liquid_enters_destination, level, 1).
provenance(g7_liquid_enters_destination, support, 12).
provenance(g7_liquid_enters_destination, kept, 7).
provenance(g7_liquid_enters_destination, confidence_permille, 534).
rule(g8_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g8_liquid_enters_destination, pour_steeply_tilted).
learned(g8_liquid_enters_destination).
provenance(g8_liquid_enters_destination, layer, general).
provenance(g8_liquid_enters_destination, level, 1).
provenance(g8_liquid_enters_destination, support, 36).
provenance(g8_liquid_enters_destination, kept, 34).
provenance(g8_liquid_enters_destination, confidence_permille, 748).
rule(g9_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g9_liquid_enters_destination, pour_very_high).
learned(g9_liquid_enters_destination).
provenance(g9_liquid_enters_destination, layer, general).
provenance(g9_liquid_enters_destination, level, 1).
provenance(g9_liquid_enters_destination, support, 12).
provenance(g9_liquid_enters_destination, kept, 7).
provenance(g9_liquid_enters_destination, confidence_permille, 794).
rule(g10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g10_liquid_enters_destination, end_below_rim).
body(g10_liquid_enters_destination, pour_slightly_tilted).
learned(g10_liquid_enters_destination).
provenance(g10_liquid_enters_destination, layer, general).
provenance(g10_liquid_enters_destination, level, 2).
provenance(g10_liquid_enters_destination, support, 0).
provenance(g10_liquid_enters_destination, kept, 0).
provenance(g10_liquid_enters_destination, confidence_permille, 631).
rule(g11_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g11_liquid_enters_destination, end_below_rim).
body(g11_liquid_enters_destination, pour_half_tilted).
learned(g11_liquid_enters_destination).
provenance(g11_liquid_enters_destination, layer, general).
provenance(g11_liquid_enters_destination, level, 2).
provenance(g11_liquid_enters_destination, support, 0).
provenance(g11_liquid_enters_destination, kept, 0).
provenance(g11_liquid_enters_destination, confidence_permille, 603).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 48).
provenance(g0_liquid_remains_in_destination, kept, 48).
provenance(g0_liquid_remains_in_destination, confidence_permille, 1000).
rule(g1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g1_liquid_remains_in_destination, pour_below_rim).
learned(g1_liquid_remains_in_destination).
provenance(g1_liquid_remains_in_destination, layer, general).
provenance(g1_liquid_remains_in_destination, level, 1).
provenance(g1_liquid_remains_in_destination, support, 12).
provenance(g1_liquid_remains_in_destination, kept, 7).
provenance(g1_liquid_remains_in_destination, confidence_permille, 787).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 48).
provenance(g0_no_spill, kept, 48).
provenance(g0_no_spill, confidence_permille, 991).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, pour_far_away).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 12).
provenance(g1_no_spill, kept, 12).
provenance(g1_no_spill, confidence_permille, 936).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, pour_to_side).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 12).
provenance(g2_no_spill, kept, 9).
provenance(g2_no_spill, confidence_permille, 827).
rule(g3_no_spill, defeasible, no_spill).
body(g3_no_spill, pour_offset_sideways).
learned(g3_no_spill).
provenance(g3_no_spill, layer, general).
provenance(g3_no_spill, level, 1).
provenance(g3_no_spill, support, 12).
provenance(g3_no_spill, kept, 7).
provenance(g3_no_spill, confidence_permille, 633).
rule(g4_no_spill, defeasible, no_spill).
body(g4_no_spill, pour_very_high).
learned(g4_no_spill).
provenance(g4_no_spill, layer, general).
provenance(g4_no_spill, level, 1).
provenance(g4_no_spill, support, 12).
provenance(g4_no_spill, kept, 7).
provenance(g4_no_spill, confidence_permille, 763).
rule(g5_no_spill, defeasible, no_spill).
body(g5_no_spill, pour_below_rim).
learned(g5_no_spill).
provenance(g5_no_spill, layer, general).
provenance(g5_no_spill, level, 1).
provenance(g5_no_spill, support, 12).
provenance(g5_no_spill, kept, 6).
provenance(g5_no_spill, confidence_permille, 802).
rule(g6_no_spill, defeasible, no_spill).
body(g6_no_spill, pour_upright).
learned(g6_no_spill).
provenance(g6_no_spill, layer, general).
provenance(g6_no_spill, level, 1).
provenance(g6_no_spill, support, 12).
provenance(g6_no_spill, kept, 12).
provenance(g6_no_spill, confidence_permille, 995).
rule(g7_no_spill, defeasible, no_spill).
body(g7_no_spill, pour_tilted_back).
learned(g7_no_spill).
provenance(g7_no_spill, layer, general).
provenance(g7_no_spill, level, 1).
provenance(g7_no_spill, support, 12).
provenance(g7_no_spill, kept, 12).
provenance(g7_no_spill, confidence_permille, 995).
rule(g8_no_spill, defeasible, no_spill).
body(g8_no_spill, pour_half_tilted).
learned(g8_no_spill).
provenance(g8_no_spill, layer, general).
provenance(g8_no_spill, level, 1).
provenance(g8_no_spill, support, 12).
provenance(g8_no_spill, kept, 12).
provenance(g8_no_spill, confidence_permille, 993).
rule(g9_no_spill, defeasible, no_spill).
body(g9_no_spill, pour_slightly_tilted).
learned(g9_no_spill).
provenance(g9_no_spill, layer, general).
provenance(g9_no_spill, level, 1).
provenance(g9_no_spill, support, 12).
provenance(g9_no_spill, kept, 12).
provenance(g9_no_spill, confidence_permille, 993).
rule(g10_no_spill, defeasible, neg(no_spill)).
body(g10_no_spill, end_upside_down).
body(g10_no_spill, pour_very_high).
learned(g10_no_spill).
provenance(g10_no_spill, layer, general).
provenance(g10_no_spill, level, 2).
provenance(g10_no_spill, support, 0).
provenance(g10_no_spill, kept, 0).
provenance(g10_no_spill, confidence_permille, 758).
rule(g11_no_spill, defeasible, neg(no_spill)).
body(g11_no_spill, end_steeply_tilted).
body(g11_no_spill, pour_very_high).
learned(g11_no_spill).
provenance(g11_no_spill, layer, general).
provenance(g11_no_spill, level, 2).
provenance(g11_no_spill, support, 0).
provenance(g11_no_spill, kept, 0).
provenance(g11_no_spill, confidence_permille, 742).
sup(g10_destination_still_approach, g5_destination_still_approach).
sup(g10_destination_still_approach, g9_destination_still_approach).
sup(g10_liquid_enters_destination, g1_liquid_enters_destination).
sup(g10_liquid_enters_destination, g4_liquid_enters_destination).
sup(g10_no_spill, g3_no_spill).
sup(g10_no_spill, g6_no_spill).
sup(g10_no_spill, g7_no_spill).
sup(g10_no_spill, g8_no_spill).
sup(g10_no_spill, g9_no_spill).
sup(g10_source_clear, g2_source_clear).
sup(g11_destination_still_approach, g10_destination_still_approach).
sup(g11_destination_still_approach, g1_destination_still_approach).
sup(g11_destination_still_retreat, g6_destination_still_retreat).
sup(g11_destination_still_retreat, g9_destination_still_retreat).
sup(g11_liquid_enters_destination, g1_liquid_enters_destination).
sup(g11_liquid_enters_destination, g4_liquid_enters_destination).
sup(g11_no_spill, g3_no_spill).
sup(g11_no_spill, g6_no_spill).
sup(g11_no_spill, g7_no_spill).
sup(g11_no_spill, g8_no_spill).
sup(g11_no_spill, g9_no_spill).
sup(g11_source_clear, g1_source_clear).
sup(g11_source_clear, g2_source_clear).
sup(g11_source_clear, g3_source_clear).
sup(g1_destination_still_approach, g2_destination_still_approach).
sup(g1_liquid_enters_destination, g7_liquid_enters_destination).
sup(g1_liquid_enters_destination, g8_liquid_enters_destination).
sup(g1_liquid_enters_destination, g9_liquid_enters_destination).
sup(g1_no_spill, g3_no_spill).
sup(g1_no_spill, g4_no_spill).
sup(g1_no_spill, g5_no_spill).
sup(g1_source_clear, g4_source_clear).
sup(g1_source_clear, g5_source_clear).
sup(g1_source_clear, g6_source_clear).
sup(g1_source_clear, g7_source_clear).
sup(g2_liquid_enters_destination, g7_liquid_enters_destination).
sup(g2_liquid_enters_destination, g9_liquid_enters_destination).
sup(g2_no_spill, g3_no_spill).
sup(g2_no_spill, g4_no_spill).
sup(g3_destination_still_approach, g1_destination_still_approach).
sup(g3_liquid_enters_destination, g7_liquid_enters_destination).
sup(g3_liquid_enters_destination, g9_liquid_enters_destination).
sup(g4_destination_still_approach, g9_destination_still_approach).
sup(g4_liquid_enters_destination, g7_liquid_enters_destination).
sup(g4_liquid_enters_destination, g8_liquid_enters_destination).
sup(g4_liquid_enters_destination, g9_liquid_enters_destination).
sup(g4_source_clear, g2_source_clear).
sup(g4_source_clear, g3_source_clear).
sup(g5_destination_still_retreat, g11_destination_still_retreat).
sup(g5_liquid_enters_destination, g7_liquid_enters_destination).
sup(g5_liquid_enters_destination, g9_liquid_enters_destination).
sup(g5_source_clear, g3_source_clear).
sup(g6_destination_still_approach, g11_destination_still_approach).
sup(g6_liquid_enters_destination, g7_liquid_enters_destination).
sup(g6_liquid_enters_destination, g9_liquid_enters_destination).
sup(g6_liquid_leaves_source, g1_liquid_leaves_source).
sup(g6_liquid_leaves_source, g2_liquid_leaves_source).
sup(g6_liquid_leaves_source, g3_liquid_leaves_source).
sup(g6_liquid_leaves_source, g4_liquid_leaves_source).
sup(g6_no_spill, g1_no_spill).
sup(g6_no_spill, g2_no_spill).
sup(g6_source_clear, g2_source_clear).
sup(g6_source_clear, g3_source_clear).
sup(g7_liquid_leaves_source, g1_liquid_leaves_source).
sup(g7_liquid_leaves_source, g2_liquid_leaves_source).
sup(g7_liquid_leaves_source, g3_liquid_leaves_source).
sup(g7_liquid_leaves_source, g4_liquid_leaves_source).
sup(g7_no_spill, g1_no_spill).
sup(g7_no_spill, g2_no_spill).
sup(g7_source_clear, g3_source_clear).
sup(g8_destination_still_approach, g11_destination_still_approach).
sup(g8_destination_still_approach, g5_destination_still_approach).
sup(g8_destination_still_approach, g9_destination_still_approach).
sup(g8_liquid_leaves_source, g6_liquid_leaves_source).
sup(g8_liquid_leaves_source, g7_liquid_leaves_source).
sup(g8_no_spill, g1_no_spill).
sup(g8_no_spill, g2_no_spill).
sup(g8_source_clear, g2_source_clear).
sup(g8_source_clear, g3_source_clear).
sup(g9_liquid_leaves_source, g6_liquid_leaves_source).
sup(g9_liquid_leaves_source, g7_liquid_leaves_source).
sup(g9_no_spill, g1_no_spill).
sup(g9_no_spill, g2_no_spill).
sup(g9_source_clear, g2_source_clear).
sup(r10_liquid_enters_destination, g1_liquid_enters_destination).
sup(r10_liquid_enters_destination, g4_liquid_enters_destination).
sup(r10_no_spill, g1_no_spill).
sup(r10_no_spill, g2_no_spill).
sup(r10_source_clear, g11_source_clear).
sup(r10_source_clear, g8_source_clear).
sup(r11_destination_still_approach, g1_destination_still_approach).
sup(r11_destination_still_approach, g6_destination_still_approach).
sup(r11_destination_still_retreat, g9_destination_still_retreat).
sup(r11_liquid_enters_destination, g9_liquid_enters_destination).
sup(r11_no_spill, g1_no_spill).
sup(r11_no_spill, g2_no_spill).
sup(r11_source_clear, g10_source_clear).
sup(r11_source_clear, g11_source_clear).
sup(r11_source_clear, g8_source_clear).
sup(r11_source_clear, g9_source_clear).
sup(r12_destination_still_approach, g5_destination_still_approach).
sup(r12_destination_still_retreat, g9_destination_still_retreat).
sup(r12_liquid_enters_destination, g9_liquid_enters_destination).
sup(r12_liquid_remains_in_destination, g1_liquid_remains_in_destination).
sup(r12_no_spill, g1_no_spill).
sup(r12_no_spill, g2_no_spill).
sup(r12_source_clear, g10_source_clear).
sup(r12_source_clear, g11_source_clear).
sup(r12_source_clear, g8_source_clear).
sup(r12_source_clear, g9_source_clear).
sup(r13_destination_still_approach, g1_destination_still_approach).
sup(r13_destination_still_approach, g6_destination_still_approach).
sup(r13_destination_still_retreat, g9_destination_still_retreat).
sup(r13_liquid_enters_destination, g1_liquid_enters_destination).
sup(r13_liquid_enters_destination, g4_liquid_enters_destination).
sup(r13_liquid_remains_in_destination, g1_liquid_remains_in_destination).
sup(r13_no_spill, g1_no_spill).
sup(r13_no_spill, g2_no_spill).
sup(r13_source_clear, g10_source_clear).
sup(r13_source_clear, g11_source_clear).
sup(r13_source_clear, g8_source_clear).
sup(r13_source_clear, g9_source_clear).
sup(r14_liquid_enters_destination, g1_liquid_enters_destination).
sup(r14_no_spill, g1_no_spill).
sup(r14_source_clear, g11_source_clear).
sup(r15_destination_still_approach, g5_destination_still_approach).
sup(r15_liquid_enters_destination, g9_liquid_enters_destination).
sup(r15_no_spill, g4_no_spill).
sup(r15_no_spill, g5_no_spill).
sup(r15_source_clear, g10_source_clear).
sup(r15_source_clear, g11_source_clear).
sup(r15_source_clear, g8_source_clear).
sup(r15_source_clear, g9_source_clear).
sup(r16_destination_still_approach, g5_destination_still_approach).
sup(r16_destination_still_retreat, g9_destination_still_retreat).
sup(r16_liquid_enters_destination, g9_liquid_enters_destination).
sup(r16_liquid_remains_in_destination, g1_liquid_remains_in_destination).
sup(r16_no_spill, g1_no_spill).
sup(r16_no_spill, g2_no_spill).
sup(r16_source_clear, g10_source_clear).
sup(r16_source_clear, g11_source_clear).
sup(r16_source_clear, g8_source_clear).
sup(r16_source_clear, g9_source_clear).
sup(r17_liquid_enters_destination, g1_liquid_enters_destination).
sup(r17_no_spill, g1_no_spill).
sup(r17_source_clear, g11_source_clear).
sup(r1_destination_still_approach, g10_destination_still_approach).
sup(r1_destination_still_approach, g8_destination_still_approach).
sup(r1_source_clear, g2_source_clear).
sup(r2_destination_still_approach, g8_destination_still_approach).
sup(r2_liquid_enters_destination, g7_liquid_enters_destination).
sup(r2_no_spill, g3_no_spill).
sup(r5_destination_still_approach, g10_destination_still_approach).
sup(r5_destination_still_approach, g8_destination_still_approach).
sup(r5_source_clear, g2_source_clear).
sup(r6_liquid_enters_destination, g7_liquid_enters_destination).
sup(r6_source_clear, g2_source_clear).
sup(r7_destination_still_approach, g5_destination_still_approach).
sup(r7_destination_still_retreat, g9_destination_still_retreat).
sup(r7_liquid_enters_destination, g9_liquid_enters_destination).
sup(r7_no_spill, g1_no_spill).
sup(r7_no_spill, g2_no_spill).
sup(r7_source_clear, g10_source_clear).
sup(r7_source_clear, g11_source_clear).
sup(r7_source_clear, g8_source_clear).
sup(r7_source_clear, g9_source_clear).
sup(r8_destination_still_approach, g5_destination_still_approach).
sup(r8_destination_still_retreat, g9_destination_still_retreat).
sup(r8_liquid_enters_destination, g9_liquid_enters_destination).
sup(r8_no_spill, g1_no_spill).
sup(r8_no_spill, g2_no_spill).
sup(r8_source_clear, g10_source_clear).
sup(r8_source_clear, g11_source_clear).
sup(r8_source_clear, g8_source_clear).
sup(r8_source_clear, g9_source_clear).
sup(r9_destination_still_approach, g1_destination_still_approach).
sup(r9_destination_still_approach, g6_destination_still_approach).
sup(r9_destination_still_retreat, g9_destination_still_retreat).
sup(r9_liquid_enters_destination, g1_liquid_enters_destination).
sup(r9_liquid_enters_destination, g4_liquid_enters_destination).
sup(r9_no_spill, g10_no_spill).
sup(r9_no_spill, g1_no_spill).
sup(r9_no_spill, g2_no_spill).
sup(r9_source_clear, g10_source_clear).
sup(r9_source_clear, g11_source_clear).
sup(r9_source_clear, g8_source_clear).
sup(r9_source_clear, g9_source_clear).
