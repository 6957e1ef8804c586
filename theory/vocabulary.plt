:- use_module(vocabulary).
:- use_module(library(aggregate)).

:- begin_tests(vocabulary).

test(thirty_parameters, N == 30) :-
    aggregate_all(count, parameter(_, _, _, _, _), N).

test(eighty_six_propositions, N == 86) :-
    aggregate_all(count, proposition(_, _, _, _), N).

test(nine_expectations, N == 9) :-
    aggregate_all(count, expectation(_, _, _), N).

test(every_parameter_has_a_prior_within_bounds_and_a_gloss, Missing == []) :-
    findall(P, ( parameter(P, _, _, Lo, Hi),
                 \+ ( prior(P, uniform(PL, PH)), parameter_gloss(P, _),
                      Lo =< PL, PL < PH, PH =< Hi ) ), Missing).

test(ranks_run_from_one_without_gaps, Bad == []) :-
    findall(D, ( dimension(D, _, _, _),
                 findall(R, proposition(_, D, R, _), Rs),
                 length(Rs, K), numlist(1, K, Expected), msort(Rs, Sorted),
                 Sorted \== Expected ), Bad).

test(every_proposition_has_one_model_within_bounds, Bad == []) :-
    findall(P, ( proposition(P, _, _, _),
                 \+ ( aggregate_all(count, model(P, _, _), 1),
                      model(P, X, M), parameter(X, _, _, Lo, Hi),
                      model_fits(M, Lo, Hi) ) ), Bad).

model_fits(uniform(A, B), Lo, Hi) :- Lo =< A, A < B, B =< Hi.
model_fits(relative(Base, A, B), _, _) :- parameter(Base, _, _, _, _), A < B.

test(ranks_increase_with_the_parameter, Bad == []) :-
    findall(P1-P2, ( proposition(P1, D, R1, _), proposition(P2, D, R2, _), R1 < R2,
                     model(P1, _, M1), model(P2, _, M2), \+ below(M1, M2) ), Bad).

below(uniform(_, B1), uniform(A2, _)) :- B1 =< A2.
below(relative(_, _, B1), relative(_, A2, _)) :- B1 =< A2.

test(every_dimension_has_a_role, Bad == []) :-
    findall(D, ( dimension(D, _, _, _), \+ role(D, manner), \+ role(D, context) ), Bad).

test(image_schema_of_a_proposition, S == verticality) :-
    image_schema(pour_low, S).

test(conflicts_name_known_constraints_and_propositions, Bad == []) :-
    findall(C, ( conflict(C, P1, P2),
                 \+ ( constraint(C, _), proposition(P1, _, _, _), proposition(P2, _, _, _) ) ), Bad).

:- end_tests(vocabulary).
