:- begin_tests(curiosity_oracle_prompt).

:- use_module(oracle_prompt).
:- use_module('../vocabulary').

% A stand-in for the foreign oracle_simulate, with known scores: one row
% of 9 scores per parameterization, 0.1 for the first, 0.2 for the next...
:- dynamic bridge:oracle_simulate/2.
bridge:oracle_simulate(Request, _{scores:Scores}) :-
    get_dict(rows, Request, Rows),
    findall(Row, ( nth1(I, Rows, _), X is I / 10, length(Row, 9), maplist(=(X), Row) ), Scores).

% simulate/3 pairs each row's scores with the expectations, in the
% vocabulary's order
test(simulate_pairs_scores_with_expectations) :-
    simulate([[1], [2]], [oracle(synthetic)], [S1, S2]),
    findall(E, expectation(E, _, _), Es),
    pairs_keys_values(S1, Es, V1), maplist(==(0.1), V1),
    pairs_keys_values(S2, Es, V2), maplist(==(0.2), V2).

% without the oracle's own foreign predicates, sampling says how to get them
test(sample_without_the_oracle, [throws(exploration_error(_))]) :-
    sample([pour_low], 1, 1, _).

:- end_tests(curiosity_oracle_prompt).
