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
setting(threshold_permille, 100).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 24).
setting(simulations, 744).
setting(failed_simulations, 0).
setting(stopped, a_new_empty).
setting(a_new_left, 0).
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
provenance(r1_destination_still_approach, simulations, 509).
provenance(r1_destination_still_approach, weight_mass_permille, 32104).
provenance(r1_destination_still_approach, confidence_permille, 994).
provenance(r1_destination_still_approach, score_permille, 968).

rule(r1_destination_still_retreat, defeasible, destination_still_retreat).
body(r1_destination_still_retreat, pour_mid_height).
body(r1_destination_still_retreat, pour_near_rim).
body(r1_destination_still_retreat, pour_steeply_tilted).
learned(r1_destination_still_retreat).
provenance(r1_destination_still_retreat, antecedent, a1).
provenance(r1_destination_still_retreat, parent, none).
provenance(r1_destination_still_retreat, simulations, 509).
provenance(r1_destination_still_retreat, weight_mass_permille, 32104).
provenance(r1_destination_still_retreat, confidence_permille, 996).
provenance(r1_destination_still_retreat, score_permille, 977).

rule(r1_destination_still_settle, defeasible, destination_still_settle).
body(r1_destination_still_settle, pour_mid_height).
body(r1_destination_still_settle, pour_near_rim).
body(r1_destination_still_settle, pour_steeply_tilted).
learned(r1_destination_still_settle).
provenance(r1_destination_still_settle, antecedent, a1).
provenance(r1_destination_still_settle, parent, none).
provenance(r1_destination_still_settle, simulations, 509).
provenance(r1_destination_still_settle, weight_mass_permille, 32104).
provenance(r1_destination_still_settle, confidence_permille, 1000).
provenance(r1_destination_still_settle, score_permille, 996).

rule(r1_destination_upright, defeasible, destination_upright).
body(r1_destination_upright, pour_mid_height).
body(r1_destination_upright, pour_near_rim).
body(r1_destination_upright, pour_steeply_tilted).
learned(r1_destination_upright).
provenance(r1_destination_upright, antecedent, a1).
provenance(r1_destination_upright, parent, none).
provenance(r1_destination_upright, simulations, 509).
provenance(r1_destination_upright, weight_mass_permille, 32104).
provenance(r1_destination_upright, confidence_permille, 1000).
provenance(r1_destination_upright, score_permille, 997).

rule(r1_source_clear, defeasible, source_clear).
body(r1_source_clear, pour_mid_height).
body(r1_source_clear, pour_near_rim).
body(r1_source_clear, pour_steeply_tilted).
learned(r1_source_clear).
provenance(r1_source_clear, antecedent, a1).
provenance(r1_source_clear, parent, none).
provenance(r1_source_clear, simulations, 509).
provenance(r1_source_clear, weight_mass_permille, 32104).
provenance(r1_source_clear, confidence_permille, 1000).
provenance(r1_source_clear, score_permille, 985).

rule(r1_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r1_liquid_leaves_source, pour_mid_height).
body(r1_liquid_leaves_source, pour_near_rim).
body(r1_liquid_leaves_source, pour_steeply_tilted).
learned(r1_liquid_leaves_source).
provenance(r1_liquid_leaves_source, antecedent, a1).
provenance(r1_liquid_leaves_source, parent, none).
provenance(r1_liquid_leaves_source, simulations, 509).
provenance(r1_liquid_leaves_source, weight_mass_permille, 32104).
provenance(r1_liquid_leaves_source, confidence_permille, 851).
provenance(r1_liquid_leaves_source, score_permille, 822).

rule(r1_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r1_liquid_enters_destination, pour_mid_height).
body(r1_liquid_enters_destination, pour_near_rim).
body(r1_liquid_enters_destination, pour_steeply_tilted).
learned(r1_liquid_enters_destination).
provenance(r1_liquid_enters_destination, antecedent, a1).
provenance(r1_liquid_enters_destination, parent, none).
provenance(r1_liquid_enters_destination, simulations, 509).
provenance(r1_liquid_enters_destination, weight_mass_permille, 32104).
provenance(r1_liquid_enters_destination, confidence_permille, 781).
provenance(r1_liquid_enters_destination, score_permille, 739).

rule(r1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r1_liquid_remains_in_destination, pour_mid_height).
body(r1_liquid_remains_in_destination, pour_near_rim).
body(r1_liquid_remains_in_destination, pour_steeply_tilted).
learned(r1_liquid_remains_in_destination).
provenance(r1_liquid_remains_in_destination, antecedent, a1).
provenance(r1_liquid_remains_in_destination, parent, none).
provenance(r1_liquid_remains_in_destination, simulations, 509).
provenance(r1_liquid_remains_in_destination, weight_mass_permille, 32104).
provenance(r1_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r1_liquid_remains_in_destination, score_permille, 993).

rule(r1_no_spill, defeasible, no_spill).
body(r1_no_spill, pour_mid_height).
body(r1_no_spill, pour_near_rim).
body(r1_no_spill, pour_steeply_tilted).
learned(r1_no_spill).
provenance(r1_no_spill, antecedent, a1).
provenance(r1_no_spill, parent, none).
provenance(r1_no_spill, simulations, 509).
provenance(r1_no_spill, weight_mass_permille, 32104).
provenance(r1_no_spill, confidence_permille, 966).
provenance(r1_no_spill, score_permille, 913).

rule(r2_destination_still_approach, defeasible, destination_still_approach).
body(r2_destination_still_approach, pour_mid_height).
body(r2_destination_still_approach, pour_near_rim).
body(r2_destination_still_approach, pour_steeply_tilted).
body(r2_destination_still_approach, slippery_destination).
learned(r2_destination_still_approach).
provenance(r2_destination_still_approach, antecedent, a2).
provenance(r2_destination_still_approach, parent, a1).
provenance(r2_destination_still_approach, simulations, 455).
provenance(r2_destination_still_approach, weight_mass_permille, 27611).
provenance(r2_destination_still_approach, confidence_permille, 946).
provenance(r2_destination_still_approach, score_permille, 919).
provenance(r2_destination_still_approach, followed, liquid_enters_destination).
provenance(r2_destination_still_approach, direction, destination_friction).
provenance(r2_destination_still_approach, sign, down).

rule(r2_destination_still_retreat, defeasible, destination_still_retreat).
body(r2_destination_still_retreat, pour_mid_height).
body(r2_destination_still_retreat, pour_near_rim).
body(r2_destination_still_retreat, pour_steeply_tilted).
body(r2_destination_still_retreat, slippery_destination).
learned(r2_destination_still_retreat).
provenance(r2_destination_still_retreat, antecedent, a2).
provenance(r2_destination_still_retreat, parent, a1).
provenance(r2_destination_still_retreat, simulations, 455).
provenance(r2_destination_still_retreat, weight_mass_permille, 27611).
provenance(r2_destination_still_retreat, confidence_permille, 962).
provenance(r2_destination_still_retreat, score_permille, 946).
provenance(r2_destination_still_retreat, followed, liquid_enters_destination).
provenance(r2_destination_still_retreat, direction, destination_friction).
provenance(r2_destination_still_retreat, sign, down).

rule(r2_destination_still_settle, defeasible, destination_still_settle).
body(r2_destination_still_settle, pour_mid_height).
body(r2_destination_still_settle, pour_near_rim).
body(r2_destination_still_settle, pour_steeply_tilted).
body(r2_destination_still_settle, slippery_destination).
learned(r2_destination_still_settle).
provenance(r2_destination_still_settle, antecedent, a2).
provenance(r2_destination_still_settle, parent, a1).
provenance(r2_destination_still_settle, simulations, 455).
provenance(r2_destination_still_settle, weight_mass_permille, 27611).
provenance(r2_destination_still_settle, confidence_permille, 999).
provenance(r2_destination_still_settle, score_permille, 995).
provenance(r2_destination_still_settle, followed, liquid_enters_destination).
provenance(r2_destination_still_settle, direction, destination_friction).
provenance(r2_destination_still_settle, sign, down).

rule(r2_destination_upright, defeasible, destination_upright).
body(r2_destination_upright, pour_mid_height).
body(r2_destination_upright, pour_near_rim).
body(r2_destination_upright, pour_steeply_tilted).
body(r2_destination_upright, slippery_destination).
learned(r2_destination_upright).
provenance(r2_destination_upright, antecedent, a2).
provenance(r2_destination_upright, parent, a1).
provenance(r2_destination_upright, simulations, 455).
provenance(r2_destination_upright, weight_mass_permille, 27611).
provenance(r2_destination_upright, confidence_permille, 1000).
provenance(r2_destination_upright, score_permille, 999).
provenance(r2_destination_upright, followed, liquid_enters_destination).
provenance(r2_destination_upright, direction, destination_friction).
provenance(r2_destination_upright, sign, down).

rule(r2_source_clear, defeasible, source_clear).
body(r2_source_clear, pour_mid_height).
body(r2_source_clear, pour_near_rim).
body(r2_source_clear, pour_steeply_tilted).
body(r2_source_clear, slippery_destination).
learned(r2_source_clear).
provenance(r2_source_clear, antecedent, a2).
provenance(r2_source_clear, parent, a1).
provenance(r2_source_clear, simulations, 455).
provenance(r2_source_clear, weight_mass_permille, 27611).
provenance(r2_source_clear, confidence_permille, 1000).
provenance(r2_source_clear, score_permille, 977).
provenance(r2_source_clear, followed, liquid_enters_destination).
provenance(r2_source_clear, direction, destination_friction).
provenance(r2_source_clear, sign, down).

rule(r2_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r2_liquid_leaves_source, pour_mid_height).
body(r2_liquid_leaves_source, pour_near_rim).
body(r2_liquid_leaves_source, pour_steeply_tilted).
body(r2_liquid_leaves_source, slippery_destination).
learned(r2_liquid_leaves_source).
provenance(r2_liquid_leaves_source, antecedent, a2).
provenance(r2_liquid_leaves_source, parent, a1).
provenance(r2_liquid_leaves_source, simulations, 455).
provenance(r2_liquid_leaves_source, weight_mass_permille, 27611).
provenance(r2_liquid_leaves_source, confidence_permille, 827).
provenance(r2_liquid_leaves_source, score_permille, 804).
provenance(r2_liquid_leaves_source, followed, liquid_enters_destination).
provenance(r2_liquid_leaves_source, direction, destination_friction).
provenance(r2_liquid_leaves_source, sign, down).

rule(r2_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r2_liquid_enters_destination, pour_mid_height).
body(r2_liquid_enters_destination, pour_near_rim).
body(r2_liquid_enters_destination, pour_steeply_tilted).
body(r2_liquid_enters_destination, slippery_destination).
learned(r2_liquid_enters_destination).
provenance(r2_liquid_enters_destination, antecedent, a2).
provenance(r2_liquid_enters_destination, parent, a1).
provenance(r2_liquid_enters_destination, simulations, 455).
provenance(r2_liquid_enters_destination, weight_mass_permille, 27611).
provenance(r2_liquid_enters_destination, confidence_permille, 766).
provenance(r2_liquid_enters_destination, score_permille, 718).
provenance(r2_liquid_enters_destination, followed, liquid_enters_destination).
provenance(r2_liquid_enters_destination, direction, destination_friction).
provenance(r2_liquid_enters_destination, sign, down).

rule(r2_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r2_liquid_remains_in_destination, pour_mid_height).
body(r2_liquid_remains_in_destination, pour_near_rim).
body(r2_liquid_remains_in_destination, pour_steeply_tilted).
body(r2_liquid_remains_in_destination, slippery_destination).
learned(r2_liquid_remains_in_destination).
provenance(r2_liquid_remains_in_destination, antecedent, a2).
provenance(r2_liquid_remains_in_destination, parent, a1).
provenance(r2_liquid_remains_in_destination, simulations, 455).
provenance(r2_liquid_remains_in_destination, weight_mass_permille, 27611).
provenance(r2_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r2_liquid_remains_in_destination, score_permille, 985).
provenance(r2_liquid_remains_in_destination, followed, liquid_enters_destination).
provenance(r2_liquid_remains_in_destination, direction, destination_friction).
provenance(r2_liquid_remains_in_destination, sign, down).

rule(r2_no_spill, defeasible, no_spill).
body(r2_no_spill, pour_mid_height).
body(r2_no_spill, pour_near_rim).
body(r2_no_spill, pour_steeply_tilted).
body(r2_no_spill, slippery_destination).
learned(r2_no_spill).
provenance(r2_no_spill, antecedent, a2).
provenance(r2_no_spill, parent, a1).
provenance(r2_no_spill, simulations, 455).
provenance(r2_no_spill, weight_mass_permille, 27611).
provenance(r2_no_spill, confidence_permille, 971).
provenance(r2_no_spill, score_permille, 901).
provenance(r2_no_spill, followed, liquid_enters_destination).
provenance(r2_no_spill, direction, destination_friction).
provenance(r2_no_spill, sign, down).

rule(r3_destination_still_approach, defeasible, destination_still_approach).
body(r3_destination_still_approach, bouncy_destination).
body(r3_destination_still_approach, pour_mid_height).
body(r3_destination_still_approach, pour_near_rim).
body(r3_destination_still_approach, pour_steeply_tilted).
learned(r3_destination_still_approach).
provenance(r3_destination_still_approach, antecedent, a3).
provenance(r3_destination_still_approach, parent, a1).
provenance(r3_destination_still_approach, simulations, 226).
provenance(r3_destination_still_approach, weight_mass_permille, 29653).
provenance(r3_destination_still_approach, confidence_permille, 998).
provenance(r3_destination_still_approach, score_permille, 971).
provenance(r3_destination_still_approach, followed, liquid_enters_destination).
provenance(r3_destination_still_approach, direction, destination_restitution).
provenance(r3_destination_still_approach, sign, up).

rule(r3_destination_still_retreat, defeasible, destination_still_retreat).
body(r3_destination_still_retreat, bouncy_destination).
body(r3_destination_still_retreat, pour_mid_height).
body(r3_destination_still_retreat, pour_near_rim).
body(r3_destination_still_retreat, pour_steeply_tilted).
learned(r3_destination_still_retreat).
provenance(r3_destination_still_retreat, antecedent, a3).
provenance(r3_destination_still_retreat, parent, a1).
provenance(r3_destination_still_retreat, simulations, 226).
provenance(r3_destination_still_retreat, weight_mass_permille, 29653).
provenance(r3_destination_still_retreat, confidence_permille, 998).
provenance(r3_destination_still_retreat, score_permille, 983).
provenance(r3_destination_still_retreat, followed, liquid_enters_destination).
provenance(r3_destination_still_retreat, direction, destination_restitution).
provenance(r3_destination_still_retreat, sign, up).

rule(r3_destination_still_settle, defeasible, destination_still_settle).
body(r3_destination_still_settle, bouncy_destination).
body(r3_destination_still_settle, pour_mid_height).
body(r3_destination_still_settle, pour_near_rim).
body(r3_destination_still_settle, pour_steeply_tilted).
learned(r3_destination_still_settle).
provenance(r3_destination_still_settle, antecedent, a3).
provenance(r3_destination_still_settle, parent, a1).
provenance(r3_destination_still_settle, simulations, 226).
provenance(r3_destination_still_settle, weight_mass_permille, 29653).
provenance(r3_destination_still_settle, confidence_permille, 1000).
provenance(r3_destination_still_settle, score_permille, 999).
provenance(r3_destination_still_settle, followed, liquid_enters_destination).
provenance(r3_destination_still_settle, direction, destination_restitution).
provenance(r3_destination_still_settle, sign, up).

rule(r3_destination_upright, defeasible, destination_upright).
body(r3_destination_upright, bouncy_destination).
body(r3_destination_upright, pour_mid_height).
body(r3_destination_upright, pour_near_rim).
body(r3_destination_upright, pour_steeply_tilted).
learned(r3_destination_upright).
provenance(r3_destination_upright, antecedent, a3).
provenance(r3_destination_upright, parent, a1).
provenance(r3_destination_upright, simulations, 226).
provenance(r3_destination_upright, weight_mass_permille, 29653).
provenance(r3_destination_upright, confidence_permille, 1000).
provenance(r3_destination_upright, score_permille, 1000).
provenance(r3_destination_upright, followed, liquid_enters_destination).
provenance(r3_destination_upright, direction, destination_restitution).
provenance(r3_destination_upright, sign, up).

rule(r3_source_clear, defeasible, source_clear).
body(r3_source_clear, bouncy_destination).
body(r3_source_clear, pour_mid_height).
body(r3_source_clear, pour_near_rim).
body(r3_source_clear, pour_steeply_tilted).
learned(r3_source_clear).
provenance(r3_source_clear, antecedent, a3).
provenance(r3_source_clear, parent, a1).
provenance(r3_source_clear, simulations, 226).
provenance(r3_source_clear, weight_mass_permille, 29653).
provenance(r3_source_clear, confidence_permille, 1000).
provenance(r3_source_clear, score_permille, 997).
provenance(r3_source_clear, followed, liquid_enters_destination).
provenance(r3_source_clear, direction, destination_restitution).
provenance(r3_source_clear, sign, up).

rule(r3_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r3_liquid_leaves_source, bouncy_destination).
body(r3_liquid_leaves_source, pour_mid_height).
body(r3_liquid_leaves_source, pour_near_rim).
body(r3_liquid_leaves_source, pour_steeply_tilted).
learned(r3_liquid_leaves_source).
provenance(r3_liquid_leaves_source, antecedent, a3).
provenance(r3_liquid_leaves_source, parent, a1).
provenance(r3_liquid_leaves_source, simulations, 226).
provenance(r3_liquid_leaves_source, weight_mass_permille, 29653).
provenance(r3_liquid_leaves_source, confidence_permille, 777).
provenance(r3_liquid_leaves_source, score_permille, 732).
provenance(r3_liquid_leaves_source, followed, liquid_enters_destination).
provenance(r3_liquid_leaves_source, direction, destination_restitution).
provenance(r3_liquid_leaves_source, sign, up).

rule(r3_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r3_liquid_enters_destination, bouncy_destination).
body(r3_liquid_enters_destination, pour_mid_height).
body(r3_liquid_enters_destination, pour_near_rim).
body(r3_liquid_enters_destination, pour_steeply_tilted).
learned(r3_liquid_enters_destination).
provenance(r3_liquid_enters_destination, antecedent, a3).
provenance(r3_liquid_enters_destination, parent, a1).
provenance(r3_liquid_enters_destination, simulations, 226).
provenance(r3_liquid_enters_destination, weight_mass_permille, 29653).
provenance(r3_liquid_enters_destination, confidence_permille, 766).
provenance(r3_liquid_enters_destination, score_permille, 650).
provenance(r3_liquid_enters_destination, followed, liquid_enters_destination).
provenance(r3_liquid_enters_destination, direction, destination_restitution).
provenance(r3_liquid_enters_destination, sign, up).

rule(r3_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r3_liquid_remains_in_destination, bouncy_destination).
body(r3_liquid_remains_in_destination, pour_mid_height).
body(r3_liquid_remains_in_destination, pour_near_rim).
body(r3_liquid_remains_in_destination, pour_steeply_tilted).
learned(r3_liquid_remains_in_destination).
provenance(r3_liquid_remains_in_destination, antecedent, a3).
provenance(r3_liquid_remains_in_destination, parent, a1).
provenance(r3_liquid_remains_in_destination, simulations, 226).
provenance(r3_liquid_remains_in_destination, weight_mass_permille, 29653).
provenance(r3_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r3_liquid_remains_in_destination, score_permille, 986).
provenance(r3_liquid_remains_in_destination, followed, liquid_enters_destination).
provenance(r3_liquid_remains_in_destination, direction, destination_restitution).
provenance(r3_liquid_remains_in_destination, sign, up).

rule(r3_no_spill, defeasible, no_spill).
body(r3_no_spill, bouncy_destination).
body(r3_no_spill, pour_mid_height).
body(r3_no_spill, pour_near_rim).
body(r3_no_spill, pour_steeply_tilted).
learned(r3_no_spill).
provenance(r3_no_spill, antecedent, a3).
provenance(r3_no_spill, parent, a1).
provenance(r3_no_spill, simulations, 226).
provenance(r3_no_spill, weight_mass_permille, 29653).
provenance(r3_no_spill, confidence_permille, 999).
provenance(r3_no_spill, score_permille, 907).
provenance(r3_no_spill, followed, liquid_enters_destination).
provenance(r3_no_spill, direction, destination_restitution).
provenance(r3_no_spill, sign, up).

rule(r4_destination_still_approach, defeasible, destination_still_approach).
body(r4_destination_still_approach, dull_liquid).
body(r4_destination_still_approach, pour_mid_height).
body(r4_destination_still_approach, pour_near_rim).
body(r4_destination_still_approach, pour_steeply_tilted).
body(r4_destination_still_approach, slippery_destination).
learned(r4_destination_still_approach).
provenance(r4_destination_still_approach, antecedent, a4).
provenance(r4_destination_still_approach, parent, a2).
provenance(r4_destination_still_approach, simulations, 224).
provenance(r4_destination_still_approach, weight_mass_permille, 33347).
provenance(r4_destination_still_approach, confidence_permille, 977).
provenance(r4_destination_still_approach, score_permille, 959).
provenance(r4_destination_still_approach, followed, liquid_leaves_source).
provenance(r4_destination_still_approach, direction, particle_restitution).
provenance(r4_destination_still_approach, sign, down).

rule(r4_destination_still_retreat, defeasible, destination_still_retreat).
body(r4_destination_still_retreat, dull_liquid).
body(r4_destination_still_retreat, pour_mid_height).
body(r4_destination_still_retreat, pour_near_rim).
body(r4_destination_still_retreat, pour_steeply_tilted).
body(r4_destination_still_retreat, slippery_destination).
learned(r4_destination_still_retreat).
provenance(r4_destination_still_retreat, antecedent, a4).
provenance(r4_destination_still_retreat, parent, a2).
provenance(r4_destination_still_retreat, simulations, 224).
provenance(r4_destination_still_retreat, weight_mass_permille, 33347).
provenance(r4_destination_still_retreat, confidence_permille, 936).
provenance(r4_destination_still_retreat, score_permille, 927).
provenance(r4_destination_still_retreat, followed, liquid_leaves_source).
provenance(r4_destination_still_retreat, direction, particle_restitution).
provenance(r4_destination_still_retreat, sign, down).

rule(r4_destination_still_settle, defeasible, destination_still_settle).
body(r4_destination_still_settle, dull_liquid).
body(r4_destination_still_settle, pour_mid_height).
body(r4_destination_still_settle, pour_near_rim).
body(r4_destination_still_settle, pour_steeply_tilted).
body(r4_destination_still_settle, slippery_destination).
learned(r4_destination_still_settle).
provenance(r4_destination_still_settle, antecedent, a4).
provenance(r4_destination_still_settle, parent, a2).
provenance(r4_destination_still_settle, simulations, 224).
provenance(r4_destination_still_settle, weight_mass_permille, 33347).
provenance(r4_destination_still_settle, confidence_permille, 997).
provenance(r4_destination_still_settle, score_permille, 983).
provenance(r4_destination_still_settle, followed, liquid_leaves_source).
provenance(r4_destination_still_settle, direction, particle_restitution).
provenance(r4_destination_still_settle, sign, down).

rule(r4_destination_upright, defeasible, destination_upright).
body(r4_destination_upright, dull_liquid).
body(r4_destination_upright, pour_mid_height).
body(r4_destination_upright, pour_near_rim).
body(r4_destination_upright, pour_steeply_tilted).
body(r4_destination_upright, slippery_destination).
learned(r4_destination_upright).
provenance(r4_destination_upright, antecedent, a4).
provenance(r4_destination_upright, parent, a2).
provenance(r4_destination_upright, simulations, 224).
provenance(r4_destination_upright, weight_mass_permille, 33347).
provenance(r4_destination_upright, confidence_permille, 1000).
provenance(r4_destination_upright, score_permille, 997).
provenance(r4_destination_upright, followed, liquid_leaves_source).
provenance(r4_destination_upright, direction, particle_restitution).
provenance(r4_destination_upright, sign, down).

rule(r4_source_clear, defeasible, source_clear).
body(r4_source_clear, dull_liquid).
body(r4_source_clear, pour_mid_height).
body(r4_source_clear, pour_near_rim).
body(r4_source_clear, pour_steeply_tilted).
body(r4_source_clear, slippery_destination).
learned(r4_source_clear).
provenance(r4_source_clear, antecedent, a4).
provenance(r4_source_clear, parent, a2).
provenance(r4_source_clear, simulations, 224).
provenance(r4_source_clear, weight_mass_permille, 33347).
provenance(r4_source_clear, confidence_permille, 998).
provenance(r4_source_clear, score_permille, 997).
provenance(r4_source_clear, followed, liquid_leaves_source).
provenance(r4_source_clear, direction, particle_restitution).
provenance(r4_source_clear, sign, down).

rule(r4_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r4_liquid_leaves_source, dull_liquid).
body(r4_liquid_leaves_source, pour_mid_height).
body(r4_liquid_leaves_source, pour_near_rim).
body(r4_liquid_leaves_source, pour_steeply_tilted).
body(r4_liquid_leaves_source, slippery_destination).
learned(r4_liquid_leaves_source).
provenance(r4_liquid_leaves_source, antecedent, a4).
provenance(r4_liquid_leaves_source, parent, a2).
provenance(r4_liquid_leaves_source, simulations, 224).
provenance(r4_liquid_leaves_source, weight_mass_permille, 33347).
provenance(r4_liquid_leaves_source, confidence_permille, 736).
provenance(r4_liquid_leaves_source, score_permille, 731).
provenance(r4_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r4_liquid_leaves_source, direction, particle_restitution).
provenance(r4_liquid_leaves_source, sign, down).

rule(r4_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r4_liquid_enters_destination, dull_liquid).
body(r4_liquid_enters_destination, pour_mid_height).
body(r4_liquid_enters_destination, pour_near_rim).
body(r4_liquid_enters_destination, pour_steeply_tilted).
body(r4_liquid_enters_destination, slippery_destination).
learned(r4_liquid_enters_destination).
provenance(r4_liquid_enters_destination, antecedent, a4).
provenance(r4_liquid_enters_destination, parent, a2).
provenance(r4_liquid_enters_destination, simulations, 224).
provenance(r4_liquid_enters_destination, weight_mass_permille, 33347).
provenance(r4_liquid_enters_destination, confidence_permille, 673).
provenance(r4_liquid_enters_destination, score_permille, 661).
provenance(r4_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r4_liquid_enters_destination, direction, particle_restitution).
provenance(r4_liquid_enters_destination, sign, down).

rule(r4_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r4_liquid_remains_in_destination, dull_liquid).
body(r4_liquid_remains_in_destination, pour_mid_height).
body(r4_liquid_remains_in_destination, pour_near_rim).
body(r4_liquid_remains_in_destination, pour_steeply_tilted).
body(r4_liquid_remains_in_destination, slippery_destination).
learned(r4_liquid_remains_in_destination).
provenance(r4_liquid_remains_in_destination, antecedent, a4).
provenance(r4_liquid_remains_in_destination, parent, a2).
provenance(r4_liquid_remains_in_destination, simulations, 224).
provenance(r4_liquid_remains_in_destination, weight_mass_permille, 33347).
provenance(r4_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r4_liquid_remains_in_destination, score_permille, 997).
provenance(r4_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r4_liquid_remains_in_destination, direction, particle_restitution).
provenance(r4_liquid_remains_in_destination, sign, down).

rule(r4_no_spill, defeasible, no_spill).
body(r4_no_spill, dull_liquid).
body(r4_no_spill, pour_mid_height).
body(r4_no_spill, pour_near_rim).
body(r4_no_spill, pour_steeply_tilted).
body(r4_no_spill, slippery_destination).
learned(r4_no_spill).
provenance(r4_no_spill, antecedent, a4).
provenance(r4_no_spill, parent, a2).
provenance(r4_no_spill, simulations, 224).
provenance(r4_no_spill, weight_mass_permille, 33347).
provenance(r4_no_spill, confidence_permille, 951).
provenance(r4_no_spill, score_permille, 928).
provenance(r4_no_spill, followed, liquid_leaves_source).
provenance(r4_no_spill, direction, particle_restitution).
provenance(r4_no_spill, sign, down).

rule(r5_destination_still_approach, defeasible, destination_still_approach).
body(r5_destination_still_approach, light_source).
body(r5_destination_still_approach, pour_mid_height).
body(r5_destination_still_approach, pour_near_rim).
body(r5_destination_still_approach, pour_steeply_tilted).
body(r5_destination_still_approach, slippery_destination).
learned(r5_destination_still_approach).
provenance(r5_destination_still_approach, antecedent, a5).
provenance(r5_destination_still_approach, parent, a2).
provenance(r5_destination_still_approach, simulations, 238).
provenance(r5_destination_still_approach, weight_mass_permille, 31993).
provenance(r5_destination_still_approach, confidence_permille, 937).
provenance(r5_destination_still_approach, score_permille, 915).
provenance(r5_destination_still_approach, followed, liquid_leaves_source).
provenance(r5_destination_still_approach, direction, source_mass).
provenance(r5_destination_still_approach, sign, down).

rule(r5_destination_still_retreat, defeasible, destination_still_retreat).
body(r5_destination_still_retreat, light_source).
body(r5_destination_still_retreat, pour_mid_height).
body(r5_destination_still_retreat, pour_near_rim).
body(r5_destination_still_retreat, pour_steeply_tilted).
body(r5_destination_still_retreat, slippery_destination).
learned(r5_destination_still_retreat).
provenance(r5_destination_still_retreat, antecedent, a5).
provenance(r5_destination_still_retreat, parent, a2).
provenance(r5_destination_still_retreat, simulations, 238).
provenance(r5_destination_still_retreat, weight_mass_permille, 31993).
provenance(r5_destination_still_retreat, confidence_permille, 958).
provenance(r5_destination_still_retreat, score_permille, 944).
provenance(r5_destination_still_retreat, followed, liquid_leaves_source).
provenance(r5_destination_still_retreat, direction, source_mass).
provenance(r5_destination_still_retreat, sign, down).

rule(r5_destination_still_settle, defeasible, destination_still_settle).
body(r5_destination_still_settle, light_source).
body(r5_destination_still_settle, pour_mid_height).
body(r5_destination_still_settle, pour_near_rim).
body(r5_destination_still_settle, pour_steeply_tilted).
body(r5_destination_still_settle, slippery_destination).
learned(r5_destination_still_settle).
provenance(r5_destination_still_settle, antecedent, a5).
provenance(r5_destination_still_settle, parent, a2).
provenance(r5_destination_still_settle, simulations, 238).
provenance(r5_destination_still_settle, weight_mass_permille, 31993).
provenance(r5_destination_still_settle, confidence_permille, 999).
provenance(r5_destination_still_settle, score_permille, 996).
provenance(r5_destination_still_settle, followed, liquid_leaves_source).
provenance(r5_destination_still_settle, direction, source_mass).
provenance(r5_destination_still_settle, sign, down).

rule(r5_destination_upright, defeasible, destination_upright).
body(r5_destination_upright, light_source).
body(r5_destination_upright, pour_mid_height).
body(r5_destination_upright, pour_near_rim).
body(r5_destination_upright, pour_steeply_tilted).
body(r5_destination_upright, slippery_destination).
learned(r5_destination_upright).
provenance(r5_destination_upright, antecedent, a5).
provenance(r5_destination_upright, parent, a2).
provenance(r5_destination_upright, simulations, 238).
provenance(r5_destination_upright, weight_mass_permille, 31993).
provenance(r5_destination_upright, confidence_permille, 1000).
provenance(r5_destination_upright, score_permille, 999).
provenance(r5_destination_upright, followed, liquid_leaves_source).
provenance(r5_destination_upright, direction, source_mass).
provenance(r5_destination_upright, sign, down).

rule(r5_source_clear, defeasible, source_clear).
body(r5_source_clear, light_source).
body(r5_source_clear, pour_mid_height).
body(r5_source_clear, pour_near_rim).
body(r5_source_clear, pour_steeply_tilted).
body(r5_source_clear, slippery_destination).
learned(r5_source_clear).
provenance(r5_source_clear, antecedent, a5).
provenance(r5_source_clear, parent, a2).
provenance(r5_source_clear, simulations, 238).
provenance(r5_source_clear, weight_mass_permille, 31993).
provenance(r5_source_clear, confidence_permille, 1000).
provenance(r5_source_clear, score_permille, 996).
provenance(r5_source_clear, followed, liquid_leaves_source).
provenance(r5_source_clear, direction, source_mass).
provenance(r5_source_clear, sign, down).

rule(r5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r5_liquid_leaves_source, light_source).
body(r5_liquid_leaves_source, pour_mid_height).
body(r5_liquid_leaves_source, pour_near_rim).
body(r5_liquid_leaves_source, pour_steeply_tilted).
body(r5_liquid_leaves_source, slippery_destination).
learned(r5_liquid_leaves_source).
provenance(r5_liquid_leaves_source, antecedent, a5).
provenance(r5_liquid_leaves_source, parent, a2).
provenance(r5_liquid_leaves_source, simulations, 238).
provenance(r5_liquid_leaves_source, weight_mass_permille, 31993).
provenance(r5_liquid_leaves_source, confidence_permille, 762).
provenance(r5_liquid_leaves_source, score_permille, 745).
provenance(r5_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r5_liquid_leaves_source, direction, source_mass).
provenance(r5_liquid_leaves_source, sign, down).

rule(r5_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r5_liquid_enters_destination, light_source).
body(r5_liquid_enters_destination, pour_mid_height).
body(r5_liquid_enters_destination, pour_near_rim).
body(r5_liquid_enters_destination, pour_steeply_tilted).
body(r5_liquid_enters_destination, slippery_destination).
learned(r5_liquid_enters_destination).
provenance(r5_liquid_enters_destination, antecedent, a5).
provenance(r5_liquid_enters_destination, parent, a2).
provenance(r5_liquid_enters_destination, simulations, 238).
provenance(r5_liquid_enters_destination, weight_mass_permille, 31993).
provenance(r5_liquid_enters_destination, confidence_permille, 695).
provenance(r5_liquid_enters_destination, score_permille, 663).
provenance(r5_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r5_liquid_enters_destination, direction, source_mass).
provenance(r5_liquid_enters_destination, sign, down).

rule(r5_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r5_liquid_remains_in_destination, light_source).
body(r5_liquid_remains_in_destination, pour_mid_height).
body(r5_liquid_remains_in_destination, pour_near_rim).
body(r5_liquid_remains_in_destination, pour_steeply_tilted).
body(r5_liquid_remains_in_destination, slippery_destination).
learned(r5_liquid_remains_in_destination).
provenance(r5_liquid_remains_in_destination, antecedent, a5).
provenance(r5_liquid_remains_in_destination, parent, a2).
provenance(r5_liquid_remains_in_destination, simulations, 238).
provenance(r5_liquid_remains_in_destination, weight_mass_permille, 31993).
provenance(r5_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r5_liquid_remains_in_destination, score_permille, 984).
provenance(r5_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r5_liquid_remains_in_destination, direction, source_mass).
provenance(r5_liquid_remains_in_destination, sign, down).

rule(r5_no_spill, defeasible, no_spill).
body(r5_no_spill, light_source).
body(r5_no_spill, pour_mid_height).
body(r5_no_spill, pour_near_rim).
body(r5_no_spill, pour_steeply_tilted).
body(r5_no_spill, slippery_destination).
learned(r5_no_spill).
provenance(r5_no_spill, antecedent, a5).
provenance(r5_no_spill, parent, a2).
provenance(r5_no_spill, simulations, 238).
provenance(r5_no_spill, weight_mass_permille, 31993).
provenance(r5_no_spill, confidence_permille, 941).
provenance(r5_no_spill, score_permille, 904).
provenance(r5_no_spill, followed, liquid_leaves_source).
provenance(r5_no_spill, direction, source_mass).
provenance(r5_no_spill, sign, down).

rule(r6_destination_still_approach, defeasible, destination_still_approach).
body(r6_destination_still_approach, pour_half_tilted).
body(r6_destination_still_approach, pour_mid_height).
body(r6_destination_still_approach, pour_near_rim).
body(r6_destination_still_approach, slippery_destination).
learned(r6_destination_still_approach).
provenance(r6_destination_still_approach, antecedent, a6).
provenance(r6_destination_still_approach, parent, a2).
provenance(r6_destination_still_approach, simulations, 155).
provenance(r6_destination_still_approach, weight_mass_permille, 30630).
provenance(r6_destination_still_approach, confidence_permille, 1000).
provenance(r6_destination_still_approach, score_permille, 992).
provenance(r6_destination_still_approach, followed, liquid_leaves_source).
provenance(r6_destination_still_approach, direction, pour_pitch).
provenance(r6_destination_still_approach, sign, down).

rule(r6_destination_still_retreat, defeasible, destination_still_retreat).
body(r6_destination_still_retreat, pour_half_tilted).
body(r6_destination_still_retreat, pour_mid_height).
body(r6_destination_still_retreat, pour_near_rim).
body(r6_destination_still_retreat, slippery_destination).
learned(r6_destination_still_retreat).
provenance(r6_destination_still_retreat, antecedent, a6).
provenance(r6_destination_still_retreat, parent, a2).
provenance(r6_destination_still_retreat, simulations, 155).
provenance(r6_destination_still_retreat, weight_mass_permille, 30630).
provenance(r6_destination_still_retreat, confidence_permille, 996).
provenance(r6_destination_still_retreat, score_permille, 992).
provenance(r6_destination_still_retreat, followed, liquid_leaves_source).
provenance(r6_destination_still_retreat, direction, pour_pitch).
provenance(r6_destination_still_retreat, sign, down).

rule(r6_destination_still_settle, defeasible, destination_still_settle).
body(r6_destination_still_settle, pour_half_tilted).
body(r6_destination_still_settle, pour_mid_height).
body(r6_destination_still_settle, pour_near_rim).
body(r6_destination_still_settle, slippery_destination).
learned(r6_destination_still_settle).
provenance(r6_destination_still_settle, antecedent, a6).
provenance(r6_destination_still_settle, parent, a2).
provenance(r6_destination_still_settle, simulations, 155).
provenance(r6_destination_still_settle, weight_mass_permille, 30630).
provenance(r6_destination_still_settle, confidence_permille, 1000).
provenance(r6_destination_still_settle, score_permille, 1000).
provenance(r6_destination_still_settle, followed, liquid_leaves_source).
provenance(r6_destination_still_settle, direction, pour_pitch).
provenance(r6_destination_still_settle, sign, down).

rule(r6_destination_upright, defeasible, destination_upright).
body(r6_destination_upright, pour_half_tilted).
body(r6_destination_upright, pour_mid_height).
body(r6_destination_upright, pour_near_rim).
body(r6_destination_upright, slippery_destination).
learned(r6_destination_upright).
provenance(r6_destination_upright, antecedent, a6).
provenance(r6_destination_upright, parent, a2).
provenance(r6_destination_upright, simulations, 155).
provenance(r6_destination_upright, weight_mass_permille, 30630).
provenance(r6_destination_upright, confidence_permille, 1000).
provenance(r6_destination_upright, score_permille, 1000).
provenance(r6_destination_upright, followed, liquid_leaves_source).
provenance(r6_destination_upright, direction, pour_pitch).
provenance(r6_destination_upright, sign, down).

rule(r6_source_clear, defeasible, source_clear).
body(r6_source_clear, pour_half_tilted).
body(r6_source_clear, pour_mid_height).
body(r6_source_clear, pour_near_rim).
body(r6_source_clear, slippery_destination).
learned(r6_source_clear).
provenance(r6_source_clear, antecedent, a6).
provenance(r6_source_clear, parent, a2).
provenance(r6_source_clear, simulations, 155).
provenance(r6_source_clear, weight_mass_permille, 30630).
provenance(r6_source_clear, confidence_permille, 1000).
provenance(r6_source_clear, score_permille, 1000).
provenance(r6_source_clear, followed, liquid_leaves_source).
provenance(r6_source_clear, direction, pour_pitch).
provenance(r6_source_clear, sign, down).

rule(r6_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r6_liquid_leaves_source, pour_half_tilted).
body(r6_liquid_leaves_source, pour_mid_height).
body(r6_liquid_leaves_source, pour_near_rim).
body(r6_liquid_leaves_source, slippery_destination).
learned(r6_liquid_leaves_source).
provenance(r6_liquid_leaves_source, antecedent, a6).
provenance(r6_liquid_leaves_source, parent, a2).
provenance(r6_liquid_leaves_source, simulations, 155).
provenance(r6_liquid_leaves_source, weight_mass_permille, 30630).
provenance(r6_liquid_leaves_source, confidence_permille, 984).
provenance(r6_liquid_leaves_source, score_permille, 32).
provenance(r6_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r6_liquid_leaves_source, direction, pour_pitch).
provenance(r6_liquid_leaves_source, sign, down).

rule(r6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r6_liquid_enters_destination, pour_half_tilted).
body(r6_liquid_enters_destination, pour_mid_height).
body(r6_liquid_enters_destination, pour_near_rim).
body(r6_liquid_enters_destination, slippery_destination).
learned(r6_liquid_enters_destination).
provenance(r6_liquid_enters_destination, antecedent, a6).
provenance(r6_liquid_enters_destination, parent, a2).
provenance(r6_liquid_enters_destination, simulations, 155).
provenance(r6_liquid_enters_destination, weight_mass_permille, 30630).
provenance(r6_liquid_enters_destination, confidence_permille, 993).
provenance(r6_liquid_enters_destination, score_permille, 27).
provenance(r6_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r6_liquid_enters_destination, direction, pour_pitch).
provenance(r6_liquid_enters_destination, sign, down).

rule(r6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r6_liquid_remains_in_destination, pour_half_tilted).
body(r6_liquid_remains_in_destination, pour_mid_height).
body(r6_liquid_remains_in_destination, pour_near_rim).
body(r6_liquid_remains_in_destination, slippery_destination).
learned(r6_liquid_remains_in_destination).
provenance(r6_liquid_remains_in_destination, antecedent, a6).
provenance(r6_liquid_remains_in_destination, parent, a2).
provenance(r6_liquid_remains_in_destination, simulations, 155).
provenance(r6_liquid_remains_in_destination, weight_mass_permille, 30630).
provenance(r6_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r6_liquid_remains_in_destination, score_permille, 998).
provenance(r6_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r6_liquid_remains_in_destination, direction, pour_pitch).
provenance(r6_liquid_remains_in_destination, sign, down).

rule(r6_no_spill, defeasible, no_spill).
body(r6_no_spill, pour_half_tilted).
body(r6_no_spill, pour_mid_height).
body(r6_no_spill, pour_near_rim).
body(r6_no_spill, slippery_destination).
learned(r6_no_spill).
provenance(r6_no_spill, antecedent, a6).
provenance(r6_no_spill, parent, a2).
provenance(r6_no_spill, simulations, 155).
provenance(r6_no_spill, weight_mass_permille, 30630).
provenance(r6_no_spill, confidence_permille, 1000).
provenance(r6_no_spill, score_permille, 995).
provenance(r6_no_spill, followed, liquid_leaves_source).
provenance(r6_no_spill, direction, pour_pitch).
provenance(r6_no_spill, sign, down).

rule(r7_destination_still_approach, defeasible, destination_still_approach).
body(r7_destination_still_approach, fast_approach).
body(r7_destination_still_approach, pour_mid_height).
body(r7_destination_still_approach, pour_near_rim).
body(r7_destination_still_approach, pour_steeply_tilted).
body(r7_destination_still_approach, slippery_destination).
learned(r7_destination_still_approach).
provenance(r7_destination_still_approach, antecedent, a7).
provenance(r7_destination_still_approach, parent, a2).
provenance(r7_destination_still_approach, simulations, 84).
provenance(r7_destination_still_approach, weight_mass_permille, 27533).
provenance(r7_destination_still_approach, confidence_permille, 1000).
provenance(r7_destination_still_approach, score_permille, 973).
provenance(r7_destination_still_approach, followed, liquid_leaves_source).
provenance(r7_destination_still_approach, direction, approach_duration).
provenance(r7_destination_still_approach, sign, down).

rule(r7_destination_still_retreat, defeasible, destination_still_retreat).
body(r7_destination_still_retreat, fast_approach).
body(r7_destination_still_retreat, pour_mid_height).
body(r7_destination_still_retreat, pour_near_rim).
body(r7_destination_still_retreat, pour_steeply_tilted).
body(r7_destination_still_retreat, slippery_destination).
learned(r7_destination_still_retreat).
provenance(r7_destination_still_retreat, antecedent, a7).
provenance(r7_destination_still_retreat, parent, a2).
provenance(r7_destination_still_retreat, simulations, 84).
provenance(r7_destination_still_retreat, weight_mass_permille, 27533).
provenance(r7_destination_still_retreat, confidence_permille, 863).
provenance(r7_destination_still_retreat, score_permille, 867).
provenance(r7_destination_still_retreat, followed, liquid_leaves_source).
provenance(r7_destination_still_retreat, direction, approach_duration).
provenance(r7_destination_still_retreat, sign, down).

rule(r7_destination_still_settle, defeasible, destination_still_settle).
body(r7_destination_still_settle, fast_approach).
body(r7_destination_still_settle, pour_mid_height).
body(r7_destination_still_settle, pour_near_rim).
body(r7_destination_still_settle, pour_steeply_tilted).
body(r7_destination_still_settle, slippery_destination).
learned(r7_destination_still_settle).
provenance(r7_destination_still_settle, antecedent, a7).
provenance(r7_destination_still_settle, parent, a2).
provenance(r7_destination_still_settle, simulations, 84).
provenance(r7_destination_still_settle, weight_mass_permille, 27533).
provenance(r7_destination_still_settle, confidence_permille, 996).
provenance(r7_destination_still_settle, score_permille, 992).
provenance(r7_destination_still_settle, followed, liquid_leaves_source).
provenance(r7_destination_still_settle, direction, approach_duration).
provenance(r7_destination_still_settle, sign, down).

rule(r7_destination_upright, defeasible, destination_upright).
body(r7_destination_upright, fast_approach).
body(r7_destination_upright, pour_mid_height).
body(r7_destination_upright, pour_near_rim).
body(r7_destination_upright, pour_steeply_tilted).
body(r7_destination_upright, slippery_destination).
learned(r7_destination_upright).
provenance(r7_destination_upright, antecedent, a7).
provenance(r7_destination_upright, parent, a2).
provenance(r7_destination_upright, simulations, 84).
provenance(r7_destination_upright, weight_mass_permille, 27533).
provenance(r7_destination_upright, confidence_permille, 1000).
provenance(r7_destination_upright, score_permille, 1000).
provenance(r7_destination_upright, followed, liquid_leaves_source).
provenance(r7_destination_upright, direction, approach_duration).
provenance(r7_destination_upright, sign, down).

rule(r7_source_clear, defeasible, source_clear).
body(r7_source_clear, fast_approach).
body(r7_source_clear, pour_mid_height).
body(r7_source_clear, pour_near_rim).
body(r7_source_clear, pour_steeply_tilted).
body(r7_source_clear, slippery_destination).
learned(r7_source_clear).
provenance(r7_source_clear, antecedent, a7).
provenance(r7_source_clear, parent, a2).
provenance(r7_source_clear, simulations, 84).
provenance(r7_source_clear, weight_mass_permille, 27533).
provenance(r7_source_clear, confidence_permille, 998).
provenance(r7_source_clear, score_permille, 996).
provenance(r7_source_clear, followed, liquid_leaves_source).
provenance(r7_source_clear, direction, approach_duration).
provenance(r7_source_clear, sign, down).

rule(r7_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r7_liquid_leaves_source, fast_approach).
body(r7_liquid_leaves_source, pour_mid_height).
body(r7_liquid_leaves_source, pour_near_rim).
body(r7_liquid_leaves_source, pour_steeply_tilted).
body(r7_liquid_leaves_source, slippery_destination).
learned(r7_liquid_leaves_source).
provenance(r7_liquid_leaves_source, antecedent, a7).
provenance(r7_liquid_leaves_source, parent, a2).
provenance(r7_liquid_leaves_source, simulations, 84).
provenance(r7_liquid_leaves_source, weight_mass_permille, 27533).
provenance(r7_liquid_leaves_source, confidence_permille, 778).
provenance(r7_liquid_leaves_source, score_permille, 769).
provenance(r7_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r7_liquid_leaves_source, direction, approach_duration).
provenance(r7_liquid_leaves_source, sign, down).

rule(r7_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r7_liquid_enters_destination, fast_approach).
body(r7_liquid_enters_destination, pour_mid_height).
body(r7_liquid_enters_destination, pour_near_rim).
body(r7_liquid_enters_destination, pour_steeply_tilted).
body(r7_liquid_enters_destination, slippery_destination).
learned(r7_liquid_enters_destination).
provenance(r7_liquid_enters_destination, antecedent, a7).
provenance(r7_liquid_enters_destination, parent, a2).
provenance(r7_liquid_enters_destination, simulations, 84).
provenance(r7_liquid_enters_destination, weight_mass_permille, 27533).
provenance(r7_liquid_enters_destination, confidence_permille, 681).
provenance(r7_liquid_enters_destination, score_permille, 676).
provenance(r7_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r7_liquid_enters_destination, direction, approach_duration).
provenance(r7_liquid_enters_destination, sign, down).

rule(r7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r7_liquid_remains_in_destination, fast_approach).
body(r7_liquid_remains_in_destination, pour_mid_height).
body(r7_liquid_remains_in_destination, pour_near_rim).
body(r7_liquid_remains_in_destination, pour_steeply_tilted).
body(r7_liquid_remains_in_destination, slippery_destination).
learned(r7_liquid_remains_in_destination).
provenance(r7_liquid_remains_in_destination, antecedent, a7).
provenance(r7_liquid_remains_in_destination, parent, a2).
provenance(r7_liquid_remains_in_destination, simulations, 84).
provenance(r7_liquid_remains_in_destination, weight_mass_permille, 27533).
provenance(r7_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r7_liquid_remains_in_destination, score_permille, 988).
provenance(r7_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r7_liquid_remains_in_destination, direction, approach_duration).
provenance(r7_liquid_remains_in_destination, sign, down).

rule(r7_no_spill, defeasible, no_spill).
body(r7_no_spill, fast_approach).
body(r7_no_spill, pour_mid_height).
body(r7_no_spill, pour_near_rim).
body(r7_no_spill, pour_steeply_tilted).
body(r7_no_spill, slippery_destination).
learned(r7_no_spill).
provenance(r7_no_spill, antecedent, a7).
provenance(r7_no_spill, parent, a2).
provenance(r7_no_spill, simulations, 84).
provenance(r7_no_spill, weight_mass_permille, 27533).
provenance(r7_no_spill, confidence_permille, 939).
provenance(r7_no_spill, score_permille, 898).
provenance(r7_no_spill, followed, liquid_leaves_source).
provenance(r7_no_spill, direction, approach_duration).
provenance(r7_no_spill, sign, down).

rule(r8_destination_still_approach, defeasible, destination_still_approach).
body(r8_destination_still_approach, moderate_approach).
body(r8_destination_still_approach, pour_mid_height).
body(r8_destination_still_approach, pour_near_rim).
body(r8_destination_still_approach, pour_steeply_tilted).
body(r8_destination_still_approach, slippery_destination).
learned(r8_destination_still_approach).
provenance(r8_destination_still_approach, antecedent, a8).
provenance(r8_destination_still_approach, parent, a2).
provenance(r8_destination_still_approach, simulations, 127).
provenance(r8_destination_still_approach, weight_mass_permille, 26403).
provenance(r8_destination_still_approach, confidence_permille, 958).
provenance(r8_destination_still_approach, score_permille, 949).
provenance(r8_destination_still_approach, followed, liquid_leaves_source).
provenance(r8_destination_still_approach, direction, approach_duration).
provenance(r8_destination_still_approach, sign, down).

rule(r8_destination_still_retreat, defeasible, destination_still_retreat).
body(r8_destination_still_retreat, moderate_approach).
body(r8_destination_still_retreat, pour_mid_height).
body(r8_destination_still_retreat, pour_near_rim).
body(r8_destination_still_retreat, pour_steeply_tilted).
body(r8_destination_still_retreat, slippery_destination).
learned(r8_destination_still_retreat).
provenance(r8_destination_still_retreat, antecedent, a8).
provenance(r8_destination_still_retreat, parent, a2).
provenance(r8_destination_still_retreat, simulations, 127).
provenance(r8_destination_still_retreat, weight_mass_permille, 26403).
provenance(r8_destination_still_retreat, confidence_permille, 963).
provenance(r8_destination_still_retreat, score_permille, 957).
provenance(r8_destination_still_retreat, followed, liquid_leaves_source).
provenance(r8_destination_still_retreat, direction, approach_duration).
provenance(r8_destination_still_retreat, sign, down).

rule(r8_destination_still_settle, defeasible, destination_still_settle).
body(r8_destination_still_settle, moderate_approach).
body(r8_destination_still_settle, pour_mid_height).
body(r8_destination_still_settle, pour_near_rim).
body(r8_destination_still_settle, pour_steeply_tilted).
body(r8_destination_still_settle, slippery_destination).
learned(r8_destination_still_settle).
provenance(r8_destination_still_settle, antecedent, a8).
provenance(r8_destination_still_settle, parent, a2).
provenance(r8_destination_still_settle, simulations, 127).
provenance(r8_destination_still_settle, weight_mass_permille, 26403).
provenance(r8_destination_still_settle, confidence_permille, 1000).
provenance(r8_destination_still_settle, score_permille, 996).
provenance(r8_destination_still_settle, followed, liquid_leaves_source).
provenance(r8_destination_still_settle, direction, approach_duration).
provenance(r8_destination_still_settle, sign, down).

rule(r8_destination_upright, defeasible, destination_upright).
body(r8_destination_upright, moderate_approach).
body(r8_destination_upright, pour_mid_height).
body(r8_destination_upright, pour_near_rim).
body(r8_destination_upright, pour_steeply_tilted).
body(r8_destination_upright, slippery_destination).
learned(r8_destination_upright).
provenance(r8_destination_upright, antecedent, a8).
provenance(r8_destination_upright, parent, a2).
provenance(r8_destination_upright, simulations, 127).
provenance(r8_destination_upright, weight_mass_permille, 26403).
provenance(r8_destination_upright, confidence_permille, 1000).
provenance(r8_destination_upright, score_permille, 1000).
provenance(r8_destination_upright, followed, liquid_leaves_source).
provenance(r8_destination_upright, direction, approach_duration).
provenance(r8_destination_upright, sign, down).

rule(r8_source_clear, defeasible, source_clear).
body(r8_source_clear, moderate_approach).
body(r8_source_clear, pour_mid_height).
body(r8_source_clear, pour_near_rim).
body(r8_source_clear, pour_steeply_tilted).
body(r8_source_clear, slippery_destination).
learned(r8_source_clear).
provenance(r8_source_clear, antecedent, a8).
provenance(r8_source_clear, parent, a2).
provenance(r8_source_clear, simulations, 127).
provenance(r8_source_clear, weight_mass_permille, 26403).
provenance(r8_source_clear, confidence_permille, 1000).
provenance(r8_source_clear, score_permille, 995).
provenance(r8_source_clear, followed, liquid_leaves_source).
provenance(r8_source_clear, direction, approach_duration).
provenance(r8_source_clear, sign, down).

rule(r8_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r8_liquid_leaves_source, moderate_approach).
body(r8_liquid_leaves_source, pour_mid_height).
body(r8_liquid_leaves_source, pour_near_rim).
body(r8_liquid_leaves_source, pour_steeply_tilted).
body(r8_liquid_leaves_source, slippery_destination).
learned(r8_liquid_leaves_source).
provenance(r8_liquid_leaves_source, antecedent, a8).
provenance(r8_liquid_leaves_source, parent, a2).
provenance(r8_liquid_leaves_source, simulations, 127).
provenance(r8_liquid_leaves_source, weight_mass_permille, 26403).
provenance(r8_liquid_leaves_source, confidence_permille, 695).
provenance(r8_liquid_leaves_source, score_permille, 691).
provenance(r8_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r8_liquid_leaves_source, direction, approach_duration).
provenance(r8_liquid_leaves_source, sign, down).

rule(r8_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r8_liquid_enters_destination, moderate_approach).
body(r8_liquid_enters_destination, pour_mid_height).
body(r8_liquid_enters_destination, pour_near_rim).
body(r8_liquid_enters_destination, pour_steeply_tilted).
body(r8_liquid_enters_destination, slippery_destination).
learned(r8_liquid_enters_destination).
provenance(r8_liquid_enters_destination, antecedent, a8).
provenance(r8_liquid_enters_destination, parent, a2).
provenance(r8_liquid_enters_destination, simulations, 127).
provenance(r8_liquid_enters_destination, weight_mass_permille, 26403).
provenance(r8_liquid_enters_destination, confidence_permille, 686).
provenance(r8_liquid_enters_destination, score_permille, 622).
provenance(r8_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r8_liquid_enters_destination, direction, approach_duration).
provenance(r8_liquid_enters_destination, sign, down).

rule(r8_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r8_liquid_remains_in_destination, moderate_approach).
body(r8_liquid_remains_in_destination, pour_mid_height).
body(r8_liquid_remains_in_destination, pour_near_rim).
body(r8_liquid_remains_in_destination, pour_steeply_tilted).
body(r8_liquid_remains_in_destination, slippery_destination).
learned(r8_liquid_remains_in_destination).
provenance(r8_liquid_remains_in_destination, antecedent, a8).
provenance(r8_liquid_remains_in_destination, parent, a2).
provenance(r8_liquid_remains_in_destination, simulations, 127).
provenance(r8_liquid_remains_in_destination, weight_mass_permille, 26403).
provenance(r8_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r8_liquid_remains_in_destination, score_permille, 989).
provenance(r8_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r8_liquid_remains_in_destination, direction, approach_duration).
provenance(r8_liquid_remains_in_destination, sign, down).

rule(r8_no_spill, defeasible, no_spill).
body(r8_no_spill, moderate_approach).
body(r8_no_spill, pour_mid_height).
body(r8_no_spill, pour_near_rim).
body(r8_no_spill, pour_steeply_tilted).
body(r8_no_spill, slippery_destination).
learned(r8_no_spill).
provenance(r8_no_spill, antecedent, a8).
provenance(r8_no_spill, parent, a2).
provenance(r8_no_spill, simulations, 127).
provenance(r8_no_spill, weight_mass_permille, 26403).
provenance(r8_no_spill, confidence_permille, 994).
provenance(r8_no_spill, score_permille, 922).
provenance(r8_no_spill, followed, liquid_leaves_source).
provenance(r8_no_spill, direction, approach_duration).
provenance(r8_no_spill, sign, down).

rule(r9_destination_still_approach, defeasible, destination_still_approach).
body(r9_destination_still_approach, dull_liquid).
body(r9_destination_still_approach, pour_half_tilted).
body(r9_destination_still_approach, pour_mid_height).
body(r9_destination_still_approach, pour_near_rim).
body(r9_destination_still_approach, slippery_destination).
learned(r9_destination_still_approach).
provenance(r9_destination_still_approach, antecedent, a9).
provenance(r9_destination_still_approach, parent, a4).
provenance(r9_destination_still_approach, simulations, 84).
provenance(r9_destination_still_approach, weight_mass_permille, 34558).
provenance(r9_destination_still_approach, confidence_permille, 1000).
provenance(r9_destination_still_approach, score_permille, 993).
provenance(r9_destination_still_approach, followed, liquid_leaves_source).
provenance(r9_destination_still_approach, direction, pour_pitch).
provenance(r9_destination_still_approach, sign, down).

rule(r9_destination_still_retreat, defeasible, destination_still_retreat).
body(r9_destination_still_retreat, dull_liquid).
body(r9_destination_still_retreat, pour_half_tilted).
body(r9_destination_still_retreat, pour_mid_height).
body(r9_destination_still_retreat, pour_near_rim).
body(r9_destination_still_retreat, slippery_destination).
learned(r9_destination_still_retreat).
provenance(r9_destination_still_retreat, antecedent, a9).
provenance(r9_destination_still_retreat, parent, a4).
provenance(r9_destination_still_retreat, simulations, 84).
provenance(r9_destination_still_retreat, weight_mass_permille, 34558).
provenance(r9_destination_still_retreat, confidence_permille, 975).
provenance(r9_destination_still_retreat, score_permille, 974).
provenance(r9_destination_still_retreat, followed, liquid_leaves_source).
provenance(r9_destination_still_retreat, direction, pour_pitch).
provenance(r9_destination_still_retreat, sign, down).

rule(r9_destination_still_settle, defeasible, destination_still_settle).
body(r9_destination_still_settle, dull_liquid).
body(r9_destination_still_settle, pour_half_tilted).
body(r9_destination_still_settle, pour_mid_height).
body(r9_destination_still_settle, pour_near_rim).
body(r9_destination_still_settle, slippery_destination).
learned(r9_destination_still_settle).
provenance(r9_destination_still_settle, antecedent, a9).
provenance(r9_destination_still_settle, parent, a4).
provenance(r9_destination_still_settle, simulations, 84).
provenance(r9_destination_still_settle, weight_mass_permille, 34558).
provenance(r9_destination_still_settle, confidence_permille, 1000).
provenance(r9_destination_still_settle, score_permille, 999).
provenance(r9_destination_still_settle, followed, liquid_leaves_source).
provenance(r9_destination_still_settle, direction, pour_pitch).
provenance(r9_destination_still_settle, sign, down).

rule(r9_destination_upright, defeasible, destination_upright).
body(r9_destination_upright, dull_liquid).
body(r9_destination_upright, pour_half_tilted).
body(r9_destination_upright, pour_mid_height).
body(r9_destination_upright, pour_near_rim).
body(r9_destination_upright, slippery_destination).
learned(r9_destination_upright).
provenance(r9_destination_upright, antecedent, a9).
provenance(r9_destination_upright, parent, a4).
provenance(r9_destination_upright, simulations, 84).
provenance(r9_destination_upright, weight_mass_permille, 34558).
provenance(r9_destination_upright, confidence_permille, 1000).
provenance(r9_destination_upright, score_permille, 1000).
provenance(r9_destination_upright, followed, liquid_leaves_source).
provenance(r9_destination_upright, direction, pour_pitch).
provenance(r9_destination_upright, sign, down).

rule(r9_source_clear, defeasible, source_clear).
body(r9_source_clear, dull_liquid).
body(r9_source_clear, pour_half_tilted).
body(r9_source_clear, pour_mid_height).
body(r9_source_clear, pour_near_rim).
body(r9_source_clear, slippery_destination).
learned(r9_source_clear).
provenance(r9_source_clear, antecedent, a9).
provenance(r9_source_clear, parent, a4).
provenance(r9_source_clear, simulations, 84).
provenance(r9_source_clear, weight_mass_permille, 34558).
provenance(r9_source_clear, confidence_permille, 1000).
provenance(r9_source_clear, score_permille, 1000).
provenance(r9_source_clear, followed, liquid_leaves_source).
provenance(r9_source_clear, direction, pour_pitch).
provenance(r9_source_clear, sign, down).

rule(r9_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r9_liquid_leaves_source, dull_liquid).
body(r9_liquid_leaves_source, pour_half_tilted).
body(r9_liquid_leaves_source, pour_mid_height).
body(r9_liquid_leaves_source, pour_near_rim).
body(r9_liquid_leaves_source, slippery_destination).
learned(r9_liquid_leaves_source).
provenance(r9_liquid_leaves_source, antecedent, a9).
provenance(r9_liquid_leaves_source, parent, a4).
provenance(r9_liquid_leaves_source, simulations, 84).
provenance(r9_liquid_leaves_source, weight_mass_permille, 34558).
provenance(r9_liquid_leaves_source, confidence_permille, 962).
provenance(r9_liquid_leaves_source, score_permille, 50).
provenance(r9_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r9_liquid_leaves_source, direction, pour_pitch).
provenance(r9_liquid_leaves_source, sign, down).

rule(r9_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r9_liquid_enters_destination, dull_liquid).
body(r9_liquid_enters_destination, pour_half_tilted).
body(r9_liquid_enters_destination, pour_mid_height).
body(r9_liquid_enters_destination, pour_near_rim).
body(r9_liquid_enters_destination, slippery_destination).
learned(r9_liquid_enters_destination).
provenance(r9_liquid_enters_destination, antecedent, a9).
provenance(r9_liquid_enters_destination, parent, a4).
provenance(r9_liquid_enters_destination, simulations, 84).
provenance(r9_liquid_enters_destination, weight_mass_permille, 34558).
provenance(r9_liquid_enters_destination, confidence_permille, 962).
provenance(r9_liquid_enters_destination, score_permille, 47).
provenance(r9_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r9_liquid_enters_destination, direction, pour_pitch).
provenance(r9_liquid_enters_destination, sign, down).

rule(r9_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r9_liquid_remains_in_destination, dull_liquid).
body(r9_liquid_remains_in_destination, pour_half_tilted).
body(r9_liquid_remains_in_destination, pour_mid_height).
body(r9_liquid_remains_in_destination, pour_near_rim).
body(r9_liquid_remains_in_destination, slippery_destination).
learned(r9_liquid_remains_in_destination).
provenance(r9_liquid_remains_in_destination, antecedent, a9).
provenance(r9_liquid_remains_in_destination, parent, a4).
provenance(r9_liquid_remains_in_destination, simulations, 84).
provenance(r9_liquid_remains_in_destination, weight_mass_permille, 34558).
provenance(r9_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r9_liquid_remains_in_destination, score_permille, 996).
provenance(r9_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r9_liquid_remains_in_destination, direction, pour_pitch).
provenance(r9_liquid_remains_in_destination, sign, down).

rule(r9_no_spill, defeasible, no_spill).
body(r9_no_spill, dull_liquid).
body(r9_no_spill, pour_half_tilted).
body(r9_no_spill, pour_mid_height).
body(r9_no_spill, pour_near_rim).
body(r9_no_spill, slippery_destination).
learned(r9_no_spill).
provenance(r9_no_spill, antecedent, a9).
provenance(r9_no_spill, parent, a4).
provenance(r9_no_spill, simulations, 84).
provenance(r9_no_spill, weight_mass_permille, 34558).
provenance(r9_no_spill, confidence_permille, 1000).
provenance(r9_no_spill, score_permille, 997).
provenance(r9_no_spill, followed, liquid_leaves_source).
provenance(r9_no_spill, direction, pour_pitch).
provenance(r9_no_spill, sign, down).

rule(r10_destination_still_approach, defeasible, destination_still_approach).
body(r10_destination_still_approach, dull_liquid).
body(r10_destination_still_approach, little_liquid).
body(r10_destination_still_approach, pour_mid_height).
body(r10_destination_still_approach, pour_near_rim).
body(r10_destination_still_approach, pour_steeply_tilted).
body(r10_destination_still_approach, slippery_destination).
learned(r10_destination_still_approach).
provenance(r10_destination_still_approach, antecedent, a10).
provenance(r10_destination_still_approach, parent, a4).
provenance(r10_destination_still_approach, simulations, 52).
provenance(r10_destination_still_approach, weight_mass_permille, 31904).
provenance(r10_destination_still_approach, confidence_permille, 1000).
provenance(r10_destination_still_approach, score_permille, 993).
provenance(r10_destination_still_approach, followed, liquid_leaves_source).
provenance(r10_destination_still_approach, direction, particle_count).
provenance(r10_destination_still_approach, sign, down).

rule(r10_destination_still_retreat, defeasible, destination_still_retreat).
body(r10_destination_still_retreat, dull_liquid).
body(r10_destination_still_retreat, little_liquid).
body(r10_destination_still_retreat, pour_mid_height).
body(r10_destination_still_retreat, pour_near_rim).
body(r10_destination_still_retreat, pour_steeply_tilted).
body(r10_destination_still_retreat, slippery_destination).
learned(r10_destination_still_retreat).
provenance(r10_destination_still_retreat, antecedent, a10).
provenance(r10_destination_still_retreat, parent, a4).
provenance(r10_destination_still_retreat, simulations, 52).
provenance(r10_destination_still_retreat, weight_mass_permille, 31904).
provenance(r10_destination_still_retreat, confidence_permille, 917).
provenance(r10_destination_still_retreat, score_permille, 932).
provenance(r10_destination_still_retreat, followed, liquid_leaves_source).
provenance(r10_destination_still_retreat, direction, particle_count).
provenance(r10_destination_still_retreat, sign, down).

rule(r10_destination_still_settle, defeasible, destination_still_settle).
body(r10_destination_still_settle, dull_liquid).
body(r10_destination_still_settle, little_liquid).
body(r10_destination_still_settle, pour_mid_height).
body(r10_destination_still_settle, pour_near_rim).
body(r10_destination_still_settle, pour_steeply_tilted).
body(r10_destination_still_settle, slippery_destination).
learned(r10_destination_still_settle).
provenance(r10_destination_still_settle, antecedent, a10).
provenance(r10_destination_still_settle, parent, a4).
provenance(r10_destination_still_settle, simulations, 52).
provenance(r10_destination_still_settle, weight_mass_permille, 31904).
provenance(r10_destination_still_settle, confidence_permille, 975).
provenance(r10_destination_still_settle, score_permille, 973).
provenance(r10_destination_still_settle, followed, liquid_leaves_source).
provenance(r10_destination_still_settle, direction, particle_count).
provenance(r10_destination_still_settle, sign, down).

rule(r10_destination_upright, defeasible, destination_upright).
body(r10_destination_upright, dull_liquid).
body(r10_destination_upright, little_liquid).
body(r10_destination_upright, pour_mid_height).
body(r10_destination_upright, pour_near_rim).
body(r10_destination_upright, pour_steeply_tilted).
body(r10_destination_upright, slippery_destination).
learned(r10_destination_upright).
provenance(r10_destination_upright, antecedent, a10).
provenance(r10_destination_upright, parent, a4).
provenance(r10_destination_upright, simulations, 52).
provenance(r10_destination_upright, weight_mass_permille, 31904).
provenance(r10_destination_upright, confidence_permille, 1000).
provenance(r10_destination_upright, score_permille, 997).
provenance(r10_destination_upright, followed, liquid_leaves_source).
provenance(r10_destination_upright, direction, particle_count).
provenance(r10_destination_upright, sign, down).

rule(r10_source_clear, defeasible, source_clear).
body(r10_source_clear, dull_liquid).
body(r10_source_clear, little_liquid).
body(r10_source_clear, pour_mid_height).
body(r10_source_clear, pour_near_rim).
body(r10_source_clear, pour_steeply_tilted).
body(r10_source_clear, slippery_destination).
learned(r10_source_clear).
provenance(r10_source_clear, antecedent, a10).
provenance(r10_source_clear, parent, a4).
provenance(r10_source_clear, simulations, 52).
provenance(r10_source_clear, weight_mass_permille, 31904).
provenance(r10_source_clear, confidence_permille, 1000).
provenance(r10_source_clear, score_permille, 1000).
provenance(r10_source_clear, followed, liquid_leaves_source).
provenance(r10_source_clear, direction, particle_count).
provenance(r10_source_clear, sign, down).

rule(r10_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r10_liquid_leaves_source, dull_liquid).
body(r10_liquid_leaves_source, little_liquid).
body(r10_liquid_leaves_source, pour_mid_height).
body(r10_liquid_leaves_source, pour_near_rim).
body(r10_liquid_leaves_source, pour_steeply_tilted).
body(r10_liquid_leaves_source, slippery_destination).
learned(r10_liquid_leaves_source).
provenance(r10_liquid_leaves_source, antecedent, a10).
provenance(r10_liquid_leaves_source, parent, a4).
provenance(r10_liquid_leaves_source, simulations, 52).
provenance(r10_liquid_leaves_source, weight_mass_permille, 31904).
provenance(r10_liquid_leaves_source, confidence_permille, 773).
provenance(r10_liquid_leaves_source, score_permille, 771).
provenance(r10_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r10_liquid_leaves_source, direction, particle_count).
provenance(r10_liquid_leaves_source, sign, down).

rule(r10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r10_liquid_enters_destination, dull_liquid).
body(r10_liquid_enters_destination, little_liquid).
body(r10_liquid_enters_destination, pour_mid_height).
body(r10_liquid_enters_destination, pour_near_rim).
body(r10_liquid_enters_destination, pour_steeply_tilted).
body(r10_liquid_enters_destination, slippery_destination).
learned(r10_liquid_enters_destination).
provenance(r10_liquid_enters_destination, antecedent, a10).
provenance(r10_liquid_enters_destination, parent, a4).
provenance(r10_liquid_enters_destination, simulations, 52).
provenance(r10_liquid_enters_destination, weight_mass_permille, 31904).
provenance(r10_liquid_enters_destination, confidence_permille, 719).
provenance(r10_liquid_enters_destination, score_permille, 729).
provenance(r10_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r10_liquid_enters_destination, direction, particle_count).
provenance(r10_liquid_enters_destination, sign, down).

rule(r10_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r10_liquid_remains_in_destination, dull_liquid).
body(r10_liquid_remains_in_destination, little_liquid).
body(r10_liquid_remains_in_destination, pour_mid_height).
body(r10_liquid_remains_in_destination, pour_near_rim).
body(r10_liquid_remains_in_destination, pour_steeply_tilted).
body(r10_liquid_remains_in_destination, slippery_destination).
learned(r10_liquid_remains_in_destination).
provenance(r10_liquid_remains_in_destination, antecedent, a10).
provenance(r10_liquid_remains_in_destination, parent, a4).
provenance(r10_liquid_remains_in_destination, simulations, 52).
provenance(r10_liquid_remains_in_destination, weight_mass_permille, 31904).
provenance(r10_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r10_liquid_remains_in_destination, score_permille, 997).
provenance(r10_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r10_liquid_remains_in_destination, direction, particle_count).
provenance(r10_liquid_remains_in_destination, sign, down).

rule(r10_no_spill, defeasible, no_spill).
body(r10_no_spill, dull_liquid).
body(r10_no_spill, little_liquid).
body(r10_no_spill, pour_mid_height).
body(r10_no_spill, pour_near_rim).
body(r10_no_spill, pour_steeply_tilted).
body(r10_no_spill, slippery_destination).
learned(r10_no_spill).
provenance(r10_no_spill, antecedent, a10).
provenance(r10_no_spill, parent, a4).
provenance(r10_no_spill, simulations, 52).
provenance(r10_no_spill, weight_mass_permille, 31904).
provenance(r10_no_spill, confidence_permille, 977).
provenance(r10_no_spill, score_permille, 955).
provenance(r10_no_spill, followed, liquid_leaves_source).
provenance(r10_no_spill, direction, particle_count).
provenance(r10_no_spill, sign, down).

rule(r11_destination_still_approach, defeasible, destination_still_approach).
body(r11_destination_still_approach, dull_liquid).
body(r11_destination_still_approach, pour_mid_height).
body(r11_destination_still_approach, pour_near_rim).
body(r11_destination_still_approach, pour_steeply_tilted).
body(r11_destination_still_approach, slippery_destination).
body(r11_destination_still_approach, some_liquid).
learned(r11_destination_still_approach).
provenance(r11_destination_still_approach, antecedent, a11).
provenance(r11_destination_still_approach, parent, a4).
provenance(r11_destination_still_approach, simulations, 120).
provenance(r11_destination_still_approach, weight_mass_permille, 31773).
provenance(r11_destination_still_approach, confidence_permille, 977).
provenance(r11_destination_still_approach, score_permille, 964).
provenance(r11_destination_still_approach, followed, liquid_leaves_source).
provenance(r11_destination_still_approach, direction, particle_count).
provenance(r11_destination_still_approach, sign, down).

rule(r11_destination_still_retreat, defeasible, destination_still_retreat).
body(r11_destination_still_retreat, dull_liquid).
body(r11_destination_still_retreat, pour_mid_height).
body(r11_destination_still_retreat, pour_near_rim).
body(r11_destination_still_retreat, pour_steeply_tilted).
body(r11_destination_still_retreat, slippery_destination).
body(r11_destination_still_retreat, some_liquid).
learned(r11_destination_still_retreat).
provenance(r11_destination_still_retreat, antecedent, a11).
provenance(r11_destination_still_retreat, parent, a4).
provenance(r11_destination_still_retreat, simulations, 120).
provenance(r11_destination_still_retreat, weight_mass_permille, 31773).
provenance(r11_destination_still_retreat, confidence_permille, 929).
provenance(r11_destination_still_retreat, score_permille, 920).
provenance(r11_destination_still_retreat, followed, liquid_leaves_source).
provenance(r11_destination_still_retreat, direction, particle_count).
provenance(r11_destination_still_retreat, sign, down).

rule(r11_destination_still_settle, defeasible, destination_still_settle).
body(r11_destination_still_settle, dull_liquid).
body(r11_destination_still_settle, pour_mid_height).
body(r11_destination_still_settle, pour_near_rim).
body(r11_destination_still_settle, pour_steeply_tilted).
body(r11_destination_still_settle, slippery_destination).
body(r11_destination_still_settle, some_liquid).
learned(r11_destination_still_settle).
provenance(r11_destination_still_settle, antecedent, a11).
provenance(r11_destination_still_settle, parent, a4).
provenance(r11_destination_still_settle, simulations, 120).
provenance(r11_destination_still_settle, weight_mass_permille, 31773).
provenance(r11_destination_still_settle, confidence_permille, 1000).
provenance(r11_destination_still_settle, score_permille, 998).
provenance(r11_destination_still_settle, followed, liquid_leaves_source).
provenance(r11_destination_still_settle, direction, particle_count).
provenance(r11_destination_still_settle, sign, down).

rule(r11_destination_upright, defeasible, destination_upright).
body(r11_destination_upright, dull_liquid).
body(r11_destination_upright, pour_mid_height).
body(r11_destination_upright, pour_near_rim).
body(r11_destination_upright, pour_steeply_tilted).
body(r11_destination_upright, slippery_destination).
body(r11_destination_upright, some_liquid).
learned(r11_destination_upright).
provenance(r11_destination_upright, antecedent, a11).
provenance(r11_destination_upright, parent, a4).
provenance(r11_destination_upright, simulations, 120).
provenance(r11_destination_upright, weight_mass_permille, 31773).
provenance(r11_destination_upright, confidence_permille, 1000).
provenance(r11_destination_upright, score_permille, 998).
provenance(r11_destination_upright, followed, liquid_leaves_source).
provenance(r11_destination_upright, direction, particle_count).
provenance(r11_destination_upright, sign, down).

rule(r11_source_clear, defeasible, source_clear).
body(r11_source_clear, dull_liquid).
body(r11_source_clear, pour_mid_height).
body(r11_source_clear, pour_near_rim).
body(r11_source_clear, pour_steeply_tilted).
body(r11_source_clear, slippery_destination).
body(r11_source_clear, some_liquid).
learned(r11_source_clear).
provenance(r11_source_clear, antecedent, a11).
provenance(r11_source_clear, parent, a4).
provenance(r11_source_clear, simulations, 120).
provenance(r11_source_clear, weight_mass_permille, 31773).
provenance(r11_source_clear, confidence_permille, 991).
provenance(r11_source_clear, score_permille, 985).
provenance(r11_source_clear, followed, liquid_leaves_source).
provenance(r11_source_clear, direction, particle_count).
provenance(r11_source_clear, sign, down).

rule(r11_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r11_liquid_leaves_source, dull_liquid).
body(r11_liquid_leaves_source, pour_mid_height).
body(r11_liquid_leaves_source, pour_near_rim).
body(r11_liquid_leaves_source, pour_steeply_tilted).
body(r11_liquid_leaves_source, slippery_destination).
body(r11_liquid_leaves_source, some_liquid).
learned(r11_liquid_leaves_source).
provenance(r11_liquid_leaves_source, antecedent, a11).
provenance(r11_liquid_leaves_source, parent, a4).
provenance(r11_liquid_leaves_source, simulations, 120).
provenance(r11_liquid_leaves_source, weight_mass_permille, 31773).
provenance(r11_liquid_leaves_source, confidence_permille, 594).
provenance(r11_liquid_leaves_source, score_permille, 631).
provenance(r11_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r11_liquid_leaves_source, direction, particle_count).
provenance(r11_liquid_leaves_source, sign, down).

rule(r11_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r11_liquid_enters_destination, dull_liquid).
body(r11_liquid_enters_destination, pour_mid_height).
body(r11_liquid_enters_destination, pour_near_rim).
body(r11_liquid_enters_destination, pour_steeply_tilted).
body(r11_liquid_enters_destination, slippery_destination).
body(r11_liquid_enters_destination, some_liquid).
learned(r11_liquid_enters_destination).
provenance(r11_liquid_enters_destination, antecedent, a11).
provenance(r11_liquid_enters_destination, parent, a4).
provenance(r11_liquid_enters_destination, simulations, 120).
provenance(r11_liquid_enters_destination, weight_mass_permille, 31773).
provenance(r11_liquid_enters_destination, confidence_permille, 546).
provenance(r11_liquid_enters_destination, score_permille, 579).
provenance(r11_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r11_liquid_enters_destination, direction, particle_count).
provenance(r11_liquid_enters_destination, sign, down).

rule(r11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r11_liquid_remains_in_destination, dull_liquid).
body(r11_liquid_remains_in_destination, pour_mid_height).
body(r11_liquid_remains_in_destination, pour_near_rim).
body(r11_liquid_remains_in_destination, pour_steeply_tilted).
body(r11_liquid_remains_in_destination, slippery_destination).
body(r11_liquid_remains_in_destination, some_liquid).
learned(r11_liquid_remains_in_destination).
provenance(r11_liquid_remains_in_destination, antecedent, a11).
provenance(r11_liquid_remains_in_destination, parent, a4).
provenance(r11_liquid_remains_in_destination, simulations, 120).
provenance(r11_liquid_remains_in_destination, weight_mass_permille, 31773).
provenance(r11_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r11_liquid_remains_in_destination, score_permille, 994).
provenance(r11_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r11_liquid_remains_in_destination, direction, particle_count).
provenance(r11_liquid_remains_in_destination, sign, down).

rule(r11_no_spill, defeasible, no_spill).
body(r11_no_spill, dull_liquid).
body(r11_no_spill, pour_mid_height).
body(r11_no_spill, pour_near_rim).
body(r11_no_spill, pour_steeply_tilted).
body(r11_no_spill, slippery_destination).
body(r11_no_spill, some_liquid).
learned(r11_no_spill).
provenance(r11_no_spill, antecedent, a11).
provenance(r11_no_spill, parent, a4).
provenance(r11_no_spill, simulations, 120).
provenance(r11_no_spill, weight_mass_permille, 31773).
provenance(r11_no_spill, confidence_permille, 975).
provenance(r11_no_spill, score_permille, 943).
provenance(r11_no_spill, followed, liquid_leaves_source).
provenance(r11_no_spill, direction, particle_count).
provenance(r11_no_spill, sign, down).

rule(r12_destination_still_approach, defeasible, destination_still_approach).
body(r12_destination_still_approach, dull_liquid).
body(r12_destination_still_approach, pour_mid_height).
body(r12_destination_still_approach, pour_near_rim).
body(r12_destination_still_approach, pour_offset_sideways).
body(r12_destination_still_approach, pour_steeply_tilted).
body(r12_destination_still_approach, slippery_destination).
learned(r12_destination_still_approach).
provenance(r12_destination_still_approach, antecedent, a12).
provenance(r12_destination_still_approach, parent, a4).
provenance(r12_destination_still_approach, simulations, 66).
provenance(r12_destination_still_approach, weight_mass_permille, 32392).
provenance(r12_destination_still_approach, confidence_permille, 983).
provenance(r12_destination_still_approach, score_permille, 976).
provenance(r12_destination_still_approach, followed, liquid_leaves_source).
provenance(r12_destination_still_approach, direction, pour_y).
provenance(r12_destination_still_approach, sign, up).

rule(r12_destination_still_retreat, defeasible, destination_still_retreat).
body(r12_destination_still_retreat, dull_liquid).
body(r12_destination_still_retreat, pour_mid_height).
body(r12_destination_still_retreat, pour_near_rim).
body(r12_destination_still_retreat, pour_offset_sideways).
body(r12_destination_still_retreat, pour_steeply_tilted).
body(r12_destination_still_retreat, slippery_destination).
learned(r12_destination_still_retreat).
provenance(r12_destination_still_retreat, antecedent, a12).
provenance(r12_destination_still_retreat, parent, a4).
provenance(r12_destination_still_retreat, simulations, 66).
provenance(r12_destination_still_retreat, weight_mass_permille, 32392).
provenance(r12_destination_still_retreat, confidence_permille, 977).
provenance(r12_destination_still_retreat, score_permille, 971).
provenance(r12_destination_still_retreat, followed, liquid_leaves_source).
provenance(r12_destination_still_retreat, direction, pour_y).
provenance(r12_destination_still_retreat, sign, up).

rule(r12_destination_still_settle, defeasible, destination_still_settle).
body(r12_destination_still_settle, dull_liquid).
body(r12_destination_still_settle, pour_mid_height).
body(r12_destination_still_settle, pour_near_rim).
body(r12_destination_still_settle, pour_offset_sideways).
body(r12_destination_still_settle, pour_steeply_tilted).
body(r12_destination_still_settle, slippery_destination).
learned(r12_destination_still_settle).
provenance(r12_destination_still_settle, antecedent, a12).
provenance(r12_destination_still_settle, parent, a4).
provenance(r12_destination_still_settle, simulations, 66).
provenance(r12_destination_still_settle, weight_mass_permille, 32392).
provenance(r12_destination_still_settle, confidence_permille, 1000).
provenance(r12_destination_still_settle, score_permille, 992).
provenance(r12_destination_still_settle, followed, liquid_leaves_source).
provenance(r12_destination_still_settle, direction, pour_y).
provenance(r12_destination_still_settle, sign, up).

rule(r12_destination_upright, defeasible, destination_upright).
body(r12_destination_upright, dull_liquid).
body(r12_destination_upright, pour_mid_height).
body(r12_destination_upright, pour_near_rim).
body(r12_destination_upright, pour_offset_sideways).
body(r12_destination_upright, pour_steeply_tilted).
body(r12_destination_upright, slippery_destination).
learned(r12_destination_upright).
provenance(r12_destination_upright, antecedent, a12).
provenance(r12_destination_upright, parent, a4).
provenance(r12_destination_upright, simulations, 66).
provenance(r12_destination_upright, weight_mass_permille, 32392).
provenance(r12_destination_upright, confidence_permille, 1000).
provenance(r12_destination_upright, score_permille, 999).
provenance(r12_destination_upright, followed, liquid_leaves_source).
provenance(r12_destination_upright, direction, pour_y).
provenance(r12_destination_upright, sign, up).

rule(r12_source_clear, defeasible, source_clear).
body(r12_source_clear, dull_liquid).
body(r12_source_clear, pour_mid_height).
body(r12_source_clear, pour_near_rim).
body(r12_source_clear, pour_offset_sideways).
body(r12_source_clear, pour_steeply_tilted).
body(r12_source_clear, slippery_destination).
learned(r12_source_clear).
provenance(r12_source_clear, antecedent, a12).
provenance(r12_source_clear, parent, a4).
provenance(r12_source_clear, simulations, 66).
provenance(r12_source_clear, weight_mass_permille, 32392).
provenance(r12_source_clear, confidence_permille, 1000).
provenance(r12_source_clear, score_permille, 1000).
provenance(r12_source_clear, followed, liquid_leaves_source).
provenance(r12_source_clear, direction, pour_y).
provenance(r12_source_clear, sign, up).

rule(r12_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r12_liquid_leaves_source, dull_liquid).
body(r12_liquid_leaves_source, pour_mid_height).
body(r12_liquid_leaves_source, pour_near_rim).
body(r12_liquid_leaves_source, pour_offset_sideways).
body(r12_liquid_leaves_source, pour_steeply_tilted).
body(r12_liquid_leaves_source, slippery_destination).
learned(r12_liquid_leaves_source).
provenance(r12_liquid_leaves_source, antecedent, a12).
provenance(r12_liquid_leaves_source, parent, a4).
provenance(r12_liquid_leaves_source, simulations, 66).
provenance(r12_liquid_leaves_source, weight_mass_permille, 32392).
provenance(r12_liquid_leaves_source, confidence_permille, 756).
provenance(r12_liquid_leaves_source, score_permille, 733).
provenance(r12_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r12_liquid_leaves_source, direction, pour_y).
provenance(r12_liquid_leaves_source, sign, up).

rule(r12_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r12_liquid_enters_destination, dull_liquid).
body(r12_liquid_enters_destination, pour_mid_height).
body(r12_liquid_enters_destination, pour_near_rim).
body(r12_liquid_enters_destination, pour_offset_sideways).
body(r12_liquid_enters_destination, pour_steeply_tilted).
body(r12_liquid_enters_destination, slippery_destination).
learned(r12_liquid_enters_destination).
provenance(r12_liquid_enters_destination, antecedent, a12).
provenance(r12_liquid_enters_destination, parent, a4).
provenance(r12_liquid_enters_destination, simulations, 66).
provenance(r12_liquid_enters_destination, weight_mass_permille, 32392).
provenance(r12_liquid_enters_destination, confidence_permille, 789).
provenance(r12_liquid_enters_destination, score_permille, 245).
provenance(r12_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r12_liquid_enters_destination, direction, pour_y).
provenance(r12_liquid_enters_destination, sign, up).

rule(r12_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r12_liquid_remains_in_destination, dull_liquid).
body(r12_liquid_remains_in_destination, pour_mid_height).
body(r12_liquid_remains_in_destination, pour_near_rim).
body(r12_liquid_remains_in_destination, pour_offset_sideways).
body(r12_liquid_remains_in_destination, pour_steeply_tilted).
body(r12_liquid_remains_in_destination, slippery_destination).
learned(r12_liquid_remains_in_destination).
provenance(r12_liquid_remains_in_destination, antecedent, a12).
provenance(r12_liquid_remains_in_destination, parent, a4).
provenance(r12_liquid_remains_in_destination, simulations, 66).
provenance(r12_liquid_remains_in_destination, weight_mass_permille, 32392).
provenance(r12_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r12_liquid_remains_in_destination, score_permille, 998).
provenance(r12_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r12_liquid_remains_in_destination, direction, pour_y).
provenance(r12_liquid_remains_in_destination, sign, up).

rule(r12_no_spill, defeasible, no_spill).
body(r12_no_spill, dull_liquid).
body(r12_no_spill, pour_mid_height).
body(r12_no_spill, pour_near_rim).
body(r12_no_spill, pour_offset_sideways).
body(r12_no_spill, pour_steeply_tilted).
body(r12_no_spill, slippery_destination).
learned(r12_no_spill).
provenance(r12_no_spill, antecedent, a12).
provenance(r12_no_spill, parent, a4).
provenance(r12_no_spill, simulations, 66).
provenance(r12_no_spill, weight_mass_permille, 32392).
provenance(r12_no_spill, confidence_permille, 508).
provenance(r12_no_spill, score_permille, 512).
provenance(r12_no_spill, followed, liquid_leaves_source).
provenance(r12_no_spill, direction, pour_y).
provenance(r12_no_spill, sign, up).

rule(r13_destination_still_approach, defeasible, destination_still_approach).
body(r13_destination_still_approach, light_source).
body(r13_destination_still_approach, pour_half_tilted).
body(r13_destination_still_approach, pour_mid_height).
body(r13_destination_still_approach, pour_near_rim).
body(r13_destination_still_approach, slippery_destination).
learned(r13_destination_still_approach).
provenance(r13_destination_still_approach, antecedent, a13).
provenance(r13_destination_still_approach, parent, a5).
provenance(r13_destination_still_approach, simulations, 82).
provenance(r13_destination_still_approach, weight_mass_permille, 27214).
provenance(r13_destination_still_approach, confidence_permille, 1000).
provenance(r13_destination_still_approach, score_permille, 990).
provenance(r13_destination_still_approach, followed, liquid_leaves_source).
provenance(r13_destination_still_approach, direction, pour_pitch).
provenance(r13_destination_still_approach, sign, down).

rule(r13_destination_still_retreat, defeasible, destination_still_retreat).
body(r13_destination_still_retreat, light_source).
body(r13_destination_still_retreat, pour_half_tilted).
body(r13_destination_still_retreat, pour_mid_height).
body(r13_destination_still_retreat, pour_near_rim).
body(r13_destination_still_retreat, slippery_destination).
learned(r13_destination_still_retreat).
provenance(r13_destination_still_retreat, antecedent, a13).
provenance(r13_destination_still_retreat, parent, a5).
provenance(r13_destination_still_retreat, simulations, 82).
provenance(r13_destination_still_retreat, weight_mass_permille, 27214).
provenance(r13_destination_still_retreat, confidence_permille, 1000).
provenance(r13_destination_still_retreat, score_permille, 988).
provenance(r13_destination_still_retreat, followed, liquid_leaves_source).
provenance(r13_destination_still_retreat, direction, pour_pitch).
provenance(r13_destination_still_retreat, sign, down).

rule(r13_destination_still_settle, defeasible, destination_still_settle).
body(r13_destination_still_settle, light_source).
body(r13_destination_still_settle, pour_half_tilted).
body(r13_destination_still_settle, pour_mid_height).
body(r13_destination_still_settle, pour_near_rim).
body(r13_destination_still_settle, slippery_destination).
learned(r13_destination_still_settle).
provenance(r13_destination_still_settle, antecedent, a13).
provenance(r13_destination_still_settle, parent, a5).
provenance(r13_destination_still_settle, simulations, 82).
provenance(r13_destination_still_settle, weight_mass_permille, 27214).
provenance(r13_destination_still_settle, confidence_permille, 1000).
provenance(r13_destination_still_settle, score_permille, 999).
provenance(r13_destination_still_settle, followed, liquid_leaves_source).
provenance(r13_destination_still_settle, direction, pour_pitch).
provenance(r13_destination_still_settle, sign, down).

rule(r13_destination_upright, defeasible, destination_upright).
body(r13_destination_upright, light_source).
body(r13_destination_upright, pour_half_tilted).
body(r13_destination_upright, pour_mid_height).
body(r13_destination_upright, pour_near_rim).
body(r13_destination_upright, slippery_destination).
learned(r13_destination_upright).
provenance(r13_destination_upright, antecedent, a13).
provenance(r13_destination_upright, parent, a5).
provenance(r13_destination_upright, simulations, 82).
provenance(r13_destination_upright, weight_mass_permille, 27214).
provenance(r13_destination_upright, confidence_permille, 1000).
provenance(r13_destination_upright, score_permille, 1000).
provenance(r13_destination_upright, followed, liquid_leaves_source).
provenance(r13_destination_upright, direction, pour_pitch).
provenance(r13_destination_upright, sign, down).

rule(r13_source_clear, defeasible, source_clear).
body(r13_source_clear, light_source).
body(r13_source_clear, pour_half_tilted).
body(r13_source_clear, pour_mid_height).
body(r13_source_clear, pour_near_rim).
body(r13_source_clear, slippery_destination).
learned(r13_source_clear).
provenance(r13_source_clear, antecedent, a13).
provenance(r13_source_clear, parent, a5).
provenance(r13_source_clear, simulations, 82).
provenance(r13_source_clear, weight_mass_permille, 27214).
provenance(r13_source_clear, confidence_permille, 1000).
provenance(r13_source_clear, score_permille, 1000).
provenance(r13_source_clear, followed, liquid_leaves_source).
provenance(r13_source_clear, direction, pour_pitch).
provenance(r13_source_clear, sign, down).

rule(r13_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r13_liquid_leaves_source, light_source).
body(r13_liquid_leaves_source, pour_half_tilted).
body(r13_liquid_leaves_source, pour_mid_height).
body(r13_liquid_leaves_source, pour_near_rim).
body(r13_liquid_leaves_source, slippery_destination).
learned(r13_liquid_leaves_source).
provenance(r13_liquid_leaves_source, antecedent, a13).
provenance(r13_liquid_leaves_source, parent, a5).
provenance(r13_liquid_leaves_source, simulations, 82).
provenance(r13_liquid_leaves_source, weight_mass_permille, 27214).
provenance(r13_liquid_leaves_source, confidence_permille, 920).
provenance(r13_liquid_leaves_source, score_permille, 77).
provenance(r13_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r13_liquid_leaves_source, direction, pour_pitch).
provenance(r13_liquid_leaves_source, sign, down).

rule(r13_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r13_liquid_enters_destination, light_source).
body(r13_liquid_enters_destination, pour_half_tilted).
body(r13_liquid_enters_destination, pour_mid_height).
body(r13_liquid_enters_destination, pour_near_rim).
body(r13_liquid_enters_destination, slippery_destination).
learned(r13_liquid_enters_destination).
provenance(r13_liquid_enters_destination, antecedent, a13).
provenance(r13_liquid_enters_destination, parent, a5).
provenance(r13_liquid_enters_destination, simulations, 82).
provenance(r13_liquid_enters_destination, weight_mass_permille, 27214).
provenance(r13_liquid_enters_destination, confidence_permille, 983).
provenance(r13_liquid_enters_destination, score_permille, 59).
provenance(r13_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r13_liquid_enters_destination, direction, pour_pitch).
provenance(r13_liquid_enters_destination, sign, down).

rule(r13_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r13_liquid_remains_in_destination, light_source).
body(r13_liquid_remains_in_destination, pour_half_tilted).
body(r13_liquid_remains_in_destination, pour_mid_height).
body(r13_liquid_remains_in_destination, pour_near_rim).
body(r13_liquid_remains_in_destination, slippery_destination).
learned(r13_liquid_remains_in_destination).
provenance(r13_liquid_remains_in_destination, antecedent, a13).
provenance(r13_liquid_remains_in_destination, parent, a5).
provenance(r13_liquid_remains_in_destination, simulations, 82).
provenance(r13_liquid_remains_in_destination, weight_mass_permille, 27214).
provenance(r13_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r13_liquid_remains_in_destination, score_permille, 995).
provenance(r13_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r13_liquid_remains_in_destination, direction, pour_pitch).
provenance(r13_liquid_remains_in_destination, sign, down).

rule(r13_no_spill, defeasible, no_spill).
body(r13_no_spill, light_source).
body(r13_no_spill, pour_half_tilted).
body(r13_no_spill, pour_mid_height).
body(r13_no_spill, pour_near_rim).
body(r13_no_spill, slippery_destination).
learned(r13_no_spill).
provenance(r13_no_spill, antecedent, a13).
provenance(r13_no_spill, parent, a5).
provenance(r13_no_spill, simulations, 82).
provenance(r13_no_spill, weight_mass_permille, 27214).
provenance(r13_no_spill, confidence_permille, 1000).
provenance(r13_no_spill, score_permille, 980).
provenance(r13_no_spill, followed, liquid_leaves_source).
provenance(r13_no_spill, direction, pour_pitch).
provenance(r13_no_spill, sign, down).

rule(r14_destination_still_approach, defeasible, destination_still_approach).
body(r14_destination_still_approach, light_source).
body(r14_destination_still_approach, little_liquid).
body(r14_destination_still_approach, pour_mid_height).
body(r14_destination_still_approach, pour_near_rim).
body(r14_destination_still_approach, pour_steeply_tilted).
body(r14_destination_still_approach, slippery_destination).
learned(r14_destination_still_approach).
provenance(r14_destination_still_approach, antecedent, a14).
provenance(r14_destination_still_approach, parent, a5).
provenance(r14_destination_still_approach, simulations, 108).
provenance(r14_destination_still_approach, weight_mass_permille, 29948).
provenance(r14_destination_still_approach, confidence_permille, 1000).
provenance(r14_destination_still_approach, score_permille, 980).
provenance(r14_destination_still_approach, followed, liquid_leaves_source).
provenance(r14_destination_still_approach, direction, particle_count).
provenance(r14_destination_still_approach, sign, down).

rule(r14_destination_still_retreat, defeasible, destination_still_retreat).
body(r14_destination_still_retreat, light_source).
body(r14_destination_still_retreat, little_liquid).
body(r14_destination_still_retreat, pour_mid_height).
body(r14_destination_still_retreat, pour_near_rim).
body(r14_destination_still_retreat, pour_steeply_tilted).
body(r14_destination_still_retreat, slippery_destination).
learned(r14_destination_still_retreat).
provenance(r14_destination_still_retreat, antecedent, a14).
provenance(r14_destination_still_retreat, parent, a5).
provenance(r14_destination_still_retreat, simulations, 108).
provenance(r14_destination_still_retreat, weight_mass_permille, 29948).
provenance(r14_destination_still_retreat, confidence_permille, 952).
provenance(r14_destination_still_retreat, score_permille, 954).
provenance(r14_destination_still_retreat, followed, liquid_leaves_source).
provenance(r14_destination_still_retreat, direction, particle_count).
provenance(r14_destination_still_retreat, sign, down).

rule(r14_destination_still_settle, defeasible, destination_still_settle).
body(r14_destination_still_settle, light_source).
body(r14_destination_still_settle, little_liquid).
body(r14_destination_still_settle, pour_mid_height).
body(r14_destination_still_settle, pour_near_rim).
body(r14_destination_still_settle, pour_steeply_tilted).
body(r14_destination_still_settle, slippery_destination).
learned(r14_destination_still_settle).
provenance(r14_destination_still_settle, antecedent, a14).
provenance(r14_destination_still_settle, parent, a5).
provenance(r14_destination_still_settle, simulations, 108).
provenance(r14_destination_still_settle, weight_mass_permille, 29948).
provenance(r14_destination_still_settle, confidence_permille, 990).
provenance(r14_destination_still_settle, score_permille, 988).
provenance(r14_destination_still_settle, followed, liquid_leaves_source).
provenance(r14_destination_still_settle, direction, particle_count).
provenance(r14_destination_still_settle, sign, down).

rule(r14_destination_upright, defeasible, destination_upright).
body(r14_destination_upright, light_source).
body(r14_destination_upright, little_liquid).
body(r14_destination_upright, pour_mid_height).
body(r14_destination_upright, pour_near_rim).
body(r14_destination_upright, pour_steeply_tilted).
body(r14_destination_upright, slippery_destination).
learned(r14_destination_upright).
provenance(r14_destination_upright, antecedent, a14).
provenance(r14_destination_upright, parent, a5).
provenance(r14_destination_upright, simulations, 108).
provenance(r14_destination_upright, weight_mass_permille, 29948).
provenance(r14_destination_upright, confidence_permille, 1000).
provenance(r14_destination_upright, score_permille, 999).
provenance(r14_destination_upright, followed, liquid_leaves_source).
provenance(r14_destination_upright, direction, particle_count).
provenance(r14_destination_upright, sign, down).

rule(r14_source_clear, defeasible, source_clear).
body(r14_source_clear, light_source).
body(r14_source_clear, little_liquid).
body(r14_source_clear, pour_mid_height).
body(r14_source_clear, pour_near_rim).
body(r14_source_clear, pour_steeply_tilted).
body(r14_source_clear, slippery_destination).
learned(r14_source_clear).
provenance(r14_source_clear, antecedent, a14).
provenance(r14_source_clear, parent, a5).
provenance(r14_source_clear, simulations, 108).
provenance(r14_source_clear, weight_mass_permille, 29948).
provenance(r14_source_clear, confidence_permille, 1000).
provenance(r14_source_clear, score_permille, 991).
provenance(r14_source_clear, followed, liquid_leaves_source).
provenance(r14_source_clear, direction, particle_count).
provenance(r14_source_clear, sign, down).

rule(r14_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r14_liquid_leaves_source, light_source).
body(r14_liquid_leaves_source, little_liquid).
body(r14_liquid_leaves_source, pour_mid_height).
body(r14_liquid_leaves_source, pour_near_rim).
body(r14_liquid_leaves_source, pour_steeply_tilted).
body(r14_liquid_leaves_source, slippery_destination).
learned(r14_liquid_leaves_source).
provenance(r14_liquid_leaves_source, antecedent, a14).
provenance(r14_liquid_leaves_source, parent, a5).
provenance(r14_liquid_leaves_source, simulations, 108).
provenance(r14_liquid_leaves_source, weight_mass_permille, 29948).
provenance(r14_liquid_leaves_source, confidence_permille, 684).
provenance(r14_liquid_leaves_source, score_permille, 692).
provenance(r14_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r14_liquid_leaves_source, direction, particle_count).
provenance(r14_liquid_leaves_source, sign, down).

rule(r14_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r14_liquid_enters_destination, light_source).
body(r14_liquid_enters_destination, little_liquid).
body(r14_liquid_enters_destination, pour_mid_height).
body(r14_liquid_enters_destination, pour_near_rim).
body(r14_liquid_enters_destination, pour_steeply_tilted).
body(r14_liquid_enters_destination, slippery_destination).
learned(r14_liquid_enters_destination).
provenance(r14_liquid_enters_destination, antecedent, a14).
provenance(r14_liquid_enters_destination, parent, a5).
provenance(r14_liquid_enters_destination, simulations, 108).
provenance(r14_liquid_enters_destination, weight_mass_permille, 29948).
provenance(r14_liquid_enters_destination, confidence_permille, 648).
provenance(r14_liquid_enters_destination, score_permille, 638).
provenance(r14_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r14_liquid_enters_destination, direction, particle_count).
provenance(r14_liquid_enters_destination, sign, down).

rule(r14_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r14_liquid_remains_in_destination, light_source).
body(r14_liquid_remains_in_destination, little_liquid).
body(r14_liquid_remains_in_destination, pour_mid_height).
body(r14_liquid_remains_in_destination, pour_near_rim).
body(r14_liquid_remains_in_destination, pour_steeply_tilted).
body(r14_liquid_remains_in_destination, slippery_destination).
learned(r14_liquid_remains_in_destination).
provenance(r14_liquid_remains_in_destination, antecedent, a14).
provenance(r14_liquid_remains_in_destination, parent, a5).
provenance(r14_liquid_remains_in_destination, simulations, 108).
provenance(r14_liquid_remains_in_destination, weight_mass_permille, 29948).
provenance(r14_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r14_liquid_remains_in_destination, score_permille, 982).
provenance(r14_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r14_liquid_remains_in_destination, direction, particle_count).
provenance(r14_liquid_remains_in_destination, sign, down).

rule(r14_no_spill, defeasible, no_spill).
body(r14_no_spill, light_source).
body(r14_no_spill, little_liquid).
body(r14_no_spill, pour_mid_height).
body(r14_no_spill, pour_near_rim).
body(r14_no_spill, pour_steeply_tilted).
body(r14_no_spill, slippery_destination).
learned(r14_no_spill).
provenance(r14_no_spill, antecedent, a14).
provenance(r14_no_spill, parent, a5).
provenance(r14_no_spill, simulations, 108).
provenance(r14_no_spill, weight_mass_permille, 29948).
provenance(r14_no_spill, confidence_permille, 991).
provenance(r14_no_spill, score_permille, 932).
provenance(r14_no_spill, followed, liquid_leaves_source).
provenance(r14_no_spill, direction, particle_count).
provenance(r14_no_spill, sign, down).

rule(r15_destination_still_approach, defeasible, destination_still_approach).
body(r15_destination_still_approach, light_source).
body(r15_destination_still_approach, pour_mid_height).
body(r15_destination_still_approach, pour_near_rim).
body(r15_destination_still_approach, pour_steeply_tilted).
body(r15_destination_still_approach, slippery_destination).
body(r15_destination_still_approach, some_liquid).
learned(r15_destination_still_approach).
provenance(r15_destination_still_approach, antecedent, a15).
provenance(r15_destination_still_approach, parent, a5).
provenance(r15_destination_still_approach, simulations, 65).
provenance(r15_destination_still_approach, weight_mass_permille, 29736).
provenance(r15_destination_still_approach, confidence_permille, 995).
provenance(r15_destination_still_approach, score_permille, 968).
provenance(r15_destination_still_approach, followed, liquid_leaves_source).
provenance(r15_destination_still_approach, direction, particle_count).
provenance(r15_destination_still_approach, sign, down).

rule(r15_destination_still_retreat, defeasible, destination_still_retreat).
body(r15_destination_still_retreat, light_source).
body(r15_destination_still_retreat, pour_mid_height).
body(r15_destination_still_retreat, pour_near_rim).
body(r15_destination_still_retreat, pour_steeply_tilted).
body(r15_destination_still_retreat, slippery_destination).
body(r15_destination_still_retreat, some_liquid).
learned(r15_destination_still_retreat).
provenance(r15_destination_still_retreat, antecedent, a15).
provenance(r15_destination_still_retreat, parent, a5).
provenance(r15_destination_still_retreat, simulations, 65).
provenance(r15_destination_still_retreat, weight_mass_permille, 29736).
provenance(r15_destination_still_retreat, confidence_permille, 955).
provenance(r15_destination_still_retreat, score_permille, 950).
provenance(r15_destination_still_retreat, followed, liquid_leaves_source).
provenance(r15_destination_still_retreat, direction, particle_count).
provenance(r15_destination_still_retreat, sign, down).

rule(r15_destination_still_settle, defeasible, destination_still_settle).
body(r15_destination_still_settle, light_source).
body(r15_destination_still_settle, pour_mid_height).
body(r15_destination_still_settle, pour_near_rim).
body(r15_destination_still_settle, pour_steeply_tilted).
body(r15_destination_still_settle, slippery_destination).
body(r15_destination_still_settle, some_liquid).
learned(r15_destination_still_settle).
provenance(r15_destination_still_settle, antecedent, a15).
provenance(r15_destination_still_settle, parent, a5).
provenance(r15_destination_still_settle, simulations, 65).
provenance(r15_destination_still_settle, weight_mass_permille, 29736).
provenance(r15_destination_still_settle, confidence_permille, 1000).
provenance(r15_destination_still_settle, score_permille, 999).
provenance(r15_destination_still_settle, followed, liquid_leaves_source).
provenance(r15_destination_still_settle, direction, particle_count).
provenance(r15_destination_still_settle, sign, down).

rule(r15_destination_upright, defeasible, destination_upright).
body(r15_destination_upright, light_source).
body(r15_destination_upright, pour_mid_height).
body(r15_destination_upright, pour_near_rim).
body(r15_destination_upright, pour_steeply_tilted).
body(r15_destination_upright, slippery_destination).
body(r15_destination_upright, some_liquid).
learned(r15_destination_upright).
provenance(r15_destination_upright, antecedent, a15).
provenance(r15_destination_upright, parent, a5).
provenance(r15_destination_upright, simulations, 65).
provenance(r15_destination_upright, weight_mass_permille, 29736).
provenance(r15_destination_upright, confidence_permille, 1000).
provenance(r15_destination_upright, score_permille, 1000).
provenance(r15_destination_upright, followed, liquid_leaves_source).
provenance(r15_destination_upright, direction, particle_count).
provenance(r15_destination_upright, sign, down).

rule(r15_source_clear, defeasible, source_clear).
body(r15_source_clear, light_source).
body(r15_source_clear, pour_mid_height).
body(r15_source_clear, pour_near_rim).
body(r15_source_clear, pour_steeply_tilted).
body(r15_source_clear, slippery_destination).
body(r15_source_clear, some_liquid).
learned(r15_source_clear).
provenance(r15_source_clear, antecedent, a15).
provenance(r15_source_clear, parent, a5).
provenance(r15_source_clear, simulations, 65).
provenance(r15_source_clear, weight_mass_permille, 29736).
provenance(r15_source_clear, confidence_permille, 1000).
provenance(r15_source_clear, score_permille, 1000).
provenance(r15_source_clear, followed, liquid_leaves_source).
provenance(r15_source_clear, direction, particle_count).
provenance(r15_source_clear, sign, down).

rule(r15_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r15_liquid_leaves_source, light_source).
body(r15_liquid_leaves_source, pour_mid_height).
body(r15_liquid_leaves_source, pour_near_rim).
body(r15_liquid_leaves_source, pour_steeply_tilted).
body(r15_liquid_leaves_source, slippery_destination).
body(r15_liquid_leaves_source, some_liquid).
learned(r15_liquid_leaves_source).
provenance(r15_liquid_leaves_source, antecedent, a15).
provenance(r15_liquid_leaves_source, parent, a5).
provenance(r15_liquid_leaves_source, simulations, 65).
provenance(r15_liquid_leaves_source, weight_mass_permille, 29736).
provenance(r15_liquid_leaves_source, confidence_permille, 667).
provenance(r15_liquid_leaves_source, score_permille, 635).
provenance(r15_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r15_liquid_leaves_source, direction, particle_count).
provenance(r15_liquid_leaves_source, sign, down).

rule(r15_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r15_liquid_enters_destination, light_source).
body(r15_liquid_enters_destination, pour_mid_height).
body(r15_liquid_enters_destination, pour_near_rim).
body(r15_liquid_enters_destination, pour_steeply_tilted).
body(r15_liquid_enters_destination, slippery_destination).
body(r15_liquid_enters_destination, some_liquid).
learned(r15_liquid_enters_destination).
provenance(r15_liquid_enters_destination, antecedent, a15).
provenance(r15_liquid_enters_destination, parent, a5).
provenance(r15_liquid_enters_destination, simulations, 65).
provenance(r15_liquid_enters_destination, weight_mass_permille, 29736).
provenance(r15_liquid_enters_destination, confidence_permille, 629).
provenance(r15_liquid_enters_destination, score_permille, 585).
provenance(r15_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r15_liquid_enters_destination, direction, particle_count).
provenance(r15_liquid_enters_destination, sign, down).

rule(r15_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r15_liquid_remains_in_destination, light_source).
body(r15_liquid_remains_in_destination, pour_mid_height).
body(r15_liquid_remains_in_destination, pour_near_rim).
body(r15_liquid_remains_in_destination, pour_steeply_tilted).
body(r15_liquid_remains_in_destination, slippery_destination).
body(r15_liquid_remains_in_destination, some_liquid).
learned(r15_liquid_remains_in_destination).
provenance(r15_liquid_remains_in_destination, antecedent, a15).
provenance(r15_liquid_remains_in_destination, parent, a5).
provenance(r15_liquid_remains_in_destination, simulations, 65).
provenance(r15_liquid_remains_in_destination, weight_mass_permille, 29736).
provenance(r15_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r15_liquid_remains_in_destination, score_permille, 988).
provenance(r15_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r15_liquid_remains_in_destination, direction, particle_count).
provenance(r15_liquid_remains_in_destination, sign, down).

rule(r15_no_spill, defeasible, no_spill).
body(r15_no_spill, light_source).
body(r15_no_spill, pour_mid_height).
body(r15_no_spill, pour_near_rim).
body(r15_no_spill, pour_steeply_tilted).
body(r15_no_spill, slippery_destination).
body(r15_no_spill, some_liquid).
learned(r15_no_spill).
provenance(r15_no_spill, antecedent, a15).
provenance(r15_no_spill, parent, a5).
provenance(r15_no_spill, simulations, 65).
provenance(r15_no_spill, weight_mass_permille, 29736).
provenance(r15_no_spill, confidence_permille, 962).
provenance(r15_no_spill, score_permille, 938).
provenance(r15_no_spill, followed, liquid_leaves_source).
provenance(r15_no_spill, direction, particle_count).
provenance(r15_no_spill, sign, down).

rule(r16_destination_still_approach, defeasible, destination_still_approach).
body(r16_destination_still_approach, light_source).
body(r16_destination_still_approach, pour_mid_height).
body(r16_destination_still_approach, pour_near_rim).
body(r16_destination_still_approach, pour_offset_sideways).
body(r16_destination_still_approach, pour_steeply_tilted).
body(r16_destination_still_approach, slippery_destination).
learned(r16_destination_still_approach).
provenance(r16_destination_still_approach, antecedent, a16).
provenance(r16_destination_still_approach, parent, a5).
provenance(r16_destination_still_approach, simulations, 74).
provenance(r16_destination_still_approach, weight_mass_permille, 31874).
provenance(r16_destination_still_approach, confidence_permille, 951).
provenance(r16_destination_still_approach, score_permille, 953).
provenance(r16_destination_still_approach, followed, liquid_leaves_source).
provenance(r16_destination_still_approach, direction, pour_y).
provenance(r16_destination_still_approach, sign, up).

rule(r16_destination_still_retreat, defeasible, destination_still_retreat).
body(r16_destination_still_retreat, light_source).
body(r16_destination_still_retreat, pour_mid_height).
body(r16_destination_still_retreat, pour_near_rim).
body(r16_destination_still_retreat, pour_offset_sideways).
body(r16_destination_still_retreat, pour_steeply_tilted).
body(r16_destination_still_retreat, slippery_destination).
learned(r16_destination_still_retreat).
provenance(r16_destination_still_retreat, antecedent, a16).
provenance(r16_destination_still_retreat, parent, a5).
provenance(r16_destination_still_retreat, simulations, 74).
provenance(r16_destination_still_retreat, weight_mass_permille, 31874).
provenance(r16_destination_still_retreat, confidence_permille, 946).
provenance(r16_destination_still_retreat, score_permille, 944).
provenance(r16_destination_still_retreat, followed, liquid_leaves_source).
provenance(r16_destination_still_retreat, direction, pour_y).
provenance(r16_destination_still_retreat, sign, up).

rule(r16_destination_still_settle, defeasible, destination_still_settle).
body(r16_destination_still_settle, light_source).
body(r16_destination_still_settle, pour_mid_height).
body(r16_destination_still_settle, pour_near_rim).
body(r16_destination_still_settle, pour_offset_sideways).
body(r16_destination_still_settle, pour_steeply_tilted).
body(r16_destination_still_settle, slippery_destination).
learned(r16_destination_still_settle).
provenance(r16_destination_still_settle, antecedent, a16).
provenance(r16_destination_still_settle, parent, a5).
provenance(r16_destination_still_settle, simulations, 74).
provenance(r16_destination_still_settle, weight_mass_permille, 31874).
provenance(r16_destination_still_settle, confidence_permille, 1000).
provenance(r16_destination_still_settle, score_permille, 999).
provenance(r16_destination_still_settle, followed, liquid_leaves_source).
provenance(r16_destination_still_settle, direction, pour_y).
provenance(r16_destination_still_settle, sign, up).

rule(r16_destination_upright, defeasible, destination_upright).
body(r16_destination_upright, light_source).
body(r16_destination_upright, pour_mid_height).
body(r16_destination_upright, pour_near_rim).
body(r16_destination_upright, pour_offset_sideways).
body(r16_destination_upright, pour_steeply_tilted).
body(r16_destination_upright, slippery_destination).
learned(r16_destination_upright).
provenance(r16_destination_upright, antecedent, a16).
provenance(r16_destination_upright, parent, a5).
provenance(r16_destination_upright, simulations, 74).
provenance(r16_destination_upright, weight_mass_permille, 31874).
provenance(r16_destination_upright, confidence_permille, 1000).
provenance(r16_destination_upright, score_permille, 1000).
provenance(r16_destination_upright, followed, liquid_leaves_source).
provenance(r16_destination_upright, direction, pour_y).
provenance(r16_destination_upright, sign, up).

rule(r16_source_clear, defeasible, source_clear).
body(r16_source_clear, light_source).
body(r16_source_clear, pour_mid_height).
body(r16_source_clear, pour_near_rim).
body(r16_source_clear, pour_offset_sideways).
body(r16_source_clear, pour_steeply_tilted).
body(r16_source_clear, slippery_destination).
learned(r16_source_clear).
provenance(r16_source_clear, antecedent, a16).
provenance(r16_source_clear, parent, a5).
provenance(r16_source_clear, simulations, 74).
provenance(r16_source_clear, weight_mass_permille, 31874).
provenance(r16_source_clear, confidence_permille, 1000).
provenance(r16_source_clear, score_permille, 996).
provenance(r16_source_clear, followed, liquid_leaves_source).
provenance(r16_source_clear, direction, pour_y).
provenance(r16_source_clear, sign, up).

rule(r16_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r16_liquid_leaves_source, light_source).
body(r16_liquid_leaves_source, pour_mid_height).
body(r16_liquid_leaves_source, pour_near_rim).
body(r16_liquid_leaves_source, pour_offset_sideways).
body(r16_liquid_leaves_source, pour_steeply_tilted).
body(r16_liquid_leaves_source, slippery_destination).
learned(r16_liquid_leaves_source).
provenance(r16_liquid_leaves_source, antecedent, a16).
provenance(r16_liquid_leaves_source, parent, a5).
provenance(r16_liquid_leaves_source, simulations, 74).
provenance(r16_liquid_leaves_source, weight_mass_permille, 31874).
provenance(r16_liquid_leaves_source, confidence_permille, 854).
provenance(r16_liquid_leaves_source, score_permille, 805).
provenance(r16_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r16_liquid_leaves_source, direction, pour_y).
provenance(r16_liquid_leaves_source, sign, up).

rule(r16_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r16_liquid_enters_destination, light_source).
body(r16_liquid_enters_destination, pour_mid_height).
body(r16_liquid_enters_destination, pour_near_rim).
body(r16_liquid_enters_destination, pour_offset_sideways).
body(r16_liquid_enters_destination, pour_steeply_tilted).
body(r16_liquid_enters_destination, slippery_destination).
learned(r16_liquid_enters_destination).
provenance(r16_liquid_enters_destination, antecedent, a16).
provenance(r16_liquid_enters_destination, parent, a5).
provenance(r16_liquid_enters_destination, simulations, 74).
provenance(r16_liquid_enters_destination, weight_mass_permille, 31874).
provenance(r16_liquid_enters_destination, confidence_permille, 869).
provenance(r16_liquid_enters_destination, score_permille, 262).
provenance(r16_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r16_liquid_enters_destination, direction, pour_y).
provenance(r16_liquid_enters_destination, sign, up).

rule(r16_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r16_liquid_remains_in_destination, light_source).
body(r16_liquid_remains_in_destination, pour_mid_height).
body(r16_liquid_remains_in_destination, pour_near_rim).
body(r16_liquid_remains_in_destination, pour_offset_sideways).
body(r16_liquid_remains_in_destination, pour_steeply_tilted).
body(r16_liquid_remains_in_destination, slippery_destination).
learned(r16_liquid_remains_in_destination).
provenance(r16_liquid_remains_in_destination, antecedent, a16).
provenance(r16_liquid_remains_in_destination, parent, a5).
provenance(r16_liquid_remains_in_destination, simulations, 74).
provenance(r16_liquid_remains_in_destination, weight_mass_permille, 31874).
provenance(r16_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r16_liquid_remains_in_destination, score_permille, 978).
provenance(r16_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r16_liquid_remains_in_destination, direction, pour_y).
provenance(r16_liquid_remains_in_destination, sign, up).

rule(r16_no_spill, defeasible, neg(no_spill)).
body(r16_no_spill, light_source).
body(r16_no_spill, pour_mid_height).
body(r16_no_spill, pour_near_rim).
body(r16_no_spill, pour_offset_sideways).
body(r16_no_spill, pour_steeply_tilted).
body(r16_no_spill, slippery_destination).
learned(r16_no_spill).
provenance(r16_no_spill, antecedent, a16).
provenance(r16_no_spill, parent, a5).
provenance(r16_no_spill, simulations, 74).
provenance(r16_no_spill, weight_mass_permille, 31874).
provenance(r16_no_spill, confidence_permille, 611).
provenance(r16_no_spill, score_permille, 449).
provenance(r16_no_spill, followed, liquid_leaves_source).
provenance(r16_no_spill, direction, pour_y).
provenance(r16_no_spill, sign, up).

rule(r17_destination_still_approach, defeasible, destination_still_approach).
body(r17_destination_still_approach, light_source).
body(r17_destination_still_approach, pour_mid_height).
body(r17_destination_still_approach, pour_near_rim).
body(r17_destination_still_approach, pour_steeply_tilted).
body(r17_destination_still_approach, slippery_destination).
body(r17_destination_still_approach, sticky_liquid).
learned(r17_destination_still_approach).
provenance(r17_destination_still_approach, antecedent, a17).
provenance(r17_destination_still_approach, parent, a5).
provenance(r17_destination_still_approach, simulations, 128).
provenance(r17_destination_still_approach, weight_mass_permille, 29349).
provenance(r17_destination_still_approach, confidence_permille, 981).
provenance(r17_destination_still_approach, score_permille, 945).
provenance(r17_destination_still_approach, followed, liquid_leaves_source).
provenance(r17_destination_still_approach, direction, particle_friction).
provenance(r17_destination_still_approach, sign, up).

rule(r17_destination_still_retreat, defeasible, destination_still_retreat).
body(r17_destination_still_retreat, light_source).
body(r17_destination_still_retreat, pour_mid_height).
body(r17_destination_still_retreat, pour_near_rim).
body(r17_destination_still_retreat, pour_steeply_tilted).
body(r17_destination_still_retreat, slippery_destination).
body(r17_destination_still_retreat, sticky_liquid).
learned(r17_destination_still_retreat).
provenance(r17_destination_still_retreat, antecedent, a17).
provenance(r17_destination_still_retreat, parent, a5).
provenance(r17_destination_still_retreat, simulations, 128).
provenance(r17_destination_still_retreat, weight_mass_permille, 29349).
provenance(r17_destination_still_retreat, confidence_permille, 982).
provenance(r17_destination_still_retreat, score_permille, 961).
provenance(r17_destination_still_retreat, followed, liquid_leaves_source).
provenance(r17_destination_still_retreat, direction, particle_friction).
provenance(r17_destination_still_retreat, sign, up).

rule(r17_destination_still_settle, defeasible, destination_still_settle).
body(r17_destination_still_settle, light_source).
body(r17_destination_still_settle, pour_mid_height).
body(r17_destination_still_settle, pour_near_rim).
body(r17_destination_still_settle, pour_steeply_tilted).
body(r17_destination_still_settle, slippery_destination).
body(r17_destination_still_settle, sticky_liquid).
learned(r17_destination_still_settle).
provenance(r17_destination_still_settle, antecedent, a17).
provenance(r17_destination_still_settle, parent, a5).
provenance(r17_destination_still_settle, simulations, 128).
provenance(r17_destination_still_settle, weight_mass_permille, 29349).
provenance(r17_destination_still_settle, confidence_permille, 1000).
provenance(r17_destination_still_settle, score_permille, 994).
provenance(r17_destination_still_settle, followed, liquid_leaves_source).
provenance(r17_destination_still_settle, direction, particle_friction).
provenance(r17_destination_still_settle, sign, up).

rule(r17_destination_upright, defeasible, destination_upright).
body(r17_destination_upright, light_source).
body(r17_destination_upright, pour_mid_height).
body(r17_destination_upright, pour_near_rim).
body(r17_destination_upright, pour_steeply_tilted).
body(r17_destination_upright, slippery_destination).
body(r17_destination_upright, sticky_liquid).
learned(r17_destination_upright).
provenance(r17_destination_upright, antecedent, a17).
provenance(r17_destination_upright, parent, a5).
provenance(r17_destination_upright, simulations, 128).
provenance(r17_destination_upright, weight_mass_permille, 29349).
provenance(r17_destination_upright, confidence_permille, 1000).
provenance(r17_destination_upright, score_permille, 997).
provenance(r17_destination_upright, followed, liquid_leaves_source).
provenance(r17_destination_upright, direction, particle_friction).
provenance(r17_destination_upright, sign, up).

rule(r17_source_clear, defeasible, source_clear).
body(r17_source_clear, light_source).
body(r17_source_clear, pour_mid_height).
body(r17_source_clear, pour_near_rim).
body(r17_source_clear, pour_steeply_tilted).
body(r17_source_clear, slippery_destination).
body(r17_source_clear, sticky_liquid).
learned(r17_source_clear).
provenance(r17_source_clear, antecedent, a17).
provenance(r17_source_clear, parent, a5).
provenance(r17_source_clear, simulations, 128).
provenance(r17_source_clear, weight_mass_permille, 29349).
provenance(r17_source_clear, confidence_permille, 1000).
provenance(r17_source_clear, score_permille, 993).
provenance(r17_source_clear, followed, liquid_leaves_source).
provenance(r17_source_clear, direction, particle_friction).
provenance(r17_source_clear, sign, up).

rule(r17_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r17_liquid_leaves_source, light_source).
body(r17_liquid_leaves_source, pour_mid_height).
body(r17_liquid_leaves_source, pour_near_rim).
body(r17_liquid_leaves_source, pour_steeply_tilted).
body(r17_liquid_leaves_source, slippery_destination).
body(r17_liquid_leaves_source, sticky_liquid).
learned(r17_liquid_leaves_source).
provenance(r17_liquid_leaves_source, antecedent, a17).
provenance(r17_liquid_leaves_source, parent, a5).
provenance(r17_liquid_leaves_source, simulations, 128).
provenance(r17_liquid_leaves_source, weight_mass_permille, 29349).
provenance(r17_liquid_leaves_source, confidence_permille, 674).
provenance(r17_liquid_leaves_source, score_permille, 657).
provenance(r17_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r17_liquid_leaves_source, direction, particle_friction).
provenance(r17_liquid_leaves_source, sign, up).

rule(r17_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r17_liquid_enters_destination, light_source).
body(r17_liquid_enters_destination, pour_mid_height).
body(r17_liquid_enters_destination, pour_near_rim).
body(r17_liquid_enters_destination, pour_steeply_tilted).
body(r17_liquid_enters_destination, slippery_destination).
body(r17_liquid_enters_destination, sticky_liquid).
learned(r17_liquid_enters_destination).
provenance(r17_liquid_enters_destination, antecedent, a17).
provenance(r17_liquid_enters_destination, parent, a5).
provenance(r17_liquid_enters_destination, simulations, 128).
provenance(r17_liquid_enters_destination, weight_mass_permille, 29349).
provenance(r17_liquid_enters_destination, confidence_permille, 629).
provenance(r17_liquid_enters_destination, score_permille, 582).
provenance(r17_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r17_liquid_enters_destination, direction, particle_friction).
provenance(r17_liquid_enters_destination, sign, up).

rule(r17_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r17_liquid_remains_in_destination, light_source).
body(r17_liquid_remains_in_destination, pour_mid_height).
body(r17_liquid_remains_in_destination, pour_near_rim).
body(r17_liquid_remains_in_destination, pour_steeply_tilted).
body(r17_liquid_remains_in_destination, slippery_destination).
body(r17_liquid_remains_in_destination, sticky_liquid).
learned(r17_liquid_remains_in_destination).
provenance(r17_liquid_remains_in_destination, antecedent, a17).
provenance(r17_liquid_remains_in_destination, parent, a5).
provenance(r17_liquid_remains_in_destination, simulations, 128).
provenance(r17_liquid_remains_in_destination, weight_mass_permille, 29349).
provenance(r17_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r17_liquid_remains_in_destination, score_permille, 994).
provenance(r17_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r17_liquid_remains_in_destination, direction, particle_friction).
provenance(r17_liquid_remains_in_destination, sign, up).

rule(r17_no_spill, defeasible, no_spill).
body(r17_no_spill, light_source).
body(r17_no_spill, pour_mid_height).
body(r17_no_spill, pour_near_rim).
body(r17_no_spill, pour_steeply_tilted).
body(r17_no_spill, slippery_destination).
body(r17_no_spill, sticky_liquid).
learned(r17_no_spill).
provenance(r17_no_spill, antecedent, a17).
provenance(r17_no_spill, parent, a5).
provenance(r17_no_spill, simulations, 128).
provenance(r17_no_spill, weight_mass_permille, 29349).
provenance(r17_no_spill, confidence_permille, 975).
provenance(r17_no_spill, score_permille, 921).
provenance(r17_no_spill, followed, liquid_leaves_source).
provenance(r17_no_spill, direction, particle_friction).
provenance(r17_no_spill, sign, up).

rule(r18_destination_still_approach, defeasible, destination_still_approach).
body(r18_destination_still_approach, dull_liquid).
body(r18_destination_still_approach, pour_half_tilted).
body(r18_destination_still_approach, pour_mid_height).
body(r18_destination_still_approach, pour_near_rim).
body(r18_destination_still_approach, slippery_destination).
body(r18_destination_still_approach, some_liquid).
learned(r18_destination_still_approach).
provenance(r18_destination_still_approach, antecedent, a18).
provenance(r18_destination_still_approach, parent, a11).
provenance(r18_destination_still_approach, simulations, 38).
provenance(r18_destination_still_approach, weight_mass_permille, 28790).
provenance(r18_destination_still_approach, confidence_permille, 1000).
provenance(r18_destination_still_approach, score_permille, 993).
provenance(r18_destination_still_approach, followed, liquid_leaves_source).
provenance(r18_destination_still_approach, direction, pour_pitch).
provenance(r18_destination_still_approach, sign, down).

rule(r18_destination_still_retreat, defeasible, destination_still_retreat).
body(r18_destination_still_retreat, dull_liquid).
body(r18_destination_still_retreat, pour_half_tilted).
body(r18_destination_still_retreat, pour_mid_height).
body(r18_destination_still_retreat, pour_near_rim).
body(r18_destination_still_retreat, slippery_destination).
body(r18_destination_still_retreat, some_liquid).
learned(r18_destination_still_retreat).
provenance(r18_destination_still_retreat, antecedent, a18).
provenance(r18_destination_still_retreat, parent, a11).
provenance(r18_destination_still_retreat, simulations, 38).
provenance(r18_destination_still_retreat, weight_mass_permille, 28790).
provenance(r18_destination_still_retreat, confidence_permille, 1000).
provenance(r18_destination_still_retreat, score_permille, 1000).
provenance(r18_destination_still_retreat, followed, liquid_leaves_source).
provenance(r18_destination_still_retreat, direction, pour_pitch).
provenance(r18_destination_still_retreat, sign, down).

rule(r18_destination_still_settle, defeasible, destination_still_settle).
body(r18_destination_still_settle, dull_liquid).
body(r18_destination_still_settle, pour_half_tilted).
body(r18_destination_still_settle, pour_mid_height).
body(r18_destination_still_settle, pour_near_rim).
body(r18_destination_still_settle, slippery_destination).
body(r18_destination_still_settle, some_liquid).
learned(r18_destination_still_settle).
provenance(r18_destination_still_settle, antecedent, a18).
provenance(r18_destination_still_settle, parent, a11).
provenance(r18_destination_still_settle, simulations, 38).
provenance(r18_destination_still_settle, weight_mass_permille, 28790).
provenance(r18_destination_still_settle, confidence_permille, 1000).
provenance(r18_destination_still_settle, score_permille, 1000).
provenance(r18_destination_still_settle, followed, liquid_leaves_source).
provenance(r18_destination_still_settle, direction, pour_pitch).
provenance(r18_destination_still_settle, sign, down).

rule(r18_destination_upright, defeasible, destination_upright).
body(r18_destination_upright, dull_liquid).
body(r18_destination_upright, pour_half_tilted).
body(r18_destination_upright, pour_mid_height).
body(r18_destination_upright, pour_near_rim).
body(r18_destination_upright, slippery_destination).
body(r18_destination_upright, some_liquid).
learned(r18_destination_upright).
provenance(r18_destination_upright, antecedent, a18).
provenance(r18_destination_upright, parent, a11).
provenance(r18_destination_upright, simulations, 38).
provenance(r18_destination_upright, weight_mass_permille, 28790).
provenance(r18_destination_upright, confidence_permille, 1000).
provenance(r18_destination_upright, score_permille, 1000).
provenance(r18_destination_upright, followed, liquid_leaves_source).
provenance(r18_destination_upright, direction, pour_pitch).
provenance(r18_destination_upright, sign, down).

rule(r18_source_clear, defeasible, source_clear).
body(r18_source_clear, dull_liquid).
body(r18_source_clear, pour_half_tilted).
body(r18_source_clear, pour_mid_height).
body(r18_source_clear, pour_near_rim).
body(r18_source_clear, slippery_destination).
body(r18_source_clear, some_liquid).
learned(r18_source_clear).
provenance(r18_source_clear, antecedent, a18).
provenance(r18_source_clear, parent, a11).
provenance(r18_source_clear, simulations, 38).
provenance(r18_source_clear, weight_mass_permille, 28790).
provenance(r18_source_clear, confidence_permille, 1000).
provenance(r18_source_clear, score_permille, 1000).
provenance(r18_source_clear, followed, liquid_leaves_source).
provenance(r18_source_clear, direction, pour_pitch).
provenance(r18_source_clear, sign, down).

rule(r18_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r18_liquid_leaves_source, dull_liquid).
body(r18_liquid_leaves_source, pour_half_tilted).
body(r18_liquid_leaves_source, pour_mid_height).
body(r18_liquid_leaves_source, pour_near_rim).
body(r18_liquid_leaves_source, slippery_destination).
body(r18_liquid_leaves_source, some_liquid).
learned(r18_liquid_leaves_source).
provenance(r18_liquid_leaves_source, antecedent, a18).
provenance(r18_liquid_leaves_source, parent, a11).
provenance(r18_liquid_leaves_source, simulations, 38).
provenance(r18_liquid_leaves_source, weight_mass_permille, 28790).
provenance(r18_liquid_leaves_source, confidence_permille, 1000).
provenance(r18_liquid_leaves_source, score_permille, 0).
provenance(r18_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r18_liquid_leaves_source, direction, pour_pitch).
provenance(r18_liquid_leaves_source, sign, down).

rule(r18_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r18_liquid_enters_destination, dull_liquid).
body(r18_liquid_enters_destination, pour_half_tilted).
body(r18_liquid_enters_destination, pour_mid_height).
body(r18_liquid_enters_destination, pour_near_rim).
body(r18_liquid_enters_destination, slippery_destination).
body(r18_liquid_enters_destination, some_liquid).
learned(r18_liquid_enters_destination).
provenance(r18_liquid_enters_destination, antecedent, a18).
provenance(r18_liquid_enters_destination, parent, a11).
provenance(r18_liquid_enters_destination, simulations, 38).
provenance(r18_liquid_enters_destination, weight_mass_permille, 28790).
provenance(r18_liquid_enters_destination, confidence_permille, 1000).
provenance(r18_liquid_enters_destination, score_permille, 0).
provenance(r18_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r18_liquid_enters_destination, direction, pour_pitch).
provenance(r18_liquid_enters_destination, sign, down).

rule(r18_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r18_liquid_remains_in_destination, dull_liquid).
body(r18_liquid_remains_in_destination, pour_half_tilted).
body(r18_liquid_remains_in_destination, pour_mid_height).
body(r18_liquid_remains_in_destination, pour_near_rim).
body(r18_liquid_remains_in_destination, slippery_destination).
body(r18_liquid_remains_in_destination, some_liquid).
learned(r18_liquid_remains_in_destination).
provenance(r18_liquid_remains_in_destination, antecedent, a18).
provenance(r18_liquid_remains_in_destination, parent, a11).
provenance(r18_liquid_remains_in_destination, simulations, 38).
provenance(r18_liquid_remains_in_destination, weight_mass_permille, 28790).
provenance(r18_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r18_liquid_remains_in_destination, score_permille, 1000).
provenance(r18_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r18_liquid_remains_in_destination, direction, pour_pitch).
provenance(r18_liquid_remains_in_destination, sign, down).

rule(r18_no_spill, defeasible, no_spill).
body(r18_no_spill, dull_liquid).
body(r18_no_spill, pour_half_tilted).
body(r18_no_spill, pour_mid_height).
body(r18_no_spill, pour_near_rim).
body(r18_no_spill, slippery_destination).
body(r18_no_spill, some_liquid).
learned(r18_no_spill).
provenance(r18_no_spill, antecedent, a18).
provenance(r18_no_spill, parent, a11).
provenance(r18_no_spill, simulations, 38).
provenance(r18_no_spill, weight_mass_permille, 28790).
provenance(r18_no_spill, confidence_permille, 1000).
provenance(r18_no_spill, score_permille, 1000).
provenance(r18_no_spill, followed, liquid_leaves_source).
provenance(r18_no_spill, direction, pour_pitch).
provenance(r18_no_spill, sign, down).

rule(r19_destination_still_approach, defeasible, destination_still_approach).
body(r19_destination_still_approach, dull_liquid).
body(r19_destination_still_approach, pour_mid_height).
body(r19_destination_still_approach, pour_near_rim).
body(r19_destination_still_approach, pour_steeply_tilted).
body(r19_destination_still_approach, slippery_destination).
body(r19_destination_still_approach, some_liquid).
body(r19_destination_still_approach, sticky_liquid).
learned(r19_destination_still_approach).
provenance(r19_destination_still_approach, antecedent, a19).
provenance(r19_destination_still_approach, parent, a11).
provenance(r19_destination_still_approach, simulations, 73).
provenance(r19_destination_still_approach, weight_mass_permille, 32874).
provenance(r19_destination_still_approach, confidence_permille, 991).
provenance(r19_destination_still_approach, score_permille, 980).
provenance(r19_destination_still_approach, followed, liquid_leaves_source).
provenance(r19_destination_still_approach, direction, particle_friction).
provenance(r19_destination_still_approach, sign, up).

rule(r19_destination_still_retreat, defeasible, destination_still_retreat).
body(r19_destination_still_retreat, dull_liquid).
body(r19_destination_still_retreat, pour_mid_height).
body(r19_destination_still_retreat, pour_near_rim).
body(r19_destination_still_retreat, pour_steeply_tilted).
body(r19_destination_still_retreat, slippery_destination).
body(r19_destination_still_retreat, some_liquid).
body(r19_destination_still_retreat, sticky_liquid).
learned(r19_destination_still_retreat).
provenance(r19_destination_still_retreat, antecedent, a19).
provenance(r19_destination_still_retreat, parent, a11).
provenance(r19_destination_still_retreat, simulations, 73).
provenance(r19_destination_still_retreat, weight_mass_permille, 32874).
provenance(r19_destination_still_retreat, confidence_permille, 944).
provenance(r19_destination_still_retreat, score_permille, 934).
provenance(r19_destination_still_retreat, followed, liquid_leaves_source).
provenance(r19_destination_still_retreat, direction, particle_friction).
provenance(r19_destination_still_retreat, sign, up).

rule(r19_destination_still_settle, defeasible, destination_still_settle).
body(r19_destination_still_settle, dull_liquid).
body(r19_destination_still_settle, pour_mid_height).
body(r19_destination_still_settle, pour_near_rim).
body(r19_destination_still_settle, pour_steeply_tilted).
body(r19_destination_still_settle, slippery_destination).
body(r19_destination_still_settle, some_liquid).
body(r19_destination_still_settle, sticky_liquid).
learned(r19_destination_still_settle).
provenance(r19_destination_still_settle, antecedent, a19).
provenance(r19_destination_still_settle, parent, a11).
provenance(r19_destination_still_settle, simulations, 73).
provenance(r19_destination_still_settle, weight_mass_permille, 32874).
provenance(r19_destination_still_settle, confidence_permille, 1000).
provenance(r19_destination_still_settle, score_permille, 999).
provenance(r19_destination_still_settle, followed, liquid_leaves_source).
provenance(r19_destination_still_settle, direction, particle_friction).
provenance(r19_destination_still_settle, sign, up).

rule(r19_destination_upright, defeasible, destination_upright).
body(r19_destination_upright, dull_liquid).
body(r19_destination_upright, pour_mid_height).
body(r19_destination_upright, pour_near_rim).
body(r19_destination_upright, pour_steeply_tilted).
body(r19_destination_upright, slippery_destination).
body(r19_destination_upright, some_liquid).
body(r19_destination_upright, sticky_liquid).
learned(r19_destination_upright).
provenance(r19_destination_upright, antecedent, a19).
provenance(r19_destination_upright, parent, a11).
provenance(r19_destination_upright, simulations, 73).
provenance(r19_destination_upright, weight_mass_permille, 32874).
provenance(r19_destination_upright, confidence_permille, 1000).
provenance(r19_destination_upright, score_permille, 997).
provenance(r19_destination_upright, followed, liquid_leaves_source).
provenance(r19_destination_upright, direction, particle_friction).
provenance(r19_destination_upright, sign, up).

rule(r19_source_clear, defeasible, source_clear).
body(r19_source_clear, dull_liquid).
body(r19_source_clear, pour_mid_height).
body(r19_source_clear, pour_near_rim).
body(r19_source_clear, pour_steeply_tilted).
body(r19_source_clear, slippery_destination).
body(r19_source_clear, some_liquid).
body(r19_source_clear, sticky_liquid).
learned(r19_source_clear).
provenance(r19_source_clear, antecedent, a19).
provenance(r19_source_clear, parent, a11).
provenance(r19_source_clear, simulations, 73).
provenance(r19_source_clear, weight_mass_permille, 32874).
provenance(r19_source_clear, confidence_permille, 982).
provenance(r19_source_clear, score_permille, 976).
provenance(r19_source_clear, followed, liquid_leaves_source).
provenance(r19_source_clear, direction, particle_friction).
provenance(r19_source_clear, sign, up).

rule(r19_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r19_liquid_leaves_source, dull_liquid).
body(r19_liquid_leaves_source, pour_mid_height).
body(r19_liquid_leaves_source, pour_near_rim).
body(r19_liquid_leaves_source, pour_steeply_tilted).
body(r19_liquid_leaves_source, slippery_destination).
body(r19_liquid_leaves_source, some_liquid).
body(r19_liquid_leaves_source, sticky_liquid).
learned(r19_liquid_leaves_source).
provenance(r19_liquid_leaves_source, antecedent, a19).
provenance(r19_liquid_leaves_source, parent, a11).
provenance(r19_liquid_leaves_source, simulations, 73).
provenance(r19_liquid_leaves_source, weight_mass_permille, 32874).
provenance(r19_liquid_leaves_source, confidence_permille, 519).
provenance(r19_liquid_leaves_source, score_permille, 546).
provenance(r19_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r19_liquid_leaves_source, direction, particle_friction).
provenance(r19_liquid_leaves_source, sign, up).

rule(r19_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r19_liquid_enters_destination, dull_liquid).
body(r19_liquid_enters_destination, pour_mid_height).
body(r19_liquid_enters_destination, pour_near_rim).
body(r19_liquid_enters_destination, pour_steeply_tilted).
body(r19_liquid_enters_destination, slippery_destination).
body(r19_liquid_enters_destination, some_liquid).
body(r19_liquid_enters_destination, sticky_liquid).
learned(r19_liquid_enters_destination).
provenance(r19_liquid_enters_destination, antecedent, a19).
provenance(r19_liquid_enters_destination, parent, a11).
provenance(r19_liquid_enters_destination, simulations, 73).
provenance(r19_liquid_enters_destination, weight_mass_permille, 32874).
provenance(r19_liquid_enters_destination, confidence_permille, 512).
provenance(r19_liquid_enters_destination, score_permille, 507).
provenance(r19_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r19_liquid_enters_destination, direction, particle_friction).
provenance(r19_liquid_enters_destination, sign, up).

rule(r19_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r19_liquid_remains_in_destination, dull_liquid).
body(r19_liquid_remains_in_destination, pour_mid_height).
body(r19_liquid_remains_in_destination, pour_near_rim).
body(r19_liquid_remains_in_destination, pour_steeply_tilted).
body(r19_liquid_remains_in_destination, slippery_destination).
body(r19_liquid_remains_in_destination, some_liquid).
body(r19_liquid_remains_in_destination, sticky_liquid).
learned(r19_liquid_remains_in_destination).
provenance(r19_liquid_remains_in_destination, antecedent, a19).
provenance(r19_liquid_remains_in_destination, parent, a11).
provenance(r19_liquid_remains_in_destination, simulations, 73).
provenance(r19_liquid_remains_in_destination, weight_mass_permille, 32874).
provenance(r19_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r19_liquid_remains_in_destination, score_permille, 994).
provenance(r19_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r19_liquid_remains_in_destination, direction, particle_friction).
provenance(r19_liquid_remains_in_destination, sign, up).

rule(r19_no_spill, defeasible, no_spill).
body(r19_no_spill, dull_liquid).
body(r19_no_spill, pour_mid_height).
body(r19_no_spill, pour_near_rim).
body(r19_no_spill, pour_steeply_tilted).
body(r19_no_spill, slippery_destination).
body(r19_no_spill, some_liquid).
body(r19_no_spill, sticky_liquid).
learned(r19_no_spill).
provenance(r19_no_spill, antecedent, a19).
provenance(r19_no_spill, parent, a11).
provenance(r19_no_spill, simulations, 73).
provenance(r19_no_spill, weight_mass_permille, 32874).
provenance(r19_no_spill, confidence_permille, 1000).
provenance(r19_no_spill, score_permille, 956).
provenance(r19_no_spill, followed, liquid_leaves_source).
provenance(r19_no_spill, direction, particle_friction).
provenance(r19_no_spill, sign, up).

rule(r20_destination_still_approach, defeasible, destination_still_approach).
body(r20_destination_still_approach, dull_liquid).
body(r20_destination_still_approach, grippy_source).
body(r20_destination_still_approach, pour_mid_height).
body(r20_destination_still_approach, pour_near_rim).
body(r20_destination_still_approach, pour_steeply_tilted).
body(r20_destination_still_approach, slippery_destination).
body(r20_destination_still_approach, some_liquid).
learned(r20_destination_still_approach).
provenance(r20_destination_still_approach, antecedent, a20).
provenance(r20_destination_still_approach, parent, a11).
provenance(r20_destination_still_approach, simulations, 74).
provenance(r20_destination_still_approach, weight_mass_permille, 34779).
provenance(r20_destination_still_approach, confidence_permille, 955).
provenance(r20_destination_still_approach, score_permille, 937).
provenance(r20_destination_still_approach, followed, liquid_leaves_source).
provenance(r20_destination_still_approach, direction, source_friction).
provenance(r20_destination_still_approach, sign, up).

rule(r20_destination_still_retreat, defeasible, destination_still_retreat).
body(r20_destination_still_retreat, dull_liquid).
body(r20_destination_still_retreat, grippy_source).
body(r20_destination_still_retreat, pour_mid_height).
body(r20_destination_still_retreat, pour_near_rim).
body(r20_destination_still_retreat, pour_steeply_tilted).
body(r20_destination_still_retreat, slippery_destination).
body(r20_destination_still_retreat, some_liquid).
learned(r20_destination_still_retreat).
provenance(r20_destination_still_retreat, antecedent, a20).
provenance(r20_destination_still_retreat, parent, a11).
provenance(r20_destination_still_retreat, simulations, 74).
provenance(r20_destination_still_retreat, weight_mass_permille, 34779).
provenance(r20_destination_still_retreat, confidence_permille, 914).
provenance(r20_destination_still_retreat, score_permille, 905).
provenance(r20_destination_still_retreat, followed, liquid_leaves_source).
provenance(r20_destination_still_retreat, direction, source_friction).
provenance(r20_destination_still_retreat, sign, up).

rule(r20_destination_still_settle, defeasible, destination_still_settle).
body(r20_destination_still_settle, dull_liquid).
body(r20_destination_still_settle, grippy_source).
body(r20_destination_still_settle, pour_mid_height).
body(r20_destination_still_settle, pour_near_rim).
body(r20_destination_still_settle, pour_steeply_tilted).
body(r20_destination_still_settle, slippery_destination).
body(r20_destination_still_settle, some_liquid).
learned(r20_destination_still_settle).
provenance(r20_destination_still_settle, antecedent, a20).
provenance(r20_destination_still_settle, parent, a11).
provenance(r20_destination_still_settle, simulations, 74).
provenance(r20_destination_still_settle, weight_mass_permille, 34779).
provenance(r20_destination_still_settle, confidence_permille, 1000).
provenance(r20_destination_still_settle, score_permille, 998).
provenance(r20_destination_still_settle, followed, liquid_leaves_source).
provenance(r20_destination_still_settle, direction, source_friction).
provenance(r20_destination_still_settle, sign, up).

rule(r20_destination_upright, defeasible, destination_upright).
body(r20_destination_upright, dull_liquid).
body(r20_destination_upright, grippy_source).
body(r20_destination_upright, pour_mid_height).
body(r20_destination_upright, pour_near_rim).
body(r20_destination_upright, pour_steeply_tilted).
body(r20_destination_upright, slippery_destination).
body(r20_destination_upright, some_liquid).
learned(r20_destination_upright).
provenance(r20_destination_upright, antecedent, a20).
provenance(r20_destination_upright, parent, a11).
provenance(r20_destination_upright, simulations, 74).
provenance(r20_destination_upright, weight_mass_permille, 34779).
provenance(r20_destination_upright, confidence_permille, 1000).
provenance(r20_destination_upright, score_permille, 1000).
provenance(r20_destination_upright, followed, liquid_leaves_source).
provenance(r20_destination_upright, direction, source_friction).
provenance(r20_destination_upright, sign, up).

rule(r20_source_clear, defeasible, source_clear).
body(r20_source_clear, dull_liquid).
body(r20_source_clear, grippy_source).
body(r20_source_clear, pour_mid_height).
body(r20_source_clear, pour_near_rim).
body(r20_source_clear, pour_steeply_tilted).
body(r20_source_clear, slippery_destination).
body(r20_source_clear, some_liquid).
learned(r20_source_clear).
provenance(r20_source_clear, antecedent, a20).
provenance(r20_source_clear, parent, a11).
provenance(r20_source_clear, simulations, 74).
provenance(r20_source_clear, weight_mass_permille, 34779).
provenance(r20_source_clear, confidence_permille, 1000).
provenance(r20_source_clear, score_permille, 1000).
provenance(r20_source_clear, followed, liquid_leaves_source).
provenance(r20_source_clear, direction, source_friction).
provenance(r20_source_clear, sign, up).

rule(r20_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r20_liquid_leaves_source, dull_liquid).
body(r20_liquid_leaves_source, grippy_source).
body(r20_liquid_leaves_source, pour_mid_height).
body(r20_liquid_leaves_source, pour_near_rim).
body(r20_liquid_leaves_source, pour_steeply_tilted).
body(r20_liquid_leaves_source, slippery_destination).
body(r20_liquid_leaves_source, some_liquid).
learned(r20_liquid_leaves_source).
provenance(r20_liquid_leaves_source, antecedent, a20).
provenance(r20_liquid_leaves_source, parent, a11).
provenance(r20_liquid_leaves_source, simulations, 74).
provenance(r20_liquid_leaves_source, weight_mass_permille, 34779).
provenance(r20_liquid_leaves_source, confidence_permille, 558).
provenance(r20_liquid_leaves_source, score_permille, 574).
provenance(r20_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r20_liquid_leaves_source, direction, source_friction).
provenance(r20_liquid_leaves_source, sign, up).

rule(r20_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r20_liquid_enters_destination, dull_liquid).
body(r20_liquid_enters_destination, grippy_source).
body(r20_liquid_enters_destination, pour_mid_height).
body(r20_liquid_enters_destination, pour_near_rim).
body(r20_liquid_enters_destination, pour_steeply_tilted).
body(r20_liquid_enters_destination, slippery_destination).
body(r20_liquid_enters_destination, some_liquid).
learned(r20_liquid_enters_destination).
provenance(r20_liquid_enters_destination, antecedent, a20).
provenance(r20_liquid_enters_destination, parent, a11).
provenance(r20_liquid_enters_destination, simulations, 74).
provenance(r20_liquid_enters_destination, weight_mass_permille, 34779).
provenance(r20_liquid_enters_destination, confidence_permille, 530).
provenance(r20_liquid_enters_destination, score_permille, 541).
provenance(r20_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r20_liquid_enters_destination, direction, source_friction).
provenance(r20_liquid_enters_destination, sign, up).

rule(r20_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r20_liquid_remains_in_destination, dull_liquid).
body(r20_liquid_remains_in_destination, grippy_source).
body(r20_liquid_remains_in_destination, pour_mid_height).
body(r20_liquid_remains_in_destination, pour_near_rim).
body(r20_liquid_remains_in_destination, pour_steeply_tilted).
body(r20_liquid_remains_in_destination, slippery_destination).
body(r20_liquid_remains_in_destination, some_liquid).
learned(r20_liquid_remains_in_destination).
provenance(r20_liquid_remains_in_destination, antecedent, a20).
provenance(r20_liquid_remains_in_destination, parent, a11).
provenance(r20_liquid_remains_in_destination, simulations, 74).
provenance(r20_liquid_remains_in_destination, weight_mass_permille, 34779).
provenance(r20_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r20_liquid_remains_in_destination, score_permille, 992).
provenance(r20_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r20_liquid_remains_in_destination, direction, source_friction).
provenance(r20_liquid_remains_in_destination, sign, up).

rule(r20_no_spill, defeasible, no_spill).
body(r20_no_spill, dull_liquid).
body(r20_no_spill, grippy_source).
body(r20_no_spill, pour_mid_height).
body(r20_no_spill, pour_near_rim).
body(r20_no_spill, pour_steeply_tilted).
body(r20_no_spill, slippery_destination).
body(r20_no_spill, some_liquid).
learned(r20_no_spill).
provenance(r20_no_spill, antecedent, a20).
provenance(r20_no_spill, parent, a11).
provenance(r20_no_spill, simulations, 74).
provenance(r20_no_spill, weight_mass_permille, 34779).
provenance(r20_no_spill, confidence_permille, 1000).
provenance(r20_no_spill, score_permille, 961).
provenance(r20_no_spill, followed, liquid_leaves_source).
provenance(r20_no_spill, direction, source_friction).
provenance(r20_no_spill, sign, up).

rule(r21_destination_still_approach, defeasible, destination_still_approach).
body(r21_destination_still_approach, bouncy_destination).
body(r21_destination_still_approach, light_source).
body(r21_destination_still_approach, little_liquid).
body(r21_destination_still_approach, pour_mid_height).
body(r21_destination_still_approach, pour_near_rim).
body(r21_destination_still_approach, pour_steeply_tilted).
body(r21_destination_still_approach, slippery_destination).
learned(r21_destination_still_approach).
provenance(r21_destination_still_approach, antecedent, a21).
provenance(r21_destination_still_approach, parent, a14).
provenance(r21_destination_still_approach, simulations, 60).
provenance(r21_destination_still_approach, weight_mass_permille, 31451).
provenance(r21_destination_still_approach, confidence_permille, 1000).
provenance(r21_destination_still_approach, score_permille, 991).
provenance(r21_destination_still_approach, followed, liquid_leaves_source).
provenance(r21_destination_still_approach, direction, destination_restitution).
provenance(r21_destination_still_approach, sign, up).

rule(r21_destination_still_retreat, defeasible, destination_still_retreat).
body(r21_destination_still_retreat, bouncy_destination).
body(r21_destination_still_retreat, light_source).
body(r21_destination_still_retreat, little_liquid).
body(r21_destination_still_retreat, pour_mid_height).
body(r21_destination_still_retreat, pour_near_rim).
body(r21_destination_still_retreat, pour_steeply_tilted).
body(r21_destination_still_retreat, slippery_destination).
learned(r21_destination_still_retreat).
provenance(r21_destination_still_retreat, antecedent, a21).
provenance(r21_destination_still_retreat, parent, a14).
provenance(r21_destination_still_retreat, simulations, 60).
provenance(r21_destination_still_retreat, weight_mass_permille, 31451).
provenance(r21_destination_still_retreat, confidence_permille, 952).
provenance(r21_destination_still_retreat, score_permille, 954).
provenance(r21_destination_still_retreat, followed, liquid_leaves_source).
provenance(r21_destination_still_retreat, direction, destination_restitution).
provenance(r21_destination_still_retreat, sign, up).

rule(r21_destination_still_settle, defeasible, destination_still_settle).
body(r21_destination_still_settle, bouncy_destination).
body(r21_destination_still_settle, light_source).
body(r21_destination_still_settle, little_liquid).
body(r21_destination_still_settle, pour_mid_height).
body(r21_destination_still_settle, pour_near_rim).
body(r21_destination_still_settle, pour_steeply_tilted).
body(r21_destination_still_settle, slippery_destination).
learned(r21_destination_still_settle).
provenance(r21_destination_still_settle, antecedent, a21).
provenance(r21_destination_still_settle, parent, a14).
provenance(r21_destination_still_settle, simulations, 60).
provenance(r21_destination_still_settle, weight_mass_permille, 31451).
provenance(r21_destination_still_settle, confidence_permille, 1000).
provenance(r21_destination_still_settle, score_permille, 996).
provenance(r21_destination_still_settle, followed, liquid_leaves_source).
provenance(r21_destination_still_settle, direction, destination_restitution).
provenance(r21_destination_still_settle, sign, up).

rule(r21_destination_upright, defeasible, destination_upright).
body(r21_destination_upright, bouncy_destination).
body(r21_destination_upright, light_source).
body(r21_destination_upright, little_liquid).
body(r21_destination_upright, pour_mid_height).
body(r21_destination_upright, pour_near_rim).
body(r21_destination_upright, pour_steeply_tilted).
body(r21_destination_upright, slippery_destination).
learned(r21_destination_upright).
provenance(r21_destination_upright, antecedent, a21).
provenance(r21_destination_upright, parent, a14).
provenance(r21_destination_upright, simulations, 60).
provenance(r21_destination_upright, weight_mass_permille, 31451).
provenance(r21_destination_upright, confidence_permille, 1000).
provenance(r21_destination_upright, score_permille, 997).
provenance(r21_destination_upright, followed, liquid_leaves_source).
provenance(r21_destination_upright, direction, destination_restitution).
provenance(r21_destination_upright, sign, up).

rule(r21_source_clear, defeasible, source_clear).
body(r21_source_clear, bouncy_destination).
body(r21_source_clear, light_source).
body(r21_source_clear, little_liquid).
body(r21_source_clear, pour_mid_height).
body(r21_source_clear, pour_near_rim).
body(r21_source_clear, pour_steeply_tilted).
body(r21_source_clear, slippery_destination).
learned(r21_source_clear).
provenance(r21_source_clear, antecedent, a21).
provenance(r21_source_clear, parent, a14).
provenance(r21_source_clear, simulations, 60).
provenance(r21_source_clear, weight_mass_permille, 31451).
provenance(r21_source_clear, confidence_permille, 1000).
provenance(r21_source_clear, score_permille, 1000).
provenance(r21_source_clear, followed, liquid_leaves_source).
provenance(r21_source_clear, direction, destination_restitution).
provenance(r21_source_clear, sign, up).

rule(r21_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r21_liquid_leaves_source, bouncy_destination).
body(r21_liquid_leaves_source, light_source).
body(r21_liquid_leaves_source, little_liquid).
body(r21_liquid_leaves_source, pour_mid_height).
body(r21_liquid_leaves_source, pour_near_rim).
body(r21_liquid_leaves_source, pour_steeply_tilted).
body(r21_liquid_leaves_source, slippery_destination).
learned(r21_liquid_leaves_source).
provenance(r21_liquid_leaves_source, antecedent, a21).
provenance(r21_liquid_leaves_source, parent, a14).
provenance(r21_liquid_leaves_source, simulations, 60).
provenance(r21_liquid_leaves_source, weight_mass_permille, 31451).
provenance(r21_liquid_leaves_source, confidence_permille, 559).
provenance(r21_liquid_leaves_source, score_permille, 568).
provenance(r21_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r21_liquid_leaves_source, direction, destination_restitution).
provenance(r21_liquid_leaves_source, sign, up).

rule(r21_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r21_liquid_enters_destination, bouncy_destination).
body(r21_liquid_enters_destination, light_source).
body(r21_liquid_enters_destination, little_liquid).
body(r21_liquid_enters_destination, pour_mid_height).
body(r21_liquid_enters_destination, pour_near_rim).
body(r21_liquid_enters_destination, pour_steeply_tilted).
body(r21_liquid_enters_destination, slippery_destination).
learned(r21_liquid_enters_destination).
provenance(r21_liquid_enters_destination, antecedent, a21).
provenance(r21_liquid_enters_destination, parent, a14).
provenance(r21_liquid_enters_destination, simulations, 60).
provenance(r21_liquid_enters_destination, weight_mass_permille, 31451).
provenance(r21_liquid_enters_destination, confidence_permille, 532).
provenance(r21_liquid_enters_destination, score_permille, 545).
provenance(r21_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r21_liquid_enters_destination, direction, destination_restitution).
provenance(r21_liquid_enters_destination, sign, up).

rule(r21_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r21_liquid_remains_in_destination, bouncy_destination).
body(r21_liquid_remains_in_destination, light_source).
body(r21_liquid_remains_in_destination, little_liquid).
body(r21_liquid_remains_in_destination, pour_mid_height).
body(r21_liquid_remains_in_destination, pour_near_rim).
body(r21_liquid_remains_in_destination, pour_steeply_tilted).
body(r21_liquid_remains_in_destination, slippery_destination).
learned(r21_liquid_remains_in_destination).
provenance(r21_liquid_remains_in_destination, antecedent, a21).
provenance(r21_liquid_remains_in_destination, parent, a14).
provenance(r21_liquid_remains_in_destination, simulations, 60).
provenance(r21_liquid_remains_in_destination, weight_mass_permille, 31451).
provenance(r21_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r21_liquid_remains_in_destination, score_permille, 982).
provenance(r21_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r21_liquid_remains_in_destination, direction, destination_restitution).
provenance(r21_liquid_remains_in_destination, sign, up).

rule(r21_no_spill, defeasible, no_spill).
body(r21_no_spill, bouncy_destination).
body(r21_no_spill, light_source).
body(r21_no_spill, little_liquid).
body(r21_no_spill, pour_mid_height).
body(r21_no_spill, pour_near_rim).
body(r21_no_spill, pour_steeply_tilted).
body(r21_no_spill, slippery_destination).
learned(r21_no_spill).
provenance(r21_no_spill, antecedent, a21).
provenance(r21_no_spill, parent, a14).
provenance(r21_no_spill, simulations, 60).
provenance(r21_no_spill, weight_mass_permille, 31451).
provenance(r21_no_spill, confidence_permille, 1000).
provenance(r21_no_spill, score_permille, 964).
provenance(r21_no_spill, followed, liquid_leaves_source).
provenance(r21_no_spill, direction, destination_restitution).
provenance(r21_no_spill, sign, up).

rule(r22_destination_still_approach, defeasible, destination_still_approach).
body(r22_destination_still_approach, light_source).
body(r22_destination_still_approach, little_liquid).
body(r22_destination_still_approach, pour_half_tilted).
body(r22_destination_still_approach, pour_mid_height).
body(r22_destination_still_approach, pour_near_rim).
body(r22_destination_still_approach, slippery_destination).
learned(r22_destination_still_approach).
provenance(r22_destination_still_approach, antecedent, a22).
provenance(r22_destination_still_approach, parent, a14).
provenance(r22_destination_still_approach, simulations, 39).
provenance(r22_destination_still_approach, weight_mass_permille, 33807).
provenance(r22_destination_still_approach, confidence_permille, 1000).
provenance(r22_destination_still_approach, score_permille, 993).
provenance(r22_destination_still_approach, followed, liquid_leaves_source).
provenance(r22_destination_still_approach, direction, pour_pitch).
provenance(r22_destination_still_approach, sign, down).

rule(r22_destination_still_retreat, defeasible, destination_still_retreat).
body(r22_destination_still_retreat, light_source).
body(r22_destination_still_retreat, little_liquid).
body(r22_destination_still_retreat, pour_half_tilted).
body(r22_destination_still_retreat, pour_mid_height).
body(r22_destination_still_retreat, pour_near_rim).
body(r22_destination_still_retreat, slippery_destination).
learned(r22_destination_still_retreat).
provenance(r22_destination_still_retreat, antecedent, a22).
provenance(r22_destination_still_retreat, parent, a14).
provenance(r22_destination_still_retreat, simulations, 39).
provenance(r22_destination_still_retreat, weight_mass_permille, 33807).
provenance(r22_destination_still_retreat, confidence_permille, 1000).
provenance(r22_destination_still_retreat, score_permille, 1000).
provenance(r22_destination_still_retreat, followed, liquid_leaves_source).
provenance(r22_destination_still_retreat, direction, pour_pitch).
provenance(r22_destination_still_retreat, sign, down).

rule(r22_destination_still_settle, defeasible, destination_still_settle).
body(r22_destination_still_settle, light_source).
body(r22_destination_still_settle, little_liquid).
body(r22_destination_still_settle, pour_half_tilted).
body(r22_destination_still_settle, pour_mid_height).
body(r22_destination_still_settle, pour_near_rim).
body(r22_destination_still_settle, slippery_destination).
learned(r22_destination_still_settle).
provenance(r22_destination_still_settle, antecedent, a22).
provenance(r22_destination_still_settle, parent, a14).
provenance(r22_destination_still_settle, simulations, 39).
provenance(r22_destination_still_settle, weight_mass_permille, 33807).
provenance(r22_destination_still_settle, confidence_permille, 1000).
provenance(r22_destination_still_settle, score_permille, 1000).
provenance(r22_destination_still_settle, followed, liquid_leaves_source).
provenance(r22_destination_still_settle, direction, pour_pitch).
provenance(r22_destination_still_settle, sign, down).

rule(r22_destination_upright, defeasible, destination_upright).
body(r22_destination_upright, light_source).
body(r22_destination_upright, little_liquid).
body(r22_destination_upright, pour_half_tilted).
body(r22_destination_upright, pour_mid_height).
body(r22_destination_upright, pour_near_rim).
body(r22_destination_upright, slippery_destination).
learned(r22_destination_upright).
provenance(r22_destination_upright, antecedent, a22).
provenance(r22_destination_upright, parent, a14).
provenance(r22_destination_upright, simulations, 39).
provenance(r22_destination_upright, weight_mass_permille, 33807).
provenance(r22_destination_upright, confidence_permille, 1000).
provenance(r22_destination_upright, score_permille, 1000).
provenance(r22_destination_upright, followed, liquid_leaves_source).
provenance(r22_destination_upright, direction, pour_pitch).
provenance(r22_destination_upright, sign, down).

rule(r22_source_clear, defeasible, source_clear).
body(r22_source_clear, light_source).
body(r22_source_clear, little_liquid).
body(r22_source_clear, pour_half_tilted).
body(r22_source_clear, pour_mid_height).
body(r22_source_clear, pour_near_rim).
body(r22_source_clear, slippery_destination).
learned(r22_source_clear).
provenance(r22_source_clear, antecedent, a22).
provenance(r22_source_clear, parent, a14).
provenance(r22_source_clear, simulations, 39).
provenance(r22_source_clear, weight_mass_permille, 33807).
provenance(r22_source_clear, confidence_permille, 1000).
provenance(r22_source_clear, score_permille, 1000).
provenance(r22_source_clear, followed, liquid_leaves_source).
provenance(r22_source_clear, direction, pour_pitch).
provenance(r22_source_clear, sign, down).

rule(r22_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r22_liquid_leaves_source, light_source).
body(r22_liquid_leaves_source, little_liquid).
body(r22_liquid_leaves_source, pour_half_tilted).
body(r22_liquid_leaves_source, pour_mid_height).
body(r22_liquid_leaves_source, pour_near_rim).
body(r22_liquid_leaves_source, slippery_destination).
learned(r22_liquid_leaves_source).
provenance(r22_liquid_leaves_source, antecedent, a22).
provenance(r22_liquid_leaves_source, parent, a14).
provenance(r22_liquid_leaves_source, simulations, 39).
provenance(r22_liquid_leaves_source, weight_mass_permille, 33807).
provenance(r22_liquid_leaves_source, confidence_permille, 1000).
provenance(r22_liquid_leaves_source, score_permille, 0).
provenance(r22_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r22_liquid_leaves_source, direction, pour_pitch).
provenance(r22_liquid_leaves_source, sign, down).

rule(r22_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r22_liquid_enters_destination, light_source).
body(r22_liquid_enters_destination, little_liquid).
body(r22_liquid_enters_destination, pour_half_tilted).
body(r22_liquid_enters_destination, pour_mid_height).
body(r22_liquid_enters_destination, pour_near_rim).
body(r22_liquid_enters_destination, slippery_destination).
learned(r22_liquid_enters_destination).
provenance(r22_liquid_enters_destination, antecedent, a22).
provenance(r22_liquid_enters_destination, parent, a14).
provenance(r22_liquid_enters_destination, simulations, 39).
provenance(r22_liquid_enters_destination, weight_mass_permille, 33807).
provenance(r22_liquid_enters_destination, confidence_permille, 1000).
provenance(r22_liquid_enters_destination, score_permille, 0).
provenance(r22_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r22_liquid_enters_destination, direction, pour_pitch).
provenance(r22_liquid_enters_destination, sign, down).

rule(r22_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r22_liquid_remains_in_destination, light_source).
body(r22_liquid_remains_in_destination, little_liquid).
body(r22_liquid_remains_in_destination, pour_half_tilted).
body(r22_liquid_remains_in_destination, pour_mid_height).
body(r22_liquid_remains_in_destination, pour_near_rim).
body(r22_liquid_remains_in_destination, slippery_destination).
learned(r22_liquid_remains_in_destination).
provenance(r22_liquid_remains_in_destination, antecedent, a22).
provenance(r22_liquid_remains_in_destination, parent, a14).
provenance(r22_liquid_remains_in_destination, simulations, 39).
provenance(r22_liquid_remains_in_destination, weight_mass_permille, 33807).
provenance(r22_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r22_liquid_remains_in_destination, score_permille, 1000).
provenance(r22_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r22_liquid_remains_in_destination, direction, pour_pitch).
provenance(r22_liquid_remains_in_destination, sign, down).

rule(r22_no_spill, defeasible, no_spill).
body(r22_no_spill, light_source).
body(r22_no_spill, little_liquid).
body(r22_no_spill, pour_half_tilted).
body(r22_no_spill, pour_mid_height).
body(r22_no_spill, pour_near_rim).
body(r22_no_spill, slippery_destination).
learned(r22_no_spill).
provenance(r22_no_spill, antecedent, a22).
provenance(r22_no_spill, parent, a14).
provenance(r22_no_spill, simulations, 39).
provenance(r22_no_spill, weight_mass_permille, 33807).
provenance(r22_no_spill, confidence_permille, 1000).
provenance(r22_no_spill, score_permille, 1000).
provenance(r22_no_spill, followed, liquid_leaves_source).
provenance(r22_no_spill, direction, pour_pitch).
provenance(r22_no_spill, sign, down).

rule(r23_destination_still_approach, defeasible, destination_still_approach).
body(r23_destination_still_approach, grippy_source).
body(r23_destination_still_approach, light_source).
body(r23_destination_still_approach, little_liquid).
body(r23_destination_still_approach, pour_mid_height).
body(r23_destination_still_approach, pour_near_rim).
body(r23_destination_still_approach, pour_steeply_tilted).
body(r23_destination_still_approach, slippery_destination).
learned(r23_destination_still_approach).
provenance(r23_destination_still_approach, antecedent, a23).
provenance(r23_destination_still_approach, parent, a14).
provenance(r23_destination_still_approach, simulations, 70).
provenance(r23_destination_still_approach, weight_mass_permille, 33277).
provenance(r23_destination_still_approach, confidence_permille, 1000).
provenance(r23_destination_still_approach, score_permille, 980).
provenance(r23_destination_still_approach, followed, liquid_leaves_source).
provenance(r23_destination_still_approach, direction, source_friction).
provenance(r23_destination_still_approach, sign, up).

rule(r23_destination_still_retreat, defeasible, destination_still_retreat).
body(r23_destination_still_retreat, grippy_source).
body(r23_destination_still_retreat, light_source).
body(r23_destination_still_retreat, little_liquid).
body(r23_destination_still_retreat, pour_mid_height).
body(r23_destination_still_retreat, pour_near_rim).
body(r23_destination_still_retreat, pour_steeply_tilted).
body(r23_destination_still_retreat, slippery_destination).
learned(r23_destination_still_retreat).
provenance(r23_destination_still_retreat, antecedent, a23).
provenance(r23_destination_still_retreat, parent, a14).
provenance(r23_destination_still_retreat, simulations, 70).
provenance(r23_destination_still_retreat, weight_mass_permille, 33277).
provenance(r23_destination_still_retreat, confidence_permille, 924).
provenance(r23_destination_still_retreat, score_permille, 929).
provenance(r23_destination_still_retreat, followed, liquid_leaves_source).
provenance(r23_destination_still_retreat, direction, source_friction).
provenance(r23_destination_still_retreat, sign, up).

rule(r23_destination_still_settle, defeasible, destination_still_settle).
body(r23_destination_still_settle, grippy_source).
body(r23_destination_still_settle, light_source).
body(r23_destination_still_settle, little_liquid).
body(r23_destination_still_settle, pour_mid_height).
body(r23_destination_still_settle, pour_near_rim).
body(r23_destination_still_settle, pour_steeply_tilted).
body(r23_destination_still_settle, slippery_destination).
learned(r23_destination_still_settle).
provenance(r23_destination_still_settle, antecedent, a23).
provenance(r23_destination_still_settle, parent, a14).
provenance(r23_destination_still_settle, simulations, 70).
provenance(r23_destination_still_settle, weight_mass_permille, 33277).
provenance(r23_destination_still_settle, confidence_permille, 981).
provenance(r23_destination_still_settle, score_permille, 979).
provenance(r23_destination_still_settle, followed, liquid_leaves_source).
provenance(r23_destination_still_settle, direction, source_friction).
provenance(r23_destination_still_settle, sign, up).

rule(r23_destination_upright, defeasible, destination_upright).
body(r23_destination_upright, grippy_source).
body(r23_destination_upright, light_source).
body(r23_destination_upright, little_liquid).
body(r23_destination_upright, pour_mid_height).
body(r23_destination_upright, pour_near_rim).
body(r23_destination_upright, pour_steeply_tilted).
body(r23_destination_upright, slippery_destination).
learned(r23_destination_upright).
provenance(r23_destination_upright, antecedent, a23).
provenance(r23_destination_upright, parent, a14).
provenance(r23_destination_upright, simulations, 70).
provenance(r23_destination_upright, weight_mass_permille, 33277).
provenance(r23_destination_upright, confidence_permille, 1000).
provenance(r23_destination_upright, score_permille, 998).
provenance(r23_destination_upright, followed, liquid_leaves_source).
provenance(r23_destination_upright, direction, source_friction).
provenance(r23_destination_upright, sign, up).

rule(r23_source_clear, defeasible, source_clear).
body(r23_source_clear, grippy_source).
body(r23_source_clear, light_source).
body(r23_source_clear, little_liquid).
body(r23_source_clear, pour_mid_height).
body(r23_source_clear, pour_near_rim).
body(r23_source_clear, pour_steeply_tilted).
body(r23_source_clear, slippery_destination).
learned(r23_source_clear).
provenance(r23_source_clear, antecedent, a23).
provenance(r23_source_clear, parent, a14).
provenance(r23_source_clear, simulations, 70).
provenance(r23_source_clear, weight_mass_permille, 33277).
provenance(r23_source_clear, confidence_permille, 1000).
provenance(r23_source_clear, score_permille, 1000).
provenance(r23_source_clear, followed, liquid_leaves_source).
provenance(r23_source_clear, direction, source_friction).
provenance(r23_source_clear, sign, up).

rule(r23_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r23_liquid_leaves_source, grippy_source).
body(r23_liquid_leaves_source, light_source).
body(r23_liquid_leaves_source, little_liquid).
body(r23_liquid_leaves_source, pour_mid_height).
body(r23_liquid_leaves_source, pour_near_rim).
body(r23_liquid_leaves_source, pour_steeply_tilted).
body(r23_liquid_leaves_source, slippery_destination).
learned(r23_liquid_leaves_source).
provenance(r23_liquid_leaves_source, antecedent, a23).
provenance(r23_liquid_leaves_source, parent, a14).
provenance(r23_liquid_leaves_source, simulations, 70).
provenance(r23_liquid_leaves_source, weight_mass_permille, 33277).
provenance(r23_liquid_leaves_source, confidence_permille, 684).
provenance(r23_liquid_leaves_source, score_permille, 654).
provenance(r23_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r23_liquid_leaves_source, direction, source_friction).
provenance(r23_liquid_leaves_source, sign, up).

rule(r23_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r23_liquid_enters_destination, grippy_source).
body(r23_liquid_enters_destination, light_source).
body(r23_liquid_enters_destination, little_liquid).
body(r23_liquid_enters_destination, pour_mid_height).
body(r23_liquid_enters_destination, pour_near_rim).
body(r23_liquid_enters_destination, pour_steeply_tilted).
body(r23_liquid_enters_destination, slippery_destination).
learned(r23_liquid_enters_destination).
provenance(r23_liquid_enters_destination, antecedent, a23).
provenance(r23_liquid_enters_destination, parent, a14).
provenance(r23_liquid_enters_destination, simulations, 70).
provenance(r23_liquid_enters_destination, weight_mass_permille, 33277).
provenance(r23_liquid_enters_destination, confidence_permille, 615).
provenance(r23_liquid_enters_destination, score_permille, 579).
provenance(r23_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r23_liquid_enters_destination, direction, source_friction).
provenance(r23_liquid_enters_destination, sign, up).

rule(r23_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r23_liquid_remains_in_destination, grippy_source).
body(r23_liquid_remains_in_destination, light_source).
body(r23_liquid_remains_in_destination, little_liquid).
body(r23_liquid_remains_in_destination, pour_mid_height).
body(r23_liquid_remains_in_destination, pour_near_rim).
body(r23_liquid_remains_in_destination, pour_steeply_tilted).
body(r23_liquid_remains_in_destination, slippery_destination).
learned(r23_liquid_remains_in_destination).
provenance(r23_liquid_remains_in_destination, antecedent, a23).
provenance(r23_liquid_remains_in_destination, parent, a14).
provenance(r23_liquid_remains_in_destination, simulations, 70).
provenance(r23_liquid_remains_in_destination, weight_mass_permille, 33277).
provenance(r23_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r23_liquid_remains_in_destination, score_permille, 986).
provenance(r23_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r23_liquid_remains_in_destination, direction, source_friction).
provenance(r23_liquid_remains_in_destination, sign, up).

rule(r23_no_spill, defeasible, no_spill).
body(r23_no_spill, grippy_source).
body(r23_no_spill, light_source).
body(r23_no_spill, little_liquid).
body(r23_no_spill, pour_mid_height).
body(r23_no_spill, pour_near_rim).
body(r23_no_spill, pour_steeply_tilted).
body(r23_no_spill, slippery_destination).
learned(r23_no_spill).
provenance(r23_no_spill, antecedent, a23).
provenance(r23_no_spill, parent, a14).
provenance(r23_no_spill, simulations, 70).
provenance(r23_no_spill, weight_mass_permille, 33277).
provenance(r23_no_spill, confidence_permille, 982).
provenance(r23_no_spill, score_permille, 914).
provenance(r23_no_spill, followed, liquid_leaves_source).
provenance(r23_no_spill, direction, source_friction).
provenance(r23_no_spill, sign, up).

rule(r24_destination_still_approach, defeasible, destination_still_approach).
body(r24_destination_still_approach, dull_liquid).
body(r24_destination_still_approach, pour_mid_height).
body(r24_destination_still_approach, pour_near_rim).
body(r24_destination_still_approach, pour_offset_sideways).
body(r24_destination_still_approach, pour_upside_down).
body(r24_destination_still_approach, slippery_destination).
learned(r24_destination_still_approach).
provenance(r24_destination_still_approach, antecedent, a24).
provenance(r24_destination_still_approach, parent, a12).
provenance(r24_destination_still_approach, simulations, 31).
provenance(r24_destination_still_approach, weight_mass_permille, 31000).
provenance(r24_destination_still_approach, confidence_permille, 968).
provenance(r24_destination_still_approach, score_permille, 932).
provenance(r24_destination_still_approach, followed, no_spill).
provenance(r24_destination_still_approach, direction, pour_pitch).
provenance(r24_destination_still_approach, sign, up).

rule(r24_destination_still_retreat, defeasible, destination_still_retreat).
body(r24_destination_still_retreat, dull_liquid).
body(r24_destination_still_retreat, pour_mid_height).
body(r24_destination_still_retreat, pour_near_rim).
body(r24_destination_still_retreat, pour_offset_sideways).
body(r24_destination_still_retreat, pour_upside_down).
body(r24_destination_still_retreat, slippery_destination).
learned(r24_destination_still_retreat).
provenance(r24_destination_still_retreat, antecedent, a24).
provenance(r24_destination_still_retreat, parent, a12).
provenance(r24_destination_still_retreat, simulations, 31).
provenance(r24_destination_still_retreat, weight_mass_permille, 31000).
provenance(r24_destination_still_retreat, confidence_permille, 968).
provenance(r24_destination_still_retreat, score_permille, 957).
provenance(r24_destination_still_retreat, followed, no_spill).
provenance(r24_destination_still_retreat, direction, pour_pitch).
provenance(r24_destination_still_retreat, sign, up).

rule(r24_destination_still_settle, defeasible, destination_still_settle).
body(r24_destination_still_settle, dull_liquid).
body(r24_destination_still_settle, pour_mid_height).
body(r24_destination_still_settle, pour_near_rim).
body(r24_destination_still_settle, pour_offset_sideways).
body(r24_destination_still_settle, pour_upside_down).
body(r24_destination_still_settle, slippery_destination).
learned(r24_destination_still_settle).
provenance(r24_destination_still_settle, antecedent, a24).
provenance(r24_destination_still_settle, parent, a12).
provenance(r24_destination_still_settle, simulations, 31).
provenance(r24_destination_still_settle, weight_mass_permille, 31000).
provenance(r24_destination_still_settle, confidence_permille, 1000).
provenance(r24_destination_still_settle, score_permille, 999).
provenance(r24_destination_still_settle, followed, no_spill).
provenance(r24_destination_still_settle, direction, pour_pitch).
provenance(r24_destination_still_settle, sign, up).

rule(r24_destination_upright, defeasible, destination_upright).
body(r24_destination_upright, dull_liquid).
body(r24_destination_upright, pour_mid_height).
body(r24_destination_upright, pour_near_rim).
body(r24_destination_upright, pour_offset_sideways).
body(r24_destination_upright, pour_upside_down).
body(r24_destination_upright, slippery_destination).
learned(r24_destination_upright).
provenance(r24_destination_upright, antecedent, a24).
provenance(r24_destination_upright, parent, a12).
provenance(r24_destination_upright, simulations, 31).
provenance(r24_destination_upright, weight_mass_permille, 31000).
provenance(r24_destination_upright, confidence_permille, 1000).
provenance(r24_destination_upright, score_permille, 1000).
provenance(r24_destination_upright, followed, no_spill).
provenance(r24_destination_upright, direction, pour_pitch).
provenance(r24_destination_upright, sign, up).

rule(r24_source_clear, defeasible, source_clear).
body(r24_source_clear, dull_liquid).
body(r24_source_clear, pour_mid_height).
body(r24_source_clear, pour_near_rim).
body(r24_source_clear, pour_offset_sideways).
body(r24_source_clear, pour_upside_down).
body(r24_source_clear, slippery_destination).
learned(r24_source_clear).
provenance(r24_source_clear, antecedent, a24).
provenance(r24_source_clear, parent, a12).
provenance(r24_source_clear, simulations, 31).
provenance(r24_source_clear, weight_mass_permille, 31000).
provenance(r24_source_clear, confidence_permille, 1000).
provenance(r24_source_clear, score_permille, 1000).
provenance(r24_source_clear, followed, no_spill).
provenance(r24_source_clear, direction, pour_pitch).
provenance(r24_source_clear, sign, up).

rule(r24_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r24_liquid_leaves_source, dull_liquid).
body(r24_liquid_leaves_source, pour_mid_height).
body(r24_liquid_leaves_source, pour_near_rim).
body(r24_liquid_leaves_source, pour_offset_sideways).
body(r24_liquid_leaves_source, pour_upside_down).
body(r24_liquid_leaves_source, slippery_destination).
learned(r24_liquid_leaves_source).
provenance(r24_liquid_leaves_source, antecedent, a24).
provenance(r24_liquid_leaves_source, parent, a12).
provenance(r24_liquid_leaves_source, simulations, 31).
provenance(r24_liquid_leaves_source, weight_mass_permille, 31000).
provenance(r24_liquid_leaves_source, confidence_permille, 1000).
provenance(r24_liquid_leaves_source, score_permille, 1000).
provenance(r24_liquid_leaves_source, followed, no_spill).
provenance(r24_liquid_leaves_source, direction, pour_pitch).
provenance(r24_liquid_leaves_source, sign, up).

rule(r24_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r24_liquid_enters_destination, dull_liquid).
body(r24_liquid_enters_destination, pour_mid_height).
body(r24_liquid_enters_destination, pour_near_rim).
body(r24_liquid_enters_destination, pour_offset_sideways).
body(r24_liquid_enters_destination, pour_upside_down).
body(r24_liquid_enters_destination, slippery_destination).
learned(r24_liquid_enters_destination).
provenance(r24_liquid_enters_destination, antecedent, a24).
provenance(r24_liquid_enters_destination, parent, a12).
provenance(r24_liquid_enters_destination, simulations, 31).
provenance(r24_liquid_enters_destination, weight_mass_permille, 31000).
provenance(r24_liquid_enters_destination, confidence_permille, 774).
provenance(r24_liquid_enters_destination, score_permille, 281).
provenance(r24_liquid_enters_destination, followed, no_spill).
provenance(r24_liquid_enters_destination, direction, pour_pitch).
provenance(r24_liquid_enters_destination, sign, up).

rule(r24_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r24_liquid_remains_in_destination, dull_liquid).
body(r24_liquid_remains_in_destination, pour_mid_height).
body(r24_liquid_remains_in_destination, pour_near_rim).
body(r24_liquid_remains_in_destination, pour_offset_sideways).
body(r24_liquid_remains_in_destination, pour_upside_down).
body(r24_liquid_remains_in_destination, slippery_destination).
learned(r24_liquid_remains_in_destination).
provenance(r24_liquid_remains_in_destination, antecedent, a24).
provenance(r24_liquid_remains_in_destination, parent, a12).
provenance(r24_liquid_remains_in_destination, simulations, 31).
provenance(r24_liquid_remains_in_destination, weight_mass_permille, 31000).
provenance(r24_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r24_liquid_remains_in_destination, score_permille, 994).
provenance(r24_liquid_remains_in_destination, followed, no_spill).
provenance(r24_liquid_remains_in_destination, direction, pour_pitch).
provenance(r24_liquid_remains_in_destination, sign, up).

rule(r24_no_spill, defeasible, neg(no_spill)).
body(r24_no_spill, dull_liquid).
body(r24_no_spill, pour_mid_height).
body(r24_no_spill, pour_near_rim).
body(r24_no_spill, pour_offset_sideways).
body(r24_no_spill, pour_upside_down).
body(r24_no_spill, slippery_destination).
learned(r24_no_spill).
provenance(r24_no_spill, antecedent, a24).
provenance(r24_no_spill, parent, a12).
provenance(r24_no_spill, simulations, 31).
provenance(r24_no_spill, weight_mass_permille, 31000).
provenance(r24_no_spill, confidence_permille, 774).
provenance(r24_no_spill, score_permille, 275).
provenance(r24_no_spill, followed, no_spill).
provenance(r24_no_spill, direction, pour_pitch).
provenance(r24_no_spill, sign, up).

% General rules, learned from every pour of the exploration
% (bridge/learning/generalize.py): a default per expectation, exceptions
% and exceptions to those. provenance(Id, support, N): the pours whose
% description holds the body; kept: how many of them keep the head;
% confidence_permille: P(head | body) for the pours sampled for the body.
% sup/2 below orders both layers (see bridge/learning/layers.py).
setting(general_pours, 744).
setting(general_rules, 12).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 744).
provenance(g0_destination_still_approach, kept, 732).
provenance(g0_destination_still_approach, confidence_permille, 1000).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 744).
provenance(g0_destination_still_retreat, kept, 713).
provenance(g0_destination_still_retreat, confidence_permille, 995).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 744).
provenance(g0_destination_still_settle, kept, 742).
provenance(g0_destination_still_settle, confidence_permille, 1000).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 744).
provenance(g0_destination_upright, kept, 744).
provenance(g0_destination_upright, confidence_permille, 1000).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 744).
provenance(g0_source_clear, kept, 743).
provenance(g0_source_clear, confidence_permille, 1000).
rule(g0_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 744).
provenance(g0_liquid_leaves_source, kept, 429).
provenance(g0_liquid_leaves_source, confidence_permille, 577).
rule(g1_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g1_liquid_leaves_source, pour_half_tilted).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 155).
provenance(g1_liquid_leaves_source, kept, 151).
provenance(g1_liquid_leaves_source, confidence_permille, 986).
rule(g0_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 744).
provenance(g0_liquid_enters_destination, kept, 405).
provenance(g0_liquid_enters_destination, confidence_permille, 544).
rule(g1_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g1_liquid_enters_destination, heavy_destination).
body(g1_liquid_enters_destination, pour_steeply_tilted).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 377).
provenance(g1_liquid_enters_destination, kept, 227).
provenance(g1_liquid_enters_destination, confidence_permille, 668).
rule(g2_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g2_liquid_enters_destination, pour_steeply_tilted).
body(g2_liquid_enters_destination, start_far_away).
learned(g2_liquid_enters_destination).
provenance(g2_liquid_enters_destination, layer, general).
provenance(g2_liquid_enters_destination, level, 1).
provenance(g2_liquid_enters_destination, support, 276).
provenance(g2_liquid_enters_destination, kept, 166).
provenance(g2_liquid_enters_destination, confidence_permille, 717).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 744).
provenance(g0_liquid_remains_in_destination, kept, 744).
provenance(g0_liquid_remains_in_destination, confidence_permille, 1000).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 744).
provenance(g0_no_spill, kept, 673).
provenance(g0_no_spill, confidence_permille, 957).
sup(r10_no_spill, r16_no_spill).
sup(r11_no_spill, r16_no_spill).
sup(r12_liquid_enters_destination, g1_liquid_enters_destination).
sup(r12_liquid_enters_destination, g2_liquid_enters_destination).
sup(r12_liquid_enters_destination, r10_liquid_enters_destination).
sup(r12_liquid_enters_destination, r11_liquid_enters_destination).
sup(r12_liquid_enters_destination, r14_liquid_enters_destination).
sup(r12_liquid_enters_destination, r15_liquid_enters_destination).
sup(r12_liquid_enters_destination, r17_liquid_enters_destination).
sup(r12_liquid_enters_destination, r3_liquid_enters_destination).
sup(r12_liquid_enters_destination, r5_liquid_enters_destination).
sup(r12_liquid_enters_destination, r7_liquid_enters_destination).
sup(r12_liquid_enters_destination, r8_liquid_enters_destination).
sup(r14_no_spill, r16_no_spill).
sup(r15_no_spill, r16_no_spill).
sup(r16_liquid_enters_destination, g1_liquid_enters_destination).
sup(r16_liquid_enters_destination, g2_liquid_enters_destination).
sup(r16_liquid_enters_destination, r10_liquid_enters_destination).
sup(r16_liquid_enters_destination, r11_liquid_enters_destination).
sup(r16_liquid_enters_destination, r14_liquid_enters_destination).
sup(r16_liquid_enters_destination, r15_liquid_enters_destination).
sup(r16_liquid_enters_destination, r17_liquid_enters_destination).
sup(r16_liquid_enters_destination, r3_liquid_enters_destination).
sup(r16_liquid_enters_destination, r4_liquid_enters_destination).
sup(r16_liquid_enters_destination, r7_liquid_enters_destination).
sup(r16_liquid_enters_destination, r8_liquid_enters_destination).
sup(r16_no_spill, r12_no_spill).
sup(r16_no_spill, r3_no_spill).
sup(r16_no_spill, r4_no_spill).
sup(r16_no_spill, r7_no_spill).
sup(r16_no_spill, r8_no_spill).
sup(r17_no_spill, r16_no_spill).
sup(r19_liquid_enters_destination, g1_liquid_enters_destination).
sup(r19_liquid_enters_destination, g2_liquid_enters_destination).
sup(r19_liquid_enters_destination, r15_liquid_enters_destination).
sup(r19_liquid_enters_destination, r17_liquid_enters_destination).
sup(r19_liquid_enters_destination, r3_liquid_enters_destination).
sup(r19_liquid_enters_destination, r5_liquid_enters_destination).
sup(r19_liquid_enters_destination, r7_liquid_enters_destination).
sup(r19_liquid_enters_destination, r8_liquid_enters_destination).
sup(r19_no_spill, r16_no_spill).
sup(r20_liquid_enters_destination, r12_liquid_enters_destination).
sup(r20_liquid_enters_destination, r16_liquid_enters_destination).
sup(r20_liquid_enters_destination, r19_liquid_enters_destination).
sup(r20_no_spill, r16_no_spill).
sup(r21_liquid_enters_destination, r12_liquid_enters_destination).
sup(r21_liquid_enters_destination, r16_liquid_enters_destination).
sup(r21_no_spill, r16_no_spill).
sup(r23_liquid_enters_destination, r12_liquid_enters_destination).
sup(r23_liquid_enters_destination, r16_liquid_enters_destination).
sup(r23_no_spill, r16_no_spill).
