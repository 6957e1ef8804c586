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
setting(oracle_version, "4").
setting(seed, 1).
setting(batch, 2).
setting(budget, 25).
setting(pours, 775).
setting(curiosity, learn).
setting(body, 2).
setting(queue, 64).
setting(uncertainty_permille, 1000).
setting(doubt_permille, 1000).
setting(newness_permille, 2000).
setting(reach, 16).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 105).
setting(simulations, 774).
setting(failed_simulations, 0).
setting(stopped, budget).
setting(a_new_left, 64).

% The rules curiosity learned: per expectation, a default (the
% ordinary pour, the empty antecedent) and the explored antecedents
% whose likelihoods the rest of the theory does not give
% (bridge/learning/generalize.py over the explored antecedents).
% provenance(Id, antecedent, A): the explored antecedent of its body;
% support: the pours whose description holds the body; kept: how
% many of them keep the head; confidence_permille: P(head | body), the
% share of the pours sampled for the body (the rest an ordinary pour)
% that keep the head, every pour of the run pooled to estimate it.
% sup/2 below orders the rules that one scene can hold (see
% bridge/learning/layers.py).
setting(general_pours, 774).
setting(general_own_pours, 0).
setting(general_rules, 84).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 18).
provenance(g0_destination_still_approach, kept, 18).
provenance(g0_destination_still_approach, confidence_permille, 989).
provenance(g0_destination_still_approach, antecedent, a1).
rule(g1_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g1_destination_still_approach, pour_below_rim).
learned(g1_destination_still_approach).
provenance(g1_destination_still_approach, layer, general).
provenance(g1_destination_still_approach, level, 1).
provenance(g1_destination_still_approach, support, 210).
provenance(g1_destination_still_approach, kept, 195).
provenance(g1_destination_still_approach, confidence_permille, 928).
provenance(g1_destination_still_approach, antecedent, a4).
rule(g2_destination_still_approach, defeasible, destination_still_approach).
body(g2_destination_still_approach, start_below_rim).
learned(g2_destination_still_approach).
provenance(g2_destination_still_approach, layer, general).
provenance(g2_destination_still_approach, level, 1).
provenance(g2_destination_still_approach, support, 20).
provenance(g2_destination_still_approach, kept, 13).
provenance(g2_destination_still_approach, confidence_permille, 664).
provenance(g2_destination_still_approach, antecedent, a2).
rule(g3_destination_still_approach, defeasible, destination_still_approach).
body(g3_destination_still_approach, pour_far_away).
learned(g3_destination_still_approach).
provenance(g3_destination_still_approach, layer, general).
provenance(g3_destination_still_approach, level, 1).
provenance(g3_destination_still_approach, support, 10).
provenance(g3_destination_still_approach, kept, 10).
provenance(g3_destination_still_approach, confidence_permille, 1000).
provenance(g3_destination_still_approach, antecedent, a20).
rule(g4_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g4_destination_still_approach, approach_raising).
body(g4_destination_still_approach, pour_low).
learned(g4_destination_still_approach).
provenance(g4_destination_still_approach, layer, general).
provenance(g4_destination_still_approach, level, 1).
provenance(g4_destination_still_approach, support, 16).
provenance(g4_destination_still_approach, kept, 14).
provenance(g4_destination_still_approach, confidence_permille, 857).
provenance(g4_destination_still_approach, antecedent, a81).
rule(g5_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g5_destination_still_approach, pour_low).
body(g5_destination_still_approach, start_low).
learned(g5_destination_still_approach).
provenance(g5_destination_still_approach, layer, general).
provenance(g5_destination_still_approach, level, 1).
provenance(g5_destination_still_approach, support, 13).
provenance(g5_destination_still_approach, kept, 10).
provenance(g5_destination_still_approach, confidence_permille, 727).
provenance(g5_destination_still_approach, antecedent, a80).
rule(g6_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g6_destination_still_approach, pour_low).
body(g6_destination_still_approach, start_below_rim).
learned(g6_destination_still_approach).
provenance(g6_destination_still_approach, layer, general).
provenance(g6_destination_still_approach, level, 2).
provenance(g6_destination_still_approach, support, 12).
provenance(g6_destination_still_approach, kept, 12).
provenance(g6_destination_still_approach, confidence_permille, 960).
provenance(g6_destination_still_approach, antecedent, a85).
rule(g7_destination_still_approach, defeasible, destination_still_approach).
body(g7_destination_still_approach, pour_below_rim).
body(g7_destination_still_approach, pour_slightly_tilted).
learned(g7_destination_still_approach).
provenance(g7_destination_still_approach, layer, general).
provenance(g7_destination_still_approach, level, 2).
provenance(g7_destination_still_approach, support, 4).
provenance(g7_destination_still_approach, kept, 3).
provenance(g7_destination_still_approach, confidence_permille, 594).
provenance(g7_destination_still_approach, antecedent, a59).
rule(g8_destination_still_approach, defeasible, destination_still_approach).
body(g8_destination_still_approach, pour_below_rim).
body(g8_destination_still_approach, pour_upright).
learned(g8_destination_still_approach).
provenance(g8_destination_still_approach, layer, general).
provenance(g8_destination_still_approach, level, 2).
provenance(g8_destination_still_approach, support, 6).
provenance(g8_destination_still_approach, kept, 4).
provenance(g8_destination_still_approach, confidence_permille, 563).
provenance(g8_destination_still_approach, antecedent, a63).
rule(g9_destination_still_approach, defeasible, destination_still_approach).
body(g9_destination_still_approach, pour_below_rim).
body(g9_destination_still_approach, pour_tilted_back).
learned(g9_destination_still_approach).
provenance(g9_destination_still_approach, layer, general).
provenance(g9_destination_still_approach, level, 2).
provenance(g9_destination_still_approach, support, 6).
provenance(g9_destination_still_approach, kept, 4).
provenance(g9_destination_still_approach, confidence_permille, 553).
provenance(g9_destination_still_approach, antecedent, a60).
rule(g10_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g10_destination_still_approach, heavy_destination).
body(g10_destination_still_approach, pour_below_rim).
learned(g10_destination_still_approach).
provenance(g10_destination_still_approach, layer, general).
provenance(g10_destination_still_approach, level, 1).
provenance(g10_destination_still_approach, support, 2).
provenance(g10_destination_still_approach, kept, 0).
provenance(g10_destination_still_approach, confidence_permille, 548).
provenance(g10_destination_still_approach, antecedent, a87).
rule(g11_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g11_destination_still_approach, pour_below_rim).
body(g11_destination_still_approach, pour_half_tilted).
learned(g11_destination_still_approach).
provenance(g11_destination_still_approach, layer, general).
provenance(g11_destination_still_approach, level, 1).
provenance(g11_destination_still_approach, support, 10).
provenance(g11_destination_still_approach, kept, 6).
provenance(g11_destination_still_approach, confidence_permille, 624).
provenance(g11_destination_still_approach, antecedent, a64).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 18).
provenance(g0_destination_still_retreat, kept, 18).
provenance(g0_destination_still_retreat, confidence_permille, 983).
provenance(g0_destination_still_retreat, antecedent, a1).
rule(g1_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g1_destination_still_retreat, pour_below_rim).
learned(g1_destination_still_retreat).
provenance(g1_destination_still_retreat, layer, general).
provenance(g1_destination_still_retreat, level, 1).
provenance(g1_destination_still_retreat, support, 210).
provenance(g1_destination_still_retreat, kept, 155).
provenance(g1_destination_still_retreat, confidence_permille, 738).
provenance(g1_destination_still_retreat, antecedent, a4).
rule(g2_destination_still_retreat, defeasible, destination_still_retreat).
body(g2_destination_still_retreat, end_below_rim).
learned(g2_destination_still_retreat).
provenance(g2_destination_still_retreat, layer, general).
provenance(g2_destination_still_retreat, level, 1).
provenance(g2_destination_still_retreat, support, 8).
provenance(g2_destination_still_retreat, kept, 4).
provenance(g2_destination_still_retreat, confidence_permille, 604).
provenance(g2_destination_still_retreat, antecedent, a7).
rule(g3_destination_still_retreat, defeasible, destination_still_retreat).
body(g3_destination_still_retreat, pour_far_away).
learned(g3_destination_still_retreat).
provenance(g3_destination_still_retreat, layer, general).
provenance(g3_destination_still_retreat, level, 1).
provenance(g3_destination_still_retreat, support, 10).
provenance(g3_destination_still_retreat, kept, 10).
provenance(g3_destination_still_retreat, confidence_permille, 999).
provenance(g3_destination_still_retreat, antecedent, a20).
rule(g4_destination_still_retreat, defeasible, destination_still_retreat).
body(g4_destination_still_retreat, approach_raising).
body(g4_destination_still_retreat, pour_below_rim).
learned(g4_destination_still_retreat).
provenance(g4_destination_still_retreat, layer, general).
provenance(g4_destination_still_retreat, level, 2).
provenance(g4_destination_still_retreat, support, 7).
provenance(g4_destination_still_retreat, kept, 5).
provenance(g4_destination_still_retreat, confidence_permille, 678).
provenance(g4_destination_still_retreat, antecedent, a68).
rule(g5_destination_still_retreat, defeasible, destination_still_retreat).
body(g5_destination_still_retreat, pour_below_rim).
body(g5_destination_still_retreat, pour_slightly_tilted).
learned(g5_destination_still_retreat).
provenance(g5_destination_still_retreat, layer, general).
provenance(g5_destination_still_retreat, level, 2).
provenance(g5_destination_still_retreat, support, 4).
provenance(g5_destination_still_retreat, kept, 3).
provenance(g5_destination_still_retreat, confidence_permille, 672).
provenance(g5_destination_still_retreat, antecedent, a59).
rule(g6_destination_still_retreat, defeasible, destination_still_retreat).
body(g6_destination_still_retreat, pour_below_rim).
body(g6_destination_still_retreat, start_below_rim).
learned(g6_destination_still_retreat).
provenance(g6_destination_still_retreat, layer, general).
provenance(g6_destination_still_retreat, level, 2).
provenance(g6_destination_still_retreat, support, 8).
provenance(g6_destination_still_retreat, kept, 5).
provenance(g6_destination_still_retreat, confidence_permille, 573).
provenance(g6_destination_still_retreat, antecedent, a76).
rule(g7_destination_still_retreat, defeasible, destination_still_retreat).
body(g7_destination_still_retreat, pour_below_rim).
body(g7_destination_still_retreat, pour_half_tilted).
learned(g7_destination_still_retreat).
provenance(g7_destination_still_retreat, layer, general).
provenance(g7_destination_still_retreat, level, 2).
provenance(g7_destination_still_retreat, support, 10).
provenance(g7_destination_still_retreat, kept, 6).
provenance(g7_destination_still_retreat, confidence_permille, 561).
provenance(g7_destination_still_retreat, antecedent, a64).
rule(g8_destination_still_retreat, defeasible, destination_still_retreat).
body(g8_destination_still_retreat, pour_below_rim).
body(g8_destination_still_retreat, pour_upright).
learned(g8_destination_still_retreat).
provenance(g8_destination_still_retreat, layer, general).
provenance(g8_destination_still_retreat, level, 2).
provenance(g8_destination_still_retreat, support, 6).
provenance(g8_destination_still_retreat, kept, 3).
provenance(g8_destination_still_retreat, confidence_permille, 517).
provenance(g8_destination_still_retreat, antecedent, a63).
rule(g9_destination_still_retreat, defeasible, destination_still_retreat).
body(g9_destination_still_retreat, pour_below_rim).
body(g9_destination_still_retreat, pour_tilted_back).
learned(g9_destination_still_retreat).
provenance(g9_destination_still_retreat, layer, general).
provenance(g9_destination_still_retreat, level, 2).
provenance(g9_destination_still_retreat, support, 6).
provenance(g9_destination_still_retreat, kept, 3).
provenance(g9_destination_still_retreat, confidence_permille, 515).
provenance(g9_destination_still_retreat, antecedent, a60).
rule(g10_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g10_destination_still_retreat, light_liquid).
body(g10_destination_still_retreat, pour_below_rim).
learned(g10_destination_still_retreat).
provenance(g10_destination_still_retreat, layer, general).
provenance(g10_destination_still_retreat, level, 1).
provenance(g10_destination_still_retreat, support, 2).
provenance(g10_destination_still_retreat, kept, 0).
provenance(g10_destination_still_retreat, confidence_permille, 513).
provenance(g10_destination_still_retreat, antecedent, a82).
rule(g11_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g11_destination_still_retreat, approach_lowering).
body(g11_destination_still_retreat, pour_below_rim).
learned(g11_destination_still_retreat).
provenance(g11_destination_still_retreat, layer, general).
provenance(g11_destination_still_retreat, level, 1).
provenance(g11_destination_still_retreat, support, 49).
provenance(g11_destination_still_retreat, kept, 25).
provenance(g11_destination_still_retreat, confidence_permille, 516).
provenance(g11_destination_still_retreat, antecedent, a104).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 18).
provenance(g0_destination_still_settle, kept, 18).
provenance(g0_destination_still_settle, confidence_permille, 999).
provenance(g0_destination_still_settle, antecedent, a1).
rule(g1_destination_still_settle, defeasible, destination_still_settle).
body(g1_destination_still_settle, grippy_destination).
body(g1_destination_still_settle, pour_below_rim).
learned(g1_destination_still_settle).
provenance(g1_destination_still_settle, layer, general).
provenance(g1_destination_still_settle, level, 1).
provenance(g1_destination_still_settle, support, 6).
provenance(g1_destination_still_settle, kept, 3).
provenance(g1_destination_still_settle, confidence_permille, 611).
provenance(g1_destination_still_settle, antecedent, a74).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 18).
provenance(g0_destination_upright, kept, 18).
provenance(g0_destination_upright, confidence_permille, 999).
provenance(g0_destination_upright, antecedent, a1).
rule(g1_destination_upright, defeasible, destination_upright).
body(g1_destination_upright, pour_below_rim).
body(g1_destination_upright, retreat_moving_closer).
learned(g1_destination_upright).
provenance(g1_destination_upright, layer, general).
provenance(g1_destination_upright, level, 1).
provenance(g1_destination_upright, support, 2).
provenance(g1_destination_upright, kept, 0).
provenance(g1_destination_upright, confidence_permille, 542).
provenance(g1_destination_upright, antecedent, a62).
rule(g2_destination_upright, defeasible, destination_upright).
body(g2_destination_upright, end_below_rim).
learned(g2_destination_upright).
provenance(g2_destination_upright, layer, general).
provenance(g2_destination_upright, level, 1).
provenance(g2_destination_upright, support, 8).
provenance(g2_destination_upright, kept, 6).
provenance(g2_destination_upright, confidence_permille, 822).
provenance(g2_destination_upright, antecedent, a7).
rule(g3_destination_upright, defeasible, destination_upright).
body(g3_destination_upright, end_tilted_back).
body(g3_destination_upright, pour_below_rim).
learned(g3_destination_upright).
provenance(g3_destination_upright, layer, general).
provenance(g3_destination_upright, level, 1).
provenance(g3_destination_upright, support, 2).
provenance(g3_destination_upright, kept, 0).
provenance(g3_destination_upright, confidence_permille, 590).
provenance(g3_destination_upright, antecedent, a73).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 18).
provenance(g0_source_clear, kept, 17).
provenance(g0_source_clear, confidence_permille, 953).
provenance(g0_source_clear, antecedent, a1).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, pour_below_rim).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 210).
provenance(g1_source_clear, kept, 210).
provenance(g1_source_clear, confidence_permille, 1000).
provenance(g1_source_clear, antecedent, a4).
rule(g2_source_clear, defeasible, neg(source_clear)).
body(g2_source_clear, pour_low).
learned(g2_source_clear).
provenance(g2_source_clear, layer, general).
provenance(g2_source_clear, level, 1).
provenance(g2_source_clear, support, 37).
provenance(g2_source_clear, kept, 25).
provenance(g2_source_clear, confidence_permille, 674).
provenance(g2_source_clear, antecedent, a42).
rule(g3_source_clear, defeasible, neg(source_clear)).
body(g3_source_clear, end_below_rim).
learned(g3_source_clear).
provenance(g3_source_clear, layer, general).
provenance(g3_source_clear, level, 1).
provenance(g3_source_clear, support, 8).
provenance(g3_source_clear, kept, 6).
provenance(g3_source_clear, confidence_permille, 667).
provenance(g3_source_clear, antecedent, a7).
rule(g4_source_clear, defeasible, source_clear).
body(g4_source_clear, start_below_rim).
learned(g4_source_clear).
provenance(g4_source_clear, layer, general).
provenance(g4_source_clear, level, 1).
provenance(g4_source_clear, support, 20).
provenance(g4_source_clear, kept, 10).
provenance(g4_source_clear, confidence_permille, 514).
provenance(g4_source_clear, antecedent, a2).
rule(g5_source_clear, defeasible, source_clear).
body(g5_source_clear, pour_to_side).
learned(g5_source_clear).
provenance(g5_source_clear, layer, general).
provenance(g5_source_clear, level, 1).
provenance(g5_source_clear, support, 23).
provenance(g5_source_clear, kept, 23).
provenance(g5_source_clear, confidence_permille, 999).
provenance(g5_source_clear, antecedent, a18).
rule(g6_source_clear, defeasible, source_clear).
body(g6_source_clear, pour_below_rim).
body(g6_source_clear, pour_far_away).
learned(g6_source_clear).
provenance(g6_source_clear, layer, general).
provenance(g6_source_clear, level, 2).
provenance(g6_source_clear, support, 12).
provenance(g6_source_clear, kept, 12).
provenance(g6_source_clear, confidence_permille, 996).
provenance(g6_source_clear, antecedent, a55).
rule(g7_source_clear, defeasible, source_clear).
body(g7_source_clear, pour_slightly_tilted).
learned(g7_source_clear).
provenance(g7_source_clear, layer, general).
provenance(g7_source_clear, level, 1).
provenance(g7_source_clear, support, 6).
provenance(g7_source_clear, kept, 6).
provenance(g7_source_clear, confidence_permille, 999).
provenance(g7_source_clear, antecedent, a45).
rule(g8_source_clear, defeasible, source_clear).
body(g8_source_clear, pour_half_tilted).
learned(g8_source_clear).
provenance(g8_source_clear, layer, general).
provenance(g8_source_clear, level, 1).
provenance(g8_source_clear, support, 13).
provenance(g8_source_clear, kept, 13).
provenance(g8_source_clear, confidence_permille, 999).
provenance(g8_source_clear, antecedent, a48).
rule(g9_source_clear, defeasible, neg(source_clear)).
body(g9_source_clear, pour_low).
body(g9_source_clear, slippery_source).
learned(g9_source_clear).
provenance(g9_source_clear, layer, general).
provenance(g9_source_clear, level, 1).
provenance(g9_source_clear, support, 3).
provenance(g9_source_clear, kept, 1).
provenance(g9_source_clear, confidence_permille, 528).
provenance(g9_source_clear, antecedent, a96).
rule(g10_source_clear, defeasible, neg(source_clear)).
body(g10_source_clear, pour_low).
body(g10_source_clear, pour_steeply_tilted).
learned(g10_source_clear).
provenance(g10_source_clear, layer, general).
provenance(g10_source_clear, level, 1).
provenance(g10_source_clear, support, 19).
provenance(g10_source_clear, kept, 11).
provenance(g10_source_clear, confidence_permille, 568).
provenance(g10_source_clear, antecedent, a105).
rule(g11_source_clear, defeasible, source_clear).
body(g11_source_clear, dull_destination).
learned(g11_source_clear).
provenance(g11_source_clear, layer, general).
provenance(g11_source_clear, level, 1).
provenance(g11_source_clear, support, 4).
provenance(g11_source_clear, kept, 3).
provenance(g11_source_clear, confidence_permille, 849).
provenance(g11_source_clear, antecedent, a11).
rule(g0_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 18).
provenance(g0_liquid_leaves_source, kept, 18).
provenance(g0_liquid_leaves_source, confidence_permille, 1000).
provenance(g0_liquid_leaves_source, antecedent, a1).
rule(g1_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g1_liquid_leaves_source, pour_half_tilted).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 13).
provenance(g1_liquid_leaves_source, kept, 13).
provenance(g1_liquid_leaves_source, confidence_permille, 1000).
provenance(g1_liquid_leaves_source, antecedent, a48).
rule(g2_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g2_liquid_leaves_source, pour_slightly_tilted).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 6).
provenance(g2_liquid_leaves_source, kept, 6).
provenance(g2_liquid_leaves_source, confidence_permille, 1000).
provenance(g2_liquid_leaves_source, antecedent, a45).
rule(g3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g3_liquid_leaves_source, pour_upright).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 4).
provenance(g3_liquid_leaves_source, kept, 4).
provenance(g3_liquid_leaves_source, confidence_permille, 1000).
provenance(g3_liquid_leaves_source, antecedent, a47).
rule(g4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g4_liquid_leaves_source, pour_tilted_back).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 4).
provenance(g4_liquid_leaves_source, kept, 4).
provenance(g4_liquid_leaves_source, confidence_permille, 1000).
provenance(g4_liquid_leaves_source, antecedent, a43).
rule(g5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g5_liquid_leaves_source, pour_steeply_tilted).
learned(g5_liquid_leaves_source).
provenance(g5_liquid_leaves_source, layer, general).
provenance(g5_liquid_leaves_source, level, 1).
provenance(g5_liquid_leaves_source, support, 23).
provenance(g5_liquid_leaves_source, kept, 16).
provenance(g5_liquid_leaves_source, confidence_permille, 710).
provenance(g5_liquid_leaves_source, antecedent, a53).
rule(g0_liquid_enters_destination, defeasible, liquid_enters_destination).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 18).
provenance(g0_liquid_enters_destination, kept, 18).
provenance(g0_liquid_enters_destination, confidence_permille, 968).
provenance(g0_liquid_enters_destination, antecedent, a1).
rule(g1_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g1_liquid_enters_destination, pour_to_side).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 23).
provenance(g1_liquid_enters_destination, kept, 15).
provenance(g1_liquid_enters_destination, confidence_permille, 678).
provenance(g1_liquid_enters_destination, antecedent, a18).
rule(g2_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g2_liquid_enters_destination, pour_far_away).
learned(g2_liquid_enters_destination).
provenance(g2_liquid_enters_destination, layer, general).
provenance(g2_liquid_enters_destination, level, 1).
provenance(g2_liquid_enters_destination, support, 10).
provenance(g2_liquid_enters_destination, kept, 10).
provenance(g2_liquid_enters_destination, confidence_permille, 991).
provenance(g2_liquid_enters_destination, antecedent, a20).
rule(g3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g3_liquid_enters_destination, pour_offset_sideways).
learned(g3_liquid_enters_destination).
provenance(g3_liquid_enters_destination, layer, general).
provenance(g3_liquid_enters_destination, level, 1).
provenance(g3_liquid_enters_destination, support, 32).
provenance(g3_liquid_enters_destination, kept, 20).
provenance(g3_liquid_enters_destination, confidence_permille, 629).
provenance(g3_liquid_enters_destination, antecedent, a34).
rule(g4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g4_liquid_enters_destination, pour_slightly_tilted).
learned(g4_liquid_enters_destination).
provenance(g4_liquid_enters_destination, layer, general).
provenance(g4_liquid_enters_destination, level, 1).
provenance(g4_liquid_enters_destination, support, 6).
provenance(g4_liquid_enters_destination, kept, 6).
provenance(g4_liquid_enters_destination, confidence_permille, 985).
provenance(g4_liquid_enters_destination, antecedent, a45).
rule(g5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g5_liquid_enters_destination, pour_upright).
learned(g5_liquid_enters_destination).
provenance(g5_liquid_enters_destination, layer, general).
provenance(g5_liquid_enters_destination, level, 1).
provenance(g5_liquid_enters_destination, support, 4).
provenance(g5_liquid_enters_destination, kept, 4).
provenance(g5_liquid_enters_destination, confidence_permille, 982).
provenance(g5_liquid_enters_destination, antecedent, a47).
rule(g6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g6_liquid_enters_destination, pour_tilted_back).
learned(g6_liquid_enters_destination).
provenance(g6_liquid_enters_destination, layer, general).
provenance(g6_liquid_enters_destination, level, 1).
provenance(g6_liquid_enters_destination, support, 4).
provenance(g6_liquid_enters_destination, kept, 4).
provenance(g6_liquid_enters_destination, confidence_permille, 981).
provenance(g6_liquid_enters_destination, antecedent, a43).
rule(g7_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g7_liquid_enters_destination, pour_half_tilted).
learned(g7_liquid_enters_destination).
provenance(g7_liquid_enters_destination, layer, general).
provenance(g7_liquid_enters_destination, level, 1).
provenance(g7_liquid_enters_destination, support, 13).
provenance(g7_liquid_enters_destination, kept, 13).
provenance(g7_liquid_enters_destination, confidence_permille, 974).
provenance(g7_liquid_enters_destination, antecedent, a48).
rule(g8_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g8_liquid_enters_destination, pour_below_rim).
learned(g8_liquid_enters_destination).
provenance(g8_liquid_enters_destination, layer, general).
provenance(g8_liquid_enters_destination, level, 1).
provenance(g8_liquid_enters_destination, support, 210).
provenance(g8_liquid_enters_destination, kept, 150).
provenance(g8_liquid_enters_destination, confidence_permille, 715).
provenance(g8_liquid_enters_destination, antecedent, a4).
rule(g9_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g9_liquid_enters_destination, pour_below_rim).
body(g9_liquid_enters_destination, pour_half_tilted).
learned(g9_liquid_enters_destination).
provenance(g9_liquid_enters_destination, layer, general).
provenance(g9_liquid_enters_destination, level, 2).
provenance(g9_liquid_enters_destination, support, 10).
provenance(g9_liquid_enters_destination, kept, 10).
provenance(g9_liquid_enters_destination, confidence_permille, 898).
provenance(g9_liquid_enters_destination, antecedent, a64).
rule(g10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g10_liquid_enters_destination, pour_below_rim).
body(g10_liquid_enters_destination, pour_slightly_tilted).
learned(g10_liquid_enters_destination).
provenance(g10_liquid_enters_destination, layer, general).
provenance(g10_liquid_enters_destination, level, 2).
provenance(g10_liquid_enters_destination, support, 4).
provenance(g10_liquid_enters_destination, kept, 4).
provenance(g10_liquid_enters_destination, confidence_permille, 829).
provenance(g10_liquid_enters_destination, antecedent, a59).
rule(g11_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g11_liquid_enters_destination, pour_low).
body(g11_liquid_enters_destination, start_below_rim).
learned(g11_liquid_enters_destination).
provenance(g11_liquid_enters_destination, layer, general).
provenance(g11_liquid_enters_destination, level, 1).
provenance(g11_liquid_enters_destination, support, 12).
provenance(g11_liquid_enters_destination, kept, 10).
provenance(g11_liquid_enters_destination, confidence_permille, 803).
provenance(g11_liquid_enters_destination, antecedent, a85).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 18).
provenance(g0_liquid_remains_in_destination, kept, 18).
provenance(g0_liquid_remains_in_destination, confidence_permille, 999).
provenance(g0_liquid_remains_in_destination, antecedent, a1).
rule(g1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g1_liquid_remains_in_destination, pour_below_rim).
learned(g1_liquid_remains_in_destination).
provenance(g1_liquid_remains_in_destination, layer, general).
provenance(g1_liquid_remains_in_destination, level, 1).
provenance(g1_liquid_remains_in_destination, support, 210).
provenance(g1_liquid_remains_in_destination, kept, 124).
provenance(g1_liquid_remains_in_destination, confidence_permille, 591).
provenance(g1_liquid_remains_in_destination, antecedent, a4).
rule(g2_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g2_liquid_remains_in_destination, pour_half_tilted).
body(g2_liquid_remains_in_destination, pour_low).
learned(g2_liquid_remains_in_destination).
provenance(g2_liquid_remains_in_destination, layer, general).
provenance(g2_liquid_remains_in_destination, level, 1).
provenance(g2_liquid_remains_in_destination, support, 9).
provenance(g2_liquid_remains_in_destination, kept, 6).
provenance(g2_liquid_remains_in_destination, confidence_permille, 567).
provenance(g2_liquid_remains_in_destination, antecedent, a94).
rule(g3_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g3_liquid_remains_in_destination, pour_below_rim).
body(g3_liquid_remains_in_destination, pour_half_tilted).
learned(g3_liquid_remains_in_destination).
provenance(g3_liquid_remains_in_destination, layer, general).
provenance(g3_liquid_remains_in_destination, level, 2).
provenance(g3_liquid_remains_in_destination, support, 10).
provenance(g3_liquid_remains_in_destination, kept, 10).
provenance(g3_liquid_remains_in_destination, confidence_permille, 951).
provenance(g3_liquid_remains_in_destination, antecedent, a64).
rule(g4_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g4_liquid_remains_in_destination, pour_below_rim).
body(g4_liquid_remains_in_destination, pour_slightly_tilted).
learned(g4_liquid_remains_in_destination).
provenance(g4_liquid_remains_in_destination, layer, general).
provenance(g4_liquid_remains_in_destination, level, 2).
provenance(g4_liquid_remains_in_destination, support, 4).
provenance(g4_liquid_remains_in_destination, kept, 4).
provenance(g4_liquid_remains_in_destination, confidence_permille, 922).
provenance(g4_liquid_remains_in_destination, antecedent, a59).
rule(g5_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g5_liquid_remains_in_destination, pour_below_rim).
body(g5_liquid_remains_in_destination, pour_upright).
learned(g5_liquid_remains_in_destination).
provenance(g5_liquid_remains_in_destination, layer, general).
provenance(g5_liquid_remains_in_destination, level, 2).
provenance(g5_liquid_remains_in_destination, support, 6).
provenance(g5_liquid_remains_in_destination, kept, 5).
provenance(g5_liquid_remains_in_destination, confidence_permille, 821).
provenance(g5_liquid_remains_in_destination, antecedent, a63).
rule(g6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g6_liquid_remains_in_destination, pour_below_rim).
body(g6_liquid_remains_in_destination, pour_far_away).
learned(g6_liquid_remains_in_destination).
provenance(g6_liquid_remains_in_destination, layer, general).
provenance(g6_liquid_remains_in_destination, level, 1).
provenance(g6_liquid_remains_in_destination, support, 12).
provenance(g6_liquid_remains_in_destination, kept, 12).
provenance(g6_liquid_remains_in_destination, confidence_permille, 985).
provenance(g6_liquid_remains_in_destination, antecedent, a55).
rule(g7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g7_liquid_remains_in_destination, approach_raising).
body(g7_liquid_remains_in_destination, pour_below_rim).
learned(g7_liquid_remains_in_destination).
provenance(g7_liquid_remains_in_destination, layer, general).
provenance(g7_liquid_remains_in_destination, level, 1).
provenance(g7_liquid_remains_in_destination, support, 7).
provenance(g7_liquid_remains_in_destination, kept, 7).
provenance(g7_liquid_remains_in_destination, confidence_permille, 983).
provenance(g7_liquid_remains_in_destination, antecedent, a68).
rule(g8_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g8_liquid_remains_in_destination, pour_below_rim).
body(g8_liquid_remains_in_destination, start_below_rim).
learned(g8_liquid_remains_in_destination).
provenance(g8_liquid_remains_in_destination, layer, general).
provenance(g8_liquid_remains_in_destination, level, 1).
provenance(g8_liquid_remains_in_destination, support, 8).
provenance(g8_liquid_remains_in_destination, kept, 8).
provenance(g8_liquid_remains_in_destination, confidence_permille, 966).
provenance(g8_liquid_remains_in_destination, antecedent, a76).
rule(g9_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g9_liquid_remains_in_destination, pour_below_rim).
body(g9_liquid_remains_in_destination, start_low).
learned(g9_liquid_remains_in_destination).
provenance(g9_liquid_remains_in_destination, layer, general).
provenance(g9_liquid_remains_in_destination, level, 1).
provenance(g9_liquid_remains_in_destination, support, 8).
provenance(g9_liquid_remains_in_destination, kept, 8).
provenance(g9_liquid_remains_in_destination, confidence_permille, 965).
provenance(g9_liquid_remains_in_destination, antecedent, a75).
rule(g10_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g10_liquid_remains_in_destination, pour_below_rim).
body(g10_liquid_remains_in_destination, pour_tilted_back).
learned(g10_liquid_remains_in_destination).
provenance(g10_liquid_remains_in_destination, layer, general).
provenance(g10_liquid_remains_in_destination, level, 2).
provenance(g10_liquid_remains_in_destination, support, 6).
provenance(g10_liquid_remains_in_destination, kept, 4).
provenance(g10_liquid_remains_in_destination, confidence_permille, 737).
provenance(g10_liquid_remains_in_destination, antecedent, a60).
rule(g11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g11_liquid_remains_in_destination, approach_lowering).
body(g11_liquid_remains_in_destination, pour_below_rim).
learned(g11_liquid_remains_in_destination).
provenance(g11_liquid_remains_in_destination, layer, general).
provenance(g11_liquid_remains_in_destination, level, 1).
provenance(g11_liquid_remains_in_destination, support, 49).
provenance(g11_liquid_remains_in_destination, kept, 42).
provenance(g11_liquid_remains_in_destination, confidence_permille, 856).
provenance(g11_liquid_remains_in_destination, antecedent, a104).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 18).
provenance(g0_no_spill, kept, 18).
provenance(g0_no_spill, confidence_permille, 978).
provenance(g0_no_spill, antecedent, a1).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, pour_below_rim).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 210).
provenance(g1_no_spill, kept, 128).
provenance(g1_no_spill, confidence_permille, 609).
provenance(g1_no_spill, antecedent, a4).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, pour_to_side).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 23).
provenance(g2_no_spill, kept, 15).
provenance(g2_no_spill, confidence_permille, 673).
provenance(g2_no_spill, antecedent, a18).
rule(g3_no_spill, defeasible, neg(no_spill)).
body(g3_no_spill, pour_far_away).
learned(g3_no_spill).
provenance(g3_no_spill, layer, general).
provenance(g3_no_spill, level, 1).
provenance(g3_no_spill, support, 10).
provenance(g3_no_spill, kept, 10).
provenance(g3_no_spill, confidence_permille, 989).
provenance(g3_no_spill, antecedent, a20).
rule(g4_no_spill, defeasible, neg(no_spill)).
body(g4_no_spill, pour_offset_sideways).
learned(g4_no_spill).
provenance(g4_no_spill, layer, general).
provenance(g4_no_spill, level, 1).
provenance(g4_no_spill, support, 32).
provenance(g4_no_spill, kept, 20).
provenance(g4_no_spill, confidence_permille, 626).
provenance(g4_no_spill, antecedent, a34).
rule(g5_no_spill, defeasible, no_spill).
body(g5_no_spill, pour_half_tilted).
learned(g5_no_spill).
provenance(g5_no_spill, layer, general).
provenance(g5_no_spill, level, 1).
provenance(g5_no_spill, support, 13).
provenance(g5_no_spill, kept, 13).
provenance(g5_no_spill, confidence_permille, 1000).
provenance(g5_no_spill, antecedent, a48).
rule(g6_no_spill, defeasible, no_spill).
body(g6_no_spill, pour_upright).
learned(g6_no_spill).
provenance(g6_no_spill, layer, general).
provenance(g6_no_spill, level, 1).
provenance(g6_no_spill, support, 4).
provenance(g6_no_spill, kept, 4).
provenance(g6_no_spill, confidence_permille, 1000).
provenance(g6_no_spill, antecedent, a47).
rule(g7_no_spill, defeasible, no_spill).
body(g7_no_spill, pour_slightly_tilted).
learned(g7_no_spill).
provenance(g7_no_spill, layer, general).
provenance(g7_no_spill, level, 1).
provenance(g7_no_spill, support, 6).
provenance(g7_no_spill, kept, 6).
provenance(g7_no_spill, confidence_permille, 1000).
provenance(g7_no_spill, antecedent, a45).
rule(g8_no_spill, defeasible, no_spill).
body(g8_no_spill, pour_very_high).
learned(g8_no_spill).
provenance(g8_no_spill, layer, general).
provenance(g8_no_spill, level, 1).
provenance(g8_no_spill, support, 4).
provenance(g8_no_spill, kept, 2).
provenance(g8_no_spill, confidence_permille, 713).
provenance(g8_no_spill, antecedent, a6).
rule(g9_no_spill, defeasible, neg(no_spill)).
body(g9_no_spill, pour_low).
body(g9_no_spill, start_below_rim).
learned(g9_no_spill).
provenance(g9_no_spill, layer, general).
provenance(g9_no_spill, level, 1).
provenance(g9_no_spill, support, 12).
provenance(g9_no_spill, kept, 10).
provenance(g9_no_spill, confidence_permille, 781).
provenance(g9_no_spill, antecedent, a85).
rule(g10_no_spill, defeasible, neg(no_spill)).
body(g10_no_spill, approach_raising).
body(g10_no_spill, pour_low).
learned(g10_no_spill).
provenance(g10_no_spill, layer, general).
provenance(g10_no_spill, level, 1).
provenance(g10_no_spill, support, 16).
provenance(g10_no_spill, kept, 12).
provenance(g10_no_spill, confidence_permille, 734).
provenance(g10_no_spill, antecedent, a81).
rule(g11_no_spill, defeasible, no_spill).
body(g11_no_spill, pour_tilted_back).
learned(g11_no_spill).
provenance(g11_no_spill, layer, general).
provenance(g11_no_spill, level, 1).
provenance(g11_no_spill, support, 4).
provenance(g11_no_spill, kept, 4).
provenance(g11_no_spill, confidence_permille, 1000).
provenance(g11_no_spill, antecedent, a43).
sup(g10_destination_still_approach, g2_destination_still_approach).
sup(g10_destination_still_approach, g3_destination_still_approach).
sup(g10_destination_still_retreat, g2_destination_still_retreat).
sup(g10_destination_still_retreat, g3_destination_still_retreat).
sup(g10_liquid_enters_destination, g2_liquid_enters_destination).
sup(g10_liquid_enters_destination, g3_liquid_enters_destination).
sup(g10_no_spill, g11_no_spill).
sup(g10_no_spill, g5_no_spill).
sup(g10_no_spill, g6_no_spill).
sup(g10_no_spill, g7_no_spill).
sup(g10_source_clear, g11_source_clear).
sup(g10_source_clear, g4_source_clear).
sup(g10_source_clear, g5_source_clear).
sup(g11_destination_still_approach, g2_destination_still_approach).
sup(g11_destination_still_approach, g3_destination_still_approach).
sup(g11_destination_still_retreat, g2_destination_still_retreat).
sup(g11_destination_still_retreat, g3_destination_still_retreat).
sup(g11_destination_still_retreat, g9_destination_still_retreat).
sup(g11_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g11_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g11_no_spill, g1_no_spill).
sup(g11_no_spill, g2_no_spill).
sup(g11_no_spill, g3_no_spill).
sup(g11_no_spill, g4_no_spill).
sup(g11_source_clear, g2_source_clear).
sup(g11_source_clear, g3_source_clear).
sup(g1_destination_still_approach, g2_destination_still_approach).
sup(g1_destination_still_retreat, g2_destination_still_retreat).
sup(g1_source_clear, g11_source_clear).
sup(g1_source_clear, g4_source_clear).
sup(g1_source_clear, g7_source_clear).
sup(g1_source_clear, g8_source_clear).
sup(g2_liquid_enters_destination, g8_liquid_enters_destination).
sup(g2_source_clear, g4_source_clear).
sup(g3_destination_still_approach, g1_destination_still_approach).
sup(g3_destination_still_retreat, g1_destination_still_retreat).
sup(g3_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g3_no_spill, g8_no_spill).
sup(g3_source_clear, g4_source_clear).
sup(g4_destination_still_approach, g3_destination_still_approach).
sup(g4_destination_still_retreat, g10_destination_still_retreat).
sup(g4_liquid_enters_destination, g8_liquid_enters_destination).
sup(g4_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g5_destination_still_approach, g3_destination_still_approach).
sup(g5_destination_still_retreat, g10_destination_still_retreat).
sup(g5_destination_still_retreat, g11_destination_still_retreat).
sup(g5_liquid_enters_destination, g8_liquid_enters_destination).
sup(g5_no_spill, g1_no_spill).
sup(g5_no_spill, g2_no_spill).
sup(g5_no_spill, g3_no_spill).
sup(g5_no_spill, g4_no_spill).
sup(g5_source_clear, g2_source_clear).
sup(g5_source_clear, g3_source_clear).
sup(g6_destination_still_approach, g3_destination_still_approach).
sup(g6_destination_still_retreat, g10_destination_still_retreat).
sup(g6_liquid_enters_destination, g8_liquid_enters_destination).
sup(g6_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g6_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g6_liquid_remains_in_destination, g4_liquid_remains_in_destination).
sup(g6_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g6_no_spill, g1_no_spill).
sup(g6_no_spill, g2_no_spill).
sup(g6_no_spill, g3_no_spill).
sup(g6_no_spill, g4_no_spill).
sup(g6_source_clear, g3_source_clear).
sup(g7_destination_still_approach, g10_destination_still_approach).
sup(g7_destination_still_retreat, g10_destination_still_retreat).
sup(g7_destination_still_retreat, g11_destination_still_retreat).
sup(g7_liquid_enters_destination, g8_liquid_enters_destination).
sup(g7_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g7_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g7_liquid_remains_in_destination, g4_liquid_remains_in_destination).
sup(g7_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g7_no_spill, g1_no_spill).
sup(g7_no_spill, g2_no_spill).
sup(g7_no_spill, g3_no_spill).
sup(g7_no_spill, g4_no_spill).
sup(g7_source_clear, g2_source_clear).
sup(g7_source_clear, g3_source_clear).
sup(g8_destination_still_approach, g10_destination_still_approach).
sup(g8_destination_still_retreat, g10_destination_still_retreat).
sup(g8_destination_still_retreat, g11_destination_still_retreat).
sup(g8_liquid_enters_destination, g3_liquid_enters_destination).
sup(g8_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g8_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g8_liquid_remains_in_destination, g4_liquid_remains_in_destination).
sup(g8_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g8_no_spill, g2_no_spill).
sup(g8_no_spill, g4_no_spill).
sup(g8_source_clear, g2_source_clear).
sup(g8_source_clear, g3_source_clear).
sup(g9_destination_still_approach, g10_destination_still_approach).
sup(g9_destination_still_retreat, g10_destination_still_retreat).
sup(g9_liquid_enters_destination, g2_liquid_enters_destination).
sup(g9_liquid_enters_destination, g3_liquid_enters_destination).
sup(g9_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g9_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g9_liquid_remains_in_destination, g4_liquid_remains_in_destination).
sup(g9_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g9_no_spill, g11_no_spill).
sup(g9_no_spill, g5_no_spill).
sup(g9_no_spill, g6_no_spill).
sup(g9_no_spill, g7_no_spill).
sup(g9_source_clear, g11_source_clear).
sup(g9_source_clear, g4_source_clear).
sup(g9_source_clear, g5_source_clear).
sup(g9_source_clear, g7_source_clear).
sup(g9_source_clear, g8_source_clear).

% The explored antecedents, with or without a rule of their own:
% explored(A, Prop): the antecedent A says Prop (the ordinary pour,
% which says nothing, has none); held(A, E, Held, Pours): of the Pours
% pours that could have been drawn for A, Held held E. An answer for
% a scene explored cites them (docs/theory-formats.md).
held(a1, destination_still_approach, 18, 18).
held(a1, destination_still_retreat, 18, 18).
held(a1, destination_still_settle, 18, 18).
held(a1, destination_upright, 18, 18).
held(a1, source_clear, 17, 18).
held(a1, liquid_leaves_source, 18, 18).
held(a1, liquid_enters_destination, 18, 18).
held(a1, liquid_remains_in_destination, 18, 18).
held(a1, no_spill, 18, 18).
explored(a2, start_below_rim).
held(a2, destination_still_approach, 13, 20).
held(a2, destination_still_retreat, 19, 20).
held(a2, destination_still_settle, 20, 20).
held(a2, destination_upright, 20, 20).
held(a2, source_clear, 10, 20).
held(a2, liquid_leaves_source, 20, 20).
held(a2, liquid_enters_destination, 19, 20).
held(a2, liquid_remains_in_destination, 20, 20).
held(a2, no_spill, 19, 20).
explored(a3, start_low).
held(a3, destination_still_approach, 6, 6).
held(a3, destination_still_retreat, 6, 6).
held(a3, destination_still_settle, 6, 6).
held(a3, destination_upright, 6, 6).
held(a3, source_clear, 5, 6).
held(a3, liquid_leaves_source, 6, 6).
held(a3, liquid_enters_destination, 6, 6).
held(a3, liquid_remains_in_destination, 6, 6).
held(a3, no_spill, 6, 6).
explored(a4, pour_below_rim).
held(a4, destination_still_approach, 15, 210).
held(a4, destination_still_retreat, 55, 210).
held(a4, destination_still_settle, 162, 210).
held(a4, destination_upright, 162, 210).
held(a4, source_clear, 0, 210).
held(a4, liquid_leaves_source, 207, 210).
held(a4, liquid_enters_destination, 150, 210).
held(a4, liquid_remains_in_destination, 124, 210).
held(a4, no_spill, 82, 210).
explored(a5, pour_high).
held(a5, destination_still_approach, 4, 4).
held(a5, destination_still_retreat, 4, 4).
held(a5, destination_still_settle, 4, 4).
held(a5, destination_upright, 4, 4).
held(a5, source_clear, 4, 4).
held(a5, liquid_leaves_source, 4, 4).
held(a5, liquid_enters_destination, 4, 4).
held(a5, liquid_remains_in_destination, 4, 4).
held(a5, no_spill, 4, 4).
explored(a6, pour_very_high).
held(a6, destination_still_approach, 4, 4).
held(a6, destination_still_retreat, 4, 4).
held(a6, destination_still_settle, 4, 4).
held(a6, destination_upright, 4, 4).
held(a6, source_clear, 4, 4).
held(a6, liquid_leaves_source, 4, 4).
held(a6, liquid_enters_destination, 2, 4).
held(a6, liquid_remains_in_destination, 4, 4).
held(a6, no_spill, 2, 4).
explored(a7, end_below_rim).
held(a7, destination_still_approach, 8, 8).
held(a7, destination_still_retreat, 4, 8).
held(a7, destination_still_settle, 8, 8).
held(a7, destination_upright, 6, 8).
held(a7, source_clear, 2, 8).
held(a7, liquid_leaves_source, 8, 8).
held(a7, liquid_enters_destination, 8, 8).
held(a7, liquid_remains_in_destination, 8, 8).
held(a7, no_spill, 8, 8).
explored(a8, heavy_liquid).
held(a8, destination_still_approach, 3, 4).
held(a8, destination_still_retreat, 4, 4).
held(a8, destination_still_settle, 4, 4).
held(a8, destination_upright, 4, 4).
held(a8, source_clear, 4, 4).
held(a8, liquid_leaves_source, 4, 4).
held(a8, liquid_enters_destination, 4, 4).
held(a8, liquid_remains_in_destination, 4, 4).
held(a8, no_spill, 4, 4).
explored(a9, slow_retreat).
held(a9, destination_still_approach, 4, 4).
held(a9, destination_still_retreat, 4, 4).
held(a9, destination_still_settle, 4, 4).
held(a9, destination_upright, 4, 4).
held(a9, source_clear, 4, 4).
held(a9, liquid_leaves_source, 4, 4).
held(a9, liquid_enters_destination, 4, 4).
held(a9, liquid_remains_in_destination, 4, 4).
held(a9, no_spill, 4, 4).
explored(a10, grippy_source).
held(a10, destination_still_approach, 4, 4).
held(a10, destination_still_retreat, 4, 4).
held(a10, destination_still_settle, 4, 4).
held(a10, destination_upright, 4, 4).
held(a10, source_clear, 4, 4).
held(a10, liquid_leaves_source, 4, 4).
held(a10, liquid_enters_destination, 4, 4).
held(a10, liquid_remains_in_destination, 4, 4).
held(a10, no_spill, 4, 4).
explored(a11, dull_destination).
held(a11, destination_still_approach, 4, 4).
held(a11, destination_still_retreat, 4, 4).
held(a11, destination_still_settle, 4, 4).
held(a11, destination_upright, 4, 4).
held(a11, source_clear, 3, 4).
held(a11, liquid_leaves_source, 4, 4).
held(a11, liquid_enters_destination, 4, 4).
held(a11, liquid_remains_in_destination, 4, 4).
held(a11, no_spill, 4, 4).
explored(a12, slippery_source).
held(a12, destination_still_approach, 4, 4).
held(a12, destination_still_retreat, 4, 4).
held(a12, destination_still_settle, 4, 4).
held(a12, destination_upright, 4, 4).
held(a12, source_clear, 4, 4).
held(a12, liquid_leaves_source, 4, 4).
held(a12, liquid_enters_destination, 4, 4).
held(a12, liquid_remains_in_destination, 4, 4).
held(a12, no_spill, 4, 4).
explored(a13, fast_approach).
held(a13, destination_still_approach, 4, 4).
held(a13, destination_still_retreat, 4, 4).
held(a13, destination_still_settle, 4, 4).
held(a13, destination_upright, 4, 4).
held(a13, source_clear, 4, 4).
held(a13, liquid_leaves_source, 4, 4).
held(a13, liquid_enters_destination, 4, 4).
held(a13, liquid_remains_in_destination, 4, 4).
held(a13, no_spill, 4, 4).
explored(a14, end_low).
held(a14, destination_still_approach, 5, 5).
held(a14, destination_still_retreat, 5, 5).
held(a14, destination_still_settle, 5, 5).
held(a14, destination_upright, 5, 5).
held(a14, source_clear, 4, 5).
held(a14, liquid_leaves_source, 5, 5).
held(a14, liquid_enters_destination, 5, 5).
held(a14, liquid_remains_in_destination, 5, 5).
held(a14, no_spill, 5, 5).
explored(a15, sticky_liquid).
held(a15, destination_still_approach, 4, 4).
held(a15, destination_still_retreat, 4, 4).
held(a15, destination_still_settle, 4, 4).
held(a15, destination_upright, 4, 4).
held(a15, source_clear, 4, 4).
held(a15, liquid_leaves_source, 4, 4).
held(a15, liquid_enters_destination, 4, 4).
held(a15, liquid_remains_in_destination, 4, 4).
held(a15, no_spill, 4, 4).
explored(a16, very_much_liquid).
held(a16, destination_still_approach, 4, 4).
held(a16, destination_still_retreat, 4, 4).
held(a16, destination_still_settle, 4, 4).
held(a16, destination_upright, 4, 4).
held(a16, source_clear, 4, 4).
held(a16, liquid_leaves_source, 4, 4).
held(a16, liquid_enters_destination, 4, 4).
held(a16, liquid_remains_in_destination, 4, 4).
held(a16, no_spill, 4, 4).
explored(a17, light_destination).
held(a17, destination_still_approach, 3, 4).
held(a17, destination_still_retreat, 3, 4).
held(a17, destination_still_settle, 4, 4).
held(a17, destination_upright, 4, 4).
held(a17, source_clear, 4, 4).
held(a17, liquid_leaves_source, 4, 4).
held(a17, liquid_enters_destination, 4, 4).
held(a17, liquid_remains_in_destination, 4, 4).
held(a17, no_spill, 4, 4).
explored(a18, pour_to_side).
held(a18, destination_still_approach, 23, 23).
held(a18, destination_still_retreat, 23, 23).
held(a18, destination_still_settle, 23, 23).
held(a18, destination_upright, 23, 23).
held(a18, source_clear, 23, 23).
held(a18, liquid_leaves_source, 23, 23).
held(a18, liquid_enters_destination, 8, 23).
held(a18, liquid_remains_in_destination, 23, 23).
held(a18, no_spill, 8, 23).
explored(a19, dull_source).
held(a19, destination_still_approach, 3, 4).
held(a19, destination_still_retreat, 3, 4).
held(a19, destination_still_settle, 4, 4).
held(a19, destination_upright, 4, 4).
held(a19, source_clear, 3, 4).
held(a19, liquid_leaves_source, 4, 4).
held(a19, liquid_enters_destination, 4, 4).
held(a19, liquid_remains_in_destination, 4, 4).
held(a19, no_spill, 4, 4).
explored(a20, pour_far_away).
held(a20, destination_still_approach, 10, 10).
held(a20, destination_still_retreat, 10, 10).
held(a20, destination_still_settle, 10, 10).
held(a20, destination_upright, 10, 10).
held(a20, source_clear, 10, 10).
held(a20, liquid_leaves_source, 10, 10).
held(a20, liquid_enters_destination, 0, 10).
held(a20, liquid_remains_in_destination, 10, 10).
held(a20, no_spill, 0, 10).
explored(a21, grippy_destination).
held(a21, destination_still_approach, 4, 4).
held(a21, destination_still_retreat, 4, 4).
held(a21, destination_still_settle, 4, 4).
held(a21, destination_upright, 4, 4).
held(a21, source_clear, 4, 4).
held(a21, liquid_leaves_source, 4, 4).
held(a21, liquid_enters_destination, 4, 4).
held(a21, liquid_remains_in_destination, 4, 4).
held(a21, no_spill, 4, 4).
explored(a22, little_liquid).
held(a22, destination_still_approach, 4, 4).
held(a22, destination_still_retreat, 4, 4).
held(a22, destination_still_settle, 4, 4).
held(a22, destination_upright, 4, 4).
held(a22, source_clear, 4, 4).
held(a22, liquid_leaves_source, 4, 4).
held(a22, liquid_enters_destination, 4, 4).
held(a22, liquid_remains_in_destination, 4, 4).
held(a22, no_spill, 4, 4).
explored(a23, bouncy_liquid).
held(a23, destination_still_approach, 4, 4).
held(a23, destination_still_retreat, 4, 4).
held(a23, destination_still_settle, 4, 4).
held(a23, destination_upright, 4, 4).
held(a23, source_clear, 4, 4).
held(a23, liquid_leaves_source, 4, 4).
held(a23, liquid_enters_destination, 4, 4).
held(a23, liquid_remains_in_destination, 4, 4).
held(a23, no_spill, 4, 4).
explored(a24, end_tilted_back).
held(a24, destination_still_approach, 6, 6).
held(a24, destination_still_retreat, 6, 6).
held(a24, destination_still_settle, 6, 6).
held(a24, destination_upright, 6, 6).
held(a24, source_clear, 5, 6).
held(a24, liquid_leaves_source, 6, 6).
held(a24, liquid_enters_destination, 6, 6).
held(a24, liquid_remains_in_destination, 6, 6).
held(a24, no_spill, 6, 6).
explored(a25, end_near_rim).
held(a25, destination_still_approach, 4, 4).
held(a25, destination_still_retreat, 4, 4).
held(a25, destination_still_settle, 4, 4).
held(a25, destination_upright, 4, 4).
held(a25, source_clear, 4, 4).
held(a25, liquid_leaves_source, 4, 4).
held(a25, liquid_enters_destination, 4, 4).
held(a25, liquid_remains_in_destination, 4, 4).
held(a25, no_spill, 4, 4).
explored(a26, light_source).
held(a26, destination_still_approach, 4, 4).
held(a26, destination_still_retreat, 4, 4).
held(a26, destination_still_settle, 4, 4).
held(a26, destination_upright, 4, 4).
held(a26, source_clear, 4, 4).
held(a26, liquid_leaves_source, 4, 4).
held(a26, liquid_enters_destination, 4, 4).
held(a26, liquid_remains_in_destination, 4, 4).
held(a26, no_spill, 4, 4).
explored(a27, end_rolled).
held(a27, destination_still_approach, 4, 4).
held(a27, destination_still_retreat, 4, 4).
held(a27, destination_still_settle, 4, 4).
held(a27, destination_upright, 4, 4).
held(a27, source_clear, 4, 4).
held(a27, liquid_leaves_source, 4, 4).
held(a27, liquid_enters_destination, 4, 4).
held(a27, liquid_remains_in_destination, 4, 4).
held(a27, no_spill, 4, 4).
explored(a28, end_centred).
held(a28, destination_still_approach, 4, 4).
held(a28, destination_still_retreat, 4, 4).
held(a28, destination_still_settle, 4, 4).
held(a28, destination_upright, 4, 4).
held(a28, source_clear, 4, 4).
held(a28, liquid_leaves_source, 4, 4).
held(a28, liquid_enters_destination, 4, 4).
held(a28, liquid_remains_in_destination, 4, 4).
held(a28, no_spill, 4, 4).
explored(a29, bouncy_destination).
held(a29, destination_still_approach, 4, 4).
held(a29, destination_still_retreat, 4, 4).
held(a29, destination_still_settle, 4, 4).
held(a29, destination_upright, 4, 4).
held(a29, source_clear, 4, 4).
held(a29, liquid_leaves_source, 4, 4).
held(a29, liquid_enters_destination, 4, 4).
held(a29, liquid_remains_in_destination, 4, 4).
held(a29, no_spill, 4, 4).
explored(a30, fast_retreat).
held(a30, destination_still_approach, 4, 4).
held(a30, destination_still_retreat, 4, 4).
held(a30, destination_still_settle, 4, 4).
held(a30, destination_upright, 4, 4).
held(a30, source_clear, 4, 4).
held(a30, liquid_leaves_source, 4, 4).
held(a30, liquid_enters_destination, 4, 4).
held(a30, liquid_remains_in_destination, 4, 4).
held(a30, no_spill, 4, 4).
explored(a31, heavy_destination).
held(a31, destination_still_approach, 4, 4).
held(a31, destination_still_retreat, 4, 4).
held(a31, destination_still_settle, 4, 4).
held(a31, destination_upright, 4, 4).
held(a31, source_clear, 4, 4).
held(a31, liquid_leaves_source, 4, 4).
held(a31, liquid_enters_destination, 4, 4).
held(a31, liquid_remains_in_destination, 4, 4).
held(a31, no_spill, 4, 4).
explored(a32, end_steeply_tilted).
held(a32, destination_still_approach, 4, 4).
held(a32, destination_still_retreat, 4, 4).
held(a32, destination_still_settle, 4, 4).
held(a32, destination_upright, 4, 4).
held(a32, source_clear, 4, 4).
held(a32, liquid_leaves_source, 4, 4).
held(a32, liquid_enters_destination, 4, 4).
held(a32, liquid_remains_in_destination, 4, 4).
held(a32, no_spill, 4, 4).
explored(a33, heavy_source).
held(a33, destination_still_approach, 4, 4).
held(a33, destination_still_retreat, 4, 4).
held(a33, destination_still_settle, 4, 4).
held(a33, destination_upright, 4, 4).
held(a33, source_clear, 4, 4).
held(a33, liquid_leaves_source, 4, 4).
held(a33, liquid_enters_destination, 4, 4).
held(a33, liquid_remains_in_destination, 4, 4).
held(a33, no_spill, 4, 4).
explored(a34, pour_offset_sideways).
held(a34, destination_still_approach, 31, 32).
held(a34, destination_still_retreat, 30, 32).
held(a34, destination_still_settle, 32, 32).
held(a34, destination_upright, 32, 32).
held(a34, source_clear, 26, 32).
held(a34, liquid_leaves_source, 32, 32).
held(a34, liquid_enters_destination, 12, 32).
held(a34, liquid_remains_in_destination, 32, 32).
held(a34, no_spill, 12, 32).
explored(a35, slow_approach).
held(a35, destination_still_approach, 4, 4).
held(a35, destination_still_retreat, 4, 4).
held(a35, destination_still_settle, 4, 4).
held(a35, destination_upright, 4, 4).
held(a35, source_clear, 3, 4).
held(a35, liquid_leaves_source, 4, 4).
held(a35, liquid_enters_destination, 4, 4).
held(a35, liquid_remains_in_destination, 4, 4).
held(a35, no_spill, 4, 4).
explored(a36, start_slightly_tilted).
held(a36, destination_still_approach, 4, 4).
held(a36, destination_still_retreat, 4, 4).
held(a36, destination_still_settle, 4, 4).
held(a36, destination_upright, 4, 4).
held(a36, source_clear, 3, 4).
held(a36, liquid_leaves_source, 4, 4).
held(a36, liquid_enters_destination, 4, 4).
held(a36, liquid_remains_in_destination, 4, 4).
held(a36, no_spill, 4, 4).
explored(a37, runny_liquid).
held(a37, destination_still_approach, 4, 4).
held(a37, destination_still_retreat, 4, 4).
held(a37, destination_still_settle, 4, 4).
held(a37, destination_upright, 4, 4).
held(a37, source_clear, 4, 4).
held(a37, liquid_leaves_source, 4, 4).
held(a37, liquid_enters_destination, 4, 4).
held(a37, liquid_remains_in_destination, 4, 4).
held(a37, no_spill, 4, 4).
explored(a38, start_centred).
held(a38, destination_still_approach, 4, 4).
held(a38, destination_still_retreat, 4, 4).
held(a38, destination_still_settle, 4, 4).
held(a38, destination_upright, 4, 4).
held(a38, source_clear, 4, 4).
held(a38, liquid_leaves_source, 4, 4).
held(a38, liquid_enters_destination, 4, 4).
held(a38, liquid_remains_in_destination, 4, 4).
held(a38, no_spill, 4, 4).
explored(a39, slippery_destination).
held(a39, destination_still_approach, 3, 4).
held(a39, destination_still_retreat, 3, 4).
held(a39, destination_still_settle, 4, 4).
held(a39, destination_upright, 4, 4).
held(a39, source_clear, 3, 4).
held(a39, liquid_leaves_source, 4, 4).
held(a39, liquid_enters_destination, 4, 4).
held(a39, liquid_remains_in_destination, 4, 4).
held(a39, no_spill, 4, 4).
explored(a40, end_upside_down).
held(a40, destination_still_approach, 3, 4).
held(a40, destination_still_retreat, 4, 4).
held(a40, destination_still_settle, 4, 4).
held(a40, destination_upright, 4, 4).
held(a40, source_clear, 3, 4).
held(a40, liquid_leaves_source, 4, 4).
held(a40, liquid_enters_destination, 4, 4).
held(a40, liquid_remains_in_destination, 4, 4).
held(a40, no_spill, 4, 4).
explored(a41, start_near_rim).
held(a41, destination_still_approach, 4, 4).
held(a41, destination_still_retreat, 4, 4).
held(a41, destination_still_settle, 4, 4).
held(a41, destination_upright, 4, 4).
held(a41, source_clear, 4, 4).
held(a41, liquid_leaves_source, 4, 4).
held(a41, liquid_enters_destination, 4, 4).
held(a41, liquid_remains_in_destination, 4, 4).
held(a41, no_spill, 4, 4).
explored(a42, pour_low).
held(a42, destination_still_approach, 22, 37).
held(a42, destination_still_retreat, 25, 37).
held(a42, destination_still_settle, 37, 37).
held(a42, destination_upright, 37, 37).
held(a42, source_clear, 12, 37).
held(a42, liquid_leaves_source, 37, 37).
held(a42, liquid_enters_destination, 33, 37).
held(a42, liquid_remains_in_destination, 37, 37).
held(a42, no_spill, 34, 37).
explored(a43, pour_tilted_back).
held(a43, destination_still_approach, 4, 4).
held(a43, destination_still_retreat, 4, 4).
held(a43, destination_still_settle, 4, 4).
held(a43, destination_upright, 4, 4).
held(a43, source_clear, 4, 4).
held(a43, liquid_leaves_source, 0, 4).
held(a43, liquid_enters_destination, 0, 4).
held(a43, liquid_remains_in_destination, 4, 4).
held(a43, no_spill, 4, 4).
explored(a44, dull_liquid).
held(a44, destination_still_approach, 4, 4).
held(a44, destination_still_retreat, 4, 4).
held(a44, destination_still_settle, 4, 4).
held(a44, destination_upright, 4, 4).
held(a44, source_clear, 4, 4).
held(a44, liquid_leaves_source, 4, 4).
held(a44, liquid_enters_destination, 4, 4).
held(a44, liquid_remains_in_destination, 4, 4).
held(a44, no_spill, 4, 4).
explored(a45, pour_slightly_tilted).
held(a45, destination_still_approach, 6, 6).
held(a45, destination_still_retreat, 6, 6).
held(a45, destination_still_settle, 6, 6).
held(a45, destination_upright, 6, 6).
held(a45, source_clear, 6, 6).
held(a45, liquid_leaves_source, 0, 6).
held(a45, liquid_enters_destination, 0, 6).
held(a45, liquid_remains_in_destination, 6, 6).
held(a45, no_spill, 6, 6).
explored(a46, end_half_tilted).
held(a46, destination_still_approach, 4, 4).
held(a46, destination_still_retreat, 4, 4).
held(a46, destination_still_settle, 4, 4).
held(a46, destination_upright, 4, 4).
held(a46, source_clear, 3, 4).
held(a46, liquid_leaves_source, 4, 4).
held(a46, liquid_enters_destination, 4, 4).
held(a46, liquid_remains_in_destination, 4, 4).
held(a46, no_spill, 4, 4).
explored(a47, pour_upright).
held(a47, destination_still_approach, 4, 4).
held(a47, destination_still_retreat, 4, 4).
held(a47, destination_still_settle, 4, 4).
held(a47, destination_upright, 4, 4).
held(a47, source_clear, 4, 4).
held(a47, liquid_leaves_source, 0, 4).
held(a47, liquid_enters_destination, 0, 4).
held(a47, liquid_remains_in_destination, 4, 4).
held(a47, no_spill, 4, 4).
explored(a48, pour_half_tilted).
held(a48, destination_still_approach, 13, 13).
held(a48, destination_still_retreat, 13, 13).
held(a48, destination_still_settle, 13, 13).
held(a48, destination_upright, 13, 13).
held(a48, source_clear, 13, 13).
held(a48, liquid_leaves_source, 0, 13).
held(a48, liquid_enters_destination, 0, 13).
held(a48, liquid_remains_in_destination, 13, 13).
held(a48, no_spill, 13, 13).
explored(a49, light_liquid).
held(a49, destination_still_approach, 4, 4).
held(a49, destination_still_retreat, 4, 4).
held(a49, destination_still_settle, 4, 4).
held(a49, destination_upright, 4, 4).
held(a49, source_clear, 4, 4).
held(a49, liquid_leaves_source, 4, 4).
held(a49, liquid_enters_destination, 4, 4).
held(a49, liquid_remains_in_destination, 4, 4).
held(a49, no_spill, 4, 4).
explored(a50, bouncy_source).
held(a50, destination_still_approach, 4, 4).
held(a50, destination_still_retreat, 4, 4).
held(a50, destination_still_settle, 4, 4).
held(a50, destination_upright, 4, 4).
held(a50, source_clear, 4, 4).
held(a50, liquid_leaves_source, 4, 4).
held(a50, liquid_enters_destination, 4, 4).
held(a50, liquid_remains_in_destination, 4, 4).
held(a50, no_spill, 4, 4).
explored(a51, start_tilted_back).
held(a51, destination_still_approach, 4, 4).
held(a51, destination_still_retreat, 4, 4).
held(a51, destination_still_settle, 4, 4).
held(a51, destination_upright, 4, 4).
held(a51, source_clear, 4, 4).
held(a51, liquid_leaves_source, 4, 4).
held(a51, liquid_enters_destination, 4, 4).
held(a51, liquid_remains_in_destination, 4, 4).
held(a51, no_spill, 4, 4).
explored(a52, end_slightly_tilted).
held(a52, destination_still_approach, 4, 4).
held(a52, destination_still_retreat, 4, 4).
held(a52, destination_still_settle, 4, 4).
held(a52, destination_upright, 4, 4).
held(a52, source_clear, 4, 4).
held(a52, liquid_leaves_source, 4, 4).
held(a52, liquid_enters_destination, 4, 4).
held(a52, liquid_remains_in_destination, 4, 4).
held(a52, no_spill, 4, 4).
explored(a53, pour_steeply_tilted).
held(a53, destination_still_approach, 23, 23).
held(a53, destination_still_retreat, 23, 23).
held(a53, destination_still_settle, 23, 23).
held(a53, destination_upright, 23, 23).
held(a53, source_clear, 23, 23).
held(a53, liquid_leaves_source, 16, 23).
held(a53, liquid_enters_destination, 15, 23).
held(a53, liquid_remains_in_destination, 23, 23).
held(a53, no_spill, 23, 23).
explored(a54, pour_rolled).
held(a54, destination_still_approach, 4, 4).
held(a54, destination_still_retreat, 4, 4).
held(a54, destination_still_settle, 4, 4).
held(a54, destination_upright, 4, 4).
held(a54, source_clear, 4, 4).
held(a54, liquid_leaves_source, 4, 4).
held(a54, liquid_enters_destination, 4, 4).
held(a54, liquid_remains_in_destination, 4, 4).
held(a54, no_spill, 4, 4).
explored(a55, pour_below_rim).
explored(a55, pour_far_away).
held(a55, destination_still_approach, 12, 12).
held(a55, destination_still_retreat, 12, 12).
held(a55, destination_still_settle, 12, 12).
held(a55, destination_upright, 12, 12).
held(a55, source_clear, 12, 12).
held(a55, liquid_leaves_source, 12, 12).
held(a55, liquid_enters_destination, 0, 12).
held(a55, liquid_remains_in_destination, 12, 12).
held(a55, no_spill, 0, 12).
explored(a56, pour_below_rim).
explored(a56, runny_liquid).
held(a56, destination_still_approach, 0, 4).
held(a56, destination_still_retreat, 1, 4).
held(a56, destination_still_settle, 4, 4).
held(a56, destination_upright, 4, 4).
held(a56, source_clear, 0, 4).
held(a56, liquid_leaves_source, 4, 4).
held(a56, liquid_enters_destination, 4, 4).
held(a56, liquid_remains_in_destination, 4, 4).
held(a56, no_spill, 4, 4).
explored(a57, pour_low).
explored(a57, pour_slightly_tilted).
held(a57, destination_still_approach, 7, 7).
held(a57, destination_still_retreat, 7, 7).
held(a57, destination_still_settle, 7, 7).
held(a57, destination_upright, 7, 7).
held(a57, source_clear, 6, 7).
held(a57, liquid_leaves_source, 0, 7).
held(a57, liquid_enters_destination, 0, 7).
held(a57, liquid_remains_in_destination, 5, 7).
held(a57, no_spill, 7, 7).
explored(a58, pour_low).
explored(a58, pour_to_side).
held(a58, destination_still_approach, 8, 8).
held(a58, destination_still_retreat, 8, 8).
held(a58, destination_still_settle, 8, 8).
held(a58, destination_upright, 8, 8).
held(a58, source_clear, 7, 8).
held(a58, liquid_leaves_source, 8, 8).
held(a58, liquid_enters_destination, 1, 8).
held(a58, liquid_remains_in_destination, 8, 8).
held(a58, no_spill, 1, 8).
explored(a59, pour_below_rim).
explored(a59, pour_slightly_tilted).
held(a59, destination_still_approach, 3, 4).
held(a59, destination_still_retreat, 3, 4).
held(a59, destination_still_settle, 4, 4).
held(a59, destination_upright, 4, 4).
held(a59, source_clear, 0, 4).
held(a59, liquid_leaves_source, 0, 4).
held(a59, liquid_enters_destination, 4, 4).
held(a59, liquid_remains_in_destination, 0, 4).
held(a59, no_spill, 4, 4).
explored(a60, pour_below_rim).
explored(a60, pour_tilted_back).
held(a60, destination_still_approach, 4, 6).
held(a60, destination_still_retreat, 3, 6).
held(a60, destination_still_settle, 6, 6).
held(a60, destination_upright, 4, 6).
held(a60, source_clear, 0, 6).
held(a60, liquid_leaves_source, 0, 6).
held(a60, liquid_enters_destination, 3, 6).
held(a60, liquid_remains_in_destination, 2, 6).
held(a60, no_spill, 6, 6).
explored(a61, approach_moving_away).
held(a61, destination_still_approach, 3, 3).
held(a61, destination_still_retreat, 3, 3).
held(a61, destination_still_settle, 3, 3).
held(a61, destination_upright, 3, 3).
held(a61, source_clear, 3, 3).
held(a61, liquid_leaves_source, 3, 3).
held(a61, liquid_enters_destination, 3, 3).
held(a61, liquid_remains_in_destination, 3, 3).
held(a61, no_spill, 3, 3).
explored(a62, pour_below_rim).
explored(a62, retreat_moving_closer).
held(a62, destination_still_approach, 0, 2).
held(a62, destination_still_retreat, 0, 2).
held(a62, destination_still_settle, 2, 2).
held(a62, destination_upright, 0, 2).
held(a62, source_clear, 0, 2).
held(a62, liquid_leaves_source, 2, 2).
held(a62, liquid_enters_destination, 2, 2).
held(a62, liquid_remains_in_destination, 0, 2).
held(a62, no_spill, 0, 2).
explored(a63, pour_below_rim).
explored(a63, pour_upright).
held(a63, destination_still_approach, 4, 6).
held(a63, destination_still_retreat, 3, 6).
held(a63, destination_still_settle, 6, 6).
held(a63, destination_upright, 6, 6).
held(a63, source_clear, 0, 6).
held(a63, liquid_leaves_source, 0, 6).
held(a63, liquid_enters_destination, 2, 6).
held(a63, liquid_remains_in_destination, 1, 6).
held(a63, no_spill, 6, 6).
explored(a64, pour_below_rim).
explored(a64, pour_half_tilted).
held(a64, destination_still_approach, 4, 10).
held(a64, destination_still_retreat, 6, 10).
held(a64, destination_still_settle, 10, 10).
held(a64, destination_upright, 10, 10).
held(a64, source_clear, 2, 10).
held(a64, liquid_leaves_source, 0, 10).
held(a64, liquid_enters_destination, 10, 10).
held(a64, liquid_remains_in_destination, 0, 10).
held(a64, no_spill, 10, 10).
explored(a65, pour_to_side).
explored(a65, pour_upright).
held(a65, destination_still_approach, 8, 8).
held(a65, destination_still_retreat, 8, 8).
held(a65, destination_still_settle, 8, 8).
held(a65, destination_upright, 8, 8).
held(a65, source_clear, 8, 8).
held(a65, liquid_leaves_source, 0, 8).
held(a65, liquid_enters_destination, 0, 8).
held(a65, liquid_remains_in_destination, 8, 8).
held(a65, no_spill, 8, 8).
explored(a66, pour_below_rim).
explored(a66, pour_steeply_tilted).
held(a66, destination_still_approach, 16, 107).
held(a66, destination_still_retreat, 34, 107).
held(a66, destination_still_settle, 90, 107).
held(a66, destination_upright, 84, 107).
held(a66, source_clear, 1, 107).
held(a66, liquid_leaves_source, 97, 107).
held(a66, liquid_enters_destination, 74, 107).
held(a66, liquid_remains_in_destination, 65, 107).
held(a66, no_spill, 52, 107).
explored(a67, pour_far_away).
explored(a67, pour_half_tilted).
held(a67, destination_still_approach, 6, 6).
held(a67, destination_still_retreat, 6, 6).
held(a67, destination_still_settle, 6, 6).
held(a67, destination_upright, 6, 6).
held(a67, source_clear, 6, 6).
held(a67, liquid_leaves_source, 0, 6).
held(a67, liquid_enters_destination, 0, 6).
held(a67, liquid_remains_in_destination, 6, 6).
held(a67, no_spill, 6, 6).
explored(a68, approach_raising).
explored(a68, pour_below_rim).
held(a68, destination_still_approach, 0, 7).
held(a68, destination_still_retreat, 5, 7).
held(a68, destination_still_settle, 6, 7).
held(a68, destination_upright, 7, 7).
held(a68, source_clear, 0, 7).
held(a68, liquid_leaves_source, 6, 7).
held(a68, liquid_enters_destination, 0, 7).
held(a68, liquid_remains_in_destination, 7, 7).
held(a68, no_spill, 1, 7).
explored(a69, pour_below_rim).
explored(a69, retreat_lowering).
held(a69, destination_still_approach, 1, 4).
held(a69, destination_still_retreat, 0, 4).
held(a69, destination_still_settle, 3, 4).
held(a69, destination_upright, 2, 4).
held(a69, source_clear, 0, 4).
held(a69, liquid_leaves_source, 4, 4).
held(a69, liquid_enters_destination, 4, 4).
held(a69, liquid_remains_in_destination, 1, 4).
held(a69, no_spill, 2, 4).
explored(a70, pour_below_rim).
explored(a70, pour_offset_sideways).
held(a70, destination_still_approach, 0, 4).
held(a70, destination_still_retreat, 1, 4).
held(a70, destination_still_settle, 2, 4).
held(a70, destination_upright, 4, 4).
held(a70, source_clear, 0, 4).
held(a70, liquid_leaves_source, 4, 4).
held(a70, liquid_enters_destination, 2, 4).
held(a70, liquid_remains_in_destination, 2, 4).
held(a70, no_spill, 1, 4).
explored(a71, pour_low).
explored(a71, slow_retreat).
held(a71, destination_still_approach, 3, 3).
held(a71, destination_still_retreat, 3, 3).
held(a71, destination_still_settle, 3, 3).
held(a71, destination_upright, 3, 3).
held(a71, source_clear, 1, 3).
held(a71, liquid_leaves_source, 3, 3).
held(a71, liquid_enters_destination, 3, 3).
held(a71, liquid_remains_in_destination, 3, 3).
held(a71, no_spill, 3, 3).
explored(a72, end_slightly_tilted).
explored(a72, pour_below_rim).
held(a72, destination_still_approach, 0, 2).
held(a72, destination_still_retreat, 0, 2).
held(a72, destination_still_settle, 1, 2).
held(a72, destination_upright, 2, 2).
held(a72, source_clear, 0, 2).
held(a72, liquid_leaves_source, 2, 2).
held(a72, liquid_enters_destination, 1, 2).
held(a72, liquid_remains_in_destination, 1, 2).
held(a72, no_spill, 0, 2).
explored(a73, end_tilted_back).
explored(a73, pour_below_rim).
held(a73, destination_still_approach, 0, 2).
held(a73, destination_still_retreat, 0, 2).
held(a73, destination_still_settle, 2, 2).
held(a73, destination_upright, 0, 2).
held(a73, source_clear, 0, 2).
held(a73, liquid_leaves_source, 1, 2).
held(a73, liquid_enters_destination, 2, 2).
held(a73, liquid_remains_in_destination, 0, 2).
held(a73, no_spill, 1, 2).
explored(a74, grippy_destination).
explored(a74, pour_below_rim).
held(a74, destination_still_approach, 0, 6).
held(a74, destination_still_retreat, 0, 6).
held(a74, destination_still_settle, 3, 6).
held(a74, destination_upright, 4, 6).
held(a74, source_clear, 0, 6).
held(a74, liquid_leaves_source, 6, 6).
held(a74, liquid_enters_destination, 3, 6).
held(a74, liquid_remains_in_destination, 4, 6).
held(a74, no_spill, 2, 6).
explored(a75, pour_below_rim).
explored(a75, start_low).
held(a75, destination_still_approach, 0, 8).
held(a75, destination_still_retreat, 3, 8).
held(a75, destination_still_settle, 8, 8).
held(a75, destination_upright, 8, 8).
held(a75, source_clear, 0, 8).
held(a75, liquid_leaves_source, 8, 8).
held(a75, liquid_enters_destination, 2, 8).
held(a75, liquid_remains_in_destination, 8, 8).
held(a75, no_spill, 2, 8).
explored(a76, pour_below_rim).
explored(a76, start_below_rim).
held(a76, destination_still_approach, 0, 8).
held(a76, destination_still_retreat, 5, 8).
held(a76, destination_still_settle, 7, 8).
held(a76, destination_upright, 8, 8).
held(a76, source_clear, 0, 8).
held(a76, liquid_leaves_source, 7, 8).
held(a76, liquid_enters_destination, 0, 8).
held(a76, liquid_remains_in_destination, 8, 8).
held(a76, no_spill, 1, 8).
explored(a77, pour_offset_sideways).
explored(a77, pour_slightly_tilted).
held(a77, destination_still_approach, 6, 6).
held(a77, destination_still_retreat, 6, 6).
held(a77, destination_still_settle, 6, 6).
held(a77, destination_upright, 6, 6).
held(a77, source_clear, 6, 6).
held(a77, liquid_leaves_source, 0, 6).
held(a77, liquid_enters_destination, 0, 6).
held(a77, liquid_remains_in_destination, 6, 6).
held(a77, no_spill, 6, 6).
explored(a78, start_mid_height).
held(a78, destination_still_approach, 4, 4).
held(a78, destination_still_retreat, 4, 4).
held(a78, destination_still_settle, 4, 4).
held(a78, destination_upright, 4, 4).
held(a78, source_clear, 4, 4).
held(a78, liquid_leaves_source, 4, 4).
held(a78, liquid_enters_destination, 4, 4).
held(a78, liquid_remains_in_destination, 4, 4).
held(a78, no_spill, 4, 4).
explored(a79, light_source).
explored(a79, pour_below_rim).
held(a79, destination_still_approach, 0, 2).
held(a79, destination_still_retreat, 0, 2).
held(a79, destination_still_settle, 1, 2).
held(a79, destination_upright, 2, 2).
held(a79, source_clear, 0, 2).
held(a79, liquid_leaves_source, 2, 2).
held(a79, liquid_enters_destination, 2, 2).
held(a79, liquid_remains_in_destination, 1, 2).
held(a79, no_spill, 1, 2).
explored(a80, pour_low).
explored(a80, start_low).
held(a80, destination_still_approach, 3, 13).
held(a80, destination_still_retreat, 11, 13).
held(a80, destination_still_settle, 12, 13).
held(a80, destination_upright, 12, 13).
held(a80, source_clear, 1, 13).
held(a80, liquid_leaves_source, 13, 13).
held(a80, liquid_enters_destination, 5, 13).
held(a80, liquid_remains_in_destination, 12, 13).
held(a80, no_spill, 5, 13).
explored(a81, approach_raising).
explored(a81, pour_low).
held(a81, destination_still_approach, 2, 16).
held(a81, destination_still_retreat, 16, 16).
held(a81, destination_still_settle, 16, 16).
held(a81, destination_upright, 16, 16).
held(a81, source_clear, 0, 16).
held(a81, liquid_leaves_source, 16, 16).
held(a81, liquid_enters_destination, 4, 16).
held(a81, liquid_remains_in_destination, 16, 16).
held(a81, no_spill, 4, 16).
explored(a82, light_liquid).
explored(a82, pour_below_rim).
held(a82, destination_still_approach, 1, 2).
held(a82, destination_still_retreat, 2, 2).
held(a82, destination_still_settle, 2, 2).
held(a82, destination_upright, 2, 2).
held(a82, source_clear, 0, 2).
held(a82, liquid_leaves_source, 2, 2).
held(a82, liquid_enters_destination, 2, 2).
held(a82, liquid_remains_in_destination, 2, 2).
held(a82, no_spill, 2, 2).
explored(a83, pour_to_side).
explored(a83, start_below_rim).
held(a83, destination_still_approach, 2, 2).
held(a83, destination_still_retreat, 2, 2).
held(a83, destination_still_settle, 2, 2).
held(a83, destination_upright, 2, 2).
held(a83, source_clear, 1, 2).
held(a83, liquid_leaves_source, 2, 2).
held(a83, liquid_enters_destination, 0, 2).
held(a83, liquid_remains_in_destination, 2, 2).
held(a83, no_spill, 1, 2).
explored(a84, pour_to_side).
explored(a84, start_low).
held(a84, destination_still_approach, 2, 2).
held(a84, destination_still_retreat, 2, 2).
held(a84, destination_still_settle, 2, 2).
held(a84, destination_upright, 2, 2).
held(a84, source_clear, 2, 2).
held(a84, liquid_leaves_source, 2, 2).
held(a84, liquid_enters_destination, 0, 2).
held(a84, liquid_remains_in_destination, 2, 2).
held(a84, no_spill, 0, 2).
explored(a85, pour_low).
explored(a85, start_below_rim).
held(a85, destination_still_approach, 0, 12).
held(a85, destination_still_retreat, 12, 12).
held(a85, destination_still_settle, 12, 12).
held(a85, destination_upright, 12, 12).
held(a85, source_clear, 0, 12).
held(a85, liquid_leaves_source, 12, 12).
held(a85, liquid_enters_destination, 2, 12).
held(a85, liquid_remains_in_destination, 12, 12).
held(a85, no_spill, 2, 12).
explored(a86, retreat_moving_closer).
held(a86, destination_still_approach, 6, 6).
held(a86, destination_still_retreat, 6, 6).
held(a86, destination_still_settle, 6, 6).
held(a86, destination_upright, 6, 6).
held(a86, source_clear, 6, 6).
held(a86, liquid_leaves_source, 6, 6).
held(a86, liquid_enters_destination, 6, 6).
held(a86, liquid_remains_in_destination, 6, 6).
held(a86, no_spill, 6, 6).
explored(a87, heavy_destination).
explored(a87, pour_below_rim).
held(a87, destination_still_approach, 2, 2).
held(a87, destination_still_retreat, 1, 2).
held(a87, destination_still_settle, 2, 2).
held(a87, destination_upright, 2, 2).
held(a87, source_clear, 0, 2).
held(a87, liquid_leaves_source, 2, 2).
held(a87, liquid_enters_destination, 2, 2).
held(a87, liquid_remains_in_destination, 2, 2).
held(a87, no_spill, 2, 2).
explored(a88, pour_far_away).
explored(a88, pour_steeply_tilted).
held(a88, destination_still_approach, 9, 9).
held(a88, destination_still_retreat, 9, 9).
held(a88, destination_still_settle, 9, 9).
held(a88, destination_upright, 9, 9).
held(a88, source_clear, 9, 9).
held(a88, liquid_leaves_source, 9, 9).
held(a88, liquid_enters_destination, 0, 9).
held(a88, liquid_remains_in_destination, 9, 9).
held(a88, no_spill, 0, 9).
explored(a89, pour_below_rim).
explored(a89, sticky_liquid).
held(a89, destination_still_approach, 0, 2).
held(a89, destination_still_retreat, 1, 2).
held(a89, destination_still_settle, 2, 2).
held(a89, destination_upright, 2, 2).
held(a89, source_clear, 0, 2).
held(a89, liquid_leaves_source, 2, 2).
held(a89, liquid_enters_destination, 1, 2).
held(a89, liquid_remains_in_destination, 2, 2).
held(a89, no_spill, 1, 2).
explored(a90, pour_steeply_tilted).
explored(a90, pour_to_side).
held(a90, destination_still_approach, 14, 14).
held(a90, destination_still_retreat, 14, 14).
held(a90, destination_still_settle, 14, 14).
held(a90, destination_upright, 14, 14).
held(a90, source_clear, 14, 14).
held(a90, liquid_leaves_source, 14, 14).
held(a90, liquid_enters_destination, 7, 14).
held(a90, liquid_remains_in_destination, 14, 14).
held(a90, no_spill, 7, 14).
explored(a91, dull_liquid).
explored(a91, pour_to_side).
held(a91, destination_still_approach, 2, 2).
held(a91, destination_still_retreat, 2, 2).
held(a91, destination_still_settle, 2, 2).
held(a91, destination_upright, 2, 2).
held(a91, source_clear, 2, 2).
held(a91, liquid_leaves_source, 2, 2).
held(a91, liquid_enters_destination, 0, 2).
held(a91, liquid_remains_in_destination, 2, 2).
held(a91, no_spill, 1, 2).
explored(a92, light_destination).
explored(a92, pour_below_rim).
held(a92, destination_still_approach, 1, 2).
held(a92, destination_still_retreat, 1, 2).
held(a92, destination_still_settle, 2, 2).
held(a92, destination_upright, 2, 2).
held(a92, source_clear, 0, 2).
held(a92, liquid_leaves_source, 2, 2).
held(a92, liquid_enters_destination, 2, 2).
held(a92, liquid_remains_in_destination, 2, 2).
held(a92, no_spill, 2, 2).
explored(a93, bouncy_destination).
explored(a93, pour_below_rim).
held(a93, destination_still_approach, 1, 4).
held(a93, destination_still_retreat, 2, 4).
held(a93, destination_still_settle, 4, 4).
held(a93, destination_upright, 4, 4).
held(a93, source_clear, 0, 4).
held(a93, liquid_leaves_source, 4, 4).
held(a93, liquid_enters_destination, 4, 4).
held(a93, liquid_remains_in_destination, 4, 4).
held(a93, no_spill, 4, 4).
explored(a94, pour_half_tilted).
explored(a94, pour_low).
held(a94, destination_still_approach, 8, 9).
held(a94, destination_still_retreat, 8, 9).
held(a94, destination_still_settle, 9, 9).
held(a94, destination_upright, 9, 9).
held(a94, source_clear, 7, 9).
held(a94, liquid_leaves_source, 0, 9).
held(a94, liquid_enters_destination, 2, 9).
held(a94, liquid_remains_in_destination, 3, 9).
held(a94, no_spill, 9, 9).
explored(a95, pour_low).
explored(a95, pour_offset_sideways).
held(a95, destination_still_approach, 8, 10).
held(a95, destination_still_retreat, 8, 10).
held(a95, destination_still_settle, 10, 10).
held(a95, destination_upright, 10, 10).
held(a95, source_clear, 2, 10).
held(a95, liquid_leaves_source, 10, 10).
held(a95, liquid_enters_destination, 6, 10).
held(a95, liquid_remains_in_destination, 10, 10).
held(a95, no_spill, 6, 10).
explored(a96, pour_low).
explored(a96, slippery_source).
held(a96, destination_still_approach, 3, 3).
held(a96, destination_still_retreat, 3, 3).
held(a96, destination_still_settle, 3, 3).
held(a96, destination_upright, 3, 3).
held(a96, source_clear, 2, 3).
held(a96, liquid_leaves_source, 3, 3).
held(a96, liquid_enters_destination, 3, 3).
held(a96, liquid_remains_in_destination, 3, 3).
held(a96, no_spill, 3, 3).
explored(a97, dull_liquid).
explored(a97, pour_below_rim).
held(a97, destination_still_approach, 0, 2).
held(a97, destination_still_retreat, 0, 2).
held(a97, destination_still_settle, 2, 2).
held(a97, destination_upright, 2, 2).
held(a97, source_clear, 0, 2).
held(a97, liquid_leaves_source, 2, 2).
held(a97, liquid_enters_destination, 1, 2).
held(a97, liquid_remains_in_destination, 1, 2).
held(a97, no_spill, 0, 2).
explored(a98, end_low).
explored(a98, pour_low).
held(a98, destination_still_approach, 3, 4).
held(a98, destination_still_retreat, 3, 4).
held(a98, destination_still_settle, 4, 4).
held(a98, destination_upright, 4, 4).
held(a98, source_clear, 0, 4).
held(a98, liquid_leaves_source, 4, 4).
held(a98, liquid_enters_destination, 3, 4).
held(a98, liquid_remains_in_destination, 4, 4).
held(a98, no_spill, 3, 4).
explored(a99, pour_offset_sideways).
explored(a99, start_below_rim).
held(a99, destination_still_approach, 3, 4).
held(a99, destination_still_retreat, 4, 4).
held(a99, destination_still_settle, 4, 4).
held(a99, destination_upright, 4, 4).
held(a99, source_clear, 2, 4).
held(a99, liquid_leaves_source, 4, 4).
held(a99, liquid_enters_destination, 2, 4).
held(a99, liquid_remains_in_destination, 4, 4).
held(a99, no_spill, 2, 4).
explored(a100, light_destination).
explored(a100, pour_offset_sideways).
held(a100, destination_still_approach, 2, 2).
held(a100, destination_still_retreat, 2, 2).
held(a100, destination_still_settle, 2, 2).
held(a100, destination_upright, 2, 2).
held(a100, source_clear, 2, 2).
held(a100, liquid_leaves_source, 2, 2).
held(a100, liquid_enters_destination, 0, 2).
held(a100, liquid_remains_in_destination, 2, 2).
held(a100, no_spill, 0, 2).
explored(a101, heavy_liquid).
explored(a101, pour_below_rim).
held(a101, destination_still_approach, 0, 2).
held(a101, destination_still_retreat, 0, 2).
held(a101, destination_still_settle, 2, 2).
held(a101, destination_upright, 2, 2).
held(a101, source_clear, 0, 2).
held(a101, liquid_leaves_source, 2, 2).
held(a101, liquid_enters_destination, 2, 2).
held(a101, liquid_remains_in_destination, 1, 2).
held(a101, no_spill, 1, 2).
explored(a102, pour_below_rim).
explored(a102, pour_rolled).
held(a102, destination_still_approach, 0, 2).
held(a102, destination_still_retreat, 0, 2).
held(a102, destination_still_settle, 2, 2).
held(a102, destination_upright, 1, 2).
held(a102, source_clear, 0, 2).
held(a102, liquid_leaves_source, 2, 2).
held(a102, liquid_enters_destination, 2, 2).
held(a102, liquid_remains_in_destination, 0, 2).
held(a102, no_spill, 0, 2).
explored(a103, end_below_rim).
explored(a103, pour_offset_sideways).
held(a103, destination_still_approach, 6, 6).
held(a103, destination_still_retreat, 4, 6).
held(a103, destination_still_settle, 6, 6).
held(a103, destination_upright, 5, 6).
held(a103, source_clear, 2, 6).
held(a103, liquid_leaves_source, 6, 6).
held(a103, liquid_enters_destination, 4, 6).
held(a103, liquid_remains_in_destination, 6, 6).
held(a103, no_spill, 4, 6).
explored(a104, approach_lowering).
explored(a104, pour_below_rim).
held(a104, destination_still_approach, 3, 49).
held(a104, destination_still_retreat, 24, 49).
held(a104, destination_still_settle, 45, 49).
held(a104, destination_upright, 44, 49).
held(a104, source_clear, 0, 49).
held(a104, liquid_leaves_source, 48, 49).
held(a104, liquid_enters_destination, 22, 49).
held(a104, liquid_remains_in_destination, 42, 49).
held(a104, no_spill, 19, 49).
explored(a105, pour_low).
explored(a105, pour_steeply_tilted).
held(a105, destination_still_approach, 13, 19).
held(a105, destination_still_retreat, 13, 19).
held(a105, destination_still_settle, 19, 19).
held(a105, destination_upright, 19, 19).
held(a105, source_clear, 8, 19).
held(a105, liquid_leaves_source, 18, 19).
held(a105, liquid_enters_destination, 19, 19).
held(a105, liquid_remains_in_destination, 18, 19).
held(a105, no_spill, 19, 19).
