:- begin_tests(curiosity).
:- use_module(library(http/json)).

:- use_module(curiosity).
:- use_module(validity).

test(default_initial_is_valid) :-
    default_initial(A),
    valid_antecedent(A).

test(direction_towards_other_verdict) :-
    direction([a-1.0, b-(-2.0)], 0.9, D1),
    D1 == [a-(-1.0), b-2.0],
    direction([a-1.0, b-(-2.0)], 0.1, D2),
    D2 == [a-1.0, b-(-2.0)].

test(parameter_mean_uniform_prior_relative) :-
    parameter_mean([pour_low], pour_z, M1), M1 =:= 30,
    parameter_mean([], pour_z, M2), M2 =:= 85,
    parameter_mean([pour_low, approach_lowering], start_z, M3), M3 =:= 30 + 85.

test(step_up_and_down) :-
    modify([pour_low, pour_steeply_tilted], [pour_z-1.0], 1, [], Up),
    Up == [mod([pour_mid_height, pour_steeply_tilted], pour_z, up)],
    modify([pour_low, pour_steeply_tilted], [pour_z-(-1.0)], 1, [], Down),
    Down == [mod([pour_below_rim, pour_steeply_tilted], pour_z, down)].

% the ordinary pour's liquid is of medium weight: lighter is a light one,
% heavier a heavy one
test(add_for_free_parameter) :-
    modify([pour_low], [particle_mass-(-1.0)], 1, [], New),
    findall(P, member(mod(P, _, _), New), Ps),
    Ps == [[light_liquid, pour_low]],
    modify([pour_low], [particle_mass-1.0], 1, [], Up),
    Up == [mod([heavy_liquid, pour_low], particle_mass, up)].

test(excluded_and_invalid_are_left_out) :-
    modify([pour_low], [particle_mass-(-1.0)], 1, [[light_liquid, pour_low]], New),
    New == [],
    modify([pour_low, pour_near_rim], [pour_z-(-1.0)], 1, [], None),
    None == [].

test(breadth_limits_parameters) :-
    Dir = [pour_z-1.0, particle_mass-0.5, pour_pitch-0.1],
    modify([pour_low, pour_half_tilted], Dir, 1, [], One),
    forall(member(mod(_, X, _), One), X == pour_z),
    modify([pour_low, pour_half_tilted], Dir, 3, [], Three),
    findall(X, member(mod(_, X, _), Three), Xs0), sort(Xs0, Xs),
    Xs == [particle_mass, pour_pitch, pour_z].

test(every_modification_valid_and_new, [forall(member(A, [[], [pour_low], [pour_to_side, light_liquid], [approach_raising, pour_high, end_upright]]))]) :-
    findall(X-1.0, parameter(X, _, _, _, _), Up),
    findall(X-(-1.0), parameter(X, _, _, _, _), Down),
    forall(member(D, [Up, Down]),
           ( modify(A, D, 30, [A], New),
             forall(member(mod(P, _, _), New),
                    ( valid_antecedent(P), msort(P, P), P \== A ))
           )).

test(rule_facts_and_theory_file, [setup(tmp_file(theory, F)), cleanup(delete_file(F))]) :-
    Q = _{id:a2, simulations:31, weight_mass_permille:900,
          outcomes:[_{expectation:no_spill, holds:false, confidence_permille:800, score_permille:300}]},
    rule_facts([ant(a2, [pour_to_side], a1, via(no_spill, pour_x, up))], [Q], Facts),
    memberchk(rule(r2_no_spill, defeasible, neg(no_spill)), Facts),
    memberchk(body(r2_no_spill, pour_to_side), Facts),
    memberchk(learned(r2_no_spill), Facts),
    memberchk(provenance(r2_no_spill, direction, pour_x), Facts),
    memberchk(provenance(r2_no_spill, parent, a1), Facts),
    write_theory(F, _{oracle:synthetic, seed:1}, [setting(oracle_version, "1")|Facts]),
    theory_files:load_facts(F, explore_plt_theory),
    explore_plt_theory:rule(r2_no_spill, defeasible, neg(no_spill)),
    explore_plt_theory:setting(oracle_version, "1").

test(modify_past_beyond_one_rank) :-
    modify_past([pour_mid_height, pour_steeply_tilted], [move(no_spill, pour_z, down, 40)], [], New),
    findall(P, member(mod(P, no_spill, pour_z, down), New), Ps),
    msort(Ps, [[pour_below_rim, pour_steeply_tilted], [pour_low, pour_steeply_tilted]]).

test(modify_past_farthest_when_none_passes) :-
    modify_past([pour_mid_height, pour_steeply_tilted], [move(e, pour_z, down, -100)], [], New),
    New == [mod([pour_below_rim, pour_steeply_tilted], e, pour_z, down)],
    modify_past([pour_mid_height, pour_steeply_tilted], [move(e, pour_z, down, -100)],
                [[pour_below_rim, pour_steeply_tilted]], New2),
    New2 == [mod([pour_low, pour_steeply_tilted], e, pour_z, down)].

test(modify_past_valid_new_and_past_the_flip,
     [forall(member(A-X-S-F, [[]-pour_x-up-150, [pour_low]-particle_mass-up-5000,
                              [pour_mid_height, pour_near_rim]-pour_y-up-30]))]) :-
    modify_past(A, [move(e, X, S, F)], [A], New),
    New \== [],
    parameter_mean(A, X, M0),
    forall(member(mod(P, e, X, S), New),
           ( valid_antecedent(P), P \== A,
             parameter_mean(P, X, M1),
             ( S == up -> M1 > M0 ; M1 < M0 ) )).

test(most_novel_first_above_the_level_up_to_the_queue,
     [ setup(assertz((bridge:exploration_predict(Req, Reply) :- fake_predict(Req, Reply)))),
       cleanup(retractall(bridge:exploration_predict(_, _))) ]) :-
    Best = _{followed:[_{antecedent:a1,
                         directions:[_{expectation:no_spill,
                                       moves:[_{parameter:pour_z, sign:down, flip:40}]}]}]},
    A = [pour_mid_height, pour_steeply_tilted],
    Explored = [ant(a1, A, none, initial)],
    Low = [pour_low, pour_steeply_tilted],
    Below = [pour_below_rim, pour_steeply_tilted],
    curiosity:discover_queue(Best, Explored, a1, A, [], [], _{seed:1, samples:3, queue:5, jumps:3},
                             1, Added, Queue),
    % both moves past the flip, the most novel first, then a neighbour;
    % nothing else reaches the level
    High = [pour_high, pour_steeply_tilted],
    Queue == [ cand(Low, a1, via(no_spill, pour_z, down)),
               cand(Below, a1, via(no_spill, pour_z, down)),
               cand(High, a1, near) ],
    Added == Queue,
    % A_new as it was is scored again, and the queue keeps only the most novel
    Old = cand(High, a0, near),
    curiosity:discover_queue(_{followed:[]}, Explored, a1, A, [Old], [Old],
                             _{seed:1, samples:3, queue:3, jumps:3}, 1, Added1, Queue1),
    Queue1 == [cand(Low, a1, near), cand(Below, a1, near), Old],
    Added1 == [cand(Low, a1, near), cand(Below, a1, near)],
    curiosity:discover_queue(_{followed:[]}, Explored, a1, A, [Old], [Old],
                             _{seed:1, samples:3, queue:1, jumps:3}, 1, _, Queue2),
    Queue2 == [cand(Low, a1, near)],
    % an antecedent set aside after its probe is no candidate again
    curiosity:discover_queue(_{followed:[]}, Explored, a1, A, [aside(1, 0, Low)], [],
                             _{seed:1, samples:3, queue:5, jumps:3}, 1, _, Queue3),
    Queue3 == [cand(Below, a1, near), cand(High, a1, near)].

% The priors (the empty antecedent) take the last batch of the budget, or
% the next when A_new is empty, once; a_0 alone starts A_new.
test(the_priors_take_the_last_batch_once) :-
    Settings = _{curiosity:discover, initial:[pour_low], prior:1, max_rules:4,
                 samples:10, probe:2, probe_attempts:3},
    curiosity:initial_state(_{}, Settings, S0),
    S0 == st(0, [], [cand([pour_low], none, initial)], []),
    C = cand([pour_high], none, jump),
    A1 = ant(a1, [pour_low], none, initial),
    % 10 spent: a step (at most 14) and the priors (10) fit in 40
    curiosity:next_move(st(1, [A1], [C], []), Settings, step),
    % 20 spent: a step and the priors would not, the priors alone do
    curiosity:next_move(st(2, [A1], [C], []), Settings, priors),
    % A_new empty: the priors before stopping
    curiosity:next_move(st(1, [A1], [], []), Settings, priors),
    % explored once, never again
    P = ant(a2, [], none, prior),
    curiosity:next_move(st(3, [A1, P], [C], []), Settings, stop(max_rules)),
    curiosity:next_move(st(2, [A1, P], [], []), Settings, stop(a_new_empty)),
    curiosity:next_move(st(2, [A1, P], [C], []), Settings, step),
    % not when they would exceed the budget, nor without prior(1), nor for
    % the paper's curiosity
    curiosity:next_move(st(4, [A1], [C], []), Settings, stop(max_rules)),
    curiosity:next_move(st(2, [A1], [C], []), Settings.put(prior, 0), step),
    curiosity:next_move(st(2, [A1], [C], []), Settings.put(curiosity, paper), step),
    curiosity:initial_state(_{}, Settings.put(prior, 0), S0).

%   A stand-in for the bridge's novelty, with known answers: pouring low is
%   the most novel, below the rim next, pouring high a little; nothing else
%   reaches the level (0.1).
fake_predict(Req, Reply) :-
    atom_json_dict(Req, D, [value_string_as(atom)]),
    findall(N-Q, ( member(C, D.candidates), fake_novelty(C, N), ( N >= 0.1 -> Q = true ; Q = false ) ),
            Pairs),
    pairs_keys_values(Pairs, Ns, Qs),
    atom_json_dict(Reply, _{novelty:Ns, queued:Qs}, [width(0)]).

fake_novelty([pour_low, pour_steeply_tilted], 0.9) :- !.
fake_novelty([pour_below_rim, pour_steeply_tilted], 0.5) :- !.
fake_novelty([pour_high, pour_steeply_tilted], 0.2) :- !.
fake_novelty(_, 0.05).

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
    curiosity:fewest([A, B, C], [], Settings, 2, Rest),
    Rest == [B, A, C],
    % a batch of more pours is no candidate for a probe
    curiosity:fewest([More, A, C], [], Settings, 2, Rest2),
    Rest2 = [cand(P, none, jump), More, A, C],
    memberchk(pour_upside_down, P), valid_antecedent(P).

test(fewest_fails_when_every_candidate_is_covered,
     [ setup(assertz((bridge:exploration_fewest(Req, Reply) :- fake_fewest(Req, Reply)))),
       cleanup(retractall(bridge:exploration_fewest(_, _))),
       fail ]) :-
    curiosity:fewest([cand([pour_high], a1, near)], [],
                     _{seed:1, jumps:0, probe:8, curiosity:discover, cover:31}, 2, _).

fake_fewest(Req, Reply) :-
    atom_json_dict(Req, D, [value_string_as(atom)]),
    (   nth0(I, D.candidates, P), memberchk(pour_upside_down, P) -> true ; I = -1 ),
    atom_json_dict(Reply, _{index:I}, [width(0)]).

test(neighbours_differ_by_one_proposition,
     [forall(member(A, [[pour_low], [pour_to_side, light_liquid], [approach_raising, pour_high, end_upright]]))]) :-
    curiosity:neighbours(A, [], New),
    New \== [],
    is_set(New),
    forall(member(P, New),
           ( valid_antecedent(P),
             subtract(P, A, Plus), subtract(A, P, Minus),
             length(Plus, 1), length(Minus, M), M =< 1 )),
    % the excluded are left out
    New = [First|_],
    curiosity:neighbours(A, [First], New1),
    \+ memberchk(First, New1).

test(bad_curiosity, [true(R = error(_))]) :-
    explore_result([curiosity(wild)], R).

test(explore_without_the_bridge_says_so, [throws(exploration_error(_))]) :-
    explore([oracle(synthetic), max_rules(1)]).

test(bad_option, [forall(member(O, [max_rules(0), novelty(2), queue(0), jumps(0), probe(-1),
                                    probe(two), probe_attempts(0), prior(2), prior(-1)])),
                  true(R = error(_))]) :-
    explore_result([O], R).

:- end_tests(curiosity).
