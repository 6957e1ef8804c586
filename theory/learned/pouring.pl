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
%   setting(Key, Value): how the exploration ran.

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
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 25).
setting(simulations, 775).
setting(failed_simulations, 0).
setting(stopped, max_rules).
setting(a_new_left, 100).
setting(initial, pour_mid_height).
setting(initial, pour_near_rim).
setting(initial, pour_steeply_tilted).

rule(r1_destination_still_approach, defeasible, destination_still_approach).
body(r1_destination_still_approach, pour_mid_height).
body(r1_destination_still_approach, pour_near_rim).
body(r1_destination_still_approach, pour_steeply_tilted).
learned(r1_destination_still_approach).
provenance(r1_destination_still_approach, antecedent, a1).
provenance(r1_destination_still_approach, parent, none).
provenance(r1_destination_still_approach, simulations, 31).
provenance(r1_destination_still_approach, weight_mass_permille, 31000).
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
provenance(r1_destination_still_retreat, weight_mass_permille, 31000).
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
provenance(r1_destination_still_settle, weight_mass_permille, 31000).
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
provenance(r1_destination_upright, weight_mass_permille, 31000).
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
provenance(r1_source_clear, weight_mass_permille, 31000).
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
provenance(r1_liquid_leaves_source, weight_mass_permille, 31000).
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
provenance(r1_liquid_enters_destination, weight_mass_permille, 31000).
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
provenance(r1_liquid_remains_in_destination, weight_mass_permille, 31000).
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
provenance(r1_no_spill, weight_mass_permille, 31000).
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
provenance(r3_destination_still_approach, simulations, 31).
provenance(r3_destination_still_approach, weight_mass_permille, 31000).
provenance(r3_destination_still_approach, confidence_permille, 516).
provenance(r3_destination_still_approach, score_permille, 441).
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
provenance(r3_destination_still_retreat, simulations, 31).
provenance(r3_destination_still_retreat, weight_mass_permille, 31000).
provenance(r3_destination_still_retreat, confidence_permille, 613).
provenance(r3_destination_still_retreat, score_permille, 599).
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
provenance(r3_destination_still_settle, simulations, 31).
provenance(r3_destination_still_settle, weight_mass_permille, 31000).
provenance(r3_destination_still_settle, confidence_permille, 871).
provenance(r3_destination_still_settle, score_permille, 871).
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
provenance(r3_destination_upright, simulations, 31).
provenance(r3_destination_upright, weight_mass_permille, 31000).
provenance(r3_destination_upright, confidence_permille, 903).
provenance(r3_destination_upright, score_permille, 903).
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
provenance(r3_source_clear, simulations, 31).
provenance(r3_source_clear, weight_mass_permille, 31000).
provenance(r3_source_clear, confidence_permille, 774).
provenance(r3_source_clear, score_permille, 195).
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
provenance(r3_liquid_leaves_source, simulations, 31).
provenance(r3_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r3_liquid_leaves_source, confidence_permille, 1000).
provenance(r3_liquid_leaves_source, score_permille, 30).
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
provenance(r3_liquid_enters_destination, simulations, 31).
provenance(r3_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r3_liquid_enters_destination, confidence_permille, 903).
provenance(r3_liquid_enters_destination, score_permille, 149).
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
provenance(r3_liquid_remains_in_destination, simulations, 31).
provenance(r3_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r3_liquid_remains_in_destination, confidence_permille, 613).
provenance(r3_liquid_remains_in_destination, score_permille, 620).
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
provenance(r3_no_spill, simulations, 31).
provenance(r3_no_spill, weight_mass_permille, 31000).
provenance(r3_no_spill, confidence_permille, 1000).
provenance(r3_no_spill, score_permille, 990).
provenance(r3_no_spill, batches, 1).

rule(r4_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r4_destination_still_approach, bouncy_liquid).
body(r4_destination_still_approach, dull_destination).
body(r4_destination_still_approach, end_far_away).
body(r4_destination_still_approach, end_slightly_tilted).
body(r4_destination_still_approach, grippy_source).
body(r4_destination_still_approach, heavy_destination).
body(r4_destination_still_approach, heavy_source).
body(r4_destination_still_approach, light_liquid).
body(r4_destination_still_approach, pour_half_tilted).
body(r4_destination_still_approach, pour_in_line).
body(r4_destination_still_approach, pour_low).
body(r4_destination_still_approach, pour_near_rim).
body(r4_destination_still_approach, retreat_lowering).
body(r4_destination_still_approach, slippery_destination).
body(r4_destination_still_approach, slow_approach).
body(r4_destination_still_approach, slow_retreat).
body(r4_destination_still_approach, start_below_rim).
body(r4_destination_still_approach, start_tilted_back).
body(r4_destination_still_approach, sticky_liquid).
learned(r4_destination_still_approach).
provenance(r4_destination_still_approach, antecedent, a4).
provenance(r4_destination_still_approach, parent, none).
provenance(r4_destination_still_approach, simulations, 31).
provenance(r4_destination_still_approach, weight_mass_permille, 31000).
provenance(r4_destination_still_approach, confidence_permille, 774).
provenance(r4_destination_still_approach, score_permille, 236).
provenance(r4_destination_still_approach, batches, 1).

rule(r4_destination_still_retreat, defeasible, destination_still_retreat).
body(r4_destination_still_retreat, bouncy_liquid).
body(r4_destination_still_retreat, dull_destination).
body(r4_destination_still_retreat, end_far_away).
body(r4_destination_still_retreat, end_slightly_tilted).
body(r4_destination_still_retreat, grippy_source).
body(r4_destination_still_retreat, heavy_destination).
body(r4_destination_still_retreat, heavy_source).
body(r4_destination_still_retreat, light_liquid).
body(r4_destination_still_retreat, pour_half_tilted).
body(r4_destination_still_retreat, pour_in_line).
body(r4_destination_still_retreat, pour_low).
body(r4_destination_still_retreat, pour_near_rim).
body(r4_destination_still_retreat, retreat_lowering).
body(r4_destination_still_retreat, slippery_destination).
body(r4_destination_still_retreat, slow_approach).
body(r4_destination_still_retreat, slow_retreat).
body(r4_destination_still_retreat, start_below_rim).
body(r4_destination_still_retreat, start_tilted_back).
body(r4_destination_still_retreat, sticky_liquid).
learned(r4_destination_still_retreat).
provenance(r4_destination_still_retreat, antecedent, a4).
provenance(r4_destination_still_retreat, parent, none).
provenance(r4_destination_still_retreat, simulations, 31).
provenance(r4_destination_still_retreat, weight_mass_permille, 31000).
provenance(r4_destination_still_retreat, confidence_permille, 871).
provenance(r4_destination_still_retreat, score_permille, 852).
provenance(r4_destination_still_retreat, batches, 1).

rule(r4_destination_still_settle, defeasible, destination_still_settle).
body(r4_destination_still_settle, bouncy_liquid).
body(r4_destination_still_settle, dull_destination).
body(r4_destination_still_settle, end_far_away).
body(r4_destination_still_settle, end_slightly_tilted).
body(r4_destination_still_settle, grippy_source).
body(r4_destination_still_settle, heavy_destination).
body(r4_destination_still_settle, heavy_source).
body(r4_destination_still_settle, light_liquid).
body(r4_destination_still_settle, pour_half_tilted).
body(r4_destination_still_settle, pour_in_line).
body(r4_destination_still_settle, pour_low).
body(r4_destination_still_settle, pour_near_rim).
body(r4_destination_still_settle, retreat_lowering).
body(r4_destination_still_settle, slippery_destination).
body(r4_destination_still_settle, slow_approach).
body(r4_destination_still_settle, slow_retreat).
body(r4_destination_still_settle, start_below_rim).
body(r4_destination_still_settle, start_tilted_back).
body(r4_destination_still_settle, sticky_liquid).
learned(r4_destination_still_settle).
provenance(r4_destination_still_settle, antecedent, a4).
provenance(r4_destination_still_settle, parent, none).
provenance(r4_destination_still_settle, simulations, 31).
provenance(r4_destination_still_settle, weight_mass_permille, 31000).
provenance(r4_destination_still_settle, confidence_permille, 1000).
provenance(r4_destination_still_settle, score_permille, 990).
provenance(r4_destination_still_settle, batches, 1).

rule(r4_destination_upright, defeasible, destination_upright).
body(r4_destination_upright, bouncy_liquid).
body(r4_destination_upright, dull_destination).
body(r4_destination_upright, end_far_away).
body(r4_destination_upright, end_slightly_tilted).
body(r4_destination_upright, grippy_source).
body(r4_destination_upright, heavy_destination).
body(r4_destination_upright, heavy_source).
body(r4_destination_upright, light_liquid).
body(r4_destination_upright, pour_half_tilted).
body(r4_destination_upright, pour_in_line).
body(r4_destination_upright, pour_low).
body(r4_destination_upright, pour_near_rim).
body(r4_destination_upright, retreat_lowering).
body(r4_destination_upright, slippery_destination).
body(r4_destination_upright, slow_approach).
body(r4_destination_upright, slow_retreat).
body(r4_destination_upright, start_below_rim).
body(r4_destination_upright, start_tilted_back).
body(r4_destination_upright, sticky_liquid).
learned(r4_destination_upright).
provenance(r4_destination_upright, antecedent, a4).
provenance(r4_destination_upright, parent, none).
provenance(r4_destination_upright, simulations, 31).
provenance(r4_destination_upright, weight_mass_permille, 31000).
provenance(r4_destination_upright, confidence_permille, 968).
provenance(r4_destination_upright, score_permille, 967).
provenance(r4_destination_upright, batches, 1).

rule(r4_source_clear, defeasible, neg(source_clear)).
body(r4_source_clear, bouncy_liquid).
body(r4_source_clear, dull_destination).
body(r4_source_clear, end_far_away).
body(r4_source_clear, end_slightly_tilted).
body(r4_source_clear, grippy_source).
body(r4_source_clear, heavy_destination).
body(r4_source_clear, heavy_source).
body(r4_source_clear, light_liquid).
body(r4_source_clear, pour_half_tilted).
body(r4_source_clear, pour_in_line).
body(r4_source_clear, pour_low).
body(r4_source_clear, pour_near_rim).
body(r4_source_clear, retreat_lowering).
body(r4_source_clear, slippery_destination).
body(r4_source_clear, slow_approach).
body(r4_source_clear, slow_retreat).
body(r4_source_clear, start_below_rim).
body(r4_source_clear, start_tilted_back).
body(r4_source_clear, sticky_liquid).
learned(r4_source_clear).
provenance(r4_source_clear, antecedent, a4).
provenance(r4_source_clear, parent, none).
provenance(r4_source_clear, simulations, 31).
provenance(r4_source_clear, weight_mass_permille, 31000).
provenance(r4_source_clear, confidence_permille, 903).
provenance(r4_source_clear, score_permille, 75).
provenance(r4_source_clear, batches, 1).

rule(r4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r4_liquid_leaves_source, bouncy_liquid).
body(r4_liquid_leaves_source, dull_destination).
body(r4_liquid_leaves_source, end_far_away).
body(r4_liquid_leaves_source, end_slightly_tilted).
body(r4_liquid_leaves_source, grippy_source).
body(r4_liquid_leaves_source, heavy_destination).
body(r4_liquid_leaves_source, heavy_source).
body(r4_liquid_leaves_source, light_liquid).
body(r4_liquid_leaves_source, pour_half_tilted).
body(r4_liquid_leaves_source, pour_in_line).
body(r4_liquid_leaves_source, pour_low).
body(r4_liquid_leaves_source, pour_near_rim).
body(r4_liquid_leaves_source, retreat_lowering).
body(r4_liquid_leaves_source, slippery_destination).
body(r4_liquid_leaves_source, slow_approach).
body(r4_liquid_leaves_source, slow_retreat).
body(r4_liquid_leaves_source, start_below_rim).
body(r4_liquid_leaves_source, start_tilted_back).
body(r4_liquid_leaves_source, sticky_liquid).
learned(r4_liquid_leaves_source).
provenance(r4_liquid_leaves_source, antecedent, a4).
provenance(r4_liquid_leaves_source, parent, none).
provenance(r4_liquid_leaves_source, simulations, 31).
provenance(r4_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r4_liquid_leaves_source, confidence_permille, 935).
provenance(r4_liquid_leaves_source, score_permille, 82).
provenance(r4_liquid_leaves_source, batches, 1).

rule(r4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r4_liquid_enters_destination, bouncy_liquid).
body(r4_liquid_enters_destination, dull_destination).
body(r4_liquid_enters_destination, end_far_away).
body(r4_liquid_enters_destination, end_slightly_tilted).
body(r4_liquid_enters_destination, grippy_source).
body(r4_liquid_enters_destination, heavy_destination).
body(r4_liquid_enters_destination, heavy_source).
body(r4_liquid_enters_destination, light_liquid).
body(r4_liquid_enters_destination, pour_half_tilted).
body(r4_liquid_enters_destination, pour_in_line).
body(r4_liquid_enters_destination, pour_low).
body(r4_liquid_enters_destination, pour_near_rim).
body(r4_liquid_enters_destination, retreat_lowering).
body(r4_liquid_enters_destination, slippery_destination).
body(r4_liquid_enters_destination, slow_approach).
body(r4_liquid_enters_destination, slow_retreat).
body(r4_liquid_enters_destination, start_below_rim).
body(r4_liquid_enters_destination, start_tilted_back).
body(r4_liquid_enters_destination, sticky_liquid).
learned(r4_liquid_enters_destination).
provenance(r4_liquid_enters_destination, antecedent, a4).
provenance(r4_liquid_enters_destination, parent, none).
provenance(r4_liquid_enters_destination, simulations, 31).
provenance(r4_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r4_liquid_enters_destination, confidence_permille, 935).
provenance(r4_liquid_enters_destination, score_permille, 77).
provenance(r4_liquid_enters_destination, batches, 1).

rule(r4_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r4_liquid_remains_in_destination, bouncy_liquid).
body(r4_liquid_remains_in_destination, dull_destination).
body(r4_liquid_remains_in_destination, end_far_away).
body(r4_liquid_remains_in_destination, end_slightly_tilted).
body(r4_liquid_remains_in_destination, grippy_source).
body(r4_liquid_remains_in_destination, heavy_destination).
body(r4_liquid_remains_in_destination, heavy_source).
body(r4_liquid_remains_in_destination, light_liquid).
body(r4_liquid_remains_in_destination, pour_half_tilted).
body(r4_liquid_remains_in_destination, pour_in_line).
body(r4_liquid_remains_in_destination, pour_low).
body(r4_liquid_remains_in_destination, pour_near_rim).
body(r4_liquid_remains_in_destination, retreat_lowering).
body(r4_liquid_remains_in_destination, slippery_destination).
body(r4_liquid_remains_in_destination, slow_approach).
body(r4_liquid_remains_in_destination, slow_retreat).
body(r4_liquid_remains_in_destination, start_below_rim).
body(r4_liquid_remains_in_destination, start_tilted_back).
body(r4_liquid_remains_in_destination, sticky_liquid).
learned(r4_liquid_remains_in_destination).
provenance(r4_liquid_remains_in_destination, antecedent, a4).
provenance(r4_liquid_remains_in_destination, parent, none).
provenance(r4_liquid_remains_in_destination, simulations, 31).
provenance(r4_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r4_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r4_liquid_remains_in_destination, score_permille, 996).
provenance(r4_liquid_remains_in_destination, batches, 1).

rule(r4_no_spill, defeasible, no_spill).
body(r4_no_spill, bouncy_liquid).
body(r4_no_spill, dull_destination).
body(r4_no_spill, end_far_away).
body(r4_no_spill, end_slightly_tilted).
body(r4_no_spill, grippy_source).
body(r4_no_spill, heavy_destination).
body(r4_no_spill, heavy_source).
body(r4_no_spill, light_liquid).
body(r4_no_spill, pour_half_tilted).
body(r4_no_spill, pour_in_line).
body(r4_no_spill, pour_low).
body(r4_no_spill, pour_near_rim).
body(r4_no_spill, retreat_lowering).
body(r4_no_spill, slippery_destination).
body(r4_no_spill, slow_approach).
body(r4_no_spill, slow_retreat).
body(r4_no_spill, start_below_rim).
body(r4_no_spill, start_tilted_back).
body(r4_no_spill, sticky_liquid).
learned(r4_no_spill).
provenance(r4_no_spill, antecedent, a4).
provenance(r4_no_spill, parent, none).
provenance(r4_no_spill, simulations, 31).
provenance(r4_no_spill, weight_mass_permille, 31000).
provenance(r4_no_spill, confidence_permille, 1000).
provenance(r4_no_spill, score_permille, 994).
provenance(r4_no_spill, batches, 1).

rule(r5_destination_still_approach, defeasible, destination_still_approach).
body(r5_destination_still_approach, bouncy_destination).
body(r5_destination_still_approach, bouncy_liquid).
body(r5_destination_still_approach, end_rolled).
body(r5_destination_still_approach, end_steeply_tilted).
body(r5_destination_still_approach, fast_retreat).
body(r5_destination_still_approach, light_destination).
body(r5_destination_still_approach, medium_liquid).
body(r5_destination_still_approach, moderate_approach).
body(r5_destination_still_approach, much_liquid).
body(r5_destination_still_approach, pour_half_tilted).
body(r5_destination_still_approach, pour_low).
body(r5_destination_still_approach, pour_offset_sideways).
body(r5_destination_still_approach, retreat_lowering).
body(r5_destination_still_approach, retreat_moving_closer).
body(r5_destination_still_approach, runny_liquid).
body(r5_destination_still_approach, slippery_destination).
body(r5_destination_still_approach, start_centred).
body(r5_destination_still_approach, start_mid_height).
body(r5_destination_still_approach, start_tilted_back).
learned(r5_destination_still_approach).
provenance(r5_destination_still_approach, antecedent, a5).
provenance(r5_destination_still_approach, parent, none).
provenance(r5_destination_still_approach, simulations, 31).
provenance(r5_destination_still_approach, weight_mass_permille, 31000).
provenance(r5_destination_still_approach, confidence_permille, 839).
provenance(r5_destination_still_approach, score_permille, 840).
provenance(r5_destination_still_approach, batches, 1).

rule(r5_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r5_destination_still_retreat, bouncy_destination).
body(r5_destination_still_retreat, bouncy_liquid).
body(r5_destination_still_retreat, end_rolled).
body(r5_destination_still_retreat, end_steeply_tilted).
body(r5_destination_still_retreat, fast_retreat).
body(r5_destination_still_retreat, light_destination).
body(r5_destination_still_retreat, medium_liquid).
body(r5_destination_still_retreat, moderate_approach).
body(r5_destination_still_retreat, much_liquid).
body(r5_destination_still_retreat, pour_half_tilted).
body(r5_destination_still_retreat, pour_low).
body(r5_destination_still_retreat, pour_offset_sideways).
body(r5_destination_still_retreat, retreat_lowering).
body(r5_destination_still_retreat, retreat_moving_closer).
body(r5_destination_still_retreat, runny_liquid).
body(r5_destination_still_retreat, slippery_destination).
body(r5_destination_still_retreat, start_centred).
body(r5_destination_still_retreat, start_mid_height).
body(r5_destination_still_retreat, start_tilted_back).
learned(r5_destination_still_retreat).
provenance(r5_destination_still_retreat, antecedent, a5).
provenance(r5_destination_still_retreat, parent, none).
provenance(r5_destination_still_retreat, simulations, 31).
provenance(r5_destination_still_retreat, weight_mass_permille, 31000).
provenance(r5_destination_still_retreat, confidence_permille, 581).
provenance(r5_destination_still_retreat, score_permille, 403).
provenance(r5_destination_still_retreat, batches, 1).

rule(r5_destination_still_settle, defeasible, destination_still_settle).
body(r5_destination_still_settle, bouncy_destination).
body(r5_destination_still_settle, bouncy_liquid).
body(r5_destination_still_settle, end_rolled).
body(r5_destination_still_settle, end_steeply_tilted).
body(r5_destination_still_settle, fast_retreat).
body(r5_destination_still_settle, light_destination).
body(r5_destination_still_settle, medium_liquid).
body(r5_destination_still_settle, moderate_approach).
body(r5_destination_still_settle, much_liquid).
body(r5_destination_still_settle, pour_half_tilted).
body(r5_destination_still_settle, pour_low).
body(r5_destination_still_settle, pour_offset_sideways).
body(r5_destination_still_settle, retreat_lowering).
body(r5_destination_still_settle, retreat_moving_closer).
body(r5_destination_still_settle, runny_liquid).
body(r5_destination_still_settle, slippery_destination).
body(r5_destination_still_settle, start_centred).
body(r5_destination_still_settle, start_mid_height).
body(r5_destination_still_settle, start_tilted_back).
learned(r5_destination_still_settle).
provenance(r5_destination_still_settle, antecedent, a5).
provenance(r5_destination_still_settle, parent, none).
provenance(r5_destination_still_settle, simulations, 31).
provenance(r5_destination_still_settle, weight_mass_permille, 31000).
provenance(r5_destination_still_settle, confidence_permille, 516).
provenance(r5_destination_still_settle, score_permille, 500).
provenance(r5_destination_still_settle, batches, 1).

rule(r5_destination_upright, defeasible, destination_upright).
body(r5_destination_upright, bouncy_destination).
body(r5_destination_upright, bouncy_liquid).
body(r5_destination_upright, end_rolled).
body(r5_destination_upright, end_steeply_tilted).
body(r5_destination_upright, fast_retreat).
body(r5_destination_upright, light_destination).
body(r5_destination_upright, medium_liquid).
body(r5_destination_upright, moderate_approach).
body(r5_destination_upright, much_liquid).
body(r5_destination_upright, pour_half_tilted).
body(r5_destination_upright, pour_low).
body(r5_destination_upright, pour_offset_sideways).
body(r5_destination_upright, retreat_lowering).
body(r5_destination_upright, retreat_moving_closer).
body(r5_destination_upright, runny_liquid).
body(r5_destination_upright, slippery_destination).
body(r5_destination_upright, start_centred).
body(r5_destination_upright, start_mid_height).
body(r5_destination_upright, start_tilted_back).
learned(r5_destination_upright).
provenance(r5_destination_upright, antecedent, a5).
provenance(r5_destination_upright, parent, none).
provenance(r5_destination_upright, simulations, 31).
provenance(r5_destination_upright, weight_mass_permille, 31000).
provenance(r5_destination_upright, confidence_permille, 935).
provenance(r5_destination_upright, score_permille, 923).
provenance(r5_destination_upright, batches, 1).

rule(r5_source_clear, defeasible, neg(source_clear)).
body(r5_source_clear, bouncy_destination).
body(r5_source_clear, bouncy_liquid).
body(r5_source_clear, end_rolled).
body(r5_source_clear, end_steeply_tilted).
body(r5_source_clear, fast_retreat).
body(r5_source_clear, light_destination).
body(r5_source_clear, medium_liquid).
body(r5_source_clear, moderate_approach).
body(r5_source_clear, much_liquid).
body(r5_source_clear, pour_half_tilted).
body(r5_source_clear, pour_low).
body(r5_source_clear, pour_offset_sideways).
body(r5_source_clear, retreat_lowering).
body(r5_source_clear, retreat_moving_closer).
body(r5_source_clear, runny_liquid).
body(r5_source_clear, slippery_destination).
body(r5_source_clear, start_centred).
body(r5_source_clear, start_mid_height).
body(r5_source_clear, start_tilted_back).
learned(r5_source_clear).
provenance(r5_source_clear, antecedent, a5).
provenance(r5_source_clear, parent, none).
provenance(r5_source_clear, simulations, 31).
provenance(r5_source_clear, weight_mass_permille, 31000).
provenance(r5_source_clear, confidence_permille, 516).
provenance(r5_source_clear, score_permille, 483).
provenance(r5_source_clear, batches, 1).

rule(r5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r5_liquid_leaves_source, bouncy_destination).
body(r5_liquid_leaves_source, bouncy_liquid).
body(r5_liquid_leaves_source, end_rolled).
body(r5_liquid_leaves_source, end_steeply_tilted).
body(r5_liquid_leaves_source, fast_retreat).
body(r5_liquid_leaves_source, light_destination).
body(r5_liquid_leaves_source, medium_liquid).
body(r5_liquid_leaves_source, moderate_approach).
body(r5_liquid_leaves_source, much_liquid).
body(r5_liquid_leaves_source, pour_half_tilted).
body(r5_liquid_leaves_source, pour_low).
body(r5_liquid_leaves_source, pour_offset_sideways).
body(r5_liquid_leaves_source, retreat_lowering).
body(r5_liquid_leaves_source, retreat_moving_closer).
body(r5_liquid_leaves_source, runny_liquid).
body(r5_liquid_leaves_source, slippery_destination).
body(r5_liquid_leaves_source, start_centred).
body(r5_liquid_leaves_source, start_mid_height).
body(r5_liquid_leaves_source, start_tilted_back).
learned(r5_liquid_leaves_source).
provenance(r5_liquid_leaves_source, antecedent, a5).
provenance(r5_liquid_leaves_source, parent, none).
provenance(r5_liquid_leaves_source, simulations, 31).
provenance(r5_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r5_liquid_leaves_source, confidence_permille, 1000).
provenance(r5_liquid_leaves_source, score_permille, 985).
provenance(r5_liquid_leaves_source, batches, 1).

rule(r5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r5_liquid_enters_destination, bouncy_destination).
body(r5_liquid_enters_destination, bouncy_liquid).
body(r5_liquid_enters_destination, end_rolled).
body(r5_liquid_enters_destination, end_steeply_tilted).
body(r5_liquid_enters_destination, fast_retreat).
body(r5_liquid_enters_destination, light_destination).
body(r5_liquid_enters_destination, medium_liquid).
body(r5_liquid_enters_destination, moderate_approach).
body(r5_liquid_enters_destination, much_liquid).
body(r5_liquid_enters_destination, pour_half_tilted).
body(r5_liquid_enters_destination, pour_low).
body(r5_liquid_enters_destination, pour_offset_sideways).
body(r5_liquid_enters_destination, retreat_lowering).
body(r5_liquid_enters_destination, retreat_moving_closer).
body(r5_liquid_enters_destination, runny_liquid).
body(r5_liquid_enters_destination, slippery_destination).
body(r5_liquid_enters_destination, start_centred).
body(r5_liquid_enters_destination, start_mid_height).
body(r5_liquid_enters_destination, start_tilted_back).
learned(r5_liquid_enters_destination).
provenance(r5_liquid_enters_destination, antecedent, a5).
provenance(r5_liquid_enters_destination, parent, none).
provenance(r5_liquid_enters_destination, simulations, 31).
provenance(r5_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r5_liquid_enters_destination, confidence_permille, 774).
provenance(r5_liquid_enters_destination, score_permille, 228).
provenance(r5_liquid_enters_destination, batches, 1).

rule(r5_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r5_liquid_remains_in_destination, bouncy_destination).
body(r5_liquid_remains_in_destination, bouncy_liquid).
body(r5_liquid_remains_in_destination, end_rolled).
body(r5_liquid_remains_in_destination, end_steeply_tilted).
body(r5_liquid_remains_in_destination, fast_retreat).
body(r5_liquid_remains_in_destination, light_destination).
body(r5_liquid_remains_in_destination, medium_liquid).
body(r5_liquid_remains_in_destination, moderate_approach).
body(r5_liquid_remains_in_destination, much_liquid).
body(r5_liquid_remains_in_destination, pour_half_tilted).
body(r5_liquid_remains_in_destination, pour_low).
body(r5_liquid_remains_in_destination, pour_offset_sideways).
body(r5_liquid_remains_in_destination, retreat_lowering).
body(r5_liquid_remains_in_destination, retreat_moving_closer).
body(r5_liquid_remains_in_destination, runny_liquid).
body(r5_liquid_remains_in_destination, slippery_destination).
body(r5_liquid_remains_in_destination, start_centred).
body(r5_liquid_remains_in_destination, start_mid_height).
body(r5_liquid_remains_in_destination, start_tilted_back).
learned(r5_liquid_remains_in_destination).
provenance(r5_liquid_remains_in_destination, antecedent, a5).
provenance(r5_liquid_remains_in_destination, parent, none).
provenance(r5_liquid_remains_in_destination, simulations, 31).
provenance(r5_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r5_liquid_remains_in_destination, confidence_permille, 806).
provenance(r5_liquid_remains_in_destination, score_permille, 804).
provenance(r5_liquid_remains_in_destination, batches, 1).

rule(r5_no_spill, defeasible, neg(no_spill)).
body(r5_no_spill, bouncy_destination).
body(r5_no_spill, bouncy_liquid).
body(r5_no_spill, end_rolled).
body(r5_no_spill, end_steeply_tilted).
body(r5_no_spill, fast_retreat).
body(r5_no_spill, light_destination).
body(r5_no_spill, medium_liquid).
body(r5_no_spill, moderate_approach).
body(r5_no_spill, much_liquid).
body(r5_no_spill, pour_half_tilted).
body(r5_no_spill, pour_low).
body(r5_no_spill, pour_offset_sideways).
body(r5_no_spill, retreat_lowering).
body(r5_no_spill, retreat_moving_closer).
body(r5_no_spill, runny_liquid).
body(r5_no_spill, slippery_destination).
body(r5_no_spill, start_centred).
body(r5_no_spill, start_mid_height).
body(r5_no_spill, start_tilted_back).
learned(r5_no_spill).
provenance(r5_no_spill, antecedent, a5).
provenance(r5_no_spill, parent, none).
provenance(r5_no_spill, simulations, 31).
provenance(r5_no_spill, weight_mass_permille, 31000).
provenance(r5_no_spill, confidence_permille, 935).
provenance(r5_no_spill, score_permille, 78).
provenance(r5_no_spill, batches, 1).

rule(r6_destination_still_approach, defeasible, destination_still_approach).
body(r6_destination_still_approach, approach_lowering).
body(r6_destination_still_approach, dull_source).
body(r6_destination_still_approach, end_slightly_tilted).
body(r6_destination_still_approach, end_to_side).
body(r6_destination_still_approach, fast_approach).
body(r6_destination_still_approach, grippy_source).
body(r6_destination_still_approach, heavy_source).
body(r6_destination_still_approach, light_destination).
body(r6_destination_still_approach, medium_liquid).
body(r6_destination_still_approach, pour_centred).
body(r6_destination_still_approach, pour_half_tilted).
body(r6_destination_still_approach, pour_high).
body(r6_destination_still_approach, pour_in_line).
body(r6_destination_still_approach, pour_level).
body(r6_destination_still_approach, runny_liquid).
body(r6_destination_still_approach, slippery_destination).
body(r6_destination_still_approach, some_liquid).
body(r6_destination_still_approach, start_centred).
learned(r6_destination_still_approach).
provenance(r6_destination_still_approach, antecedent, a6).
provenance(r6_destination_still_approach, parent, none).
provenance(r6_destination_still_approach, simulations, 31).
provenance(r6_destination_still_approach, weight_mass_permille, 31000).
provenance(r6_destination_still_approach, confidence_permille, 1000).
provenance(r6_destination_still_approach, score_permille, 993).
provenance(r6_destination_still_approach, batches, 1).

rule(r6_destination_still_retreat, defeasible, destination_still_retreat).
body(r6_destination_still_retreat, approach_lowering).
body(r6_destination_still_retreat, dull_source).
body(r6_destination_still_retreat, end_slightly_tilted).
body(r6_destination_still_retreat, end_to_side).
body(r6_destination_still_retreat, fast_approach).
body(r6_destination_still_retreat, grippy_source).
body(r6_destination_still_retreat, heavy_source).
body(r6_destination_still_retreat, light_destination).
body(r6_destination_still_retreat, medium_liquid).
body(r6_destination_still_retreat, pour_centred).
body(r6_destination_still_retreat, pour_half_tilted).
body(r6_destination_still_retreat, pour_high).
body(r6_destination_still_retreat, pour_in_line).
body(r6_destination_still_retreat, pour_level).
body(r6_destination_still_retreat, runny_liquid).
body(r6_destination_still_retreat, slippery_destination).
body(r6_destination_still_retreat, some_liquid).
body(r6_destination_still_retreat, start_centred).
learned(r6_destination_still_retreat).
provenance(r6_destination_still_retreat, antecedent, a6).
provenance(r6_destination_still_retreat, parent, none).
provenance(r6_destination_still_retreat, simulations, 31).
provenance(r6_destination_still_retreat, weight_mass_permille, 31000).
provenance(r6_destination_still_retreat, confidence_permille, 1000).
provenance(r6_destination_still_retreat, score_permille, 1000).
provenance(r6_destination_still_retreat, batches, 1).

rule(r6_destination_still_settle, defeasible, destination_still_settle).
body(r6_destination_still_settle, approach_lowering).
body(r6_destination_still_settle, dull_source).
body(r6_destination_still_settle, end_slightly_tilted).
body(r6_destination_still_settle, end_to_side).
body(r6_destination_still_settle, fast_approach).
body(r6_destination_still_settle, grippy_source).
body(r6_destination_still_settle, heavy_source).
body(r6_destination_still_settle, light_destination).
body(r6_destination_still_settle, medium_liquid).
body(r6_destination_still_settle, pour_centred).
body(r6_destination_still_settle, pour_half_tilted).
body(r6_destination_still_settle, pour_high).
body(r6_destination_still_settle, pour_in_line).
body(r6_destination_still_settle, pour_level).
body(r6_destination_still_settle, runny_liquid).
body(r6_destination_still_settle, slippery_destination).
body(r6_destination_still_settle, some_liquid).
body(r6_destination_still_settle, start_centred).
learned(r6_destination_still_settle).
provenance(r6_destination_still_settle, antecedent, a6).
provenance(r6_destination_still_settle, parent, none).
provenance(r6_destination_still_settle, simulations, 31).
provenance(r6_destination_still_settle, weight_mass_permille, 31000).
provenance(r6_destination_still_settle, confidence_permille, 1000).
provenance(r6_destination_still_settle, score_permille, 1000).
provenance(r6_destination_still_settle, batches, 1).

rule(r6_destination_upright, defeasible, destination_upright).
body(r6_destination_upright, approach_lowering).
body(r6_destination_upright, dull_source).
body(r6_destination_upright, end_slightly_tilted).
body(r6_destination_upright, end_to_side).
body(r6_destination_upright, fast_approach).
body(r6_destination_upright, grippy_source).
body(r6_destination_upright, heavy_source).
body(r6_destination_upright, light_destination).
body(r6_destination_upright, medium_liquid).
body(r6_destination_upright, pour_centred).
body(r6_destination_upright, pour_half_tilted).
body(r6_destination_upright, pour_high).
body(r6_destination_upright, pour_in_line).
body(r6_destination_upright, pour_level).
body(r6_destination_upright, runny_liquid).
body(r6_destination_upright, slippery_destination).
body(r6_destination_upright, some_liquid).
body(r6_destination_upright, start_centred).
learned(r6_destination_upright).
provenance(r6_destination_upright, antecedent, a6).
provenance(r6_destination_upright, parent, none).
provenance(r6_destination_upright, simulations, 31).
provenance(r6_destination_upright, weight_mass_permille, 31000).
provenance(r6_destination_upright, confidence_permille, 1000).
provenance(r6_destination_upright, score_permille, 1000).
provenance(r6_destination_upright, batches, 1).

rule(r6_source_clear, defeasible, source_clear).
body(r6_source_clear, approach_lowering).
body(r6_source_clear, dull_source).
body(r6_source_clear, end_slightly_tilted).
body(r6_source_clear, end_to_side).
body(r6_source_clear, fast_approach).
body(r6_source_clear, grippy_source).
body(r6_source_clear, heavy_source).
body(r6_source_clear, light_destination).
body(r6_source_clear, medium_liquid).
body(r6_source_clear, pour_centred).
body(r6_source_clear, pour_half_tilted).
body(r6_source_clear, pour_high).
body(r6_source_clear, pour_in_line).
body(r6_source_clear, pour_level).
body(r6_source_clear, runny_liquid).
body(r6_source_clear, slippery_destination).
body(r6_source_clear, some_liquid).
body(r6_source_clear, start_centred).
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
body(r6_liquid_leaves_source, dull_source).
body(r6_liquid_leaves_source, end_slightly_tilted).
body(r6_liquid_leaves_source, end_to_side).
body(r6_liquid_leaves_source, fast_approach).
body(r6_liquid_leaves_source, grippy_source).
body(r6_liquid_leaves_source, heavy_source).
body(r6_liquid_leaves_source, light_destination).
body(r6_liquid_leaves_source, medium_liquid).
body(r6_liquid_leaves_source, pour_centred).
body(r6_liquid_leaves_source, pour_half_tilted).
body(r6_liquid_leaves_source, pour_high).
body(r6_liquid_leaves_source, pour_in_line).
body(r6_liquid_leaves_source, pour_level).
body(r6_liquid_leaves_source, runny_liquid).
body(r6_liquid_leaves_source, slippery_destination).
body(r6_liquid_leaves_source, some_liquid).
body(r6_liquid_leaves_source, start_centred).
learned(r6_liquid_leaves_source).
provenance(r6_liquid_leaves_source, antecedent, a6).
provenance(r6_liquid_leaves_source, parent, none).
provenance(r6_liquid_leaves_source, simulations, 31).
provenance(r6_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r6_liquid_leaves_source, confidence_permille, 1000).
provenance(r6_liquid_leaves_source, score_permille, 1).
provenance(r6_liquid_leaves_source, batches, 1).

rule(r6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r6_liquid_enters_destination, approach_lowering).
body(r6_liquid_enters_destination, dull_source).
body(r6_liquid_enters_destination, end_slightly_tilted).
body(r6_liquid_enters_destination, end_to_side).
body(r6_liquid_enters_destination, fast_approach).
body(r6_liquid_enters_destination, grippy_source).
body(r6_liquid_enters_destination, heavy_source).
body(r6_liquid_enters_destination, light_destination).
body(r6_liquid_enters_destination, medium_liquid).
body(r6_liquid_enters_destination, pour_centred).
body(r6_liquid_enters_destination, pour_half_tilted).
body(r6_liquid_enters_destination, pour_high).
body(r6_liquid_enters_destination, pour_in_line).
body(r6_liquid_enters_destination, pour_level).
body(r6_liquid_enters_destination, runny_liquid).
body(r6_liquid_enters_destination, slippery_destination).
body(r6_liquid_enters_destination, some_liquid).
body(r6_liquid_enters_destination, start_centred).
learned(r6_liquid_enters_destination).
provenance(r6_liquid_enters_destination, antecedent, a6).
provenance(r6_liquid_enters_destination, parent, none).
provenance(r6_liquid_enters_destination, simulations, 31).
provenance(r6_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r6_liquid_enters_destination, confidence_permille, 1000).
provenance(r6_liquid_enters_destination, score_permille, 0).
provenance(r6_liquid_enters_destination, batches, 1).

rule(r6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r6_liquid_remains_in_destination, approach_lowering).
body(r6_liquid_remains_in_destination, dull_source).
body(r6_liquid_remains_in_destination, end_slightly_tilted).
body(r6_liquid_remains_in_destination, end_to_side).
body(r6_liquid_remains_in_destination, fast_approach).
body(r6_liquid_remains_in_destination, grippy_source).
body(r6_liquid_remains_in_destination, heavy_source).
body(r6_liquid_remains_in_destination, light_destination).
body(r6_liquid_remains_in_destination, medium_liquid).
body(r6_liquid_remains_in_destination, pour_centred).
body(r6_liquid_remains_in_destination, pour_half_tilted).
body(r6_liquid_remains_in_destination, pour_high).
body(r6_liquid_remains_in_destination, pour_in_line).
body(r6_liquid_remains_in_destination, pour_level).
body(r6_liquid_remains_in_destination, runny_liquid).
body(r6_liquid_remains_in_destination, slippery_destination).
body(r6_liquid_remains_in_destination, some_liquid).
body(r6_liquid_remains_in_destination, start_centred).
learned(r6_liquid_remains_in_destination).
provenance(r6_liquid_remains_in_destination, antecedent, a6).
provenance(r6_liquid_remains_in_destination, parent, none).
provenance(r6_liquid_remains_in_destination, simulations, 31).
provenance(r6_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r6_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r6_liquid_remains_in_destination, score_permille, 1000).
provenance(r6_liquid_remains_in_destination, batches, 1).

rule(r6_no_spill, defeasible, no_spill).
body(r6_no_spill, approach_lowering).
body(r6_no_spill, dull_source).
body(r6_no_spill, end_slightly_tilted).
body(r6_no_spill, end_to_side).
body(r6_no_spill, fast_approach).
body(r6_no_spill, grippy_source).
body(r6_no_spill, heavy_source).
body(r6_no_spill, light_destination).
body(r6_no_spill, medium_liquid).
body(r6_no_spill, pour_centred).
body(r6_no_spill, pour_half_tilted).
body(r6_no_spill, pour_high).
body(r6_no_spill, pour_in_line).
body(r6_no_spill, pour_level).
body(r6_no_spill, runny_liquid).
body(r6_no_spill, slippery_destination).
body(r6_no_spill, some_liquid).
body(r6_no_spill, start_centred).
learned(r6_no_spill).
provenance(r6_no_spill, antecedent, a6).
provenance(r6_no_spill, parent, none).
provenance(r6_no_spill, simulations, 31).
provenance(r6_no_spill, weight_mass_permille, 31000).
provenance(r6_no_spill, confidence_permille, 1000).
provenance(r6_no_spill, score_permille, 999).
provenance(r6_no_spill, batches, 1).

rule(r7_destination_still_approach, defeasible, destination_still_approach).
body(r7_destination_still_approach, dull_liquid).
body(r7_destination_still_approach, end_below_rim).
body(r7_destination_still_approach, end_level).
body(r7_destination_still_approach, end_slightly_tilted).
body(r7_destination_still_approach, fast_retreat).
body(r7_destination_still_approach, heavy_destination).
body(r7_destination_still_approach, heavy_liquid).
body(r7_destination_still_approach, little_liquid).
body(r7_destination_still_approach, moderate_approach).
body(r7_destination_still_approach, pour_low).
body(r7_destination_still_approach, pour_near_rim).
body(r7_destination_still_approach, pour_rolled).
body(r7_destination_still_approach, pour_upright).
body(r7_destination_still_approach, retreat_moving_closer).
body(r7_destination_still_approach, slippery_destination).
body(r7_destination_still_approach, start_mid_height).
body(r7_destination_still_approach, start_tilted_back).
body(r7_destination_still_approach, sticky_liquid).
learned(r7_destination_still_approach).
provenance(r7_destination_still_approach, antecedent, a7).
provenance(r7_destination_still_approach, parent, none).
provenance(r7_destination_still_approach, simulations, 31).
provenance(r7_destination_still_approach, weight_mass_permille, 31000).
provenance(r7_destination_still_approach, confidence_permille, 935).
provenance(r7_destination_still_approach, score_permille, 933).
provenance(r7_destination_still_approach, batches, 1).

rule(r7_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r7_destination_still_retreat, dull_liquid).
body(r7_destination_still_retreat, end_below_rim).
body(r7_destination_still_retreat, end_level).
body(r7_destination_still_retreat, end_slightly_tilted).
body(r7_destination_still_retreat, fast_retreat).
body(r7_destination_still_retreat, heavy_destination).
body(r7_destination_still_retreat, heavy_liquid).
body(r7_destination_still_retreat, little_liquid).
body(r7_destination_still_retreat, moderate_approach).
body(r7_destination_still_retreat, pour_low).
body(r7_destination_still_retreat, pour_near_rim).
body(r7_destination_still_retreat, pour_rolled).
body(r7_destination_still_retreat, pour_upright).
body(r7_destination_still_retreat, retreat_moving_closer).
body(r7_destination_still_retreat, slippery_destination).
body(r7_destination_still_retreat, start_mid_height).
body(r7_destination_still_retreat, start_tilted_back).
body(r7_destination_still_retreat, sticky_liquid).
learned(r7_destination_still_retreat).
provenance(r7_destination_still_retreat, antecedent, a7).
provenance(r7_destination_still_retreat, parent, none).
provenance(r7_destination_still_retreat, simulations, 31).
provenance(r7_destination_still_retreat, weight_mass_permille, 31000).
provenance(r7_destination_still_retreat, confidence_permille, 774).
provenance(r7_destination_still_retreat, score_permille, 202).
provenance(r7_destination_still_retreat, batches, 1).

rule(r7_destination_still_settle, defeasible, destination_still_settle).
body(r7_destination_still_settle, dull_liquid).
body(r7_destination_still_settle, end_below_rim).
body(r7_destination_still_settle, end_level).
body(r7_destination_still_settle, end_slightly_tilted).
body(r7_destination_still_settle, fast_retreat).
body(r7_destination_still_settle, heavy_destination).
body(r7_destination_still_settle, heavy_liquid).
body(r7_destination_still_settle, little_liquid).
body(r7_destination_still_settle, moderate_approach).
body(r7_destination_still_settle, pour_low).
body(r7_destination_still_settle, pour_near_rim).
body(r7_destination_still_settle, pour_rolled).
body(r7_destination_still_settle, pour_upright).
body(r7_destination_still_settle, retreat_moving_closer).
body(r7_destination_still_settle, slippery_destination).
body(r7_destination_still_settle, start_mid_height).
body(r7_destination_still_settle, start_tilted_back).
body(r7_destination_still_settle, sticky_liquid).
learned(r7_destination_still_settle).
provenance(r7_destination_still_settle, antecedent, a7).
provenance(r7_destination_still_settle, parent, none).
provenance(r7_destination_still_settle, simulations, 31).
provenance(r7_destination_still_settle, weight_mass_permille, 31000).
provenance(r7_destination_still_settle, confidence_permille, 516).
provenance(r7_destination_still_settle, score_permille, 500).
provenance(r7_destination_still_settle, batches, 1).

rule(r7_destination_upright, defeasible, destination_upright).
body(r7_destination_upright, dull_liquid).
body(r7_destination_upright, end_below_rim).
body(r7_destination_upright, end_level).
body(r7_destination_upright, end_slightly_tilted).
body(r7_destination_upright, fast_retreat).
body(r7_destination_upright, heavy_destination).
body(r7_destination_upright, heavy_liquid).
body(r7_destination_upright, little_liquid).
body(r7_destination_upright, moderate_approach).
body(r7_destination_upright, pour_low).
body(r7_destination_upright, pour_near_rim).
body(r7_destination_upright, pour_rolled).
body(r7_destination_upright, pour_upright).
body(r7_destination_upright, retreat_moving_closer).
body(r7_destination_upright, slippery_destination).
body(r7_destination_upright, start_mid_height).
body(r7_destination_upright, start_tilted_back).
body(r7_destination_upright, sticky_liquid).
learned(r7_destination_upright).
provenance(r7_destination_upright, antecedent, a7).
provenance(r7_destination_upright, parent, none).
provenance(r7_destination_upright, simulations, 31).
provenance(r7_destination_upright, weight_mass_permille, 31000).
provenance(r7_destination_upright, confidence_permille, 1000).
provenance(r7_destination_upright, score_permille, 999).
provenance(r7_destination_upright, batches, 1).

rule(r7_source_clear, defeasible, neg(source_clear)).
body(r7_source_clear, dull_liquid).
body(r7_source_clear, end_below_rim).
body(r7_source_clear, end_level).
body(r7_source_clear, end_slightly_tilted).
body(r7_source_clear, fast_retreat).
body(r7_source_clear, heavy_destination).
body(r7_source_clear, heavy_liquid).
body(r7_source_clear, little_liquid).
body(r7_source_clear, moderate_approach).
body(r7_source_clear, pour_low).
body(r7_source_clear, pour_near_rim).
body(r7_source_clear, pour_rolled).
body(r7_source_clear, pour_upright).
body(r7_source_clear, retreat_moving_closer).
body(r7_source_clear, slippery_destination).
body(r7_source_clear, start_mid_height).
body(r7_source_clear, start_tilted_back).
body(r7_source_clear, sticky_liquid).
learned(r7_source_clear).
provenance(r7_source_clear, antecedent, a7).
provenance(r7_source_clear, parent, none).
provenance(r7_source_clear, simulations, 31).
provenance(r7_source_clear, weight_mass_permille, 31000).
provenance(r7_source_clear, confidence_permille, 935).
provenance(r7_source_clear, score_permille, 47).
provenance(r7_source_clear, batches, 1).

rule(r7_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r7_liquid_leaves_source, dull_liquid).
body(r7_liquid_leaves_source, end_below_rim).
body(r7_liquid_leaves_source, end_level).
body(r7_liquid_leaves_source, end_slightly_tilted).
body(r7_liquid_leaves_source, fast_retreat).
body(r7_liquid_leaves_source, heavy_destination).
body(r7_liquid_leaves_source, heavy_liquid).
body(r7_liquid_leaves_source, little_liquid).
body(r7_liquid_leaves_source, moderate_approach).
body(r7_liquid_leaves_source, pour_low).
body(r7_liquid_leaves_source, pour_near_rim).
body(r7_liquid_leaves_source, pour_rolled).
body(r7_liquid_leaves_source, pour_upright).
body(r7_liquid_leaves_source, retreat_moving_closer).
body(r7_liquid_leaves_source, slippery_destination).
body(r7_liquid_leaves_source, start_mid_height).
body(r7_liquid_leaves_source, start_tilted_back).
body(r7_liquid_leaves_source, sticky_liquid).
learned(r7_liquid_leaves_source).
provenance(r7_liquid_leaves_source, antecedent, a7).
provenance(r7_liquid_leaves_source, parent, none).
provenance(r7_liquid_leaves_source, simulations, 31).
provenance(r7_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r7_liquid_leaves_source, confidence_permille, 839).
provenance(r7_liquid_leaves_source, score_permille, 824).
provenance(r7_liquid_leaves_source, batches, 1).

rule(r7_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r7_liquid_enters_destination, dull_liquid).
body(r7_liquid_enters_destination, end_below_rim).
body(r7_liquid_enters_destination, end_level).
body(r7_liquid_enters_destination, end_slightly_tilted).
body(r7_liquid_enters_destination, fast_retreat).
body(r7_liquid_enters_destination, heavy_destination).
body(r7_liquid_enters_destination, heavy_liquid).
body(r7_liquid_enters_destination, little_liquid).
body(r7_liquid_enters_destination, moderate_approach).
body(r7_liquid_enters_destination, pour_low).
body(r7_liquid_enters_destination, pour_near_rim).
body(r7_liquid_enters_destination, pour_rolled).
body(r7_liquid_enters_destination, pour_upright).
body(r7_liquid_enters_destination, retreat_moving_closer).
body(r7_liquid_enters_destination, slippery_destination).
body(r7_liquid_enters_destination, start_mid_height).
body(r7_liquid_enters_destination, start_tilted_back).
body(r7_liquid_enters_destination, sticky_liquid).
learned(r7_liquid_enters_destination).
provenance(r7_liquid_enters_destination, antecedent, a7).
provenance(r7_liquid_enters_destination, parent, none).
provenance(r7_liquid_enters_destination, simulations, 31).
provenance(r7_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r7_liquid_enters_destination, confidence_permille, 806).
provenance(r7_liquid_enters_destination, score_permille, 795).
provenance(r7_liquid_enters_destination, batches, 1).

rule(r7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r7_liquid_remains_in_destination, dull_liquid).
body(r7_liquid_remains_in_destination, end_below_rim).
body(r7_liquid_remains_in_destination, end_level).
body(r7_liquid_remains_in_destination, end_slightly_tilted).
body(r7_liquid_remains_in_destination, fast_retreat).
body(r7_liquid_remains_in_destination, heavy_destination).
body(r7_liquid_remains_in_destination, heavy_liquid).
body(r7_liquid_remains_in_destination, little_liquid).
body(r7_liquid_remains_in_destination, moderate_approach).
body(r7_liquid_remains_in_destination, pour_low).
body(r7_liquid_remains_in_destination, pour_near_rim).
body(r7_liquid_remains_in_destination, pour_rolled).
body(r7_liquid_remains_in_destination, pour_upright).
body(r7_liquid_remains_in_destination, retreat_moving_closer).
body(r7_liquid_remains_in_destination, slippery_destination).
body(r7_liquid_remains_in_destination, start_mid_height).
body(r7_liquid_remains_in_destination, start_tilted_back).
body(r7_liquid_remains_in_destination, sticky_liquid).
learned(r7_liquid_remains_in_destination).
provenance(r7_liquid_remains_in_destination, antecedent, a7).
provenance(r7_liquid_remains_in_destination, parent, none).
provenance(r7_liquid_remains_in_destination, simulations, 31).
provenance(r7_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r7_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r7_liquid_remains_in_destination, score_permille, 985).
provenance(r7_liquid_remains_in_destination, batches, 1).

rule(r7_no_spill, defeasible, no_spill).
body(r7_no_spill, dull_liquid).
body(r7_no_spill, end_below_rim).
body(r7_no_spill, end_level).
body(r7_no_spill, end_slightly_tilted).
body(r7_no_spill, fast_retreat).
body(r7_no_spill, heavy_destination).
body(r7_no_spill, heavy_liquid).
body(r7_no_spill, little_liquid).
body(r7_no_spill, moderate_approach).
body(r7_no_spill, pour_low).
body(r7_no_spill, pour_near_rim).
body(r7_no_spill, pour_rolled).
body(r7_no_spill, pour_upright).
body(r7_no_spill, retreat_moving_closer).
body(r7_no_spill, slippery_destination).
body(r7_no_spill, start_mid_height).
body(r7_no_spill, start_tilted_back).
body(r7_no_spill, sticky_liquid).
learned(r7_no_spill).
provenance(r7_no_spill, antecedent, a7).
provenance(r7_no_spill, parent, none).
provenance(r7_no_spill, simulations, 31).
provenance(r7_no_spill, weight_mass_permille, 31000).
provenance(r7_no_spill, confidence_permille, 935).
provenance(r7_no_spill, score_permille, 958).
provenance(r7_no_spill, batches, 1).

rule(r8_destination_still_approach, defeasible, destination_still_approach).
body(r8_destination_still_approach, dull_liquid).
body(r8_destination_still_approach, end_below_rim).
body(r8_destination_still_approach, end_level).
body(r8_destination_still_approach, end_upside_down).
body(r8_destination_still_approach, fast_retreat).
body(r8_destination_still_approach, heavy_destination).
body(r8_destination_still_approach, heavy_liquid).
body(r8_destination_still_approach, little_liquid).
body(r8_destination_still_approach, moderate_approach).
body(r8_destination_still_approach, pour_low).
body(r8_destination_still_approach, pour_near_rim).
body(r8_destination_still_approach, pour_rolled).
body(r8_destination_still_approach, pour_upright).
body(r8_destination_still_approach, retreat_moving_closer).
body(r8_destination_still_approach, slippery_destination).
body(r8_destination_still_approach, start_mid_height).
body(r8_destination_still_approach, start_tilted_back).
body(r8_destination_still_approach, sticky_liquid).
learned(r8_destination_still_approach).
provenance(r8_destination_still_approach, antecedent, a8).
provenance(r8_destination_still_approach, parent, a7).
provenance(r8_destination_still_approach, simulations, 31).
provenance(r8_destination_still_approach, weight_mass_permille, 31000).
provenance(r8_destination_still_approach, confidence_permille, 1000).
provenance(r8_destination_still_approach, score_permille, 961).
provenance(r8_destination_still_approach, batches, 1).

rule(r8_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r8_destination_still_retreat, dull_liquid).
body(r8_destination_still_retreat, end_below_rim).
body(r8_destination_still_retreat, end_level).
body(r8_destination_still_retreat, end_upside_down).
body(r8_destination_still_retreat, fast_retreat).
body(r8_destination_still_retreat, heavy_destination).
body(r8_destination_still_retreat, heavy_liquid).
body(r8_destination_still_retreat, little_liquid).
body(r8_destination_still_retreat, moderate_approach).
body(r8_destination_still_retreat, pour_low).
body(r8_destination_still_retreat, pour_near_rim).
body(r8_destination_still_retreat, pour_rolled).
body(r8_destination_still_retreat, pour_upright).
body(r8_destination_still_retreat, retreat_moving_closer).
body(r8_destination_still_retreat, slippery_destination).
body(r8_destination_still_retreat, start_mid_height).
body(r8_destination_still_retreat, start_tilted_back).
body(r8_destination_still_retreat, sticky_liquid).
learned(r8_destination_still_retreat).
provenance(r8_destination_still_retreat, antecedent, a8).
provenance(r8_destination_still_retreat, parent, a7).
provenance(r8_destination_still_retreat, simulations, 31).
provenance(r8_destination_still_retreat, weight_mass_permille, 31000).
provenance(r8_destination_still_retreat, confidence_permille, 1000).
provenance(r8_destination_still_retreat, score_permille, 19).
provenance(r8_destination_still_retreat, batches, 1).

rule(r8_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r8_destination_still_settle, dull_liquid).
body(r8_destination_still_settle, end_below_rim).
body(r8_destination_still_settle, end_level).
body(r8_destination_still_settle, end_upside_down).
body(r8_destination_still_settle, fast_retreat).
body(r8_destination_still_settle, heavy_destination).
body(r8_destination_still_settle, heavy_liquid).
body(r8_destination_still_settle, little_liquid).
body(r8_destination_still_settle, moderate_approach).
body(r8_destination_still_settle, pour_low).
body(r8_destination_still_settle, pour_near_rim).
body(r8_destination_still_settle, pour_rolled).
body(r8_destination_still_settle, pour_upright).
body(r8_destination_still_settle, retreat_moving_closer).
body(r8_destination_still_settle, slippery_destination).
body(r8_destination_still_settle, start_mid_height).
body(r8_destination_still_settle, start_tilted_back).
body(r8_destination_still_settle, sticky_liquid).
learned(r8_destination_still_settle).
provenance(r8_destination_still_settle, antecedent, a8).
provenance(r8_destination_still_settle, parent, a7).
provenance(r8_destination_still_settle, simulations, 31).
provenance(r8_destination_still_settle, weight_mass_permille, 31000).
provenance(r8_destination_still_settle, confidence_permille, 710).
provenance(r8_destination_still_settle, score_permille, 250).
provenance(r8_destination_still_settle, batches, 1).

rule(r8_destination_upright, defeasible, destination_upright).
body(r8_destination_upright, dull_liquid).
body(r8_destination_upright, end_below_rim).
body(r8_destination_upright, end_level).
body(r8_destination_upright, end_upside_down).
body(r8_destination_upright, fast_retreat).
body(r8_destination_upright, heavy_destination).
body(r8_destination_upright, heavy_liquid).
body(r8_destination_upright, little_liquid).
body(r8_destination_upright, moderate_approach).
body(r8_destination_upright, pour_low).
body(r8_destination_upright, pour_near_rim).
body(r8_destination_upright, pour_rolled).
body(r8_destination_upright, pour_upright).
body(r8_destination_upright, retreat_moving_closer).
body(r8_destination_upright, slippery_destination).
body(r8_destination_upright, start_mid_height).
body(r8_destination_upright, start_tilted_back).
body(r8_destination_upright, sticky_liquid).
learned(r8_destination_upright).
provenance(r8_destination_upright, antecedent, a8).
provenance(r8_destination_upright, parent, a7).
provenance(r8_destination_upright, simulations, 31).
provenance(r8_destination_upright, weight_mass_permille, 31000).
provenance(r8_destination_upright, confidence_permille, 903).
provenance(r8_destination_upright, score_permille, 835).
provenance(r8_destination_upright, batches, 1).

rule(r8_source_clear, defeasible, neg(source_clear)).
body(r8_source_clear, dull_liquid).
body(r8_source_clear, end_below_rim).
body(r8_source_clear, end_level).
body(r8_source_clear, end_upside_down).
body(r8_source_clear, fast_retreat).
body(r8_source_clear, heavy_destination).
body(r8_source_clear, heavy_liquid).
body(r8_source_clear, little_liquid).
body(r8_source_clear, moderate_approach).
body(r8_source_clear, pour_low).
body(r8_source_clear, pour_near_rim).
body(r8_source_clear, pour_rolled).
body(r8_source_clear, pour_upright).
body(r8_source_clear, retreat_moving_closer).
body(r8_source_clear, slippery_destination).
body(r8_source_clear, start_mid_height).
body(r8_source_clear, start_tilted_back).
body(r8_source_clear, sticky_liquid).
learned(r8_source_clear).
provenance(r8_source_clear, antecedent, a8).
provenance(r8_source_clear, parent, a7).
provenance(r8_source_clear, simulations, 31).
provenance(r8_source_clear, weight_mass_permille, 31000).
provenance(r8_source_clear, confidence_permille, 1000).
provenance(r8_source_clear, score_permille, 0).
provenance(r8_source_clear, batches, 1).

rule(r8_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r8_liquid_leaves_source, dull_liquid).
body(r8_liquid_leaves_source, end_below_rim).
body(r8_liquid_leaves_source, end_level).
body(r8_liquid_leaves_source, end_upside_down).
body(r8_liquid_leaves_source, fast_retreat).
body(r8_liquid_leaves_source, heavy_destination).
body(r8_liquid_leaves_source, heavy_liquid).
body(r8_liquid_leaves_source, little_liquid).
body(r8_liquid_leaves_source, moderate_approach).
body(r8_liquid_leaves_source, pour_low).
body(r8_liquid_leaves_source, pour_near_rim).
body(r8_liquid_leaves_source, pour_rolled).
body(r8_liquid_leaves_source, pour_upright).
body(r8_liquid_leaves_source, retreat_moving_closer).
body(r8_liquid_leaves_source, slippery_destination).
body(r8_liquid_leaves_source, start_mid_height).
body(r8_liquid_leaves_source, start_tilted_back).
body(r8_liquid_leaves_source, sticky_liquid).
learned(r8_liquid_leaves_source).
provenance(r8_liquid_leaves_source, antecedent, a8).
provenance(r8_liquid_leaves_source, parent, a7).
provenance(r8_liquid_leaves_source, simulations, 31).
provenance(r8_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r8_liquid_leaves_source, confidence_permille, 1000).
provenance(r8_liquid_leaves_source, score_permille, 971).
provenance(r8_liquid_leaves_source, batches, 1).

rule(r8_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r8_liquid_enters_destination, dull_liquid).
body(r8_liquid_enters_destination, end_below_rim).
body(r8_liquid_enters_destination, end_level).
body(r8_liquid_enters_destination, end_upside_down).
body(r8_liquid_enters_destination, fast_retreat).
body(r8_liquid_enters_destination, heavy_destination).
body(r8_liquid_enters_destination, heavy_liquid).
body(r8_liquid_enters_destination, little_liquid).
body(r8_liquid_enters_destination, moderate_approach).
body(r8_liquid_enters_destination, pour_low).
body(r8_liquid_enters_destination, pour_near_rim).
body(r8_liquid_enters_destination, pour_rolled).
body(r8_liquid_enters_destination, pour_upright).
body(r8_liquid_enters_destination, retreat_moving_closer).
body(r8_liquid_enters_destination, slippery_destination).
body(r8_liquid_enters_destination, start_mid_height).
body(r8_liquid_enters_destination, start_tilted_back).
body(r8_liquid_enters_destination, sticky_liquid).
learned(r8_liquid_enters_destination).
provenance(r8_liquid_enters_destination, antecedent, a8).
provenance(r8_liquid_enters_destination, parent, a7).
provenance(r8_liquid_enters_destination, simulations, 31).
provenance(r8_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r8_liquid_enters_destination, confidence_permille, 742).
provenance(r8_liquid_enters_destination, score_permille, 759).
provenance(r8_liquid_enters_destination, batches, 1).

rule(r8_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r8_liquid_remains_in_destination, dull_liquid).
body(r8_liquid_remains_in_destination, end_below_rim).
body(r8_liquid_remains_in_destination, end_level).
body(r8_liquid_remains_in_destination, end_upside_down).
body(r8_liquid_remains_in_destination, fast_retreat).
body(r8_liquid_remains_in_destination, heavy_destination).
body(r8_liquid_remains_in_destination, heavy_liquid).
body(r8_liquid_remains_in_destination, little_liquid).
body(r8_liquid_remains_in_destination, moderate_approach).
body(r8_liquid_remains_in_destination, pour_low).
body(r8_liquid_remains_in_destination, pour_near_rim).
body(r8_liquid_remains_in_destination, pour_rolled).
body(r8_liquid_remains_in_destination, pour_upright).
body(r8_liquid_remains_in_destination, retreat_moving_closer).
body(r8_liquid_remains_in_destination, slippery_destination).
body(r8_liquid_remains_in_destination, start_mid_height).
body(r8_liquid_remains_in_destination, start_tilted_back).
body(r8_liquid_remains_in_destination, sticky_liquid).
learned(r8_liquid_remains_in_destination).
provenance(r8_liquid_remains_in_destination, antecedent, a8).
provenance(r8_liquid_remains_in_destination, parent, a7).
provenance(r8_liquid_remains_in_destination, simulations, 31).
provenance(r8_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r8_liquid_remains_in_destination, confidence_permille, 516).
provenance(r8_liquid_remains_in_destination, score_permille, 561).
provenance(r8_liquid_remains_in_destination, batches, 1).

rule(r8_no_spill, defeasible, neg(no_spill)).
body(r8_no_spill, dull_liquid).
body(r8_no_spill, end_below_rim).
body(r8_no_spill, end_level).
body(r8_no_spill, end_upside_down).
body(r8_no_spill, fast_retreat).
body(r8_no_spill, heavy_destination).
body(r8_no_spill, heavy_liquid).
body(r8_no_spill, little_liquid).
body(r8_no_spill, moderate_approach).
body(r8_no_spill, pour_low).
body(r8_no_spill, pour_near_rim).
body(r8_no_spill, pour_rolled).
body(r8_no_spill, pour_upright).
body(r8_no_spill, retreat_moving_closer).
body(r8_no_spill, slippery_destination).
body(r8_no_spill, start_mid_height).
body(r8_no_spill, start_tilted_back).
body(r8_no_spill, sticky_liquid).
learned(r8_no_spill).
provenance(r8_no_spill, antecedent, a8).
provenance(r8_no_spill, parent, a7).
provenance(r8_no_spill, simulations, 31).
provenance(r8_no_spill, weight_mass_permille, 31000).
provenance(r8_no_spill, confidence_permille, 613).
provenance(r8_no_spill, score_permille, 432).
provenance(r8_no_spill, batches, 1).

rule(r9_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r9_destination_still_approach, approach_raising).
body(r9_destination_still_approach, bouncy_destination).
body(r9_destination_still_approach, dull_liquid).
body(r9_destination_still_approach, dull_source).
body(r9_destination_still_approach, end_level).
body(r9_destination_still_approach, end_upside_down).
body(r9_destination_still_approach, fast_retreat).
body(r9_destination_still_approach, heavy_destination).
body(r9_destination_still_approach, heavy_liquid).
body(r9_destination_still_approach, light_source).
body(r9_destination_still_approach, moderate_approach).
body(r9_destination_still_approach, pour_centred).
body(r9_destination_still_approach, pour_level).
body(r9_destination_still_approach, pour_low).
body(r9_destination_still_approach, pour_offset_sideways).
body(r9_destination_still_approach, pour_steeply_tilted).
body(r9_destination_still_approach, slippery_destination).
body(r9_destination_still_approach, slippery_source).
body(r9_destination_still_approach, some_liquid).
body(r9_destination_still_approach, start_tilted_back).
body(r9_destination_still_approach, start_to_side).
learned(r9_destination_still_approach).
provenance(r9_destination_still_approach, antecedent, a9).
provenance(r9_destination_still_approach, parent, none).
provenance(r9_destination_still_approach, simulations, 31).
provenance(r9_destination_still_approach, weight_mass_permille, 31000).
provenance(r9_destination_still_approach, confidence_permille, 839).
provenance(r9_destination_still_approach, score_permille, 173).
provenance(r9_destination_still_approach, batches, 1).

rule(r9_destination_still_retreat, defeasible, destination_still_retreat).
body(r9_destination_still_retreat, approach_raising).
body(r9_destination_still_retreat, bouncy_destination).
body(r9_destination_still_retreat, dull_liquid).
body(r9_destination_still_retreat, dull_source).
body(r9_destination_still_retreat, end_level).
body(r9_destination_still_retreat, end_upside_down).
body(r9_destination_still_retreat, fast_retreat).
body(r9_destination_still_retreat, heavy_destination).
body(r9_destination_still_retreat, heavy_liquid).
body(r9_destination_still_retreat, light_source).
body(r9_destination_still_retreat, moderate_approach).
body(r9_destination_still_retreat, pour_centred).
body(r9_destination_still_retreat, pour_level).
body(r9_destination_still_retreat, pour_low).
body(r9_destination_still_retreat, pour_offset_sideways).
body(r9_destination_still_retreat, pour_steeply_tilted).
body(r9_destination_still_retreat, slippery_destination).
body(r9_destination_still_retreat, slippery_source).
body(r9_destination_still_retreat, some_liquid).
body(r9_destination_still_retreat, start_tilted_back).
body(r9_destination_still_retreat, start_to_side).
learned(r9_destination_still_retreat).
provenance(r9_destination_still_retreat, antecedent, a9).
provenance(r9_destination_still_retreat, parent, none).
provenance(r9_destination_still_retreat, simulations, 31).
provenance(r9_destination_still_retreat, weight_mass_permille, 31000).
provenance(r9_destination_still_retreat, confidence_permille, 903).
provenance(r9_destination_still_retreat, score_permille, 898).
provenance(r9_destination_still_retreat, batches, 1).

rule(r9_destination_still_settle, defeasible, destination_still_settle).
body(r9_destination_still_settle, approach_raising).
body(r9_destination_still_settle, bouncy_destination).
body(r9_destination_still_settle, dull_liquid).
body(r9_destination_still_settle, dull_source).
body(r9_destination_still_settle, end_level).
body(r9_destination_still_settle, end_upside_down).
body(r9_destination_still_settle, fast_retreat).
body(r9_destination_still_settle, heavy_destination).
body(r9_destination_still_settle, heavy_liquid).
body(r9_destination_still_settle, light_source).
body(r9_destination_still_settle, moderate_approach).
body(r9_destination_still_settle, pour_centred).
body(r9_destination_still_settle, pour_level).
body(r9_destination_still_settle, pour_low).
body(r9_destination_still_settle, pour_offset_sideways).
body(r9_destination_still_settle, pour_steeply_tilted).
body(r9_destination_still_settle, slippery_destination).
body(r9_destination_still_settle, slippery_source).
body(r9_destination_still_settle, some_liquid).
body(r9_destination_still_settle, start_tilted_back).
body(r9_destination_still_settle, start_to_side).
learned(r9_destination_still_settle).
provenance(r9_destination_still_settle, antecedent, a9).
provenance(r9_destination_still_settle, parent, none).
provenance(r9_destination_still_settle, simulations, 31).
provenance(r9_destination_still_settle, weight_mass_permille, 31000).
provenance(r9_destination_still_settle, confidence_permille, 968).
provenance(r9_destination_still_settle, score_permille, 966).
provenance(r9_destination_still_settle, batches, 1).

rule(r9_destination_upright, defeasible, destination_upright).
body(r9_destination_upright, approach_raising).
body(r9_destination_upright, bouncy_destination).
body(r9_destination_upright, dull_liquid).
body(r9_destination_upright, dull_source).
body(r9_destination_upright, end_level).
body(r9_destination_upright, end_upside_down).
body(r9_destination_upright, fast_retreat).
body(r9_destination_upright, heavy_destination).
body(r9_destination_upright, heavy_liquid).
body(r9_destination_upright, light_source).
body(r9_destination_upright, moderate_approach).
body(r9_destination_upright, pour_centred).
body(r9_destination_upright, pour_level).
body(r9_destination_upright, pour_low).
body(r9_destination_upright, pour_offset_sideways).
body(r9_destination_upright, pour_steeply_tilted).
body(r9_destination_upright, slippery_destination).
body(r9_destination_upright, slippery_source).
body(r9_destination_upright, some_liquid).
body(r9_destination_upright, start_tilted_back).
body(r9_destination_upright, start_to_side).
learned(r9_destination_upright).
provenance(r9_destination_upright, antecedent, a9).
provenance(r9_destination_upright, parent, none).
provenance(r9_destination_upright, simulations, 31).
provenance(r9_destination_upright, weight_mass_permille, 31000).
provenance(r9_destination_upright, confidence_permille, 1000).
provenance(r9_destination_upright, score_permille, 1000).
provenance(r9_destination_upright, batches, 1).

rule(r9_source_clear, defeasible, neg(source_clear)).
body(r9_source_clear, approach_raising).
body(r9_source_clear, bouncy_destination).
body(r9_source_clear, dull_liquid).
body(r9_source_clear, dull_source).
body(r9_source_clear, end_level).
body(r9_source_clear, end_upside_down).
body(r9_source_clear, fast_retreat).
body(r9_source_clear, heavy_destination).
body(r9_source_clear, heavy_liquid).
body(r9_source_clear, light_source).
body(r9_source_clear, moderate_approach).
body(r9_source_clear, pour_centred).
body(r9_source_clear, pour_level).
body(r9_source_clear, pour_low).
body(r9_source_clear, pour_offset_sideways).
body(r9_source_clear, pour_steeply_tilted).
body(r9_source_clear, slippery_destination).
body(r9_source_clear, slippery_source).
body(r9_source_clear, some_liquid).
body(r9_source_clear, start_tilted_back).
body(r9_source_clear, start_to_side).
learned(r9_source_clear).
provenance(r9_source_clear, antecedent, a9).
provenance(r9_source_clear, parent, none).
provenance(r9_source_clear, simulations, 31).
provenance(r9_source_clear, weight_mass_permille, 31000).
provenance(r9_source_clear, confidence_permille, 968).
provenance(r9_source_clear, score_permille, 22).
provenance(r9_source_clear, batches, 1).

rule(r9_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r9_liquid_leaves_source, approach_raising).
body(r9_liquid_leaves_source, bouncy_destination).
body(r9_liquid_leaves_source, dull_liquid).
body(r9_liquid_leaves_source, dull_source).
body(r9_liquid_leaves_source, end_level).
body(r9_liquid_leaves_source, end_upside_down).
body(r9_liquid_leaves_source, fast_retreat).
body(r9_liquid_leaves_source, heavy_destination).
body(r9_liquid_leaves_source, heavy_liquid).
body(r9_liquid_leaves_source, light_source).
body(r9_liquid_leaves_source, moderate_approach).
body(r9_liquid_leaves_source, pour_centred).
body(r9_liquid_leaves_source, pour_level).
body(r9_liquid_leaves_source, pour_low).
body(r9_liquid_leaves_source, pour_offset_sideways).
body(r9_liquid_leaves_source, pour_steeply_tilted).
body(r9_liquid_leaves_source, slippery_destination).
body(r9_liquid_leaves_source, slippery_source).
body(r9_liquid_leaves_source, some_liquid).
body(r9_liquid_leaves_source, start_tilted_back).
body(r9_liquid_leaves_source, start_to_side).
learned(r9_liquid_leaves_source).
provenance(r9_liquid_leaves_source, antecedent, a9).
provenance(r9_liquid_leaves_source, parent, none).
provenance(r9_liquid_leaves_source, simulations, 31).
provenance(r9_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r9_liquid_leaves_source, confidence_permille, 1000).
provenance(r9_liquid_leaves_source, score_permille, 1000).
provenance(r9_liquid_leaves_source, batches, 1).

rule(r9_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r9_liquid_enters_destination, approach_raising).
body(r9_liquid_enters_destination, bouncy_destination).
body(r9_liquid_enters_destination, dull_liquid).
body(r9_liquid_enters_destination, dull_source).
body(r9_liquid_enters_destination, end_level).
body(r9_liquid_enters_destination, end_upside_down).
body(r9_liquid_enters_destination, fast_retreat).
body(r9_liquid_enters_destination, heavy_destination).
body(r9_liquid_enters_destination, heavy_liquid).
body(r9_liquid_enters_destination, light_source).
body(r9_liquid_enters_destination, moderate_approach).
body(r9_liquid_enters_destination, pour_centred).
body(r9_liquid_enters_destination, pour_level).
body(r9_liquid_enters_destination, pour_low).
body(r9_liquid_enters_destination, pour_offset_sideways).
body(r9_liquid_enters_destination, pour_steeply_tilted).
body(r9_liquid_enters_destination, slippery_destination).
body(r9_liquid_enters_destination, slippery_source).
body(r9_liquid_enters_destination, some_liquid).
body(r9_liquid_enters_destination, start_tilted_back).
body(r9_liquid_enters_destination, start_to_side).
learned(r9_liquid_enters_destination).
provenance(r9_liquid_enters_destination, antecedent, a9).
provenance(r9_liquid_enters_destination, parent, none).
provenance(r9_liquid_enters_destination, simulations, 31).
provenance(r9_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r9_liquid_enters_destination, confidence_permille, 806).
provenance(r9_liquid_enters_destination, score_permille, 179).
provenance(r9_liquid_enters_destination, batches, 1).

rule(r9_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r9_liquid_remains_in_destination, approach_raising).
body(r9_liquid_remains_in_destination, bouncy_destination).
body(r9_liquid_remains_in_destination, dull_liquid).
body(r9_liquid_remains_in_destination, dull_source).
body(r9_liquid_remains_in_destination, end_level).
body(r9_liquid_remains_in_destination, end_upside_down).
body(r9_liquid_remains_in_destination, fast_retreat).
body(r9_liquid_remains_in_destination, heavy_destination).
body(r9_liquid_remains_in_destination, heavy_liquid).
body(r9_liquid_remains_in_destination, light_source).
body(r9_liquid_remains_in_destination, moderate_approach).
body(r9_liquid_remains_in_destination, pour_centred).
body(r9_liquid_remains_in_destination, pour_level).
body(r9_liquid_remains_in_destination, pour_low).
body(r9_liquid_remains_in_destination, pour_offset_sideways).
body(r9_liquid_remains_in_destination, pour_steeply_tilted).
body(r9_liquid_remains_in_destination, slippery_destination).
body(r9_liquid_remains_in_destination, slippery_source).
body(r9_liquid_remains_in_destination, some_liquid).
body(r9_liquid_remains_in_destination, start_tilted_back).
body(r9_liquid_remains_in_destination, start_to_side).
learned(r9_liquid_remains_in_destination).
provenance(r9_liquid_remains_in_destination, antecedent, a9).
provenance(r9_liquid_remains_in_destination, parent, none).
provenance(r9_liquid_remains_in_destination, simulations, 31).
provenance(r9_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r9_liquid_remains_in_destination, confidence_permille, 968).
provenance(r9_liquid_remains_in_destination, score_permille, 982).
provenance(r9_liquid_remains_in_destination, batches, 1).

rule(r9_no_spill, defeasible, neg(no_spill)).
body(r9_no_spill, approach_raising).
body(r9_no_spill, bouncy_destination).
body(r9_no_spill, dull_liquid).
body(r9_no_spill, dull_source).
body(r9_no_spill, end_level).
body(r9_no_spill, end_upside_down).
body(r9_no_spill, fast_retreat).
body(r9_no_spill, heavy_destination).
body(r9_no_spill, heavy_liquid).
body(r9_no_spill, light_source).
body(r9_no_spill, moderate_approach).
body(r9_no_spill, pour_centred).
body(r9_no_spill, pour_level).
body(r9_no_spill, pour_low).
body(r9_no_spill, pour_offset_sideways).
body(r9_no_spill, pour_steeply_tilted).
body(r9_no_spill, slippery_destination).
body(r9_no_spill, slippery_source).
body(r9_no_spill, some_liquid).
body(r9_no_spill, start_tilted_back).
body(r9_no_spill, start_to_side).
learned(r9_no_spill).
provenance(r9_no_spill, antecedent, a9).
provenance(r9_no_spill, parent, none).
provenance(r9_no_spill, simulations, 31).
provenance(r9_no_spill, weight_mass_permille, 31000).
provenance(r9_no_spill, confidence_permille, 839).
provenance(r9_no_spill, score_permille, 161).
provenance(r9_no_spill, batches, 1).

rule(r10_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r10_destination_still_approach, bouncy_destination).
body(r10_destination_still_approach, bouncy_liquid).
body(r10_destination_still_approach, bouncy_source).
body(r10_destination_still_approach, end_rolled).
body(r10_destination_still_approach, light_source).
body(r10_destination_still_approach, little_liquid).
body(r10_destination_still_approach, medium_destination).
body(r10_destination_still_approach, medium_liquid).
body(r10_destination_still_approach, moderate_retreat).
body(r10_destination_still_approach, pour_centred).
body(r10_destination_still_approach, pour_low).
body(r10_destination_still_approach, pour_offset_sideways).
body(r10_destination_still_approach, pour_steeply_tilted).
body(r10_destination_still_approach, retreat_lowering).
body(r10_destination_still_approach, retreat_moving_closer).
body(r10_destination_still_approach, slippery_destination).
body(r10_destination_still_approach, slippery_source).
body(r10_destination_still_approach, slow_approach).
body(r10_destination_still_approach, start_centred).
body(r10_destination_still_approach, start_slightly_tilted).
body(r10_destination_still_approach, start_very_high).
body(r10_destination_still_approach, sticky_liquid).
learned(r10_destination_still_approach).
provenance(r10_destination_still_approach, antecedent, a10).
provenance(r10_destination_still_approach, parent, none).
provenance(r10_destination_still_approach, simulations, 31).
provenance(r10_destination_still_approach, weight_mass_permille, 31000).
provenance(r10_destination_still_approach, confidence_permille, 516).
provenance(r10_destination_still_approach, score_permille, 432).
provenance(r10_destination_still_approach, batches, 1).

rule(r10_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r10_destination_still_retreat, bouncy_destination).
body(r10_destination_still_retreat, bouncy_liquid).
body(r10_destination_still_retreat, bouncy_source).
body(r10_destination_still_retreat, end_rolled).
body(r10_destination_still_retreat, light_source).
body(r10_destination_still_retreat, little_liquid).
body(r10_destination_still_retreat, medium_destination).
body(r10_destination_still_retreat, medium_liquid).
body(r10_destination_still_retreat, moderate_retreat).
body(r10_destination_still_retreat, pour_centred).
body(r10_destination_still_retreat, pour_low).
body(r10_destination_still_retreat, pour_offset_sideways).
body(r10_destination_still_retreat, pour_steeply_tilted).
body(r10_destination_still_retreat, retreat_lowering).
body(r10_destination_still_retreat, retreat_moving_closer).
body(r10_destination_still_retreat, slippery_destination).
body(r10_destination_still_retreat, slippery_source).
body(r10_destination_still_retreat, slow_approach).
body(r10_destination_still_retreat, start_centred).
body(r10_destination_still_retreat, start_slightly_tilted).
body(r10_destination_still_retreat, start_very_high).
body(r10_destination_still_retreat, sticky_liquid).
learned(r10_destination_still_retreat).
provenance(r10_destination_still_retreat, antecedent, a10).
provenance(r10_destination_still_retreat, parent, none).
provenance(r10_destination_still_retreat, simulations, 31).
provenance(r10_destination_still_retreat, weight_mass_permille, 31000).
provenance(r10_destination_still_retreat, confidence_permille, 903).
provenance(r10_destination_still_retreat, score_permille, 80).
provenance(r10_destination_still_retreat, batches, 1).

rule(r10_destination_still_settle, defeasible, destination_still_settle).
body(r10_destination_still_settle, bouncy_destination).
body(r10_destination_still_settle, bouncy_liquid).
body(r10_destination_still_settle, bouncy_source).
body(r10_destination_still_settle, end_rolled).
body(r10_destination_still_settle, light_source).
body(r10_destination_still_settle, little_liquid).
body(r10_destination_still_settle, medium_destination).
body(r10_destination_still_settle, medium_liquid).
body(r10_destination_still_settle, moderate_retreat).
body(r10_destination_still_settle, pour_centred).
body(r10_destination_still_settle, pour_low).
body(r10_destination_still_settle, pour_offset_sideways).
body(r10_destination_still_settle, pour_steeply_tilted).
body(r10_destination_still_settle, retreat_lowering).
body(r10_destination_still_settle, retreat_moving_closer).
body(r10_destination_still_settle, slippery_destination).
body(r10_destination_still_settle, slippery_source).
body(r10_destination_still_settle, slow_approach).
body(r10_destination_still_settle, start_centred).
body(r10_destination_still_settle, start_slightly_tilted).
body(r10_destination_still_settle, start_very_high).
body(r10_destination_still_settle, sticky_liquid).
learned(r10_destination_still_settle).
provenance(r10_destination_still_settle, antecedent, a10).
provenance(r10_destination_still_settle, parent, none).
provenance(r10_destination_still_settle, simulations, 31).
provenance(r10_destination_still_settle, weight_mass_permille, 31000).
provenance(r10_destination_still_settle, confidence_permille, 806).
provenance(r10_destination_still_settle, score_permille, 779).
provenance(r10_destination_still_settle, batches, 1).

rule(r10_destination_upright, defeasible, destination_upright).
body(r10_destination_upright, bouncy_destination).
body(r10_destination_upright, bouncy_liquid).
body(r10_destination_upright, bouncy_source).
body(r10_destination_upright, end_rolled).
body(r10_destination_upright, light_source).
body(r10_destination_upright, little_liquid).
body(r10_destination_upright, medium_destination).
body(r10_destination_upright, medium_liquid).
body(r10_destination_upright, moderate_retreat).
body(r10_destination_upright, pour_centred).
body(r10_destination_upright, pour_low).
body(r10_destination_upright, pour_offset_sideways).
body(r10_destination_upright, pour_steeply_tilted).
body(r10_destination_upright, retreat_lowering).
body(r10_destination_upright, retreat_moving_closer).
body(r10_destination_upright, slippery_destination).
body(r10_destination_upright, slippery_source).
body(r10_destination_upright, slow_approach).
body(r10_destination_upright, start_centred).
body(r10_destination_upright, start_slightly_tilted).
body(r10_destination_upright, start_very_high).
body(r10_destination_upright, sticky_liquid).
learned(r10_destination_upright).
provenance(r10_destination_upright, antecedent, a10).
provenance(r10_destination_upright, parent, none).
provenance(r10_destination_upright, simulations, 31).
provenance(r10_destination_upright, weight_mass_permille, 31000).
provenance(r10_destination_upright, confidence_permille, 1000).
provenance(r10_destination_upright, score_permille, 992).
provenance(r10_destination_upright, batches, 1).

rule(r10_source_clear, defeasible, neg(source_clear)).
body(r10_source_clear, bouncy_destination).
body(r10_source_clear, bouncy_liquid).
body(r10_source_clear, bouncy_source).
body(r10_source_clear, end_rolled).
body(r10_source_clear, light_source).
body(r10_source_clear, little_liquid).
body(r10_source_clear, medium_destination).
body(r10_source_clear, medium_liquid).
body(r10_source_clear, moderate_retreat).
body(r10_source_clear, pour_centred).
body(r10_source_clear, pour_low).
body(r10_source_clear, pour_offset_sideways).
body(r10_source_clear, pour_steeply_tilted).
body(r10_source_clear, retreat_lowering).
body(r10_source_clear, retreat_moving_closer).
body(r10_source_clear, slippery_destination).
body(r10_source_clear, slippery_source).
body(r10_source_clear, slow_approach).
body(r10_source_clear, start_centred).
body(r10_source_clear, start_slightly_tilted).
body(r10_source_clear, start_very_high).
body(r10_source_clear, sticky_liquid).
learned(r10_source_clear).
provenance(r10_source_clear, antecedent, a10).
provenance(r10_source_clear, parent, none).
provenance(r10_source_clear, simulations, 31).
provenance(r10_source_clear, weight_mass_permille, 31000).
provenance(r10_source_clear, confidence_permille, 968).
provenance(r10_source_clear, score_permille, 23).
provenance(r10_source_clear, batches, 1).

rule(r10_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r10_liquid_leaves_source, bouncy_destination).
body(r10_liquid_leaves_source, bouncy_liquid).
body(r10_liquid_leaves_source, bouncy_source).
body(r10_liquid_leaves_source, end_rolled).
body(r10_liquid_leaves_source, light_source).
body(r10_liquid_leaves_source, little_liquid).
body(r10_liquid_leaves_source, medium_destination).
body(r10_liquid_leaves_source, medium_liquid).
body(r10_liquid_leaves_source, moderate_retreat).
body(r10_liquid_leaves_source, pour_centred).
body(r10_liquid_leaves_source, pour_low).
body(r10_liquid_leaves_source, pour_offset_sideways).
body(r10_liquid_leaves_source, pour_steeply_tilted).
body(r10_liquid_leaves_source, retreat_lowering).
body(r10_liquid_leaves_source, retreat_moving_closer).
body(r10_liquid_leaves_source, slippery_destination).
body(r10_liquid_leaves_source, slippery_source).
body(r10_liquid_leaves_source, slow_approach).
body(r10_liquid_leaves_source, start_centred).
body(r10_liquid_leaves_source, start_slightly_tilted).
body(r10_liquid_leaves_source, start_very_high).
body(r10_liquid_leaves_source, sticky_liquid).
learned(r10_liquid_leaves_source).
provenance(r10_liquid_leaves_source, antecedent, a10).
provenance(r10_liquid_leaves_source, parent, none).
provenance(r10_liquid_leaves_source, simulations, 31).
provenance(r10_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r10_liquid_leaves_source, confidence_permille, 968).
provenance(r10_liquid_leaves_source, score_permille, 944).
provenance(r10_liquid_leaves_source, batches, 1).

rule(r10_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r10_liquid_enters_destination, bouncy_destination).
body(r10_liquid_enters_destination, bouncy_liquid).
body(r10_liquid_enters_destination, bouncy_source).
body(r10_liquid_enters_destination, end_rolled).
body(r10_liquid_enters_destination, light_source).
body(r10_liquid_enters_destination, little_liquid).
body(r10_liquid_enters_destination, medium_destination).
body(r10_liquid_enters_destination, medium_liquid).
body(r10_liquid_enters_destination, moderate_retreat).
body(r10_liquid_enters_destination, pour_centred).
body(r10_liquid_enters_destination, pour_low).
body(r10_liquid_enters_destination, pour_offset_sideways).
body(r10_liquid_enters_destination, pour_steeply_tilted).
body(r10_liquid_enters_destination, retreat_lowering).
body(r10_liquid_enters_destination, retreat_moving_closer).
body(r10_liquid_enters_destination, slippery_destination).
body(r10_liquid_enters_destination, slippery_source).
body(r10_liquid_enters_destination, slow_approach).
body(r10_liquid_enters_destination, start_centred).
body(r10_liquid_enters_destination, start_slightly_tilted).
body(r10_liquid_enters_destination, start_very_high).
body(r10_liquid_enters_destination, sticky_liquid).
learned(r10_liquid_enters_destination).
provenance(r10_liquid_enters_destination, antecedent, a10).
provenance(r10_liquid_enters_destination, parent, none).
provenance(r10_liquid_enters_destination, simulations, 31).
provenance(r10_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r10_liquid_enters_destination, confidence_permille, 839).
provenance(r10_liquid_enters_destination, score_permille, 187).
provenance(r10_liquid_enters_destination, batches, 1).

rule(r10_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r10_liquid_remains_in_destination, bouncy_destination).
body(r10_liquid_remains_in_destination, bouncy_liquid).
body(r10_liquid_remains_in_destination, bouncy_source).
body(r10_liquid_remains_in_destination, end_rolled).
body(r10_liquid_remains_in_destination, light_source).
body(r10_liquid_remains_in_destination, little_liquid).
body(r10_liquid_remains_in_destination, medium_destination).
body(r10_liquid_remains_in_destination, medium_liquid).
body(r10_liquid_remains_in_destination, moderate_retreat).
body(r10_liquid_remains_in_destination, pour_centred).
body(r10_liquid_remains_in_destination, pour_low).
body(r10_liquid_remains_in_destination, pour_offset_sideways).
body(r10_liquid_remains_in_destination, pour_steeply_tilted).
body(r10_liquid_remains_in_destination, retreat_lowering).
body(r10_liquid_remains_in_destination, retreat_moving_closer).
body(r10_liquid_remains_in_destination, slippery_destination).
body(r10_liquid_remains_in_destination, slippery_source).
body(r10_liquid_remains_in_destination, slow_approach).
body(r10_liquid_remains_in_destination, start_centred).
body(r10_liquid_remains_in_destination, start_slightly_tilted).
body(r10_liquid_remains_in_destination, start_very_high).
body(r10_liquid_remains_in_destination, sticky_liquid).
learned(r10_liquid_remains_in_destination).
provenance(r10_liquid_remains_in_destination, antecedent, a10).
provenance(r10_liquid_remains_in_destination, parent, none).
provenance(r10_liquid_remains_in_destination, simulations, 31).
provenance(r10_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r10_liquid_remains_in_destination, confidence_permille, 871).
provenance(r10_liquid_remains_in_destination, score_permille, 887).
provenance(r10_liquid_remains_in_destination, batches, 1).

rule(r10_no_spill, defeasible, neg(no_spill)).
body(r10_no_spill, bouncy_destination).
body(r10_no_spill, bouncy_liquid).
body(r10_no_spill, bouncy_source).
body(r10_no_spill, end_rolled).
body(r10_no_spill, light_source).
body(r10_no_spill, little_liquid).
body(r10_no_spill, medium_destination).
body(r10_no_spill, medium_liquid).
body(r10_no_spill, moderate_retreat).
body(r10_no_spill, pour_centred).
body(r10_no_spill, pour_low).
body(r10_no_spill, pour_offset_sideways).
body(r10_no_spill, pour_steeply_tilted).
body(r10_no_spill, retreat_lowering).
body(r10_no_spill, retreat_moving_closer).
body(r10_no_spill, slippery_destination).
body(r10_no_spill, slippery_source).
body(r10_no_spill, slow_approach).
body(r10_no_spill, start_centred).
body(r10_no_spill, start_slightly_tilted).
body(r10_no_spill, start_very_high).
body(r10_no_spill, sticky_liquid).
learned(r10_no_spill).
provenance(r10_no_spill, antecedent, a10).
provenance(r10_no_spill, parent, none).
provenance(r10_no_spill, simulations, 31).
provenance(r10_no_spill, weight_mass_permille, 31000).
provenance(r10_no_spill, confidence_permille, 806).
provenance(r10_no_spill, score_permille, 213).
provenance(r10_no_spill, batches, 1).

rule(r11_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r11_destination_still_approach, approach_moving_away).
body(r11_destination_still_approach, approach_raising).
body(r11_destination_still_approach, bouncy_source).
body(r11_destination_still_approach, dull_destination).
body(r11_destination_still_approach, dull_liquid).
body(r11_destination_still_approach, end_centred).
body(r11_destination_still_approach, end_rolled).
body(r11_destination_still_approach, end_tilted_back).
body(r11_destination_still_approach, end_very_high).
body(r11_destination_still_approach, fast_approach).
body(r11_destination_still_approach, grippy_destination).
body(r11_destination_still_approach, heavy_destination).
body(r11_destination_still_approach, heavy_source).
body(r11_destination_still_approach, medium_liquid).
body(r11_destination_still_approach, moderate_retreat).
body(r11_destination_still_approach, pour_centred).
body(r11_destination_still_approach, pour_low).
body(r11_destination_still_approach, pour_tilted_back).
body(r11_destination_still_approach, start_tilted_back).
body(r11_destination_still_approach, sticky_liquid).
learned(r11_destination_still_approach).
provenance(r11_destination_still_approach, antecedent, a11).
provenance(r11_destination_still_approach, parent, a3).
provenance(r11_destination_still_approach, simulations, 31).
provenance(r11_destination_still_approach, weight_mass_permille, 31000).
provenance(r11_destination_still_approach, confidence_permille, 806).
provenance(r11_destination_still_approach, score_permille, 199).
provenance(r11_destination_still_approach, batches, 1).

rule(r11_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r11_destination_still_retreat, approach_moving_away).
body(r11_destination_still_retreat, approach_raising).
body(r11_destination_still_retreat, bouncy_source).
body(r11_destination_still_retreat, dull_destination).
body(r11_destination_still_retreat, dull_liquid).
body(r11_destination_still_retreat, end_centred).
body(r11_destination_still_retreat, end_rolled).
body(r11_destination_still_retreat, end_tilted_back).
body(r11_destination_still_retreat, end_very_high).
body(r11_destination_still_retreat, fast_approach).
body(r11_destination_still_retreat, grippy_destination).
body(r11_destination_still_retreat, heavy_destination).
body(r11_destination_still_retreat, heavy_source).
body(r11_destination_still_retreat, medium_liquid).
body(r11_destination_still_retreat, moderate_retreat).
body(r11_destination_still_retreat, pour_centred).
body(r11_destination_still_retreat, pour_low).
body(r11_destination_still_retreat, pour_tilted_back).
body(r11_destination_still_retreat, start_tilted_back).
body(r11_destination_still_retreat, sticky_liquid).
learned(r11_destination_still_retreat).
provenance(r11_destination_still_retreat, antecedent, a11).
provenance(r11_destination_still_retreat, parent, a3).
provenance(r11_destination_still_retreat, simulations, 31).
provenance(r11_destination_still_retreat, weight_mass_permille, 31000).
provenance(r11_destination_still_retreat, confidence_permille, 613).
provenance(r11_destination_still_retreat, score_permille, 379).
provenance(r11_destination_still_retreat, batches, 1).

rule(r11_destination_still_settle, defeasible, destination_still_settle).
body(r11_destination_still_settle, approach_moving_away).
body(r11_destination_still_settle, approach_raising).
body(r11_destination_still_settle, bouncy_source).
body(r11_destination_still_settle, dull_destination).
body(r11_destination_still_settle, dull_liquid).
body(r11_destination_still_settle, end_centred).
body(r11_destination_still_settle, end_rolled).
body(r11_destination_still_settle, end_tilted_back).
body(r11_destination_still_settle, end_very_high).
body(r11_destination_still_settle, fast_approach).
body(r11_destination_still_settle, grippy_destination).
body(r11_destination_still_settle, heavy_destination).
body(r11_destination_still_settle, heavy_source).
body(r11_destination_still_settle, medium_liquid).
body(r11_destination_still_settle, moderate_retreat).
body(r11_destination_still_settle, pour_centred).
body(r11_destination_still_settle, pour_low).
body(r11_destination_still_settle, pour_tilted_back).
body(r11_destination_still_settle, start_tilted_back).
body(r11_destination_still_settle, sticky_liquid).
learned(r11_destination_still_settle).
provenance(r11_destination_still_settle, antecedent, a11).
provenance(r11_destination_still_settle, parent, a3).
provenance(r11_destination_still_settle, simulations, 31).
provenance(r11_destination_still_settle, weight_mass_permille, 31000).
provenance(r11_destination_still_settle, confidence_permille, 903).
provenance(r11_destination_still_settle, score_permille, 890).
provenance(r11_destination_still_settle, batches, 1).

rule(r11_destination_upright, defeasible, destination_upright).
body(r11_destination_upright, approach_moving_away).
body(r11_destination_upright, approach_raising).
body(r11_destination_upright, bouncy_source).
body(r11_destination_upright, dull_destination).
body(r11_destination_upright, dull_liquid).
body(r11_destination_upright, end_centred).
body(r11_destination_upright, end_rolled).
body(r11_destination_upright, end_tilted_back).
body(r11_destination_upright, end_very_high).
body(r11_destination_upright, fast_approach).
body(r11_destination_upright, grippy_destination).
body(r11_destination_upright, heavy_destination).
body(r11_destination_upright, heavy_source).
body(r11_destination_upright, medium_liquid).
body(r11_destination_upright, moderate_retreat).
body(r11_destination_upright, pour_centred).
body(r11_destination_upright, pour_low).
body(r11_destination_upright, pour_tilted_back).
body(r11_destination_upright, start_tilted_back).
body(r11_destination_upright, sticky_liquid).
learned(r11_destination_upright).
provenance(r11_destination_upright, antecedent, a11).
provenance(r11_destination_upright, parent, a3).
provenance(r11_destination_upright, simulations, 31).
provenance(r11_destination_upright, weight_mass_permille, 31000).
provenance(r11_destination_upright, confidence_permille, 935).
provenance(r11_destination_upright, score_permille, 948).
provenance(r11_destination_upright, batches, 1).

rule(r11_source_clear, defeasible, neg(source_clear)).
body(r11_source_clear, approach_moving_away).
body(r11_source_clear, approach_raising).
body(r11_source_clear, bouncy_source).
body(r11_source_clear, dull_destination).
body(r11_source_clear, dull_liquid).
body(r11_source_clear, end_centred).
body(r11_source_clear, end_rolled).
body(r11_source_clear, end_tilted_back).
body(r11_source_clear, end_very_high).
body(r11_source_clear, fast_approach).
body(r11_source_clear, grippy_destination).
body(r11_source_clear, heavy_destination).
body(r11_source_clear, heavy_source).
body(r11_source_clear, medium_liquid).
body(r11_source_clear, moderate_retreat).
body(r11_source_clear, pour_centred).
body(r11_source_clear, pour_low).
body(r11_source_clear, pour_tilted_back).
body(r11_source_clear, start_tilted_back).
body(r11_source_clear, sticky_liquid).
learned(r11_source_clear).
provenance(r11_source_clear, antecedent, a11).
provenance(r11_source_clear, parent, a3).
provenance(r11_source_clear, simulations, 31).
provenance(r11_source_clear, weight_mass_permille, 31000).
provenance(r11_source_clear, confidence_permille, 935).
provenance(r11_source_clear, score_permille, 51).
provenance(r11_source_clear, batches, 1).

rule(r11_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r11_liquid_leaves_source, approach_moving_away).
body(r11_liquid_leaves_source, approach_raising).
body(r11_liquid_leaves_source, bouncy_source).
body(r11_liquid_leaves_source, dull_destination).
body(r11_liquid_leaves_source, dull_liquid).
body(r11_liquid_leaves_source, end_centred).
body(r11_liquid_leaves_source, end_rolled).
body(r11_liquid_leaves_source, end_tilted_back).
body(r11_liquid_leaves_source, end_very_high).
body(r11_liquid_leaves_source, fast_approach).
body(r11_liquid_leaves_source, grippy_destination).
body(r11_liquid_leaves_source, heavy_destination).
body(r11_liquid_leaves_source, heavy_source).
body(r11_liquid_leaves_source, medium_liquid).
body(r11_liquid_leaves_source, moderate_retreat).
body(r11_liquid_leaves_source, pour_centred).
body(r11_liquid_leaves_source, pour_low).
body(r11_liquid_leaves_source, pour_tilted_back).
body(r11_liquid_leaves_source, start_tilted_back).
body(r11_liquid_leaves_source, sticky_liquid).
learned(r11_liquid_leaves_source).
provenance(r11_liquid_leaves_source, antecedent, a11).
provenance(r11_liquid_leaves_source, parent, a3).
provenance(r11_liquid_leaves_source, simulations, 31).
provenance(r11_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r11_liquid_leaves_source, confidence_permille, 1000).
provenance(r11_liquid_leaves_source, score_permille, 8).
provenance(r11_liquid_leaves_source, batches, 1).

rule(r11_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r11_liquid_enters_destination, approach_moving_away).
body(r11_liquid_enters_destination, approach_raising).
body(r11_liquid_enters_destination, bouncy_source).
body(r11_liquid_enters_destination, dull_destination).
body(r11_liquid_enters_destination, dull_liquid).
body(r11_liquid_enters_destination, end_centred).
body(r11_liquid_enters_destination, end_rolled).
body(r11_liquid_enters_destination, end_tilted_back).
body(r11_liquid_enters_destination, end_very_high).
body(r11_liquid_enters_destination, fast_approach).
body(r11_liquid_enters_destination, grippy_destination).
body(r11_liquid_enters_destination, heavy_destination).
body(r11_liquid_enters_destination, heavy_source).
body(r11_liquid_enters_destination, medium_liquid).
body(r11_liquid_enters_destination, moderate_retreat).
body(r11_liquid_enters_destination, pour_centred).
body(r11_liquid_enters_destination, pour_low).
body(r11_liquid_enters_destination, pour_tilted_back).
body(r11_liquid_enters_destination, start_tilted_back).
body(r11_liquid_enters_destination, sticky_liquid).
learned(r11_liquid_enters_destination).
provenance(r11_liquid_enters_destination, antecedent, a11).
provenance(r11_liquid_enters_destination, parent, a3).
provenance(r11_liquid_enters_destination, simulations, 31).
provenance(r11_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r11_liquid_enters_destination, confidence_permille, 710).
provenance(r11_liquid_enters_destination, score_permille, 345).
provenance(r11_liquid_enters_destination, batches, 1).

rule(r11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r11_liquid_remains_in_destination, approach_moving_away).
body(r11_liquid_remains_in_destination, approach_raising).
body(r11_liquid_remains_in_destination, bouncy_source).
body(r11_liquid_remains_in_destination, dull_destination).
body(r11_liquid_remains_in_destination, dull_liquid).
body(r11_liquid_remains_in_destination, end_centred).
body(r11_liquid_remains_in_destination, end_rolled).
body(r11_liquid_remains_in_destination, end_tilted_back).
body(r11_liquid_remains_in_destination, end_very_high).
body(r11_liquid_remains_in_destination, fast_approach).
body(r11_liquid_remains_in_destination, grippy_destination).
body(r11_liquid_remains_in_destination, heavy_destination).
body(r11_liquid_remains_in_destination, heavy_source).
body(r11_liquid_remains_in_destination, medium_liquid).
body(r11_liquid_remains_in_destination, moderate_retreat).
body(r11_liquid_remains_in_destination, pour_centred).
body(r11_liquid_remains_in_destination, pour_low).
body(r11_liquid_remains_in_destination, pour_tilted_back).
body(r11_liquid_remains_in_destination, start_tilted_back).
body(r11_liquid_remains_in_destination, sticky_liquid).
learned(r11_liquid_remains_in_destination).
provenance(r11_liquid_remains_in_destination, antecedent, a11).
provenance(r11_liquid_remains_in_destination, parent, a3).
provenance(r11_liquid_remains_in_destination, simulations, 31).
provenance(r11_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r11_liquid_remains_in_destination, confidence_permille, 516).
provenance(r11_liquid_remains_in_destination, score_permille, 516).
provenance(r11_liquid_remains_in_destination, batches, 1).

rule(r11_no_spill, defeasible, no_spill).
body(r11_no_spill, approach_moving_away).
body(r11_no_spill, approach_raising).
body(r11_no_spill, bouncy_source).
body(r11_no_spill, dull_destination).
body(r11_no_spill, dull_liquid).
body(r11_no_spill, end_centred).
body(r11_no_spill, end_rolled).
body(r11_no_spill, end_tilted_back).
body(r11_no_spill, end_very_high).
body(r11_no_spill, fast_approach).
body(r11_no_spill, grippy_destination).
body(r11_no_spill, heavy_destination).
body(r11_no_spill, heavy_source).
body(r11_no_spill, medium_liquid).
body(r11_no_spill, moderate_retreat).
body(r11_no_spill, pour_centred).
body(r11_no_spill, pour_low).
body(r11_no_spill, pour_tilted_back).
body(r11_no_spill, start_tilted_back).
body(r11_no_spill, sticky_liquid).
learned(r11_no_spill).
provenance(r11_no_spill, antecedent, a11).
provenance(r11_no_spill, parent, a3).
provenance(r11_no_spill, simulations, 31).
provenance(r11_no_spill, weight_mass_permille, 31000).
provenance(r11_no_spill, confidence_permille, 1000).
provenance(r11_no_spill, score_permille, 995).
provenance(r11_no_spill, batches, 1).

rule(r12_destination_still_approach, defeasible, destination_still_approach).
body(r12_destination_still_approach, approach_moving_closer).
body(r12_destination_still_approach, bouncy_destination).
body(r12_destination_still_approach, dull_liquid).
body(r12_destination_still_approach, dull_source).
body(r12_destination_still_approach, end_far_away).
body(r12_destination_still_approach, end_level).
body(r12_destination_still_approach, end_very_high).
body(r12_destination_still_approach, fast_retreat).
body(r12_destination_still_approach, grippy_destination).
body(r12_destination_still_approach, heavy_destination).
body(r12_destination_still_approach, heavy_liquid).
body(r12_destination_still_approach, heavy_source).
body(r12_destination_still_approach, pour_half_tilted).
body(r12_destination_still_approach, pour_level).
body(r12_destination_still_approach, pour_low).
body(r12_destination_still_approach, pour_offset_sideways).
body(r12_destination_still_approach, runny_liquid).
body(r12_destination_still_approach, slow_approach).
body(r12_destination_still_approach, start_low).
body(r12_destination_still_approach, start_tilted_back).
body(r12_destination_still_approach, very_much_liquid).
learned(r12_destination_still_approach).
provenance(r12_destination_still_approach, antecedent, a12).
provenance(r12_destination_still_approach, parent, none).
provenance(r12_destination_still_approach, simulations, 31).
provenance(r12_destination_still_approach, weight_mass_permille, 31000).
provenance(r12_destination_still_approach, confidence_permille, 935).
provenance(r12_destination_still_approach, score_permille, 926).
provenance(r12_destination_still_approach, batches, 1).

rule(r12_destination_still_retreat, defeasible, destination_still_retreat).
body(r12_destination_still_retreat, approach_moving_closer).
body(r12_destination_still_retreat, bouncy_destination).
body(r12_destination_still_retreat, dull_liquid).
body(r12_destination_still_retreat, dull_source).
body(r12_destination_still_retreat, end_far_away).
body(r12_destination_still_retreat, end_level).
body(r12_destination_still_retreat, end_very_high).
body(r12_destination_still_retreat, fast_retreat).
body(r12_destination_still_retreat, grippy_destination).
body(r12_destination_still_retreat, heavy_destination).
body(r12_destination_still_retreat, heavy_liquid).
body(r12_destination_still_retreat, heavy_source).
body(r12_destination_still_retreat, pour_half_tilted).
body(r12_destination_still_retreat, pour_level).
body(r12_destination_still_retreat, pour_low).
body(r12_destination_still_retreat, pour_offset_sideways).
body(r12_destination_still_retreat, runny_liquid).
body(r12_destination_still_retreat, slow_approach).
body(r12_destination_still_retreat, start_low).
body(r12_destination_still_retreat, start_tilted_back).
body(r12_destination_still_retreat, very_much_liquid).
learned(r12_destination_still_retreat).
provenance(r12_destination_still_retreat, antecedent, a12).
provenance(r12_destination_still_retreat, parent, none).
provenance(r12_destination_still_retreat, simulations, 31).
provenance(r12_destination_still_retreat, weight_mass_permille, 31000).
provenance(r12_destination_still_retreat, confidence_permille, 935).
provenance(r12_destination_still_retreat, score_permille, 933).
provenance(r12_destination_still_retreat, batches, 1).

rule(r12_destination_still_settle, defeasible, destination_still_settle).
body(r12_destination_still_settle, approach_moving_closer).
body(r12_destination_still_settle, bouncy_destination).
body(r12_destination_still_settle, dull_liquid).
body(r12_destination_still_settle, dull_source).
body(r12_destination_still_settle, end_far_away).
body(r12_destination_still_settle, end_level).
body(r12_destination_still_settle, end_very_high).
body(r12_destination_still_settle, fast_retreat).
body(r12_destination_still_settle, grippy_destination).
body(r12_destination_still_settle, heavy_destination).
body(r12_destination_still_settle, heavy_liquid).
body(r12_destination_still_settle, heavy_source).
body(r12_destination_still_settle, pour_half_tilted).
body(r12_destination_still_settle, pour_level).
body(r12_destination_still_settle, pour_low).
body(r12_destination_still_settle, pour_offset_sideways).
body(r12_destination_still_settle, runny_liquid).
body(r12_destination_still_settle, slow_approach).
body(r12_destination_still_settle, start_low).
body(r12_destination_still_settle, start_tilted_back).
body(r12_destination_still_settle, very_much_liquid).
learned(r12_destination_still_settle).
provenance(r12_destination_still_settle, antecedent, a12).
provenance(r12_destination_still_settle, parent, none).
provenance(r12_destination_still_settle, simulations, 31).
provenance(r12_destination_still_settle, weight_mass_permille, 31000).
provenance(r12_destination_still_settle, confidence_permille, 968).
provenance(r12_destination_still_settle, score_permille, 974).
provenance(r12_destination_still_settle, batches, 1).

rule(r12_destination_upright, defeasible, destination_upright).
body(r12_destination_upright, approach_moving_closer).
body(r12_destination_upright, bouncy_destination).
body(r12_destination_upright, dull_liquid).
body(r12_destination_upright, dull_source).
body(r12_destination_upright, end_far_away).
body(r12_destination_upright, end_level).
body(r12_destination_upright, end_very_high).
body(r12_destination_upright, fast_retreat).
body(r12_destination_upright, grippy_destination).
body(r12_destination_upright, heavy_destination).
body(r12_destination_upright, heavy_liquid).
body(r12_destination_upright, heavy_source).
body(r12_destination_upright, pour_half_tilted).
body(r12_destination_upright, pour_level).
body(r12_destination_upright, pour_low).
body(r12_destination_upright, pour_offset_sideways).
body(r12_destination_upright, runny_liquid).
body(r12_destination_upright, slow_approach).
body(r12_destination_upright, start_low).
body(r12_destination_upright, start_tilted_back).
body(r12_destination_upright, very_much_liquid).
learned(r12_destination_upright).
provenance(r12_destination_upright, antecedent, a12).
provenance(r12_destination_upright, parent, none).
provenance(r12_destination_upright, simulations, 31).
provenance(r12_destination_upright, weight_mass_permille, 31000).
provenance(r12_destination_upright, confidence_permille, 1000).
provenance(r12_destination_upright, score_permille, 1000).
provenance(r12_destination_upright, batches, 1).

rule(r12_source_clear, defeasible, source_clear).
body(r12_source_clear, approach_moving_closer).
body(r12_source_clear, bouncy_destination).
body(r12_source_clear, dull_liquid).
body(r12_source_clear, dull_source).
body(r12_source_clear, end_far_away).
body(r12_source_clear, end_level).
body(r12_source_clear, end_very_high).
body(r12_source_clear, fast_retreat).
body(r12_source_clear, grippy_destination).
body(r12_source_clear, heavy_destination).
body(r12_source_clear, heavy_liquid).
body(r12_source_clear, heavy_source).
body(r12_source_clear, pour_half_tilted).
body(r12_source_clear, pour_level).
body(r12_source_clear, pour_low).
body(r12_source_clear, pour_offset_sideways).
body(r12_source_clear, runny_liquid).
body(r12_source_clear, slow_approach).
body(r12_source_clear, start_low).
body(r12_source_clear, start_tilted_back).
body(r12_source_clear, very_much_liquid).
learned(r12_source_clear).
provenance(r12_source_clear, antecedent, a12).
provenance(r12_source_clear, parent, none).
provenance(r12_source_clear, simulations, 31).
provenance(r12_source_clear, weight_mass_permille, 31000).
provenance(r12_source_clear, confidence_permille, 871).
provenance(r12_source_clear, score_permille, 830).
provenance(r12_source_clear, batches, 1).

rule(r12_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r12_liquid_leaves_source, approach_moving_closer).
body(r12_liquid_leaves_source, bouncy_destination).
body(r12_liquid_leaves_source, dull_liquid).
body(r12_liquid_leaves_source, dull_source).
body(r12_liquid_leaves_source, end_far_away).
body(r12_liquid_leaves_source, end_level).
body(r12_liquid_leaves_source, end_very_high).
body(r12_liquid_leaves_source, fast_retreat).
body(r12_liquid_leaves_source, grippy_destination).
body(r12_liquid_leaves_source, heavy_destination).
body(r12_liquid_leaves_source, heavy_liquid).
body(r12_liquid_leaves_source, heavy_source).
body(r12_liquid_leaves_source, pour_half_tilted).
body(r12_liquid_leaves_source, pour_level).
body(r12_liquid_leaves_source, pour_low).
body(r12_liquid_leaves_source, pour_offset_sideways).
body(r12_liquid_leaves_source, runny_liquid).
body(r12_liquid_leaves_source, slow_approach).
body(r12_liquid_leaves_source, start_low).
body(r12_liquid_leaves_source, start_tilted_back).
body(r12_liquid_leaves_source, very_much_liquid).
learned(r12_liquid_leaves_source).
provenance(r12_liquid_leaves_source, antecedent, a12).
provenance(r12_liquid_leaves_source, parent, none).
provenance(r12_liquid_leaves_source, simulations, 31).
provenance(r12_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r12_liquid_leaves_source, confidence_permille, 581).
provenance(r12_liquid_leaves_source, score_permille, 397).
provenance(r12_liquid_leaves_source, batches, 1).

rule(r12_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r12_liquid_enters_destination, approach_moving_closer).
body(r12_liquid_enters_destination, bouncy_destination).
body(r12_liquid_enters_destination, dull_liquid).
body(r12_liquid_enters_destination, dull_source).
body(r12_liquid_enters_destination, end_far_away).
body(r12_liquid_enters_destination, end_level).
body(r12_liquid_enters_destination, end_very_high).
body(r12_liquid_enters_destination, fast_retreat).
body(r12_liquid_enters_destination, grippy_destination).
body(r12_liquid_enters_destination, heavy_destination).
body(r12_liquid_enters_destination, heavy_liquid).
body(r12_liquid_enters_destination, heavy_source).
body(r12_liquid_enters_destination, pour_half_tilted).
body(r12_liquid_enters_destination, pour_level).
body(r12_liquid_enters_destination, pour_low).
body(r12_liquid_enters_destination, pour_offset_sideways).
body(r12_liquid_enters_destination, runny_liquid).
body(r12_liquid_enters_destination, slow_approach).
body(r12_liquid_enters_destination, start_low).
body(r12_liquid_enters_destination, start_tilted_back).
body(r12_liquid_enters_destination, very_much_liquid).
learned(r12_liquid_enters_destination).
provenance(r12_liquid_enters_destination, antecedent, a12).
provenance(r12_liquid_enters_destination, parent, none).
provenance(r12_liquid_enters_destination, simulations, 31).
provenance(r12_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r12_liquid_enters_destination, confidence_permille, 968).
provenance(r12_liquid_enters_destination, score_permille, 39).
provenance(r12_liquid_enters_destination, batches, 1).

rule(r12_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r12_liquid_remains_in_destination, approach_moving_closer).
body(r12_liquid_remains_in_destination, bouncy_destination).
body(r12_liquid_remains_in_destination, dull_liquid).
body(r12_liquid_remains_in_destination, dull_source).
body(r12_liquid_remains_in_destination, end_far_away).
body(r12_liquid_remains_in_destination, end_level).
body(r12_liquid_remains_in_destination, end_very_high).
body(r12_liquid_remains_in_destination, fast_retreat).
body(r12_liquid_remains_in_destination, grippy_destination).
body(r12_liquid_remains_in_destination, heavy_destination).
body(r12_liquid_remains_in_destination, heavy_liquid).
body(r12_liquid_remains_in_destination, heavy_source).
body(r12_liquid_remains_in_destination, pour_half_tilted).
body(r12_liquid_remains_in_destination, pour_level).
body(r12_liquid_remains_in_destination, pour_low).
body(r12_liquid_remains_in_destination, pour_offset_sideways).
body(r12_liquid_remains_in_destination, runny_liquid).
body(r12_liquid_remains_in_destination, slow_approach).
body(r12_liquid_remains_in_destination, start_low).
body(r12_liquid_remains_in_destination, start_tilted_back).
body(r12_liquid_remains_in_destination, very_much_liquid).
learned(r12_liquid_remains_in_destination).
provenance(r12_liquid_remains_in_destination, antecedent, a12).
provenance(r12_liquid_remains_in_destination, parent, none).
provenance(r12_liquid_remains_in_destination, simulations, 31).
provenance(r12_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r12_liquid_remains_in_destination, confidence_permille, 968).
provenance(r12_liquid_remains_in_destination, score_permille, 965).
provenance(r12_liquid_remains_in_destination, batches, 1).

rule(r12_no_spill, defeasible, no_spill).
body(r12_no_spill, approach_moving_closer).
body(r12_no_spill, bouncy_destination).
body(r12_no_spill, dull_liquid).
body(r12_no_spill, dull_source).
body(r12_no_spill, end_far_away).
body(r12_no_spill, end_level).
body(r12_no_spill, end_very_high).
body(r12_no_spill, fast_retreat).
body(r12_no_spill, grippy_destination).
body(r12_no_spill, heavy_destination).
body(r12_no_spill, heavy_liquid).
body(r12_no_spill, heavy_source).
body(r12_no_spill, pour_half_tilted).
body(r12_no_spill, pour_level).
body(r12_no_spill, pour_low).
body(r12_no_spill, pour_offset_sideways).
body(r12_no_spill, runny_liquid).
body(r12_no_spill, slow_approach).
body(r12_no_spill, start_low).
body(r12_no_spill, start_tilted_back).
body(r12_no_spill, very_much_liquid).
learned(r12_no_spill).
provenance(r12_no_spill, antecedent, a12).
provenance(r12_no_spill, parent, none).
provenance(r12_no_spill, simulations, 31).
provenance(r12_no_spill, weight_mass_permille, 31000).
provenance(r12_no_spill, confidence_permille, 581).
provenance(r12_no_spill, score_permille, 620).
provenance(r12_no_spill, batches, 1).

rule(r13_destination_still_approach, defeasible, destination_still_approach).
body(r13_destination_still_approach, bouncy_liquid).
body(r13_destination_still_approach, dull_destination).
body(r13_destination_still_approach, end_low).
body(r13_destination_still_approach, end_near_rim).
body(r13_destination_still_approach, end_tilted_back).
body(r13_destination_still_approach, light_source).
body(r13_destination_still_approach, pour_below_rim).
body(r13_destination_still_approach, pour_far_away).
body(r13_destination_still_approach, pour_offset_sideways).
body(r13_destination_still_approach, pour_rolled).
body(r13_destination_still_approach, pour_slightly_tilted).
body(r13_destination_still_approach, slippery_destination).
body(r13_destination_still_approach, slippery_source).
body(r13_destination_still_approach, slow_retreat).
body(r13_destination_still_approach, start_near_rim).
body(r13_destination_still_approach, start_very_high).
body(r13_destination_still_approach, very_much_liquid).
learned(r13_destination_still_approach).
provenance(r13_destination_still_approach, antecedent, a13).
provenance(r13_destination_still_approach, parent, none).
provenance(r13_destination_still_approach, simulations, 31).
provenance(r13_destination_still_approach, weight_mass_permille, 31000).
provenance(r13_destination_still_approach, confidence_permille, 1000).
provenance(r13_destination_still_approach, score_permille, 984).
provenance(r13_destination_still_approach, batches, 1).

rule(r13_destination_still_retreat, defeasible, destination_still_retreat).
body(r13_destination_still_retreat, bouncy_liquid).
body(r13_destination_still_retreat, dull_destination).
body(r13_destination_still_retreat, end_low).
body(r13_destination_still_retreat, end_near_rim).
body(r13_destination_still_retreat, end_tilted_back).
body(r13_destination_still_retreat, light_source).
body(r13_destination_still_retreat, pour_below_rim).
body(r13_destination_still_retreat, pour_far_away).
body(r13_destination_still_retreat, pour_offset_sideways).
body(r13_destination_still_retreat, pour_rolled).
body(r13_destination_still_retreat, pour_slightly_tilted).
body(r13_destination_still_retreat, slippery_destination).
body(r13_destination_still_retreat, slippery_source).
body(r13_destination_still_retreat, slow_retreat).
body(r13_destination_still_retreat, start_near_rim).
body(r13_destination_still_retreat, start_very_high).
body(r13_destination_still_retreat, very_much_liquid).
learned(r13_destination_still_retreat).
provenance(r13_destination_still_retreat, antecedent, a13).
provenance(r13_destination_still_retreat, parent, none).
provenance(r13_destination_still_retreat, simulations, 31).
provenance(r13_destination_still_retreat, weight_mass_permille, 31000).
provenance(r13_destination_still_retreat, confidence_permille, 935).
provenance(r13_destination_still_retreat, score_permille, 894).
provenance(r13_destination_still_retreat, batches, 1).

rule(r13_destination_still_settle, defeasible, destination_still_settle).
body(r13_destination_still_settle, bouncy_liquid).
body(r13_destination_still_settle, dull_destination).
body(r13_destination_still_settle, end_low).
body(r13_destination_still_settle, end_near_rim).
body(r13_destination_still_settle, end_tilted_back).
body(r13_destination_still_settle, light_source).
body(r13_destination_still_settle, pour_below_rim).
body(r13_destination_still_settle, pour_far_away).
body(r13_destination_still_settle, pour_offset_sideways).
body(r13_destination_still_settle, pour_rolled).
body(r13_destination_still_settle, pour_slightly_tilted).
body(r13_destination_still_settle, slippery_destination).
body(r13_destination_still_settle, slippery_source).
body(r13_destination_still_settle, slow_retreat).
body(r13_destination_still_settle, start_near_rim).
body(r13_destination_still_settle, start_very_high).
body(r13_destination_still_settle, very_much_liquid).
learned(r13_destination_still_settle).
provenance(r13_destination_still_settle, antecedent, a13).
provenance(r13_destination_still_settle, parent, none).
provenance(r13_destination_still_settle, simulations, 31).
provenance(r13_destination_still_settle, weight_mass_permille, 31000).
provenance(r13_destination_still_settle, confidence_permille, 1000).
provenance(r13_destination_still_settle, score_permille, 999).
provenance(r13_destination_still_settle, batches, 1).

rule(r13_destination_upright, defeasible, destination_upright).
body(r13_destination_upright, bouncy_liquid).
body(r13_destination_upright, dull_destination).
body(r13_destination_upright, end_low).
body(r13_destination_upright, end_near_rim).
body(r13_destination_upright, end_tilted_back).
body(r13_destination_upright, light_source).
body(r13_destination_upright, pour_below_rim).
body(r13_destination_upright, pour_far_away).
body(r13_destination_upright, pour_offset_sideways).
body(r13_destination_upright, pour_rolled).
body(r13_destination_upright, pour_slightly_tilted).
body(r13_destination_upright, slippery_destination).
body(r13_destination_upright, slippery_source).
body(r13_destination_upright, slow_retreat).
body(r13_destination_upright, start_near_rim).
body(r13_destination_upright, start_very_high).
body(r13_destination_upright, very_much_liquid).
learned(r13_destination_upright).
provenance(r13_destination_upright, antecedent, a13).
provenance(r13_destination_upright, parent, none).
provenance(r13_destination_upright, simulations, 31).
provenance(r13_destination_upright, weight_mass_permille, 31000).
provenance(r13_destination_upright, confidence_permille, 1000).
provenance(r13_destination_upright, score_permille, 1000).
provenance(r13_destination_upright, batches, 1).

rule(r13_source_clear, defeasible, source_clear).
body(r13_source_clear, bouncy_liquid).
body(r13_source_clear, dull_destination).
body(r13_source_clear, end_low).
body(r13_source_clear, end_near_rim).
body(r13_source_clear, end_tilted_back).
body(r13_source_clear, light_source).
body(r13_source_clear, pour_below_rim).
body(r13_source_clear, pour_far_away).
body(r13_source_clear, pour_offset_sideways).
body(r13_source_clear, pour_rolled).
body(r13_source_clear, pour_slightly_tilted).
body(r13_source_clear, slippery_destination).
body(r13_source_clear, slippery_source).
body(r13_source_clear, slow_retreat).
body(r13_source_clear, start_near_rim).
body(r13_source_clear, start_very_high).
body(r13_source_clear, very_much_liquid).
learned(r13_source_clear).
provenance(r13_source_clear, antecedent, a13).
provenance(r13_source_clear, parent, none).
provenance(r13_source_clear, simulations, 31).
provenance(r13_source_clear, weight_mass_permille, 31000).
provenance(r13_source_clear, confidence_permille, 839).
provenance(r13_source_clear, score_permille, 786).
provenance(r13_source_clear, batches, 1).

rule(r13_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r13_liquid_leaves_source, bouncy_liquid).
body(r13_liquid_leaves_source, dull_destination).
body(r13_liquid_leaves_source, end_low).
body(r13_liquid_leaves_source, end_near_rim).
body(r13_liquid_leaves_source, end_tilted_back).
body(r13_liquid_leaves_source, light_source).
body(r13_liquid_leaves_source, pour_below_rim).
body(r13_liquid_leaves_source, pour_far_away).
body(r13_liquid_leaves_source, pour_offset_sideways).
body(r13_liquid_leaves_source, pour_rolled).
body(r13_liquid_leaves_source, pour_slightly_tilted).
body(r13_liquid_leaves_source, slippery_destination).
body(r13_liquid_leaves_source, slippery_source).
body(r13_liquid_leaves_source, slow_retreat).
body(r13_liquid_leaves_source, start_near_rim).
body(r13_liquid_leaves_source, start_very_high).
body(r13_liquid_leaves_source, very_much_liquid).
learned(r13_liquid_leaves_source).
provenance(r13_liquid_leaves_source, antecedent, a13).
provenance(r13_liquid_leaves_source, parent, none).
provenance(r13_liquid_leaves_source, simulations, 31).
provenance(r13_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r13_liquid_leaves_source, confidence_permille, 935).
provenance(r13_liquid_leaves_source, score_permille, 94).
provenance(r13_liquid_leaves_source, batches, 1).

rule(r13_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r13_liquid_enters_destination, bouncy_liquid).
body(r13_liquid_enters_destination, dull_destination).
body(r13_liquid_enters_destination, end_low).
body(r13_liquid_enters_destination, end_near_rim).
body(r13_liquid_enters_destination, end_tilted_back).
body(r13_liquid_enters_destination, light_source).
body(r13_liquid_enters_destination, pour_below_rim).
body(r13_liquid_enters_destination, pour_far_away).
body(r13_liquid_enters_destination, pour_offset_sideways).
body(r13_liquid_enters_destination, pour_rolled).
body(r13_liquid_enters_destination, pour_slightly_tilted).
body(r13_liquid_enters_destination, slippery_destination).
body(r13_liquid_enters_destination, slippery_source).
body(r13_liquid_enters_destination, slow_retreat).
body(r13_liquid_enters_destination, start_near_rim).
body(r13_liquid_enters_destination, start_very_high).
body(r13_liquid_enters_destination, very_much_liquid).
learned(r13_liquid_enters_destination).
provenance(r13_liquid_enters_destination, antecedent, a13).
provenance(r13_liquid_enters_destination, parent, none).
provenance(r13_liquid_enters_destination, simulations, 31).
provenance(r13_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r13_liquid_enters_destination, confidence_permille, 1000).
provenance(r13_liquid_enters_destination, score_permille, 10).
provenance(r13_liquid_enters_destination, batches, 1).

rule(r13_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r13_liquid_remains_in_destination, bouncy_liquid).
body(r13_liquid_remains_in_destination, dull_destination).
body(r13_liquid_remains_in_destination, end_low).
body(r13_liquid_remains_in_destination, end_near_rim).
body(r13_liquid_remains_in_destination, end_tilted_back).
body(r13_liquid_remains_in_destination, light_source).
body(r13_liquid_remains_in_destination, pour_below_rim).
body(r13_liquid_remains_in_destination, pour_far_away).
body(r13_liquid_remains_in_destination, pour_offset_sideways).
body(r13_liquid_remains_in_destination, pour_rolled).
body(r13_liquid_remains_in_destination, pour_slightly_tilted).
body(r13_liquid_remains_in_destination, slippery_destination).
body(r13_liquid_remains_in_destination, slippery_source).
body(r13_liquid_remains_in_destination, slow_retreat).
body(r13_liquid_remains_in_destination, start_near_rim).
body(r13_liquid_remains_in_destination, start_very_high).
body(r13_liquid_remains_in_destination, very_much_liquid).
learned(r13_liquid_remains_in_destination).
provenance(r13_liquid_remains_in_destination, antecedent, a13).
provenance(r13_liquid_remains_in_destination, parent, none).
provenance(r13_liquid_remains_in_destination, simulations, 31).
provenance(r13_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r13_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r13_liquid_remains_in_destination, score_permille, 992).
provenance(r13_liquid_remains_in_destination, batches, 1).

rule(r13_no_spill, defeasible, no_spill).
body(r13_no_spill, bouncy_liquid).
body(r13_no_spill, dull_destination).
body(r13_no_spill, end_low).
body(r13_no_spill, end_near_rim).
body(r13_no_spill, end_tilted_back).
body(r13_no_spill, light_source).
body(r13_no_spill, pour_below_rim).
body(r13_no_spill, pour_far_away).
body(r13_no_spill, pour_offset_sideways).
body(r13_no_spill, pour_rolled).
body(r13_no_spill, pour_slightly_tilted).
body(r13_no_spill, slippery_destination).
body(r13_no_spill, slippery_source).
body(r13_no_spill, slow_retreat).
body(r13_no_spill, start_near_rim).
body(r13_no_spill, start_very_high).
body(r13_no_spill, very_much_liquid).
learned(r13_no_spill).
provenance(r13_no_spill, antecedent, a13).
provenance(r13_no_spill, parent, none).
provenance(r13_no_spill, simulations, 31).
provenance(r13_no_spill, weight_mass_permille, 31000).
provenance(r13_no_spill, confidence_permille, 935).
provenance(r13_no_spill, score_permille, 915).
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
provenance(r14_destination_still_approach, confidence_permille, 1000).
provenance(r14_destination_still_approach, score_permille, 0).
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
provenance(r14_destination_still_retreat, confidence_permille, 903).
provenance(r14_destination_still_retreat, score_permille, 89).
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
provenance(r14_destination_still_settle, confidence_permille, 613).
provenance(r14_destination_still_settle, score_permille, 365).
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
provenance(r14_destination_upright, confidence_permille, 742).
provenance(r14_destination_upright, score_permille, 750).
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
provenance(r14_liquid_leaves_source, confidence_permille, 806).
provenance(r14_liquid_leaves_source, score_permille, 798).
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
provenance(r14_liquid_enters_destination, score_permille, 995).
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
provenance(r14_liquid_remains_in_destination, confidence_permille, 710).
provenance(r14_liquid_remains_in_destination, score_permille, 676).
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
provenance(r14_no_spill, confidence_permille, 903).
provenance(r14_no_spill, score_permille, 875).
provenance(r14_no_spill, batches, 1).

rule(r15_destination_still_approach, defeasible, destination_still_approach).
body(r15_destination_still_approach, approach_lowering).
body(r15_destination_still_approach, dull_liquid).
body(r15_destination_still_approach, end_to_side).
body(r15_destination_still_approach, end_upright).
body(r15_destination_still_approach, fast_approach).
body(r15_destination_still_approach, light_source).
body(r15_destination_still_approach, medium_destination).
body(r15_destination_still_approach, medium_liquid).
body(r15_destination_still_approach, much_liquid).
body(r15_destination_still_approach, pour_below_rim).
body(r15_destination_still_approach, pour_far_away).
body(r15_destination_still_approach, pour_steeply_tilted).
body(r15_destination_still_approach, retreat_lowering).
body(r15_destination_still_approach, runny_liquid).
body(r15_destination_still_approach, slippery_source).
body(r15_destination_still_approach, slow_retreat).
body(r15_destination_still_approach, start_far_away).
body(r15_destination_still_approach, start_tilted_back).
learned(r15_destination_still_approach).
provenance(r15_destination_still_approach, antecedent, a15).
provenance(r15_destination_still_approach, parent, none).
provenance(r15_destination_still_approach, simulations, 31).
provenance(r15_destination_still_approach, weight_mass_permille, 31000).
provenance(r15_destination_still_approach, confidence_permille, 1000).
provenance(r15_destination_still_approach, score_permille, 993).
provenance(r15_destination_still_approach, batches, 1).

rule(r15_destination_still_retreat, defeasible, destination_still_retreat).
body(r15_destination_still_retreat, approach_lowering).
body(r15_destination_still_retreat, dull_liquid).
body(r15_destination_still_retreat, end_to_side).
body(r15_destination_still_retreat, end_upright).
body(r15_destination_still_retreat, fast_approach).
body(r15_destination_still_retreat, light_source).
body(r15_destination_still_retreat, medium_destination).
body(r15_destination_still_retreat, medium_liquid).
body(r15_destination_still_retreat, much_liquid).
body(r15_destination_still_retreat, pour_below_rim).
body(r15_destination_still_retreat, pour_far_away).
body(r15_destination_still_retreat, pour_steeply_tilted).
body(r15_destination_still_retreat, retreat_lowering).
body(r15_destination_still_retreat, runny_liquid).
body(r15_destination_still_retreat, slippery_source).
body(r15_destination_still_retreat, slow_retreat).
body(r15_destination_still_retreat, start_far_away).
body(r15_destination_still_retreat, start_tilted_back).
learned(r15_destination_still_retreat).
provenance(r15_destination_still_retreat, antecedent, a15).
provenance(r15_destination_still_retreat, parent, none).
provenance(r15_destination_still_retreat, simulations, 31).
provenance(r15_destination_still_retreat, weight_mass_permille, 31000).
provenance(r15_destination_still_retreat, confidence_permille, 968).
provenance(r15_destination_still_retreat, score_permille, 918).
provenance(r15_destination_still_retreat, batches, 1).

rule(r15_destination_still_settle, defeasible, destination_still_settle).
body(r15_destination_still_settle, approach_lowering).
body(r15_destination_still_settle, dull_liquid).
body(r15_destination_still_settle, end_to_side).
body(r15_destination_still_settle, end_upright).
body(r15_destination_still_settle, fast_approach).
body(r15_destination_still_settle, light_source).
body(r15_destination_still_settle, medium_destination).
body(r15_destination_still_settle, medium_liquid).
body(r15_destination_still_settle, much_liquid).
body(r15_destination_still_settle, pour_below_rim).
body(r15_destination_still_settle, pour_far_away).
body(r15_destination_still_settle, pour_steeply_tilted).
body(r15_destination_still_settle, retreat_lowering).
body(r15_destination_still_settle, runny_liquid).
body(r15_destination_still_settle, slippery_source).
body(r15_destination_still_settle, slow_retreat).
body(r15_destination_still_settle, start_far_away).
body(r15_destination_still_settle, start_tilted_back).
learned(r15_destination_still_settle).
provenance(r15_destination_still_settle, antecedent, a15).
provenance(r15_destination_still_settle, parent, none).
provenance(r15_destination_still_settle, simulations, 31).
provenance(r15_destination_still_settle, weight_mass_permille, 31000).
provenance(r15_destination_still_settle, confidence_permille, 1000).
provenance(r15_destination_still_settle, score_permille, 997).
provenance(r15_destination_still_settle, batches, 1).

rule(r15_destination_upright, defeasible, destination_upright).
body(r15_destination_upright, approach_lowering).
body(r15_destination_upright, dull_liquid).
body(r15_destination_upright, end_to_side).
body(r15_destination_upright, end_upright).
body(r15_destination_upright, fast_approach).
body(r15_destination_upright, light_source).
body(r15_destination_upright, medium_destination).
body(r15_destination_upright, medium_liquid).
body(r15_destination_upright, much_liquid).
body(r15_destination_upright, pour_below_rim).
body(r15_destination_upright, pour_far_away).
body(r15_destination_upright, pour_steeply_tilted).
body(r15_destination_upright, retreat_lowering).
body(r15_destination_upright, runny_liquid).
body(r15_destination_upright, slippery_source).
body(r15_destination_upright, slow_retreat).
body(r15_destination_upright, start_far_away).
body(r15_destination_upright, start_tilted_back).
learned(r15_destination_upright).
provenance(r15_destination_upright, antecedent, a15).
provenance(r15_destination_upright, parent, none).
provenance(r15_destination_upright, simulations, 31).
provenance(r15_destination_upright, weight_mass_permille, 31000).
provenance(r15_destination_upright, confidence_permille, 1000).
provenance(r15_destination_upright, score_permille, 997).
provenance(r15_destination_upright, batches, 1).

rule(r15_source_clear, defeasible, source_clear).
body(r15_source_clear, approach_lowering).
body(r15_source_clear, dull_liquid).
body(r15_source_clear, end_to_side).
body(r15_source_clear, end_upright).
body(r15_source_clear, fast_approach).
body(r15_source_clear, light_source).
body(r15_source_clear, medium_destination).
body(r15_source_clear, medium_liquid).
body(r15_source_clear, much_liquid).
body(r15_source_clear, pour_below_rim).
body(r15_source_clear, pour_far_away).
body(r15_source_clear, pour_steeply_tilted).
body(r15_source_clear, retreat_lowering).
body(r15_source_clear, runny_liquid).
body(r15_source_clear, slippery_source).
body(r15_source_clear, slow_retreat).
body(r15_source_clear, start_far_away).
body(r15_source_clear, start_tilted_back).
learned(r15_source_clear).
provenance(r15_source_clear, antecedent, a15).
provenance(r15_source_clear, parent, none).
provenance(r15_source_clear, simulations, 31).
provenance(r15_source_clear, weight_mass_permille, 31000).
provenance(r15_source_clear, confidence_permille, 806).
provenance(r15_source_clear, score_permille, 738).
provenance(r15_source_clear, batches, 1).

rule(r15_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r15_liquid_leaves_source, approach_lowering).
body(r15_liquid_leaves_source, dull_liquid).
body(r15_liquid_leaves_source, end_to_side).
body(r15_liquid_leaves_source, end_upright).
body(r15_liquid_leaves_source, fast_approach).
body(r15_liquid_leaves_source, light_source).
body(r15_liquid_leaves_source, medium_destination).
body(r15_liquid_leaves_source, medium_liquid).
body(r15_liquid_leaves_source, much_liquid).
body(r15_liquid_leaves_source, pour_below_rim).
body(r15_liquid_leaves_source, pour_far_away).
body(r15_liquid_leaves_source, pour_steeply_tilted).
body(r15_liquid_leaves_source, retreat_lowering).
body(r15_liquid_leaves_source, runny_liquid).
body(r15_liquid_leaves_source, slippery_source).
body(r15_liquid_leaves_source, slow_retreat).
body(r15_liquid_leaves_source, start_far_away).
body(r15_liquid_leaves_source, start_tilted_back).
learned(r15_liquid_leaves_source).
provenance(r15_liquid_leaves_source, antecedent, a15).
provenance(r15_liquid_leaves_source, parent, none).
provenance(r15_liquid_leaves_source, simulations, 31).
provenance(r15_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r15_liquid_leaves_source, confidence_permille, 1000).
provenance(r15_liquid_leaves_source, score_permille, 893).
provenance(r15_liquid_leaves_source, batches, 1).

rule(r15_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r15_liquid_enters_destination, approach_lowering).
body(r15_liquid_enters_destination, dull_liquid).
body(r15_liquid_enters_destination, end_to_side).
body(r15_liquid_enters_destination, end_upright).
body(r15_liquid_enters_destination, fast_approach).
body(r15_liquid_enters_destination, light_source).
body(r15_liquid_enters_destination, medium_destination).
body(r15_liquid_enters_destination, medium_liquid).
body(r15_liquid_enters_destination, much_liquid).
body(r15_liquid_enters_destination, pour_below_rim).
body(r15_liquid_enters_destination, pour_far_away).
body(r15_liquid_enters_destination, pour_steeply_tilted).
body(r15_liquid_enters_destination, retreat_lowering).
body(r15_liquid_enters_destination, runny_liquid).
body(r15_liquid_enters_destination, slippery_source).
body(r15_liquid_enters_destination, slow_retreat).
body(r15_liquid_enters_destination, start_far_away).
body(r15_liquid_enters_destination, start_tilted_back).
learned(r15_liquid_enters_destination).
provenance(r15_liquid_enters_destination, antecedent, a15).
provenance(r15_liquid_enters_destination, parent, none).
provenance(r15_liquid_enters_destination, simulations, 31).
provenance(r15_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r15_liquid_enters_destination, confidence_permille, 1000).
provenance(r15_liquid_enters_destination, score_permille, 1).
provenance(r15_liquid_enters_destination, batches, 1).

rule(r15_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r15_liquid_remains_in_destination, approach_lowering).
body(r15_liquid_remains_in_destination, dull_liquid).
body(r15_liquid_remains_in_destination, end_to_side).
body(r15_liquid_remains_in_destination, end_upright).
body(r15_liquid_remains_in_destination, fast_approach).
body(r15_liquid_remains_in_destination, light_source).
body(r15_liquid_remains_in_destination, medium_destination).
body(r15_liquid_remains_in_destination, medium_liquid).
body(r15_liquid_remains_in_destination, much_liquid).
body(r15_liquid_remains_in_destination, pour_below_rim).
body(r15_liquid_remains_in_destination, pour_far_away).
body(r15_liquid_remains_in_destination, pour_steeply_tilted).
body(r15_liquid_remains_in_destination, retreat_lowering).
body(r15_liquid_remains_in_destination, runny_liquid).
body(r15_liquid_remains_in_destination, slippery_source).
body(r15_liquid_remains_in_destination, slow_retreat).
body(r15_liquid_remains_in_destination, start_far_away).
body(r15_liquid_remains_in_destination, start_tilted_back).
learned(r15_liquid_remains_in_destination).
provenance(r15_liquid_remains_in_destination, antecedent, a15).
provenance(r15_liquid_remains_in_destination, parent, none).
provenance(r15_liquid_remains_in_destination, simulations, 31).
provenance(r15_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r15_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r15_liquid_remains_in_destination, score_permille, 1000).
provenance(r15_liquid_remains_in_destination, batches, 1).

rule(r15_no_spill, defeasible, neg(no_spill)).
body(r15_no_spill, approach_lowering).
body(r15_no_spill, dull_liquid).
body(r15_no_spill, end_to_side).
body(r15_no_spill, end_upright).
body(r15_no_spill, fast_approach).
body(r15_no_spill, light_source).
body(r15_no_spill, medium_destination).
body(r15_no_spill, medium_liquid).
body(r15_no_spill, much_liquid).
body(r15_no_spill, pour_below_rim).
body(r15_no_spill, pour_far_away).
body(r15_no_spill, pour_steeply_tilted).
body(r15_no_spill, retreat_lowering).
body(r15_no_spill, runny_liquid).
body(r15_no_spill, slippery_source).
body(r15_no_spill, slow_retreat).
body(r15_no_spill, start_far_away).
body(r15_no_spill, start_tilted_back).
learned(r15_no_spill).
provenance(r15_no_spill, antecedent, a15).
provenance(r15_no_spill, parent, none).
provenance(r15_no_spill, simulations, 31).
provenance(r15_no_spill, weight_mass_permille, 31000).
provenance(r15_no_spill, confidence_permille, 1000).
provenance(r15_no_spill, score_permille, 107).
provenance(r15_no_spill, batches, 1).

rule(r16_destination_still_approach, defeasible, destination_still_approach).
body(r16_destination_still_approach, approach_lowering).
body(r16_destination_still_approach, dull_destination).
body(r16_destination_still_approach, dull_source).
body(r16_destination_still_approach, end_level).
body(r16_destination_still_approach, end_upright).
body(r16_destination_still_approach, fast_approach).
body(r16_destination_still_approach, grippy_source).
body(r16_destination_still_approach, light_destination).
body(r16_destination_still_approach, light_source).
body(r16_destination_still_approach, little_liquid).
body(r16_destination_still_approach, pour_far_away).
body(r16_destination_still_approach, pour_in_line).
body(r16_destination_still_approach, pour_low).
body(r16_destination_still_approach, pour_tilted_back).
body(r16_destination_still_approach, retreat_lowering).
body(r16_destination_still_approach, retreat_moving_away).
body(r16_destination_still_approach, slow_retreat).
body(r16_destination_still_approach, start_centred).
body(r16_destination_still_approach, start_tilted_back).
body(r16_destination_still_approach, sticky_liquid).
learned(r16_destination_still_approach).
provenance(r16_destination_still_approach, antecedent, a16).
provenance(r16_destination_still_approach, parent, none).
provenance(r16_destination_still_approach, simulations, 31).
provenance(r16_destination_still_approach, weight_mass_permille, 31000).
provenance(r16_destination_still_approach, confidence_permille, 1000).
provenance(r16_destination_still_approach, score_permille, 993).
provenance(r16_destination_still_approach, batches, 1).

rule(r16_destination_still_retreat, defeasible, destination_still_retreat).
body(r16_destination_still_retreat, approach_lowering).
body(r16_destination_still_retreat, dull_destination).
body(r16_destination_still_retreat, dull_source).
body(r16_destination_still_retreat, end_level).
body(r16_destination_still_retreat, end_upright).
body(r16_destination_still_retreat, fast_approach).
body(r16_destination_still_retreat, grippy_source).
body(r16_destination_still_retreat, light_destination).
body(r16_destination_still_retreat, light_source).
body(r16_destination_still_retreat, little_liquid).
body(r16_destination_still_retreat, pour_far_away).
body(r16_destination_still_retreat, pour_in_line).
body(r16_destination_still_retreat, pour_low).
body(r16_destination_still_retreat, pour_tilted_back).
body(r16_destination_still_retreat, retreat_lowering).
body(r16_destination_still_retreat, retreat_moving_away).
body(r16_destination_still_retreat, slow_retreat).
body(r16_destination_still_retreat, start_centred).
body(r16_destination_still_retreat, start_tilted_back).
body(r16_destination_still_retreat, sticky_liquid).
learned(r16_destination_still_retreat).
provenance(r16_destination_still_retreat, antecedent, a16).
provenance(r16_destination_still_retreat, parent, none).
provenance(r16_destination_still_retreat, simulations, 31).
provenance(r16_destination_still_retreat, weight_mass_permille, 31000).
provenance(r16_destination_still_retreat, confidence_permille, 1000).
provenance(r16_destination_still_retreat, score_permille, 1000).
provenance(r16_destination_still_retreat, batches, 1).

rule(r16_destination_still_settle, defeasible, destination_still_settle).
body(r16_destination_still_settle, approach_lowering).
body(r16_destination_still_settle, dull_destination).
body(r16_destination_still_settle, dull_source).
body(r16_destination_still_settle, end_level).
body(r16_destination_still_settle, end_upright).
body(r16_destination_still_settle, fast_approach).
body(r16_destination_still_settle, grippy_source).
body(r16_destination_still_settle, light_destination).
body(r16_destination_still_settle, light_source).
body(r16_destination_still_settle, little_liquid).
body(r16_destination_still_settle, pour_far_away).
body(r16_destination_still_settle, pour_in_line).
body(r16_destination_still_settle, pour_low).
body(r16_destination_still_settle, pour_tilted_back).
body(r16_destination_still_settle, retreat_lowering).
body(r16_destination_still_settle, retreat_moving_away).
body(r16_destination_still_settle, slow_retreat).
body(r16_destination_still_settle, start_centred).
body(r16_destination_still_settle, start_tilted_back).
body(r16_destination_still_settle, sticky_liquid).
learned(r16_destination_still_settle).
provenance(r16_destination_still_settle, antecedent, a16).
provenance(r16_destination_still_settle, parent, none).
provenance(r16_destination_still_settle, simulations, 31).
provenance(r16_destination_still_settle, weight_mass_permille, 31000).
provenance(r16_destination_still_settle, confidence_permille, 1000).
provenance(r16_destination_still_settle, score_permille, 1000).
provenance(r16_destination_still_settle, batches, 1).

rule(r16_destination_upright, defeasible, destination_upright).
body(r16_destination_upright, approach_lowering).
body(r16_destination_upright, dull_destination).
body(r16_destination_upright, dull_source).
body(r16_destination_upright, end_level).
body(r16_destination_upright, end_upright).
body(r16_destination_upright, fast_approach).
body(r16_destination_upright, grippy_source).
body(r16_destination_upright, light_destination).
body(r16_destination_upright, light_source).
body(r16_destination_upright, little_liquid).
body(r16_destination_upright, pour_far_away).
body(r16_destination_upright, pour_in_line).
body(r16_destination_upright, pour_low).
body(r16_destination_upright, pour_tilted_back).
body(r16_destination_upright, retreat_lowering).
body(r16_destination_upright, retreat_moving_away).
body(r16_destination_upright, slow_retreat).
body(r16_destination_upright, start_centred).
body(r16_destination_upright, start_tilted_back).
body(r16_destination_upright, sticky_liquid).
learned(r16_destination_upright).
provenance(r16_destination_upright, antecedent, a16).
provenance(r16_destination_upright, parent, none).
provenance(r16_destination_upright, simulations, 31).
provenance(r16_destination_upright, weight_mass_permille, 31000).
provenance(r16_destination_upright, confidence_permille, 1000).
provenance(r16_destination_upright, score_permille, 1000).
provenance(r16_destination_upright, batches, 1).

rule(r16_source_clear, defeasible, source_clear).
body(r16_source_clear, approach_lowering).
body(r16_source_clear, dull_destination).
body(r16_source_clear, dull_source).
body(r16_source_clear, end_level).
body(r16_source_clear, end_upright).
body(r16_source_clear, fast_approach).
body(r16_source_clear, grippy_source).
body(r16_source_clear, light_destination).
body(r16_source_clear, light_source).
body(r16_source_clear, little_liquid).
body(r16_source_clear, pour_far_away).
body(r16_source_clear, pour_in_line).
body(r16_source_clear, pour_low).
body(r16_source_clear, pour_tilted_back).
body(r16_source_clear, retreat_lowering).
body(r16_source_clear, retreat_moving_away).
body(r16_source_clear, slow_retreat).
body(r16_source_clear, start_centred).
body(r16_source_clear, start_tilted_back).
body(r16_source_clear, sticky_liquid).
learned(r16_source_clear).
provenance(r16_source_clear, antecedent, a16).
provenance(r16_source_clear, parent, none).
provenance(r16_source_clear, simulations, 31).
provenance(r16_source_clear, weight_mass_permille, 31000).
provenance(r16_source_clear, confidence_permille, 1000).
provenance(r16_source_clear, score_permille, 988).
provenance(r16_source_clear, batches, 1).

rule(r16_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r16_liquid_leaves_source, approach_lowering).
body(r16_liquid_leaves_source, dull_destination).
body(r16_liquid_leaves_source, dull_source).
body(r16_liquid_leaves_source, end_level).
body(r16_liquid_leaves_source, end_upright).
body(r16_liquid_leaves_source, fast_approach).
body(r16_liquid_leaves_source, grippy_source).
body(r16_liquid_leaves_source, light_destination).
body(r16_liquid_leaves_source, light_source).
body(r16_liquid_leaves_source, little_liquid).
body(r16_liquid_leaves_source, pour_far_away).
body(r16_liquid_leaves_source, pour_in_line).
body(r16_liquid_leaves_source, pour_low).
body(r16_liquid_leaves_source, pour_tilted_back).
body(r16_liquid_leaves_source, retreat_lowering).
body(r16_liquid_leaves_source, retreat_moving_away).
body(r16_liquid_leaves_source, slow_retreat).
body(r16_liquid_leaves_source, start_centred).
body(r16_liquid_leaves_source, start_tilted_back).
body(r16_liquid_leaves_source, sticky_liquid).
learned(r16_liquid_leaves_source).
provenance(r16_liquid_leaves_source, antecedent, a16).
provenance(r16_liquid_leaves_source, parent, none).
provenance(r16_liquid_leaves_source, simulations, 31).
provenance(r16_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r16_liquid_leaves_source, confidence_permille, 1000).
provenance(r16_liquid_leaves_source, score_permille, 0).
provenance(r16_liquid_leaves_source, batches, 1).

rule(r16_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r16_liquid_enters_destination, approach_lowering).
body(r16_liquid_enters_destination, dull_destination).
body(r16_liquid_enters_destination, dull_source).
body(r16_liquid_enters_destination, end_level).
body(r16_liquid_enters_destination, end_upright).
body(r16_liquid_enters_destination, fast_approach).
body(r16_liquid_enters_destination, grippy_source).
body(r16_liquid_enters_destination, light_destination).
body(r16_liquid_enters_destination, light_source).
body(r16_liquid_enters_destination, little_liquid).
body(r16_liquid_enters_destination, pour_far_away).
body(r16_liquid_enters_destination, pour_in_line).
body(r16_liquid_enters_destination, pour_low).
body(r16_liquid_enters_destination, pour_tilted_back).
body(r16_liquid_enters_destination, retreat_lowering).
body(r16_liquid_enters_destination, retreat_moving_away).
body(r16_liquid_enters_destination, slow_retreat).
body(r16_liquid_enters_destination, start_centred).
body(r16_liquid_enters_destination, start_tilted_back).
body(r16_liquid_enters_destination, sticky_liquid).
learned(r16_liquid_enters_destination).
provenance(r16_liquid_enters_destination, antecedent, a16).
provenance(r16_liquid_enters_destination, parent, none).
provenance(r16_liquid_enters_destination, simulations, 31).
provenance(r16_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r16_liquid_enters_destination, confidence_permille, 1000).
provenance(r16_liquid_enters_destination, score_permille, 0).
provenance(r16_liquid_enters_destination, batches, 1).

rule(r16_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r16_liquid_remains_in_destination, approach_lowering).
body(r16_liquid_remains_in_destination, dull_destination).
body(r16_liquid_remains_in_destination, dull_source).
body(r16_liquid_remains_in_destination, end_level).
body(r16_liquid_remains_in_destination, end_upright).
body(r16_liquid_remains_in_destination, fast_approach).
body(r16_liquid_remains_in_destination, grippy_source).
body(r16_liquid_remains_in_destination, light_destination).
body(r16_liquid_remains_in_destination, light_source).
body(r16_liquid_remains_in_destination, little_liquid).
body(r16_liquid_remains_in_destination, pour_far_away).
body(r16_liquid_remains_in_destination, pour_in_line).
body(r16_liquid_remains_in_destination, pour_low).
body(r16_liquid_remains_in_destination, pour_tilted_back).
body(r16_liquid_remains_in_destination, retreat_lowering).
body(r16_liquid_remains_in_destination, retreat_moving_away).
body(r16_liquid_remains_in_destination, slow_retreat).
body(r16_liquid_remains_in_destination, start_centred).
body(r16_liquid_remains_in_destination, start_tilted_back).
body(r16_liquid_remains_in_destination, sticky_liquid).
learned(r16_liquid_remains_in_destination).
provenance(r16_liquid_remains_in_destination, antecedent, a16).
provenance(r16_liquid_remains_in_destination, parent, none).
provenance(r16_liquid_remains_in_destination, simulations, 31).
provenance(r16_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r16_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r16_liquid_remains_in_destination, score_permille, 1000).
provenance(r16_liquid_remains_in_destination, batches, 1).

rule(r16_no_spill, defeasible, no_spill).
body(r16_no_spill, approach_lowering).
body(r16_no_spill, dull_destination).
body(r16_no_spill, dull_source).
body(r16_no_spill, end_level).
body(r16_no_spill, end_upright).
body(r16_no_spill, fast_approach).
body(r16_no_spill, grippy_source).
body(r16_no_spill, light_destination).
body(r16_no_spill, light_source).
body(r16_no_spill, little_liquid).
body(r16_no_spill, pour_far_away).
body(r16_no_spill, pour_in_line).
body(r16_no_spill, pour_low).
body(r16_no_spill, pour_tilted_back).
body(r16_no_spill, retreat_lowering).
body(r16_no_spill, retreat_moving_away).
body(r16_no_spill, slow_retreat).
body(r16_no_spill, start_centred).
body(r16_no_spill, start_tilted_back).
body(r16_no_spill, sticky_liquid).
learned(r16_no_spill).
provenance(r16_no_spill, antecedent, a16).
provenance(r16_no_spill, parent, none).
provenance(r16_no_spill, simulations, 31).
provenance(r16_no_spill, weight_mass_permille, 31000).
provenance(r16_no_spill, confidence_permille, 1000).
provenance(r16_no_spill, score_permille, 1000).
provenance(r16_no_spill, batches, 1).

rule(r17_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r17_destination_still_approach, approach_moving_closer).
body(r17_destination_still_approach, bouncy_source).
body(r17_destination_still_approach, dull_liquid).
body(r17_destination_still_approach, end_level).
body(r17_destination_still_approach, end_low).
body(r17_destination_still_approach, grippy_source).
body(r17_destination_still_approach, heavy_source).
body(r17_destination_still_approach, light_liquid).
body(r17_destination_still_approach, little_liquid).
body(r17_destination_still_approach, moderate_retreat).
body(r17_destination_still_approach, pour_centred).
body(r17_destination_still_approach, pour_mid_height).
body(r17_destination_still_approach, pour_offset_sideways).
body(r17_destination_still_approach, pour_upright).
body(r17_destination_still_approach, runny_liquid).
body(r17_destination_still_approach, slow_approach).
body(r17_destination_still_approach, start_below_rim).
body(r17_destination_still_approach, start_upright).
learned(r17_destination_still_approach).
provenance(r17_destination_still_approach, antecedent, a17).
provenance(r17_destination_still_approach, parent, none).
provenance(r17_destination_still_approach, simulations, 31).
provenance(r17_destination_still_approach, weight_mass_permille, 31000).
provenance(r17_destination_still_approach, confidence_permille, 516).
provenance(r17_destination_still_approach, score_permille, 461).
provenance(r17_destination_still_approach, batches, 1).

rule(r17_destination_still_retreat, defeasible, destination_still_retreat).
body(r17_destination_still_retreat, approach_moving_closer).
body(r17_destination_still_retreat, bouncy_source).
body(r17_destination_still_retreat, dull_liquid).
body(r17_destination_still_retreat, end_level).
body(r17_destination_still_retreat, end_low).
body(r17_destination_still_retreat, grippy_source).
body(r17_destination_still_retreat, heavy_source).
body(r17_destination_still_retreat, light_liquid).
body(r17_destination_still_retreat, little_liquid).
body(r17_destination_still_retreat, moderate_retreat).
body(r17_destination_still_retreat, pour_centred).
body(r17_destination_still_retreat, pour_mid_height).
body(r17_destination_still_retreat, pour_offset_sideways).
body(r17_destination_still_retreat, pour_upright).
body(r17_destination_still_retreat, runny_liquid).
body(r17_destination_still_retreat, slow_approach).
body(r17_destination_still_retreat, start_below_rim).
body(r17_destination_still_retreat, start_upright).
learned(r17_destination_still_retreat).
provenance(r17_destination_still_retreat, antecedent, a17).
provenance(r17_destination_still_retreat, parent, none).
provenance(r17_destination_still_retreat, simulations, 31).
provenance(r17_destination_still_retreat, weight_mass_permille, 31000).
provenance(r17_destination_still_retreat, confidence_permille, 806).
provenance(r17_destination_still_retreat, score_permille, 801).
provenance(r17_destination_still_retreat, batches, 1).

rule(r17_destination_still_settle, defeasible, destination_still_settle).
body(r17_destination_still_settle, approach_moving_closer).
body(r17_destination_still_settle, bouncy_source).
body(r17_destination_still_settle, dull_liquid).
body(r17_destination_still_settle, end_level).
body(r17_destination_still_settle, end_low).
body(r17_destination_still_settle, grippy_source).
body(r17_destination_still_settle, heavy_source).
body(r17_destination_still_settle, light_liquid).
body(r17_destination_still_settle, little_liquid).
body(r17_destination_still_settle, moderate_retreat).
body(r17_destination_still_settle, pour_centred).
body(r17_destination_still_settle, pour_mid_height).
body(r17_destination_still_settle, pour_offset_sideways).
body(r17_destination_still_settle, pour_upright).
body(r17_destination_still_settle, runny_liquid).
body(r17_destination_still_settle, slow_approach).
body(r17_destination_still_settle, start_below_rim).
body(r17_destination_still_settle, start_upright).
learned(r17_destination_still_settle).
provenance(r17_destination_still_settle, antecedent, a17).
provenance(r17_destination_still_settle, parent, none).
provenance(r17_destination_still_settle, simulations, 31).
provenance(r17_destination_still_settle, weight_mass_permille, 31000).
provenance(r17_destination_still_settle, confidence_permille, 871).
provenance(r17_destination_still_settle, score_permille, 858).
provenance(r17_destination_still_settle, batches, 1).

rule(r17_destination_upright, defeasible, destination_upright).
body(r17_destination_upright, approach_moving_closer).
body(r17_destination_upright, bouncy_source).
body(r17_destination_upright, dull_liquid).
body(r17_destination_upright, end_level).
body(r17_destination_upright, end_low).
body(r17_destination_upright, grippy_source).
body(r17_destination_upright, heavy_source).
body(r17_destination_upright, light_liquid).
body(r17_destination_upright, little_liquid).
body(r17_destination_upright, moderate_retreat).
body(r17_destination_upright, pour_centred).
body(r17_destination_upright, pour_mid_height).
body(r17_destination_upright, pour_offset_sideways).
body(r17_destination_upright, pour_upright).
body(r17_destination_upright, runny_liquid).
body(r17_destination_upright, slow_approach).
body(r17_destination_upright, start_below_rim).
body(r17_destination_upright, start_upright).
learned(r17_destination_upright).
provenance(r17_destination_upright, antecedent, a17).
provenance(r17_destination_upright, parent, none).
provenance(r17_destination_upright, simulations, 31).
provenance(r17_destination_upright, weight_mass_permille, 31000).
provenance(r17_destination_upright, confidence_permille, 935).
provenance(r17_destination_upright, score_permille, 934).
provenance(r17_destination_upright, batches, 1).

rule(r17_source_clear, defeasible, neg(source_clear)).
body(r17_source_clear, approach_moving_closer).
body(r17_source_clear, bouncy_source).
body(r17_source_clear, dull_liquid).
body(r17_source_clear, end_level).
body(r17_source_clear, end_low).
body(r17_source_clear, grippy_source).
body(r17_source_clear, heavy_source).
body(r17_source_clear, light_liquid).
body(r17_source_clear, little_liquid).
body(r17_source_clear, moderate_retreat).
body(r17_source_clear, pour_centred).
body(r17_source_clear, pour_mid_height).
body(r17_source_clear, pour_offset_sideways).
body(r17_source_clear, pour_upright).
body(r17_source_clear, runny_liquid).
body(r17_source_clear, slow_approach).
body(r17_source_clear, start_below_rim).
body(r17_source_clear, start_upright).
learned(r17_source_clear).
provenance(r17_source_clear, antecedent, a17).
provenance(r17_source_clear, parent, none).
provenance(r17_source_clear, simulations, 31).
provenance(r17_source_clear, weight_mass_permille, 31000).
provenance(r17_source_clear, confidence_permille, 774).
provenance(r17_source_clear, score_permille, 158).
provenance(r17_source_clear, batches, 1).

rule(r17_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r17_liquid_leaves_source, approach_moving_closer).
body(r17_liquid_leaves_source, bouncy_source).
body(r17_liquid_leaves_source, dull_liquid).
body(r17_liquid_leaves_source, end_level).
body(r17_liquid_leaves_source, end_low).
body(r17_liquid_leaves_source, grippy_source).
body(r17_liquid_leaves_source, heavy_source).
body(r17_liquid_leaves_source, light_liquid).
body(r17_liquid_leaves_source, little_liquid).
body(r17_liquid_leaves_source, moderate_retreat).
body(r17_liquid_leaves_source, pour_centred).
body(r17_liquid_leaves_source, pour_mid_height).
body(r17_liquid_leaves_source, pour_offset_sideways).
body(r17_liquid_leaves_source, pour_upright).
body(r17_liquid_leaves_source, runny_liquid).
body(r17_liquid_leaves_source, slow_approach).
body(r17_liquid_leaves_source, start_below_rim).
body(r17_liquid_leaves_source, start_upright).
learned(r17_liquid_leaves_source).
provenance(r17_liquid_leaves_source, antecedent, a17).
provenance(r17_liquid_leaves_source, parent, none).
provenance(r17_liquid_leaves_source, simulations, 31).
provenance(r17_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r17_liquid_leaves_source, confidence_permille, 935).
provenance(r17_liquid_leaves_source, score_permille, 56).
provenance(r17_liquid_leaves_source, batches, 1).

rule(r17_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r17_liquid_enters_destination, approach_moving_closer).
body(r17_liquid_enters_destination, bouncy_source).
body(r17_liquid_enters_destination, dull_liquid).
body(r17_liquid_enters_destination, end_level).
body(r17_liquid_enters_destination, end_low).
body(r17_liquid_enters_destination, grippy_source).
body(r17_liquid_enters_destination, heavy_source).
body(r17_liquid_enters_destination, light_liquid).
body(r17_liquid_enters_destination, little_liquid).
body(r17_liquid_enters_destination, moderate_retreat).
body(r17_liquid_enters_destination, pour_centred).
body(r17_liquid_enters_destination, pour_mid_height).
body(r17_liquid_enters_destination, pour_offset_sideways).
body(r17_liquid_enters_destination, pour_upright).
body(r17_liquid_enters_destination, runny_liquid).
body(r17_liquid_enters_destination, slow_approach).
body(r17_liquid_enters_destination, start_below_rim).
body(r17_liquid_enters_destination, start_upright).
learned(r17_liquid_enters_destination).
provenance(r17_liquid_enters_destination, antecedent, a17).
provenance(r17_liquid_enters_destination, parent, none).
provenance(r17_liquid_enters_destination, simulations, 31).
provenance(r17_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r17_liquid_enters_destination, confidence_permille, 548).
provenance(r17_liquid_enters_destination, score_permille, 416).
provenance(r17_liquid_enters_destination, batches, 1).

rule(r17_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r17_liquid_remains_in_destination, approach_moving_closer).
body(r17_liquid_remains_in_destination, bouncy_source).
body(r17_liquid_remains_in_destination, dull_liquid).
body(r17_liquid_remains_in_destination, end_level).
body(r17_liquid_remains_in_destination, end_low).
body(r17_liquid_remains_in_destination, grippy_source).
body(r17_liquid_remains_in_destination, heavy_source).
body(r17_liquid_remains_in_destination, light_liquid).
body(r17_liquid_remains_in_destination, little_liquid).
body(r17_liquid_remains_in_destination, moderate_retreat).
body(r17_liquid_remains_in_destination, pour_centred).
body(r17_liquid_remains_in_destination, pour_mid_height).
body(r17_liquid_remains_in_destination, pour_offset_sideways).
body(r17_liquid_remains_in_destination, pour_upright).
body(r17_liquid_remains_in_destination, runny_liquid).
body(r17_liquid_remains_in_destination, slow_approach).
body(r17_liquid_remains_in_destination, start_below_rim).
body(r17_liquid_remains_in_destination, start_upright).
learned(r17_liquid_remains_in_destination).
provenance(r17_liquid_remains_in_destination, antecedent, a17).
provenance(r17_liquid_remains_in_destination, parent, none).
provenance(r17_liquid_remains_in_destination, simulations, 31).
provenance(r17_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r17_liquid_remains_in_destination, confidence_permille, 516).
provenance(r17_liquid_remains_in_destination, score_permille, 541).
provenance(r17_liquid_remains_in_destination, batches, 1).

rule(r17_no_spill, defeasible, no_spill).
body(r17_no_spill, approach_moving_closer).
body(r17_no_spill, bouncy_source).
body(r17_no_spill, dull_liquid).
body(r17_no_spill, end_level).
body(r17_no_spill, end_low).
body(r17_no_spill, grippy_source).
body(r17_no_spill, heavy_source).
body(r17_no_spill, light_liquid).
body(r17_no_spill, little_liquid).
body(r17_no_spill, moderate_retreat).
body(r17_no_spill, pour_centred).
body(r17_no_spill, pour_mid_height).
body(r17_no_spill, pour_offset_sideways).
body(r17_no_spill, pour_upright).
body(r17_no_spill, runny_liquid).
body(r17_no_spill, slow_approach).
body(r17_no_spill, start_below_rim).
body(r17_no_spill, start_upright).
learned(r17_no_spill).
provenance(r17_no_spill, antecedent, a17).
provenance(r17_no_spill, parent, none).
provenance(r17_no_spill, simulations, 31).
provenance(r17_no_spill, weight_mass_permille, 31000).
provenance(r17_no_spill, confidence_permille, 1000).
provenance(r17_no_spill, score_permille, 993).
provenance(r17_no_spill, batches, 1).

rule(r18_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r18_destination_still_approach, approach_raising).
body(r18_destination_still_approach, bouncy_destination).
body(r18_destination_still_approach, dull_source).
body(r18_destination_still_approach, end_near_rim).
body(r18_destination_still_approach, end_rolled).
body(r18_destination_still_approach, end_tilted_back).
body(r18_destination_still_approach, grippy_destination).
body(r18_destination_still_approach, grippy_source).
body(r18_destination_still_approach, heavy_liquid).
body(r18_destination_still_approach, light_source).
body(r18_destination_still_approach, pour_below_rim).
body(r18_destination_still_approach, pour_rolled).
body(r18_destination_still_approach, pour_slightly_tilted).
body(r18_destination_still_approach, retreat_lowering).
body(r18_destination_still_approach, slow_retreat).
body(r18_destination_still_approach, start_centred).
body(r18_destination_still_approach, start_upright).
learned(r18_destination_still_approach).
provenance(r18_destination_still_approach, antecedent, a18).
provenance(r18_destination_still_approach, parent, a14).
provenance(r18_destination_still_approach, simulations, 31).
provenance(r18_destination_still_approach, weight_mass_permille, 31000).
provenance(r18_destination_still_approach, confidence_permille, 968).
provenance(r18_destination_still_approach, score_permille, 34).
provenance(r18_destination_still_approach, batches, 1).

rule(r18_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r18_destination_still_retreat, approach_raising).
body(r18_destination_still_retreat, bouncy_destination).
body(r18_destination_still_retreat, dull_source).
body(r18_destination_still_retreat, end_near_rim).
body(r18_destination_still_retreat, end_rolled).
body(r18_destination_still_retreat, end_tilted_back).
body(r18_destination_still_retreat, grippy_destination).
body(r18_destination_still_retreat, grippy_source).
body(r18_destination_still_retreat, heavy_liquid).
body(r18_destination_still_retreat, light_source).
body(r18_destination_still_retreat, pour_below_rim).
body(r18_destination_still_retreat, pour_rolled).
body(r18_destination_still_retreat, pour_slightly_tilted).
body(r18_destination_still_retreat, retreat_lowering).
body(r18_destination_still_retreat, slow_retreat).
body(r18_destination_still_retreat, start_centred).
body(r18_destination_still_retreat, start_upright).
learned(r18_destination_still_retreat).
provenance(r18_destination_still_retreat, antecedent, a18).
provenance(r18_destination_still_retreat, parent, a14).
provenance(r18_destination_still_retreat, simulations, 31).
provenance(r18_destination_still_retreat, weight_mass_permille, 31000).
provenance(r18_destination_still_retreat, confidence_permille, 903).
provenance(r18_destination_still_retreat, score_permille, 92).
provenance(r18_destination_still_retreat, batches, 1).

rule(r18_destination_still_settle, defeasible, destination_still_settle).
body(r18_destination_still_settle, approach_raising).
body(r18_destination_still_settle, bouncy_destination).
body(r18_destination_still_settle, dull_source).
body(r18_destination_still_settle, end_near_rim).
body(r18_destination_still_settle, end_rolled).
body(r18_destination_still_settle, end_tilted_back).
body(r18_destination_still_settle, grippy_destination).
body(r18_destination_still_settle, grippy_source).
body(r18_destination_still_settle, heavy_liquid).
body(r18_destination_still_settle, light_source).
body(r18_destination_still_settle, pour_below_rim).
body(r18_destination_still_settle, pour_rolled).
body(r18_destination_still_settle, pour_slightly_tilted).
body(r18_destination_still_settle, retreat_lowering).
body(r18_destination_still_settle, slow_retreat).
body(r18_destination_still_settle, start_centred).
body(r18_destination_still_settle, start_upright).
learned(r18_destination_still_settle).
provenance(r18_destination_still_settle, antecedent, a18).
provenance(r18_destination_still_settle, parent, a14).
provenance(r18_destination_still_settle, simulations, 31).
provenance(r18_destination_still_settle, weight_mass_permille, 31000).
provenance(r18_destination_still_settle, confidence_permille, 645).
provenance(r18_destination_still_settle, score_permille, 618).
provenance(r18_destination_still_settle, batches, 1).

rule(r18_destination_upright, defeasible, destination_upright).
body(r18_destination_upright, approach_raising).
body(r18_destination_upright, bouncy_destination).
body(r18_destination_upright, dull_source).
body(r18_destination_upright, end_near_rim).
body(r18_destination_upright, end_rolled).
body(r18_destination_upright, end_tilted_back).
body(r18_destination_upright, grippy_destination).
body(r18_destination_upright, grippy_source).
body(r18_destination_upright, heavy_liquid).
body(r18_destination_upright, light_source).
body(r18_destination_upright, pour_below_rim).
body(r18_destination_upright, pour_rolled).
body(r18_destination_upright, pour_slightly_tilted).
body(r18_destination_upright, retreat_lowering).
body(r18_destination_upright, slow_retreat).
body(r18_destination_upright, start_centred).
body(r18_destination_upright, start_upright).
learned(r18_destination_upright).
provenance(r18_destination_upright, antecedent, a18).
provenance(r18_destination_upright, parent, a14).
provenance(r18_destination_upright, simulations, 31).
provenance(r18_destination_upright, weight_mass_permille, 31000).
provenance(r18_destination_upright, confidence_permille, 774).
provenance(r18_destination_upright, score_permille, 773).
provenance(r18_destination_upright, batches, 1).

rule(r18_source_clear, defeasible, neg(source_clear)).
body(r18_source_clear, approach_raising).
body(r18_source_clear, bouncy_destination).
body(r18_source_clear, dull_source).
body(r18_source_clear, end_near_rim).
body(r18_source_clear, end_rolled).
body(r18_source_clear, end_tilted_back).
body(r18_source_clear, grippy_destination).
body(r18_source_clear, grippy_source).
body(r18_source_clear, heavy_liquid).
body(r18_source_clear, light_source).
body(r18_source_clear, pour_below_rim).
body(r18_source_clear, pour_rolled).
body(r18_source_clear, pour_slightly_tilted).
body(r18_source_clear, retreat_lowering).
body(r18_source_clear, slow_retreat).
body(r18_source_clear, start_centred).
body(r18_source_clear, start_upright).
learned(r18_source_clear).
provenance(r18_source_clear, antecedent, a18).
provenance(r18_source_clear, parent, a14).
provenance(r18_source_clear, simulations, 31).
provenance(r18_source_clear, weight_mass_permille, 31000).
provenance(r18_source_clear, confidence_permille, 1000).
provenance(r18_source_clear, score_permille, 0).
provenance(r18_source_clear, batches, 1).

rule(r18_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r18_liquid_leaves_source, approach_raising).
body(r18_liquid_leaves_source, bouncy_destination).
body(r18_liquid_leaves_source, dull_source).
body(r18_liquid_leaves_source, end_near_rim).
body(r18_liquid_leaves_source, end_rolled).
body(r18_liquid_leaves_source, end_tilted_back).
body(r18_liquid_leaves_source, grippy_destination).
body(r18_liquid_leaves_source, grippy_source).
body(r18_liquid_leaves_source, heavy_liquid).
body(r18_liquid_leaves_source, light_source).
body(r18_liquid_leaves_source, pour_below_rim).
body(r18_liquid_leaves_source, pour_rolled).
body(r18_liquid_leaves_source, pour_slightly_tilted).
body(r18_liquid_leaves_source, retreat_lowering).
body(r18_liquid_leaves_source, slow_retreat).
body(r18_liquid_leaves_source, start_centred).
body(r18_liquid_leaves_source, start_upright).
learned(r18_liquid_leaves_source).
provenance(r18_liquid_leaves_source, antecedent, a18).
provenance(r18_liquid_leaves_source, parent, a14).
provenance(r18_liquid_leaves_source, simulations, 31).
provenance(r18_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r18_liquid_leaves_source, confidence_permille, 871).
provenance(r18_liquid_leaves_source, score_permille, 839).
provenance(r18_liquid_leaves_source, batches, 1).

rule(r18_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r18_liquid_enters_destination, approach_raising).
body(r18_liquid_enters_destination, bouncy_destination).
body(r18_liquid_enters_destination, dull_source).
body(r18_liquid_enters_destination, end_near_rim).
body(r18_liquid_enters_destination, end_rolled).
body(r18_liquid_enters_destination, end_tilted_back).
body(r18_liquid_enters_destination, grippy_destination).
body(r18_liquid_enters_destination, grippy_source).
body(r18_liquid_enters_destination, heavy_liquid).
body(r18_liquid_enters_destination, light_source).
body(r18_liquid_enters_destination, pour_below_rim).
body(r18_liquid_enters_destination, pour_rolled).
body(r18_liquid_enters_destination, pour_slightly_tilted).
body(r18_liquid_enters_destination, retreat_lowering).
body(r18_liquid_enters_destination, slow_retreat).
body(r18_liquid_enters_destination, start_centred).
body(r18_liquid_enters_destination, start_upright).
learned(r18_liquid_enters_destination).
provenance(r18_liquid_enters_destination, antecedent, a18).
provenance(r18_liquid_enters_destination, parent, a14).
provenance(r18_liquid_enters_destination, simulations, 31).
provenance(r18_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r18_liquid_enters_destination, confidence_permille, 1000).
provenance(r18_liquid_enters_destination, score_permille, 1000).
provenance(r18_liquid_enters_destination, batches, 1).

rule(r18_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r18_liquid_remains_in_destination, approach_raising).
body(r18_liquid_remains_in_destination, bouncy_destination).
body(r18_liquid_remains_in_destination, dull_source).
body(r18_liquid_remains_in_destination, end_near_rim).
body(r18_liquid_remains_in_destination, end_rolled).
body(r18_liquid_remains_in_destination, end_tilted_back).
body(r18_liquid_remains_in_destination, grippy_destination).
body(r18_liquid_remains_in_destination, grippy_source).
body(r18_liquid_remains_in_destination, heavy_liquid).
body(r18_liquid_remains_in_destination, light_source).
body(r18_liquid_remains_in_destination, pour_below_rim).
body(r18_liquid_remains_in_destination, pour_rolled).
body(r18_liquid_remains_in_destination, pour_slightly_tilted).
body(r18_liquid_remains_in_destination, retreat_lowering).
body(r18_liquid_remains_in_destination, slow_retreat).
body(r18_liquid_remains_in_destination, start_centred).
body(r18_liquid_remains_in_destination, start_upright).
learned(r18_liquid_remains_in_destination).
provenance(r18_liquid_remains_in_destination, antecedent, a18).
provenance(r18_liquid_remains_in_destination, parent, a14).
provenance(r18_liquid_remains_in_destination, simulations, 31).
provenance(r18_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r18_liquid_remains_in_destination, confidence_permille, 806).
provenance(r18_liquid_remains_in_destination, score_permille, 792).
provenance(r18_liquid_remains_in_destination, batches, 1).

rule(r18_no_spill, defeasible, no_spill).
body(r18_no_spill, approach_raising).
body(r18_no_spill, bouncy_destination).
body(r18_no_spill, dull_source).
body(r18_no_spill, end_near_rim).
body(r18_no_spill, end_rolled).
body(r18_no_spill, end_tilted_back).
body(r18_no_spill, grippy_destination).
body(r18_no_spill, grippy_source).
body(r18_no_spill, heavy_liquid).
body(r18_no_spill, light_source).
body(r18_no_spill, pour_below_rim).
body(r18_no_spill, pour_rolled).
body(r18_no_spill, pour_slightly_tilted).
body(r18_no_spill, retreat_lowering).
body(r18_no_spill, slow_retreat).
body(r18_no_spill, start_centred).
body(r18_no_spill, start_upright).
learned(r18_no_spill).
provenance(r18_no_spill, antecedent, a18).
provenance(r18_no_spill, parent, a14).
provenance(r18_no_spill, simulations, 31).
provenance(r18_no_spill, weight_mass_permille, 31000).
provenance(r18_no_spill, confidence_permille, 935).
provenance(r18_no_spill, score_permille, 952).
provenance(r18_no_spill, batches, 1).

rule(r19_destination_still_approach, defeasible, destination_still_approach).
body(r19_destination_still_approach, approach_lowering).
body(r19_destination_still_approach, dull_liquid).
body(r19_destination_still_approach, end_centred).
body(r19_destination_still_approach, end_upright).
body(r19_destination_still_approach, fast_approach).
body(r19_destination_still_approach, light_source).
body(r19_destination_still_approach, medium_destination).
body(r19_destination_still_approach, medium_liquid).
body(r19_destination_still_approach, much_liquid).
body(r19_destination_still_approach, pour_below_rim).
body(r19_destination_still_approach, pour_far_away).
body(r19_destination_still_approach, pour_steeply_tilted).
body(r19_destination_still_approach, retreat_lowering).
body(r19_destination_still_approach, runny_liquid).
body(r19_destination_still_approach, slippery_source).
body(r19_destination_still_approach, slow_retreat).
body(r19_destination_still_approach, start_far_away).
body(r19_destination_still_approach, start_tilted_back).
learned(r19_destination_still_approach).
provenance(r19_destination_still_approach, antecedent, a19).
provenance(r19_destination_still_approach, parent, a15).
provenance(r19_destination_still_approach, simulations, 31).
provenance(r19_destination_still_approach, weight_mass_permille, 31000).
provenance(r19_destination_still_approach, confidence_permille, 1000).
provenance(r19_destination_still_approach, score_permille, 993).
provenance(r19_destination_still_approach, batches, 1).
provenance(r19_destination_still_approach, followed, source_clear).
provenance(r19_destination_still_approach, direction, end_x).
provenance(r19_destination_still_approach, sign, down).

rule(r19_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r19_destination_still_retreat, approach_lowering).
body(r19_destination_still_retreat, dull_liquid).
body(r19_destination_still_retreat, end_centred).
body(r19_destination_still_retreat, end_upright).
body(r19_destination_still_retreat, fast_approach).
body(r19_destination_still_retreat, light_source).
body(r19_destination_still_retreat, medium_destination).
body(r19_destination_still_retreat, medium_liquid).
body(r19_destination_still_retreat, much_liquid).
body(r19_destination_still_retreat, pour_below_rim).
body(r19_destination_still_retreat, pour_far_away).
body(r19_destination_still_retreat, pour_steeply_tilted).
body(r19_destination_still_retreat, retreat_lowering).
body(r19_destination_still_retreat, runny_liquid).
body(r19_destination_still_retreat, slippery_source).
body(r19_destination_still_retreat, slow_retreat).
body(r19_destination_still_retreat, start_far_away).
body(r19_destination_still_retreat, start_tilted_back).
learned(r19_destination_still_retreat).
provenance(r19_destination_still_retreat, antecedent, a19).
provenance(r19_destination_still_retreat, parent, a15).
provenance(r19_destination_still_retreat, simulations, 31).
provenance(r19_destination_still_retreat, weight_mass_permille, 31000).
provenance(r19_destination_still_retreat, confidence_permille, 1000).
provenance(r19_destination_still_retreat, score_permille, 0).
provenance(r19_destination_still_retreat, batches, 1).
provenance(r19_destination_still_retreat, followed, source_clear).
provenance(r19_destination_still_retreat, direction, end_x).
provenance(r19_destination_still_retreat, sign, down).

rule(r19_destination_still_settle, defeasible, destination_still_settle).
body(r19_destination_still_settle, approach_lowering).
body(r19_destination_still_settle, dull_liquid).
body(r19_destination_still_settle, end_centred).
body(r19_destination_still_settle, end_upright).
body(r19_destination_still_settle, fast_approach).
body(r19_destination_still_settle, light_source).
body(r19_destination_still_settle, medium_destination).
body(r19_destination_still_settle, medium_liquid).
body(r19_destination_still_settle, much_liquid).
body(r19_destination_still_settle, pour_below_rim).
body(r19_destination_still_settle, pour_far_away).
body(r19_destination_still_settle, pour_steeply_tilted).
body(r19_destination_still_settle, retreat_lowering).
body(r19_destination_still_settle, runny_liquid).
body(r19_destination_still_settle, slippery_source).
body(r19_destination_still_settle, slow_retreat).
body(r19_destination_still_settle, start_far_away).
body(r19_destination_still_settle, start_tilted_back).
learned(r19_destination_still_settle).
provenance(r19_destination_still_settle, antecedent, a19).
provenance(r19_destination_still_settle, parent, a15).
provenance(r19_destination_still_settle, simulations, 31).
provenance(r19_destination_still_settle, weight_mass_permille, 31000).
provenance(r19_destination_still_settle, confidence_permille, 968).
provenance(r19_destination_still_settle, score_permille, 948).
provenance(r19_destination_still_settle, batches, 1).
provenance(r19_destination_still_settle, followed, source_clear).
provenance(r19_destination_still_settle, direction, end_x).
provenance(r19_destination_still_settle, sign, down).

rule(r19_destination_upright, defeasible, destination_upright).
body(r19_destination_upright, approach_lowering).
body(r19_destination_upright, dull_liquid).
body(r19_destination_upright, end_centred).
body(r19_destination_upright, end_upright).
body(r19_destination_upright, fast_approach).
body(r19_destination_upright, light_source).
body(r19_destination_upright, medium_destination).
body(r19_destination_upright, medium_liquid).
body(r19_destination_upright, much_liquid).
body(r19_destination_upright, pour_below_rim).
body(r19_destination_upright, pour_far_away).
body(r19_destination_upright, pour_steeply_tilted).
body(r19_destination_upright, retreat_lowering).
body(r19_destination_upright, runny_liquid).
body(r19_destination_upright, slippery_source).
body(r19_destination_upright, slow_retreat).
body(r19_destination_upright, start_far_away).
body(r19_destination_upright, start_tilted_back).
learned(r19_destination_upright).
provenance(r19_destination_upright, antecedent, a19).
provenance(r19_destination_upright, parent, a15).
provenance(r19_destination_upright, simulations, 31).
provenance(r19_destination_upright, weight_mass_permille, 31000).
provenance(r19_destination_upright, confidence_permille, 1000).
provenance(r19_destination_upright, score_permille, 999).
provenance(r19_destination_upright, batches, 1).
provenance(r19_destination_upright, followed, source_clear).
provenance(r19_destination_upright, direction, end_x).
provenance(r19_destination_upright, sign, down).

rule(r19_source_clear, defeasible, neg(source_clear)).
body(r19_source_clear, approach_lowering).
body(r19_source_clear, dull_liquid).
body(r19_source_clear, end_centred).
body(r19_source_clear, end_upright).
body(r19_source_clear, fast_approach).
body(r19_source_clear, light_source).
body(r19_source_clear, medium_destination).
body(r19_source_clear, medium_liquid).
body(r19_source_clear, much_liquid).
body(r19_source_clear, pour_below_rim).
body(r19_source_clear, pour_far_away).
body(r19_source_clear, pour_steeply_tilted).
body(r19_source_clear, retreat_lowering).
body(r19_source_clear, runny_liquid).
body(r19_source_clear, slippery_source).
body(r19_source_clear, slow_retreat).
body(r19_source_clear, start_far_away).
body(r19_source_clear, start_tilted_back).
learned(r19_source_clear).
provenance(r19_source_clear, antecedent, a19).
provenance(r19_source_clear, parent, a15).
provenance(r19_source_clear, simulations, 31).
provenance(r19_source_clear, weight_mass_permille, 31000).
provenance(r19_source_clear, confidence_permille, 1000).
provenance(r19_source_clear, score_permille, 2).
provenance(r19_source_clear, batches, 1).
provenance(r19_source_clear, followed, source_clear).
provenance(r19_source_clear, direction, end_x).
provenance(r19_source_clear, sign, down).

rule(r19_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r19_liquid_leaves_source, approach_lowering).
body(r19_liquid_leaves_source, dull_liquid).
body(r19_liquid_leaves_source, end_centred).
body(r19_liquid_leaves_source, end_upright).
body(r19_liquid_leaves_source, fast_approach).
body(r19_liquid_leaves_source, light_source).
body(r19_liquid_leaves_source, medium_destination).
body(r19_liquid_leaves_source, medium_liquid).
body(r19_liquid_leaves_source, much_liquid).
body(r19_liquid_leaves_source, pour_below_rim).
body(r19_liquid_leaves_source, pour_far_away).
body(r19_liquid_leaves_source, pour_steeply_tilted).
body(r19_liquid_leaves_source, retreat_lowering).
body(r19_liquid_leaves_source, runny_liquid).
body(r19_liquid_leaves_source, slippery_source).
body(r19_liquid_leaves_source, slow_retreat).
body(r19_liquid_leaves_source, start_far_away).
body(r19_liquid_leaves_source, start_tilted_back).
learned(r19_liquid_leaves_source).
provenance(r19_liquid_leaves_source, antecedent, a19).
provenance(r19_liquid_leaves_source, parent, a15).
provenance(r19_liquid_leaves_source, simulations, 31).
provenance(r19_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r19_liquid_leaves_source, confidence_permille, 1000).
provenance(r19_liquid_leaves_source, score_permille, 914).
provenance(r19_liquid_leaves_source, batches, 1).
provenance(r19_liquid_leaves_source, followed, source_clear).
provenance(r19_liquid_leaves_source, direction, end_x).
provenance(r19_liquid_leaves_source, sign, down).

rule(r19_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r19_liquid_enters_destination, approach_lowering).
body(r19_liquid_enters_destination, dull_liquid).
body(r19_liquid_enters_destination, end_centred).
body(r19_liquid_enters_destination, end_upright).
body(r19_liquid_enters_destination, fast_approach).
body(r19_liquid_enters_destination, light_source).
body(r19_liquid_enters_destination, medium_destination).
body(r19_liquid_enters_destination, medium_liquid).
body(r19_liquid_enters_destination, much_liquid).
body(r19_liquid_enters_destination, pour_below_rim).
body(r19_liquid_enters_destination, pour_far_away).
body(r19_liquid_enters_destination, pour_steeply_tilted).
body(r19_liquid_enters_destination, retreat_lowering).
body(r19_liquid_enters_destination, runny_liquid).
body(r19_liquid_enters_destination, slippery_source).
body(r19_liquid_enters_destination, slow_retreat).
body(r19_liquid_enters_destination, start_far_away).
body(r19_liquid_enters_destination, start_tilted_back).
learned(r19_liquid_enters_destination).
provenance(r19_liquid_enters_destination, antecedent, a19).
provenance(r19_liquid_enters_destination, parent, a15).
provenance(r19_liquid_enters_destination, simulations, 31).
provenance(r19_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r19_liquid_enters_destination, confidence_permille, 1000).
provenance(r19_liquid_enters_destination, score_permille, 2).
provenance(r19_liquid_enters_destination, batches, 1).
provenance(r19_liquid_enters_destination, followed, source_clear).
provenance(r19_liquid_enters_destination, direction, end_x).
provenance(r19_liquid_enters_destination, sign, down).

rule(r19_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r19_liquid_remains_in_destination, approach_lowering).
body(r19_liquid_remains_in_destination, dull_liquid).
body(r19_liquid_remains_in_destination, end_centred).
body(r19_liquid_remains_in_destination, end_upright).
body(r19_liquid_remains_in_destination, fast_approach).
body(r19_liquid_remains_in_destination, light_source).
body(r19_liquid_remains_in_destination, medium_destination).
body(r19_liquid_remains_in_destination, medium_liquid).
body(r19_liquid_remains_in_destination, much_liquid).
body(r19_liquid_remains_in_destination, pour_below_rim).
body(r19_liquid_remains_in_destination, pour_far_away).
body(r19_liquid_remains_in_destination, pour_steeply_tilted).
body(r19_liquid_remains_in_destination, retreat_lowering).
body(r19_liquid_remains_in_destination, runny_liquid).
body(r19_liquid_remains_in_destination, slippery_source).
body(r19_liquid_remains_in_destination, slow_retreat).
body(r19_liquid_remains_in_destination, start_far_away).
body(r19_liquid_remains_in_destination, start_tilted_back).
learned(r19_liquid_remains_in_destination).
provenance(r19_liquid_remains_in_destination, antecedent, a19).
provenance(r19_liquid_remains_in_destination, parent, a15).
provenance(r19_liquid_remains_in_destination, simulations, 31).
provenance(r19_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r19_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r19_liquid_remains_in_destination, score_permille, 1000).
provenance(r19_liquid_remains_in_destination, batches, 1).
provenance(r19_liquid_remains_in_destination, followed, source_clear).
provenance(r19_liquid_remains_in_destination, direction, end_x).
provenance(r19_liquid_remains_in_destination, sign, down).

rule(r19_no_spill, defeasible, neg(no_spill)).
body(r19_no_spill, approach_lowering).
body(r19_no_spill, dull_liquid).
body(r19_no_spill, end_centred).
body(r19_no_spill, end_upright).
body(r19_no_spill, fast_approach).
body(r19_no_spill, light_source).
body(r19_no_spill, medium_destination).
body(r19_no_spill, medium_liquid).
body(r19_no_spill, much_liquid).
body(r19_no_spill, pour_below_rim).
body(r19_no_spill, pour_far_away).
body(r19_no_spill, pour_steeply_tilted).
body(r19_no_spill, retreat_lowering).
body(r19_no_spill, runny_liquid).
body(r19_no_spill, slippery_source).
body(r19_no_spill, slow_retreat).
body(r19_no_spill, start_far_away).
body(r19_no_spill, start_tilted_back).
learned(r19_no_spill).
provenance(r19_no_spill, antecedent, a19).
provenance(r19_no_spill, parent, a15).
provenance(r19_no_spill, simulations, 31).
provenance(r19_no_spill, weight_mass_permille, 31000).
provenance(r19_no_spill, confidence_permille, 1000).
provenance(r19_no_spill, score_permille, 88).
provenance(r19_no_spill, batches, 1).
provenance(r19_no_spill, followed, source_clear).
provenance(r19_no_spill, direction, end_x).
provenance(r19_no_spill, sign, down).

rule(r20_destination_still_approach, defeasible, destination_still_approach).
body(r20_destination_still_approach, dull_liquid).
body(r20_destination_still_approach, end_below_rim).
body(r20_destination_still_approach, end_level).
body(r20_destination_still_approach, end_upside_down).
body(r20_destination_still_approach, fast_retreat).
body(r20_destination_still_approach, heavy_destination).
body(r20_destination_still_approach, heavy_liquid).
body(r20_destination_still_approach, little_liquid).
body(r20_destination_still_approach, moderate_approach).
body(r20_destination_still_approach, pour_low).
body(r20_destination_still_approach, pour_near_rim).
body(r20_destination_still_approach, pour_rolled).
body(r20_destination_still_approach, pour_upright).
body(r20_destination_still_approach, retreat_moving_closer).
body(r20_destination_still_approach, slippery_destination).
body(r20_destination_still_approach, start_below_rim).
body(r20_destination_still_approach, start_tilted_back).
body(r20_destination_still_approach, sticky_liquid).
learned(r20_destination_still_approach).
provenance(r20_destination_still_approach, antecedent, a20).
provenance(r20_destination_still_approach, parent, a8).
provenance(r20_destination_still_approach, simulations, 31).
provenance(r20_destination_still_approach, weight_mass_permille, 31000).
provenance(r20_destination_still_approach, confidence_permille, 871).
provenance(r20_destination_still_approach, score_permille, 872).
provenance(r20_destination_still_approach, batches, 1).

rule(r20_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r20_destination_still_retreat, dull_liquid).
body(r20_destination_still_retreat, end_below_rim).
body(r20_destination_still_retreat, end_level).
body(r20_destination_still_retreat, end_upside_down).
body(r20_destination_still_retreat, fast_retreat).
body(r20_destination_still_retreat, heavy_destination).
body(r20_destination_still_retreat, heavy_liquid).
body(r20_destination_still_retreat, little_liquid).
body(r20_destination_still_retreat, moderate_approach).
body(r20_destination_still_retreat, pour_low).
body(r20_destination_still_retreat, pour_near_rim).
body(r20_destination_still_retreat, pour_rolled).
body(r20_destination_still_retreat, pour_upright).
body(r20_destination_still_retreat, retreat_moving_closer).
body(r20_destination_still_retreat, slippery_destination).
body(r20_destination_still_retreat, start_below_rim).
body(r20_destination_still_retreat, start_tilted_back).
body(r20_destination_still_retreat, sticky_liquid).
learned(r20_destination_still_retreat).
provenance(r20_destination_still_retreat, antecedent, a20).
provenance(r20_destination_still_retreat, parent, a8).
provenance(r20_destination_still_retreat, simulations, 31).
provenance(r20_destination_still_retreat, weight_mass_permille, 31000).
provenance(r20_destination_still_retreat, confidence_permille, 1000).
provenance(r20_destination_still_retreat, score_permille, 0).
provenance(r20_destination_still_retreat, batches, 1).

rule(r20_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r20_destination_still_settle, dull_liquid).
body(r20_destination_still_settle, end_below_rim).
body(r20_destination_still_settle, end_level).
body(r20_destination_still_settle, end_upside_down).
body(r20_destination_still_settle, fast_retreat).
body(r20_destination_still_settle, heavy_destination).
body(r20_destination_still_settle, heavy_liquid).
body(r20_destination_still_settle, little_liquid).
body(r20_destination_still_settle, moderate_approach).
body(r20_destination_still_settle, pour_low).
body(r20_destination_still_settle, pour_near_rim).
body(r20_destination_still_settle, pour_rolled).
body(r20_destination_still_settle, pour_upright).
body(r20_destination_still_settle, retreat_moving_closer).
body(r20_destination_still_settle, slippery_destination).
body(r20_destination_still_settle, start_below_rim).
body(r20_destination_still_settle, start_tilted_back).
body(r20_destination_still_settle, sticky_liquid).
learned(r20_destination_still_settle).
provenance(r20_destination_still_settle, antecedent, a20).
provenance(r20_destination_still_settle, parent, a8).
provenance(r20_destination_still_settle, simulations, 31).
provenance(r20_destination_still_settle, weight_mass_permille, 31000).
provenance(r20_destination_still_settle, confidence_permille, 742).
provenance(r20_destination_still_settle, score_permille, 220).
provenance(r20_destination_still_settle, batches, 1).

rule(r20_destination_upright, defeasible, destination_upright).
body(r20_destination_upright, dull_liquid).
body(r20_destination_upright, end_below_rim).
body(r20_destination_upright, end_level).
body(r20_destination_upright, end_upside_down).
body(r20_destination_upright, fast_retreat).
body(r20_destination_upright, heavy_destination).
body(r20_destination_upright, heavy_liquid).
body(r20_destination_upright, little_liquid).
body(r20_destination_upright, moderate_approach).
body(r20_destination_upright, pour_low).
body(r20_destination_upright, pour_near_rim).
body(r20_destination_upright, pour_rolled).
body(r20_destination_upright, pour_upright).
body(r20_destination_upright, retreat_moving_closer).
body(r20_destination_upright, slippery_destination).
body(r20_destination_upright, start_below_rim).
body(r20_destination_upright, start_tilted_back).
body(r20_destination_upright, sticky_liquid).
learned(r20_destination_upright).
provenance(r20_destination_upright, antecedent, a20).
provenance(r20_destination_upright, parent, a8).
provenance(r20_destination_upright, simulations, 31).
provenance(r20_destination_upright, weight_mass_permille, 31000).
provenance(r20_destination_upright, confidence_permille, 645).
provenance(r20_destination_upright, score_permille, 682).
provenance(r20_destination_upright, batches, 1).

rule(r20_source_clear, defeasible, neg(source_clear)).
body(r20_source_clear, dull_liquid).
body(r20_source_clear, end_below_rim).
body(r20_source_clear, end_level).
body(r20_source_clear, end_upside_down).
body(r20_source_clear, fast_retreat).
body(r20_source_clear, heavy_destination).
body(r20_source_clear, heavy_liquid).
body(r20_source_clear, little_liquid).
body(r20_source_clear, moderate_approach).
body(r20_source_clear, pour_low).
body(r20_source_clear, pour_near_rim).
body(r20_source_clear, pour_rolled).
body(r20_source_clear, pour_upright).
body(r20_source_clear, retreat_moving_closer).
body(r20_source_clear, slippery_destination).
body(r20_source_clear, start_below_rim).
body(r20_source_clear, start_tilted_back).
body(r20_source_clear, sticky_liquid).
learned(r20_source_clear).
provenance(r20_source_clear, antecedent, a20).
provenance(r20_source_clear, parent, a8).
provenance(r20_source_clear, simulations, 31).
provenance(r20_source_clear, weight_mass_permille, 31000).
provenance(r20_source_clear, confidence_permille, 1000).
provenance(r20_source_clear, score_permille, 0).
provenance(r20_source_clear, batches, 1).

rule(r20_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r20_liquid_leaves_source, dull_liquid).
body(r20_liquid_leaves_source, end_below_rim).
body(r20_liquid_leaves_source, end_level).
body(r20_liquid_leaves_source, end_upside_down).
body(r20_liquid_leaves_source, fast_retreat).
body(r20_liquid_leaves_source, heavy_destination).
body(r20_liquid_leaves_source, heavy_liquid).
body(r20_liquid_leaves_source, little_liquid).
body(r20_liquid_leaves_source, moderate_approach).
body(r20_liquid_leaves_source, pour_low).
body(r20_liquid_leaves_source, pour_near_rim).
body(r20_liquid_leaves_source, pour_rolled).
body(r20_liquid_leaves_source, pour_upright).
body(r20_liquid_leaves_source, retreat_moving_closer).
body(r20_liquid_leaves_source, slippery_destination).
body(r20_liquid_leaves_source, start_below_rim).
body(r20_liquid_leaves_source, start_tilted_back).
body(r20_liquid_leaves_source, sticky_liquid).
learned(r20_liquid_leaves_source).
provenance(r20_liquid_leaves_source, antecedent, a20).
provenance(r20_liquid_leaves_source, parent, a8).
provenance(r20_liquid_leaves_source, simulations, 31).
provenance(r20_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r20_liquid_leaves_source, confidence_permille, 935).
provenance(r20_liquid_leaves_source, score_permille, 896).
provenance(r20_liquid_leaves_source, batches, 1).

rule(r20_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r20_liquid_enters_destination, dull_liquid).
body(r20_liquid_enters_destination, end_below_rim).
body(r20_liquid_enters_destination, end_level).
body(r20_liquid_enters_destination, end_upside_down).
body(r20_liquid_enters_destination, fast_retreat).
body(r20_liquid_enters_destination, heavy_destination).
body(r20_liquid_enters_destination, heavy_liquid).
body(r20_liquid_enters_destination, little_liquid).
body(r20_liquid_enters_destination, moderate_approach).
body(r20_liquid_enters_destination, pour_low).
body(r20_liquid_enters_destination, pour_near_rim).
body(r20_liquid_enters_destination, pour_rolled).
body(r20_liquid_enters_destination, pour_upright).
body(r20_liquid_enters_destination, retreat_moving_closer).
body(r20_liquid_enters_destination, slippery_destination).
body(r20_liquid_enters_destination, start_below_rim).
body(r20_liquid_enters_destination, start_tilted_back).
body(r20_liquid_enters_destination, sticky_liquid).
learned(r20_liquid_enters_destination).
provenance(r20_liquid_enters_destination, antecedent, a20).
provenance(r20_liquid_enters_destination, parent, a8).
provenance(r20_liquid_enters_destination, simulations, 31).
provenance(r20_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r20_liquid_enters_destination, confidence_permille, 581).
provenance(r20_liquid_enters_destination, score_permille, 585).
provenance(r20_liquid_enters_destination, batches, 1).

rule(r20_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r20_liquid_remains_in_destination, dull_liquid).
body(r20_liquid_remains_in_destination, end_below_rim).
body(r20_liquid_remains_in_destination, end_level).
body(r20_liquid_remains_in_destination, end_upside_down).
body(r20_liquid_remains_in_destination, fast_retreat).
body(r20_liquid_remains_in_destination, heavy_destination).
body(r20_liquid_remains_in_destination, heavy_liquid).
body(r20_liquid_remains_in_destination, little_liquid).
body(r20_liquid_remains_in_destination, moderate_approach).
body(r20_liquid_remains_in_destination, pour_low).
body(r20_liquid_remains_in_destination, pour_near_rim).
body(r20_liquid_remains_in_destination, pour_rolled).
body(r20_liquid_remains_in_destination, pour_upright).
body(r20_liquid_remains_in_destination, retreat_moving_closer).
body(r20_liquid_remains_in_destination, slippery_destination).
body(r20_liquid_remains_in_destination, start_below_rim).
body(r20_liquid_remains_in_destination, start_tilted_back).
body(r20_liquid_remains_in_destination, sticky_liquid).
learned(r20_liquid_remains_in_destination).
provenance(r20_liquid_remains_in_destination, antecedent, a20).
provenance(r20_liquid_remains_in_destination, parent, a8).
provenance(r20_liquid_remains_in_destination, simulations, 31).
provenance(r20_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r20_liquid_remains_in_destination, confidence_permille, 548).
provenance(r20_liquid_remains_in_destination, score_permille, 544).
provenance(r20_liquid_remains_in_destination, batches, 1).

rule(r20_no_spill, defeasible, neg(no_spill)).
body(r20_no_spill, dull_liquid).
body(r20_no_spill, end_below_rim).
body(r20_no_spill, end_level).
body(r20_no_spill, end_upside_down).
body(r20_no_spill, fast_retreat).
body(r20_no_spill, heavy_destination).
body(r20_no_spill, heavy_liquid).
body(r20_no_spill, little_liquid).
body(r20_no_spill, moderate_approach).
body(r20_no_spill, pour_low).
body(r20_no_spill, pour_near_rim).
body(r20_no_spill, pour_rolled).
body(r20_no_spill, pour_upright).
body(r20_no_spill, retreat_moving_closer).
body(r20_no_spill, slippery_destination).
body(r20_no_spill, start_below_rim).
body(r20_no_spill, start_tilted_back).
body(r20_no_spill, sticky_liquid).
learned(r20_no_spill).
provenance(r20_no_spill, antecedent, a20).
provenance(r20_no_spill, parent, a8).
provenance(r20_no_spill, simulations, 31).
provenance(r20_no_spill, weight_mass_permille, 31000).
provenance(r20_no_spill, confidence_permille, 774).
provenance(r20_no_spill, score_permille, 257).
provenance(r20_no_spill, batches, 1).

rule(r21_destination_still_approach, defeasible, destination_still_approach).
body(r21_destination_still_approach, dull_destination).
body(r21_destination_still_approach, end_level).
body(r21_destination_still_approach, end_low).
body(r21_destination_still_approach, end_steeply_tilted).
body(r21_destination_still_approach, grippy_destination).
body(r21_destination_still_approach, heavy_liquid).
body(r21_destination_still_approach, light_destination).
body(r21_destination_still_approach, light_source).
body(r21_destination_still_approach, pour_far_away).
body(r21_destination_still_approach, pour_low).
body(r21_destination_still_approach, pour_rolled).
body(r21_destination_still_approach, pour_steeply_tilted).
body(r21_destination_still_approach, retreat_moving_closer).
body(r21_destination_still_approach, slow_approach).
body(r21_destination_still_approach, slow_retreat).
body(r21_destination_still_approach, start_below_rim).
body(r21_destination_still_approach, start_slightly_tilted).
body(r21_destination_still_approach, sticky_liquid).
learned(r21_destination_still_approach).
provenance(r21_destination_still_approach, antecedent, a21).
provenance(r21_destination_still_approach, parent, none).
provenance(r21_destination_still_approach, simulations, 31).
provenance(r21_destination_still_approach, weight_mass_permille, 31000).
provenance(r21_destination_still_approach, confidence_permille, 903).
provenance(r21_destination_still_approach, score_permille, 894).
provenance(r21_destination_still_approach, batches, 1).

rule(r21_destination_still_retreat, defeasible, destination_still_retreat).
body(r21_destination_still_retreat, dull_destination).
body(r21_destination_still_retreat, end_level).
body(r21_destination_still_retreat, end_low).
body(r21_destination_still_retreat, end_steeply_tilted).
body(r21_destination_still_retreat, grippy_destination).
body(r21_destination_still_retreat, heavy_liquid).
body(r21_destination_still_retreat, light_destination).
body(r21_destination_still_retreat, light_source).
body(r21_destination_still_retreat, pour_far_away).
body(r21_destination_still_retreat, pour_low).
body(r21_destination_still_retreat, pour_rolled).
body(r21_destination_still_retreat, pour_steeply_tilted).
body(r21_destination_still_retreat, retreat_moving_closer).
body(r21_destination_still_retreat, slow_approach).
body(r21_destination_still_retreat, slow_retreat).
body(r21_destination_still_retreat, start_below_rim).
body(r21_destination_still_retreat, start_slightly_tilted).
body(r21_destination_still_retreat, sticky_liquid).
learned(r21_destination_still_retreat).
provenance(r21_destination_still_retreat, antecedent, a21).
provenance(r21_destination_still_retreat, parent, none).
provenance(r21_destination_still_retreat, simulations, 31).
provenance(r21_destination_still_retreat, weight_mass_permille, 31000).
provenance(r21_destination_still_retreat, confidence_permille, 774).
provenance(r21_destination_still_retreat, score_permille, 799).
provenance(r21_destination_still_retreat, batches, 1).

rule(r21_destination_still_settle, defeasible, destination_still_settle).
body(r21_destination_still_settle, dull_destination).
body(r21_destination_still_settle, end_level).
body(r21_destination_still_settle, end_low).
body(r21_destination_still_settle, end_steeply_tilted).
body(r21_destination_still_settle, grippy_destination).
body(r21_destination_still_settle, heavy_liquid).
body(r21_destination_still_settle, light_destination).
body(r21_destination_still_settle, light_source).
body(r21_destination_still_settle, pour_far_away).
body(r21_destination_still_settle, pour_low).
body(r21_destination_still_settle, pour_rolled).
body(r21_destination_still_settle, pour_steeply_tilted).
body(r21_destination_still_settle, retreat_moving_closer).
body(r21_destination_still_settle, slow_approach).
body(r21_destination_still_settle, slow_retreat).
body(r21_destination_still_settle, start_below_rim).
body(r21_destination_still_settle, start_slightly_tilted).
body(r21_destination_still_settle, sticky_liquid).
learned(r21_destination_still_settle).
provenance(r21_destination_still_settle, antecedent, a21).
provenance(r21_destination_still_settle, parent, none).
provenance(r21_destination_still_settle, simulations, 31).
provenance(r21_destination_still_settle, weight_mass_permille, 31000).
provenance(r21_destination_still_settle, confidence_permille, 968).
provenance(r21_destination_still_settle, score_permille, 969).
provenance(r21_destination_still_settle, batches, 1).

rule(r21_destination_upright, defeasible, destination_upright).
body(r21_destination_upright, dull_destination).
body(r21_destination_upright, end_level).
body(r21_destination_upright, end_low).
body(r21_destination_upright, end_steeply_tilted).
body(r21_destination_upright, grippy_destination).
body(r21_destination_upright, heavy_liquid).
body(r21_destination_upright, light_destination).
body(r21_destination_upright, light_source).
body(r21_destination_upright, pour_far_away).
body(r21_destination_upright, pour_low).
body(r21_destination_upright, pour_rolled).
body(r21_destination_upright, pour_steeply_tilted).
body(r21_destination_upright, retreat_moving_closer).
body(r21_destination_upright, slow_approach).
body(r21_destination_upright, slow_retreat).
body(r21_destination_upright, start_below_rim).
body(r21_destination_upright, start_slightly_tilted).
body(r21_destination_upright, sticky_liquid).
learned(r21_destination_upright).
provenance(r21_destination_upright, antecedent, a21).
provenance(r21_destination_upright, parent, none).
provenance(r21_destination_upright, simulations, 31).
provenance(r21_destination_upright, weight_mass_permille, 31000).
provenance(r21_destination_upright, confidence_permille, 968).
provenance(r21_destination_upright, score_permille, 961).
provenance(r21_destination_upright, batches, 1).

rule(r21_source_clear, defeasible, source_clear).
body(r21_source_clear, dull_destination).
body(r21_source_clear, end_level).
body(r21_source_clear, end_low).
body(r21_source_clear, end_steeply_tilted).
body(r21_source_clear, grippy_destination).
body(r21_source_clear, heavy_liquid).
body(r21_source_clear, light_destination).
body(r21_source_clear, light_source).
body(r21_source_clear, pour_far_away).
body(r21_source_clear, pour_low).
body(r21_source_clear, pour_rolled).
body(r21_source_clear, pour_steeply_tilted).
body(r21_source_clear, retreat_moving_closer).
body(r21_source_clear, slow_approach).
body(r21_source_clear, slow_retreat).
body(r21_source_clear, start_below_rim).
body(r21_source_clear, start_slightly_tilted).
body(r21_source_clear, sticky_liquid).
learned(r21_source_clear).
provenance(r21_source_clear, antecedent, a21).
provenance(r21_source_clear, parent, none).
provenance(r21_source_clear, simulations, 31).
provenance(r21_source_clear, weight_mass_permille, 31000).
provenance(r21_source_clear, confidence_permille, 774).
provenance(r21_source_clear, score_permille, 744).
provenance(r21_source_clear, batches, 1).

rule(r21_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r21_liquid_leaves_source, dull_destination).
body(r21_liquid_leaves_source, end_level).
body(r21_liquid_leaves_source, end_low).
body(r21_liquid_leaves_source, end_steeply_tilted).
body(r21_liquid_leaves_source, grippy_destination).
body(r21_liquid_leaves_source, heavy_liquid).
body(r21_liquid_leaves_source, light_destination).
body(r21_liquid_leaves_source, light_source).
body(r21_liquid_leaves_source, pour_far_away).
body(r21_liquid_leaves_source, pour_low).
body(r21_liquid_leaves_source, pour_rolled).
body(r21_liquid_leaves_source, pour_steeply_tilted).
body(r21_liquid_leaves_source, retreat_moving_closer).
body(r21_liquid_leaves_source, slow_approach).
body(r21_liquid_leaves_source, slow_retreat).
body(r21_liquid_leaves_source, start_below_rim).
body(r21_liquid_leaves_source, start_slightly_tilted).
body(r21_liquid_leaves_source, sticky_liquid).
learned(r21_liquid_leaves_source).
provenance(r21_liquid_leaves_source, antecedent, a21).
provenance(r21_liquid_leaves_source, parent, none).
provenance(r21_liquid_leaves_source, simulations, 31).
provenance(r21_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r21_liquid_leaves_source, confidence_permille, 968).
provenance(r21_liquid_leaves_source, score_permille, 933).
provenance(r21_liquid_leaves_source, batches, 1).

rule(r21_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r21_liquid_enters_destination, dull_destination).
body(r21_liquid_enters_destination, end_level).
body(r21_liquid_enters_destination, end_low).
body(r21_liquid_enters_destination, end_steeply_tilted).
body(r21_liquid_enters_destination, grippy_destination).
body(r21_liquid_enters_destination, heavy_liquid).
body(r21_liquid_enters_destination, light_destination).
body(r21_liquid_enters_destination, light_source).
body(r21_liquid_enters_destination, pour_far_away).
body(r21_liquid_enters_destination, pour_low).
body(r21_liquid_enters_destination, pour_rolled).
body(r21_liquid_enters_destination, pour_steeply_tilted).
body(r21_liquid_enters_destination, retreat_moving_closer).
body(r21_liquid_enters_destination, slow_approach).
body(r21_liquid_enters_destination, slow_retreat).
body(r21_liquid_enters_destination, start_below_rim).
body(r21_liquid_enters_destination, start_slightly_tilted).
body(r21_liquid_enters_destination, sticky_liquid).
learned(r21_liquid_enters_destination).
provenance(r21_liquid_enters_destination, antecedent, a21).
provenance(r21_liquid_enters_destination, parent, none).
provenance(r21_liquid_enters_destination, simulations, 31).
provenance(r21_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r21_liquid_enters_destination, confidence_permille, 1000).
provenance(r21_liquid_enters_destination, score_permille, 3).
provenance(r21_liquid_enters_destination, batches, 1).

rule(r21_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r21_liquid_remains_in_destination, dull_destination).
body(r21_liquid_remains_in_destination, end_level).
body(r21_liquid_remains_in_destination, end_low).
body(r21_liquid_remains_in_destination, end_steeply_tilted).
body(r21_liquid_remains_in_destination, grippy_destination).
body(r21_liquid_remains_in_destination, heavy_liquid).
body(r21_liquid_remains_in_destination, light_destination).
body(r21_liquid_remains_in_destination, light_source).
body(r21_liquid_remains_in_destination, pour_far_away).
body(r21_liquid_remains_in_destination, pour_low).
body(r21_liquid_remains_in_destination, pour_rolled).
body(r21_liquid_remains_in_destination, pour_steeply_tilted).
body(r21_liquid_remains_in_destination, retreat_moving_closer).
body(r21_liquid_remains_in_destination, slow_approach).
body(r21_liquid_remains_in_destination, slow_retreat).
body(r21_liquid_remains_in_destination, start_below_rim).
body(r21_liquid_remains_in_destination, start_slightly_tilted).
body(r21_liquid_remains_in_destination, sticky_liquid).
learned(r21_liquid_remains_in_destination).
provenance(r21_liquid_remains_in_destination, antecedent, a21).
provenance(r21_liquid_remains_in_destination, parent, none).
provenance(r21_liquid_remains_in_destination, simulations, 31).
provenance(r21_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r21_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r21_liquid_remains_in_destination, score_permille, 998).
provenance(r21_liquid_remains_in_destination, batches, 1).

rule(r21_no_spill, defeasible, neg(no_spill)).
body(r21_no_spill, dull_destination).
body(r21_no_spill, end_level).
body(r21_no_spill, end_low).
body(r21_no_spill, end_steeply_tilted).
body(r21_no_spill, grippy_destination).
body(r21_no_spill, heavy_liquid).
body(r21_no_spill, light_destination).
body(r21_no_spill, light_source).
body(r21_no_spill, pour_far_away).
body(r21_no_spill, pour_low).
body(r21_no_spill, pour_rolled).
body(r21_no_spill, pour_steeply_tilted).
body(r21_no_spill, retreat_moving_closer).
body(r21_no_spill, slow_approach).
body(r21_no_spill, slow_retreat).
body(r21_no_spill, start_below_rim).
body(r21_no_spill, start_slightly_tilted).
body(r21_no_spill, sticky_liquid).
learned(r21_no_spill).
provenance(r21_no_spill, antecedent, a21).
provenance(r21_no_spill, parent, none).
provenance(r21_no_spill, simulations, 31).
provenance(r21_no_spill, weight_mass_permille, 31000).
provenance(r21_no_spill, confidence_permille, 968).
provenance(r21_no_spill, score_permille, 69).
provenance(r21_no_spill, batches, 1).

rule(r22_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r22_destination_still_approach, approach_raising).
body(r22_destination_still_approach, dull_destination).
body(r22_destination_still_approach, dull_liquid).
body(r22_destination_still_approach, end_centred).
body(r22_destination_still_approach, end_half_tilted).
body(r22_destination_still_approach, end_mid_height).
body(r22_destination_still_approach, grippy_destination).
body(r22_destination_still_approach, heavy_liquid).
body(r22_destination_still_approach, heavy_source).
body(r22_destination_still_approach, moderate_approach).
body(r22_destination_still_approach, pour_below_rim).
body(r22_destination_still_approach, pour_level).
body(r22_destination_still_approach, pour_offset_sideways).
body(r22_destination_still_approach, pour_slightly_tilted).
body(r22_destination_still_approach, slow_retreat).
body(r22_destination_still_approach, start_centred).
learned(r22_destination_still_approach).
provenance(r22_destination_still_approach, antecedent, a22).
provenance(r22_destination_still_approach, parent, none).
provenance(r22_destination_still_approach, simulations, 31).
provenance(r22_destination_still_approach, weight_mass_permille, 31000).
provenance(r22_destination_still_approach, confidence_permille, 1000).
provenance(r22_destination_still_approach, score_permille, 0).
provenance(r22_destination_still_approach, batches, 1).

rule(r22_destination_still_retreat, defeasible, destination_still_retreat).
body(r22_destination_still_retreat, approach_raising).
body(r22_destination_still_retreat, dull_destination).
body(r22_destination_still_retreat, dull_liquid).
body(r22_destination_still_retreat, end_centred).
body(r22_destination_still_retreat, end_half_tilted).
body(r22_destination_still_retreat, end_mid_height).
body(r22_destination_still_retreat, grippy_destination).
body(r22_destination_still_retreat, heavy_liquid).
body(r22_destination_still_retreat, heavy_source).
body(r22_destination_still_retreat, moderate_approach).
body(r22_destination_still_retreat, pour_below_rim).
body(r22_destination_still_retreat, pour_level).
body(r22_destination_still_retreat, pour_offset_sideways).
body(r22_destination_still_retreat, pour_slightly_tilted).
body(r22_destination_still_retreat, slow_retreat).
body(r22_destination_still_retreat, start_centred).
learned(r22_destination_still_retreat).
provenance(r22_destination_still_retreat, antecedent, a22).
provenance(r22_destination_still_retreat, parent, none).
provenance(r22_destination_still_retreat, simulations, 31).
provenance(r22_destination_still_retreat, weight_mass_permille, 31000).
provenance(r22_destination_still_retreat, confidence_permille, 645).
provenance(r22_destination_still_retreat, score_permille, 642).
provenance(r22_destination_still_retreat, batches, 1).

rule(r22_destination_still_settle, defeasible, destination_still_settle).
body(r22_destination_still_settle, approach_raising).
body(r22_destination_still_settle, dull_destination).
body(r22_destination_still_settle, dull_liquid).
body(r22_destination_still_settle, end_centred).
body(r22_destination_still_settle, end_half_tilted).
body(r22_destination_still_settle, end_mid_height).
body(r22_destination_still_settle, grippy_destination).
body(r22_destination_still_settle, heavy_liquid).
body(r22_destination_still_settle, heavy_source).
body(r22_destination_still_settle, moderate_approach).
body(r22_destination_still_settle, pour_below_rim).
body(r22_destination_still_settle, pour_level).
body(r22_destination_still_settle, pour_offset_sideways).
body(r22_destination_still_settle, pour_slightly_tilted).
body(r22_destination_still_settle, slow_retreat).
body(r22_destination_still_settle, start_centred).
learned(r22_destination_still_settle).
provenance(r22_destination_still_settle, antecedent, a22).
provenance(r22_destination_still_settle, parent, none).
provenance(r22_destination_still_settle, simulations, 31).
provenance(r22_destination_still_settle, weight_mass_permille, 31000).
provenance(r22_destination_still_settle, confidence_permille, 1000).
provenance(r22_destination_still_settle, score_permille, 999).
provenance(r22_destination_still_settle, batches, 1).

rule(r22_destination_upright, defeasible, destination_upright).
body(r22_destination_upright, approach_raising).
body(r22_destination_upright, dull_destination).
body(r22_destination_upright, dull_liquid).
body(r22_destination_upright, end_centred).
body(r22_destination_upright, end_half_tilted).
body(r22_destination_upright, end_mid_height).
body(r22_destination_upright, grippy_destination).
body(r22_destination_upright, heavy_liquid).
body(r22_destination_upright, heavy_source).
body(r22_destination_upright, moderate_approach).
body(r22_destination_upright, pour_below_rim).
body(r22_destination_upright, pour_level).
body(r22_destination_upright, pour_offset_sideways).
body(r22_destination_upright, pour_slightly_tilted).
body(r22_destination_upright, slow_retreat).
body(r22_destination_upright, start_centred).
learned(r22_destination_upright).
provenance(r22_destination_upright, antecedent, a22).
provenance(r22_destination_upright, parent, none).
provenance(r22_destination_upright, simulations, 31).
provenance(r22_destination_upright, weight_mass_permille, 31000).
provenance(r22_destination_upright, confidence_permille, 1000).
provenance(r22_destination_upright, score_permille, 1000).
provenance(r22_destination_upright, batches, 1).

rule(r22_source_clear, defeasible, neg(source_clear)).
body(r22_source_clear, approach_raising).
body(r22_source_clear, dull_destination).
body(r22_source_clear, dull_liquid).
body(r22_source_clear, end_centred).
body(r22_source_clear, end_half_tilted).
body(r22_source_clear, end_mid_height).
body(r22_source_clear, grippy_destination).
body(r22_source_clear, heavy_liquid).
body(r22_source_clear, heavy_source).
body(r22_source_clear, moderate_approach).
body(r22_source_clear, pour_below_rim).
body(r22_source_clear, pour_level).
body(r22_source_clear, pour_offset_sideways).
body(r22_source_clear, pour_slightly_tilted).
body(r22_source_clear, slow_retreat).
body(r22_source_clear, start_centred).
learned(r22_source_clear).
provenance(r22_source_clear, antecedent, a22).
provenance(r22_source_clear, parent, none).
provenance(r22_source_clear, simulations, 31).
provenance(r22_source_clear, weight_mass_permille, 31000).
provenance(r22_source_clear, confidence_permille, 1000).
provenance(r22_source_clear, score_permille, 0).
provenance(r22_source_clear, batches, 1).

rule(r22_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r22_liquid_leaves_source, approach_raising).
body(r22_liquid_leaves_source, dull_destination).
body(r22_liquid_leaves_source, dull_liquid).
body(r22_liquid_leaves_source, end_centred).
body(r22_liquid_leaves_source, end_half_tilted).
body(r22_liquid_leaves_source, end_mid_height).
body(r22_liquid_leaves_source, grippy_destination).
body(r22_liquid_leaves_source, heavy_liquid).
body(r22_liquid_leaves_source, heavy_source).
body(r22_liquid_leaves_source, moderate_approach).
body(r22_liquid_leaves_source, pour_below_rim).
body(r22_liquid_leaves_source, pour_level).
body(r22_liquid_leaves_source, pour_offset_sideways).
body(r22_liquid_leaves_source, pour_slightly_tilted).
body(r22_liquid_leaves_source, slow_retreat).
body(r22_liquid_leaves_source, start_centred).
learned(r22_liquid_leaves_source).
provenance(r22_liquid_leaves_source, antecedent, a22).
provenance(r22_liquid_leaves_source, parent, none).
provenance(r22_liquid_leaves_source, simulations, 31).
provenance(r22_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r22_liquid_leaves_source, confidence_permille, 968).
provenance(r22_liquid_leaves_source, score_permille, 64).
provenance(r22_liquid_leaves_source, batches, 1).

rule(r22_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r22_liquid_enters_destination, approach_raising).
body(r22_liquid_enters_destination, dull_destination).
body(r22_liquid_enters_destination, dull_liquid).
body(r22_liquid_enters_destination, end_centred).
body(r22_liquid_enters_destination, end_half_tilted).
body(r22_liquid_enters_destination, end_mid_height).
body(r22_liquid_enters_destination, grippy_destination).
body(r22_liquid_enters_destination, heavy_liquid).
body(r22_liquid_enters_destination, heavy_source).
body(r22_liquid_enters_destination, moderate_approach).
body(r22_liquid_enters_destination, pour_below_rim).
body(r22_liquid_enters_destination, pour_level).
body(r22_liquid_enters_destination, pour_offset_sideways).
body(r22_liquid_enters_destination, pour_slightly_tilted).
body(r22_liquid_enters_destination, slow_retreat).
body(r22_liquid_enters_destination, start_centred).
learned(r22_liquid_enters_destination).
provenance(r22_liquid_enters_destination, antecedent, a22).
provenance(r22_liquid_enters_destination, parent, none).
provenance(r22_liquid_enters_destination, simulations, 31).
provenance(r22_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r22_liquid_enters_destination, confidence_permille, 1000).
provenance(r22_liquid_enters_destination, score_permille, 994).
provenance(r22_liquid_enters_destination, batches, 1).

rule(r22_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r22_liquid_remains_in_destination, approach_raising).
body(r22_liquid_remains_in_destination, dull_destination).
body(r22_liquid_remains_in_destination, dull_liquid).
body(r22_liquid_remains_in_destination, end_centred).
body(r22_liquid_remains_in_destination, end_half_tilted).
body(r22_liquid_remains_in_destination, end_mid_height).
body(r22_liquid_remains_in_destination, grippy_destination).
body(r22_liquid_remains_in_destination, heavy_liquid).
body(r22_liquid_remains_in_destination, heavy_source).
body(r22_liquid_remains_in_destination, moderate_approach).
body(r22_liquid_remains_in_destination, pour_below_rim).
body(r22_liquid_remains_in_destination, pour_level).
body(r22_liquid_remains_in_destination, pour_offset_sideways).
body(r22_liquid_remains_in_destination, pour_slightly_tilted).
body(r22_liquid_remains_in_destination, slow_retreat).
body(r22_liquid_remains_in_destination, start_centred).
learned(r22_liquid_remains_in_destination).
provenance(r22_liquid_remains_in_destination, antecedent, a22).
provenance(r22_liquid_remains_in_destination, parent, none).
provenance(r22_liquid_remains_in_destination, simulations, 31).
provenance(r22_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r22_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r22_liquid_remains_in_destination, score_permille, 18).
provenance(r22_liquid_remains_in_destination, batches, 1).

rule(r22_no_spill, defeasible, no_spill).
body(r22_no_spill, approach_raising).
body(r22_no_spill, dull_destination).
body(r22_no_spill, dull_liquid).
body(r22_no_spill, end_centred).
body(r22_no_spill, end_half_tilted).
body(r22_no_spill, end_mid_height).
body(r22_no_spill, grippy_destination).
body(r22_no_spill, heavy_liquid).
body(r22_no_spill, heavy_source).
body(r22_no_spill, moderate_approach).
body(r22_no_spill, pour_below_rim).
body(r22_no_spill, pour_level).
body(r22_no_spill, pour_offset_sideways).
body(r22_no_spill, pour_slightly_tilted).
body(r22_no_spill, slow_retreat).
body(r22_no_spill, start_centred).
learned(r22_no_spill).
provenance(r22_no_spill, antecedent, a22).
provenance(r22_no_spill, parent, none).
provenance(r22_no_spill, simulations, 31).
provenance(r22_no_spill, weight_mass_permille, 31000).
provenance(r22_no_spill, confidence_permille, 1000).
provenance(r22_no_spill, score_permille, 954).
provenance(r22_no_spill, batches, 1).

rule(r23_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r23_destination_still_approach, approach_moving_away).
body(r23_destination_still_approach, bouncy_destination).
body(r23_destination_still_approach, bouncy_liquid).
body(r23_destination_still_approach, dull_source).
body(r23_destination_still_approach, end_centred).
body(r23_destination_still_approach, end_level).
body(r23_destination_still_approach, end_low).
body(r23_destination_still_approach, end_upside_down).
body(r23_destination_still_approach, fast_retreat).
body(r23_destination_still_approach, heavy_source).
body(r23_destination_still_approach, light_destination).
body(r23_destination_still_approach, medium_liquid).
body(r23_destination_still_approach, pour_level).
body(r23_destination_still_approach, pour_offset_sideways).
body(r23_destination_still_approach, pour_to_side).
body(r23_destination_still_approach, pour_very_high).
body(r23_destination_still_approach, slippery_destination).
body(r23_destination_still_approach, slippery_source).
body(r23_destination_still_approach, start_below_rim).
body(r23_destination_still_approach, start_upright).
body(r23_destination_still_approach, very_much_liquid).
learned(r23_destination_still_approach).
provenance(r23_destination_still_approach, antecedent, a23).
provenance(r23_destination_still_approach, parent, none).
provenance(r23_destination_still_approach, simulations, 31).
provenance(r23_destination_still_approach, weight_mass_permille, 31000).
provenance(r23_destination_still_approach, confidence_permille, 677).
provenance(r23_destination_still_approach, score_permille, 325).
provenance(r23_destination_still_approach, batches, 1).

rule(r23_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r23_destination_still_retreat, approach_moving_away).
body(r23_destination_still_retreat, bouncy_destination).
body(r23_destination_still_retreat, bouncy_liquid).
body(r23_destination_still_retreat, dull_source).
body(r23_destination_still_retreat, end_centred).
body(r23_destination_still_retreat, end_level).
body(r23_destination_still_retreat, end_low).
body(r23_destination_still_retreat, end_upside_down).
body(r23_destination_still_retreat, fast_retreat).
body(r23_destination_still_retreat, heavy_source).
body(r23_destination_still_retreat, light_destination).
body(r23_destination_still_retreat, medium_liquid).
body(r23_destination_still_retreat, pour_level).
body(r23_destination_still_retreat, pour_offset_sideways).
body(r23_destination_still_retreat, pour_to_side).
body(r23_destination_still_retreat, pour_very_high).
body(r23_destination_still_retreat, slippery_destination).
body(r23_destination_still_retreat, slippery_source).
body(r23_destination_still_retreat, start_below_rim).
body(r23_destination_still_retreat, start_upright).
body(r23_destination_still_retreat, very_much_liquid).
learned(r23_destination_still_retreat).
provenance(r23_destination_still_retreat, antecedent, a23).
provenance(r23_destination_still_retreat, parent, none).
provenance(r23_destination_still_retreat, simulations, 31).
provenance(r23_destination_still_retreat, weight_mass_permille, 31000).
provenance(r23_destination_still_retreat, confidence_permille, 839).
provenance(r23_destination_still_retreat, score_permille, 174).
provenance(r23_destination_still_retreat, batches, 1).

rule(r23_destination_still_settle, defeasible, neg(destination_still_settle)).
body(r23_destination_still_settle, approach_moving_away).
body(r23_destination_still_settle, bouncy_destination).
body(r23_destination_still_settle, bouncy_liquid).
body(r23_destination_still_settle, dull_source).
body(r23_destination_still_settle, end_centred).
body(r23_destination_still_settle, end_level).
body(r23_destination_still_settle, end_low).
body(r23_destination_still_settle, end_upside_down).
body(r23_destination_still_settle, fast_retreat).
body(r23_destination_still_settle, heavy_source).
body(r23_destination_still_settle, light_destination).
body(r23_destination_still_settle, medium_liquid).
body(r23_destination_still_settle, pour_level).
body(r23_destination_still_settle, pour_offset_sideways).
body(r23_destination_still_settle, pour_to_side).
body(r23_destination_still_settle, pour_very_high).
body(r23_destination_still_settle, slippery_destination).
body(r23_destination_still_settle, slippery_source).
body(r23_destination_still_settle, start_below_rim).
body(r23_destination_still_settle, start_upright).
body(r23_destination_still_settle, very_much_liquid).
learned(r23_destination_still_settle).
provenance(r23_destination_still_settle, antecedent, a23).
provenance(r23_destination_still_settle, parent, none).
provenance(r23_destination_still_settle, simulations, 31).
provenance(r23_destination_still_settle, weight_mass_permille, 31000).
provenance(r23_destination_still_settle, confidence_permille, 548).
provenance(r23_destination_still_settle, score_permille, 459).
provenance(r23_destination_still_settle, batches, 1).

rule(r23_destination_upright, defeasible, destination_upright).
body(r23_destination_upright, approach_moving_away).
body(r23_destination_upright, bouncy_destination).
body(r23_destination_upright, bouncy_liquid).
body(r23_destination_upright, dull_source).
body(r23_destination_upright, end_centred).
body(r23_destination_upright, end_level).
body(r23_destination_upright, end_low).
body(r23_destination_upright, end_upside_down).
body(r23_destination_upright, fast_retreat).
body(r23_destination_upright, heavy_source).
body(r23_destination_upright, light_destination).
body(r23_destination_upright, medium_liquid).
body(r23_destination_upright, pour_level).
body(r23_destination_upright, pour_offset_sideways).
body(r23_destination_upright, pour_to_side).
body(r23_destination_upright, pour_very_high).
body(r23_destination_upright, slippery_destination).
body(r23_destination_upright, slippery_source).
body(r23_destination_upright, start_below_rim).
body(r23_destination_upright, start_upright).
body(r23_destination_upright, very_much_liquid).
learned(r23_destination_upright).
provenance(r23_destination_upright, antecedent, a23).
provenance(r23_destination_upright, parent, none).
provenance(r23_destination_upright, simulations, 31).
provenance(r23_destination_upright, weight_mass_permille, 31000).
provenance(r23_destination_upright, confidence_permille, 774).
provenance(r23_destination_upright, score_permille, 769).
provenance(r23_destination_upright, batches, 1).

rule(r23_source_clear, defeasible, neg(source_clear)).
body(r23_source_clear, approach_moving_away).
body(r23_source_clear, bouncy_destination).
body(r23_source_clear, bouncy_liquid).
body(r23_source_clear, dull_source).
body(r23_source_clear, end_centred).
body(r23_source_clear, end_level).
body(r23_source_clear, end_low).
body(r23_source_clear, end_upside_down).
body(r23_source_clear, fast_retreat).
body(r23_source_clear, heavy_source).
body(r23_source_clear, light_destination).
body(r23_source_clear, medium_liquid).
body(r23_source_clear, pour_level).
body(r23_source_clear, pour_offset_sideways).
body(r23_source_clear, pour_to_side).
body(r23_source_clear, pour_very_high).
body(r23_source_clear, slippery_destination).
body(r23_source_clear, slippery_source).
body(r23_source_clear, start_below_rim).
body(r23_source_clear, start_upright).
body(r23_source_clear, very_much_liquid).
learned(r23_source_clear).
provenance(r23_source_clear, antecedent, a23).
provenance(r23_source_clear, parent, none).
provenance(r23_source_clear, simulations, 31).
provenance(r23_source_clear, weight_mass_permille, 31000).
provenance(r23_source_clear, confidence_permille, 935).
provenance(r23_source_clear, score_permille, 72).
provenance(r23_source_clear, batches, 1).

rule(r23_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r23_liquid_leaves_source, approach_moving_away).
body(r23_liquid_leaves_source, bouncy_destination).
body(r23_liquid_leaves_source, bouncy_liquid).
body(r23_liquid_leaves_source, dull_source).
body(r23_liquid_leaves_source, end_centred).
body(r23_liquid_leaves_source, end_level).
body(r23_liquid_leaves_source, end_low).
body(r23_liquid_leaves_source, end_upside_down).
body(r23_liquid_leaves_source, fast_retreat).
body(r23_liquid_leaves_source, heavy_source).
body(r23_liquid_leaves_source, light_destination).
body(r23_liquid_leaves_source, medium_liquid).
body(r23_liquid_leaves_source, pour_level).
body(r23_liquid_leaves_source, pour_offset_sideways).
body(r23_liquid_leaves_source, pour_to_side).
body(r23_liquid_leaves_source, pour_very_high).
body(r23_liquid_leaves_source, slippery_destination).
body(r23_liquid_leaves_source, slippery_source).
body(r23_liquid_leaves_source, start_below_rim).
body(r23_liquid_leaves_source, start_upright).
body(r23_liquid_leaves_source, very_much_liquid).
learned(r23_liquid_leaves_source).
provenance(r23_liquid_leaves_source, antecedent, a23).
provenance(r23_liquid_leaves_source, parent, none).
provenance(r23_liquid_leaves_source, simulations, 31).
provenance(r23_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r23_liquid_leaves_source, confidence_permille, 1000).
provenance(r23_liquid_leaves_source, score_permille, 999).
provenance(r23_liquid_leaves_source, batches, 1).

rule(r23_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r23_liquid_enters_destination, approach_moving_away).
body(r23_liquid_enters_destination, bouncy_destination).
body(r23_liquid_enters_destination, bouncy_liquid).
body(r23_liquid_enters_destination, dull_source).
body(r23_liquid_enters_destination, end_centred).
body(r23_liquid_enters_destination, end_level).
body(r23_liquid_enters_destination, end_low).
body(r23_liquid_enters_destination, end_upside_down).
body(r23_liquid_enters_destination, fast_retreat).
body(r23_liquid_enters_destination, heavy_source).
body(r23_liquid_enters_destination, light_destination).
body(r23_liquid_enters_destination, medium_liquid).
body(r23_liquid_enters_destination, pour_level).
body(r23_liquid_enters_destination, pour_offset_sideways).
body(r23_liquid_enters_destination, pour_to_side).
body(r23_liquid_enters_destination, pour_very_high).
body(r23_liquid_enters_destination, slippery_destination).
body(r23_liquid_enters_destination, slippery_source).
body(r23_liquid_enters_destination, start_below_rim).
body(r23_liquid_enters_destination, start_upright).
body(r23_liquid_enters_destination, very_much_liquid).
learned(r23_liquid_enters_destination).
provenance(r23_liquid_enters_destination, antecedent, a23).
provenance(r23_liquid_enters_destination, parent, none).
provenance(r23_liquid_enters_destination, simulations, 31).
provenance(r23_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r23_liquid_enters_destination, confidence_permille, 581).
provenance(r23_liquid_enters_destination, score_permille, 552).
provenance(r23_liquid_enters_destination, batches, 1).

rule(r23_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r23_liquid_remains_in_destination, approach_moving_away).
body(r23_liquid_remains_in_destination, bouncy_destination).
body(r23_liquid_remains_in_destination, bouncy_liquid).
body(r23_liquid_remains_in_destination, dull_source).
body(r23_liquid_remains_in_destination, end_centred).
body(r23_liquid_remains_in_destination, end_level).
body(r23_liquid_remains_in_destination, end_low).
body(r23_liquid_remains_in_destination, end_upside_down).
body(r23_liquid_remains_in_destination, fast_retreat).
body(r23_liquid_remains_in_destination, heavy_source).
body(r23_liquid_remains_in_destination, light_destination).
body(r23_liquid_remains_in_destination, medium_liquid).
body(r23_liquid_remains_in_destination, pour_level).
body(r23_liquid_remains_in_destination, pour_offset_sideways).
body(r23_liquid_remains_in_destination, pour_to_side).
body(r23_liquid_remains_in_destination, pour_very_high).
body(r23_liquid_remains_in_destination, slippery_destination).
body(r23_liquid_remains_in_destination, slippery_source).
body(r23_liquid_remains_in_destination, start_below_rim).
body(r23_liquid_remains_in_destination, start_upright).
body(r23_liquid_remains_in_destination, very_much_liquid).
learned(r23_liquid_remains_in_destination).
provenance(r23_liquid_remains_in_destination, antecedent, a23).
provenance(r23_liquid_remains_in_destination, parent, none).
provenance(r23_liquid_remains_in_destination, simulations, 31).
provenance(r23_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r23_liquid_remains_in_destination, confidence_permille, 516).
provenance(r23_liquid_remains_in_destination, score_permille, 500).
provenance(r23_liquid_remains_in_destination, batches, 1).

rule(r23_no_spill, defeasible, neg(no_spill)).
body(r23_no_spill, approach_moving_away).
body(r23_no_spill, bouncy_destination).
body(r23_no_spill, bouncy_liquid).
body(r23_no_spill, dull_source).
body(r23_no_spill, end_centred).
body(r23_no_spill, end_level).
body(r23_no_spill, end_low).
body(r23_no_spill, end_upside_down).
body(r23_no_spill, fast_retreat).
body(r23_no_spill, heavy_source).
body(r23_no_spill, light_destination).
body(r23_no_spill, medium_liquid).
body(r23_no_spill, pour_level).
body(r23_no_spill, pour_offset_sideways).
body(r23_no_spill, pour_to_side).
body(r23_no_spill, pour_very_high).
body(r23_no_spill, slippery_destination).
body(r23_no_spill, slippery_source).
body(r23_no_spill, start_below_rim).
body(r23_no_spill, start_upright).
body(r23_no_spill, very_much_liquid).
learned(r23_no_spill).
provenance(r23_no_spill, antecedent, a23).
provenance(r23_no_spill, parent, none).
provenance(r23_no_spill, simulations, 31).
provenance(r23_no_spill, weight_mass_permille, 31000).
provenance(r23_no_spill, confidence_permille, 774).
provenance(r23_no_spill, score_permille, 254).
provenance(r23_no_spill, batches, 1).

rule(r24_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r24_destination_still_approach, approach_moving_closer).
body(r24_destination_still_approach, bouncy_source).
body(r24_destination_still_approach, dull_liquid).
body(r24_destination_still_approach, end_centred).
body(r24_destination_still_approach, end_level).
body(r24_destination_still_approach, end_low).
body(r24_destination_still_approach, grippy_source).
body(r24_destination_still_approach, heavy_source).
body(r24_destination_still_approach, light_liquid).
body(r24_destination_still_approach, little_liquid).
body(r24_destination_still_approach, moderate_retreat).
body(r24_destination_still_approach, pour_centred).
body(r24_destination_still_approach, pour_mid_height).
body(r24_destination_still_approach, pour_offset_sideways).
body(r24_destination_still_approach, pour_upright).
body(r24_destination_still_approach, runny_liquid).
body(r24_destination_still_approach, slow_approach).
body(r24_destination_still_approach, start_below_rim).
body(r24_destination_still_approach, start_upright).
learned(r24_destination_still_approach).
provenance(r24_destination_still_approach, antecedent, a24).
provenance(r24_destination_still_approach, parent, a17).
provenance(r24_destination_still_approach, simulations, 31).
provenance(r24_destination_still_approach, weight_mass_permille, 31000).
provenance(r24_destination_still_approach, confidence_permille, 742).
provenance(r24_destination_still_approach, score_permille, 240).
provenance(r24_destination_still_approach, batches, 1).

rule(r24_destination_still_retreat, defeasible, destination_still_retreat).
body(r24_destination_still_retreat, approach_moving_closer).
body(r24_destination_still_retreat, bouncy_source).
body(r24_destination_still_retreat, dull_liquid).
body(r24_destination_still_retreat, end_centred).
body(r24_destination_still_retreat, end_level).
body(r24_destination_still_retreat, end_low).
body(r24_destination_still_retreat, grippy_source).
body(r24_destination_still_retreat, heavy_source).
body(r24_destination_still_retreat, light_liquid).
body(r24_destination_still_retreat, little_liquid).
body(r24_destination_still_retreat, moderate_retreat).
body(r24_destination_still_retreat, pour_centred).
body(r24_destination_still_retreat, pour_mid_height).
body(r24_destination_still_retreat, pour_offset_sideways).
body(r24_destination_still_retreat, pour_upright).
body(r24_destination_still_retreat, runny_liquid).
body(r24_destination_still_retreat, slow_approach).
body(r24_destination_still_retreat, start_below_rim).
body(r24_destination_still_retreat, start_upright).
learned(r24_destination_still_retreat).
provenance(r24_destination_still_retreat, antecedent, a24).
provenance(r24_destination_still_retreat, parent, a17).
provenance(r24_destination_still_retreat, simulations, 31).
provenance(r24_destination_still_retreat, weight_mass_permille, 31000).
provenance(r24_destination_still_retreat, confidence_permille, 871).
provenance(r24_destination_still_retreat, score_permille, 858).
provenance(r24_destination_still_retreat, batches, 1).

rule(r24_destination_still_settle, defeasible, destination_still_settle).
body(r24_destination_still_settle, approach_moving_closer).
body(r24_destination_still_settle, bouncy_source).
body(r24_destination_still_settle, dull_liquid).
body(r24_destination_still_settle, end_centred).
body(r24_destination_still_settle, end_level).
body(r24_destination_still_settle, end_low).
body(r24_destination_still_settle, grippy_source).
body(r24_destination_still_settle, heavy_source).
body(r24_destination_still_settle, light_liquid).
body(r24_destination_still_settle, little_liquid).
body(r24_destination_still_settle, moderate_retreat).
body(r24_destination_still_settle, pour_centred).
body(r24_destination_still_settle, pour_mid_height).
body(r24_destination_still_settle, pour_offset_sideways).
body(r24_destination_still_settle, pour_upright).
body(r24_destination_still_settle, runny_liquid).
body(r24_destination_still_settle, slow_approach).
body(r24_destination_still_settle, start_below_rim).
body(r24_destination_still_settle, start_upright).
learned(r24_destination_still_settle).
provenance(r24_destination_still_settle, antecedent, a24).
provenance(r24_destination_still_settle, parent, a17).
provenance(r24_destination_still_settle, simulations, 31).
provenance(r24_destination_still_settle, weight_mass_permille, 31000).
provenance(r24_destination_still_settle, confidence_permille, 968).
provenance(r24_destination_still_settle, score_permille, 945).
provenance(r24_destination_still_settle, batches, 1).

rule(r24_destination_upright, defeasible, destination_upright).
body(r24_destination_upright, approach_moving_closer).
body(r24_destination_upright, bouncy_source).
body(r24_destination_upright, dull_liquid).
body(r24_destination_upright, end_centred).
body(r24_destination_upright, end_level).
body(r24_destination_upright, end_low).
body(r24_destination_upright, grippy_source).
body(r24_destination_upright, heavy_source).
body(r24_destination_upright, light_liquid).
body(r24_destination_upright, little_liquid).
body(r24_destination_upright, moderate_retreat).
body(r24_destination_upright, pour_centred).
body(r24_destination_upright, pour_mid_height).
body(r24_destination_upright, pour_offset_sideways).
body(r24_destination_upright, pour_upright).
body(r24_destination_upright, runny_liquid).
body(r24_destination_upright, slow_approach).
body(r24_destination_upright, start_below_rim).
body(r24_destination_upright, start_upright).
learned(r24_destination_upright).
provenance(r24_destination_upright, antecedent, a24).
provenance(r24_destination_upright, parent, a17).
provenance(r24_destination_upright, simulations, 31).
provenance(r24_destination_upright, weight_mass_permille, 31000).
provenance(r24_destination_upright, confidence_permille, 968).
provenance(r24_destination_upright, score_permille, 958).
provenance(r24_destination_upright, batches, 1).

rule(r24_source_clear, defeasible, neg(source_clear)).
body(r24_source_clear, approach_moving_closer).
body(r24_source_clear, bouncy_source).
body(r24_source_clear, dull_liquid).
body(r24_source_clear, end_centred).
body(r24_source_clear, end_level).
body(r24_source_clear, end_low).
body(r24_source_clear, grippy_source).
body(r24_source_clear, heavy_source).
body(r24_source_clear, light_liquid).
body(r24_source_clear, little_liquid).
body(r24_source_clear, moderate_retreat).
body(r24_source_clear, pour_centred).
body(r24_source_clear, pour_mid_height).
body(r24_source_clear, pour_offset_sideways).
body(r24_source_clear, pour_upright).
body(r24_source_clear, runny_liquid).
body(r24_source_clear, slow_approach).
body(r24_source_clear, start_below_rim).
body(r24_source_clear, start_upright).
learned(r24_source_clear).
provenance(r24_source_clear, antecedent, a24).
provenance(r24_source_clear, parent, a17).
provenance(r24_source_clear, simulations, 31).
provenance(r24_source_clear, weight_mass_permille, 31000).
provenance(r24_source_clear, confidence_permille, 935).
provenance(r24_source_clear, score_permille, 65).
provenance(r24_source_clear, batches, 1).

rule(r24_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r24_liquid_leaves_source, approach_moving_closer).
body(r24_liquid_leaves_source, bouncy_source).
body(r24_liquid_leaves_source, dull_liquid).
body(r24_liquid_leaves_source, end_centred).
body(r24_liquid_leaves_source, end_level).
body(r24_liquid_leaves_source, end_low).
body(r24_liquid_leaves_source, grippy_source).
body(r24_liquid_leaves_source, heavy_source).
body(r24_liquid_leaves_source, light_liquid).
body(r24_liquid_leaves_source, little_liquid).
body(r24_liquid_leaves_source, moderate_retreat).
body(r24_liquid_leaves_source, pour_centred).
body(r24_liquid_leaves_source, pour_mid_height).
body(r24_liquid_leaves_source, pour_offset_sideways).
body(r24_liquid_leaves_source, pour_upright).
body(r24_liquid_leaves_source, runny_liquid).
body(r24_liquid_leaves_source, slow_approach).
body(r24_liquid_leaves_source, start_below_rim).
body(r24_liquid_leaves_source, start_upright).
learned(r24_liquid_leaves_source).
provenance(r24_liquid_leaves_source, antecedent, a24).
provenance(r24_liquid_leaves_source, parent, a17).
provenance(r24_liquid_leaves_source, simulations, 31).
provenance(r24_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r24_liquid_leaves_source, confidence_permille, 968).
provenance(r24_liquid_leaves_source, score_permille, 81).
provenance(r24_liquid_leaves_source, batches, 1).

rule(r24_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r24_liquid_enters_destination, approach_moving_closer).
body(r24_liquid_enters_destination, bouncy_source).
body(r24_liquid_enters_destination, dull_liquid).
body(r24_liquid_enters_destination, end_centred).
body(r24_liquid_enters_destination, end_level).
body(r24_liquid_enters_destination, end_low).
body(r24_liquid_enters_destination, grippy_source).
body(r24_liquid_enters_destination, heavy_source).
body(r24_liquid_enters_destination, light_liquid).
body(r24_liquid_enters_destination, little_liquid).
body(r24_liquid_enters_destination, moderate_retreat).
body(r24_liquid_enters_destination, pour_centred).
body(r24_liquid_enters_destination, pour_mid_height).
body(r24_liquid_enters_destination, pour_offset_sideways).
body(r24_liquid_enters_destination, pour_upright).
body(r24_liquid_enters_destination, runny_liquid).
body(r24_liquid_enters_destination, slow_approach).
body(r24_liquid_enters_destination, start_below_rim).
body(r24_liquid_enters_destination, start_upright).
learned(r24_liquid_enters_destination).
provenance(r24_liquid_enters_destination, antecedent, a24).
provenance(r24_liquid_enters_destination, parent, a17).
provenance(r24_liquid_enters_destination, simulations, 31).
provenance(r24_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r24_liquid_enters_destination, confidence_permille, 742).
provenance(r24_liquid_enters_destination, score_permille, 250).
provenance(r24_liquid_enters_destination, batches, 1).

rule(r24_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r24_liquid_remains_in_destination, approach_moving_closer).
body(r24_liquid_remains_in_destination, bouncy_source).
body(r24_liquid_remains_in_destination, dull_liquid).
body(r24_liquid_remains_in_destination, end_centred).
body(r24_liquid_remains_in_destination, end_level).
body(r24_liquid_remains_in_destination, end_low).
body(r24_liquid_remains_in_destination, grippy_source).
body(r24_liquid_remains_in_destination, heavy_source).
body(r24_liquid_remains_in_destination, light_liquid).
body(r24_liquid_remains_in_destination, little_liquid).
body(r24_liquid_remains_in_destination, moderate_retreat).
body(r24_liquid_remains_in_destination, pour_centred).
body(r24_liquid_remains_in_destination, pour_mid_height).
body(r24_liquid_remains_in_destination, pour_offset_sideways).
body(r24_liquid_remains_in_destination, pour_upright).
body(r24_liquid_remains_in_destination, runny_liquid).
body(r24_liquid_remains_in_destination, slow_approach).
body(r24_liquid_remains_in_destination, start_below_rim).
body(r24_liquid_remains_in_destination, start_upright).
learned(r24_liquid_remains_in_destination).
provenance(r24_liquid_remains_in_destination, antecedent, a24).
provenance(r24_liquid_remains_in_destination, parent, a17).
provenance(r24_liquid_remains_in_destination, simulations, 31).
provenance(r24_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r24_liquid_remains_in_destination, confidence_permille, 645).
provenance(r24_liquid_remains_in_destination, score_permille, 650).
provenance(r24_liquid_remains_in_destination, batches, 1).

rule(r24_no_spill, defeasible, no_spill).
body(r24_no_spill, approach_moving_closer).
body(r24_no_spill, bouncy_source).
body(r24_no_spill, dull_liquid).
body(r24_no_spill, end_centred).
body(r24_no_spill, end_level).
body(r24_no_spill, end_low).
body(r24_no_spill, grippy_source).
body(r24_no_spill, heavy_source).
body(r24_no_spill, light_liquid).
body(r24_no_spill, little_liquid).
body(r24_no_spill, moderate_retreat).
body(r24_no_spill, pour_centred).
body(r24_no_spill, pour_mid_height).
body(r24_no_spill, pour_offset_sideways).
body(r24_no_spill, pour_upright).
body(r24_no_spill, runny_liquid).
body(r24_no_spill, slow_approach).
body(r24_no_spill, start_below_rim).
body(r24_no_spill, start_upright).
learned(r24_no_spill).
provenance(r24_no_spill, antecedent, a24).
provenance(r24_no_spill, parent, a17).
provenance(r24_no_spill, simulations, 31).
provenance(r24_no_spill, weight_mass_permille, 31000).
provenance(r24_no_spill, confidence_permille, 968).
provenance(r24_no_spill, score_permille, 928).
provenance(r24_no_spill, batches, 1).

rule(r25_destination_still_approach, defeasible, neg(destination_still_approach)).
body(r25_destination_still_approach, approach_raising).
body(r25_destination_still_approach, dull_destination).
body(r25_destination_still_approach, dull_liquid).
body(r25_destination_still_approach, end_centred).
body(r25_destination_still_approach, end_mid_height).
body(r25_destination_still_approach, end_steeply_tilted).
body(r25_destination_still_approach, grippy_destination).
body(r25_destination_still_approach, heavy_liquid).
body(r25_destination_still_approach, heavy_source).
body(r25_destination_still_approach, moderate_approach).
body(r25_destination_still_approach, pour_below_rim).
body(r25_destination_still_approach, pour_level).
body(r25_destination_still_approach, pour_offset_sideways).
body(r25_destination_still_approach, pour_slightly_tilted).
body(r25_destination_still_approach, slow_retreat).
body(r25_destination_still_approach, start_centred).
learned(r25_destination_still_approach).
provenance(r25_destination_still_approach, antecedent, a25).
provenance(r25_destination_still_approach, parent, a22).
provenance(r25_destination_still_approach, simulations, 31).
provenance(r25_destination_still_approach, weight_mass_permille, 31000).
provenance(r25_destination_still_approach, confidence_permille, 1000).
provenance(r25_destination_still_approach, score_permille, 0).
provenance(r25_destination_still_approach, batches, 1).

rule(r25_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(r25_destination_still_retreat, approach_raising).
body(r25_destination_still_retreat, dull_destination).
body(r25_destination_still_retreat, dull_liquid).
body(r25_destination_still_retreat, end_centred).
body(r25_destination_still_retreat, end_mid_height).
body(r25_destination_still_retreat, end_steeply_tilted).
body(r25_destination_still_retreat, grippy_destination).
body(r25_destination_still_retreat, heavy_liquid).
body(r25_destination_still_retreat, heavy_source).
body(r25_destination_still_retreat, moderate_approach).
body(r25_destination_still_retreat, pour_below_rim).
body(r25_destination_still_retreat, pour_level).
body(r25_destination_still_retreat, pour_offset_sideways).
body(r25_destination_still_retreat, pour_slightly_tilted).
body(r25_destination_still_retreat, slow_retreat).
body(r25_destination_still_retreat, start_centred).
learned(r25_destination_still_retreat).
provenance(r25_destination_still_retreat, antecedent, a25).
provenance(r25_destination_still_retreat, parent, a22).
provenance(r25_destination_still_retreat, simulations, 31).
provenance(r25_destination_still_retreat, weight_mass_permille, 31000).
provenance(r25_destination_still_retreat, confidence_permille, 581).
provenance(r25_destination_still_retreat, score_permille, 413).
provenance(r25_destination_still_retreat, batches, 1).

rule(r25_destination_still_settle, defeasible, destination_still_settle).
body(r25_destination_still_settle, approach_raising).
body(r25_destination_still_settle, dull_destination).
body(r25_destination_still_settle, dull_liquid).
body(r25_destination_still_settle, end_centred).
body(r25_destination_still_settle, end_mid_height).
body(r25_destination_still_settle, end_steeply_tilted).
body(r25_destination_still_settle, grippy_destination).
body(r25_destination_still_settle, heavy_liquid).
body(r25_destination_still_settle, heavy_source).
body(r25_destination_still_settle, moderate_approach).
body(r25_destination_still_settle, pour_below_rim).
body(r25_destination_still_settle, pour_level).
body(r25_destination_still_settle, pour_offset_sideways).
body(r25_destination_still_settle, pour_slightly_tilted).
body(r25_destination_still_settle, slow_retreat).
body(r25_destination_still_settle, start_centred).
learned(r25_destination_still_settle).
provenance(r25_destination_still_settle, antecedent, a25).
provenance(r25_destination_still_settle, parent, a22).
provenance(r25_destination_still_settle, simulations, 31).
provenance(r25_destination_still_settle, weight_mass_permille, 31000).
provenance(r25_destination_still_settle, confidence_permille, 1000).
provenance(r25_destination_still_settle, score_permille, 979).
provenance(r25_destination_still_settle, batches, 1).

rule(r25_destination_upright, defeasible, destination_upright).
body(r25_destination_upright, approach_raising).
body(r25_destination_upright, dull_destination).
body(r25_destination_upright, dull_liquid).
body(r25_destination_upright, end_centred).
body(r25_destination_upright, end_mid_height).
body(r25_destination_upright, end_steeply_tilted).
body(r25_destination_upright, grippy_destination).
body(r25_destination_upright, heavy_liquid).
body(r25_destination_upright, heavy_source).
body(r25_destination_upright, moderate_approach).
body(r25_destination_upright, pour_below_rim).
body(r25_destination_upright, pour_level).
body(r25_destination_upright, pour_offset_sideways).
body(r25_destination_upright, pour_slightly_tilted).
body(r25_destination_upright, slow_retreat).
body(r25_destination_upright, start_centred).
learned(r25_destination_upright).
provenance(r25_destination_upright, antecedent, a25).
provenance(r25_destination_upright, parent, a22).
provenance(r25_destination_upright, simulations, 31).
provenance(r25_destination_upright, weight_mass_permille, 31000).
provenance(r25_destination_upright, confidence_permille, 1000).
provenance(r25_destination_upright, score_permille, 994).
provenance(r25_destination_upright, batches, 1).

rule(r25_source_clear, defeasible, neg(source_clear)).
body(r25_source_clear, approach_raising).
body(r25_source_clear, dull_destination).
body(r25_source_clear, dull_liquid).
body(r25_source_clear, end_centred).
body(r25_source_clear, end_mid_height).
body(r25_source_clear, end_steeply_tilted).
body(r25_source_clear, grippy_destination).
body(r25_source_clear, heavy_liquid).
body(r25_source_clear, heavy_source).
body(r25_source_clear, moderate_approach).
body(r25_source_clear, pour_below_rim).
body(r25_source_clear, pour_level).
body(r25_source_clear, pour_offset_sideways).
body(r25_source_clear, pour_slightly_tilted).
body(r25_source_clear, slow_retreat).
body(r25_source_clear, start_centred).
learned(r25_source_clear).
provenance(r25_source_clear, antecedent, a25).
provenance(r25_source_clear, parent, a22).
provenance(r25_source_clear, simulations, 31).
provenance(r25_source_clear, weight_mass_permille, 31000).
provenance(r25_source_clear, confidence_permille, 1000).
provenance(r25_source_clear, score_permille, 0).
provenance(r25_source_clear, batches, 1).

rule(r25_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r25_liquid_leaves_source, approach_raising).
body(r25_liquid_leaves_source, dull_destination).
body(r25_liquid_leaves_source, dull_liquid).
body(r25_liquid_leaves_source, end_centred).
body(r25_liquid_leaves_source, end_mid_height).
body(r25_liquid_leaves_source, end_steeply_tilted).
body(r25_liquid_leaves_source, grippy_destination).
body(r25_liquid_leaves_source, heavy_liquid).
body(r25_liquid_leaves_source, heavy_source).
body(r25_liquid_leaves_source, moderate_approach).
body(r25_liquid_leaves_source, pour_below_rim).
body(r25_liquid_leaves_source, pour_level).
body(r25_liquid_leaves_source, pour_offset_sideways).
body(r25_liquid_leaves_source, pour_slightly_tilted).
body(r25_liquid_leaves_source, slow_retreat).
body(r25_liquid_leaves_source, start_centred).
learned(r25_liquid_leaves_source).
provenance(r25_liquid_leaves_source, antecedent, a25).
provenance(r25_liquid_leaves_source, parent, a22).
provenance(r25_liquid_leaves_source, simulations, 31).
provenance(r25_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r25_liquid_leaves_source, confidence_permille, 871).
provenance(r25_liquid_leaves_source, score_permille, 818).
provenance(r25_liquid_leaves_source, batches, 1).

rule(r25_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r25_liquid_enters_destination, approach_raising).
body(r25_liquid_enters_destination, dull_destination).
body(r25_liquid_enters_destination, dull_liquid).
body(r25_liquid_enters_destination, end_centred).
body(r25_liquid_enters_destination, end_mid_height).
body(r25_liquid_enters_destination, end_steeply_tilted).
body(r25_liquid_enters_destination, grippy_destination).
body(r25_liquid_enters_destination, heavy_liquid).
body(r25_liquid_enters_destination, heavy_source).
body(r25_liquid_enters_destination, moderate_approach).
body(r25_liquid_enters_destination, pour_below_rim).
body(r25_liquid_enters_destination, pour_level).
body(r25_liquid_enters_destination, pour_offset_sideways).
body(r25_liquid_enters_destination, pour_slightly_tilted).
body(r25_liquid_enters_destination, slow_retreat).
body(r25_liquid_enters_destination, start_centred).
learned(r25_liquid_enters_destination).
provenance(r25_liquid_enters_destination, antecedent, a25).
provenance(r25_liquid_enters_destination, parent, a22).
provenance(r25_liquid_enters_destination, simulations, 31).
provenance(r25_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r25_liquid_enters_destination, confidence_permille, 1000).
provenance(r25_liquid_enters_destination, score_permille, 993).
provenance(r25_liquid_enters_destination, batches, 1).

rule(r25_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(r25_liquid_remains_in_destination, approach_raising).
body(r25_liquid_remains_in_destination, dull_destination).
body(r25_liquid_remains_in_destination, dull_liquid).
body(r25_liquid_remains_in_destination, end_centred).
body(r25_liquid_remains_in_destination, end_mid_height).
body(r25_liquid_remains_in_destination, end_steeply_tilted).
body(r25_liquid_remains_in_destination, grippy_destination).
body(r25_liquid_remains_in_destination, heavy_liquid).
body(r25_liquid_remains_in_destination, heavy_source).
body(r25_liquid_remains_in_destination, moderate_approach).
body(r25_liquid_remains_in_destination, pour_below_rim).
body(r25_liquid_remains_in_destination, pour_level).
body(r25_liquid_remains_in_destination, pour_offset_sideways).
body(r25_liquid_remains_in_destination, pour_slightly_tilted).
body(r25_liquid_remains_in_destination, slow_retreat).
body(r25_liquid_remains_in_destination, start_centred).
learned(r25_liquid_remains_in_destination).
provenance(r25_liquid_remains_in_destination, antecedent, a25).
provenance(r25_liquid_remains_in_destination, parent, a22).
provenance(r25_liquid_remains_in_destination, simulations, 31).
provenance(r25_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r25_liquid_remains_in_destination, confidence_permille, 742).
provenance(r25_liquid_remains_in_destination, score_permille, 230).
provenance(r25_liquid_remains_in_destination, batches, 1).

rule(r25_no_spill, defeasible, neg(no_spill)).
body(r25_no_spill, approach_raising).
body(r25_no_spill, dull_destination).
body(r25_no_spill, dull_liquid).
body(r25_no_spill, end_centred).
body(r25_no_spill, end_mid_height).
body(r25_no_spill, end_steeply_tilted).
body(r25_no_spill, grippy_destination).
body(r25_no_spill, heavy_liquid).
body(r25_no_spill, heavy_source).
body(r25_no_spill, moderate_approach).
body(r25_no_spill, pour_below_rim).
body(r25_no_spill, pour_level).
body(r25_no_spill, pour_offset_sideways).
body(r25_no_spill, pour_slightly_tilted).
body(r25_no_spill, slow_retreat).
body(r25_no_spill, start_centred).
learned(r25_no_spill).
provenance(r25_no_spill, antecedent, a25).
provenance(r25_no_spill, parent, a22).
provenance(r25_no_spill, simulations, 31).
provenance(r25_no_spill, weight_mass_permille, 31000).
provenance(r25_no_spill, confidence_permille, 613).
provenance(r25_no_spill, score_permille, 411).
provenance(r25_no_spill, batches, 1).

% General rules, learned from every pour of the exploration
% (bridge/learning/generalize.py): a default per expectation, exceptions
% and exceptions to those. provenance(Id, support, N): the pours whose
% description holds the body; kept: how many of them keep the head;
% confidence_permille: P(head | body) for the pours sampled for the body
% (a default the priors leave open: for the pours of the uniformly random
% scenes it decides).
% sup/2 below orders both layers (see bridge/learning/layers.py).
setting(general_pours, 775).
setting(general_rules, 23).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 775).
provenance(g0_destination_still_approach, kept, 469).
provenance(g0_destination_still_approach, confidence_permille, 991).
rule(g1_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g1_destination_still_approach, pour_below_rim).
body(g1_destination_still_approach, start_below_rim).
learned(g1_destination_still_approach).
provenance(g1_destination_still_approach, layer, general).
provenance(g1_destination_still_approach, level, 1).
provenance(g1_destination_still_approach, support, 124).
provenance(g1_destination_still_approach, kept, 123).
provenance(g1_destination_still_approach, confidence_permille, 710).
rule(g2_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g2_destination_still_approach, approach_moving_away).
body(g2_destination_still_approach, start_below_rim).
learned(g2_destination_still_approach).
provenance(g2_destination_still_approach, layer, general).
provenance(g2_destination_still_approach, level, 1).
provenance(g2_destination_still_approach, support, 135).
provenance(g2_destination_still_approach, kept, 91).
provenance(g2_destination_still_approach, confidence_permille, 735).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 775).
provenance(g0_destination_still_retreat, kept, 441).
provenance(g0_destination_still_retreat, confidence_permille, 988).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 775).
provenance(g0_destination_still_settle, kept, 631).
provenance(g0_destination_still_settle, confidence_permille, 994).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 775).
provenance(g0_destination_upright, kept, 727).
provenance(g0_destination_upright, confidence_permille, 1000).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 775).
provenance(g0_source_clear, kept, 268).
provenance(g0_source_clear, confidence_permille, 983).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, end_centred).
body(g1_source_clear, start_below_rim).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 187).
provenance(g1_source_clear, kept, 180).
provenance(g1_source_clear, confidence_permille, 751).
rule(g2_source_clear, defeasible, neg(source_clear)).
body(g2_source_clear, end_near_rim).
body(g2_source_clear, start_below_rim).
learned(g2_source_clear).
provenance(g2_source_clear, layer, general).
provenance(g2_source_clear, level, 1).
provenance(g2_source_clear, support, 68).
provenance(g2_source_clear, kept, 66).
provenance(g2_source_clear, confidence_permille, 624).
rule(g3_source_clear, defeasible, neg(source_clear)).
body(g3_source_clear, pour_low).
body(g3_source_clear, start_below_rim).
learned(g3_source_clear).
provenance(g3_source_clear, layer, general).
provenance(g3_source_clear, level, 1).
provenance(g3_source_clear, support, 166).
provenance(g3_source_clear, kept, 135).
provenance(g3_source_clear, confidence_permille, 604).
rule(g0_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 775).
provenance(g0_liquid_leaves_source, kept, 319).
provenance(g0_liquid_leaves_source, confidence_permille, 794).
rule(g1_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g1_liquid_leaves_source, retreat_lowering).
body(g1_liquid_leaves_source, retreat_moving_closer).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 242).
provenance(g1_liquid_leaves_source, kept, 224).
provenance(g1_liquid_leaves_source, confidence_permille, 633).
rule(g2_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g2_liquid_leaves_source, pour_steeply_tilted).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 193).
provenance(g2_liquid_leaves_source, kept, 187).
provenance(g2_liquid_leaves_source, confidence_permille, 815).
rule(g3_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g3_liquid_leaves_source, end_upside_down).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 124).
provenance(g3_liquid_leaves_source, kept, 122).
provenance(g3_liquid_leaves_source, confidence_permille, 979).
rule(g4_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g4_liquid_leaves_source, end_steeply_tilted).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 124).
provenance(g4_liquid_leaves_source, kept, 116).
provenance(g4_liquid_leaves_source, confidence_permille, 886).
rule(g5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g5_liquid_leaves_source, end_below_rim).
body(g5_liquid_leaves_source, pour_rolled).
learned(g5_liquid_leaves_source).
provenance(g5_liquid_leaves_source, layer, general).
provenance(g5_liquid_leaves_source, level, 1).
provenance(g5_liquid_leaves_source, support, 155).
provenance(g5_liquid_leaves_source, kept, 138).
provenance(g5_liquid_leaves_source, confidence_permille, 662).
rule(g6_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g6_liquid_leaves_source, pour_upside_down).
learned(g6_liquid_leaves_source).
provenance(g6_liquid_leaves_source, layer, general).
provenance(g6_liquid_leaves_source, level, 1).
provenance(g6_liquid_leaves_source, support, 12).
provenance(g6_liquid_leaves_source, kept, 12).
provenance(g6_liquid_leaves_source, confidence_permille, 989).
rule(g0_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 775).
provenance(g0_liquid_enters_destination, kept, 480).
provenance(g0_liquid_enters_destination, confidence_permille, 721).
rule(g1_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g1_liquid_enters_destination, heavy_liquid).
body(g1_liquid_enters_destination, moderate_approach).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 216).
provenance(g1_liquid_enters_destination, kept, 158).
provenance(g1_liquid_enters_destination, confidence_permille, 609).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 775).
provenance(g0_liquid_remains_in_destination, kept, 597).
provenance(g0_liquid_remains_in_destination, confidence_permille, 992).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 775).
provenance(g0_no_spill, kept, 472).
provenance(g0_no_spill, confidence_permille, 894).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, end_steeply_tilted).
body(g1_no_spill, retreat_moving_closer).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 100).
provenance(g1_no_spill, kept, 85).
provenance(g1_no_spill, confidence_permille, 686).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, end_upside_down).
body(g2_no_spill, start_below_rim).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 83).
provenance(g2_no_spill, kept, 68).
provenance(g2_no_spill, confidence_permille, 642).
sup(r12_liquid_leaves_source, g3_liquid_leaves_source).
sup(r12_liquid_leaves_source, g4_liquid_leaves_source).
sup(r13_liquid_enters_destination, g1_liquid_enters_destination).
sup(r17_liquid_leaves_source, g3_liquid_leaves_source).
sup(r17_liquid_leaves_source, g4_liquid_leaves_source).
sup(r17_no_spill, g1_no_spill).
sup(r17_no_spill, g2_no_spill).
sup(r1_destination_still_approach, g2_destination_still_approach).
sup(r1_no_spill, g1_no_spill).
sup(r1_no_spill, g2_no_spill).
sup(r1_source_clear, g1_source_clear).
sup(r1_source_clear, g2_source_clear).
sup(r20_destination_still_approach, g2_destination_still_approach).
sup(r21_destination_still_approach, g2_destination_still_approach).
sup(r24_liquid_leaves_source, g3_liquid_leaves_source).
sup(r24_liquid_leaves_source, g4_liquid_leaves_source).
sup(r24_no_spill, g2_no_spill).
sup(r2_destination_still_approach, g2_destination_still_approach).
