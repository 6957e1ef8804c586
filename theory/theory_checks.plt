:- begin_tests(theory_checks).

:- use_module(theory_checks).

% a theory Python read (a DFL file) is checked as a file read as written,
% at the lines Python read its facts: a body another rule concludes, a
% head another rule uses and a negated literal's name are the theory's own
% words; rows of provenance and sup name no literal
test(unknown_names_of_rows, [true(Us == [[3, "rule c2: body", "wet"], [4, "fact", "lihgt_liquid"],
                                         [5, "rule c3: head", "spilled"]])]) :-
    unknown_names([[2, rule, c1, "wet_table"], [2, body, c1, "pour_to_side"],
                   [3, rule, c2, "neg(no_spill)"], [3, body, c2, "wet_table"], [3, body, c2, "wet"],
                   [5, rule, c3, "neg(spilled)"], [5, body, c3, "pour_low"],
                   [4, fact, '', "lihgt_liquid"], [6, provenance, c1, layer], [7, sup, c1, c3]], Us).

% a stand-in's facts at the lines of the file it stands for, the first of
% each; a fact no written_at/4 places at line 0
test(written_lines, [true(W == [9-rule(g1, defeasible, wet), 9-body(g1, pour_to_side),
                                12-provenance(g1, layer, general), 0-provenance(g1, kept, 3)])]) :-
    written_lines([1-rule(g1, defeasible, wet), 2-body(g1, pour_to_side),
                   3-provenance(g1, layer, general), 4-provenance(g1, kept, 3), 5-fact(a),
                   6-written_at(9, rule, g1, wet), 7-written_at(9, body, g1, pour_to_side),
                   8-written_at(14, provenance, g1, layer), 9-written_at(12, provenance, g1, layer)],
                  W).

% a general rule's head must be an expectation: said at the rule's line
test(general_head, [throws(theory_error('G', 4, "general rule g1: wet is not an expectation"))]) :-
    check_general_rules('G', [4-rule(g1, defeasible, neg(wet)), 5-provenance(g1, layer, general)]).

% the evidence of a general rule: the last value of each key, said at the
% line of its first fact
test(general_confidence, [throws(theory_error('G', 2, "general rule g1: a confidence in permille is 0 to 1000, not 2000"))]) :-
    check_general_rules('G', [1-rule(g1, defeasible, no_spill), 2-provenance(g1, confidence_permille, 500),
                              3-provenance(g1, layer, general), 4-provenance(g1, confidence_permille, 2000)]).

% a rule of no general layer is not checked
test(not_general) :-
    check_general_rules('G', [1-rule(r1, defeasible, wet), 2-body(r1, pour_sideways)]).

:- end_tests(theory_checks).
