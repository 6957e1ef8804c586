:- begin_tests(curiosity_run).

:- use_module(run).

test(bad_curiosity, [true(R = error(_))]) :-
    explore_result([curiosity(wild)], R).

test(explore_without_the_bridge_says_so, [throws(exploration_error(_))]) :-
    explore([oracle(synthetic), pours(1)]).

% a value out of range, for a curiosity that reads the option: the error
% names the option and why
test(bad_option, [forall(member(C-O, [discover-budget(0), discover-novelty(2), discover-jumps(0),
                                      discover-probe(-1), discover-probe(two),
                                      discover-probe_attempts(0), discover-prior_batch(2),
                                      discover-prior_batch(-1), discover-significance(2),
                                      paper-slope(-1), paper-budget(0), learn-pours(0),
                                      learn-body(9)])),
                  true(R = error(_))]) :-
    explore_result([curiosity(C), O], R),
    R = error(Text),
    functor(O, Name, 1),
    format(string(Start), "~w: expected", [Name]),
    sub_string(Text, 0, _, _, Start).

% an option the curiosity does not read: refused before anything is run
test(an_option_the_curiosity_does_not_read, [true(sub_string(Text, 0, _, _, "budget: not an option of curiosity(learn)"))]) :-
    explore_result([curiosity(learn), budget(5)], error(Text)).

:- end_tests(curiosity_run).
