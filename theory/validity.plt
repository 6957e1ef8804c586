:- use_module(validity).

:- begin_tests(validity).

test(empty_antecedent_is_valid) :-
    valid_antecedent([]).

test(an_ordinary_pour_is_valid) :-
    valid_antecedent([pour_near_rim, pour_low, pour_half_tilted, slow_approach, some_liquid]).

test(two_values_of_one_dimension, [C, P1, P2] == [one_value_per_dimension, pour_high, pour_low]) :-
    violations([pour_low, pour_high], [violation(C, P1, P2, _)]).

test(two_models_of_one_parameter, C == one_model_per_parameter) :-
    violations([start_high, approach_lowering], [violation(C, _, _, _)]).

test(centred_below_the_rim, C == inside_destination) :-
    violations([pour_below_rim, pour_centred], [violation(C, _, _, _)]).

test(below_the_rim_far_away_is_valid) :-
    valid_antecedent([pour_below_rim, pour_far_away]).

test(violations_are_in_words, Words == "pour_below_rim and pour_centred: the source cannot be below the destination's rim unless it is far from the destination: it would be inside the destination's wall") :-
    violations([pour_centred, pour_below_rim], [violation(_, _, _, Words)]).

test(unknown_names_are_reported, Why = [unknown(pour_sideways, _)]) :-
    violations([pour_sideways], Why).

test(duplicates_do_not_matter) :-
    valid_antecedent([pour_low, pour_low]).

% The component method agrees with testing every subset, on sub-vocabularies
% that join linked dimensions (shared parameters, conflicts) and free ones.
test(count_agrees_with_brute_force, forall(member(Dims,
        [ [pour_height, pour_alignment],
          [start_height, start_alignment, approach_vertical, approach_horizontal],
          [end_height, end_alignment, retreat_vertical, pour_lateral, liquid_amount] ]))) :-
    count_valid(Dims, N),
    brute_force_count(Dims, M),
    N =:= M.

% Unlinked dimensions multiply: (4 values or none) * (2 values or none).
test(count_of_independent_dimensions_is_a_product, N == 15) :-
    count_valid([liquid_amount, source_weight], N).

test(random_antecedents_are_valid_and_repeatable, true((A1 == A2, A1 \== A3))) :-
    random_antecedents(7, 50, A1),
    random_antecedents(7, 50, A2),
    random_antecedents(8, 50, A3),
    forall(member(A, A1), valid_antecedent(A)).

% Uniform over valid antecedents: a dimension with k values, unlinked to
% others, is left out in 1/(k+1) of draws.
test(random_antecedents_are_uniform_over_a_free_dimension) :-
    random_antecedents(1, 2000, As),
    aggregate_all(count, ( member(A, As), \+ ( member(P, A), proposition(P, liquid_amount, _, _) ) ), None),
    Share is None / 2000,
    abs(Share - 0.2) < 0.03.

:- end_tests(validity).
