:- begin_tests(default_values).
:- use_module(default_values).

test(permille_defaults_read_as_numbers, [nondet]) :-
    default(uncertain_band, B),
    B =:= 0.15.

test(a_0_is_a_list_of_propositions, [true(Props \== [])]) :-
    default_initial(Props).

:- end_tests(default_values).
