:- begin_tests(curiosity_settings).

:- use_module('../default_values').
:- use_module('../validity').

% a_0, the default of initial(Props), is a valid antecedent
test(default_initial_is_valid) :-
    default_initial(A),
    valid_antecedent(A).

:- end_tests(curiosity_settings).
