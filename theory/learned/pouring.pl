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
setting(oracle_version, "3").
setting(seed, 1).
setting(samples, 31).
setting(max_rules, 25).
setting(curiosity, discover).
setting(significance_permille, 50).
setting(permutations, 199).
setting(resample, 2).
setting(novelty_permille, 100).
setting(queue, 100).
setting(jumps, 31).
setting(probe, 8).
setting(probe_attempts, 3).
setting(cover, 0).
setting(prior, 1).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 19).
setting(simulations, 765).
setting(failed_simulations, 0).
setting(stopped, max_rules).
setting(a_new_left, 101).
setting(initial, pour_mid_height).
setting(initial, pour_near_rim).
setting(initial, pour_steeply_tilted).
set_aside(4, 0, bouncy_liquid).
set_aside(4, 0, dull_destination).
set_aside(4, 0, end_far_away).
set_aside(4, 0, end_slightly_tilted).
set_aside(4, 0, grippy_source).
set_aside(4, 0, heavy_destination).
set_aside(4, 0, heavy_source).
set_aside(4, 0, light_liquid).
set_aside(4, 0, pour_half_tilted).
set_aside(4, 0, pour_in_line).
set_aside(4, 0, pour_low).
set_aside(4, 0, pour_near_rim).
set_aside(4, 0, retreat_lowering).
set_aside(4, 0, slippery_destination).
set_aside(4, 0, slow_approach).
set_aside(4, 0, slow_retreat).
set_aside(4, 0, start_below_rim).
set_aside(4, 0, start_tilted_back).
set_aside(4, 0, sticky_liquid).
set_aside(5, 1, approach_moving_away).
set_aside(5, 1, approach_raising).
set_aside(5, 1, bouncy_source).
set_aside(5, 1, dull_destination).
set_aside(5, 1, dull_liquid).
set_aside(5, 1, end_centred).
set_aside(5, 1, end_rolled).
set_aside(5, 1, end_tilted_back).
set_aside(5, 1, end_very_high).
set_aside(5, 1, fast_approach).
set_aside(5, 1, grippy_destination).
set_aside(5, 1, heavy_destination).
set_aside(5, 1, light_liquid).
set_aside(5, 1, light_source).
set_aside(5, 1, moderate_retreat).
set_aside(5, 1, pour_centred).
set_aside(5, 1, pour_low).
set_aside(5, 1, pour_tilted_back).
set_aside(5, 1, start_tilted_back).
set_aside(5, 1, sticky_liquid).
set_aside(5, 2, approach_moving_away).
set_aside(5, 2, approach_raising).
set_aside(5, 2, bouncy_source).
set_aside(5, 2, dull_destination).
set_aside(5, 2, dull_liquid).
set_aside(5, 2, end_centred).
set_aside(5, 2, end_rolled).
set_aside(5, 2, end_tilted_back).
set_aside(5, 2, end_very_high).
set_aside(5, 2, fast_approach).
set_aside(5, 2, grippy_destination).
set_aside(5, 2, heavy_destination).
set_aside(5, 2, heavy_source).
set_aside(5, 2, light_liquid).
set_aside(5, 2, moderate_retreat).
set_aside(5, 2, pour_centred).
set_aside(5, 2, pour_low).
set_aside(5, 2, pour_rolled).
set_aside(5, 2, pour_tilted_back).
set_aside(5, 2, start_tilted_back).
set_aside(5, 2, sticky_liquid).
set_aside(6, 0, approach_moving_away).
set_aside(6, 0, approach_raising).
set_aside(6, 0, bouncy_source).
set_aside(6, 0, dull_destination).
set_aside(6, 0, dull_liquid).
set_aside(6, 0, end_rolled).
set_aside(6, 0, end_tilted_back).
set_aside(6, 0, end_to_side).
set_aside(6, 0, end_very_high).
set_aside(6, 0, fast_approach).
set_aside(6, 0, grippy_destination).
set_aside(6, 0, heavy_destination).
set_aside(6, 0, heavy_source).
set_aside(6, 0, light_liquid).
set_aside(6, 0, moderate_retreat).
set_aside(6, 0, pour_centred).
set_aside(6, 0, pour_low).
set_aside(6, 0, pour_tilted_back).
set_aside(6, 0, start_tilted_back).
set_aside(6, 0, sticky_liquid).
set_aside(6, 0, very_much_liquid).
set_aside(7, 0, approach_moving_away).
set_aside(7, 0, approach_raising).
set_aside(7, 0, bouncy_source).
set_aside(7, 0, dull_destination).
set_aside(7, 0, dull_liquid).
set_aside(7, 0, end_centred).
set_aside(7, 0, end_rolled).
set_aside(7, 0, end_tilted_back).
set_aside(7, 0, end_very_high).
set_aside(7, 0, fast_approach).
set_aside(7, 0, grippy_destination).
set_aside(7, 0, heavy_source).
set_aside(7, 0, light_destination).
set_aside(7, 0, light_liquid).
set_aside(7, 0, moderate_retreat).
set_aside(7, 0, pour_centred).
set_aside(7, 0, pour_level).
set_aside(7, 0, pour_low).
set_aside(7, 0, pour_tilted_back).
set_aside(7, 0, start_tilted_back).
set_aside(7, 0, sticky_liquid).
set_aside(7, 2, approach_moving_away).
set_aside(7, 2, approach_raising).
set_aside(7, 2, bouncy_source).
set_aside(7, 2, dull_destination).
set_aside(7, 2, dull_liquid).
set_aside(7, 2, end_centred).
set_aside(7, 2, end_level).
set_aside(7, 2, end_tilted_back).
set_aside(7, 2, end_very_high).
set_aside(7, 2, fast_approach).
set_aside(7, 2, grippy_destination).
set_aside(7, 2, heavy_destination).
set_aside(7, 2, heavy_source).
set_aside(7, 2, light_liquid).
set_aside(7, 2, moderate_retreat).
set_aside(7, 2, pour_centred).
set_aside(7, 2, pour_level).
set_aside(7, 2, pour_low).
set_aside(7, 2, pour_tilted_back).
set_aside(7, 2, start_tilted_back).
set_aside(7, 2, sticky_liquid).
set_aside(8, 0, approach_moving_away).
set_aside(8, 0, bouncy_source).
set_aside(8, 0, dull_destination).
set_aside(8, 0, end_level).
set_aside(8, 0, end_to_side).
set_aside(8, 0, end_upright).
set_aside(8, 0, fast_approach).
set_aside(8, 0, heavy_source).
set_aside(8, 0, light_destination).
set_aside(8, 0, light_liquid).
set_aside(8, 0, little_liquid).
set_aside(8, 0, pour_mid_height).
set_aside(8, 0, pour_near_rim).
set_aside(8, 0, pour_rolled).
set_aside(8, 0, pour_upside_down).
set_aside(8, 0, retreat_raising).
set_aside(8, 0, slippery_source).
set_aside(8, 0, start_below_rim).
set_aside(8, 0, start_tilted_back).
set_aside(8, 2, approach_moving_closer).
set_aside(8, 2, approach_raising).
set_aside(8, 2, bouncy_source).
set_aside(8, 2, dull_destination).
set_aside(8, 2, dull_liquid).
set_aside(8, 2, end_centred).
set_aside(8, 2, end_rolled).
set_aside(8, 2, end_tilted_back).
set_aside(8, 2, end_very_high).
set_aside(8, 2, fast_approach).
set_aside(8, 2, grippy_destination).
set_aside(8, 2, heavy_destination).
set_aside(8, 2, heavy_source).
set_aside(8, 2, light_liquid).
set_aside(8, 2, moderate_retreat).
set_aside(8, 2, pour_centred).
set_aside(8, 2, pour_low).
set_aside(8, 2, pour_tilted_back).
set_aside(8, 2, start_tilted_back).
set_aside(8, 2, sticky_liquid).
set_aside(8, 2, very_much_liquid).
set_aside(9, 0, approach_raising).
set_aside(9, 0, bouncy_destination).
set_aside(9, 0, bouncy_source).
set_aside(9, 0, end_far_away).
set_aside(9, 0, end_level).
set_aside(9, 0, end_slightly_tilted).
set_aside(9, 0, heavy_liquid).
set_aside(9, 0, pour_half_tilted).
set_aside(9, 0, pour_in_line).
set_aside(9, 0, pour_mid_height).
set_aside(9, 0, retreat_lowering).
set_aside(9, 0, slow_approach).
set_aside(9, 0, slow_retreat).
set_aside(9, 0, some_liquid).
set_aside(9, 0, start_centred).
set_aside(9, 0, start_tilted_back).
set_aside(9, 2, approach_moving_away).
set_aside(9, 2, approach_raising).
set_aside(9, 2, bouncy_source).
set_aside(9, 2, dull_destination).
set_aside(9, 2, dull_liquid).
set_aside(9, 2, end_centred).
set_aside(9, 2, end_rolled).
set_aside(9, 2, end_tilted_back).
set_aside(9, 2, end_very_high).
set_aside(9, 2, fast_approach).
set_aside(9, 2, grippy_destination).
set_aside(9, 2, heavy_destination).
set_aside(9, 2, heavy_source).
set_aside(9, 2, light_liquid).
set_aside(9, 2, moderate_retreat).
set_aside(9, 2, pour_level).
set_aside(9, 2, pour_mid_height).
set_aside(9, 2, pour_near_rim).
set_aside(9, 2, pour_tilted_back).
set_aside(9, 2, start_tilted_back).
set_aside(9, 2, sticky_liquid).
set_aside(11, 0, approach_moving_away).
set_aside(11, 0, bouncy_source).
set_aside(11, 0, dull_destination).
set_aside(11, 0, end_far_away).
set_aside(11, 0, end_low).
set_aside(11, 0, end_rolled).
set_aside(11, 0, fast_approach).
set_aside(11, 0, light_liquid).
set_aside(11, 0, light_source).
set_aside(11, 0, little_liquid).
set_aside(11, 0, medium_destination).
set_aside(11, 0, moderate_retreat).
set_aside(11, 0, pour_centred).
set_aside(11, 0, pour_half_tilted).
set_aside(11, 0, pour_in_line).
set_aside(11, 0, pour_rolled).
set_aside(11, 0, pour_very_high).
set_aside(11, 0, slippery_source).
set_aside(11, 0, start_below_rim).
set_aside(11, 0, start_tilted_back).
set_aside(12, 0, approach_moving_away).
set_aside(12, 0, approach_raising).
set_aside(12, 0, bouncy_source).
set_aside(12, 0, dull_destination).
set_aside(12, 0, dull_liquid).
set_aside(12, 0, end_centred).
set_aside(12, 0, end_level).
set_aside(12, 0, end_upside_down).
set_aside(12, 0, end_very_high).
set_aside(12, 0, fast_approach).
set_aside(12, 0, grippy_destination).
set_aside(12, 0, heavy_source).
set_aside(12, 0, light_destination).
set_aside(12, 0, light_liquid).
set_aside(12, 0, moderate_retreat).
set_aside(12, 0, pour_level).
set_aside(12, 0, pour_low).
set_aside(12, 0, pour_near_rim).
set_aside(12, 0, pour_tilted_back).
set_aside(12, 0, start_tilted_back).
set_aside(12, 0, sticky_liquid).
set_aside(12, 1, approach_moving_away).
set_aside(12, 1, approach_raising).
set_aside(12, 1, bouncy_source).
set_aside(12, 1, dull_destination).
set_aside(12, 1, dull_liquid).
set_aside(12, 1, end_centred).
set_aside(12, 1, end_level).
set_aside(12, 1, end_steeply_tilted).
set_aside(12, 1, end_very_high).
set_aside(12, 1, fast_approach).
set_aside(12, 1, grippy_destination).
set_aside(12, 1, heavy_destination).
set_aside(12, 1, heavy_source).
set_aside(12, 1, light_liquid).
set_aside(12, 1, moderate_retreat).
set_aside(12, 1, pour_level).
set_aside(12, 1, pour_low).
set_aside(12, 1, pour_near_rim).
set_aside(12, 1, pour_tilted_back).
set_aside(12, 1, start_tilted_back).
set_aside(12, 1, sticky_liquid).
set_aside(13, 1, approach_moving_away).
set_aside(13, 1, approach_raising).
set_aside(13, 1, bouncy_source).
set_aside(13, 1, dull_destination).
set_aside(13, 1, dull_liquid).
set_aside(13, 1, end_centred).
set_aside(13, 1, end_level).
set_aside(13, 1, end_steeply_tilted).
set_aside(13, 1, end_very_high).
set_aside(13, 1, fast_approach).
set_aside(13, 1, grippy_destination).
set_aside(13, 1, heavy_source).
set_aside(13, 1, light_destination).
set_aside(13, 1, light_liquid).
set_aside(13, 1, moderate_retreat).
set_aside(13, 1, pour_level).
set_aside(13, 1, pour_low).
set_aside(13, 1, pour_near_rim).
set_aside(13, 1, pour_tilted_back).
set_aside(13, 1, start_tilted_back).
set_aside(13, 1, sticky_liquid).
set_aside(13, 2, approach_moving_away).
set_aside(13, 2, approach_raising).
set_aside(13, 2, bouncy_source).
set_aside(13, 2, dull_destination).
set_aside(13, 2, dull_liquid).
set_aside(13, 2, end_centred).
set_aside(13, 2, end_rolled).
set_aside(13, 2, end_steeply_tilted).
set_aside(13, 2, end_very_high).
set_aside(13, 2, fast_approach).
set_aside(13, 2, grippy_destination).
set_aside(13, 2, heavy_destination).
set_aside(13, 2, heavy_source).
set_aside(13, 2, light_liquid).
set_aside(13, 2, moderate_retreat).
set_aside(13, 2, pour_centred).
set_aside(13, 2, pour_low).
set_aside(13, 2, pour_tilted_back).
set_aside(13, 2, start_tilted_back).
set_aside(13, 2, sticky_liquid).
set_aside(14, 1, approach_moving_away).
set_aside(14, 1, bouncy_liquid).
set_aside(14, 1, dull_destination).
set_aside(14, 1, dull_source).
set_aside(14, 1, end_steeply_tilted).
set_aside(14, 1, end_to_side).
set_aside(14, 1, fast_retreat).
set_aside(14, 1, grippy_source).
set_aside(14, 1, heavy_liquid).
set_aside(14, 1, light_destination).
set_aside(14, 1, little_liquid).
set_aside(14, 1, pour_in_line).
set_aside(14, 1, pour_mid_height).
set_aside(14, 1, pour_tilted_back).
set_aside(14, 1, pour_to_side).
set_aside(14, 1, retreat_lowering).
set_aside(14, 1, runny_liquid).
set_aside(14, 1, slippery_destination).
set_aside(14, 1, start_below_rim).
set_aside(14, 1, start_slightly_tilted).
set_aside(14, 2, approach_moving_away).
set_aside(14, 2, bouncy_liquid).
set_aside(14, 2, dull_destination).
set_aside(14, 2, end_steeply_tilted).
set_aside(14, 2, end_to_side).
set_aside(14, 2, fast_retreat).
set_aside(14, 2, grippy_source).
set_aside(14, 2, heavy_liquid).
set_aside(14, 2, light_destination).
set_aside(14, 2, little_liquid).
set_aside(14, 2, pour_high).
set_aside(14, 2, pour_in_line).
set_aside(14, 2, pour_tilted_back).
set_aside(14, 2, pour_to_side).
set_aside(14, 2, retreat_lowering).
set_aside(14, 2, runny_liquid).
set_aside(14, 2, slippery_destination).
set_aside(14, 2, start_below_rim).
set_aside(14, 2, start_slightly_tilted).
set_aside(15, 1, approach_moving_away).
set_aside(15, 1, bouncy_liquid).
set_aside(15, 1, dull_destination).
set_aside(15, 1, end_steeply_tilted).
set_aside(15, 1, end_to_side).
set_aside(15, 1, fast_retreat).
set_aside(15, 1, grippy_source).
set_aside(15, 1, heavy_liquid).
set_aside(15, 1, light_destination).
set_aside(15, 1, little_liquid).
set_aside(15, 1, pour_centred).
set_aside(15, 1, pour_in_line).
set_aside(15, 1, pour_mid_height).
set_aside(15, 1, pour_tilted_back).
set_aside(15, 1, retreat_lowering).
set_aside(15, 1, runny_liquid).
set_aside(15, 1, slippery_destination).
set_aside(15, 1, start_below_rim).
set_aside(15, 1, start_slightly_tilted).
set_aside(15, 2, approach_moving_away).
set_aside(15, 2, bouncy_liquid).
set_aside(15, 2, dull_destination).
set_aside(15, 2, end_near_rim).
set_aside(15, 2, end_steeply_tilted).
set_aside(15, 2, fast_retreat).
set_aside(15, 2, grippy_source).
set_aside(15, 2, heavy_liquid).
set_aside(15, 2, light_destination).
set_aside(15, 2, little_liquid).
set_aside(15, 2, pour_in_line).
set_aside(15, 2, pour_mid_height).
set_aside(15, 2, pour_tilted_back).
set_aside(15, 2, pour_to_side).
set_aside(15, 2, retreat_lowering).
set_aside(15, 2, runny_liquid).
set_aside(15, 2, slippery_destination).
set_aside(15, 2, start_below_rim).
set_aside(15, 2, start_slightly_tilted).
set_aside(17, 1, approach_moving_away).
set_aside(17, 1, bouncy_liquid).
set_aside(17, 1, dull_destination).
set_aside(17, 1, end_rolled).
set_aside(17, 1, end_steeply_tilted).
set_aside(17, 1, end_to_side).
set_aside(17, 1, fast_retreat).
set_aside(17, 1, grippy_source).
set_aside(17, 1, heavy_liquid).
set_aside(17, 1, light_destination).
set_aside(17, 1, little_liquid).
set_aside(17, 1, pour_centred).
set_aside(17, 1, pour_in_line).
set_aside(17, 1, pour_mid_height).
set_aside(17, 1, pour_tilted_back).
set_aside(17, 1, retreat_raising).
set_aside(17, 1, runny_liquid).
set_aside(17, 1, slippery_destination).
set_aside(17, 1, start_below_rim).
set_aside(17, 1, start_slightly_tilted).
set_aside(17, 2, approach_moving_away).
set_aside(17, 2, bouncy_liquid).
set_aside(17, 2, bouncy_source).
set_aside(17, 2, dull_destination).
set_aside(17, 2, end_rolled).
set_aside(17, 2, end_steeply_tilted).
set_aside(17, 2, end_to_side).
set_aside(17, 2, fast_retreat).
set_aside(17, 2, grippy_source).
set_aside(17, 2, heavy_liquid).
set_aside(17, 2, light_destination).
set_aside(17, 2, little_liquid).
set_aside(17, 2, pour_centred).
set_aside(17, 2, pour_in_line).
set_aside(17, 2, pour_mid_height).
set_aside(17, 2, pour_tilted_back).
set_aside(17, 2, retreat_lowering).
set_aside(17, 2, runny_liquid).
set_aside(17, 2, slippery_destination).
set_aside(17, 2, start_below_rim).
set_aside(17, 2, start_slightly_tilted).
set_aside(18, 0, approach_moving_away).
set_aside(18, 0, bouncy_liquid).
set_aside(18, 0, dull_destination).
set_aside(18, 0, end_rolled).
set_aside(18, 0, end_steeply_tilted).
set_aside(18, 0, end_to_side).
set_aside(18, 0, grippy_source).
set_aside(18, 0, heavy_liquid).
set_aside(18, 0, light_destination).
set_aside(18, 0, little_liquid).
set_aside(18, 0, pour_centred).
set_aside(18, 0, pour_in_line).
set_aside(18, 0, pour_mid_height).
set_aside(18, 0, pour_rolled).
set_aside(18, 0, pour_tilted_back).
set_aside(18, 0, retreat_lowering).
set_aside(18, 0, runny_liquid).
set_aside(18, 0, slippery_destination).
set_aside(18, 0, slow_retreat).
set_aside(18, 0, start_below_rim).
set_aside(18, 0, start_slightly_tilted).

rule(r1_destination_still_approach, defeasible, destination_still_approach).
body(r1_destination_still_approach, pour_mid_height).
body(r1_destination_still_approach, pour_near_rim).
body(r1_destination_still_approach, pour_steeply_tilted).
learned(r1_destination_still_approach).
provenance(r1_destination_still_approach, antecedent, a1).
provenance(r1_destination_still_approach, parent, none).
provenance(r1_destination_still_approach, simulations, 31).
provenance(r1_destination_still_approach, weight_mass_permille, 30882).
provenance(r1_destination_still_approach, confidence_permille, 1000).
provenance(r1_destination_still_approach, score_permille, 972).
provenance(r1_destination_still_approach, batches, 1).

rule(r1_destination_still_retreat, defeasible, destination_still_retreat).
body(r1_destination_still_retreat, pour_mid_height).
body(r1_destination_still_retreat, pour_near_rim).
body(r1_destination_still_retreat, pour_steeply_tilted).
learned(r1_destination_still_retreat).
provenance(r1_destination_still_retreat, antecedent, a1).
provenance(r1_destination_still_retreat, parent, none).
provenance(r1_destination_still_retreat, simulations, 31).
provenance(r1_destination_still_retreat, weight_mass_permille, 30882).
provenance(r1_destination_still_retreat, confidence_permille, 1000).
provenance(r1_destination_still_retreat, score_permille, 975).
provenance(r1_destination_still_retreat, batches, 1).

rule(r1_destination_still_settle, defeasible, destination_still_settle).
body(r1_destination_still_settle, pour_mid_height).
body(r1_destination_still_settle, pour_near_rim).
body(r1_destination_still_settle, pour_steeply_tilted).
learned(r1_destination_still_settle).
provenance(r1_destination_still_settle, antecedent, a1).
provenance(r1_destination_still_settle, parent, none).
provenance(r1_destination_still_settle, simulations, 31).
provenance(r1_destination_still_settle, weight_mass_permille, 30882).
provenance(r1_destination_still_settle, confidence_permille, 1000).
provenance(r1_destination_still_settle, score_permille, 995).
provenance(r1_destination_still_settle, batches, 1).

rule(r1_destination_upright, defeasible, destination_upright).
body(r1_destination_upright, pour_mid_height).
body(r1_destination_upright, pour_near_rim).
body(r1_destination_upright, pour_steeply_tilted).
learned(r1_destination_upright).
provenance(r1_destination_upright, antecedent, a1).
provenance(r1_destination_upright, parent, none).
provenance(r1_destination_upright, simulations, 31).
provenance(r1_destination_upright, weight_mass_permille, 30882).
provenance(r1_destination_upright, confidence_permille, 1000).
provenance(r1_destination_upright, score_permille, 997).
provenance(r1_destination_upright, batches, 1).

rule(r1_source_clear, defeasible, source_clear).
body(r1_source_clear, pour_mid_height).
body(r1_source_clear, pour_near_rim).
body(r1_source_clear, pour_steeply_tilted).
learned(r1_source_clear).
provenance(r1_source_clear, antecedent, a1).
provenance(r1_source_clear, parent, none).
provenance(r1_source_clear, simulations, 31).
provenance(r1_source_clear, weight_mass_permille, 30882).
provenance(r1_source_clear, confidence_permille, 1000).
provenance(r1_source_clear, score_permille, 987).
provenance(r1_source_clear, batches, 1).

rule(r1_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r1_liquid_leaves_source, pour_mid_height).
body(r1_liquid_leaves_source, pour_near_rim).
body(r1_liquid_leaves_source, pour_steeply_tilted).
learned(r1_liquid_leaves_source).
provenance(r1_liquid_leaves_source, antecedent, a1).
provenance(r1_liquid_leaves_source, parent, none).
provenance(r1_liquid_leaves_source, simulations, 31).
provenance(r1_liquid_leaves_source, weight_mass_permille, 30882).
provenance(r1_liquid_leaves_source, confidence_permille, 871).
provenance(r1_liquid_leaves_source, score_permille, 832).
provenance(r1_liquid_leaves_source, batches, 1).

rule(r1_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r1_liquid_enters_destination, pour_mid_height).
body(r1_liquid_enters_destination, pour_near_rim).
body(r1_liquid_enters_destination, pour_steeply_tilted).
learned(r1_liquid_enters_destination).
provenance(r1_liquid_enters_destination, antecedent, a1).
provenance(r1_liquid_enters_destination, parent, none).
provenance(r1_liquid_enters_destination, simulations, 31).
provenance(r1_liquid_enters_destination, weight_mass_permille, 30882).
provenance(r1_liquid_enters_destination, confidence_permille, 774).
provenance(r1_liquid_enters_destination, score_permille, 743).
provenance(r1_liquid_enters_destination, batches, 1).

rule(r1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r1_liquid_remains_in_destination, pour_mid_height).
body(r1_liquid_remains_in_destination, pour_near_rim).
body(r1_liquid_remains_in_destination, pour_steeply_tilted).
learned(r1_liquid_remains_in_destination).
provenance(r1_liquid_remains_in_destination, antecedent, a1).
provenance(r1_liquid_remains_in_destination, parent, none).
provenance(r1_liquid_remains_in_destination, simulations, 31).
provenance(r1_liquid_remains_in_destination, weight_mass_permille, 30882).
provenance(r1_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r1_liquid_remains_in_destination, score_permille, 988).
provenance(r1_liquid_remains_in_destination, batches, 1).

rule(r1_no_spill, defeasible, no_spill).
body(r1_no_spill, pour_mid_height).
body(r1_no_spill, pour_near_rim).
body(r1_no_spill, pour_steeply_tilted).
learned(r1_no_spill).
provenance(r1_no_spill, antecedent, a1).
provenance(r1_no_spill, parent, none).
provenance(r1_no_spill, simulations, 31).
provenance(r1_no_spill, weight_mass_permille, 30882).
provenance(r1_no_spill, confidence_permille, 935).
provenance(r1_no_spill, score_permille, 902).
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
provenance(r2_liquid_leaves_source, confidence_permille, 903).
provenance(r2_liquid_leaves_source, score_permille, 910).
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
provenance(r2_liquid_enters_destination, confidence_permille, 742).
provenance(r2_liquid_enters_destination, score_permille, 253).
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
provenance(r2_no_spill, confidence_permille, 645).
provenance(r2_no_spill, score_permille, 343).
provenance(r2_no_spill, batches, 1).

rule(r3_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r3_destination_still_approach, approach_moving_away).
body(r3_destination_still_approach, approach_raising).
body(r3_destination_still_approach, bouncy_source).
body(r3_destination_still_approach, dull_destination).
body(r3_destination_still_approach, dull_liquid).
body(r3_destination_still_approach, end_centred).
body(r3_destination_still_approach, end_rolled).
body(r3_destination_still_approach, end_tilted_back).
body(r3_destination_still_approach, end_very_high).
body(r3_destination_still_approach, fast_approach).
body(r3_destination_still_approach, grippy_destination).
body(r3_destination_still_approach, heavy_destination).
body(r3_destination_still_approach, heavy_source).
body(r3_destination_still_approach, light_liquid).
body(r3_destination_still_approach, moderate_retreat).
body(r3_destination_still_approach, pour_centred).
body(r3_destination_still_approach, pour_low).
body(r3_destination_still_approach, pour_tilted_back).
body(r3_destination_still_approach, start_tilted_back).
body(r3_destination_still_approach, sticky_liquid).
learned(r3_destination_still_approach).
provenance(r3_destination_still_approach, antecedent, a3).
provenance(r3_destination_still_approach, parent, none).
provenance(r3_destination_still_approach, simulations, 93).
provenance(r3_destination_still_approach, weight_mass_permille, 31507).
provenance(r3_destination_still_approach, confidence_permille, 642).
provenance(r3_destination_still_approach, score_permille, 353).
provenance(r3_destination_still_approach, batches, 1).

rule(r3_destination_still_retreat, defeasible, destination_still_retreat).
body(r3_destination_still_retreat, approach_moving_away).
body(r3_destination_still_retreat, approach_raising).
body(r3_destination_still_retreat, bouncy_source).
body(r3_destination_still_retreat, dull_destination).
body(r3_destination_still_retreat, dull_liquid).
body(r3_destination_still_retreat, end_centred).
body(r3_destination_still_retreat, end_rolled).
body(r3_destination_still_retreat, end_tilted_back).
body(r3_destination_still_retreat, end_very_high).
body(r3_destination_still_retreat, fast_approach).
body(r3_destination_still_retreat, grippy_destination).
body(r3_destination_still_retreat, heavy_destination).
body(r3_destination_still_retreat, heavy_source).
body(r3_destination_still_retreat, light_liquid).
body(r3_destination_still_retreat, moderate_retreat).
body(r3_destination_still_retreat, pour_centred).
body(r3_destination_still_retreat, pour_low).
body(r3_destination_still_retreat, pour_tilted_back).
body(r3_destination_still_retreat, start_tilted_back).
body(r3_destination_still_retreat, sticky_liquid).
learned(r3_destination_still_retreat).
provenance(r3_destination_still_retreat, antecedent, a3).
provenance(r3_destination_still_retreat, parent, none).
provenance(r3_destination_still_retreat, simulations, 93).
provenance(r3_destination_still_retreat, weight_mass_permille, 31507).
provenance(r3_destination_still_retreat, confidence_permille, 545).
provenance(r3_destination_still_retreat, score_permille, 533).
provenance(r3_destination_still_retreat, batches, 1).

rule(r3_destination_still_settle, defeasible, destination_still_settle).
body(r3_destination_still_settle, approach_moving_away).
body(r3_destination_still_settle, approach_raising).
body(r3_destination_still_settle, bouncy_source).
body(r3_destination_still_settle, dull_destination).
body(r3_destination_still_settle, dull_liquid).
body(r3_destination_still_settle, end_centred).
body(r3_destination_still_settle, end_rolled).
body(r3_destination_still_settle, end_tilted_back).
body(r3_destination_still_settle, end_very_high).
body(r3_destination_still_settle, fast_approach).
body(r3_destination_still_settle, grippy_destination).
body(r3_destination_still_settle, heavy_destination).
body(r3_destination_still_settle, heavy_source).
body(r3_destination_still_settle, light_liquid).
body(r3_destination_still_settle, moderate_retreat).
body(r3_destination_still_settle, pour_centred).
body(r3_destination_still_settle, pour_low).
body(r3_destination_still_settle, pour_tilted_back).
body(r3_destination_still_settle, start_tilted_back).
body(r3_destination_still_settle, sticky_liquid).
learned(r3_destination_still_settle).
provenance(r3_destination_still_settle, antecedent, a3).
provenance(r3_destination_still_settle, parent, none).
provenance(r3_destination_still_settle, simulations, 93).
provenance(r3_destination_still_settle, weight_mass_permille, 31507).
provenance(r3_destination_still_settle, confidence_permille, 866).
provenance(r3_destination_still_settle, score_permille, 851).
provenance(r3_destination_still_settle, batches, 1).

rule(r3_destination_upright, defeasible, destination_upright).
body(r3_destination_upright, approach_moving_away).
body(r3_destination_upright, approach_raising).
body(r3_destination_upright, bouncy_source).
body(r3_destination_upright, dull_destination).
body(r3_destination_upright, dull_liquid).
body(r3_destination_upright, end_centred).
body(r3_destination_upright, end_rolled).
body(r3_destination_upright, end_tilted_back).
body(r3_destination_upright, end_very_high).
body(r3_destination_upright, fast_approach).
body(r3_destination_upright, grippy_destination).
body(r3_destination_upright, heavy_destination).
body(r3_destination_upright, heavy_source).
body(r3_destination_upright, light_liquid).
body(r3_destination_upright, moderate_retreat).
body(r3_destination_upright, pour_centred).
body(r3_destination_upright, pour_low).
body(r3_destination_upright, pour_tilted_back).
body(r3_destination_upright, start_tilted_back).
body(r3_destination_upright, sticky_liquid).
learned(r3_destination_upright).
provenance(r3_destination_upright, antecedent, a3).
provenance(r3_destination_upright, parent, none).
provenance(r3_destination_upright, simulations, 93).
provenance(r3_destination_upright, weight_mass_permille, 31507).
provenance(r3_destination_upright, confidence_permille, 893).
provenance(r3_destination_upright, score_permille, 899).
provenance(r3_destination_upright, batches, 1).

rule(r3_source_clear, defeasible, neg(source_clear)).
body(r3_source_clear, approach_moving_away).
body(r3_source_clear, approach_raising).
body(r3_source_clear, bouncy_source).
body(r3_source_clear, dull_destination).
body(r3_source_clear, dull_liquid).
body(r3_source_clear, end_centred).
body(r3_source_clear, end_rolled).
body(r3_source_clear, end_tilted_back).
body(r3_source_clear, end_very_high).
body(r3_source_clear, fast_approach).
body(r3_source_clear, grippy_destination).
body(r3_source_clear, heavy_destination).
body(r3_source_clear, heavy_source).
body(r3_source_clear, light_liquid).
body(r3_source_clear, moderate_retreat).
body(r3_source_clear, pour_centred).
body(r3_source_clear, pour_low).
body(r3_source_clear, pour_tilted_back).
body(r3_source_clear, start_tilted_back).
body(r3_source_clear, sticky_liquid).
learned(r3_source_clear).
provenance(r3_source_clear, antecedent, a3).
provenance(r3_source_clear, parent, none).
provenance(r3_source_clear, simulations, 93).
provenance(r3_source_clear, weight_mass_permille, 31507).
provenance(r3_source_clear, confidence_permille, 761).
provenance(r3_source_clear, score_permille, 213).
provenance(r3_source_clear, batches, 1).

rule(r3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r3_liquid_leaves_source, approach_moving_away).
body(r3_liquid_leaves_source, approach_raising).
body(r3_liquid_leaves_source, bouncy_source).
body(r3_liquid_leaves_source, dull_destination).
body(r3_liquid_leaves_source, dull_liquid).
body(r3_liquid_leaves_source, end_centred).
body(r3_liquid_leaves_source, end_rolled).
body(r3_liquid_leaves_source, end_tilted_back).
body(r3_liquid_leaves_source, end_very_high).
body(r3_liquid_leaves_source, fast_approach).
body(r3_liquid_leaves_source, grippy_destination).
body(r3_liquid_leaves_source, heavy_destination).
body(r3_liquid_leaves_source, heavy_source).
body(r3_liquid_leaves_source, light_liquid).
body(r3_liquid_leaves_source, moderate_retreat).
body(r3_liquid_leaves_source, pour_centred).
body(r3_liquid_leaves_source, pour_low).
body(r3_liquid_leaves_source, pour_tilted_back).
body(r3_liquid_leaves_source, start_tilted_back).
body(r3_liquid_leaves_source, sticky_liquid).
learned(r3_liquid_leaves_source).
provenance(r3_liquid_leaves_source, antecedent, a3).
provenance(r3_liquid_leaves_source, parent, none).
provenance(r3_liquid_leaves_source, simulations, 93).
provenance(r3_liquid_leaves_source, weight_mass_permille, 31507).
provenance(r3_liquid_leaves_source, confidence_permille, 962).
provenance(r3_liquid_leaves_source, score_permille, 43).
provenance(r3_liquid_leaves_source, batches, 1).

rule(r3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r3_liquid_enters_destination, approach_moving_away).
body(r3_liquid_enters_destination, approach_raising).
body(r3_liquid_enters_destination, bouncy_source).
body(r3_liquid_enters_destination, dull_destination).
body(r3_liquid_enters_destination, dull_liquid).
body(r3_liquid_enters_destination, end_centred).
body(r3_liquid_enters_destination, end_rolled).
body(r3_liquid_enters_destination, end_tilted_back).
body(r3_liquid_enters_destination, end_very_high).
body(r3_liquid_enters_destination, fast_approach).
body(r3_liquid_enters_destination, grippy_destination).
body(r3_liquid_enters_destination, heavy_destination).
body(r3_liquid_enters_destination, heavy_source).
body(r3_liquid_enters_destination, light_liquid).
body(r3_liquid_enters_destination, moderate_retreat).
body(r3_liquid_enters_destination, pour_centred).
body(r3_liquid_enters_destination, pour_low).
body(r3_liquid_enters_destination, pour_tilted_back).
body(r3_liquid_enters_destination, start_tilted_back).
body(r3_liquid_enters_destination, sticky_liquid).
learned(r3_liquid_enters_destination).
provenance(r3_liquid_enters_destination, antecedent, a3).
provenance(r3_liquid_enters_destination, parent, none).
provenance(r3_liquid_enters_destination, simulations, 93).
provenance(r3_liquid_enters_destination, weight_mass_permille, 31507).
provenance(r3_liquid_enters_destination, confidence_permille, 796).
provenance(r3_liquid_enters_destination, score_permille, 226).
provenance(r3_liquid_enters_destination, batches, 1).

rule(r3_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r3_liquid_remains_in_destination, approach_moving_away).
body(r3_liquid_remains_in_destination, approach_raising).
body(r3_liquid_remains_in_destination, bouncy_source).
body(r3_liquid_remains_in_destination, dull_destination).
body(r3_liquid_remains_in_destination, dull_liquid).
body(r3_liquid_remains_in_destination, end_centred).
body(r3_liquid_remains_in_destination, end_rolled).
body(r3_liquid_remains_in_destination, end_tilted_back).
body(r3_liquid_remains_in_destination, end_very_high).
body(r3_liquid_remains_in_destination, fast_approach).
body(r3_liquid_remains_in_destination, grippy_destination).
body(r3_liquid_remains_in_destination, heavy_destination).
body(r3_liquid_remains_in_destination, heavy_source).
body(r3_liquid_remains_in_destination, light_liquid).
body(r3_liquid_remains_in_destination, moderate_retreat).
body(r3_liquid_remains_in_destination, pour_centred).
body(r3_liquid_remains_in_destination, pour_low).
body(r3_liquid_remains_in_destination, pour_tilted_back).
body(r3_liquid_remains_in_destination, start_tilted_back).
body(r3_liquid_remains_in_destination, sticky_liquid).
learned(r3_liquid_remains_in_destination).
provenance(r3_liquid_remains_in_destination, antecedent, a3).
provenance(r3_liquid_remains_in_destination, parent, none).
provenance(r3_liquid_remains_in_destination, simulations, 93).
provenance(r3_liquid_remains_in_destination, weight_mass_permille, 31507).
provenance(r3_liquid_remains_in_destination, confidence_permille, 631).
provenance(r3_liquid_remains_in_destination, score_permille, 622).
provenance(r3_liquid_remains_in_destination, batches, 1).

rule(r3_no_spill, defeasible, no_spill).
body(r3_no_spill, approach_moving_away).
body(r3_no_spill, approach_raising).
body(r3_no_spill, bouncy_source).
body(r3_no_spill, dull_destination).
body(r3_no_spill, dull_liquid).
body(r3_no_spill, end_centred).
body(r3_no_spill, end_rolled).
body(r3_no_spill, end_tilted_back).
body(r3_no_spill, end_very_high).
body(r3_no_spill, fast_approach).
body(r3_no_spill, grippy_destination).
body(r3_no_spill, heavy_destination).
body(r3_no_spill, heavy_source).
body(r3_no_spill, light_liquid).
body(r3_no_spill, moderate_retreat).
body(r3_no_spill, pour_centred).
body(r3_no_spill, pour_low).
body(r3_no_spill, pour_tilted_back).
body(r3_no_spill, start_tilted_back).
body(r3_no_spill, sticky_liquid).
learned(r3_no_spill).
provenance(r3_no_spill, antecedent, a3).
provenance(r3_no_spill, parent, none).
provenance(r3_no_spill, simulations, 93).
provenance(r3_no_spill, weight_mass_permille, 31507).
provenance(r3_no_spill, confidence_permille, 1000).
provenance(r3_no_spill, score_permille, 987).
provenance(r3_no_spill, batches, 1).

rule(r4_destination_still_approach, defeasible, destination_still_approach).
body(r4_destination_still_approach, approach_raising).
body(r4_destination_still_approach, bouncy_liquid).
body(r4_destination_still_approach, dull_source).
body(r4_destination_still_approach, end_half_tilted).
body(r4_destination_still_approach, end_rolled).
body(r4_destination_still_approach, heavy_destination).
body(r4_destination_still_approach, light_liquid).
body(r4_destination_still_approach, light_source).
body(r4_destination_still_approach, little_liquid).
body(r4_destination_still_approach, moderate_approach).
body(r4_destination_still_approach, pour_half_tilted).
body(r4_destination_still_approach, pour_in_line).
body(r4_destination_still_approach, pour_low).
body(r4_destination_still_approach, pour_to_side).
body(r4_destination_still_approach, retreat_moving_closer).
body(r4_destination_still_approach, runny_liquid).
body(r4_destination_still_approach, slippery_destination).
body(r4_destination_still_approach, slippery_source).
body(r4_destination_still_approach, start_slightly_tilted).
learned(r4_destination_still_approach).
provenance(r4_destination_still_approach, antecedent, a4).
provenance(r4_destination_still_approach, parent, none).
provenance(r4_destination_still_approach, simulations, 31).
provenance(r4_destination_still_approach, weight_mass_permille, 31000).
provenance(r4_destination_still_approach, confidence_permille, 839).
provenance(r4_destination_still_approach, score_permille, 845).
provenance(r4_destination_still_approach, batches, 1).

rule(r4_destination_still_retreat, defeasible, destination_still_retreat).
body(r4_destination_still_retreat, approach_raising).
body(r4_destination_still_retreat, bouncy_liquid).
body(r4_destination_still_retreat, dull_source).
body(r4_destination_still_retreat, end_half_tilted).
body(r4_destination_still_retreat, end_rolled).
body(r4_destination_still_retreat, heavy_destination).
body(r4_destination_still_retreat, light_liquid).
body(r4_destination_still_retreat, light_source).
body(r4_destination_still_retreat, little_liquid).
body(r4_destination_still_retreat, moderate_approach).
body(r4_destination_still_retreat, pour_half_tilted).
body(r4_destination_still_retreat, pour_in_line).
body(r4_destination_still_retreat, pour_low).
body(r4_destination_still_retreat, pour_to_side).
body(r4_destination_still_retreat, retreat_moving_closer).
body(r4_destination_still_retreat, runny_liquid).
body(r4_destination_still_retreat, slippery_destination).
body(r4_destination_still_retreat, slippery_source).
body(r4_destination_still_retreat, start_slightly_tilted).
learned(r4_destination_still_retreat).
provenance(r4_destination_still_retreat, antecedent, a4).
provenance(r4_destination_still_retreat, parent, none).
provenance(r4_destination_still_retreat, simulations, 31).
provenance(r4_destination_still_retreat, weight_mass_permille, 31000).
provenance(r4_destination_still_retreat, confidence_permille, 968).
provenance(r4_destination_still_retreat, score_permille, 964).
provenance(r4_destination_still_retreat, batches, 1).

rule(r4_destination_still_settle, defeasible, destination_still_settle).
body(r4_destination_still_settle, approach_raising).
body(r4_destination_still_settle, bouncy_liquid).
body(r4_destination_still_settle, dull_source).
body(r4_destination_still_settle, end_half_tilted).
body(r4_destination_still_settle, end_rolled).
body(r4_destination_still_settle, heavy_destination).
body(r4_destination_still_settle, light_liquid).
body(r4_destination_still_settle, light_source).
body(r4_destination_still_settle, little_liquid).
body(r4_destination_still_settle, moderate_approach).
body(r4_destination_still_settle, pour_half_tilted).
body(r4_destination_still_settle, pour_in_line).
body(r4_destination_still_settle, pour_low).
body(r4_destination_still_settle, pour_to_side).
body(r4_destination_still_settle, retreat_moving_closer).
body(r4_destination_still_settle, runny_liquid).
body(r4_destination_still_settle, slippery_destination).
body(r4_destination_still_settle, slippery_source).
body(r4_destination_still_settle, start_slightly_tilted).
learned(r4_destination_still_settle).
provenance(r4_destination_still_settle, antecedent, a4).
provenance(r4_destination_still_settle, parent, none).
provenance(r4_destination_still_settle, simulations, 31).
provenance(r4_destination_still_settle, weight_mass_permille, 31000).
provenance(r4_destination_still_settle, confidence_permille, 1000).
provenance(r4_destination_still_settle, score_permille, 1000).
provenance(r4_destination_still_settle, batches, 1).

rule(r4_destination_upright, defeasible, destination_upright).
body(r4_destination_upright, approach_raising).
body(r4_destination_upright, bouncy_liquid).
body(r4_destination_upright, dull_source).
body(r4_destination_upright, end_half_tilted).
body(r4_destination_upright, end_rolled).
body(r4_destination_upright, heavy_destination).
body(r4_destination_upright, light_liquid).
body(r4_destination_upright, light_source).
body(r4_destination_upright, little_liquid).
body(r4_destination_upright, moderate_approach).
body(r4_destination_upright, pour_half_tilted).
body(r4_destination_upright, pour_in_line).
body(r4_destination_upright, pour_low).
body(r4_destination_upright, pour_to_side).
body(r4_destination_upright, retreat_moving_closer).
body(r4_destination_upright, runny_liquid).
body(r4_destination_upright, slippery_destination).
body(r4_destination_upright, slippery_source).
body(r4_destination_upright, start_slightly_tilted).
learned(r4_destination_upright).
provenance(r4_destination_upright, antecedent, a4).
provenance(r4_destination_upright, parent, none).
provenance(r4_destination_upright, simulations, 31).
provenance(r4_destination_upright, weight_mass_permille, 31000).
provenance(r4_destination_upright, confidence_permille, 1000).
provenance(r4_destination_upright, score_permille, 1000).
provenance(r4_destination_upright, batches, 1).

rule(r4_source_clear, defeasible, source_clear).
body(r4_source_clear, approach_raising).
body(r4_source_clear, bouncy_liquid).
body(r4_source_clear, dull_source).
body(r4_source_clear, end_half_tilted).
body(r4_source_clear, end_rolled).
body(r4_source_clear, heavy_destination).
body(r4_source_clear, light_liquid).
body(r4_source_clear, light_source).
body(r4_source_clear, little_liquid).
body(r4_source_clear, moderate_approach).
body(r4_source_clear, pour_half_tilted).
body(r4_source_clear, pour_in_line).
body(r4_source_clear, pour_low).
body(r4_source_clear, pour_to_side).
body(r4_source_clear, retreat_moving_closer).
body(r4_source_clear, runny_liquid).
body(r4_source_clear, slippery_destination).
body(r4_source_clear, slippery_source).
body(r4_source_clear, start_slightly_tilted).
learned(r4_source_clear).
provenance(r4_source_clear, antecedent, a4).
provenance(r4_source_clear, parent, none).
provenance(r4_source_clear, simulations, 31).
provenance(r4_source_clear, weight_mass_permille, 31000).
provenance(r4_source_clear, confidence_permille, 710).
provenance(r4_source_clear, score_permille, 685).
provenance(r4_source_clear, batches, 1).

rule(r4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r4_liquid_leaves_source, approach_raising).
body(r4_liquid_leaves_source, bouncy_liquid).
body(r4_liquid_leaves_source, dull_source).
body(r4_liquid_leaves_source, end_half_tilted).
body(r4_liquid_leaves_source, end_rolled).
body(r4_liquid_leaves_source, heavy_destination).
body(r4_liquid_leaves_source, light_liquid).
body(r4_liquid_leaves_source, light_source).
body(r4_liquid_leaves_source, little_liquid).
body(r4_liquid_leaves_source, moderate_approach).
body(r4_liquid_leaves_source, pour_half_tilted).
body(r4_liquid_leaves_source, pour_in_line).
body(r4_liquid_leaves_source, pour_low).
body(r4_liquid_leaves_source, pour_to_side).
body(r4_liquid_leaves_source, retreat_moving_closer).
body(r4_liquid_leaves_source, runny_liquid).
body(r4_liquid_leaves_source, slippery_destination).
body(r4_liquid_leaves_source, slippery_source).
body(r4_liquid_leaves_source, start_slightly_tilted).
learned(r4_liquid_leaves_source).
provenance(r4_liquid_leaves_source, antecedent, a4).
provenance(r4_liquid_leaves_source, parent, none).
provenance(r4_liquid_leaves_source, simulations, 31).
provenance(r4_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r4_liquid_leaves_source, confidence_permille, 1000).
provenance(r4_liquid_leaves_source, score_permille, 9).
provenance(r4_liquid_leaves_source, batches, 1).

rule(r4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r4_liquid_enters_destination, approach_raising).
body(r4_liquid_enters_destination, bouncy_liquid).
body(r4_liquid_enters_destination, dull_source).
body(r4_liquid_enters_destination, end_half_tilted).
body(r4_liquid_enters_destination, end_rolled).
body(r4_liquid_enters_destination, heavy_destination).
body(r4_liquid_enters_destination, light_liquid).
body(r4_liquid_enters_destination, light_source).
body(r4_liquid_enters_destination, little_liquid).
body(r4_liquid_enters_destination, moderate_approach).
body(r4_liquid_enters_destination, pour_half_tilted).
body(r4_liquid_enters_destination, pour_in_line).
body(r4_liquid_enters_destination, pour_low).
body(r4_liquid_enters_destination, pour_to_side).
body(r4_liquid_enters_destination, retreat_moving_closer).
body(r4_liquid_enters_destination, runny_liquid).
body(r4_liquid_enters_destination, slippery_destination).
body(r4_liquid_enters_destination, slippery_source).
body(r4_liquid_enters_destination, start_slightly_tilted).
learned(r4_liquid_enters_destination).
provenance(r4_liquid_enters_destination, antecedent, a4).
provenance(r4_liquid_enters_destination, parent, none).
provenance(r4_liquid_enters_destination, simulations, 31).
provenance(r4_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r4_liquid_enters_destination, confidence_permille, 1000).
provenance(r4_liquid_enters_destination, score_permille, 9).
provenance(r4_liquid_enters_destination, batches, 1).

rule(r4_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r4_liquid_remains_in_destination, approach_raising).
body(r4_liquid_remains_in_destination, bouncy_liquid).
body(r4_liquid_remains_in_destination, dull_source).
body(r4_liquid_remains_in_destination, end_half_tilted).
body(r4_liquid_remains_in_destination, end_rolled).
body(r4_liquid_remains_in_destination, heavy_destination).
body(r4_liquid_remains_in_destination, light_liquid).
body(r4_liquid_remains_in_destination, light_source).
body(r4_liquid_remains_in_destination, little_liquid).
body(r4_liquid_remains_in_destination, moderate_approach).
body(r4_liquid_remains_in_destination, pour_half_tilted).
body(r4_liquid_remains_in_destination, pour_in_line).
body(r4_liquid_remains_in_destination, pour_low).
body(r4_liquid_remains_in_destination, pour_to_side).
body(r4_liquid_remains_in_destination, retreat_moving_closer).
body(r4_liquid_remains_in_destination, runny_liquid).
body(r4_liquid_remains_in_destination, slippery_destination).
body(r4_liquid_remains_in_destination, slippery_source).
body(r4_liquid_remains_in_destination, start_slightly_tilted).
learned(r4_liquid_remains_in_destination).
provenance(r4_liquid_remains_in_destination, antecedent, a4).
provenance(r4_liquid_remains_in_destination, parent, none).
provenance(r4_liquid_remains_in_destination, simulations, 31).
provenance(r4_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r4_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r4_liquid_remains_in_destination, score_permille, 1000).
provenance(r4_liquid_remains_in_destination, batches, 1).

rule(r4_no_spill, defeasible, no_spill).
body(r4_no_spill, approach_raising).
body(r4_no_spill, bouncy_liquid).
body(r4_no_spill, dull_source).
body(r4_no_spill, end_half_tilted).
body(r4_no_spill, end_rolled).
body(r4_no_spill, heavy_destination).
body(r4_no_spill, light_liquid).
body(r4_no_spill, light_source).
body(r4_no_spill, little_liquid).
body(r4_no_spill, moderate_approach).
body(r4_no_spill, pour_half_tilted).
body(r4_no_spill, pour_in_line).
body(r4_no_spill, pour_low).
body(r4_no_spill, pour_to_side).
body(r4_no_spill, retreat_moving_closer).
body(r4_no_spill, runny_liquid).
body(r4_no_spill, slippery_destination).
body(r4_no_spill, slippery_source).
body(r4_no_spill, start_slightly_tilted).
learned(r4_no_spill).
provenance(r4_no_spill, antecedent, a4).
provenance(r4_no_spill, parent, none).
provenance(r4_no_spill, simulations, 31).
provenance(r4_no_spill, weight_mass_permille, 31000).
provenance(r4_no_spill, confidence_permille, 1000).
provenance(r4_no_spill, score_permille, 1000).
provenance(r4_no_spill, batches, 1).

rule(r5_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r5_destination_still_approach, approach_moving_away).
body(r5_destination_still_approach, approach_raising).
body(r5_destination_still_approach, bouncy_source).
body(r5_destination_still_approach, dull_destination).
body(r5_destination_still_approach, dull_liquid).
body(r5_destination_still_approach, end_centred).
body(r5_destination_still_approach, end_rolled).
body(r5_destination_still_approach, end_tilted_back).
body(r5_destination_still_approach, end_very_high).
body(r5_destination_still_approach, fast_approach).
body(r5_destination_still_approach, grippy_destination).
body(r5_destination_still_approach, heavy_destination).
body(r5_destination_still_approach, heavy_source).
body(r5_destination_still_approach, light_liquid).
body(r5_destination_still_approach, moderate_retreat).
body(r5_destination_still_approach, pour_centred).
body(r5_destination_still_approach, pour_low).
body(r5_destination_still_approach, pour_tilted_back).
body(r5_destination_still_approach, start_tilted_back).
body(r5_destination_still_approach, sticky_liquid).
body(r5_destination_still_approach, very_much_liquid).
learned(r5_destination_still_approach).
provenance(r5_destination_still_approach, antecedent, a5).
provenance(r5_destination_still_approach, parent, a3).
provenance(r5_destination_still_approach, simulations, 46).
provenance(r5_destination_still_approach, weight_mass_permille, 29986).
provenance(r5_destination_still_approach, confidence_permille, 652).
provenance(r5_destination_still_approach, score_permille, 321).
provenance(r5_destination_still_approach, batches, 1).

rule(r5_destination_still_retreat, defeasible, destination_still_retreat).
body(r5_destination_still_retreat, approach_moving_away).
body(r5_destination_still_retreat, approach_raising).
body(r5_destination_still_retreat, bouncy_source).
body(r5_destination_still_retreat, dull_destination).
body(r5_destination_still_retreat, dull_liquid).
body(r5_destination_still_retreat, end_centred).
body(r5_destination_still_retreat, end_rolled).
body(r5_destination_still_retreat, end_tilted_back).
body(r5_destination_still_retreat, end_very_high).
body(r5_destination_still_retreat, fast_approach).
body(r5_destination_still_retreat, grippy_destination).
body(r5_destination_still_retreat, heavy_destination).
body(r5_destination_still_retreat, heavy_source).
body(r5_destination_still_retreat, light_liquid).
body(r5_destination_still_retreat, moderate_retreat).
body(r5_destination_still_retreat, pour_centred).
body(r5_destination_still_retreat, pour_low).
body(r5_destination_still_retreat, pour_tilted_back).
body(r5_destination_still_retreat, start_tilted_back).
body(r5_destination_still_retreat, sticky_liquid).
body(r5_destination_still_retreat, very_much_liquid).
learned(r5_destination_still_retreat).
provenance(r5_destination_still_retreat, antecedent, a5).
provenance(r5_destination_still_retreat, parent, a3).
provenance(r5_destination_still_retreat, simulations, 46).
provenance(r5_destination_still_retreat, weight_mass_permille, 29986).
provenance(r5_destination_still_retreat, confidence_permille, 522).
provenance(r5_destination_still_retreat, score_permille, 510).
provenance(r5_destination_still_retreat, batches, 1).

rule(r5_destination_still_settle, defeasible, destination_still_settle).
body(r5_destination_still_settle, approach_moving_away).
body(r5_destination_still_settle, approach_raising).
body(r5_destination_still_settle, bouncy_source).
body(r5_destination_still_settle, dull_destination).
body(r5_destination_still_settle, dull_liquid).
body(r5_destination_still_settle, end_centred).
body(r5_destination_still_settle, end_rolled).
body(r5_destination_still_settle, end_tilted_back).
body(r5_destination_still_settle, end_very_high).
body(r5_destination_still_settle, fast_approach).
body(r5_destination_still_settle, grippy_destination).
body(r5_destination_still_settle, heavy_destination).
body(r5_destination_still_settle, heavy_source).
body(r5_destination_still_settle, light_liquid).
body(r5_destination_still_settle, moderate_retreat).
body(r5_destination_still_settle, pour_centred).
body(r5_destination_still_settle, pour_low).
body(r5_destination_still_settle, pour_tilted_back).
body(r5_destination_still_settle, start_tilted_back).
body(r5_destination_still_settle, sticky_liquid).
body(r5_destination_still_settle, very_much_liquid).
learned(r5_destination_still_settle).
provenance(r5_destination_still_settle, antecedent, a5).
provenance(r5_destination_still_settle, parent, a3).
provenance(r5_destination_still_settle, simulations, 46).
provenance(r5_destination_still_settle, weight_mass_permille, 29986).
provenance(r5_destination_still_settle, confidence_permille, 848).
provenance(r5_destination_still_settle, score_permille, 841).
provenance(r5_destination_still_settle, batches, 1).

rule(r5_destination_upright, defeasible, destination_upright).
body(r5_destination_upright, approach_moving_away).
body(r5_destination_upright, approach_raising).
body(r5_destination_upright, bouncy_source).
body(r5_destination_upright, dull_destination).
body(r5_destination_upright, dull_liquid).
body(r5_destination_upright, end_centred).
body(r5_destination_upright, end_rolled).
body(r5_destination_upright, end_tilted_back).
body(r5_destination_upright, end_very_high).
body(r5_destination_upright, fast_approach).
body(r5_destination_upright, grippy_destination).
body(r5_destination_upright, heavy_destination).
body(r5_destination_upright, heavy_source).
body(r5_destination_upright, light_liquid).
body(r5_destination_upright, moderate_retreat).
body(r5_destination_upright, pour_centred).
body(r5_destination_upright, pour_low).
body(r5_destination_upright, pour_tilted_back).
body(r5_destination_upright, start_tilted_back).
body(r5_destination_upright, sticky_liquid).
body(r5_destination_upright, very_much_liquid).
learned(r5_destination_upright).
provenance(r5_destination_upright, antecedent, a5).
provenance(r5_destination_upright, parent, a3).
provenance(r5_destination_upright, simulations, 46).
provenance(r5_destination_upright, weight_mass_permille, 29986).
provenance(r5_destination_upright, confidence_permille, 891).
provenance(r5_destination_upright, score_permille, 891).
provenance(r5_destination_upright, batches, 1).

rule(r5_source_clear, defeasible, neg(source_clear)).
body(r5_source_clear, approach_moving_away).
body(r5_source_clear, approach_raising).
body(r5_source_clear, bouncy_source).
body(r5_source_clear, dull_destination).
body(r5_source_clear, dull_liquid).
body(r5_source_clear, end_centred).
body(r5_source_clear, end_rolled).
body(r5_source_clear, end_tilted_back).
body(r5_source_clear, end_very_high).
body(r5_source_clear, fast_approach).
body(r5_source_clear, grippy_destination).
body(r5_source_clear, heavy_destination).
body(r5_source_clear, heavy_source).
body(r5_source_clear, light_liquid).
body(r5_source_clear, moderate_retreat).
body(r5_source_clear, pour_centred).
body(r5_source_clear, pour_low).
body(r5_source_clear, pour_tilted_back).
body(r5_source_clear, start_tilted_back).
body(r5_source_clear, sticky_liquid).
body(r5_source_clear, very_much_liquid).
learned(r5_source_clear).
provenance(r5_source_clear, antecedent, a5).
provenance(r5_source_clear, parent, a3).
provenance(r5_source_clear, simulations, 46).
provenance(r5_source_clear, weight_mass_permille, 29986).
provenance(r5_source_clear, confidence_permille, 870).
provenance(r5_source_clear, score_permille, 133).
provenance(r5_source_clear, batches, 1).

rule(r5_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r5_liquid_leaves_source, approach_moving_away).
body(r5_liquid_leaves_source, approach_raising).
body(r5_liquid_leaves_source, bouncy_source).
body(r5_liquid_leaves_source, dull_destination).
body(r5_liquid_leaves_source, dull_liquid).
body(r5_liquid_leaves_source, end_centred).
body(r5_liquid_leaves_source, end_rolled).
body(r5_liquid_leaves_source, end_tilted_back).
body(r5_liquid_leaves_source, end_very_high).
body(r5_liquid_leaves_source, fast_approach).
body(r5_liquid_leaves_source, grippy_destination).
body(r5_liquid_leaves_source, heavy_destination).
body(r5_liquid_leaves_source, heavy_source).
body(r5_liquid_leaves_source, light_liquid).
body(r5_liquid_leaves_source, moderate_retreat).
body(r5_liquid_leaves_source, pour_centred).
body(r5_liquid_leaves_source, pour_low).
body(r5_liquid_leaves_source, pour_tilted_back).
body(r5_liquid_leaves_source, start_tilted_back).
body(r5_liquid_leaves_source, sticky_liquid).
body(r5_liquid_leaves_source, very_much_liquid).
learned(r5_liquid_leaves_source).
provenance(r5_liquid_leaves_source, antecedent, a5).
provenance(r5_liquid_leaves_source, parent, a3).
provenance(r5_liquid_leaves_source, simulations, 46).
provenance(r5_liquid_leaves_source, weight_mass_permille, 29986).
provenance(r5_liquid_leaves_source, confidence_permille, 913).
provenance(r5_liquid_leaves_source, score_permille, 78).
provenance(r5_liquid_leaves_source, batches, 1).

rule(r5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r5_liquid_enters_destination, approach_moving_away).
body(r5_liquid_enters_destination, approach_raising).
body(r5_liquid_enters_destination, bouncy_source).
body(r5_liquid_enters_destination, dull_destination).
body(r5_liquid_enters_destination, dull_liquid).
body(r5_liquid_enters_destination, end_centred).
body(r5_liquid_enters_destination, end_rolled).
body(r5_liquid_enters_destination, end_tilted_back).
body(r5_liquid_enters_destination, end_very_high).
body(r5_liquid_enters_destination, fast_approach).
body(r5_liquid_enters_destination, grippy_destination).
body(r5_liquid_enters_destination, heavy_destination).
body(r5_liquid_enters_destination, heavy_source).
body(r5_liquid_enters_destination, light_liquid).
body(r5_liquid_enters_destination, moderate_retreat).
body(r5_liquid_enters_destination, pour_centred).
body(r5_liquid_enters_destination, pour_low).
body(r5_liquid_enters_destination, pour_tilted_back).
body(r5_liquid_enters_destination, start_tilted_back).
body(r5_liquid_enters_destination, sticky_liquid).
body(r5_liquid_enters_destination, very_much_liquid).
learned(r5_liquid_enters_destination).
provenance(r5_liquid_enters_destination, antecedent, a5).
provenance(r5_liquid_enters_destination, parent, a3).
provenance(r5_liquid_enters_destination, simulations, 46).
provenance(r5_liquid_enters_destination, weight_mass_permille, 29986).
provenance(r5_liquid_enters_destination, confidence_permille, 696).
provenance(r5_liquid_enters_destination, score_permille, 310).
provenance(r5_liquid_enters_destination, batches, 1).

rule(r5_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r5_liquid_remains_in_destination, approach_moving_away).
body(r5_liquid_remains_in_destination, approach_raising).
body(r5_liquid_remains_in_destination, bouncy_source).
body(r5_liquid_remains_in_destination, dull_destination).
body(r5_liquid_remains_in_destination, dull_liquid).
body(r5_liquid_remains_in_destination, end_centred).
body(r5_liquid_remains_in_destination, end_rolled).
body(r5_liquid_remains_in_destination, end_tilted_back).
body(r5_liquid_remains_in_destination, end_very_high).
body(r5_liquid_remains_in_destination, fast_approach).
body(r5_liquid_remains_in_destination, grippy_destination).
body(r5_liquid_remains_in_destination, heavy_destination).
body(r5_liquid_remains_in_destination, heavy_source).
body(r5_liquid_remains_in_destination, light_liquid).
body(r5_liquid_remains_in_destination, moderate_retreat).
body(r5_liquid_remains_in_destination, pour_centred).
body(r5_liquid_remains_in_destination, pour_low).
body(r5_liquid_remains_in_destination, pour_tilted_back).
body(r5_liquid_remains_in_destination, start_tilted_back).
body(r5_liquid_remains_in_destination, sticky_liquid).
body(r5_liquid_remains_in_destination, very_much_liquid).
learned(r5_liquid_remains_in_destination).
provenance(r5_liquid_remains_in_destination, antecedent, a5).
provenance(r5_liquid_remains_in_destination, parent, a3).
provenance(r5_liquid_remains_in_destination, simulations, 46).
provenance(r5_liquid_remains_in_destination, weight_mass_permille, 29986).
provenance(r5_liquid_remains_in_destination, confidence_permille, 609).
provenance(r5_liquid_remains_in_destination, score_permille, 603).
provenance(r5_liquid_remains_in_destination, batches, 1).

rule(r5_no_spill, defeasible, no_spill).
body(r5_no_spill, approach_moving_away).
body(r5_no_spill, approach_raising).
body(r5_no_spill, bouncy_source).
body(r5_no_spill, dull_destination).
body(r5_no_spill, dull_liquid).
body(r5_no_spill, end_centred).
body(r5_no_spill, end_rolled).
body(r5_no_spill, end_tilted_back).
body(r5_no_spill, end_very_high).
body(r5_no_spill, fast_approach).
body(r5_no_spill, grippy_destination).
body(r5_no_spill, heavy_destination).
body(r5_no_spill, heavy_source).
body(r5_no_spill, light_liquid).
body(r5_no_spill, moderate_retreat).
body(r5_no_spill, pour_centred).
body(r5_no_spill, pour_low).
body(r5_no_spill, pour_tilted_back).
body(r5_no_spill, start_tilted_back).
body(r5_no_spill, sticky_liquid).
body(r5_no_spill, very_much_liquid).
learned(r5_no_spill).
provenance(r5_no_spill, antecedent, a5).
provenance(r5_no_spill, parent, a3).
provenance(r5_no_spill, simulations, 46).
provenance(r5_no_spill, weight_mass_permille, 29986).
provenance(r5_no_spill, confidence_permille, 1000).
provenance(r5_no_spill, score_permille, 990).
provenance(r5_no_spill, batches, 1).

rule(r6_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r6_destination_still_approach, approach_moving_away).
body(r6_destination_still_approach, approach_raising).
body(r6_destination_still_approach, bouncy_source).
body(r6_destination_still_approach, dull_destination).
body(r6_destination_still_approach, dull_liquid).
body(r6_destination_still_approach, end_centred).
body(r6_destination_still_approach, end_rolled).
body(r6_destination_still_approach, end_tilted_back).
body(r6_destination_still_approach, end_very_high).
body(r6_destination_still_approach, fast_approach).
body(r6_destination_still_approach, grippy_destination).
body(r6_destination_still_approach, heavy_destination).
body(r6_destination_still_approach, heavy_source).
body(r6_destination_still_approach, light_liquid).
body(r6_destination_still_approach, moderate_retreat).
body(r6_destination_still_approach, pour_centred).
body(r6_destination_still_approach, pour_level).
body(r6_destination_still_approach, pour_low).
body(r6_destination_still_approach, pour_tilted_back).
body(r6_destination_still_approach, start_tilted_back).
body(r6_destination_still_approach, sticky_liquid).
learned(r6_destination_still_approach).
provenance(r6_destination_still_approach, antecedent, a6).
provenance(r6_destination_still_approach, parent, a3).
provenance(r6_destination_still_approach, simulations, 93).
provenance(r6_destination_still_approach, weight_mass_permille, 31507).
provenance(r6_destination_still_approach, confidence_permille, 642).
provenance(r6_destination_still_approach, score_permille, 353).
provenance(r6_destination_still_approach, batches, 1).

rule(r6_destination_still_retreat, defeasible, destination_still_retreat).
body(r6_destination_still_retreat, approach_moving_away).
body(r6_destination_still_retreat, approach_raising).
body(r6_destination_still_retreat, bouncy_source).
body(r6_destination_still_retreat, dull_destination).
body(r6_destination_still_retreat, dull_liquid).
body(r6_destination_still_retreat, end_centred).
body(r6_destination_still_retreat, end_rolled).
body(r6_destination_still_retreat, end_tilted_back).
body(r6_destination_still_retreat, end_very_high).
body(r6_destination_still_retreat, fast_approach).
body(r6_destination_still_retreat, grippy_destination).
body(r6_destination_still_retreat, heavy_destination).
body(r6_destination_still_retreat, heavy_source).
body(r6_destination_still_retreat, light_liquid).
body(r6_destination_still_retreat, moderate_retreat).
body(r6_destination_still_retreat, pour_centred).
body(r6_destination_still_retreat, pour_level).
body(r6_destination_still_retreat, pour_low).
body(r6_destination_still_retreat, pour_tilted_back).
body(r6_destination_still_retreat, start_tilted_back).
body(r6_destination_still_retreat, sticky_liquid).
learned(r6_destination_still_retreat).
provenance(r6_destination_still_retreat, antecedent, a6).
provenance(r6_destination_still_retreat, parent, a3).
provenance(r6_destination_still_retreat, simulations, 93).
provenance(r6_destination_still_retreat, weight_mass_permille, 31507).
provenance(r6_destination_still_retreat, confidence_permille, 545).
provenance(r6_destination_still_retreat, score_permille, 533).
provenance(r6_destination_still_retreat, batches, 1).

rule(r6_destination_still_settle, defeasible, destination_still_settle).
body(r6_destination_still_settle, approach_moving_away).
body(r6_destination_still_settle, approach_raising).
body(r6_destination_still_settle, bouncy_source).
body(r6_destination_still_settle, dull_destination).
body(r6_destination_still_settle, dull_liquid).
body(r6_destination_still_settle, end_centred).
body(r6_destination_still_settle, end_rolled).
body(r6_destination_still_settle, end_tilted_back).
body(r6_destination_still_settle, end_very_high).
body(r6_destination_still_settle, fast_approach).
body(r6_destination_still_settle, grippy_destination).
body(r6_destination_still_settle, heavy_destination).
body(r6_destination_still_settle, heavy_source).
body(r6_destination_still_settle, light_liquid).
body(r6_destination_still_settle, moderate_retreat).
body(r6_destination_still_settle, pour_centred).
body(r6_destination_still_settle, pour_level).
body(r6_destination_still_settle, pour_low).
body(r6_destination_still_settle, pour_tilted_back).
body(r6_destination_still_settle, start_tilted_back).
body(r6_destination_still_settle, sticky_liquid).
learned(r6_destination_still_settle).
provenance(r6_destination_still_settle, antecedent, a6).
provenance(r6_destination_still_settle, parent, a3).
provenance(r6_destination_still_settle, simulations, 93).
provenance(r6_destination_still_settle, weight_mass_permille, 31507).
provenance(r6_destination_still_settle, confidence_permille, 866).
provenance(r6_destination_still_settle, score_permille, 851).
provenance(r6_destination_still_settle, batches, 1).

rule(r6_destination_upright, defeasible, destination_upright).
body(r6_destination_upright, approach_moving_away).
body(r6_destination_upright, approach_raising).
body(r6_destination_upright, bouncy_source).
body(r6_destination_upright, dull_destination).
body(r6_destination_upright, dull_liquid).
body(r6_destination_upright, end_centred).
body(r6_destination_upright, end_rolled).
body(r6_destination_upright, end_tilted_back).
body(r6_destination_upright, end_very_high).
body(r6_destination_upright, fast_approach).
body(r6_destination_upright, grippy_destination).
body(r6_destination_upright, heavy_destination).
body(r6_destination_upright, heavy_source).
body(r6_destination_upright, light_liquid).
body(r6_destination_upright, moderate_retreat).
body(r6_destination_upright, pour_centred).
body(r6_destination_upright, pour_level).
body(r6_destination_upright, pour_low).
body(r6_destination_upright, pour_tilted_back).
body(r6_destination_upright, start_tilted_back).
body(r6_destination_upright, sticky_liquid).
learned(r6_destination_upright).
provenance(r6_destination_upright, antecedent, a6).
provenance(r6_destination_upright, parent, a3).
provenance(r6_destination_upright, simulations, 93).
provenance(r6_destination_upright, weight_mass_permille, 31507).
provenance(r6_destination_upright, confidence_permille, 893).
provenance(r6_destination_upright, score_permille, 899).
provenance(r6_destination_upright, batches, 1).

rule(r6_source_clear, defeasible, neg(source_clear)).
body(r6_source_clear, approach_moving_away).
body(r6_source_clear, approach_raising).
body(r6_source_clear, bouncy_source).
body(r6_source_clear, dull_destination).
body(r6_source_clear, dull_liquid).
body(r6_source_clear, end_centred).
body(r6_source_clear, end_rolled).
body(r6_source_clear, end_tilted_back).
body(r6_source_clear, end_very_high).
body(r6_source_clear, fast_approach).
body(r6_source_clear, grippy_destination).
body(r6_source_clear, heavy_destination).
body(r6_source_clear, heavy_source).
body(r6_source_clear, light_liquid).
body(r6_source_clear, moderate_retreat).
body(r6_source_clear, pour_centred).
body(r6_source_clear, pour_level).
body(r6_source_clear, pour_low).
body(r6_source_clear, pour_tilted_back).
body(r6_source_clear, start_tilted_back).
body(r6_source_clear, sticky_liquid).
learned(r6_source_clear).
provenance(r6_source_clear, antecedent, a6).
provenance(r6_source_clear, parent, a3).
provenance(r6_source_clear, simulations, 93).
provenance(r6_source_clear, weight_mass_permille, 31507).
provenance(r6_source_clear, confidence_permille, 761).
provenance(r6_source_clear, score_permille, 213).
provenance(r6_source_clear, batches, 1).

rule(r6_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r6_liquid_leaves_source, approach_moving_away).
body(r6_liquid_leaves_source, approach_raising).
body(r6_liquid_leaves_source, bouncy_source).
body(r6_liquid_leaves_source, dull_destination).
body(r6_liquid_leaves_source, dull_liquid).
body(r6_liquid_leaves_source, end_centred).
body(r6_liquid_leaves_source, end_rolled).
body(r6_liquid_leaves_source, end_tilted_back).
body(r6_liquid_leaves_source, end_very_high).
body(r6_liquid_leaves_source, fast_approach).
body(r6_liquid_leaves_source, grippy_destination).
body(r6_liquid_leaves_source, heavy_destination).
body(r6_liquid_leaves_source, heavy_source).
body(r6_liquid_leaves_source, light_liquid).
body(r6_liquid_leaves_source, moderate_retreat).
body(r6_liquid_leaves_source, pour_centred).
body(r6_liquid_leaves_source, pour_level).
body(r6_liquid_leaves_source, pour_low).
body(r6_liquid_leaves_source, pour_tilted_back).
body(r6_liquid_leaves_source, start_tilted_back).
body(r6_liquid_leaves_source, sticky_liquid).
learned(r6_liquid_leaves_source).
provenance(r6_liquid_leaves_source, antecedent, a6).
provenance(r6_liquid_leaves_source, parent, a3).
provenance(r6_liquid_leaves_source, simulations, 93).
provenance(r6_liquid_leaves_source, weight_mass_permille, 31507).
provenance(r6_liquid_leaves_source, confidence_permille, 962).
provenance(r6_liquid_leaves_source, score_permille, 43).
provenance(r6_liquid_leaves_source, batches, 1).

rule(r6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r6_liquid_enters_destination, approach_moving_away).
body(r6_liquid_enters_destination, approach_raising).
body(r6_liquid_enters_destination, bouncy_source).
body(r6_liquid_enters_destination, dull_destination).
body(r6_liquid_enters_destination, dull_liquid).
body(r6_liquid_enters_destination, end_centred).
body(r6_liquid_enters_destination, end_rolled).
body(r6_liquid_enters_destination, end_tilted_back).
body(r6_liquid_enters_destination, end_very_high).
body(r6_liquid_enters_destination, fast_approach).
body(r6_liquid_enters_destination, grippy_destination).
body(r6_liquid_enters_destination, heavy_destination).
body(r6_liquid_enters_destination, heavy_source).
body(r6_liquid_enters_destination, light_liquid).
body(r6_liquid_enters_destination, moderate_retreat).
body(r6_liquid_enters_destination, pour_centred).
body(r6_liquid_enters_destination, pour_level).
body(r6_liquid_enters_destination, pour_low).
body(r6_liquid_enters_destination, pour_tilted_back).
body(r6_liquid_enters_destination, start_tilted_back).
body(r6_liquid_enters_destination, sticky_liquid).
learned(r6_liquid_enters_destination).
provenance(r6_liquid_enters_destination, antecedent, a6).
provenance(r6_liquid_enters_destination, parent, a3).
provenance(r6_liquid_enters_destination, simulations, 93).
provenance(r6_liquid_enters_destination, weight_mass_permille, 31507).
provenance(r6_liquid_enters_destination, confidence_permille, 796).
provenance(r6_liquid_enters_destination, score_permille, 226).
provenance(r6_liquid_enters_destination, batches, 1).

rule(r6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r6_liquid_remains_in_destination, approach_moving_away).
body(r6_liquid_remains_in_destination, approach_raising).
body(r6_liquid_remains_in_destination, bouncy_source).
body(r6_liquid_remains_in_destination, dull_destination).
body(r6_liquid_remains_in_destination, dull_liquid).
body(r6_liquid_remains_in_destination, end_centred).
body(r6_liquid_remains_in_destination, end_rolled).
body(r6_liquid_remains_in_destination, end_tilted_back).
body(r6_liquid_remains_in_destination, end_very_high).
body(r6_liquid_remains_in_destination, fast_approach).
body(r6_liquid_remains_in_destination, grippy_destination).
body(r6_liquid_remains_in_destination, heavy_destination).
body(r6_liquid_remains_in_destination, heavy_source).
body(r6_liquid_remains_in_destination, light_liquid).
body(r6_liquid_remains_in_destination, moderate_retreat).
body(r6_liquid_remains_in_destination, pour_centred).
body(r6_liquid_remains_in_destination, pour_level).
body(r6_liquid_remains_in_destination, pour_low).
body(r6_liquid_remains_in_destination, pour_tilted_back).
body(r6_liquid_remains_in_destination, start_tilted_back).
body(r6_liquid_remains_in_destination, sticky_liquid).
learned(r6_liquid_remains_in_destination).
provenance(r6_liquid_remains_in_destination, antecedent, a6).
provenance(r6_liquid_remains_in_destination, parent, a3).
provenance(r6_liquid_remains_in_destination, simulations, 93).
provenance(r6_liquid_remains_in_destination, weight_mass_permille, 31507).
provenance(r6_liquid_remains_in_destination, confidence_permille, 631).
provenance(r6_liquid_remains_in_destination, score_permille, 622).
provenance(r6_liquid_remains_in_destination, batches, 1).

rule(r6_no_spill, defeasible, no_spill).
body(r6_no_spill, approach_moving_away).
body(r6_no_spill, approach_raising).
body(r6_no_spill, bouncy_source).
body(r6_no_spill, dull_destination).
body(r6_no_spill, dull_liquid).
body(r6_no_spill, end_centred).
body(r6_no_spill, end_rolled).
body(r6_no_spill, end_tilted_back).
body(r6_no_spill, end_very_high).
body(r6_no_spill, fast_approach).
body(r6_no_spill, grippy_destination).
body(r6_no_spill, heavy_destination).
body(r6_no_spill, heavy_source).
body(r6_no_spill, light_liquid).
body(r6_no_spill, moderate_retreat).
body(r6_no_spill, pour_centred).
body(r6_no_spill, pour_level).
body(r6_no_spill, pour_low).
body(r6_no_spill, pour_tilted_back).
body(r6_no_spill, start_tilted_back).
body(r6_no_spill, sticky_liquid).
learned(r6_no_spill).
provenance(r6_no_spill, antecedent, a6).
provenance(r6_no_spill, parent, a3).
provenance(r6_no_spill, simulations, 93).
provenance(r6_no_spill, weight_mass_permille, 31507).
provenance(r6_no_spill, confidence_permille, 1000).
provenance(r6_no_spill, score_permille, 987).
provenance(r6_no_spill, batches, 1).

rule(r7_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r7_destination_still_approach, approach_moving_away).
body(r7_destination_still_approach, approach_raising).
body(r7_destination_still_approach, bouncy_source).
body(r7_destination_still_approach, dull_destination).
body(r7_destination_still_approach, dull_liquid).
body(r7_destination_still_approach, end_centred).
body(r7_destination_still_approach, end_rolled).
body(r7_destination_still_approach, end_tilted_back).
body(r7_destination_still_approach, end_very_high).
body(r7_destination_still_approach, grippy_destination).
body(r7_destination_still_approach, heavy_destination).
body(r7_destination_still_approach, heavy_source).
body(r7_destination_still_approach, light_liquid).
body(r7_destination_still_approach, moderate_retreat).
body(r7_destination_still_approach, pour_centred).
body(r7_destination_still_approach, pour_low).
body(r7_destination_still_approach, pour_tilted_back).
body(r7_destination_still_approach, slow_approach).
body(r7_destination_still_approach, start_tilted_back).
body(r7_destination_still_approach, sticky_liquid).
body(r7_destination_still_approach, very_much_liquid).
learned(r7_destination_still_approach).
provenance(r7_destination_still_approach, antecedent, a7).
provenance(r7_destination_still_approach, parent, a5).
provenance(r7_destination_still_approach, simulations, 31).
provenance(r7_destination_still_approach, weight_mass_permille, 31000).
provenance(r7_destination_still_approach, confidence_permille, 871).
provenance(r7_destination_still_approach, score_permille, 115).
provenance(r7_destination_still_approach, batches, 1).

rule(r7_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r7_destination_still_retreat, approach_moving_away).
body(r7_destination_still_retreat, approach_raising).
body(r7_destination_still_retreat, bouncy_source).
body(r7_destination_still_retreat, dull_destination).
body(r7_destination_still_retreat, dull_liquid).
body(r7_destination_still_retreat, end_centred).
body(r7_destination_still_retreat, end_rolled).
body(r7_destination_still_retreat, end_tilted_back).
body(r7_destination_still_retreat, end_very_high).
body(r7_destination_still_retreat, grippy_destination).
body(r7_destination_still_retreat, heavy_destination).
body(r7_destination_still_retreat, heavy_source).
body(r7_destination_still_retreat, light_liquid).
body(r7_destination_still_retreat, moderate_retreat).
body(r7_destination_still_retreat, pour_centred).
body(r7_destination_still_retreat, pour_low).
body(r7_destination_still_retreat, pour_tilted_back).
body(r7_destination_still_retreat, slow_approach).
body(r7_destination_still_retreat, start_tilted_back).
body(r7_destination_still_retreat, sticky_liquid).
body(r7_destination_still_retreat, very_much_liquid).
learned(r7_destination_still_retreat).
provenance(r7_destination_still_retreat, antecedent, a7).
provenance(r7_destination_still_retreat, parent, a5).
provenance(r7_destination_still_retreat, simulations, 31).
provenance(r7_destination_still_retreat, weight_mass_permille, 31000).
provenance(r7_destination_still_retreat, confidence_permille, 548).
provenance(r7_destination_still_retreat, score_permille, 450).
provenance(r7_destination_still_retreat, batches, 1).

rule(r7_destination_still_settle, defeasible, destination_still_settle).
body(r7_destination_still_settle, approach_moving_away).
body(r7_destination_still_settle, approach_raising).
body(r7_destination_still_settle, bouncy_source).
body(r7_destination_still_settle, dull_destination).
body(r7_destination_still_settle, dull_liquid).
body(r7_destination_still_settle, end_centred).
body(r7_destination_still_settle, end_rolled).
body(r7_destination_still_settle, end_tilted_back).
body(r7_destination_still_settle, end_very_high).
body(r7_destination_still_settle, grippy_destination).
body(r7_destination_still_settle, heavy_destination).
body(r7_destination_still_settle, heavy_source).
body(r7_destination_still_settle, light_liquid).
body(r7_destination_still_settle, moderate_retreat).
body(r7_destination_still_settle, pour_centred).
body(r7_destination_still_settle, pour_low).
body(r7_destination_still_settle, pour_tilted_back).
body(r7_destination_still_settle, slow_approach).
body(r7_destination_still_settle, start_tilted_back).
body(r7_destination_still_settle, sticky_liquid).
body(r7_destination_still_settle, very_much_liquid).
learned(r7_destination_still_settle).
provenance(r7_destination_still_settle, antecedent, a7).
provenance(r7_destination_still_settle, parent, a5).
provenance(r7_destination_still_settle, simulations, 31).
provenance(r7_destination_still_settle, weight_mass_permille, 31000).
provenance(r7_destination_still_settle, confidence_permille, 935).
provenance(r7_destination_still_settle, score_permille, 930).
provenance(r7_destination_still_settle, batches, 1).

rule(r7_destination_upright, defeasible, destination_upright).
body(r7_destination_upright, approach_moving_away).
body(r7_destination_upright, approach_raising).
body(r7_destination_upright, bouncy_source).
body(r7_destination_upright, dull_destination).
body(r7_destination_upright, dull_liquid).
body(r7_destination_upright, end_centred).
body(r7_destination_upright, end_rolled).
body(r7_destination_upright, end_tilted_back).
body(r7_destination_upright, end_very_high).
body(r7_destination_upright, grippy_destination).
body(r7_destination_upright, heavy_destination).
body(r7_destination_upright, heavy_source).
body(r7_destination_upright, light_liquid).
body(r7_destination_upright, moderate_retreat).
body(r7_destination_upright, pour_centred).
body(r7_destination_upright, pour_low).
body(r7_destination_upright, pour_tilted_back).
body(r7_destination_upright, slow_approach).
body(r7_destination_upright, start_tilted_back).
body(r7_destination_upright, sticky_liquid).
body(r7_destination_upright, very_much_liquid).
learned(r7_destination_upright).
provenance(r7_destination_upright, antecedent, a7).
provenance(r7_destination_upright, parent, a5).
provenance(r7_destination_upright, simulations, 31).
provenance(r7_destination_upright, weight_mass_permille, 31000).
provenance(r7_destination_upright, confidence_permille, 806).
provenance(r7_destination_upright, score_permille, 838).
provenance(r7_destination_upright, batches, 1).

rule(r7_source_clear, defeasible, neg(source_clear)).
body(r7_source_clear, approach_moving_away).
body(r7_source_clear, approach_raising).
body(r7_source_clear, bouncy_source).
body(r7_source_clear, dull_destination).
body(r7_source_clear, dull_liquid).
body(r7_source_clear, end_centred).
body(r7_source_clear, end_rolled).
body(r7_source_clear, end_tilted_back).
body(r7_source_clear, end_very_high).
body(r7_source_clear, grippy_destination).
body(r7_source_clear, heavy_destination).
body(r7_source_clear, heavy_source).
body(r7_source_clear, light_liquid).
body(r7_source_clear, moderate_retreat).
body(r7_source_clear, pour_centred).
body(r7_source_clear, pour_low).
body(r7_source_clear, pour_tilted_back).
body(r7_source_clear, slow_approach).
body(r7_source_clear, start_tilted_back).
body(r7_source_clear, sticky_liquid).
body(r7_source_clear, very_much_liquid).
learned(r7_source_clear).
provenance(r7_source_clear, antecedent, a7).
provenance(r7_source_clear, parent, a5).
provenance(r7_source_clear, simulations, 31).
provenance(r7_source_clear, weight_mass_permille, 31000).
provenance(r7_source_clear, confidence_permille, 968).
provenance(r7_source_clear, score_permille, 23).
provenance(r7_source_clear, batches, 1).

rule(r7_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r7_liquid_leaves_source, approach_moving_away).
body(r7_liquid_leaves_source, approach_raising).
body(r7_liquid_leaves_source, bouncy_source).
body(r7_liquid_leaves_source, dull_destination).
body(r7_liquid_leaves_source, dull_liquid).
body(r7_liquid_leaves_source, end_centred).
body(r7_liquid_leaves_source, end_rolled).
body(r7_liquid_leaves_source, end_tilted_back).
body(r7_liquid_leaves_source, end_very_high).
body(r7_liquid_leaves_source, grippy_destination).
body(r7_liquid_leaves_source, heavy_destination).
body(r7_liquid_leaves_source, heavy_source).
body(r7_liquid_leaves_source, light_liquid).
body(r7_liquid_leaves_source, moderate_retreat).
body(r7_liquid_leaves_source, pour_centred).
body(r7_liquid_leaves_source, pour_low).
body(r7_liquid_leaves_source, pour_tilted_back).
body(r7_liquid_leaves_source, slow_approach).
body(r7_liquid_leaves_source, start_tilted_back).
body(r7_liquid_leaves_source, sticky_liquid).
body(r7_liquid_leaves_source, very_much_liquid).
learned(r7_liquid_leaves_source).
provenance(r7_liquid_leaves_source, antecedent, a7).
provenance(r7_liquid_leaves_source, parent, a5).
provenance(r7_liquid_leaves_source, simulations, 31).
provenance(r7_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r7_liquid_leaves_source, confidence_permille, 903).
provenance(r7_liquid_leaves_source, score_permille, 84).
provenance(r7_liquid_leaves_source, batches, 1).

rule(r7_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r7_liquid_enters_destination, approach_moving_away).
body(r7_liquid_enters_destination, approach_raising).
body(r7_liquid_enters_destination, bouncy_source).
body(r7_liquid_enters_destination, dull_destination).
body(r7_liquid_enters_destination, dull_liquid).
body(r7_liquid_enters_destination, end_centred).
body(r7_liquid_enters_destination, end_rolled).
body(r7_liquid_enters_destination, end_tilted_back).
body(r7_liquid_enters_destination, end_very_high).
body(r7_liquid_enters_destination, grippy_destination).
body(r7_liquid_enters_destination, heavy_destination).
body(r7_liquid_enters_destination, heavy_source).
body(r7_liquid_enters_destination, light_liquid).
body(r7_liquid_enters_destination, moderate_retreat).
body(r7_liquid_enters_destination, pour_centred).
body(r7_liquid_enters_destination, pour_low).
body(r7_liquid_enters_destination, pour_tilted_back).
body(r7_liquid_enters_destination, slow_approach).
body(r7_liquid_enters_destination, start_tilted_back).
body(r7_liquid_enters_destination, sticky_liquid).
body(r7_liquid_enters_destination, very_much_liquid).
learned(r7_liquid_enters_destination).
provenance(r7_liquid_enters_destination, antecedent, a7).
provenance(r7_liquid_enters_destination, parent, a5).
provenance(r7_liquid_enters_destination, simulations, 31).
provenance(r7_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r7_liquid_enters_destination, confidence_permille, 806).
provenance(r7_liquid_enters_destination, score_permille, 258).
provenance(r7_liquid_enters_destination, batches, 1).

rule(r7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r7_liquid_remains_in_destination, approach_moving_away).
body(r7_liquid_remains_in_destination, approach_raising).
body(r7_liquid_remains_in_destination, bouncy_source).
body(r7_liquid_remains_in_destination, dull_destination).
body(r7_liquid_remains_in_destination, dull_liquid).
body(r7_liquid_remains_in_destination, end_centred).
body(r7_liquid_remains_in_destination, end_rolled).
body(r7_liquid_remains_in_destination, end_tilted_back).
body(r7_liquid_remains_in_destination, end_very_high).
body(r7_liquid_remains_in_destination, grippy_destination).
body(r7_liquid_remains_in_destination, heavy_destination).
body(r7_liquid_remains_in_destination, heavy_source).
body(r7_liquid_remains_in_destination, light_liquid).
body(r7_liquid_remains_in_destination, moderate_retreat).
body(r7_liquid_remains_in_destination, pour_centred).
body(r7_liquid_remains_in_destination, pour_low).
body(r7_liquid_remains_in_destination, pour_tilted_back).
body(r7_liquid_remains_in_destination, slow_approach).
body(r7_liquid_remains_in_destination, start_tilted_back).
body(r7_liquid_remains_in_destination, sticky_liquid).
body(r7_liquid_remains_in_destination, very_much_liquid).
learned(r7_liquid_remains_in_destination).
provenance(r7_liquid_remains_in_destination, antecedent, a7).
provenance(r7_liquid_remains_in_destination, parent, a5).
provenance(r7_liquid_remains_in_destination, simulations, 31).
provenance(r7_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r7_liquid_remains_in_destination, confidence_permille, 581).
provenance(r7_liquid_remains_in_destination, score_permille, 588).
provenance(r7_liquid_remains_in_destination, batches, 1).

rule(r7_no_spill, defeasible, no_spill).
body(r7_no_spill, approach_moving_away).
body(r7_no_spill, approach_raising).
body(r7_no_spill, bouncy_source).
body(r7_no_spill, dull_destination).
body(r7_no_spill, dull_liquid).
body(r7_no_spill, end_centred).
body(r7_no_spill, end_rolled).
body(r7_no_spill, end_tilted_back).
body(r7_no_spill, end_very_high).
body(r7_no_spill, grippy_destination).
body(r7_no_spill, heavy_destination).
body(r7_no_spill, heavy_source).
body(r7_no_spill, light_liquid).
body(r7_no_spill, moderate_retreat).
body(r7_no_spill, pour_centred).
body(r7_no_spill, pour_low).
body(r7_no_spill, pour_tilted_back).
body(r7_no_spill, slow_approach).
body(r7_no_spill, start_tilted_back).
body(r7_no_spill, sticky_liquid).
body(r7_no_spill, very_much_liquid).
learned(r7_no_spill).
provenance(r7_no_spill, antecedent, a7).
provenance(r7_no_spill, parent, a5).
provenance(r7_no_spill, simulations, 31).
provenance(r7_no_spill, weight_mass_permille, 31000).
provenance(r7_no_spill, confidence_permille, 935).
provenance(r7_no_spill, score_permille, 952).
provenance(r7_no_spill, batches, 1).

rule(r8_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r8_destination_still_approach, approach_moving_away).
body(r8_destination_still_approach, approach_raising).
body(r8_destination_still_approach, bouncy_source).
body(r8_destination_still_approach, dull_destination).
body(r8_destination_still_approach, dull_liquid).
body(r8_destination_still_approach, end_centred).
body(r8_destination_still_approach, end_rolled).
body(r8_destination_still_approach, end_tilted_back).
body(r8_destination_still_approach, end_very_high).
body(r8_destination_still_approach, fast_approach).
body(r8_destination_still_approach, grippy_destination).
body(r8_destination_still_approach, heavy_destination).
body(r8_destination_still_approach, heavy_source).
body(r8_destination_still_approach, light_liquid).
body(r8_destination_still_approach, moderate_retreat).
body(r8_destination_still_approach, pour_level).
body(r8_destination_still_approach, pour_low).
body(r8_destination_still_approach, pour_near_rim).
body(r8_destination_still_approach, pour_tilted_back).
body(r8_destination_still_approach, start_tilted_back).
body(r8_destination_still_approach, sticky_liquid).
learned(r8_destination_still_approach).
provenance(r8_destination_still_approach, antecedent, a8).
provenance(r8_destination_still_approach, parent, a6).
provenance(r8_destination_still_approach, simulations, 31).
provenance(r8_destination_still_approach, weight_mass_permille, 31000).
provenance(r8_destination_still_approach, confidence_permille, 774).
provenance(r8_destination_still_approach, score_permille, 222).
provenance(r8_destination_still_approach, batches, 1).

rule(r8_destination_still_retreat, defeasible, destination_still_retreat).
body(r8_destination_still_retreat, approach_moving_away).
body(r8_destination_still_retreat, approach_raising).
body(r8_destination_still_retreat, bouncy_source).
body(r8_destination_still_retreat, dull_destination).
body(r8_destination_still_retreat, dull_liquid).
body(r8_destination_still_retreat, end_centred).
body(r8_destination_still_retreat, end_rolled).
body(r8_destination_still_retreat, end_tilted_back).
body(r8_destination_still_retreat, end_very_high).
body(r8_destination_still_retreat, fast_approach).
body(r8_destination_still_retreat, grippy_destination).
body(r8_destination_still_retreat, heavy_destination).
body(r8_destination_still_retreat, heavy_source).
body(r8_destination_still_retreat, light_liquid).
body(r8_destination_still_retreat, moderate_retreat).
body(r8_destination_still_retreat, pour_level).
body(r8_destination_still_retreat, pour_low).
body(r8_destination_still_retreat, pour_near_rim).
body(r8_destination_still_retreat, pour_tilted_back).
body(r8_destination_still_retreat, start_tilted_back).
body(r8_destination_still_retreat, sticky_liquid).
learned(r8_destination_still_retreat).
provenance(r8_destination_still_retreat, antecedent, a8).
provenance(r8_destination_still_retreat, parent, a6).
provenance(r8_destination_still_retreat, simulations, 31).
provenance(r8_destination_still_retreat, weight_mass_permille, 31000).
provenance(r8_destination_still_retreat, confidence_permille, 645).
provenance(r8_destination_still_retreat, score_permille, 626).
provenance(r8_destination_still_retreat, batches, 1).

rule(r8_destination_still_settle, defeasible, destination_still_settle).
body(r8_destination_still_settle, approach_moving_away).
body(r8_destination_still_settle, approach_raising).
body(r8_destination_still_settle, bouncy_source).
body(r8_destination_still_settle, dull_destination).
body(r8_destination_still_settle, dull_liquid).
body(r8_destination_still_settle, end_centred).
body(r8_destination_still_settle, end_rolled).
body(r8_destination_still_settle, end_tilted_back).
body(r8_destination_still_settle, end_very_high).
body(r8_destination_still_settle, fast_approach).
body(r8_destination_still_settle, grippy_destination).
body(r8_destination_still_settle, heavy_destination).
body(r8_destination_still_settle, heavy_source).
body(r8_destination_still_settle, light_liquid).
body(r8_destination_still_settle, moderate_retreat).
body(r8_destination_still_settle, pour_level).
body(r8_destination_still_settle, pour_low).
body(r8_destination_still_settle, pour_near_rim).
body(r8_destination_still_settle, pour_tilted_back).
body(r8_destination_still_settle, start_tilted_back).
body(r8_destination_still_settle, sticky_liquid).
learned(r8_destination_still_settle).
provenance(r8_destination_still_settle, antecedent, a8).
provenance(r8_destination_still_settle, parent, a6).
provenance(r8_destination_still_settle, simulations, 31).
provenance(r8_destination_still_settle, weight_mass_permille, 31000).
provenance(r8_destination_still_settle, confidence_permille, 903).
provenance(r8_destination_still_settle, score_permille, 914).
provenance(r8_destination_still_settle, batches, 1).

rule(r8_destination_upright, defeasible, destination_upright).
body(r8_destination_upright, approach_moving_away).
body(r8_destination_upright, approach_raising).
body(r8_destination_upright, bouncy_source).
body(r8_destination_upright, dull_destination).
body(r8_destination_upright, dull_liquid).
body(r8_destination_upright, end_centred).
body(r8_destination_upright, end_rolled).
body(r8_destination_upright, end_tilted_back).
body(r8_destination_upright, end_very_high).
body(r8_destination_upright, fast_approach).
body(r8_destination_upright, grippy_destination).
body(r8_destination_upright, heavy_destination).
body(r8_destination_upright, heavy_source).
body(r8_destination_upright, light_liquid).
body(r8_destination_upright, moderate_retreat).
body(r8_destination_upright, pour_level).
body(r8_destination_upright, pour_low).
body(r8_destination_upright, pour_near_rim).
body(r8_destination_upright, pour_tilted_back).
body(r8_destination_upright, start_tilted_back).
body(r8_destination_upright, sticky_liquid).
learned(r8_destination_upright).
provenance(r8_destination_upright, antecedent, a8).
provenance(r8_destination_upright, parent, a6).
provenance(r8_destination_upright, simulations, 31).
provenance(r8_destination_upright, weight_mass_permille, 31000).
provenance(r8_destination_upright, confidence_permille, 903).
provenance(r8_destination_upright, score_permille, 912).
provenance(r8_destination_upright, batches, 1).

rule(r8_source_clear, defeasible, neg(source_clear)).
body(r8_source_clear, approach_moving_away).
body(r8_source_clear, approach_raising).
body(r8_source_clear, bouncy_source).
body(r8_source_clear, dull_destination).
body(r8_source_clear, dull_liquid).
body(r8_source_clear, end_centred).
body(r8_source_clear, end_rolled).
body(r8_source_clear, end_tilted_back).
body(r8_source_clear, end_very_high).
body(r8_source_clear, fast_approach).
body(r8_source_clear, grippy_destination).
body(r8_source_clear, heavy_destination).
body(r8_source_clear, heavy_source).
body(r8_source_clear, light_liquid).
body(r8_source_clear, moderate_retreat).
body(r8_source_clear, pour_level).
body(r8_source_clear, pour_low).
body(r8_source_clear, pour_near_rim).
body(r8_source_clear, pour_tilted_back).
body(r8_source_clear, start_tilted_back).
body(r8_source_clear, sticky_liquid).
learned(r8_source_clear).
provenance(r8_source_clear, antecedent, a8).
provenance(r8_source_clear, parent, a6).
provenance(r8_source_clear, simulations, 31).
provenance(r8_source_clear, weight_mass_permille, 31000).
provenance(r8_source_clear, confidence_permille, 839).
provenance(r8_source_clear, score_permille, 161).
provenance(r8_source_clear, batches, 1).

rule(r8_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r8_liquid_leaves_source, approach_moving_away).
body(r8_liquid_leaves_source, approach_raising).
body(r8_liquid_leaves_source, bouncy_source).
body(r8_liquid_leaves_source, dull_destination).
body(r8_liquid_leaves_source, dull_liquid).
body(r8_liquid_leaves_source, end_centred).
body(r8_liquid_leaves_source, end_rolled).
body(r8_liquid_leaves_source, end_tilted_back).
body(r8_liquid_leaves_source, end_very_high).
body(r8_liquid_leaves_source, fast_approach).
body(r8_liquid_leaves_source, grippy_destination).
body(r8_liquid_leaves_source, heavy_destination).
body(r8_liquid_leaves_source, heavy_source).
body(r8_liquid_leaves_source, light_liquid).
body(r8_liquid_leaves_source, moderate_retreat).
body(r8_liquid_leaves_source, pour_level).
body(r8_liquid_leaves_source, pour_low).
body(r8_liquid_leaves_source, pour_near_rim).
body(r8_liquid_leaves_source, pour_tilted_back).
body(r8_liquid_leaves_source, start_tilted_back).
body(r8_liquid_leaves_source, sticky_liquid).
learned(r8_liquid_leaves_source).
provenance(r8_liquid_leaves_source, antecedent, a8).
provenance(r8_liquid_leaves_source, parent, a6).
provenance(r8_liquid_leaves_source, simulations, 31).
provenance(r8_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r8_liquid_leaves_source, confidence_permille, 903).
provenance(r8_liquid_leaves_source, score_permille, 79).
provenance(r8_liquid_leaves_source, batches, 1).

rule(r8_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r8_liquid_enters_destination, approach_moving_away).
body(r8_liquid_enters_destination, approach_raising).
body(r8_liquid_enters_destination, bouncy_source).
body(r8_liquid_enters_destination, dull_destination).
body(r8_liquid_enters_destination, dull_liquid).
body(r8_liquid_enters_destination, end_centred).
body(r8_liquid_enters_destination, end_rolled).
body(r8_liquid_enters_destination, end_tilted_back).
body(r8_liquid_enters_destination, end_very_high).
body(r8_liquid_enters_destination, fast_approach).
body(r8_liquid_enters_destination, grippy_destination).
body(r8_liquid_enters_destination, heavy_destination).
body(r8_liquid_enters_destination, heavy_source).
body(r8_liquid_enters_destination, light_liquid).
body(r8_liquid_enters_destination, moderate_retreat).
body(r8_liquid_enters_destination, pour_level).
body(r8_liquid_enters_destination, pour_low).
body(r8_liquid_enters_destination, pour_near_rim).
body(r8_liquid_enters_destination, pour_tilted_back).
body(r8_liquid_enters_destination, start_tilted_back).
body(r8_liquid_enters_destination, sticky_liquid).
learned(r8_liquid_enters_destination).
provenance(r8_liquid_enters_destination, antecedent, a8).
provenance(r8_liquid_enters_destination, parent, a6).
provenance(r8_liquid_enters_destination, simulations, 31).
provenance(r8_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r8_liquid_enters_destination, confidence_permille, 774).
provenance(r8_liquid_enters_destination, score_permille, 680).
provenance(r8_liquid_enters_destination, batches, 1).

rule(r8_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r8_liquid_remains_in_destination, approach_moving_away).
body(r8_liquid_remains_in_destination, approach_raising).
body(r8_liquid_remains_in_destination, bouncy_source).
body(r8_liquid_remains_in_destination, dull_destination).
body(r8_liquid_remains_in_destination, dull_liquid).
body(r8_liquid_remains_in_destination, end_centred).
body(r8_liquid_remains_in_destination, end_rolled).
body(r8_liquid_remains_in_destination, end_tilted_back).
body(r8_liquid_remains_in_destination, end_very_high).
body(r8_liquid_remains_in_destination, fast_approach).
body(r8_liquid_remains_in_destination, grippy_destination).
body(r8_liquid_remains_in_destination, heavy_destination).
body(r8_liquid_remains_in_destination, heavy_source).
body(r8_liquid_remains_in_destination, light_liquid).
body(r8_liquid_remains_in_destination, moderate_retreat).
body(r8_liquid_remains_in_destination, pour_level).
body(r8_liquid_remains_in_destination, pour_low).
body(r8_liquid_remains_in_destination, pour_near_rim).
body(r8_liquid_remains_in_destination, pour_tilted_back).
body(r8_liquid_remains_in_destination, start_tilted_back).
body(r8_liquid_remains_in_destination, sticky_liquid).
learned(r8_liquid_remains_in_destination).
provenance(r8_liquid_remains_in_destination, antecedent, a8).
provenance(r8_liquid_remains_in_destination, parent, a6).
provenance(r8_liquid_remains_in_destination, simulations, 31).
provenance(r8_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r8_liquid_remains_in_destination, confidence_permille, 742).
provenance(r8_liquid_remains_in_destination, score_permille, 253).
provenance(r8_liquid_remains_in_destination, batches, 1).

rule(r8_no_spill, defeasible, no_spill).
body(r8_no_spill, approach_moving_away).
body(r8_no_spill, approach_raising).
body(r8_no_spill, bouncy_source).
body(r8_no_spill, dull_destination).
body(r8_no_spill, dull_liquid).
body(r8_no_spill, end_centred).
body(r8_no_spill, end_rolled).
body(r8_no_spill, end_tilted_back).
body(r8_no_spill, end_very_high).
body(r8_no_spill, fast_approach).
body(r8_no_spill, grippy_destination).
body(r8_no_spill, heavy_destination).
body(r8_no_spill, heavy_source).
body(r8_no_spill, light_liquid).
body(r8_no_spill, moderate_retreat).
body(r8_no_spill, pour_level).
body(r8_no_spill, pour_low).
body(r8_no_spill, pour_near_rim).
body(r8_no_spill, pour_tilted_back).
body(r8_no_spill, start_tilted_back).
body(r8_no_spill, sticky_liquid).
learned(r8_no_spill).
provenance(r8_no_spill, antecedent, a8).
provenance(r8_no_spill, parent, a6).
provenance(r8_no_spill, simulations, 31).
provenance(r8_no_spill, weight_mass_permille, 31000).
provenance(r8_no_spill, confidence_permille, 1000).
provenance(r8_no_spill, score_permille, 970).
provenance(r8_no_spill, batches, 1).

rule(r9_destination_still_approach, defeasible, destination_still_approach).
body(r9_destination_still_approach, approach_moving_away).
body(r9_destination_still_approach, approach_raising).
body(r9_destination_still_approach, bouncy_source).
body(r9_destination_still_approach, dull_destination).
body(r9_destination_still_approach, dull_liquid).
body(r9_destination_still_approach, end_centred).
body(r9_destination_still_approach, end_level).
body(r9_destination_still_approach, end_tilted_back).
body(r9_destination_still_approach, end_very_high).
body(r9_destination_still_approach, fast_approach).
body(r9_destination_still_approach, grippy_destination).
body(r9_destination_still_approach, heavy_destination).
body(r9_destination_still_approach, heavy_source).
body(r9_destination_still_approach, light_liquid).
body(r9_destination_still_approach, moderate_retreat).
body(r9_destination_still_approach, pour_level).
body(r9_destination_still_approach, pour_low).
body(r9_destination_still_approach, pour_near_rim).
body(r9_destination_still_approach, pour_tilted_back).
body(r9_destination_still_approach, start_tilted_back).
body(r9_destination_still_approach, sticky_liquid).
learned(r9_destination_still_approach).
provenance(r9_destination_still_approach, antecedent, a9).
provenance(r9_destination_still_approach, parent, a8).
provenance(r9_destination_still_approach, simulations, 31).
provenance(r9_destination_still_approach, weight_mass_permille, 31000).
provenance(r9_destination_still_approach, confidence_permille, 548).
provenance(r9_destination_still_approach, score_permille, 516).
provenance(r9_destination_still_approach, batches, 1).

rule(r9_destination_still_retreat, defeasible, destination_still_retreat).
body(r9_destination_still_retreat, approach_moving_away).
body(r9_destination_still_retreat, approach_raising).
body(r9_destination_still_retreat, bouncy_source).
body(r9_destination_still_retreat, dull_destination).
body(r9_destination_still_retreat, dull_liquid).
body(r9_destination_still_retreat, end_centred).
body(r9_destination_still_retreat, end_level).
body(r9_destination_still_retreat, end_tilted_back).
body(r9_destination_still_retreat, end_very_high).
body(r9_destination_still_retreat, fast_approach).
body(r9_destination_still_retreat, grippy_destination).
body(r9_destination_still_retreat, heavy_destination).
body(r9_destination_still_retreat, heavy_source).
body(r9_destination_still_retreat, light_liquid).
body(r9_destination_still_retreat, moderate_retreat).
body(r9_destination_still_retreat, pour_level).
body(r9_destination_still_retreat, pour_low).
body(r9_destination_still_retreat, pour_near_rim).
body(r9_destination_still_retreat, pour_tilted_back).
body(r9_destination_still_retreat, start_tilted_back).
body(r9_destination_still_retreat, sticky_liquid).
learned(r9_destination_still_retreat).
provenance(r9_destination_still_retreat, antecedent, a9).
provenance(r9_destination_still_retreat, parent, a8).
provenance(r9_destination_still_retreat, simulations, 31).
provenance(r9_destination_still_retreat, weight_mass_permille, 31000).
provenance(r9_destination_still_retreat, confidence_permille, 806).
provenance(r9_destination_still_retreat, score_permille, 789).
provenance(r9_destination_still_retreat, batches, 1).

rule(r9_destination_still_settle, defeasible, destination_still_settle).
body(r9_destination_still_settle, approach_moving_away).
body(r9_destination_still_settle, approach_raising).
body(r9_destination_still_settle, bouncy_source).
body(r9_destination_still_settle, dull_destination).
body(r9_destination_still_settle, dull_liquid).
body(r9_destination_still_settle, end_centred).
body(r9_destination_still_settle, end_level).
body(r9_destination_still_settle, end_tilted_back).
body(r9_destination_still_settle, end_very_high).
body(r9_destination_still_settle, fast_approach).
body(r9_destination_still_settle, grippy_destination).
body(r9_destination_still_settle, heavy_destination).
body(r9_destination_still_settle, heavy_source).
body(r9_destination_still_settle, light_liquid).
body(r9_destination_still_settle, moderate_retreat).
body(r9_destination_still_settle, pour_level).
body(r9_destination_still_settle, pour_low).
body(r9_destination_still_settle, pour_near_rim).
body(r9_destination_still_settle, pour_tilted_back).
body(r9_destination_still_settle, start_tilted_back).
body(r9_destination_still_settle, sticky_liquid).
learned(r9_destination_still_settle).
provenance(r9_destination_still_settle, antecedent, a9).
provenance(r9_destination_still_settle, parent, a8).
provenance(r9_destination_still_settle, simulations, 31).
provenance(r9_destination_still_settle, weight_mass_permille, 31000).
provenance(r9_destination_still_settle, confidence_permille, 903).
provenance(r9_destination_still_settle, score_permille, 897).
provenance(r9_destination_still_settle, batches, 1).

rule(r9_destination_upright, defeasible, destination_upright).
body(r9_destination_upright, approach_moving_away).
body(r9_destination_upright, approach_raising).
body(r9_destination_upright, bouncy_source).
body(r9_destination_upright, dull_destination).
body(r9_destination_upright, dull_liquid).
body(r9_destination_upright, end_centred).
body(r9_destination_upright, end_level).
body(r9_destination_upright, end_tilted_back).
body(r9_destination_upright, end_very_high).
body(r9_destination_upright, fast_approach).
body(r9_destination_upright, grippy_destination).
body(r9_destination_upright, heavy_destination).
body(r9_destination_upright, heavy_source).
body(r9_destination_upright, light_liquid).
body(r9_destination_upright, moderate_retreat).
body(r9_destination_upright, pour_level).
body(r9_destination_upright, pour_low).
body(r9_destination_upright, pour_near_rim).
body(r9_destination_upright, pour_tilted_back).
body(r9_destination_upright, start_tilted_back).
body(r9_destination_upright, sticky_liquid).
learned(r9_destination_upright).
provenance(r9_destination_upright, antecedent, a9).
provenance(r9_destination_upright, parent, a8).
provenance(r9_destination_upright, simulations, 31).
provenance(r9_destination_upright, weight_mass_permille, 31000).
provenance(r9_destination_upright, confidence_permille, 968).
provenance(r9_destination_upright, score_permille, 957).
provenance(r9_destination_upright, batches, 1).

rule(r9_source_clear, defeasible, neg(source_clear)).
body(r9_source_clear, approach_moving_away).
body(r9_source_clear, approach_raising).
body(r9_source_clear, bouncy_source).
body(r9_source_clear, dull_destination).
body(r9_source_clear, dull_liquid).
body(r9_source_clear, end_centred).
body(r9_source_clear, end_level).
body(r9_source_clear, end_tilted_back).
body(r9_source_clear, end_very_high).
body(r9_source_clear, fast_approach).
body(r9_source_clear, grippy_destination).
body(r9_source_clear, heavy_destination).
body(r9_source_clear, heavy_source).
body(r9_source_clear, light_liquid).
body(r9_source_clear, moderate_retreat).
body(r9_source_clear, pour_level).
body(r9_source_clear, pour_low).
body(r9_source_clear, pour_near_rim).
body(r9_source_clear, pour_tilted_back).
body(r9_source_clear, start_tilted_back).
body(r9_source_clear, sticky_liquid).
learned(r9_source_clear).
provenance(r9_source_clear, antecedent, a9).
provenance(r9_source_clear, parent, a8).
provenance(r9_source_clear, simulations, 31).
provenance(r9_source_clear, weight_mass_permille, 31000).
provenance(r9_source_clear, confidence_permille, 581).
provenance(r9_source_clear, score_permille, 364).
provenance(r9_source_clear, batches, 1).

rule(r9_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r9_liquid_leaves_source, approach_moving_away).
body(r9_liquid_leaves_source, approach_raising).
body(r9_liquid_leaves_source, bouncy_source).
body(r9_liquid_leaves_source, dull_destination).
body(r9_liquid_leaves_source, dull_liquid).
body(r9_liquid_leaves_source, end_centred).
body(r9_liquid_leaves_source, end_level).
body(r9_liquid_leaves_source, end_tilted_back).
body(r9_liquid_leaves_source, end_very_high).
body(r9_liquid_leaves_source, fast_approach).
body(r9_liquid_leaves_source, grippy_destination).
body(r9_liquid_leaves_source, heavy_destination).
body(r9_liquid_leaves_source, heavy_source).
body(r9_liquid_leaves_source, light_liquid).
body(r9_liquid_leaves_source, moderate_retreat).
body(r9_liquid_leaves_source, pour_level).
body(r9_liquid_leaves_source, pour_low).
body(r9_liquid_leaves_source, pour_near_rim).
body(r9_liquid_leaves_source, pour_tilted_back).
body(r9_liquid_leaves_source, start_tilted_back).
body(r9_liquid_leaves_source, sticky_liquid).
learned(r9_liquid_leaves_source).
provenance(r9_liquid_leaves_source, antecedent, a9).
provenance(r9_liquid_leaves_source, parent, a8).
provenance(r9_liquid_leaves_source, simulations, 31).
provenance(r9_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r9_liquid_leaves_source, confidence_permille, 1000).
provenance(r9_liquid_leaves_source, score_permille, 36).
provenance(r9_liquid_leaves_source, batches, 1).

rule(r9_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r9_liquid_enters_destination, approach_moving_away).
body(r9_liquid_enters_destination, approach_raising).
body(r9_liquid_enters_destination, bouncy_source).
body(r9_liquid_enters_destination, dull_destination).
body(r9_liquid_enters_destination, dull_liquid).
body(r9_liquid_enters_destination, end_centred).
body(r9_liquid_enters_destination, end_level).
body(r9_liquid_enters_destination, end_tilted_back).
body(r9_liquid_enters_destination, end_very_high).
body(r9_liquid_enters_destination, fast_approach).
body(r9_liquid_enters_destination, grippy_destination).
body(r9_liquid_enters_destination, heavy_destination).
body(r9_liquid_enters_destination, heavy_source).
body(r9_liquid_enters_destination, light_liquid).
body(r9_liquid_enters_destination, moderate_retreat).
body(r9_liquid_enters_destination, pour_level).
body(r9_liquid_enters_destination, pour_low).
body(r9_liquid_enters_destination, pour_near_rim).
body(r9_liquid_enters_destination, pour_tilted_back).
body(r9_liquid_enters_destination, start_tilted_back).
body(r9_liquid_enters_destination, sticky_liquid).
learned(r9_liquid_enters_destination).
provenance(r9_liquid_enters_destination, antecedent, a9).
provenance(r9_liquid_enters_destination, parent, a8).
provenance(r9_liquid_enters_destination, simulations, 31).
provenance(r9_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r9_liquid_enters_destination, confidence_permille, 581).
provenance(r9_liquid_enters_destination, score_permille, 400).
provenance(r9_liquid_enters_destination, batches, 1).

rule(r9_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r9_liquid_remains_in_destination, approach_moving_away).
body(r9_liquid_remains_in_destination, approach_raising).
body(r9_liquid_remains_in_destination, bouncy_source).
body(r9_liquid_remains_in_destination, dull_destination).
body(r9_liquid_remains_in_destination, dull_liquid).
body(r9_liquid_remains_in_destination, end_centred).
body(r9_liquid_remains_in_destination, end_level).
body(r9_liquid_remains_in_destination, end_tilted_back).
body(r9_liquid_remains_in_destination, end_very_high).
body(r9_liquid_remains_in_destination, fast_approach).
body(r9_liquid_remains_in_destination, grippy_destination).
body(r9_liquid_remains_in_destination, heavy_destination).
body(r9_liquid_remains_in_destination, heavy_source).
body(r9_liquid_remains_in_destination, light_liquid).
body(r9_liquid_remains_in_destination, moderate_retreat).
body(r9_liquid_remains_in_destination, pour_level).
body(r9_liquid_remains_in_destination, pour_low).
body(r9_liquid_remains_in_destination, pour_near_rim).
body(r9_liquid_remains_in_destination, pour_tilted_back).
body(r9_liquid_remains_in_destination, start_tilted_back).
body(r9_liquid_remains_in_destination, sticky_liquid).
learned(r9_liquid_remains_in_destination).
provenance(r9_liquid_remains_in_destination, antecedent, a9).
provenance(r9_liquid_remains_in_destination, parent, a8).
provenance(r9_liquid_remains_in_destination, simulations, 31).
provenance(r9_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r9_liquid_remains_in_destination, confidence_permille, 581).
provenance(r9_liquid_remains_in_destination, score_permille, 438).
provenance(r9_liquid_remains_in_destination, batches, 1).

rule(r9_no_spill, defeasible, no_spill).
body(r9_no_spill, approach_moving_away).
body(r9_no_spill, approach_raising).
body(r9_no_spill, bouncy_source).
body(r9_no_spill, dull_destination).
body(r9_no_spill, dull_liquid).
body(r9_no_spill, end_centred).
body(r9_no_spill, end_level).
body(r9_no_spill, end_tilted_back).
body(r9_no_spill, end_very_high).
body(r9_no_spill, fast_approach).
body(r9_no_spill, grippy_destination).
body(r9_no_spill, heavy_destination).
body(r9_no_spill, heavy_source).
body(r9_no_spill, light_liquid).
body(r9_no_spill, moderate_retreat).
body(r9_no_spill, pour_level).
body(r9_no_spill, pour_low).
body(r9_no_spill, pour_near_rim).
body(r9_no_spill, pour_tilted_back).
body(r9_no_spill, start_tilted_back).
body(r9_no_spill, sticky_liquid).
learned(r9_no_spill).
provenance(r9_no_spill, antecedent, a9).
provenance(r9_no_spill, parent, a8).
provenance(r9_no_spill, simulations, 31).
provenance(r9_no_spill, weight_mass_permille, 31000).
provenance(r9_no_spill, confidence_permille, 1000).
provenance(r9_no_spill, score_permille, 984).
provenance(r9_no_spill, batches, 1).

rule(r10_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r10_destination_still_approach, approach_moving_away).
body(r10_destination_still_approach, approach_raising).
body(r10_destination_still_approach, bouncy_source).
body(r10_destination_still_approach, dull_destination).
body(r10_destination_still_approach, dull_liquid).
body(r10_destination_still_approach, end_centred).
body(r10_destination_still_approach, end_level).
body(r10_destination_still_approach, end_tilted_back).
body(r10_destination_still_approach, end_very_high).
body(r10_destination_still_approach, fast_approach).
body(r10_destination_still_approach, grippy_destination).
body(r10_destination_still_approach, heavy_source).
body(r10_destination_still_approach, light_destination).
body(r10_destination_still_approach, light_liquid).
body(r10_destination_still_approach, moderate_retreat).
body(r10_destination_still_approach, pour_level).
body(r10_destination_still_approach, pour_low).
body(r10_destination_still_approach, pour_near_rim).
body(r10_destination_still_approach, pour_tilted_back).
body(r10_destination_still_approach, start_tilted_back).
body(r10_destination_still_approach, sticky_liquid).
learned(r10_destination_still_approach).
provenance(r10_destination_still_approach, antecedent, a10).
provenance(r10_destination_still_approach, parent, a9).
provenance(r10_destination_still_approach, simulations, 31).
provenance(r10_destination_still_approach, weight_mass_permille, 31000).
provenance(r10_destination_still_approach, confidence_permille, 774).
provenance(r10_destination_still_approach, score_permille, 243).
provenance(r10_destination_still_approach, batches, 1).

rule(r10_destination_still_retreat, defeasible, destination_still_retreat).
body(r10_destination_still_retreat, approach_moving_away).
body(r10_destination_still_retreat, approach_raising).
body(r10_destination_still_retreat, bouncy_source).
body(r10_destination_still_retreat, dull_destination).
body(r10_destination_still_retreat, dull_liquid).
body(r10_destination_still_retreat, end_centred).
body(r10_destination_still_retreat, end_level).
body(r10_destination_still_retreat, end_tilted_back).
body(r10_destination_still_retreat, end_very_high).
body(r10_destination_still_retreat, fast_approach).
body(r10_destination_still_retreat, grippy_destination).
body(r10_destination_still_retreat, heavy_source).
body(r10_destination_still_retreat, light_destination).
body(r10_destination_still_retreat, light_liquid).
body(r10_destination_still_retreat, moderate_retreat).
body(r10_destination_still_retreat, pour_level).
body(r10_destination_still_retreat, pour_low).
body(r10_destination_still_retreat, pour_near_rim).
body(r10_destination_still_retreat, pour_tilted_back).
body(r10_destination_still_retreat, start_tilted_back).
body(r10_destination_still_retreat, sticky_liquid).
learned(r10_destination_still_retreat).
provenance(r10_destination_still_retreat, antecedent, a10).
provenance(r10_destination_still_retreat, parent, a9).
provenance(r10_destination_still_retreat, simulations, 31).
provenance(r10_destination_still_retreat, weight_mass_permille, 31000).
provenance(r10_destination_still_retreat, confidence_permille, 645).
provenance(r10_destination_still_retreat, score_permille, 625).
provenance(r10_destination_still_retreat, batches, 1).

rule(r10_destination_still_settle, defeasible, destination_still_settle).
body(r10_destination_still_settle, approach_moving_away).
body(r10_destination_still_settle, approach_raising).
body(r10_destination_still_settle, bouncy_source).
body(r10_destination_still_settle, dull_destination).
body(r10_destination_still_settle, dull_liquid).
body(r10_destination_still_settle, end_centred).
body(r10_destination_still_settle, end_level).
body(r10_destination_still_settle, end_tilted_back).
body(r10_destination_still_settle, end_very_high).
body(r10_destination_still_settle, fast_approach).
body(r10_destination_still_settle, grippy_destination).
body(r10_destination_still_settle, heavy_source).
body(r10_destination_still_settle, light_destination).
body(r10_destination_still_settle, light_liquid).
body(r10_destination_still_settle, moderate_retreat).
body(r10_destination_still_settle, pour_level).
body(r10_destination_still_settle, pour_low).
body(r10_destination_still_settle, pour_near_rim).
body(r10_destination_still_settle, pour_tilted_back).
body(r10_destination_still_settle, start_tilted_back).
body(r10_destination_still_settle, sticky_liquid).
learned(r10_destination_still_settle).
provenance(r10_destination_still_settle, antecedent, a10).
provenance(r10_destination_still_settle, parent, a9).
provenance(r10_destination_still_settle, simulations, 31).
provenance(r10_destination_still_settle, weight_mass_permille, 31000).
provenance(r10_destination_still_settle, confidence_permille, 806).
provenance(r10_destination_still_settle, score_permille, 790).
provenance(r10_destination_still_settle, batches, 1).

rule(r10_destination_upright, defeasible, destination_upright).
body(r10_destination_upright, approach_moving_away).
body(r10_destination_upright, approach_raising).
body(r10_destination_upright, bouncy_source).
body(r10_destination_upright, dull_destination).
body(r10_destination_upright, dull_liquid).
body(r10_destination_upright, end_centred).
body(r10_destination_upright, end_level).
body(r10_destination_upright, end_tilted_back).
body(r10_destination_upright, end_very_high).
body(r10_destination_upright, fast_approach).
body(r10_destination_upright, grippy_destination).
body(r10_destination_upright, heavy_source).
body(r10_destination_upright, light_destination).
body(r10_destination_upright, light_liquid).
body(r10_destination_upright, moderate_retreat).
body(r10_destination_upright, pour_level).
body(r10_destination_upright, pour_low).
body(r10_destination_upright, pour_near_rim).
body(r10_destination_upright, pour_tilted_back).
body(r10_destination_upright, start_tilted_back).
body(r10_destination_upright, sticky_liquid).
learned(r10_destination_upright).
provenance(r10_destination_upright, antecedent, a10).
provenance(r10_destination_upright, parent, a9).
provenance(r10_destination_upright, simulations, 31).
provenance(r10_destination_upright, weight_mass_permille, 31000).
provenance(r10_destination_upright, confidence_permille, 871).
provenance(r10_destination_upright, score_permille, 870).
provenance(r10_destination_upright, batches, 1).

rule(r10_source_clear, defeasible, neg(source_clear)).
body(r10_source_clear, approach_moving_away).
body(r10_source_clear, approach_raising).
body(r10_source_clear, bouncy_source).
body(r10_source_clear, dull_destination).
body(r10_source_clear, dull_liquid).
body(r10_source_clear, end_centred).
body(r10_source_clear, end_level).
body(r10_source_clear, end_tilted_back).
body(r10_source_clear, end_very_high).
body(r10_source_clear, fast_approach).
body(r10_source_clear, grippy_destination).
body(r10_source_clear, heavy_source).
body(r10_source_clear, light_destination).
body(r10_source_clear, light_liquid).
body(r10_source_clear, moderate_retreat).
body(r10_source_clear, pour_level).
body(r10_source_clear, pour_low).
body(r10_source_clear, pour_near_rim).
body(r10_source_clear, pour_tilted_back).
body(r10_source_clear, start_tilted_back).
body(r10_source_clear, sticky_liquid).
learned(r10_source_clear).
provenance(r10_source_clear, antecedent, a10).
provenance(r10_source_clear, parent, a9).
provenance(r10_source_clear, simulations, 31).
provenance(r10_source_clear, weight_mass_permille, 31000).
provenance(r10_source_clear, confidence_permille, 839).
provenance(r10_source_clear, score_permille, 156).
provenance(r10_source_clear, batches, 1).

rule(r10_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r10_liquid_leaves_source, approach_moving_away).
body(r10_liquid_leaves_source, approach_raising).
body(r10_liquid_leaves_source, bouncy_source).
body(r10_liquid_leaves_source, dull_destination).
body(r10_liquid_leaves_source, dull_liquid).
body(r10_liquid_leaves_source, end_centred).
body(r10_liquid_leaves_source, end_level).
body(r10_liquid_leaves_source, end_tilted_back).
body(r10_liquid_leaves_source, end_very_high).
body(r10_liquid_leaves_source, fast_approach).
body(r10_liquid_leaves_source, grippy_destination).
body(r10_liquid_leaves_source, heavy_source).
body(r10_liquid_leaves_source, light_destination).
body(r10_liquid_leaves_source, light_liquid).
body(r10_liquid_leaves_source, moderate_retreat).
body(r10_liquid_leaves_source, pour_level).
body(r10_liquid_leaves_source, pour_low).
body(r10_liquid_leaves_source, pour_near_rim).
body(r10_liquid_leaves_source, pour_tilted_back).
body(r10_liquid_leaves_source, start_tilted_back).
body(r10_liquid_leaves_source, sticky_liquid).
learned(r10_liquid_leaves_source).
provenance(r10_liquid_leaves_source, antecedent, a10).
provenance(r10_liquid_leaves_source, parent, a9).
provenance(r10_liquid_leaves_source, simulations, 31).
provenance(r10_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r10_liquid_leaves_source, confidence_permille, 968).
provenance(r10_liquid_leaves_source, score_permille, 69).
provenance(r10_liquid_leaves_source, batches, 1).

rule(r10_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r10_liquid_enters_destination, approach_moving_away).
body(r10_liquid_enters_destination, approach_raising).
body(r10_liquid_enters_destination, bouncy_source).
body(r10_liquid_enters_destination, dull_destination).
body(r10_liquid_enters_destination, dull_liquid).
body(r10_liquid_enters_destination, end_centred).
body(r10_liquid_enters_destination, end_level).
body(r10_liquid_enters_destination, end_tilted_back).
body(r10_liquid_enters_destination, end_very_high).
body(r10_liquid_enters_destination, fast_approach).
body(r10_liquid_enters_destination, grippy_destination).
body(r10_liquid_enters_destination, heavy_source).
body(r10_liquid_enters_destination, light_destination).
body(r10_liquid_enters_destination, light_liquid).
body(r10_liquid_enters_destination, moderate_retreat).
body(r10_liquid_enters_destination, pour_level).
body(r10_liquid_enters_destination, pour_low).
body(r10_liquid_enters_destination, pour_near_rim).
body(r10_liquid_enters_destination, pour_tilted_back).
body(r10_liquid_enters_destination, start_tilted_back).
body(r10_liquid_enters_destination, sticky_liquid).
learned(r10_liquid_enters_destination).
provenance(r10_liquid_enters_destination, antecedent, a10).
provenance(r10_liquid_enters_destination, parent, a9).
provenance(r10_liquid_enters_destination, simulations, 31).
provenance(r10_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r10_liquid_enters_destination, confidence_permille, 613).
provenance(r10_liquid_enters_destination, score_permille, 440).
provenance(r10_liquid_enters_destination, batches, 1).

rule(r10_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r10_liquid_remains_in_destination, approach_moving_away).
body(r10_liquid_remains_in_destination, approach_raising).
body(r10_liquid_remains_in_destination, bouncy_source).
body(r10_liquid_remains_in_destination, dull_destination).
body(r10_liquid_remains_in_destination, dull_liquid).
body(r10_liquid_remains_in_destination, end_centred).
body(r10_liquid_remains_in_destination, end_level).
body(r10_liquid_remains_in_destination, end_tilted_back).
body(r10_liquid_remains_in_destination, end_very_high).
body(r10_liquid_remains_in_destination, fast_approach).
body(r10_liquid_remains_in_destination, grippy_destination).
body(r10_liquid_remains_in_destination, heavy_source).
body(r10_liquid_remains_in_destination, light_destination).
body(r10_liquid_remains_in_destination, light_liquid).
body(r10_liquid_remains_in_destination, moderate_retreat).
body(r10_liquid_remains_in_destination, pour_level).
body(r10_liquid_remains_in_destination, pour_low).
body(r10_liquid_remains_in_destination, pour_near_rim).
body(r10_liquid_remains_in_destination, pour_tilted_back).
body(r10_liquid_remains_in_destination, start_tilted_back).
body(r10_liquid_remains_in_destination, sticky_liquid).
learned(r10_liquid_remains_in_destination).
provenance(r10_liquid_remains_in_destination, antecedent, a10).
provenance(r10_liquid_remains_in_destination, parent, a9).
provenance(r10_liquid_remains_in_destination, simulations, 31).
provenance(r10_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r10_liquid_remains_in_destination, confidence_permille, 645).
provenance(r10_liquid_remains_in_destination, score_permille, 366).
provenance(r10_liquid_remains_in_destination, batches, 1).

rule(r10_no_spill, defeasible, no_spill).
body(r10_no_spill, approach_moving_away).
body(r10_no_spill, approach_raising).
body(r10_no_spill, bouncy_source).
body(r10_no_spill, dull_destination).
body(r10_no_spill, dull_liquid).
body(r10_no_spill, end_centred).
body(r10_no_spill, end_level).
body(r10_no_spill, end_tilted_back).
body(r10_no_spill, end_very_high).
body(r10_no_spill, fast_approach).
body(r10_no_spill, grippy_destination).
body(r10_no_spill, heavy_source).
body(r10_no_spill, light_destination).
body(r10_no_spill, light_liquid).
body(r10_no_spill, moderate_retreat).
body(r10_no_spill, pour_level).
body(r10_no_spill, pour_low).
body(r10_no_spill, pour_near_rim).
body(r10_no_spill, pour_tilted_back).
body(r10_no_spill, start_tilted_back).
body(r10_no_spill, sticky_liquid).
learned(r10_no_spill).
provenance(r10_no_spill, antecedent, a10).
provenance(r10_no_spill, parent, a9).
provenance(r10_no_spill, simulations, 31).
provenance(r10_no_spill, weight_mass_permille, 31000).
provenance(r10_no_spill, confidence_permille, 1000).
provenance(r10_no_spill, score_permille, 998).
provenance(r10_no_spill, batches, 1).

rule(r11_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r11_destination_still_approach, approach_moving_away).
body(r11_destination_still_approach, approach_raising).
body(r11_destination_still_approach, bouncy_source).
body(r11_destination_still_approach, dull_destination).
body(r11_destination_still_approach, dull_liquid).
body(r11_destination_still_approach, end_centred).
body(r11_destination_still_approach, end_rolled).
body(r11_destination_still_approach, end_steeply_tilted).
body(r11_destination_still_approach, end_very_high).
body(r11_destination_still_approach, grippy_destination).
body(r11_destination_still_approach, heavy_destination).
body(r11_destination_still_approach, heavy_source).
body(r11_destination_still_approach, light_liquid).
body(r11_destination_still_approach, moderate_retreat).
body(r11_destination_still_approach, pour_centred).
body(r11_destination_still_approach, pour_low).
body(r11_destination_still_approach, pour_tilted_back).
body(r11_destination_still_approach, slow_approach).
body(r11_destination_still_approach, start_tilted_back).
body(r11_destination_still_approach, sticky_liquid).
body(r11_destination_still_approach, very_much_liquid).
learned(r11_destination_still_approach).
provenance(r11_destination_still_approach, antecedent, a11).
provenance(r11_destination_still_approach, parent, a7).
provenance(r11_destination_still_approach, simulations, 31).
provenance(r11_destination_still_approach, weight_mass_permille, 31000).
provenance(r11_destination_still_approach, confidence_permille, 645).
provenance(r11_destination_still_approach, score_permille, 339).
provenance(r11_destination_still_approach, batches, 1).

rule(r11_destination_still_retreat, defeasible, destination_still_retreat).
body(r11_destination_still_retreat, approach_moving_away).
body(r11_destination_still_retreat, approach_raising).
body(r11_destination_still_retreat, bouncy_source).
body(r11_destination_still_retreat, dull_destination).
body(r11_destination_still_retreat, dull_liquid).
body(r11_destination_still_retreat, end_centred).
body(r11_destination_still_retreat, end_rolled).
body(r11_destination_still_retreat, end_steeply_tilted).
body(r11_destination_still_retreat, end_very_high).
body(r11_destination_still_retreat, grippy_destination).
body(r11_destination_still_retreat, heavy_destination).
body(r11_destination_still_retreat, heavy_source).
body(r11_destination_still_retreat, light_liquid).
body(r11_destination_still_retreat, moderate_retreat).
body(r11_destination_still_retreat, pour_centred).
body(r11_destination_still_retreat, pour_low).
body(r11_destination_still_retreat, pour_tilted_back).
body(r11_destination_still_retreat, slow_approach).
body(r11_destination_still_retreat, start_tilted_back).
body(r11_destination_still_retreat, sticky_liquid).
body(r11_destination_still_retreat, very_much_liquid).
learned(r11_destination_still_retreat).
provenance(r11_destination_still_retreat, antecedent, a11).
provenance(r11_destination_still_retreat, parent, a7).
provenance(r11_destination_still_retreat, simulations, 31).
provenance(r11_destination_still_retreat, weight_mass_permille, 31000).
provenance(r11_destination_still_retreat, confidence_permille, 581).
provenance(r11_destination_still_retreat, score_permille, 589).
provenance(r11_destination_still_retreat, batches, 1).

rule(r11_destination_still_settle, defeasible, destination_still_settle).
body(r11_destination_still_settle, approach_moving_away).
body(r11_destination_still_settle, approach_raising).
body(r11_destination_still_settle, bouncy_source).
body(r11_destination_still_settle, dull_destination).
body(r11_destination_still_settle, dull_liquid).
body(r11_destination_still_settle, end_centred).
body(r11_destination_still_settle, end_rolled).
body(r11_destination_still_settle, end_steeply_tilted).
body(r11_destination_still_settle, end_very_high).
body(r11_destination_still_settle, grippy_destination).
body(r11_destination_still_settle, heavy_destination).
body(r11_destination_still_settle, heavy_source).
body(r11_destination_still_settle, light_liquid).
body(r11_destination_still_settle, moderate_retreat).
body(r11_destination_still_settle, pour_centred).
body(r11_destination_still_settle, pour_low).
body(r11_destination_still_settle, pour_tilted_back).
body(r11_destination_still_settle, slow_approach).
body(r11_destination_still_settle, start_tilted_back).
body(r11_destination_still_settle, sticky_liquid).
body(r11_destination_still_settle, very_much_liquid).
learned(r11_destination_still_settle).
provenance(r11_destination_still_settle, antecedent, a11).
provenance(r11_destination_still_settle, parent, a7).
provenance(r11_destination_still_settle, simulations, 31).
provenance(r11_destination_still_settle, weight_mass_permille, 31000).
provenance(r11_destination_still_settle, confidence_permille, 935).
provenance(r11_destination_still_settle, score_permille, 935).
provenance(r11_destination_still_settle, batches, 1).

rule(r11_destination_upright, defeasible, destination_upright).
body(r11_destination_upright, approach_moving_away).
body(r11_destination_upright, approach_raising).
body(r11_destination_upright, bouncy_source).
body(r11_destination_upright, dull_destination).
body(r11_destination_upright, dull_liquid).
body(r11_destination_upright, end_centred).
body(r11_destination_upright, end_rolled).
body(r11_destination_upright, end_steeply_tilted).
body(r11_destination_upright, end_very_high).
body(r11_destination_upright, grippy_destination).
body(r11_destination_upright, heavy_destination).
body(r11_destination_upright, heavy_source).
body(r11_destination_upright, light_liquid).
body(r11_destination_upright, moderate_retreat).
body(r11_destination_upright, pour_centred).
body(r11_destination_upright, pour_low).
body(r11_destination_upright, pour_tilted_back).
body(r11_destination_upright, slow_approach).
body(r11_destination_upright, start_tilted_back).
body(r11_destination_upright, sticky_liquid).
body(r11_destination_upright, very_much_liquid).
learned(r11_destination_upright).
provenance(r11_destination_upright, antecedent, a11).
provenance(r11_destination_upright, parent, a7).
provenance(r11_destination_upright, simulations, 31).
provenance(r11_destination_upright, weight_mass_permille, 31000).
provenance(r11_destination_upright, confidence_permille, 935).
provenance(r11_destination_upright, score_permille, 951).
provenance(r11_destination_upright, batches, 1).

rule(r11_source_clear, defeasible, neg(source_clear)).
body(r11_source_clear, approach_moving_away).
body(r11_source_clear, approach_raising).
body(r11_source_clear, bouncy_source).
body(r11_source_clear, dull_destination).
body(r11_source_clear, dull_liquid).
body(r11_source_clear, end_centred).
body(r11_source_clear, end_rolled).
body(r11_source_clear, end_steeply_tilted).
body(r11_source_clear, end_very_high).
body(r11_source_clear, grippy_destination).
body(r11_source_clear, heavy_destination).
body(r11_source_clear, heavy_source).
body(r11_source_clear, light_liquid).
body(r11_source_clear, moderate_retreat).
body(r11_source_clear, pour_centred).
body(r11_source_clear, pour_low).
body(r11_source_clear, pour_tilted_back).
body(r11_source_clear, slow_approach).
body(r11_source_clear, start_tilted_back).
body(r11_source_clear, sticky_liquid).
body(r11_source_clear, very_much_liquid).
learned(r11_source_clear).
provenance(r11_source_clear, antecedent, a11).
provenance(r11_source_clear, parent, a7).
provenance(r11_source_clear, simulations, 31).
provenance(r11_source_clear, weight_mass_permille, 31000).
provenance(r11_source_clear, confidence_permille, 806).
provenance(r11_source_clear, score_permille, 194).
provenance(r11_source_clear, batches, 1).

rule(r11_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r11_liquid_leaves_source, approach_moving_away).
body(r11_liquid_leaves_source, approach_raising).
body(r11_liquid_leaves_source, bouncy_source).
body(r11_liquid_leaves_source, dull_destination).
body(r11_liquid_leaves_source, dull_liquid).
body(r11_liquid_leaves_source, end_centred).
body(r11_liquid_leaves_source, end_rolled).
body(r11_liquid_leaves_source, end_steeply_tilted).
body(r11_liquid_leaves_source, end_very_high).
body(r11_liquid_leaves_source, grippy_destination).
body(r11_liquid_leaves_source, heavy_destination).
body(r11_liquid_leaves_source, heavy_source).
body(r11_liquid_leaves_source, light_liquid).
body(r11_liquid_leaves_source, moderate_retreat).
body(r11_liquid_leaves_source, pour_centred).
body(r11_liquid_leaves_source, pour_low).
body(r11_liquid_leaves_source, pour_tilted_back).
body(r11_liquid_leaves_source, slow_approach).
body(r11_liquid_leaves_source, start_tilted_back).
body(r11_liquid_leaves_source, sticky_liquid).
body(r11_liquid_leaves_source, very_much_liquid).
learned(r11_liquid_leaves_source).
provenance(r11_liquid_leaves_source, antecedent, a11).
provenance(r11_liquid_leaves_source, parent, a7).
provenance(r11_liquid_leaves_source, simulations, 31).
provenance(r11_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r11_liquid_leaves_source, confidence_permille, 839).
provenance(r11_liquid_leaves_source, score_permille, 813).
provenance(r11_liquid_leaves_source, batches, 1).

rule(r11_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r11_liquid_enters_destination, approach_moving_away).
body(r11_liquid_enters_destination, approach_raising).
body(r11_liquid_enters_destination, bouncy_source).
body(r11_liquid_enters_destination, dull_destination).
body(r11_liquid_enters_destination, dull_liquid).
body(r11_liquid_enters_destination, end_centred).
body(r11_liquid_enters_destination, end_rolled).
body(r11_liquid_enters_destination, end_steeply_tilted).
body(r11_liquid_enters_destination, end_very_high).
body(r11_liquid_enters_destination, grippy_destination).
body(r11_liquid_enters_destination, heavy_destination).
body(r11_liquid_enters_destination, heavy_source).
body(r11_liquid_enters_destination, light_liquid).
body(r11_liquid_enters_destination, moderate_retreat).
body(r11_liquid_enters_destination, pour_centred).
body(r11_liquid_enters_destination, pour_low).
body(r11_liquid_enters_destination, pour_tilted_back).
body(r11_liquid_enters_destination, slow_approach).
body(r11_liquid_enters_destination, start_tilted_back).
body(r11_liquid_enters_destination, sticky_liquid).
body(r11_liquid_enters_destination, very_much_liquid).
learned(r11_liquid_enters_destination).
provenance(r11_liquid_enters_destination, antecedent, a11).
provenance(r11_liquid_enters_destination, parent, a7).
provenance(r11_liquid_enters_destination, simulations, 31).
provenance(r11_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r11_liquid_enters_destination, confidence_permille, 774).
provenance(r11_liquid_enters_destination, score_permille, 287).
provenance(r11_liquid_enters_destination, batches, 1).

rule(r11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r11_liquid_remains_in_destination, approach_moving_away).
body(r11_liquid_remains_in_destination, approach_raising).
body(r11_liquid_remains_in_destination, bouncy_source).
body(r11_liquid_remains_in_destination, dull_destination).
body(r11_liquid_remains_in_destination, dull_liquid).
body(r11_liquid_remains_in_destination, end_centred).
body(r11_liquid_remains_in_destination, end_rolled).
body(r11_liquid_remains_in_destination, end_steeply_tilted).
body(r11_liquid_remains_in_destination, end_very_high).
body(r11_liquid_remains_in_destination, grippy_destination).
body(r11_liquid_remains_in_destination, heavy_destination).
body(r11_liquid_remains_in_destination, heavy_source).
body(r11_liquid_remains_in_destination, light_liquid).
body(r11_liquid_remains_in_destination, moderate_retreat).
body(r11_liquid_remains_in_destination, pour_centred).
body(r11_liquid_remains_in_destination, pour_low).
body(r11_liquid_remains_in_destination, pour_tilted_back).
body(r11_liquid_remains_in_destination, slow_approach).
body(r11_liquid_remains_in_destination, start_tilted_back).
body(r11_liquid_remains_in_destination, sticky_liquid).
body(r11_liquid_remains_in_destination, very_much_liquid).
learned(r11_liquid_remains_in_destination).
provenance(r11_liquid_remains_in_destination, antecedent, a11).
provenance(r11_liquid_remains_in_destination, parent, a7).
provenance(r11_liquid_remains_in_destination, simulations, 31).
provenance(r11_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r11_liquid_remains_in_destination, confidence_permille, 774).
provenance(r11_liquid_remains_in_destination, score_permille, 760).
provenance(r11_liquid_remains_in_destination, batches, 1).

rule(r11_no_spill, defeasible, neg(no_spill)).
body(r11_no_spill, approach_moving_away).
body(r11_no_spill, approach_raising).
body(r11_no_spill, bouncy_source).
body(r11_no_spill, dull_destination).
body(r11_no_spill, dull_liquid).
body(r11_no_spill, end_centred).
body(r11_no_spill, end_rolled).
body(r11_no_spill, end_steeply_tilted).
body(r11_no_spill, end_very_high).
body(r11_no_spill, grippy_destination).
body(r11_no_spill, heavy_destination).
body(r11_no_spill, heavy_source).
body(r11_no_spill, light_liquid).
body(r11_no_spill, moderate_retreat).
body(r11_no_spill, pour_centred).
body(r11_no_spill, pour_low).
body(r11_no_spill, pour_tilted_back).
body(r11_no_spill, slow_approach).
body(r11_no_spill, start_tilted_back).
body(r11_no_spill, sticky_liquid).
body(r11_no_spill, very_much_liquid).
learned(r11_no_spill).
provenance(r11_no_spill, antecedent, a11).
provenance(r11_no_spill, parent, a7).
provenance(r11_no_spill, simulations, 31).
provenance(r11_no_spill, weight_mass_permille, 31000).
provenance(r11_no_spill, confidence_permille, 774).
provenance(r11_no_spill, score_permille, 319).
provenance(r11_no_spill, batches, 1).

rule(r12_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r12_destination_still_approach, approach_moving_away).
body(r12_destination_still_approach, approach_raising).
body(r12_destination_still_approach, bouncy_source).
body(r12_destination_still_approach, dull_destination).
body(r12_destination_still_approach, dull_liquid).
body(r12_destination_still_approach, end_centred).
body(r12_destination_still_approach, end_rolled).
body(r12_destination_still_approach, end_upside_down).
body(r12_destination_still_approach, end_very_high).
body(r12_destination_still_approach, fast_approach).
body(r12_destination_still_approach, grippy_destination).
body(r12_destination_still_approach, heavy_destination).
body(r12_destination_still_approach, heavy_source).
body(r12_destination_still_approach, light_liquid).
body(r12_destination_still_approach, moderate_retreat).
body(r12_destination_still_approach, pour_level).
body(r12_destination_still_approach, pour_low).
body(r12_destination_still_approach, pour_near_rim).
body(r12_destination_still_approach, pour_tilted_back).
body(r12_destination_still_approach, start_tilted_back).
body(r12_destination_still_approach, sticky_liquid).
learned(r12_destination_still_approach).
provenance(r12_destination_still_approach, antecedent, a12).
provenance(r12_destination_still_approach, parent, a8).
provenance(r12_destination_still_approach, simulations, 31).
provenance(r12_destination_still_approach, weight_mass_permille, 31000).
provenance(r12_destination_still_approach, confidence_permille, 806).
provenance(r12_destination_still_approach, score_permille, 202).
provenance(r12_destination_still_approach, batches, 1).

rule(r12_destination_still_retreat, defeasible, destination_still_retreat).
body(r12_destination_still_retreat, approach_moving_away).
body(r12_destination_still_retreat, approach_raising).
body(r12_destination_still_retreat, bouncy_source).
body(r12_destination_still_retreat, dull_destination).
body(r12_destination_still_retreat, dull_liquid).
body(r12_destination_still_retreat, end_centred).
body(r12_destination_still_retreat, end_rolled).
body(r12_destination_still_retreat, end_upside_down).
body(r12_destination_still_retreat, end_very_high).
body(r12_destination_still_retreat, fast_approach).
body(r12_destination_still_retreat, grippy_destination).
body(r12_destination_still_retreat, heavy_destination).
body(r12_destination_still_retreat, heavy_source).
body(r12_destination_still_retreat, light_liquid).
body(r12_destination_still_retreat, moderate_retreat).
body(r12_destination_still_retreat, pour_level).
body(r12_destination_still_retreat, pour_low).
body(r12_destination_still_retreat, pour_near_rim).
body(r12_destination_still_retreat, pour_tilted_back).
body(r12_destination_still_retreat, start_tilted_back).
body(r12_destination_still_retreat, sticky_liquid).
learned(r12_destination_still_retreat).
provenance(r12_destination_still_retreat, antecedent, a12).
provenance(r12_destination_still_retreat, parent, a8).
provenance(r12_destination_still_retreat, simulations, 31).
provenance(r12_destination_still_retreat, weight_mass_permille, 31000).
provenance(r12_destination_still_retreat, confidence_permille, 710).
provenance(r12_destination_still_retreat, score_permille, 703).
provenance(r12_destination_still_retreat, batches, 1).

rule(r12_destination_still_settle, defeasible, destination_still_settle).
body(r12_destination_still_settle, approach_moving_away).
body(r12_destination_still_settle, approach_raising).
body(r12_destination_still_settle, bouncy_source).
body(r12_destination_still_settle, dull_destination).
body(r12_destination_still_settle, dull_liquid).
body(r12_destination_still_settle, end_centred).
body(r12_destination_still_settle, end_rolled).
body(r12_destination_still_settle, end_upside_down).
body(r12_destination_still_settle, end_very_high).
body(r12_destination_still_settle, fast_approach).
body(r12_destination_still_settle, grippy_destination).
body(r12_destination_still_settle, heavy_destination).
body(r12_destination_still_settle, heavy_source).
body(r12_destination_still_settle, light_liquid).
body(r12_destination_still_settle, moderate_retreat).
body(r12_destination_still_settle, pour_level).
body(r12_destination_still_settle, pour_low).
body(r12_destination_still_settle, pour_near_rim).
body(r12_destination_still_settle, pour_tilted_back).
body(r12_destination_still_settle, start_tilted_back).
body(r12_destination_still_settle, sticky_liquid).
learned(r12_destination_still_settle).
provenance(r12_destination_still_settle, antecedent, a12).
provenance(r12_destination_still_settle, parent, a8).
provenance(r12_destination_still_settle, simulations, 31).
provenance(r12_destination_still_settle, weight_mass_permille, 31000).
provenance(r12_destination_still_settle, confidence_permille, 903).
provenance(r12_destination_still_settle, score_permille, 891).
provenance(r12_destination_still_settle, batches, 1).

rule(r12_destination_upright, defeasible, destination_upright).
body(r12_destination_upright, approach_moving_away).
body(r12_destination_upright, approach_raising).
body(r12_destination_upright, bouncy_source).
body(r12_destination_upright, dull_destination).
body(r12_destination_upright, dull_liquid).
body(r12_destination_upright, end_centred).
body(r12_destination_upright, end_rolled).
body(r12_destination_upright, end_upside_down).
body(r12_destination_upright, end_very_high).
body(r12_destination_upright, fast_approach).
body(r12_destination_upright, grippy_destination).
body(r12_destination_upright, heavy_destination).
body(r12_destination_upright, heavy_source).
body(r12_destination_upright, light_liquid).
body(r12_destination_upright, moderate_retreat).
body(r12_destination_upright, pour_level).
body(r12_destination_upright, pour_low).
body(r12_destination_upright, pour_near_rim).
body(r12_destination_upright, pour_tilted_back).
body(r12_destination_upright, start_tilted_back).
body(r12_destination_upright, sticky_liquid).
learned(r12_destination_upright).
provenance(r12_destination_upright, antecedent, a12).
provenance(r12_destination_upright, parent, a8).
provenance(r12_destination_upright, simulations, 31).
provenance(r12_destination_upright, weight_mass_permille, 31000).
provenance(r12_destination_upright, confidence_permille, 871).
provenance(r12_destination_upright, score_permille, 871).
provenance(r12_destination_upright, batches, 1).

rule(r12_source_clear, defeasible, neg(source_clear)).
body(r12_source_clear, approach_moving_away).
body(r12_source_clear, approach_raising).
body(r12_source_clear, bouncy_source).
body(r12_source_clear, dull_destination).
body(r12_source_clear, dull_liquid).
body(r12_source_clear, end_centred).
body(r12_source_clear, end_rolled).
body(r12_source_clear, end_upside_down).
body(r12_source_clear, end_very_high).
body(r12_source_clear, fast_approach).
body(r12_source_clear, grippy_destination).
body(r12_source_clear, heavy_destination).
body(r12_source_clear, heavy_source).
body(r12_source_clear, light_liquid).
body(r12_source_clear, moderate_retreat).
body(r12_source_clear, pour_level).
body(r12_source_clear, pour_low).
body(r12_source_clear, pour_near_rim).
body(r12_source_clear, pour_tilted_back).
body(r12_source_clear, start_tilted_back).
body(r12_source_clear, sticky_liquid).
learned(r12_source_clear).
provenance(r12_source_clear, antecedent, a12).
provenance(r12_source_clear, parent, a8).
provenance(r12_source_clear, simulations, 31).
provenance(r12_source_clear, weight_mass_permille, 31000).
provenance(r12_source_clear, confidence_permille, 871).
provenance(r12_source_clear, score_permille, 113).
provenance(r12_source_clear, batches, 1).

rule(r12_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r12_liquid_leaves_source, approach_moving_away).
body(r12_liquid_leaves_source, approach_raising).
body(r12_liquid_leaves_source, bouncy_source).
body(r12_liquid_leaves_source, dull_destination).
body(r12_liquid_leaves_source, dull_liquid).
body(r12_liquid_leaves_source, end_centred).
body(r12_liquid_leaves_source, end_rolled).
body(r12_liquid_leaves_source, end_upside_down).
body(r12_liquid_leaves_source, end_very_high).
body(r12_liquid_leaves_source, fast_approach).
body(r12_liquid_leaves_source, grippy_destination).
body(r12_liquid_leaves_source, heavy_destination).
body(r12_liquid_leaves_source, heavy_source).
body(r12_liquid_leaves_source, light_liquid).
body(r12_liquid_leaves_source, moderate_retreat).
body(r12_liquid_leaves_source, pour_level).
body(r12_liquid_leaves_source, pour_low).
body(r12_liquid_leaves_source, pour_near_rim).
body(r12_liquid_leaves_source, pour_tilted_back).
body(r12_liquid_leaves_source, start_tilted_back).
body(r12_liquid_leaves_source, sticky_liquid).
learned(r12_liquid_leaves_source).
provenance(r12_liquid_leaves_source, antecedent, a12).
provenance(r12_liquid_leaves_source, parent, a8).
provenance(r12_liquid_leaves_source, simulations, 31).
provenance(r12_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r12_liquid_leaves_source, confidence_permille, 1000).
provenance(r12_liquid_leaves_source, score_permille, 1000).
provenance(r12_liquid_leaves_source, batches, 1).

rule(r12_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r12_liquid_enters_destination, approach_moving_away).
body(r12_liquid_enters_destination, approach_raising).
body(r12_liquid_enters_destination, bouncy_source).
body(r12_liquid_enters_destination, dull_destination).
body(r12_liquid_enters_destination, dull_liquid).
body(r12_liquid_enters_destination, end_centred).
body(r12_liquid_enters_destination, end_rolled).
body(r12_liquid_enters_destination, end_upside_down).
body(r12_liquid_enters_destination, end_very_high).
body(r12_liquid_enters_destination, fast_approach).
body(r12_liquid_enters_destination, grippy_destination).
body(r12_liquid_enters_destination, heavy_destination).
body(r12_liquid_enters_destination, heavy_source).
body(r12_liquid_enters_destination, light_liquid).
body(r12_liquid_enters_destination, moderate_retreat).
body(r12_liquid_enters_destination, pour_level).
body(r12_liquid_enters_destination, pour_low).
body(r12_liquid_enters_destination, pour_near_rim).
body(r12_liquid_enters_destination, pour_tilted_back).
body(r12_liquid_enters_destination, start_tilted_back).
body(r12_liquid_enters_destination, sticky_liquid).
learned(r12_liquid_enters_destination).
provenance(r12_liquid_enters_destination, antecedent, a12).
provenance(r12_liquid_enters_destination, parent, a8).
provenance(r12_liquid_enters_destination, simulations, 31).
provenance(r12_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r12_liquid_enters_destination, confidence_permille, 839).
provenance(r12_liquid_enters_destination, score_permille, 808).
provenance(r12_liquid_enters_destination, batches, 1).

rule(r12_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r12_liquid_remains_in_destination, approach_moving_away).
body(r12_liquid_remains_in_destination, approach_raising).
body(r12_liquid_remains_in_destination, bouncy_source).
body(r12_liquid_remains_in_destination, dull_destination).
body(r12_liquid_remains_in_destination, dull_liquid).
body(r12_liquid_remains_in_destination, end_centred).
body(r12_liquid_remains_in_destination, end_rolled).
body(r12_liquid_remains_in_destination, end_upside_down).
body(r12_liquid_remains_in_destination, end_very_high).
body(r12_liquid_remains_in_destination, fast_approach).
body(r12_liquid_remains_in_destination, grippy_destination).
body(r12_liquid_remains_in_destination, heavy_destination).
body(r12_liquid_remains_in_destination, heavy_source).
body(r12_liquid_remains_in_destination, light_liquid).
body(r12_liquid_remains_in_destination, moderate_retreat).
body(r12_liquid_remains_in_destination, pour_level).
body(r12_liquid_remains_in_destination, pour_low).
body(r12_liquid_remains_in_destination, pour_near_rim).
body(r12_liquid_remains_in_destination, pour_tilted_back).
body(r12_liquid_remains_in_destination, start_tilted_back).
body(r12_liquid_remains_in_destination, sticky_liquid).
learned(r12_liquid_remains_in_destination).
provenance(r12_liquid_remains_in_destination, antecedent, a12).
provenance(r12_liquid_remains_in_destination, parent, a8).
provenance(r12_liquid_remains_in_destination, simulations, 31).
provenance(r12_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r12_liquid_remains_in_destination, confidence_permille, 613).
provenance(r12_liquid_remains_in_destination, score_permille, 409).
provenance(r12_liquid_remains_in_destination, batches, 1).

rule(r12_no_spill, defeasible, neg(no_spill)).
body(r12_no_spill, approach_moving_away).
body(r12_no_spill, approach_raising).
body(r12_no_spill, bouncy_source).
body(r12_no_spill, dull_destination).
body(r12_no_spill, dull_liquid).
body(r12_no_spill, end_centred).
body(r12_no_spill, end_rolled).
body(r12_no_spill, end_upside_down).
body(r12_no_spill, end_very_high).
body(r12_no_spill, fast_approach).
body(r12_no_spill, grippy_destination).
body(r12_no_spill, heavy_destination).
body(r12_no_spill, heavy_source).
body(r12_no_spill, light_liquid).
body(r12_no_spill, moderate_retreat).
body(r12_no_spill, pour_level).
body(r12_no_spill, pour_low).
body(r12_no_spill, pour_near_rim).
body(r12_no_spill, pour_tilted_back).
body(r12_no_spill, start_tilted_back).
body(r12_no_spill, sticky_liquid).
learned(r12_no_spill).
provenance(r12_no_spill, antecedent, a12).
provenance(r12_no_spill, parent, a8).
provenance(r12_no_spill, simulations, 31).
provenance(r12_no_spill, weight_mass_permille, 31000).
provenance(r12_no_spill, confidence_permille, 774).
provenance(r12_no_spill, score_permille, 277).
provenance(r12_no_spill, batches, 1).

rule(r13_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r13_destination_still_approach, approach_moving_away).
body(r13_destination_still_approach, bouncy_liquid).
body(r13_destination_still_approach, dull_destination).
body(r13_destination_still_approach, end_steeply_tilted).
body(r13_destination_still_approach, end_to_side).
body(r13_destination_still_approach, fast_retreat).
body(r13_destination_still_approach, grippy_source).
body(r13_destination_still_approach, heavy_liquid).
body(r13_destination_still_approach, light_destination).
body(r13_destination_still_approach, little_liquid).
body(r13_destination_still_approach, pour_in_line).
body(r13_destination_still_approach, pour_mid_height).
body(r13_destination_still_approach, pour_tilted_back).
body(r13_destination_still_approach, pour_to_side).
body(r13_destination_still_approach, retreat_lowering).
body(r13_destination_still_approach, runny_liquid).
body(r13_destination_still_approach, slippery_destination).
body(r13_destination_still_approach, start_below_rim).
body(r13_destination_still_approach, start_slightly_tilted).
learned(r13_destination_still_approach).
provenance(r13_destination_still_approach, antecedent, a13).
provenance(r13_destination_still_approach, parent, none).
provenance(r13_destination_still_approach, simulations, 39).
provenance(r13_destination_still_approach, weight_mass_permille, 39000).
provenance(r13_destination_still_approach, confidence_permille, 718).
provenance(r13_destination_still_approach, score_permille, 276).
provenance(r13_destination_still_approach, batches, 1).

rule(r13_destination_still_retreat, defeasible, destination_still_retreat).
body(r13_destination_still_retreat, approach_moving_away).
body(r13_destination_still_retreat, bouncy_liquid).
body(r13_destination_still_retreat, dull_destination).
body(r13_destination_still_retreat, end_steeply_tilted).
body(r13_destination_still_retreat, end_to_side).
body(r13_destination_still_retreat, fast_retreat).
body(r13_destination_still_retreat, grippy_source).
body(r13_destination_still_retreat, heavy_liquid).
body(r13_destination_still_retreat, light_destination).
body(r13_destination_still_retreat, little_liquid).
body(r13_destination_still_retreat, pour_in_line).
body(r13_destination_still_retreat, pour_mid_height).
body(r13_destination_still_retreat, pour_tilted_back).
body(r13_destination_still_retreat, pour_to_side).
body(r13_destination_still_retreat, retreat_lowering).
body(r13_destination_still_retreat, runny_liquid).
body(r13_destination_still_retreat, slippery_destination).
body(r13_destination_still_retreat, start_below_rim).
body(r13_destination_still_retreat, start_slightly_tilted).
learned(r13_destination_still_retreat).
provenance(r13_destination_still_retreat, antecedent, a13).
provenance(r13_destination_still_retreat, parent, none).
provenance(r13_destination_still_retreat, simulations, 39).
provenance(r13_destination_still_retreat, weight_mass_permille, 39000).
provenance(r13_destination_still_retreat, confidence_permille, 538).
provenance(r13_destination_still_retreat, score_permille, 510).
provenance(r13_destination_still_retreat, batches, 1).

rule(r13_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r13_destination_still_settle, approach_moving_away).
body(r13_destination_still_settle, bouncy_liquid).
body(r13_destination_still_settle, dull_destination).
body(r13_destination_still_settle, end_steeply_tilted).
body(r13_destination_still_settle, end_to_side).
body(r13_destination_still_settle, fast_retreat).
body(r13_destination_still_settle, grippy_source).
body(r13_destination_still_settle, heavy_liquid).
body(r13_destination_still_settle, light_destination).
body(r13_destination_still_settle, little_liquid).
body(r13_destination_still_settle, pour_in_line).
body(r13_destination_still_settle, pour_mid_height).
body(r13_destination_still_settle, pour_tilted_back).
body(r13_destination_still_settle, pour_to_side).
body(r13_destination_still_settle, retreat_lowering).
body(r13_destination_still_settle, runny_liquid).
body(r13_destination_still_settle, slippery_destination).
body(r13_destination_still_settle, start_below_rim).
body(r13_destination_still_settle, start_slightly_tilted).
learned(r13_destination_still_settle).
provenance(r13_destination_still_settle, antecedent, a13).
provenance(r13_destination_still_settle, parent, none).
provenance(r13_destination_still_settle, simulations, 39).
provenance(r13_destination_still_settle, weight_mass_permille, 39000).
provenance(r13_destination_still_settle, confidence_permille, 615).
provenance(r13_destination_still_settle, score_permille, 360).
provenance(r13_destination_still_settle, batches, 1).

rule(r13_destination_upright, defeasible, destination_upright).
body(r13_destination_upright, approach_moving_away).
body(r13_destination_upright, bouncy_liquid).
body(r13_destination_upright, dull_destination).
body(r13_destination_upright, end_steeply_tilted).
body(r13_destination_upright, end_to_side).
body(r13_destination_upright, fast_retreat).
body(r13_destination_upright, grippy_source).
body(r13_destination_upright, heavy_liquid).
body(r13_destination_upright, light_destination).
body(r13_destination_upright, little_liquid).
body(r13_destination_upright, pour_in_line).
body(r13_destination_upright, pour_mid_height).
body(r13_destination_upright, pour_tilted_back).
body(r13_destination_upright, pour_to_side).
body(r13_destination_upright, retreat_lowering).
body(r13_destination_upright, runny_liquid).
body(r13_destination_upright, slippery_destination).
body(r13_destination_upright, start_below_rim).
body(r13_destination_upright, start_slightly_tilted).
learned(r13_destination_upright).
provenance(r13_destination_upright, antecedent, a13).
provenance(r13_destination_upright, parent, none).
provenance(r13_destination_upright, simulations, 39).
provenance(r13_destination_upright, weight_mass_permille, 39000).
provenance(r13_destination_upright, confidence_permille, 821).
provenance(r13_destination_upright, score_permille, 840).
provenance(r13_destination_upright, batches, 1).

rule(r13_source_clear, defeasible, neg(source_clear)).
body(r13_source_clear, approach_moving_away).
body(r13_source_clear, bouncy_liquid).
body(r13_source_clear, dull_destination).
body(r13_source_clear, end_steeply_tilted).
body(r13_source_clear, end_to_side).
body(r13_source_clear, fast_retreat).
body(r13_source_clear, grippy_source).
body(r13_source_clear, heavy_liquid).
body(r13_source_clear, light_destination).
body(r13_source_clear, little_liquid).
body(r13_source_clear, pour_in_line).
body(r13_source_clear, pour_mid_height).
body(r13_source_clear, pour_tilted_back).
body(r13_source_clear, pour_to_side).
body(r13_source_clear, retreat_lowering).
body(r13_source_clear, runny_liquid).
body(r13_source_clear, slippery_destination).
body(r13_source_clear, start_below_rim).
body(r13_source_clear, start_slightly_tilted).
learned(r13_source_clear).
provenance(r13_source_clear, antecedent, a13).
provenance(r13_source_clear, parent, none).
provenance(r13_source_clear, simulations, 39).
provenance(r13_source_clear, weight_mass_permille, 39000).
provenance(r13_source_clear, confidence_permille, 846).
provenance(r13_source_clear, score_permille, 116).
provenance(r13_source_clear, batches, 1).

rule(r13_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r13_liquid_leaves_source, approach_moving_away).
body(r13_liquid_leaves_source, bouncy_liquid).
body(r13_liquid_leaves_source, dull_destination).
body(r13_liquid_leaves_source, end_steeply_tilted).
body(r13_liquid_leaves_source, end_to_side).
body(r13_liquid_leaves_source, fast_retreat).
body(r13_liquid_leaves_source, grippy_source).
body(r13_liquid_leaves_source, heavy_liquid).
body(r13_liquid_leaves_source, light_destination).
body(r13_liquid_leaves_source, little_liquid).
body(r13_liquid_leaves_source, pour_in_line).
body(r13_liquid_leaves_source, pour_mid_height).
body(r13_liquid_leaves_source, pour_tilted_back).
body(r13_liquid_leaves_source, pour_to_side).
body(r13_liquid_leaves_source, retreat_lowering).
body(r13_liquid_leaves_source, runny_liquid).
body(r13_liquid_leaves_source, slippery_destination).
body(r13_liquid_leaves_source, start_below_rim).
body(r13_liquid_leaves_source, start_slightly_tilted).
learned(r13_liquid_leaves_source).
provenance(r13_liquid_leaves_source, antecedent, a13).
provenance(r13_liquid_leaves_source, parent, none).
provenance(r13_liquid_leaves_source, simulations, 39).
provenance(r13_liquid_leaves_source, weight_mass_permille, 39000).
provenance(r13_liquid_leaves_source, confidence_permille, 718).
provenance(r13_liquid_leaves_source, score_permille, 726).
provenance(r13_liquid_leaves_source, batches, 1).

rule(r13_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r13_liquid_enters_destination, approach_moving_away).
body(r13_liquid_enters_destination, bouncy_liquid).
body(r13_liquid_enters_destination, dull_destination).
body(r13_liquid_enters_destination, end_steeply_tilted).
body(r13_liquid_enters_destination, end_to_side).
body(r13_liquid_enters_destination, fast_retreat).
body(r13_liquid_enters_destination, grippy_source).
body(r13_liquid_enters_destination, heavy_liquid).
body(r13_liquid_enters_destination, light_destination).
body(r13_liquid_enters_destination, little_liquid).
body(r13_liquid_enters_destination, pour_in_line).
body(r13_liquid_enters_destination, pour_mid_height).
body(r13_liquid_enters_destination, pour_tilted_back).
body(r13_liquid_enters_destination, pour_to_side).
body(r13_liquid_enters_destination, retreat_lowering).
body(r13_liquid_enters_destination, runny_liquid).
body(r13_liquid_enters_destination, slippery_destination).
body(r13_liquid_enters_destination, start_below_rim).
body(r13_liquid_enters_destination, start_slightly_tilted).
learned(r13_liquid_enters_destination).
provenance(r13_liquid_enters_destination, antecedent, a13).
provenance(r13_liquid_enters_destination, parent, none).
provenance(r13_liquid_enters_destination, simulations, 39).
provenance(r13_liquid_enters_destination, weight_mass_permille, 39000).
provenance(r13_liquid_enters_destination, confidence_permille, 692).
provenance(r13_liquid_enters_destination, score_permille, 697).
provenance(r13_liquid_enters_destination, batches, 1).

rule(r13_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r13_liquid_remains_in_destination, approach_moving_away).
body(r13_liquid_remains_in_destination, bouncy_liquid).
body(r13_liquid_remains_in_destination, dull_destination).
body(r13_liquid_remains_in_destination, end_steeply_tilted).
body(r13_liquid_remains_in_destination, end_to_side).
body(r13_liquid_remains_in_destination, fast_retreat).
body(r13_liquid_remains_in_destination, grippy_source).
body(r13_liquid_remains_in_destination, heavy_liquid).
body(r13_liquid_remains_in_destination, light_destination).
body(r13_liquid_remains_in_destination, little_liquid).
body(r13_liquid_remains_in_destination, pour_in_line).
body(r13_liquid_remains_in_destination, pour_mid_height).
body(r13_liquid_remains_in_destination, pour_tilted_back).
body(r13_liquid_remains_in_destination, pour_to_side).
body(r13_liquid_remains_in_destination, retreat_lowering).
body(r13_liquid_remains_in_destination, runny_liquid).
body(r13_liquid_remains_in_destination, slippery_destination).
body(r13_liquid_remains_in_destination, start_below_rim).
body(r13_liquid_remains_in_destination, start_slightly_tilted).
learned(r13_liquid_remains_in_destination).
provenance(r13_liquid_remains_in_destination, antecedent, a13).
provenance(r13_liquid_remains_in_destination, parent, none).
provenance(r13_liquid_remains_in_destination, simulations, 39).
provenance(r13_liquid_remains_in_destination, weight_mass_permille, 39000).
provenance(r13_liquid_remains_in_destination, confidence_permille, 538).
provenance(r13_liquid_remains_in_destination, score_permille, 472).
provenance(r13_liquid_remains_in_destination, batches, 1).

rule(r13_no_spill, defeasible, no_spill).
body(r13_no_spill, approach_moving_away).
body(r13_no_spill, bouncy_liquid).
body(r13_no_spill, dull_destination).
body(r13_no_spill, end_steeply_tilted).
body(r13_no_spill, end_to_side).
body(r13_no_spill, fast_retreat).
body(r13_no_spill, grippy_source).
body(r13_no_spill, heavy_liquid).
body(r13_no_spill, light_destination).
body(r13_no_spill, little_liquid).
body(r13_no_spill, pour_in_line).
body(r13_no_spill, pour_mid_height).
body(r13_no_spill, pour_tilted_back).
body(r13_no_spill, pour_to_side).
body(r13_no_spill, retreat_lowering).
body(r13_no_spill, runny_liquid).
body(r13_no_spill, slippery_destination).
body(r13_no_spill, start_below_rim).
body(r13_no_spill, start_slightly_tilted).
learned(r13_no_spill).
provenance(r13_no_spill, antecedent, a13).
provenance(r13_no_spill, parent, none).
provenance(r13_no_spill, simulations, 39).
provenance(r13_no_spill, weight_mass_permille, 39000).
provenance(r13_no_spill, confidence_permille, 564).
provenance(r13_no_spill, score_permille, 534).
provenance(r13_no_spill, batches, 1).

rule(r14_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r14_destination_still_approach, approach_moving_away).
body(r14_destination_still_approach, bouncy_liquid).
body(r14_destination_still_approach, dull_destination).
body(r14_destination_still_approach, end_steeply_tilted).
body(r14_destination_still_approach, end_to_side).
body(r14_destination_still_approach, fast_retreat).
body(r14_destination_still_approach, grippy_source).
body(r14_destination_still_approach, heavy_liquid).
body(r14_destination_still_approach, light_destination).
body(r14_destination_still_approach, little_liquid).
body(r14_destination_still_approach, pour_far_away).
body(r14_destination_still_approach, pour_in_line).
body(r14_destination_still_approach, pour_mid_height).
body(r14_destination_still_approach, pour_tilted_back).
body(r14_destination_still_approach, retreat_lowering).
body(r14_destination_still_approach, runny_liquid).
body(r14_destination_still_approach, slippery_destination).
body(r14_destination_still_approach, start_below_rim).
body(r14_destination_still_approach, start_slightly_tilted).
learned(r14_destination_still_approach).
provenance(r14_destination_still_approach, antecedent, a14).
provenance(r14_destination_still_approach, parent, a13).
provenance(r14_destination_still_approach, simulations, 31).
provenance(r14_destination_still_approach, weight_mass_permille, 31000).
provenance(r14_destination_still_approach, confidence_permille, 516).
provenance(r14_destination_still_approach, score_permille, 492).
provenance(r14_destination_still_approach, batches, 1).

rule(r14_destination_still_retreat, defeasible, destination_still_retreat).
body(r14_destination_still_retreat, approach_moving_away).
body(r14_destination_still_retreat, bouncy_liquid).
body(r14_destination_still_retreat, dull_destination).
body(r14_destination_still_retreat, end_steeply_tilted).
body(r14_destination_still_retreat, end_to_side).
body(r14_destination_still_retreat, fast_retreat).
body(r14_destination_still_retreat, grippy_source).
body(r14_destination_still_retreat, heavy_liquid).
body(r14_destination_still_retreat, light_destination).
body(r14_destination_still_retreat, little_liquid).
body(r14_destination_still_retreat, pour_far_away).
body(r14_destination_still_retreat, pour_in_line).
body(r14_destination_still_retreat, pour_mid_height).
body(r14_destination_still_retreat, pour_tilted_back).
body(r14_destination_still_retreat, retreat_lowering).
body(r14_destination_still_retreat, runny_liquid).
body(r14_destination_still_retreat, slippery_destination).
body(r14_destination_still_retreat, start_below_rim).
body(r14_destination_still_retreat, start_slightly_tilted).
learned(r14_destination_still_retreat).
provenance(r14_destination_still_retreat, antecedent, a14).
provenance(r14_destination_still_retreat, parent, a13).
provenance(r14_destination_still_retreat, simulations, 31).
provenance(r14_destination_still_retreat, weight_mass_permille, 31000).
provenance(r14_destination_still_retreat, confidence_permille, 613).
provenance(r14_destination_still_retreat, score_permille, 614).
provenance(r14_destination_still_retreat, batches, 1).

rule(r14_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r14_destination_still_settle, approach_moving_away).
body(r14_destination_still_settle, bouncy_liquid).
body(r14_destination_still_settle, dull_destination).
body(r14_destination_still_settle, end_steeply_tilted).
body(r14_destination_still_settle, end_to_side).
body(r14_destination_still_settle, fast_retreat).
body(r14_destination_still_settle, grippy_source).
body(r14_destination_still_settle, heavy_liquid).
body(r14_destination_still_settle, light_destination).
body(r14_destination_still_settle, little_liquid).
body(r14_destination_still_settle, pour_far_away).
body(r14_destination_still_settle, pour_in_line).
body(r14_destination_still_settle, pour_mid_height).
body(r14_destination_still_settle, pour_tilted_back).
body(r14_destination_still_settle, retreat_lowering).
body(r14_destination_still_settle, runny_liquid).
body(r14_destination_still_settle, slippery_destination).
body(r14_destination_still_settle, start_below_rim).
body(r14_destination_still_settle, start_slightly_tilted).
learned(r14_destination_still_settle).
provenance(r14_destination_still_settle, antecedent, a14).
provenance(r14_destination_still_settle, parent, a13).
provenance(r14_destination_still_settle, simulations, 31).
provenance(r14_destination_still_settle, weight_mass_permille, 31000).
provenance(r14_destination_still_settle, confidence_permille, 710).
provenance(r14_destination_still_settle, score_permille, 278).
provenance(r14_destination_still_settle, batches, 1).

rule(r14_destination_upright, defeasible, destination_upright).
body(r14_destination_upright, approach_moving_away).
body(r14_destination_upright, bouncy_liquid).
body(r14_destination_upright, dull_destination).
body(r14_destination_upright, end_steeply_tilted).
body(r14_destination_upright, end_to_side).
body(r14_destination_upright, fast_retreat).
body(r14_destination_upright, grippy_source).
body(r14_destination_upright, heavy_liquid).
body(r14_destination_upright, light_destination).
body(r14_destination_upright, little_liquid).
body(r14_destination_upright, pour_far_away).
body(r14_destination_upright, pour_in_line).
body(r14_destination_upright, pour_mid_height).
body(r14_destination_upright, pour_tilted_back).
body(r14_destination_upright, retreat_lowering).
body(r14_destination_upright, runny_liquid).
body(r14_destination_upright, slippery_destination).
body(r14_destination_upright, start_below_rim).
body(r14_destination_upright, start_slightly_tilted).
learned(r14_destination_upright).
provenance(r14_destination_upright, antecedent, a14).
provenance(r14_destination_upright, parent, a13).
provenance(r14_destination_upright, simulations, 31).
provenance(r14_destination_upright, weight_mass_permille, 31000).
provenance(r14_destination_upright, confidence_permille, 968).
provenance(r14_destination_upright, score_permille, 967).
provenance(r14_destination_upright, batches, 1).

rule(r14_source_clear, defeasible, neg(source_clear)).
body(r14_source_clear, approach_moving_away).
body(r14_source_clear, bouncy_liquid).
body(r14_source_clear, dull_destination).
body(r14_source_clear, end_steeply_tilted).
body(r14_source_clear, end_to_side).
body(r14_source_clear, fast_retreat).
body(r14_source_clear, grippy_source).
body(r14_source_clear, heavy_liquid).
body(r14_source_clear, light_destination).
body(r14_source_clear, little_liquid).
body(r14_source_clear, pour_far_away).
body(r14_source_clear, pour_in_line).
body(r14_source_clear, pour_mid_height).
body(r14_source_clear, pour_tilted_back).
body(r14_source_clear, retreat_lowering).
body(r14_source_clear, runny_liquid).
body(r14_source_clear, slippery_destination).
body(r14_source_clear, start_below_rim).
body(r14_source_clear, start_slightly_tilted).
learned(r14_source_clear).
provenance(r14_source_clear, antecedent, a14).
provenance(r14_source_clear, parent, a13).
provenance(r14_source_clear, simulations, 31).
provenance(r14_source_clear, weight_mass_permille, 31000).
provenance(r14_source_clear, confidence_permille, 516).
provenance(r14_source_clear, score_permille, 448).
provenance(r14_source_clear, batches, 1).

rule(r14_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r14_liquid_leaves_source, approach_moving_away).
body(r14_liquid_leaves_source, bouncy_liquid).
body(r14_liquid_leaves_source, dull_destination).
body(r14_liquid_leaves_source, end_steeply_tilted).
body(r14_liquid_leaves_source, end_to_side).
body(r14_liquid_leaves_source, fast_retreat).
body(r14_liquid_leaves_source, grippy_source).
body(r14_liquid_leaves_source, heavy_liquid).
body(r14_liquid_leaves_source, light_destination).
body(r14_liquid_leaves_source, little_liquid).
body(r14_liquid_leaves_source, pour_far_away).
body(r14_liquid_leaves_source, pour_in_line).
body(r14_liquid_leaves_source, pour_mid_height).
body(r14_liquid_leaves_source, pour_tilted_back).
body(r14_liquid_leaves_source, retreat_lowering).
body(r14_liquid_leaves_source, runny_liquid).
body(r14_liquid_leaves_source, slippery_destination).
body(r14_liquid_leaves_source, start_below_rim).
body(r14_liquid_leaves_source, start_slightly_tilted).
learned(r14_liquid_leaves_source).
provenance(r14_liquid_leaves_source, antecedent, a14).
provenance(r14_liquid_leaves_source, parent, a13).
provenance(r14_liquid_leaves_source, simulations, 31).
provenance(r14_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r14_liquid_leaves_source, confidence_permille, 839).
provenance(r14_liquid_leaves_source, score_permille, 817).
provenance(r14_liquid_leaves_source, batches, 1).

rule(r14_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r14_liquid_enters_destination, approach_moving_away).
body(r14_liquid_enters_destination, bouncy_liquid).
body(r14_liquid_enters_destination, dull_destination).
body(r14_liquid_enters_destination, end_steeply_tilted).
body(r14_liquid_enters_destination, end_to_side).
body(r14_liquid_enters_destination, fast_retreat).
body(r14_liquid_enters_destination, grippy_source).
body(r14_liquid_enters_destination, heavy_liquid).
body(r14_liquid_enters_destination, light_destination).
body(r14_liquid_enters_destination, little_liquid).
body(r14_liquid_enters_destination, pour_far_away).
body(r14_liquid_enters_destination, pour_in_line).
body(r14_liquid_enters_destination, pour_mid_height).
body(r14_liquid_enters_destination, pour_tilted_back).
body(r14_liquid_enters_destination, retreat_lowering).
body(r14_liquid_enters_destination, runny_liquid).
body(r14_liquid_enters_destination, slippery_destination).
body(r14_liquid_enters_destination, start_below_rim).
body(r14_liquid_enters_destination, start_slightly_tilted).
learned(r14_liquid_enters_destination).
provenance(r14_liquid_enters_destination, antecedent, a14).
provenance(r14_liquid_enters_destination, parent, a13).
provenance(r14_liquid_enters_destination, simulations, 31).
provenance(r14_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r14_liquid_enters_destination, confidence_permille, 871).
provenance(r14_liquid_enters_destination, score_permille, 142).
provenance(r14_liquid_enters_destination, batches, 1).

rule(r14_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r14_liquid_remains_in_destination, approach_moving_away).
body(r14_liquid_remains_in_destination, bouncy_liquid).
body(r14_liquid_remains_in_destination, dull_destination).
body(r14_liquid_remains_in_destination, end_steeply_tilted).
body(r14_liquid_remains_in_destination, end_to_side).
body(r14_liquid_remains_in_destination, fast_retreat).
body(r14_liquid_remains_in_destination, grippy_source).
body(r14_liquid_remains_in_destination, heavy_liquid).
body(r14_liquid_remains_in_destination, light_destination).
body(r14_liquid_remains_in_destination, little_liquid).
body(r14_liquid_remains_in_destination, pour_far_away).
body(r14_liquid_remains_in_destination, pour_in_line).
body(r14_liquid_remains_in_destination, pour_mid_height).
body(r14_liquid_remains_in_destination, pour_tilted_back).
body(r14_liquid_remains_in_destination, retreat_lowering).
body(r14_liquid_remains_in_destination, runny_liquid).
body(r14_liquid_remains_in_destination, slippery_destination).
body(r14_liquid_remains_in_destination, start_below_rim).
body(r14_liquid_remains_in_destination, start_slightly_tilted).
learned(r14_liquid_remains_in_destination).
provenance(r14_liquid_remains_in_destination, antecedent, a14).
provenance(r14_liquid_remains_in_destination, parent, a13).
provenance(r14_liquid_remains_in_destination, simulations, 31).
provenance(r14_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r14_liquid_remains_in_destination, confidence_permille, 903).
provenance(r14_liquid_remains_in_destination, score_permille, 898).
provenance(r14_liquid_remains_in_destination, batches, 1).

rule(r14_no_spill, defeasible, neg(no_spill)).
body(r14_no_spill, approach_moving_away).
body(r14_no_spill, bouncy_liquid).
body(r14_no_spill, dull_destination).
body(r14_no_spill, end_steeply_tilted).
body(r14_no_spill, end_to_side).
body(r14_no_spill, fast_retreat).
body(r14_no_spill, grippy_source).
body(r14_no_spill, heavy_liquid).
body(r14_no_spill, light_destination).
body(r14_no_spill, little_liquid).
body(r14_no_spill, pour_far_away).
body(r14_no_spill, pour_in_line).
body(r14_no_spill, pour_mid_height).
body(r14_no_spill, pour_tilted_back).
body(r14_no_spill, retreat_lowering).
body(r14_no_spill, runny_liquid).
body(r14_no_spill, slippery_destination).
body(r14_no_spill, start_below_rim).
body(r14_no_spill, start_slightly_tilted).
learned(r14_no_spill).
provenance(r14_no_spill, antecedent, a14).
provenance(r14_no_spill, parent, a13).
provenance(r14_no_spill, simulations, 31).
provenance(r14_no_spill, weight_mass_permille, 31000).
provenance(r14_no_spill, confidence_permille, 774).
provenance(r14_no_spill, score_permille, 254).
provenance(r14_no_spill, batches, 1).

rule(r15_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r15_destination_still_approach, approach_moving_away).
body(r15_destination_still_approach, bouncy_liquid).
body(r15_destination_still_approach, dull_destination).
body(r15_destination_still_approach, end_rolled).
body(r15_destination_still_approach, end_steeply_tilted).
body(r15_destination_still_approach, end_to_side).
body(r15_destination_still_approach, fast_retreat).
body(r15_destination_still_approach, grippy_source).
body(r15_destination_still_approach, heavy_liquid).
body(r15_destination_still_approach, light_destination).
body(r15_destination_still_approach, little_liquid).
body(r15_destination_still_approach, pour_in_line).
body(r15_destination_still_approach, pour_mid_height).
body(r15_destination_still_approach, pour_tilted_back).
body(r15_destination_still_approach, pour_to_side).
body(r15_destination_still_approach, retreat_lowering).
body(r15_destination_still_approach, runny_liquid).
body(r15_destination_still_approach, slippery_destination).
body(r15_destination_still_approach, start_below_rim).
body(r15_destination_still_approach, start_slightly_tilted).
learned(r15_destination_still_approach).
provenance(r15_destination_still_approach, antecedent, a15).
provenance(r15_destination_still_approach, parent, a13).
provenance(r15_destination_still_approach, simulations, 31).
provenance(r15_destination_still_approach, weight_mass_permille, 31000).
provenance(r15_destination_still_approach, confidence_permille, 839).
provenance(r15_destination_still_approach, score_permille, 226).
provenance(r15_destination_still_approach, batches, 1).

rule(r15_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r15_destination_still_retreat, approach_moving_away).
body(r15_destination_still_retreat, bouncy_liquid).
body(r15_destination_still_retreat, dull_destination).
body(r15_destination_still_retreat, end_rolled).
body(r15_destination_still_retreat, end_steeply_tilted).
body(r15_destination_still_retreat, end_to_side).
body(r15_destination_still_retreat, fast_retreat).
body(r15_destination_still_retreat, grippy_source).
body(r15_destination_still_retreat, heavy_liquid).
body(r15_destination_still_retreat, light_destination).
body(r15_destination_still_retreat, little_liquid).
body(r15_destination_still_retreat, pour_in_line).
body(r15_destination_still_retreat, pour_mid_height).
body(r15_destination_still_retreat, pour_tilted_back).
body(r15_destination_still_retreat, pour_to_side).
body(r15_destination_still_retreat, retreat_lowering).
body(r15_destination_still_retreat, runny_liquid).
body(r15_destination_still_retreat, slippery_destination).
body(r15_destination_still_retreat, start_below_rim).
body(r15_destination_still_retreat, start_slightly_tilted).
learned(r15_destination_still_retreat).
provenance(r15_destination_still_retreat, antecedent, a15).
provenance(r15_destination_still_retreat, parent, a13).
provenance(r15_destination_still_retreat, simulations, 31).
provenance(r15_destination_still_retreat, weight_mass_permille, 31000).
provenance(r15_destination_still_retreat, confidence_permille, 516).
provenance(r15_destination_still_retreat, score_permille, 457).
provenance(r15_destination_still_retreat, batches, 1).

rule(r15_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r15_destination_still_settle, approach_moving_away).
body(r15_destination_still_settle, bouncy_liquid).
body(r15_destination_still_settle, dull_destination).
body(r15_destination_still_settle, end_rolled).
body(r15_destination_still_settle, end_steeply_tilted).
body(r15_destination_still_settle, end_to_side).
body(r15_destination_still_settle, fast_retreat).
body(r15_destination_still_settle, grippy_source).
body(r15_destination_still_settle, heavy_liquid).
body(r15_destination_still_settle, light_destination).
body(r15_destination_still_settle, little_liquid).
body(r15_destination_still_settle, pour_in_line).
body(r15_destination_still_settle, pour_mid_height).
body(r15_destination_still_settle, pour_tilted_back).
body(r15_destination_still_settle, pour_to_side).
body(r15_destination_still_settle, retreat_lowering).
body(r15_destination_still_settle, runny_liquid).
body(r15_destination_still_settle, slippery_destination).
body(r15_destination_still_settle, start_below_rim).
body(r15_destination_still_settle, start_slightly_tilted).
learned(r15_destination_still_settle).
provenance(r15_destination_still_settle, antecedent, a15).
provenance(r15_destination_still_settle, parent, a13).
provenance(r15_destination_still_settle, simulations, 31).
provenance(r15_destination_still_settle, weight_mass_permille, 31000).
provenance(r15_destination_still_settle, confidence_permille, 677).
provenance(r15_destination_still_settle, score_permille, 292).
provenance(r15_destination_still_settle, batches, 1).

rule(r15_destination_upright, defeasible, destination_upright).
body(r15_destination_upright, approach_moving_away).
body(r15_destination_upright, bouncy_liquid).
body(r15_destination_upright, dull_destination).
body(r15_destination_upright, end_rolled).
body(r15_destination_upright, end_steeply_tilted).
body(r15_destination_upright, end_to_side).
body(r15_destination_upright, fast_retreat).
body(r15_destination_upright, grippy_source).
body(r15_destination_upright, heavy_liquid).
body(r15_destination_upright, light_destination).
body(r15_destination_upright, little_liquid).
body(r15_destination_upright, pour_in_line).
body(r15_destination_upright, pour_mid_height).
body(r15_destination_upright, pour_tilted_back).
body(r15_destination_upright, pour_to_side).
body(r15_destination_upright, retreat_lowering).
body(r15_destination_upright, runny_liquid).
body(r15_destination_upright, slippery_destination).
body(r15_destination_upright, start_below_rim).
body(r15_destination_upright, start_slightly_tilted).
learned(r15_destination_upright).
provenance(r15_destination_upright, antecedent, a15).
provenance(r15_destination_upright, parent, a13).
provenance(r15_destination_upright, simulations, 31).
provenance(r15_destination_upright, weight_mass_permille, 31000).
provenance(r15_destination_upright, confidence_permille, 935).
provenance(r15_destination_upright, score_permille, 934).
provenance(r15_destination_upright, batches, 1).

rule(r15_source_clear, defeasible, neg(source_clear)).
body(r15_source_clear, approach_moving_away).
body(r15_source_clear, bouncy_liquid).
body(r15_source_clear, dull_destination).
body(r15_source_clear, end_rolled).
body(r15_source_clear, end_steeply_tilted).
body(r15_source_clear, end_to_side).
body(r15_source_clear, fast_retreat).
body(r15_source_clear, grippy_source).
body(r15_source_clear, heavy_liquid).
body(r15_source_clear, light_destination).
body(r15_source_clear, little_liquid).
body(r15_source_clear, pour_in_line).
body(r15_source_clear, pour_mid_height).
body(r15_source_clear, pour_tilted_back).
body(r15_source_clear, pour_to_side).
body(r15_source_clear, retreat_lowering).
body(r15_source_clear, runny_liquid).
body(r15_source_clear, slippery_destination).
body(r15_source_clear, start_below_rim).
body(r15_source_clear, start_slightly_tilted).
learned(r15_source_clear).
provenance(r15_source_clear, antecedent, a15).
provenance(r15_source_clear, parent, a13).
provenance(r15_source_clear, simulations, 31).
provenance(r15_source_clear, weight_mass_permille, 31000).
provenance(r15_source_clear, confidence_permille, 1000).
provenance(r15_source_clear, score_permille, 0).
provenance(r15_source_clear, batches, 1).

rule(r15_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r15_liquid_leaves_source, approach_moving_away).
body(r15_liquid_leaves_source, bouncy_liquid).
body(r15_liquid_leaves_source, dull_destination).
body(r15_liquid_leaves_source, end_rolled).
body(r15_liquid_leaves_source, end_steeply_tilted).
body(r15_liquid_leaves_source, end_to_side).
body(r15_liquid_leaves_source, fast_retreat).
body(r15_liquid_leaves_source, grippy_source).
body(r15_liquid_leaves_source, heavy_liquid).
body(r15_liquid_leaves_source, light_destination).
body(r15_liquid_leaves_source, little_liquid).
body(r15_liquid_leaves_source, pour_in_line).
body(r15_liquid_leaves_source, pour_mid_height).
body(r15_liquid_leaves_source, pour_tilted_back).
body(r15_liquid_leaves_source, pour_to_side).
body(r15_liquid_leaves_source, retreat_lowering).
body(r15_liquid_leaves_source, runny_liquid).
body(r15_liquid_leaves_source, slippery_destination).
body(r15_liquid_leaves_source, start_below_rim).
body(r15_liquid_leaves_source, start_slightly_tilted).
learned(r15_liquid_leaves_source).
provenance(r15_liquid_leaves_source, antecedent, a15).
provenance(r15_liquid_leaves_source, parent, a13).
provenance(r15_liquid_leaves_source, simulations, 31).
provenance(r15_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r15_liquid_leaves_source, confidence_permille, 839).
provenance(r15_liquid_leaves_source, score_permille, 825).
provenance(r15_liquid_leaves_source, batches, 1).

rule(r15_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r15_liquid_enters_destination, approach_moving_away).
body(r15_liquid_enters_destination, bouncy_liquid).
body(r15_liquid_enters_destination, dull_destination).
body(r15_liquid_enters_destination, end_rolled).
body(r15_liquid_enters_destination, end_steeply_tilted).
body(r15_liquid_enters_destination, end_to_side).
body(r15_liquid_enters_destination, fast_retreat).
body(r15_liquid_enters_destination, grippy_source).
body(r15_liquid_enters_destination, heavy_liquid).
body(r15_liquid_enters_destination, light_destination).
body(r15_liquid_enters_destination, little_liquid).
body(r15_liquid_enters_destination, pour_in_line).
body(r15_liquid_enters_destination, pour_mid_height).
body(r15_liquid_enters_destination, pour_tilted_back).
body(r15_liquid_enters_destination, pour_to_side).
body(r15_liquid_enters_destination, retreat_lowering).
body(r15_liquid_enters_destination, runny_liquid).
body(r15_liquid_enters_destination, slippery_destination).
body(r15_liquid_enters_destination, start_below_rim).
body(r15_liquid_enters_destination, start_slightly_tilted).
learned(r15_liquid_enters_destination).
provenance(r15_liquid_enters_destination, antecedent, a15).
provenance(r15_liquid_enters_destination, parent, a13).
provenance(r15_liquid_enters_destination, simulations, 31).
provenance(r15_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r15_liquid_enters_destination, confidence_permille, 710).
provenance(r15_liquid_enters_destination, score_permille, 707).
provenance(r15_liquid_enters_destination, batches, 1).

rule(r15_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r15_liquid_remains_in_destination, approach_moving_away).
body(r15_liquid_remains_in_destination, bouncy_liquid).
body(r15_liquid_remains_in_destination, dull_destination).
body(r15_liquid_remains_in_destination, end_rolled).
body(r15_liquid_remains_in_destination, end_steeply_tilted).
body(r15_liquid_remains_in_destination, end_to_side).
body(r15_liquid_remains_in_destination, fast_retreat).
body(r15_liquid_remains_in_destination, grippy_source).
body(r15_liquid_remains_in_destination, heavy_liquid).
body(r15_liquid_remains_in_destination, light_destination).
body(r15_liquid_remains_in_destination, little_liquid).
body(r15_liquid_remains_in_destination, pour_in_line).
body(r15_liquid_remains_in_destination, pour_mid_height).
body(r15_liquid_remains_in_destination, pour_tilted_back).
body(r15_liquid_remains_in_destination, pour_to_side).
body(r15_liquid_remains_in_destination, retreat_lowering).
body(r15_liquid_remains_in_destination, runny_liquid).
body(r15_liquid_remains_in_destination, slippery_destination).
body(r15_liquid_remains_in_destination, start_below_rim).
body(r15_liquid_remains_in_destination, start_slightly_tilted).
learned(r15_liquid_remains_in_destination).
provenance(r15_liquid_remains_in_destination, antecedent, a15).
provenance(r15_liquid_remains_in_destination, parent, a13).
provenance(r15_liquid_remains_in_destination, simulations, 31).
provenance(r15_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r15_liquid_remains_in_destination, confidence_permille, 645).
provenance(r15_liquid_remains_in_destination, score_permille, 354).
provenance(r15_liquid_remains_in_destination, batches, 1).

rule(r15_no_spill, defeasible, neg(no_spill)).
body(r15_no_spill, approach_moving_away).
body(r15_no_spill, bouncy_liquid).
body(r15_no_spill, dull_destination).
body(r15_no_spill, end_rolled).
body(r15_no_spill, end_steeply_tilted).
body(r15_no_spill, end_to_side).
body(r15_no_spill, fast_retreat).
body(r15_no_spill, grippy_source).
body(r15_no_spill, heavy_liquid).
body(r15_no_spill, light_destination).
body(r15_no_spill, little_liquid).
body(r15_no_spill, pour_in_line).
body(r15_no_spill, pour_mid_height).
body(r15_no_spill, pour_tilted_back).
body(r15_no_spill, pour_to_side).
body(r15_no_spill, retreat_lowering).
body(r15_no_spill, runny_liquid).
body(r15_no_spill, slippery_destination).
body(r15_no_spill, start_below_rim).
body(r15_no_spill, start_slightly_tilted).
learned(r15_no_spill).
provenance(r15_no_spill, antecedent, a15).
provenance(r15_no_spill, parent, a13).
provenance(r15_no_spill, simulations, 31).
provenance(r15_no_spill, weight_mass_permille, 31000).
provenance(r15_no_spill, confidence_permille, 742).
provenance(r15_no_spill, score_permille, 280).
provenance(r15_no_spill, batches, 1).

rule(r16_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r16_destination_still_approach, approach_moving_away).
body(r16_destination_still_approach, bouncy_liquid).
body(r16_destination_still_approach, dull_destination).
body(r16_destination_still_approach, end_rolled).
body(r16_destination_still_approach, end_steeply_tilted).
body(r16_destination_still_approach, end_to_side).
body(r16_destination_still_approach, fast_retreat).
body(r16_destination_still_approach, grippy_source).
body(r16_destination_still_approach, heavy_liquid).
body(r16_destination_still_approach, light_destination).
body(r16_destination_still_approach, little_liquid).
body(r16_destination_still_approach, pour_centred).
body(r16_destination_still_approach, pour_in_line).
body(r16_destination_still_approach, pour_mid_height).
body(r16_destination_still_approach, pour_tilted_back).
body(r16_destination_still_approach, retreat_lowering).
body(r16_destination_still_approach, runny_liquid).
body(r16_destination_still_approach, slippery_destination).
body(r16_destination_still_approach, start_below_rim).
body(r16_destination_still_approach, start_slightly_tilted).
learned(r16_destination_still_approach).
provenance(r16_destination_still_approach, antecedent, a16).
provenance(r16_destination_still_approach, parent, a15).
provenance(r16_destination_still_approach, simulations, 39).
provenance(r16_destination_still_approach, weight_mass_permille, 39000).
provenance(r16_destination_still_approach, confidence_permille, 692).
provenance(r16_destination_still_approach, score_permille, 340).
provenance(r16_destination_still_approach, batches, 1).

rule(r16_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r16_destination_still_retreat, approach_moving_away).
body(r16_destination_still_retreat, bouncy_liquid).
body(r16_destination_still_retreat, dull_destination).
body(r16_destination_still_retreat, end_rolled).
body(r16_destination_still_retreat, end_steeply_tilted).
body(r16_destination_still_retreat, end_to_side).
body(r16_destination_still_retreat, fast_retreat).
body(r16_destination_still_retreat, grippy_source).
body(r16_destination_still_retreat, heavy_liquid).
body(r16_destination_still_retreat, light_destination).
body(r16_destination_still_retreat, little_liquid).
body(r16_destination_still_retreat, pour_centred).
body(r16_destination_still_retreat, pour_in_line).
body(r16_destination_still_retreat, pour_mid_height).
body(r16_destination_still_retreat, pour_tilted_back).
body(r16_destination_still_retreat, retreat_lowering).
body(r16_destination_still_retreat, runny_liquid).
body(r16_destination_still_retreat, slippery_destination).
body(r16_destination_still_retreat, start_below_rim).
body(r16_destination_still_retreat, start_slightly_tilted).
learned(r16_destination_still_retreat).
provenance(r16_destination_still_retreat, antecedent, a16).
provenance(r16_destination_still_retreat, parent, a15).
provenance(r16_destination_still_retreat, simulations, 39).
provenance(r16_destination_still_retreat, weight_mass_permille, 39000).
provenance(r16_destination_still_retreat, confidence_permille, 590).
provenance(r16_destination_still_retreat, score_permille, 399).
provenance(r16_destination_still_retreat, batches, 1).

rule(r16_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r16_destination_still_settle, approach_moving_away).
body(r16_destination_still_settle, bouncy_liquid).
body(r16_destination_still_settle, dull_destination).
body(r16_destination_still_settle, end_rolled).
body(r16_destination_still_settle, end_steeply_tilted).
body(r16_destination_still_settle, end_to_side).
body(r16_destination_still_settle, fast_retreat).
body(r16_destination_still_settle, grippy_source).
body(r16_destination_still_settle, heavy_liquid).
body(r16_destination_still_settle, light_destination).
body(r16_destination_still_settle, little_liquid).
body(r16_destination_still_settle, pour_centred).
body(r16_destination_still_settle, pour_in_line).
body(r16_destination_still_settle, pour_mid_height).
body(r16_destination_still_settle, pour_tilted_back).
body(r16_destination_still_settle, retreat_lowering).
body(r16_destination_still_settle, runny_liquid).
body(r16_destination_still_settle, slippery_destination).
body(r16_destination_still_settle, start_below_rim).
body(r16_destination_still_settle, start_slightly_tilted).
learned(r16_destination_still_settle).
provenance(r16_destination_still_settle, antecedent, a16).
provenance(r16_destination_still_settle, parent, a15).
provenance(r16_destination_still_settle, simulations, 39).
provenance(r16_destination_still_settle, weight_mass_permille, 39000).
provenance(r16_destination_still_settle, confidence_permille, 769).
provenance(r16_destination_still_settle, score_permille, 240).
provenance(r16_destination_still_settle, batches, 1).

rule(r16_destination_upright, defeasible, destination_upright).
body(r16_destination_upright, approach_moving_away).
body(r16_destination_upright, bouncy_liquid).
body(r16_destination_upright, dull_destination).
body(r16_destination_upright, end_rolled).
body(r16_destination_upright, end_steeply_tilted).
body(r16_destination_upright, end_to_side).
body(r16_destination_upright, fast_retreat).
body(r16_destination_upright, grippy_source).
body(r16_destination_upright, heavy_liquid).
body(r16_destination_upright, light_destination).
body(r16_destination_upright, little_liquid).
body(r16_destination_upright, pour_centred).
body(r16_destination_upright, pour_in_line).
body(r16_destination_upright, pour_mid_height).
body(r16_destination_upright, pour_tilted_back).
body(r16_destination_upright, retreat_lowering).
body(r16_destination_upright, runny_liquid).
body(r16_destination_upright, slippery_destination).
body(r16_destination_upright, start_below_rim).
body(r16_destination_upright, start_slightly_tilted).
learned(r16_destination_upright).
provenance(r16_destination_upright, antecedent, a16).
provenance(r16_destination_upright, parent, a15).
provenance(r16_destination_upright, simulations, 39).
provenance(r16_destination_upright, weight_mass_permille, 39000).
provenance(r16_destination_upright, confidence_permille, 897).
provenance(r16_destination_upright, score_permille, 894).
provenance(r16_destination_upright, batches, 1).

rule(r16_source_clear, defeasible, neg(source_clear)).
body(r16_source_clear, approach_moving_away).
body(r16_source_clear, bouncy_liquid).
body(r16_source_clear, dull_destination).
body(r16_source_clear, end_rolled).
body(r16_source_clear, end_steeply_tilted).
body(r16_source_clear, end_to_side).
body(r16_source_clear, fast_retreat).
body(r16_source_clear, grippy_source).
body(r16_source_clear, heavy_liquid).
body(r16_source_clear, light_destination).
body(r16_source_clear, little_liquid).
body(r16_source_clear, pour_centred).
body(r16_source_clear, pour_in_line).
body(r16_source_clear, pour_mid_height).
body(r16_source_clear, pour_tilted_back).
body(r16_source_clear, retreat_lowering).
body(r16_source_clear, runny_liquid).
body(r16_source_clear, slippery_destination).
body(r16_source_clear, start_below_rim).
body(r16_source_clear, start_slightly_tilted).
learned(r16_source_clear).
provenance(r16_source_clear, antecedent, a16).
provenance(r16_source_clear, parent, a15).
provenance(r16_source_clear, simulations, 39).
provenance(r16_source_clear, weight_mass_permille, 39000).
provenance(r16_source_clear, confidence_permille, 872).
provenance(r16_source_clear, score_permille, 94).
provenance(r16_source_clear, batches, 1).

rule(r16_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r16_liquid_leaves_source, approach_moving_away).
body(r16_liquid_leaves_source, bouncy_liquid).
body(r16_liquid_leaves_source, dull_destination).
body(r16_liquid_leaves_source, end_rolled).
body(r16_liquid_leaves_source, end_steeply_tilted).
body(r16_liquid_leaves_source, end_to_side).
body(r16_liquid_leaves_source, fast_retreat).
body(r16_liquid_leaves_source, grippy_source).
body(r16_liquid_leaves_source, heavy_liquid).
body(r16_liquid_leaves_source, light_destination).
body(r16_liquid_leaves_source, little_liquid).
body(r16_liquid_leaves_source, pour_centred).
body(r16_liquid_leaves_source, pour_in_line).
body(r16_liquid_leaves_source, pour_mid_height).
body(r16_liquid_leaves_source, pour_tilted_back).
body(r16_liquid_leaves_source, retreat_lowering).
body(r16_liquid_leaves_source, runny_liquid).
body(r16_liquid_leaves_source, slippery_destination).
body(r16_liquid_leaves_source, start_below_rim).
body(r16_liquid_leaves_source, start_slightly_tilted).
learned(r16_liquid_leaves_source).
provenance(r16_liquid_leaves_source, antecedent, a16).
provenance(r16_liquid_leaves_source, parent, a15).
provenance(r16_liquid_leaves_source, simulations, 39).
provenance(r16_liquid_leaves_source, weight_mass_permille, 39000).
provenance(r16_liquid_leaves_source, confidence_permille, 923).
provenance(r16_liquid_leaves_source, score_permille, 927).
provenance(r16_liquid_leaves_source, batches, 1).

rule(r16_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r16_liquid_enters_destination, approach_moving_away).
body(r16_liquid_enters_destination, bouncy_liquid).
body(r16_liquid_enters_destination, dull_destination).
body(r16_liquid_enters_destination, end_rolled).
body(r16_liquid_enters_destination, end_steeply_tilted).
body(r16_liquid_enters_destination, end_to_side).
body(r16_liquid_enters_destination, fast_retreat).
body(r16_liquid_enters_destination, grippy_source).
body(r16_liquid_enters_destination, heavy_liquid).
body(r16_liquid_enters_destination, light_destination).
body(r16_liquid_enters_destination, little_liquid).
body(r16_liquid_enters_destination, pour_centred).
body(r16_liquid_enters_destination, pour_in_line).
body(r16_liquid_enters_destination, pour_mid_height).
body(r16_liquid_enters_destination, pour_tilted_back).
body(r16_liquid_enters_destination, retreat_lowering).
body(r16_liquid_enters_destination, runny_liquid).
body(r16_liquid_enters_destination, slippery_destination).
body(r16_liquid_enters_destination, start_below_rim).
body(r16_liquid_enters_destination, start_slightly_tilted).
learned(r16_liquid_enters_destination).
provenance(r16_liquid_enters_destination, antecedent, a16).
provenance(r16_liquid_enters_destination, parent, a15).
provenance(r16_liquid_enters_destination, simulations, 39).
provenance(r16_liquid_enters_destination, weight_mass_permille, 39000).
provenance(r16_liquid_enters_destination, confidence_permille, 769).
provenance(r16_liquid_enters_destination, score_permille, 743).
provenance(r16_liquid_enters_destination, batches, 1).

rule(r16_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r16_liquid_remains_in_destination, approach_moving_away).
body(r16_liquid_remains_in_destination, bouncy_liquid).
body(r16_liquid_remains_in_destination, dull_destination).
body(r16_liquid_remains_in_destination, end_rolled).
body(r16_liquid_remains_in_destination, end_steeply_tilted).
body(r16_liquid_remains_in_destination, end_to_side).
body(r16_liquid_remains_in_destination, fast_retreat).
body(r16_liquid_remains_in_destination, grippy_source).
body(r16_liquid_remains_in_destination, heavy_liquid).
body(r16_liquid_remains_in_destination, light_destination).
body(r16_liquid_remains_in_destination, little_liquid).
body(r16_liquid_remains_in_destination, pour_centred).
body(r16_liquid_remains_in_destination, pour_in_line).
body(r16_liquid_remains_in_destination, pour_mid_height).
body(r16_liquid_remains_in_destination, pour_tilted_back).
body(r16_liquid_remains_in_destination, retreat_lowering).
body(r16_liquid_remains_in_destination, runny_liquid).
body(r16_liquid_remains_in_destination, slippery_destination).
body(r16_liquid_remains_in_destination, start_below_rim).
body(r16_liquid_remains_in_destination, start_slightly_tilted).
learned(r16_liquid_remains_in_destination).
provenance(r16_liquid_remains_in_destination, antecedent, a16).
provenance(r16_liquid_remains_in_destination, parent, a15).
provenance(r16_liquid_remains_in_destination, simulations, 39).
provenance(r16_liquid_remains_in_destination, weight_mass_permille, 39000).
provenance(r16_liquid_remains_in_destination, confidence_permille, 667).
provenance(r16_liquid_remains_in_destination, score_permille, 654).
provenance(r16_liquid_remains_in_destination, batches, 1).

rule(r16_no_spill, defeasible, no_spill).
body(r16_no_spill, approach_moving_away).
body(r16_no_spill, bouncy_liquid).
body(r16_no_spill, dull_destination).
body(r16_no_spill, end_rolled).
body(r16_no_spill, end_steeply_tilted).
body(r16_no_spill, end_to_side).
body(r16_no_spill, fast_retreat).
body(r16_no_spill, grippy_source).
body(r16_no_spill, heavy_liquid).
body(r16_no_spill, light_destination).
body(r16_no_spill, little_liquid).
body(r16_no_spill, pour_centred).
body(r16_no_spill, pour_in_line).
body(r16_no_spill, pour_mid_height).
body(r16_no_spill, pour_tilted_back).
body(r16_no_spill, retreat_lowering).
body(r16_no_spill, runny_liquid).
body(r16_no_spill, slippery_destination).
body(r16_no_spill, start_below_rim).
body(r16_no_spill, start_slightly_tilted).
learned(r16_no_spill).
provenance(r16_no_spill, antecedent, a16).
provenance(r16_no_spill, parent, a15).
provenance(r16_no_spill, simulations, 39).
provenance(r16_no_spill, weight_mass_permille, 39000).
provenance(r16_no_spill, confidence_permille, 538).
provenance(r16_no_spill, score_permille, 504).
provenance(r16_no_spill, batches, 1).

rule(r17_destination_still_approach, defeasible, destination_still_approach).
body(r17_destination_still_approach, approach_moving_away).
body(r17_destination_still_approach, bouncy_liquid).
body(r17_destination_still_approach, dull_destination).
body(r17_destination_still_approach, end_rolled).
body(r17_destination_still_approach, end_steeply_tilted).
body(r17_destination_still_approach, end_to_side).
body(r17_destination_still_approach, grippy_source).
body(r17_destination_still_approach, heavy_liquid).
body(r17_destination_still_approach, light_destination).
body(r17_destination_still_approach, little_liquid).
body(r17_destination_still_approach, pour_centred).
body(r17_destination_still_approach, pour_in_line).
body(r17_destination_still_approach, pour_mid_height).
body(r17_destination_still_approach, pour_tilted_back).
body(r17_destination_still_approach, retreat_lowering).
body(r17_destination_still_approach, runny_liquid).
body(r17_destination_still_approach, slippery_destination).
body(r17_destination_still_approach, slow_retreat).
body(r17_destination_still_approach, start_below_rim).
body(r17_destination_still_approach, start_slightly_tilted).
learned(r17_destination_still_approach).
provenance(r17_destination_still_approach, antecedent, a17).
provenance(r17_destination_still_approach, parent, a16).
provenance(r17_destination_still_approach, simulations, 31).
provenance(r17_destination_still_approach, weight_mass_permille, 31000).
provenance(r17_destination_still_approach, confidence_permille, 548).
provenance(r17_destination_still_approach, score_permille, 561).
provenance(r17_destination_still_approach, batches, 1).

rule(r17_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r17_destination_still_retreat, approach_moving_away).
body(r17_destination_still_retreat, bouncy_liquid).
body(r17_destination_still_retreat, dull_destination).
body(r17_destination_still_retreat, end_rolled).
body(r17_destination_still_retreat, end_steeply_tilted).
body(r17_destination_still_retreat, end_to_side).
body(r17_destination_still_retreat, grippy_source).
body(r17_destination_still_retreat, heavy_liquid).
body(r17_destination_still_retreat, light_destination).
body(r17_destination_still_retreat, little_liquid).
body(r17_destination_still_retreat, pour_centred).
body(r17_destination_still_retreat, pour_in_line).
body(r17_destination_still_retreat, pour_mid_height).
body(r17_destination_still_retreat, pour_tilted_back).
body(r17_destination_still_retreat, retreat_lowering).
body(r17_destination_still_retreat, runny_liquid).
body(r17_destination_still_retreat, slippery_destination).
body(r17_destination_still_retreat, slow_retreat).
body(r17_destination_still_retreat, start_below_rim).
body(r17_destination_still_retreat, start_slightly_tilted).
learned(r17_destination_still_retreat).
provenance(r17_destination_still_retreat, antecedent, a17).
provenance(r17_destination_still_retreat, parent, a16).
provenance(r17_destination_still_retreat, simulations, 31).
provenance(r17_destination_still_retreat, weight_mass_permille, 31000).
provenance(r17_destination_still_retreat, confidence_permille, 710).
provenance(r17_destination_still_retreat, score_permille, 297).
provenance(r17_destination_still_retreat, batches, 1).

rule(r17_destination_still_settle, defeasible, destination_still_settle).
body(r17_destination_still_settle, approach_moving_away).
body(r17_destination_still_settle, bouncy_liquid).
body(r17_destination_still_settle, dull_destination).
body(r17_destination_still_settle, end_rolled).
body(r17_destination_still_settle, end_steeply_tilted).
body(r17_destination_still_settle, end_to_side).
body(r17_destination_still_settle, grippy_source).
body(r17_destination_still_settle, heavy_liquid).
body(r17_destination_still_settle, light_destination).
body(r17_destination_still_settle, little_liquid).
body(r17_destination_still_settle, pour_centred).
body(r17_destination_still_settle, pour_in_line).
body(r17_destination_still_settle, pour_mid_height).
body(r17_destination_still_settle, pour_tilted_back).
body(r17_destination_still_settle, retreat_lowering).
body(r17_destination_still_settle, runny_liquid).
body(r17_destination_still_settle, slippery_destination).
body(r17_destination_still_settle, slow_retreat).
body(r17_destination_still_settle, start_below_rim).
body(r17_destination_still_settle, start_slightly_tilted).
learned(r17_destination_still_settle).
provenance(r17_destination_still_settle, antecedent, a17).
provenance(r17_destination_still_settle, parent, a16).
provenance(r17_destination_still_settle, simulations, 31).
provenance(r17_destination_still_settle, weight_mass_permille, 31000).
provenance(r17_destination_still_settle, confidence_permille, 742).
provenance(r17_destination_still_settle, score_permille, 657).
provenance(r17_destination_still_settle, batches, 1).

rule(r17_destination_upright, defeasible, destination_upright).
body(r17_destination_upright, approach_moving_away).
body(r17_destination_upright, bouncy_liquid).
body(r17_destination_upright, dull_destination).
body(r17_destination_upright, end_rolled).
body(r17_destination_upright, end_steeply_tilted).
body(r17_destination_upright, end_to_side).
body(r17_destination_upright, grippy_source).
body(r17_destination_upright, heavy_liquid).
body(r17_destination_upright, light_destination).
body(r17_destination_upright, little_liquid).
body(r17_destination_upright, pour_centred).
body(r17_destination_upright, pour_in_line).
body(r17_destination_upright, pour_mid_height).
body(r17_destination_upright, pour_tilted_back).
body(r17_destination_upright, retreat_lowering).
body(r17_destination_upright, runny_liquid).
body(r17_destination_upright, slippery_destination).
body(r17_destination_upright, slow_retreat).
body(r17_destination_upright, start_below_rim).
body(r17_destination_upright, start_slightly_tilted).
learned(r17_destination_upright).
provenance(r17_destination_upright, antecedent, a17).
provenance(r17_destination_upright, parent, a16).
provenance(r17_destination_upright, simulations, 31).
provenance(r17_destination_upright, weight_mass_permille, 31000).
provenance(r17_destination_upright, confidence_permille, 871).
provenance(r17_destination_upright, score_permille, 849).
provenance(r17_destination_upright, batches, 1).

rule(r17_source_clear, defeasible, neg(source_clear)).
body(r17_source_clear, approach_moving_away).
body(r17_source_clear, bouncy_liquid).
body(r17_source_clear, dull_destination).
body(r17_source_clear, end_rolled).
body(r17_source_clear, end_steeply_tilted).
body(r17_source_clear, end_to_side).
body(r17_source_clear, grippy_source).
body(r17_source_clear, heavy_liquid).
body(r17_source_clear, light_destination).
body(r17_source_clear, little_liquid).
body(r17_source_clear, pour_centred).
body(r17_source_clear, pour_in_line).
body(r17_source_clear, pour_mid_height).
body(r17_source_clear, pour_tilted_back).
body(r17_source_clear, retreat_lowering).
body(r17_source_clear, runny_liquid).
body(r17_source_clear, slippery_destination).
body(r17_source_clear, slow_retreat).
body(r17_source_clear, start_below_rim).
body(r17_source_clear, start_slightly_tilted).
learned(r17_source_clear).
provenance(r17_source_clear, antecedent, a17).
provenance(r17_source_clear, parent, a16).
provenance(r17_source_clear, simulations, 31).
provenance(r17_source_clear, weight_mass_permille, 31000).
provenance(r17_source_clear, confidence_permille, 742).
provenance(r17_source_clear, score_permille, 214).
provenance(r17_source_clear, batches, 1).

rule(r17_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r17_liquid_leaves_source, approach_moving_away).
body(r17_liquid_leaves_source, bouncy_liquid).
body(r17_liquid_leaves_source, dull_destination).
body(r17_liquid_leaves_source, end_rolled).
body(r17_liquid_leaves_source, end_steeply_tilted).
body(r17_liquid_leaves_source, end_to_side).
body(r17_liquid_leaves_source, grippy_source).
body(r17_liquid_leaves_source, heavy_liquid).
body(r17_liquid_leaves_source, light_destination).
body(r17_liquid_leaves_source, little_liquid).
body(r17_liquid_leaves_source, pour_centred).
body(r17_liquid_leaves_source, pour_in_line).
body(r17_liquid_leaves_source, pour_mid_height).
body(r17_liquid_leaves_source, pour_tilted_back).
body(r17_liquid_leaves_source, retreat_lowering).
body(r17_liquid_leaves_source, runny_liquid).
body(r17_liquid_leaves_source, slippery_destination).
body(r17_liquid_leaves_source, slow_retreat).
body(r17_liquid_leaves_source, start_below_rim).
body(r17_liquid_leaves_source, start_slightly_tilted).
learned(r17_liquid_leaves_source).
provenance(r17_liquid_leaves_source, antecedent, a17).
provenance(r17_liquid_leaves_source, parent, a16).
provenance(r17_liquid_leaves_source, simulations, 31).
provenance(r17_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r17_liquid_leaves_source, confidence_permille, 774).
provenance(r17_liquid_leaves_source, score_permille, 772).
provenance(r17_liquid_leaves_source, batches, 1).

rule(r17_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r17_liquid_enters_destination, approach_moving_away).
body(r17_liquid_enters_destination, bouncy_liquid).
body(r17_liquid_enters_destination, dull_destination).
body(r17_liquid_enters_destination, end_rolled).
body(r17_liquid_enters_destination, end_steeply_tilted).
body(r17_liquid_enters_destination, end_to_side).
body(r17_liquid_enters_destination, grippy_source).
body(r17_liquid_enters_destination, heavy_liquid).
body(r17_liquid_enters_destination, light_destination).
body(r17_liquid_enters_destination, little_liquid).
body(r17_liquid_enters_destination, pour_centred).
body(r17_liquid_enters_destination, pour_in_line).
body(r17_liquid_enters_destination, pour_mid_height).
body(r17_liquid_enters_destination, pour_tilted_back).
body(r17_liquid_enters_destination, retreat_lowering).
body(r17_liquid_enters_destination, runny_liquid).
body(r17_liquid_enters_destination, slippery_destination).
body(r17_liquid_enters_destination, slow_retreat).
body(r17_liquid_enters_destination, start_below_rim).
body(r17_liquid_enters_destination, start_slightly_tilted).
learned(r17_liquid_enters_destination).
provenance(r17_liquid_enters_destination, antecedent, a17).
provenance(r17_liquid_enters_destination, parent, a16).
provenance(r17_liquid_enters_destination, simulations, 31).
provenance(r17_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r17_liquid_enters_destination, confidence_permille, 581).
provenance(r17_liquid_enters_destination, score_permille, 586).
provenance(r17_liquid_enters_destination, batches, 1).

rule(r17_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r17_liquid_remains_in_destination, approach_moving_away).
body(r17_liquid_remains_in_destination, bouncy_liquid).
body(r17_liquid_remains_in_destination, dull_destination).
body(r17_liquid_remains_in_destination, end_rolled).
body(r17_liquid_remains_in_destination, end_steeply_tilted).
body(r17_liquid_remains_in_destination, end_to_side).
body(r17_liquid_remains_in_destination, grippy_source).
body(r17_liquid_remains_in_destination, heavy_liquid).
body(r17_liquid_remains_in_destination, light_destination).
body(r17_liquid_remains_in_destination, little_liquid).
body(r17_liquid_remains_in_destination, pour_centred).
body(r17_liquid_remains_in_destination, pour_in_line).
body(r17_liquid_remains_in_destination, pour_mid_height).
body(r17_liquid_remains_in_destination, pour_tilted_back).
body(r17_liquid_remains_in_destination, retreat_lowering).
body(r17_liquid_remains_in_destination, runny_liquid).
body(r17_liquid_remains_in_destination, slippery_destination).
body(r17_liquid_remains_in_destination, slow_retreat).
body(r17_liquid_remains_in_destination, start_below_rim).
body(r17_liquid_remains_in_destination, start_slightly_tilted).
learned(r17_liquid_remains_in_destination).
provenance(r17_liquid_remains_in_destination, antecedent, a17).
provenance(r17_liquid_remains_in_destination, parent, a16).
provenance(r17_liquid_remains_in_destination, simulations, 31).
provenance(r17_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r17_liquid_remains_in_destination, confidence_permille, 677).
provenance(r17_liquid_remains_in_destination, score_permille, 698).
provenance(r17_liquid_remains_in_destination, batches, 1).

rule(r17_no_spill, defeasible, no_spill).
body(r17_no_spill, approach_moving_away).
body(r17_no_spill, bouncy_liquid).
body(r17_no_spill, dull_destination).
body(r17_no_spill, end_rolled).
body(r17_no_spill, end_steeply_tilted).
body(r17_no_spill, end_to_side).
body(r17_no_spill, grippy_source).
body(r17_no_spill, heavy_liquid).
body(r17_no_spill, light_destination).
body(r17_no_spill, little_liquid).
body(r17_no_spill, pour_centred).
body(r17_no_spill, pour_in_line).
body(r17_no_spill, pour_mid_height).
body(r17_no_spill, pour_tilted_back).
body(r17_no_spill, retreat_lowering).
body(r17_no_spill, runny_liquid).
body(r17_no_spill, slippery_destination).
body(r17_no_spill, slow_retreat).
body(r17_no_spill, start_below_rim).
body(r17_no_spill, start_slightly_tilted).
learned(r17_no_spill).
provenance(r17_no_spill, antecedent, a17).
provenance(r17_no_spill, parent, a16).
provenance(r17_no_spill, simulations, 31).
provenance(r17_no_spill, weight_mass_permille, 31000).
provenance(r17_no_spill, confidence_permille, 548).
provenance(r17_no_spill, score_permille, 562).
provenance(r17_no_spill, batches, 1).

rule(r18_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r18_destination_still_approach, approach_moving_away).
body(r18_destination_still_approach, bouncy_liquid).
body(r18_destination_still_approach, dull_destination).
body(r18_destination_still_approach, end_rolled).
body(r18_destination_still_approach, end_steeply_tilted).
body(r18_destination_still_approach, end_to_side).
body(r18_destination_still_approach, grippy_source).
body(r18_destination_still_approach, heavy_liquid).
body(r18_destination_still_approach, light_destination).
body(r18_destination_still_approach, little_liquid).
body(r18_destination_still_approach, pour_centred).
body(r18_destination_still_approach, pour_in_line).
body(r18_destination_still_approach, pour_mid_height).
body(r18_destination_still_approach, pour_steeply_tilted).
body(r18_destination_still_approach, retreat_lowering).
body(r18_destination_still_approach, runny_liquid).
body(r18_destination_still_approach, slippery_destination).
body(r18_destination_still_approach, slow_retreat).
body(r18_destination_still_approach, start_below_rim).
body(r18_destination_still_approach, start_slightly_tilted).
learned(r18_destination_still_approach).
provenance(r18_destination_still_approach, antecedent, a18).
provenance(r18_destination_still_approach, parent, a17).
provenance(r18_destination_still_approach, simulations, 31).
provenance(r18_destination_still_approach, weight_mass_permille, 31000).
provenance(r18_destination_still_approach, confidence_permille, 710).
provenance(r18_destination_still_approach, score_permille, 265).
provenance(r18_destination_still_approach, batches, 1).

rule(r18_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r18_destination_still_retreat, approach_moving_away).
body(r18_destination_still_retreat, bouncy_liquid).
body(r18_destination_still_retreat, dull_destination).
body(r18_destination_still_retreat, end_rolled).
body(r18_destination_still_retreat, end_steeply_tilted).
body(r18_destination_still_retreat, end_to_side).
body(r18_destination_still_retreat, grippy_source).
body(r18_destination_still_retreat, heavy_liquid).
body(r18_destination_still_retreat, light_destination).
body(r18_destination_still_retreat, little_liquid).
body(r18_destination_still_retreat, pour_centred).
body(r18_destination_still_retreat, pour_in_line).
body(r18_destination_still_retreat, pour_mid_height).
body(r18_destination_still_retreat, pour_steeply_tilted).
body(r18_destination_still_retreat, retreat_lowering).
body(r18_destination_still_retreat, runny_liquid).
body(r18_destination_still_retreat, slippery_destination).
body(r18_destination_still_retreat, slow_retreat).
body(r18_destination_still_retreat, start_below_rim).
body(r18_destination_still_retreat, start_slightly_tilted).
learned(r18_destination_still_retreat).
provenance(r18_destination_still_retreat, antecedent, a18).
provenance(r18_destination_still_retreat, parent, a17).
provenance(r18_destination_still_retreat, simulations, 31).
provenance(r18_destination_still_retreat, weight_mass_permille, 31000).
provenance(r18_destination_still_retreat, confidence_permille, 806).
provenance(r18_destination_still_retreat, score_permille, 198).
provenance(r18_destination_still_retreat, batches, 1).

rule(r18_destination_still_settle, defeasible, destination_still_settle).
body(r18_destination_still_settle, approach_moving_away).
body(r18_destination_still_settle, bouncy_liquid).
body(r18_destination_still_settle, dull_destination).
body(r18_destination_still_settle, end_rolled).
body(r18_destination_still_settle, end_steeply_tilted).
body(r18_destination_still_settle, end_to_side).
body(r18_destination_still_settle, grippy_source).
body(r18_destination_still_settle, heavy_liquid).
body(r18_destination_still_settle, light_destination).
body(r18_destination_still_settle, little_liquid).
body(r18_destination_still_settle, pour_centred).
body(r18_destination_still_settle, pour_in_line).
body(r18_destination_still_settle, pour_mid_height).
body(r18_destination_still_settle, pour_steeply_tilted).
body(r18_destination_still_settle, retreat_lowering).
body(r18_destination_still_settle, runny_liquid).
body(r18_destination_still_settle, slippery_destination).
body(r18_destination_still_settle, slow_retreat).
body(r18_destination_still_settle, start_below_rim).
body(r18_destination_still_settle, start_slightly_tilted).
learned(r18_destination_still_settle).
provenance(r18_destination_still_settle, antecedent, a18).
provenance(r18_destination_still_settle, parent, a17).
provenance(r18_destination_still_settle, simulations, 31).
provenance(r18_destination_still_settle, weight_mass_permille, 31000).
provenance(r18_destination_still_settle, confidence_permille, 839).
provenance(r18_destination_still_settle, score_permille, 785).
provenance(r18_destination_still_settle, batches, 1).

rule(r18_destination_upright, defeasible, destination_upright).
body(r18_destination_upright, approach_moving_away).
body(r18_destination_upright, bouncy_liquid).
body(r18_destination_upright, dull_destination).
body(r18_destination_upright, end_rolled).
body(r18_destination_upright, end_steeply_tilted).
body(r18_destination_upright, end_to_side).
body(r18_destination_upright, grippy_source).
body(r18_destination_upright, heavy_liquid).
body(r18_destination_upright, light_destination).
body(r18_destination_upright, little_liquid).
body(r18_destination_upright, pour_centred).
body(r18_destination_upright, pour_in_line).
body(r18_destination_upright, pour_mid_height).
body(r18_destination_upright, pour_steeply_tilted).
body(r18_destination_upright, retreat_lowering).
body(r18_destination_upright, runny_liquid).
body(r18_destination_upright, slippery_destination).
body(r18_destination_upright, slow_retreat).
body(r18_destination_upright, start_below_rim).
body(r18_destination_upright, start_slightly_tilted).
learned(r18_destination_upright).
provenance(r18_destination_upright, antecedent, a18).
provenance(r18_destination_upright, parent, a17).
provenance(r18_destination_upright, simulations, 31).
provenance(r18_destination_upright, weight_mass_permille, 31000).
provenance(r18_destination_upright, confidence_permille, 935).
provenance(r18_destination_upright, score_permille, 914).
provenance(r18_destination_upright, batches, 1).

rule(r18_source_clear, defeasible, neg(source_clear)).
body(r18_source_clear, approach_moving_away).
body(r18_source_clear, bouncy_liquid).
body(r18_source_clear, dull_destination).
body(r18_source_clear, end_rolled).
body(r18_source_clear, end_steeply_tilted).
body(r18_source_clear, end_to_side).
body(r18_source_clear, grippy_source).
body(r18_source_clear, heavy_liquid).
body(r18_source_clear, light_destination).
body(r18_source_clear, little_liquid).
body(r18_source_clear, pour_centred).
body(r18_source_clear, pour_in_line).
body(r18_source_clear, pour_mid_height).
body(r18_source_clear, pour_steeply_tilted).
body(r18_source_clear, retreat_lowering).
body(r18_source_clear, runny_liquid).
body(r18_source_clear, slippery_destination).
body(r18_source_clear, slow_retreat).
body(r18_source_clear, start_below_rim).
body(r18_source_clear, start_slightly_tilted).
learned(r18_source_clear).
provenance(r18_source_clear, antecedent, a18).
provenance(r18_source_clear, parent, a17).
provenance(r18_source_clear, simulations, 31).
provenance(r18_source_clear, weight_mass_permille, 31000).
provenance(r18_source_clear, confidence_permille, 968).
provenance(r18_source_clear, score_permille, 32).
provenance(r18_source_clear, batches, 1).

rule(r18_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r18_liquid_leaves_source, approach_moving_away).
body(r18_liquid_leaves_source, bouncy_liquid).
body(r18_liquid_leaves_source, dull_destination).
body(r18_liquid_leaves_source, end_rolled).
body(r18_liquid_leaves_source, end_steeply_tilted).
body(r18_liquid_leaves_source, end_to_side).
body(r18_liquid_leaves_source, grippy_source).
body(r18_liquid_leaves_source, heavy_liquid).
body(r18_liquid_leaves_source, light_destination).
body(r18_liquid_leaves_source, little_liquid).
body(r18_liquid_leaves_source, pour_centred).
body(r18_liquid_leaves_source, pour_in_line).
body(r18_liquid_leaves_source, pour_mid_height).
body(r18_liquid_leaves_source, pour_steeply_tilted).
body(r18_liquid_leaves_source, retreat_lowering).
body(r18_liquid_leaves_source, runny_liquid).
body(r18_liquid_leaves_source, slippery_destination).
body(r18_liquid_leaves_source, slow_retreat).
body(r18_liquid_leaves_source, start_below_rim).
body(r18_liquid_leaves_source, start_slightly_tilted).
learned(r18_liquid_leaves_source).
provenance(r18_liquid_leaves_source, antecedent, a18).
provenance(r18_liquid_leaves_source, parent, a17).
provenance(r18_liquid_leaves_source, simulations, 31).
provenance(r18_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r18_liquid_leaves_source, confidence_permille, 839).
provenance(r18_liquid_leaves_source, score_permille, 830).
provenance(r18_liquid_leaves_source, batches, 1).

rule(r18_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r18_liquid_enters_destination, approach_moving_away).
body(r18_liquid_enters_destination, bouncy_liquid).
body(r18_liquid_enters_destination, dull_destination).
body(r18_liquid_enters_destination, end_rolled).
body(r18_liquid_enters_destination, end_steeply_tilted).
body(r18_liquid_enters_destination, end_to_side).
body(r18_liquid_enters_destination, grippy_source).
body(r18_liquid_enters_destination, heavy_liquid).
body(r18_liquid_enters_destination, light_destination).
body(r18_liquid_enters_destination, little_liquid).
body(r18_liquid_enters_destination, pour_centred).
body(r18_liquid_enters_destination, pour_in_line).
body(r18_liquid_enters_destination, pour_mid_height).
body(r18_liquid_enters_destination, pour_steeply_tilted).
body(r18_liquid_enters_destination, retreat_lowering).
body(r18_liquid_enters_destination, runny_liquid).
body(r18_liquid_enters_destination, slippery_destination).
body(r18_liquid_enters_destination, slow_retreat).
body(r18_liquid_enters_destination, start_below_rim).
body(r18_liquid_enters_destination, start_slightly_tilted).
learned(r18_liquid_enters_destination).
provenance(r18_liquid_enters_destination, antecedent, a18).
provenance(r18_liquid_enters_destination, parent, a17).
provenance(r18_liquid_enters_destination, simulations, 31).
provenance(r18_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r18_liquid_enters_destination, confidence_permille, 677).
provenance(r18_liquid_enters_destination, score_permille, 365).
provenance(r18_liquid_enters_destination, batches, 1).

rule(r18_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r18_liquid_remains_in_destination, approach_moving_away).
body(r18_liquid_remains_in_destination, bouncy_liquid).
body(r18_liquid_remains_in_destination, dull_destination).
body(r18_liquid_remains_in_destination, end_rolled).
body(r18_liquid_remains_in_destination, end_steeply_tilted).
body(r18_liquid_remains_in_destination, end_to_side).
body(r18_liquid_remains_in_destination, grippy_source).
body(r18_liquid_remains_in_destination, heavy_liquid).
body(r18_liquid_remains_in_destination, light_destination).
body(r18_liquid_remains_in_destination, little_liquid).
body(r18_liquid_remains_in_destination, pour_centred).
body(r18_liquid_remains_in_destination, pour_in_line).
body(r18_liquid_remains_in_destination, pour_mid_height).
body(r18_liquid_remains_in_destination, pour_steeply_tilted).
body(r18_liquid_remains_in_destination, retreat_lowering).
body(r18_liquid_remains_in_destination, runny_liquid).
body(r18_liquid_remains_in_destination, slippery_destination).
body(r18_liquid_remains_in_destination, slow_retreat).
body(r18_liquid_remains_in_destination, start_below_rim).
body(r18_liquid_remains_in_destination, start_slightly_tilted).
learned(r18_liquid_remains_in_destination).
provenance(r18_liquid_remains_in_destination, antecedent, a18).
provenance(r18_liquid_remains_in_destination, parent, a17).
provenance(r18_liquid_remains_in_destination, simulations, 31).
provenance(r18_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r18_liquid_remains_in_destination, confidence_permille, 839).
provenance(r18_liquid_remains_in_destination, score_permille, 820).
provenance(r18_liquid_remains_in_destination, batches, 1).

rule(r18_no_spill, defeasible, neg(no_spill)).
body(r18_no_spill, approach_moving_away).
body(r18_no_spill, bouncy_liquid).
body(r18_no_spill, dull_destination).
body(r18_no_spill, end_rolled).
body(r18_no_spill, end_steeply_tilted).
body(r18_no_spill, end_to_side).
body(r18_no_spill, grippy_source).
body(r18_no_spill, heavy_liquid).
body(r18_no_spill, light_destination).
body(r18_no_spill, little_liquid).
body(r18_no_spill, pour_centred).
body(r18_no_spill, pour_in_line).
body(r18_no_spill, pour_mid_height).
body(r18_no_spill, pour_steeply_tilted).
body(r18_no_spill, retreat_lowering).
body(r18_no_spill, runny_liquid).
body(r18_no_spill, slippery_destination).
body(r18_no_spill, slow_retreat).
body(r18_no_spill, start_below_rim).
body(r18_no_spill, start_slightly_tilted).
learned(r18_no_spill).
provenance(r18_no_spill, antecedent, a18).
provenance(r18_no_spill, parent, a17).
provenance(r18_no_spill, simulations, 31).
provenance(r18_no_spill, weight_mass_permille, 31000).
provenance(r18_no_spill, confidence_permille, 613).
provenance(r18_no_spill, score_permille, 417).
provenance(r18_no_spill, batches, 1).

rule(r19_destination_still_approach, defeasible, destination_still_approach).
learned(r19_destination_still_approach).
provenance(r19_destination_still_approach, antecedent, a19).
provenance(r19_destination_still_approach, parent, none).
provenance(r19_destination_still_approach, simulations, 62).
provenance(r19_destination_still_approach, weight_mass_permille, 31118).
provenance(r19_destination_still_approach, confidence_permille, 968).
provenance(r19_destination_still_approach, score_permille, 960).
provenance(r19_destination_still_approach, batches, 1).

rule(r19_destination_still_retreat, defeasible, destination_still_retreat).
learned(r19_destination_still_retreat).
provenance(r19_destination_still_retreat, antecedent, a19).
provenance(r19_destination_still_retreat, parent, none).
provenance(r19_destination_still_retreat, simulations, 62).
provenance(r19_destination_still_retreat, weight_mass_permille, 31118).
provenance(r19_destination_still_retreat, confidence_permille, 968).
provenance(r19_destination_still_retreat, score_permille, 977).
provenance(r19_destination_still_retreat, batches, 1).

rule(r19_destination_still_settle, defeasible, destination_still_settle).
learned(r19_destination_still_settle).
provenance(r19_destination_still_settle, antecedent, a19).
provenance(r19_destination_still_settle, parent, none).
provenance(r19_destination_still_settle, simulations, 62).
provenance(r19_destination_still_settle, weight_mass_permille, 31118).
provenance(r19_destination_still_settle, confidence_permille, 1000).
provenance(r19_destination_still_settle, score_permille, 998).
provenance(r19_destination_still_settle, batches, 1).

rule(r19_destination_upright, defeasible, destination_upright).
learned(r19_destination_upright).
provenance(r19_destination_upright, antecedent, a19).
provenance(r19_destination_upright, parent, none).
provenance(r19_destination_upright, simulations, 62).
provenance(r19_destination_upright, weight_mass_permille, 31118).
provenance(r19_destination_upright, confidence_permille, 1000).
provenance(r19_destination_upright, score_permille, 995).
provenance(r19_destination_upright, batches, 1).

rule(r19_source_clear, defeasible, source_clear).
learned(r19_source_clear).
provenance(r19_source_clear, antecedent, a19).
provenance(r19_source_clear, parent, none).
provenance(r19_source_clear, simulations, 62).
provenance(r19_source_clear, weight_mass_permille, 31118).
provenance(r19_source_clear, confidence_permille, 936).
provenance(r19_source_clear, score_permille, 936).
provenance(r19_source_clear, batches, 1).

rule(r19_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
learned(r19_liquid_leaves_source).
provenance(r19_liquid_leaves_source, antecedent, a19).
provenance(r19_liquid_leaves_source, parent, none).
provenance(r19_liquid_leaves_source, simulations, 62).
provenance(r19_liquid_leaves_source, weight_mass_permille, 31118).
provenance(r19_liquid_leaves_source, confidence_permille, 611).
provenance(r19_liquid_leaves_source, score_permille, 391).
provenance(r19_liquid_leaves_source, batches, 1).

rule(r19_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
learned(r19_liquid_enters_destination).
provenance(r19_liquid_enters_destination, antecedent, a19).
provenance(r19_liquid_enters_destination, parent, none).
provenance(r19_liquid_enters_destination, simulations, 62).
provenance(r19_liquid_enters_destination, weight_mass_permille, 31118).
provenance(r19_liquid_enters_destination, confidence_permille, 869).
provenance(r19_liquid_enters_destination, score_permille, 122).
provenance(r19_liquid_enters_destination, batches, 1).

rule(r19_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(r19_liquid_remains_in_destination).
provenance(r19_liquid_remains_in_destination, antecedent, a19).
provenance(r19_liquid_remains_in_destination, parent, none).
provenance(r19_liquid_remains_in_destination, simulations, 62).
provenance(r19_liquid_remains_in_destination, weight_mass_permille, 31118).
provenance(r19_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r19_liquid_remains_in_destination, score_permille, 987).
provenance(r19_liquid_remains_in_destination, batches, 1).

rule(r19_no_spill, defeasible, no_spill).
learned(r19_no_spill).
provenance(r19_no_spill, antecedent, a19).
provenance(r19_no_spill, parent, none).
provenance(r19_no_spill, simulations, 62).
provenance(r19_no_spill, weight_mass_permille, 31118).
provenance(r19_no_spill, confidence_permille, 743).
provenance(r19_no_spill, score_permille, 726).
provenance(r19_no_spill, batches, 1).

% General rules, learned from every pour of the exploration
% (bridge/learning/generalize.py): a default per expectation, exceptions
% and exceptions to those. provenance(Id, support, N): the pours whose
% description holds the body; kept: how many of them keep the head;
% confidence_permille: P(head | body) for the pours sampled for the body
% (a default the priors leave open: for the pours of the uniformly random
% scenes it decides).
% sup/2 below orders both layers (see bridge/learning/layers.py).
setting(general_pours, 765).
setting(general_rules, 16).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 765).
provenance(g0_destination_still_approach, kept, 340).
provenance(g0_destination_still_approach, confidence_permille, 990).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 765).
provenance(g0_destination_still_retreat, kept, 473).
provenance(g0_destination_still_retreat, confidence_permille, 993).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 765).
provenance(g0_destination_still_settle, kept, 591).
provenance(g0_destination_still_settle, confidence_permille, 999).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 765).
provenance(g0_destination_upright, kept, 701).
provenance(g0_destination_upright, confidence_permille, 1000).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 765).
provenance(g0_source_clear, kept, 239).
provenance(g0_source_clear, confidence_permille, 979).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, start_below_rim).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 567).
provenance(g1_source_clear, kept, 499).
provenance(g1_source_clear, confidence_permille, 619).
rule(g0_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 765).
provenance(g0_liquid_leaves_source, kept, 396).
provenance(g0_liquid_leaves_source, confidence_permille, 882).
rule(g1_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g1_liquid_leaves_source, end_steeply_tilted).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 328).
provenance(g1_liquid_leaves_source, kept, 267).
provenance(g1_liquid_leaves_source, confidence_permille, 810).
rule(g2_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g2_liquid_leaves_source, end_upside_down).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 39).
provenance(g2_liquid_leaves_source, kept, 39).
provenance(g2_liquid_leaves_source, confidence_permille, 999).
rule(g3_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g3_liquid_leaves_source, pour_steeply_tilted).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 65).
provenance(g3_liquid_leaves_source, kept, 56).
provenance(g3_liquid_leaves_source, confidence_permille, 640).
rule(g4_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g4_liquid_leaves_source, pour_upside_down).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 17).
provenance(g4_liquid_leaves_source, kept, 17).
provenance(g4_liquid_leaves_source, confidence_permille, 993).
rule(g0_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 765).
provenance(g0_liquid_enters_destination, kept, 449).
provenance(g0_liquid_enters_destination, confidence_permille, 798).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 765).
provenance(g0_liquid_remains_in_destination, kept, 492).
provenance(g0_liquid_remains_in_destination, confidence_permille, 1000).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 765).
provenance(g0_no_spill, kept, 522).
provenance(g0_no_spill, confidence_permille, 816).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, end_steeply_tilted).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 328).
provenance(g1_no_spill, kept, 197).
provenance(g1_no_spill, confidence_permille, 617).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, end_upside_down).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 39).
provenance(g2_no_spill, kept, 29).
provenance(g2_no_spill, confidence_permille, 729).
sup(r1_no_spill, g1_no_spill).
sup(r1_no_spill, g2_no_spill).
sup(r1_source_clear, g1_source_clear).
sup(r2_source_clear, g1_source_clear).
