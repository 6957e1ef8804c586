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
setting(doubt_permille, 1000).
setting(newness_permille, 2000).
setting(reach, 16).
setting(breadth, 3).
setting(ridge_permille, 1000).
setting(qualify, weighted).
setting(explored, 147).
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
setting(general_rules, 70).
rule(g0_destination_still_approach, defeasible, destination_still_approach).
learned(g0_destination_still_approach).
provenance(g0_destination_still_approach, layer, general).
provenance(g0_destination_still_approach, level, 0).
provenance(g0_destination_still_approach, support, 15).
provenance(g0_destination_still_approach, kept, 15).
provenance(g0_destination_still_approach, confidence_permille, 996).
provenance(g0_destination_still_approach, antecedent, a1).
rule(g1_destination_still_approach, defeasible, neg(destination_still_approach)).
body(g1_destination_still_approach, pour_below_rim).
learned(g1_destination_still_approach).
provenance(g1_destination_still_approach, layer, general).
provenance(g1_destination_still_approach, level, 1).
provenance(g1_destination_still_approach, support, 16).
provenance(g1_destination_still_approach, kept, 16).
provenance(g1_destination_still_approach, confidence_permille, 882).
provenance(g1_destination_still_approach, antecedent, a4).
rule(g2_destination_still_approach, defeasible, destination_still_approach).
body(g2_destination_still_approach, pour_low).
learned(g2_destination_still_approach).
provenance(g2_destination_still_approach, layer, general).
provenance(g2_destination_still_approach, level, 1).
provenance(g2_destination_still_approach, support, 7).
provenance(g2_destination_still_approach, kept, 7).
provenance(g2_destination_still_approach, confidence_permille, 613).
provenance(g2_destination_still_approach, antecedent, a5).
rule(g3_destination_still_approach, defeasible, destination_still_approach).
body(g3_destination_still_approach, pour_far_away).
learned(g3_destination_still_approach).
provenance(g3_destination_still_approach, layer, general).
provenance(g3_destination_still_approach, level, 1).
provenance(g3_destination_still_approach, support, 4).
provenance(g3_destination_still_approach, kept, 4).
provenance(g3_destination_still_approach, confidence_permille, 1000).
provenance(g3_destination_still_approach, antecedent, a10).
rule(g4_destination_still_approach, defeasible, destination_still_approach).
body(g4_destination_still_approach, start_below_rim).
learned(g4_destination_still_approach).
provenance(g4_destination_still_approach, layer, general).
provenance(g4_destination_still_approach, level, 1).
provenance(g4_destination_still_approach, support, 4).
provenance(g4_destination_still_approach, kept, 2).
provenance(g4_destination_still_approach, confidence_permille, 772).
provenance(g4_destination_still_approach, antecedent, a2).
rule(g5_destination_still_approach, defeasible, destination_still_approach).
body(g5_destination_still_approach, pour_below_rim).
body(g5_destination_still_approach, pour_slightly_tilted).
learned(g5_destination_still_approach).
provenance(g5_destination_still_approach, layer, general).
provenance(g5_destination_still_approach, level, 2).
provenance(g5_destination_still_approach, support, 12).
provenance(g5_destination_still_approach, kept, 7).
provenance(g5_destination_still_approach, confidence_permille, 556).
provenance(g5_destination_still_approach, antecedent, a36).
rule(g6_destination_still_approach, defeasible, destination_still_approach).
body(g6_destination_still_approach, pour_below_rim).
body(g6_destination_still_approach, pour_upright).
learned(g6_destination_still_approach).
provenance(g6_destination_still_approach, layer, general).
provenance(g6_destination_still_approach, level, 2).
provenance(g6_destination_still_approach, support, 12).
provenance(g6_destination_still_approach, kept, 7).
provenance(g6_destination_still_approach, confidence_permille, 554).
provenance(g6_destination_still_approach, antecedent, a37).
rule(g7_destination_still_approach, defeasible, destination_still_approach).
body(g7_destination_still_approach, pour_below_rim).
body(g7_destination_still_approach, pour_tilted_back).
learned(g7_destination_still_approach).
provenance(g7_destination_still_approach, layer, general).
provenance(g7_destination_still_approach, level, 2).
provenance(g7_destination_still_approach, support, 12).
provenance(g7_destination_still_approach, kept, 8).
provenance(g7_destination_still_approach, confidence_permille, 518).
provenance(g7_destination_still_approach, antecedent, a39).
rule(g8_destination_still_approach, defeasible, destination_still_approach).
body(g8_destination_still_approach, bouncy_source).
body(g8_destination_still_approach, pour_low).
learned(g8_destination_still_approach).
provenance(g8_destination_still_approach, layer, general).
provenance(g8_destination_still_approach, level, 1).
provenance(g8_destination_still_approach, support, 5).
provenance(g8_destination_still_approach, kept, 3).
provenance(g8_destination_still_approach, confidence_permille, 691).
provenance(g8_destination_still_approach, antecedent, a144).
rule(g9_destination_still_approach, defeasible, destination_still_approach).
body(g9_destination_still_approach, dull_liquid).
body(g9_destination_still_approach, pour_low).
learned(g9_destination_still_approach).
provenance(g9_destination_still_approach, layer, general).
provenance(g9_destination_still_approach, level, 1).
provenance(g9_destination_still_approach, support, 4).
provenance(g9_destination_still_approach, kept, 3).
provenance(g9_destination_still_approach, confidence_permille, 688).
provenance(g9_destination_still_approach, antecedent, a131).
rule(g10_destination_still_approach, defeasible, destination_still_approach).
body(g10_destination_still_approach, light_liquid).
body(g10_destination_still_approach, pour_low).
learned(g10_destination_still_approach).
provenance(g10_destination_still_approach, layer, general).
provenance(g10_destination_still_approach, level, 1).
provenance(g10_destination_still_approach, support, 4).
provenance(g10_destination_still_approach, kept, 3).
provenance(g10_destination_still_approach, confidence_permille, 674).
provenance(g10_destination_still_approach, antecedent, a139).
rule(g0_destination_still_retreat, defeasible, destination_still_retreat).
learned(g0_destination_still_retreat).
provenance(g0_destination_still_retreat, layer, general).
provenance(g0_destination_still_retreat, level, 0).
provenance(g0_destination_still_retreat, support, 15).
provenance(g0_destination_still_retreat, kept, 15).
provenance(g0_destination_still_retreat, confidence_permille, 996).
provenance(g0_destination_still_retreat, antecedent, a1).
rule(g1_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g1_destination_still_retreat, pour_below_rim).
learned(g1_destination_still_retreat).
provenance(g1_destination_still_retreat, layer, general).
provenance(g1_destination_still_retreat, level, 1).
provenance(g1_destination_still_retreat, support, 16).
provenance(g1_destination_still_retreat, kept, 13).
provenance(g1_destination_still_retreat, confidence_permille, 751).
provenance(g1_destination_still_retreat, antecedent, a4).
rule(g2_destination_still_retreat, defeasible, destination_still_retreat).
body(g2_destination_still_retreat, pour_low).
learned(g2_destination_still_retreat).
provenance(g2_destination_still_retreat, layer, general).
provenance(g2_destination_still_retreat, level, 1).
provenance(g2_destination_still_retreat, support, 7).
provenance(g2_destination_still_retreat, kept, 7).
provenance(g2_destination_still_retreat, confidence_permille, 845).
provenance(g2_destination_still_retreat, antecedent, a5).
rule(g3_destination_still_retreat, defeasible, destination_still_retreat).
body(g3_destination_still_retreat, pour_below_rim).
body(g3_destination_still_retreat, pour_far_away).
learned(g3_destination_still_retreat).
provenance(g3_destination_still_retreat, layer, general).
provenance(g3_destination_still_retreat, level, 2).
provenance(g3_destination_still_retreat, support, 12).
provenance(g3_destination_still_retreat, kept, 12).
provenance(g3_destination_still_retreat, confidence_permille, 881).
provenance(g3_destination_still_retreat, antecedent, a15).
rule(g4_destination_still_retreat, defeasible, destination_still_retreat).
body(g4_destination_still_retreat, pour_below_rim).
body(g4_destination_still_retreat, pour_upright).
learned(g4_destination_still_retreat).
provenance(g4_destination_still_retreat, layer, general).
provenance(g4_destination_still_retreat, level, 2).
provenance(g4_destination_still_retreat, support, 12).
provenance(g4_destination_still_retreat, kept, 4).
provenance(g4_destination_still_retreat, confidence_permille, 511).
provenance(g4_destination_still_retreat, antecedent, a37).
rule(g5_destination_still_retreat, defeasible, destination_still_retreat).
body(g5_destination_still_retreat, pour_below_rim).
body(g5_destination_still_retreat, pour_slightly_tilted).
learned(g5_destination_still_retreat).
provenance(g5_destination_still_retreat, layer, general).
provenance(g5_destination_still_retreat, level, 2).
provenance(g5_destination_still_retreat, support, 12).
provenance(g5_destination_still_retreat, kept, 7).
provenance(g5_destination_still_retreat, confidence_permille, 509).
provenance(g5_destination_still_retreat, antecedent, a36).
rule(g6_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g6_destination_still_retreat, pour_below_rim).
body(g6_destination_still_retreat, pour_tilted_back).
learned(g6_destination_still_retreat).
provenance(g6_destination_still_retreat, layer, general).
provenance(g6_destination_still_retreat, level, 1).
provenance(g6_destination_still_retreat, support, 12).
provenance(g6_destination_still_retreat, kept, 6).
provenance(g6_destination_still_retreat, confidence_permille, 533).
provenance(g6_destination_still_retreat, antecedent, a39).
rule(g7_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g7_destination_still_retreat, pour_below_rim).
body(g7_destination_still_retreat, pour_half_tilted).
learned(g7_destination_still_retreat).
provenance(g7_destination_still_retreat, layer, general).
provenance(g7_destination_still_retreat, level, 1).
provenance(g7_destination_still_retreat, support, 16).
provenance(g7_destination_still_retreat, kept, 6).
provenance(g7_destination_still_retreat, confidence_permille, 570).
provenance(g7_destination_still_retreat, antecedent, a38).
rule(g8_destination_still_retreat, defeasible, neg(destination_still_retreat)).
body(g8_destination_still_retreat, grippy_source).
body(g8_destination_still_retreat, pour_below_rim).
learned(g8_destination_still_retreat).
provenance(g8_destination_still_retreat, layer, general).
provenance(g8_destination_still_retreat, level, 1).
provenance(g8_destination_still_retreat, support, 8).
provenance(g8_destination_still_retreat, kept, 2).
provenance(g8_destination_still_retreat, confidence_permille, 577).
provenance(g8_destination_still_retreat, antecedent, a63).
rule(g0_destination_still_settle, defeasible, destination_still_settle).
learned(g0_destination_still_settle).
provenance(g0_destination_still_settle, layer, general).
provenance(g0_destination_still_settle, level, 0).
provenance(g0_destination_still_settle, support, 15).
provenance(g0_destination_still_settle, kept, 15).
provenance(g0_destination_still_settle, confidence_permille, 999).
provenance(g0_destination_still_settle, antecedent, a1).
rule(g1_destination_still_settle, defeasible, destination_still_settle).
body(g1_destination_still_settle, pour_below_rim).
learned(g1_destination_still_settle).
provenance(g1_destination_still_settle, layer, general).
provenance(g1_destination_still_settle, level, 1).
provenance(g1_destination_still_settle, support, 16).
provenance(g1_destination_still_settle, kept, 9).
provenance(g1_destination_still_settle, confidence_permille, 871).
provenance(g1_destination_still_settle, antecedent, a4).
rule(g0_destination_upright, defeasible, destination_upright).
learned(g0_destination_upright).
provenance(g0_destination_upright, layer, general).
provenance(g0_destination_upright, level, 0).
provenance(g0_destination_upright, support, 15).
provenance(g0_destination_upright, kept, 15).
provenance(g0_destination_upright, confidence_permille, 999).
provenance(g0_destination_upright, antecedent, a1).
rule(g1_destination_upright, defeasible, destination_upright).
body(g1_destination_upright, pour_below_rim).
learned(g1_destination_upright).
provenance(g1_destination_upright, layer, general).
provenance(g1_destination_upright, level, 1).
provenance(g1_destination_upright, support, 16).
provenance(g1_destination_upright, kept, 10).
provenance(g1_destination_upright, confidence_permille, 851).
provenance(g1_destination_upright, antecedent, a4).
rule(g0_source_clear, defeasible, source_clear).
learned(g0_source_clear).
provenance(g0_source_clear, layer, general).
provenance(g0_source_clear, level, 0).
provenance(g0_source_clear, support, 15).
provenance(g0_source_clear, kept, 15).
provenance(g0_source_clear, confidence_permille, 974).
provenance(g0_source_clear, antecedent, a1).
rule(g1_source_clear, defeasible, neg(source_clear)).
body(g1_source_clear, pour_below_rim).
learned(g1_source_clear).
provenance(g1_source_clear, layer, general).
provenance(g1_source_clear, level, 1).
provenance(g1_source_clear, support, 16).
provenance(g1_source_clear, kept, 16).
provenance(g1_source_clear, confidence_permille, 999).
provenance(g1_source_clear, antecedent, a4).
rule(g2_source_clear, defeasible, neg(source_clear)).
body(g2_source_clear, pour_low).
learned(g2_source_clear).
provenance(g2_source_clear, layer, general).
provenance(g2_source_clear, level, 1).
provenance(g2_source_clear, support, 7).
provenance(g2_source_clear, kept, 2).
provenance(g2_source_clear, confidence_permille, 624).
provenance(g2_source_clear, antecedent, a5).
rule(g3_source_clear, defeasible, source_clear).
body(g3_source_clear, pour_below_rim).
body(g3_source_clear, pour_far_away).
learned(g3_source_clear).
provenance(g3_source_clear, layer, general).
provenance(g3_source_clear, level, 2).
provenance(g3_source_clear, support, 12).
provenance(g3_source_clear, kept, 12).
provenance(g3_source_clear, confidence_permille, 996).
provenance(g3_source_clear, antecedent, a15).
rule(g4_source_clear, defeasible, source_clear).
body(g4_source_clear, start_below_rim).
learned(g4_source_clear).
provenance(g4_source_clear, layer, general).
provenance(g4_source_clear, level, 1).
provenance(g4_source_clear, support, 4).
provenance(g4_source_clear, kept, 0).
provenance(g4_source_clear, confidence_permille, 681).
provenance(g4_source_clear, antecedent, a2).
rule(g0_liquid_leaves_source, defeasible, liquid_leaves_source).
learned(g0_liquid_leaves_source).
provenance(g0_liquid_leaves_source, layer, general).
provenance(g0_liquid_leaves_source, level, 0).
provenance(g0_liquid_leaves_source, support, 15).
provenance(g0_liquid_leaves_source, kept, 15).
provenance(g0_liquid_leaves_source, confidence_permille, 1000).
provenance(g0_liquid_leaves_source, antecedent, a1).
rule(g1_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g1_liquid_leaves_source, pour_half_tilted).
learned(g1_liquid_leaves_source).
provenance(g1_liquid_leaves_source, layer, general).
provenance(g1_liquid_leaves_source, level, 1).
provenance(g1_liquid_leaves_source, support, 4).
provenance(g1_liquid_leaves_source, kept, 4).
provenance(g1_liquid_leaves_source, confidence_permille, 1000).
provenance(g1_liquid_leaves_source, antecedent, a33).
rule(g2_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g2_liquid_leaves_source, pour_upright).
learned(g2_liquid_leaves_source).
provenance(g2_liquid_leaves_source, layer, general).
provenance(g2_liquid_leaves_source, level, 1).
provenance(g2_liquid_leaves_source, support, 4).
provenance(g2_liquid_leaves_source, kept, 4).
provenance(g2_liquid_leaves_source, confidence_permille, 1000).
provenance(g2_liquid_leaves_source, antecedent, a28).
rule(g3_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g3_liquid_leaves_source, pour_slightly_tilted).
learned(g3_liquid_leaves_source).
provenance(g3_liquid_leaves_source, layer, general).
provenance(g3_liquid_leaves_source, level, 1).
provenance(g3_liquid_leaves_source, support, 4).
provenance(g3_liquid_leaves_source, kept, 4).
provenance(g3_liquid_leaves_source, confidence_permille, 1000).
provenance(g3_liquid_leaves_source, antecedent, a31).
rule(g4_liquid_leaves_source, defeasible, neg(liquid_leaves_source)).
body(g4_liquid_leaves_source, pour_tilted_back).
learned(g4_liquid_leaves_source).
provenance(g4_liquid_leaves_source, layer, general).
provenance(g4_liquid_leaves_source, level, 1).
provenance(g4_liquid_leaves_source, support, 4).
provenance(g4_liquid_leaves_source, kept, 4).
provenance(g4_liquid_leaves_source, confidence_permille, 1000).
provenance(g4_liquid_leaves_source, antecedent, a32).
rule(g0_liquid_enters_destination, defeasible, liquid_enters_destination).
learned(g0_liquid_enters_destination).
provenance(g0_liquid_enters_destination, layer, general).
provenance(g0_liquid_enters_destination, level, 0).
provenance(g0_liquid_enters_destination, support, 15).
provenance(g0_liquid_enters_destination, kept, 15).
provenance(g0_liquid_enters_destination, confidence_permille, 938).
provenance(g0_liquid_enters_destination, antecedent, a1).
rule(g1_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g1_liquid_enters_destination, pour_offset_sideways).
learned(g1_liquid_enters_destination).
provenance(g1_liquid_enters_destination, layer, general).
provenance(g1_liquid_enters_destination, level, 1).
provenance(g1_liquid_enters_destination, support, 4).
provenance(g1_liquid_enters_destination, kept, 3).
provenance(g1_liquid_enters_destination, confidence_permille, 718).
provenance(g1_liquid_enters_destination, antecedent, a66).
rule(g2_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g2_liquid_enters_destination, pour_to_side).
learned(g2_liquid_enters_destination).
provenance(g2_liquid_enters_destination, layer, general).
provenance(g2_liquid_enters_destination, level, 1).
provenance(g2_liquid_enters_destination, support, 4).
provenance(g2_liquid_enters_destination, kept, 4).
provenance(g2_liquid_enters_destination, confidence_permille, 916).
provenance(g2_liquid_enters_destination, antecedent, a11).
rule(g3_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g3_liquid_enters_destination, pour_half_tilted).
learned(g3_liquid_enters_destination).
provenance(g3_liquid_enters_destination, layer, general).
provenance(g3_liquid_enters_destination, level, 1).
provenance(g3_liquid_enters_destination, support, 4).
provenance(g3_liquid_enters_destination, kept, 4).
provenance(g3_liquid_enters_destination, confidence_permille, 810).
provenance(g3_liquid_enters_destination, antecedent, a33).
rule(g4_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g4_liquid_enters_destination, pour_far_away).
learned(g4_liquid_enters_destination).
provenance(g4_liquid_enters_destination, layer, general).
provenance(g4_liquid_enters_destination, level, 1).
provenance(g4_liquid_enters_destination, support, 4).
provenance(g4_liquid_enters_destination, kept, 4).
provenance(g4_liquid_enters_destination, confidence_permille, 977).
provenance(g4_liquid_enters_destination, antecedent, a10).
rule(g5_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g5_liquid_enters_destination, pour_upright).
learned(g5_liquid_enters_destination).
provenance(g5_liquid_enters_destination, layer, general).
provenance(g5_liquid_enters_destination, level, 1).
provenance(g5_liquid_enters_destination, support, 4).
provenance(g5_liquid_enters_destination, kept, 4).
provenance(g5_liquid_enters_destination, confidence_permille, 872).
provenance(g5_liquid_enters_destination, antecedent, a28).
rule(g6_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g6_liquid_enters_destination, pour_tilted_back).
learned(g6_liquid_enters_destination).
provenance(g6_liquid_enters_destination, layer, general).
provenance(g6_liquid_enters_destination, level, 1).
provenance(g6_liquid_enters_destination, support, 4).
provenance(g6_liquid_enters_destination, kept, 4).
provenance(g6_liquid_enters_destination, confidence_permille, 920).
provenance(g6_liquid_enters_destination, antecedent, a32).
rule(g7_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g7_liquid_enters_destination, pour_slightly_tilted).
learned(g7_liquid_enters_destination).
provenance(g7_liquid_enters_destination, layer, general).
provenance(g7_liquid_enters_destination, level, 1).
provenance(g7_liquid_enters_destination, support, 4).
provenance(g7_liquid_enters_destination, kept, 4).
provenance(g7_liquid_enters_destination, confidence_permille, 831).
provenance(g7_liquid_enters_destination, antecedent, a31).
rule(g8_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g8_liquid_enters_destination, pour_below_rim).
learned(g8_liquid_enters_destination).
provenance(g8_liquid_enters_destination, layer, general).
provenance(g8_liquid_enters_destination, level, 1).
provenance(g8_liquid_enters_destination, support, 16).
provenance(g8_liquid_enters_destination, kept, 11).
provenance(g8_liquid_enters_destination, confidence_permille, 807).
provenance(g8_liquid_enters_destination, antecedent, a4).
rule(g9_liquid_enters_destination, defeasible, neg(liquid_enters_destination)).
body(g9_liquid_enters_destination, pour_below_rim).
body(g9_liquid_enters_destination, pour_offset_sideways).
learned(g9_liquid_enters_destination).
provenance(g9_liquid_enters_destination, layer, general).
provenance(g9_liquid_enters_destination, level, 2).
provenance(g9_liquid_enters_destination, support, 12).
provenance(g9_liquid_enters_destination, kept, 9).
provenance(g9_liquid_enters_destination, confidence_permille, 725).
provenance(g9_liquid_enters_destination, antecedent, a67).
rule(g10_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g10_liquid_enters_destination, pour_below_rim).
body(g10_liquid_enters_destination, pour_slightly_tilted).
learned(g10_liquid_enters_destination).
provenance(g10_liquid_enters_destination, layer, general).
provenance(g10_liquid_enters_destination, level, 2).
provenance(g10_liquid_enters_destination, support, 12).
provenance(g10_liquid_enters_destination, kept, 10).
provenance(g10_liquid_enters_destination, confidence_permille, 680).
provenance(g10_liquid_enters_destination, antecedent, a36).
rule(g11_liquid_enters_destination, defeasible, liquid_enters_destination).
body(g11_liquid_enters_destination, pour_below_rim).
body(g11_liquid_enters_destination, pour_upright).
learned(g11_liquid_enters_destination).
provenance(g11_liquid_enters_destination, layer, general).
provenance(g11_liquid_enters_destination, level, 2).
provenance(g11_liquid_enters_destination, support, 12).
provenance(g11_liquid_enters_destination, kept, 10).
provenance(g11_liquid_enters_destination, confidence_permille, 630).
provenance(g11_liquid_enters_destination, antecedent, a37).
rule(g0_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
learned(g0_liquid_remains_in_destination).
provenance(g0_liquid_remains_in_destination, layer, general).
provenance(g0_liquid_remains_in_destination, level, 0).
provenance(g0_liquid_remains_in_destination, support, 15).
provenance(g0_liquid_remains_in_destination, kept, 15).
provenance(g0_liquid_remains_in_destination, confidence_permille, 999).
provenance(g0_liquid_remains_in_destination, antecedent, a1).
rule(g1_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g1_liquid_remains_in_destination, pour_below_rim).
learned(g1_liquid_remains_in_destination).
provenance(g1_liquid_remains_in_destination, layer, general).
provenance(g1_liquid_remains_in_destination, level, 1).
provenance(g1_liquid_remains_in_destination, support, 16).
provenance(g1_liquid_remains_in_destination, kept, 9).
provenance(g1_liquid_remains_in_destination, confidence_permille, 710).
provenance(g1_liquid_remains_in_destination, antecedent, a4).
rule(g2_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g2_liquid_remains_in_destination, pour_below_rim).
body(g2_liquid_remains_in_destination, pour_upright).
learned(g2_liquid_remains_in_destination).
provenance(g2_liquid_remains_in_destination, layer, general).
provenance(g2_liquid_remains_in_destination, level, 2).
provenance(g2_liquid_remains_in_destination, support, 12).
provenance(g2_liquid_remains_in_destination, kept, 9).
provenance(g2_liquid_remains_in_destination, confidence_permille, 722).
provenance(g2_liquid_remains_in_destination, antecedent, a37).
rule(g3_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g3_liquid_remains_in_destination, pour_below_rim).
body(g3_liquid_remains_in_destination, pour_slightly_tilted).
learned(g3_liquid_remains_in_destination).
provenance(g3_liquid_remains_in_destination, layer, general).
provenance(g3_liquid_remains_in_destination, level, 2).
provenance(g3_liquid_remains_in_destination, support, 12).
provenance(g3_liquid_remains_in_destination, kept, 11).
provenance(g3_liquid_remains_in_destination, confidence_permille, 711).
provenance(g3_liquid_remains_in_destination, antecedent, a36).
rule(g4_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g4_liquid_remains_in_destination, pour_below_rim).
body(g4_liquid_remains_in_destination, pour_tilted_back).
learned(g4_liquid_remains_in_destination).
provenance(g4_liquid_remains_in_destination, layer, general).
provenance(g4_liquid_remains_in_destination, level, 2).
provenance(g4_liquid_remains_in_destination, support, 12).
provenance(g4_liquid_remains_in_destination, kept, 7).
provenance(g4_liquid_remains_in_destination, confidence_permille, 639).
provenance(g4_liquid_remains_in_destination, antecedent, a39).
rule(g5_liquid_remains_in_destination, defeasible, neg(liquid_remains_in_destination)).
body(g5_liquid_remains_in_destination, pour_below_rim).
body(g5_liquid_remains_in_destination, pour_half_tilted).
learned(g5_liquid_remains_in_destination).
provenance(g5_liquid_remains_in_destination, layer, general).
provenance(g5_liquid_remains_in_destination, level, 2).
provenance(g5_liquid_remains_in_destination, support, 16).
provenance(g5_liquid_remains_in_destination, kept, 14).
provenance(g5_liquid_remains_in_destination, confidence_permille, 632).
provenance(g5_liquid_remains_in_destination, antecedent, a38).
rule(g6_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g6_liquid_remains_in_destination, pour_below_rim).
body(g6_liquid_remains_in_destination, pour_upside_down).
learned(g6_liquid_remains_in_destination).
provenance(g6_liquid_remains_in_destination, layer, general).
provenance(g6_liquid_remains_in_destination, level, 1).
provenance(g6_liquid_remains_in_destination, support, 10).
provenance(g6_liquid_remains_in_destination, kept, 5).
provenance(g6_liquid_remains_in_destination, confidence_permille, 560).
provenance(g6_liquid_remains_in_destination, antecedent, a130).
rule(g7_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g7_liquid_remains_in_destination, approach_moving_away).
body(g7_liquid_remains_in_destination, pour_below_rim).
learned(g7_liquid_remains_in_destination).
provenance(g7_liquid_remains_in_destination, layer, general).
provenance(g7_liquid_remains_in_destination, level, 1).
provenance(g7_liquid_remains_in_destination, support, 10).
provenance(g7_liquid_remains_in_destination, kept, 6).
provenance(g7_liquid_remains_in_destination, confidence_permille, 565).
provenance(g7_liquid_remains_in_destination, antecedent, a145).
rule(g8_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g8_liquid_remains_in_destination, pour_below_rim).
body(g8_liquid_remains_in_destination, start_near_rim).
learned(g8_liquid_remains_in_destination).
provenance(g8_liquid_remains_in_destination, layer, general).
provenance(g8_liquid_remains_in_destination, level, 1).
provenance(g8_liquid_remains_in_destination, support, 8).
provenance(g8_liquid_remains_in_destination, kept, 6).
provenance(g8_liquid_remains_in_destination, confidence_permille, 576).
provenance(g8_liquid_remains_in_destination, antecedent, a89).
rule(g9_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g9_liquid_remains_in_destination, pour_below_rim).
body(g9_liquid_remains_in_destination, very_much_liquid).
learned(g9_liquid_remains_in_destination).
provenance(g9_liquid_remains_in_destination, layer, general).
provenance(g9_liquid_remains_in_destination, level, 1).
provenance(g9_liquid_remains_in_destination, support, 8).
provenance(g9_liquid_remains_in_destination, kept, 6).
provenance(g9_liquid_remains_in_destination, confidence_permille, 628).
provenance(g9_liquid_remains_in_destination, antecedent, a74).
rule(g10_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g10_liquid_remains_in_destination, fast_approach).
body(g10_liquid_remains_in_destination, pour_below_rim).
learned(g10_liquid_remains_in_destination).
provenance(g10_liquid_remains_in_destination, layer, general).
provenance(g10_liquid_remains_in_destination, level, 1).
provenance(g10_liquid_remains_in_destination, support, 8).
provenance(g10_liquid_remains_in_destination, kept, 4).
provenance(g10_liquid_remains_in_destination, confidence_permille, 637).
provenance(g10_liquid_remains_in_destination, antecedent, a48).
rule(g11_liquid_remains_in_destination, defeasible, liquid_remains_in_destination).
body(g11_liquid_remains_in_destination, bouncy_liquid).
body(g11_liquid_remains_in_destination, pour_below_rim).
learned(g11_liquid_remains_in_destination).
provenance(g11_liquid_remains_in_destination, layer, general).
provenance(g11_liquid_remains_in_destination, level, 1).
provenance(g11_liquid_remains_in_destination, support, 8).
provenance(g11_liquid_remains_in_destination, kept, 4).
provenance(g11_liquid_remains_in_destination, confidence_permille, 638).
provenance(g11_liquid_remains_in_destination, antecedent, a51).
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, layer, general).
provenance(g0_no_spill, level, 0).
provenance(g0_no_spill, support, 15).
provenance(g0_no_spill, kept, 15).
provenance(g0_no_spill, confidence_permille, 970).
provenance(g0_no_spill, antecedent, a1).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, pour_below_rim).
learned(g1_no_spill).
provenance(g1_no_spill, layer, general).
provenance(g1_no_spill, level, 1).
provenance(g1_no_spill, support, 16).
provenance(g1_no_spill, kept, 11).
provenance(g1_no_spill, confidence_permille, 520).
provenance(g1_no_spill, antecedent, a4).
rule(g2_no_spill, defeasible, neg(no_spill)).
body(g2_no_spill, pour_offset_sideways).
learned(g2_no_spill).
provenance(g2_no_spill, layer, general).
provenance(g2_no_spill, level, 1).
provenance(g2_no_spill, support, 4).
provenance(g2_no_spill, kept, 3).
provenance(g2_no_spill, confidence_permille, 702).
provenance(g2_no_spill, antecedent, a66).
rule(g3_no_spill, defeasible, neg(no_spill)).
body(g3_no_spill, pour_to_side).
learned(g3_no_spill).
provenance(g3_no_spill, layer, general).
provenance(g3_no_spill, level, 1).
provenance(g3_no_spill, support, 4).
provenance(g3_no_spill, kept, 4).
provenance(g3_no_spill, confidence_permille, 909).
provenance(g3_no_spill, antecedent, a11).
rule(g4_no_spill, defeasible, neg(no_spill)).
body(g4_no_spill, pour_far_away).
learned(g4_no_spill).
provenance(g4_no_spill, layer, general).
provenance(g4_no_spill, level, 1).
provenance(g4_no_spill, support, 4).
provenance(g4_no_spill, kept, 4).
provenance(g4_no_spill, confidence_permille, 973).
provenance(g4_no_spill, antecedent, a10).
rule(g5_no_spill, defeasible, no_spill).
body(g5_no_spill, pour_half_tilted).
learned(g5_no_spill).
provenance(g5_no_spill, layer, general).
provenance(g5_no_spill, level, 1).
provenance(g5_no_spill, support, 4).
provenance(g5_no_spill, kept, 4).
provenance(g5_no_spill, confidence_permille, 999).
provenance(g5_no_spill, antecedent, a33).
rule(g6_no_spill, defeasible, no_spill).
body(g6_no_spill, pour_slightly_tilted).
learned(g6_no_spill).
provenance(g6_no_spill, layer, general).
provenance(g6_no_spill, level, 1).
provenance(g6_no_spill, support, 4).
provenance(g6_no_spill, kept, 4).
provenance(g6_no_spill, confidence_permille, 999).
provenance(g6_no_spill, antecedent, a31).
rule(g7_no_spill, defeasible, no_spill).
body(g7_no_spill, pour_upright).
learned(g7_no_spill).
provenance(g7_no_spill, layer, general).
provenance(g7_no_spill, level, 1).
provenance(g7_no_spill, support, 4).
provenance(g7_no_spill, kept, 4).
provenance(g7_no_spill, confidence_permille, 999).
provenance(g7_no_spill, antecedent, a28).
rule(g8_no_spill, defeasible, no_spill).
body(g8_no_spill, pour_tilted_back).
learned(g8_no_spill).
provenance(g8_no_spill, layer, general).
provenance(g8_no_spill, level, 1).
provenance(g8_no_spill, support, 4).
provenance(g8_no_spill, kept, 4).
provenance(g8_no_spill, confidence_permille, 999).
provenance(g8_no_spill, antecedent, a32).
rule(g9_no_spill, defeasible, no_spill).
body(g9_no_spill, pour_below_rim).
body(g9_no_spill, pour_steeply_tilted).
learned(g9_no_spill).
provenance(g9_no_spill, layer, general).
provenance(g9_no_spill, level, 2).
provenance(g9_no_spill, support, 18).
provenance(g9_no_spill, kept, 11).
provenance(g9_no_spill, confidence_permille, 692).
provenance(g9_no_spill, antecedent, a115).
rule(g10_no_spill, defeasible, neg(no_spill)).
body(g10_no_spill, grippy_destination).
body(g10_no_spill, pour_offset_sideways).
learned(g10_no_spill).
provenance(g10_no_spill, layer, general).
provenance(g10_no_spill, level, 1).
provenance(g10_no_spill, support, 4).
provenance(g10_no_spill, kept, 3).
provenance(g10_no_spill, confidence_permille, 583).
provenance(g10_no_spill, antecedent, a146).
rule(g11_no_spill, defeasible, neg(no_spill)).
body(g11_no_spill, fast_retreat).
body(g11_no_spill, pour_offset_sideways).
learned(g11_no_spill).
provenance(g11_no_spill, layer, general).
provenance(g11_no_spill, level, 1).
provenance(g11_no_spill, support, 4).
provenance(g11_no_spill, kept, 2).
provenance(g11_no_spill, confidence_permille, 587).
provenance(g11_no_spill, antecedent, a112).
sup(g10_liquid_enters_destination, g1_liquid_enters_destination).
sup(g10_liquid_enters_destination, g4_liquid_enters_destination).
sup(g10_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g10_no_spill, g5_no_spill).
sup(g10_no_spill, g6_no_spill).
sup(g10_no_spill, g7_no_spill).
sup(g10_no_spill, g8_no_spill).
sup(g11_liquid_enters_destination, g1_liquid_enters_destination).
sup(g11_liquid_enters_destination, g4_liquid_enters_destination).
sup(g11_liquid_remains_in_destination, g5_liquid_remains_in_destination).
sup(g11_no_spill, g5_no_spill).
sup(g11_no_spill, g6_no_spill).
sup(g11_no_spill, g7_no_spill).
sup(g11_no_spill, g8_no_spill).
sup(g1_destination_still_approach, g4_destination_still_approach).
sup(g1_source_clear, g4_source_clear).
sup(g2_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g2_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g2_liquid_remains_in_destination, g7_liquid_remains_in_destination).
sup(g2_liquid_remains_in_destination, g8_liquid_remains_in_destination).
sup(g2_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g3_destination_still_approach, g1_destination_still_approach).
sup(g3_destination_still_retreat, g6_destination_still_retreat).
sup(g3_destination_still_retreat, g7_destination_still_retreat).
sup(g3_destination_still_retreat, g8_destination_still_retreat).
sup(g3_liquid_enters_destination, g8_liquid_enters_destination).
sup(g3_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g3_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g3_liquid_remains_in_destination, g7_liquid_remains_in_destination).
sup(g3_liquid_remains_in_destination, g8_liquid_remains_in_destination).
sup(g3_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g4_liquid_enters_destination, g8_liquid_enters_destination).
sup(g4_liquid_remains_in_destination, g10_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g11_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g7_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g8_liquid_remains_in_destination).
sup(g4_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g4_source_clear, g2_source_clear).
sup(g5_liquid_enters_destination, g8_liquid_enters_destination).
sup(g5_liquid_remains_in_destination, g7_liquid_remains_in_destination).
sup(g5_liquid_remains_in_destination, g8_liquid_remains_in_destination).
sup(g5_liquid_remains_in_destination, g9_liquid_remains_in_destination).
sup(g5_no_spill, g1_no_spill).
sup(g5_no_spill, g2_no_spill).
sup(g5_no_spill, g3_no_spill).
sup(g5_no_spill, g4_no_spill).
sup(g6_liquid_enters_destination, g8_liquid_enters_destination).
sup(g6_no_spill, g1_no_spill).
sup(g6_no_spill, g2_no_spill).
sup(g6_no_spill, g3_no_spill).
sup(g6_no_spill, g4_no_spill).
sup(g7_liquid_enters_destination, g8_liquid_enters_destination).
sup(g7_no_spill, g1_no_spill).
sup(g7_no_spill, g2_no_spill).
sup(g7_no_spill, g3_no_spill).
sup(g7_no_spill, g4_no_spill).
sup(g8_destination_still_retreat, g4_destination_still_retreat).
sup(g8_destination_still_retreat, g5_destination_still_retreat).
sup(g8_liquid_enters_destination, g1_liquid_enters_destination).
sup(g8_no_spill, g1_no_spill).
sup(g8_no_spill, g2_no_spill).
sup(g8_no_spill, g3_no_spill).
sup(g8_no_spill, g4_no_spill).
sup(g9_liquid_enters_destination, g10_liquid_enters_destination).
sup(g9_liquid_enters_destination, g11_liquid_enters_destination).
sup(g9_no_spill, g10_no_spill).
sup(g9_no_spill, g11_no_spill).
sup(g9_no_spill, g2_no_spill).
sup(g9_no_spill, g4_no_spill).
