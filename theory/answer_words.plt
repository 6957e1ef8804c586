:- begin_tests(answer_words).

:- use_module(plunit_helpers).

:- use_module(defeasible).
:- use_module(answer_words).

% the rule to name: the general rule of the same body and head
test(named_rule_is_the_general_twin, [true(N-G == g1-g2)]) :-
    once(load_theory_text("rule(r1, defeasible, no_spill).\nbody(r1, pour_to_side).\nrule(g1, defeasible, no_spill).\nbody(g1, pour_to_side).\nprovenance(g1, layer, general).\nrule(g2, defeasible, no_spill).\nprovenance(g2, layer, general).\n")),
    defeasible:theory_loaded,
    named_rule(r1, N),
    named_rule(g2, G).

% one voice: the likelihood that the expectation holds, and the pours of
% the body counted for it holding (of a rule for its failure, the pours
% that did not keep the head)
test(rule_in_words,
     [true(T == "pour from the side: holds in 12% of such pours (the pooled estimate); held in 7 of 8 pours of pour from the side (rule g1)")]) :-
    once(load_theory_text("rule(g1, defeasible, neg(no_spill)).\nbody(g1, pour_to_side).\nprovenance(g1, layer, general).\nprovenance(g1, confidence_permille, 875).\nprovenance(g1, support, 8).\nprovenance(g1, kept, 1).\n")),
    defeasible:theory_loaded,
    rule_in_words(g1, T).

% a rule the learner wrote where it doubted its parts' answer says why:
% beside the explored pair whose pours depart from its parts'
test(rule_in_words_beside_an_interaction,
     [true(T == "pour centred over the destination, pour high above the destination: holds in 65% of such pours (the pooled estimate); maybe: beside pour centred over the destination, pour very high above the destination, whose pours depart from what its parts do, and too few of its own pours tell; no such pour simulated: estimated from the pours nearby (rule g1)")]) :-
    once(load_theory_text("rule(g1, defeasible, no_spill).\nbody(g1, pour_centred).\nbody(g1, pour_high).\nprovenance(g1, layer, general).\nprovenance(g1, confidence_permille, 650).\nprovenance(g1, support, 0).\nprovenance(g1, kept, 0).\nprovenance(g1, doubt, beside_interaction).\nprovenance(g1, beside, pour_centred).\nprovenance(g1, beside, pour_very_high).\n")),
    defeasible:theory_loaded,
    rule_in_words(g1, T).

test(rule_in_words_where_the_parts_disagree,
     [true(sub_string(T, _, _, _, "(the pooled estimate); maybe: the rules of its parts disagree, and too few of its own pours tell;"))]) :-
    once(load_theory_text("rule(g1, defeasible, no_spill).\nbody(g1, pour_centred).\nbody(g1, light_liquid).\nprovenance(g1, layer, general).\nprovenance(g1, confidence_permille, 600).\nprovenance(g1, support, 2).\nprovenance(g1, kept, 1).\nprovenance(g1, doubt, unsettled).\n")),
    defeasible:theory_loaded,
    rule_in_words(g1, T).

% a pair whose one pour departs from its parts' sure answer
test(rule_in_words_where_few_pours_depart,
     [true(sub_string(T, _, _, _, "(the pooled estimate); maybe: too few of its own pours tell, and each of them departs from what the rules of its parts say;"))]) :-
    once(load_theory_text("rule(g1, defeasible, no_spill).\nbody(g1, pour_centred).\nbody(g1, pour_high).\nprovenance(g1, layer, general).\nprovenance(g1, confidence_permille, 648).\nprovenance(g1, support, 1).\nprovenance(g1, kept, 0).\nprovenance(g1, doubt, few_pours_depart).\n")),
    defeasible:theory_loaded,
    rule_in_words(g1, T).

test(rule_in_words_of_the_empty_body,
     [true(T == "an ordinary pour: holds in 90% of such pours (the pooled estimate); the weighted pours of a0 (rule r0)")]) :-
    once(load_theory_text("rule(r0, defeasible, no_spill).\nprovenance(r0, confidence_permille, 900).\nprovenance(r0, antecedent, a0).\n")),
    defeasible:theory_loaded,
    rule_in_words(r0, T).

test(answers_say_why, [true(B-R-Ev == "given"-""-none)]) :-
    once(load_theory_text("fact(no_spill).\n")),
    answers([], [], As),
    memberchk(answer(no_spill, holds, _, _, B, R, Ev), As).

test(answers_say_why_not, [true(sub_string(B, 0, _, _, "why not: "))]) :-
    once(load_theory_text("fact(no_spill).\n")),
    answers([], [], As),
    memberchk(answer(source_clear, unknown, none, none, B, _, none), As).

% the evidence of a holding head counts the pours that kept it; a scene's
% proposition that the deciding rule's body does not hold is said
test(answers_count_pours_for_the_expectation_holding,
     [true(Ev-Ws == pours(50, 60, [], [light_liquid])-"an ordinary pour: holds in 90% of such pours (the pooled estimate); held in 50 of 60 ordinary pours (rule g0); a light liquid: no rule of its own decides this, so it is answered as an ordinary pour")]) :-
    once(load_theory_text("rule(g0, defeasible, no_spill).\nlearned(g0).\nprovenance(g0, support, 60).\nprovenance(g0, kept, 50).\nprovenance(g0, confidence_permille, 900).\n")),
    answers([light_liquid], [], As),
    memberchk(answer(no_spill, holds, _, g0, B, _, Ev), As),
    sub_string(B, 8, _, 0, Ws).

% a proof as a structure: the deciding rule, its body's proofs, and the
% rules against it with why each loses
test(proof_json, [true(K-R-Kinds == defeasible-g1-[beaten])]) :-
    once(load_theory_text("rule(g0, defeasible, no_spill).\nlearned(g0).\nrule(g1, defeasible, neg(no_spill)).\nbody(g1, pour_to_side).\nlearned(g1).\n")),
    queries:why([pour_to_side], neg(no_spill), [], Proof),
    proof_json(Proof, D),
    K = D.kind, R = D.rule,
    findall(X, ( member(Reb, D.rebuttals), X = Reb.kind ), Kinds).

% a scene that is an explored antecedent without a rule of its own: the
% pours cited are its own (held/4), for the expectation holding, and the
% words say whether they agree with the rule that decides
explored_theory("rule(g0, defeasible, neg(no_spill)).\nprovenance(g0, layer, general).\nprovenance(g0, confidence_permille, 900).\nprovenance(g0, support, 20).\nprovenance(g0, kept, 18).\nexplored(a2, light_liquid).\nheld(a2, no_spill, 1, 8).\nexplored(a3, heavy_liquid).\nheld(a3, no_spill, 7, 8).\n").

test(evidence_of_an_explored_antecedent,
     [true(Ev-Ev0 == explored(a2, [light_liquid], 1, 8, [], [light_liquid])-pours(2, 20, [], [pour_centred]))]) :-
    explored_theory(T),
    once(load_theory_text(T)),
    defeasible:theory_loaded,
    evidence(g0, no_spill, [light_liquid], Ev),
    evidence(g0, no_spill, [pour_centred], Ev0).

test(answers_cite_the_pours_of_an_explored_antecedent,
     [true(B-B2 == "because an ordinary pour: holds in 10% of such pours (the pooled estimate); held in 1 of 8 pours of a light liquid (explored, no rule of its own: its pours agree with rule g0)"-"because an ordinary pour: holds in 10% of such pours (the pooled estimate); held in 7 of 8 pours of a heavy liquid (explored, no rule of its own: rule g0 decides, though its pours differ)")]) :-
    explored_theory(T),
    once(load_theory_text(T)),
    answers([light_liquid], [], As),
    memberchk(answer(no_spill, fails, _, g0, B, _, _), As),
    answers([heavy_liquid], [], As2),
    memberchk(answer(no_spill, fails, _, g0, B2, _, _), As2).

:- end_tests(answer_words).
