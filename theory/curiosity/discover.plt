:- begin_tests(curiosity_discover).

:- use_module(discover).
:- use_module('../validity').

test(most_novel_first_above_the_level,
     [ setup(assertz((bridge:exploration_predict(Req, Reply) :- fake_predict(Req, Reply)))),
       cleanup(retractall(bridge:exploration_predict(_, _))) ]) :-
    Best = _{followed:[_{antecedent:a1,
                         directions:[_{expectation:no_spill,
                                       moves:[_{parameter:pour_z, sign:down, flip:40}]}]}]},
    A = [pour_mid_height, pour_steeply_tilted],
    Explored = [ant(a1, A, none, initial)],
    Low = [pour_low, pour_steeply_tilted],
    Below = [pour_below_rim, pour_steeply_tilted],
    discover_queue(Best, Explored, a1, A, [], [], _{seed:1, batch:3, jumps:3, qualify:weighted, novelty:0.1},
                             1, Added, Queue),
    % both moves past the flip, the most novel first, then a neighbour;
    % nothing else reaches the level
    High = [pour_high, pour_steeply_tilted],
    Queue == [ cand(Low, a1, via(no_spill, pour_z, down)),
               cand(Below, a1, via(no_spill, pour_z, down)),
               cand(High, a1, near) ],
    Added == Queue,
    % A_new as it was is scored again, in its place by novelty
    Old = cand(High, a0, near),
    discover_queue(_{followed:[]}, Explored, a1, A, [Old], [Old],
                             _{seed:1, batch:3, jumps:3, qualify:weighted, novelty:0.1}, 1, Added1, Queue1),
    Queue1 == [cand(Low, a1, near), cand(Below, a1, near), Old],
    Added1 == [cand(Low, a1, near), cand(Below, a1, near)],
    % an antecedent set aside after its probe is no candidate again
    discover_queue(_{followed:[]}, Explored, a1, A, [aside(1, 0, Low)], [],
                             _{seed:1, batch:3, jumps:3, qualify:weighted, novelty:0.1}, 1, _, Queue3),
    Queue3 == [cand(Below, a1, near), cand(High, a1, near)].

%   A stand-in for the bridge's novelty, with known answers: pouring low is
%   the most novel, below the rim next, pouring high a little; nothing else
%   reaches the level (0.1).
fake_predict(Req, Reply) :-
    % the level comes with the request (Python holds no setting)
    findall(N-Q, ( member(C, Req.candidates), fake_novelty(C, N),
                   ( N >= Req.novelty -> Q = true ; Q = false ) ),
            Pairs),
    pairs_keys_values(Pairs, Ns, Qs),
    Reply = _{novelty:Ns, queued:Qs}.

fake_novelty([pour_low, pour_steeply_tilted], 0.9) :- !.
fake_novelty([pour_below_rim, pour_steeply_tilted], 0.5) :- !.
fake_novelty([pour_high, pour_steeply_tilted], 0.2) :- !.
fake_novelty(_, 0.05).

test(neighbours_differ_by_one_proposition,
     [forall(member(A, [[pour_low], [pour_to_side, light_liquid], [approach_raising, pour_high, end_upright]]))]) :-
    neighbours(A, [], New),
    New \== [],
    is_set(New),
    forall(member(P, New),
           ( valid_antecedent(P),
             subtract(P, A, Plus), subtract(A, P, Minus),
             length(Plus, 1), length(Minus, M), M =< 1 )),
    % the excluded are left out
    New = [First|_],
    neighbours(A, [First], New1),
    \+ memberchk(First, New1).

:- end_tests(curiosity_discover).
