:- begin_tests(curiosity_run).

:- use_module(run).

test(bad_curiosity, [true(R = error(_))]) :-
    explore_result([curiosity(wild)], R).

test(explore_without_the_bridge_says_so, [throws(exploration_error(_))]) :-
    explore([oracle(synthetic), budget(1)]).

test(bad_option, [forall(member(O, [budget(0), novelty(2), jumps(0), probe(-1),
                                    probe(two), probe_attempts(0), prior_batch(2),
                                    prior_batch(-1), significance(2), slope(-1)])),
                  true(R = error(_))]) :-
    explore_result([O], R).

:- end_tests(curiosity_run).
