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
setting(oracle_version, "2").
setting(seed, 1).
setting(samples, 31).
setting(max_rules, 25).
setting(threshold_permille, 100).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 25).
setting(simulations, 775).
setting(failed_simulations, 0).
setting(stopped, max_rules).
setting(a_new_left, 3).
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
provenance(r1_destination_still_approach, simulations, 558).
provenance(r1_destination_still_approach, weight_mass_permille, 32095).
provenance(r1_destination_still_approach, confidence_permille, 963).
provenance(r1_destination_still_approach, score_permille, 956).

rule(r1_destination_still_retreat, defeasible, destination_still_retreat).
body(r1_destination_still_retreat, pour_mid_height).
body(r1_destination_still_retreat, pour_near_rim).
body(r1_destination_still_retreat, pour_steeply_tilted).
learned(r1_destination_still_retreat).
provenance(r1_destination_still_retreat, antecedent, a1).
provenance(r1_destination_still_retreat, parent, none).
provenance(r1_destination_still_retreat, simulations, 558).
provenance(r1_destination_still_retreat, weight_mass_permille, 32095).
provenance(r1_destination_still_retreat, confidence_permille, 996).
provenance(r1_destination_still_retreat, score_permille, 979).

rule(r1_destination_still_settle, defeasible, destination_still_settle).
body(r1_destination_still_settle, pour_mid_height).
body(r1_destination_still_settle, pour_near_rim).
body(r1_destination_still_settle, pour_steeply_tilted).
learned(r1_destination_still_settle).
provenance(r1_destination_still_settle, antecedent, a1).
provenance(r1_destination_still_settle, parent, none).
provenance(r1_destination_still_settle, simulations, 558).
provenance(r1_destination_still_settle, weight_mass_permille, 32095).
provenance(r1_destination_still_settle, confidence_permille, 1000).
provenance(r1_destination_still_settle, score_permille, 997).

rule(r1_destination_upright, defeasible, destination_upright).
body(r1_destination_upright, pour_mid_height).
body(r1_destination_upright, pour_near_rim).
body(r1_destination_upright, pour_steeply_tilted).
learned(r1_destination_upright).
provenance(r1_destination_upright, antecedent, a1).
provenance(r1_destination_upright, parent, none).
provenance(r1_destination_upright, simulations, 558).
provenance(r1_destination_upright, weight_mass_permille, 32095).
provenance(r1_destination_upright, confidence_permille, 1000).
provenance(r1_destination_upright, score_permille, 999).

rule(r1_source_clear, defeasible, source_clear).
body(r1_source_clear, pour_mid_height).
body(r1_source_clear, pour_near_rim).
body(r1_source_clear, pour_steeply_tilted).
learned(r1_source_clear).
provenance(r1_source_clear, antecedent, a1).
provenance(r1_source_clear, parent, none).
provenance(r1_source_clear, simulations, 558).
provenance(r1_source_clear, weight_mass_permille, 32095).
provenance(r1_source_clear, confidence_permille, 1000).
provenance(r1_source_clear, score_permille, 985).

rule(r1_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r1_liquid_leaves_source, pour_mid_height).
body(r1_liquid_leaves_source, pour_near_rim).
body(r1_liquid_leaves_source, pour_steeply_tilted).
learned(r1_liquid_leaves_source).
provenance(r1_liquid_leaves_source, antecedent, a1).
provenance(r1_liquid_leaves_source, parent, none).
provenance(r1_liquid_leaves_source, simulations, 558).
provenance(r1_liquid_leaves_source, weight_mass_permille, 32095).
provenance(r1_liquid_leaves_source, confidence_permille, 844).
provenance(r1_liquid_leaves_source, score_permille, 820).

rule(r1_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r1_liquid_enters_destination, pour_mid_height).
body(r1_liquid_enters_destination, pour_near_rim).
body(r1_liquid_enters_destination, pour_steeply_tilted).
learned(r1_liquid_enters_destination).
provenance(r1_liquid_enters_destination, antecedent, a1).
provenance(r1_liquid_enters_destination, parent, none).
provenance(r1_liquid_enters_destination, simulations, 558).
provenance(r1_liquid_enters_destination, weight_mass_permille, 32095).
provenance(r1_liquid_enters_destination, confidence_permille, 773).
provenance(r1_liquid_enters_destination, score_permille, 735).

rule(r1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r1_liquid_remains_in_destination, pour_mid_height).
body(r1_liquid_remains_in_destination, pour_near_rim).
body(r1_liquid_remains_in_destination, pour_steeply_tilted).
learned(r1_liquid_remains_in_destination).
provenance(r1_liquid_remains_in_destination, antecedent, a1).
provenance(r1_liquid_remains_in_destination, parent, none).
provenance(r1_liquid_remains_in_destination, simulations, 558).
provenance(r1_liquid_remains_in_destination, weight_mass_permille, 32095).
provenance(r1_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r1_liquid_remains_in_destination, score_permille, 994).

rule(r1_no_spill, defeasible, no_spill).
body(r1_no_spill, pour_mid_height).
body(r1_no_spill, pour_near_rim).
body(r1_no_spill, pour_steeply_tilted).
learned(r1_no_spill).
provenance(r1_no_spill, antecedent, a1).
provenance(r1_no_spill, parent, none).
provenance(r1_no_spill, simulations, 558).
provenance(r1_no_spill, weight_mass_permille, 32095).
provenance(r1_no_spill, confidence_permille, 966).
provenance(r1_no_spill, score_permille, 911).

rule(r2_destination_still_approach, defeasible, destination_still_approach).
body(r2_destination_still_approach, pour_mid_height).
body(r2_destination_still_approach, pour_near_rim).
body(r2_destination_still_approach, pour_steeply_tilted).
body(r2_destination_still_approach, slippery_destination).
learned(r2_destination_still_approach).
provenance(r2_destination_still_approach, antecedent, a2).
provenance(r2_destination_still_approach, parent, a1).
provenance(r2_destination_still_approach, simulations, 504).
provenance(r2_destination_still_approach, weight_mass_permille, 27543).
provenance(r2_destination_still_approach, confidence_permille, 945).
provenance(r2_destination_still_approach, score_permille, 931).
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
provenance(r2_destination_still_retreat, simulations, 504).
provenance(r2_destination_still_retreat, weight_mass_permille, 27543).
provenance(r2_destination_still_retreat, confidence_permille, 964).
provenance(r2_destination_still_retreat, score_permille, 947).
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
provenance(r2_destination_still_settle, simulations, 504).
provenance(r2_destination_still_settle, weight_mass_permille, 27543).
provenance(r2_destination_still_settle, confidence_permille, 998).
provenance(r2_destination_still_settle, score_permille, 996).
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
provenance(r2_destination_upright, simulations, 504).
provenance(r2_destination_upright, weight_mass_permille, 27543).
provenance(r2_destination_upright, confidence_permille, 1000).
provenance(r2_destination_upright, score_permille, 1000).
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
provenance(r2_source_clear, simulations, 504).
provenance(r2_source_clear, weight_mass_permille, 27543).
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
provenance(r2_liquid_leaves_source, simulations, 504).
provenance(r2_liquid_leaves_source, weight_mass_permille, 27543).
provenance(r2_liquid_leaves_source, confidence_permille, 839).
provenance(r2_liquid_leaves_source, score_permille, 802).
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
provenance(r2_liquid_enters_destination, simulations, 504).
provenance(r2_liquid_enters_destination, weight_mass_permille, 27543).
provenance(r2_liquid_enters_destination, confidence_permille, 765).
provenance(r2_liquid_enters_destination, score_permille, 723).
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
provenance(r2_liquid_remains_in_destination, simulations, 504).
provenance(r2_liquid_remains_in_destination, weight_mass_permille, 27543).
provenance(r2_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r2_liquid_remains_in_destination, score_permille, 989).
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
provenance(r2_no_spill, simulations, 504).
provenance(r2_no_spill, weight_mass_permille, 27543).
provenance(r2_no_spill, confidence_permille, 978).
provenance(r2_no_spill, score_permille, 913).
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
provenance(r3_destination_still_approach, simulations, 270).
provenance(r3_destination_still_approach, weight_mass_permille, 29686).
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
provenance(r3_destination_still_retreat, simulations, 270).
provenance(r3_destination_still_retreat, weight_mass_permille, 29686).
provenance(r3_destination_still_retreat, confidence_permille, 998).
provenance(r3_destination_still_retreat, score_permille, 977).
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
provenance(r3_destination_still_settle, simulations, 270).
provenance(r3_destination_still_settle, weight_mass_permille, 29686).
provenance(r3_destination_still_settle, confidence_permille, 1000).
provenance(r3_destination_still_settle, score_permille, 998).
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
provenance(r3_destination_upright, simulations, 270).
provenance(r3_destination_upright, weight_mass_permille, 29686).
provenance(r3_destination_upright, confidence_permille, 1000).
provenance(r3_destination_upright, score_permille, 998).
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
provenance(r3_source_clear, simulations, 270).
provenance(r3_source_clear, weight_mass_permille, 29686).
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
provenance(r3_liquid_leaves_source, simulations, 270).
provenance(r3_liquid_leaves_source, weight_mass_permille, 29686).
provenance(r3_liquid_leaves_source, confidence_permille, 752).
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
provenance(r3_liquid_enters_destination, simulations, 270).
provenance(r3_liquid_enters_destination, weight_mass_permille, 29686).
provenance(r3_liquid_enters_destination, confidence_permille, 739).
provenance(r3_liquid_enters_destination, score_permille, 652).
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
provenance(r3_liquid_remains_in_destination, simulations, 270).
provenance(r3_liquid_remains_in_destination, weight_mass_permille, 29686).
provenance(r3_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r3_liquid_remains_in_destination, score_permille, 987).
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
provenance(r3_no_spill, simulations, 270).
provenance(r3_no_spill, weight_mass_permille, 29686).
provenance(r3_no_spill, confidence_permille, 1000).
provenance(r3_no_spill, score_permille, 912).
provenance(r3_no_spill, followed, liquid_enters_destination).
provenance(r3_no_spill, direction, destination_restitution).
provenance(r3_no_spill, sign, up).

rule(r4_destination_still_approach, defeasible, destination_still_approach).
body(r4_destination_still_approach, light_source).
body(r4_destination_still_approach, pour_mid_height).
body(r4_destination_still_approach, pour_near_rim).
body(r4_destination_still_approach, pour_steeply_tilted).
body(r4_destination_still_approach, slippery_destination).
learned(r4_destination_still_approach).
provenance(r4_destination_still_approach, antecedent, a4).
provenance(r4_destination_still_approach, parent, a2).
provenance(r4_destination_still_approach, simulations, 403).
provenance(r4_destination_still_approach, weight_mass_permille, 32217).
provenance(r4_destination_still_approach, confidence_permille, 969).
provenance(r4_destination_still_approach, score_permille, 936).
provenance(r4_destination_still_approach, followed, liquid_leaves_source).
provenance(r4_destination_still_approach, direction, source_mass).
provenance(r4_destination_still_approach, sign, down).

rule(r4_destination_still_retreat, defeasible, destination_still_retreat).
body(r4_destination_still_retreat, light_source).
body(r4_destination_still_retreat, pour_mid_height).
body(r4_destination_still_retreat, pour_near_rim).
body(r4_destination_still_retreat, pour_steeply_tilted).
body(r4_destination_still_retreat, slippery_destination).
learned(r4_destination_still_retreat).
provenance(r4_destination_still_retreat, antecedent, a4).
provenance(r4_destination_still_retreat, parent, a2).
provenance(r4_destination_still_retreat, simulations, 403).
provenance(r4_destination_still_retreat, weight_mass_permille, 32217).
provenance(r4_destination_still_retreat, confidence_permille, 964).
provenance(r4_destination_still_retreat, score_permille, 949).
provenance(r4_destination_still_retreat, followed, liquid_leaves_source).
provenance(r4_destination_still_retreat, direction, source_mass).
provenance(r4_destination_still_retreat, sign, down).

rule(r4_destination_still_settle, defeasible, destination_still_settle).
body(r4_destination_still_settle, light_source).
body(r4_destination_still_settle, pour_mid_height).
body(r4_destination_still_settle, pour_near_rim).
body(r4_destination_still_settle, pour_steeply_tilted).
body(r4_destination_still_settle, slippery_destination).
learned(r4_destination_still_settle).
provenance(r4_destination_still_settle, antecedent, a4).
provenance(r4_destination_still_settle, parent, a2).
provenance(r4_destination_still_settle, simulations, 403).
provenance(r4_destination_still_settle, weight_mass_permille, 32217).
provenance(r4_destination_still_settle, confidence_permille, 991).
provenance(r4_destination_still_settle, score_permille, 987).
provenance(r4_destination_still_settle, followed, liquid_leaves_source).
provenance(r4_destination_still_settle, direction, source_mass).
provenance(r4_destination_still_settle, sign, down).

rule(r4_destination_upright, defeasible, destination_upright).
body(r4_destination_upright, light_source).
body(r4_destination_upright, pour_mid_height).
body(r4_destination_upright, pour_near_rim).
body(r4_destination_upright, pour_steeply_tilted).
body(r4_destination_upright, slippery_destination).
learned(r4_destination_upright).
provenance(r4_destination_upright, antecedent, a4).
provenance(r4_destination_upright, parent, a2).
provenance(r4_destination_upright, simulations, 403).
provenance(r4_destination_upright, weight_mass_permille, 32217).
provenance(r4_destination_upright, confidence_permille, 1000).
provenance(r4_destination_upright, score_permille, 998).
provenance(r4_destination_upright, followed, liquid_leaves_source).
provenance(r4_destination_upright, direction, source_mass).
provenance(r4_destination_upright, sign, down).

rule(r4_source_clear, defeasible, source_clear).
body(r4_source_clear, light_source).
body(r4_source_clear, pour_mid_height).
body(r4_source_clear, pour_near_rim).
body(r4_source_clear, pour_steeply_tilted).
body(r4_source_clear, slippery_destination).
learned(r4_source_clear).
provenance(r4_source_clear, antecedent, a4).
provenance(r4_source_clear, parent, a2).
provenance(r4_source_clear, simulations, 403).
provenance(r4_source_clear, weight_mass_permille, 32217).
provenance(r4_source_clear, confidence_permille, 1000).
provenance(r4_source_clear, score_permille, 990).
provenance(r4_source_clear, followed, liquid_leaves_source).
provenance(r4_source_clear, direction, source_mass).
provenance(r4_source_clear, sign, down).

rule(r4_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r4_liquid_leaves_source, light_source).
body(r4_liquid_leaves_source, pour_mid_height).
body(r4_liquid_leaves_source, pour_near_rim).
body(r4_liquid_leaves_source, pour_steeply_tilted).
body(r4_liquid_leaves_source, slippery_destination).
learned(r4_liquid_leaves_source).
provenance(r4_liquid_leaves_source, antecedent, a4).
provenance(r4_liquid_leaves_source, parent, a2).
provenance(r4_liquid_leaves_source, simulations, 403).
provenance(r4_liquid_leaves_source, weight_mass_permille, 32217).
provenance(r4_liquid_leaves_source, confidence_permille, 763).
provenance(r4_liquid_leaves_source, score_permille, 755).
provenance(r4_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r4_liquid_leaves_source, direction, source_mass).
provenance(r4_liquid_leaves_source, sign, down).

rule(r4_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r4_liquid_enters_destination, light_source).
body(r4_liquid_enters_destination, pour_mid_height).
body(r4_liquid_enters_destination, pour_near_rim).
body(r4_liquid_enters_destination, pour_steeply_tilted).
body(r4_liquid_enters_destination, slippery_destination).
learned(r4_liquid_enters_destination).
provenance(r4_liquid_enters_destination, antecedent, a4).
provenance(r4_liquid_enters_destination, parent, a2).
provenance(r4_liquid_enters_destination, simulations, 403).
provenance(r4_liquid_enters_destination, weight_mass_permille, 32217).
provenance(r4_liquid_enters_destination, confidence_permille, 725).
provenance(r4_liquid_enters_destination, score_permille, 702).
provenance(r4_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r4_liquid_enters_destination, direction, source_mass).
provenance(r4_liquid_enters_destination, sign, down).

rule(r4_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r4_liquid_remains_in_destination, light_source).
body(r4_liquid_remains_in_destination, pour_mid_height).
body(r4_liquid_remains_in_destination, pour_near_rim).
body(r4_liquid_remains_in_destination, pour_steeply_tilted).
body(r4_liquid_remains_in_destination, slippery_destination).
learned(r4_liquid_remains_in_destination).
provenance(r4_liquid_remains_in_destination, antecedent, a4).
provenance(r4_liquid_remains_in_destination, parent, a2).
provenance(r4_liquid_remains_in_destination, simulations, 403).
provenance(r4_liquid_remains_in_destination, weight_mass_permille, 32217).
provenance(r4_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r4_liquid_remains_in_destination, score_permille, 984).
provenance(r4_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r4_liquid_remains_in_destination, direction, source_mass).
provenance(r4_liquid_remains_in_destination, sign, down).

rule(r4_no_spill, defeasible, no_spill).
body(r4_no_spill, light_source).
body(r4_no_spill, pour_mid_height).
body(r4_no_spill, pour_near_rim).
body(r4_no_spill, pour_steeply_tilted).
body(r4_no_spill, slippery_destination).
learned(r4_no_spill).
provenance(r4_no_spill, antecedent, a4).
provenance(r4_no_spill, parent, a2).
provenance(r4_no_spill, simulations, 403).
provenance(r4_no_spill, weight_mass_permille, 32217).
provenance(r4_no_spill, confidence_permille, 985).
provenance(r4_no_spill, score_permille, 934).
provenance(r4_no_spill, followed, liquid_leaves_source).
provenance(r4_no_spill, direction, source_mass).
provenance(r4_no_spill, sign, down).

rule(r5_destination_still_approach, defeasible, destination_still_approach).
body(r5_destination_still_approach, dull_liquid).
body(r5_destination_still_approach, pour_mid_height).
body(r5_destination_still_approach, pour_near_rim).
body(r5_destination_still_approach, pour_steeply_tilted).
body(r5_destination_still_approach, slippery_destination).
learned(r5_destination_still_approach).
provenance(r5_destination_still_approach, antecedent, a5).
provenance(r5_destination_still_approach, parent, a2).
provenance(r5_destination_still_approach, simulations, 143).
provenance(r5_destination_still_approach, weight_mass_permille, 32817).
provenance(r5_destination_still_approach, confidence_permille, 950).
provenance(r5_destination_still_approach, score_permille, 933).
provenance(r5_destination_still_approach, followed, liquid_leaves_source).
provenance(r5_destination_still_approach, direction, particle_restitution).
provenance(r5_destination_still_approach, sign, down).

rule(r5_destination_still_retreat, defeasible, destination_still_retreat).
body(r5_destination_still_retreat, dull_liquid).
body(r5_destination_still_retreat, pour_mid_height).
body(r5_destination_still_retreat, pour_near_rim).
body(r5_destination_still_retreat, pour_steeply_tilted).
body(r5_destination_still_retreat, slippery_destination).
learned(r5_destination_still_retreat).
provenance(r5_destination_still_retreat, antecedent, a5).
provenance(r5_destination_still_retreat, parent, a2).
provenance(r5_destination_still_retreat, simulations, 143).
provenance(r5_destination_still_retreat, weight_mass_permille, 32817).
provenance(r5_destination_still_retreat, confidence_permille, 948).
provenance(r5_destination_still_retreat, score_permille, 937).
provenance(r5_destination_still_retreat, followed, liquid_leaves_source).
provenance(r5_destination_still_retreat, direction, particle_restitution).
provenance(r5_destination_still_retreat, sign, down).

rule(r5_destination_still_settle, defeasible, destination_still_settle).
body(r5_destination_still_settle, dull_liquid).
body(r5_destination_still_settle, pour_mid_height).
body(r5_destination_still_settle, pour_near_rim).
body(r5_destination_still_settle, pour_steeply_tilted).
body(r5_destination_still_settle, slippery_destination).
learned(r5_destination_still_settle).
provenance(r5_destination_still_settle, antecedent, a5).
provenance(r5_destination_still_settle, parent, a2).
provenance(r5_destination_still_settle, simulations, 143).
provenance(r5_destination_still_settle, weight_mass_permille, 32817).
provenance(r5_destination_still_settle, confidence_permille, 1000).
provenance(r5_destination_still_settle, score_permille, 994).
provenance(r5_destination_still_settle, followed, liquid_leaves_source).
provenance(r5_destination_still_settle, direction, particle_restitution).
provenance(r5_destination_still_settle, sign, down).

rule(r5_destination_upright, defeasible, destination_upright).
body(r5_destination_upright, dull_liquid).
body(r5_destination_upright, pour_mid_height).
body(r5_destination_upright, pour_near_rim).
body(r5_destination_upright, pour_steeply_tilted).
body(r5_destination_upright, slippery_destination).
learned(r5_destination_upright).
provenance(r5_destination_upright, antecedent, a5).
provenance(r5_destination_upright, parent, a2).
provenance(r5_destination_upright, simulations, 143).
provenance(r5_destination_upright, weight_mass_permille, 32817).
provenance(r5_destination_upright, confidence_permille, 1000).
provenance(r5_destination_upright, score_permille, 999).
provenance(r5_destination_upright, followed, liquid_leaves_source).
provenance(r5_destination_upright, direction, particle_restitution).
provenance(r5_destination_upright, sign, down).

rule(r5_source_clear, defeasible, source_clear).
body(r5_source_clear, dull_liquid).
body(r5_source_clear, pour_mid_height).
body(r5_source_clear, pour_near_rim).
body(r5_source_clear, pour_steeply_tilted).
body(r5_source_clear, slippery_destination).
learned(r5_source_clear).
provenance(r5_source_clear, antecedent, a5).
provenance(r5_source_clear, parent, a2).
provenance(r5_source_clear, simulations, 143).
provenance(r5_source_clear, weight_mass_permille, 32817).
provenance(r5_source_clear, confidence_permille, 1000).
provenance(r5_source_clear, score_permille, 1000).
provenance(r5_source_clear, followed, liquid_leaves_source).
provenance(r5_source_clear, direction, particle_restitution).
provenance(r5_source_clear, sign, down).

rule(r5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r5_liquid_leaves_source, dull_liquid).
body(r5_liquid_leaves_source, pour_mid_height).
body(r5_liquid_leaves_source, pour_near_rim).
body(r5_liquid_leaves_source, pour_steeply_tilted).
body(r5_liquid_leaves_source, slippery_destination).
learned(r5_liquid_leaves_source).
provenance(r5_liquid_leaves_source, antecedent, a5).
provenance(r5_liquid_leaves_source, parent, a2).
provenance(r5_liquid_leaves_source, simulations, 143).
provenance(r5_liquid_leaves_source, weight_mass_permille, 32817).
provenance(r5_liquid_leaves_source, confidence_permille, 770).
provenance(r5_liquid_leaves_source, score_permille, 707).
provenance(r5_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r5_liquid_leaves_source, direction, particle_restitution).
provenance(r5_liquid_leaves_source, sign, down).

rule(r5_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r5_liquid_enters_destination, dull_liquid).
body(r5_liquid_enters_destination, pour_mid_height).
body(r5_liquid_enters_destination, pour_near_rim).
body(r5_liquid_enters_destination, pour_steeply_tilted).
body(r5_liquid_enters_destination, slippery_destination).
learned(r5_liquid_enters_destination).
provenance(r5_liquid_enters_destination, antecedent, a5).
provenance(r5_liquid_enters_destination, parent, a2).
provenance(r5_liquid_enters_destination, simulations, 143).
provenance(r5_liquid_enters_destination, weight_mass_permille, 32817).
provenance(r5_liquid_enters_destination, confidence_permille, 645).
provenance(r5_liquid_enters_destination, score_permille, 649).
provenance(r5_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r5_liquid_enters_destination, direction, particle_restitution).
provenance(r5_liquid_enters_destination, sign, down).

rule(r5_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r5_liquid_remains_in_destination, dull_liquid).
body(r5_liquid_remains_in_destination, pour_mid_height).
body(r5_liquid_remains_in_destination, pour_near_rim).
body(r5_liquid_remains_in_destination, pour_steeply_tilted).
body(r5_liquid_remains_in_destination, slippery_destination).
learned(r5_liquid_remains_in_destination).
provenance(r5_liquid_remains_in_destination, antecedent, a5).
provenance(r5_liquid_remains_in_destination, parent, a2).
provenance(r5_liquid_remains_in_destination, simulations, 143).
provenance(r5_liquid_remains_in_destination, weight_mass_permille, 32817).
provenance(r5_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r5_liquid_remains_in_destination, score_permille, 997).
provenance(r5_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r5_liquid_remains_in_destination, direction, particle_restitution).
provenance(r5_liquid_remains_in_destination, sign, down).

rule(r5_no_spill, defeasible, no_spill).
body(r5_no_spill, dull_liquid).
body(r5_no_spill, pour_mid_height).
body(r5_no_spill, pour_near_rim).
body(r5_no_spill, pour_steeply_tilted).
body(r5_no_spill, slippery_destination).
learned(r5_no_spill).
provenance(r5_no_spill, antecedent, a5).
provenance(r5_no_spill, parent, a2).
provenance(r5_no_spill, simulations, 143).
provenance(r5_no_spill, weight_mass_permille, 32817).
provenance(r5_no_spill, confidence_permille, 945).
provenance(r5_no_spill, score_permille, 940).
provenance(r5_no_spill, followed, liquid_leaves_source).
provenance(r5_no_spill, direction, particle_restitution).
provenance(r5_no_spill, sign, down).

rule(r6_destination_still_approach, defeasible, destination_still_approach).
body(r6_destination_still_approach, pour_half_tilted).
body(r6_destination_still_approach, pour_mid_height).
body(r6_destination_still_approach, pour_near_rim).
body(r6_destination_still_approach, slippery_destination).
learned(r6_destination_still_approach).
provenance(r6_destination_still_approach, antecedent, a6).
provenance(r6_destination_still_approach, parent, a2).
provenance(r6_destination_still_approach, simulations, 217).
provenance(r6_destination_still_approach, weight_mass_permille, 31730).
provenance(r6_destination_still_approach, confidence_permille, 1000).
provenance(r6_destination_still_approach, score_permille, 993).
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
provenance(r6_destination_still_retreat, simulations, 217).
provenance(r6_destination_still_retreat, weight_mass_permille, 31730).
provenance(r6_destination_still_retreat, confidence_permille, 1000).
provenance(r6_destination_still_retreat, score_permille, 999).
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
provenance(r6_destination_still_settle, simulations, 217).
provenance(r6_destination_still_settle, weight_mass_permille, 31730).
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
provenance(r6_destination_upright, simulations, 217).
provenance(r6_destination_upright, weight_mass_permille, 31730).
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
provenance(r6_source_clear, simulations, 217).
provenance(r6_source_clear, weight_mass_permille, 31730).
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
provenance(r6_liquid_leaves_source, simulations, 217).
provenance(r6_liquid_leaves_source, weight_mass_permille, 31730).
provenance(r6_liquid_leaves_source, confidence_permille, 1000).
provenance(r6_liquid_leaves_source, score_permille, 19).
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
provenance(r6_liquid_enters_destination, simulations, 217).
provenance(r6_liquid_enters_destination, weight_mass_permille, 31730).
provenance(r6_liquid_enters_destination, confidence_permille, 1000).
provenance(r6_liquid_enters_destination, score_permille, 14).
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
provenance(r6_liquid_remains_in_destination, simulations, 217).
provenance(r6_liquid_remains_in_destination, weight_mass_permille, 31730).
provenance(r6_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r6_liquid_remains_in_destination, score_permille, 1000).
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
provenance(r6_no_spill, simulations, 217).
provenance(r6_no_spill, weight_mass_permille, 31730).
provenance(r6_no_spill, confidence_permille, 1000).
provenance(r6_no_spill, score_permille, 996).
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
provenance(r7_destination_still_approach, simulations, 106).
provenance(r7_destination_still_approach, weight_mass_permille, 27331).
provenance(r7_destination_still_approach, confidence_permille, 1000).
provenance(r7_destination_still_approach, score_permille, 972).
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
provenance(r7_destination_still_retreat, simulations, 106).
provenance(r7_destination_still_retreat, weight_mass_permille, 27331).
provenance(r7_destination_still_retreat, confidence_permille, 859).
provenance(r7_destination_still_retreat, score_permille, 852).
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
provenance(r7_destination_still_settle, simulations, 106).
provenance(r7_destination_still_settle, weight_mass_permille, 27331).
provenance(r7_destination_still_settle, confidence_permille, 990).
provenance(r7_destination_still_settle, score_permille, 984).
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
provenance(r7_destination_upright, simulations, 106).
provenance(r7_destination_upright, weight_mass_permille, 27331).
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
provenance(r7_source_clear, simulations, 106).
provenance(r7_source_clear, weight_mass_permille, 27331).
provenance(r7_source_clear, confidence_permille, 1000).
provenance(r7_source_clear, score_permille, 998).
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
provenance(r7_liquid_leaves_source, simulations, 106).
provenance(r7_liquid_leaves_source, weight_mass_permille, 27331).
provenance(r7_liquid_leaves_source, confidence_permille, 850).
provenance(r7_liquid_leaves_source, score_permille, 771).
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
provenance(r7_liquid_enters_destination, simulations, 106).
provenance(r7_liquid_enters_destination, weight_mass_permille, 27331).
provenance(r7_liquid_enters_destination, confidence_permille, 707).
provenance(r7_liquid_enters_destination, score_permille, 677).
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
provenance(r7_liquid_remains_in_destination, simulations, 106).
provenance(r7_liquid_remains_in_destination, weight_mass_permille, 27331).
provenance(r7_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r7_liquid_remains_in_destination, score_permille, 990).
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
provenance(r7_no_spill, simulations, 106).
provenance(r7_no_spill, weight_mass_permille, 27331).
provenance(r7_no_spill, confidence_permille, 938).
provenance(r7_no_spill, score_permille, 897).
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
provenance(r8_destination_still_approach, simulations, 171).
provenance(r8_destination_still_approach, weight_mass_permille, 27023).
provenance(r8_destination_still_approach, confidence_permille, 972).
provenance(r8_destination_still_approach, score_permille, 956).
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
provenance(r8_destination_still_retreat, simulations, 171).
provenance(r8_destination_still_retreat, weight_mass_permille, 27023).
provenance(r8_destination_still_retreat, confidence_permille, 968).
provenance(r8_destination_still_retreat, score_permille, 966).
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
provenance(r8_destination_still_settle, simulations, 171).
provenance(r8_destination_still_settle, weight_mass_permille, 27023).
provenance(r8_destination_still_settle, confidence_permille, 1000).
provenance(r8_destination_still_settle, score_permille, 998).
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
provenance(r8_destination_upright, simulations, 171).
provenance(r8_destination_upright, weight_mass_permille, 27023).
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
provenance(r8_source_clear, simulations, 171).
provenance(r8_source_clear, weight_mass_permille, 27023).
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
provenance(r8_liquid_leaves_source, simulations, 171).
provenance(r8_liquid_leaves_source, weight_mass_permille, 27023).
provenance(r8_liquid_leaves_source, confidence_permille, 666).
provenance(r8_liquid_leaves_source, score_permille, 687).
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
provenance(r8_liquid_enters_destination, simulations, 171).
provenance(r8_liquid_enters_destination, weight_mass_permille, 27023).
provenance(r8_liquid_enters_destination, confidence_permille, 644).
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
provenance(r8_liquid_remains_in_destination, simulations, 171).
provenance(r8_liquid_remains_in_destination, weight_mass_permille, 27023).
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
provenance(r8_no_spill, simulations, 171).
provenance(r8_no_spill, weight_mass_permille, 27023).
provenance(r8_no_spill, confidence_permille, 994).
provenance(r8_no_spill, score_permille, 926).
provenance(r8_no_spill, followed, liquid_leaves_source).
provenance(r8_no_spill, direction, approach_duration).
provenance(r8_no_spill, sign, down).

rule(r9_destination_still_approach, defeasible, destination_still_approach).
body(r9_destination_still_approach, light_source).
body(r9_destination_still_approach, little_liquid).
body(r9_destination_still_approach, pour_mid_height).
body(r9_destination_still_approach, pour_near_rim).
body(r9_destination_still_approach, pour_steeply_tilted).
body(r9_destination_still_approach, slippery_destination).
learned(r9_destination_still_approach).
provenance(r9_destination_still_approach, antecedent, a9).
provenance(r9_destination_still_approach, parent, a4).
provenance(r9_destination_still_approach, simulations, 263).
provenance(r9_destination_still_approach, weight_mass_permille, 31388).
provenance(r9_destination_still_approach, confidence_permille, 999).
provenance(r9_destination_still_approach, score_permille, 976).
provenance(r9_destination_still_approach, followed, liquid_leaves_source).
provenance(r9_destination_still_approach, direction, particle_count).
provenance(r9_destination_still_approach, sign, down).

rule(r9_destination_still_retreat, defeasible, destination_still_retreat).
body(r9_destination_still_retreat, light_source).
body(r9_destination_still_retreat, little_liquid).
body(r9_destination_still_retreat, pour_mid_height).
body(r9_destination_still_retreat, pour_near_rim).
body(r9_destination_still_retreat, pour_steeply_tilted).
body(r9_destination_still_retreat, slippery_destination).
learned(r9_destination_still_retreat).
provenance(r9_destination_still_retreat, antecedent, a9).
provenance(r9_destination_still_retreat, parent, a4).
provenance(r9_destination_still_retreat, simulations, 263).
provenance(r9_destination_still_retreat, weight_mass_permille, 31388).
provenance(r9_destination_still_retreat, confidence_permille, 948).
provenance(r9_destination_still_retreat, score_permille, 933).
provenance(r9_destination_still_retreat, followed, liquid_leaves_source).
provenance(r9_destination_still_retreat, direction, particle_count).
provenance(r9_destination_still_retreat, sign, down).

rule(r9_destination_still_settle, defeasible, destination_still_settle).
body(r9_destination_still_settle, light_source).
body(r9_destination_still_settle, little_liquid).
body(r9_destination_still_settle, pour_mid_height).
body(r9_destination_still_settle, pour_near_rim).
body(r9_destination_still_settle, pour_steeply_tilted).
body(r9_destination_still_settle, slippery_destination).
learned(r9_destination_still_settle).
provenance(r9_destination_still_settle, antecedent, a9).
provenance(r9_destination_still_settle, parent, a4).
provenance(r9_destination_still_settle, simulations, 263).
provenance(r9_destination_still_settle, weight_mass_permille, 31388).
provenance(r9_destination_still_settle, confidence_permille, 1000).
provenance(r9_destination_still_settle, score_permille, 999).
provenance(r9_destination_still_settle, followed, liquid_leaves_source).
provenance(r9_destination_still_settle, direction, particle_count).
provenance(r9_destination_still_settle, sign, down).

rule(r9_destination_upright, defeasible, destination_upright).
body(r9_destination_upright, light_source).
body(r9_destination_upright, little_liquid).
body(r9_destination_upright, pour_mid_height).
body(r9_destination_upright, pour_near_rim).
body(r9_destination_upright, pour_steeply_tilted).
body(r9_destination_upright, slippery_destination).
learned(r9_destination_upright).
provenance(r9_destination_upright, antecedent, a9).
provenance(r9_destination_upright, parent, a4).
provenance(r9_destination_upright, simulations, 263).
provenance(r9_destination_upright, weight_mass_permille, 31388).
provenance(r9_destination_upright, confidence_permille, 1000).
provenance(r9_destination_upright, score_permille, 1000).
provenance(r9_destination_upright, followed, liquid_leaves_source).
provenance(r9_destination_upright, direction, particle_count).
provenance(r9_destination_upright, sign, down).

rule(r9_source_clear, defeasible, source_clear).
body(r9_source_clear, light_source).
body(r9_source_clear, little_liquid).
body(r9_source_clear, pour_mid_height).
body(r9_source_clear, pour_near_rim).
body(r9_source_clear, pour_steeply_tilted).
body(r9_source_clear, slippery_destination).
learned(r9_source_clear).
provenance(r9_source_clear, antecedent, a9).
provenance(r9_source_clear, parent, a4).
provenance(r9_source_clear, simulations, 263).
provenance(r9_source_clear, weight_mass_permille, 31388).
provenance(r9_source_clear, confidence_permille, 1000).
provenance(r9_source_clear, score_permille, 991).
provenance(r9_source_clear, followed, liquid_leaves_source).
provenance(r9_source_clear, direction, particle_count).
provenance(r9_source_clear, sign, down).

rule(r9_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r9_liquid_leaves_source, light_source).
body(r9_liquid_leaves_source, little_liquid).
body(r9_liquid_leaves_source, pour_mid_height).
body(r9_liquid_leaves_source, pour_near_rim).
body(r9_liquid_leaves_source, pour_steeply_tilted).
body(r9_liquid_leaves_source, slippery_destination).
learned(r9_liquid_leaves_source).
provenance(r9_liquid_leaves_source, antecedent, a9).
provenance(r9_liquid_leaves_source, parent, a4).
provenance(r9_liquid_leaves_source, simulations, 263).
provenance(r9_liquid_leaves_source, weight_mass_permille, 31388).
provenance(r9_liquid_leaves_source, confidence_permille, 657).
provenance(r9_liquid_leaves_source, score_permille, 689).
provenance(r9_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r9_liquid_leaves_source, direction, particle_count).
provenance(r9_liquid_leaves_source, sign, down).

rule(r9_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r9_liquid_enters_destination, light_source).
body(r9_liquid_enters_destination, little_liquid).
body(r9_liquid_enters_destination, pour_mid_height).
body(r9_liquid_enters_destination, pour_near_rim).
body(r9_liquid_enters_destination, pour_steeply_tilted).
body(r9_liquid_enters_destination, slippery_destination).
learned(r9_liquid_enters_destination).
provenance(r9_liquid_enters_destination, antecedent, a9).
provenance(r9_liquid_enters_destination, parent, a4).
provenance(r9_liquid_enters_destination, simulations, 263).
provenance(r9_liquid_enters_destination, weight_mass_permille, 31388).
provenance(r9_liquid_enters_destination, confidence_permille, 651).
provenance(r9_liquid_enters_destination, score_permille, 642).
provenance(r9_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r9_liquid_enters_destination, direction, particle_count).
provenance(r9_liquid_enters_destination, sign, down).

rule(r9_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r9_liquid_remains_in_destination, light_source).
body(r9_liquid_remains_in_destination, little_liquid).
body(r9_liquid_remains_in_destination, pour_mid_height).
body(r9_liquid_remains_in_destination, pour_near_rim).
body(r9_liquid_remains_in_destination, pour_steeply_tilted).
body(r9_liquid_remains_in_destination, slippery_destination).
learned(r9_liquid_remains_in_destination).
provenance(r9_liquid_remains_in_destination, antecedent, a9).
provenance(r9_liquid_remains_in_destination, parent, a4).
provenance(r9_liquid_remains_in_destination, simulations, 263).
provenance(r9_liquid_remains_in_destination, weight_mass_permille, 31388).
provenance(r9_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r9_liquid_remains_in_destination, score_permille, 996).
provenance(r9_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r9_liquid_remains_in_destination, direction, particle_count).
provenance(r9_liquid_remains_in_destination, sign, down).

rule(r9_no_spill, defeasible, no_spill).
body(r9_no_spill, light_source).
body(r9_no_spill, little_liquid).
body(r9_no_spill, pour_mid_height).
body(r9_no_spill, pour_near_rim).
body(r9_no_spill, pour_steeply_tilted).
body(r9_no_spill, slippery_destination).
learned(r9_no_spill).
provenance(r9_no_spill, antecedent, a9).
provenance(r9_no_spill, parent, a4).
provenance(r9_no_spill, simulations, 263).
provenance(r9_no_spill, weight_mass_permille, 31388).
provenance(r9_no_spill, confidence_permille, 997).
provenance(r9_no_spill, score_permille, 949).
provenance(r9_no_spill, followed, liquid_leaves_source).
provenance(r9_no_spill, direction, particle_count).
provenance(r9_no_spill, sign, down).

rule(r10_destination_still_approach, defeasible, destination_still_approach).
body(r10_destination_still_approach, light_source).
body(r10_destination_still_approach, pour_mid_height).
body(r10_destination_still_approach, pour_near_rim).
body(r10_destination_still_approach, pour_steeply_tilted).
body(r10_destination_still_approach, slippery_destination).
body(r10_destination_still_approach, some_liquid).
learned(r10_destination_still_approach).
provenance(r10_destination_still_approach, antecedent, a10).
provenance(r10_destination_still_approach, parent, a4).
provenance(r10_destination_still_approach, simulations, 56).
provenance(r10_destination_still_approach, weight_mass_permille, 32419).
provenance(r10_destination_still_approach, confidence_permille, 977).
provenance(r10_destination_still_approach, score_permille, 955).
provenance(r10_destination_still_approach, followed, liquid_leaves_source).
provenance(r10_destination_still_approach, direction, particle_count).
provenance(r10_destination_still_approach, sign, down).

rule(r10_destination_still_retreat, defeasible, destination_still_retreat).
body(r10_destination_still_retreat, light_source).
body(r10_destination_still_retreat, pour_mid_height).
body(r10_destination_still_retreat, pour_near_rim).
body(r10_destination_still_retreat, pour_steeply_tilted).
body(r10_destination_still_retreat, slippery_destination).
body(r10_destination_still_retreat, some_liquid).
learned(r10_destination_still_retreat).
provenance(r10_destination_still_retreat, antecedent, a10).
provenance(r10_destination_still_retreat, parent, a4).
provenance(r10_destination_still_retreat, simulations, 56).
provenance(r10_destination_still_retreat, weight_mass_permille, 32419).
provenance(r10_destination_still_retreat, confidence_permille, 903).
provenance(r10_destination_still_retreat, score_permille, 887).
provenance(r10_destination_still_retreat, followed, liquid_leaves_source).
provenance(r10_destination_still_retreat, direction, particle_count).
provenance(r10_destination_still_retreat, sign, down).

rule(r10_destination_still_settle, defeasible, destination_still_settle).
body(r10_destination_still_settle, light_source).
body(r10_destination_still_settle, pour_mid_height).
body(r10_destination_still_settle, pour_near_rim).
body(r10_destination_still_settle, pour_steeply_tilted).
body(r10_destination_still_settle, slippery_destination).
body(r10_destination_still_settle, some_liquid).
learned(r10_destination_still_settle).
provenance(r10_destination_still_settle, antecedent, a10).
provenance(r10_destination_still_settle, parent, a4).
provenance(r10_destination_still_settle, simulations, 56).
provenance(r10_destination_still_settle, weight_mass_permille, 32419).
provenance(r10_destination_still_settle, confidence_permille, 958).
provenance(r10_destination_still_settle, score_permille, 953).
provenance(r10_destination_still_settle, followed, liquid_leaves_source).
provenance(r10_destination_still_settle, direction, particle_count).
provenance(r10_destination_still_settle, sign, down).

rule(r10_destination_upright, defeasible, destination_upright).
body(r10_destination_upright, light_source).
body(r10_destination_upright, pour_mid_height).
body(r10_destination_upright, pour_near_rim).
body(r10_destination_upright, pour_steeply_tilted).
body(r10_destination_upright, slippery_destination).
body(r10_destination_upright, some_liquid).
learned(r10_destination_upright).
provenance(r10_destination_upright, antecedent, a10).
provenance(r10_destination_upright, parent, a4).
provenance(r10_destination_upright, simulations, 56).
provenance(r10_destination_upright, weight_mass_permille, 32419).
provenance(r10_destination_upright, confidence_permille, 1000).
provenance(r10_destination_upright, score_permille, 994).
provenance(r10_destination_upright, followed, liquid_leaves_source).
provenance(r10_destination_upright, direction, particle_count).
provenance(r10_destination_upright, sign, down).

rule(r10_source_clear, defeasible, source_clear).
body(r10_source_clear, light_source).
body(r10_source_clear, pour_mid_height).
body(r10_source_clear, pour_near_rim).
body(r10_source_clear, pour_steeply_tilted).
body(r10_source_clear, slippery_destination).
body(r10_source_clear, some_liquid).
learned(r10_source_clear).
provenance(r10_source_clear, antecedent, a10).
provenance(r10_source_clear, parent, a4).
provenance(r10_source_clear, simulations, 56).
provenance(r10_source_clear, weight_mass_permille, 32419).
provenance(r10_source_clear, confidence_permille, 1000).
provenance(r10_source_clear, score_permille, 1000).
provenance(r10_source_clear, followed, liquid_leaves_source).
provenance(r10_source_clear, direction, particle_count).
provenance(r10_source_clear, sign, down).

rule(r10_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r10_liquid_leaves_source, light_source).
body(r10_liquid_leaves_source, pour_mid_height).
body(r10_liquid_leaves_source, pour_near_rim).
body(r10_liquid_leaves_source, pour_steeply_tilted).
body(r10_liquid_leaves_source, slippery_destination).
body(r10_liquid_leaves_source, some_liquid).
learned(r10_liquid_leaves_source).
provenance(r10_liquid_leaves_source, antecedent, a10).
provenance(r10_liquid_leaves_source, parent, a4).
provenance(r10_liquid_leaves_source, simulations, 56).
provenance(r10_liquid_leaves_source, weight_mass_permille, 32419).
provenance(r10_liquid_leaves_source, confidence_permille, 751).
provenance(r10_liquid_leaves_source, score_permille, 751).
provenance(r10_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r10_liquid_leaves_source, direction, particle_count).
provenance(r10_liquid_leaves_source, sign, down).

rule(r10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r10_liquid_enters_destination, light_source).
body(r10_liquid_enters_destination, pour_mid_height).
body(r10_liquid_enters_destination, pour_near_rim).
body(r10_liquid_enters_destination, pour_steeply_tilted).
body(r10_liquid_enters_destination, slippery_destination).
body(r10_liquid_enters_destination, some_liquid).
learned(r10_liquid_enters_destination).
provenance(r10_liquid_enters_destination, antecedent, a10).
provenance(r10_liquid_enters_destination, parent, a4).
provenance(r10_liquid_enters_destination, simulations, 56).
provenance(r10_liquid_enters_destination, weight_mass_permille, 32419).
provenance(r10_liquid_enters_destination, confidence_permille, 719).
provenance(r10_liquid_enters_destination, score_permille, 690).
provenance(r10_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r10_liquid_enters_destination, direction, particle_count).
provenance(r10_liquid_enters_destination, sign, down).

rule(r10_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r10_liquid_remains_in_destination, light_source).
body(r10_liquid_remains_in_destination, pour_mid_height).
body(r10_liquid_remains_in_destination, pour_near_rim).
body(r10_liquid_remains_in_destination, pour_steeply_tilted).
body(r10_liquid_remains_in_destination, slippery_destination).
body(r10_liquid_remains_in_destination, some_liquid).
learned(r10_liquid_remains_in_destination).
provenance(r10_liquid_remains_in_destination, antecedent, a10).
provenance(r10_liquid_remains_in_destination, parent, a4).
provenance(r10_liquid_remains_in_destination, simulations, 56).
provenance(r10_liquid_remains_in_destination, weight_mass_permille, 32419).
provenance(r10_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r10_liquid_remains_in_destination, score_permille, 975).
provenance(r10_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r10_liquid_remains_in_destination, direction, particle_count).
provenance(r10_liquid_remains_in_destination, sign, down).

rule(r10_no_spill, defeasible, no_spill).
body(r10_no_spill, light_source).
body(r10_no_spill, pour_mid_height).
body(r10_no_spill, pour_near_rim).
body(r10_no_spill, pour_steeply_tilted).
body(r10_no_spill, slippery_destination).
body(r10_no_spill, some_liquid).
learned(r10_no_spill).
provenance(r10_no_spill, antecedent, a10).
provenance(r10_no_spill, parent, a4).
provenance(r10_no_spill, simulations, 56).
provenance(r10_no_spill, weight_mass_permille, 32419).
provenance(r10_no_spill, confidence_permille, 966).
provenance(r10_no_spill, score_permille, 918).
provenance(r10_no_spill, followed, liquid_leaves_source).
provenance(r10_no_spill, direction, particle_count).
provenance(r10_no_spill, sign, down).

rule(r11_destination_still_approach, defeasible, destination_still_approach).
body(r11_destination_still_approach, light_source).
body(r11_destination_still_approach, pour_half_tilted).
body(r11_destination_still_approach, pour_mid_height).
body(r11_destination_still_approach, pour_near_rim).
body(r11_destination_still_approach, slippery_destination).
learned(r11_destination_still_approach).
provenance(r11_destination_still_approach, antecedent, a11).
provenance(r11_destination_still_approach, parent, a4).
provenance(r11_destination_still_approach, simulations, 190).
provenance(r11_destination_still_approach, weight_mass_permille, 29955).
provenance(r11_destination_still_approach, confidence_permille, 1000).
provenance(r11_destination_still_approach, score_permille, 993).
provenance(r11_destination_still_approach, followed, liquid_leaves_source).
provenance(r11_destination_still_approach, direction, pour_pitch).
provenance(r11_destination_still_approach, sign, down).

rule(r11_destination_still_retreat, defeasible, destination_still_retreat).
body(r11_destination_still_retreat, light_source).
body(r11_destination_still_retreat, pour_half_tilted).
body(r11_destination_still_retreat, pour_mid_height).
body(r11_destination_still_retreat, pour_near_rim).
body(r11_destination_still_retreat, slippery_destination).
learned(r11_destination_still_retreat).
provenance(r11_destination_still_retreat, antecedent, a11).
provenance(r11_destination_still_retreat, parent, a4).
provenance(r11_destination_still_retreat, simulations, 190).
provenance(r11_destination_still_retreat, weight_mass_permille, 29955).
provenance(r11_destination_still_retreat, confidence_permille, 1000).
provenance(r11_destination_still_retreat, score_permille, 999).
provenance(r11_destination_still_retreat, followed, liquid_leaves_source).
provenance(r11_destination_still_retreat, direction, pour_pitch).
provenance(r11_destination_still_retreat, sign, down).

rule(r11_destination_still_settle, defeasible, destination_still_settle).
body(r11_destination_still_settle, light_source).
body(r11_destination_still_settle, pour_half_tilted).
body(r11_destination_still_settle, pour_mid_height).
body(r11_destination_still_settle, pour_near_rim).
body(r11_destination_still_settle, slippery_destination).
learned(r11_destination_still_settle).
provenance(r11_destination_still_settle, antecedent, a11).
provenance(r11_destination_still_settle, parent, a4).
provenance(r11_destination_still_settle, simulations, 190).
provenance(r11_destination_still_settle, weight_mass_permille, 29955).
provenance(r11_destination_still_settle, confidence_permille, 1000).
provenance(r11_destination_still_settle, score_permille, 1000).
provenance(r11_destination_still_settle, followed, liquid_leaves_source).
provenance(r11_destination_still_settle, direction, pour_pitch).
provenance(r11_destination_still_settle, sign, down).

rule(r11_destination_upright, defeasible, destination_upright).
body(r11_destination_upright, light_source).
body(r11_destination_upright, pour_half_tilted).
body(r11_destination_upright, pour_mid_height).
body(r11_destination_upright, pour_near_rim).
body(r11_destination_upright, slippery_destination).
learned(r11_destination_upright).
provenance(r11_destination_upright, antecedent, a11).
provenance(r11_destination_upright, parent, a4).
provenance(r11_destination_upright, simulations, 190).
provenance(r11_destination_upright, weight_mass_permille, 29955).
provenance(r11_destination_upright, confidence_permille, 1000).
provenance(r11_destination_upright, score_permille, 1000).
provenance(r11_destination_upright, followed, liquid_leaves_source).
provenance(r11_destination_upright, direction, pour_pitch).
provenance(r11_destination_upright, sign, down).

rule(r11_source_clear, defeasible, source_clear).
body(r11_source_clear, light_source).
body(r11_source_clear, pour_half_tilted).
body(r11_source_clear, pour_mid_height).
body(r11_source_clear, pour_near_rim).
body(r11_source_clear, slippery_destination).
learned(r11_source_clear).
provenance(r11_source_clear, antecedent, a11).
provenance(r11_source_clear, parent, a4).
provenance(r11_source_clear, simulations, 190).
provenance(r11_source_clear, weight_mass_permille, 29955).
provenance(r11_source_clear, confidence_permille, 1000).
provenance(r11_source_clear, score_permille, 1000).
provenance(r11_source_clear, followed, liquid_leaves_source).
provenance(r11_source_clear, direction, pour_pitch).
provenance(r11_source_clear, sign, down).

rule(r11_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r11_liquid_leaves_source, light_source).
body(r11_liquid_leaves_source, pour_half_tilted).
body(r11_liquid_leaves_source, pour_mid_height).
body(r11_liquid_leaves_source, pour_near_rim).
body(r11_liquid_leaves_source, slippery_destination).
learned(r11_liquid_leaves_source).
provenance(r11_liquid_leaves_source, antecedent, a11).
provenance(r11_liquid_leaves_source, parent, a4).
provenance(r11_liquid_leaves_source, simulations, 190).
provenance(r11_liquid_leaves_source, weight_mass_permille, 29955).
provenance(r11_liquid_leaves_source, confidence_permille, 998).
provenance(r11_liquid_leaves_source, score_permille, 51).
provenance(r11_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r11_liquid_leaves_source, direction, pour_pitch).
provenance(r11_liquid_leaves_source, sign, down).

rule(r11_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r11_liquid_enters_destination, light_source).
body(r11_liquid_enters_destination, pour_half_tilted).
body(r11_liquid_enters_destination, pour_mid_height).
body(r11_liquid_enters_destination, pour_near_rim).
body(r11_liquid_enters_destination, slippery_destination).
learned(r11_liquid_enters_destination).
provenance(r11_liquid_enters_destination, antecedent, a11).
provenance(r11_liquid_enters_destination, parent, a4).
provenance(r11_liquid_enters_destination, simulations, 190).
provenance(r11_liquid_enters_destination, weight_mass_permille, 29955).
provenance(r11_liquid_enters_destination, confidence_permille, 1000).
provenance(r11_liquid_enters_destination, score_permille, 36).
provenance(r11_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r11_liquid_enters_destination, direction, pour_pitch).
provenance(r11_liquid_enters_destination, sign, down).

rule(r11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r11_liquid_remains_in_destination, light_source).
body(r11_liquid_remains_in_destination, pour_half_tilted).
body(r11_liquid_remains_in_destination, pour_mid_height).
body(r11_liquid_remains_in_destination, pour_near_rim).
body(r11_liquid_remains_in_destination, slippery_destination).
learned(r11_liquid_remains_in_destination).
provenance(r11_liquid_remains_in_destination, antecedent, a11).
provenance(r11_liquid_remains_in_destination, parent, a4).
provenance(r11_liquid_remains_in_destination, simulations, 190).
provenance(r11_liquid_remains_in_destination, weight_mass_permille, 29955).
provenance(r11_liquid_remains_in_destination, confidence_permille, 998).
provenance(r11_liquid_remains_in_destination, score_permille, 998).
provenance(r11_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r11_liquid_remains_in_destination, direction, pour_pitch).
provenance(r11_liquid_remains_in_destination, sign, down).

rule(r11_no_spill, defeasible, no_spill).
body(r11_no_spill, light_source).
body(r11_no_spill, pour_half_tilted).
body(r11_no_spill, pour_mid_height).
body(r11_no_spill, pour_near_rim).
body(r11_no_spill, slippery_destination).
learned(r11_no_spill).
provenance(r11_no_spill, antecedent, a11).
provenance(r11_no_spill, parent, a4).
provenance(r11_no_spill, simulations, 190).
provenance(r11_no_spill, weight_mass_permille, 29955).
provenance(r11_no_spill, confidence_permille, 1000).
provenance(r11_no_spill, score_permille, 984).
provenance(r11_no_spill, followed, liquid_leaves_source).
provenance(r11_no_spill, direction, pour_pitch).
provenance(r11_no_spill, sign, down).

rule(r12_destination_still_approach, defeasible, destination_still_approach).
body(r12_destination_still_approach, light_liquid).
body(r12_destination_still_approach, light_source).
body(r12_destination_still_approach, pour_mid_height).
body(r12_destination_still_approach, pour_near_rim).
body(r12_destination_still_approach, pour_steeply_tilted).
body(r12_destination_still_approach, slippery_destination).
learned(r12_destination_still_approach).
provenance(r12_destination_still_approach, antecedent, a12).
provenance(r12_destination_still_approach, parent, a4).
provenance(r12_destination_still_approach, simulations, 106).
provenance(r12_destination_still_approach, weight_mass_permille, 37063).
provenance(r12_destination_still_approach, confidence_permille, 1000).
provenance(r12_destination_still_approach, score_permille, 989).
provenance(r12_destination_still_approach, followed, liquid_leaves_source).
provenance(r12_destination_still_approach, direction, particle_mass).
provenance(r12_destination_still_approach, sign, down).

rule(r12_destination_still_retreat, defeasible, destination_still_retreat).
body(r12_destination_still_retreat, light_liquid).
body(r12_destination_still_retreat, light_source).
body(r12_destination_still_retreat, pour_mid_height).
body(r12_destination_still_retreat, pour_near_rim).
body(r12_destination_still_retreat, pour_steeply_tilted).
body(r12_destination_still_retreat, slippery_destination).
learned(r12_destination_still_retreat).
provenance(r12_destination_still_retreat, antecedent, a12).
provenance(r12_destination_still_retreat, parent, a4).
provenance(r12_destination_still_retreat, simulations, 106).
provenance(r12_destination_still_retreat, weight_mass_permille, 37063).
provenance(r12_destination_still_retreat, confidence_permille, 1000).
provenance(r12_destination_still_retreat, score_permille, 997).
provenance(r12_destination_still_retreat, followed, liquid_leaves_source).
provenance(r12_destination_still_retreat, direction, particle_mass).
provenance(r12_destination_still_retreat, sign, down).

rule(r12_destination_still_settle, defeasible, destination_still_settle).
body(r12_destination_still_settle, light_liquid).
body(r12_destination_still_settle, light_source).
body(r12_destination_still_settle, pour_mid_height).
body(r12_destination_still_settle, pour_near_rim).
body(r12_destination_still_settle, pour_steeply_tilted).
body(r12_destination_still_settle, slippery_destination).
learned(r12_destination_still_settle).
provenance(r12_destination_still_settle, antecedent, a12).
provenance(r12_destination_still_settle, parent, a4).
provenance(r12_destination_still_settle, simulations, 106).
provenance(r12_destination_still_settle, weight_mass_permille, 37063).
provenance(r12_destination_still_settle, confidence_permille, 1000).
provenance(r12_destination_still_settle, score_permille, 1000).
provenance(r12_destination_still_settle, followed, liquid_leaves_source).
provenance(r12_destination_still_settle, direction, particle_mass).
provenance(r12_destination_still_settle, sign, down).

rule(r12_destination_upright, defeasible, destination_upright).
body(r12_destination_upright, light_liquid).
body(r12_destination_upright, light_source).
body(r12_destination_upright, pour_mid_height).
body(r12_destination_upright, pour_near_rim).
body(r12_destination_upright, pour_steeply_tilted).
body(r12_destination_upright, slippery_destination).
learned(r12_destination_upright).
provenance(r12_destination_upright, antecedent, a12).
provenance(r12_destination_upright, parent, a4).
provenance(r12_destination_upright, simulations, 106).
provenance(r12_destination_upright, weight_mass_permille, 37063).
provenance(r12_destination_upright, confidence_permille, 1000).
provenance(r12_destination_upright, score_permille, 1000).
provenance(r12_destination_upright, followed, liquid_leaves_source).
provenance(r12_destination_upright, direction, particle_mass).
provenance(r12_destination_upright, sign, down).

rule(r12_source_clear, defeasible, source_clear).
body(r12_source_clear, light_liquid).
body(r12_source_clear, light_source).
body(r12_source_clear, pour_mid_height).
body(r12_source_clear, pour_near_rim).
body(r12_source_clear, pour_steeply_tilted).
body(r12_source_clear, slippery_destination).
learned(r12_source_clear).
provenance(r12_source_clear, antecedent, a12).
provenance(r12_source_clear, parent, a4).
provenance(r12_source_clear, simulations, 106).
provenance(r12_source_clear, weight_mass_permille, 37063).
provenance(r12_source_clear, confidence_permille, 1000).
provenance(r12_source_clear, score_permille, 1000).
provenance(r12_source_clear, followed, liquid_leaves_source).
provenance(r12_source_clear, direction, particle_mass).
provenance(r12_source_clear, sign, down).

rule(r12_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r12_liquid_leaves_source, light_liquid).
body(r12_liquid_leaves_source, light_source).
body(r12_liquid_leaves_source, pour_mid_height).
body(r12_liquid_leaves_source, pour_near_rim).
body(r12_liquid_leaves_source, pour_steeply_tilted).
body(r12_liquid_leaves_source, slippery_destination).
learned(r12_liquid_leaves_source).
provenance(r12_liquid_leaves_source, antecedent, a12).
provenance(r12_liquid_leaves_source, parent, a4).
provenance(r12_liquid_leaves_source, simulations, 106).
provenance(r12_liquid_leaves_source, weight_mass_permille, 37063).
provenance(r12_liquid_leaves_source, confidence_permille, 743).
provenance(r12_liquid_leaves_source, score_permille, 723).
provenance(r12_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r12_liquid_leaves_source, direction, particle_mass).
provenance(r12_liquid_leaves_source, sign, down).

rule(r12_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r12_liquid_enters_destination, light_liquid).
body(r12_liquid_enters_destination, light_source).
body(r12_liquid_enters_destination, pour_mid_height).
body(r12_liquid_enters_destination, pour_near_rim).
body(r12_liquid_enters_destination, pour_steeply_tilted).
body(r12_liquid_enters_destination, slippery_destination).
learned(r12_liquid_enters_destination).
provenance(r12_liquid_enters_destination, antecedent, a12).
provenance(r12_liquid_enters_destination, parent, a4).
provenance(r12_liquid_enters_destination, simulations, 106).
provenance(r12_liquid_enters_destination, weight_mass_permille, 37063).
provenance(r12_liquid_enters_destination, confidence_permille, 712).
provenance(r12_liquid_enters_destination, score_permille, 658).
provenance(r12_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r12_liquid_enters_destination, direction, particle_mass).
provenance(r12_liquid_enters_destination, sign, down).

rule(r12_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r12_liquid_remains_in_destination, light_liquid).
body(r12_liquid_remains_in_destination, light_source).
body(r12_liquid_remains_in_destination, pour_mid_height).
body(r12_liquid_remains_in_destination, pour_near_rim).
body(r12_liquid_remains_in_destination, pour_steeply_tilted).
body(r12_liquid_remains_in_destination, slippery_destination).
learned(r12_liquid_remains_in_destination).
provenance(r12_liquid_remains_in_destination, antecedent, a12).
provenance(r12_liquid_remains_in_destination, parent, a4).
provenance(r12_liquid_remains_in_destination, simulations, 106).
provenance(r12_liquid_remains_in_destination, weight_mass_permille, 37063).
provenance(r12_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r12_liquid_remains_in_destination, score_permille, 989).
provenance(r12_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r12_liquid_remains_in_destination, direction, particle_mass).
provenance(r12_liquid_remains_in_destination, sign, down).

rule(r12_no_spill, defeasible, no_spill).
body(r12_no_spill, light_liquid).
body(r12_no_spill, light_source).
body(r12_no_spill, pour_mid_height).
body(r12_no_spill, pour_near_rim).
body(r12_no_spill, pour_steeply_tilted).
body(r12_no_spill, slippery_destination).
learned(r12_no_spill).
provenance(r12_no_spill, antecedent, a12).
provenance(r12_no_spill, parent, a4).
provenance(r12_no_spill, simulations, 106).
provenance(r12_no_spill, weight_mass_permille, 37063).
provenance(r12_no_spill, confidence_permille, 997).
provenance(r12_no_spill, score_permille, 928).
provenance(r12_no_spill, followed, liquid_leaves_source).
provenance(r12_no_spill, direction, particle_mass).
provenance(r12_no_spill, sign, down).

rule(r13_destination_still_approach, defeasible, destination_still_approach).
body(r13_destination_still_approach, light_source).
body(r13_destination_still_approach, medium_liquid).
body(r13_destination_still_approach, pour_mid_height).
body(r13_destination_still_approach, pour_near_rim).
body(r13_destination_still_approach, pour_steeply_tilted).
body(r13_destination_still_approach, slippery_destination).
learned(r13_destination_still_approach).
provenance(r13_destination_still_approach, antecedent, a13).
provenance(r13_destination_still_approach, parent, a4).
provenance(r13_destination_still_approach, simulations, 205).
provenance(r13_destination_still_approach, weight_mass_permille, 29307).
provenance(r13_destination_still_approach, confidence_permille, 963).
provenance(r13_destination_still_approach, score_permille, 946).
provenance(r13_destination_still_approach, followed, liquid_leaves_source).
provenance(r13_destination_still_approach, direction, particle_mass).
provenance(r13_destination_still_approach, sign, down).

rule(r13_destination_still_retreat, defeasible, destination_still_retreat).
body(r13_destination_still_retreat, light_source).
body(r13_destination_still_retreat, medium_liquid).
body(r13_destination_still_retreat, pour_mid_height).
body(r13_destination_still_retreat, pour_near_rim).
body(r13_destination_still_retreat, pour_steeply_tilted).
body(r13_destination_still_retreat, slippery_destination).
learned(r13_destination_still_retreat).
provenance(r13_destination_still_retreat, antecedent, a13).
provenance(r13_destination_still_retreat, parent, a4).
provenance(r13_destination_still_retreat, simulations, 205).
provenance(r13_destination_still_retreat, weight_mass_permille, 29307).
provenance(r13_destination_still_retreat, confidence_permille, 980).
provenance(r13_destination_still_retreat, score_permille, 960).
provenance(r13_destination_still_retreat, followed, liquid_leaves_source).
provenance(r13_destination_still_retreat, direction, particle_mass).
provenance(r13_destination_still_retreat, sign, down).

rule(r13_destination_still_settle, defeasible, destination_still_settle).
body(r13_destination_still_settle, light_source).
body(r13_destination_still_settle, medium_liquid).
body(r13_destination_still_settle, pour_mid_height).
body(r13_destination_still_settle, pour_near_rim).
body(r13_destination_still_settle, pour_steeply_tilted).
body(r13_destination_still_settle, slippery_destination).
learned(r13_destination_still_settle).
provenance(r13_destination_still_settle, antecedent, a13).
provenance(r13_destination_still_settle, parent, a4).
provenance(r13_destination_still_settle, simulations, 205).
provenance(r13_destination_still_settle, weight_mass_permille, 29307).
provenance(r13_destination_still_settle, confidence_permille, 1000).
provenance(r13_destination_still_settle, score_permille, 996).
provenance(r13_destination_still_settle, followed, liquid_leaves_source).
provenance(r13_destination_still_settle, direction, particle_mass).
provenance(r13_destination_still_settle, sign, down).

rule(r13_destination_upright, defeasible, destination_upright).
body(r13_destination_upright, light_source).
body(r13_destination_upright, medium_liquid).
body(r13_destination_upright, pour_mid_height).
body(r13_destination_upright, pour_near_rim).
body(r13_destination_upright, pour_steeply_tilted).
body(r13_destination_upright, slippery_destination).
learned(r13_destination_upright).
provenance(r13_destination_upright, antecedent, a13).
provenance(r13_destination_upright, parent, a4).
provenance(r13_destination_upright, simulations, 205).
provenance(r13_destination_upright, weight_mass_permille, 29307).
provenance(r13_destination_upright, confidence_permille, 1000).
provenance(r13_destination_upright, score_permille, 997).
provenance(r13_destination_upright, followed, liquid_leaves_source).
provenance(r13_destination_upright, direction, particle_mass).
provenance(r13_destination_upright, sign, down).

rule(r13_source_clear, defeasible, source_clear).
body(r13_source_clear, light_source).
body(r13_source_clear, medium_liquid).
body(r13_source_clear, pour_mid_height).
body(r13_source_clear, pour_near_rim).
body(r13_source_clear, pour_steeply_tilted).
body(r13_source_clear, slippery_destination).
learned(r13_source_clear).
provenance(r13_source_clear, antecedent, a13).
provenance(r13_source_clear, parent, a4).
provenance(r13_source_clear, simulations, 205).
provenance(r13_source_clear, weight_mass_permille, 29307).
provenance(r13_source_clear, confidence_permille, 1000).
provenance(r13_source_clear, score_permille, 999).
provenance(r13_source_clear, followed, liquid_leaves_source).
provenance(r13_source_clear, direction, particle_mass).
provenance(r13_source_clear, sign, down).

rule(r13_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r13_liquid_leaves_source, light_source).
body(r13_liquid_leaves_source, medium_liquid).
body(r13_liquid_leaves_source, pour_mid_height).
body(r13_liquid_leaves_source, pour_near_rim).
body(r13_liquid_leaves_source, pour_steeply_tilted).
body(r13_liquid_leaves_source, slippery_destination).
learned(r13_liquid_leaves_source).
provenance(r13_liquid_leaves_source, antecedent, a13).
provenance(r13_liquid_leaves_source, parent, a4).
provenance(r13_liquid_leaves_source, simulations, 205).
provenance(r13_liquid_leaves_source, weight_mass_permille, 29307).
provenance(r13_liquid_leaves_source, confidence_permille, 784).
provenance(r13_liquid_leaves_source, score_permille, 761).
provenance(r13_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r13_liquid_leaves_source, direction, particle_mass).
provenance(r13_liquid_leaves_source, sign, down).

rule(r13_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r13_liquid_enters_destination, light_source).
body(r13_liquid_enters_destination, medium_liquid).
body(r13_liquid_enters_destination, pour_mid_height).
body(r13_liquid_enters_destination, pour_near_rim).
body(r13_liquid_enters_destination, pour_steeply_tilted).
body(r13_liquid_enters_destination, slippery_destination).
learned(r13_liquid_enters_destination).
provenance(r13_liquid_enters_destination, antecedent, a13).
provenance(r13_liquid_enters_destination, parent, a4).
provenance(r13_liquid_enters_destination, simulations, 205).
provenance(r13_liquid_enters_destination, weight_mass_permille, 29307).
provenance(r13_liquid_enters_destination, confidence_permille, 662).
provenance(r13_liquid_enters_destination, score_permille, 640).
provenance(r13_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r13_liquid_enters_destination, direction, particle_mass).
provenance(r13_liquid_enters_destination, sign, down).

rule(r13_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r13_liquid_remains_in_destination, light_source).
body(r13_liquid_remains_in_destination, medium_liquid).
body(r13_liquid_remains_in_destination, pour_mid_height).
body(r13_liquid_remains_in_destination, pour_near_rim).
body(r13_liquid_remains_in_destination, pour_steeply_tilted).
body(r13_liquid_remains_in_destination, slippery_destination).
learned(r13_liquid_remains_in_destination).
provenance(r13_liquid_remains_in_destination, antecedent, a13).
provenance(r13_liquid_remains_in_destination, parent, a4).
provenance(r13_liquid_remains_in_destination, simulations, 205).
provenance(r13_liquid_remains_in_destination, weight_mass_permille, 29307).
provenance(r13_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r13_liquid_remains_in_destination, score_permille, 964).
provenance(r13_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r13_liquid_remains_in_destination, direction, particle_mass).
provenance(r13_liquid_remains_in_destination, sign, down).

rule(r13_no_spill, defeasible, no_spill).
body(r13_no_spill, light_source).
body(r13_no_spill, medium_liquid).
body(r13_no_spill, pour_mid_height).
body(r13_no_spill, pour_near_rim).
body(r13_no_spill, pour_steeply_tilted).
body(r13_no_spill, slippery_destination).
learned(r13_no_spill).
provenance(r13_no_spill, antecedent, a13).
provenance(r13_no_spill, parent, a4).
provenance(r13_no_spill, simulations, 205).
provenance(r13_no_spill, weight_mass_permille, 29307).
provenance(r13_no_spill, confidence_permille, 929).
provenance(r13_no_spill, score_permille, 857).
provenance(r13_no_spill, followed, liquid_leaves_source).
provenance(r13_no_spill, direction, particle_mass).
provenance(r13_no_spill, sign, down).

rule(r14_destination_still_approach, defeasible, destination_still_approach).
body(r14_destination_still_approach, light_source).
body(r14_destination_still_approach, little_liquid).
body(r14_destination_still_approach, pour_half_tilted).
body(r14_destination_still_approach, pour_mid_height).
body(r14_destination_still_approach, pour_near_rim).
body(r14_destination_still_approach, slippery_destination).
learned(r14_destination_still_approach).
provenance(r14_destination_still_approach, antecedent, a14).
provenance(r14_destination_still_approach, parent, a9).
provenance(r14_destination_still_approach, simulations, 133).
provenance(r14_destination_still_approach, weight_mass_permille, 35272).
provenance(r14_destination_still_approach, confidence_permille, 1000).
provenance(r14_destination_still_approach, score_permille, 993).
provenance(r14_destination_still_approach, followed, liquid_leaves_source).
provenance(r14_destination_still_approach, direction, pour_pitch).
provenance(r14_destination_still_approach, sign, down).

rule(r14_destination_still_retreat, defeasible, destination_still_retreat).
body(r14_destination_still_retreat, light_source).
body(r14_destination_still_retreat, little_liquid).
body(r14_destination_still_retreat, pour_half_tilted).
body(r14_destination_still_retreat, pour_mid_height).
body(r14_destination_still_retreat, pour_near_rim).
body(r14_destination_still_retreat, slippery_destination).
learned(r14_destination_still_retreat).
provenance(r14_destination_still_retreat, antecedent, a14).
provenance(r14_destination_still_retreat, parent, a9).
provenance(r14_destination_still_retreat, simulations, 133).
provenance(r14_destination_still_retreat, weight_mass_permille, 35272).
provenance(r14_destination_still_retreat, confidence_permille, 1000).
provenance(r14_destination_still_retreat, score_permille, 1000).
provenance(r14_destination_still_retreat, followed, liquid_leaves_source).
provenance(r14_destination_still_retreat, direction, pour_pitch).
provenance(r14_destination_still_retreat, sign, down).

rule(r14_destination_still_settle, defeasible, destination_still_settle).
body(r14_destination_still_settle, light_source).
body(r14_destination_still_settle, little_liquid).
body(r14_destination_still_settle, pour_half_tilted).
body(r14_destination_still_settle, pour_mid_height).
body(r14_destination_still_settle, pour_near_rim).
body(r14_destination_still_settle, slippery_destination).
learned(r14_destination_still_settle).
provenance(r14_destination_still_settle, antecedent, a14).
provenance(r14_destination_still_settle, parent, a9).
provenance(r14_destination_still_settle, simulations, 133).
provenance(r14_destination_still_settle, weight_mass_permille, 35272).
provenance(r14_destination_still_settle, confidence_permille, 1000).
provenance(r14_destination_still_settle, score_permille, 1000).
provenance(r14_destination_still_settle, followed, liquid_leaves_source).
provenance(r14_destination_still_settle, direction, pour_pitch).
provenance(r14_destination_still_settle, sign, down).

rule(r14_destination_upright, defeasible, destination_upright).
body(r14_destination_upright, light_source).
body(r14_destination_upright, little_liquid).
body(r14_destination_upright, pour_half_tilted).
body(r14_destination_upright, pour_mid_height).
body(r14_destination_upright, pour_near_rim).
body(r14_destination_upright, slippery_destination).
learned(r14_destination_upright).
provenance(r14_destination_upright, antecedent, a14).
provenance(r14_destination_upright, parent, a9).
provenance(r14_destination_upright, simulations, 133).
provenance(r14_destination_upright, weight_mass_permille, 35272).
provenance(r14_destination_upright, confidence_permille, 1000).
provenance(r14_destination_upright, score_permille, 1000).
provenance(r14_destination_upright, followed, liquid_leaves_source).
provenance(r14_destination_upright, direction, pour_pitch).
provenance(r14_destination_upright, sign, down).

rule(r14_source_clear, defeasible, source_clear).
body(r14_source_clear, light_source).
body(r14_source_clear, little_liquid).
body(r14_source_clear, pour_half_tilted).
body(r14_source_clear, pour_mid_height).
body(r14_source_clear, pour_near_rim).
body(r14_source_clear, slippery_destination).
learned(r14_source_clear).
provenance(r14_source_clear, antecedent, a14).
provenance(r14_source_clear, parent, a9).
provenance(r14_source_clear, simulations, 133).
provenance(r14_source_clear, weight_mass_permille, 35272).
provenance(r14_source_clear, confidence_permille, 1000).
provenance(r14_source_clear, score_permille, 1000).
provenance(r14_source_clear, followed, liquid_leaves_source).
provenance(r14_source_clear, direction, pour_pitch).
provenance(r14_source_clear, sign, down).

rule(r14_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r14_liquid_leaves_source, light_source).
body(r14_liquid_leaves_source, little_liquid).
body(r14_liquid_leaves_source, pour_half_tilted).
body(r14_liquid_leaves_source, pour_mid_height).
body(r14_liquid_leaves_source, pour_near_rim).
body(r14_liquid_leaves_source, slippery_destination).
learned(r14_liquid_leaves_source).
provenance(r14_liquid_leaves_source, antecedent, a14).
provenance(r14_liquid_leaves_source, parent, a9).
provenance(r14_liquid_leaves_source, simulations, 133).
provenance(r14_liquid_leaves_source, weight_mass_permille, 35272).
provenance(r14_liquid_leaves_source, confidence_permille, 1000).
provenance(r14_liquid_leaves_source, score_permille, 0).
provenance(r14_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r14_liquid_leaves_source, direction, pour_pitch).
provenance(r14_liquid_leaves_source, sign, down).

rule(r14_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r14_liquid_enters_destination, light_source).
body(r14_liquid_enters_destination, little_liquid).
body(r14_liquid_enters_destination, pour_half_tilted).
body(r14_liquid_enters_destination, pour_mid_height).
body(r14_liquid_enters_destination, pour_near_rim).
body(r14_liquid_enters_destination, slippery_destination).
learned(r14_liquid_enters_destination).
provenance(r14_liquid_enters_destination, antecedent, a14).
provenance(r14_liquid_enters_destination, parent, a9).
provenance(r14_liquid_enters_destination, simulations, 133).
provenance(r14_liquid_enters_destination, weight_mass_permille, 35272).
provenance(r14_liquid_enters_destination, confidence_permille, 1000).
provenance(r14_liquid_enters_destination, score_permille, 0).
provenance(r14_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r14_liquid_enters_destination, direction, pour_pitch).
provenance(r14_liquid_enters_destination, sign, down).

rule(r14_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r14_liquid_remains_in_destination, light_source).
body(r14_liquid_remains_in_destination, little_liquid).
body(r14_liquid_remains_in_destination, pour_half_tilted).
body(r14_liquid_remains_in_destination, pour_mid_height).
body(r14_liquid_remains_in_destination, pour_near_rim).
body(r14_liquid_remains_in_destination, slippery_destination).
learned(r14_liquid_remains_in_destination).
provenance(r14_liquid_remains_in_destination, antecedent, a14).
provenance(r14_liquid_remains_in_destination, parent, a9).
provenance(r14_liquid_remains_in_destination, simulations, 133).
provenance(r14_liquid_remains_in_destination, weight_mass_permille, 35272).
provenance(r14_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r14_liquid_remains_in_destination, score_permille, 1000).
provenance(r14_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r14_liquid_remains_in_destination, direction, pour_pitch).
provenance(r14_liquid_remains_in_destination, sign, down).

rule(r14_no_spill, defeasible, no_spill).
body(r14_no_spill, light_source).
body(r14_no_spill, little_liquid).
body(r14_no_spill, pour_half_tilted).
body(r14_no_spill, pour_mid_height).
body(r14_no_spill, pour_near_rim).
body(r14_no_spill, slippery_destination).
learned(r14_no_spill).
provenance(r14_no_spill, antecedent, a14).
provenance(r14_no_spill, parent, a9).
provenance(r14_no_spill, simulations, 133).
provenance(r14_no_spill, weight_mass_permille, 35272).
provenance(r14_no_spill, confidence_permille, 1000).
provenance(r14_no_spill, score_permille, 1000).
provenance(r14_no_spill, followed, liquid_leaves_source).
provenance(r14_no_spill, direction, pour_pitch).
provenance(r14_no_spill, sign, down).

rule(r15_destination_still_approach, defeasible, destination_still_approach).
body(r15_destination_still_approach, light_liquid).
body(r15_destination_still_approach, light_source).
body(r15_destination_still_approach, little_liquid).
body(r15_destination_still_approach, pour_mid_height).
body(r15_destination_still_approach, pour_near_rim).
body(r15_destination_still_approach, pour_steeply_tilted).
body(r15_destination_still_approach, slippery_destination).
learned(r15_destination_still_approach).
provenance(r15_destination_still_approach, antecedent, a15).
provenance(r15_destination_still_approach, parent, a9).
provenance(r15_destination_still_approach, simulations, 66).
provenance(r15_destination_still_approach, weight_mass_permille, 29251).
provenance(r15_destination_still_approach, confidence_permille, 1000).
provenance(r15_destination_still_approach, score_permille, 993).
provenance(r15_destination_still_approach, followed, liquid_leaves_source).
provenance(r15_destination_still_approach, direction, particle_mass).
provenance(r15_destination_still_approach, sign, down).

rule(r15_destination_still_retreat, defeasible, destination_still_retreat).
body(r15_destination_still_retreat, light_liquid).
body(r15_destination_still_retreat, light_source).
body(r15_destination_still_retreat, little_liquid).
body(r15_destination_still_retreat, pour_mid_height).
body(r15_destination_still_retreat, pour_near_rim).
body(r15_destination_still_retreat, pour_steeply_tilted).
body(r15_destination_still_retreat, slippery_destination).
learned(r15_destination_still_retreat).
provenance(r15_destination_still_retreat, antecedent, a15).
provenance(r15_destination_still_retreat, parent, a9).
provenance(r15_destination_still_retreat, simulations, 66).
provenance(r15_destination_still_retreat, weight_mass_permille, 29251).
provenance(r15_destination_still_retreat, confidence_permille, 1000).
provenance(r15_destination_still_retreat, score_permille, 999).
provenance(r15_destination_still_retreat, followed, liquid_leaves_source).
provenance(r15_destination_still_retreat, direction, particle_mass).
provenance(r15_destination_still_retreat, sign, down).

rule(r15_destination_still_settle, defeasible, destination_still_settle).
body(r15_destination_still_settle, light_liquid).
body(r15_destination_still_settle, light_source).
body(r15_destination_still_settle, little_liquid).
body(r15_destination_still_settle, pour_mid_height).
body(r15_destination_still_settle, pour_near_rim).
body(r15_destination_still_settle, pour_steeply_tilted).
body(r15_destination_still_settle, slippery_destination).
learned(r15_destination_still_settle).
provenance(r15_destination_still_settle, antecedent, a15).
provenance(r15_destination_still_settle, parent, a9).
provenance(r15_destination_still_settle, simulations, 66).
provenance(r15_destination_still_settle, weight_mass_permille, 29251).
provenance(r15_destination_still_settle, confidence_permille, 1000).
provenance(r15_destination_still_settle, score_permille, 1000).
provenance(r15_destination_still_settle, followed, liquid_leaves_source).
provenance(r15_destination_still_settle, direction, particle_mass).
provenance(r15_destination_still_settle, sign, down).

rule(r15_destination_upright, defeasible, destination_upright).
body(r15_destination_upright, light_liquid).
body(r15_destination_upright, light_source).
body(r15_destination_upright, little_liquid).
body(r15_destination_upright, pour_mid_height).
body(r15_destination_upright, pour_near_rim).
body(r15_destination_upright, pour_steeply_tilted).
body(r15_destination_upright, slippery_destination).
learned(r15_destination_upright).
provenance(r15_destination_upright, antecedent, a15).
provenance(r15_destination_upright, parent, a9).
provenance(r15_destination_upright, simulations, 66).
provenance(r15_destination_upright, weight_mass_permille, 29251).
provenance(r15_destination_upright, confidence_permille, 1000).
provenance(r15_destination_upright, score_permille, 1000).
provenance(r15_destination_upright, followed, liquid_leaves_source).
provenance(r15_destination_upright, direction, particle_mass).
provenance(r15_destination_upright, sign, down).

rule(r15_source_clear, defeasible, source_clear).
body(r15_source_clear, light_liquid).
body(r15_source_clear, light_source).
body(r15_source_clear, little_liquid).
body(r15_source_clear, pour_mid_height).
body(r15_source_clear, pour_near_rim).
body(r15_source_clear, pour_steeply_tilted).
body(r15_source_clear, slippery_destination).
learned(r15_source_clear).
provenance(r15_source_clear, antecedent, a15).
provenance(r15_source_clear, parent, a9).
provenance(r15_source_clear, simulations, 66).
provenance(r15_source_clear, weight_mass_permille, 29251).
provenance(r15_source_clear, confidence_permille, 1000).
provenance(r15_source_clear, score_permille, 1000).
provenance(r15_source_clear, followed, liquid_leaves_source).
provenance(r15_source_clear, direction, particle_mass).
provenance(r15_source_clear, sign, down).

rule(r15_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r15_liquid_leaves_source, light_liquid).
body(r15_liquid_leaves_source, light_source).
body(r15_liquid_leaves_source, little_liquid).
body(r15_liquid_leaves_source, pour_mid_height).
body(r15_liquid_leaves_source, pour_near_rim).
body(r15_liquid_leaves_source, pour_steeply_tilted).
body(r15_liquid_leaves_source, slippery_destination).
learned(r15_liquid_leaves_source).
provenance(r15_liquid_leaves_source, antecedent, a15).
provenance(r15_liquid_leaves_source, parent, a9).
provenance(r15_liquid_leaves_source, simulations, 66).
provenance(r15_liquid_leaves_source, weight_mass_permille, 29251).
provenance(r15_liquid_leaves_source, confidence_permille, 616).
provenance(r15_liquid_leaves_source, score_permille, 593).
provenance(r15_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r15_liquid_leaves_source, direction, particle_mass).
provenance(r15_liquid_leaves_source, sign, down).

rule(r15_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r15_liquid_enters_destination, light_liquid).
body(r15_liquid_enters_destination, light_source).
body(r15_liquid_enters_destination, little_liquid).
body(r15_liquid_enters_destination, pour_mid_height).
body(r15_liquid_enters_destination, pour_near_rim).
body(r15_liquid_enters_destination, pour_steeply_tilted).
body(r15_liquid_enters_destination, slippery_destination).
learned(r15_liquid_enters_destination).
provenance(r15_liquid_enters_destination, antecedent, a15).
provenance(r15_liquid_enters_destination, parent, a9).
provenance(r15_liquid_enters_destination, simulations, 66).
provenance(r15_liquid_enters_destination, weight_mass_permille, 29251).
provenance(r15_liquid_enters_destination, confidence_permille, 554).
provenance(r15_liquid_enters_destination, score_permille, 547).
provenance(r15_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r15_liquid_enters_destination, direction, particle_mass).
provenance(r15_liquid_enters_destination, sign, down).

rule(r15_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r15_liquid_remains_in_destination, light_liquid).
body(r15_liquid_remains_in_destination, light_source).
body(r15_liquid_remains_in_destination, little_liquid).
body(r15_liquid_remains_in_destination, pour_mid_height).
body(r15_liquid_remains_in_destination, pour_near_rim).
body(r15_liquid_remains_in_destination, pour_steeply_tilted).
body(r15_liquid_remains_in_destination, slippery_destination).
learned(r15_liquid_remains_in_destination).
provenance(r15_liquid_remains_in_destination, antecedent, a15).
provenance(r15_liquid_remains_in_destination, parent, a9).
provenance(r15_liquid_remains_in_destination, simulations, 66).
provenance(r15_liquid_remains_in_destination, weight_mass_permille, 29251).
provenance(r15_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r15_liquid_remains_in_destination, score_permille, 992).
provenance(r15_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r15_liquid_remains_in_destination, direction, particle_mass).
provenance(r15_liquid_remains_in_destination, sign, down).

rule(r15_no_spill, defeasible, no_spill).
body(r15_no_spill, light_liquid).
body(r15_no_spill, light_source).
body(r15_no_spill, little_liquid).
body(r15_no_spill, pour_mid_height).
body(r15_no_spill, pour_near_rim).
body(r15_no_spill, pour_steeply_tilted).
body(r15_no_spill, slippery_destination).
learned(r15_no_spill).
provenance(r15_no_spill, antecedent, a15).
provenance(r15_no_spill, parent, a9).
provenance(r15_no_spill, simulations, 66).
provenance(r15_no_spill, weight_mass_permille, 29251).
provenance(r15_no_spill, confidence_permille, 967).
provenance(r15_no_spill, score_permille, 946).
provenance(r15_no_spill, followed, liquid_leaves_source).
provenance(r15_no_spill, direction, particle_mass).
provenance(r15_no_spill, sign, down).

rule(r16_destination_still_approach, defeasible, destination_still_approach).
body(r16_destination_still_approach, light_source).
body(r16_destination_still_approach, little_liquid).
body(r16_destination_still_approach, medium_liquid).
body(r16_destination_still_approach, pour_mid_height).
body(r16_destination_still_approach, pour_near_rim).
body(r16_destination_still_approach, pour_steeply_tilted).
body(r16_destination_still_approach, slippery_destination).
learned(r16_destination_still_approach).
provenance(r16_destination_still_approach, antecedent, a16).
provenance(r16_destination_still_approach, parent, a9).
provenance(r16_destination_still_approach, simulations, 168).
provenance(r16_destination_still_approach, weight_mass_permille, 31936).
provenance(r16_destination_still_approach, confidence_permille, 992).
provenance(r16_destination_still_approach, score_permille, 986).
provenance(r16_destination_still_approach, followed, liquid_leaves_source).
provenance(r16_destination_still_approach, direction, particle_mass).
provenance(r16_destination_still_approach, sign, down).

rule(r16_destination_still_retreat, defeasible, destination_still_retreat).
body(r16_destination_still_retreat, light_source).
body(r16_destination_still_retreat, little_liquid).
body(r16_destination_still_retreat, medium_liquid).
body(r16_destination_still_retreat, pour_mid_height).
body(r16_destination_still_retreat, pour_near_rim).
body(r16_destination_still_retreat, pour_steeply_tilted).
body(r16_destination_still_retreat, slippery_destination).
learned(r16_destination_still_retreat).
provenance(r16_destination_still_retreat, antecedent, a16).
provenance(r16_destination_still_retreat, parent, a9).
provenance(r16_destination_still_retreat, simulations, 168).
provenance(r16_destination_still_retreat, weight_mass_permille, 31936).
provenance(r16_destination_still_retreat, confidence_permille, 986).
provenance(r16_destination_still_retreat, score_permille, 982).
provenance(r16_destination_still_retreat, followed, liquid_leaves_source).
provenance(r16_destination_still_retreat, direction, particle_mass).
provenance(r16_destination_still_retreat, sign, down).

rule(r16_destination_still_settle, defeasible, destination_still_settle).
body(r16_destination_still_settle, light_source).
body(r16_destination_still_settle, little_liquid).
body(r16_destination_still_settle, medium_liquid).
body(r16_destination_still_settle, pour_mid_height).
body(r16_destination_still_settle, pour_near_rim).
body(r16_destination_still_settle, pour_steeply_tilted).
body(r16_destination_still_settle, slippery_destination).
learned(r16_destination_still_settle).
provenance(r16_destination_still_settle, antecedent, a16).
provenance(r16_destination_still_settle, parent, a9).
provenance(r16_destination_still_settle, simulations, 168).
provenance(r16_destination_still_settle, weight_mass_permille, 31936).
provenance(r16_destination_still_settle, confidence_permille, 1000).
provenance(r16_destination_still_settle, score_permille, 999).
provenance(r16_destination_still_settle, followed, liquid_leaves_source).
provenance(r16_destination_still_settle, direction, particle_mass).
provenance(r16_destination_still_settle, sign, down).

rule(r16_destination_upright, defeasible, destination_upright).
body(r16_destination_upright, light_source).
body(r16_destination_upright, little_liquid).
body(r16_destination_upright, medium_liquid).
body(r16_destination_upright, pour_mid_height).
body(r16_destination_upright, pour_near_rim).
body(r16_destination_upright, pour_steeply_tilted).
body(r16_destination_upright, slippery_destination).
learned(r16_destination_upright).
provenance(r16_destination_upright, antecedent, a16).
provenance(r16_destination_upright, parent, a9).
provenance(r16_destination_upright, simulations, 168).
provenance(r16_destination_upright, weight_mass_permille, 31936).
provenance(r16_destination_upright, confidence_permille, 1000).
provenance(r16_destination_upright, score_permille, 999).
provenance(r16_destination_upright, followed, liquid_leaves_source).
provenance(r16_destination_upright, direction, particle_mass).
provenance(r16_destination_upright, sign, down).

rule(r16_source_clear, defeasible, source_clear).
body(r16_source_clear, light_source).
body(r16_source_clear, little_liquid).
body(r16_source_clear, medium_liquid).
body(r16_source_clear, pour_mid_height).
body(r16_source_clear, pour_near_rim).
body(r16_source_clear, pour_steeply_tilted).
body(r16_source_clear, slippery_destination).
learned(r16_source_clear).
provenance(r16_source_clear, antecedent, a16).
provenance(r16_source_clear, parent, a9).
provenance(r16_source_clear, simulations, 168).
provenance(r16_source_clear, weight_mass_permille, 31936).
provenance(r16_source_clear, confidence_permille, 1000).
provenance(r16_source_clear, score_permille, 990).
provenance(r16_source_clear, followed, liquid_leaves_source).
provenance(r16_source_clear, direction, particle_mass).
provenance(r16_source_clear, sign, down).

rule(r16_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r16_liquid_leaves_source, light_source).
body(r16_liquid_leaves_source, little_liquid).
body(r16_liquid_leaves_source, medium_liquid).
body(r16_liquid_leaves_source, pour_mid_height).
body(r16_liquid_leaves_source, pour_near_rim).
body(r16_liquid_leaves_source, pour_steeply_tilted).
body(r16_liquid_leaves_source, slippery_destination).
learned(r16_liquid_leaves_source).
provenance(r16_liquid_leaves_source, antecedent, a16).
provenance(r16_liquid_leaves_source, parent, a9).
provenance(r16_liquid_leaves_source, simulations, 168).
provenance(r16_liquid_leaves_source, weight_mass_permille, 31936).
provenance(r16_liquid_leaves_source, confidence_permille, 715).
provenance(r16_liquid_leaves_source, score_permille, 708).
provenance(r16_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r16_liquid_leaves_source, direction, particle_mass).
provenance(r16_liquid_leaves_source, sign, down).

rule(r16_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r16_liquid_enters_destination, light_source).
body(r16_liquid_enters_destination, little_liquid).
body(r16_liquid_enters_destination, medium_liquid).
body(r16_liquid_enters_destination, pour_mid_height).
body(r16_liquid_enters_destination, pour_near_rim).
body(r16_liquid_enters_destination, pour_steeply_tilted).
body(r16_liquid_enters_destination, slippery_destination).
learned(r16_liquid_enters_destination).
provenance(r16_liquid_enters_destination, antecedent, a16).
provenance(r16_liquid_enters_destination, parent, a9).
provenance(r16_liquid_enters_destination, simulations, 168).
provenance(r16_liquid_enters_destination, weight_mass_permille, 31936).
provenance(r16_liquid_enters_destination, confidence_permille, 705).
provenance(r16_liquid_enters_destination, score_permille, 669).
provenance(r16_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r16_liquid_enters_destination, direction, particle_mass).
provenance(r16_liquid_enters_destination, sign, down).

rule(r16_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r16_liquid_remains_in_destination, light_source).
body(r16_liquid_remains_in_destination, little_liquid).
body(r16_liquid_remains_in_destination, medium_liquid).
body(r16_liquid_remains_in_destination, pour_mid_height).
body(r16_liquid_remains_in_destination, pour_near_rim).
body(r16_liquid_remains_in_destination, pour_steeply_tilted).
body(r16_liquid_remains_in_destination, slippery_destination).
learned(r16_liquid_remains_in_destination).
provenance(r16_liquid_remains_in_destination, antecedent, a16).
provenance(r16_liquid_remains_in_destination, parent, a9).
provenance(r16_liquid_remains_in_destination, simulations, 168).
provenance(r16_liquid_remains_in_destination, weight_mass_permille, 31936).
provenance(r16_liquid_remains_in_destination, confidence_permille, 997).
provenance(r16_liquid_remains_in_destination, score_permille, 988).
provenance(r16_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r16_liquid_remains_in_destination, direction, particle_mass).
provenance(r16_liquid_remains_in_destination, sign, down).

rule(r16_no_spill, defeasible, no_spill).
body(r16_no_spill, light_source).
body(r16_no_spill, little_liquid).
body(r16_no_spill, medium_liquid).
body(r16_no_spill, pour_mid_height).
body(r16_no_spill, pour_near_rim).
body(r16_no_spill, pour_steeply_tilted).
body(r16_no_spill, slippery_destination).
learned(r16_no_spill).
provenance(r16_no_spill, antecedent, a16).
provenance(r16_no_spill, parent, a9).
provenance(r16_no_spill, simulations, 168).
provenance(r16_no_spill, weight_mass_permille, 31936).
provenance(r16_no_spill, confidence_permille, 993).
provenance(r16_no_spill, score_permille, 950).
provenance(r16_no_spill, followed, liquid_leaves_source).
provenance(r16_no_spill, direction, particle_mass).
provenance(r16_no_spill, sign, down).

rule(r17_destination_still_approach, defeasible, destination_still_approach).
body(r17_destination_still_approach, light_liquid).
body(r17_destination_still_approach, light_source).
body(r17_destination_still_approach, little_liquid).
body(r17_destination_still_approach, pour_half_tilted).
body(r17_destination_still_approach, pour_mid_height).
body(r17_destination_still_approach, pour_near_rim).
body(r17_destination_still_approach, slippery_destination).
learned(r17_destination_still_approach).
provenance(r17_destination_still_approach, antecedent, a17).
provenance(r17_destination_still_approach, parent, a15).
provenance(r17_destination_still_approach, simulations, 38).
provenance(r17_destination_still_approach, weight_mass_permille, 31942).
provenance(r17_destination_still_approach, confidence_permille, 1000).
provenance(r17_destination_still_approach, score_permille, 993).
provenance(r17_destination_still_approach, followed, liquid_leaves_source).
provenance(r17_destination_still_approach, direction, pour_pitch).
provenance(r17_destination_still_approach, sign, down).

rule(r17_destination_still_retreat, defeasible, destination_still_retreat).
body(r17_destination_still_retreat, light_liquid).
body(r17_destination_still_retreat, light_source).
body(r17_destination_still_retreat, little_liquid).
body(r17_destination_still_retreat, pour_half_tilted).
body(r17_destination_still_retreat, pour_mid_height).
body(r17_destination_still_retreat, pour_near_rim).
body(r17_destination_still_retreat, slippery_destination).
learned(r17_destination_still_retreat).
provenance(r17_destination_still_retreat, antecedent, a17).
provenance(r17_destination_still_retreat, parent, a15).
provenance(r17_destination_still_retreat, simulations, 38).
provenance(r17_destination_still_retreat, weight_mass_permille, 31942).
provenance(r17_destination_still_retreat, confidence_permille, 1000).
provenance(r17_destination_still_retreat, score_permille, 1000).
provenance(r17_destination_still_retreat, followed, liquid_leaves_source).
provenance(r17_destination_still_retreat, direction, pour_pitch).
provenance(r17_destination_still_retreat, sign, down).

rule(r17_destination_still_settle, defeasible, destination_still_settle).
body(r17_destination_still_settle, light_liquid).
body(r17_destination_still_settle, light_source).
body(r17_destination_still_settle, little_liquid).
body(r17_destination_still_settle, pour_half_tilted).
body(r17_destination_still_settle, pour_mid_height).
body(r17_destination_still_settle, pour_near_rim).
body(r17_destination_still_settle, slippery_destination).
learned(r17_destination_still_settle).
provenance(r17_destination_still_settle, antecedent, a17).
provenance(r17_destination_still_settle, parent, a15).
provenance(r17_destination_still_settle, simulations, 38).
provenance(r17_destination_still_settle, weight_mass_permille, 31942).
provenance(r17_destination_still_settle, confidence_permille, 1000).
provenance(r17_destination_still_settle, score_permille, 1000).
provenance(r17_destination_still_settle, followed, liquid_leaves_source).
provenance(r17_destination_still_settle, direction, pour_pitch).
provenance(r17_destination_still_settle, sign, down).

rule(r17_destination_upright, defeasible, destination_upright).
body(r17_destination_upright, light_liquid).
body(r17_destination_upright, light_source).
body(r17_destination_upright, little_liquid).
body(r17_destination_upright, pour_half_tilted).
body(r17_destination_upright, pour_mid_height).
body(r17_destination_upright, pour_near_rim).
body(r17_destination_upright, slippery_destination).
learned(r17_destination_upright).
provenance(r17_destination_upright, antecedent, a17).
provenance(r17_destination_upright, parent, a15).
provenance(r17_destination_upright, simulations, 38).
provenance(r17_destination_upright, weight_mass_permille, 31942).
provenance(r17_destination_upright, confidence_permille, 1000).
provenance(r17_destination_upright, score_permille, 1000).
provenance(r17_destination_upright, followed, liquid_leaves_source).
provenance(r17_destination_upright, direction, pour_pitch).
provenance(r17_destination_upright, sign, down).

rule(r17_source_clear, defeasible, source_clear).
body(r17_source_clear, light_liquid).
body(r17_source_clear, light_source).
body(r17_source_clear, little_liquid).
body(r17_source_clear, pour_half_tilted).
body(r17_source_clear, pour_mid_height).
body(r17_source_clear, pour_near_rim).
body(r17_source_clear, slippery_destination).
learned(r17_source_clear).
provenance(r17_source_clear, antecedent, a17).
provenance(r17_source_clear, parent, a15).
provenance(r17_source_clear, simulations, 38).
provenance(r17_source_clear, weight_mass_permille, 31942).
provenance(r17_source_clear, confidence_permille, 1000).
provenance(r17_source_clear, score_permille, 1000).
provenance(r17_source_clear, followed, liquid_leaves_source).
provenance(r17_source_clear, direction, pour_pitch).
provenance(r17_source_clear, sign, down).

rule(r17_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r17_liquid_leaves_source, light_liquid).
body(r17_liquid_leaves_source, light_source).
body(r17_liquid_leaves_source, little_liquid).
body(r17_liquid_leaves_source, pour_half_tilted).
body(r17_liquid_leaves_source, pour_mid_height).
body(r17_liquid_leaves_source, pour_near_rim).
body(r17_liquid_leaves_source, slippery_destination).
learned(r17_liquid_leaves_source).
provenance(r17_liquid_leaves_source, antecedent, a17).
provenance(r17_liquid_leaves_source, parent, a15).
provenance(r17_liquid_leaves_source, simulations, 38).
provenance(r17_liquid_leaves_source, weight_mass_permille, 31942).
provenance(r17_liquid_leaves_source, confidence_permille, 1000).
provenance(r17_liquid_leaves_source, score_permille, 0).
provenance(r17_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r17_liquid_leaves_source, direction, pour_pitch).
provenance(r17_liquid_leaves_source, sign, down).

rule(r17_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r17_liquid_enters_destination, light_liquid).
body(r17_liquid_enters_destination, light_source).
body(r17_liquid_enters_destination, little_liquid).
body(r17_liquid_enters_destination, pour_half_tilted).
body(r17_liquid_enters_destination, pour_mid_height).
body(r17_liquid_enters_destination, pour_near_rim).
body(r17_liquid_enters_destination, slippery_destination).
learned(r17_liquid_enters_destination).
provenance(r17_liquid_enters_destination, antecedent, a17).
provenance(r17_liquid_enters_destination, parent, a15).
provenance(r17_liquid_enters_destination, simulations, 38).
provenance(r17_liquid_enters_destination, weight_mass_permille, 31942).
provenance(r17_liquid_enters_destination, confidence_permille, 1000).
provenance(r17_liquid_enters_destination, score_permille, 0).
provenance(r17_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r17_liquid_enters_destination, direction, pour_pitch).
provenance(r17_liquid_enters_destination, sign, down).

rule(r17_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r17_liquid_remains_in_destination, light_liquid).
body(r17_liquid_remains_in_destination, light_source).
body(r17_liquid_remains_in_destination, little_liquid).
body(r17_liquid_remains_in_destination, pour_half_tilted).
body(r17_liquid_remains_in_destination, pour_mid_height).
body(r17_liquid_remains_in_destination, pour_near_rim).
body(r17_liquid_remains_in_destination, slippery_destination).
learned(r17_liquid_remains_in_destination).
provenance(r17_liquid_remains_in_destination, antecedent, a17).
provenance(r17_liquid_remains_in_destination, parent, a15).
provenance(r17_liquid_remains_in_destination, simulations, 38).
provenance(r17_liquid_remains_in_destination, weight_mass_permille, 31942).
provenance(r17_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r17_liquid_remains_in_destination, score_permille, 1000).
provenance(r17_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r17_liquid_remains_in_destination, direction, pour_pitch).
provenance(r17_liquid_remains_in_destination, sign, down).

rule(r17_no_spill, defeasible, no_spill).
body(r17_no_spill, light_liquid).
body(r17_no_spill, light_source).
body(r17_no_spill, little_liquid).
body(r17_no_spill, pour_half_tilted).
body(r17_no_spill, pour_mid_height).
body(r17_no_spill, pour_near_rim).
body(r17_no_spill, slippery_destination).
learned(r17_no_spill).
provenance(r17_no_spill, antecedent, a17).
provenance(r17_no_spill, parent, a15).
provenance(r17_no_spill, simulations, 38).
provenance(r17_no_spill, weight_mass_permille, 31942).
provenance(r17_no_spill, confidence_permille, 1000).
provenance(r17_no_spill, score_permille, 1000).
provenance(r17_no_spill, followed, liquid_leaves_source).
provenance(r17_no_spill, direction, pour_pitch).
provenance(r17_no_spill, sign, down).

rule(r18_destination_still_approach, defeasible, destination_still_approach).
body(r18_destination_still_approach, dull_liquid).
body(r18_destination_still_approach, light_liquid).
body(r18_destination_still_approach, light_source).
body(r18_destination_still_approach, little_liquid).
body(r18_destination_still_approach, pour_mid_height).
body(r18_destination_still_approach, pour_near_rim).
body(r18_destination_still_approach, pour_steeply_tilted).
body(r18_destination_still_approach, slippery_destination).
learned(r18_destination_still_approach).
provenance(r18_destination_still_approach, antecedent, a18).
provenance(r18_destination_still_approach, parent, a15).
provenance(r18_destination_still_approach, simulations, 37).
provenance(r18_destination_still_approach, weight_mass_permille, 31103).
provenance(r18_destination_still_approach, confidence_permille, 1000).
provenance(r18_destination_still_approach, score_permille, 993).
provenance(r18_destination_still_approach, followed, liquid_leaves_source).
provenance(r18_destination_still_approach, direction, particle_restitution).
provenance(r18_destination_still_approach, sign, down).

rule(r18_destination_still_retreat, defeasible, destination_still_retreat).
body(r18_destination_still_retreat, dull_liquid).
body(r18_destination_still_retreat, light_liquid).
body(r18_destination_still_retreat, light_source).
body(r18_destination_still_retreat, little_liquid).
body(r18_destination_still_retreat, pour_mid_height).
body(r18_destination_still_retreat, pour_near_rim).
body(r18_destination_still_retreat, pour_steeply_tilted).
body(r18_destination_still_retreat, slippery_destination).
learned(r18_destination_still_retreat).
provenance(r18_destination_still_retreat, antecedent, a18).
provenance(r18_destination_still_retreat, parent, a15).
provenance(r18_destination_still_retreat, simulations, 37).
provenance(r18_destination_still_retreat, weight_mass_permille, 31103).
provenance(r18_destination_still_retreat, confidence_permille, 1000).
provenance(r18_destination_still_retreat, score_permille, 999).
provenance(r18_destination_still_retreat, followed, liquid_leaves_source).
provenance(r18_destination_still_retreat, direction, particle_restitution).
provenance(r18_destination_still_retreat, sign, down).

rule(r18_destination_still_settle, defeasible, destination_still_settle).
body(r18_destination_still_settle, dull_liquid).
body(r18_destination_still_settle, light_liquid).
body(r18_destination_still_settle, light_source).
body(r18_destination_still_settle, little_liquid).
body(r18_destination_still_settle, pour_mid_height).
body(r18_destination_still_settle, pour_near_rim).
body(r18_destination_still_settle, pour_steeply_tilted).
body(r18_destination_still_settle, slippery_destination).
learned(r18_destination_still_settle).
provenance(r18_destination_still_settle, antecedent, a18).
provenance(r18_destination_still_settle, parent, a15).
provenance(r18_destination_still_settle, simulations, 37).
provenance(r18_destination_still_settle, weight_mass_permille, 31103).
provenance(r18_destination_still_settle, confidence_permille, 1000).
provenance(r18_destination_still_settle, score_permille, 1000).
provenance(r18_destination_still_settle, followed, liquid_leaves_source).
provenance(r18_destination_still_settle, direction, particle_restitution).
provenance(r18_destination_still_settle, sign, down).

rule(r18_destination_upright, defeasible, destination_upright).
body(r18_destination_upright, dull_liquid).
body(r18_destination_upright, light_liquid).
body(r18_destination_upright, light_source).
body(r18_destination_upright, little_liquid).
body(r18_destination_upright, pour_mid_height).
body(r18_destination_upright, pour_near_rim).
body(r18_destination_upright, pour_steeply_tilted).
body(r18_destination_upright, slippery_destination).
learned(r18_destination_upright).
provenance(r18_destination_upright, antecedent, a18).
provenance(r18_destination_upright, parent, a15).
provenance(r18_destination_upright, simulations, 37).
provenance(r18_destination_upright, weight_mass_permille, 31103).
provenance(r18_destination_upright, confidence_permille, 1000).
provenance(r18_destination_upright, score_permille, 1000).
provenance(r18_destination_upright, followed, liquid_leaves_source).
provenance(r18_destination_upright, direction, particle_restitution).
provenance(r18_destination_upright, sign, down).

rule(r18_source_clear, defeasible, source_clear).
body(r18_source_clear, dull_liquid).
body(r18_source_clear, light_liquid).
body(r18_source_clear, light_source).
body(r18_source_clear, little_liquid).
body(r18_source_clear, pour_mid_height).
body(r18_source_clear, pour_near_rim).
body(r18_source_clear, pour_steeply_tilted).
body(r18_source_clear, slippery_destination).
learned(r18_source_clear).
provenance(r18_source_clear, antecedent, a18).
provenance(r18_source_clear, parent, a15).
provenance(r18_source_clear, simulations, 37).
provenance(r18_source_clear, weight_mass_permille, 31103).
provenance(r18_source_clear, confidence_permille, 1000).
provenance(r18_source_clear, score_permille, 1000).
provenance(r18_source_clear, followed, liquid_leaves_source).
provenance(r18_source_clear, direction, particle_restitution).
provenance(r18_source_clear, sign, down).

rule(r18_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r18_liquid_leaves_source, dull_liquid).
body(r18_liquid_leaves_source, light_liquid).
body(r18_liquid_leaves_source, light_source).
body(r18_liquid_leaves_source, little_liquid).
body(r18_liquid_leaves_source, pour_mid_height).
body(r18_liquid_leaves_source, pour_near_rim).
body(r18_liquid_leaves_source, pour_steeply_tilted).
body(r18_liquid_leaves_source, slippery_destination).
learned(r18_liquid_leaves_source).
provenance(r18_liquid_leaves_source, antecedent, a18).
provenance(r18_liquid_leaves_source, parent, a15).
provenance(r18_liquid_leaves_source, simulations, 37).
provenance(r18_liquid_leaves_source, weight_mass_permille, 31103).
provenance(r18_liquid_leaves_source, confidence_permille, 595).
provenance(r18_liquid_leaves_source, score_permille, 611).
provenance(r18_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r18_liquid_leaves_source, direction, particle_restitution).
provenance(r18_liquid_leaves_source, sign, down).

rule(r18_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r18_liquid_enters_destination, dull_liquid).
body(r18_liquid_enters_destination, light_liquid).
body(r18_liquid_enters_destination, light_source).
body(r18_liquid_enters_destination, little_liquid).
body(r18_liquid_enters_destination, pour_mid_height).
body(r18_liquid_enters_destination, pour_near_rim).
body(r18_liquid_enters_destination, pour_steeply_tilted).
body(r18_liquid_enters_destination, slippery_destination).
learned(r18_liquid_enters_destination).
provenance(r18_liquid_enters_destination, antecedent, a18).
provenance(r18_liquid_enters_destination, parent, a15).
provenance(r18_liquid_enters_destination, simulations, 37).
provenance(r18_liquid_enters_destination, weight_mass_permille, 31103).
provenance(r18_liquid_enters_destination, confidence_permille, 568).
provenance(r18_liquid_enters_destination, score_permille, 577).
provenance(r18_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r18_liquid_enters_destination, direction, particle_restitution).
provenance(r18_liquid_enters_destination, sign, down).

rule(r18_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r18_liquid_remains_in_destination, dull_liquid).
body(r18_liquid_remains_in_destination, light_liquid).
body(r18_liquid_remains_in_destination, light_source).
body(r18_liquid_remains_in_destination, little_liquid).
body(r18_liquid_remains_in_destination, pour_mid_height).
body(r18_liquid_remains_in_destination, pour_near_rim).
body(r18_liquid_remains_in_destination, pour_steeply_tilted).
body(r18_liquid_remains_in_destination, slippery_destination).
learned(r18_liquid_remains_in_destination).
provenance(r18_liquid_remains_in_destination, antecedent, a18).
provenance(r18_liquid_remains_in_destination, parent, a15).
provenance(r18_liquid_remains_in_destination, simulations, 37).
provenance(r18_liquid_remains_in_destination, weight_mass_permille, 31103).
provenance(r18_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r18_liquid_remains_in_destination, score_permille, 1000).
provenance(r18_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r18_liquid_remains_in_destination, direction, particle_restitution).
provenance(r18_liquid_remains_in_destination, sign, down).

rule(r18_no_spill, defeasible, no_spill).
body(r18_no_spill, dull_liquid).
body(r18_no_spill, light_liquid).
body(r18_no_spill, light_source).
body(r18_no_spill, little_liquid).
body(r18_no_spill, pour_mid_height).
body(r18_no_spill, pour_near_rim).
body(r18_no_spill, pour_steeply_tilted).
body(r18_no_spill, slippery_destination).
learned(r18_no_spill).
provenance(r18_no_spill, antecedent, a18).
provenance(r18_no_spill, parent, a15).
provenance(r18_no_spill, simulations, 37).
provenance(r18_no_spill, weight_mass_permille, 31103).
provenance(r18_no_spill, confidence_permille, 973).
provenance(r18_no_spill, score_permille, 966).
provenance(r18_no_spill, followed, liquid_leaves_source).
provenance(r18_no_spill, direction, particle_restitution).
provenance(r18_no_spill, sign, down).

rule(r19_destination_still_approach, defeasible, destination_still_approach).
body(r19_destination_still_approach, light_source).
body(r19_destination_still_approach, little_liquid).
body(r19_destination_still_approach, medium_liquid).
body(r19_destination_still_approach, pour_half_tilted).
body(r19_destination_still_approach, pour_mid_height).
body(r19_destination_still_approach, pour_near_rim).
body(r19_destination_still_approach, slippery_destination).
learned(r19_destination_still_approach).
provenance(r19_destination_still_approach, antecedent, a19).
provenance(r19_destination_still_approach, parent, a16).
provenance(r19_destination_still_approach, simulations, 63).
provenance(r19_destination_still_approach, weight_mass_permille, 30537).
provenance(r19_destination_still_approach, confidence_permille, 1000).
provenance(r19_destination_still_approach, score_permille, 993).
provenance(r19_destination_still_approach, followed, liquid_enters_destination).
provenance(r19_destination_still_approach, direction, pour_pitch).
provenance(r19_destination_still_approach, sign, down).

rule(r19_destination_still_retreat, defeasible, destination_still_retreat).
body(r19_destination_still_retreat, light_source).
body(r19_destination_still_retreat, little_liquid).
body(r19_destination_still_retreat, medium_liquid).
body(r19_destination_still_retreat, pour_half_tilted).
body(r19_destination_still_retreat, pour_mid_height).
body(r19_destination_still_retreat, pour_near_rim).
body(r19_destination_still_retreat, slippery_destination).
learned(r19_destination_still_retreat).
provenance(r19_destination_still_retreat, antecedent, a19).
provenance(r19_destination_still_retreat, parent, a16).
provenance(r19_destination_still_retreat, simulations, 63).
provenance(r19_destination_still_retreat, weight_mass_permille, 30537).
provenance(r19_destination_still_retreat, confidence_permille, 1000).
provenance(r19_destination_still_retreat, score_permille, 1000).
provenance(r19_destination_still_retreat, followed, liquid_enters_destination).
provenance(r19_destination_still_retreat, direction, pour_pitch).
provenance(r19_destination_still_retreat, sign, down).

rule(r19_destination_still_settle, defeasible, destination_still_settle).
body(r19_destination_still_settle, light_source).
body(r19_destination_still_settle, little_liquid).
body(r19_destination_still_settle, medium_liquid).
body(r19_destination_still_settle, pour_half_tilted).
body(r19_destination_still_settle, pour_mid_height).
body(r19_destination_still_settle, pour_near_rim).
body(r19_destination_still_settle, slippery_destination).
learned(r19_destination_still_settle).
provenance(r19_destination_still_settle, antecedent, a19).
provenance(r19_destination_still_settle, parent, a16).
provenance(r19_destination_still_settle, simulations, 63).
provenance(r19_destination_still_settle, weight_mass_permille, 30537).
provenance(r19_destination_still_settle, confidence_permille, 1000).
provenance(r19_destination_still_settle, score_permille, 1000).
provenance(r19_destination_still_settle, followed, liquid_enters_destination).
provenance(r19_destination_still_settle, direction, pour_pitch).
provenance(r19_destination_still_settle, sign, down).

rule(r19_destination_upright, defeasible, destination_upright).
body(r19_destination_upright, light_source).
body(r19_destination_upright, little_liquid).
body(r19_destination_upright, medium_liquid).
body(r19_destination_upright, pour_half_tilted).
body(r19_destination_upright, pour_mid_height).
body(r19_destination_upright, pour_near_rim).
body(r19_destination_upright, slippery_destination).
learned(r19_destination_upright).
provenance(r19_destination_upright, antecedent, a19).
provenance(r19_destination_upright, parent, a16).
provenance(r19_destination_upright, simulations, 63).
provenance(r19_destination_upright, weight_mass_permille, 30537).
provenance(r19_destination_upright, confidence_permille, 1000).
provenance(r19_destination_upright, score_permille, 1000).
provenance(r19_destination_upright, followed, liquid_enters_destination).
provenance(r19_destination_upright, direction, pour_pitch).
provenance(r19_destination_upright, sign, down).

rule(r19_source_clear, defeasible, source_clear).
body(r19_source_clear, light_source).
body(r19_source_clear, little_liquid).
body(r19_source_clear, medium_liquid).
body(r19_source_clear, pour_half_tilted).
body(r19_source_clear, pour_mid_height).
body(r19_source_clear, pour_near_rim).
body(r19_source_clear, slippery_destination).
learned(r19_source_clear).
provenance(r19_source_clear, antecedent, a19).
provenance(r19_source_clear, parent, a16).
provenance(r19_source_clear, simulations, 63).
provenance(r19_source_clear, weight_mass_permille, 30537).
provenance(r19_source_clear, confidence_permille, 1000).
provenance(r19_source_clear, score_permille, 1000).
provenance(r19_source_clear, followed, liquid_enters_destination).
provenance(r19_source_clear, direction, pour_pitch).
provenance(r19_source_clear, sign, down).

rule(r19_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r19_liquid_leaves_source, light_source).
body(r19_liquid_leaves_source, little_liquid).
body(r19_liquid_leaves_source, medium_liquid).
body(r19_liquid_leaves_source, pour_half_tilted).
body(r19_liquid_leaves_source, pour_mid_height).
body(r19_liquid_leaves_source, pour_near_rim).
body(r19_liquid_leaves_source, slippery_destination).
learned(r19_liquid_leaves_source).
provenance(r19_liquid_leaves_source, antecedent, a19).
provenance(r19_liquid_leaves_source, parent, a16).
provenance(r19_liquid_leaves_source, simulations, 63).
provenance(r19_liquid_leaves_source, weight_mass_permille, 30537).
provenance(r19_liquid_leaves_source, confidence_permille, 1000).
provenance(r19_liquid_leaves_source, score_permille, 0).
provenance(r19_liquid_leaves_source, followed, liquid_enters_destination).
provenance(r19_liquid_leaves_source, direction, pour_pitch).
provenance(r19_liquid_leaves_source, sign, down).

rule(r19_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r19_liquid_enters_destination, light_source).
body(r19_liquid_enters_destination, little_liquid).
body(r19_liquid_enters_destination, medium_liquid).
body(r19_liquid_enters_destination, pour_half_tilted).
body(r19_liquid_enters_destination, pour_mid_height).
body(r19_liquid_enters_destination, pour_near_rim).
body(r19_liquid_enters_destination, slippery_destination).
learned(r19_liquid_enters_destination).
provenance(r19_liquid_enters_destination, antecedent, a19).
provenance(r19_liquid_enters_destination, parent, a16).
provenance(r19_liquid_enters_destination, simulations, 63).
provenance(r19_liquid_enters_destination, weight_mass_permille, 30537).
provenance(r19_liquid_enters_destination, confidence_permille, 1000).
provenance(r19_liquid_enters_destination, score_permille, 0).
provenance(r19_liquid_enters_destination, followed, liquid_enters_destination).
provenance(r19_liquid_enters_destination, direction, pour_pitch).
provenance(r19_liquid_enters_destination, sign, down).

rule(r19_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r19_liquid_remains_in_destination, light_source).
body(r19_liquid_remains_in_destination, little_liquid).
body(r19_liquid_remains_in_destination, medium_liquid).
body(r19_liquid_remains_in_destination, pour_half_tilted).
body(r19_liquid_remains_in_destination, pour_mid_height).
body(r19_liquid_remains_in_destination, pour_near_rim).
body(r19_liquid_remains_in_destination, slippery_destination).
learned(r19_liquid_remains_in_destination).
provenance(r19_liquid_remains_in_destination, antecedent, a19).
provenance(r19_liquid_remains_in_destination, parent, a16).
provenance(r19_liquid_remains_in_destination, simulations, 63).
provenance(r19_liquid_remains_in_destination, weight_mass_permille, 30537).
provenance(r19_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r19_liquid_remains_in_destination, score_permille, 1000).
provenance(r19_liquid_remains_in_destination, followed, liquid_enters_destination).
provenance(r19_liquid_remains_in_destination, direction, pour_pitch).
provenance(r19_liquid_remains_in_destination, sign, down).

rule(r19_no_spill, defeasible, no_spill).
body(r19_no_spill, light_source).
body(r19_no_spill, little_liquid).
body(r19_no_spill, medium_liquid).
body(r19_no_spill, pour_half_tilted).
body(r19_no_spill, pour_mid_height).
body(r19_no_spill, pour_near_rim).
body(r19_no_spill, slippery_destination).
learned(r19_no_spill).
provenance(r19_no_spill, antecedent, a19).
provenance(r19_no_spill, parent, a16).
provenance(r19_no_spill, simulations, 63).
provenance(r19_no_spill, weight_mass_permille, 30537).
provenance(r19_no_spill, confidence_permille, 1000).
provenance(r19_no_spill, score_permille, 1000).
provenance(r19_no_spill, followed, liquid_enters_destination).
provenance(r19_no_spill, direction, pour_pitch).
provenance(r19_no_spill, sign, down).

rule(r20_destination_still_approach, defeasible, destination_still_approach).
body(r20_destination_still_approach, bouncy_destination).
body(r20_destination_still_approach, light_source).
body(r20_destination_still_approach, little_liquid).
body(r20_destination_still_approach, medium_liquid).
body(r20_destination_still_approach, pour_mid_height).
body(r20_destination_still_approach, pour_near_rim).
body(r20_destination_still_approach, pour_steeply_tilted).
body(r20_destination_still_approach, slippery_destination).
learned(r20_destination_still_approach).
provenance(r20_destination_still_approach, antecedent, a20).
provenance(r20_destination_still_approach, parent, a16).
provenance(r20_destination_still_approach, simulations, 105).
provenance(r20_destination_still_approach, weight_mass_permille, 33017).
provenance(r20_destination_still_approach, confidence_permille, 979).
provenance(r20_destination_still_approach, score_permille, 977).
provenance(r20_destination_still_approach, followed, liquid_enters_destination).
provenance(r20_destination_still_approach, direction, destination_restitution).
provenance(r20_destination_still_approach, sign, up).

rule(r20_destination_still_retreat, defeasible, destination_still_retreat).
body(r20_destination_still_retreat, bouncy_destination).
body(r20_destination_still_retreat, light_source).
body(r20_destination_still_retreat, little_liquid).
body(r20_destination_still_retreat, medium_liquid).
body(r20_destination_still_retreat, pour_mid_height).
body(r20_destination_still_retreat, pour_near_rim).
body(r20_destination_still_retreat, pour_steeply_tilted).
body(r20_destination_still_retreat, slippery_destination).
learned(r20_destination_still_retreat).
provenance(r20_destination_still_retreat, antecedent, a20).
provenance(r20_destination_still_retreat, parent, a16).
provenance(r20_destination_still_retreat, simulations, 105).
provenance(r20_destination_still_retreat, weight_mass_permille, 33017).
provenance(r20_destination_still_retreat, confidence_permille, 986).
provenance(r20_destination_still_retreat, score_permille, 978).
provenance(r20_destination_still_retreat, followed, liquid_enters_destination).
provenance(r20_destination_still_retreat, direction, destination_restitution).
provenance(r20_destination_still_retreat, sign, up).

rule(r20_destination_still_settle, defeasible, destination_still_settle).
body(r20_destination_still_settle, bouncy_destination).
body(r20_destination_still_settle, light_source).
body(r20_destination_still_settle, little_liquid).
body(r20_destination_still_settle, medium_liquid).
body(r20_destination_still_settle, pour_mid_height).
body(r20_destination_still_settle, pour_near_rim).
body(r20_destination_still_settle, pour_steeply_tilted).
body(r20_destination_still_settle, slippery_destination).
learned(r20_destination_still_settle).
provenance(r20_destination_still_settle, antecedent, a20).
provenance(r20_destination_still_settle, parent, a16).
provenance(r20_destination_still_settle, simulations, 105).
provenance(r20_destination_still_settle, weight_mass_permille, 33017).
provenance(r20_destination_still_settle, confidence_permille, 1000).
provenance(r20_destination_still_settle, score_permille, 1000).
provenance(r20_destination_still_settle, followed, liquid_enters_destination).
provenance(r20_destination_still_settle, direction, destination_restitution).
provenance(r20_destination_still_settle, sign, up).

rule(r20_destination_upright, defeasible, destination_upright).
body(r20_destination_upright, bouncy_destination).
body(r20_destination_upright, light_source).
body(r20_destination_upright, little_liquid).
body(r20_destination_upright, medium_liquid).
body(r20_destination_upright, pour_mid_height).
body(r20_destination_upright, pour_near_rim).
body(r20_destination_upright, pour_steeply_tilted).
body(r20_destination_upright, slippery_destination).
learned(r20_destination_upright).
provenance(r20_destination_upright, antecedent, a20).
provenance(r20_destination_upright, parent, a16).
provenance(r20_destination_upright, simulations, 105).
provenance(r20_destination_upright, weight_mass_permille, 33017).
provenance(r20_destination_upright, confidence_permille, 1000).
provenance(r20_destination_upright, score_permille, 999).
provenance(r20_destination_upright, followed, liquid_enters_destination).
provenance(r20_destination_upright, direction, destination_restitution).
provenance(r20_destination_upright, sign, up).

rule(r20_source_clear, defeasible, source_clear).
body(r20_source_clear, bouncy_destination).
body(r20_source_clear, light_source).
body(r20_source_clear, little_liquid).
body(r20_source_clear, medium_liquid).
body(r20_source_clear, pour_mid_height).
body(r20_source_clear, pour_near_rim).
body(r20_source_clear, pour_steeply_tilted).
body(r20_source_clear, slippery_destination).
learned(r20_source_clear).
provenance(r20_source_clear, antecedent, a20).
provenance(r20_source_clear, parent, a16).
provenance(r20_source_clear, simulations, 105).
provenance(r20_source_clear, weight_mass_permille, 33017).
provenance(r20_source_clear, confidence_permille, 1000).
provenance(r20_source_clear, score_permille, 999).
provenance(r20_source_clear, followed, liquid_enters_destination).
provenance(r20_source_clear, direction, destination_restitution).
provenance(r20_source_clear, sign, up).

rule(r20_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r20_liquid_leaves_source, bouncy_destination).
body(r20_liquid_leaves_source, light_source).
body(r20_liquid_leaves_source, little_liquid).
body(r20_liquid_leaves_source, medium_liquid).
body(r20_liquid_leaves_source, pour_mid_height).
body(r20_liquid_leaves_source, pour_near_rim).
body(r20_liquid_leaves_source, pour_steeply_tilted).
body(r20_liquid_leaves_source, slippery_destination).
learned(r20_liquid_leaves_source).
provenance(r20_liquid_leaves_source, antecedent, a20).
provenance(r20_liquid_leaves_source, parent, a16).
provenance(r20_liquid_leaves_source, simulations, 105).
provenance(r20_liquid_leaves_source, weight_mass_permille, 33017).
provenance(r20_liquid_leaves_source, confidence_permille, 642).
provenance(r20_liquid_leaves_source, score_permille, 638).
provenance(r20_liquid_leaves_source, followed, liquid_enters_destination).
provenance(r20_liquid_leaves_source, direction, destination_restitution).
provenance(r20_liquid_leaves_source, sign, up).

rule(r20_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r20_liquid_enters_destination, bouncy_destination).
body(r20_liquid_enters_destination, light_source).
body(r20_liquid_enters_destination, little_liquid).
body(r20_liquid_enters_destination, medium_liquid).
body(r20_liquid_enters_destination, pour_mid_height).
body(r20_liquid_enters_destination, pour_near_rim).
body(r20_liquid_enters_destination, pour_steeply_tilted).
body(r20_liquid_enters_destination, slippery_destination).
learned(r20_liquid_enters_destination).
provenance(r20_liquid_enters_destination, antecedent, a20).
provenance(r20_liquid_enters_destination, parent, a16).
provenance(r20_liquid_enters_destination, simulations, 105).
provenance(r20_liquid_enters_destination, weight_mass_permille, 33017).
provenance(r20_liquid_enters_destination, confidence_permille, 627).
provenance(r20_liquid_enters_destination, score_permille, 603).
provenance(r20_liquid_enters_destination, followed, liquid_enters_destination).
provenance(r20_liquid_enters_destination, direction, destination_restitution).
provenance(r20_liquid_enters_destination, sign, up).

rule(r20_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r20_liquid_remains_in_destination, bouncy_destination).
body(r20_liquid_remains_in_destination, light_source).
body(r20_liquid_remains_in_destination, little_liquid).
body(r20_liquid_remains_in_destination, medium_liquid).
body(r20_liquid_remains_in_destination, pour_mid_height).
body(r20_liquid_remains_in_destination, pour_near_rim).
body(r20_liquid_remains_in_destination, pour_steeply_tilted).
body(r20_liquid_remains_in_destination, slippery_destination).
learned(r20_liquid_remains_in_destination).
provenance(r20_liquid_remains_in_destination, antecedent, a20).
provenance(r20_liquid_remains_in_destination, parent, a16).
provenance(r20_liquid_remains_in_destination, simulations, 105).
provenance(r20_liquid_remains_in_destination, weight_mass_permille, 33017).
provenance(r20_liquid_remains_in_destination, confidence_permille, 993).
provenance(r20_liquid_remains_in_destination, score_permille, 984).
provenance(r20_liquid_remains_in_destination, followed, liquid_enters_destination).
provenance(r20_liquid_remains_in_destination, direction, destination_restitution).
provenance(r20_liquid_remains_in_destination, sign, up).

rule(r20_no_spill, defeasible, no_spill).
body(r20_no_spill, bouncy_destination).
body(r20_no_spill, light_source).
body(r20_no_spill, little_liquid).
body(r20_no_spill, medium_liquid).
body(r20_no_spill, pour_mid_height).
body(r20_no_spill, pour_near_rim).
body(r20_no_spill, pour_steeply_tilted).
body(r20_no_spill, slippery_destination).
learned(r20_no_spill).
provenance(r20_no_spill, antecedent, a20).
provenance(r20_no_spill, parent, a16).
provenance(r20_no_spill, simulations, 105).
provenance(r20_no_spill, weight_mass_permille, 33017).
provenance(r20_no_spill, confidence_permille, 983).
provenance(r20_no_spill, score_permille, 951).
provenance(r20_no_spill, followed, liquid_enters_destination).
provenance(r20_no_spill, direction, destination_restitution).
provenance(r20_no_spill, sign, up).

rule(r21_destination_still_approach, defeasible, destination_still_approach).
body(r21_destination_still_approach, fast_approach).
body(r21_destination_still_approach, light_source).
body(r21_destination_still_approach, little_liquid).
body(r21_destination_still_approach, medium_liquid).
body(r21_destination_still_approach, pour_mid_height).
body(r21_destination_still_approach, pour_near_rim).
body(r21_destination_still_approach, pour_steeply_tilted).
body(r21_destination_still_approach, slippery_destination).
learned(r21_destination_still_approach).
provenance(r21_destination_still_approach, antecedent, a21).
provenance(r21_destination_still_approach, parent, a16).
provenance(r21_destination_still_approach, simulations, 46).
provenance(r21_destination_still_approach, weight_mass_permille, 30380).
provenance(r21_destination_still_approach, confidence_permille, 1000).
provenance(r21_destination_still_approach, score_permille, 993).
provenance(r21_destination_still_approach, followed, liquid_enters_destination).
provenance(r21_destination_still_approach, direction, approach_duration).
provenance(r21_destination_still_approach, sign, down).

rule(r21_destination_still_retreat, defeasible, destination_still_retreat).
body(r21_destination_still_retreat, fast_approach).
body(r21_destination_still_retreat, light_source).
body(r21_destination_still_retreat, little_liquid).
body(r21_destination_still_retreat, medium_liquid).
body(r21_destination_still_retreat, pour_mid_height).
body(r21_destination_still_retreat, pour_near_rim).
body(r21_destination_still_retreat, pour_steeply_tilted).
body(r21_destination_still_retreat, slippery_destination).
learned(r21_destination_still_retreat).
provenance(r21_destination_still_retreat, antecedent, a21).
provenance(r21_destination_still_retreat, parent, a16).
provenance(r21_destination_still_retreat, simulations, 46).
provenance(r21_destination_still_retreat, weight_mass_permille, 30380).
provenance(r21_destination_still_retreat, confidence_permille, 926).
provenance(r21_destination_still_retreat, score_permille, 931).
provenance(r21_destination_still_retreat, followed, liquid_enters_destination).
provenance(r21_destination_still_retreat, direction, approach_duration).
provenance(r21_destination_still_retreat, sign, down).

rule(r21_destination_still_settle, defeasible, destination_still_settle).
body(r21_destination_still_settle, fast_approach).
body(r21_destination_still_settle, light_source).
body(r21_destination_still_settle, little_liquid).
body(r21_destination_still_settle, medium_liquid).
body(r21_destination_still_settle, pour_mid_height).
body(r21_destination_still_settle, pour_near_rim).
body(r21_destination_still_settle, pour_steeply_tilted).
body(r21_destination_still_settle, slippery_destination).
learned(r21_destination_still_settle).
provenance(r21_destination_still_settle, antecedent, a21).
provenance(r21_destination_still_settle, parent, a16).
provenance(r21_destination_still_settle, simulations, 46).
provenance(r21_destination_still_settle, weight_mass_permille, 30380).
provenance(r21_destination_still_settle, confidence_permille, 1000).
provenance(r21_destination_still_settle, score_permille, 999).
provenance(r21_destination_still_settle, followed, liquid_enters_destination).
provenance(r21_destination_still_settle, direction, approach_duration).
provenance(r21_destination_still_settle, sign, down).

rule(r21_destination_upright, defeasible, destination_upright).
body(r21_destination_upright, fast_approach).
body(r21_destination_upright, light_source).
body(r21_destination_upright, little_liquid).
body(r21_destination_upright, medium_liquid).
body(r21_destination_upright, pour_mid_height).
body(r21_destination_upright, pour_near_rim).
body(r21_destination_upright, pour_steeply_tilted).
body(r21_destination_upright, slippery_destination).
learned(r21_destination_upright).
provenance(r21_destination_upright, antecedent, a21).
provenance(r21_destination_upright, parent, a16).
provenance(r21_destination_upright, simulations, 46).
provenance(r21_destination_upright, weight_mass_permille, 30380).
provenance(r21_destination_upright, confidence_permille, 1000).
provenance(r21_destination_upright, score_permille, 995).
provenance(r21_destination_upright, followed, liquid_enters_destination).
provenance(r21_destination_upright, direction, approach_duration).
provenance(r21_destination_upright, sign, down).

rule(r21_source_clear, defeasible, source_clear).
body(r21_source_clear, fast_approach).
body(r21_source_clear, light_source).
body(r21_source_clear, little_liquid).
body(r21_source_clear, medium_liquid).
body(r21_source_clear, pour_mid_height).
body(r21_source_clear, pour_near_rim).
body(r21_source_clear, pour_steeply_tilted).
body(r21_source_clear, slippery_destination).
learned(r21_source_clear).
provenance(r21_source_clear, antecedent, a21).
provenance(r21_source_clear, parent, a16).
provenance(r21_source_clear, simulations, 46).
provenance(r21_source_clear, weight_mass_permille, 30380).
provenance(r21_source_clear, confidence_permille, 1000).
provenance(r21_source_clear, score_permille, 998).
provenance(r21_source_clear, followed, liquid_enters_destination).
provenance(r21_source_clear, direction, approach_duration).
provenance(r21_source_clear, sign, down).

rule(r21_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r21_liquid_leaves_source, fast_approach).
body(r21_liquid_leaves_source, light_source).
body(r21_liquid_leaves_source, little_liquid).
body(r21_liquid_leaves_source, medium_liquid).
body(r21_liquid_leaves_source, pour_mid_height).
body(r21_liquid_leaves_source, pour_near_rim).
body(r21_liquid_leaves_source, pour_steeply_tilted).
body(r21_liquid_leaves_source, slippery_destination).
learned(r21_liquid_leaves_source).
provenance(r21_liquid_leaves_source, antecedent, a21).
provenance(r21_liquid_leaves_source, parent, a16).
provenance(r21_liquid_leaves_source, simulations, 46).
provenance(r21_liquid_leaves_source, weight_mass_permille, 30380).
provenance(r21_liquid_leaves_source, confidence_permille, 664).
provenance(r21_liquid_leaves_source, score_permille, 654).
provenance(r21_liquid_leaves_source, followed, liquid_enters_destination).
provenance(r21_liquid_leaves_source, direction, approach_duration).
provenance(r21_liquid_leaves_source, sign, down).

rule(r21_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r21_liquid_enters_destination, fast_approach).
body(r21_liquid_enters_destination, light_source).
body(r21_liquid_enters_destination, little_liquid).
body(r21_liquid_enters_destination, medium_liquid).
body(r21_liquid_enters_destination, pour_mid_height).
body(r21_liquid_enters_destination, pour_near_rim).
body(r21_liquid_enters_destination, pour_steeply_tilted).
body(r21_liquid_enters_destination, slippery_destination).
learned(r21_liquid_enters_destination).
provenance(r21_liquid_enters_destination, antecedent, a21).
provenance(r21_liquid_enters_destination, parent, a16).
provenance(r21_liquid_enters_destination, simulations, 46).
provenance(r21_liquid_enters_destination, weight_mass_permille, 30380).
provenance(r21_liquid_enters_destination, confidence_permille, 625).
provenance(r21_liquid_enters_destination, score_permille, 599).
provenance(r21_liquid_enters_destination, followed, liquid_enters_destination).
provenance(r21_liquid_enters_destination, direction, approach_duration).
provenance(r21_liquid_enters_destination, sign, down).

rule(r21_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r21_liquid_remains_in_destination, fast_approach).
body(r21_liquid_remains_in_destination, light_source).
body(r21_liquid_remains_in_destination, little_liquid).
body(r21_liquid_remains_in_destination, medium_liquid).
body(r21_liquid_remains_in_destination, pour_mid_height).
body(r21_liquid_remains_in_destination, pour_near_rim).
body(r21_liquid_remains_in_destination, pour_steeply_tilted).
body(r21_liquid_remains_in_destination, slippery_destination).
learned(r21_liquid_remains_in_destination).
provenance(r21_liquid_remains_in_destination, antecedent, a21).
provenance(r21_liquid_remains_in_destination, parent, a16).
provenance(r21_liquid_remains_in_destination, simulations, 46).
provenance(r21_liquid_remains_in_destination, weight_mass_permille, 30380).
provenance(r21_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r21_liquid_remains_in_destination, score_permille, 979).
provenance(r21_liquid_remains_in_destination, followed, liquid_enters_destination).
provenance(r21_liquid_remains_in_destination, direction, approach_duration).
provenance(r21_liquid_remains_in_destination, sign, down).

rule(r21_no_spill, defeasible, no_spill).
body(r21_no_spill, fast_approach).
body(r21_no_spill, light_source).
body(r21_no_spill, little_liquid).
body(r21_no_spill, medium_liquid).
body(r21_no_spill, pour_mid_height).
body(r21_no_spill, pour_near_rim).
body(r21_no_spill, pour_steeply_tilted).
body(r21_no_spill, slippery_destination).
learned(r21_no_spill).
provenance(r21_no_spill, antecedent, a21).
provenance(r21_no_spill, parent, a16).
provenance(r21_no_spill, simulations, 46).
provenance(r21_no_spill, weight_mass_permille, 30380).
provenance(r21_no_spill, confidence_permille, 988).
provenance(r21_no_spill, score_permille, 928).
provenance(r21_no_spill, followed, liquid_enters_destination).
provenance(r21_no_spill, direction, approach_duration).
provenance(r21_no_spill, sign, down).

rule(r22_destination_still_approach, defeasible, destination_still_approach).
body(r22_destination_still_approach, light_source).
body(r22_destination_still_approach, little_liquid).
body(r22_destination_still_approach, medium_liquid).
body(r22_destination_still_approach, moderate_approach).
body(r22_destination_still_approach, pour_mid_height).
body(r22_destination_still_approach, pour_near_rim).
body(r22_destination_still_approach, pour_steeply_tilted).
body(r22_destination_still_approach, slippery_destination).
learned(r22_destination_still_approach).
provenance(r22_destination_still_approach, antecedent, a22).
provenance(r22_destination_still_approach, parent, a16).
provenance(r22_destination_still_approach, simulations, 63).
provenance(r22_destination_still_approach, weight_mass_permille, 32763).
provenance(r22_destination_still_approach, confidence_permille, 1000).
provenance(r22_destination_still_approach, score_permille, 986).
provenance(r22_destination_still_approach, followed, liquid_enters_destination).
provenance(r22_destination_still_approach, direction, approach_duration).
provenance(r22_destination_still_approach, sign, down).

rule(r22_destination_still_retreat, defeasible, destination_still_retreat).
body(r22_destination_still_retreat, light_source).
body(r22_destination_still_retreat, little_liquid).
body(r22_destination_still_retreat, medium_liquid).
body(r22_destination_still_retreat, moderate_approach).
body(r22_destination_still_retreat, pour_mid_height).
body(r22_destination_still_retreat, pour_near_rim).
body(r22_destination_still_retreat, pour_steeply_tilted).
body(r22_destination_still_retreat, slippery_destination).
learned(r22_destination_still_retreat).
provenance(r22_destination_still_retreat, antecedent, a22).
provenance(r22_destination_still_retreat, parent, a16).
provenance(r22_destination_still_retreat, simulations, 63).
provenance(r22_destination_still_retreat, weight_mass_permille, 32763).
provenance(r22_destination_still_retreat, confidence_permille, 993).
provenance(r22_destination_still_retreat, score_permille, 985).
provenance(r22_destination_still_retreat, followed, liquid_enters_destination).
provenance(r22_destination_still_retreat, direction, approach_duration).
provenance(r22_destination_still_retreat, sign, down).

rule(r22_destination_still_settle, defeasible, destination_still_settle).
body(r22_destination_still_settle, light_source).
body(r22_destination_still_settle, little_liquid).
body(r22_destination_still_settle, medium_liquid).
body(r22_destination_still_settle, moderate_approach).
body(r22_destination_still_settle, pour_mid_height).
body(r22_destination_still_settle, pour_near_rim).
body(r22_destination_still_settle, pour_steeply_tilted).
body(r22_destination_still_settle, slippery_destination).
learned(r22_destination_still_settle).
provenance(r22_destination_still_settle, antecedent, a22).
provenance(r22_destination_still_settle, parent, a16).
provenance(r22_destination_still_settle, simulations, 63).
provenance(r22_destination_still_settle, weight_mass_permille, 32763).
provenance(r22_destination_still_settle, confidence_permille, 1000).
provenance(r22_destination_still_settle, score_permille, 1000).
provenance(r22_destination_still_settle, followed, liquid_enters_destination).
provenance(r22_destination_still_settle, direction, approach_duration).
provenance(r22_destination_still_settle, sign, down).

rule(r22_destination_upright, defeasible, destination_upright).
body(r22_destination_upright, light_source).
body(r22_destination_upright, little_liquid).
body(r22_destination_upright, medium_liquid).
body(r22_destination_upright, moderate_approach).
body(r22_destination_upright, pour_mid_height).
body(r22_destination_upright, pour_near_rim).
body(r22_destination_upright, pour_steeply_tilted).
body(r22_destination_upright, slippery_destination).
learned(r22_destination_upright).
provenance(r22_destination_upright, antecedent, a22).
provenance(r22_destination_upright, parent, a16).
provenance(r22_destination_upright, simulations, 63).
provenance(r22_destination_upright, weight_mass_permille, 32763).
provenance(r22_destination_upright, confidence_permille, 1000).
provenance(r22_destination_upright, score_permille, 1000).
provenance(r22_destination_upright, followed, liquid_enters_destination).
provenance(r22_destination_upright, direction, approach_duration).
provenance(r22_destination_upright, sign, down).

rule(r22_source_clear, defeasible, source_clear).
body(r22_source_clear, light_source).
body(r22_source_clear, little_liquid).
body(r22_source_clear, medium_liquid).
body(r22_source_clear, moderate_approach).
body(r22_source_clear, pour_mid_height).
body(r22_source_clear, pour_near_rim).
body(r22_source_clear, pour_steeply_tilted).
body(r22_source_clear, slippery_destination).
learned(r22_source_clear).
provenance(r22_source_clear, antecedent, a22).
provenance(r22_source_clear, parent, a16).
provenance(r22_source_clear, simulations, 63).
provenance(r22_source_clear, weight_mass_permille, 32763).
provenance(r22_source_clear, confidence_permille, 1000).
provenance(r22_source_clear, score_permille, 998).
provenance(r22_source_clear, followed, liquid_enters_destination).
provenance(r22_source_clear, direction, approach_duration).
provenance(r22_source_clear, sign, down).

rule(r22_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r22_liquid_leaves_source, light_source).
body(r22_liquid_leaves_source, little_liquid).
body(r22_liquid_leaves_source, medium_liquid).
body(r22_liquid_leaves_source, moderate_approach).
body(r22_liquid_leaves_source, pour_mid_height).
body(r22_liquid_leaves_source, pour_near_rim).
body(r22_liquid_leaves_source, pour_steeply_tilted).
body(r22_liquid_leaves_source, slippery_destination).
learned(r22_liquid_leaves_source).
provenance(r22_liquid_leaves_source, antecedent, a22).
provenance(r22_liquid_leaves_source, parent, a16).
provenance(r22_liquid_leaves_source, simulations, 63).
provenance(r22_liquid_leaves_source, weight_mass_permille, 32763).
provenance(r22_liquid_leaves_source, confidence_permille, 694).
provenance(r22_liquid_leaves_source, score_permille, 646).
provenance(r22_liquid_leaves_source, followed, liquid_enters_destination).
provenance(r22_liquid_leaves_source, direction, approach_duration).
provenance(r22_liquid_leaves_source, sign, down).

rule(r22_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r22_liquid_enters_destination, light_source).
body(r22_liquid_enters_destination, little_liquid).
body(r22_liquid_enters_destination, medium_liquid).
body(r22_liquid_enters_destination, moderate_approach).
body(r22_liquid_enters_destination, pour_mid_height).
body(r22_liquid_enters_destination, pour_near_rim).
body(r22_liquid_enters_destination, pour_steeply_tilted).
body(r22_liquid_enters_destination, slippery_destination).
learned(r22_liquid_enters_destination).
provenance(r22_liquid_enters_destination, antecedent, a22).
provenance(r22_liquid_enters_destination, parent, a16).
provenance(r22_liquid_enters_destination, simulations, 63).
provenance(r22_liquid_enters_destination, weight_mass_permille, 32763).
provenance(r22_liquid_enters_destination, confidence_permille, 679).
provenance(r22_liquid_enters_destination, score_permille, 619).
provenance(r22_liquid_enters_destination, followed, liquid_enters_destination).
provenance(r22_liquid_enters_destination, direction, approach_duration).
provenance(r22_liquid_enters_destination, sign, down).

rule(r22_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r22_liquid_remains_in_destination, light_source).
body(r22_liquid_remains_in_destination, little_liquid).
body(r22_liquid_remains_in_destination, medium_liquid).
body(r22_liquid_remains_in_destination, moderate_approach).
body(r22_liquid_remains_in_destination, pour_mid_height).
body(r22_liquid_remains_in_destination, pour_near_rim).
body(r22_liquid_remains_in_destination, pour_steeply_tilted).
body(r22_liquid_remains_in_destination, slippery_destination).
learned(r22_liquid_remains_in_destination).
provenance(r22_liquid_remains_in_destination, antecedent, a22).
provenance(r22_liquid_remains_in_destination, parent, a16).
provenance(r22_liquid_remains_in_destination, simulations, 63).
provenance(r22_liquid_remains_in_destination, weight_mass_permille, 32763).
provenance(r22_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r22_liquid_remains_in_destination, score_permille, 983).
provenance(r22_liquid_remains_in_destination, followed, liquid_enters_destination).
provenance(r22_liquid_remains_in_destination, direction, approach_duration).
provenance(r22_liquid_remains_in_destination, sign, down).

rule(r22_no_spill, defeasible, no_spill).
body(r22_no_spill, light_source).
body(r22_no_spill, little_liquid).
body(r22_no_spill, medium_liquid).
body(r22_no_spill, moderate_approach).
body(r22_no_spill, pour_mid_height).
body(r22_no_spill, pour_near_rim).
body(r22_no_spill, pour_steeply_tilted).
body(r22_no_spill, slippery_destination).
learned(r22_no_spill).
provenance(r22_no_spill, antecedent, a22).
provenance(r22_no_spill, parent, a16).
provenance(r22_no_spill, simulations, 63).
provenance(r22_no_spill, weight_mass_permille, 32763).
provenance(r22_no_spill, confidence_permille, 993).
provenance(r22_no_spill, score_permille, 958).
provenance(r22_no_spill, followed, liquid_enters_destination).
provenance(r22_no_spill, direction, approach_duration).
provenance(r22_no_spill, sign, down).

rule(r23_destination_still_approach, defeasible, destination_still_approach).
body(r23_destination_still_approach, bouncy_destination).
body(r23_destination_still_approach, light_source).
body(r23_destination_still_approach, little_liquid).
body(r23_destination_still_approach, medium_liquid).
body(r23_destination_still_approach, pour_half_tilted).
body(r23_destination_still_approach, pour_mid_height).
body(r23_destination_still_approach, pour_near_rim).
body(r23_destination_still_approach, slippery_destination).
learned(r23_destination_still_approach).
provenance(r23_destination_still_approach, antecedent, a23).
provenance(r23_destination_still_approach, parent, a20).
provenance(r23_destination_still_approach, simulations, 39).
provenance(r23_destination_still_approach, weight_mass_permille, 27247).
provenance(r23_destination_still_approach, confidence_permille, 1000).
provenance(r23_destination_still_approach, score_permille, 993).
provenance(r23_destination_still_approach, followed, liquid_leaves_source).
provenance(r23_destination_still_approach, direction, pour_pitch).
provenance(r23_destination_still_approach, sign, down).

rule(r23_destination_still_retreat, defeasible, destination_still_retreat).
body(r23_destination_still_retreat, bouncy_destination).
body(r23_destination_still_retreat, light_source).
body(r23_destination_still_retreat, little_liquid).
body(r23_destination_still_retreat, medium_liquid).
body(r23_destination_still_retreat, pour_half_tilted).
body(r23_destination_still_retreat, pour_mid_height).
body(r23_destination_still_retreat, pour_near_rim).
body(r23_destination_still_retreat, slippery_destination).
learned(r23_destination_still_retreat).
provenance(r23_destination_still_retreat, antecedent, a23).
provenance(r23_destination_still_retreat, parent, a20).
provenance(r23_destination_still_retreat, simulations, 39).
provenance(r23_destination_still_retreat, weight_mass_permille, 27247).
provenance(r23_destination_still_retreat, confidence_permille, 1000).
provenance(r23_destination_still_retreat, score_permille, 1000).
provenance(r23_destination_still_retreat, followed, liquid_leaves_source).
provenance(r23_destination_still_retreat, direction, pour_pitch).
provenance(r23_destination_still_retreat, sign, down).

rule(r23_destination_still_settle, defeasible, destination_still_settle).
body(r23_destination_still_settle, bouncy_destination).
body(r23_destination_still_settle, light_source).
body(r23_destination_still_settle, little_liquid).
body(r23_destination_still_settle, medium_liquid).
body(r23_destination_still_settle, pour_half_tilted).
body(r23_destination_still_settle, pour_mid_height).
body(r23_destination_still_settle, pour_near_rim).
body(r23_destination_still_settle, slippery_destination).
learned(r23_destination_still_settle).
provenance(r23_destination_still_settle, antecedent, a23).
provenance(r23_destination_still_settle, parent, a20).
provenance(r23_destination_still_settle, simulations, 39).
provenance(r23_destination_still_settle, weight_mass_permille, 27247).
provenance(r23_destination_still_settle, confidence_permille, 1000).
provenance(r23_destination_still_settle, score_permille, 1000).
provenance(r23_destination_still_settle, followed, liquid_leaves_source).
provenance(r23_destination_still_settle, direction, pour_pitch).
provenance(r23_destination_still_settle, sign, down).

rule(r23_destination_upright, defeasible, destination_upright).
body(r23_destination_upright, bouncy_destination).
body(r23_destination_upright, light_source).
body(r23_destination_upright, little_liquid).
body(r23_destination_upright, medium_liquid).
body(r23_destination_upright, pour_half_tilted).
body(r23_destination_upright, pour_mid_height).
body(r23_destination_upright, pour_near_rim).
body(r23_destination_upright, slippery_destination).
learned(r23_destination_upright).
provenance(r23_destination_upright, antecedent, a23).
provenance(r23_destination_upright, parent, a20).
provenance(r23_destination_upright, simulations, 39).
provenance(r23_destination_upright, weight_mass_permille, 27247).
provenance(r23_destination_upright, confidence_permille, 1000).
provenance(r23_destination_upright, score_permille, 1000).
provenance(r23_destination_upright, followed, liquid_leaves_source).
provenance(r23_destination_upright, direction, pour_pitch).
provenance(r23_destination_upright, sign, down).

rule(r23_source_clear, defeasible, source_clear).
body(r23_source_clear, bouncy_destination).
body(r23_source_clear, light_source).
body(r23_source_clear, little_liquid).
body(r23_source_clear, medium_liquid).
body(r23_source_clear, pour_half_tilted).
body(r23_source_clear, pour_mid_height).
body(r23_source_clear, pour_near_rim).
body(r23_source_clear, slippery_destination).
learned(r23_source_clear).
provenance(r23_source_clear, antecedent, a23).
provenance(r23_source_clear, parent, a20).
provenance(r23_source_clear, simulations, 39).
provenance(r23_source_clear, weight_mass_permille, 27247).
provenance(r23_source_clear, confidence_permille, 1000).
provenance(r23_source_clear, score_permille, 1000).
provenance(r23_source_clear, followed, liquid_leaves_source).
provenance(r23_source_clear, direction, pour_pitch).
provenance(r23_source_clear, sign, down).

rule(r23_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r23_liquid_leaves_source, bouncy_destination).
body(r23_liquid_leaves_source, light_source).
body(r23_liquid_leaves_source, little_liquid).
body(r23_liquid_leaves_source, medium_liquid).
body(r23_liquid_leaves_source, pour_half_tilted).
body(r23_liquid_leaves_source, pour_mid_height).
body(r23_liquid_leaves_source, pour_near_rim).
body(r23_liquid_leaves_source, slippery_destination).
learned(r23_liquid_leaves_source).
provenance(r23_liquid_leaves_source, antecedent, a23).
provenance(r23_liquid_leaves_source, parent, a20).
provenance(r23_liquid_leaves_source, simulations, 39).
provenance(r23_liquid_leaves_source, weight_mass_permille, 27247).
provenance(r23_liquid_leaves_source, confidence_permille, 1000).
provenance(r23_liquid_leaves_source, score_permille, 0).
provenance(r23_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r23_liquid_leaves_source, direction, pour_pitch).
provenance(r23_liquid_leaves_source, sign, down).

rule(r23_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r23_liquid_enters_destination, bouncy_destination).
body(r23_liquid_enters_destination, light_source).
body(r23_liquid_enters_destination, little_liquid).
body(r23_liquid_enters_destination, medium_liquid).
body(r23_liquid_enters_destination, pour_half_tilted).
body(r23_liquid_enters_destination, pour_mid_height).
body(r23_liquid_enters_destination, pour_near_rim).
body(r23_liquid_enters_destination, slippery_destination).
learned(r23_liquid_enters_destination).
provenance(r23_liquid_enters_destination, antecedent, a23).
provenance(r23_liquid_enters_destination, parent, a20).
provenance(r23_liquid_enters_destination, simulations, 39).
provenance(r23_liquid_enters_destination, weight_mass_permille, 27247).
provenance(r23_liquid_enters_destination, confidence_permille, 1000).
provenance(r23_liquid_enters_destination, score_permille, 0).
provenance(r23_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r23_liquid_enters_destination, direction, pour_pitch).
provenance(r23_liquid_enters_destination, sign, down).

rule(r23_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r23_liquid_remains_in_destination, bouncy_destination).
body(r23_liquid_remains_in_destination, light_source).
body(r23_liquid_remains_in_destination, little_liquid).
body(r23_liquid_remains_in_destination, medium_liquid).
body(r23_liquid_remains_in_destination, pour_half_tilted).
body(r23_liquid_remains_in_destination, pour_mid_height).
body(r23_liquid_remains_in_destination, pour_near_rim).
body(r23_liquid_remains_in_destination, slippery_destination).
learned(r23_liquid_remains_in_destination).
provenance(r23_liquid_remains_in_destination, antecedent, a23).
provenance(r23_liquid_remains_in_destination, parent, a20).
provenance(r23_liquid_remains_in_destination, simulations, 39).
provenance(r23_liquid_remains_in_destination, weight_mass_permille, 27247).
provenance(r23_liquid_remains_in_destination, confidence_permille, 1000).
provenance(r23_liquid_remains_in_destination, score_permille, 1000).
provenance(r23_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r23_liquid_remains_in_destination, direction, pour_pitch).
provenance(r23_liquid_remains_in_destination, sign, down).

rule(r23_no_spill, defeasible, no_spill).
body(r23_no_spill, bouncy_destination).
body(r23_no_spill, light_source).
body(r23_no_spill, little_liquid).
body(r23_no_spill, medium_liquid).
body(r23_no_spill, pour_half_tilted).
body(r23_no_spill, pour_mid_height).
body(r23_no_spill, pour_near_rim).
body(r23_no_spill, slippery_destination).
learned(r23_no_spill).
provenance(r23_no_spill, antecedent, a23).
provenance(r23_no_spill, parent, a20).
provenance(r23_no_spill, simulations, 39).
provenance(r23_no_spill, weight_mass_permille, 27247).
provenance(r23_no_spill, confidence_permille, 1000).
provenance(r23_no_spill, score_permille, 1000).
provenance(r23_no_spill, followed, liquid_leaves_source).
provenance(r23_no_spill, direction, pour_pitch).
provenance(r23_no_spill, sign, down).

rule(r24_destination_still_approach, defeasible, destination_still_approach).
body(r24_destination_still_approach, bouncy_destination).
body(r24_destination_still_approach, bouncy_liquid).
body(r24_destination_still_approach, light_source).
body(r24_destination_still_approach, little_liquid).
body(r24_destination_still_approach, medium_liquid).
body(r24_destination_still_approach, pour_mid_height).
body(r24_destination_still_approach, pour_near_rim).
body(r24_destination_still_approach, pour_steeply_tilted).
body(r24_destination_still_approach, slippery_destination).
learned(r24_destination_still_approach).
provenance(r24_destination_still_approach, antecedent, a24).
provenance(r24_destination_still_approach, parent, a20).
provenance(r24_destination_still_approach, simulations, 55).
provenance(r24_destination_still_approach, weight_mass_permille, 30661).
provenance(r24_destination_still_approach, confidence_permille, 1000).
provenance(r24_destination_still_approach, score_permille, 979).
provenance(r24_destination_still_approach, followed, liquid_leaves_source).
provenance(r24_destination_still_approach, direction, particle_restitution).
provenance(r24_destination_still_approach, sign, up).

rule(r24_destination_still_retreat, defeasible, destination_still_retreat).
body(r24_destination_still_retreat, bouncy_destination).
body(r24_destination_still_retreat, bouncy_liquid).
body(r24_destination_still_retreat, light_source).
body(r24_destination_still_retreat, little_liquid).
body(r24_destination_still_retreat, medium_liquid).
body(r24_destination_still_retreat, pour_mid_height).
body(r24_destination_still_retreat, pour_near_rim).
body(r24_destination_still_retreat, pour_steeply_tilted).
body(r24_destination_still_retreat, slippery_destination).
learned(r24_destination_still_retreat).
provenance(r24_destination_still_retreat, antecedent, a24).
provenance(r24_destination_still_retreat, parent, a20).
provenance(r24_destination_still_retreat, simulations, 55).
provenance(r24_destination_still_retreat, weight_mass_permille, 30661).
provenance(r24_destination_still_retreat, confidence_permille, 984).
provenance(r24_destination_still_retreat, score_permille, 980).
provenance(r24_destination_still_retreat, followed, liquid_leaves_source).
provenance(r24_destination_still_retreat, direction, particle_restitution).
provenance(r24_destination_still_retreat, sign, up).

rule(r24_destination_still_settle, defeasible, destination_still_settle).
body(r24_destination_still_settle, bouncy_destination).
body(r24_destination_still_settle, bouncy_liquid).
body(r24_destination_still_settle, light_source).
body(r24_destination_still_settle, little_liquid).
body(r24_destination_still_settle, medium_liquid).
body(r24_destination_still_settle, pour_mid_height).
body(r24_destination_still_settle, pour_near_rim).
body(r24_destination_still_settle, pour_steeply_tilted).
body(r24_destination_still_settle, slippery_destination).
learned(r24_destination_still_settle).
provenance(r24_destination_still_settle, antecedent, a24).
provenance(r24_destination_still_settle, parent, a20).
provenance(r24_destination_still_settle, simulations, 55).
provenance(r24_destination_still_settle, weight_mass_permille, 30661).
provenance(r24_destination_still_settle, confidence_permille, 1000).
provenance(r24_destination_still_settle, score_permille, 1000).
provenance(r24_destination_still_settle, followed, liquid_leaves_source).
provenance(r24_destination_still_settle, direction, particle_restitution).
provenance(r24_destination_still_settle, sign, up).

rule(r24_destination_upright, defeasible, destination_upright).
body(r24_destination_upright, bouncy_destination).
body(r24_destination_upright, bouncy_liquid).
body(r24_destination_upright, light_source).
body(r24_destination_upright, little_liquid).
body(r24_destination_upright, medium_liquid).
body(r24_destination_upright, pour_mid_height).
body(r24_destination_upright, pour_near_rim).
body(r24_destination_upright, pour_steeply_tilted).
body(r24_destination_upright, slippery_destination).
learned(r24_destination_upright).
provenance(r24_destination_upright, antecedent, a24).
provenance(r24_destination_upright, parent, a20).
provenance(r24_destination_upright, simulations, 55).
provenance(r24_destination_upright, weight_mass_permille, 30661).
provenance(r24_destination_upright, confidence_permille, 1000).
provenance(r24_destination_upright, score_permille, 1000).
provenance(r24_destination_upright, followed, liquid_leaves_source).
provenance(r24_destination_upright, direction, particle_restitution).
provenance(r24_destination_upright, sign, up).

rule(r24_source_clear, defeasible, source_clear).
body(r24_source_clear, bouncy_destination).
body(r24_source_clear, bouncy_liquid).
body(r24_source_clear, light_source).
body(r24_source_clear, little_liquid).
body(r24_source_clear, medium_liquid).
body(r24_source_clear, pour_mid_height).
body(r24_source_clear, pour_near_rim).
body(r24_source_clear, pour_steeply_tilted).
body(r24_source_clear, slippery_destination).
learned(r24_source_clear).
provenance(r24_source_clear, antecedent, a24).
provenance(r24_source_clear, parent, a20).
provenance(r24_source_clear, simulations, 55).
provenance(r24_source_clear, weight_mass_permille, 30661).
provenance(r24_source_clear, confidence_permille, 1000).
provenance(r24_source_clear, score_permille, 996).
provenance(r24_source_clear, followed, liquid_leaves_source).
provenance(r24_source_clear, direction, particle_restitution).
provenance(r24_source_clear, sign, up).

rule(r24_liquid_leaves_source, defeasible, liquid_leaves_source).
body(r24_liquid_leaves_source, bouncy_destination).
body(r24_liquid_leaves_source, bouncy_liquid).
body(r24_liquid_leaves_source, light_source).
body(r24_liquid_leaves_source, little_liquid).
body(r24_liquid_leaves_source, medium_liquid).
body(r24_liquid_leaves_source, pour_mid_height).
body(r24_liquid_leaves_source, pour_near_rim).
body(r24_liquid_leaves_source, pour_steeply_tilted).
body(r24_liquid_leaves_source, slippery_destination).
learned(r24_liquid_leaves_source).
provenance(r24_liquid_leaves_source, antecedent, a24).
provenance(r24_liquid_leaves_source, parent, a20).
provenance(r24_liquid_leaves_source, simulations, 55).
provenance(r24_liquid_leaves_source, weight_mass_permille, 30661).
provenance(r24_liquid_leaves_source, confidence_permille, 568).
provenance(r24_liquid_leaves_source, score_permille, 602).
provenance(r24_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r24_liquid_leaves_source, direction, particle_restitution).
provenance(r24_liquid_leaves_source, sign, up).

rule(r24_liquid_enters_destination, defeasible, liquid_enters_destination).
body(r24_liquid_enters_destination, bouncy_destination).
body(r24_liquid_enters_destination, bouncy_liquid).
body(r24_liquid_enters_destination, light_source).
body(r24_liquid_enters_destination, little_liquid).
body(r24_liquid_enters_destination, medium_liquid).
body(r24_liquid_enters_destination, pour_mid_height).
body(r24_liquid_enters_destination, pour_near_rim).
body(r24_liquid_enters_destination, pour_steeply_tilted).
body(r24_liquid_enters_destination, slippery_destination).
learned(r24_liquid_enters_destination).
provenance(r24_liquid_enters_destination, antecedent, a24).
provenance(r24_liquid_enters_destination, parent, a20).
provenance(r24_liquid_enters_destination, simulations, 55).
provenance(r24_liquid_enters_destination, weight_mass_permille, 30661).
provenance(r24_liquid_enters_destination, confidence_permille, 522).
provenance(r24_liquid_enters_destination, score_permille, 568).
provenance(r24_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r24_liquid_enters_destination, direction, particle_restitution).
provenance(r24_liquid_enters_destination, sign, up).

rule(r24_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r24_liquid_remains_in_destination, bouncy_destination).
body(r24_liquid_remains_in_destination, bouncy_liquid).
body(r24_liquid_remains_in_destination, light_source).
body(r24_liquid_remains_in_destination, little_liquid).
body(r24_liquid_remains_in_destination, medium_liquid).
body(r24_liquid_remains_in_destination, pour_mid_height).
body(r24_liquid_remains_in_destination, pour_near_rim).
body(r24_liquid_remains_in_destination, pour_steeply_tilted).
body(r24_liquid_remains_in_destination, slippery_destination).
learned(r24_liquid_remains_in_destination).
provenance(r24_liquid_remains_in_destination, antecedent, a24).
provenance(r24_liquid_remains_in_destination, parent, a20).
provenance(r24_liquid_remains_in_destination, simulations, 55).
provenance(r24_liquid_remains_in_destination, weight_mass_permille, 30661).
provenance(r24_liquid_remains_in_destination, confidence_permille, 979).
provenance(r24_liquid_remains_in_destination, score_permille, 957).
provenance(r24_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r24_liquid_remains_in_destination, direction, particle_restitution).
provenance(r24_liquid_remains_in_destination, sign, up).

rule(r24_no_spill, defeasible, no_spill).
body(r24_no_spill, bouncy_destination).
body(r24_no_spill, bouncy_liquid).
body(r24_no_spill, light_source).
body(r24_no_spill, little_liquid).
body(r24_no_spill, medium_liquid).
body(r24_no_spill, pour_mid_height).
body(r24_no_spill, pour_near_rim).
body(r24_no_spill, pour_steeply_tilted).
body(r24_no_spill, slippery_destination).
learned(r24_no_spill).
provenance(r24_no_spill, antecedent, a24).
provenance(r24_no_spill, parent, a20).
provenance(r24_no_spill, simulations, 55).
provenance(r24_no_spill, weight_mass_permille, 30661).
provenance(r24_no_spill, confidence_permille, 949).
provenance(r24_no_spill, score_permille, 930).
provenance(r24_no_spill, followed, liquid_leaves_source).
provenance(r24_no_spill, direction, particle_restitution).
provenance(r24_no_spill, sign, up).

rule(r25_destination_still_approach, defeasible, destination_still_approach).
body(r25_destination_still_approach, light_liquid).
body(r25_destination_still_approach, light_source).
body(r25_destination_still_approach, pour_half_tilted).
body(r25_destination_still_approach, pour_mid_height).
body(r25_destination_still_approach, pour_near_rim).
body(r25_destination_still_approach, slippery_destination).
learned(r25_destination_still_approach).
provenance(r25_destination_still_approach, antecedent, a25).
provenance(r25_destination_still_approach, parent, a12).
provenance(r25_destination_still_approach, simulations, 67).
provenance(r25_destination_still_approach, weight_mass_permille, 30317).
provenance(r25_destination_still_approach, confidence_permille, 1000).
provenance(r25_destination_still_approach, score_permille, 993).
provenance(r25_destination_still_approach, followed, liquid_leaves_source).
provenance(r25_destination_still_approach, direction, pour_pitch).
provenance(r25_destination_still_approach, sign, down).

rule(r25_destination_still_retreat, defeasible, destination_still_retreat).
body(r25_destination_still_retreat, light_liquid).
body(r25_destination_still_retreat, light_source).
body(r25_destination_still_retreat, pour_half_tilted).
body(r25_destination_still_retreat, pour_mid_height).
body(r25_destination_still_retreat, pour_near_rim).
body(r25_destination_still_retreat, slippery_destination).
learned(r25_destination_still_retreat).
provenance(r25_destination_still_retreat, antecedent, a25).
provenance(r25_destination_still_retreat, parent, a12).
provenance(r25_destination_still_retreat, simulations, 67).
provenance(r25_destination_still_retreat, weight_mass_permille, 30317).
provenance(r25_destination_still_retreat, confidence_permille, 1000).
provenance(r25_destination_still_retreat, score_permille, 1000).
provenance(r25_destination_still_retreat, followed, liquid_leaves_source).
provenance(r25_destination_still_retreat, direction, pour_pitch).
provenance(r25_destination_still_retreat, sign, down).

rule(r25_destination_still_settle, defeasible, destination_still_settle).
body(r25_destination_still_settle, light_liquid).
body(r25_destination_still_settle, light_source).
body(r25_destination_still_settle, pour_half_tilted).
body(r25_destination_still_settle, pour_mid_height).
body(r25_destination_still_settle, pour_near_rim).
body(r25_destination_still_settle, slippery_destination).
learned(r25_destination_still_settle).
provenance(r25_destination_still_settle, antecedent, a25).
provenance(r25_destination_still_settle, parent, a12).
provenance(r25_destination_still_settle, simulations, 67).
provenance(r25_destination_still_settle, weight_mass_permille, 30317).
provenance(r25_destination_still_settle, confidence_permille, 1000).
provenance(r25_destination_still_settle, score_permille, 1000).
provenance(r25_destination_still_settle, followed, liquid_leaves_source).
provenance(r25_destination_still_settle, direction, pour_pitch).
provenance(r25_destination_still_settle, sign, down).

rule(r25_destination_upright, defeasible, destination_upright).
body(r25_destination_upright, light_liquid).
body(r25_destination_upright, light_source).
body(r25_destination_upright, pour_half_tilted).
body(r25_destination_upright, pour_mid_height).
body(r25_destination_upright, pour_near_rim).
body(r25_destination_upright, slippery_destination).
learned(r25_destination_upright).
provenance(r25_destination_upright, antecedent, a25).
provenance(r25_destination_upright, parent, a12).
provenance(r25_destination_upright, simulations, 67).
provenance(r25_destination_upright, weight_mass_permille, 30317).
provenance(r25_destination_upright, confidence_permille, 1000).
provenance(r25_destination_upright, score_permille, 1000).
provenance(r25_destination_upright, followed, liquid_leaves_source).
provenance(r25_destination_upright, direction, pour_pitch).
provenance(r25_destination_upright, sign, down).

rule(r25_source_clear, defeasible, source_clear).
body(r25_source_clear, light_liquid).
body(r25_source_clear, light_source).
body(r25_source_clear, pour_half_tilted).
body(r25_source_clear, pour_mid_height).
body(r25_source_clear, pour_near_rim).
body(r25_source_clear, slippery_destination).
learned(r25_source_clear).
provenance(r25_source_clear, antecedent, a25).
provenance(r25_source_clear, parent, a12).
provenance(r25_source_clear, simulations, 67).
provenance(r25_source_clear, weight_mass_permille, 30317).
provenance(r25_source_clear, confidence_permille, 1000).
provenance(r25_source_clear, score_permille, 1000).
provenance(r25_source_clear, followed, liquid_leaves_source).
provenance(r25_source_clear, direction, pour_pitch).
provenance(r25_source_clear, sign, down).

rule(r25_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(r25_liquid_leaves_source, light_liquid).
body(r25_liquid_leaves_source, light_source).
body(r25_liquid_leaves_source, pour_half_tilted).
body(r25_liquid_leaves_source, pour_mid_height).
body(r25_liquid_leaves_source, pour_near_rim).
body(r25_liquid_leaves_source, slippery_destination).
learned(r25_liquid_leaves_source).
provenance(r25_liquid_leaves_source, antecedent, a25).
provenance(r25_liquid_leaves_source, parent, a12).
provenance(r25_liquid_leaves_source, simulations, 67).
provenance(r25_liquid_leaves_source, weight_mass_permille, 30317).
provenance(r25_liquid_leaves_source, confidence_permille, 970).
provenance(r25_liquid_leaves_source, score_permille, 43).
provenance(r25_liquid_leaves_source, followed, liquid_leaves_source).
provenance(r25_liquid_leaves_source, direction, pour_pitch).
provenance(r25_liquid_leaves_source, sign, down).

rule(r25_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(r25_liquid_enters_destination, light_liquid).
body(r25_liquid_enters_destination, light_source).
body(r25_liquid_enters_destination, pour_half_tilted).
body(r25_liquid_enters_destination, pour_mid_height).
body(r25_liquid_enters_destination, pour_near_rim).
body(r25_liquid_enters_destination, slippery_destination).
learned(r25_liquid_enters_destination).
provenance(r25_liquid_enters_destination, antecedent, a25).
provenance(r25_liquid_enters_destination, parent, a12).
provenance(r25_liquid_enters_destination, simulations, 67).
provenance(r25_liquid_enters_destination, weight_mass_permille, 30317).
provenance(r25_liquid_enters_destination, confidence_permille, 1000).
provenance(r25_liquid_enters_destination, score_permille, 31).
provenance(r25_liquid_enters_destination, followed, liquid_leaves_source).
provenance(r25_liquid_enters_destination, direction, pour_pitch).
provenance(r25_liquid_enters_destination, sign, down).

rule(r25_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(r25_liquid_remains_in_destination, light_liquid).
body(r25_liquid_remains_in_destination, light_source).
body(r25_liquid_remains_in_destination, pour_half_tilted).
body(r25_liquid_remains_in_destination, pour_mid_height).
body(r25_liquid_remains_in_destination, pour_near_rim).
body(r25_liquid_remains_in_destination, slippery_destination).
learned(r25_liquid_remains_in_destination).
provenance(r25_liquid_remains_in_destination, antecedent, a25).
provenance(r25_liquid_remains_in_destination, parent, a12).
provenance(r25_liquid_remains_in_destination, simulations, 67).
provenance(r25_liquid_remains_in_destination, weight_mass_permille, 30317).
provenance(r25_liquid_remains_in_destination, confidence_permille, 970).
provenance(r25_liquid_remains_in_destination, score_permille, 971).
provenance(r25_liquid_remains_in_destination, followed, liquid_leaves_source).
provenance(r25_liquid_remains_in_destination, direction, pour_pitch).
provenance(r25_liquid_remains_in_destination, sign, down).

rule(r25_no_spill, defeasible, no_spill).
body(r25_no_spill, light_liquid).
body(r25_no_spill, light_source).
body(r25_no_spill, pour_half_tilted).
body(r25_no_spill, pour_mid_height).
body(r25_no_spill, pour_near_rim).
body(r25_no_spill, slippery_destination).
learned(r25_no_spill).
provenance(r25_no_spill, antecedent, a25).
provenance(r25_no_spill, parent, a12).
provenance(r25_no_spill, simulations, 67).
provenance(r25_no_spill, weight_mass_permille, 30317).
provenance(r25_no_spill, confidence_permille, 1000).
provenance(r25_no_spill, score_permille, 977).
provenance(r25_no_spill, followed, liquid_leaves_source).
provenance(r25_no_spill, direction, pour_pitch).
provenance(r25_no_spill, sign, down).
