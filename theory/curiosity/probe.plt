:- begin_tests(curiosity_probe).
:- use_module(library(http/json)).

:- use_module(probe).
:- use_module('../validity').

% The last probe of a step goes where the pours are fewest: here (a stand-in
% for the pours so far) only the pours upside down are few.
test(fewest_puts_the_least_covered_candidate_first,
     [ setup(assertz((bridge:exploration_fewest(Req, Reply) :- fake_fewest(Req, Reply)))),
       cleanup(retractall(bridge:exploration_fewest(_, _))) ]) :-
    A = cand([pour_mid_height, pour_steeply_tilted], a1, near),
    B = cand([pour_mid_height, pour_upside_down], a1, near),
    C = cand([pour_high, pour_steeply_tilted], a1, near),
    More = cand([pour_low], a1, more(a1, 1)),
    Settings = _{seed:1, jumps:31, probe:8, curiosity:discover, cover:31},
    % in A_new: moved to the front, the others in their order
    fewest([A, B, C], [], Settings, 2, Rest),
    Rest == [B, A, C],
    % a batch of more pours is no candidate for a probe
    fewest([More, A, C], [], Settings, 2, Rest2),
    Rest2 = [cand(P, none, jump), More, A, C],
    memberchk(pour_upside_down, P), valid_antecedent(P).

test(fewest_fails_when_every_candidate_is_covered,
     [ setup(assertz((bridge:exploration_fewest(Req, Reply) :- fake_fewest(Req, Reply)))),
       cleanup(retractall(bridge:exploration_fewest(_, _))),
       fail ]) :-
    fewest([cand([pour_high], a1, near)], [],
                     _{seed:1, jumps:0, probe:8, curiosity:discover, cover:31}, 2, _).

fake_fewest(Req, Reply) :-
    atom_json_dict(Req, D, [value_string_as(atom)]),
    (   nth0(I, D.candidates, P), memberchk(pour_upside_down, P) -> true ; I = -1 ),
    atom_json_dict(Reply, _{index:I}, [width(0)]).

:- end_tests(curiosity_probe).
