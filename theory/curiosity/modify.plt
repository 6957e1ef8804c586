:- begin_tests(curiosity_modify).

:- use_module(modify).
:- use_module('../vocabulary').
:- use_module('../validity').

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

:- end_tests(curiosity_modify).
