:- begin_tests(curiosity_state).

:- use_module(state).

% a fresh run starts from a_0 alone in A_new; a resumed one from the
% state saved as text
test(initial_state) :-
    initial_state(_{state:""}, _{initial:[pour_low]}, S0),
    S0 == st(0, [], [cand([pour_low], none, initial)], []),
    Saved = st(2, [ant(a1, [pour_low], none, initial)], [cand([], a1, jump)], []),
    format(string(Text), "~k", [Saved]),
    initial_state(_{state:Text}, _{initial:[pour_high]}, S1),
    S1 == Saved.

% the explored antecedents, the queued candidates and those set aside are
% no new candidates
test(exclusions) :-
    exclusions([ant(a1, [pour_low], none, initial)],
               [cand([pour_high], a1, near), aside(1, 0, [pour_to_side])], X),
    X == [[pour_low], [pour_high], [pour_to_side]].

test(entry) :-
    entry(ant(a3, [pour_low], a1, jump), E),
    E.id == a3, E.antecedent == [pour_low].

:- end_tests(curiosity_state).
