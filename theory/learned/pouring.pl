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
setting(whole_every, 3).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(learner, general).
setting(explored, 252).
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
setting(general_rules, 121).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 20).
provenance(g0_destination_still_approach, kept, 20).
provenance(g0_destination_still_approach, confidence_permille, 988).
provenance(g0_destination_still_approach, antecedent, a1).
rule(g1_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g1_destination_still_approach, pour_below_rim).
learned(g1_destination_still_approach).
provenance(g1_destination_still_approach, layer, general).
provenance(g1_destination_still_approach, level, 1).
provenance(g1_destination_still_approach, support, 82).
provenance(g1_destination_still_approach, kept, 75).
provenance(g1_destination_still_approach, confidence_permille, 914).
provenance(g1_destination_still_approach, antecedent, a4).
rule(g2_destination_still_approach, defeasible, destination_still_approach).
body(g2_destination_still_approach, start_below_rim).
learned(g2_destination_still_approach).
provenance(g2_destination_still_approach, layer, general).
provenance(g2_destination_still_approach, level, 1).
provenance(g2_destination_still_approach, support, 10).
provenance(g2_destination_still_approach, kept, 6).
provenance(g2_destination_still_approach, confidence_permille, 630).
provenance(g2_destination_still_approach, antecedent, a2).
rule(g3_destination_still_approach, defeasible, destination_still_approach).
body(g3_destination_still_approach, approach_raising).
learned(g3_destination_still_approach).
provenance(g3_destination_still_approach, layer, general).
provenance(g3_destination_still_approach, level, 1).
provenance(g3_destination_still_approach, support, 15).
provenance(g3_destination_still_approach, kept, 10).
provenance(g3_destination_still_approach, confidence_permille, 705).
provenance(g3_destination_still_approach, antecedent, a190).
rule(g4_destination_still_approach, defeasible, destination_still_approach).
body(g4_destination_still_approach, pour_below_rim).
body(g4_destination_still_approach, pour_far_away).
learned(g4_destination_still_approach).
provenance(g4_destination_still_approach, layer, general).
provenance(g4_destination_still_approach, level, 2).
provenance(g4_destination_still_approach, support, 2).
provenance(g4_destination_still_approach, kept, 2).
provenance(g4_destination_still_approach, confidence_permille, 912).
provenance(g4_destination_still_approach, antecedent, a91).
rule(g5_destination_still_approach, defeasible, destination_still_approach).
body(g5_destination_still_approach, pour_low).
learned(g5_destination_still_approach).
provenance(g5_destination_still_approach, layer, general).
provenance(g5_destination_still_approach, level, 1).
provenance(g5_destination_still_approach, support, 9).
provenance(g5_destination_still_approach, kept, 7).
provenance(g5_destination_still_approach, confidence_permille, 740).
provenance(g5_destination_still_approach, antecedent, a87).
rule(g6_destination_still_approach, defeasible, destination_still_approach).
body(g6_destination_still_approach, pour_slightly_tilted).
learned(g6_destination_still_approach).
provenance(g6_destination_still_approach, layer, general).
provenance(g6_destination_still_approach, level, 1).
provenance(g6_destination_still_approach, support, 5).
provenance(g6_destination_still_approach, kept, 5).
provenance(g6_destination_still_approach, confidence_permille, 999).
provenance(g6_destination_still_approach, antecedent, a24).
rule(g7_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g7_destination_still_approach, approach_raising).
body(g7_destination_still_approach, pour_low).
learned(g7_destination_still_approach).
provenance(g7_destination_still_approach, layer, general).
provenance(g7_destination_still_approach, level, 2).
provenance(g7_destination_still_approach, support, 6).
provenance(g7_destination_still_approach, kept, 6).
provenance(g7_destination_still_approach, confidence_permille, 902).
provenance(g7_destination_still_approach, antecedent, a137).
rule(g8_destination_still_approach, defeasible, destination_still_approach).
body(g8_destination_still_approach, pour_below_rim).
body(g8_destination_still_approach, pour_upright).
learned(g8_destination_still_approach).
provenance(g8_destination_still_approach, layer, general).
provenance(g8_destination_still_approach, level, 2).
provenance(g8_destination_still_approach, support, 6).
provenance(g8_destination_still_approach, kept, 4).
provenance(g8_destination_still_approach, confidence_permille, 619).
provenance(g8_destination_still_approach, antecedent, a120).
rule(g9_destination_still_approach, defeasible, destination_still_approach).
body(g9_destination_still_approach, slippery_destination).
learned(g9_destination_still_approach).
provenance(g9_destination_still_approach, layer, general).
provenance(g9_destination_still_approach, level, 1).
provenance(g9_destination_still_approach, support, 6).
provenance(g9_destination_still_approach, kept, 4).
provenance(g9_destination_still_approach, confidence_permille, 784).
provenance(g9_destination_still_approach, antecedent, a72).
rule(g10_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g10_destination_still_approach, pour_below_rim).
body(g10_destination_still_approach, pour_half_tilted).
learned(g10_destination_still_approach).
provenance(g10_destination_still_approach, layer, general).
provenance(g10_destination_still_approach, level, 1).
provenance(g10_destination_still_approach, support, 4).
provenance(g10_destination_still_approach, kept, 2).
provenance(g10_destination_still_approach, confidence_permille, 542).
provenance(g10_destination_still_approach, antecedent, a119).
rule(g11_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g11_destination_still_approach, end_upside_down).
body(g11_destination_still_approach, pour_below_rim).
learned(g11_destination_still_approach).
provenance(g11_destination_still_approach, layer, general).
provenance(g11_destination_still_approach, level, 1).
provenance(g11_destination_still_approach, support, 2).
provenance(g11_destination_still_approach, kept, 0).
provenance(g11_destination_still_approach, confidence_permille, 595).
provenance(g11_destination_still_approach, antecedent, a152).
rule(g12_destination_still_approach, defeasible, destination_still_approach).
body(g12_destination_still_approach, pour_below_rim).
body(g12_destination_still_approach, pour_slightly_tilted).
learned(g12_destination_still_approach).
provenance(g12_destination_still_approach, layer, general).
provenance(g12_destination_still_approach, level, 2).
provenance(g12_destination_still_approach, support, 8).
provenance(g12_destination_still_approach, kept, 7).
provenance(g12_destination_still_approach, confidence_permille, 533).
provenance(g12_destination_still_approach, antecedent, a122).
provenance(g12_destination_still_approach, doubt, parts_disagree).
rule(g13_destination_still_approach, defeasible, destination_still_approach).
body(g13_destination_still_approach, pour_centred).
body(g13_destination_still_approach, pour_offset_sideways).
learned(g13_destination_still_approach).
provenance(g13_destination_still_approach, layer, general).
provenance(g13_destination_still_approach, level, 1).
provenance(g13_destination_still_approach, support, 1).
provenance(g13_destination_still_approach, kept, 0).
provenance(g13_destination_still_approach, confidence_permille, 648).
provenance(g13_destination_still_approach, doubt, few_pours_depart).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 20).
provenance(g0_destination_still_retreat, kept, 20).
provenance(g0_destination_still_retreat, confidence_permille, 984).
provenance(g0_destination_still_retreat, antecedent, a1).
rule(g1_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g1_destination_still_retreat, pour_below_rim).
learned(g1_destination_still_retreat).
provenance(g1_destination_still_retreat, layer, general).
provenance(g1_destination_still_retreat, level, 1).
provenance(g1_destination_still_retreat, support, 82).
provenance(g1_destination_still_retreat, kept, 56).
provenance(g1_destination_still_retreat, confidence_permille, 682).
provenance(g1_destination_still_retreat, antecedent, a4).
rule(g2_destination_still_retreat, defeasible, destination_still_retreat).
body(g2_destination_still_retreat, end_below_rim).
learned(g2_destination_still_retreat).
provenance(g2_destination_still_retreat, layer, general).
provenance(g2_destination_still_retreat, level, 1).
provenance(g2_destination_still_retreat, support, 13).
provenance(g2_destination_still_retreat, kept, 6).
provenance(g2_destination_still_retreat, confidence_permille, 524).
provenance(g2_destination_still_retreat, antecedent, a33).
rule(g3_destination_still_retreat, defeasible, destination_still_retreat).
body(g3_destination_still_retreat, retreat_lowering).
learned(g3_destination_still_retreat).
provenance(g3_destination_still_retreat, layer, general).
provenance(g3_destination_still_retreat, level, 1).
provenance(g3_destination_still_retreat, support, 17).
provenance(g3_destination_still_retreat, kept, 9).
provenance(g3_destination_still_retreat, confidence_permille, 586).
provenance(g3_destination_still_retreat, antecedent, a13).
rule(g4_destination_still_retreat, defeasible, destination_still_retreat).
body(g4_destination_still_retreat, pour_half_tilted).
learned(g4_destination_still_retreat).
provenance(g4_destination_still_retreat, layer, general).
provenance(g4_destination_still_retreat, level, 1).
provenance(g4_destination_still_retreat, support, 5).
provenance(g4_destination_still_retreat, kept, 5).
provenance(g4_destination_still_retreat, confidence_permille, 997).
provenance(g4_destination_still_retreat, antecedent, a25).
rule(g5_destination_still_retreat, defeasible, destination_still_retreat).
body(g5_destination_still_retreat, pour_offset_sideways).
learned(g5_destination_still_retreat).
provenance(g5_destination_still_retreat, layer, general).
provenance(g5_destination_still_retreat, level, 1).
provenance(g5_destination_still_retreat, support, 11).
provenance(g5_destination_still_retreat, kept, 10).
provenance(g5_destination_still_retreat, confidence_permille, 930).
provenance(g5_destination_still_retreat, antecedent, a39).
rule(g6_destination_still_retreat, defeasible, destination_still_retreat).
body(g6_destination_still_retreat, pour_below_rim).
body(g6_destination_still_retreat, pour_far_away).
learned(g6_destination_still_retreat).
provenance(g6_destination_still_retreat, layer, general).
provenance(g6_destination_still_retreat, level, 2).
provenance(g6_destination_still_retreat, support, 2).
provenance(g6_destination_still_retreat, kept, 2).
provenance(g6_destination_still_retreat, confidence_permille, 885).
provenance(g6_destination_still_retreat, antecedent, a91).
rule(g7_destination_still_retreat, defeasible, destination_still_retreat).
body(g7_destination_still_retreat, slippery_destination).
learned(g7_destination_still_retreat).
provenance(g7_destination_still_retreat, layer, general).
provenance(g7_destination_still_retreat, level, 1).
provenance(g7_destination_still_retreat, support, 6).
provenance(g7_destination_still_retreat, kept, 4).
provenance(g7_destination_still_retreat, confidence_permille, 782).
provenance(g7_destination_still_retreat, antecedent, a72).
rule(g8_destination_still_retreat, defeasible, destination_still_retreat).
body(g8_destination_still_retreat, pour_very_high).
learned(g8_destination_still_retreat).
provenance(g8_destination_still_retreat, layer, general).
provenance(g8_destination_still_retreat, level, 1).
provenance(g8_destination_still_retreat, support, 5).
provenance(g8_destination_still_retreat, kept, 5).
provenance(g8_destination_still_retreat, confidence_permille, 997).
provenance(g8_destination_still_retreat, antecedent, a43).
rule(g9_destination_still_retreat, defeasible, destination_still_retreat).
body(g9_destination_still_retreat, pour_to_side).
learned(g9_destination_still_retreat).
provenance(g9_destination_still_retreat, layer, general).
provenance(g9_destination_still_retreat, level, 1).
provenance(g9_destination_still_retreat, support, 5).
provenance(g9_destination_still_retreat, kept, 5).
provenance(g9_destination_still_retreat, confidence_permille, 999).
provenance(g9_destination_still_retreat, antecedent, a60).
rule(g10_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g10_destination_still_retreat, pour_low).
body(g10_destination_still_retreat, retreat_lowering).
learned(g10_destination_still_retreat).
provenance(g10_destination_still_retreat, layer, general).
provenance(g10_destination_still_retreat, level, 2).
provenance(g10_destination_still_retreat, support, 10).
provenance(g10_destination_still_retreat, kept, 9).
provenance(g10_destination_still_retreat, confidence_permille, 830).
provenance(g10_destination_still_retreat, antecedent, a144).
rule(g11_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g11_destination_still_retreat, end_below_rim).
body(g11_destination_still_retreat, pour_low).
learned(g11_destination_still_retreat).
provenance(g11_destination_still_retreat, layer, general).
provenance(g11_destination_still_retreat, level, 2).
provenance(g11_destination_still_retreat, support, 9).
provenance(g11_destination_still_retreat, kept, 8).
provenance(g11_destination_still_retreat, confidence_permille, 838).
provenance(g11_destination_still_retreat, antecedent, a115).
rule(g12_destination_still_retreat, defeasible, destination_still_retreat).
body(g12_destination_still_retreat, pour_low).
body(g12_destination_still_retreat, pour_tilted_back).
learned(g12_destination_still_retreat).
provenance(g12_destination_still_retreat, layer, general).
provenance(g12_destination_still_retreat, level, 1).
provenance(g12_destination_still_retreat, support, 1).
provenance(g12_destination_still_retreat, kept, 1).
provenance(g12_destination_still_retreat, confidence_permille, 648).
provenance(g12_destination_still_retreat, doubt, beside_interaction).
provenance(g12_destination_still_retreat, beside, pour_below_rim).
provenance(g12_destination_still_retreat, beside, pour_tilted_back).
rule(g13_destination_still_retreat, defeasible, destination_still_retreat).
body(g13_destination_still_retreat, pour_centred).
body(g13_destination_still_retreat, pour_offset_sideways).
learned(g13_destination_still_retreat).
provenance(g13_destination_still_retreat, layer, general).
provenance(g13_destination_still_retreat, level, 1).
provenance(g13_destination_still_retreat, support, 1).
provenance(g13_destination_still_retreat, kept, 0).
provenance(g13_destination_still_retreat, confidence_permille, 648).
provenance(g13_destination_still_retreat, doubt, few_pours_depart).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 20).
provenance(g0_destination_still_settle, kept, 20).
provenance(g0_destination_still_settle, confidence_permille, 998).
provenance(g0_destination_still_settle, antecedent, a1).
rule(g1_destination_still_settle, defeasible, destination_still_settle).
body(g1_destination_still_settle, approach_moving_away).
body(g1_destination_still_settle, pour_below_rim).
learned(g1_destination_still_settle).
provenance(g1_destination_still_settle, layer, general).
provenance(g1_destination_still_settle, level, 1).
provenance(g1_destination_still_settle, support, 2).
provenance(g1_destination_still_settle, kept, 0).
provenance(g1_destination_still_settle, confidence_permille, 566).
provenance(g1_destination_still_settle, antecedent, a215).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 20).
provenance(g0_destination_upright, kept, 20).
provenance(g0_destination_upright, confidence_permille, 999).
provenance(g0_destination_upright, antecedent, a1).
rule(g1_destination_upright, defeasible, destination_upright).
body(g1_destination_upright, approach_moving_away).
body(g1_destination_upright, pour_below_rim).
learned(g1_destination_upright).
provenance(g1_destination_upright, layer, general).
provenance(g1_destination_upright, level, 1).
provenance(g1_destination_upright, support, 2).
provenance(g1_destination_upright, kept, 0).
provenance(g1_destination_upright, confidence_permille, 594).
provenance(g1_destination_upright, antecedent, a215).
rule(g2_destination_upright, defeasible, destination_upright).
body(g2_destination_upright, retreat_lowering).
learned(g2_destination_upright).
provenance(g2_destination_upright, layer, general).
provenance(g2_destination_upright, level, 1).
provenance(g2_destination_upright, support, 17).
provenance(g2_destination_upright, kept, 13).
provenance(g2_destination_upright, confidence_permille, 807).
provenance(g2_destination_upright, antecedent, a13).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 20).
provenance(g0_source_clear, kept, 19).
provenance(g0_source_clear, confidence_permille, 979).
provenance(g0_source_clear, antecedent, a1).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, pour_below_rim).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 82).
provenance(g1_source_clear, kept, 82).
provenance(g1_source_clear, confidence_permille, 1000).
provenance(g1_source_clear, antecedent, a4).
rule(g2_source_clear, defeasible, neg(source_clear)).
body(g2_source_clear, end_below_rim).
learned(g2_source_clear).
provenance(g2_source_clear, layer, general).
provenance(g2_source_clear, level, 1).
provenance(g2_source_clear, support, 13).
provenance(g2_source_clear, kept, 9).
provenance(g2_source_clear, confidence_permille, 642).
provenance(g2_source_clear, antecedent, a33).
rule(g3_source_clear, defeasible, neg(source_clear)).
body(g3_source_clear, start_below_rim).
learned(g3_source_clear).
provenance(g3_source_clear, layer, general).
provenance(g3_source_clear, level, 1).
provenance(g3_source_clear, support, 10).
provenance(g3_source_clear, kept, 7).
provenance(g3_source_clear, confidence_permille, 633).
provenance(g3_source_clear, antecedent, a2).
rule(g4_source_clear, defeasible, neg(source_clear)).
body(g4_source_clear, retreat_lowering).
learned(g4_source_clear).
provenance(g4_source_clear, layer, general).
provenance(g4_source_clear, level, 1).
provenance(g4_source_clear, support, 17).
provenance(g4_source_clear, kept, 10).
provenance(g4_source_clear, confidence_permille, 531).
provenance(g4_source_clear, antecedent, a13).
rule(g5_source_clear, defeasible, source_clear).
body(g5_source_clear, approach_raising).
learned(g5_source_clear).
provenance(g5_source_clear, layer, general).
provenance(g5_source_clear, level, 1).
provenance(g5_source_clear, support, 15).
provenance(g5_source_clear, kept, 7).
provenance(g5_source_clear, confidence_permille, 534).
provenance(g5_source_clear, antecedent, a190).
rule(g6_source_clear, defeasible, neg(source_clear)).
body(g6_source_clear, pour_low).
learned(g6_source_clear).
provenance(g6_source_clear, layer, general).
provenance(g6_source_clear, level, 1).
provenance(g6_source_clear, support, 9).
provenance(g6_source_clear, kept, 5).
provenance(g6_source_clear, confidence_permille, 528).
provenance(g6_source_clear, antecedent, a87).
rule(g7_source_clear, defeasible, source_clear).
body(g7_source_clear, pour_upright).
learned(g7_source_clear).
provenance(g7_source_clear, layer, general).
provenance(g7_source_clear, level, 1).
provenance(g7_source_clear, support, 4).
provenance(g7_source_clear, kept, 4).
provenance(g7_source_clear, confidence_permille, 998).
provenance(g7_source_clear, antecedent, a22).
rule(g8_source_clear, defeasible, source_clear).
body(g8_source_clear, pour_below_rim).
body(g8_source_clear, pour_far_away).
learned(g8_source_clear).
provenance(g8_source_clear, layer, general).
provenance(g8_source_clear, level, 2).
provenance(g8_source_clear, support, 2).
provenance(g8_source_clear, kept, 2).
provenance(g8_source_clear, confidence_permille, 964).
provenance(g8_source_clear, antecedent, a91).
rule(g9_source_clear, defeasible, source_clear).
body(g9_source_clear, pour_half_tilted).
learned(g9_source_clear).
provenance(g9_source_clear, layer, general).
provenance(g9_source_clear, level, 1).
provenance(g9_source_clear, support, 5).
provenance(g9_source_clear, kept, 5).
provenance(g9_source_clear, confidence_permille, 996).
provenance(g9_source_clear, antecedent, a25).
rule(g10_source_clear, defeasible, source_clear).
body(g10_source_clear, end_low).
learned(g10_source_clear).
provenance(g10_source_clear, layer, general).
provenance(g10_source_clear, level, 1).
provenance(g10_source_clear, support, 4).
provenance(g10_source_clear, kept, 3).
provenance(g10_source_clear, confidence_permille, 804).
provenance(g10_source_clear, antecedent, a161).
rule(g11_source_clear, defeasible, source_clear).
body(g11_source_clear, pour_slightly_tilted).
learned(g11_source_clear).
provenance(g11_source_clear, layer, general).
provenance(g11_source_clear, level, 1).
provenance(g11_source_clear, support, 5).
provenance(g11_source_clear, kept, 5).
provenance(g11_source_clear, confidence_permille, 998).
provenance(g11_source_clear, antecedent, a24).
rule(g12_source_clear, defeasible, neg(source_clear)).
body(g12_source_clear, end_low).
body(g12_source_clear, pour_below_rim).
learned(g12_source_clear).
provenance(g12_source_clear, layer, general).
provenance(g12_source_clear, level, 2).
provenance(g12_source_clear, support, 0).
provenance(g12_source_clear, kept, 0).
provenance(g12_source_clear, confidence_permille, 648).
provenance(g12_source_clear, doubt, unsettled).
rule(g13_source_clear, defeasible, source_clear).
body(g13_source_clear, end_low).
body(g13_source_clear, end_upside_down).
learned(g13_source_clear).
provenance(g13_source_clear, layer, general).
provenance(g13_source_clear, level, 1).
provenance(g13_source_clear, support, 2).
provenance(g13_source_clear, kept, 0).
provenance(g13_source_clear, confidence_permille, 550).
provenance(g13_source_clear, antecedent, a164).
provenance(g13_source_clear, doubt, pours_contradict).
rule(g14_source_clear, defeasible, source_clear).
body(g14_source_clear, end_low).
body(g14_source_clear, retreat_moving_closer).
learned(g14_source_clear).
provenance(g14_source_clear, layer, general).
provenance(g14_source_clear, level, 1).
provenance(g14_source_clear, support, 1).
provenance(g14_source_clear, kept, 1).
provenance(g14_source_clear, confidence_permille, 648).
provenance(g14_source_clear, doubt, beside_interaction).
provenance(g14_source_clear, beside, end_below_rim).
provenance(g14_source_clear, beside, retreat_moving_closer).
rule(g15_source_clear, defeasible, source_clear).
body(g15_source_clear, pour_centred).
body(g15_source_clear, pour_offset_sideways).
learned(g15_source_clear).
provenance(g15_source_clear, layer, general).
provenance(g15_source_clear, level, 1).
provenance(g15_source_clear, support, 1).
provenance(g15_source_clear, kept, 0).
provenance(g15_source_clear, confidence_permille, 648).
provenance(g15_source_clear, doubt, few_pours_depart).
rule(g0_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 20).
provenance(g0_liquid_leaves_source, kept, 20).
provenance(g0_liquid_leaves_source, confidence_permille, 1000).
provenance(g0_liquid_leaves_source, antecedent, a1).
rule(g1_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g1_liquid_leaves_source, pour_slightly_tilted).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 5).
provenance(g1_liquid_leaves_source, kept, 5).
provenance(g1_liquid_leaves_source, confidence_permille, 1000).
provenance(g1_liquid_leaves_source, antecedent, a24).
rule(g2_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g2_liquid_leaves_source, pour_half_tilted).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 5).
provenance(g2_liquid_leaves_source, kept, 5).
provenance(g2_liquid_leaves_source, confidence_permille, 1000).
provenance(g2_liquid_leaves_source, antecedent, a25).
rule(g3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g3_liquid_leaves_source, pour_tilted_back).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 4).
provenance(g3_liquid_leaves_source, kept, 4).
provenance(g3_liquid_leaves_source, confidence_permille, 1000).
provenance(g3_liquid_leaves_source, antecedent, a18).
rule(g4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g4_liquid_leaves_source, pour_upright).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 4).
provenance(g4_liquid_leaves_source, kept, 4).
provenance(g4_liquid_leaves_source, confidence_permille, 1000).
provenance(g4_liquid_leaves_source, antecedent, a22).
rule(g5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g5_liquid_leaves_source, end_upside_down).
learned(g5_liquid_leaves_source).
provenance(g5_liquid_leaves_source, layer, general).
provenance(g5_liquid_leaves_source, level, 1).
provenance(g5_liquid_leaves_source, support, 6).
provenance(g5_liquid_leaves_source, kept, 6).
provenance(g5_liquid_leaves_source, confidence_permille, 1000).
provenance(g5_liquid_leaves_source, antecedent, a37).
rule(g6_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g6_liquid_leaves_source, end_steeply_tilted).
learned(g6_liquid_leaves_source).
provenance(g6_liquid_leaves_source, layer, general).
provenance(g6_liquid_leaves_source, level, 1).
provenance(g6_liquid_leaves_source, support, 4).
provenance(g6_liquid_leaves_source, kept, 4).
provenance(g6_liquid_leaves_source, confidence_permille, 1000).
provenance(g6_liquid_leaves_source, antecedent, a46).
rule(g7_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g7_liquid_leaves_source, pour_steeply_tilted).
learned(g7_liquid_leaves_source).
provenance(g7_liquid_leaves_source, layer, general).
provenance(g7_liquid_leaves_source, level, 1).
provenance(g7_liquid_leaves_source, support, 8).
provenance(g7_liquid_leaves_source, kept, 6).
provenance(g7_liquid_leaves_source, confidence_permille, 731).
provenance(g7_liquid_leaves_source, antecedent, a229).
rule(g8_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g8_liquid_leaves_source, end_steeply_tilted).
body(g8_liquid_leaves_source, pour_slightly_tilted).
learned(g8_liquid_leaves_source).
provenance(g8_liquid_leaves_source, layer, general).
provenance(g8_liquid_leaves_source, level, 2).
provenance(g8_liquid_leaves_source, support, 4).
provenance(g8_liquid_leaves_source, kept, 2).
provenance(g8_liquid_leaves_source, confidence_permille, 649).
provenance(g8_liquid_leaves_source, antecedent, a139).
rule(g9_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g9_liquid_leaves_source, pour_centred).
body(g9_liquid_leaves_source, pour_steeply_tilted).
learned(g9_liquid_leaves_source).
provenance(g9_liquid_leaves_source, layer, general).
provenance(g9_liquid_leaves_source, level, 1).
provenance(g9_liquid_leaves_source, support, 2).
provenance(g9_liquid_leaves_source, kept, 1).
provenance(g9_liquid_leaves_source, confidence_permille, 637).
provenance(g9_liquid_leaves_source, antecedent, a232).
rule(g10_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g10_liquid_leaves_source, end_upside_down).
body(g10_liquid_leaves_source, pour_slightly_tilted).
learned(g10_liquid_leaves_source).
provenance(g10_liquid_leaves_source, layer, general).
provenance(g10_liquid_leaves_source, level, 2).
provenance(g10_liquid_leaves_source, support, 2).
provenance(g10_liquid_leaves_source, kept, 2).
provenance(g10_liquid_leaves_source, confidence_permille, 648).
provenance(g10_liquid_leaves_source, antecedent, a202).
provenance(g10_liquid_leaves_source, doubt, unsettled).
rule(g11_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g11_liquid_leaves_source, end_upside_down).
body(g11_liquid_leaves_source, pour_half_tilted).
learned(g11_liquid_leaves_source).
provenance(g11_liquid_leaves_source, layer, general).
provenance(g11_liquid_leaves_source, level, 2).
provenance(g11_liquid_leaves_source, support, 2).
provenance(g11_liquid_leaves_source, kept, 2).
provenance(g11_liquid_leaves_source, confidence_permille, 648).
provenance(g11_liquid_leaves_source, antecedent, a248).
provenance(g11_liquid_leaves_source, doubt, unsettled).
rule(g12_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g12_liquid_leaves_source, end_steeply_tilted).
body(g12_liquid_leaves_source, pour_half_tilted).
learned(g12_liquid_leaves_source).
provenance(g12_liquid_leaves_source, layer, general).
provenance(g12_liquid_leaves_source, level, 2).
provenance(g12_liquid_leaves_source, support, 0).
provenance(g12_liquid_leaves_source, kept, 0).
provenance(g12_liquid_leaves_source, confidence_permille, 648).
provenance(g12_liquid_leaves_source, doubt, unsettled).
rule(g0_liquid_enters_destination, defeasible, liquid_enters_destination).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 20).
provenance(g0_liquid_enters_destination, kept, 20).
provenance(g0_liquid_enters_destination, confidence_permille, 954).
provenance(g0_liquid_enters_destination, antecedent, a1).
rule(g1_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g1_liquid_enters_destination, pour_slightly_tilted).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 5).
provenance(g1_liquid_enters_destination, kept, 5).
provenance(g1_liquid_enters_destination, confidence_permille, 961).
provenance(g1_liquid_enters_destination, antecedent, a24).
rule(g2_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g2_liquid_enters_destination, pour_offset_sideways).
learned(g2_liquid_enters_destination).
provenance(g2_liquid_enters_destination, layer, general).
provenance(g2_liquid_enters_destination, level, 1).
provenance(g2_liquid_enters_destination, support, 11).
provenance(g2_liquid_enters_destination, kept, 9).
provenance(g2_liquid_enters_destination, confidence_permille, 796).
provenance(g2_liquid_enters_destination, antecedent, a39).
rule(g3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g3_liquid_enters_destination, pour_tilted_back).
learned(g3_liquid_enters_destination).
provenance(g3_liquid_enters_destination, layer, general).
provenance(g3_liquid_enters_destination, level, 1).
provenance(g3_liquid_enters_destination, support, 4).
provenance(g3_liquid_enters_destination, kept, 4).
provenance(g3_liquid_enters_destination, confidence_permille, 973).
provenance(g3_liquid_enters_destination, antecedent, a18).
rule(g4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g4_liquid_enters_destination, pour_upright).
learned(g4_liquid_enters_destination).
provenance(g4_liquid_enters_destination, layer, general).
provenance(g4_liquid_enters_destination, level, 1).
provenance(g4_liquid_enters_destination, support, 4).
provenance(g4_liquid_enters_destination, kept, 4).
provenance(g4_liquid_enters_destination, confidence_permille, 972).
provenance(g4_liquid_enters_destination, antecedent, a22).
rule(g5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g5_liquid_enters_destination, pour_half_tilted).
learned(g5_liquid_enters_destination).
provenance(g5_liquid_enters_destination, layer, general).
provenance(g5_liquid_enters_destination, level, 1).
provenance(g5_liquid_enters_destination, support, 5).
provenance(g5_liquid_enters_destination, kept, 5).
provenance(g5_liquid_enters_destination, confidence_permille, 948).
provenance(g5_liquid_enters_destination, antecedent, a25).
rule(g6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g6_liquid_enters_destination, pour_to_side).
learned(g6_liquid_enters_destination).
provenance(g6_liquid_enters_destination, layer, general).
provenance(g6_liquid_enters_destination, level, 1).
provenance(g6_liquid_enters_destination, support, 5).
provenance(g6_liquid_enters_destination, kept, 5).
provenance(g6_liquid_enters_destination, confidence_permille, 891).
provenance(g6_liquid_enters_destination, antecedent, a60).
rule(g7_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g7_liquid_enters_destination, pour_far_away).
learned(g7_liquid_enters_destination).
provenance(g7_liquid_enters_destination, layer, general).
provenance(g7_liquid_enters_destination, level, 1).
provenance(g7_liquid_enters_destination, support, 4).
provenance(g7_liquid_enters_destination, kept, 4).
provenance(g7_liquid_enters_destination, confidence_permille, 962).
provenance(g7_liquid_enters_destination, antecedent, a45).
rule(g8_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g8_liquid_enters_destination, pour_very_high).
learned(g8_liquid_enters_destination).
provenance(g8_liquid_enters_destination, layer, general).
provenance(g8_liquid_enters_destination, level, 1).
provenance(g8_liquid_enters_destination, support, 5).
provenance(g8_liquid_enters_destination, kept, 2).
provenance(g8_liquid_enters_destination, confidence_permille, 607).
provenance(g8_liquid_enters_destination, antecedent, a43).
rule(g9_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g9_liquid_enters_destination, pour_below_rim).
learned(g9_liquid_enters_destination).
provenance(g9_liquid_enters_destination, layer, general).
provenance(g9_liquid_enters_destination, level, 1).
provenance(g9_liquid_enters_destination, support, 82).
provenance(g9_liquid_enters_destination, kept, 63).
provenance(g9_liquid_enters_destination, confidence_permille, 770).
provenance(g9_liquid_enters_destination, antecedent, a4).
rule(g10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g10_liquid_enters_destination, pour_steeply_tilted).
learned(g10_liquid_enters_destination).
provenance(g10_liquid_enters_destination, layer, general).
provenance(g10_liquid_enters_destination, level, 1).
provenance(g10_liquid_enters_destination, support, 8).
provenance(g10_liquid_enters_destination, kept, 6).
provenance(g10_liquid_enters_destination, confidence_permille, 750).
provenance(g10_liquid_enters_destination, antecedent, a229).
rule(g11_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g11_liquid_enters_destination, pour_below_rim).
body(g11_liquid_enters_destination, pour_slightly_tilted).
learned(g11_liquid_enters_destination).
provenance(g11_liquid_enters_destination, layer, general).
provenance(g11_liquid_enters_destination, level, 2).
provenance(g11_liquid_enters_destination, support, 8).
provenance(g11_liquid_enters_destination, kept, 6).
provenance(g11_liquid_enters_destination, confidence_permille, 675).
provenance(g11_liquid_enters_destination, antecedent, a122).
rule(g12_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g12_liquid_enters_destination, approach_raising).
body(g12_liquid_enters_destination, pour_low).
learned(g12_liquid_enters_destination).
provenance(g12_liquid_enters_destination, layer, general).
provenance(g12_liquid_enters_destination, level, 1).
provenance(g12_liquid_enters_destination, support, 6).
provenance(g12_liquid_enters_destination, kept, 5).
provenance(g12_liquid_enters_destination, confidence_permille, 594).
provenance(g12_liquid_enters_destination, antecedent, a137).
provenance(g12_liquid_enters_destination, doubt, pours_contradict).
rule(g13_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g13_liquid_enters_destination, pour_below_rim).
body(g13_liquid_enters_destination, pour_half_tilted).
learned(g13_liquid_enters_destination).
provenance(g13_liquid_enters_destination, layer, general).
provenance(g13_liquid_enters_destination, level, 2).
provenance(g13_liquid_enters_destination, support, 4).
provenance(g13_liquid_enters_destination, kept, 3).
provenance(g13_liquid_enters_destination, confidence_permille, 646).
provenance(g13_liquid_enters_destination, antecedent, a119).
provenance(g13_liquid_enters_destination, doubt, pours_contradict).
rule(g14_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g14_liquid_enters_destination, pour_below_rim).
body(g14_liquid_enters_destination, pour_tilted_back).
learned(g14_liquid_enters_destination).
provenance(g14_liquid_enters_destination, layer, general).
provenance(g14_liquid_enters_destination, level, 2).
provenance(g14_liquid_enters_destination, support, 8).
provenance(g14_liquid_enters_destination, kept, 4).
provenance(g14_liquid_enters_destination, confidence_permille, 525).
provenance(g14_liquid_enters_destination, antecedent, a96).
provenance(g14_liquid_enters_destination, doubt, pours_contradict).
rule(g15_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g15_liquid_enters_destination, pour_below_rim).
body(g15_liquid_enters_destination, pour_upright).
learned(g15_liquid_enters_destination).
provenance(g15_liquid_enters_destination, layer, general).
provenance(g15_liquid_enters_destination, level, 2).
provenance(g15_liquid_enters_destination, support, 6).
provenance(g15_liquid_enters_destination, kept, 4).
provenance(g15_liquid_enters_destination, confidence_permille, 593).
provenance(g15_liquid_enters_destination, antecedent, a120).
provenance(g15_liquid_enters_destination, doubt, pours_contradict).
rule(g16_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g16_liquid_enters_destination, pour_low).
body(g16_liquid_enters_destination, pour_tilted_back).
learned(g16_liquid_enters_destination).
provenance(g16_liquid_enters_destination, layer, general).
provenance(g16_liquid_enters_destination, level, 1).
provenance(g16_liquid_enters_destination, support, 1).
provenance(g16_liquid_enters_destination, kept, 1).
provenance(g16_liquid_enters_destination, confidence_permille, 648).
provenance(g16_liquid_enters_destination, doubt, beside_interaction).
provenance(g16_liquid_enters_destination, beside, pour_below_rim).
provenance(g16_liquid_enters_destination, beside, pour_tilted_back).
rule(g17_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g17_liquid_enters_destination, pour_centred).
body(g17_liquid_enters_destination, pour_high).
learned(g17_liquid_enters_destination).
provenance(g17_liquid_enters_destination, layer, general).
provenance(g17_liquid_enters_destination, level, 1).
provenance(g17_liquid_enters_destination, support, 1).
provenance(g17_liquid_enters_destination, kept, 0).
provenance(g17_liquid_enters_destination, confidence_permille, 648).
provenance(g17_liquid_enters_destination, doubt, few_pours_depart).
rule(g18_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g18_liquid_enters_destination, pour_high).
body(g18_liquid_enters_destination, retreat_lowering).
learned(g18_liquid_enters_destination).
provenance(g18_liquid_enters_destination, layer, general).
provenance(g18_liquid_enters_destination, level, 1).
provenance(g18_liquid_enters_destination, support, 1).
provenance(g18_liquid_enters_destination, kept, 0).
provenance(g18_liquid_enters_destination, confidence_permille, 648).
provenance(g18_liquid_enters_destination, doubt, few_pours_depart).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 20).
provenance(g0_liquid_remains_in_destination, kept, 20).
provenance(g0_liquid_remains_in_destination, confidence_permille, 996).
provenance(g0_liquid_remains_in_destination, antecedent, a1).
rule(g1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g1_liquid_remains_in_destination, pour_below_rim).
learned(g1_liquid_remains_in_destination).
provenance(g1_liquid_remains_in_destination, layer, general).
provenance(g1_liquid_remains_in_destination, level, 1).
provenance(g1_liquid_remains_in_destination, support, 82).
provenance(g1_liquid_remains_in_destination, kept, 50).
provenance(g1_liquid_remains_in_destination, confidence_permille, 612).
provenance(g1_liquid_remains_in_destination, antecedent, a4).
rule(g2_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g2_liquid_remains_in_destination, retreat_lowering).
learned(g2_liquid_remains_in_destination).
provenance(g2_liquid_remains_in_destination, layer, general).
provenance(g2_liquid_remains_in_destination, level, 1).
provenance(g2_liquid_remains_in_destination, support, 17).
provenance(g2_liquid_remains_in_destination, kept, 16).
provenance(g2_liquid_remains_in_destination, confidence_permille, 951).
provenance(g2_liquid_remains_in_destination, antecedent, a13).
rule(g3_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g3_liquid_remains_in_destination, pour_below_rim).
body(g3_liquid_remains_in_destination, pour_slightly_tilted).
learned(g3_liquid_remains_in_destination).
provenance(g3_liquid_remains_in_destination, layer, general).
provenance(g3_liquid_remains_in_destination, level, 2).
provenance(g3_liquid_remains_in_destination, support, 8).
provenance(g3_liquid_remains_in_destination, kept, 8).
provenance(g3_liquid_remains_in_destination, confidence_permille, 836).
provenance(g3_liquid_remains_in_destination, antecedent, a122).
rule(g4_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g4_liquid_remains_in_destination, pour_half_tilted).
body(g4_liquid_remains_in_destination, pour_low).
learned(g4_liquid_remains_in_destination).
provenance(g4_liquid_remains_in_destination, layer, general).
provenance(g4_liquid_remains_in_destination, level, 1).
provenance(g4_liquid_remains_in_destination, support, 8).
provenance(g4_liquid_remains_in_destination, kept, 4).
provenance(g4_liquid_remains_in_destination, confidence_permille, 604).
provenance(g4_liquid_remains_in_destination, antecedent, a100).
rule(g5_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g5_liquid_remains_in_destination, pour_below_rim).
body(g5_liquid_remains_in_destination, pour_far_away).
learned(g5_liquid_remains_in_destination).
provenance(g5_liquid_remains_in_destination, layer, general).
provenance(g5_liquid_remains_in_destination, level, 1).
provenance(g5_liquid_remains_in_destination, support, 2).
provenance(g5_liquid_remains_in_destination, kept, 2).
provenance(g5_liquid_remains_in_destination, confidence_permille, 966).
provenance(g5_liquid_remains_in_destination, antecedent, a91).
rule(g6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g6_liquid_remains_in_destination, approach_raising).
body(g6_liquid_remains_in_destination, pour_below_rim).
learned(g6_liquid_remains_in_destination).
provenance(g6_liquid_remains_in_destination, layer, general).
provenance(g6_liquid_remains_in_destination, level, 1).
provenance(g6_liquid_remains_in_destination, support, 2).
provenance(g6_liquid_remains_in_destination, kept, 2).
provenance(g6_liquid_remains_in_destination, confidence_permille, 957).
provenance(g6_liquid_remains_in_destination, antecedent, a148).
rule(g7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g7_liquid_remains_in_destination, pour_below_rim).
body(g7_liquid_remains_in_destination, pour_offset_sideways).
learned(g7_liquid_remains_in_destination).
provenance(g7_liquid_remains_in_destination, layer, general).
provenance(g7_liquid_remains_in_destination, level, 1).
provenance(g7_liquid_remains_in_destination, support, 2).
provenance(g7_liquid_remains_in_destination, kept, 2).
provenance(g7_liquid_remains_in_destination, confidence_permille, 862).
provenance(g7_liquid_remains_in_destination, antecedent, a98).
rule(g8_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g8_liquid_remains_in_destination, end_upside_down).
body(g8_liquid_remains_in_destination, pour_below_rim).
learned(g8_liquid_remains_in_destination).
provenance(g8_liquid_remains_in_destination, layer, general).
provenance(g8_liquid_remains_in_destination, level, 1).
provenance(g8_liquid_remains_in_destination, support, 2).
provenance(g8_liquid_remains_in_destination, kept, 2).
provenance(g8_liquid_remains_in_destination, confidence_permille, 817).
provenance(g8_liquid_remains_in_destination, antecedent, a152).
rule(g9_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g9_liquid_remains_in_destination, fast_approach).
body(g9_liquid_remains_in_destination, pour_below_rim).
learned(g9_liquid_remains_in_destination).
provenance(g9_liquid_remains_in_destination, layer, general).
provenance(g9_liquid_remains_in_destination, level, 1).
provenance(g9_liquid_remains_in_destination, support, 2).
provenance(g9_liquid_remains_in_destination, kept, 2).
provenance(g9_liquid_remains_in_destination, confidence_permille, 782).
provenance(g9_liquid_remains_in_destination, antecedent, a220).
rule(g10_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g10_liquid_remains_in_destination, end_near_rim).
body(g10_liquid_remains_in_destination, pour_below_rim).
learned(g10_liquid_remains_in_destination).
provenance(g10_liquid_remains_in_destination, layer, general).
provenance(g10_liquid_remains_in_destination, level, 1).
provenance(g10_liquid_remains_in_destination, support, 2).
provenance(g10_liquid_remains_in_destination, kept, 2).
provenance(g10_liquid_remains_in_destination, confidence_permille, 756).
provenance(g10_liquid_remains_in_destination, antecedent, a218).
rule(g11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g11_liquid_remains_in_destination, pour_low).
body(g11_liquid_remains_in_destination, pour_steeply_tilted).
learned(g11_liquid_remains_in_destination).
provenance(g11_liquid_remains_in_destination, layer, general).
provenance(g11_liquid_remains_in_destination, level, 1).
provenance(g11_liquid_remains_in_destination, support, 1).
provenance(g11_liquid_remains_in_destination, kept, 1).
provenance(g11_liquid_remains_in_destination, confidence_permille, 648).
provenance(g11_liquid_remains_in_destination, doubt, beside_interaction).
provenance(g11_liquid_remains_in_destination, beside, pour_half_tilted).
provenance(g11_liquid_remains_in_destination, beside, pour_low).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 20).
provenance(g0_no_spill, kept, 20).
provenance(g0_no_spill, confidence_permille, 962).
provenance(g0_no_spill, antecedent, a1).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, pour_offset_sideways).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 11).
provenance(g1_no_spill, kept, 9).
provenance(g1_no_spill, confidence_permille, 775).
provenance(g1_no_spill, antecedent, a39).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, pour_to_side).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 5).
provenance(g2_no_spill, kept, 5).
provenance(g2_no_spill, confidence_permille, 861).
provenance(g2_no_spill, antecedent, a60).
rule(g3_no_spill, defeasible, neg(no_spill)).
body(g3_no_spill, pour_far_away).
learned(g3_no_spill).
provenance(g3_no_spill, layer, general).
provenance(g3_no_spill, level, 1).
provenance(g3_no_spill, support, 4).
provenance(g3_no_spill, kept, 4).
provenance(g3_no_spill, confidence_permille, 897).
provenance(g3_no_spill, antecedent, a45).
rule(g4_no_spill, defeasible, neg(no_spill)).
body(g4_no_spill, pour_below_rim).
learned(g4_no_spill).
provenance(g4_no_spill, layer, general).
provenance(g4_no_spill, level, 1).
provenance(g4_no_spill, support, 82).
provenance(g4_no_spill, kept, 44).
provenance(g4_no_spill, confidence_permille, 533).
provenance(g4_no_spill, antecedent, a4).
rule(g5_no_spill, defeasible, no_spill).
body(g5_no_spill, pour_very_high).
learned(g5_no_spill).
provenance(g5_no_spill, layer, general).
provenance(g5_no_spill, level, 1).
provenance(g5_no_spill, support, 5).
provenance(g5_no_spill, kept, 2).
provenance(g5_no_spill, confidence_permille, 613).
provenance(g5_no_spill, antecedent, a43).
rule(g6_no_spill, defeasible, no_spill).
body(g6_no_spill, pour_tilted_back).
learned(g6_no_spill).
provenance(g6_no_spill, layer, general).
provenance(g6_no_spill, level, 1).
provenance(g6_no_spill, support, 4).
provenance(g6_no_spill, kept, 4).
provenance(g6_no_spill, confidence_permille, 996).
provenance(g6_no_spill, antecedent, a18).
rule(g7_no_spill, defeasible, neg(no_spill)).
body(g7_no_spill, end_upside_down).
body(g7_no_spill, pour_tilted_back).
learned(g7_no_spill).
provenance(g7_no_spill, layer, general).
provenance(g7_no_spill, level, 2).
provenance(g7_no_spill, support, 4).
provenance(g7_no_spill, kept, 4).
provenance(g7_no_spill, confidence_permille, 844).
provenance(g7_no_spill, antecedent, a237).
rule(g8_no_spill, defeasible, neg(no_spill)).
body(g8_no_spill, end_upside_down).
body(g8_no_spill, pour_upright).
learned(g8_no_spill).
provenance(g8_no_spill, layer, general).
provenance(g8_no_spill, level, 1).
provenance(g8_no_spill, support, 4).
provenance(g8_no_spill, kept, 4).
provenance(g8_no_spill, confidence_permille, 829).
provenance(g8_no_spill, antecedent, a167).
rule(g9_no_spill, defeasible, no_spill).
body(g9_no_spill, pour_slightly_tilted).
learned(g9_no_spill).
provenance(g9_no_spill, layer, general).
provenance(g9_no_spill, level, 1).
provenance(g9_no_spill, support, 5).
provenance(g9_no_spill, kept, 5).
provenance(g9_no_spill, confidence_permille, 997).
provenance(g9_no_spill, antecedent, a24).
rule(g10_no_spill, defeasible, no_spill).
body(g10_no_spill, pour_half_tilted).
learned(g10_no_spill).
provenance(g10_no_spill, layer, general).
provenance(g10_no_spill, level, 1).
provenance(g10_no_spill, support, 5).
provenance(g10_no_spill, kept, 5).
provenance(g10_no_spill, confidence_permille, 997).
provenance(g10_no_spill, antecedent, a25).
rule(g11_no_spill, defeasible, no_spill).
body(g11_no_spill, pour_upright).
learned(g11_no_spill).
provenance(g11_no_spill, layer, general).
provenance(g11_no_spill, level, 1).
provenance(g11_no_spill, support, 4).
provenance(g11_no_spill, kept, 4).
provenance(g11_no_spill, confidence_permille, 996).
provenance(g11_no_spill, antecedent, a22).
rule(g12_no_spill, defeasible, no_spill).
body(g12_no_spill, pour_far_away).
body(g12_no_spill, pour_slightly_tilted).
learned(g12_no_spill).
provenance(g12_no_spill, layer, general).
provenance(g12_no_spill, level, 2).
provenance(g12_no_spill, support, 0).
provenance(g12_no_spill, kept, 0).
provenance(g12_no_spill, confidence_permille, 648).
provenance(g12_no_spill, doubt, unsettled).
rule(g13_no_spill, defeasible, no_spill).
body(g13_no_spill, pour_far_away).
body(g13_no_spill, pour_half_tilted).
learned(g13_no_spill).
provenance(g13_no_spill, layer, general).
provenance(g13_no_spill, level, 2).
provenance(g13_no_spill, support, 0).
provenance(g13_no_spill, kept, 0).
provenance(g13_no_spill, confidence_permille, 648).
provenance(g13_no_spill, doubt, unsettled).
rule(g14_no_spill, defeasible, no_spill).
body(g14_no_spill, pour_far_away).
body(g14_no_spill, pour_upright).
learned(g14_no_spill).
provenance(g14_no_spill, layer, general).
provenance(g14_no_spill, level, 2).
provenance(g14_no_spill, support, 0).
provenance(g14_no_spill, kept, 0).
provenance(g14_no_spill, confidence_permille, 648).
provenance(g14_no_spill, doubt, unsettled).
rule(g15_no_spill, defeasible, no_spill).
body(g15_no_spill, pour_far_away).
body(g15_no_spill, pour_tilted_back).
learned(g15_no_spill).
provenance(g15_no_spill, layer, general).
provenance(g15_no_spill, level, 2).
provenance(g15_no_spill, support, 2).
provenance(g15_no_spill, kept, 2).
provenance(g15_no_spill, confidence_permille, 648).
provenance(g15_no_spill, antecedent, a129).
provenance(g15_no_spill, doubt, unsettled).
rule(g16_no_spill, defeasible, no_spill).
body(g16_no_spill, pour_slightly_tilted).
body(g16_no_spill, pour_to_side).
learned(g16_no_spill).
provenance(g16_no_spill, layer, general).
provenance(g16_no_spill, level, 2).
provenance(g16_no_spill, support, 0).
provenance(g16_no_spill, kept, 0).
provenance(g16_no_spill, confidence_permille, 648).
provenance(g16_no_spill, doubt, unsettled).
rule(g17_no_spill, defeasible, no_spill).
body(g17_no_spill, pour_half_tilted).
body(g17_no_spill, pour_to_side).
learned(g17_no_spill).
provenance(g17_no_spill, layer, general).
provenance(g17_no_spill, level, 2).
provenance(g17_no_spill, support, 0).
provenance(g17_no_spill, kept, 0).
provenance(g17_no_spill, confidence_permille, 648).
provenance(g17_no_spill, doubt, unsettled).
rule(g18_no_spill, defeasible, no_spill).
body(g18_no_spill, pour_to_side).
body(g18_no_spill, pour_upright).
learned(g18_no_spill).
provenance(g18_no_spill, layer, general).
provenance(g18_no_spill, level, 2).
provenance(g18_no_spill, support, 0).
provenance(g18_no_spill, kept, 0).
provenance(g18_no_spill, confidence_permille, 648).
provenance(g18_no_spill, doubt, unsettled).
rule(g19_no_spill, defeasible, no_spill).
body(g19_no_spill, pour_tilted_back).
body(g19_no_spill, pour_to_side).
learned(g19_no_spill).
provenance(g19_no_spill, layer, general).
provenance(g19_no_spill, level, 2).
provenance(g19_no_spill, support, 0).
provenance(g19_no_spill, kept, 0).
provenance(g19_no_spill, confidence_permille, 648).
provenance(g19_no_spill, doubt, unsettled).
rule(g20_no_spill, defeasible, no_spill).
body(g20_no_spill, approach_raising).
body(g20_no_spill, pour_low).
learned(g20_no_spill).
provenance(g20_no_spill, layer, general).
provenance(g20_no_spill, level, 1).
provenance(g20_no_spill, support, 6).
provenance(g20_no_spill, kept, 2).
provenance(g20_no_spill, confidence_permille, 562).
provenance(g20_no_spill, antecedent, a137).
provenance(g20_no_spill, doubt, pours_contradict).
rule(g21_no_spill, defeasible, no_spill).
body(g21_no_spill, end_steeply_tilted).
body(g21_no_spill, pour_slightly_tilted).
learned(g21_no_spill).
provenance(g21_no_spill, layer, general).
provenance(g21_no_spill, level, 1).
provenance(g21_no_spill, support, 4).
provenance(g21_no_spill, kept, 2).
provenance(g21_no_spill, confidence_permille, 614).
provenance(g21_no_spill, antecedent, a139).
provenance(g21_no_spill, doubt, pours_contradict).
rule(g22_no_spill, defeasible, no_spill).
body(g22_no_spill, end_steeply_tilted).
body(g22_no_spill, pour_tilted_back).
learned(g22_no_spill).
provenance(g22_no_spill, layer, general).
provenance(g22_no_spill, level, 1).
provenance(g22_no_spill, support, 4).
provenance(g22_no_spill, kept, 2).
provenance(g22_no_spill, confidence_permille, 511).
provenance(g22_no_spill, antecedent, a51).
provenance(g22_no_spill, doubt, pours_contradict).
rule(g23_no_spill, defeasible, no_spill).
body(g23_no_spill, end_steeply_tilted).
body(g23_no_spill, pour_upright).
learned(g23_no_spill).
provenance(g23_no_spill, layer, general).
provenance(g23_no_spill, level, 1).
provenance(g23_no_spill, support, 4).
provenance(g23_no_spill, kept, 3).
provenance(g23_no_spill, confidence_permille, 638).
provenance(g23_no_spill, antecedent, a141).
provenance(g23_no_spill, doubt, pours_contradict).
rule(g24_no_spill, defeasible, no_spill).
body(g24_no_spill, end_upside_down).
body(g24_no_spill, pour_half_tilted).
learned(g24_no_spill).
provenance(g24_no_spill, layer, general).
provenance(g24_no_spill, level, 1).
provenance(g24_no_spill, support, 2).
provenance(g24_no_spill, kept, 1).
provenance(g24_no_spill, confidence_permille, 620).
provenance(g24_no_spill, antecedent, a248).
provenance(g24_no_spill, doubt, pours_contradict).
rule(g25_no_spill, defeasible, neg(no_spill)).
body(g25_no_spill, end_upside_down).
body(g25_no_spill, pour_slightly_tilted).
learned(g25_no_spill).
provenance(g25_no_spill, layer, general).
provenance(g25_no_spill, level, 2).
provenance(g25_no_spill, support, 2).
provenance(g25_no_spill, kept, 2).
provenance(g25_no_spill, confidence_permille, 637).
provenance(g25_no_spill, antecedent, a202).
provenance(g25_no_spill, doubt, pours_contradict).
rule(g26_no_spill, defeasible, no_spill).
body(g26_no_spill, pour_centred).
body(g26_no_spill, pour_high).
learned(g26_no_spill).
provenance(g26_no_spill, layer, general).
provenance(g26_no_spill, level, 1).
provenance(g26_no_spill, support, 1).
provenance(g26_no_spill, kept, 0).
provenance(g26_no_spill, confidence_permille, 648).
provenance(g26_no_spill, doubt, few_pours_depart).
rule(g27_no_spill, defeasible, no_spill).
body(g27_no_spill, pour_high).
body(g27_no_spill, retreat_lowering).
learned(g27_no_spill).
provenance(g27_no_spill, layer, general).
provenance(g27_no_spill, level, 1).
provenance(g27_no_spill, support, 1).
provenance(g27_no_spill, kept, 0).
provenance(g27_no_spill, confidence_permille, 648).
provenance(g27_no_spill, doubt, few_pours_depart).
sup(g10_destination_still_approach, g2_destination_still_approach).
sup(g10_destination_still_approach, g3_destination_still_approach).
sup(g10_destination_still_approach, g9_destination_still_approach).
sup(g10_destination_still_retreat, g12_destination_still_retreat).
sup(g10_destination_still_retreat, g13_destination_still_retreat).
sup(g10_destination_still_retreat, g4_destination_still_retreat).
sup(g10_destination_still_retreat, g5_destination_still_retreat).
sup(g10_destination_still_retreat, g7_destination_still_retreat).
sup(g10_destination_still_retreat, g9_destination_still_retreat).
sup(g10_no_spill, g1_no_spill).
sup(g10_no_spill, g2_no_spill).
sup(g10_no_spill, g3_no_spill).
sup(g10_no_spill, g4_no_spill).
sup(g10_source_clear, g3_source_clear).
sup(g10_source_clear, g6_source_clear).
sup(g11_destination_still_approach, g12_destination_still_approach).
sup(g11_destination_still_approach, g2_destination_still_approach).
sup(g11_destination_still_approach, g3_destination_still_approach).
sup(g11_destination_still_approach, g6_destination_still_approach).
sup(g11_destination_still_approach, g9_destination_still_approach).
sup(g11_destination_still_retreat, g12_destination_still_retreat).
sup(g11_destination_still_retreat, g13_destination_still_retreat).
sup(g11_destination_still_retreat, g4_destination_still_retreat).
sup(g11_destination_still_retreat, g5_destination_still_retreat).
sup(g11_destination_still_retreat, g7_destination_still_retreat).
sup(g11_destination_still_retreat, g9_destination_still_retreat).
sup(g11_liquid_enters_destination, g2_liquid_enters_destination).
sup(g11_liquid_enters_destination, g7_liquid_enters_destination).
sup(g11_no_spill, g1_no_spill).
sup(g11_no_spill, g2_no_spill).
sup(g11_no_spill, g3_no_spill).
sup(g11_no_spill, g4_no_spill).
sup(g11_source_clear, g2_source_clear).
sup(g11_source_clear, g3_source_clear).
sup(g11_source_clear, g4_source_clear).
sup(g11_source_clear, g6_source_clear).
sup(g12_liquid_enters_destination, g10_liquid_enters_destination).
sup(g12_no_spill, g1_no_spill).
sup(g12_no_spill, g25_no_spill).
sup(g12_no_spill, g4_no_spill).
sup(g12_source_clear, g11_source_clear).
sup(g12_source_clear, g13_source_clear).
sup(g12_source_clear, g5_source_clear).
sup(g12_source_clear, g7_source_clear).
sup(g12_source_clear, g9_source_clear).
sup(g13_liquid_enters_destination, g2_liquid_enters_destination).
sup(g13_liquid_enters_destination, g7_liquid_enters_destination).
sup(g13_no_spill, g1_no_spill).
sup(g13_no_spill, g4_no_spill).
sup(g13_source_clear, g1_source_clear).
sup(g13_source_clear, g3_source_clear).
sup(g13_source_clear, g6_source_clear).
sup(g14_no_spill, g1_no_spill).
sup(g14_no_spill, g4_no_spill).
sup(g14_source_clear, g12_source_clear).
sup(g14_source_clear, g1_source_clear).
sup(g14_source_clear, g3_source_clear).
sup(g14_source_clear, g6_source_clear).
sup(g15_liquid_enters_destination, g2_liquid_enters_destination).
sup(g15_liquid_enters_destination, g7_liquid_enters_destination).
sup(g15_no_spill, g1_no_spill).
sup(g15_no_spill, g4_no_spill).
sup(g15_source_clear, g2_source_clear).
sup(g15_source_clear, g3_source_clear).
sup(g15_source_clear, g4_source_clear).
sup(g15_source_clear, g6_source_clear).
sup(g16_no_spill, g1_no_spill).
sup(g16_no_spill, g25_no_spill).
sup(g17_liquid_enters_destination, g1_liquid_enters_destination).
sup(g17_liquid_enters_destination, g2_liquid_enters_destination).
sup(g17_liquid_enters_destination, g3_liquid_enters_destination).
sup(g17_liquid_enters_destination, g4_liquid_enters_destination).
sup(g17_liquid_enters_destination, g5_liquid_enters_destination).
sup(g17_no_spill, g1_no_spill).
sup(g18_liquid_enters_destination, g1_liquid_enters_destination).
sup(g18_liquid_enters_destination, g2_liquid_enters_destination).
sup(g18_liquid_enters_destination, g3_liquid_enters_destination).
sup(g18_liquid_enters_destination, g4_liquid_enters_destination).
sup(g18_liquid_enters_destination, g5_liquid_enters_destination).
sup(g18_liquid_enters_destination, g6_liquid_enters_destination).
sup(g18_liquid_enters_destination, g7_liquid_enters_destination).
sup(g18_no_spill, g1_no_spill).
sup(g19_no_spill, g1_no_spill).
sup(g1_destination_still_approach, g2_destination_still_approach).
sup(g1_destination_still_approach, g3_destination_still_approach).
sup(g1_destination_still_approach, g9_destination_still_approach).
sup(g1_destination_still_retreat, g2_destination_still_retreat).
sup(g1_destination_still_retreat, g3_destination_still_retreat).
sup(g1_liquid_enters_destination, g8_liquid_enters_destination).
sup(g1_liquid_enters_destination, g9_liquid_enters_destination).
sup(g1_no_spill, g5_no_spill).
sup(g1_source_clear, g10_source_clear).
sup(g1_source_clear, g11_source_clear).
sup(g1_source_clear, g5_source_clear).
sup(g1_source_clear, g7_source_clear).
sup(g1_source_clear, g9_source_clear).
sup(g20_no_spill, g1_no_spill).
sup(g20_no_spill, g2_no_spill).
sup(g20_no_spill, g3_no_spill).
sup(g21_no_spill, g1_no_spill).
sup(g21_no_spill, g2_no_spill).
sup(g21_no_spill, g3_no_spill).
sup(g21_no_spill, g4_no_spill).
sup(g22_no_spill, g1_no_spill).
sup(g22_no_spill, g2_no_spill).
sup(g22_no_spill, g3_no_spill).
sup(g22_no_spill, g4_no_spill).
sup(g23_no_spill, g1_no_spill).
sup(g23_no_spill, g2_no_spill).
sup(g23_no_spill, g3_no_spill).
sup(g23_no_spill, g4_no_spill).
sup(g24_no_spill, g1_no_spill).
sup(g24_no_spill, g2_no_spill).
sup(g24_no_spill, g3_no_spill).
sup(g24_no_spill, g4_no_spill).
sup(g25_no_spill, g20_no_spill).
sup(g25_no_spill, g5_no_spill).
sup(g26_no_spill, g1_no_spill).
sup(g26_no_spill, g25_no_spill).
sup(g27_no_spill, g1_no_spill).
sup(g27_no_spill, g25_no_spill).
sup(g27_no_spill, g2_no_spill).
sup(g27_no_spill, g3_no_spill).
sup(g2_liquid_enters_destination, g10_liquid_enters_destination).
sup(g2_liquid_enters_destination, g8_liquid_enters_destination).
sup(g2_liquid_enters_destination, g9_liquid_enters_destination).
sup(g2_no_spill, g5_no_spill).
sup(g2_source_clear, g5_source_clear).
sup(g3_liquid_enters_destination, g8_liquid_enters_destination).
sup(g3_liquid_enters_destination, g9_liquid_enters_destination).
sup(g3_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g3_liquid_remains_in_destination, g2_liquid_remains_in_destination).
sup(g3_liquid_remains_in_destination, g8_liquid_remains_in_destination).
sup(g3_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g3_no_spill, g5_no_spill).
sup(g4_destination_still_approach, g10_destination_still_approach).
sup(g4_destination_still_approach, g11_destination_still_approach).
sup(g4_destination_still_retreat, g1_destination_still_retreat).
sup(g4_liquid_enters_destination, g8_liquid_enters_destination).
sup(g4_liquid_enters_destination, g9_liquid_enters_destination).
sup(g5_destination_still_retreat, g1_destination_still_retreat).
sup(g5_liquid_enters_destination, g8_liquid_enters_destination).
sup(g5_liquid_enters_destination, g9_liquid_enters_destination).
sup(g5_liquid_leaves_source, g1_liquid_leaves_source).
sup(g5_liquid_leaves_source, g2_liquid_leaves_source).
sup(g5_liquid_leaves_source, g3_liquid_leaves_source).
sup(g5_liquid_leaves_source, g4_liquid_leaves_source).
sup(g5_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g5_source_clear, g4_source_clear).
sup(g5_source_clear, g6_source_clear).
sup(g6_destination_still_approach, g1_destination_still_approach).
sup(g6_liquid_enters_destination, g10_liquid_enters_destination).
sup(g6_liquid_enters_destination, g8_liquid_enters_destination).
sup(g6_liquid_leaves_source, g1_liquid_leaves_source).
sup(g6_liquid_leaves_source, g2_liquid_leaves_source).
sup(g6_liquid_leaves_source, g3_liquid_leaves_source).
sup(g6_liquid_leaves_source, g4_liquid_leaves_source).
sup(g6_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g6_no_spill, g1_no_spill).
sup(g6_no_spill, g2_no_spill).
sup(g6_no_spill, g3_no_spill).
sup(g6_no_spill, g4_no_spill).
sup(g7_destination_still_approach, g13_destination_still_approach).
sup(g7_destination_still_approach, g6_destination_still_approach).
sup(g7_destination_still_approach, g9_destination_still_approach).
sup(g7_destination_still_retreat, g1_destination_still_retreat).
sup(g7_liquid_enters_destination, g10_liquid_enters_destination).
sup(g7_liquid_enters_destination, g8_liquid_enters_destination).
sup(g7_liquid_enters_destination, g9_liquid_enters_destination).
sup(g7_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g7_no_spill, g15_no_spill).
sup(g7_no_spill, g19_no_spill).
sup(g7_no_spill, g20_no_spill).
sup(g7_no_spill, g26_no_spill).
sup(g7_no_spill, g27_no_spill).
sup(g7_no_spill, g5_no_spill).
sup(g7_source_clear, g2_source_clear).
sup(g7_source_clear, g3_source_clear).
sup(g7_source_clear, g4_source_clear).
sup(g7_source_clear, g6_source_clear).
sup(g8_destination_still_approach, g11_destination_still_approach).
sup(g8_no_spill, g14_no_spill).
sup(g8_no_spill, g18_no_spill).
sup(g8_no_spill, g20_no_spill).
sup(g8_no_spill, g26_no_spill).
sup(g8_no_spill, g27_no_spill).
sup(g8_no_spill, g5_no_spill).
sup(g8_source_clear, g12_source_clear).
sup(g8_source_clear, g2_source_clear).
sup(g8_source_clear, g3_source_clear).
sup(g8_source_clear, g4_source_clear).
sup(g9_no_spill, g1_no_spill).
sup(g9_no_spill, g2_no_spill).
sup(g9_no_spill, g3_no_spill).
sup(g9_no_spill, g4_no_spill).
sup(g9_source_clear, g2_source_clear).
sup(g9_source_clear, g3_source_clear).
sup(g9_source_clear, g4_source_clear).
sup(g9_source_clear, g6_source_clear).

% The explored antecedents, with or without a rule of their own:
% explored(A, Prop): the antecedent A says Prop (the ordinary pour,
% which says nothing, has none); held(A, E, Held, Pours): of the Pours
% pours that could have been drawn for A, Held held E. An answer for
% a scene explored cites them (docs/theory-formats.md).
held(a1, destination_still_approach, 20, 20).
held(a1, destination_still_retreat, 20, 20).
held(a1, destination_still_settle, 20, 20).
held(a1, destination_upright, 20, 20).
held(a1, source_clear, 19, 20).
held(a1, liquid_leaves_source, 20, 20).
held(a1, liquid_enters_destination, 20, 20).
held(a1, liquid_remains_in_destination, 20, 20).
held(a1, no_spill, 20, 20).
explored(a2, start_below_rim).
held(a2, destination_still_approach, 6, 10).
held(a2, destination_still_retreat, 9, 10).
held(a2, destination_still_settle, 10, 10).
held(a2, destination_upright, 10, 10).
held(a2, source_clear, 3, 10).
held(a2, liquid_leaves_source, 10, 10).
held(a2, liquid_enters_destination, 9, 10).
held(a2, liquid_remains_in_destination, 10, 10).
held(a2, no_spill, 9, 10).
explored(a3, start_low).
held(a3, destination_still_approach, 4, 5).
held(a3, destination_still_retreat, 5, 5).
held(a3, destination_still_settle, 5, 5).
held(a3, destination_upright, 5, 5).
held(a3, source_clear, 4, 5).
held(a3, liquid_leaves_source, 5, 5).
held(a3, liquid_enters_destination, 4, 5).
held(a3, liquid_remains_in_destination, 5, 5).
held(a3, no_spill, 4, 5).
explored(a4, pour_below_rim).
held(a4, destination_still_approach, 7, 82).
held(a4, destination_still_retreat, 26, 82).
held(a4, destination_still_settle, 64, 82).
held(a4, destination_upright, 67, 82).
held(a4, source_clear, 0, 82).
held(a4, liquid_leaves_source, 82, 82).
held(a4, liquid_enters_destination, 63, 82).
held(a4, liquid_remains_in_destination, 50, 82).
held(a4, no_spill, 38, 82).
explored(a5, approach_moving_closer).
explored(a5, bouncy_destination).
explored(a5, bouncy_source).
explored(a5, end_level).
explored(a5, end_steeply_tilted).
explored(a5, end_to_side).
explored(a5, heavy_destination).
explored(a5, heavy_source).
explored(a5, much_liquid).
explored(a5, pour_in_line).
explored(a5, pour_level).
explored(a5, pour_near_rim).
explored(a5, pour_very_high).
explored(a5, slippery_destination).
explored(a5, slippery_source).
explored(a5, slow_retreat).
explored(a5, start_slightly_tilted).
held(a5, destination_still_approach, 2, 2).
held(a5, destination_still_retreat, 2, 2).
held(a5, destination_still_settle, 2, 2).
held(a5, destination_upright, 2, 2).
held(a5, source_clear, 2, 2).
held(a5, liquid_leaves_source, 2, 2).
held(a5, liquid_enters_destination, 2, 2).
held(a5, liquid_remains_in_destination, 2, 2).
held(a5, no_spill, 2, 2).
explored(a6, pour_high).
held(a6, destination_still_approach, 6, 6).
held(a6, destination_still_retreat, 6, 6).
held(a6, destination_still_settle, 6, 6).
held(a6, destination_upright, 6, 6).
held(a6, source_clear, 6, 6).
held(a6, liquid_leaves_source, 6, 6).
held(a6, liquid_enters_destination, 5, 6).
held(a6, liquid_remains_in_destination, 6, 6).
held(a6, no_spill, 5, 6).
explored(a7, end_rolled).
held(a7, destination_still_approach, 4, 4).
held(a7, destination_still_retreat, 4, 4).
held(a7, destination_still_settle, 4, 4).
held(a7, destination_upright, 4, 4).
held(a7, source_clear, 4, 4).
held(a7, liquid_leaves_source, 4, 4).
held(a7, liquid_enters_destination, 4, 4).
held(a7, liquid_remains_in_destination, 4, 4).
held(a7, no_spill, 4, 4).
explored(a8, approach_lowering).
explored(a8, bouncy_source).
explored(a8, dull_liquid).
explored(a8, end_half_tilted).
explored(a8, end_rolled).
explored(a8, grippy_destination).
explored(a8, heavy_destination).
explored(a8, light_liquid).
explored(a8, moderate_retreat).
explored(a8, pour_high).
explored(a8, pour_in_line).
explored(a8, pour_rolled).
explored(a8, pour_slightly_tilted).
explored(a8, pour_to_side).
explored(a8, retreat_raising).
explored(a8, slippery_source).
explored(a8, start_centred).
explored(a8, start_upright).
explored(a8, sticky_liquid).
explored(a8, very_much_liquid).
held(a8, destination_still_approach, 2, 2).
held(a8, destination_still_retreat, 2, 2).
held(a8, destination_still_settle, 2, 2).
held(a8, destination_upright, 2, 2).
held(a8, source_clear, 2, 2).
held(a8, liquid_leaves_source, 1, 2).
held(a8, liquid_enters_destination, 0, 2).
held(a8, liquid_remains_in_destination, 2, 2).
held(a8, no_spill, 2, 2).
explored(a9, sticky_liquid).
held(a9, destination_still_approach, 4, 4).
held(a9, destination_still_retreat, 4, 4).
held(a9, destination_still_settle, 4, 4).
held(a9, destination_upright, 4, 4).
held(a9, source_clear, 4, 4).
held(a9, liquid_leaves_source, 4, 4).
held(a9, liquid_enters_destination, 4, 4).
held(a9, liquid_remains_in_destination, 4, 4).
held(a9, no_spill, 4, 4).
explored(a10, very_much_liquid).
held(a10, destination_still_approach, 4, 4).
held(a10, destination_still_retreat, 4, 4).
held(a10, destination_still_settle, 4, 4).
held(a10, destination_upright, 4, 4).
held(a10, source_clear, 4, 4).
held(a10, liquid_leaves_source, 4, 4).
held(a10, liquid_enters_destination, 4, 4).
held(a10, liquid_remains_in_destination, 4, 4).
held(a10, no_spill, 4, 4).
explored(a11, approach_moving_closer).
explored(a11, end_level).
explored(a11, end_to_side).
explored(a11, end_upside_down).
explored(a11, grippy_destination).
explored(a11, medium_destination).
explored(a11, moderate_approach).
explored(a11, moderate_retreat).
explored(a11, pour_centred).
explored(a11, pour_level).
explored(a11, pour_low).
explored(a11, pour_upright).
explored(a11, retreat_raising).
explored(a11, start_below_rim).
explored(a11, sticky_liquid).
explored(a11, very_much_liquid).
held(a11, destination_still_approach, 1, 2).
held(a11, destination_still_retreat, 1, 2).
held(a11, destination_still_settle, 2, 2).
held(a11, destination_upright, 1, 2).
held(a11, source_clear, 0, 2).
held(a11, liquid_leaves_source, 2, 2).
held(a11, liquid_enters_destination, 0, 2).
held(a11, liquid_remains_in_destination, 0, 2).
held(a11, no_spill, 0, 2).
explored(a12, end_half_tilted).
held(a12, destination_still_approach, 4, 4).
held(a12, destination_still_retreat, 4, 4).
held(a12, destination_still_settle, 4, 4).
held(a12, destination_upright, 4, 4).
held(a12, source_clear, 4, 4).
held(a12, liquid_leaves_source, 4, 4).
held(a12, liquid_enters_destination, 4, 4).
held(a12, liquid_remains_in_destination, 4, 4).
held(a12, no_spill, 4, 4).
explored(a13, retreat_lowering).
held(a13, destination_still_approach, 17, 17).
held(a13, destination_still_retreat, 9, 17).
held(a13, destination_still_settle, 16, 17).
held(a13, destination_upright, 13, 17).
held(a13, source_clear, 7, 17).
held(a13, liquid_leaves_source, 17, 17).
held(a13, liquid_enters_destination, 17, 17).
held(a13, liquid_remains_in_destination, 16, 17).
held(a13, no_spill, 16, 17).
explored(a14, approach_moving_closer).
explored(a14, dull_liquid).
explored(a14, end_far_away).
explored(a14, end_half_tilted).
explored(a14, end_rolled).
explored(a14, fast_retreat).
explored(a14, grippy_destination).
explored(a14, medium_liquid).
explored(a14, pour_in_line).
explored(a14, pour_mid_height).
explored(a14, pour_near_rim).
explored(a14, pour_slightly_tilted).
explored(a14, retreat_lowering).
explored(a14, runny_liquid).
explored(a14, start_mid_height).
explored(a14, start_upright).
explored(a14, very_much_liquid).
held(a14, destination_still_approach, 2, 2).
held(a14, destination_still_retreat, 2, 2).
held(a14, destination_still_settle, 2, 2).
held(a14, destination_upright, 2, 2).
held(a14, source_clear, 2, 2).
held(a14, liquid_leaves_source, 0, 2).
held(a14, liquid_enters_destination, 0, 2).
held(a14, liquid_remains_in_destination, 2, 2).
held(a14, no_spill, 2, 2).
explored(a15, dull_source).
held(a15, destination_still_approach, 4, 4).
held(a15, destination_still_retreat, 4, 4).
held(a15, destination_still_settle, 4, 4).
held(a15, destination_upright, 4, 4).
held(a15, source_clear, 4, 4).
held(a15, liquid_leaves_source, 4, 4).
held(a15, liquid_enters_destination, 4, 4).
held(a15, liquid_remains_in_destination, 4, 4).
held(a15, no_spill, 4, 4).
explored(a16, slow_retreat).
held(a16, destination_still_approach, 4, 4).
held(a16, destination_still_retreat, 4, 4).
held(a16, destination_still_settle, 4, 4).
held(a16, destination_upright, 4, 4).
held(a16, source_clear, 4, 4).
held(a16, liquid_leaves_source, 4, 4).
held(a16, liquid_enters_destination, 4, 4).
held(a16, liquid_remains_in_destination, 4, 4).
held(a16, no_spill, 4, 4).
explored(a17, approach_moving_closer).
explored(a17, approach_raising).
explored(a17, bouncy_liquid).
explored(a17, dull_destination).
explored(a17, dull_source).
explored(a17, end_centred).
explored(a17, end_level).
explored(a17, end_mid_height).
explored(a17, end_upside_down).
explored(a17, fast_retreat).
explored(a17, little_liquid).
explored(a17, medium_liquid).
explored(a17, pour_level).
explored(a17, pour_offset_sideways).
explored(a17, pour_tilted_back).
explored(a17, pour_very_high).
explored(a17, slippery_destination).
explored(a17, slippery_source).
explored(a17, slow_approach).
explored(a17, start_upright).
explored(a17, sticky_liquid).
held(a17, destination_still_approach, 2, 2).
held(a17, destination_still_retreat, 1, 2).
held(a17, destination_still_settle, 1, 2).
held(a17, destination_upright, 2, 2).
held(a17, source_clear, 2, 2).
held(a17, liquid_leaves_source, 2, 2).
held(a17, liquid_enters_destination, 1, 2).
held(a17, liquid_remains_in_destination, 2, 2).
held(a17, no_spill, 1, 2).
explored(a18, pour_tilted_back).
held(a18, destination_still_approach, 4, 4).
held(a18, destination_still_retreat, 4, 4).
held(a18, destination_still_settle, 4, 4).
held(a18, destination_upright, 4, 4).
held(a18, source_clear, 4, 4).
held(a18, liquid_leaves_source, 0, 4).
held(a18, liquid_enters_destination, 0, 4).
held(a18, liquid_remains_in_destination, 4, 4).
held(a18, no_spill, 4, 4).
explored(a19, slow_approach).
held(a19, destination_still_approach, 4, 4).
held(a19, destination_still_retreat, 4, 4).
held(a19, destination_still_settle, 4, 4).
held(a19, destination_upright, 4, 4).
held(a19, source_clear, 4, 4).
held(a19, liquid_leaves_source, 4, 4).
held(a19, liquid_enters_destination, 4, 4).
held(a19, liquid_remains_in_destination, 4, 4).
held(a19, no_spill, 4, 4).
explored(a20, dull_destination).
explored(a20, dull_liquid).
explored(a20, end_level).
explored(a20, end_mid_height).
explored(a20, end_near_rim).
explored(a20, end_steeply_tilted).
explored(a20, heavy_source).
explored(a20, light_liquid).
explored(a20, moderate_approach).
explored(a20, moderate_retreat).
explored(a20, pour_half_tilted).
explored(a20, pour_high).
explored(a20, pour_in_line).
explored(a20, pour_level).
explored(a20, pour_to_side).
explored(a20, start_far_away).
explored(a20, start_low).
explored(a20, start_tilted_back).
explored(a20, sticky_liquid).
explored(a20, very_much_liquid).
held(a20, destination_still_approach, 2, 2).
held(a20, destination_still_retreat, 2, 2).
held(a20, destination_still_settle, 2, 2).
held(a20, destination_upright, 2, 2).
held(a20, source_clear, 2, 2).
held(a20, liquid_leaves_source, 2, 2).
held(a20, liquid_enters_destination, 2, 2).
held(a20, liquid_remains_in_destination, 2, 2).
held(a20, no_spill, 2, 2).
explored(a21, slow_approach).
explored(a21, sticky_liquid).
held(a21, destination_still_approach, 2, 2).
held(a21, destination_still_retreat, 2, 2).
held(a21, destination_still_settle, 2, 2).
held(a21, destination_upright, 2, 2).
held(a21, source_clear, 2, 2).
held(a21, liquid_leaves_source, 2, 2).
held(a21, liquid_enters_destination, 2, 2).
held(a21, liquid_remains_in_destination, 2, 2).
held(a21, no_spill, 2, 2).
explored(a22, pour_upright).
held(a22, destination_still_approach, 4, 4).
held(a22, destination_still_retreat, 4, 4).
held(a22, destination_still_settle, 4, 4).
held(a22, destination_upright, 4, 4).
held(a22, source_clear, 4, 4).
held(a22, liquid_leaves_source, 0, 4).
held(a22, liquid_enters_destination, 0, 4).
held(a22, liquid_remains_in_destination, 4, 4).
held(a22, no_spill, 4, 4).
explored(a23, bouncy_destination).
explored(a23, dull_source).
explored(a23, end_far_away).
explored(a23, end_half_tilted).
explored(a23, end_high).
explored(a23, end_rolled).
explored(a23, fast_approach).
explored(a23, grippy_destination).
explored(a23, light_destination).
explored(a23, light_source).
explored(a23, medium_liquid).
explored(a23, pour_offset_sideways).
explored(a23, pour_upright).
explored(a23, pour_very_high).
explored(a23, slippery_source).
explored(a23, start_near_rim).
explored(a23, start_upright).
explored(a23, start_very_high).
explored(a23, sticky_liquid).
explored(a23, very_much_liquid).
held(a23, destination_still_approach, 2, 2).
held(a23, destination_still_retreat, 2, 2).
held(a23, destination_still_settle, 2, 2).
held(a23, destination_upright, 2, 2).
held(a23, source_clear, 2, 2).
held(a23, liquid_leaves_source, 0, 2).
held(a23, liquid_enters_destination, 0, 2).
held(a23, liquid_remains_in_destination, 2, 2).
held(a23, no_spill, 2, 2).
explored(a24, pour_slightly_tilted).
held(a24, destination_still_approach, 5, 5).
held(a24, destination_still_retreat, 5, 5).
held(a24, destination_still_settle, 5, 5).
held(a24, destination_upright, 5, 5).
held(a24, source_clear, 5, 5).
held(a24, liquid_leaves_source, 0, 5).
held(a24, liquid_enters_destination, 0, 5).
held(a24, liquid_remains_in_destination, 5, 5).
held(a24, no_spill, 5, 5).
explored(a25, pour_half_tilted).
held(a25, destination_still_approach, 5, 5).
held(a25, destination_still_retreat, 5, 5).
held(a25, destination_still_settle, 5, 5).
held(a25, destination_upright, 5, 5).
held(a25, source_clear, 5, 5).
held(a25, liquid_leaves_source, 0, 5).
held(a25, liquid_enters_destination, 0, 5).
held(a25, liquid_remains_in_destination, 5, 5).
held(a25, no_spill, 5, 5).
explored(a26, approach_lowering).
explored(a26, bouncy_destination).
explored(a26, end_low).
explored(a26, end_rolled).
explored(a26, end_slightly_tilted).
explored(a26, fast_approach).
explored(a26, light_destination).
explored(a26, light_source).
explored(a26, pour_centred).
explored(a26, pour_low).
explored(a26, pour_slightly_tilted).
explored(a26, retreat_moving_closer).
explored(a26, slippery_destination).
explored(a26, start_far_away).
explored(a26, start_tilted_back).
explored(a26, sticky_liquid).
held(a26, destination_still_approach, 2, 2).
held(a26, destination_still_retreat, 1, 2).
held(a26, destination_still_settle, 2, 2).
held(a26, destination_upright, 2, 2).
held(a26, source_clear, 1, 2).
held(a26, liquid_leaves_source, 0, 2).
held(a26, liquid_enters_destination, 0, 2).
held(a26, liquid_remains_in_destination, 2, 2).
held(a26, no_spill, 2, 2).
explored(a27, approach_moving_away).
held(a27, destination_still_approach, 3, 3).
held(a27, destination_still_retreat, 3, 3).
held(a27, destination_still_settle, 3, 3).
held(a27, destination_upright, 3, 3).
held(a27, source_clear, 3, 3).
held(a27, liquid_leaves_source, 3, 3).
held(a27, liquid_enters_destination, 3, 3).
held(a27, liquid_remains_in_destination, 3, 3).
held(a27, no_spill, 3, 3).
explored(a28, start_centred).
held(a28, destination_still_approach, 4, 4).
held(a28, destination_still_retreat, 4, 4).
held(a28, destination_still_settle, 4, 4).
held(a28, destination_upright, 4, 4).
held(a28, source_clear, 4, 4).
held(a28, liquid_leaves_source, 4, 4).
held(a28, liquid_enters_destination, 4, 4).
held(a28, liquid_remains_in_destination, 4, 4).
held(a28, no_spill, 4, 4).
explored(a29, approach_lowering).
explored(a29, approach_moving_closer).
explored(a29, dull_liquid).
explored(a29, end_far_away).
explored(a29, end_low).
explored(a29, end_rolled).
explored(a29, end_slightly_tilted).
explored(a29, light_liquid).
explored(a29, moderate_approach).
explored(a29, moderate_retreat).
explored(a29, pour_level).
explored(a29, pour_low).
explored(a29, pour_near_rim).
explored(a29, pour_offset_sideways).
explored(a29, pour_steeply_tilted).
explored(a29, runny_liquid).
held(a29, destination_still_approach, 2, 2).
held(a29, destination_still_retreat, 2, 2).
held(a29, destination_still_settle, 2, 2).
held(a29, destination_upright, 2, 2).
held(a29, source_clear, 0, 2).
held(a29, liquid_leaves_source, 1, 2).
held(a29, liquid_enters_destination, 0, 2).
held(a29, liquid_remains_in_destination, 2, 2).
held(a29, no_spill, 1, 2).
explored(a30, start_near_rim).
held(a30, destination_still_approach, 4, 4).
held(a30, destination_still_retreat, 4, 4).
held(a30, destination_still_settle, 4, 4).
held(a30, destination_upright, 4, 4).
held(a30, source_clear, 4, 4).
held(a30, liquid_leaves_source, 4, 4).
held(a30, liquid_enters_destination, 4, 4).
held(a30, liquid_remains_in_destination, 4, 4).
held(a30, no_spill, 4, 4).
explored(a31, light_destination).
held(a31, destination_still_approach, 5, 6).
held(a31, destination_still_retreat, 6, 6).
held(a31, destination_still_settle, 6, 6).
held(a31, destination_upright, 6, 6).
held(a31, source_clear, 6, 6).
held(a31, liquid_leaves_source, 6, 6).
held(a31, liquid_enters_destination, 6, 6).
held(a31, liquid_remains_in_destination, 6, 6).
held(a31, no_spill, 6, 6).
explored(a32, bouncy_source).
explored(a32, dull_destination).
explored(a32, dull_liquid).
explored(a32, end_centred).
explored(a32, end_half_tilted).
explored(a32, grippy_destination).
explored(a32, grippy_source).
explored(a32, heavy_destination).
explored(a32, light_source).
explored(a32, medium_liquid).
explored(a32, moderate_retreat).
explored(a32, pour_far_away).
explored(a32, pour_level).
explored(a32, pour_mid_height).
explored(a32, pour_offset_sideways).
explored(a32, pour_tilted_back).
explored(a32, retreat_raising).
explored(a32, start_far_away).
explored(a32, start_mid_height).
explored(a32, start_upright).
explored(a32, sticky_liquid).
held(a32, destination_still_approach, 2, 2).
held(a32, destination_still_retreat, 2, 2).
held(a32, destination_still_settle, 2, 2).
held(a32, destination_upright, 2, 2).
held(a32, source_clear, 2, 2).
held(a32, liquid_leaves_source, 0, 2).
held(a32, liquid_enters_destination, 0, 2).
held(a32, liquid_remains_in_destination, 2, 2).
held(a32, no_spill, 2, 2).
explored(a33, end_below_rim).
held(a33, destination_still_approach, 13, 13).
held(a33, destination_still_retreat, 6, 13).
held(a33, destination_still_settle, 12, 13).
held(a33, destination_upright, 9, 13).
held(a33, source_clear, 4, 13).
held(a33, liquid_leaves_source, 13, 13).
held(a33, liquid_enters_destination, 13, 13).
held(a33, liquid_remains_in_destination, 12, 13).
held(a33, no_spill, 12, 13).
explored(a34, light_source).
held(a34, destination_still_approach, 4, 4).
held(a34, destination_still_retreat, 4, 4).
held(a34, destination_still_settle, 4, 4).
held(a34, destination_upright, 4, 4).
held(a34, source_clear, 4, 4).
held(a34, liquid_leaves_source, 4, 4).
held(a34, liquid_enters_destination, 4, 4).
held(a34, liquid_remains_in_destination, 4, 4).
held(a34, no_spill, 4, 4).
explored(a35, approach_raising).
explored(a35, bouncy_destination).
explored(a35, bouncy_liquid).
explored(a35, bouncy_source).
explored(a35, end_near_rim).
explored(a35, end_upright).
explored(a35, heavy_destination).
explored(a35, light_source).
explored(a35, moderate_retreat).
explored(a35, pour_far_away).
explored(a35, pour_low).
explored(a35, pour_upright).
explored(a35, slippery_destination).
explored(a35, sticky_liquid).
held(a35, destination_still_approach, 2, 2).
held(a35, destination_still_retreat, 2, 2).
held(a35, destination_still_settle, 2, 2).
held(a35, destination_upright, 2, 2).
held(a35, source_clear, 2, 2).
held(a35, liquid_leaves_source, 0, 2).
held(a35, liquid_enters_destination, 0, 2).
held(a35, liquid_remains_in_destination, 2, 2).
held(a35, no_spill, 2, 2).
explored(a36, grippy_destination).
held(a36, destination_still_approach, 4, 4).
held(a36, destination_still_retreat, 4, 4).
held(a36, destination_still_settle, 4, 4).
held(a36, destination_upright, 4, 4).
held(a36, source_clear, 4, 4).
held(a36, liquid_leaves_source, 4, 4).
held(a36, liquid_enters_destination, 4, 4).
held(a36, liquid_remains_in_destination, 4, 4).
held(a36, no_spill, 4, 4).
explored(a37, end_upside_down).
held(a37, destination_still_approach, 6, 6).
held(a37, destination_still_retreat, 6, 6).
held(a37, destination_still_settle, 6, 6).
held(a37, destination_upright, 6, 6).
held(a37, source_clear, 6, 6).
held(a37, liquid_leaves_source, 6, 6).
held(a37, liquid_enters_destination, 6, 6).
held(a37, liquid_remains_in_destination, 6, 6).
held(a37, no_spill, 6, 6).
explored(a38, bouncy_liquid).
explored(a38, dull_destination).
explored(a38, dull_source).
explored(a38, end_high).
explored(a38, end_level).
explored(a38, end_tilted_back).
explored(a38, heavy_source).
explored(a38, pour_below_rim).
explored(a38, pour_in_line).
explored(a38, pour_level).
explored(a38, pour_slightly_tilted).
explored(a38, retreat_moving_away).
explored(a38, runny_liquid).
explored(a38, slow_approach).
explored(a38, some_liquid).
explored(a38, start_mid_height).
explored(a38, start_to_side).
held(a38, destination_still_approach, 0, 2).
held(a38, destination_still_retreat, 0, 2).
held(a38, destination_still_settle, 2, 2).
held(a38, destination_upright, 2, 2).
held(a38, source_clear, 0, 2).
held(a38, liquid_leaves_source, 0, 2).
held(a38, liquid_enters_destination, 2, 2).
held(a38, liquid_remains_in_destination, 0, 2).
held(a38, no_spill, 2, 2).
explored(a39, pour_offset_sideways).
held(a39, destination_still_approach, 10, 11).
held(a39, destination_still_retreat, 10, 11).
held(a39, destination_still_settle, 11, 11).
held(a39, destination_upright, 11, 11).
held(a39, source_clear, 8, 11).
held(a39, liquid_leaves_source, 11, 11).
held(a39, liquid_enters_destination, 2, 11).
held(a39, liquid_remains_in_destination, 11, 11).
held(a39, no_spill, 2, 11).
explored(a40, dull_destination).
held(a40, destination_still_approach, 4, 4).
held(a40, destination_still_retreat, 4, 4).
held(a40, destination_still_settle, 4, 4).
held(a40, destination_upright, 4, 4).
held(a40, source_clear, 4, 4).
held(a40, liquid_leaves_source, 4, 4).
held(a40, liquid_enters_destination, 4, 4).
held(a40, liquid_remains_in_destination, 4, 4).
held(a40, no_spill, 4, 4).
explored(a41, approach_raising).
explored(a41, bouncy_source).
explored(a41, dull_liquid).
explored(a41, end_level).
explored(a41, end_steeply_tilted).
explored(a41, end_very_high).
explored(a41, fast_retreat).
explored(a41, grippy_destination).
explored(a41, light_destination).
explored(a41, little_liquid).
explored(a41, pour_far_away).
explored(a41, pour_mid_height).
explored(a41, pour_offset_sideways).
explored(a41, pour_rolled).
explored(a41, pour_tilted_back).
explored(a41, slippery_source).
explored(a41, start_near_rim).
explored(a41, sticky_liquid).
held(a41, destination_still_approach, 2, 2).
held(a41, destination_still_retreat, 2, 2).
held(a41, destination_still_settle, 2, 2).
held(a41, destination_upright, 2, 2).
held(a41, source_clear, 1, 2).
held(a41, liquid_leaves_source, 2, 2).
held(a41, liquid_enters_destination, 1, 2).
held(a41, liquid_remains_in_destination, 1, 2).
held(a41, no_spill, 0, 2).
explored(a42, slippery_source).
held(a42, destination_still_approach, 4, 4).
held(a42, destination_still_retreat, 4, 4).
held(a42, destination_still_settle, 4, 4).
held(a42, destination_upright, 4, 4).
held(a42, source_clear, 4, 4).
held(a42, liquid_leaves_source, 4, 4).
held(a42, liquid_enters_destination, 4, 4).
held(a42, liquid_remains_in_destination, 4, 4).
held(a42, no_spill, 4, 4).
explored(a43, pour_very_high).
held(a43, destination_still_approach, 5, 5).
held(a43, destination_still_retreat, 5, 5).
held(a43, destination_still_settle, 5, 5).
held(a43, destination_upright, 5, 5).
held(a43, source_clear, 5, 5).
held(a43, liquid_leaves_source, 5, 5).
held(a43, liquid_enters_destination, 2, 5).
held(a43, liquid_remains_in_destination, 5, 5).
held(a43, no_spill, 2, 5).
explored(a44, approach_moving_closer).
explored(a44, bouncy_destination).
explored(a44, dull_liquid).
explored(a44, dull_source).
explored(a44, end_far_away).
explored(a44, end_level).
explored(a44, end_low).
explored(a44, end_upright).
explored(a44, grippy_destination).
explored(a44, heavy_destination).
explored(a44, medium_liquid).
explored(a44, pour_far_away).
explored(a44, pour_low).
explored(a44, pour_tilted_back).
explored(a44, runny_liquid).
explored(a44, slippery_source).
explored(a44, slow_retreat).
explored(a44, start_low).
explored(a44, start_upright).
explored(a44, very_much_liquid).
held(a44, destination_still_approach, 2, 2).
held(a44, destination_still_retreat, 2, 2).
held(a44, destination_still_settle, 2, 2).
held(a44, destination_upright, 2, 2).
held(a44, source_clear, 2, 2).
held(a44, liquid_leaves_source, 0, 2).
held(a44, liquid_enters_destination, 0, 2).
held(a44, liquid_remains_in_destination, 2, 2).
held(a44, no_spill, 2, 2).
explored(a45, pour_far_away).
held(a45, destination_still_approach, 4, 4).
held(a45, destination_still_retreat, 4, 4).
held(a45, destination_still_settle, 4, 4).
held(a45, destination_upright, 4, 4).
held(a45, source_clear, 4, 4).
held(a45, liquid_leaves_source, 4, 4).
held(a45, liquid_enters_destination, 0, 4).
held(a45, liquid_remains_in_destination, 4, 4).
held(a45, no_spill, 0, 4).
explored(a46, end_steeply_tilted).
held(a46, destination_still_approach, 4, 4).
held(a46, destination_still_retreat, 4, 4).
held(a46, destination_still_settle, 4, 4).
held(a46, destination_upright, 4, 4).
held(a46, source_clear, 4, 4).
held(a46, liquid_leaves_source, 4, 4).
held(a46, liquid_enters_destination, 4, 4).
held(a46, liquid_remains_in_destination, 4, 4).
held(a46, no_spill, 4, 4).
explored(a47, approach_moving_closer).
explored(a47, bouncy_source).
explored(a47, dull_destination).
explored(a47, dull_liquid).
explored(a47, end_centred).
explored(a47, end_low).
explored(a47, end_rolled).
explored(a47, end_tilted_back).
explored(a47, fast_retreat).
explored(a47, grippy_source).
explored(a47, heavy_liquid).
explored(a47, heavy_source).
explored(a47, light_destination).
explored(a47, moderate_approach).
explored(a47, much_liquid).
explored(a47, pour_centred).
explored(a47, pour_half_tilted).
explored(a47, pour_level).
explored(a47, pour_mid_height).
explored(a47, start_low).
explored(a47, start_tilted_back).
explored(a47, sticky_liquid).
held(a47, destination_still_approach, 2, 2).
held(a47, destination_still_retreat, 2, 2).
held(a47, destination_still_settle, 2, 2).
held(a47, destination_upright, 2, 2).
held(a47, source_clear, 2, 2).
held(a47, liquid_leaves_source, 0, 2).
held(a47, liquid_enters_destination, 0, 2).
held(a47, liquid_remains_in_destination, 2, 2).
held(a47, no_spill, 2, 2).
explored(a48, fast_retreat).
held(a48, destination_still_approach, 4, 4).
held(a48, destination_still_retreat, 4, 4).
held(a48, destination_still_settle, 4, 4).
held(a48, destination_upright, 4, 4).
held(a48, source_clear, 4, 4).
held(a48, liquid_leaves_source, 4, 4).
held(a48, liquid_enters_destination, 4, 4).
held(a48, liquid_remains_in_destination, 4, 4).
held(a48, no_spill, 4, 4).
explored(a49, pour_rolled).
held(a49, destination_still_approach, 4, 4).
held(a49, destination_still_retreat, 4, 4).
held(a49, destination_still_settle, 4, 4).
held(a49, destination_upright, 4, 4).
held(a49, source_clear, 3, 4).
held(a49, liquid_leaves_source, 4, 4).
held(a49, liquid_enters_destination, 4, 4).
held(a49, liquid_remains_in_destination, 4, 4).
held(a49, no_spill, 4, 4).
explored(a50, bouncy_destination).
explored(a50, bouncy_liquid).
explored(a50, bouncy_source).
explored(a50, end_rolled).
explored(a50, end_steeply_tilted).
explored(a50, fast_approach).
explored(a50, fast_retreat).
explored(a50, grippy_destination).
explored(a50, light_source).
explored(a50, medium_destination).
explored(a50, pour_far_away).
explored(a50, pour_in_line).
explored(a50, pour_low).
explored(a50, pour_upright).
explored(a50, retreat_moving_away).
explored(a50, slippery_source).
explored(a50, start_mid_height).
explored(a50, start_tilted_back).
held(a50, destination_still_approach, 2, 2).
held(a50, destination_still_retreat, 2, 2).
held(a50, destination_still_settle, 2, 2).
held(a50, destination_upright, 2, 2).
held(a50, source_clear, 2, 2).
held(a50, liquid_leaves_source, 2, 2).
held(a50, liquid_enters_destination, 0, 2).
held(a50, liquid_remains_in_destination, 2, 2).
held(a50, no_spill, 0, 2).
explored(a51, end_steeply_tilted).
explored(a51, pour_tilted_back).
held(a51, destination_still_approach, 4, 4).
held(a51, destination_still_retreat, 4, 4).
held(a51, destination_still_settle, 4, 4).
held(a51, destination_upright, 4, 4).
held(a51, source_clear, 4, 4).
held(a51, liquid_leaves_source, 4, 4).
held(a51, liquid_enters_destination, 1, 4).
held(a51, liquid_remains_in_destination, 4, 4).
held(a51, no_spill, 2, 4).
explored(a52, start_tilted_back).
held(a52, destination_still_approach, 4, 4).
held(a52, destination_still_retreat, 4, 4).
held(a52, destination_still_settle, 4, 4).
held(a52, destination_upright, 4, 4).
held(a52, source_clear, 4, 4).
held(a52, liquid_leaves_source, 4, 4).
held(a52, liquid_enters_destination, 4, 4).
held(a52, liquid_remains_in_destination, 4, 4).
held(a52, no_spill, 4, 4).
explored(a53, bouncy_destination).
explored(a53, bouncy_liquid).
explored(a53, dull_source).
explored(a53, end_rolled).
explored(a53, end_tilted_back).
explored(a53, end_very_high).
explored(a53, light_source).
explored(a53, medium_destination).
explored(a53, moderate_retreat).
explored(a53, pour_below_rim).
explored(a53, pour_in_line).
explored(a53, pour_level).
explored(a53, runny_liquid).
explored(a53, slippery_destination).
explored(a53, slippery_source).
explored(a53, slow_approach).
explored(a53, some_liquid).
explored(a53, start_far_away).
explored(a53, start_low).
explored(a53, start_tilted_back).
held(a53, destination_still_approach, 0, 2).
held(a53, destination_still_retreat, 2, 2).
held(a53, destination_still_settle, 2, 2).
held(a53, destination_upright, 2, 2).
held(a53, source_clear, 0, 2).
held(a53, liquid_leaves_source, 2, 2).
held(a53, liquid_enters_destination, 0, 2).
held(a53, liquid_remains_in_destination, 2, 2).
held(a53, no_spill, 0, 2).
explored(a54, end_tilted_back).
held(a54, destination_still_approach, 4, 4).
held(a54, destination_still_retreat, 4, 4).
held(a54, destination_still_settle, 4, 4).
held(a54, destination_upright, 4, 4).
held(a54, source_clear, 4, 4).
held(a54, liquid_leaves_source, 4, 4).
held(a54, liquid_enters_destination, 4, 4).
held(a54, liquid_remains_in_destination, 4, 4).
held(a54, no_spill, 4, 4).
explored(a55, bouncy_destination).
held(a55, destination_still_approach, 4, 4).
held(a55, destination_still_retreat, 4, 4).
held(a55, destination_still_settle, 4, 4).
held(a55, destination_upright, 4, 4).
held(a55, source_clear, 4, 4).
held(a55, liquid_leaves_source, 4, 4).
held(a55, liquid_enters_destination, 4, 4).
held(a55, liquid_remains_in_destination, 4, 4).
held(a55, no_spill, 4, 4).
explored(a56, approach_moving_closer).
explored(a56, dull_liquid).
explored(a56, end_below_rim).
explored(a56, end_level).
explored(a56, end_slightly_tilted).
explored(a56, grippy_source).
explored(a56, heavy_liquid).
explored(a56, heavy_source).
explored(a56, light_destination).
explored(a56, little_liquid).
explored(a56, moderate_retreat).
explored(a56, pour_high).
explored(a56, pour_offset_sideways).
explored(a56, pour_to_side).
explored(a56, pour_upright).
explored(a56, slippery_destination).
explored(a56, slow_approach).
explored(a56, start_below_rim).
explored(a56, start_slightly_tilted).
explored(a56, sticky_liquid).
held(a56, destination_still_approach, 2, 2).
held(a56, destination_still_retreat, 2, 2).
held(a56, destination_still_settle, 2, 2).
held(a56, destination_upright, 2, 2).
held(a56, source_clear, 2, 2).
held(a56, liquid_leaves_source, 0, 2).
held(a56, liquid_enters_destination, 0, 2).
held(a56, liquid_remains_in_destination, 2, 2).
held(a56, no_spill, 2, 2).
explored(a57, light_liquid).
held(a57, destination_still_approach, 4, 4).
held(a57, destination_still_retreat, 4, 4).
held(a57, destination_still_settle, 4, 4).
held(a57, destination_upright, 4, 4).
held(a57, source_clear, 4, 4).
held(a57, liquid_leaves_source, 4, 4).
held(a57, liquid_enters_destination, 4, 4).
held(a57, liquid_remains_in_destination, 4, 4).
held(a57, no_spill, 4, 4).
explored(a58, grippy_source).
held(a58, destination_still_approach, 4, 4).
held(a58, destination_still_retreat, 4, 4).
held(a58, destination_still_settle, 4, 4).
held(a58, destination_upright, 4, 4).
held(a58, source_clear, 4, 4).
held(a58, liquid_leaves_source, 4, 4).
held(a58, liquid_enters_destination, 4, 4).
held(a58, liquid_remains_in_destination, 4, 4).
held(a58, no_spill, 4, 4).
explored(a59, approach_raising).
explored(a59, bouncy_destination).
explored(a59, end_half_tilted).
explored(a59, end_mid_height).
explored(a59, fast_approach).
explored(a59, grippy_destination).
explored(a59, heavy_destination).
explored(a59, heavy_source).
explored(a59, medium_liquid).
explored(a59, pour_below_rim).
explored(a59, pour_half_tilted).
explored(a59, runny_liquid).
explored(a59, start_to_side).
explored(a59, start_upright).
held(a59, destination_still_approach, 0, 2).
held(a59, destination_still_retreat, 2, 2).
held(a59, destination_still_settle, 2, 2).
held(a59, destination_upright, 2, 2).
held(a59, source_clear, 0, 2).
held(a59, liquid_leaves_source, 0, 2).
held(a59, liquid_enters_destination, 0, 2).
held(a59, liquid_remains_in_destination, 2, 2).
held(a59, no_spill, 2, 2).
explored(a60, pour_to_side).
held(a60, destination_still_approach, 5, 5).
held(a60, destination_still_retreat, 5, 5).
held(a60, destination_still_settle, 5, 5).
held(a60, destination_upright, 5, 5).
held(a60, source_clear, 5, 5).
held(a60, liquid_leaves_source, 5, 5).
held(a60, liquid_enters_destination, 0, 5).
held(a60, liquid_remains_in_destination, 5, 5).
held(a60, no_spill, 0, 5).
explored(a61, bouncy_liquid).
explored(a61, dull_source).
explored(a61, end_level).
explored(a61, end_near_rim).
explored(a61, end_steeply_tilted).
explored(a61, fast_approach).
explored(a61, grippy_destination).
explored(a61, grippy_source).
explored(a61, heavy_source).
explored(a61, light_destination).
explored(a61, light_liquid).
explored(a61, pour_high).
explored(a61, pour_level).
explored(a61, pour_tilted_back).
explored(a61, pour_to_side).
explored(a61, retreat_raising).
explored(a61, runny_liquid).
explored(a61, some_liquid).
explored(a61, start_centred).
explored(a61, start_high).
explored(a61, start_upright).
held(a61, destination_still_approach, 2, 2).
held(a61, destination_still_retreat, 2, 2).
held(a61, destination_still_settle, 2, 2).
held(a61, destination_upright, 2, 2).
held(a61, source_clear, 2, 2).
held(a61, liquid_leaves_source, 2, 2).
held(a61, liquid_enters_destination, 2, 2).
held(a61, liquid_remains_in_destination, 2, 2).
held(a61, no_spill, 2, 2).
explored(a62, bouncy_liquid).
held(a62, destination_still_approach, 4, 4).
held(a62, destination_still_retreat, 4, 4).
held(a62, destination_still_settle, 4, 4).
held(a62, destination_upright, 4, 4).
held(a62, source_clear, 4, 4).
held(a62, liquid_leaves_source, 4, 4).
held(a62, liquid_enters_destination, 4, 4).
held(a62, liquid_remains_in_destination, 4, 4).
held(a62, no_spill, 4, 4).
explored(a63, runny_liquid).
held(a63, destination_still_approach, 4, 4).
held(a63, destination_still_retreat, 4, 4).
held(a63, destination_still_settle, 4, 4).
held(a63, destination_upright, 4, 4).
held(a63, source_clear, 4, 4).
held(a63, liquid_leaves_source, 4, 4).
held(a63, liquid_enters_destination, 4, 4).
held(a63, liquid_remains_in_destination, 4, 4).
held(a63, no_spill, 4, 4).
explored(a64, dull_liquid).
explored(a64, end_high).
explored(a64, end_steeply_tilted).
explored(a64, grippy_source).
explored(a64, heavy_source).
explored(a64, light_destination).
explored(a64, light_liquid).
explored(a64, moderate_approach).
explored(a64, moderate_retreat).
explored(a64, pour_level).
explored(a64, pour_low).
explored(a64, pour_slightly_tilted).
explored(a64, pour_to_side).
explored(a64, slippery_destination).
explored(a64, start_mid_height).
explored(a64, sticky_liquid).
explored(a64, very_much_liquid).
held(a64, destination_still_approach, 2, 2).
held(a64, destination_still_retreat, 2, 2).
held(a64, destination_still_settle, 2, 2).
held(a64, destination_upright, 2, 2).
held(a64, source_clear, 2, 2).
held(a64, liquid_leaves_source, 2, 2).
held(a64, liquid_enters_destination, 0, 2).
held(a64, liquid_remains_in_destination, 2, 2).
held(a64, no_spill, 0, 2).
explored(a65, little_liquid).
held(a65, destination_still_approach, 4, 4).
held(a65, destination_still_retreat, 4, 4).
held(a65, destination_still_settle, 4, 4).
held(a65, destination_upright, 4, 4).
held(a65, source_clear, 4, 4).
held(a65, liquid_leaves_source, 4, 4).
held(a65, liquid_enters_destination, 4, 4).
held(a65, liquid_remains_in_destination, 4, 4).
held(a65, no_spill, 4, 4).
explored(a66, heavy_source).
held(a66, destination_still_approach, 4, 4).
held(a66, destination_still_retreat, 4, 4).
held(a66, destination_still_settle, 4, 4).
held(a66, destination_upright, 4, 4).
held(a66, source_clear, 4, 4).
held(a66, liquid_leaves_source, 4, 4).
held(a66, liquid_enters_destination, 4, 4).
held(a66, liquid_remains_in_destination, 4, 4).
held(a66, no_spill, 4, 4).
explored(a67, approach_moving_away).
explored(a67, bouncy_source).
explored(a67, dull_destination).
explored(a67, dull_liquid).
explored(a67, end_high).
explored(a67, end_to_side).
explored(a67, end_upside_down).
explored(a67, heavy_source).
explored(a67, light_destination).
explored(a67, light_liquid).
explored(a67, moderate_approach).
explored(a67, pour_high).
explored(a67, pour_in_line).
explored(a67, pour_level).
explored(a67, pour_tilted_back).
explored(a67, pour_to_side).
explored(a67, slow_retreat).
explored(a67, some_liquid).
explored(a67, start_below_rim).
explored(a67, start_tilted_back).
explored(a67, sticky_liquid).
held(a67, destination_still_approach, 2, 2).
held(a67, destination_still_retreat, 2, 2).
held(a67, destination_still_settle, 2, 2).
held(a67, destination_upright, 2, 2).
held(a67, source_clear, 1, 2).
held(a67, liquid_leaves_source, 2, 2).
held(a67, liquid_enters_destination, 0, 2).
held(a67, liquid_remains_in_destination, 1, 2).
held(a67, no_spill, 0, 2).
explored(a68, fast_approach).
held(a68, destination_still_approach, 4, 4).
held(a68, destination_still_retreat, 4, 4).
held(a68, destination_still_settle, 4, 4).
held(a68, destination_upright, 4, 4).
held(a68, source_clear, 4, 4).
held(a68, liquid_leaves_source, 4, 4).
held(a68, liquid_enters_destination, 4, 4).
held(a68, liquid_remains_in_destination, 4, 4).
held(a68, no_spill, 4, 4).
explored(a69, bouncy_source).
held(a69, destination_still_approach, 4, 4).
held(a69, destination_still_retreat, 4, 4).
held(a69, destination_still_settle, 4, 4).
held(a69, destination_upright, 4, 4).
held(a69, source_clear, 4, 4).
held(a69, liquid_leaves_source, 4, 4).
held(a69, liquid_enters_destination, 4, 4).
held(a69, liquid_remains_in_destination, 4, 4).
held(a69, no_spill, 4, 4).
explored(a70, approach_moving_away).
explored(a70, dull_source).
explored(a70, end_mid_height).
explored(a70, end_rolled).
explored(a70, end_upright).
explored(a70, heavy_source).
explored(a70, light_destination).
explored(a70, medium_liquid).
explored(a70, much_liquid).
explored(a70, pour_below_rim).
explored(a70, pour_far_away).
explored(a70, pour_in_line).
explored(a70, pour_level).
explored(a70, pour_upright).
explored(a70, retreat_moving_away).
explored(a70, slippery_source).
explored(a70, slow_approach).
explored(a70, start_tilted_back).
explored(a70, start_very_high).
explored(a70, sticky_liquid).
held(a70, destination_still_approach, 2, 2).
held(a70, destination_still_retreat, 2, 2).
held(a70, destination_still_settle, 2, 2).
held(a70, destination_upright, 2, 2).
held(a70, source_clear, 2, 2).
held(a70, liquid_leaves_source, 0, 2).
held(a70, liquid_enters_destination, 0, 2).
held(a70, liquid_remains_in_destination, 2, 2).
held(a70, no_spill, 2, 2).
explored(a71, dull_liquid).
held(a71, destination_still_approach, 4, 4).
held(a71, destination_still_retreat, 4, 4).
held(a71, destination_still_settle, 4, 4).
held(a71, destination_upright, 4, 4).
held(a71, source_clear, 4, 4).
held(a71, liquid_leaves_source, 4, 4).
held(a71, liquid_enters_destination, 4, 4).
held(a71, liquid_remains_in_destination, 4, 4).
held(a71, no_spill, 4, 4).
explored(a72, slippery_destination).
held(a72, destination_still_approach, 4, 6).
held(a72, destination_still_retreat, 4, 6).
held(a72, destination_still_settle, 6, 6).
held(a72, destination_upright, 6, 6).
held(a72, source_clear, 6, 6).
held(a72, liquid_leaves_source, 6, 6).
held(a72, liquid_enters_destination, 6, 6).
held(a72, liquid_remains_in_destination, 6, 6).
held(a72, no_spill, 6, 6).
explored(a73, approach_lowering).
explored(a73, dull_liquid).
explored(a73, end_upside_down).
explored(a73, end_very_high).
explored(a73, light_source).
explored(a73, medium_destination).
explored(a73, moderate_approach).
explored(a73, much_liquid).
explored(a73, pour_far_away).
explored(a73, pour_in_line).
explored(a73, pour_mid_height).
explored(a73, pour_rolled).
explored(a73, retreat_moving_away).
explored(a73, slippery_destination).
explored(a73, slow_retreat).
explored(a73, start_near_rim).
explored(a73, start_tilted_back).
held(a73, destination_still_approach, 2, 2).
held(a73, destination_still_retreat, 2, 2).
held(a73, destination_still_settle, 2, 2).
held(a73, destination_upright, 2, 2).
held(a73, source_clear, 2, 2).
held(a73, liquid_leaves_source, 2, 2).
held(a73, liquid_enters_destination, 0, 2).
held(a73, liquid_remains_in_destination, 2, 2).
held(a73, no_spill, 0, 2).
explored(a74, start_slightly_tilted).
held(a74, destination_still_approach, 4, 4).
held(a74, destination_still_retreat, 4, 4).
held(a74, destination_still_settle, 4, 4).
held(a74, destination_upright, 4, 4).
held(a74, source_clear, 4, 4).
held(a74, liquid_leaves_source, 4, 4).
held(a74, liquid_enters_destination, 4, 4).
held(a74, liquid_remains_in_destination, 4, 4).
held(a74, no_spill, 4, 4).
explored(a75, end_slightly_tilted).
held(a75, destination_still_approach, 4, 4).
held(a75, destination_still_retreat, 4, 4).
held(a75, destination_still_settle, 4, 4).
held(a75, destination_upright, 4, 4).
held(a75, source_clear, 4, 4).
held(a75, liquid_leaves_source, 4, 4).
held(a75, liquid_enters_destination, 4, 4).
held(a75, liquid_remains_in_destination, 4, 4).
held(a75, no_spill, 4, 4).
explored(a76, bouncy_liquid).
explored(a76, dull_destination).
explored(a76, dull_source).
explored(a76, end_half_tilted).
explored(a76, end_mid_height).
explored(a76, end_rolled).
explored(a76, grippy_source).
explored(a76, heavy_liquid).
explored(a76, light_source).
explored(a76, little_liquid).
explored(a76, medium_destination).
explored(a76, pour_in_line).
explored(a76, pour_rolled).
explored(a76, pour_to_side).
explored(a76, pour_very_high).
explored(a76, retreat_moving_away).
explored(a76, slow_retreat).
explored(a76, start_to_side).
explored(a76, start_upright).
explored(a76, sticky_liquid).
held(a76, destination_still_approach, 2, 2).
held(a76, destination_still_retreat, 1, 2).
held(a76, destination_still_settle, 2, 2).
held(a76, destination_upright, 2, 2).
held(a76, source_clear, 2, 2).
held(a76, liquid_leaves_source, 2, 2).
held(a76, liquid_enters_destination, 0, 2).
held(a76, liquid_remains_in_destination, 2, 2).
held(a76, no_spill, 0, 2).
explored(a77, heavy_liquid).
held(a77, destination_still_approach, 4, 4).
held(a77, destination_still_retreat, 4, 4).
held(a77, destination_still_settle, 4, 4).
held(a77, destination_upright, 4, 4).
held(a77, source_clear, 4, 4).
held(a77, liquid_leaves_source, 4, 4).
held(a77, liquid_enters_destination, 4, 4).
held(a77, liquid_remains_in_destination, 4, 4).
held(a77, no_spill, 4, 4).
explored(a78, bouncy_source).
explored(a78, dull_liquid).
explored(a78, end_centred).
explored(a78, end_mid_height).
explored(a78, end_rolled).
explored(a78, end_upside_down).
explored(a78, fast_retreat).
explored(a78, heavy_destination).
explored(a78, heavy_liquid).
explored(a78, light_source).
explored(a78, pour_far_away).
explored(a78, pour_rolled).
explored(a78, pour_slightly_tilted).
explored(a78, pour_very_high).
explored(a78, runny_liquid).
explored(a78, slippery_destination).
explored(a78, slippery_source).
explored(a78, some_liquid).
explored(a78, start_near_rim).
explored(a78, start_slightly_tilted).
explored(a78, start_very_high).
held(a78, destination_still_approach, 2, 2).
held(a78, destination_still_retreat, 2, 2).
held(a78, destination_still_settle, 0, 2).
held(a78, destination_upright, 2, 2).
held(a78, source_clear, 2, 2).
held(a78, liquid_leaves_source, 2, 2).
held(a78, liquid_enters_destination, 2, 2).
held(a78, liquid_remains_in_destination, 2, 2).
held(a78, no_spill, 2, 2).
explored(a79, end_near_rim).
held(a79, destination_still_approach, 4, 4).
held(a79, destination_still_retreat, 4, 4).
held(a79, destination_still_settle, 4, 4).
held(a79, destination_upright, 4, 4).
held(a79, source_clear, 4, 4).
held(a79, liquid_leaves_source, 4, 4).
held(a79, liquid_enters_destination, 4, 4).
held(a79, liquid_remains_in_destination, 4, 4).
held(a79, no_spill, 4, 4).
explored(a80, approach_lowering).
explored(a80, bouncy_source).
explored(a80, end_slightly_tilted).
explored(a80, grippy_destination).
explored(a80, heavy_source).
explored(a80, light_liquid).
explored(a80, little_liquid).
explored(a80, pour_in_line).
explored(a80, pour_low).
explored(a80, pour_rolled).
explored(a80, pour_steeply_tilted).
explored(a80, retreat_lowering).
explored(a80, retreat_moving_away).
explored(a80, start_slightly_tilted).
held(a80, destination_still_approach, 1, 2).
held(a80, destination_still_retreat, 0, 2).
held(a80, destination_still_settle, 2, 2).
held(a80, destination_upright, 0, 2).
held(a80, source_clear, 0, 2).
held(a80, liquid_leaves_source, 1, 2).
held(a80, liquid_enters_destination, 2, 2).
held(a80, liquid_remains_in_destination, 1, 2).
held(a80, no_spill, 2, 2).
explored(a81, heavy_destination).
held(a81, destination_still_approach, 4, 4).
held(a81, destination_still_retreat, 4, 4).
held(a81, destination_still_settle, 4, 4).
held(a81, destination_upright, 4, 4).
held(a81, source_clear, 4, 4).
held(a81, liquid_leaves_source, 4, 4).
held(a81, liquid_enters_destination, 4, 4).
held(a81, liquid_remains_in_destination, 4, 4).
held(a81, no_spill, 4, 4).
explored(a82, end_centred).
held(a82, destination_still_approach, 3, 3).
held(a82, destination_still_retreat, 3, 3).
held(a82, destination_still_settle, 3, 3).
held(a82, destination_upright, 3, 3).
held(a82, source_clear, 3, 3).
held(a82, liquid_leaves_source, 3, 3).
held(a82, liquid_enters_destination, 3, 3).
held(a82, liquid_remains_in_destination, 3, 3).
held(a82, no_spill, 3, 3).
explored(a83, bouncy_liquid).
explored(a83, dull_destination).
explored(a83, dull_source).
explored(a83, end_half_tilted).
explored(a83, end_mid_height).
explored(a83, end_near_rim).
explored(a83, grippy_destination).
explored(a83, heavy_liquid).
explored(a83, light_destination).
explored(a83, pour_centred).
explored(a83, pour_in_line).
explored(a83, pour_low).
explored(a83, pour_upside_down).
explored(a83, some_liquid).
explored(a83, start_centred).
explored(a83, start_low).
explored(a83, start_upright).
held(a83, destination_still_approach, 1, 2).
held(a83, destination_still_retreat, 1, 2).
held(a83, destination_still_settle, 2, 2).
held(a83, destination_upright, 2, 2).
held(a83, source_clear, 1, 2).
held(a83, liquid_leaves_source, 2, 2).
held(a83, liquid_enters_destination, 2, 2).
held(a83, liquid_remains_in_destination, 2, 2).
held(a83, no_spill, 2, 2).
explored(a84, bouncy_destination).
explored(a84, dull_liquid).
explored(a84, dull_source).
explored(a84, end_far_away).
explored(a84, end_rolled).
explored(a84, end_steeply_tilted).
explored(a84, fast_approach).
explored(a84, grippy_source).
explored(a84, pour_upright).
explored(a84, retreat_raising).
explored(a84, some_liquid).
explored(a84, start_to_side).
explored(a84, start_very_high).
held(a84, destination_still_approach, 2, 2).
held(a84, destination_still_retreat, 2, 2).
held(a84, destination_still_settle, 2, 2).
held(a84, destination_upright, 2, 2).
held(a84, source_clear, 2, 2).
held(a84, liquid_leaves_source, 0, 2).
held(a84, liquid_enters_destination, 0, 2).
held(a84, liquid_remains_in_destination, 2, 2).
held(a84, no_spill, 2, 2).
explored(a85, pour_low).
explored(a85, pour_to_side).
held(a85, destination_still_approach, 4, 4).
held(a85, destination_still_retreat, 4, 4).
held(a85, destination_still_settle, 4, 4).
held(a85, destination_upright, 4, 4).
held(a85, source_clear, 4, 4).
held(a85, liquid_leaves_source, 4, 4).
held(a85, liquid_enters_destination, 0, 4).
held(a85, liquid_remains_in_destination, 4, 4).
held(a85, no_spill, 0, 4).
explored(a86, approach_raising).
explored(a86, dull_source).
explored(a86, end_centred).
explored(a86, end_high).
explored(a86, end_level).
explored(a86, end_tilted_back).
explored(a86, fast_retreat).
explored(a86, heavy_destination).
explored(a86, pour_far_away).
explored(a86, pour_offset_sideways).
explored(a86, pour_rolled).
explored(a86, pour_very_high).
explored(a86, runny_liquid).
explored(a86, slow_approach).
explored(a86, start_tilted_back).
held(a86, destination_still_approach, 2, 2).
held(a86, destination_still_retreat, 2, 2).
held(a86, destination_still_settle, 2, 2).
held(a86, destination_upright, 2, 2).
held(a86, source_clear, 2, 2).
held(a86, liquid_leaves_source, 2, 2).
held(a86, liquid_enters_destination, 0, 2).
held(a86, liquid_remains_in_destination, 2, 2).
held(a86, no_spill, 0, 2).
explored(a87, pour_low).
held(a87, destination_still_approach, 7, 9).
held(a87, destination_still_retreat, 7, 9).
held(a87, destination_still_settle, 9, 9).
held(a87, destination_upright, 9, 9).
held(a87, source_clear, 4, 9).
held(a87, liquid_leaves_source, 9, 9).
held(a87, liquid_enters_destination, 9, 9).
held(a87, liquid_remains_in_destination, 9, 9).
held(a87, no_spill, 9, 9).
explored(a88, bouncy_liquid).
explored(a88, dull_destination).
explored(a88, dull_source).
explored(a88, end_half_tilted).
explored(a88, end_level).
explored(a88, end_mid_height).
explored(a88, grippy_source).
explored(a88, heavy_destination).
explored(a88, light_liquid).
explored(a88, light_source).
explored(a88, moderate_approach).
explored(a88, moderate_retreat).
explored(a88, pour_in_line).
explored(a88, pour_steeply_tilted).
explored(a88, pour_to_side).
explored(a88, retreat_moving_away).
explored(a88, runny_liquid).
explored(a88, some_liquid).
explored(a88, start_far_away).
explored(a88, start_very_high).
held(a88, destination_still_approach, 2, 2).
held(a88, destination_still_retreat, 2, 2).
held(a88, destination_still_settle, 2, 2).
held(a88, destination_upright, 2, 2).
held(a88, source_clear, 2, 2).
held(a88, liquid_leaves_source, 1, 2).
held(a88, liquid_enters_destination, 1, 2).
held(a88, liquid_remains_in_destination, 2, 2).
held(a88, no_spill, 2, 2).
explored(a89, approach_moving_away).
explored(a89, bouncy_source).
explored(a89, dull_liquid).
explored(a89, end_centred).
explored(a89, end_level).
explored(a89, end_steeply_tilted).
explored(a89, fast_retreat).
explored(a89, grippy_destination).
explored(a89, heavy_destination).
explored(a89, light_liquid).
explored(a89, light_source).
explored(a89, pour_far_away).
explored(a89, pour_offset_sideways).
explored(a89, pour_upright).
explored(a89, runny_liquid).
explored(a89, slow_approach).
explored(a89, start_mid_height).
explored(a89, start_upright).
held(a89, destination_still_approach, 2, 2).
held(a89, destination_still_retreat, 2, 2).
held(a89, destination_still_settle, 2, 2).
held(a89, destination_upright, 2, 2).
held(a89, source_clear, 2, 2).
held(a89, liquid_leaves_source, 2, 2).
held(a89, liquid_enters_destination, 0, 2).
held(a89, liquid_remains_in_destination, 2, 2).
held(a89, no_spill, 0, 2).
explored(a90, bouncy_destination).
explored(a90, bouncy_source).
explored(a90, dull_liquid).
explored(a90, end_below_rim).
explored(a90, end_rolled).
explored(a90, end_steeply_tilted).
explored(a90, fast_approach).
explored(a90, grippy_destination).
explored(a90, light_destination).
explored(a90, light_liquid).
explored(a90, light_source).
explored(a90, pour_centred).
explored(a90, pour_mid_height).
explored(a90, pour_offset_sideways).
explored(a90, pour_tilted_back).
explored(a90, retreat_moving_closer).
explored(a90, some_liquid).
explored(a90, start_far_away).
explored(a90, start_tilted_back).
explored(a90, sticky_liquid).
held(a90, destination_still_approach, 2, 2).
held(a90, destination_still_retreat, 0, 2).
held(a90, destination_still_settle, 1, 2).
held(a90, destination_upright, 1, 2).
held(a90, source_clear, 0, 2).
held(a90, liquid_leaves_source, 2, 2).
held(a90, liquid_enters_destination, 2, 2).
held(a90, liquid_remains_in_destination, 1, 2).
held(a90, no_spill, 1, 2).
explored(a91, pour_below_rim).
explored(a91, pour_far_away).
held(a91, destination_still_approach, 2, 2).
held(a91, destination_still_retreat, 2, 2).
held(a91, destination_still_settle, 2, 2).
held(a91, destination_upright, 2, 2).
held(a91, source_clear, 2, 2).
held(a91, liquid_leaves_source, 2, 2).
held(a91, liquid_enters_destination, 0, 2).
held(a91, liquid_remains_in_destination, 2, 2).
held(a91, no_spill, 0, 2).
explored(a92, approach_moving_away).
explored(a92, bouncy_liquid).
explored(a92, end_level).
explored(a92, end_steeply_tilted).
explored(a92, moderate_approach).
explored(a92, much_liquid).
explored(a92, pour_half_tilted).
explored(a92, pour_in_line).
explored(a92, pour_low).
explored(a92, retreat_lowering).
explored(a92, retreat_moving_away).
explored(a92, slippery_destination).
explored(a92, slippery_source).
explored(a92, start_high).
explored(a92, sticky_liquid).
held(a92, destination_still_approach, 2, 2).
held(a92, destination_still_retreat, 0, 2).
held(a92, destination_still_settle, 1, 2).
held(a92, destination_upright, 2, 2).
held(a92, source_clear, 0, 2).
held(a92, liquid_leaves_source, 2, 2).
held(a92, liquid_enters_destination, 2, 2).
held(a92, liquid_remains_in_destination, 1, 2).
held(a92, no_spill, 1, 2).
explored(a93, bouncy_source).
explored(a93, dull_destination).
explored(a93, end_mid_height).
explored(a93, end_steeply_tilted).
explored(a93, fast_retreat).
explored(a93, heavy_source).
explored(a93, medium_destination).
explored(a93, pour_below_rim).
explored(a93, pour_in_line).
explored(a93, pour_rolled).
explored(a93, pour_slightly_tilted).
explored(a93, retreat_moving_closer).
explored(a93, runny_liquid).
explored(a93, slippery_destination).
explored(a93, start_far_away).
explored(a93, start_upright).
explored(a93, very_much_liquid).
held(a93, destination_still_approach, 0, 2).
held(a93, destination_still_retreat, 1, 2).
held(a93, destination_still_settle, 1, 2).
held(a93, destination_upright, 2, 2).
held(a93, source_clear, 0, 2).
held(a93, liquid_leaves_source, 2, 2).
held(a93, liquid_enters_destination, 2, 2).
held(a93, liquid_remains_in_destination, 1, 2).
held(a93, no_spill, 1, 2).
explored(a94, pour_offset_sideways).
explored(a94, slow_approach).
held(a94, destination_still_approach, 2, 2).
held(a94, destination_still_retreat, 2, 2).
held(a94, destination_still_settle, 2, 2).
held(a94, destination_upright, 2, 2).
held(a94, source_clear, 2, 2).
held(a94, liquid_leaves_source, 2, 2).
held(a94, liquid_enters_destination, 1, 2).
held(a94, liquid_remains_in_destination, 2, 2).
held(a94, no_spill, 1, 2).
explored(a95, dull_liquid).
explored(a95, dull_source).
explored(a95, end_half_tilted).
explored(a95, fast_approach).
explored(a95, heavy_destination).
explored(a95, heavy_liquid).
explored(a95, little_liquid).
explored(a95, moderate_retreat).
explored(a95, pour_below_rim).
explored(a95, pour_steeply_tilted).
explored(a95, retreat_moving_closer).
explored(a95, runny_liquid).
explored(a95, slippery_destination).
explored(a95, start_centred).
explored(a95, start_low).
explored(a95, start_slightly_tilted).
held(a95, destination_still_approach, 2, 2).
held(a95, destination_still_retreat, 0, 2).
held(a95, destination_still_settle, 2, 2).
held(a95, destination_upright, 2, 2).
held(a95, source_clear, 0, 2).
held(a95, liquid_leaves_source, 2, 2).
held(a95, liquid_enters_destination, 2, 2).
held(a95, liquid_remains_in_destination, 2, 2).
held(a95, no_spill, 2, 2).
explored(a96, pour_below_rim).
explored(a96, pour_tilted_back).
held(a96, destination_still_approach, 1, 8).
held(a96, destination_still_retreat, 4, 8).
held(a96, destination_still_settle, 8, 8).
held(a96, destination_upright, 7, 8).
held(a96, source_clear, 0, 8).
held(a96, liquid_leaves_source, 0, 8).
held(a96, liquid_enters_destination, 4, 8).
held(a96, liquid_remains_in_destination, 3, 8).
held(a96, no_spill, 8, 8).
explored(a97, bouncy_destination).
explored(a97, bouncy_source).
explored(a97, end_centred).
explored(a97, end_high).
explored(a97, end_level).
explored(a97, end_upside_down).
explored(a97, fast_approach).
explored(a97, heavy_liquid).
explored(a97, heavy_source).
explored(a97, medium_destination).
explored(a97, much_liquid).
explored(a97, pour_far_away).
explored(a97, pour_in_line).
explored(a97, pour_low).
explored(a97, pour_rolled).
explored(a97, pour_upright).
explored(a97, slippery_destination).
explored(a97, slippery_source).
explored(a97, start_below_rim).
explored(a97, start_far_away).
explored(a97, start_slightly_tilted).
explored(a97, sticky_liquid).
held(a97, destination_still_approach, 2, 2).
held(a97, destination_still_retreat, 1, 2).
held(a97, destination_still_settle, 2, 2).
held(a97, destination_upright, 2, 2).
held(a97, source_clear, 2, 2).
held(a97, liquid_leaves_source, 2, 2).
held(a97, liquid_enters_destination, 2, 2).
held(a97, liquid_remains_in_destination, 2, 2).
held(a97, no_spill, 2, 2).
explored(a98, pour_below_rim).
explored(a98, pour_offset_sideways).
held(a98, destination_still_approach, 1, 2).
held(a98, destination_still_retreat, 2, 2).
held(a98, destination_still_settle, 2, 2).
held(a98, destination_upright, 2, 2).
held(a98, source_clear, 0, 2).
held(a98, liquid_leaves_source, 2, 2).
held(a98, liquid_enters_destination, 0, 2).
held(a98, liquid_remains_in_destination, 2, 2).
held(a98, no_spill, 0, 2).
explored(a99, end_rolled).
explored(a99, end_to_side).
explored(a99, end_upside_down).
explored(a99, fast_retreat).
explored(a99, heavy_destination).
explored(a99, heavy_source).
explored(a99, light_liquid).
explored(a99, moderate_approach).
explored(a99, much_liquid).
explored(a99, pour_rolled).
explored(a99, pour_steeply_tilted).
explored(a99, pour_to_side).
explored(a99, pour_very_high).
explored(a99, retreat_lowering).
explored(a99, slippery_destination).
explored(a99, slippery_source).
explored(a99, start_to_side).
held(a99, destination_still_approach, 2, 2).
held(a99, destination_still_retreat, 2, 2).
held(a99, destination_still_settle, 2, 2).
held(a99, destination_upright, 2, 2).
held(a99, source_clear, 2, 2).
held(a99, liquid_leaves_source, 2, 2).
held(a99, liquid_enters_destination, 1, 2).
held(a99, liquid_remains_in_destination, 2, 2).
held(a99, no_spill, 1, 2).
explored(a100, pour_half_tilted).
explored(a100, pour_low).
held(a100, destination_still_approach, 8, 8).
held(a100, destination_still_retreat, 8, 8).
held(a100, destination_still_settle, 8, 8).
held(a100, destination_upright, 8, 8).
held(a100, source_clear, 7, 8).
held(a100, liquid_leaves_source, 0, 8).
held(a100, liquid_enters_destination, 0, 8).
held(a100, liquid_remains_in_destination, 4, 8).
held(a100, no_spill, 8, 8).
explored(a101, approach_lowering).
explored(a101, bouncy_liquid).
explored(a101, bouncy_source).
explored(a101, dull_destination).
explored(a101, end_level).
explored(a101, end_low).
explored(a101, end_slightly_tilted).
explored(a101, heavy_destination).
explored(a101, heavy_source).
explored(a101, pour_level).
explored(a101, pour_to_side).
explored(a101, pour_upside_down).
explored(a101, pour_very_high).
explored(a101, retreat_moving_closer).
explored(a101, slippery_destination).
explored(a101, slippery_source).
explored(a101, start_near_rim).
explored(a101, start_upright).
held(a101, destination_still_approach, 2, 2).
held(a101, destination_still_retreat, 2, 2).
held(a101, destination_still_settle, 2, 2).
held(a101, destination_upright, 2, 2).
held(a101, source_clear, 2, 2).
held(a101, liquid_leaves_source, 2, 2).
held(a101, liquid_enters_destination, 0, 2).
held(a101, liquid_remains_in_destination, 2, 2).
held(a101, no_spill, 0, 2).
explored(a102, approach_moving_away).
explored(a102, approach_raising).
explored(a102, bouncy_liquid).
explored(a102, dull_destination).
explored(a102, end_high).
explored(a102, end_level).
explored(a102, end_steeply_tilted).
explored(a102, end_to_side).
explored(a102, fast_retreat).
explored(a102, light_source).
explored(a102, pour_low).
explored(a102, pour_near_rim).
explored(a102, pour_rolled).
explored(a102, pour_slightly_tilted).
explored(a102, slippery_destination).
explored(a102, slippery_source).
explored(a102, start_slightly_tilted).
held(a102, destination_still_approach, 0, 2).
held(a102, destination_still_retreat, 2, 2).
held(a102, destination_still_settle, 1, 2).
held(a102, destination_upright, 2, 2).
held(a102, source_clear, 0, 2).
held(a102, liquid_leaves_source, 2, 2).
held(a102, liquid_enters_destination, 2, 2).
held(a102, liquid_remains_in_destination, 1, 2).
held(a102, no_spill, 1, 2).
explored(a103, pour_low).
explored(a103, pour_slightly_tilted).
held(a103, destination_still_approach, 5, 5).
held(a103, destination_still_retreat, 5, 5).
held(a103, destination_still_settle, 5, 5).
held(a103, destination_upright, 5, 5).
held(a103, source_clear, 5, 5).
held(a103, liquid_leaves_source, 0, 5).
held(a103, liquid_enters_destination, 0, 5).
held(a103, liquid_remains_in_destination, 4, 5).
held(a103, no_spill, 5, 5).
explored(a104, pour_low).
explored(a104, pour_upright).
held(a104, destination_still_approach, 2, 2).
held(a104, destination_still_retreat, 2, 2).
held(a104, destination_still_settle, 2, 2).
held(a104, destination_upright, 2, 2).
held(a104, source_clear, 2, 2).
held(a104, liquid_leaves_source, 0, 2).
held(a104, liquid_enters_destination, 0, 2).
held(a104, liquid_remains_in_destination, 2, 2).
held(a104, no_spill, 2, 2).
explored(a105, bouncy_liquid).
explored(a105, dull_destination).
explored(a105, dull_source).
explored(a105, end_half_tilted).
explored(a105, end_rolled).
explored(a105, end_very_high).
explored(a105, heavy_liquid).
explored(a105, heavy_source).
explored(a105, light_destination).
explored(a105, moderate_approach).
explored(a105, much_liquid).
explored(a105, pour_half_tilted).
explored(a105, pour_mid_height).
explored(a105, pour_offset_sideways).
explored(a105, pour_rolled).
explored(a105, retreat_moving_closer).
explored(a105, slippery_destination).
explored(a105, start_mid_height).
explored(a105, start_slightly_tilted).
explored(a105, sticky_liquid).
held(a105, destination_still_approach, 2, 2).
held(a105, destination_still_retreat, 1, 2).
held(a105, destination_still_settle, 2, 2).
held(a105, destination_upright, 2, 2).
held(a105, source_clear, 2, 2).
held(a105, liquid_leaves_source, 0, 2).
held(a105, liquid_enters_destination, 0, 2).
held(a105, liquid_remains_in_destination, 2, 2).
held(a105, no_spill, 2, 2).
explored(a106, approach_moving_closer).
explored(a106, end_level).
explored(a106, end_steeply_tilted).
explored(a106, fast_retreat).
explored(a106, grippy_destination).
explored(a106, heavy_source).
explored(a106, light_liquid).
explored(a106, moderate_approach).
explored(a106, pour_far_away).
explored(a106, pour_in_line).
explored(a106, pour_upside_down).
explored(a106, retreat_moving_away).
explored(a106, retreat_raising).
explored(a106, runny_liquid).
explored(a106, some_liquid).
explored(a106, start_mid_height).
explored(a106, start_slightly_tilted).
held(a106, destination_still_approach, 2, 2).
held(a106, destination_still_retreat, 2, 2).
held(a106, destination_still_settle, 2, 2).
held(a106, destination_upright, 2, 2).
held(a106, source_clear, 2, 2).
held(a106, liquid_leaves_source, 2, 2).
held(a106, liquid_enters_destination, 0, 2).
held(a106, liquid_remains_in_destination, 2, 2).
held(a106, no_spill, 0, 2).
explored(a107, bouncy_liquid).
explored(a107, bouncy_source).
explored(a107, dull_destination).
explored(a107, end_near_rim).
explored(a107, end_rolled).
explored(a107, heavy_liquid).
explored(a107, heavy_source).
explored(a107, medium_destination).
explored(a107, moderate_retreat).
explored(a107, pour_low).
explored(a107, pour_near_rim).
explored(a107, pour_offset_sideways).
explored(a107, pour_upright).
explored(a107, slippery_source).
explored(a107, slow_approach).
explored(a107, start_centred).
explored(a107, start_high).
held(a107, destination_still_approach, 2, 2).
held(a107, destination_still_retreat, 2, 2).
held(a107, destination_still_settle, 2, 2).
held(a107, destination_upright, 2, 2).
held(a107, source_clear, 2, 2).
held(a107, liquid_leaves_source, 0, 2).
held(a107, liquid_enters_destination, 0, 2).
held(a107, liquid_remains_in_destination, 2, 2).
held(a107, no_spill, 2, 2).
explored(a108, dull_destination).
explored(a108, end_level).
explored(a108, end_upright).
explored(a108, end_very_high).
explored(a108, fast_retreat).
explored(a108, grippy_destination).
explored(a108, heavy_source).
explored(a108, light_liquid).
explored(a108, medium_destination).
explored(a108, moderate_approach).
explored(a108, pour_half_tilted).
explored(a108, pour_high).
explored(a108, pour_offset_sideways).
explored(a108, pour_rolled).
explored(a108, retreat_moving_away).
explored(a108, slippery_source).
explored(a108, start_far_away).
explored(a108, start_high).
explored(a108, start_slightly_tilted).
explored(a108, sticky_liquid).
held(a108, destination_still_approach, 2, 2).
held(a108, destination_still_retreat, 2, 2).
held(a108, destination_still_settle, 2, 2).
held(a108, destination_upright, 2, 2).
held(a108, source_clear, 2, 2).
held(a108, liquid_leaves_source, 0, 2).
held(a108, liquid_enters_destination, 0, 2).
held(a108, liquid_remains_in_destination, 2, 2).
held(a108, no_spill, 2, 2).
explored(a109, retreat_moving_closer).
held(a109, destination_still_approach, 3, 3).
held(a109, destination_still_retreat, 3, 3).
held(a109, destination_still_settle, 3, 3).
held(a109, destination_upright, 3, 3).
held(a109, source_clear, 3, 3).
held(a109, liquid_leaves_source, 3, 3).
held(a109, liquid_enters_destination, 3, 3).
held(a109, liquid_remains_in_destination, 3, 3).
held(a109, no_spill, 3, 3).
explored(a110, approach_raising).
explored(a110, dull_destination).
explored(a110, end_far_away).
explored(a110, end_mid_height).
explored(a110, end_rolled).
explored(a110, end_steeply_tilted).
explored(a110, fast_retreat).
explored(a110, light_destination).
explored(a110, little_liquid).
explored(a110, medium_liquid).
explored(a110, pour_centred).
explored(a110, pour_low).
explored(a110, pour_offset_sideways).
explored(a110, pour_rolled).
explored(a110, pour_upside_down).
explored(a110, runny_liquid).
explored(a110, start_far_away).
explored(a110, start_upright).
held(a110, destination_still_approach, 0, 2).
held(a110, destination_still_retreat, 2, 2).
held(a110, destination_still_settle, 2, 2).
held(a110, destination_upright, 2, 2).
held(a110, source_clear, 0, 2).
held(a110, liquid_leaves_source, 2, 2).
held(a110, liquid_enters_destination, 0, 2).
held(a110, liquid_remains_in_destination, 2, 2).
held(a110, no_spill, 0, 2).
explored(a111, pour_below_rim).
explored(a111, retreat_lowering).
held(a111, destination_still_approach, 0, 2).
held(a111, destination_still_retreat, 1, 2).
held(a111, destination_still_settle, 1, 2).
held(a111, destination_upright, 2, 2).
held(a111, source_clear, 0, 2).
held(a111, liquid_leaves_source, 2, 2).
held(a111, liquid_enters_destination, 1, 2).
held(a111, liquid_remains_in_destination, 2, 2).
held(a111, no_spill, 1, 2).
explored(a112, approach_moving_closer).
explored(a112, bouncy_liquid).
explored(a112, dull_destination).
explored(a112, end_level).
explored(a112, end_low).
explored(a112, fast_retreat).
explored(a112, grippy_destination).
explored(a112, light_destination).
explored(a112, little_liquid).
explored(a112, pour_centred).
explored(a112, pour_level).
explored(a112, pour_mid_height).
explored(a112, pour_slightly_tilted).
explored(a112, runny_liquid).
explored(a112, start_low).
held(a112, destination_still_approach, 2, 2).
held(a112, destination_still_retreat, 2, 2).
held(a112, destination_still_settle, 2, 2).
held(a112, destination_upright, 2, 2).
held(a112, source_clear, 2, 2).
held(a112, liquid_leaves_source, 0, 2).
held(a112, liquid_enters_destination, 0, 2).
held(a112, liquid_remains_in_destination, 2, 2).
held(a112, no_spill, 2, 2).
explored(a113, bouncy_liquid).
explored(a113, pour_slightly_tilted).
held(a113, destination_still_approach, 2, 2).
held(a113, destination_still_retreat, 2, 2).
held(a113, destination_still_settle, 2, 2).
held(a113, destination_upright, 2, 2).
held(a113, source_clear, 2, 2).
held(a113, liquid_leaves_source, 0, 2).
held(a113, liquid_enters_destination, 0, 2).
held(a113, liquid_remains_in_destination, 2, 2).
held(a113, no_spill, 2, 2).
explored(a114, bouncy_source).
explored(a114, dull_liquid).
explored(a114, end_high).
explored(a114, end_upside_down).
explored(a114, fast_retreat).
explored(a114, grippy_destination).
explored(a114, heavy_destination).
explored(a114, heavy_liquid).
explored(a114, light_source).
explored(a114, much_liquid).
explored(a114, pour_below_rim).
explored(a114, pour_half_tilted).
explored(a114, pour_offset_sideways).
explored(a114, start_far_away).
explored(a114, start_slightly_tilted).
explored(a114, start_very_high).
explored(a114, sticky_liquid).
held(a114, destination_still_approach, 1, 2).
held(a114, destination_still_retreat, 0, 2).
held(a114, destination_still_settle, 1, 2).
held(a114, destination_upright, 2, 2).
held(a114, source_clear, 0, 2).
held(a114, liquid_leaves_source, 2, 2).
held(a114, liquid_enters_destination, 0, 2).
held(a114, liquid_remains_in_destination, 2, 2).
held(a114, no_spill, 0, 2).
explored(a115, end_below_rim).
explored(a115, pour_low).
held(a115, destination_still_approach, 6, 9).
held(a115, destination_still_retreat, 1, 9).
held(a115, destination_still_settle, 7, 9).
held(a115, destination_upright, 5, 9).
held(a115, source_clear, 0, 9).
held(a115, liquid_leaves_source, 9, 9).
held(a115, liquid_enters_destination, 7, 9).
held(a115, liquid_remains_in_destination, 8, 9).
held(a115, no_spill, 6, 9).
explored(a116, approach_moving_away).
explored(a116, bouncy_destination).
explored(a116, bouncy_liquid).
explored(a116, end_far_away).
explored(a116, end_level).
explored(a116, end_upright).
explored(a116, fast_retreat).
explored(a116, grippy_source).
explored(a116, light_liquid).
explored(a116, medium_destination).
explored(a116, pour_half_tilted).
explored(a116, pour_high).
explored(a116, pour_level).
explored(a116, pour_near_rim).
explored(a116, pour_offset_sideways).
explored(a116, retreat_raising).
explored(a116, slow_approach).
explored(a116, start_tilted_back).
held(a116, destination_still_approach, 2, 2).
held(a116, destination_still_retreat, 2, 2).
held(a116, destination_still_settle, 2, 2).
held(a116, destination_upright, 2, 2).
held(a116, source_clear, 2, 2).
held(a116, liquid_leaves_source, 0, 2).
held(a116, liquid_enters_destination, 0, 2).
held(a116, liquid_remains_in_destination, 2, 2).
held(a116, no_spill, 2, 2).
explored(a117, end_below_rim).
explored(a117, pour_offset_sideways).
held(a117, destination_still_approach, 4, 4).
held(a117, destination_still_retreat, 3, 4).
held(a117, destination_still_settle, 4, 4).
held(a117, destination_upright, 4, 4).
held(a117, source_clear, 2, 4).
held(a117, liquid_leaves_source, 4, 4).
held(a117, liquid_enters_destination, 1, 4).
held(a117, liquid_remains_in_destination, 4, 4).
held(a117, no_spill, 1, 4).
explored(a118, bouncy_liquid).
explored(a118, bouncy_source).
explored(a118, end_below_rim).
explored(a118, end_upright).
explored(a118, fast_retreat).
explored(a118, grippy_destination).
explored(a118, grippy_source).
explored(a118, heavy_source).
explored(a118, little_liquid).
explored(a118, medium_liquid).
explored(a118, pour_offset_sideways).
explored(a118, pour_rolled).
explored(a118, pour_upright).
explored(a118, pour_very_high).
explored(a118, retreat_moving_away).
explored(a118, slow_approach).
explored(a118, start_far_away).
explored(a118, start_low).
explored(a118, start_upright).
held(a118, destination_still_approach, 2, 2).
held(a118, destination_still_retreat, 2, 2).
held(a118, destination_still_settle, 1, 2).
held(a118, destination_upright, 2, 2).
held(a118, source_clear, 1, 2).
held(a118, liquid_leaves_source, 0, 2).
held(a118, liquid_enters_destination, 0, 2).
held(a118, liquid_remains_in_destination, 2, 2).
held(a118, no_spill, 2, 2).
explored(a119, pour_below_rim).
explored(a119, pour_half_tilted).
held(a119, destination_still_approach, 2, 4).
held(a119, destination_still_retreat, 4, 4).
held(a119, destination_still_settle, 4, 4).
held(a119, destination_upright, 4, 4).
held(a119, source_clear, 0, 4).
held(a119, liquid_leaves_source, 0, 4).
held(a119, liquid_enters_destination, 3, 4).
held(a119, liquid_remains_in_destination, 1, 4).
held(a119, no_spill, 4, 4).
explored(a120, pour_below_rim).
explored(a120, pour_upright).
held(a120, destination_still_approach, 4, 6).
held(a120, destination_still_retreat, 3, 6).
held(a120, destination_still_settle, 6, 6).
held(a120, destination_upright, 6, 6).
held(a120, source_clear, 0, 6).
held(a120, liquid_leaves_source, 0, 6).
held(a120, liquid_enters_destination, 4, 6).
held(a120, liquid_remains_in_destination, 2, 6).
held(a120, no_spill, 6, 6).
explored(a121, approach_raising).
explored(a121, dull_source).
explored(a121, end_high).
explored(a121, end_rolled).
explored(a121, end_tilted_back).
explored(a121, light_liquid).
explored(a121, much_liquid).
explored(a121, pour_in_line).
explored(a121, pour_low).
explored(a121, pour_near_rim).
explored(a121, pour_rolled).
explored(a121, pour_steeply_tilted).
explored(a121, slippery_destination).
explored(a121, slippery_source).
explored(a121, slow_approach).
explored(a121, start_far_away).
explored(a121, start_tilted_back).
explored(a121, sticky_liquid).
held(a121, destination_still_approach, 1, 2).
held(a121, destination_still_retreat, 2, 2).
held(a121, destination_still_settle, 2, 2).
held(a121, destination_upright, 2, 2).
held(a121, source_clear, 1, 2).
held(a121, liquid_leaves_source, 2, 2).
held(a121, liquid_enters_destination, 1, 2).
held(a121, liquid_remains_in_destination, 2, 2).
held(a121, no_spill, 1, 2).
explored(a122, pour_below_rim).
explored(a122, pour_slightly_tilted).
held(a122, destination_still_approach, 7, 8).
held(a122, destination_still_retreat, 5, 8).
held(a122, destination_still_settle, 7, 8).
held(a122, destination_upright, 8, 8).
held(a122, source_clear, 1, 8).
held(a122, liquid_leaves_source, 0, 8).
held(a122, liquid_enters_destination, 6, 8).
held(a122, liquid_remains_in_destination, 0, 8).
held(a122, no_spill, 8, 8).
explored(a123, approach_moving_away).
explored(a123, bouncy_source).
explored(a123, dull_liquid).
explored(a123, end_far_away).
explored(a123, end_level).
explored(a123, end_mid_height).
explored(a123, end_upside_down).
explored(a123, grippy_destination).
explored(a123, grippy_source).
explored(a123, heavy_destination).
explored(a123, heavy_source).
explored(a123, light_liquid).
explored(a123, little_liquid).
explored(a123, pour_centred).
explored(a123, pour_half_tilted).
explored(a123, pour_in_line).
explored(a123, pour_level).
explored(a123, pour_very_high).
explored(a123, runny_liquid).
explored(a123, slow_approach).
explored(a123, slow_retreat).
explored(a123, start_below_rim).
explored(a123, start_tilted_back).
held(a123, destination_still_approach, 1, 2).
held(a123, destination_still_retreat, 2, 2).
held(a123, destination_still_settle, 2, 2).
held(a123, destination_upright, 2, 2).
held(a123, source_clear, 0, 2).
held(a123, liquid_leaves_source, 2, 2).
held(a123, liquid_enters_destination, 2, 2).
held(a123, liquid_remains_in_destination, 2, 2).
held(a123, no_spill, 2, 2).
explored(a124, approach_raising).
explored(a124, bouncy_liquid).
explored(a124, end_near_rim).
explored(a124, end_rolled).
explored(a124, end_steeply_tilted).
explored(a124, end_very_high).
explored(a124, grippy_destination).
explored(a124, grippy_source).
explored(a124, heavy_liquid).
explored(a124, light_source).
explored(a124, little_liquid).
explored(a124, medium_destination).
explored(a124, moderate_approach).
explored(a124, pour_in_line).
explored(a124, pour_level).
explored(a124, pour_slightly_tilted).
explored(a124, pour_to_side).
explored(a124, pour_very_high).
explored(a124, start_centred).
explored(a124, sticky_liquid).
held(a124, destination_still_approach, 2, 2).
held(a124, destination_still_retreat, 2, 2).
held(a124, destination_still_settle, 1, 2).
held(a124, destination_upright, 2, 2).
held(a124, source_clear, 2, 2).
held(a124, liquid_leaves_source, 1, 2).
held(a124, liquid_enters_destination, 1, 2).
held(a124, liquid_remains_in_destination, 2, 2).
held(a124, no_spill, 2, 2).
explored(a125, approach_moving_away).
explored(a125, pour_slightly_tilted).
held(a125, destination_still_approach, 2, 2).
held(a125, destination_still_retreat, 2, 2).
held(a125, destination_still_settle, 2, 2).
held(a125, destination_upright, 2, 2).
held(a125, source_clear, 2, 2).
held(a125, liquid_leaves_source, 0, 2).
held(a125, liquid_enters_destination, 0, 2).
held(a125, liquid_remains_in_destination, 2, 2).
held(a125, no_spill, 2, 2).
explored(a126, dull_destination).
explored(a126, dull_liquid).
explored(a126, dull_source).
explored(a126, end_below_rim).
explored(a126, end_half_tilted).
explored(a126, light_source).
explored(a126, medium_liquid).
explored(a126, moderate_retreat).
explored(a126, much_liquid).
explored(a126, pour_centred).
explored(a126, pour_half_tilted).
explored(a126, pour_offset_sideways).
explored(a126, runny_liquid).
explored(a126, slippery_destination).
explored(a126, start_high).
explored(a126, start_upright).
held(a126, destination_still_approach, 2, 2).
held(a126, destination_still_retreat, 0, 2).
held(a126, destination_still_settle, 2, 2).
held(a126, destination_upright, 2, 2).
held(a126, source_clear, 0, 2).
held(a126, liquid_leaves_source, 2, 2).
held(a126, liquid_enters_destination, 1, 2).
held(a126, liquid_remains_in_destination, 2, 2).
held(a126, no_spill, 1, 2).
explored(a127, approach_raising).
explored(a127, dull_source).
explored(a127, end_below_rim).
explored(a127, end_rolled).
explored(a127, end_steeply_tilted).
explored(a127, light_source).
explored(a127, medium_liquid).
explored(a127, much_liquid).
explored(a127, pour_offset_sideways).
explored(a127, pour_slightly_tilted).
explored(a127, slow_approach).
explored(a127, slow_retreat).
explored(a127, start_to_side).
explored(a127, start_upright).
explored(a127, sticky_liquid).
held(a127, destination_still_approach, 1, 2).
held(a127, destination_still_retreat, 1, 2).
held(a127, destination_still_settle, 1, 2).
held(a127, destination_upright, 2, 2).
held(a127, source_clear, 0, 2).
held(a127, liquid_leaves_source, 2, 2).
held(a127, liquid_enters_destination, 1, 2).
held(a127, liquid_remains_in_destination, 1, 2).
held(a127, no_spill, 0, 2).
explored(a128, bouncy_liquid).
explored(a128, end_far_away).
explored(a128, end_low).
explored(a128, end_steeply_tilted).
explored(a128, heavy_destination).
explored(a128, medium_liquid).
explored(a128, much_liquid).
explored(a128, pour_high).
explored(a128, pour_level).
explored(a128, pour_near_rim).
explored(a128, pour_offset_sideways).
explored(a128, pour_slightly_tilted).
explored(a128, runny_liquid).
explored(a128, slow_approach).
explored(a128, slow_retreat).
explored(a128, start_high).
held(a128, destination_still_approach, 2, 2).
held(a128, destination_still_retreat, 2, 2).
held(a128, destination_still_settle, 2, 2).
held(a128, destination_upright, 2, 2).
held(a128, source_clear, 2, 2).
held(a128, liquid_leaves_source, 1, 2).
held(a128, liquid_enters_destination, 0, 2).
held(a128, liquid_remains_in_destination, 2, 2).
held(a128, no_spill, 1, 2).
explored(a129, pour_far_away).
explored(a129, pour_tilted_back).
held(a129, destination_still_approach, 2, 2).
held(a129, destination_still_retreat, 2, 2).
held(a129, destination_still_settle, 2, 2).
held(a129, destination_upright, 2, 2).
held(a129, source_clear, 2, 2).
held(a129, liquid_leaves_source, 0, 2).
held(a129, liquid_enters_destination, 0, 2).
held(a129, liquid_remains_in_destination, 2, 2).
held(a129, no_spill, 2, 2).
explored(a130, approach_moving_closer).
explored(a130, bouncy_destination).
explored(a130, end_far_away).
explored(a130, end_upside_down).
explored(a130, end_very_high).
explored(a130, grippy_source).
explored(a130, heavy_destination).
explored(a130, heavy_source).
explored(a130, light_liquid).
explored(a130, pour_below_rim).
explored(a130, pour_far_away).
explored(a130, pour_in_line).
explored(a130, pour_level).
explored(a130, slippery_destination).
explored(a130, start_mid_height).
explored(a130, start_upright).
explored(a130, sticky_liquid).
explored(a130, very_much_liquid).
held(a130, destination_still_approach, 2, 2).
held(a130, destination_still_retreat, 2, 2).
held(a130, destination_still_settle, 2, 2).
held(a130, destination_upright, 2, 2).
held(a130, source_clear, 2, 2).
held(a130, liquid_leaves_source, 2, 2).
held(a130, liquid_enters_destination, 0, 2).
held(a130, liquid_remains_in_destination, 2, 2).
held(a130, no_spill, 0, 2).
explored(a131, approach_moving_away).
explored(a131, pour_half_tilted).
held(a131, destination_still_approach, 2, 2).
held(a131, destination_still_retreat, 2, 2).
held(a131, destination_still_settle, 2, 2).
held(a131, destination_upright, 2, 2).
held(a131, source_clear, 2, 2).
held(a131, liquid_leaves_source, 0, 2).
held(a131, liquid_enters_destination, 0, 2).
held(a131, liquid_remains_in_destination, 2, 2).
held(a131, no_spill, 2, 2).
explored(a132, approach_moving_away).
explored(a132, approach_raising).
explored(a132, bouncy_destination).
explored(a132, bouncy_source).
explored(a132, end_slightly_tilted).
explored(a132, fast_approach).
explored(a132, heavy_source).
explored(a132, light_liquid).
explored(a132, little_liquid).
explored(a132, medium_destination).
explored(a132, moderate_retreat).
explored(a132, pour_half_tilted).
explored(a132, pour_rolled).
explored(a132, retreat_moving_closer).
explored(a132, slippery_destination).
explored(a132, slippery_source).
held(a132, destination_still_approach, 2, 2).
held(a132, destination_still_retreat, 2, 2).
held(a132, destination_still_settle, 2, 2).
held(a132, destination_upright, 2, 2).
held(a132, source_clear, 2, 2).
held(a132, liquid_leaves_source, 0, 2).
held(a132, liquid_enters_destination, 0, 2).
held(a132, liquid_remains_in_destination, 2, 2).
held(a132, no_spill, 2, 2).
explored(a133, pour_tilted_back).
explored(a133, retreat_moving_closer).
held(a133, destination_still_approach, 2, 2).
held(a133, destination_still_retreat, 2, 2).
held(a133, destination_still_settle, 2, 2).
held(a133, destination_upright, 2, 2).
held(a133, source_clear, 2, 2).
held(a133, liquid_leaves_source, 0, 2).
held(a133, liquid_enters_destination, 0, 2).
held(a133, liquid_remains_in_destination, 2, 2).
held(a133, no_spill, 2, 2).
explored(a134, approach_moving_closer).
explored(a134, dull_destination).
explored(a134, dull_source).
explored(a134, end_centred).
explored(a134, end_upside_down).
explored(a134, end_very_high).
explored(a134, fast_approach).
explored(a134, grippy_source).
explored(a134, heavy_destination).
explored(a134, medium_liquid).
explored(a134, pour_level).
explored(a134, pour_mid_height).
explored(a134, pour_offset_sideways).
explored(a134, pour_upright).
explored(a134, runny_liquid).
explored(a134, slippery_destination).
explored(a134, slow_retreat).
explored(a134, start_slightly_tilted).
explored(a134, start_very_high).
held(a134, destination_still_approach, 2, 2).
held(a134, destination_still_retreat, 2, 2).
held(a134, destination_still_settle, 2, 2).
held(a134, destination_upright, 2, 2).
held(a134, source_clear, 2, 2).
held(a134, liquid_leaves_source, 2, 2).
held(a134, liquid_enters_destination, 0, 2).
held(a134, liquid_remains_in_destination, 2, 2).
held(a134, no_spill, 0, 2).
explored(a135, bouncy_destination).
explored(a135, bouncy_liquid).
explored(a135, end_far_away).
explored(a135, end_mid_height).
explored(a135, end_rolled).
explored(a135, end_steeply_tilted).
explored(a135, light_source).
explored(a135, medium_destination).
explored(a135, moderate_approach).
explored(a135, pour_high).
explored(a135, pour_near_rim).
explored(a135, pour_upright).
explored(a135, runny_liquid).
explored(a135, slippery_destination).
explored(a135, slippery_source).
explored(a135, slow_retreat).
explored(a135, start_high).
explored(a135, start_tilted_back).
explored(a135, start_to_side).
explored(a135, very_much_liquid).
held(a135, destination_still_approach, 2, 2).
held(a135, destination_still_retreat, 1, 2).
held(a135, destination_still_settle, 2, 2).
held(a135, destination_upright, 2, 2).
held(a135, source_clear, 2, 2).
held(a135, liquid_leaves_source, 2, 2).
held(a135, liquid_enters_destination, 0, 2).
held(a135, liquid_remains_in_destination, 1, 2).
held(a135, no_spill, 0, 2).
explored(a136, approach_moving_away).
explored(a136, pour_tilted_back).
held(a136, destination_still_approach, 2, 2).
held(a136, destination_still_retreat, 2, 2).
held(a136, destination_still_settle, 2, 2).
held(a136, destination_upright, 2, 2).
held(a136, source_clear, 2, 2).
held(a136, liquid_leaves_source, 0, 2).
held(a136, liquid_enters_destination, 0, 2).
held(a136, liquid_remains_in_destination, 2, 2).
held(a136, no_spill, 2, 2).
explored(a137, approach_raising).
explored(a137, pour_low).
held(a137, destination_still_approach, 0, 6).
held(a137, destination_still_retreat, 5, 6).
held(a137, destination_still_settle, 6, 6).
held(a137, destination_upright, 6, 6).
held(a137, source_clear, 0, 6).
held(a137, liquid_leaves_source, 6, 6).
held(a137, liquid_enters_destination, 1, 6).
held(a137, liquid_remains_in_destination, 6, 6).
held(a137, no_spill, 2, 6).
explored(a138, approach_moving_closer).
explored(a138, bouncy_destination).
explored(a138, dull_liquid).
explored(a138, end_rolled).
explored(a138, end_slightly_tilted).
explored(a138, fast_retreat).
explored(a138, grippy_destination).
explored(a138, heavy_source).
explored(a138, little_liquid).
explored(a138, medium_liquid).
explored(a138, pour_below_rim).
explored(a138, pour_in_line).
explored(a138, pour_rolled).
explored(a138, pour_slightly_tilted).
explored(a138, retreat_lowering).
explored(a138, retreat_moving_closer).
explored(a138, slippery_source).
explored(a138, start_mid_height).
held(a138, destination_still_approach, 1, 2).
held(a138, destination_still_retreat, 0, 2).
held(a138, destination_still_settle, 2, 2).
held(a138, destination_upright, 2, 2).
held(a138, source_clear, 0, 2).
held(a138, liquid_leaves_source, 2, 2).
held(a138, liquid_enters_destination, 2, 2).
held(a138, liquid_remains_in_destination, 2, 2).
held(a138, no_spill, 2, 2).
explored(a139, end_steeply_tilted).
explored(a139, pour_slightly_tilted).
held(a139, destination_still_approach, 4, 4).
held(a139, destination_still_retreat, 4, 4).
held(a139, destination_still_settle, 4, 4).
held(a139, destination_upright, 4, 4).
held(a139, source_clear, 4, 4).
held(a139, liquid_leaves_source, 2, 4).
held(a139, liquid_enters_destination, 0, 4).
held(a139, liquid_remains_in_destination, 4, 4).
held(a139, no_spill, 2, 4).
explored(a140, bouncy_destination).
explored(a140, bouncy_liquid).
explored(a140, dull_source).
explored(a140, end_upside_down).
explored(a140, end_very_high).
explored(a140, heavy_source).
explored(a140, light_destination).
explored(a140, medium_liquid).
explored(a140, moderate_approach).
explored(a140, pour_centred).
explored(a140, pour_half_tilted).
explored(a140, pour_low).
explored(a140, pour_rolled).
explored(a140, retreat_moving_away).
explored(a140, slippery_source).
explored(a140, start_centred).
explored(a140, start_upright).
explored(a140, start_very_high).
explored(a140, sticky_liquid).
held(a140, destination_still_approach, 2, 2).
held(a140, destination_still_retreat, 1, 2).
held(a140, destination_still_settle, 2, 2).
held(a140, destination_upright, 2, 2).
held(a140, source_clear, 2, 2).
held(a140, liquid_leaves_source, 2, 2).
held(a140, liquid_enters_destination, 1, 2).
held(a140, liquid_remains_in_destination, 2, 2).
held(a140, no_spill, 1, 2).
explored(a141, end_steeply_tilted).
explored(a141, pour_upright).
held(a141, destination_still_approach, 4, 4).
held(a141, destination_still_retreat, 4, 4).
held(a141, destination_still_settle, 4, 4).
held(a141, destination_upright, 4, 4).
held(a141, source_clear, 4, 4).
held(a141, liquid_leaves_source, 2, 4).
held(a141, liquid_enters_destination, 1, 4).
held(a141, liquid_remains_in_destination, 4, 4).
held(a141, no_spill, 3, 4).
explored(a142, approach_moving_away).
explored(a142, bouncy_destination).
explored(a142, dull_liquid).
explored(a142, dull_source).
explored(a142, end_steeply_tilted).
explored(a142, heavy_destination).
explored(a142, heavy_source).
explored(a142, light_liquid).
explored(a142, pour_half_tilted).
explored(a142, pour_low).
explored(a142, pour_near_rim).
explored(a142, retreat_raising).
explored(a142, runny_liquid).
explored(a142, slippery_destination).
explored(a142, slippery_source).
explored(a142, slow_retreat).
explored(a142, start_high).
explored(a142, start_tilted_back).
explored(a142, very_much_liquid).
held(a142, destination_still_approach, 2, 2).
held(a142, destination_still_retreat, 1, 2).
held(a142, destination_still_settle, 2, 2).
held(a142, destination_upright, 2, 2).
held(a142, source_clear, 1, 2).
held(a142, liquid_leaves_source, 2, 2).
held(a142, liquid_enters_destination, 2, 2).
held(a142, liquid_remains_in_destination, 2, 2).
held(a142, no_spill, 2, 2).
explored(a143, end_below_rim).
explored(a143, end_steeply_tilted).
held(a143, destination_still_approach, 4, 4).
held(a143, destination_still_retreat, 2, 4).
held(a143, destination_still_settle, 2, 4).
held(a143, destination_upright, 4, 4).
held(a143, source_clear, 1, 4).
held(a143, liquid_leaves_source, 4, 4).
held(a143, liquid_enters_destination, 4, 4).
held(a143, liquid_remains_in_destination, 2, 4).
held(a143, no_spill, 2, 4).
explored(a144, pour_low).
explored(a144, retreat_lowering).
held(a144, destination_still_approach, 7, 10).
held(a144, destination_still_retreat, 1, 10).
held(a144, destination_still_settle, 8, 10).
held(a144, destination_upright, 6, 10).
held(a144, source_clear, 0, 10).
held(a144, liquid_leaves_source, 10, 10).
held(a144, liquid_enters_destination, 8, 10).
held(a144, liquid_remains_in_destination, 9, 10).
held(a144, no_spill, 7, 10).
explored(a145, approach_moving_away).
explored(a145, dull_destination).
explored(a145, dull_liquid).
explored(a145, end_level).
explored(a145, end_near_rim).
explored(a145, fast_retreat).
explored(a145, grippy_destination).
explored(a145, medium_liquid).
explored(a145, pour_centred).
explored(a145, pour_level).
explored(a145, pour_low).
explored(a145, pour_offset_sideways).
explored(a145, pour_upside_down).
explored(a145, retreat_raising).
explored(a145, slippery_source).
explored(a145, start_tilted_back).
explored(a145, very_much_liquid).
held(a145, destination_still_approach, 1, 2).
held(a145, destination_still_retreat, 1, 2).
held(a145, destination_still_settle, 2, 2).
held(a145, destination_upright, 2, 2).
held(a145, source_clear, 0, 2).
held(a145, liquid_leaves_source, 2, 2).
held(a145, liquid_enters_destination, 1, 2).
held(a145, liquid_remains_in_destination, 2, 2).
held(a145, no_spill, 1, 2).
explored(a146, pour_below_rim).
explored(a146, pour_rolled).
held(a146, destination_still_approach, 0, 2).
held(a146, destination_still_retreat, 0, 2).
held(a146, destination_still_settle, 1, 2).
held(a146, destination_upright, 2, 2).
held(a146, source_clear, 0, 2).
held(a146, liquid_leaves_source, 2, 2).
held(a146, liquid_enters_destination, 2, 2).
held(a146, liquid_remains_in_destination, 1, 2).
held(a146, no_spill, 1, 2).
explored(a147, bouncy_source).
explored(a147, dull_destination).
explored(a147, end_mid_height).
explored(a147, end_rolled).
explored(a147, end_tilted_back).
explored(a147, fast_approach).
explored(a147, grippy_destination).
explored(a147, grippy_source).
explored(a147, heavy_source).
explored(a147, light_liquid).
explored(a147, much_liquid).
explored(a147, pour_below_rim).
explored(a147, pour_in_line).
explored(a147, pour_rolled).
explored(a147, pour_upright).
explored(a147, retreat_moving_closer).
explored(a147, start_far_away).
explored(a147, start_upright).
explored(a147, start_very_high).
held(a147, destination_still_approach, 2, 2).
held(a147, destination_still_retreat, 1, 2).
held(a147, destination_still_settle, 1, 2).
held(a147, destination_upright, 1, 2).
held(a147, source_clear, 0, 2).
held(a147, liquid_leaves_source, 0, 2).
held(a147, liquid_enters_destination, 1, 2).
held(a147, liquid_remains_in_destination, 0, 2).
held(a147, no_spill, 2, 2).
explored(a148, approach_raising).
explored(a148, pour_below_rim).
held(a148, destination_still_approach, 0, 2).
held(a148, destination_still_retreat, 1, 2).
held(a148, destination_still_settle, 2, 2).
held(a148, destination_upright, 2, 2).
held(a148, source_clear, 0, 2).
held(a148, liquid_leaves_source, 2, 2).
held(a148, liquid_enters_destination, 0, 2).
held(a148, liquid_remains_in_destination, 2, 2).
held(a148, no_spill, 0, 2).
explored(a149, approach_lowering).
explored(a149, bouncy_destination).
explored(a149, bouncy_liquid).
explored(a149, end_high).
explored(a149, end_rolled).
explored(a149, end_tilted_back).
explored(a149, grippy_source).
explored(a149, heavy_destination).
explored(a149, heavy_source).
explored(a149, much_liquid).
explored(a149, pour_centred).
explored(a149, pour_mid_height).
explored(a149, pour_offset_sideways).
explored(a149, pour_rolled).
explored(a149, pour_steeply_tilted).
explored(a149, retreat_moving_closer).
explored(a149, runny_liquid).
explored(a149, start_slightly_tilted).
explored(a149, start_to_side).
held(a149, destination_still_approach, 2, 2).
held(a149, destination_still_retreat, 2, 2).
held(a149, destination_still_settle, 2, 2).
held(a149, destination_upright, 2, 2).
held(a149, source_clear, 2, 2).
held(a149, liquid_leaves_source, 2, 2).
held(a149, liquid_enters_destination, 0, 2).
held(a149, liquid_remains_in_destination, 1, 2).
held(a149, no_spill, 0, 2).
explored(a150, pour_near_rim).
explored(a150, pour_very_high).
held(a150, destination_still_approach, 2, 2).
held(a150, destination_still_retreat, 2, 2).
held(a150, destination_still_settle, 2, 2).
held(a150, destination_upright, 2, 2).
held(a150, source_clear, 2, 2).
held(a150, liquid_leaves_source, 2, 2).
held(a150, liquid_enters_destination, 2, 2).
held(a150, liquid_remains_in_destination, 2, 2).
held(a150, no_spill, 2, 2).
explored(a151, approach_raising).
explored(a151, bouncy_destination).
explored(a151, dull_liquid).
explored(a151, dull_source).
explored(a151, end_below_rim).
explored(a151, end_level).
explored(a151, end_steeply_tilted).
explored(a151, grippy_destination).
explored(a151, heavy_destination).
explored(a151, pour_rolled).
explored(a151, pour_steeply_tilted).
explored(a151, pour_to_side).
explored(a151, pour_very_high).
explored(a151, retreat_moving_closer).
explored(a151, runny_liquid).
explored(a151, slow_approach).
explored(a151, slow_retreat).
explored(a151, some_liquid).
explored(a151, start_centred).
held(a151, destination_still_approach, 2, 2).
held(a151, destination_still_retreat, 1, 2).
held(a151, destination_still_settle, 2, 2).
held(a151, destination_upright, 2, 2).
held(a151, source_clear, 0, 2).
held(a151, liquid_leaves_source, 2, 2).
held(a151, liquid_enters_destination, 0, 2).
held(a151, liquid_remains_in_destination, 2, 2).
held(a151, no_spill, 0, 2).
explored(a152, end_upside_down).
explored(a152, pour_below_rim).
held(a152, destination_still_approach, 2, 2).
held(a152, destination_still_retreat, 0, 2).
held(a152, destination_still_settle, 2, 2).
held(a152, destination_upright, 2, 2).
held(a152, source_clear, 0, 2).
held(a152, liquid_leaves_source, 2, 2).
held(a152, liquid_enters_destination, 2, 2).
held(a152, liquid_remains_in_destination, 2, 2).
held(a152, no_spill, 2, 2).
explored(a153, bouncy_liquid).
explored(a153, dull_source).
explored(a153, end_far_away).
explored(a153, end_low).
explored(a153, end_slightly_tilted).
explored(a153, light_source).
explored(a153, medium_destination).
explored(a153, medium_liquid).
explored(a153, much_liquid).
explored(a153, pour_half_tilted).
explored(a153, pour_low).
explored(a153, pour_rolled).
explored(a153, slippery_destination).
explored(a153, slippery_source).
explored(a153, start_low).
held(a153, destination_still_approach, 1, 2).
held(a153, destination_still_retreat, 1, 2).
held(a153, destination_still_settle, 2, 2).
held(a153, destination_upright, 2, 2).
held(a153, source_clear, 0, 2).
held(a153, liquid_leaves_source, 0, 2).
held(a153, liquid_enters_destination, 1, 2).
held(a153, liquid_remains_in_destination, 2, 2).
held(a153, no_spill, 2, 2).
explored(a154, approach_lowering).
explored(a154, bouncy_destination).
explored(a154, bouncy_liquid).
explored(a154, bouncy_source).
explored(a154, end_upright).
explored(a154, end_very_high).
explored(a154, heavy_source).
explored(a154, light_destination).
explored(a154, light_liquid).
explored(a154, pour_centred).
explored(a154, pour_in_line).
explored(a154, pour_low).
explored(a154, pour_rolled).
explored(a154, pour_tilted_back).
explored(a154, retreat_moving_away).
explored(a154, slippery_destination).
explored(a154, slow_approach).
explored(a154, some_liquid).
explored(a154, start_centred).
held(a154, destination_still_approach, 2, 2).
held(a154, destination_still_retreat, 2, 2).
held(a154, destination_still_settle, 2, 2).
held(a154, destination_upright, 2, 2).
held(a154, source_clear, 2, 2).
held(a154, liquid_leaves_source, 0, 2).
held(a154, liquid_enters_destination, 0, 2).
held(a154, liquid_remains_in_destination, 0, 2).
held(a154, no_spill, 2, 2).
explored(a155, dull_destination).
explored(a155, dull_liquid).
explored(a155, end_far_away).
explored(a155, end_rolled).
explored(a155, end_steeply_tilted).
explored(a155, grippy_destination).
explored(a155, heavy_source).
explored(a155, light_liquid).
explored(a155, little_liquid).
explored(a155, medium_destination).
explored(a155, pour_below_rim).
explored(a155, pour_far_away).
explored(a155, pour_in_line).
explored(a155, pour_level).
explored(a155, pour_slightly_tilted).
explored(a155, retreat_raising).
explored(a155, slow_approach).
explored(a155, start_near_rim).
explored(a155, start_slightly_tilted).
held(a155, destination_still_approach, 2, 2).
held(a155, destination_still_retreat, 2, 2).
held(a155, destination_still_settle, 2, 2).
held(a155, destination_upright, 2, 2).
held(a155, source_clear, 2, 2).
held(a155, liquid_leaves_source, 1, 2).
held(a155, liquid_enters_destination, 0, 2).
held(a155, liquid_remains_in_destination, 2, 2).
held(a155, no_spill, 1, 2).
explored(a156, end_below_rim).
explored(a156, end_upside_down).
held(a156, destination_still_approach, 2, 2).
held(a156, destination_still_retreat, 0, 2).
held(a156, destination_still_settle, 1, 2).
held(a156, destination_upright, 2, 2).
held(a156, source_clear, 0, 2).
held(a156, liquid_leaves_source, 2, 2).
held(a156, liquid_enters_destination, 2, 2).
held(a156, liquid_remains_in_destination, 1, 2).
held(a156, no_spill, 1, 2).
explored(a157, bouncy_liquid).
explored(a157, bouncy_source).
explored(a157, dull_destination).
explored(a157, end_half_tilted).
explored(a157, end_level).
explored(a157, fast_retreat).
explored(a157, little_liquid).
explored(a157, medium_liquid).
explored(a157, pour_low).
explored(a157, pour_offset_sideways).
explored(a157, pour_rolled).
explored(a157, retreat_moving_closer).
explored(a157, slippery_destination).
explored(a157, slippery_source).
explored(a157, slow_approach).
explored(a157, start_low).
explored(a157, sticky_liquid).
held(a157, destination_still_approach, 1, 2).
held(a157, destination_still_retreat, 2, 2).
held(a157, destination_still_settle, 2, 2).
held(a157, destination_upright, 2, 2).
held(a157, source_clear, 0, 2).
held(a157, liquid_leaves_source, 2, 2).
held(a157, liquid_enters_destination, 1, 2).
held(a157, liquid_remains_in_destination, 2, 2).
held(a157, no_spill, 1, 2).
explored(a158, pour_low).
explored(a158, pour_offset_sideways).
held(a158, destination_still_approach, 4, 6).
held(a158, destination_still_retreat, 5, 6).
held(a158, destination_still_settle, 6, 6).
held(a158, destination_upright, 6, 6).
held(a158, source_clear, 1, 6).
held(a158, liquid_leaves_source, 6, 6).
held(a158, liquid_enters_destination, 1, 6).
held(a158, liquid_remains_in_destination, 6, 6).
held(a158, no_spill, 1, 6).
explored(a159, approach_lowering).
explored(a159, bouncy_liquid).
explored(a159, dull_destination).
explored(a159, end_low).
explored(a159, end_near_rim).
explored(a159, end_rolled).
explored(a159, end_upright).
explored(a159, fast_retreat).
explored(a159, grippy_destination).
explored(a159, light_destination).
explored(a159, little_liquid).
explored(a159, moderate_approach).
explored(a159, pour_half_tilted).
explored(a159, pour_in_line).
explored(a159, pour_low).
explored(a159, pour_near_rim).
explored(a159, pour_rolled).
explored(a159, runny_liquid).
explored(a159, start_centred).
held(a159, destination_still_approach, 1, 2).
held(a159, destination_still_retreat, 0, 2).
held(a159, destination_still_settle, 2, 2).
held(a159, destination_upright, 2, 2).
held(a159, source_clear, 0, 2).
held(a159, liquid_leaves_source, 0, 2).
held(a159, liquid_enters_destination, 1, 2).
held(a159, liquid_remains_in_destination, 0, 2).
held(a159, no_spill, 2, 2).
explored(a160, approach_lowering).
explored(a160, approach_moving_closer).
explored(a160, end_level).
explored(a160, end_steeply_tilted).
explored(a160, end_very_high).
explored(a160, fast_approach).
explored(a160, light_liquid).
explored(a160, light_source).
explored(a160, medium_destination).
explored(a160, pour_far_away).
explored(a160, pour_level).
explored(a160, pour_slightly_tilted).
explored(a160, slow_retreat).
explored(a160, start_slightly_tilted).
held(a160, destination_still_approach, 2, 2).
held(a160, destination_still_retreat, 2, 2).
held(a160, destination_still_settle, 2, 2).
held(a160, destination_upright, 2, 2).
held(a160, source_clear, 2, 2).
held(a160, liquid_leaves_source, 2, 2).
held(a160, liquid_enters_destination, 1, 2).
held(a160, liquid_remains_in_destination, 2, 2).
held(a160, no_spill, 1, 2).
explored(a161, end_low).
held(a161, destination_still_approach, 4, 4).
held(a161, destination_still_retreat, 3, 4).
held(a161, destination_still_settle, 4, 4).
held(a161, destination_upright, 4, 4).
held(a161, source_clear, 3, 4).
held(a161, liquid_leaves_source, 4, 4).
held(a161, liquid_enters_destination, 4, 4).
held(a161, liquid_remains_in_destination, 4, 4).
held(a161, no_spill, 4, 4).
explored(a162, approach_moving_away).
explored(a162, approach_raising).
explored(a162, bouncy_source).
explored(a162, dull_liquid).
explored(a162, end_centred).
explored(a162, end_high).
explored(a162, end_steeply_tilted).
explored(a162, fast_retreat).
explored(a162, light_destination).
explored(a162, light_liquid).
explored(a162, much_liquid).
explored(a162, pour_far_away).
explored(a162, pour_half_tilted).
explored(a162, pour_in_line).
explored(a162, pour_level).
explored(a162, pour_very_high).
explored(a162, slow_approach).
explored(a162, start_tilted_back).
held(a162, destination_still_approach, 2, 2).
held(a162, destination_still_retreat, 2, 2).
held(a162, destination_still_settle, 2, 2).
held(a162, destination_upright, 2, 2).
held(a162, source_clear, 2, 2).
held(a162, liquid_leaves_source, 2, 2).
held(a162, liquid_enters_destination, 0, 2).
held(a162, liquid_remains_in_destination, 2, 2).
held(a162, no_spill, 0, 2).
explored(a163, bouncy_destination).
explored(a163, dull_source).
explored(a163, end_level).
explored(a163, end_steeply_tilted).
explored(a163, grippy_source).
explored(a163, heavy_liquid).
explored(a163, heavy_source).
explored(a163, medium_destination).
explored(a163, moderate_retreat).
explored(a163, pour_far_away).
explored(a163, pour_in_line).
explored(a163, pour_rolled).
explored(a163, pour_upright).
explored(a163, retreat_lowering).
explored(a163, retreat_moving_closer).
explored(a163, slow_approach).
explored(a163, start_far_away).
explored(a163, start_slightly_tilted).
explored(a163, start_very_high).
explored(a163, very_much_liquid).
held(a163, destination_still_approach, 2, 2).
held(a163, destination_still_retreat, 1, 2).
held(a163, destination_still_settle, 2, 2).
held(a163, destination_upright, 2, 2).
held(a163, source_clear, 0, 2).
held(a163, liquid_leaves_source, 1, 2).
held(a163, liquid_enters_destination, 0, 2).
held(a163, liquid_remains_in_destination, 2, 2).
held(a163, no_spill, 1, 2).
explored(a164, end_low).
explored(a164, end_upside_down).
held(a164, destination_still_approach, 2, 2).
held(a164, destination_still_retreat, 1, 2).
held(a164, destination_still_settle, 2, 2).
held(a164, destination_upright, 2, 2).
held(a164, source_clear, 0, 2).
held(a164, liquid_leaves_source, 2, 2).
held(a164, liquid_enters_destination, 2, 2).
held(a164, liquid_remains_in_destination, 2, 2).
held(a164, no_spill, 2, 2).
explored(a165, end_low).
explored(a165, end_steeply_tilted).
held(a165, destination_still_approach, 2, 2).
held(a165, destination_still_retreat, 2, 2).
held(a165, destination_still_settle, 2, 2).
held(a165, destination_upright, 2, 2).
held(a165, source_clear, 1, 2).
held(a165, liquid_leaves_source, 2, 2).
held(a165, liquid_enters_destination, 2, 2).
held(a165, liquid_remains_in_destination, 2, 2).
held(a165, no_spill, 2, 2).
explored(a166, approach_moving_closer).
explored(a166, bouncy_liquid).
explored(a166, bouncy_source).
explored(a166, end_centred).
explored(a166, end_level).
explored(a166, end_steeply_tilted).
explored(a166, grippy_source).
explored(a166, heavy_liquid).
explored(a166, light_destination).
explored(a166, light_source).
explored(a166, moderate_retreat).
explored(a166, pour_centred).
explored(a166, pour_in_line).
explored(a166, pour_low).
explored(a166, pour_upright).
explored(a166, retreat_lowering).
explored(a166, runny_liquid).
explored(a166, slow_approach).
explored(a166, start_mid_height).
held(a166, destination_still_approach, 2, 2).
held(a166, destination_still_retreat, 0, 2).
held(a166, destination_still_settle, 0, 2).
held(a166, destination_upright, 0, 2).
held(a166, source_clear, 0, 2).
held(a166, liquid_leaves_source, 2, 2).
held(a166, liquid_enters_destination, 2, 2).
held(a166, liquid_remains_in_destination, 0, 2).
held(a166, no_spill, 0, 2).
explored(a167, end_upside_down).
explored(a167, pour_upright).
held(a167, destination_still_approach, 4, 4).
held(a167, destination_still_retreat, 4, 4).
held(a167, destination_still_settle, 4, 4).
held(a167, destination_upright, 4, 4).
held(a167, source_clear, 4, 4).
held(a167, liquid_leaves_source, 4, 4).
held(a167, liquid_enters_destination, 0, 4).
held(a167, liquid_remains_in_destination, 4, 4).
held(a167, no_spill, 0, 4).
explored(a168, approach_moving_away).
explored(a168, dull_destination).
explored(a168, dull_source).
explored(a168, end_rolled).
explored(a168, grippy_destination).
explored(a168, grippy_source).
explored(a168, heavy_source).
explored(a168, light_destination).
explored(a168, light_liquid).
explored(a168, moderate_approach).
explored(a168, moderate_retreat).
explored(a168, pour_high).
explored(a168, pour_level).
explored(a168, pour_near_rim).
explored(a168, pour_offset_sideways).
explored(a168, pour_steeply_tilted).
explored(a168, retreat_moving_away).
explored(a168, some_liquid).
explored(a168, start_below_rim).
explored(a168, sticky_liquid).
held(a168, destination_still_approach, 2, 2).
held(a168, destination_still_retreat, 2, 2).
held(a168, destination_still_settle, 2, 2).
held(a168, destination_upright, 2, 2).
held(a168, source_clear, 0, 2).
held(a168, liquid_leaves_source, 1, 2).
held(a168, liquid_enters_destination, 0, 2).
held(a168, liquid_remains_in_destination, 1, 2).
held(a168, no_spill, 1, 2).
explored(a169, pour_upright).
explored(a169, retreat_lowering).
held(a169, destination_still_approach, 2, 2).
held(a169, destination_still_retreat, 2, 2).
held(a169, destination_still_settle, 2, 2).
held(a169, destination_upright, 2, 2).
held(a169, source_clear, 2, 2).
held(a169, liquid_leaves_source, 0, 2).
held(a169, liquid_enters_destination, 0, 2).
held(a169, liquid_remains_in_destination, 2, 2).
held(a169, no_spill, 2, 2).
explored(a170, approach_raising).
explored(a170, end_far_away).
explored(a170, end_low).
explored(a170, end_rolled).
explored(a170, fast_approach).
explored(a170, grippy_destination).
explored(a170, grippy_source).
explored(a170, heavy_source).
explored(a170, light_liquid).
explored(a170, little_liquid).
explored(a170, medium_destination).
explored(a170, pour_centred).
explored(a170, pour_low).
explored(a170, pour_offset_sideways).
explored(a170, pour_upright).
explored(a170, slow_retreat).
explored(a170, start_slightly_tilted).
explored(a170, sticky_liquid).
held(a170, destination_still_approach, 0, 2).
held(a170, destination_still_retreat, 2, 2).
held(a170, destination_still_settle, 2, 2).
held(a170, destination_upright, 2, 2).
held(a170, source_clear, 0, 2).
held(a170, liquid_leaves_source, 0, 2).
held(a170, liquid_enters_destination, 0, 2).
held(a170, liquid_remains_in_destination, 2, 2).
held(a170, no_spill, 2, 2).
explored(a171, approach_moving_closer).
explored(a171, bouncy_source).
explored(a171, dull_destination).
explored(a171, end_below_rim).
explored(a171, end_rolled).
explored(a171, fast_retreat).
explored(a171, grippy_destination).
explored(a171, medium_destination).
explored(a171, medium_liquid).
explored(a171, moderate_approach).
explored(a171, pour_half_tilted).
explored(a171, pour_in_line).
explored(a171, pour_level).
explored(a171, pour_very_high).
explored(a171, retreat_moving_closer).
explored(a171, runny_liquid).
explored(a171, slippery_source).
explored(a171, start_below_rim).
explored(a171, very_much_liquid).
held(a171, destination_still_approach, 2, 2).
held(a171, destination_still_retreat, 0, 2).
held(a171, destination_still_settle, 0, 2).
held(a171, destination_upright, 0, 2).
held(a171, source_clear, 0, 2).
held(a171, liquid_leaves_source, 2, 2).
held(a171, liquid_enters_destination, 2, 2).
held(a171, liquid_remains_in_destination, 2, 2).
held(a171, no_spill, 2, 2).
explored(a172, end_below_rim).
explored(a172, pour_half_tilted).
held(a172, destination_still_approach, 4, 4).
held(a172, destination_still_retreat, 3, 4).
held(a172, destination_still_settle, 3, 4).
held(a172, destination_upright, 4, 4).
held(a172, source_clear, 3, 4).
held(a172, liquid_leaves_source, 0, 4).
held(a172, liquid_enters_destination, 0, 4).
held(a172, liquid_remains_in_destination, 3, 4).
held(a172, no_spill, 4, 4).
explored(a173, end_below_rim).
explored(a173, pour_to_side).
held(a173, destination_still_approach, 2, 2).
held(a173, destination_still_retreat, 2, 2).
held(a173, destination_still_settle, 2, 2).
held(a173, destination_upright, 2, 2).
held(a173, source_clear, 1, 2).
held(a173, liquid_leaves_source, 2, 2).
held(a173, liquid_enters_destination, 0, 2).
held(a173, liquid_remains_in_destination, 2, 2).
held(a173, no_spill, 0, 2).
explored(a174, bouncy_source).
explored(a174, dull_destination).
explored(a174, end_far_away).
explored(a174, end_rolled).
explored(a174, end_slightly_tilted).
explored(a174, grippy_destination).
explored(a174, heavy_destination).
explored(a174, little_liquid).
explored(a174, pour_in_line).
explored(a174, pour_steeply_tilted).
explored(a174, pour_very_high).
explored(a174, retreat_raising).
explored(a174, runny_liquid).
explored(a174, slippery_source).
explored(a174, slow_approach).
explored(a174, slow_retreat).
explored(a174, start_low).
held(a174, destination_still_approach, 2, 2).
held(a174, destination_still_retreat, 2, 2).
held(a174, destination_still_settle, 2, 2).
held(a174, destination_upright, 2, 2).
held(a174, source_clear, 2, 2).
held(a174, liquid_leaves_source, 2, 2).
held(a174, liquid_enters_destination, 1, 2).
held(a174, liquid_remains_in_destination, 2, 2).
held(a174, no_spill, 1, 2).
explored(a175, bouncy_destination).
explored(a175, dull_liquid).
explored(a175, end_mid_height).
explored(a175, end_rolled).
explored(a175, end_upside_down).
explored(a175, heavy_source).
explored(a175, little_liquid).
explored(a175, pour_near_rim).
explored(a175, pour_slightly_tilted).
explored(a175, retreat_moving_closer).
explored(a175, slow_approach).
explored(a175, slow_retreat).
explored(a175, start_below_rim).
explored(a175, start_slightly_tilted).
held(a175, destination_still_approach, 2, 2).
held(a175, destination_still_retreat, 2, 2).
held(a175, destination_still_settle, 2, 2).
held(a175, destination_upright, 2, 2).
held(a175, source_clear, 1, 2).
held(a175, liquid_leaves_source, 2, 2).
held(a175, liquid_enters_destination, 2, 2).
held(a175, liquid_remains_in_destination, 2, 2).
held(a175, no_spill, 2, 2).
explored(a176, end_below_rim).
explored(a176, pour_very_high).
held(a176, destination_still_approach, 2, 2).
held(a176, destination_still_retreat, 2, 2).
held(a176, destination_still_settle, 2, 2).
held(a176, destination_upright, 2, 2).
held(a176, source_clear, 2, 2).
held(a176, liquid_leaves_source, 2, 2).
held(a176, liquid_enters_destination, 2, 2).
held(a176, liquid_remains_in_destination, 2, 2).
held(a176, no_spill, 2, 2).
explored(a177, approach_moving_closer).
explored(a177, approach_raising).
explored(a177, bouncy_liquid).
explored(a177, dull_source).
explored(a177, end_far_away).
explored(a177, end_rolled).
explored(a177, end_tilted_back).
explored(a177, fast_approach).
explored(a177, medium_destination).
explored(a177, pour_below_rim).
explored(a177, pour_offset_sideways).
explored(a177, pour_rolled).
explored(a177, pour_tilted_back).
explored(a177, retreat_lowering).
explored(a177, runny_liquid).
explored(a177, slippery_source).
explored(a177, slow_retreat).
explored(a177, some_liquid).
explored(a177, start_tilted_back).
held(a177, destination_still_approach, 0, 2).
held(a177, destination_still_retreat, 1, 2).
held(a177, destination_still_settle, 1, 2).
held(a177, destination_upright, 2, 2).
held(a177, source_clear, 0, 2).
held(a177, liquid_leaves_source, 0, 2).
held(a177, liquid_enters_destination, 0, 2).
held(a177, liquid_remains_in_destination, 2, 2).
held(a177, no_spill, 2, 2).
explored(a178, heavy_liquid).
explored(a178, very_much_liquid).
held(a178, destination_still_approach, 2, 2).
held(a178, destination_still_retreat, 2, 2).
held(a178, destination_still_settle, 2, 2).
held(a178, destination_upright, 2, 2).
held(a178, source_clear, 1, 2).
held(a178, liquid_leaves_source, 2, 2).
held(a178, liquid_enters_destination, 2, 2).
held(a178, liquid_remains_in_destination, 2, 2).
held(a178, no_spill, 2, 2).
explored(a179, approach_moving_away).
explored(a179, bouncy_source).
explored(a179, dull_destination).
explored(a179, dull_liquid).
explored(a179, end_far_away).
explored(a179, end_low).
explored(a179, end_upside_down).
explored(a179, fast_approach).
explored(a179, fast_retreat).
explored(a179, heavy_source).
explored(a179, little_liquid).
explored(a179, medium_destination).
explored(a179, pour_below_rim).
explored(a179, pour_steeply_tilted).
explored(a179, slippery_source).
explored(a179, start_low).
explored(a179, start_tilted_back).
held(a179, destination_still_approach, 0, 2).
held(a179, destination_still_retreat, 0, 2).
held(a179, destination_still_settle, 1, 2).
held(a179, destination_upright, 2, 2).
held(a179, source_clear, 0, 2).
held(a179, liquid_leaves_source, 2, 2).
held(a179, liquid_enters_destination, 2, 2).
held(a179, liquid_remains_in_destination, 0, 2).
held(a179, no_spill, 0, 2).
explored(a180, approach_moving_away).
explored(a180, bouncy_liquid).
explored(a180, end_low).
explored(a180, end_tilted_back).
explored(a180, fast_approach).
explored(a180, grippy_source).
explored(a180, light_liquid).
explored(a180, light_source).
explored(a180, little_liquid).
explored(a180, pour_half_tilted).
explored(a180, pour_offset_sideways).
explored(a180, pour_very_high).
explored(a180, retreat_moving_away).
explored(a180, slippery_destination).
explored(a180, start_below_rim).
explored(a180, start_tilted_back).
held(a180, destination_still_approach, 0, 2).
held(a180, destination_still_retreat, 2, 2).
held(a180, destination_still_settle, 2, 2).
held(a180, destination_upright, 2, 2).
held(a180, source_clear, 0, 2).
held(a180, liquid_leaves_source, 0, 2).
held(a180, liquid_enters_destination, 0, 2).
held(a180, liquid_remains_in_destination, 2, 2).
held(a180, no_spill, 2, 2).
explored(a181, approach_moving_closer).
explored(a181, approach_raising).
explored(a181, bouncy_liquid).
explored(a181, dull_destination).
explored(a181, end_far_away).
explored(a181, end_half_tilted).
explored(a181, end_level).
explored(a181, end_mid_height).
explored(a181, fast_retreat).
explored(a181, grippy_destination).
explored(a181, light_liquid).
explored(a181, medium_destination).
explored(a181, moderate_approach).
explored(a181, much_liquid).
explored(a181, pour_level).
explored(a181, pour_low).
explored(a181, pour_tilted_back).
explored(a181, slippery_source).
explored(a181, start_tilted_back).
held(a181, destination_still_approach, 2, 2).
held(a181, destination_still_retreat, 2, 2).
held(a181, destination_still_settle, 2, 2).
held(a181, destination_upright, 2, 2).
held(a181, source_clear, 2, 2).
held(a181, liquid_leaves_source, 0, 2).
held(a181, liquid_enters_destination, 0, 2).
held(a181, liquid_remains_in_destination, 2, 2).
held(a181, no_spill, 2, 2).
explored(a182, pour_offset_sideways).
explored(a182, start_below_rim).
held(a182, destination_still_approach, 2, 2).
held(a182, destination_still_retreat, 2, 2).
held(a182, destination_still_settle, 2, 2).
held(a182, destination_upright, 2, 2).
held(a182, source_clear, 1, 2).
held(a182, liquid_leaves_source, 2, 2).
held(a182, liquid_enters_destination, 0, 2).
held(a182, liquid_remains_in_destination, 2, 2).
held(a182, no_spill, 0, 2).
explored(a183, bouncy_destination).
explored(a183, bouncy_liquid).
explored(a183, bouncy_source).
explored(a183, end_high).
explored(a183, end_upside_down).
explored(a183, fast_approach).
explored(a183, grippy_destination).
explored(a183, light_destination).
explored(a183, light_liquid).
explored(a183, pour_in_line).
explored(a183, pour_rolled).
explored(a183, pour_upright).
explored(a183, pour_very_high).
explored(a183, retreat_moving_away).
explored(a183, runny_liquid).
explored(a183, slippery_source).
explored(a183, slow_retreat).
explored(a183, some_liquid).
explored(a183, start_low).
explored(a183, start_to_side).
held(a183, destination_still_approach, 2, 2).
held(a183, destination_still_retreat, 2, 2).
held(a183, destination_still_settle, 2, 2).
held(a183, destination_upright, 2, 2).
held(a183, source_clear, 2, 2).
held(a183, liquid_leaves_source, 2, 2).
held(a183, liquid_enters_destination, 0, 2).
held(a183, liquid_remains_in_destination, 1, 2).
held(a183, no_spill, 0, 2).
explored(a184, end_steeply_tilted).
explored(a184, start_below_rim).
held(a184, destination_still_approach, 1, 2).
held(a184, destination_still_retreat, 2, 2).
held(a184, destination_still_settle, 2, 2).
held(a184, destination_upright, 2, 2).
held(a184, source_clear, 1, 2).
held(a184, liquid_leaves_source, 2, 2).
held(a184, liquid_enters_destination, 2, 2).
held(a184, liquid_remains_in_destination, 2, 2).
held(a184, no_spill, 2, 2).
explored(a185, bouncy_destination).
explored(a185, bouncy_source).
explored(a185, dull_liquid).
explored(a185, end_half_tilted).
explored(a185, end_to_side).
explored(a185, grippy_destination).
explored(a185, light_destination).
explored(a185, light_source).
explored(a185, medium_liquid).
explored(a185, moderate_retreat).
explored(a185, pour_centred).
explored(a185, pour_level).
explored(a185, pour_mid_height).
explored(a185, pour_offset_sideways).
explored(a185, pour_slightly_tilted).
explored(a185, retreat_lowering).
explored(a185, runny_liquid).
explored(a185, slow_approach).
explored(a185, some_liquid).
explored(a185, start_high).
explored(a185, start_upright).
held(a185, destination_still_approach, 2, 2).
held(a185, destination_still_retreat, 1, 2).
held(a185, destination_still_settle, 2, 2).
held(a185, destination_upright, 2, 2).
held(a185, source_clear, 0, 2).
held(a185, liquid_leaves_source, 1, 2).
held(a185, liquid_enters_destination, 0, 2).
held(a185, liquid_remains_in_destination, 2, 2).
held(a185, no_spill, 1, 2).
explored(a186, bouncy_liquid).
explored(a186, dull_destination).
explored(a186, dull_source).
explored(a186, end_low).
explored(a186, end_upside_down).
explored(a186, fast_retreat).
explored(a186, grippy_destination).
explored(a186, heavy_liquid).
explored(a186, light_source).
explored(a186, little_liquid).
explored(a186, moderate_approach).
explored(a186, pour_centred).
explored(a186, pour_half_tilted).
explored(a186, pour_in_line).
explored(a186, pour_level).
explored(a186, pour_very_high).
explored(a186, retreat_moving_away).
explored(a186, start_low).
explored(a186, start_tilted_back).
held(a186, destination_still_approach, 2, 2).
held(a186, destination_still_retreat, 0, 2).
held(a186, destination_still_settle, 0, 2).
held(a186, destination_upright, 1, 2).
held(a186, source_clear, 1, 2).
held(a186, liquid_leaves_source, 2, 2).
held(a186, liquid_enters_destination, 2, 2).
held(a186, liquid_remains_in_destination, 1, 2).
held(a186, no_spill, 0, 2).
explored(a187, end_below_rim).
explored(a187, end_half_tilted).
held(a187, destination_still_approach, 2, 2).
held(a187, destination_still_retreat, 2, 2).
held(a187, destination_still_settle, 2, 2).
held(a187, destination_upright, 2, 2).
held(a187, source_clear, 2, 2).
held(a187, liquid_leaves_source, 2, 2).
held(a187, liquid_enters_destination, 2, 2).
held(a187, liquid_remains_in_destination, 2, 2).
held(a187, no_spill, 2, 2).
explored(a188, approach_moving_away).
explored(a188, bouncy_destination).
explored(a188, dull_liquid).
explored(a188, dull_source).
explored(a188, end_below_rim).
explored(a188, end_rolled).
explored(a188, end_upside_down).
explored(a188, fast_retreat).
explored(a188, grippy_destination).
explored(a188, heavy_destination).
explored(a188, heavy_liquid).
explored(a188, light_source).
explored(a188, little_liquid).
explored(a188, moderate_approach).
explored(a188, pour_level).
explored(a188, pour_low).
explored(a188, pour_slightly_tilted).
explored(a188, pour_to_side).
explored(a188, retreat_moving_closer).
explored(a188, slippery_source).
explored(a188, start_low).
explored(a188, start_tilted_back).
held(a188, destination_still_approach, 2, 2).
held(a188, destination_still_retreat, 0, 2).
held(a188, destination_still_settle, 0, 2).
held(a188, destination_upright, 1, 2).
held(a188, source_clear, 0, 2).
held(a188, liquid_leaves_source, 2, 2).
held(a188, liquid_enters_destination, 0, 2).
held(a188, liquid_remains_in_destination, 0, 2).
held(a188, no_spill, 0, 2).
explored(a189, approach_lowering).
explored(a189, bouncy_liquid).
explored(a189, end_below_rim).
explored(a189, end_steeply_tilted).
explored(a189, fast_approach).
explored(a189, fast_retreat).
explored(a189, grippy_destination).
explored(a189, grippy_source).
explored(a189, light_liquid).
explored(a189, light_source).
explored(a189, little_liquid).
explored(a189, pour_high).
explored(a189, pour_in_line).
explored(a189, pour_slightly_tilted).
explored(a189, start_near_rim).
explored(a189, start_upright).
explored(a189, sticky_liquid).
held(a189, destination_still_approach, 2, 2).
held(a189, destination_still_retreat, 2, 2).
held(a189, destination_still_settle, 2, 2).
held(a189, destination_upright, 2, 2).
held(a189, source_clear, 2, 2).
held(a189, liquid_leaves_source, 1, 2).
held(a189, liquid_enters_destination, 0, 2).
held(a189, liquid_remains_in_destination, 2, 2).
held(a189, no_spill, 1, 2).
explored(a190, approach_raising).
held(a190, destination_still_approach, 10, 15).
held(a190, destination_still_retreat, 14, 15).
held(a190, destination_still_settle, 15, 15).
held(a190, destination_upright, 15, 15).
held(a190, source_clear, 7, 15).
held(a190, liquid_leaves_source, 15, 15).
held(a190, liquid_enters_destination, 13, 15).
held(a190, liquid_remains_in_destination, 15, 15).
held(a190, no_spill, 13, 15).
explored(a191, approach_lowering).
explored(a191, approach_moving_closer).
explored(a191, bouncy_destination).
explored(a191, bouncy_liquid).
explored(a191, dull_source).
explored(a191, end_level).
explored(a191, end_tilted_back).
explored(a191, fast_approach).
explored(a191, light_destination).
explored(a191, light_source).
explored(a191, little_liquid).
explored(a191, pour_centred).
explored(a191, pour_offset_sideways).
explored(a191, pour_very_high).
explored(a191, retreat_moving_closer).
explored(a191, retreat_raising).
explored(a191, slow_retreat).
explored(a191, start_slightly_tilted).
explored(a191, sticky_liquid).
held(a191, destination_still_approach, 2, 2).
held(a191, destination_still_retreat, 1, 2).
held(a191, destination_still_settle, 2, 2).
held(a191, destination_upright, 2, 2).
held(a191, source_clear, 2, 2).
held(a191, liquid_leaves_source, 2, 2).
held(a191, liquid_enters_destination, 0, 2).
held(a191, liquid_remains_in_destination, 2, 2).
held(a191, no_spill, 0, 2).
explored(a192, fast_retreat).
explored(a192, pour_below_rim).
held(a192, destination_still_approach, 0, 2).
held(a192, destination_still_retreat, 1, 2).
held(a192, destination_still_settle, 1, 2).
held(a192, destination_upright, 1, 2).
held(a192, source_clear, 0, 2).
held(a192, liquid_leaves_source, 2, 2).
held(a192, liquid_enters_destination, 1, 2).
held(a192, liquid_remains_in_destination, 1, 2).
held(a192, no_spill, 0, 2).
explored(a193, approach_lowering).
explored(a193, bouncy_destination).
explored(a193, bouncy_source).
explored(a193, end_low).
explored(a193, end_upside_down).
explored(a193, grippy_source).
explored(a193, heavy_liquid).
explored(a193, light_destination).
explored(a193, light_source).
explored(a193, pour_centred).
explored(a193, pour_in_line).
explored(a193, pour_level).
explored(a193, pour_low).
explored(a193, pour_slightly_tilted).
explored(a193, retreat_moving_away).
explored(a193, slow_approach).
explored(a193, slow_retreat).
explored(a193, some_liquid).
explored(a193, start_centred).
held(a193, destination_still_approach, 2, 2).
held(a193, destination_still_retreat, 2, 2).
held(a193, destination_still_settle, 2, 2).
held(a193, destination_upright, 2, 2).
held(a193, source_clear, 1, 2).
held(a193, liquid_leaves_source, 2, 2).
held(a193, liquid_enters_destination, 2, 2).
held(a193, liquid_remains_in_destination, 2, 2).
held(a193, no_spill, 2, 2).
explored(a194, approach_raising).
explored(a194, start_near_rim).
held(a194, destination_still_approach, 1, 2).
held(a194, destination_still_retreat, 2, 2).
held(a194, destination_still_settle, 2, 2).
held(a194, destination_upright, 2, 2).
held(a194, source_clear, 0, 2).
held(a194, liquid_leaves_source, 2, 2).
held(a194, liquid_enters_destination, 2, 2).
held(a194, liquid_remains_in_destination, 2, 2).
held(a194, no_spill, 2, 2).
explored(a195, start_below_rim).
explored(a195, start_tilted_back).
held(a195, destination_still_approach, 2, 2).
held(a195, destination_still_retreat, 2, 2).
held(a195, destination_still_settle, 2, 2).
held(a195, destination_upright, 2, 2).
held(a195, source_clear, 2, 2).
held(a195, liquid_leaves_source, 2, 2).
held(a195, liquid_enters_destination, 2, 2).
held(a195, liquid_remains_in_destination, 2, 2).
held(a195, no_spill, 2, 2).
explored(a196, dull_destination).
explored(a196, dull_source).
explored(a196, end_tilted_back).
explored(a196, fast_approach).
explored(a196, grippy_destination).
explored(a196, heavy_source).
explored(a196, light_destination).
explored(a196, light_liquid).
explored(a196, much_liquid).
explored(a196, pour_centred).
explored(a196, pour_mid_height).
explored(a196, pour_offset_sideways).
explored(a196, pour_upside_down).
explored(a196, retreat_raising).
explored(a196, slow_retreat).
explored(a196, start_centred).
explored(a196, start_low).
explored(a196, start_slightly_tilted).
held(a196, destination_still_approach, 1, 2).
held(a196, destination_still_retreat, 1, 2).
held(a196, destination_still_settle, 2, 2).
held(a196, destination_upright, 2, 2).
held(a196, source_clear, 1, 2).
held(a196, liquid_leaves_source, 2, 2).
held(a196, liquid_enters_destination, 1, 2).
held(a196, liquid_remains_in_destination, 2, 2).
held(a196, no_spill, 1, 2).
explored(a197, dull_destination).
explored(a197, dull_liquid).
explored(a197, end_to_side).
explored(a197, end_upside_down).
explored(a197, heavy_liquid).
explored(a197, light_source).
explored(a197, medium_destination).
explored(a197, pour_centred).
explored(a197, pour_half_tilted).
explored(a197, pour_low).
explored(a197, pour_rolled).
explored(a197, retreat_raising).
explored(a197, runny_liquid).
explored(a197, slippery_destination).
explored(a197, slippery_source).
explored(a197, slow_approach).
explored(a197, slow_retreat).
explored(a197, start_far_away).
explored(a197, start_mid_height).
explored(a197, start_slightly_tilted).
explored(a197, very_much_liquid).
held(a197, destination_still_approach, 2, 2).
held(a197, destination_still_retreat, 0, 2).
held(a197, destination_still_settle, 2, 2).
held(a197, destination_upright, 2, 2).
held(a197, source_clear, 0, 2).
held(a197, liquid_leaves_source, 2, 2).
held(a197, liquid_enters_destination, 2, 2).
held(a197, liquid_remains_in_destination, 2, 2).
held(a197, no_spill, 2, 2).
explored(a198, approach_moving_closer).
explored(a198, dull_destination).
explored(a198, dull_liquid).
explored(a198, end_below_rim).
explored(a198, end_upside_down).
explored(a198, fast_approach).
explored(a198, fast_retreat).
explored(a198, grippy_source).
explored(a198, heavy_destination).
explored(a198, light_liquid).
explored(a198, light_source).
explored(a198, pour_below_rim).
explored(a198, pour_half_tilted).
explored(a198, pour_level).
explored(a198, some_liquid).
explored(a198, start_mid_height).
explored(a198, sticky_liquid).
held(a198, destination_still_approach, 2, 2).
held(a198, destination_still_retreat, 0, 2).
held(a198, destination_still_settle, 1, 2).
held(a198, destination_upright, 2, 2).
held(a198, source_clear, 0, 2).
held(a198, liquid_leaves_source, 2, 2).
held(a198, liquid_enters_destination, 2, 2).
held(a198, liquid_remains_in_destination, 1, 2).
held(a198, no_spill, 1, 2).
explored(a199, approach_moving_closer).
explored(a199, dull_source).
explored(a199, end_far_away).
explored(a199, end_rolled).
explored(a199, grippy_source).
explored(a199, heavy_source).
explored(a199, light_destination).
explored(a199, medium_liquid).
explored(a199, moderate_approach).
explored(a199, pour_centred).
explored(a199, pour_low).
explored(a199, pour_upright).
explored(a199, slippery_destination).
explored(a199, slow_retreat).
explored(a199, start_below_rim).
held(a199, destination_still_approach, 0, 2).
held(a199, destination_still_retreat, 0, 2).
held(a199, destination_still_settle, 1, 2).
held(a199, destination_upright, 2, 2).
held(a199, source_clear, 0, 2).
held(a199, liquid_leaves_source, 1, 2).
held(a199, liquid_enters_destination, 1, 2).
held(a199, liquid_remains_in_destination, 2, 2).
held(a199, no_spill, 2, 2).
explored(a200, end_below_rim).
explored(a200, end_slightly_tilted).
held(a200, destination_still_approach, 2, 2).
held(a200, destination_still_retreat, 1, 2).
held(a200, destination_still_settle, 2, 2).
held(a200, destination_upright, 2, 2).
held(a200, source_clear, 0, 2).
held(a200, liquid_leaves_source, 2, 2).
held(a200, liquid_enters_destination, 2, 2).
held(a200, liquid_remains_in_destination, 2, 2).
held(a200, no_spill, 2, 2).
explored(a201, bouncy_source).
explored(a201, dull_destination).
explored(a201, dull_liquid).
explored(a201, end_near_rim).
explored(a201, end_rolled).
explored(a201, end_steeply_tilted).
explored(a201, grippy_destination).
explored(a201, medium_destination).
explored(a201, pour_centred).
explored(a201, pour_mid_height).
explored(a201, pour_offset_sideways).
explored(a201, retreat_lowering).
explored(a201, runny_liquid).
explored(a201, slow_approach).
explored(a201, start_centred).
explored(a201, start_mid_height).
explored(a201, start_tilted_back).
explored(a201, very_much_liquid).
held(a201, destination_still_approach, 2, 2).
held(a201, destination_still_retreat, 0, 2).
held(a201, destination_still_settle, 1, 2).
held(a201, destination_upright, 2, 2).
held(a201, source_clear, 0, 2).
held(a201, liquid_leaves_source, 2, 2).
held(a201, liquid_enters_destination, 0, 2).
held(a201, liquid_remains_in_destination, 2, 2).
held(a201, no_spill, 0, 2).
explored(a202, end_upside_down).
explored(a202, pour_slightly_tilted).
held(a202, destination_still_approach, 2, 2).
held(a202, destination_still_retreat, 2, 2).
held(a202, destination_still_settle, 2, 2).
held(a202, destination_upright, 2, 2).
held(a202, source_clear, 2, 2).
held(a202, liquid_leaves_source, 2, 2).
held(a202, liquid_enters_destination, 0, 2).
held(a202, liquid_remains_in_destination, 2, 2).
held(a202, no_spill, 0, 2).
explored(a203, bouncy_source).
explored(a203, dull_destination).
explored(a203, end_level).
explored(a203, end_low).
explored(a203, end_tilted_back).
explored(a203, end_to_side).
explored(a203, grippy_destination).
explored(a203, light_liquid).
explored(a203, light_source).
explored(a203, moderate_approach).
explored(a203, pour_offset_sideways).
explored(a203, pour_slightly_tilted).
explored(a203, slippery_source).
explored(a203, start_centred).
explored(a203, start_high).
explored(a203, sticky_liquid).
held(a203, destination_still_approach, 2, 2).
held(a203, destination_still_retreat, 2, 2).
held(a203, destination_still_settle, 2, 2).
held(a203, destination_upright, 2, 2).
held(a203, source_clear, 2, 2).
held(a203, liquid_leaves_source, 0, 2).
held(a203, liquid_enters_destination, 0, 2).
held(a203, liquid_remains_in_destination, 2, 2).
held(a203, no_spill, 2, 2).
explored(a204, pour_slightly_tilted).
explored(a204, retreat_moving_closer).
held(a204, destination_still_approach, 2, 2).
held(a204, destination_still_retreat, 2, 2).
held(a204, destination_still_settle, 2, 2).
held(a204, destination_upright, 2, 2).
held(a204, source_clear, 2, 2).
held(a204, liquid_leaves_source, 0, 2).
held(a204, liquid_enters_destination, 0, 2).
held(a204, liquid_remains_in_destination, 2, 2).
held(a204, no_spill, 2, 2).
explored(a205, approach_raising).
explored(a205, bouncy_destination).
explored(a205, dull_liquid).
explored(a205, end_rolled).
explored(a205, fast_approach).
explored(a205, grippy_destination).
explored(a205, light_liquid).
explored(a205, pour_centred).
explored(a205, pour_in_line).
explored(a205, pour_mid_height).
explored(a205, pour_upright).
explored(a205, retreat_moving_closer).
explored(a205, runny_liquid).
explored(a205, slippery_source).
explored(a205, slow_retreat).
explored(a205, start_near_rim).
explored(a205, start_upright).
explored(a205, very_much_liquid).
held(a205, destination_still_approach, 1, 2).
held(a205, destination_still_retreat, 1, 2).
held(a205, destination_still_settle, 2, 2).
held(a205, destination_upright, 2, 2).
held(a205, source_clear, 1, 2).
held(a205, liquid_leaves_source, 0, 2).
held(a205, liquid_enters_destination, 0, 2).
held(a205, liquid_remains_in_destination, 1, 2).
held(a205, no_spill, 2, 2).
explored(a206, pour_offset_sideways).
explored(a206, pour_steeply_tilted).
held(a206, destination_still_approach, 3, 3).
held(a206, destination_still_retreat, 3, 3).
held(a206, destination_still_settle, 3, 3).
held(a206, destination_upright, 3, 3).
held(a206, source_clear, 2, 3).
held(a206, liquid_leaves_source, 2, 3).
held(a206, liquid_enters_destination, 1, 3).
held(a206, liquid_remains_in_destination, 3, 3).
held(a206, no_spill, 2, 3).
explored(a207, bouncy_liquid).
explored(a207, dull_destination).
explored(a207, dull_source).
explored(a207, end_centred).
explored(a207, end_low).
explored(a207, end_steeply_tilted).
explored(a207, grippy_source).
explored(a207, heavy_destination).
explored(a207, heavy_source).
explored(a207, medium_liquid).
explored(a207, much_liquid).
explored(a207, pour_centred).
explored(a207, pour_in_line).
explored(a207, pour_level).
explored(a207, pour_low).
explored(a207, pour_slightly_tilted).
explored(a207, runny_liquid).
explored(a207, slippery_destination).
explored(a207, slow_retreat).
explored(a207, start_high).
held(a207, destination_still_approach, 2, 2).
held(a207, destination_still_retreat, 2, 2).
held(a207, destination_still_settle, 2, 2).
held(a207, destination_upright, 2, 2).
held(a207, source_clear, 1, 2).
held(a207, liquid_leaves_source, 2, 2).
held(a207, liquid_enters_destination, 2, 2).
held(a207, liquid_remains_in_destination, 2, 2).
held(a207, no_spill, 2, 2).
explored(a208, dull_destination).
explored(a208, dull_liquid).
explored(a208, end_centred).
explored(a208, end_rolled).
explored(a208, end_tilted_back).
explored(a208, heavy_liquid).
explored(a208, heavy_source).
explored(a208, light_destination).
explored(a208, moderate_approach).
explored(a208, pour_centred).
explored(a208, pour_level).
explored(a208, pour_low).
explored(a208, pour_offset_sideways).
explored(a208, pour_upright).
explored(a208, runny_liquid).
explored(a208, slippery_destination).
explored(a208, slippery_source).
explored(a208, start_far_away).
explored(a208, start_tilted_back).
explored(a208, start_very_high).
held(a208, destination_still_approach, 2, 2).
held(a208, destination_still_retreat, 2, 2).
held(a208, destination_still_settle, 2, 2).
held(a208, destination_upright, 2, 2).
held(a208, source_clear, 2, 2).
held(a208, liquid_leaves_source, 0, 2).
held(a208, liquid_enters_destination, 0, 2).
held(a208, liquid_remains_in_destination, 2, 2).
held(a208, no_spill, 2, 2).
explored(a209, approach_moving_away).
explored(a209, pour_offset_sideways).
held(a209, destination_still_approach, 2, 2).
held(a209, destination_still_retreat, 2, 2).
held(a209, destination_still_settle, 2, 2).
held(a209, destination_upright, 2, 2).
held(a209, source_clear, 1, 2).
held(a209, liquid_leaves_source, 2, 2).
held(a209, liquid_enters_destination, 0, 2).
held(a209, liquid_remains_in_destination, 2, 2).
held(a209, no_spill, 0, 2).
explored(a210, bouncy_source).
explored(a210, dull_liquid).
explored(a210, end_centred).
explored(a210, end_high).
explored(a210, end_steeply_tilted).
explored(a210, heavy_liquid).
explored(a210, heavy_source).
explored(a210, medium_destination).
explored(a210, pour_below_rim).
explored(a210, pour_half_tilted).
explored(a210, pour_in_line).
explored(a210, runny_liquid).
explored(a210, slippery_source).
explored(a210, slow_approach).
explored(a210, start_mid_height).
explored(a210, start_near_rim).
explored(a210, start_slightly_tilted).
held(a210, destination_still_approach, 2, 2).
held(a210, destination_still_retreat, 2, 2).
held(a210, destination_still_settle, 2, 2).
held(a210, destination_upright, 2, 2).
held(a210, source_clear, 2, 2).
held(a210, liquid_leaves_source, 2, 2).
held(a210, liquid_enters_destination, 2, 2).
held(a210, liquid_remains_in_destination, 2, 2).
held(a210, no_spill, 1, 2).
explored(a211, approach_moving_closer).
explored(a211, dull_destination).
explored(a211, end_rolled).
explored(a211, end_slightly_tilted).
explored(a211, end_to_side).
explored(a211, heavy_source).
explored(a211, moderate_approach).
explored(a211, moderate_retreat).
explored(a211, pour_below_rim).
explored(a211, pour_in_line).
explored(a211, pour_upright).
explored(a211, retreat_lowering).
explored(a211, runny_liquid).
explored(a211, start_high).
explored(a211, start_upright).
held(a211, destination_still_approach, 1, 2).
held(a211, destination_still_retreat, 0, 2).
held(a211, destination_still_settle, 1, 2).
held(a211, destination_upright, 2, 2).
held(a211, source_clear, 0, 2).
held(a211, liquid_leaves_source, 1, 2).
held(a211, liquid_enters_destination, 2, 2).
held(a211, liquid_remains_in_destination, 1, 2).
held(a211, no_spill, 2, 2).
explored(a212, pour_below_rim).
explored(a212, retreat_moving_closer).
held(a212, destination_still_approach, 0, 2).
held(a212, destination_still_retreat, 0, 2).
held(a212, destination_still_settle, 2, 2).
held(a212, destination_upright, 2, 2).
held(a212, source_clear, 0, 2).
held(a212, liquid_leaves_source, 2, 2).
held(a212, liquid_enters_destination, 2, 2).
held(a212, liquid_remains_in_destination, 1, 2).
held(a212, no_spill, 1, 2).
explored(a213, dull_destination).
explored(a213, dull_liquid).
explored(a213, end_low).
explored(a213, end_rolled).
explored(a213, heavy_destination).
explored(a213, heavy_source).
explored(a213, light_liquid).
explored(a213, moderate_retreat).
explored(a213, pour_half_tilted).
explored(a213, pour_level).
explored(a213, pour_low).
explored(a213, pour_near_rim).
explored(a213, retreat_moving_away).
explored(a213, slow_approach).
explored(a213, some_liquid).
explored(a213, start_centred).
explored(a213, start_high).
explored(a213, start_upright).
explored(a213, sticky_liquid).
held(a213, destination_still_approach, 1, 2).
held(a213, destination_still_retreat, 2, 2).
held(a213, destination_still_settle, 2, 2).
held(a213, destination_upright, 2, 2).
held(a213, source_clear, 1, 2).
held(a213, liquid_leaves_source, 0, 2).
held(a213, liquid_enters_destination, 1, 2).
held(a213, liquid_remains_in_destination, 1, 2).
held(a213, no_spill, 2, 2).
explored(a214, bouncy_source).
explored(a214, dull_destination).
explored(a214, dull_liquid).
explored(a214, end_below_rim).
explored(a214, end_steeply_tilted).
explored(a214, light_destination).
explored(a214, light_liquid).
explored(a214, little_liquid).
explored(a214, moderate_approach).
explored(a214, pour_level).
explored(a214, pour_low).
explored(a214, pour_near_rim).
explored(a214, pour_offset_sideways).
explored(a214, retreat_moving_away).
explored(a214, slippery_destination).
explored(a214, slow_retreat).
explored(a214, start_tilted_back).
explored(a214, start_to_side).
explored(a214, sticky_liquid).
held(a214, destination_still_approach, 0, 2).
held(a214, destination_still_retreat, 1, 2).
held(a214, destination_still_settle, 2, 2).
held(a214, destination_upright, 2, 2).
held(a214, source_clear, 0, 2).
held(a214, liquid_leaves_source, 2, 2).
held(a214, liquid_enters_destination, 1, 2).
held(a214, liquid_remains_in_destination, 2, 2).
held(a214, no_spill, 1, 2).
explored(a215, approach_moving_away).
explored(a215, pour_below_rim).
held(a215, destination_still_approach, 0, 2).
held(a215, destination_still_retreat, 0, 2).
held(a215, destination_still_settle, 0, 2).
held(a215, destination_upright, 0, 2).
held(a215, source_clear, 0, 2).
held(a215, liquid_leaves_source, 2, 2).
held(a215, liquid_enters_destination, 2, 2).
held(a215, liquid_remains_in_destination, 0, 2).
held(a215, no_spill, 0, 2).
explored(a216, bouncy_destination).
explored(a216, end_half_tilted).
explored(a216, end_low).
explored(a216, grippy_source).
explored(a216, heavy_source).
explored(a216, light_destination).
explored(a216, light_liquid).
explored(a216, moderate_retreat).
explored(a216, pour_below_rim).
explored(a216, pour_far_away).
explored(a216, pour_in_line).
explored(a216, pour_rolled).
explored(a216, pour_tilted_back).
explored(a216, runny_liquid).
explored(a216, slippery_destination).
explored(a216, some_liquid).
explored(a216, start_low).
explored(a216, start_slightly_tilted).
held(a216, destination_still_approach, 2, 2).
held(a216, destination_still_retreat, 2, 2).
held(a216, destination_still_settle, 2, 2).
held(a216, destination_upright, 2, 2).
held(a216, source_clear, 2, 2).
held(a216, liquid_leaves_source, 0, 2).
held(a216, liquid_enters_destination, 0, 2).
held(a216, liquid_remains_in_destination, 2, 2).
held(a216, no_spill, 2, 2).
explored(a217, approach_raising).
explored(a217, dull_liquid).
explored(a217, dull_source).
explored(a217, end_rolled).
explored(a217, end_slightly_tilted).
explored(a217, end_to_side).
explored(a217, fast_retreat).
explored(a217, grippy_source).
explored(a217, heavy_liquid).
explored(a217, heavy_source).
explored(a217, medium_destination).
explored(a217, much_liquid).
explored(a217, pour_centred).
explored(a217, pour_half_tilted).
explored(a217, pour_in_line).
explored(a217, pour_level).
explored(a217, retreat_lowering).
explored(a217, runny_liquid).
explored(a217, slippery_destination).
explored(a217, slow_approach).
explored(a217, start_near_rim).
explored(a217, start_tilted_back).
held(a217, destination_still_approach, 0, 2).
held(a217, destination_still_retreat, 2, 2).
held(a217, destination_still_settle, 2, 2).
held(a217, destination_upright, 2, 2).
held(a217, source_clear, 0, 2).
held(a217, liquid_leaves_source, 0, 2).
held(a217, liquid_enters_destination, 0, 2).
held(a217, liquid_remains_in_destination, 1, 2).
held(a217, no_spill, 2, 2).
explored(a218, end_near_rim).
explored(a218, pour_below_rim).
held(a218, destination_still_approach, 0, 2).
held(a218, destination_still_retreat, 1, 2).
held(a218, destination_still_settle, 2, 2).
held(a218, destination_upright, 2, 2).
held(a218, source_clear, 0, 2).
held(a218, liquid_leaves_source, 2, 2).
held(a218, liquid_enters_destination, 0, 2).
held(a218, liquid_remains_in_destination, 2, 2).
held(a218, no_spill, 1, 2).
explored(a219, bouncy_destination).
explored(a219, bouncy_liquid).
explored(a219, bouncy_source).
explored(a219, end_below_rim).
explored(a219, end_rolled).
explored(a219, end_steeply_tilted).
explored(a219, fast_approach).
explored(a219, grippy_source).
explored(a219, light_liquid).
explored(a219, light_source).
explored(a219, pour_centred).
explored(a219, pour_in_line).
explored(a219, pour_low).
explored(a219, pour_upright).
explored(a219, runny_liquid).
explored(a219, slow_retreat).
explored(a219, start_mid_height).
explored(a219, start_to_side).
explored(a219, start_upright).
explored(a219, very_much_liquid).
held(a219, destination_still_approach, 2, 2).
held(a219, destination_still_retreat, 0, 2).
held(a219, destination_still_settle, 0, 2).
held(a219, destination_upright, 1, 2).
held(a219, source_clear, 0, 2).
held(a219, liquid_leaves_source, 2, 2).
held(a219, liquid_enters_destination, 2, 2).
held(a219, liquid_remains_in_destination, 0, 2).
held(a219, no_spill, 0, 2).
explored(a220, fast_approach).
explored(a220, pour_below_rim).
held(a220, destination_still_approach, 1, 2).
held(a220, destination_still_retreat, 0, 2).
held(a220, destination_still_settle, 2, 2).
held(a220, destination_upright, 2, 2).
held(a220, source_clear, 0, 2).
held(a220, liquid_leaves_source, 2, 2).
held(a220, liquid_enters_destination, 2, 2).
held(a220, liquid_remains_in_destination, 2, 2).
held(a220, no_spill, 2, 2).
explored(a221, approach_raising).
explored(a221, bouncy_liquid).
explored(a221, end_low).
explored(a221, grippy_destination).
explored(a221, grippy_source).
explored(a221, heavy_source).
explored(a221, light_liquid).
explored(a221, little_liquid).
explored(a221, medium_destination).
explored(a221, pour_centred).
explored(a221, pour_half_tilted).
explored(a221, pour_in_line).
explored(a221, retreat_moving_closer).
explored(a221, runny_liquid).
explored(a221, slow_retreat).
explored(a221, start_tilted_back).
explored(a221, start_to_side).
held(a221, destination_still_approach, 1, 2).
held(a221, destination_still_retreat, 1, 2).
held(a221, destination_still_settle, 2, 2).
held(a221, destination_upright, 1, 2).
held(a221, source_clear, 1, 2).
held(a221, liquid_leaves_source, 0, 2).
held(a221, liquid_enters_destination, 0, 2).
held(a221, liquid_remains_in_destination, 2, 2).
held(a221, no_spill, 2, 2).
explored(a222, approach_raising).
explored(a222, bouncy_source).
explored(a222, dull_destination).
explored(a222, dull_liquid).
explored(a222, end_far_away).
explored(a222, end_slightly_tilted).
explored(a222, light_liquid).
explored(a222, light_source).
explored(a222, much_liquid).
explored(a222, pour_below_rim).
explored(a222, pour_far_away).
explored(a222, pour_half_tilted).
explored(a222, pour_level).
explored(a222, retreat_raising).
explored(a222, runny_liquid).
explored(a222, start_upright).
held(a222, destination_still_approach, 2, 2).
held(a222, destination_still_retreat, 2, 2).
held(a222, destination_still_settle, 2, 2).
held(a222, destination_upright, 2, 2).
held(a222, source_clear, 2, 2).
held(a222, liquid_leaves_source, 0, 2).
held(a222, liquid_enters_destination, 0, 2).
held(a222, liquid_remains_in_destination, 2, 2).
held(a222, no_spill, 2, 2).
explored(a223, end_below_rim).
explored(a223, retreat_moving_closer).
held(a223, destination_still_approach, 4, 4).
held(a223, destination_still_retreat, 2, 4).
held(a223, destination_still_settle, 4, 4).
held(a223, destination_upright, 4, 4).
held(a223, source_clear, 0, 4).
held(a223, liquid_leaves_source, 4, 4).
held(a223, liquid_enters_destination, 4, 4).
held(a223, liquid_remains_in_destination, 4, 4).
held(a223, no_spill, 4, 4).
explored(a224, end_upside_down).
explored(a224, retreat_moving_closer).
held(a224, destination_still_approach, 2, 2).
held(a224, destination_still_retreat, 2, 2).
held(a224, destination_still_settle, 2, 2).
held(a224, destination_upright, 2, 2).
held(a224, source_clear, 2, 2).
held(a224, liquid_leaves_source, 2, 2).
held(a224, liquid_enters_destination, 2, 2).
held(a224, liquid_remains_in_destination, 2, 2).
held(a224, no_spill, 2, 2).
explored(a225, dull_source).
explored(a225, end_high).
explored(a225, end_rolled).
explored(a225, end_tilted_back).
explored(a225, grippy_destination).
explored(a225, grippy_source).
explored(a225, heavy_destination).
explored(a225, light_source).
explored(a225, medium_liquid).
explored(a225, pour_centred).
explored(a225, pour_level).
explored(a225, pour_low).
explored(a225, pour_offset_sideways).
explored(a225, pour_tilted_back).
explored(a225, retreat_moving_away).
explored(a225, start_far_away).
explored(a225, start_slightly_tilted).
explored(a225, very_much_liquid).
held(a225, destination_still_approach, 2, 2).
held(a225, destination_still_retreat, 2, 2).
held(a225, destination_still_settle, 2, 2).
held(a225, destination_upright, 2, 2).
held(a225, source_clear, 2, 2).
held(a225, liquid_leaves_source, 0, 2).
held(a225, liquid_enters_destination, 0, 2).
held(a225, liquid_remains_in_destination, 2, 2).
held(a225, no_spill, 2, 2).
explored(a226, pour_low).
explored(a226, retreat_moving_closer).
held(a226, destination_still_approach, 1, 2).
held(a226, destination_still_retreat, 1, 2).
held(a226, destination_still_settle, 2, 2).
held(a226, destination_upright, 2, 2).
held(a226, source_clear, 0, 2).
held(a226, liquid_leaves_source, 2, 2).
held(a226, liquid_enters_destination, 2, 2).
held(a226, liquid_remains_in_destination, 2, 2).
held(a226, no_spill, 2, 2).
explored(a227, approach_moving_away).
explored(a227, bouncy_liquid).
explored(a227, bouncy_source).
explored(a227, dull_destination).
explored(a227, end_below_rim).
explored(a227, end_level).
explored(a227, end_slightly_tilted).
explored(a227, fast_retreat).
explored(a227, grippy_destination).
explored(a227, heavy_destination).
explored(a227, medium_liquid).
explored(a227, much_liquid).
explored(a227, pour_centred).
explored(a227, pour_high).
explored(a227, pour_offset_sideways).
explored(a227, pour_rolled).
explored(a227, pour_slightly_tilted).
explored(a227, retreat_moving_closer).
explored(a227, slow_approach).
explored(a227, start_below_rim).
explored(a227, start_upright).
explored(a227, sticky_liquid).
held(a227, destination_still_approach, 2, 2).
held(a227, destination_still_retreat, 2, 2).
held(a227, destination_still_settle, 1, 2).
held(a227, destination_upright, 2, 2).
held(a227, source_clear, 0, 2).
held(a227, liquid_leaves_source, 2, 2).
held(a227, liquid_enters_destination, 1, 2).
held(a227, liquid_remains_in_destination, 0, 2).
held(a227, no_spill, 0, 2).
explored(a228, dull_destination).
explored(a228, dull_liquid).
explored(a228, dull_source).
explored(a228, end_below_rim).
explored(a228, end_level).
explored(a228, end_steeply_tilted).
explored(a228, fast_approach).
explored(a228, grippy_destination).
explored(a228, medium_destination).
explored(a228, medium_liquid).
explored(a228, moderate_retreat).
explored(a228, pour_level).
explored(a228, pour_mid_height).
explored(a228, pour_near_rim).
explored(a228, pour_slightly_tilted).
explored(a228, retreat_moving_closer).
explored(a228, start_mid_height).
explored(a228, start_near_rim).
explored(a228, start_upright).
explored(a228, very_much_liquid).
held(a228, destination_still_approach, 2, 2).
held(a228, destination_still_retreat, 0, 2).
held(a228, destination_still_settle, 1, 2).
held(a228, destination_upright, 0, 2).
held(a228, source_clear, 0, 2).
held(a228, liquid_leaves_source, 2, 2).
held(a228, liquid_enters_destination, 2, 2).
held(a228, liquid_remains_in_destination, 2, 2).
held(a228, no_spill, 2, 2).
explored(a229, pour_steeply_tilted).
held(a229, destination_still_approach, 8, 8).
held(a229, destination_still_retreat, 8, 8).
held(a229, destination_still_settle, 8, 8).
held(a229, destination_upright, 8, 8).
held(a229, source_clear, 8, 8).
held(a229, liquid_leaves_source, 6, 8).
held(a229, liquid_enters_destination, 6, 8).
held(a229, liquid_remains_in_destination, 8, 8).
held(a229, no_spill, 8, 8).
explored(a230, approach_moving_away).
explored(a230, dull_destination).
explored(a230, dull_source).
explored(a230, end_level).
explored(a230, end_to_side).
explored(a230, end_upright).
explored(a230, end_very_high).
explored(a230, fast_retreat).
explored(a230, light_destination).
explored(a230, light_liquid).
explored(a230, little_liquid).
explored(a230, pour_in_line).
explored(a230, pour_level).
explored(a230, pour_low).
explored(a230, pour_to_side).
explored(a230, pour_upright).
explored(a230, slippery_source).
explored(a230, start_below_rim).
explored(a230, start_tilted_back).
held(a230, destination_still_approach, 2, 2).
held(a230, destination_still_retreat, 2, 2).
held(a230, destination_still_settle, 2, 2).
held(a230, destination_upright, 2, 2).
held(a230, source_clear, 0, 2).
held(a230, liquid_leaves_source, 0, 2).
held(a230, liquid_enters_destination, 0, 2).
held(a230, liquid_remains_in_destination, 2, 2).
held(a230, no_spill, 2, 2).
explored(a231, approach_raising).
explored(a231, start_centred).
held(a231, destination_still_approach, 2, 2).
held(a231, destination_still_retreat, 2, 2).
held(a231, destination_still_settle, 2, 2).
held(a231, destination_upright, 2, 2).
held(a231, source_clear, 2, 2).
held(a231, liquid_leaves_source, 2, 2).
held(a231, liquid_enters_destination, 2, 2).
held(a231, liquid_remains_in_destination, 2, 2).
held(a231, no_spill, 2, 2).
explored(a232, pour_centred).
explored(a232, pour_steeply_tilted).
held(a232, destination_still_approach, 2, 2).
held(a232, destination_still_retreat, 2, 2).
held(a232, destination_still_settle, 2, 2).
held(a232, destination_upright, 2, 2).
held(a232, source_clear, 2, 2).
held(a232, liquid_leaves_source, 1, 2).
held(a232, liquid_enters_destination, 1, 2).
held(a232, liquid_remains_in_destination, 2, 2).
held(a232, no_spill, 2, 2).
explored(a233, approach_raising).
explored(a233, bouncy_liquid).
explored(a233, bouncy_source).
explored(a233, dull_destination).
explored(a233, end_low).
explored(a233, end_near_rim).
explored(a233, end_rolled).
explored(a233, end_tilted_back).
explored(a233, light_destination).
explored(a233, moderate_approach).
explored(a233, pour_below_rim).
explored(a233, pour_half_tilted).
explored(a233, pour_rolled).
explored(a233, runny_liquid).
explored(a233, slippery_source).
explored(a233, slow_retreat).
explored(a233, some_liquid).
explored(a233, start_near_rim).
explored(a233, start_slightly_tilted).
held(a233, destination_still_approach, 0, 2).
held(a233, destination_still_retreat, 1, 2).
held(a233, destination_still_settle, 2, 2).
held(a233, destination_upright, 1, 2).
held(a233, source_clear, 0, 2).
held(a233, liquid_leaves_source, 1, 2).
held(a233, liquid_enters_destination, 2, 2).
held(a233, liquid_remains_in_destination, 1, 2).
held(a233, no_spill, 2, 2).
explored(a234, dull_source).
explored(a234, end_below_rim).
explored(a234, end_far_away).
explored(a234, end_half_tilted).
explored(a234, end_rolled).
explored(a234, fast_approach).
explored(a234, heavy_source).
explored(a234, pour_low).
explored(a234, pour_near_rim).
explored(a234, pour_offset_sideways).
explored(a234, pour_upside_down).
explored(a234, slippery_destination).
explored(a234, slippery_source).
explored(a234, start_far_away).
explored(a234, start_very_high).
explored(a234, sticky_liquid).
explored(a234, very_much_liquid).
held(a234, destination_still_approach, 1, 2).
held(a234, destination_still_retreat, 2, 2).
held(a234, destination_still_settle, 2, 2).
held(a234, destination_upright, 2, 2).
held(a234, source_clear, 2, 2).
held(a234, liquid_leaves_source, 2, 2).
held(a234, liquid_enters_destination, 0, 2).
held(a234, liquid_remains_in_destination, 2, 2).
held(a234, no_spill, 0, 2).
explored(a235, end_near_rim).
explored(a235, retreat_lowering).
held(a235, destination_still_approach, 2, 2).
held(a235, destination_still_retreat, 1, 2).
held(a235, destination_still_settle, 1, 2).
held(a235, destination_upright, 2, 2).
held(a235, source_clear, 1, 2).
held(a235, liquid_leaves_source, 2, 2).
held(a235, liquid_enters_destination, 2, 2).
held(a235, liquid_remains_in_destination, 2, 2).
held(a235, no_spill, 2, 2).
explored(a236, dull_liquid).
explored(a236, end_centred).
explored(a236, end_mid_height).
explored(a236, end_steeply_tilted).
explored(a236, fast_retreat).
explored(a236, heavy_liquid).
explored(a236, light_destination).
explored(a236, moderate_approach).
explored(a236, much_liquid).
explored(a236, pour_low).
explored(a236, pour_offset_sideways).
explored(a236, pour_rolled).
explored(a236, slippery_destination).
explored(a236, start_mid_height).
explored(a236, start_near_rim).
explored(a236, sticky_liquid).
held(a236, destination_still_approach, 0, 2).
held(a236, destination_still_retreat, 2, 2).
held(a236, destination_still_settle, 2, 2).
held(a236, destination_upright, 2, 2).
held(a236, source_clear, 0, 2).
held(a236, liquid_leaves_source, 2, 2).
held(a236, liquid_enters_destination, 2, 2).
held(a236, liquid_remains_in_destination, 2, 2).
held(a236, no_spill, 2, 2).
explored(a237, end_upside_down).
explored(a237, pour_tilted_back).
held(a237, destination_still_approach, 4, 4).
held(a237, destination_still_retreat, 4, 4).
held(a237, destination_still_settle, 4, 4).
held(a237, destination_upright, 4, 4).
held(a237, source_clear, 4, 4).
held(a237, liquid_leaves_source, 4, 4).
held(a237, liquid_enters_destination, 0, 4).
held(a237, liquid_remains_in_destination, 4, 4).
held(a237, no_spill, 0, 4).
explored(a238, approach_moving_away).
explored(a238, approach_raising).
explored(a238, bouncy_liquid).
explored(a238, bouncy_source).
explored(a238, dull_destination).
explored(a238, end_far_away).
explored(a238, end_low).
explored(a238, end_rolled).
explored(a238, end_steeply_tilted).
explored(a238, grippy_source).
explored(a238, heavy_destination).
explored(a238, heavy_liquid).
explored(a238, light_source).
explored(a238, little_liquid).
explored(a238, moderate_retreat).
explored(a238, pour_half_tilted).
explored(a238, pour_mid_height).
explored(a238, pour_near_rim).
explored(a238, pour_rolled).
explored(a238, slippery_destination).
explored(a238, slow_approach).
explored(a238, start_slightly_tilted).
explored(a238, sticky_liquid).
held(a238, destination_still_approach, 0, 2).
held(a238, destination_still_retreat, 2, 2).
held(a238, destination_still_settle, 2, 2).
held(a238, destination_upright, 2, 2).
held(a238, source_clear, 0, 2).
held(a238, liquid_leaves_source, 1, 2).
held(a238, liquid_enters_destination, 1, 2).
held(a238, liquid_remains_in_destination, 1, 2).
held(a238, no_spill, 1, 2).
explored(a239, dull_destination).
explored(a239, end_level).
explored(a239, end_upside_down).
explored(a239, fast_approach).
explored(a239, heavy_source).
explored(a239, medium_destination).
explored(a239, medium_liquid).
explored(a239, moderate_retreat).
explored(a239, much_liquid).
explored(a239, pour_low).
explored(a239, retreat_moving_closer).
explored(a239, slippery_source).
explored(a239, start_mid_height).
explored(a239, start_tilted_back).
explored(a239, start_to_side).
explored(a239, sticky_liquid).
held(a239, destination_still_approach, 0, 2).
held(a239, destination_still_retreat, 1, 2).
held(a239, destination_still_settle, 2, 2).
held(a239, destination_upright, 2, 2).
held(a239, source_clear, 0, 2).
held(a239, liquid_leaves_source, 2, 2).
held(a239, liquid_enters_destination, 2, 2).
held(a239, liquid_remains_in_destination, 2, 2).
held(a239, no_spill, 2, 2).
explored(a240, bouncy_destination).
explored(a240, dull_source).
explored(a240, end_far_away).
explored(a240, end_level).
explored(a240, end_steeply_tilted).
explored(a240, fast_retreat).
explored(a240, heavy_liquid).
explored(a240, light_destination).
explored(a240, light_source).
explored(a240, pour_centred).
explored(a240, pour_in_line).
explored(a240, pour_rolled).
explored(a240, pour_upright).
explored(a240, retreat_lowering).
explored(a240, runny_liquid).
explored(a240, slippery_source).
explored(a240, start_low).
explored(a240, start_upright).
explored(a240, very_much_liquid).
held(a240, destination_still_approach, 2, 2).
held(a240, destination_still_retreat, 2, 2).
held(a240, destination_still_settle, 1, 2).
held(a240, destination_upright, 2, 2).
held(a240, source_clear, 2, 2).
held(a240, liquid_leaves_source, 2, 2).
held(a240, liquid_enters_destination, 0, 2).
held(a240, liquid_remains_in_destination, 2, 2).
held(a240, no_spill, 0, 2).
explored(a241, end_rolled).
explored(a241, end_upside_down).
held(a241, destination_still_approach, 2, 2).
held(a241, destination_still_retreat, 2, 2).
held(a241, destination_still_settle, 2, 2).
held(a241, destination_upright, 2, 2).
held(a241, source_clear, 2, 2).
held(a241, liquid_leaves_source, 2, 2).
held(a241, liquid_enters_destination, 2, 2).
held(a241, liquid_remains_in_destination, 2, 2).
held(a241, no_spill, 2, 2).
explored(a242, approach_moving_closer).
explored(a242, dull_liquid).
explored(a242, end_half_tilted).
explored(a242, end_level).
explored(a242, end_low).
explored(a242, end_to_side).
explored(a242, light_destination).
explored(a242, light_liquid).
explored(a242, light_source).
explored(a242, pour_low).
explored(a242, pour_upright).
explored(a242, slippery_source).
explored(a242, slow_approach).
explored(a242, slow_retreat).
explored(a242, some_liquid).
explored(a242, start_low).
explored(a242, start_upright).
explored(a242, sticky_liquid).
held(a242, destination_still_approach, 2, 2).
held(a242, destination_still_retreat, 1, 2).
held(a242, destination_still_settle, 2, 2).
held(a242, destination_upright, 1, 2).
held(a242, source_clear, 1, 2).
held(a242, liquid_leaves_source, 0, 2).
held(a242, liquid_enters_destination, 1, 2).
held(a242, liquid_remains_in_destination, 2, 2).
held(a242, no_spill, 2, 2).
explored(a243, bouncy_liquid).
explored(a243, bouncy_source).
explored(a243, dull_destination).
explored(a243, end_mid_height).
explored(a243, end_steeply_tilted).
explored(a243, grippy_destination).
explored(a243, light_source).
explored(a243, little_liquid).
explored(a243, moderate_retreat).
explored(a243, pour_below_rim).
explored(a243, pour_in_line).
explored(a243, pour_rolled).
explored(a243, pour_tilted_back).
explored(a243, retreat_moving_away).
explored(a243, slow_approach).
explored(a243, start_high).
explored(a243, start_upright).
explored(a243, sticky_liquid).
held(a243, destination_still_approach, 0, 2).
held(a243, destination_still_retreat, 0, 2).
held(a243, destination_still_settle, 2, 2).
held(a243, destination_upright, 2, 2).
held(a243, source_clear, 0, 2).
held(a243, liquid_leaves_source, 1, 2).
held(a243, liquid_enters_destination, 2, 2).
held(a243, liquid_remains_in_destination, 1, 2).
held(a243, no_spill, 1, 2).
explored(a244, approach_moving_away).
explored(a244, bouncy_destination).
explored(a244, dull_liquid).
explored(a244, dull_source).
explored(a244, end_centred).
explored(a244, end_rolled).
explored(a244, end_upside_down).
explored(a244, fast_retreat).
explored(a244, grippy_source).
explored(a244, heavy_liquid).
explored(a244, medium_destination).
explored(a244, pour_far_away).
explored(a244, pour_low).
explored(a244, pour_rolled).
explored(a244, start_below_rim).
held(a244, destination_still_approach, 1, 2).
held(a244, destination_still_retreat, 1, 2).
held(a244, destination_still_settle, 1, 2).
held(a244, destination_upright, 1, 2).
held(a244, source_clear, 0, 2).
held(a244, liquid_leaves_source, 2, 2).
held(a244, liquid_enters_destination, 0, 2).
held(a244, liquid_remains_in_destination, 1, 2).
held(a244, no_spill, 0, 2).
explored(a245, dull_destination).
explored(a245, dull_liquid).
explored(a245, dull_source).
explored(a245, end_below_rim).
explored(a245, end_far_away).
explored(a245, end_level).
explored(a245, end_steeply_tilted).
explored(a245, grippy_source).
explored(a245, heavy_source).
explored(a245, medium_destination).
explored(a245, much_liquid).
explored(a245, pour_low).
explored(a245, pour_near_rim).
explored(a245, pour_offset_sideways).
explored(a245, pour_rolled).
explored(a245, pour_slightly_tilted).
explored(a245, slippery_destination).
explored(a245, slow_retreat).
explored(a245, start_centred).
explored(a245, start_mid_height).
explored(a245, sticky_liquid).
held(a245, destination_still_approach, 1, 2).
held(a245, destination_still_retreat, 0, 2).
held(a245, destination_still_settle, 0, 2).
held(a245, destination_upright, 2, 2).
held(a245, source_clear, 0, 2).
held(a245, liquid_leaves_source, 2, 2).
held(a245, liquid_enters_destination, 2, 2).
held(a245, liquid_remains_in_destination, 1, 2).
held(a245, no_spill, 1, 2).
explored(a246, end_mid_height).
held(a246, destination_still_approach, 5, 5).
held(a246, destination_still_retreat, 5, 5).
held(a246, destination_still_settle, 5, 5).
held(a246, destination_upright, 5, 5).
held(a246, source_clear, 4, 5).
held(a246, liquid_leaves_source, 5, 5).
held(a246, liquid_enters_destination, 5, 5).
held(a246, liquid_remains_in_destination, 5, 5).
held(a246, no_spill, 5, 5).
explored(a247, approach_moving_away).
explored(a247, bouncy_source).
explored(a247, dull_destination).
explored(a247, dull_liquid).
explored(a247, end_below_rim).
explored(a247, end_upside_down).
explored(a247, fast_approach).
explored(a247, heavy_destination).
explored(a247, heavy_liquid).
explored(a247, heavy_source).
explored(a247, moderate_retreat).
explored(a247, much_liquid).
explored(a247, pour_near_rim).
explored(a247, pour_offset_sideways).
explored(a247, pour_rolled).
explored(a247, pour_very_high).
explored(a247, retreat_moving_closer).
explored(a247, runny_liquid).
explored(a247, slippery_destination).
explored(a247, slippery_source).
explored(a247, start_tilted_back).
held(a247, destination_still_approach, 2, 2).
held(a247, destination_still_retreat, 0, 2).
held(a247, destination_still_settle, 2, 2).
held(a247, destination_upright, 2, 2).
held(a247, source_clear, 0, 2).
held(a247, liquid_leaves_source, 2, 2).
held(a247, liquid_enters_destination, 1, 2).
held(a247, liquid_remains_in_destination, 2, 2).
held(a247, no_spill, 1, 2).
explored(a248, end_upside_down).
explored(a248, pour_half_tilted).
held(a248, destination_still_approach, 2, 2).
held(a248, destination_still_retreat, 2, 2).
held(a248, destination_still_settle, 2, 2).
held(a248, destination_upright, 2, 2).
held(a248, source_clear, 2, 2).
held(a248, liquid_leaves_source, 2, 2).
held(a248, liquid_enters_destination, 1, 2).
held(a248, liquid_remains_in_destination, 2, 2).
held(a248, no_spill, 1, 2).
explored(a249, approach_moving_away).
explored(a249, bouncy_source).
explored(a249, dull_liquid).
explored(a249, end_centred).
explored(a249, end_rolled).
explored(a249, end_upside_down).
explored(a249, grippy_source).
explored(a249, heavy_source).
explored(a249, light_destination).
explored(a249, pour_low).
explored(a249, pour_offset_sideways).
explored(a249, pour_steeply_tilted).
explored(a249, slippery_destination).
explored(a249, some_liquid).
explored(a249, start_slightly_tilted).
held(a249, destination_still_approach, 1, 2).
held(a249, destination_still_retreat, 0, 2).
held(a249, destination_still_settle, 2, 2).
held(a249, destination_upright, 2, 2).
held(a249, source_clear, 1, 2).
held(a249, liquid_leaves_source, 2, 2).
held(a249, liquid_enters_destination, 1, 2).
held(a249, liquid_remains_in_destination, 2, 2).
held(a249, no_spill, 1, 2).
explored(a250, end_upside_down).
explored(a250, light_source).
held(a250, destination_still_approach, 2, 2).
held(a250, destination_still_retreat, 2, 2).
held(a250, destination_still_settle, 2, 2).
held(a250, destination_upright, 2, 2).
held(a250, source_clear, 2, 2).
held(a250, liquid_leaves_source, 2, 2).
held(a250, liquid_enters_destination, 2, 2).
held(a250, liquid_remains_in_destination, 2, 2).
held(a250, no_spill, 2, 2).
explored(a251, bouncy_destination).
explored(a251, dull_liquid).
explored(a251, dull_source).
explored(a251, end_level).
explored(a251, end_near_rim).
explored(a251, grippy_source).
explored(a251, light_destination).
explored(a251, light_liquid).
explored(a251, light_source).
explored(a251, little_liquid).
explored(a251, moderate_approach).
explored(a251, pour_low).
explored(a251, pour_near_rim).
explored(a251, pour_rolled).
explored(a251, pour_upright).
explored(a251, retreat_lowering).
explored(a251, runny_liquid).
explored(a251, slow_retreat).
explored(a251, start_centred).
held(a251, destination_still_approach, 2, 2).
held(a251, destination_still_retreat, 0, 2).
held(a251, destination_still_settle, 0, 2).
held(a251, destination_upright, 2, 2).
held(a251, source_clear, 0, 2).
held(a251, liquid_leaves_source, 1, 2).
held(a251, liquid_enters_destination, 1, 2).
held(a251, liquid_remains_in_destination, 1, 2).
held(a251, no_spill, 2, 2).
explored(a252, approach_lowering).
explored(a252, bouncy_destination).
explored(a252, dull_source).
explored(a252, end_steeply_tilted).
explored(a252, fast_approach).
explored(a252, fast_retreat).
explored(a252, grippy_source).
explored(a252, heavy_source).
explored(a252, medium_destination).
explored(a252, pour_mid_height).
explored(a252, pour_rolled).
explored(a252, pour_upright).
explored(a252, retreat_moving_closer).
explored(a252, retreat_raising).
explored(a252, runny_liquid).
explored(a252, slippery_destination).
explored(a252, some_liquid).
explored(a252, start_to_side).
explored(a252, start_upright).
held(a252, destination_still_approach, 2, 2).
held(a252, destination_still_retreat, 2, 2).
held(a252, destination_still_settle, 2, 2).
held(a252, destination_upright, 2, 2).
held(a252, source_clear, 2, 2).
held(a252, liquid_leaves_source, 1, 2).
held(a252, liquid_enters_destination, 0, 2).
held(a252, liquid_remains_in_destination, 2, 2).
held(a252, no_spill, 1, 2).
