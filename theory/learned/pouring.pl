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
setting(whole_every, 0).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(learner, general).
setting(explored, 190).
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
setting(general_rules, 106).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 24).
provenance(g0_destination_still_approach, kept, 24).
provenance(g0_destination_still_approach, confidence_permille, 988).
provenance(g0_destination_still_approach, antecedent, a1).
rule(g1_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g1_destination_still_approach, pour_below_rim).
learned(g1_destination_still_approach).
provenance(g1_destination_still_approach, layer, general).
provenance(g1_destination_still_approach, level, 1).
provenance(g1_destination_still_approach, support, 50).
provenance(g1_destination_still_approach, kept, 46).
provenance(g1_destination_still_approach, confidence_permille, 918).
provenance(g1_destination_still_approach, antecedent, a4).
rule(g2_destination_still_approach, defeasible, destination_still_approach).
body(g2_destination_still_approach, start_below_rim).
learned(g2_destination_still_approach).
provenance(g2_destination_still_approach, layer, general).
provenance(g2_destination_still_approach, level, 1).
provenance(g2_destination_still_approach, support, 11).
provenance(g2_destination_still_approach, kept, 6).
provenance(g2_destination_still_approach, confidence_permille, 589).
provenance(g2_destination_still_approach, antecedent, a2).
rule(g3_destination_still_approach, defeasible, destination_still_approach).
body(g3_destination_still_approach, pour_low).
learned(g3_destination_still_approach).
provenance(g3_destination_still_approach, layer, general).
provenance(g3_destination_still_approach, level, 1).
provenance(g3_destination_still_approach, support, 19).
provenance(g3_destination_still_approach, kept, 11).
provenance(g3_destination_still_approach, confidence_permille, 573).
provenance(g3_destination_still_approach, antecedent, a56).
rule(g4_destination_still_approach, defeasible, destination_still_approach).
body(g4_destination_still_approach, approach_raising).
learned(g4_destination_still_approach).
provenance(g4_destination_still_approach, layer, general).
provenance(g4_destination_still_approach, level, 1).
provenance(g4_destination_still_approach, support, 20).
provenance(g4_destination_still_approach, kept, 14).
provenance(g4_destination_still_approach, confidence_permille, 728).
provenance(g4_destination_still_approach, antecedent, a111).
rule(g5_destination_still_approach, defeasible, destination_still_approach).
body(g5_destination_still_approach, pour_slightly_tilted).
learned(g5_destination_still_approach).
provenance(g5_destination_still_approach, layer, general).
provenance(g5_destination_still_approach, level, 1).
provenance(g5_destination_still_approach, support, 6).
provenance(g5_destination_still_approach, kept, 6).
provenance(g5_destination_still_approach, confidence_permille, 999).
provenance(g5_destination_still_approach, antecedent, a27).
rule(g6_destination_still_approach, defeasible, destination_still_approach).
body(g6_destination_still_approach, pour_far_away).
learned(g6_destination_still_approach).
provenance(g6_destination_still_approach, layer, general).
provenance(g6_destination_still_approach, level, 1).
provenance(g6_destination_still_approach, support, 10).
provenance(g6_destination_still_approach, kept, 10).
provenance(g6_destination_still_approach, confidence_permille, 1000).
provenance(g6_destination_still_approach, antecedent, a39).
rule(g7_destination_still_approach, defeasible, destination_still_approach).
body(g7_destination_still_approach, pour_to_side).
learned(g7_destination_still_approach).
provenance(g7_destination_still_approach, layer, general).
provenance(g7_destination_still_approach, level, 1).
provenance(g7_destination_still_approach, support, 15).
provenance(g7_destination_still_approach, kept, 15).
provenance(g7_destination_still_approach, confidence_permille, 1000).
provenance(g7_destination_still_approach, antecedent, a29).
rule(g8_destination_still_approach, defeasible, destination_still_approach).
body(g8_destination_still_approach, pour_upright).
learned(g8_destination_still_approach).
provenance(g8_destination_still_approach, layer, general).
provenance(g8_destination_still_approach, level, 1).
provenance(g8_destination_still_approach, support, 6).
provenance(g8_destination_still_approach, kept, 6).
provenance(g8_destination_still_approach, confidence_permille, 999).
provenance(g8_destination_still_approach, antecedent, a24).
rule(g9_destination_still_approach, defeasible, destination_still_approach).
body(g9_destination_still_approach, pour_very_high).
learned(g9_destination_still_approach).
provenance(g9_destination_still_approach, layer, general).
provenance(g9_destination_still_approach, level, 1).
provenance(g9_destination_still_approach, support, 13).
provenance(g9_destination_still_approach, kept, 13).
provenance(g9_destination_still_approach, confidence_permille, 1000).
provenance(g9_destination_still_approach, antecedent, a6).
rule(g10_destination_still_approach, defeasible, destination_still_approach).
body(g10_destination_still_approach, pour_half_tilted).
learned(g10_destination_still_approach).
provenance(g10_destination_still_approach, layer, general).
provenance(g10_destination_still_approach, level, 1).
provenance(g10_destination_still_approach, support, 8).
provenance(g10_destination_still_approach, kept, 8).
provenance(g10_destination_still_approach, confidence_permille, 998).
provenance(g10_destination_still_approach, antecedent, a28).
rule(g11_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g11_destination_still_approach, pour_below_rim).
body(g11_destination_still_approach, pour_half_tilted).
learned(g11_destination_still_approach).
provenance(g11_destination_still_approach, layer, general).
provenance(g11_destination_still_approach, level, 2).
provenance(g11_destination_still_approach, support, 14).
provenance(g11_destination_still_approach, kept, 7).
provenance(g11_destination_still_approach, confidence_permille, 530).
provenance(g11_destination_still_approach, antecedent, a62).
rule(g12_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g12_destination_still_approach, pour_below_rim).
body(g12_destination_still_approach, pour_upright).
learned(g12_destination_still_approach).
provenance(g12_destination_still_approach, layer, general).
provenance(g12_destination_still_approach, level, 2).
provenance(g12_destination_still_approach, support, 10).
provenance(g12_destination_still_approach, kept, 3).
provenance(g12_destination_still_approach, confidence_permille, 521).
provenance(g12_destination_still_approach, antecedent, a60).
provenance(g12_destination_still_approach, doubt, parts_disagree).
rule(g13_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g13_destination_still_approach, pour_below_rim).
body(g13_destination_still_approach, pour_slightly_tilted).
learned(g13_destination_still_approach).
provenance(g13_destination_still_approach, layer, general).
provenance(g13_destination_still_approach, level, 2).
provenance(g13_destination_still_approach, support, 16).
provenance(g13_destination_still_approach, kept, 5).
provenance(g13_destination_still_approach, confidence_permille, 546).
provenance(g13_destination_still_approach, antecedent, a61).
provenance(g13_destination_still_approach, doubt, parts_disagree).
rule(g14_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g14_destination_still_approach, approach_moving_away).
body(g14_destination_still_approach, pour_below_rim).
learned(g14_destination_still_approach).
provenance(g14_destination_still_approach, layer, general).
provenance(g14_destination_still_approach, level, 1).
provenance(g14_destination_still_approach, support, 6).
provenance(g14_destination_still_approach, kept, 3).
provenance(g14_destination_still_approach, confidence_permille, 633).
provenance(g14_destination_still_approach, antecedent, a79).
provenance(g14_destination_still_approach, doubt, pours_contradict).
rule(g15_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g15_destination_still_approach, pour_below_rim).
body(g15_destination_still_approach, pour_tilted_back).
learned(g15_destination_still_approach).
provenance(g15_destination_still_approach, layer, general).
provenance(g15_destination_still_approach, level, 1).
provenance(g15_destination_still_approach, support, 24).
provenance(g15_destination_still_approach, kept, 12).
provenance(g15_destination_still_approach, confidence_permille, 502).
provenance(g15_destination_still_approach, antecedent, a63).
provenance(g15_destination_still_approach, doubt, pours_contradict).
rule(g16_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g16_destination_still_approach, pour_below_rim).
body(g16_destination_still_approach, start_centred).
learned(g16_destination_still_approach).
provenance(g16_destination_still_approach, layer, general).
provenance(g16_destination_still_approach, level, 1).
provenance(g16_destination_still_approach, support, 5).
provenance(g16_destination_still_approach, kept, 2).
provenance(g16_destination_still_approach, confidence_permille, 598).
provenance(g16_destination_still_approach, antecedent, a120).
provenance(g16_destination_still_approach, doubt, pours_contradict).
rule(g17_destination_still_approach, defeasible, destination_still_approach).
body(g17_destination_still_approach, approach_moving_away).
body(g17_destination_still_approach, start_low).
learned(g17_destination_still_approach).
provenance(g17_destination_still_approach, layer, general).
provenance(g17_destination_still_approach, level, 1).
provenance(g17_destination_still_approach, support, 2).
provenance(g17_destination_still_approach, kept, 2).
provenance(g17_destination_still_approach, confidence_permille, 648).
provenance(g17_destination_still_approach, doubt, beside_interaction).
provenance(g17_destination_still_approach, beside, approach_moving_away).
provenance(g17_destination_still_approach, beside, start_below_rim).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 24).
provenance(g0_destination_still_retreat, kept, 24).
provenance(g0_destination_still_retreat, confidence_permille, 987).
provenance(g0_destination_still_retreat, antecedent, a1).
rule(g1_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g1_destination_still_retreat, pour_below_rim).
learned(g1_destination_still_retreat).
provenance(g1_destination_still_retreat, layer, general).
provenance(g1_destination_still_retreat, level, 1).
provenance(g1_destination_still_retreat, support, 50).
provenance(g1_destination_still_retreat, kept, 39).
provenance(g1_destination_still_retreat, confidence_permille, 774).
provenance(g1_destination_still_retreat, antecedent, a4).
rule(g2_destination_still_retreat, defeasible, destination_still_retreat).
body(g2_destination_still_retreat, end_below_rim).
learned(g2_destination_still_retreat).
provenance(g2_destination_still_retreat, layer, general).
provenance(g2_destination_still_retreat, level, 1).
provenance(g2_destination_still_retreat, support, 12).
provenance(g2_destination_still_retreat, kept, 8).
provenance(g2_destination_still_retreat, confidence_permille, 696).
provenance(g2_destination_still_retreat, antecedent, a14).
rule(g3_destination_still_retreat, defeasible, destination_still_retreat).
body(g3_destination_still_retreat, pour_far_away).
learned(g3_destination_still_retreat).
provenance(g3_destination_still_retreat, layer, general).
provenance(g3_destination_still_retreat, level, 1).
provenance(g3_destination_still_retreat, support, 10).
provenance(g3_destination_still_retreat, kept, 10).
provenance(g3_destination_still_retreat, confidence_permille, 1000).
provenance(g3_destination_still_retreat, antecedent, a39).
rule(g4_destination_still_retreat, defeasible, destination_still_retreat).
body(g4_destination_still_retreat, pour_low).
learned(g4_destination_still_retreat).
provenance(g4_destination_still_retreat, layer, general).
provenance(g4_destination_still_retreat, level, 1).
provenance(g4_destination_still_retreat, support, 19).
provenance(g4_destination_still_retreat, kept, 13).
provenance(g4_destination_still_retreat, confidence_permille, 699).
provenance(g4_destination_still_retreat, antecedent, a56).
rule(g5_destination_still_retreat, defeasible, destination_still_retreat).
body(g5_destination_still_retreat, pour_below_rim).
body(g5_destination_still_retreat, start_low).
learned(g5_destination_still_retreat).
provenance(g5_destination_still_retreat, layer, general).
provenance(g5_destination_still_retreat, level, 2).
provenance(g5_destination_still_retreat, support, 4).
provenance(g5_destination_still_retreat, kept, 4).
provenance(g5_destination_still_retreat, confidence_permille, 825).
provenance(g5_destination_still_retreat, antecedent, a105).
rule(g6_destination_still_retreat, defeasible, destination_still_retreat).
body(g6_destination_still_retreat, approach_raising).
body(g6_destination_still_retreat, pour_below_rim).
learned(g6_destination_still_retreat).
provenance(g6_destination_still_retreat, layer, general).
provenance(g6_destination_still_retreat, level, 2).
provenance(g6_destination_still_retreat, support, 4).
provenance(g6_destination_still_retreat, kept, 3).
provenance(g6_destination_still_retreat, confidence_permille, 742).
provenance(g6_destination_still_retreat, antecedent, a84).
rule(g7_destination_still_retreat, defeasible, destination_still_retreat).
body(g7_destination_still_retreat, pour_below_rim).
body(g7_destination_still_retreat, start_below_rim).
learned(g7_destination_still_retreat).
provenance(g7_destination_still_retreat, layer, general).
provenance(g7_destination_still_retreat, level, 2).
provenance(g7_destination_still_retreat, support, 6).
provenance(g7_destination_still_retreat, kept, 4).
provenance(g7_destination_still_retreat, confidence_permille, 655).
provenance(g7_destination_still_retreat, antecedent, a131).
rule(g8_destination_still_retreat, defeasible, destination_still_retreat).
body(g8_destination_still_retreat, pour_below_rim).
body(g8_destination_still_retreat, pour_slightly_tilted).
learned(g8_destination_still_retreat).
provenance(g8_destination_still_retreat, layer, general).
provenance(g8_destination_still_retreat, level, 2).
provenance(g8_destination_still_retreat, support, 16).
provenance(g8_destination_still_retreat, kept, 10).
provenance(g8_destination_still_retreat, confidence_permille, 595).
provenance(g8_destination_still_retreat, antecedent, a61).
rule(g9_destination_still_retreat, defeasible, destination_still_retreat).
body(g9_destination_still_retreat, pour_below_rim).
body(g9_destination_still_retreat, pour_half_tilted).
learned(g9_destination_still_retreat).
provenance(g9_destination_still_retreat, layer, general).
provenance(g9_destination_still_retreat, level, 2).
provenance(g9_destination_still_retreat, support, 14).
provenance(g9_destination_still_retreat, kept, 8).
provenance(g9_destination_still_retreat, confidence_permille, 544).
provenance(g9_destination_still_retreat, antecedent, a62).
rule(g10_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g10_destination_still_retreat, pour_below_rim).
body(g10_destination_still_retreat, retreat_moving_closer).
learned(g10_destination_still_retreat).
provenance(g10_destination_still_retreat, layer, general).
provenance(g10_destination_still_retreat, level, 1).
provenance(g10_destination_still_retreat, support, 7).
provenance(g10_destination_still_retreat, kept, 3).
provenance(g10_destination_still_retreat, confidence_permille, 516).
provenance(g10_destination_still_retreat, antecedent, a73).
rule(g11_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g11_destination_still_retreat, pour_below_rim).
body(g11_destination_still_retreat, pour_tilted_back).
learned(g11_destination_still_retreat).
provenance(g11_destination_still_retreat, layer, general).
provenance(g11_destination_still_retreat, level, 1).
provenance(g11_destination_still_retreat, support, 24).
provenance(g11_destination_still_retreat, kept, 13).
provenance(g11_destination_still_retreat, confidence_permille, 543).
provenance(g11_destination_still_retreat, antecedent, a63).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 24).
provenance(g0_destination_still_settle, kept, 24).
provenance(g0_destination_still_settle, confidence_permille, 999).
provenance(g0_destination_still_settle, antecedent, a1).
rule(g1_destination_still_settle, defeasible, destination_still_settle).
body(g1_destination_still_settle, pour_below_rim).
learned(g1_destination_still_settle).
provenance(g1_destination_still_settle, layer, general).
provenance(g1_destination_still_settle, level, 1).
provenance(g1_destination_still_settle, support, 50).
provenance(g1_destination_still_settle, kept, 39).
provenance(g1_destination_still_settle, confidence_permille, 790).
provenance(g1_destination_still_settle, antecedent, a4).
rule(g2_destination_still_settle, defeasible, destination_still_settle).
body(g2_destination_still_settle, bouncy_liquid).
body(g2_destination_still_settle, pour_below_rim).
learned(g2_destination_still_settle).
provenance(g2_destination_still_settle, layer, general).
provenance(g2_destination_still_settle, level, 1).
provenance(g2_destination_still_settle, support, 4).
provenance(g2_destination_still_settle, kept, 1).
provenance(g2_destination_still_settle, confidence_permille, 561).
provenance(g2_destination_still_settle, antecedent, a123).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 24).
provenance(g0_destination_upright, kept, 24).
provenance(g0_destination_upright, confidence_permille, 1000).
provenance(g0_destination_upright, antecedent, a1).
rule(g1_destination_upright, defeasible, destination_upright).
body(g1_destination_upright, pour_below_rim).
learned(g1_destination_upright).
provenance(g1_destination_upright, layer, general).
provenance(g1_destination_upright, level, 1).
provenance(g1_destination_upright, support, 50).
provenance(g1_destination_upright, kept, 42).
provenance(g1_destination_upright, confidence_permille, 845).
provenance(g1_destination_upright, antecedent, a4).
rule(g2_destination_upright, defeasible, neg(destination_upright)).
body(g2_destination_upright, pour_below_rim).
body(g2_destination_upright, retreat_lowering).
learned(g2_destination_upright).
provenance(g2_destination_upright, layer, general).
provenance(g2_destination_upright, level, 2).
provenance(g2_destination_upright, support, 6).
provenance(g2_destination_upright, kept, 5).
provenance(g2_destination_upright, confidence_permille, 643).
provenance(g2_destination_upright, antecedent, a69).
rule(g3_destination_upright, defeasible, destination_upright).
body(g3_destination_upright, pour_below_rim).
body(g3_destination_upright, start_tilted_back).
learned(g3_destination_upright).
provenance(g3_destination_upright, layer, general).
provenance(g3_destination_upright, level, 1).
provenance(g3_destination_upright, support, 6).
provenance(g3_destination_upright, kept, 3).
provenance(g3_destination_upright, confidence_permille, 647).
provenance(g3_destination_upright, antecedent, a115).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 24).
provenance(g0_source_clear, kept, 23).
provenance(g0_source_clear, confidence_permille, 943).
provenance(g0_source_clear, antecedent, a1).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, pour_below_rim).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 50).
provenance(g1_source_clear, kept, 50).
provenance(g1_source_clear, confidence_permille, 999).
provenance(g1_source_clear, antecedent, a4).
rule(g2_source_clear, defeasible, neg(source_clear)).
body(g2_source_clear, start_below_rim).
learned(g2_source_clear).
provenance(g2_source_clear, layer, general).
provenance(g2_source_clear, level, 1).
provenance(g2_source_clear, support, 11).
provenance(g2_source_clear, kept, 7).
provenance(g2_source_clear, confidence_permille, 610).
provenance(g2_source_clear, antecedent, a2).
rule(g3_source_clear, defeasible, neg(source_clear)).
body(g3_source_clear, approach_raising).
learned(g3_source_clear).
provenance(g3_source_clear, layer, general).
provenance(g3_source_clear, level, 1).
provenance(g3_source_clear, support, 20).
provenance(g3_source_clear, kept, 11).
provenance(g3_source_clear, confidence_permille, 511).
provenance(g3_source_clear, antecedent, a111).
rule(g4_source_clear, defeasible, source_clear).
body(g4_source_clear, end_below_rim).
learned(g4_source_clear).
provenance(g4_source_clear, layer, general).
provenance(g4_source_clear, level, 1).
provenance(g4_source_clear, support, 12).
provenance(g4_source_clear, kept, 6).
provenance(g4_source_clear, confidence_permille, 522).
provenance(g4_source_clear, antecedent, a14).
rule(g5_source_clear, defeasible, neg(source_clear)).
body(g5_source_clear, pour_low).
learned(g5_source_clear).
provenance(g5_source_clear, layer, general).
provenance(g5_source_clear, level, 1).
provenance(g5_source_clear, support, 19).
provenance(g5_source_clear, kept, 12).
provenance(g5_source_clear, confidence_permille, 638).
provenance(g5_source_clear, antecedent, a56).
rule(g6_source_clear, defeasible, source_clear).
body(g6_source_clear, pour_to_side).
learned(g6_source_clear).
provenance(g6_source_clear, layer, general).
provenance(g6_source_clear, level, 1).
provenance(g6_source_clear, support, 15).
provenance(g6_source_clear, kept, 15).
provenance(g6_source_clear, confidence_permille, 999).
provenance(g6_source_clear, antecedent, a29).
rule(g7_source_clear, defeasible, source_clear).
body(g7_source_clear, pour_very_high).
learned(g7_source_clear).
provenance(g7_source_clear, layer, general).
provenance(g7_source_clear, level, 1).
provenance(g7_source_clear, support, 13).
provenance(g7_source_clear, kept, 13).
provenance(g7_source_clear, confidence_permille, 999).
provenance(g7_source_clear, antecedent, a6).
rule(g8_source_clear, defeasible, source_clear).
body(g8_source_clear, start_low).
learned(g8_source_clear).
provenance(g8_source_clear, layer, general).
provenance(g8_source_clear, level, 1).
provenance(g8_source_clear, support, 9).
provenance(g8_source_clear, kept, 5).
provenance(g8_source_clear, confidence_permille, 641).
provenance(g8_source_clear, antecedent, a3).
rule(g9_source_clear, defeasible, source_clear).
body(g9_source_clear, pour_half_tilted).
learned(g9_source_clear).
provenance(g9_source_clear, layer, general).
provenance(g9_source_clear, level, 1).
provenance(g9_source_clear, support, 8).
provenance(g9_source_clear, kept, 8).
provenance(g9_source_clear, confidence_permille, 997).
provenance(g9_source_clear, antecedent, a28).
rule(g10_source_clear, defeasible, source_clear).
body(g10_source_clear, pour_below_rim).
body(g10_source_clear, pour_far_away).
learned(g10_source_clear).
provenance(g10_source_clear, layer, general).
provenance(g10_source_clear, level, 2).
provenance(g10_source_clear, support, 6).
provenance(g10_source_clear, kept, 6).
provenance(g10_source_clear, confidence_permille, 941).
provenance(g10_source_clear, antecedent, a64).
rule(g11_source_clear, defeasible, source_clear).
body(g11_source_clear, pour_upright).
learned(g11_source_clear).
provenance(g11_source_clear, layer, general).
provenance(g11_source_clear, level, 1).
provenance(g11_source_clear, support, 6).
provenance(g11_source_clear, kept, 6).
provenance(g11_source_clear, confidence_permille, 998).
provenance(g11_source_clear, antecedent, a24).
rule(g12_source_clear, defeasible, source_clear).
body(g12_source_clear, end_low).
body(g12_source_clear, end_upside_down).
learned(g12_source_clear).
provenance(g12_source_clear, layer, general).
provenance(g12_source_clear, level, 1).
provenance(g12_source_clear, support, 2).
provenance(g12_source_clear, kept, 0).
provenance(g12_source_clear, confidence_permille, 614).
provenance(g12_source_clear, antecedent, a143).
provenance(g12_source_clear, doubt, pours_contradict).
rule(g0_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 24).
provenance(g0_liquid_leaves_source, kept, 24).
provenance(g0_liquid_leaves_source, confidence_permille, 1000).
provenance(g0_liquid_leaves_source, antecedent, a1).
rule(g1_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g1_liquid_leaves_source, pour_half_tilted).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 8).
provenance(g1_liquid_leaves_source, kept, 8).
provenance(g1_liquid_leaves_source, confidence_permille, 1000).
provenance(g1_liquid_leaves_source, antecedent, a28).
rule(g2_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g2_liquid_leaves_source, pour_slightly_tilted).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 6).
provenance(g2_liquid_leaves_source, kept, 6).
provenance(g2_liquid_leaves_source, confidence_permille, 1000).
provenance(g2_liquid_leaves_source, antecedent, a27).
rule(g3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g3_liquid_leaves_source, pour_upright).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 6).
provenance(g3_liquid_leaves_source, kept, 6).
provenance(g3_liquid_leaves_source, confidence_permille, 1000).
provenance(g3_liquid_leaves_source, antecedent, a24).
rule(g4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g4_liquid_leaves_source, pour_tilted_back).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 10).
provenance(g4_liquid_leaves_source, kept, 10).
provenance(g4_liquid_leaves_source, confidence_permille, 1000).
provenance(g4_liquid_leaves_source, antecedent, a23).
rule(g5_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g5_liquid_leaves_source, pour_steeply_tilted).
learned(g5_liquid_leaves_source).
provenance(g5_liquid_leaves_source, layer, general).
provenance(g5_liquid_leaves_source, level, 1).
provenance(g5_liquid_leaves_source, support, 11).
provenance(g5_liquid_leaves_source, kept, 10).
provenance(g5_liquid_leaves_source, confidence_permille, 880).
provenance(g5_liquid_leaves_source, antecedent, a126).
rule(g6_liquid_leaves_source, defeasible, liquid_leaves_source).
body(g6_liquid_leaves_source, fast_approach).
body(g6_liquid_leaves_source, pour_steeply_tilted).
learned(g6_liquid_leaves_source).
provenance(g6_liquid_leaves_source, layer, general).
provenance(g6_liquid_leaves_source, level, 1).
provenance(g6_liquid_leaves_source, support, 5).
provenance(g6_liquid_leaves_source, kept, 2).
provenance(g6_liquid_leaves_source, confidence_permille, 591).
provenance(g6_liquid_leaves_source, antecedent, a157).
rule(g0_liquid_enters_destination, defeasible, liquid_enters_destination).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 24).
provenance(g0_liquid_enters_destination, kept, 24).
provenance(g0_liquid_enters_destination, confidence_permille, 961).
provenance(g0_liquid_enters_destination, antecedent, a1).
rule(g1_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g1_liquid_enters_destination, pour_half_tilted).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 8).
provenance(g1_liquid_enters_destination, kept, 8).
provenance(g1_liquid_enters_destination, confidence_permille, 974).
provenance(g1_liquid_enters_destination, antecedent, a28).
rule(g2_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g2_liquid_enters_destination, pour_offset_sideways).
learned(g2_liquid_enters_destination).
provenance(g2_liquid_enters_destination, layer, general).
provenance(g2_liquid_enters_destination, level, 1).
provenance(g2_liquid_enters_destination, support, 13).
provenance(g2_liquid_enters_destination, kept, 10).
provenance(g2_liquid_enters_destination, confidence_permille, 731).
provenance(g2_liquid_enters_destination, antecedent, a52).
rule(g3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g3_liquid_enters_destination, pour_far_away).
learned(g3_liquid_enters_destination).
provenance(g3_liquid_enters_destination, layer, general).
provenance(g3_liquid_enters_destination, level, 1).
provenance(g3_liquid_enters_destination, support, 10).
provenance(g3_liquid_enters_destination, kept, 10).
provenance(g3_liquid_enters_destination, confidence_permille, 992).
provenance(g3_liquid_enters_destination, antecedent, a39).
rule(g4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g4_liquid_enters_destination, pour_to_side).
learned(g4_liquid_enters_destination).
provenance(g4_liquid_enters_destination, layer, general).
provenance(g4_liquid_enters_destination, level, 1).
provenance(g4_liquid_enters_destination, support, 15).
provenance(g4_liquid_enters_destination, kept, 11).
provenance(g4_liquid_enters_destination, confidence_permille, 736).
provenance(g4_liquid_enters_destination, antecedent, a29).
rule(g5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g5_liquid_enters_destination, pour_slightly_tilted).
learned(g5_liquid_enters_destination).
provenance(g5_liquid_enters_destination, layer, general).
provenance(g5_liquid_enters_destination, level, 1).
provenance(g5_liquid_enters_destination, support, 6).
provenance(g5_liquid_enters_destination, kept, 6).
provenance(g5_liquid_enters_destination, confidence_permille, 975).
provenance(g5_liquid_enters_destination, antecedent, a27).
rule(g6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g6_liquid_enters_destination, pour_upright).
learned(g6_liquid_enters_destination).
provenance(g6_liquid_enters_destination, layer, general).
provenance(g6_liquid_enters_destination, level, 1).
provenance(g6_liquid_enters_destination, support, 6).
provenance(g6_liquid_enters_destination, kept, 6).
provenance(g6_liquid_enters_destination, confidence_permille, 981).
provenance(g6_liquid_enters_destination, antecedent, a24).
rule(g7_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g7_liquid_enters_destination, pour_tilted_back).
learned(g7_liquid_enters_destination).
provenance(g7_liquid_enters_destination, layer, general).
provenance(g7_liquid_enters_destination, level, 1).
provenance(g7_liquid_enters_destination, support, 10).
provenance(g7_liquid_enters_destination, kept, 10).
provenance(g7_liquid_enters_destination, confidence_permille, 990).
provenance(g7_liquid_enters_destination, antecedent, a23).
rule(g8_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g8_liquid_enters_destination, pour_very_high).
learned(g8_liquid_enters_destination).
provenance(g8_liquid_enters_destination, layer, general).
provenance(g8_liquid_enters_destination, level, 1).
provenance(g8_liquid_enters_destination, support, 13).
provenance(g8_liquid_enters_destination, kept, 8).
provenance(g8_liquid_enters_destination, confidence_permille, 546).
provenance(g8_liquid_enters_destination, antecedent, a6).
rule(g9_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g9_liquid_enters_destination, pour_below_rim).
learned(g9_liquid_enters_destination).
provenance(g9_liquid_enters_destination, layer, general).
provenance(g9_liquid_enters_destination, level, 1).
provenance(g9_liquid_enters_destination, support, 50).
provenance(g9_liquid_enters_destination, kept, 38).
provenance(g9_liquid_enters_destination, confidence_permille, 763).
provenance(g9_liquid_enters_destination, antecedent, a4).
rule(g10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g10_liquid_enters_destination, pour_below_rim).
body(g10_liquid_enters_destination, pour_upright).
learned(g10_liquid_enters_destination).
provenance(g10_liquid_enters_destination, layer, general).
provenance(g10_liquid_enters_destination, level, 2).
provenance(g10_liquid_enters_destination, support, 10).
provenance(g10_liquid_enters_destination, kept, 9).
provenance(g10_liquid_enters_destination, confidence_permille, 835).
provenance(g10_liquid_enters_destination, antecedent, a60).
rule(g11_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g11_liquid_enters_destination, pour_below_rim).
body(g11_liquid_enters_destination, pour_slightly_tilted).
learned(g11_liquid_enters_destination).
provenance(g11_liquid_enters_destination, layer, general).
provenance(g11_liquid_enters_destination, level, 2).
provenance(g11_liquid_enters_destination, support, 16).
provenance(g11_liquid_enters_destination, kept, 13).
provenance(g11_liquid_enters_destination, confidence_permille, 779).
provenance(g11_liquid_enters_destination, antecedent, a61).
rule(g12_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g12_liquid_enters_destination, approach_moving_away).
body(g12_liquid_enters_destination, start_below_rim).
learned(g12_liquid_enters_destination).
provenance(g12_liquid_enters_destination, layer, general).
provenance(g12_liquid_enters_destination, level, 1).
provenance(g12_liquid_enters_destination, support, 4).
provenance(g12_liquid_enters_destination, kept, 1).
provenance(g12_liquid_enters_destination, confidence_permille, 550).
provenance(g12_liquid_enters_destination, antecedent, a185).
provenance(g12_liquid_enters_destination, doubt, pours_contradict).
rule(g13_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g13_liquid_enters_destination, fast_approach).
body(g13_liquid_enters_destination, pour_steeply_tilted).
learned(g13_liquid_enters_destination).
provenance(g13_liquid_enters_destination, layer, general).
provenance(g13_liquid_enters_destination, level, 1).
provenance(g13_liquid_enters_destination, support, 5).
provenance(g13_liquid_enters_destination, kept, 4).
provenance(g13_liquid_enters_destination, confidence_permille, 534).
provenance(g13_liquid_enters_destination, antecedent, a157).
provenance(g13_liquid_enters_destination, doubt, pours_contradict).
rule(g14_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g14_liquid_enters_destination, pour_below_rim).
body(g14_liquid_enters_destination, pour_half_tilted).
learned(g14_liquid_enters_destination).
provenance(g14_liquid_enters_destination, layer, general).
provenance(g14_liquid_enters_destination, level, 2).
provenance(g14_liquid_enters_destination, support, 14).
provenance(g14_liquid_enters_destination, kept, 11).
provenance(g14_liquid_enters_destination, confidence_permille, 750).
provenance(g14_liquid_enters_destination, antecedent, a62).
provenance(g14_liquid_enters_destination, doubt, pours_contradict).
rule(g15_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g15_liquid_enters_destination, pour_below_rim).
body(g15_liquid_enters_destination, pour_tilted_back).
learned(g15_liquid_enters_destination).
provenance(g15_liquid_enters_destination, layer, general).
provenance(g15_liquid_enters_destination, level, 2).
provenance(g15_liquid_enters_destination, support, 24).
provenance(g15_liquid_enters_destination, kept, 12).
provenance(g15_liquid_enters_destination, confidence_permille, 506).
provenance(g15_liquid_enters_destination, antecedent, a63).
provenance(g15_liquid_enters_destination, doubt, pours_contradict).
rule(g16_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g16_liquid_enters_destination, pour_low).
body(g16_liquid_enters_destination, start_below_rim).
learned(g16_liquid_enters_destination).
provenance(g16_liquid_enters_destination, layer, general).
provenance(g16_liquid_enters_destination, level, 1).
provenance(g16_liquid_enters_destination, support, 2).
provenance(g16_liquid_enters_destination, kept, 2).
provenance(g16_liquid_enters_destination, confidence_permille, 598).
provenance(g16_liquid_enters_destination, antecedent, a184).
provenance(g16_liquid_enters_destination, doubt, pours_contradict).
rule(g17_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g17_liquid_enters_destination, approach_moving_away).
body(g17_liquid_enters_destination, start_low).
learned(g17_liquid_enters_destination).
provenance(g17_liquid_enters_destination, layer, general).
provenance(g17_liquid_enters_destination, level, 1).
provenance(g17_liquid_enters_destination, support, 2).
provenance(g17_liquid_enters_destination, kept, 2).
provenance(g17_liquid_enters_destination, confidence_permille, 648).
provenance(g17_liquid_enters_destination, doubt, beside_interaction).
provenance(g17_liquid_enters_destination, beside, approach_moving_away).
provenance(g17_liquid_enters_destination, beside, start_below_rim).
rule(g18_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g18_liquid_enters_destination, pour_centred).
body(g18_liquid_enters_destination, pour_high).
learned(g18_liquid_enters_destination).
provenance(g18_liquid_enters_destination, layer, general).
provenance(g18_liquid_enters_destination, level, 1).
provenance(g18_liquid_enters_destination, support, 1).
provenance(g18_liquid_enters_destination, kept, 1).
provenance(g18_liquid_enters_destination, confidence_permille, 648).
provenance(g18_liquid_enters_destination, doubt, beside_interaction).
provenance(g18_liquid_enters_destination, beside, pour_centred).
provenance(g18_liquid_enters_destination, beside, pour_very_high).
rule(g19_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g19_liquid_enters_destination, pour_low).
body(g19_liquid_enters_destination, pour_tilted_back).
learned(g19_liquid_enters_destination).
provenance(g19_liquid_enters_destination, layer, general).
provenance(g19_liquid_enters_destination, level, 1).
provenance(g19_liquid_enters_destination, support, 2).
provenance(g19_liquid_enters_destination, kept, 2).
provenance(g19_liquid_enters_destination, confidence_permille, 648).
provenance(g19_liquid_enters_destination, doubt, beside_interaction).
provenance(g19_liquid_enters_destination, beside, pour_below_rim).
provenance(g19_liquid_enters_destination, beside, pour_tilted_back).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 24).
provenance(g0_liquid_remains_in_destination, kept, 24).
provenance(g0_liquid_remains_in_destination, confidence_permille, 999).
provenance(g0_liquid_remains_in_destination, antecedent, a1).
rule(g1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g1_liquid_remains_in_destination, pour_below_rim).
learned(g1_liquid_remains_in_destination).
provenance(g1_liquid_remains_in_destination, layer, general).
provenance(g1_liquid_remains_in_destination, level, 1).
provenance(g1_liquid_remains_in_destination, support, 50).
provenance(g1_liquid_remains_in_destination, kept, 30).
provenance(g1_liquid_remains_in_destination, confidence_permille, 603).
provenance(g1_liquid_remains_in_destination, antecedent, a4).
rule(g2_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g2_liquid_remains_in_destination, pour_below_rim).
body(g2_liquid_remains_in_destination, pour_slightly_tilted).
learned(g2_liquid_remains_in_destination).
provenance(g2_liquid_remains_in_destination, layer, general).
provenance(g2_liquid_remains_in_destination, level, 2).
provenance(g2_liquid_remains_in_destination, support, 16).
provenance(g2_liquid_remains_in_destination, kept, 15).
provenance(g2_liquid_remains_in_destination, confidence_permille, 902).
provenance(g2_liquid_remains_in_destination, antecedent, a61).
rule(g3_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g3_liquid_remains_in_destination, pour_below_rim).
body(g3_liquid_remains_in_destination, pour_upright).
learned(g3_liquid_remains_in_destination).
provenance(g3_liquid_remains_in_destination, layer, general).
provenance(g3_liquid_remains_in_destination, level, 2).
provenance(g3_liquid_remains_in_destination, support, 10).
provenance(g3_liquid_remains_in_destination, kept, 9).
provenance(g3_liquid_remains_in_destination, confidence_permille, 849).
provenance(g3_liquid_remains_in_destination, antecedent, a60).
rule(g4_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g4_liquid_remains_in_destination, approach_raising).
body(g4_liquid_remains_in_destination, pour_below_rim).
learned(g4_liquid_remains_in_destination).
provenance(g4_liquid_remains_in_destination, layer, general).
provenance(g4_liquid_remains_in_destination, level, 1).
provenance(g4_liquid_remains_in_destination, support, 4).
provenance(g4_liquid_remains_in_destination, kept, 4).
provenance(g4_liquid_remains_in_destination, confidence_permille, 940).
provenance(g4_liquid_remains_in_destination, antecedent, a84).
rule(g5_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g5_liquid_remains_in_destination, bouncy_liquid).
body(g5_liquid_remains_in_destination, pour_below_rim).
learned(g5_liquid_remains_in_destination).
provenance(g5_liquid_remains_in_destination, layer, general).
provenance(g5_liquid_remains_in_destination, level, 2).
provenance(g5_liquid_remains_in_destination, support, 4).
provenance(g5_liquid_remains_in_destination, kept, 4).
provenance(g5_liquid_remains_in_destination, confidence_permille, 726).
provenance(g5_liquid_remains_in_destination, antecedent, a123).
rule(g6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g6_liquid_remains_in_destination, pour_below_rim).
body(g6_liquid_remains_in_destination, start_low).
learned(g6_liquid_remains_in_destination).
provenance(g6_liquid_remains_in_destination, layer, general).
provenance(g6_liquid_remains_in_destination, level, 1).
provenance(g6_liquid_remains_in_destination, support, 4).
provenance(g6_liquid_remains_in_destination, kept, 4).
provenance(g6_liquid_remains_in_destination, confidence_permille, 918).
provenance(g6_liquid_remains_in_destination, antecedent, a105).
rule(g7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g7_liquid_remains_in_destination, end_half_tilted).
body(g7_liquid_remains_in_destination, pour_below_rim).
learned(g7_liquid_remains_in_destination).
provenance(g7_liquid_remains_in_destination, layer, general).
provenance(g7_liquid_remains_in_destination, level, 1).
provenance(g7_liquid_remains_in_destination, support, 2).
provenance(g7_liquid_remains_in_destination, kept, 2).
provenance(g7_liquid_remains_in_destination, confidence_permille, 913).
provenance(g7_liquid_remains_in_destination, antecedent, a140).
rule(g8_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g8_liquid_remains_in_destination, pour_below_rim).
body(g8_liquid_remains_in_destination, pour_far_away).
learned(g8_liquid_remains_in_destination).
provenance(g8_liquid_remains_in_destination, layer, general).
provenance(g8_liquid_remains_in_destination, level, 1).
provenance(g8_liquid_remains_in_destination, support, 6).
provenance(g8_liquid_remains_in_destination, kept, 6).
provenance(g8_liquid_remains_in_destination, confidence_permille, 911).
provenance(g8_liquid_remains_in_destination, antecedent, a64).
rule(g9_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g9_liquid_remains_in_destination, bouncy_destination).
body(g9_liquid_remains_in_destination, pour_below_rim).
learned(g9_liquid_remains_in_destination).
provenance(g9_liquid_remains_in_destination, layer, general).
provenance(g9_liquid_remains_in_destination, level, 2).
provenance(g9_liquid_remains_in_destination, support, 4).
provenance(g9_liquid_remains_in_destination, kept, 4).
provenance(g9_liquid_remains_in_destination, confidence_permille, 699).
provenance(g9_liquid_remains_in_destination, antecedent, a99).
rule(g10_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g10_liquid_remains_in_destination, end_slightly_tilted).
body(g10_liquid_remains_in_destination, pour_below_rim).
learned(g10_liquid_remains_in_destination).
provenance(g10_liquid_remains_in_destination, layer, general).
provenance(g10_liquid_remains_in_destination, level, 1).
provenance(g10_liquid_remains_in_destination, support, 2).
provenance(g10_liquid_remains_in_destination, kept, 2).
provenance(g10_liquid_remains_in_destination, confidence_permille, 876).
provenance(g10_liquid_remains_in_destination, antecedent, a118).
rule(g11_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g11_liquid_remains_in_destination, bouncy_source).
body(g11_liquid_remains_in_destination, pour_below_rim).
learned(g11_liquid_remains_in_destination).
provenance(g11_liquid_remains_in_destination, layer, general).
provenance(g11_liquid_remains_in_destination, level, 2).
provenance(g11_liquid_remains_in_destination, support, 2).
provenance(g11_liquid_remains_in_destination, kept, 2).
provenance(g11_liquid_remains_in_destination, confidence_permille, 661).
provenance(g11_liquid_remains_in_destination, antecedent, a144).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 24).
provenance(g0_no_spill, kept, 24).
provenance(g0_no_spill, confidence_permille, 971).
provenance(g0_no_spill, antecedent, a1).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, pour_below_rim).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 50).
provenance(g1_no_spill, kept, 26).
provenance(g1_no_spill, confidence_permille, 521).
provenance(g1_no_spill, antecedent, a4).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, pour_far_away).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 10).
provenance(g2_no_spill, kept, 10).
provenance(g2_no_spill, confidence_permille, 987).
provenance(g2_no_spill, antecedent, a39).
rule(g3_no_spill, defeasible, neg(no_spill)).
body(g3_no_spill, pour_to_side).
learned(g3_no_spill).
provenance(g3_no_spill, layer, general).
provenance(g3_no_spill, level, 1).
provenance(g3_no_spill, support, 15).
provenance(g3_no_spill, kept, 10).
provenance(g3_no_spill, confidence_permille, 677).
provenance(g3_no_spill, antecedent, a29).
rule(g4_no_spill, defeasible, neg(no_spill)).
body(g4_no_spill, pour_offset_sideways).
learned(g4_no_spill).
provenance(g4_no_spill, layer, general).
provenance(g4_no_spill, level, 1).
provenance(g4_no_spill, support, 13).
provenance(g4_no_spill, kept, 10).
provenance(g4_no_spill, confidence_permille, 731).
provenance(g4_no_spill, antecedent, a52).
rule(g5_no_spill, defeasible, neg(no_spill)).
body(g5_no_spill, pour_very_high).
learned(g5_no_spill).
provenance(g5_no_spill, layer, general).
provenance(g5_no_spill, level, 1).
provenance(g5_no_spill, support, 13).
provenance(g5_no_spill, kept, 8).
provenance(g5_no_spill, confidence_permille, 538).
provenance(g5_no_spill, antecedent, a6).
rule(g6_no_spill, defeasible, no_spill).
body(g6_no_spill, pour_half_tilted).
learned(g6_no_spill).
provenance(g6_no_spill, layer, general).
provenance(g6_no_spill, level, 1).
provenance(g6_no_spill, support, 8).
provenance(g6_no_spill, kept, 8).
provenance(g6_no_spill, confidence_permille, 999).
provenance(g6_no_spill, antecedent, a28).
rule(g7_no_spill, defeasible, no_spill).
body(g7_no_spill, pour_slightly_tilted).
learned(g7_no_spill).
provenance(g7_no_spill, layer, general).
provenance(g7_no_spill, level, 1).
provenance(g7_no_spill, support, 6).
provenance(g7_no_spill, kept, 6).
provenance(g7_no_spill, confidence_permille, 1000).
provenance(g7_no_spill, antecedent, a27).
rule(g8_no_spill, defeasible, no_spill).
body(g8_no_spill, pour_tilted_back).
learned(g8_no_spill).
provenance(g8_no_spill, layer, general).
provenance(g8_no_spill, level, 1).
provenance(g8_no_spill, support, 10).
provenance(g8_no_spill, kept, 10).
provenance(g8_no_spill, confidence_permille, 1000).
provenance(g8_no_spill, antecedent, a23).
rule(g9_no_spill, defeasible, no_spill).
body(g9_no_spill, pour_upright).
learned(g9_no_spill).
provenance(g9_no_spill, layer, general).
provenance(g9_no_spill, level, 1).
provenance(g9_no_spill, support, 6).
provenance(g9_no_spill, kept, 6).
provenance(g9_no_spill, confidence_permille, 1000).
provenance(g9_no_spill, antecedent, a24).
rule(g10_no_spill, defeasible, neg(no_spill)).
body(g10_no_spill, approach_moving_away).
body(g10_no_spill, start_below_rim).
learned(g10_no_spill).
provenance(g10_no_spill, layer, general).
provenance(g10_no_spill, level, 1).
provenance(g10_no_spill, support, 4).
provenance(g10_no_spill, kept, 4).
provenance(g10_no_spill, confidence_permille, 590).
provenance(g10_no_spill, antecedent, a185).
rule(g11_no_spill, defeasible, neg(no_spill)).
body(g11_no_spill, pour_low).
body(g11_no_spill, start_below_rim).
learned(g11_no_spill).
provenance(g11_no_spill, layer, general).
provenance(g11_no_spill, level, 1).
provenance(g11_no_spill, support, 2).
provenance(g11_no_spill, kept, 2).
provenance(g11_no_spill, confidence_permille, 518).
provenance(g11_no_spill, antecedent, a184).
rule(g12_no_spill, defeasible, no_spill).
body(g12_no_spill, pour_far_away).
body(g12_no_spill, pour_tilted_back).
learned(g12_no_spill).
provenance(g12_no_spill, layer, general).
provenance(g12_no_spill, level, 2).
provenance(g12_no_spill, support, 0).
provenance(g12_no_spill, kept, 0).
provenance(g12_no_spill, confidence_permille, 648).
provenance(g12_no_spill, doubt, unsettled).
rule(g13_no_spill, defeasible, no_spill).
body(g13_no_spill, pour_far_away).
body(g13_no_spill, pour_slightly_tilted).
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
body(g15_no_spill, approach_moving_away).
body(g15_no_spill, start_low).
learned(g15_no_spill).
provenance(g15_no_spill, layer, general).
provenance(g15_no_spill, level, 1).
provenance(g15_no_spill, support, 2).
provenance(g15_no_spill, kept, 2).
provenance(g15_no_spill, confidence_permille, 648).
provenance(g15_no_spill, doubt, beside_interaction).
provenance(g15_no_spill, beside, approach_moving_away).
provenance(g15_no_spill, beside, start_below_rim).
rule(g16_no_spill, defeasible, no_spill).
body(g16_no_spill, pour_centred).
body(g16_no_spill, pour_high).
learned(g16_no_spill).
provenance(g16_no_spill, layer, general).
provenance(g16_no_spill, level, 1).
provenance(g16_no_spill, support, 1).
provenance(g16_no_spill, kept, 1).
provenance(g16_no_spill, confidence_permille, 648).
provenance(g16_no_spill, doubt, beside_interaction).
provenance(g16_no_spill, beside, pour_centred).
provenance(g16_no_spill, beside, pour_very_high).
sup(g10_destination_still_approach, g1_destination_still_approach).
sup(g10_destination_still_retreat, g2_destination_still_retreat).
sup(g10_destination_still_retreat, g3_destination_still_retreat).
sup(g10_liquid_enters_destination, g2_liquid_enters_destination).
sup(g10_liquid_enters_destination, g3_liquid_enters_destination).
sup(g10_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g10_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g10_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g10_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g10_no_spill, g6_no_spill).
sup(g10_no_spill, g7_no_spill).
sup(g10_no_spill, g8_no_spill).
sup(g10_no_spill, g9_no_spill).
sup(g10_source_clear, g2_source_clear).
sup(g10_source_clear, g3_source_clear).
sup(g11_destination_still_approach, g2_destination_still_approach).
sup(g11_destination_still_approach, g4_destination_still_approach).
sup(g11_destination_still_approach, g6_destination_still_approach).
sup(g11_destination_still_retreat, g2_destination_still_retreat).
sup(g11_destination_still_retreat, g3_destination_still_retreat).
sup(g11_liquid_enters_destination, g2_liquid_enters_destination).
sup(g11_liquid_enters_destination, g3_liquid_enters_destination).
sup(g11_no_spill, g6_no_spill).
sup(g11_no_spill, g7_no_spill).
sup(g11_no_spill, g8_no_spill).
sup(g11_no_spill, g9_no_spill).
sup(g11_source_clear, g2_source_clear).
sup(g11_source_clear, g3_source_clear).
sup(g11_source_clear, g5_source_clear).
sup(g12_destination_still_approach, g2_destination_still_approach).
sup(g12_destination_still_approach, g4_destination_still_approach).
sup(g12_destination_still_approach, g6_destination_still_approach).
sup(g12_liquid_enters_destination, g13_liquid_enters_destination).
sup(g12_liquid_enters_destination, g1_liquid_enters_destination).
sup(g12_liquid_enters_destination, g2_liquid_enters_destination).
sup(g12_liquid_enters_destination, g3_liquid_enters_destination).
sup(g12_liquid_enters_destination, g4_liquid_enters_destination).
sup(g12_liquid_enters_destination, g5_liquid_enters_destination).
sup(g12_liquid_enters_destination, g6_liquid_enters_destination).
sup(g12_liquid_enters_destination, g7_liquid_enters_destination).
sup(g12_liquid_enters_destination, g8_liquid_enters_destination).
sup(g12_no_spill, g10_no_spill).
sup(g12_no_spill, g11_no_spill).
sup(g12_no_spill, g1_no_spill).
sup(g12_no_spill, g4_no_spill).
sup(g12_no_spill, g5_no_spill).
sup(g12_source_clear, g1_source_clear).
sup(g12_source_clear, g2_source_clear).
sup(g12_source_clear, g3_source_clear).
sup(g12_source_clear, g5_source_clear).
sup(g13_destination_still_approach, g2_destination_still_approach).
sup(g13_destination_still_approach, g4_destination_still_approach).
sup(g13_destination_still_approach, g6_destination_still_approach).
sup(g13_liquid_enters_destination, g9_liquid_enters_destination).
sup(g13_no_spill, g10_no_spill).
sup(g13_no_spill, g11_no_spill).
sup(g13_no_spill, g1_no_spill).
sup(g13_no_spill, g4_no_spill).
sup(g13_no_spill, g5_no_spill).
sup(g14_destination_still_approach, g10_destination_still_approach).
sup(g14_destination_still_approach, g2_destination_still_approach).
sup(g14_destination_still_approach, g4_destination_still_approach).
sup(g14_destination_still_approach, g5_destination_still_approach).
sup(g14_destination_still_approach, g6_destination_still_approach).
sup(g14_destination_still_approach, g8_destination_still_approach).
sup(g14_liquid_enters_destination, g2_liquid_enters_destination).
sup(g14_liquid_enters_destination, g3_liquid_enters_destination).
sup(g14_no_spill, g10_no_spill).
sup(g14_no_spill, g11_no_spill).
sup(g14_no_spill, g1_no_spill).
sup(g14_no_spill, g4_no_spill).
sup(g14_no_spill, g5_no_spill).
sup(g15_destination_still_approach, g2_destination_still_approach).
sup(g15_destination_still_approach, g4_destination_still_approach).
sup(g15_destination_still_approach, g6_destination_still_approach).
sup(g15_liquid_enters_destination, g2_liquid_enters_destination).
sup(g15_liquid_enters_destination, g3_liquid_enters_destination).
sup(g15_no_spill, g1_no_spill).
sup(g15_no_spill, g2_no_spill).
sup(g15_no_spill, g3_no_spill).
sup(g15_no_spill, g4_no_spill).
sup(g15_no_spill, g5_no_spill).
sup(g16_destination_still_approach, g10_destination_still_approach).
sup(g16_destination_still_approach, g4_destination_still_approach).
sup(g16_destination_still_approach, g5_destination_still_approach).
sup(g16_destination_still_approach, g6_destination_still_approach).
sup(g16_destination_still_approach, g8_destination_still_approach).
sup(g16_liquid_enters_destination, g12_liquid_enters_destination).
sup(g16_no_spill, g10_no_spill).
sup(g16_no_spill, g4_no_spill).
sup(g17_destination_still_approach, g11_destination_still_approach).
sup(g17_destination_still_approach, g12_destination_still_approach).
sup(g17_destination_still_approach, g13_destination_still_approach).
sup(g17_destination_still_approach, g14_destination_still_approach).
sup(g17_destination_still_approach, g15_destination_still_approach).
sup(g17_destination_still_approach, g1_destination_still_approach).
sup(g17_liquid_enters_destination, g13_liquid_enters_destination).
sup(g17_liquid_enters_destination, g1_liquid_enters_destination).
sup(g17_liquid_enters_destination, g2_liquid_enters_destination).
sup(g17_liquid_enters_destination, g3_liquid_enters_destination).
sup(g17_liquid_enters_destination, g4_liquid_enters_destination).
sup(g17_liquid_enters_destination, g5_liquid_enters_destination).
sup(g17_liquid_enters_destination, g6_liquid_enters_destination).
sup(g17_liquid_enters_destination, g7_liquid_enters_destination).
sup(g17_liquid_enters_destination, g8_liquid_enters_destination).
sup(g18_liquid_enters_destination, g13_liquid_enters_destination).
sup(g18_liquid_enters_destination, g1_liquid_enters_destination).
sup(g18_liquid_enters_destination, g2_liquid_enters_destination).
sup(g18_liquid_enters_destination, g5_liquid_enters_destination).
sup(g18_liquid_enters_destination, g6_liquid_enters_destination).
sup(g18_liquid_enters_destination, g7_liquid_enters_destination).
sup(g19_liquid_enters_destination, g12_liquid_enters_destination).
sup(g19_liquid_enters_destination, g17_liquid_enters_destination).
sup(g1_destination_still_approach, g2_destination_still_approach).
sup(g1_destination_still_approach, g4_destination_still_approach).
sup(g1_destination_still_retreat, g2_destination_still_retreat).
sup(g1_liquid_enters_destination, g9_liquid_enters_destination).
sup(g1_source_clear, g11_source_clear).
sup(g1_source_clear, g4_source_clear).
sup(g1_source_clear, g8_source_clear).
sup(g1_source_clear, g9_source_clear).
sup(g2_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g2_source_clear, g4_source_clear).
sup(g3_destination_still_retreat, g1_destination_still_retreat).
sup(g3_destination_upright, g2_destination_upright).
sup(g3_liquid_enters_destination, g9_liquid_enters_destination).
sup(g4_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g2_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g4_source_clear, g3_source_clear).
sup(g5_destination_still_approach, g1_destination_still_approach).
sup(g5_destination_still_retreat, g10_destination_still_retreat).
sup(g5_destination_still_retreat, g11_destination_still_retreat).
sup(g5_liquid_enters_destination, g9_liquid_enters_destination).
sup(g5_source_clear, g4_source_clear).
sup(g6_destination_still_approach, g1_destination_still_approach).
sup(g6_destination_still_retreat, g10_destination_still_retreat).
sup(g6_destination_still_retreat, g11_destination_still_retreat).
sup(g6_liquid_enters_destination, g9_liquid_enters_destination).
sup(g6_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g6_liquid_remains_in_destination, g2_liquid_remains_in_destination).
sup(g6_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g6_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g6_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g6_no_spill, g1_no_spill).
sup(g6_no_spill, g2_no_spill).
sup(g6_no_spill, g3_no_spill).
sup(g6_no_spill, g4_no_spill).
sup(g6_no_spill, g5_no_spill).
sup(g6_source_clear, g2_source_clear).
sup(g6_source_clear, g3_source_clear).
sup(g6_source_clear, g5_source_clear).
sup(g7_destination_still_retreat, g10_destination_still_retreat).
sup(g7_destination_still_retreat, g11_destination_still_retreat).
sup(g7_liquid_enters_destination, g9_liquid_enters_destination).
sup(g7_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g7_liquid_remains_in_destination, g2_liquid_remains_in_destination).
sup(g7_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g7_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g7_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g7_no_spill, g1_no_spill).
sup(g7_no_spill, g2_no_spill).
sup(g7_no_spill, g3_no_spill).
sup(g7_no_spill, g4_no_spill).
sup(g7_no_spill, g5_no_spill).
sup(g7_source_clear, g2_source_clear).
sup(g7_source_clear, g3_source_clear).
sup(g8_destination_still_approach, g1_destination_still_approach).
sup(g8_destination_still_retreat, g10_destination_still_retreat).
sup(g8_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g8_liquid_remains_in_destination, g2_liquid_remains_in_destination).
sup(g8_liquid_remains_in_destination, g3_liquid_remains_in_destination).
sup(g8_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g8_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g8_no_spill, g1_no_spill).
sup(g8_no_spill, g2_no_spill).
sup(g8_no_spill, g3_no_spill).
sup(g8_no_spill, g4_no_spill).
sup(g8_no_spill, g5_no_spill).
sup(g8_source_clear, g5_source_clear).
sup(g9_destination_still_retreat, g10_destination_still_retreat).
sup(g9_liquid_enters_destination, g2_liquid_enters_destination).
sup(g9_no_spill, g1_no_spill).
sup(g9_no_spill, g2_no_spill).
sup(g9_no_spill, g3_no_spill).
sup(g9_no_spill, g4_no_spill).
sup(g9_no_spill, g5_no_spill).
sup(g9_source_clear, g2_source_clear).
sup(g9_source_clear, g3_source_clear).
sup(g9_source_clear, g5_source_clear).

% The explored antecedents, with or without a rule of their own:
% explored(A, Prop): the antecedent A says Prop (the ordinary pour,
% which says nothing, has none); held(A, E, Held, Pours): of the Pours
% pours that could have been drawn for A, Held held E. An answer for
% a scene explored cites them (docs/theory-formats.md).
held(a1, destination_still_approach, 24, 24).
held(a1, destination_still_retreat, 24, 24).
held(a1, destination_still_settle, 24, 24).
held(a1, destination_upright, 24, 24).
held(a1, source_clear, 23, 24).
held(a1, liquid_leaves_source, 24, 24).
held(a1, liquid_enters_destination, 24, 24).
held(a1, liquid_remains_in_destination, 24, 24).
held(a1, no_spill, 24, 24).
explored(a2, start_below_rim).
held(a2, destination_still_approach, 6, 11).
held(a2, destination_still_retreat, 11, 11).
held(a2, destination_still_settle, 11, 11).
held(a2, destination_upright, 11, 11).
held(a2, source_clear, 4, 11).
held(a2, liquid_leaves_source, 11, 11).
held(a2, liquid_enters_destination, 10, 11).
held(a2, liquid_remains_in_destination, 11, 11).
held(a2, no_spill, 10, 11).
explored(a3, start_low).
held(a3, destination_still_approach, 8, 9).
held(a3, destination_still_retreat, 9, 9).
held(a3, destination_still_settle, 9, 9).
held(a3, destination_upright, 9, 9).
held(a3, source_clear, 5, 9).
held(a3, liquid_leaves_source, 9, 9).
held(a3, liquid_enters_destination, 8, 9).
held(a3, liquid_remains_in_destination, 9, 9).
held(a3, no_spill, 8, 9).
explored(a4, pour_below_rim).
held(a4, destination_still_approach, 4, 50).
held(a4, destination_still_retreat, 11, 50).
held(a4, destination_still_settle, 39, 50).
held(a4, destination_upright, 42, 50).
held(a4, source_clear, 0, 50).
held(a4, liquid_leaves_source, 48, 50).
held(a4, liquid_enters_destination, 38, 50).
held(a4, liquid_remains_in_destination, 30, 50).
held(a4, no_spill, 24, 50).
explored(a5, pour_high).
held(a5, destination_still_approach, 6, 6).
held(a5, destination_still_retreat, 6, 6).
held(a5, destination_still_settle, 6, 6).
held(a5, destination_upright, 6, 6).
held(a5, source_clear, 6, 6).
held(a5, liquid_leaves_source, 6, 6).
held(a5, liquid_enters_destination, 6, 6).
held(a5, liquid_remains_in_destination, 6, 6).
held(a5, no_spill, 6, 6).
explored(a6, pour_very_high).
held(a6, destination_still_approach, 13, 13).
held(a6, destination_still_retreat, 13, 13).
held(a6, destination_still_settle, 13, 13).
held(a6, destination_upright, 13, 13).
held(a6, source_clear, 13, 13).
held(a6, liquid_leaves_source, 13, 13).
held(a6, liquid_enters_destination, 5, 13).
held(a6, liquid_remains_in_destination, 13, 13).
held(a6, no_spill, 5, 13).
explored(a7, start_tilted_back).
held(a7, destination_still_approach, 6, 6).
held(a7, destination_still_retreat, 6, 6).
held(a7, destination_still_settle, 6, 6).
held(a7, destination_upright, 6, 6).
held(a7, source_clear, 6, 6).
held(a7, liquid_leaves_source, 6, 6).
held(a7, liquid_enters_destination, 6, 6).
held(a7, liquid_remains_in_destination, 6, 6).
held(a7, no_spill, 6, 6).
explored(a8, slow_approach).
held(a8, destination_still_approach, 4, 4).
held(a8, destination_still_retreat, 4, 4).
held(a8, destination_still_settle, 4, 4).
held(a8, destination_upright, 4, 4).
held(a8, source_clear, 4, 4).
held(a8, liquid_leaves_source, 4, 4).
held(a8, liquid_enters_destination, 4, 4).
held(a8, liquid_remains_in_destination, 4, 4).
held(a8, no_spill, 4, 4).
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
explored(a10, end_steeply_tilted).
held(a10, destination_still_approach, 4, 4).
held(a10, destination_still_retreat, 4, 4).
held(a10, destination_still_settle, 4, 4).
held(a10, destination_upright, 4, 4).
held(a10, source_clear, 4, 4).
held(a10, liquid_leaves_source, 4, 4).
held(a10, liquid_enters_destination, 4, 4).
held(a10, liquid_remains_in_destination, 4, 4).
held(a10, no_spill, 4, 4).
explored(a11, end_upside_down).
held(a11, destination_still_approach, 4, 4).
held(a11, destination_still_retreat, 4, 4).
held(a11, destination_still_settle, 4, 4).
held(a11, destination_upright, 4, 4).
held(a11, source_clear, 4, 4).
held(a11, liquid_leaves_source, 4, 4).
held(a11, liquid_enters_destination, 4, 4).
held(a11, liquid_remains_in_destination, 4, 4).
held(a11, no_spill, 4, 4).
explored(a12, dull_source).
held(a12, destination_still_approach, 4, 4).
held(a12, destination_still_retreat, 4, 4).
held(a12, destination_still_settle, 4, 4).
held(a12, destination_upright, 4, 4).
held(a12, source_clear, 3, 4).
held(a12, liquid_leaves_source, 4, 4).
held(a12, liquid_enters_destination, 4, 4).
held(a12, liquid_remains_in_destination, 4, 4).
held(a12, no_spill, 4, 4).
explored(a13, end_low).
held(a13, destination_still_approach, 4, 4).
held(a13, destination_still_retreat, 3, 4).
held(a13, destination_still_settle, 4, 4).
held(a13, destination_upright, 4, 4).
held(a13, source_clear, 3, 4).
held(a13, liquid_leaves_source, 4, 4).
held(a13, liquid_enters_destination, 4, 4).
held(a13, liquid_remains_in_destination, 4, 4).
held(a13, no_spill, 4, 4).
explored(a14, end_below_rim).
held(a14, destination_still_approach, 12, 12).
held(a14, destination_still_retreat, 8, 12).
held(a14, destination_still_settle, 12, 12).
held(a14, destination_upright, 10, 12).
held(a14, source_clear, 6, 12).
held(a14, liquid_leaves_source, 12, 12).
held(a14, liquid_enters_destination, 12, 12).
held(a14, liquid_remains_in_destination, 12, 12).
held(a14, no_spill, 12, 12).
explored(a15, very_much_liquid).
held(a15, destination_still_approach, 4, 4).
held(a15, destination_still_retreat, 4, 4).
held(a15, destination_still_settle, 4, 4).
held(a15, destination_upright, 4, 4).
held(a15, source_clear, 3, 4).
held(a15, liquid_leaves_source, 4, 4).
held(a15, liquid_enters_destination, 4, 4).
held(a15, liquid_remains_in_destination, 4, 4).
held(a15, no_spill, 4, 4).
explored(a16, grippy_source).
held(a16, destination_still_approach, 4, 4).
held(a16, destination_still_retreat, 4, 4).
held(a16, destination_still_settle, 4, 4).
held(a16, destination_upright, 4, 4).
held(a16, source_clear, 4, 4).
held(a16, liquid_leaves_source, 4, 4).
held(a16, liquid_enters_destination, 4, 4).
held(a16, liquid_remains_in_destination, 4, 4).
held(a16, no_spill, 4, 4).
explored(a17, slow_retreat).
held(a17, destination_still_approach, 4, 4).
held(a17, destination_still_retreat, 4, 4).
held(a17, destination_still_settle, 4, 4).
held(a17, destination_upright, 4, 4).
held(a17, source_clear, 4, 4).
held(a17, liquid_leaves_source, 4, 4).
held(a17, liquid_enters_destination, 4, 4).
held(a17, liquid_remains_in_destination, 4, 4).
held(a17, no_spill, 4, 4).
explored(a18, heavy_liquid).
held(a18, destination_still_approach, 4, 4).
held(a18, destination_still_retreat, 4, 4).
held(a18, destination_still_settle, 4, 4).
held(a18, destination_upright, 4, 4).
held(a18, source_clear, 3, 4).
held(a18, liquid_leaves_source, 4, 4).
held(a18, liquid_enters_destination, 4, 4).
held(a18, liquid_remains_in_destination, 4, 4).
held(a18, no_spill, 4, 4).
explored(a19, end_tilted_back).
held(a19, destination_still_approach, 4, 4).
held(a19, destination_still_retreat, 4, 4).
held(a19, destination_still_settle, 4, 4).
held(a19, destination_upright, 4, 4).
held(a19, source_clear, 4, 4).
held(a19, liquid_leaves_source, 4, 4).
held(a19, liquid_enters_destination, 4, 4).
held(a19, liquid_remains_in_destination, 4, 4).
held(a19, no_spill, 4, 4).
explored(a20, little_liquid).
held(a20, destination_still_approach, 4, 4).
held(a20, destination_still_retreat, 4, 4).
held(a20, destination_still_settle, 4, 4).
held(a20, destination_upright, 4, 4).
held(a20, source_clear, 4, 4).
held(a20, liquid_leaves_source, 4, 4).
held(a20, liquid_enters_destination, 4, 4).
held(a20, liquid_remains_in_destination, 4, 4).
held(a20, no_spill, 4, 4).
explored(a21, light_source).
held(a21, destination_still_approach, 4, 4).
held(a21, destination_still_retreat, 4, 4).
held(a21, destination_still_settle, 4, 4).
held(a21, destination_upright, 4, 4).
held(a21, source_clear, 4, 4).
held(a21, liquid_leaves_source, 4, 4).
held(a21, liquid_enters_destination, 4, 4).
held(a21, liquid_remains_in_destination, 4, 4).
held(a21, no_spill, 4, 4).
explored(a22, bouncy_liquid).
held(a22, destination_still_approach, 4, 4).
held(a22, destination_still_retreat, 4, 4).
held(a22, destination_still_settle, 4, 4).
held(a22, destination_upright, 4, 4).
held(a22, source_clear, 4, 4).
held(a22, liquid_leaves_source, 4, 4).
held(a22, liquid_enters_destination, 4, 4).
held(a22, liquid_remains_in_destination, 4, 4).
held(a22, no_spill, 4, 4).
explored(a23, pour_tilted_back).
held(a23, destination_still_approach, 10, 10).
held(a23, destination_still_retreat, 10, 10).
held(a23, destination_still_settle, 10, 10).
held(a23, destination_upright, 10, 10).
held(a23, source_clear, 10, 10).
held(a23, liquid_leaves_source, 0, 10).
held(a23, liquid_enters_destination, 0, 10).
held(a23, liquid_remains_in_destination, 10, 10).
held(a23, no_spill, 10, 10).
explored(a24, pour_upright).
held(a24, destination_still_approach, 6, 6).
held(a24, destination_still_retreat, 6, 6).
held(a24, destination_still_settle, 6, 6).
held(a24, destination_upright, 6, 6).
held(a24, source_clear, 6, 6).
held(a24, liquid_leaves_source, 0, 6).
held(a24, liquid_enters_destination, 0, 6).
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
explored(a26, bouncy_destination).
held(a26, destination_still_approach, 4, 4).
held(a26, destination_still_retreat, 4, 4).
held(a26, destination_still_settle, 4, 4).
held(a26, destination_upright, 4, 4).
held(a26, source_clear, 3, 4).
held(a26, liquid_leaves_source, 4, 4).
held(a26, liquid_enters_destination, 4, 4).
held(a26, liquid_remains_in_destination, 4, 4).
held(a26, no_spill, 4, 4).
explored(a27, pour_slightly_tilted).
held(a27, destination_still_approach, 6, 6).
held(a27, destination_still_retreat, 6, 6).
held(a27, destination_still_settle, 6, 6).
held(a27, destination_upright, 6, 6).
held(a27, source_clear, 6, 6).
held(a27, liquid_leaves_source, 0, 6).
held(a27, liquid_enters_destination, 0, 6).
held(a27, liquid_remains_in_destination, 6, 6).
held(a27, no_spill, 6, 6).
explored(a28, pour_half_tilted).
held(a28, destination_still_approach, 8, 8).
held(a28, destination_still_retreat, 8, 8).
held(a28, destination_still_settle, 8, 8).
held(a28, destination_upright, 8, 8).
held(a28, source_clear, 8, 8).
held(a28, liquid_leaves_source, 0, 8).
held(a28, liquid_enters_destination, 0, 8).
held(a28, liquid_remains_in_destination, 8, 8).
held(a28, no_spill, 8, 8).
explored(a29, pour_to_side).
held(a29, destination_still_approach, 15, 15).
held(a29, destination_still_retreat, 15, 15).
held(a29, destination_still_settle, 15, 15).
held(a29, destination_upright, 15, 15).
held(a29, source_clear, 15, 15).
held(a29, liquid_leaves_source, 15, 15).
held(a29, liquid_enters_destination, 4, 15).
held(a29, liquid_remains_in_destination, 15, 15).
held(a29, no_spill, 5, 15).
explored(a30, light_destination).
held(a30, destination_still_approach, 3, 4).
held(a30, destination_still_retreat, 4, 4).
held(a30, destination_still_settle, 4, 4).
held(a30, destination_upright, 4, 4).
held(a30, source_clear, 2, 4).
held(a30, liquid_leaves_source, 4, 4).
held(a30, liquid_enters_destination, 4, 4).
held(a30, liquid_remains_in_destination, 4, 4).
held(a30, no_spill, 4, 4).
explored(a31, end_slightly_tilted).
held(a31, destination_still_approach, 4, 4).
held(a31, destination_still_retreat, 4, 4).
held(a31, destination_still_settle, 4, 4).
held(a31, destination_upright, 4, 4).
held(a31, source_clear, 4, 4).
held(a31, liquid_leaves_source, 4, 4).
held(a31, liquid_enters_destination, 4, 4).
held(a31, liquid_remains_in_destination, 4, 4).
held(a31, no_spill, 4, 4).
explored(a32, dull_liquid).
held(a32, destination_still_approach, 4, 4).
held(a32, destination_still_retreat, 4, 4).
held(a32, destination_still_settle, 4, 4).
held(a32, destination_upright, 4, 4).
held(a32, source_clear, 3, 4).
held(a32, liquid_leaves_source, 4, 4).
held(a32, liquid_enters_destination, 4, 4).
held(a32, liquid_remains_in_destination, 4, 4).
held(a32, no_spill, 4, 4).
explored(a33, retreat_moving_closer).
held(a33, destination_still_approach, 6, 6).
held(a33, destination_still_retreat, 6, 6).
held(a33, destination_still_settle, 6, 6).
held(a33, destination_upright, 6, 6).
held(a33, source_clear, 5, 6).
held(a33, liquid_leaves_source, 6, 6).
held(a33, liquid_enters_destination, 6, 6).
held(a33, liquid_remains_in_destination, 6, 6).
held(a33, no_spill, 6, 6).
explored(a34, start_centred).
held(a34, destination_still_approach, 6, 6).
held(a34, destination_still_retreat, 5, 6).
held(a34, destination_still_settle, 6, 6).
held(a34, destination_upright, 6, 6).
held(a34, source_clear, 5, 6).
held(a34, liquid_leaves_source, 6, 6).
held(a34, liquid_enters_destination, 6, 6).
held(a34, liquid_remains_in_destination, 6, 6).
held(a34, no_spill, 6, 6).
explored(a35, bouncy_source).
held(a35, destination_still_approach, 4, 4).
held(a35, destination_still_retreat, 4, 4).
held(a35, destination_still_settle, 4, 4).
held(a35, destination_upright, 4, 4).
held(a35, source_clear, 4, 4).
held(a35, liquid_leaves_source, 4, 4).
held(a35, liquid_enters_destination, 4, 4).
held(a35, liquid_remains_in_destination, 4, 4).
held(a35, no_spill, 4, 4).
explored(a36, runny_liquid).
held(a36, destination_still_approach, 4, 4).
held(a36, destination_still_retreat, 4, 4).
held(a36, destination_still_settle, 4, 4).
held(a36, destination_upright, 4, 4).
held(a36, source_clear, 4, 4).
held(a36, liquid_leaves_source, 4, 4).
held(a36, liquid_enters_destination, 4, 4).
held(a36, liquid_remains_in_destination, 4, 4).
held(a36, no_spill, 4, 4).
explored(a37, start_near_rim).
held(a37, destination_still_approach, 3, 4).
held(a37, destination_still_retreat, 3, 4).
held(a37, destination_still_settle, 4, 4).
held(a37, destination_upright, 4, 4).
held(a37, source_clear, 3, 4).
held(a37, liquid_leaves_source, 4, 4).
held(a37, liquid_enters_destination, 4, 4).
held(a37, liquid_remains_in_destination, 4, 4).
held(a37, no_spill, 4, 4).
explored(a38, bouncy_source).
explored(a38, pour_tilted_back).
held(a38, destination_still_approach, 2, 2).
held(a38, destination_still_retreat, 2, 2).
held(a38, destination_still_settle, 2, 2).
held(a38, destination_upright, 2, 2).
held(a38, source_clear, 2, 2).
held(a38, liquid_leaves_source, 0, 2).
held(a38, liquid_enters_destination, 0, 2).
held(a38, liquid_remains_in_destination, 2, 2).
held(a38, no_spill, 2, 2).
explored(a39, pour_far_away).
held(a39, destination_still_approach, 10, 10).
held(a39, destination_still_retreat, 10, 10).
held(a39, destination_still_settle, 10, 10).
held(a39, destination_upright, 10, 10).
held(a39, source_clear, 10, 10).
held(a39, liquid_leaves_source, 10, 10).
held(a39, liquid_enters_destination, 0, 10).
held(a39, liquid_remains_in_destination, 10, 10).
held(a39, no_spill, 0, 10).
explored(a40, fast_retreat).
held(a40, destination_still_approach, 4, 4).
held(a40, destination_still_retreat, 4, 4).
held(a40, destination_still_settle, 4, 4).
held(a40, destination_upright, 4, 4).
held(a40, source_clear, 4, 4).
held(a40, liquid_leaves_source, 4, 4).
held(a40, liquid_enters_destination, 4, 4).
held(a40, liquid_remains_in_destination, 4, 4).
held(a40, no_spill, 4, 4).
explored(a41, end_rolled).
held(a41, destination_still_approach, 4, 4).
held(a41, destination_still_retreat, 4, 4).
held(a41, destination_still_settle, 4, 4).
held(a41, destination_upright, 4, 4).
held(a41, source_clear, 4, 4).
held(a41, liquid_leaves_source, 4, 4).
held(a41, liquid_enters_destination, 4, 4).
held(a41, liquid_remains_in_destination, 4, 4).
held(a41, no_spill, 4, 4).
explored(a42, dull_destination).
held(a42, destination_still_approach, 4, 4).
held(a42, destination_still_retreat, 4, 4).
held(a42, destination_still_settle, 4, 4).
held(a42, destination_upright, 4, 4).
held(a42, source_clear, 4, 4).
held(a42, liquid_leaves_source, 4, 4).
held(a42, liquid_enters_destination, 4, 4).
held(a42, liquid_remains_in_destination, 4, 4).
held(a42, no_spill, 4, 4).
explored(a43, end_half_tilted).
held(a43, destination_still_approach, 4, 4).
held(a43, destination_still_retreat, 4, 4).
held(a43, destination_still_settle, 4, 4).
held(a43, destination_upright, 4, 4).
held(a43, source_clear, 4, 4).
held(a43, liquid_leaves_source, 4, 4).
held(a43, liquid_enters_destination, 4, 4).
held(a43, liquid_remains_in_destination, 4, 4).
held(a43, no_spill, 4, 4).
explored(a44, heavy_destination).
held(a44, destination_still_approach, 4, 4).
held(a44, destination_still_retreat, 4, 4).
held(a44, destination_still_settle, 4, 4).
held(a44, destination_upright, 4, 4).
held(a44, source_clear, 4, 4).
held(a44, liquid_leaves_source, 4, 4).
held(a44, liquid_enters_destination, 4, 4).
held(a44, liquid_remains_in_destination, 4, 4).
held(a44, no_spill, 4, 4).
explored(a45, end_centred).
held(a45, destination_still_approach, 4, 4).
held(a45, destination_still_retreat, 4, 4).
held(a45, destination_still_settle, 4, 4).
held(a45, destination_upright, 4, 4).
held(a45, source_clear, 3, 4).
held(a45, liquid_leaves_source, 4, 4).
held(a45, liquid_enters_destination, 4, 4).
held(a45, liquid_remains_in_destination, 4, 4).
held(a45, no_spill, 4, 4).
explored(a46, heavy_source).
held(a46, destination_still_approach, 4, 4).
held(a46, destination_still_retreat, 4, 4).
held(a46, destination_still_settle, 4, 4).
held(a46, destination_upright, 4, 4).
held(a46, source_clear, 4, 4).
held(a46, liquid_leaves_source, 4, 4).
held(a46, liquid_enters_destination, 4, 4).
held(a46, liquid_remains_in_destination, 4, 4).
held(a46, no_spill, 4, 4).
explored(a47, grippy_destination).
held(a47, destination_still_approach, 4, 4).
held(a47, destination_still_retreat, 4, 4).
held(a47, destination_still_settle, 4, 4).
held(a47, destination_upright, 4, 4).
held(a47, source_clear, 4, 4).
held(a47, liquid_leaves_source, 4, 4).
held(a47, liquid_enters_destination, 4, 4).
held(a47, liquid_remains_in_destination, 4, 4).
held(a47, no_spill, 4, 4).
explored(a48, pour_rolled).
held(a48, destination_still_approach, 4, 4).
held(a48, destination_still_retreat, 4, 4).
held(a48, destination_still_settle, 4, 4).
held(a48, destination_upright, 4, 4).
held(a48, source_clear, 4, 4).
held(a48, liquid_leaves_source, 4, 4).
held(a48, liquid_enters_destination, 4, 4).
held(a48, liquid_remains_in_destination, 4, 4).
held(a48, no_spill, 4, 4).
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
explored(a50, fast_approach).
held(a50, destination_still_approach, 6, 6).
held(a50, destination_still_retreat, 6, 6).
held(a50, destination_still_settle, 6, 6).
held(a50, destination_upright, 6, 6).
held(a50, source_clear, 6, 6).
held(a50, liquid_leaves_source, 6, 6).
held(a50, liquid_enters_destination, 5, 6).
held(a50, liquid_remains_in_destination, 6, 6).
held(a50, no_spill, 5, 6).
explored(a51, start_slightly_tilted).
held(a51, destination_still_approach, 4, 4).
held(a51, destination_still_retreat, 4, 4).
held(a51, destination_still_settle, 4, 4).
held(a51, destination_upright, 4, 4).
held(a51, source_clear, 4, 4).
held(a51, liquid_leaves_source, 4, 4).
held(a51, liquid_enters_destination, 4, 4).
held(a51, liquid_remains_in_destination, 4, 4).
held(a51, no_spill, 4, 4).
explored(a52, pour_offset_sideways).
held(a52, destination_still_approach, 11, 13).
held(a52, destination_still_retreat, 11, 13).
held(a52, destination_still_settle, 13, 13).
held(a52, destination_upright, 13, 13).
held(a52, source_clear, 9, 13).
held(a52, liquid_leaves_source, 13, 13).
held(a52, liquid_enters_destination, 3, 13).
held(a52, liquid_remains_in_destination, 13, 13).
held(a52, no_spill, 3, 13).
explored(a53, slippery_destination).
held(a53, destination_still_approach, 5, 6).
held(a53, destination_still_retreat, 6, 6).
held(a53, destination_still_settle, 6, 6).
held(a53, destination_upright, 6, 6).
held(a53, source_clear, 6, 6).
held(a53, liquid_leaves_source, 6, 6).
held(a53, liquid_enters_destination, 6, 6).
held(a53, liquid_remains_in_destination, 6, 6).
held(a53, no_spill, 6, 6).
explored(a54, slippery_source).
held(a54, destination_still_approach, 4, 4).
held(a54, destination_still_retreat, 4, 4).
held(a54, destination_still_settle, 4, 4).
held(a54, destination_upright, 4, 4).
held(a54, source_clear, 4, 4).
held(a54, liquid_leaves_source, 4, 4).
held(a54, liquid_enters_destination, 4, 4).
held(a54, liquid_remains_in_destination, 4, 4).
held(a54, no_spill, 4, 4).
explored(a55, approach_moving_away).
held(a55, destination_still_approach, 5, 6).
held(a55, destination_still_retreat, 4, 6).
held(a55, destination_still_settle, 6, 6).
held(a55, destination_upright, 6, 6).
held(a55, source_clear, 4, 6).
held(a55, liquid_leaves_source, 6, 6).
held(a55, liquid_enters_destination, 6, 6).
held(a55, liquid_remains_in_destination, 6, 6).
held(a55, no_spill, 6, 6).
explored(a56, pour_low).
held(a56, destination_still_approach, 11, 19).
held(a56, destination_still_retreat, 13, 19).
held(a56, destination_still_settle, 19, 19).
held(a56, destination_upright, 19, 19).
held(a56, source_clear, 7, 19).
held(a56, liquid_leaves_source, 19, 19).
held(a56, liquid_enters_destination, 15, 19).
held(a56, liquid_remains_in_destination, 19, 19).
held(a56, no_spill, 15, 19).
explored(a57, pour_low).
explored(a57, pour_offset_sideways).
held(a57, destination_still_approach, 5, 11).
held(a57, destination_still_retreat, 6, 11).
held(a57, destination_still_settle, 11, 11).
held(a57, destination_upright, 11, 11).
held(a57, source_clear, 2, 11).
held(a57, liquid_leaves_source, 11, 11).
held(a57, liquid_enters_destination, 4, 11).
held(a57, liquid_remains_in_destination, 11, 11).
held(a57, no_spill, 4, 11).
explored(a58, end_far_away).
held(a58, destination_still_approach, 9, 9).
held(a58, destination_still_retreat, 9, 9).
held(a58, destination_still_settle, 9, 9).
held(a58, destination_upright, 9, 9).
held(a58, source_clear, 9, 9).
held(a58, liquid_leaves_source, 9, 9).
held(a58, liquid_enters_destination, 9, 9).
held(a58, liquid_remains_in_destination, 9, 9).
held(a58, no_spill, 9, 9).
explored(a59, pour_below_rim).
explored(a59, pour_offset_sideways).
held(a59, destination_still_approach, 1, 4).
held(a59, destination_still_retreat, 2, 4).
held(a59, destination_still_settle, 4, 4).
held(a59, destination_upright, 3, 4).
held(a59, source_clear, 0, 4).
held(a59, liquid_leaves_source, 4, 4).
held(a59, liquid_enters_destination, 2, 4).
held(a59, liquid_remains_in_destination, 3, 4).
held(a59, no_spill, 1, 4).
explored(a60, pour_below_rim).
explored(a60, pour_upright).
held(a60, destination_still_approach, 7, 10).
held(a60, destination_still_retreat, 4, 10).
held(a60, destination_still_settle, 8, 10).
held(a60, destination_upright, 10, 10).
held(a60, source_clear, 1, 10).
held(a60, liquid_leaves_source, 0, 10).
held(a60, liquid_enters_destination, 9, 10).
held(a60, liquid_remains_in_destination, 1, 10).
held(a60, no_spill, 10, 10).
explored(a61, pour_below_rim).
explored(a61, pour_slightly_tilted).
held(a61, destination_still_approach, 11, 16).
held(a61, destination_still_retreat, 10, 16).
held(a61, destination_still_settle, 15, 16).
held(a61, destination_upright, 15, 16).
held(a61, source_clear, 4, 16).
held(a61, liquid_leaves_source, 1, 16).
held(a61, liquid_enters_destination, 13, 16).
held(a61, liquid_remains_in_destination, 1, 16).
held(a61, no_spill, 16, 16).
explored(a62, pour_below_rim).
explored(a62, pour_half_tilted).
held(a62, destination_still_approach, 7, 14).
held(a62, destination_still_retreat, 8, 14).
held(a62, destination_still_settle, 13, 14).
held(a62, destination_upright, 13, 14).
held(a62, source_clear, 2, 14).
held(a62, liquid_leaves_source, 4, 14).
held(a62, liquid_enters_destination, 11, 14).
held(a62, liquid_remains_in_destination, 5, 14).
held(a62, no_spill, 12, 14).
explored(a63, pour_below_rim).
explored(a63, pour_tilted_back).
held(a63, destination_still_approach, 12, 24).
held(a63, destination_still_retreat, 11, 24).
held(a63, destination_still_settle, 20, 24).
held(a63, destination_upright, 23, 24).
held(a63, source_clear, 0, 24).
held(a63, liquid_leaves_source, 1, 24).
held(a63, liquid_enters_destination, 12, 24).
held(a63, liquid_remains_in_destination, 12, 24).
held(a63, no_spill, 24, 24).
explored(a64, pour_below_rim).
explored(a64, pour_far_away).
held(a64, destination_still_approach, 6, 6).
held(a64, destination_still_retreat, 6, 6).
held(a64, destination_still_settle, 6, 6).
held(a64, destination_upright, 6, 6).
held(a64, source_clear, 6, 6).
held(a64, liquid_leaves_source, 6, 6).
held(a64, liquid_enters_destination, 0, 6).
held(a64, liquid_remains_in_destination, 6, 6).
held(a64, no_spill, 0, 6).
explored(a65, pour_below_rim).
explored(a65, slippery_destination).
held(a65, destination_still_approach, 0, 4).
held(a65, destination_still_retreat, 0, 4).
held(a65, destination_still_settle, 2, 4).
held(a65, destination_upright, 4, 4).
held(a65, source_clear, 0, 4).
held(a65, liquid_leaves_source, 4, 4).
held(a65, liquid_enters_destination, 2, 4).
held(a65, liquid_remains_in_destination, 3, 4).
held(a65, no_spill, 1, 4).
explored(a66, pour_low).
explored(a66, pour_slightly_tilted).
held(a66, destination_still_approach, 3, 4).
held(a66, destination_still_retreat, 3, 4).
held(a66, destination_still_settle, 4, 4).
held(a66, destination_upright, 4, 4).
held(a66, source_clear, 3, 4).
held(a66, liquid_leaves_source, 0, 4).
held(a66, liquid_enters_destination, 0, 4).
held(a66, liquid_remains_in_destination, 3, 4).
held(a66, no_spill, 4, 4).
explored(a67, pour_far_away).
explored(a67, pour_offset_sideways).
held(a67, destination_still_approach, 2, 2).
held(a67, destination_still_retreat, 2, 2).
held(a67, destination_still_settle, 2, 2).
held(a67, destination_upright, 2, 2).
held(a67, source_clear, 2, 2).
held(a67, liquid_leaves_source, 2, 2).
held(a67, liquid_enters_destination, 0, 2).
held(a67, liquid_remains_in_destination, 2, 2).
held(a67, no_spill, 0, 2).
explored(a68, pour_below_rim).
explored(a68, pour_rolled).
held(a68, destination_still_approach, 1, 2).
held(a68, destination_still_retreat, 1, 2).
held(a68, destination_still_settle, 2, 2).
held(a68, destination_upright, 2, 2).
held(a68, source_clear, 0, 2).
held(a68, liquid_leaves_source, 2, 2).
held(a68, liquid_enters_destination, 1, 2).
held(a68, liquid_remains_in_destination, 2, 2).
held(a68, no_spill, 1, 2).
explored(a69, pour_below_rim).
explored(a69, retreat_lowering).
held(a69, destination_still_approach, 1, 6).
held(a69, destination_still_retreat, 0, 6).
held(a69, destination_still_settle, 4, 6).
held(a69, destination_upright, 1, 6).
held(a69, source_clear, 0, 6).
held(a69, liquid_leaves_source, 6, 6).
held(a69, liquid_enters_destination, 5, 6).
held(a69, liquid_remains_in_destination, 3, 6).
held(a69, no_spill, 2, 6).
explored(a70, pour_low).
explored(a70, pour_upright).
held(a70, destination_still_approach, 3, 3).
held(a70, destination_still_retreat, 3, 3).
held(a70, destination_still_settle, 3, 3).
held(a70, destination_upright, 3, 3).
held(a70, source_clear, 3, 3).
held(a70, liquid_leaves_source, 0, 3).
held(a70, liquid_enters_destination, 0, 3).
held(a70, liquid_remains_in_destination, 3, 3).
held(a70, no_spill, 3, 3).
explored(a71, end_tilted_back).
explored(a71, pour_half_tilted).
held(a71, destination_still_approach, 2, 2).
held(a71, destination_still_retreat, 2, 2).
held(a71, destination_still_settle, 2, 2).
held(a71, destination_upright, 2, 2).
held(a71, source_clear, 2, 2).
held(a71, liquid_leaves_source, 0, 2).
held(a71, liquid_enters_destination, 0, 2).
held(a71, liquid_remains_in_destination, 2, 2).
held(a71, no_spill, 2, 2).
explored(a72, dull_liquid).
explored(a72, pour_slightly_tilted).
held(a72, destination_still_approach, 2, 2).
held(a72, destination_still_retreat, 2, 2).
held(a72, destination_still_settle, 2, 2).
held(a72, destination_upright, 2, 2).
held(a72, source_clear, 2, 2).
held(a72, liquid_leaves_source, 0, 2).
held(a72, liquid_enters_destination, 0, 2).
held(a72, liquid_remains_in_destination, 2, 2).
held(a72, no_spill, 2, 2).
explored(a73, pour_below_rim).
explored(a73, retreat_moving_closer).
held(a73, destination_still_approach, 0, 7).
held(a73, destination_still_retreat, 4, 7).
held(a73, destination_still_settle, 7, 7).
held(a73, destination_upright, 6, 7).
held(a73, source_clear, 0, 7).
held(a73, liquid_leaves_source, 7, 7).
held(a73, liquid_enters_destination, 4, 7).
held(a73, liquid_remains_in_destination, 5, 7).
held(a73, no_spill, 2, 7).
explored(a74, bouncy_liquid).
explored(a74, pour_to_side).
held(a74, destination_still_approach, 2, 2).
held(a74, destination_still_retreat, 2, 2).
held(a74, destination_still_settle, 2, 2).
held(a74, destination_upright, 2, 2).
held(a74, source_clear, 2, 2).
held(a74, liquid_leaves_source, 2, 2).
held(a74, liquid_enters_destination, 1, 2).
held(a74, liquid_remains_in_destination, 2, 2).
held(a74, no_spill, 1, 2).
explored(a75, pour_offset_sideways).
explored(a75, pour_to_side).
held(a75, destination_still_approach, 2, 2).
held(a75, destination_still_retreat, 2, 2).
held(a75, destination_still_settle, 2, 2).
held(a75, destination_upright, 2, 2).
held(a75, source_clear, 2, 2).
held(a75, liquid_leaves_source, 2, 2).
held(a75, liquid_enters_destination, 0, 2).
held(a75, liquid_remains_in_destination, 2, 2).
held(a75, no_spill, 0, 2).
explored(a76, little_liquid).
explored(a76, pour_below_rim).
held(a76, destination_still_approach, 1, 6).
held(a76, destination_still_retreat, 0, 6).
held(a76, destination_still_settle, 6, 6).
held(a76, destination_upright, 5, 6).
held(a76, source_clear, 0, 6).
held(a76, liquid_leaves_source, 6, 6).
held(a76, liquid_enters_destination, 4, 6).
held(a76, liquid_remains_in_destination, 4, 6).
held(a76, no_spill, 3, 6).
explored(a77, pour_half_tilted).
explored(a77, pour_offset_sideways).
held(a77, destination_still_approach, 4, 4).
held(a77, destination_still_retreat, 4, 4).
held(a77, destination_still_settle, 4, 4).
held(a77, destination_upright, 4, 4).
held(a77, source_clear, 4, 4).
held(a77, liquid_leaves_source, 0, 4).
held(a77, liquid_enters_destination, 0, 4).
held(a77, liquid_remains_in_destination, 4, 4).
held(a77, no_spill, 4, 4).
explored(a78, pour_offset_sideways).
explored(a78, pour_slightly_tilted).
held(a78, destination_still_approach, 2, 2).
held(a78, destination_still_retreat, 2, 2).
held(a78, destination_still_settle, 2, 2).
held(a78, destination_upright, 2, 2).
held(a78, source_clear, 2, 2).
held(a78, liquid_leaves_source, 0, 2).
held(a78, liquid_enters_destination, 0, 2).
held(a78, liquid_remains_in_destination, 2, 2).
held(a78, no_spill, 2, 2).
explored(a79, approach_moving_away).
explored(a79, pour_below_rim).
held(a79, destination_still_approach, 3, 6).
held(a79, destination_still_retreat, 1, 6).
held(a79, destination_still_settle, 6, 6).
held(a79, destination_upright, 5, 6).
held(a79, source_clear, 0, 6).
held(a79, liquid_leaves_source, 6, 6).
held(a79, liquid_enters_destination, 6, 6).
held(a79, liquid_remains_in_destination, 4, 6).
held(a79, no_spill, 4, 6).
explored(a80, pour_far_away).
explored(a80, pour_half_tilted).
held(a80, destination_still_approach, 4, 4).
held(a80, destination_still_retreat, 4, 4).
held(a80, destination_still_settle, 4, 4).
held(a80, destination_upright, 4, 4).
held(a80, source_clear, 4, 4).
held(a80, liquid_leaves_source, 0, 4).
held(a80, liquid_enters_destination, 0, 4).
held(a80, liquid_remains_in_destination, 4, 4).
held(a80, no_spill, 4, 4).
explored(a81, pour_half_tilted).
explored(a81, pour_to_side).
held(a81, destination_still_approach, 2, 2).
held(a81, destination_still_retreat, 2, 2).
held(a81, destination_still_settle, 2, 2).
held(a81, destination_upright, 2, 2).
held(a81, source_clear, 2, 2).
held(a81, liquid_leaves_source, 0, 2).
held(a81, liquid_enters_destination, 0, 2).
held(a81, liquid_remains_in_destination, 2, 2).
held(a81, no_spill, 2, 2).
explored(a82, pour_slightly_tilted).
explored(a82, pour_to_side).
held(a82, destination_still_approach, 2, 2).
held(a82, destination_still_retreat, 2, 2).
held(a82, destination_still_settle, 2, 2).
held(a82, destination_upright, 2, 2).
held(a82, source_clear, 2, 2).
held(a82, liquid_leaves_source, 0, 2).
held(a82, liquid_enters_destination, 0, 2).
held(a82, liquid_remains_in_destination, 2, 2).
held(a82, no_spill, 2, 2).
explored(a83, dull_liquid).
explored(a83, pour_offset_sideways).
held(a83, destination_still_approach, 2, 2).
held(a83, destination_still_retreat, 2, 2).
held(a83, destination_still_settle, 2, 2).
held(a83, destination_upright, 2, 2).
held(a83, source_clear, 2, 2).
held(a83, liquid_leaves_source, 2, 2).
held(a83, liquid_enters_destination, 0, 2).
held(a83, liquid_remains_in_destination, 2, 2).
held(a83, no_spill, 0, 2).
explored(a84, approach_raising).
explored(a84, pour_below_rim).
held(a84, destination_still_approach, 0, 4).
held(a84, destination_still_retreat, 3, 4).
held(a84, destination_still_settle, 4, 4).
held(a84, destination_upright, 4, 4).
held(a84, source_clear, 0, 4).
held(a84, liquid_leaves_source, 4, 4).
held(a84, liquid_enters_destination, 0, 4).
held(a84, liquid_remains_in_destination, 4, 4).
held(a84, no_spill, 0, 4).
explored(a85, bouncy_source).
explored(a85, pour_far_away).
held(a85, destination_still_approach, 4, 4).
held(a85, destination_still_retreat, 4, 4).
held(a85, destination_still_settle, 4, 4).
held(a85, destination_upright, 4, 4).
held(a85, source_clear, 4, 4).
held(a85, liquid_leaves_source, 4, 4).
held(a85, liquid_enters_destination, 0, 4).
held(a85, liquid_remains_in_destination, 4, 4).
held(a85, no_spill, 0, 4).
explored(a86, heavy_liquid).
explored(a86, pour_below_rim).
held(a86, destination_still_approach, 0, 4).
held(a86, destination_still_retreat, 1, 4).
held(a86, destination_still_settle, 4, 4).
held(a86, destination_upright, 3, 4).
held(a86, source_clear, 0, 4).
held(a86, liquid_leaves_source, 3, 4).
held(a86, liquid_enters_destination, 3, 4).
held(a86, liquid_remains_in_destination, 2, 4).
held(a86, no_spill, 2, 4).
explored(a87, pour_far_away).
explored(a87, slippery_source).
held(a87, destination_still_approach, 2, 2).
held(a87, destination_still_retreat, 2, 2).
held(a87, destination_still_settle, 2, 2).
held(a87, destination_upright, 2, 2).
held(a87, source_clear, 2, 2).
held(a87, liquid_leaves_source, 2, 2).
held(a87, liquid_enters_destination, 0, 2).
held(a87, liquid_remains_in_destination, 2, 2).
held(a87, no_spill, 0, 2).
explored(a88, pour_half_tilted).
explored(a88, pour_low).
held(a88, destination_still_approach, 5, 5).
held(a88, destination_still_retreat, 5, 5).
held(a88, destination_still_settle, 5, 5).
held(a88, destination_upright, 5, 5).
held(a88, source_clear, 4, 5).
held(a88, liquid_leaves_source, 0, 5).
held(a88, liquid_enters_destination, 1, 5).
held(a88, liquid_remains_in_destination, 4, 5).
held(a88, no_spill, 5, 5).
explored(a89, pour_centred).
held(a89, destination_still_approach, 7, 7).
held(a89, destination_still_retreat, 7, 7).
held(a89, destination_still_settle, 7, 7).
held(a89, destination_upright, 7, 7).
held(a89, source_clear, 7, 7).
held(a89, liquid_leaves_source, 7, 7).
held(a89, liquid_enters_destination, 7, 7).
held(a89, liquid_remains_in_destination, 7, 7).
held(a89, no_spill, 7, 7).
explored(a90, approach_moving_closer).
explored(a90, pour_far_away).
held(a90, destination_still_approach, 2, 2).
held(a90, destination_still_retreat, 2, 2).
held(a90, destination_still_settle, 2, 2).
held(a90, destination_upright, 2, 2).
held(a90, source_clear, 2, 2).
held(a90, liquid_leaves_source, 2, 2).
held(a90, liquid_enters_destination, 0, 2).
held(a90, liquid_remains_in_destination, 2, 2).
held(a90, no_spill, 0, 2).
explored(a91, pour_far_away).
explored(a91, retreat_moving_away).
held(a91, destination_still_approach, 2, 2).
held(a91, destination_still_retreat, 2, 2).
held(a91, destination_still_settle, 2, 2).
held(a91, destination_upright, 2, 2).
held(a91, source_clear, 2, 2).
held(a91, liquid_leaves_source, 2, 2).
held(a91, liquid_enters_destination, 0, 2).
held(a91, liquid_remains_in_destination, 2, 2).
held(a91, no_spill, 0, 2).
explored(a92, grippy_destination).
explored(a92, pour_below_rim).
held(a92, destination_still_approach, 0, 2).
held(a92, destination_still_retreat, 1, 2).
held(a92, destination_still_settle, 2, 2).
held(a92, destination_upright, 2, 2).
held(a92, source_clear, 0, 2).
held(a92, liquid_leaves_source, 2, 2).
held(a92, liquid_enters_destination, 1, 2).
held(a92, liquid_remains_in_destination, 2, 2).
held(a92, no_spill, 1, 2).
explored(a93, bouncy_source).
explored(a93, pour_slightly_tilted).
held(a93, destination_still_approach, 2, 2).
held(a93, destination_still_retreat, 2, 2).
held(a93, destination_still_settle, 2, 2).
held(a93, destination_upright, 2, 2).
held(a93, source_clear, 2, 2).
held(a93, liquid_leaves_source, 0, 2).
held(a93, liquid_enters_destination, 0, 2).
held(a93, liquid_remains_in_destination, 2, 2).
held(a93, no_spill, 2, 2).
explored(a94, approach_raising).
explored(a94, pour_to_side).
held(a94, destination_still_approach, 2, 2).
held(a94, destination_still_retreat, 2, 2).
held(a94, destination_still_settle, 2, 2).
held(a94, destination_upright, 2, 2).
held(a94, source_clear, 2, 2).
held(a94, liquid_leaves_source, 2, 2).
held(a94, liquid_enters_destination, 0, 2).
held(a94, liquid_remains_in_destination, 2, 2).
held(a94, no_spill, 0, 2).
explored(a95, pour_low).
explored(a95, pour_to_side).
held(a95, destination_still_approach, 4, 4).
held(a95, destination_still_retreat, 4, 4).
held(a95, destination_still_settle, 4, 4).
held(a95, destination_upright, 4, 4).
held(a95, source_clear, 3, 4).
held(a95, liquid_leaves_source, 4, 4).
held(a95, liquid_enters_destination, 0, 4).
held(a95, liquid_remains_in_destination, 4, 4).
held(a95, no_spill, 0, 4).
explored(a96, pour_below_rim).
explored(a96, start_near_rim).
held(a96, destination_still_approach, 0, 2).
held(a96, destination_still_retreat, 0, 2).
held(a96, destination_still_settle, 2, 2).
held(a96, destination_upright, 2, 2).
held(a96, source_clear, 0, 2).
held(a96, liquid_leaves_source, 2, 2).
held(a96, liquid_enters_destination, 2, 2).
held(a96, liquid_remains_in_destination, 0, 2).
held(a96, no_spill, 0, 2).
explored(a97, heavy_destination).
explored(a97, pour_below_rim).
held(a97, destination_still_approach, 0, 2).
held(a97, destination_still_retreat, 1, 2).
held(a97, destination_still_settle, 2, 2).
held(a97, destination_upright, 2, 2).
held(a97, source_clear, 0, 2).
held(a97, liquid_leaves_source, 2, 2).
held(a97, liquid_enters_destination, 2, 2).
held(a97, liquid_remains_in_destination, 2, 2).
held(a97, no_spill, 2, 2).
explored(a98, end_near_rim).
explored(a98, pour_to_side).
held(a98, destination_still_approach, 2, 2).
held(a98, destination_still_retreat, 2, 2).
held(a98, destination_still_settle, 2, 2).
held(a98, destination_upright, 2, 2).
held(a98, source_clear, 2, 2).
held(a98, liquid_leaves_source, 2, 2).
held(a98, liquid_enters_destination, 2, 2).
held(a98, liquid_remains_in_destination, 2, 2).
held(a98, no_spill, 2, 2).
explored(a99, bouncy_destination).
explored(a99, pour_below_rim).
held(a99, destination_still_approach, 0, 4).
held(a99, destination_still_retreat, 0, 4).
held(a99, destination_still_settle, 3, 4).
held(a99, destination_upright, 4, 4).
held(a99, source_clear, 0, 4).
held(a99, liquid_leaves_source, 4, 4).
held(a99, liquid_enters_destination, 4, 4).
held(a99, liquid_remains_in_destination, 0, 4).
held(a99, no_spill, 0, 4).
explored(a100, pour_rolled).
explored(a100, pour_to_side).
held(a100, destination_still_approach, 2, 2).
held(a100, destination_still_retreat, 2, 2).
held(a100, destination_still_settle, 2, 2).
held(a100, destination_upright, 2, 2).
held(a100, source_clear, 2, 2).
held(a100, liquid_leaves_source, 2, 2).
held(a100, liquid_enters_destination, 0, 2).
held(a100, liquid_remains_in_destination, 2, 2).
held(a100, no_spill, 0, 2).
explored(a101, pour_to_side).
explored(a101, pour_very_high).
held(a101, destination_still_approach, 2, 2).
held(a101, destination_still_retreat, 2, 2).
held(a101, destination_still_settle, 2, 2).
held(a101, destination_upright, 2, 2).
held(a101, source_clear, 2, 2).
held(a101, liquid_leaves_source, 2, 2).
held(a101, liquid_enters_destination, 2, 2).
held(a101, liquid_remains_in_destination, 2, 2).
held(a101, no_spill, 2, 2).
explored(a102, approach_moving_away).
explored(a102, pour_to_side).
held(a102, destination_still_approach, 2, 2).
held(a102, destination_still_retreat, 2, 2).
held(a102, destination_still_settle, 2, 2).
held(a102, destination_upright, 2, 2).
held(a102, source_clear, 2, 2).
held(a102, liquid_leaves_source, 2, 2).
held(a102, liquid_enters_destination, 1, 2).
held(a102, liquid_remains_in_destination, 2, 2).
held(a102, no_spill, 1, 2).
explored(a103, pour_to_side).
explored(a103, retreat_lowering).
held(a103, destination_still_approach, 2, 2).
held(a103, destination_still_retreat, 2, 2).
held(a103, destination_still_settle, 2, 2).
held(a103, destination_upright, 2, 2).
held(a103, source_clear, 2, 2).
held(a103, liquid_leaves_source, 2, 2).
held(a103, liquid_enters_destination, 0, 2).
held(a103, liquid_remains_in_destination, 2, 2).
held(a103, no_spill, 0, 2).
explored(a104, dull_source).
explored(a104, pour_below_rim).
held(a104, destination_still_approach, 0, 2).
held(a104, destination_still_retreat, 0, 2).
held(a104, destination_still_settle, 1, 2).
held(a104, destination_upright, 1, 2).
held(a104, source_clear, 0, 2).
held(a104, liquid_leaves_source, 2, 2).
held(a104, liquid_enters_destination, 2, 2).
held(a104, liquid_remains_in_destination, 1, 2).
held(a104, no_spill, 1, 2).
explored(a105, pour_below_rim).
explored(a105, start_low).
held(a105, destination_still_approach, 0, 4).
held(a105, destination_still_retreat, 4, 4).
held(a105, destination_still_settle, 4, 4).
held(a105, destination_upright, 4, 4).
held(a105, source_clear, 0, 4).
held(a105, liquid_leaves_source, 4, 4).
held(a105, liquid_enters_destination, 0, 4).
held(a105, liquid_remains_in_destination, 4, 4).
held(a105, no_spill, 0, 4).
explored(a106, pour_rolled).
explored(a106, pour_upright).
held(a106, destination_still_approach, 2, 2).
held(a106, destination_still_retreat, 2, 2).
held(a106, destination_still_settle, 2, 2).
held(a106, destination_upright, 2, 2).
held(a106, source_clear, 2, 2).
held(a106, liquid_leaves_source, 0, 2).
held(a106, liquid_enters_destination, 0, 2).
held(a106, liquid_remains_in_destination, 2, 2).
held(a106, no_spill, 2, 2).
explored(a107, approach_moving_away).
explored(a107, pour_half_tilted).
held(a107, destination_still_approach, 2, 2).
held(a107, destination_still_retreat, 2, 2).
held(a107, destination_still_settle, 2, 2).
held(a107, destination_upright, 2, 2).
held(a107, source_clear, 2, 2).
held(a107, liquid_leaves_source, 0, 2).
held(a107, liquid_enters_destination, 0, 2).
held(a107, liquid_remains_in_destination, 2, 2).
held(a107, no_spill, 2, 2).
explored(a108, approach_raising).
explored(a108, pour_offset_sideways).
held(a108, destination_still_approach, 6, 8).
held(a108, destination_still_retreat, 8, 8).
held(a108, destination_still_settle, 8, 8).
held(a108, destination_upright, 8, 8).
held(a108, source_clear, 5, 8).
held(a108, liquid_leaves_source, 8, 8).
held(a108, liquid_enters_destination, 3, 8).
held(a108, liquid_remains_in_destination, 8, 8).
held(a108, no_spill, 3, 8).
explored(a109, pour_high).
explored(a109, pour_offset_sideways).
held(a109, destination_still_approach, 4, 4).
held(a109, destination_still_retreat, 4, 4).
held(a109, destination_still_settle, 4, 4).
held(a109, destination_upright, 4, 4).
held(a109, source_clear, 4, 4).
held(a109, liquid_leaves_source, 4, 4).
held(a109, liquid_enters_destination, 2, 4).
held(a109, liquid_remains_in_destination, 4, 4).
held(a109, no_spill, 1, 4).
explored(a110, pour_offset_sideways).
explored(a110, pour_very_high).
held(a110, destination_still_approach, 4, 4).
held(a110, destination_still_retreat, 4, 4).
held(a110, destination_still_settle, 4, 4).
held(a110, destination_upright, 4, 4).
held(a110, source_clear, 4, 4).
held(a110, liquid_leaves_source, 4, 4).
held(a110, liquid_enters_destination, 1, 4).
held(a110, liquid_remains_in_destination, 4, 4).
held(a110, no_spill, 1, 4).
explored(a111, approach_raising).
held(a111, destination_still_approach, 14, 20).
held(a111, destination_still_retreat, 20, 20).
held(a111, destination_still_settle, 20, 20).
held(a111, destination_upright, 20, 20).
held(a111, source_clear, 9, 20).
held(a111, liquid_leaves_source, 20, 20).
held(a111, liquid_enters_destination, 18, 20).
held(a111, liquid_remains_in_destination, 20, 20).
held(a111, no_spill, 18, 20).
explored(a112, pour_offset_sideways).
explored(a112, retreat_lowering).
held(a112, destination_still_approach, 6, 6).
held(a112, destination_still_retreat, 6, 6).
held(a112, destination_still_settle, 6, 6).
held(a112, destination_upright, 6, 6).
held(a112, source_clear, 5, 6).
held(a112, liquid_leaves_source, 6, 6).
held(a112, liquid_enters_destination, 5, 6).
held(a112, liquid_remains_in_destination, 6, 6).
held(a112, no_spill, 5, 6).
explored(a113, approach_moving_away).
explored(a113, pour_offset_sideways).
held(a113, destination_still_approach, 4, 4).
held(a113, destination_still_retreat, 4, 4).
held(a113, destination_still_settle, 4, 4).
held(a113, destination_upright, 4, 4).
held(a113, source_clear, 4, 4).
held(a113, liquid_leaves_source, 4, 4).
held(a113, liquid_enters_destination, 2, 4).
held(a113, liquid_remains_in_destination, 4, 4).
held(a113, no_spill, 2, 4).
explored(a114, pour_below_rim).
explored(a114, runny_liquid).
held(a114, destination_still_approach, 0, 2).
held(a114, destination_still_retreat, 0, 2).
held(a114, destination_still_settle, 1, 2).
held(a114, destination_upright, 2, 2).
held(a114, source_clear, 0, 2).
held(a114, liquid_leaves_source, 2, 2).
held(a114, liquid_enters_destination, 2, 2).
held(a114, liquid_remains_in_destination, 1, 2).
held(a114, no_spill, 1, 2).
explored(a115, pour_below_rim).
explored(a115, start_tilted_back).
held(a115, destination_still_approach, 0, 6).
held(a115, destination_still_retreat, 1, 6).
held(a115, destination_still_settle, 4, 6).
held(a115, destination_upright, 3, 6).
held(a115, source_clear, 0, 6).
held(a115, liquid_leaves_source, 6, 6).
held(a115, liquid_enters_destination, 4, 6).
held(a115, liquid_remains_in_destination, 4, 6).
held(a115, no_spill, 2, 6).
explored(a116, dull_destination).
explored(a116, pour_steeply_tilted).
held(a116, destination_still_approach, 4, 4).
held(a116, destination_still_retreat, 4, 4).
held(a116, destination_still_settle, 4, 4).
held(a116, destination_upright, 4, 4).
held(a116, source_clear, 4, 4).
held(a116, liquid_leaves_source, 3, 4).
held(a116, liquid_enters_destination, 3, 4).
held(a116, liquid_remains_in_destination, 4, 4).
held(a116, no_spill, 4, 4).
explored(a117, start_below_rim).
explored(a117, start_tilted_back).
held(a117, destination_still_approach, 3, 4).
held(a117, destination_still_retreat, 4, 4).
held(a117, destination_still_settle, 4, 4).
held(a117, destination_upright, 4, 4).
held(a117, source_clear, 2, 4).
held(a117, liquid_leaves_source, 4, 4).
held(a117, liquid_enters_destination, 4, 4).
held(a117, liquid_remains_in_destination, 4, 4).
held(a117, no_spill, 4, 4).
explored(a118, end_slightly_tilted).
explored(a118, pour_below_rim).
held(a118, destination_still_approach, 0, 2).
held(a118, destination_still_retreat, 1, 2).
held(a118, destination_still_settle, 2, 2).
held(a118, destination_upright, 2, 2).
held(a118, source_clear, 0, 2).
held(a118, liquid_leaves_source, 2, 2).
held(a118, liquid_enters_destination, 1, 2).
held(a118, liquid_remains_in_destination, 2, 2).
held(a118, no_spill, 1, 2).
explored(a119, light_source).
explored(a119, pour_below_rim).
held(a119, destination_still_approach, 0, 4).
held(a119, destination_still_retreat, 0, 4).
held(a119, destination_still_settle, 2, 4).
held(a119, destination_upright, 3, 4).
held(a119, source_clear, 0, 4).
held(a119, liquid_leaves_source, 4, 4).
held(a119, liquid_enters_destination, 3, 4).
held(a119, liquid_remains_in_destination, 3, 4).
held(a119, no_spill, 2, 4).
explored(a120, pour_below_rim).
explored(a120, start_centred).
held(a120, destination_still_approach, 3, 5).
held(a120, destination_still_retreat, 2, 5).
held(a120, destination_still_settle, 5, 5).
held(a120, destination_upright, 5, 5).
held(a120, source_clear, 0, 5).
held(a120, liquid_leaves_source, 5, 5).
held(a120, liquid_enters_destination, 5, 5).
held(a120, liquid_remains_in_destination, 4, 5).
held(a120, no_spill, 4, 5).
explored(a121, light_liquid).
explored(a121, pour_below_rim).
held(a121, destination_still_approach, 0, 2).
held(a121, destination_still_retreat, 0, 2).
held(a121, destination_still_settle, 2, 2).
held(a121, destination_upright, 2, 2).
held(a121, source_clear, 0, 2).
held(a121, liquid_leaves_source, 2, 2).
held(a121, liquid_enters_destination, 1, 2).
held(a121, liquid_remains_in_destination, 1, 2).
held(a121, no_spill, 0, 2).
explored(a122, pour_below_rim).
explored(a122, start_slightly_tilted).
held(a122, destination_still_approach, 0, 4).
held(a122, destination_still_retreat, 1, 4).
held(a122, destination_still_settle, 2, 4).
held(a122, destination_upright, 2, 4).
held(a122, source_clear, 0, 4).
held(a122, liquid_leaves_source, 4, 4).
held(a122, liquid_enters_destination, 4, 4).
held(a122, liquid_remains_in_destination, 1, 4).
held(a122, no_spill, 2, 4).
explored(a123, bouncy_liquid).
explored(a123, pour_below_rim).
held(a123, destination_still_approach, 0, 4).
held(a123, destination_still_retreat, 0, 4).
held(a123, destination_still_settle, 1, 4).
held(a123, destination_upright, 2, 4).
held(a123, source_clear, 0, 4).
held(a123, liquid_leaves_source, 4, 4).
held(a123, liquid_enters_destination, 3, 4).
held(a123, liquid_remains_in_destination, 0, 4).
held(a123, no_spill, 0, 4).
explored(a124, pour_very_high).
explored(a124, start_below_rim).
held(a124, destination_still_approach, 4, 4).
held(a124, destination_still_retreat, 4, 4).
held(a124, destination_still_settle, 4, 4).
held(a124, destination_upright, 4, 4).
held(a124, source_clear, 4, 4).
held(a124, liquid_leaves_source, 4, 4).
held(a124, liquid_enters_destination, 3, 4).
held(a124, liquid_remains_in_destination, 4, 4).
held(a124, no_spill, 3, 4).
explored(a125, pour_offset_sideways).
explored(a125, pour_tilted_back).
held(a125, destination_still_approach, 2, 2).
held(a125, destination_still_retreat, 2, 2).
held(a125, destination_still_settle, 2, 2).
held(a125, destination_upright, 2, 2).
held(a125, source_clear, 2, 2).
held(a125, liquid_leaves_source, 0, 2).
held(a125, liquid_enters_destination, 0, 2).
held(a125, liquid_remains_in_destination, 2, 2).
held(a125, no_spill, 2, 2).
explored(a126, pour_steeply_tilted).
held(a126, destination_still_approach, 11, 11).
held(a126, destination_still_retreat, 11, 11).
held(a126, destination_still_settle, 11, 11).
held(a126, destination_upright, 11, 11).
held(a126, source_clear, 11, 11).
held(a126, liquid_leaves_source, 10, 11).
held(a126, liquid_enters_destination, 10, 11).
held(a126, liquid_remains_in_destination, 11, 11).
held(a126, no_spill, 11, 11).
explored(a127, grippy_source).
explored(a127, pour_below_rim).
held(a127, destination_still_approach, 0, 2).
held(a127, destination_still_retreat, 1, 2).
held(a127, destination_still_settle, 2, 2).
held(a127, destination_upright, 2, 2).
held(a127, source_clear, 0, 2).
held(a127, liquid_leaves_source, 2, 2).
held(a127, liquid_enters_destination, 1, 2).
held(a127, liquid_remains_in_destination, 2, 2).
held(a127, no_spill, 1, 2).
explored(a128, end_centred).
explored(a128, pour_below_rim).
held(a128, destination_still_approach, 0, 5).
held(a128, destination_still_retreat, 2, 5).
held(a128, destination_still_settle, 5, 5).
held(a128, destination_upright, 3, 5).
held(a128, source_clear, 0, 5).
held(a128, liquid_leaves_source, 5, 5).
held(a128, liquid_enters_destination, 4, 5).
held(a128, liquid_remains_in_destination, 3, 5).
held(a128, no_spill, 2, 5).
explored(a129, pour_below_rim).
explored(a129, slippery_source).
held(a129, destination_still_approach, 0, 4).
held(a129, destination_still_retreat, 0, 4).
held(a129, destination_still_settle, 3, 4).
held(a129, destination_upright, 3, 4).
held(a129, source_clear, 0, 4).
held(a129, liquid_leaves_source, 4, 4).
held(a129, liquid_enters_destination, 3, 4).
held(a129, liquid_remains_in_destination, 3, 4).
held(a129, no_spill, 3, 4).
explored(a130, fast_retreat).
explored(a130, pour_below_rim).
held(a130, destination_still_approach, 0, 2).
held(a130, destination_still_retreat, 0, 2).
held(a130, destination_still_settle, 2, 2).
held(a130, destination_upright, 2, 2).
held(a130, source_clear, 0, 2).
held(a130, liquid_leaves_source, 2, 2).
held(a130, liquid_enters_destination, 2, 2).
held(a130, liquid_remains_in_destination, 0, 2).
held(a130, no_spill, 0, 2).
explored(a131, pour_below_rim).
explored(a131, start_below_rim).
held(a131, destination_still_approach, 0, 6).
held(a131, destination_still_retreat, 4, 6).
held(a131, destination_still_settle, 6, 6).
held(a131, destination_upright, 6, 6).
held(a131, source_clear, 0, 6).
held(a131, liquid_leaves_source, 6, 6).
held(a131, liquid_enters_destination, 0, 6).
held(a131, liquid_remains_in_destination, 5, 6).
held(a131, no_spill, 0, 6).
explored(a132, pour_very_high).
explored(a132, start_low).
held(a132, destination_still_approach, 2, 2).
held(a132, destination_still_retreat, 2, 2).
held(a132, destination_still_settle, 2, 2).
held(a132, destination_upright, 2, 2).
held(a132, source_clear, 2, 2).
held(a132, liquid_leaves_source, 2, 2).
held(a132, liquid_enters_destination, 2, 2).
held(a132, liquid_remains_in_destination, 2, 2).
held(a132, no_spill, 2, 2).
explored(a133, approach_lowering).
explored(a133, pour_very_high).
held(a133, destination_still_approach, 2, 2).
held(a133, destination_still_retreat, 2, 2).
held(a133, destination_still_settle, 2, 2).
held(a133, destination_upright, 2, 2).
held(a133, source_clear, 2, 2).
held(a133, liquid_leaves_source, 2, 2).
held(a133, liquid_enters_destination, 2, 2).
held(a133, liquid_remains_in_destination, 2, 2).
held(a133, no_spill, 2, 2).
explored(a134, end_low).
explored(a134, end_tilted_back).
held(a134, destination_still_approach, 2, 2).
held(a134, destination_still_retreat, 2, 2).
held(a134, destination_still_settle, 2, 2).
held(a134, destination_upright, 2, 2).
held(a134, source_clear, 2, 2).
held(a134, liquid_leaves_source, 2, 2).
held(a134, liquid_enters_destination, 2, 2).
held(a134, liquid_remains_in_destination, 2, 2).
held(a134, no_spill, 2, 2).
explored(a135, end_below_rim).
explored(a135, end_tilted_back).
held(a135, destination_still_approach, 2, 2).
held(a135, destination_still_retreat, 1, 2).
held(a135, destination_still_settle, 2, 2).
held(a135, destination_upright, 2, 2).
held(a135, source_clear, 1, 2).
held(a135, liquid_leaves_source, 2, 2).
held(a135, liquid_enters_destination, 2, 2).
held(a135, liquid_remains_in_destination, 2, 2).
held(a135, no_spill, 2, 2).
explored(a136, pour_centred).
explored(a136, pour_very_high).
held(a136, destination_still_approach, 7, 7).
held(a136, destination_still_retreat, 7, 7).
held(a136, destination_still_settle, 7, 7).
held(a136, destination_upright, 7, 7).
held(a136, source_clear, 7, 7).
held(a136, liquid_leaves_source, 7, 7).
held(a136, liquid_enters_destination, 0, 7).
held(a136, liquid_remains_in_destination, 7, 7).
held(a136, no_spill, 0, 7).
explored(a137, pour_very_high).
explored(a137, retreat_moving_closer).
held(a137, destination_still_approach, 2, 2).
held(a137, destination_still_retreat, 2, 2).
held(a137, destination_still_settle, 2, 2).
held(a137, destination_upright, 2, 2).
held(a137, source_clear, 2, 2).
held(a137, liquid_leaves_source, 2, 2).
held(a137, liquid_enters_destination, 1, 2).
held(a137, liquid_remains_in_destination, 2, 2).
held(a137, no_spill, 1, 2).
explored(a138, pour_rolled).
explored(a138, pour_very_high).
held(a138, destination_still_approach, 2, 2).
held(a138, destination_still_retreat, 2, 2).
held(a138, destination_still_settle, 2, 2).
held(a138, destination_upright, 2, 2).
held(a138, source_clear, 2, 2).
held(a138, liquid_leaves_source, 2, 2).
held(a138, liquid_enters_destination, 1, 2).
held(a138, liquid_remains_in_destination, 2, 2).
held(a138, no_spill, 1, 2).
explored(a139, fast_approach).
explored(a139, pour_below_rim).
held(a139, destination_still_approach, 1, 4).
held(a139, destination_still_retreat, 2, 4).
held(a139, destination_still_settle, 3, 4).
held(a139, destination_upright, 3, 4).
held(a139, source_clear, 0, 4).
held(a139, liquid_leaves_source, 4, 4).
held(a139, liquid_enters_destination, 2, 4).
held(a139, liquid_remains_in_destination, 3, 4).
held(a139, no_spill, 2, 4).
explored(a140, end_half_tilted).
explored(a140, pour_below_rim).
held(a140, destination_still_approach, 0, 2).
held(a140, destination_still_retreat, 1, 2).
held(a140, destination_still_settle, 1, 2).
held(a140, destination_upright, 2, 2).
held(a140, source_clear, 0, 2).
held(a140, liquid_leaves_source, 2, 2).
held(a140, liquid_enters_destination, 0, 2).
held(a140, liquid_remains_in_destination, 2, 2).
held(a140, no_spill, 0, 2).
explored(a141, pour_below_rim).
explored(a141, slow_approach).
held(a141, destination_still_approach, 0, 2).
held(a141, destination_still_retreat, 0, 2).
held(a141, destination_still_settle, 1, 2).
held(a141, destination_upright, 1, 2).
held(a141, source_clear, 0, 2).
held(a141, liquid_leaves_source, 2, 2).
held(a141, liquid_enters_destination, 2, 2).
held(a141, liquid_remains_in_destination, 0, 2).
held(a141, no_spill, 0, 2).
explored(a142, pour_low).
explored(a142, pour_rolled).
held(a142, destination_still_approach, 0, 2).
held(a142, destination_still_retreat, 0, 2).
held(a142, destination_still_settle, 2, 2).
held(a142, destination_upright, 2, 2).
held(a142, source_clear, 0, 2).
held(a142, liquid_leaves_source, 2, 2).
held(a142, liquid_enters_destination, 2, 2).
held(a142, liquid_remains_in_destination, 2, 2).
held(a142, no_spill, 2, 2).
explored(a143, end_low).
explored(a143, end_upside_down).
held(a143, destination_still_approach, 2, 2).
held(a143, destination_still_retreat, 1, 2).
held(a143, destination_still_settle, 1, 2).
held(a143, destination_upright, 2, 2).
held(a143, source_clear, 0, 2).
held(a143, liquid_leaves_source, 2, 2).
held(a143, liquid_enters_destination, 2, 2).
held(a143, liquid_remains_in_destination, 2, 2).
held(a143, no_spill, 2, 2).
explored(a144, bouncy_source).
explored(a144, pour_below_rim).
held(a144, destination_still_approach, 0, 2).
held(a144, destination_still_retreat, 0, 2).
held(a144, destination_still_settle, 2, 2).
held(a144, destination_upright, 2, 2).
held(a144, source_clear, 0, 2).
held(a144, liquid_leaves_source, 2, 2).
held(a144, liquid_enters_destination, 2, 2).
held(a144, liquid_remains_in_destination, 0, 2).
held(a144, no_spill, 0, 2).
explored(a145, light_destination).
explored(a145, slippery_destination).
held(a145, destination_still_approach, 2, 2).
held(a145, destination_still_retreat, 1, 2).
held(a145, destination_still_settle, 2, 2).
held(a145, destination_upright, 2, 2).
held(a145, source_clear, 2, 2).
held(a145, liquid_leaves_source, 2, 2).
held(a145, liquid_enters_destination, 2, 2).
held(a145, liquid_remains_in_destination, 2, 2).
held(a145, no_spill, 2, 2).
explored(a146, pour_very_high).
explored(a146, retreat_raising).
held(a146, destination_still_approach, 3, 3).
held(a146, destination_still_retreat, 3, 3).
held(a146, destination_still_settle, 3, 3).
held(a146, destination_upright, 3, 3).
held(a146, source_clear, 3, 3).
held(a146, liquid_leaves_source, 3, 3).
held(a146, liquid_enters_destination, 1, 3).
held(a146, liquid_remains_in_destination, 3, 3).
held(a146, no_spill, 1, 3).
explored(a147, bouncy_liquid).
explored(a147, runny_liquid).
held(a147, destination_still_approach, 2, 2).
held(a147, destination_still_retreat, 2, 2).
held(a147, destination_still_settle, 2, 2).
held(a147, destination_upright, 2, 2).
held(a147, source_clear, 1, 2).
held(a147, liquid_leaves_source, 2, 2).
held(a147, liquid_enters_destination, 2, 2).
held(a147, liquid_remains_in_destination, 2, 2).
held(a147, no_spill, 2, 2).
explored(a148, pour_far_away).
explored(a148, pour_high).
held(a148, destination_still_approach, 2, 2).
held(a148, destination_still_retreat, 2, 2).
held(a148, destination_still_settle, 2, 2).
held(a148, destination_upright, 2, 2).
held(a148, source_clear, 2, 2).
held(a148, liquid_leaves_source, 2, 2).
held(a148, liquid_enters_destination, 0, 2).
held(a148, liquid_remains_in_destination, 2, 2).
held(a148, no_spill, 0, 2).
explored(a149, end_very_high).
held(a149, destination_still_approach, 8, 8).
held(a149, destination_still_retreat, 8, 8).
held(a149, destination_still_settle, 8, 8).
held(a149, destination_upright, 8, 8).
held(a149, source_clear, 8, 8).
held(a149, liquid_leaves_source, 8, 8).
held(a149, liquid_enters_destination, 8, 8).
held(a149, liquid_remains_in_destination, 8, 8).
held(a149, no_spill, 8, 8).
explored(a150, approach_raising).
explored(a150, start_centred).
held(a150, destination_still_approach, 2, 2).
held(a150, destination_still_retreat, 2, 2).
held(a150, destination_still_settle, 2, 2).
held(a150, destination_upright, 2, 2).
held(a150, source_clear, 2, 2).
held(a150, liquid_leaves_source, 2, 2).
held(a150, liquid_enters_destination, 2, 2).
held(a150, liquid_remains_in_destination, 2, 2).
held(a150, no_spill, 2, 2).
explored(a151, pour_centred).
explored(a151, pour_upright).
held(a151, destination_still_approach, 2, 2).
held(a151, destination_still_retreat, 2, 2).
held(a151, destination_still_settle, 2, 2).
held(a151, destination_upright, 2, 2).
held(a151, source_clear, 2, 2).
held(a151, liquid_leaves_source, 0, 2).
held(a151, liquid_enters_destination, 0, 2).
held(a151, liquid_remains_in_destination, 2, 2).
held(a151, no_spill, 2, 2).
explored(a152, little_liquid).
explored(a152, runny_liquid).
held(a152, destination_still_approach, 2, 2).
held(a152, destination_still_retreat, 2, 2).
held(a152, destination_still_settle, 2, 2).
held(a152, destination_upright, 2, 2).
held(a152, source_clear, 2, 2).
held(a152, liquid_leaves_source, 2, 2).
held(a152, liquid_enters_destination, 2, 2).
held(a152, liquid_remains_in_destination, 2, 2).
held(a152, no_spill, 2, 2).
explored(a153, end_below_rim).
explored(a153, start_low).
held(a153, destination_still_approach, 1, 2).
held(a153, destination_still_retreat, 2, 2).
held(a153, destination_still_settle, 2, 2).
held(a153, destination_upright, 2, 2).
held(a153, source_clear, 0, 2).
held(a153, liquid_leaves_source, 2, 2).
held(a153, liquid_enters_destination, 1, 2).
held(a153, liquid_remains_in_destination, 2, 2).
held(a153, no_spill, 1, 2).
explored(a154, dull_destination).
explored(a154, light_destination).
held(a154, destination_still_approach, 2, 2).
held(a154, destination_still_retreat, 2, 2).
held(a154, destination_still_settle, 2, 2).
held(a154, destination_upright, 2, 2).
held(a154, source_clear, 2, 2).
held(a154, liquid_leaves_source, 2, 2).
held(a154, liquid_enters_destination, 2, 2).
held(a154, liquid_remains_in_destination, 2, 2).
held(a154, no_spill, 2, 2).
explored(a155, end_tilted_back).
explored(a155, pour_below_rim).
held(a155, destination_still_approach, 0, 2).
held(a155, destination_still_retreat, 0, 2).
held(a155, destination_still_settle, 1, 2).
held(a155, destination_upright, 2, 2).
held(a155, source_clear, 0, 2).
held(a155, liquid_leaves_source, 2, 2).
held(a155, liquid_enters_destination, 2, 2).
held(a155, liquid_remains_in_destination, 1, 2).
held(a155, no_spill, 1, 2).
explored(a156, approach_raising).
explored(a156, fast_approach).
held(a156, destination_still_approach, 2, 5).
held(a156, destination_still_retreat, 5, 5).
held(a156, destination_still_settle, 5, 5).
held(a156, destination_upright, 5, 5).
held(a156, source_clear, 1, 5).
held(a156, liquid_leaves_source, 5, 5).
held(a156, liquid_enters_destination, 5, 5).
held(a156, liquid_remains_in_destination, 5, 5).
held(a156, no_spill, 5, 5).
explored(a157, fast_approach).
explored(a157, pour_steeply_tilted).
held(a157, destination_still_approach, 5, 5).
held(a157, destination_still_retreat, 5, 5).
held(a157, destination_still_settle, 5, 5).
held(a157, destination_upright, 5, 5).
held(a157, source_clear, 5, 5).
held(a157, liquid_leaves_source, 2, 5).
held(a157, liquid_enters_destination, 1, 5).
held(a157, liquid_remains_in_destination, 5, 5).
held(a157, no_spill, 4, 5).
explored(a158, end_below_rim).
explored(a158, pour_very_high).
held(a158, destination_still_approach, 4, 4).
held(a158, destination_still_retreat, 4, 4).
held(a158, destination_still_settle, 4, 4).
held(a158, destination_upright, 4, 4).
held(a158, source_clear, 3, 4).
held(a158, liquid_leaves_source, 4, 4).
held(a158, liquid_enters_destination, 1, 4).
held(a158, liquid_remains_in_destination, 4, 4).
held(a158, no_spill, 1, 4).
explored(a159, approach_raising).
explored(a159, pour_rolled).
held(a159, destination_still_approach, 2, 2).
held(a159, destination_still_retreat, 2, 2).
held(a159, destination_still_settle, 2, 2).
held(a159, destination_upright, 2, 2).
held(a159, source_clear, 0, 2).
held(a159, liquid_leaves_source, 2, 2).
held(a159, liquid_enters_destination, 2, 2).
held(a159, liquid_remains_in_destination, 2, 2).
held(a159, no_spill, 2, 2).
explored(a160, end_low).
explored(a160, fast_approach).
held(a160, destination_still_approach, 2, 2).
held(a160, destination_still_retreat, 1, 2).
held(a160, destination_still_settle, 2, 2).
held(a160, destination_upright, 2, 2).
held(a160, source_clear, 1, 2).
held(a160, liquid_leaves_source, 2, 2).
held(a160, liquid_enters_destination, 2, 2).
held(a160, liquid_remains_in_destination, 2, 2).
held(a160, no_spill, 2, 2).
explored(a161, fast_approach).
explored(a161, start_tilted_back).
held(a161, destination_still_approach, 4, 4).
held(a161, destination_still_retreat, 4, 4).
held(a161, destination_still_settle, 4, 4).
held(a161, destination_upright, 4, 4).
held(a161, source_clear, 4, 4).
held(a161, liquid_leaves_source, 4, 4).
held(a161, liquid_enters_destination, 4, 4).
held(a161, liquid_remains_in_destination, 4, 4).
held(a161, no_spill, 4, 4).
explored(a162, fast_approach).
explored(a162, start_low).
held(a162, destination_still_approach, 3, 4).
held(a162, destination_still_retreat, 4, 4).
held(a162, destination_still_settle, 4, 4).
held(a162, destination_upright, 4, 4).
held(a162, source_clear, 2, 4).
held(a162, liquid_leaves_source, 4, 4).
held(a162, liquid_enters_destination, 4, 4).
held(a162, liquid_remains_in_destination, 4, 4).
held(a162, no_spill, 4, 4).
explored(a163, approach_moving_away).
explored(a163, pour_very_high).
held(a163, destination_still_approach, 2, 2).
held(a163, destination_still_retreat, 2, 2).
held(a163, destination_still_settle, 2, 2).
held(a163, destination_upright, 2, 2).
held(a163, source_clear, 2, 2).
held(a163, liquid_leaves_source, 2, 2).
held(a163, liquid_enters_destination, 1, 2).
held(a163, liquid_remains_in_destination, 2, 2).
held(a163, no_spill, 1, 2).
explored(a164, fast_approach).
explored(a164, fast_retreat).
held(a164, destination_still_approach, 2, 2).
held(a164, destination_still_retreat, 2, 2).
held(a164, destination_still_settle, 2, 2).
held(a164, destination_upright, 2, 2).
held(a164, source_clear, 2, 2).
held(a164, liquid_leaves_source, 2, 2).
held(a164, liquid_enters_destination, 2, 2).
held(a164, liquid_remains_in_destination, 2, 2).
held(a164, no_spill, 2, 2).
explored(a165, end_low).
explored(a165, pour_offset_sideways).
held(a165, destination_still_approach, 4, 4).
held(a165, destination_still_retreat, 4, 4).
held(a165, destination_still_settle, 4, 4).
held(a165, destination_upright, 4, 4).
held(a165, source_clear, 4, 4).
held(a165, liquid_leaves_source, 4, 4).
held(a165, liquid_enters_destination, 4, 4).
held(a165, liquid_remains_in_destination, 4, 4).
held(a165, no_spill, 4, 4).
explored(a166, pour_offset_sideways).
explored(a166, start_low).
held(a166, destination_still_approach, 4, 4).
held(a166, destination_still_retreat, 4, 4).
held(a166, destination_still_settle, 4, 4).
held(a166, destination_upright, 4, 4).
held(a166, source_clear, 3, 4).
held(a166, liquid_leaves_source, 4, 4).
held(a166, liquid_enters_destination, 1, 4).
held(a166, liquid_remains_in_destination, 4, 4).
held(a166, no_spill, 1, 4).
explored(a167, pour_offset_sideways).
explored(a167, pour_rolled).
held(a167, destination_still_approach, 2, 2).
held(a167, destination_still_retreat, 2, 2).
held(a167, destination_still_settle, 2, 2).
held(a167, destination_upright, 2, 2).
held(a167, source_clear, 2, 2).
held(a167, liquid_leaves_source, 2, 2).
held(a167, liquid_enters_destination, 1, 2).
held(a167, liquid_remains_in_destination, 2, 2).
held(a167, no_spill, 1, 2).
explored(a168, fast_approach).
explored(a168, slow_retreat).
held(a168, destination_still_approach, 2, 2).
held(a168, destination_still_retreat, 2, 2).
held(a168, destination_still_settle, 2, 2).
held(a168, destination_upright, 2, 2).
held(a168, source_clear, 2, 2).
held(a168, liquid_leaves_source, 2, 2).
held(a168, liquid_enters_destination, 2, 2).
held(a168, liquid_remains_in_destination, 2, 2).
held(a168, no_spill, 2, 2).
explored(a169, pour_offset_sideways).
explored(a169, retreat_moving_closer).
held(a169, destination_still_approach, 2, 2).
held(a169, destination_still_retreat, 2, 2).
held(a169, destination_still_settle, 2, 2).
held(a169, destination_upright, 2, 2).
held(a169, source_clear, 2, 2).
held(a169, liquid_leaves_source, 2, 2).
held(a169, liquid_enters_destination, 1, 2).
held(a169, liquid_remains_in_destination, 2, 2).
held(a169, no_spill, 1, 2).
explored(a170, pour_half_tilted).
explored(a170, retreat_lowering).
held(a170, destination_still_approach, 4, 4).
held(a170, destination_still_retreat, 3, 4).
held(a170, destination_still_settle, 4, 4).
held(a170, destination_upright, 3, 4).
held(a170, source_clear, 3, 4).
held(a170, liquid_leaves_source, 0, 4).
held(a170, liquid_enters_destination, 0, 4).
held(a170, liquid_remains_in_destination, 4, 4).
held(a170, no_spill, 4, 4).
explored(a171, pour_offset_sideways).
explored(a171, slippery_destination).
held(a171, destination_still_approach, 1, 2).
held(a171, destination_still_retreat, 2, 2).
held(a171, destination_still_settle, 2, 2).
held(a171, destination_upright, 2, 2).
held(a171, source_clear, 1, 2).
held(a171, liquid_leaves_source, 2, 2).
held(a171, liquid_enters_destination, 1, 2).
held(a171, liquid_remains_in_destination, 2, 2).
held(a171, no_spill, 1, 2).
explored(a172, pour_slightly_tilted).
explored(a172, retreat_moving_closer).
held(a172, destination_still_approach, 2, 2).
held(a172, destination_still_retreat, 2, 2).
held(a172, destination_still_settle, 2, 2).
held(a172, destination_upright, 2, 2).
held(a172, source_clear, 2, 2).
held(a172, liquid_leaves_source, 0, 2).
held(a172, liquid_enters_destination, 0, 2).
held(a172, liquid_remains_in_destination, 2, 2).
held(a172, no_spill, 2, 2).
explored(a173, pour_offset_sideways).
explored(a173, slippery_source).
held(a173, destination_still_approach, 2, 2).
held(a173, destination_still_retreat, 2, 2).
held(a173, destination_still_settle, 2, 2).
held(a173, destination_upright, 2, 2).
held(a173, source_clear, 2, 2).
held(a173, liquid_leaves_source, 2, 2).
held(a173, liquid_enters_destination, 0, 2).
held(a173, liquid_remains_in_destination, 2, 2).
held(a173, no_spill, 0, 2).
explored(a174, approach_raising).
explored(a174, pour_half_tilted).
held(a174, destination_still_approach, 2, 2).
held(a174, destination_still_retreat, 2, 2).
held(a174, destination_still_settle, 2, 2).
held(a174, destination_upright, 2, 2).
held(a174, source_clear, 2, 2).
held(a174, liquid_leaves_source, 0, 2).
held(a174, liquid_enters_destination, 0, 2).
held(a174, liquid_remains_in_destination, 2, 2).
held(a174, no_spill, 2, 2).
explored(a175, pour_slightly_tilted).
explored(a175, start_below_rim).
held(a175, destination_still_approach, 3, 4).
held(a175, destination_still_retreat, 4, 4).
held(a175, destination_still_settle, 4, 4).
held(a175, destination_upright, 4, 4).
held(a175, source_clear, 2, 4).
held(a175, liquid_leaves_source, 0, 4).
held(a175, liquid_enters_destination, 0, 4).
held(a175, liquid_remains_in_destination, 4, 4).
held(a175, no_spill, 4, 4).
explored(a176, pour_half_tilted).
explored(a176, retreat_moving_closer).
held(a176, destination_still_approach, 2, 2).
held(a176, destination_still_retreat, 2, 2).
held(a176, destination_still_settle, 2, 2).
held(a176, destination_upright, 2, 2).
held(a176, source_clear, 2, 2).
held(a176, liquid_leaves_source, 0, 2).
held(a176, liquid_enters_destination, 0, 2).
held(a176, liquid_remains_in_destination, 2, 2).
held(a176, no_spill, 2, 2).
explored(a177, pour_half_tilted).
explored(a177, pour_high).
held(a177, destination_still_approach, 2, 2).
held(a177, destination_still_retreat, 2, 2).
held(a177, destination_still_settle, 2, 2).
held(a177, destination_upright, 2, 2).
held(a177, source_clear, 2, 2).
held(a177, liquid_leaves_source, 0, 2).
held(a177, liquid_enters_destination, 0, 2).
held(a177, liquid_remains_in_destination, 2, 2).
held(a177, no_spill, 2, 2).
explored(a178, pour_half_tilted).
explored(a178, pour_rolled).
held(a178, destination_still_approach, 2, 2).
held(a178, destination_still_retreat, 2, 2).
held(a178, destination_still_settle, 2, 2).
held(a178, destination_upright, 2, 2).
held(a178, source_clear, 2, 2).
held(a178, liquid_leaves_source, 0, 2).
held(a178, liquid_enters_destination, 0, 2).
held(a178, liquid_remains_in_destination, 2, 2).
held(a178, no_spill, 2, 2).
explored(a179, pour_half_tilted).
explored(a179, start_slightly_tilted).
held(a179, destination_still_approach, 2, 2).
held(a179, destination_still_retreat, 2, 2).
held(a179, destination_still_settle, 2, 2).
held(a179, destination_upright, 2, 2).
held(a179, source_clear, 2, 2).
held(a179, liquid_leaves_source, 0, 2).
held(a179, liquid_enters_destination, 0, 2).
held(a179, liquid_remains_in_destination, 2, 2).
held(a179, no_spill, 2, 2).
explored(a180, pour_high).
explored(a180, pour_to_side).
held(a180, destination_still_approach, 2, 2).
held(a180, destination_still_retreat, 2, 2).
held(a180, destination_still_settle, 2, 2).
held(a180, destination_upright, 2, 2).
held(a180, source_clear, 2, 2).
held(a180, liquid_leaves_source, 2, 2).
held(a180, liquid_enters_destination, 2, 2).
held(a180, liquid_remains_in_destination, 2, 2).
held(a180, no_spill, 2, 2).
explored(a181, sticky_liquid).
explored(a181, very_much_liquid).
held(a181, destination_still_approach, 2, 2).
held(a181, destination_still_retreat, 2, 2).
held(a181, destination_still_settle, 2, 2).
held(a181, destination_upright, 2, 2).
held(a181, source_clear, 2, 2).
held(a181, liquid_leaves_source, 2, 2).
held(a181, liquid_enters_destination, 2, 2).
held(a181, liquid_remains_in_destination, 2, 2).
held(a181, no_spill, 2, 2).
explored(a182, start_low).
explored(a182, start_tilted_back).
held(a182, destination_still_approach, 2, 2).
held(a182, destination_still_retreat, 2, 2).
held(a182, destination_still_settle, 2, 2).
held(a182, destination_upright, 2, 2).
held(a182, source_clear, 1, 2).
held(a182, liquid_leaves_source, 2, 2).
held(a182, liquid_enters_destination, 2, 2).
held(a182, liquid_remains_in_destination, 2, 2).
held(a182, no_spill, 2, 2).
explored(a183, light_destination).
explored(a183, pour_offset_sideways).
held(a183, destination_still_approach, 2, 2).
held(a183, destination_still_retreat, 2, 2).
held(a183, destination_still_settle, 2, 2).
held(a183, destination_upright, 2, 2).
held(a183, source_clear, 2, 2).
held(a183, liquid_leaves_source, 2, 2).
held(a183, liquid_enters_destination, 1, 2).
held(a183, liquid_remains_in_destination, 2, 2).
held(a183, no_spill, 1, 2).
explored(a184, pour_low).
explored(a184, start_below_rim).
held(a184, destination_still_approach, 0, 2).
held(a184, destination_still_retreat, 2, 2).
held(a184, destination_still_settle, 2, 2).
held(a184, destination_upright, 2, 2).
held(a184, source_clear, 0, 2).
held(a184, liquid_leaves_source, 2, 2).
held(a184, liquid_enters_destination, 0, 2).
held(a184, liquid_remains_in_destination, 2, 2).
held(a184, no_spill, 0, 2).
explored(a185, approach_moving_away).
explored(a185, start_below_rim).
held(a185, destination_still_approach, 0, 4).
held(a185, destination_still_retreat, 2, 4).
held(a185, destination_still_settle, 4, 4).
held(a185, destination_upright, 4, 4).
held(a185, source_clear, 0, 4).
held(a185, liquid_leaves_source, 4, 4).
held(a185, liquid_enters_destination, 1, 4).
held(a185, liquid_remains_in_destination, 2, 4).
held(a185, no_spill, 0, 4).
explored(a186, pour_high).
explored(a186, pour_rolled).
held(a186, destination_still_approach, 2, 2).
held(a186, destination_still_retreat, 2, 2).
held(a186, destination_still_settle, 2, 2).
held(a186, destination_upright, 2, 2).
held(a186, source_clear, 2, 2).
held(a186, liquid_leaves_source, 2, 2).
held(a186, liquid_enters_destination, 1, 2).
held(a186, liquid_remains_in_destination, 2, 2).
held(a186, no_spill, 1, 2).
explored(a187, approach_raising).
explored(a187, bouncy_source).
held(a187, destination_still_approach, 1, 2).
held(a187, destination_still_retreat, 2, 2).
held(a187, destination_still_settle, 2, 2).
held(a187, destination_upright, 2, 2).
held(a187, source_clear, 0, 2).
held(a187, liquid_leaves_source, 2, 2).
held(a187, liquid_enters_destination, 2, 2).
held(a187, liquid_remains_in_destination, 2, 2).
held(a187, no_spill, 2, 2).
explored(a188, end_low).
explored(a188, end_slightly_tilted).
held(a188, destination_still_approach, 2, 2).
held(a188, destination_still_retreat, 2, 2).
held(a188, destination_still_settle, 2, 2).
held(a188, destination_upright, 2, 2).
held(a188, source_clear, 2, 2).
held(a188, liquid_leaves_source, 2, 2).
held(a188, liquid_enters_destination, 2, 2).
held(a188, liquid_remains_in_destination, 2, 2).
held(a188, no_spill, 2, 2).
explored(a189, pour_steeply_tilted).
explored(a189, pour_to_side).
held(a189, destination_still_approach, 11, 11).
held(a189, destination_still_retreat, 11, 11).
held(a189, destination_still_settle, 11, 11).
held(a189, destination_upright, 11, 11).
held(a189, source_clear, 11, 11).
held(a189, liquid_leaves_source, 10, 11).
held(a189, liquid_enters_destination, 3, 11).
held(a189, liquid_remains_in_destination, 11, 11).
held(a189, no_spill, 5, 11).
explored(a190, end_below_rim).
explored(a190, retreat_moving_closer).
held(a190, destination_still_approach, 2, 2).
held(a190, destination_still_retreat, 0, 2).
held(a190, destination_still_settle, 1, 2).
held(a190, destination_upright, 2, 2).
held(a190, source_clear, 0, 2).
held(a190, liquid_leaves_source, 2, 2).
held(a190, liquid_enters_destination, 2, 2).
held(a190, liquid_remains_in_destination, 2, 2).
held(a190, no_spill, 2, 2).
