:- begin_tests(curiosity_plane_steps).

:- use_module(plane_steps).

best(_{antecedent:a1, expectation:no_spill, slope:0.4, mean:0.7,
       gradient:_{pour_z:0.3, pour_speed: -0.1}}).

% A step's line of the trace; the plane's direction only when it is followed.
test(a_step_records_its_plane_and_the_direction_it_follows) :-
    best(Best),
    Cand = cand([pour_low], a0, via(no_spill, pour_z, down)),
    Sim = _{simulations:62, failed:1},
    Added = [cand([pour_high], a1, near)],
    plane_step_trace(Best, true, 2-a2, Cand, Sim, Added, 5, T),
    T.iteration == 2, T.id == a2, T.antecedent == [pour_low], T.parent == a0,
    T.via == "via(no_spill,pour_z,down)", T.simulations == 62, T.failed == 1,
    T.added == [[pour_high]], T.a_new == 5,
    T.best.antecedent == a1, T.best.slope == 0.4,
    T.best.direction = [First|_], First.parameter == pour_z,
    plane_step_trace(Best, false, 2-a2, Cand, Sim, Added, 5, T2),
    T2.best.direction == [].

test(no_general_layer_unless_asked) :-
    general_layer_if_asked([], _{general:false}, General),
    General == [].

:- end_tests(curiosity_plane_steps).
