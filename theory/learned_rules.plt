:- use_module(learned_rules).

:- begin_tests(learned_rules).

higher(A, B) :-
    rank_key(A, KA), rank_key(B, KB), KA @> KB.

test(the_larger_body_ranks_higher) :-
    higher(rule(r2, 2, rule, 0.51), rule(g1, 1, general, 1.0)).

test(of_equal_bodies_the_general_layer_ranks_higher) :-
    higher(rule(g0, 0, general, 0.51), rule(r1, 0, rule, 0.99)).

test(then_the_surer) :-
    higher(rule(g2, 1, general, 0.1), rule(g1, 1, general, 0.8)).

test(then_the_id) :-
    higher(rule(g2, 1, general, 0.8), rule(g10, 1, general, 0.8)).

test(a_confidence_and_its_complement_are_equally_sure) :-
    forall(between(0, 1000, C),
           ( P is C / 1000, Q is 1 - P,
             rank_key(rule(r, 1, general, P), k(_, _, D, _)),
             rank_key(rule(r, 1, general, Q), k(_, _, D, _)),
             D =:= abs(C - 500) * 1000000 )).

test(no_confidence_is_as_unsure_as_one_half, D-E == 0-0) :-
    rank_key(rule(r, 1, rule, none), k(_, _, D, _)),
    rank_key(rule(r, 1, rule, 0.5), k(_, _, E, _)).

test(distance_rounds_half_to_even, D-E == 976562-2929688) :-
    P is 0.5 + 1 / 1024,            % 0.0009765625 from one half
    rank_key(rule(r, 0, rule, P), k(_, _, D, _)),
    Q is 0.5 - 3 / 1024,            % 0.0029296875 from one half
    rank_key(rule(r, 0, rule, Q), k(_, _, E, _)).

test(rank_order, Ps == [1, 3, 0, 2, 1]) :-
    rank_order([ rule(a, 1, rule, 0.8), rule(b, 2, rule, 0.6), rule(a, 0, general, 1.0),
                 rule(c, 1, general, 0.5), rule(a, 1, rule, 0.2) ], Ps).

test(likelihood_of_a_head_and_of_its_negation, [P, Q, R] == [0.73, 0.27, none]) :-
    likelihood(730, no_spill, P),
    likelihood(730, neg(no_spill), Q),
    likelihood(none, no_spill, R).

test(uncertain_within_the_band, Vs == [holds, uncertain, uncertain, fails, fails, holds]) :-
    maplist([C-P, V]>>verdict(C, P, 0.15, V),
            [holds-0.9, holds-0.6, fails-0.4, fails-0.35, fails-0.1, holds-none], Vs).

test(the_band_of_the_defaults, V == uncertain) :-
    verdict(holds, 0.55, V).

test(rule_id, Id == r12_no_spill) :-
    rule_id(12, no_spill, Id).

test(antecedent_id, [Id, I] == [a12, 7]) :-
    antecedent_id(12, Id),
    antecedent_id(I, a7).

test(antecedent_id_of_no_antecedent, fail) :-
    member(Id, [none, a, b1, 'a-1', a1x, 'a 1']),
    antecedent_id(_, Id).

:- end_tests(learned_rules).
