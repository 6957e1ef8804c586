:- begin_tests(curiosity_probe).

:- use_module(probe).

% A stand-in for the probes' simulations: pouring high passes (0.9), pouring
% mid-height comes close (0.4), anything else finds nothing new (0.1).
settings(_{curiosity:discover, probe:8, probe_attempts:3, batch:31, seed:1,
            qualify:weighted}).

test(the_first_candidate_whose_probe_passes_is_explored,
     [ setup(assertz((bridge:exploration_probe(Req, Reply) :- fake_probe(Req, Reply)))),
       cleanup(retractall(bridge:exploration_probe(_, _))) ]) :-
    A = cand([pour_low], a1, near), B = cand([pour_high], a1, near),
    C = cand([pour_mid_height], a1, near),
    settings(S),
    choose(st(1, [], [A, B, C], []), S, Cand, Attempt, Rest, Probes),
    Cand == B, Attempt == 1, Rest == [C],
    Probes == [probe([pour_low], 0.1, false, 0), probe([pour_high], 0.9, true, 1)].

test(when_none_passes_the_best_of_probe_attempts_is_explored,
     [ setup(assertz((bridge:exploration_probe(Req, Reply) :- fake_probe(Req, Reply)))),
       cleanup(retractall(bridge:exploration_probe(_, _))) ]) :-
    A = cand([pour_low], a1, near), C = cand([pour_mid_height], a1, near),
    D = cand([pour_to_side], a1, near), E = cand([pour_high], a1, near),
    settings(S),
    choose(st(1, [], [A, C, D, E], []), S, Cand, Attempt, Rest, Probes),
    Cand == C, Attempt == 1, Rest == [E],
    findall(K-Kept, member(probe(_, _, Kept, K), Probes), [0-false, 1-true, 2-false]).

test(more_batches_and_a_0_are_explored_without_a_probe,
     [ setup(assertz((bridge:exploration_probe(_, _) :- fail))),
       cleanup(retractall(bridge:exploration_probe(_, _))) ]) :-
    settings(S),
    More = cand([pour_low], a1, more(a1, 1)),
    choose(st(1, [], [More], []), S, More, 0, [], []),
    A0 = cand([pour_low], none, initial),
    choose(st(0, [], [A0], []), S, A0, 0, [], []),
    % and without probes every candidate is
    C = cand([pour_high], a1, near),
    choose(st(1, [], [C], []), S.put(probe, 0), C, 0, [], []).

fake_probe(Req, Reply) :-
    % the request carries the settings the probe needs: Python holds none
    _{batch:31, seed:1, probe:8, qualify:weighted} :< Req,
    (   memberchk(pour_high, Req.antecedent) -> Score = 0.9
    ;   memberchk(pour_mid_height, Req.antecedent) -> Score = 0.4
    ;   Score = 0.1
    ),
    ( Score >= 0.5 -> Pass = true ; Pass = false ),
    Reply = _{score:Score, pass:Pass, simulations:8}.

:- end_tests(curiosity_probe).
