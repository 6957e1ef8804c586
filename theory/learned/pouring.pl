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
setting(batch, 4).
setting(budget, 25).
setting(pours, 775).
setting(curiosity, learn).
setting(body, 2).
setting(queue, 64).
setting(uncertainty_permille, 1000).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 81).
setting(simulations, 772).
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
setting(general_pours, 772).
setting(general_own_pours, 0).
setting(general_rules, 46).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 68).
provenance(g0_destination_still_approach, kept, 67).
provenance(g0_destination_still_approach, confidence_permille, 997).
provenance(g0_destination_still_approach, antecedent, a1).
rule(g1_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g1_destination_still_approach, pour_below_rim).
learned(g1_destination_still_approach).
provenance(g1_destination_still_approach, layer, general).
provenance(g1_destination_still_approach, level, 1).
provenance(g1_destination_still_approach, support, 12).
provenance(g1_destination_still_approach, kept, 11).
provenance(g1_destination_still_approach, confidence_permille, 688).
provenance(g1_destination_still_approach, antecedent, a11).
rule(g2_destination_still_approach, defeasible, destination_still_approach).
body(g2_destination_still_approach, start_below_rim).
learned(g2_destination_still_approach).
provenance(g2_destination_still_approach, layer, general).
provenance(g2_destination_still_approach, level, 1).
provenance(g2_destination_still_approach, support, 14).
provenance(g2_destination_still_approach, kept, 8).
provenance(g2_destination_still_approach, confidence_permille, 596).
provenance(g2_destination_still_approach, antecedent, a2).
rule(g3_destination_still_approach, defeasible, destination_still_approach).
body(g3_destination_still_approach, pour_low).
learned(g3_destination_still_approach).
provenance(g3_destination_still_approach, layer, general).
provenance(g3_destination_still_approach, level, 1).
provenance(g3_destination_still_approach, support, 24).
provenance(g3_destination_still_approach, kept, 17).
provenance(g3_destination_still_approach, confidence_permille, 745).
provenance(g3_destination_still_approach, antecedent, a54).
rule(g4_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g4_destination_still_approach, pour_low).
body(g4_destination_still_approach, start_below_rim).
learned(g4_destination_still_approach).
provenance(g4_destination_still_approach, layer, general).
provenance(g4_destination_still_approach, level, 2).
provenance(g4_destination_still_approach, support, 5).
provenance(g4_destination_still_approach, kept, 5).
provenance(g4_destination_still_approach, confidence_permille, 530).
provenance(g4_destination_still_approach, antecedent, a75).
rule(g5_destination_still_approach, defeasible, destination_still_approach).
body(g5_destination_still_approach, approach_raising).
learned(g5_destination_still_approach).
provenance(g5_destination_still_approach, layer, general).
provenance(g5_destination_still_approach, level, 1).
provenance(g5_destination_still_approach, support, 27).
provenance(g5_destination_still_approach, kept, 20).
provenance(g5_destination_still_approach, confidence_permille, 859).
provenance(g5_destination_still_approach, antecedent, a62).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 68).
provenance(g0_destination_still_retreat, kept, 67).
provenance(g0_destination_still_retreat, confidence_permille, 998).
provenance(g0_destination_still_retreat, antecedent, a1).
rule(g1_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g1_destination_still_retreat, pour_below_rim).
learned(g1_destination_still_retreat).
provenance(g1_destination_still_retreat, layer, general).
provenance(g1_destination_still_retreat, level, 1).
provenance(g1_destination_still_retreat, support, 12).
provenance(g1_destination_still_retreat, kept, 8).
provenance(g1_destination_still_retreat, confidence_permille, 579).
provenance(g1_destination_still_retreat, antecedent, a11).
rule(g2_destination_still_retreat, defeasible, destination_still_retreat).
body(g2_destination_still_retreat, pour_low).
learned(g2_destination_still_retreat).
provenance(g2_destination_still_retreat, layer, general).
provenance(g2_destination_still_retreat, level, 1).
provenance(g2_destination_still_retreat, support, 24).
provenance(g2_destination_still_retreat, kept, 16).
provenance(g2_destination_still_retreat, confidence_permille, 836).
provenance(g2_destination_still_retreat, antecedent, a54).
rule(g3_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g3_destination_still_retreat, pour_low).
body(g3_destination_still_retreat, retreat_lowering).
learned(g3_destination_still_retreat).
provenance(g3_destination_still_retreat, layer, general).
provenance(g3_destination_still_retreat, level, 2).
provenance(g3_destination_still_retreat, support, 10).
provenance(g3_destination_still_retreat, kept, 9).
provenance(g3_destination_still_retreat, confidence_permille, 511).
provenance(g3_destination_still_retreat, antecedent, a76).
rule(g4_destination_still_retreat, defeasible, destination_still_retreat).
body(g4_destination_still_retreat, end_below_rim).
body(g4_destination_still_retreat, pour_low).
learned(g4_destination_still_retreat).
provenance(g4_destination_still_retreat, layer, general).
provenance(g4_destination_still_retreat, level, 1).
provenance(g4_destination_still_retreat, support, 9).
provenance(g4_destination_still_retreat, kept, 1).
provenance(g4_destination_still_retreat, confidence_permille, 544).
provenance(g4_destination_still_retreat, antecedent, a80).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 68).
provenance(g0_destination_still_settle, kept, 68).
provenance(g0_destination_still_settle, confidence_permille, 1000).
provenance(g0_destination_still_settle, antecedent, a1).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 68).
provenance(g0_destination_upright, kept, 68).
provenance(g0_destination_upright, confidence_permille, 1000).
provenance(g0_destination_upright, antecedent, a1).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 68).
provenance(g0_source_clear, kept, 66).
provenance(g0_source_clear, confidence_permille, 968).
provenance(g0_source_clear, antecedent, a1).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, pour_low).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 24).
provenance(g1_source_clear, kept, 10).
provenance(g1_source_clear, confidence_permille, 573).
provenance(g1_source_clear, antecedent, a54).
rule(g2_source_clear, defeasible, neg(source_clear)).
body(g2_source_clear, pour_below_rim).
learned(g2_source_clear).
provenance(g2_source_clear, layer, general).
provenance(g2_source_clear, level, 1).
provenance(g2_source_clear, support, 12).
provenance(g2_source_clear, kept, 12).
provenance(g2_source_clear, confidence_permille, 968).
provenance(g2_source_clear, antecedent, a11).
rule(g3_source_clear, defeasible, source_clear).
body(g3_source_clear, end_below_rim).
learned(g3_source_clear).
provenance(g3_source_clear, layer, general).
provenance(g3_source_clear, level, 1).
provenance(g3_source_clear, support, 14).
provenance(g3_source_clear, kept, 4).
provenance(g3_source_clear, confidence_permille, 509).
provenance(g3_source_clear, antecedent, a31).
rule(g4_source_clear, defeasible, source_clear).
body(g4_source_clear, start_below_rim).
learned(g4_source_clear).
provenance(g4_source_clear, layer, general).
provenance(g4_source_clear, level, 1).
provenance(g4_source_clear, support, 14).
provenance(g4_source_clear, kept, 5).
provenance(g4_source_clear, confidence_permille, 564).
provenance(g4_source_clear, antecedent, a2).
rule(g5_source_clear, defeasible, source_clear).
body(g5_source_clear, pour_low).
body(g5_source_clear, pour_slightly_tilted).
learned(g5_source_clear).
provenance(g5_source_clear, layer, general).
provenance(g5_source_clear, level, 2).
provenance(g5_source_clear, support, 6).
provenance(g5_source_clear, kept, 6).
provenance(g5_source_clear, confidence_permille, 829).
provenance(g5_source_clear, antecedent, a70).
rule(g6_source_clear, defeasible, neg(source_clear)).
body(g6_source_clear, end_below_rim).
body(g6_source_clear, pour_low).
learned(g6_source_clear).
provenance(g6_source_clear, layer, general).
provenance(g6_source_clear, level, 2).
provenance(g6_source_clear, support, 9).
provenance(g6_source_clear, kept, 9).
provenance(g6_source_clear, confidence_permille, 925).
provenance(g6_source_clear, antecedent, a80).
rule(g7_source_clear, defeasible, source_clear).
body(g7_source_clear, approach_raising).
learned(g7_source_clear).
provenance(g7_source_clear, layer, general).
provenance(g7_source_clear, level, 1).
provenance(g7_source_clear, support, 27).
provenance(g7_source_clear, kept, 16).
provenance(g7_source_clear, confidence_permille, 800).
provenance(g7_source_clear, antecedent, a62).
rule(g8_source_clear, defeasible, neg(source_clear)).
body(g8_source_clear, pour_low).
body(g8_source_clear, start_below_rim).
learned(g8_source_clear).
provenance(g8_source_clear, layer, general).
provenance(g8_source_clear, level, 2).
provenance(g8_source_clear, support, 5).
provenance(g8_source_clear, kept, 5).
provenance(g8_source_clear, confidence_permille, 877).
provenance(g8_source_clear, antecedent, a75).
rule(g9_source_clear, defeasible, neg(source_clear)).
body(g9_source_clear, pour_low).
body(g9_source_clear, retreat_lowering).
learned(g9_source_clear).
provenance(g9_source_clear, layer, general).
provenance(g9_source_clear, level, 1).
provenance(g9_source_clear, support, 10).
provenance(g9_source_clear, kept, 10).
provenance(g9_source_clear, confidence_permille, 874).
provenance(g9_source_clear, antecedent, a76).
rule(g10_source_clear, defeasible, source_clear).
body(g10_source_clear, retreat_lowering).
learned(g10_source_clear).
provenance(g10_source_clear, layer, general).
provenance(g10_source_clear, level, 1).
provenance(g10_source_clear, support, 28).
provenance(g10_source_clear, kept, 17).
provenance(g10_source_clear, confidence_permille, 746).
provenance(g10_source_clear, antecedent, a61).
rule(g0_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 68).
provenance(g0_liquid_leaves_source, kept, 68).
provenance(g0_liquid_leaves_source, confidence_permille, 1000).
provenance(g0_liquid_leaves_source, antecedent, a1).
rule(g1_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g1_liquid_leaves_source, pour_slightly_tilted).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 12).
provenance(g1_liquid_leaves_source, kept, 12).
provenance(g1_liquid_leaves_source, confidence_permille, 1000).
provenance(g1_liquid_leaves_source, antecedent, a8).
rule(g2_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g2_liquid_leaves_source, pour_upright).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 12).
provenance(g2_liquid_leaves_source, kept, 12).
provenance(g2_liquid_leaves_source, confidence_permille, 1000).
provenance(g2_liquid_leaves_source, antecedent, a6).
rule(g3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g3_liquid_leaves_source, pour_tilted_back).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 12).
provenance(g3_liquid_leaves_source, kept, 12).
provenance(g3_liquid_leaves_source, confidence_permille, 1000).
provenance(g3_liquid_leaves_source, antecedent, a10).
rule(g4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g4_liquid_leaves_source, pour_half_tilted).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 12).
provenance(g4_liquid_leaves_source, kept, 12).
provenance(g4_liquid_leaves_source, confidence_permille, 988).
provenance(g4_liquid_leaves_source, antecedent, a9).
rule(g0_liquid_enters_destination, defeasible, liquid_enters_destination).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 68).
provenance(g0_liquid_enters_destination, kept, 68).
provenance(g0_liquid_enters_destination, confidence_permille, 996).
provenance(g0_liquid_enters_destination, antecedent, a1).
rule(g1_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g1_liquid_enters_destination, pour_slightly_tilted).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 12).
provenance(g1_liquid_enters_destination, kept, 12).
provenance(g1_liquid_enters_destination, confidence_permille, 993).
provenance(g1_liquid_enters_destination, antecedent, a8).
rule(g2_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g2_liquid_enters_destination, pour_upright).
learned(g2_liquid_enters_destination).
provenance(g2_liquid_enters_destination, layer, general).
provenance(g2_liquid_enters_destination, level, 1).
provenance(g2_liquid_enters_destination, support, 12).
provenance(g2_liquid_enters_destination, kept, 12).
provenance(g2_liquid_enters_destination, confidence_permille, 993).
provenance(g2_liquid_enters_destination, antecedent, a6).
rule(g3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g3_liquid_enters_destination, pour_tilted_back).
learned(g3_liquid_enters_destination).
provenance(g3_liquid_enters_destination, layer, general).
provenance(g3_liquid_enters_destination, level, 1).
provenance(g3_liquid_enters_destination, support, 12).
provenance(g3_liquid_enters_destination, kept, 12).
provenance(g3_liquid_enters_destination, confidence_permille, 993).
provenance(g3_liquid_enters_destination, antecedent, a10).
rule(g4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g4_liquid_enters_destination, pour_far_away).
learned(g4_liquid_enters_destination).
provenance(g4_liquid_enters_destination, layer, general).
provenance(g4_liquid_enters_destination, level, 1).
provenance(g4_liquid_enters_destination, support, 12).
provenance(g4_liquid_enters_destination, kept, 12).
provenance(g4_liquid_enters_destination, confidence_permille, 984).
provenance(g4_liquid_enters_destination, antecedent, a22).
rule(g5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g5_liquid_enters_destination, pour_to_side).
learned(g5_liquid_enters_destination).
provenance(g5_liquid_enters_destination, layer, general).
provenance(g5_liquid_enters_destination, level, 1).
provenance(g5_liquid_enters_destination, support, 12).
provenance(g5_liquid_enters_destination, kept, 12).
provenance(g5_liquid_enters_destination, confidence_permille, 984).
provenance(g5_liquid_enters_destination, antecedent, a25).
rule(g6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g6_liquid_enters_destination, pour_half_tilted).
learned(g6_liquid_enters_destination).
provenance(g6_liquid_enters_destination, layer, general).
provenance(g6_liquid_enters_destination, level, 1).
provenance(g6_liquid_enters_destination, support, 12).
provenance(g6_liquid_enters_destination, kept, 12).
provenance(g6_liquid_enters_destination, confidence_permille, 982).
provenance(g6_liquid_enters_destination, antecedent, a9).
rule(g7_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g7_liquid_enters_destination, pour_offset_sideways).
learned(g7_liquid_enters_destination).
provenance(g7_liquid_enters_destination, layer, general).
provenance(g7_liquid_enters_destination, level, 1).
provenance(g7_liquid_enters_destination, support, 12).
provenance(g7_liquid_enters_destination, kept, 4).
provenance(g7_liquid_enters_destination, confidence_permille, 543).
provenance(g7_liquid_enters_destination, antecedent, a46).
rule(g8_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g8_liquid_enters_destination, pour_offset_sideways).
body(g8_liquid_enters_destination, pour_very_high).
learned(g8_liquid_enters_destination).
provenance(g8_liquid_enters_destination, layer, general).
provenance(g8_liquid_enters_destination, level, 2).
provenance(g8_liquid_enters_destination, support, 4).
provenance(g8_liquid_enters_destination, kept, 3).
provenance(g8_liquid_enters_destination, confidence_permille, 900).
provenance(g8_liquid_enters_destination, antecedent, a71).
rule(g9_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g9_liquid_enters_destination, pour_very_high).
learned(g9_liquid_enters_destination).
provenance(g9_liquid_enters_destination, layer, general).
provenance(g9_liquid_enters_destination, level, 1).
provenance(g9_liquid_enters_destination, support, 12).
provenance(g9_liquid_enters_destination, kept, 9).
provenance(g9_liquid_enters_destination, confidence_permille, 849).
provenance(g9_liquid_enters_destination, antecedent, a12).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 68).
provenance(g0_liquid_remains_in_destination, kept, 68).
provenance(g0_liquid_remains_in_destination, confidence_permille, 1000).
provenance(g0_liquid_remains_in_destination, antecedent, a1).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 68).
provenance(g0_no_spill, kept, 68).
provenance(g0_no_spill, confidence_permille, 997).
provenance(g0_no_spill, antecedent, a1).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, pour_far_away).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 12).
provenance(g1_no_spill, kept, 12).
provenance(g1_no_spill, confidence_permille, 988).
provenance(g1_no_spill, antecedent, a22).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, pour_to_side).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 12).
provenance(g2_no_spill, kept, 12).
provenance(g2_no_spill, confidence_permille, 988).
provenance(g2_no_spill, antecedent, a25).
rule(g3_no_spill, defeasible, no_spill).
body(g3_no_spill, pour_offset_sideways).
learned(g3_no_spill).
provenance(g3_no_spill, layer, general).
provenance(g3_no_spill, level, 1).
provenance(g3_no_spill, support, 12).
provenance(g3_no_spill, kept, 4).
provenance(g3_no_spill, confidence_permille, 632).
provenance(g3_no_spill, antecedent, a46).
rule(g4_no_spill, defeasible, neg(no_spill)).
body(g4_no_spill, pour_offset_sideways).
body(g4_no_spill, pour_very_high).
learned(g4_no_spill).
provenance(g4_no_spill, layer, general).
provenance(g4_no_spill, level, 2).
provenance(g4_no_spill, support, 4).
provenance(g4_no_spill, kept, 3).
provenance(g4_no_spill, confidence_permille, 840).
provenance(g4_no_spill, antecedent, a71).
rule(g5_no_spill, defeasible, no_spill).
body(g5_no_spill, pour_very_high).
learned(g5_no_spill).
provenance(g5_no_spill, layer, general).
provenance(g5_no_spill, level, 1).
provenance(g5_no_spill, support, 12).
provenance(g5_no_spill, kept, 9).
provenance(g5_no_spill, confidence_permille, 880).
provenance(g5_no_spill, antecedent, a12).
sup(g10_source_clear, g1_source_clear).
sup(g1_destination_still_approach, g2_destination_still_approach).
sup(g1_liquid_enters_destination, g7_liquid_enters_destination).
sup(g1_liquid_enters_destination, g9_liquid_enters_destination).
sup(g1_no_spill, g3_no_spill).
sup(g1_no_spill, g5_no_spill).
sup(g1_source_clear, g3_source_clear).
sup(g1_source_clear, g4_source_clear).
sup(g2_liquid_enters_destination, g7_liquid_enters_destination).
sup(g2_liquid_enters_destination, g9_liquid_enters_destination).
sup(g2_no_spill, g3_no_spill).
sup(g2_no_spill, g5_no_spill).
sup(g2_source_clear, g10_source_clear).
sup(g2_source_clear, g3_source_clear).
sup(g2_source_clear, g4_source_clear).
sup(g2_source_clear, g7_source_clear).
sup(g3_liquid_enters_destination, g7_liquid_enters_destination).
sup(g3_liquid_enters_destination, g9_liquid_enters_destination).
sup(g4_liquid_enters_destination, g7_liquid_enters_destination).
sup(g4_liquid_enters_destination, g9_liquid_enters_destination).
sup(g5_destination_still_approach, g1_destination_still_approach).
sup(g5_liquid_enters_destination, g7_liquid_enters_destination).
sup(g5_liquid_enters_destination, g9_liquid_enters_destination).
sup(g6_liquid_enters_destination, g7_liquid_enters_destination).
sup(g6_liquid_enters_destination, g9_liquid_enters_destination).
sup(g6_source_clear, g4_source_clear).
sup(g6_source_clear, g5_source_clear).
sup(g6_source_clear, g7_source_clear).
sup(g7_source_clear, g1_source_clear).
sup(g8_source_clear, g10_source_clear).
sup(g8_source_clear, g3_source_clear).
sup(g8_source_clear, g5_source_clear).
sup(g9_source_clear, g4_source_clear).
sup(g9_source_clear, g5_source_clear).
sup(g9_source_clear, g7_source_clear).
