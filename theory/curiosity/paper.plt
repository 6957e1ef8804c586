:- begin_tests(curiosity_paper).

:- use_module(paper).

% modify/5 along a plane steeper than the slope setting; nothing below it.
test(a_plane_steeper_than_the_slope_setting_is_followed) :-
    Explored = [ant(a1, [pour_mid_height, pour_steeply_tilted], none, initial)],
    Best = _{antecedent:a1, expectation:no_spill, slope:0.5, mean:0.8,
             gradient:_{pour_z:0.5}},
    paper_added(Best, _{slope:0.1, breadth:3}, Explored, [], Added),
    Added \== [],
    forall(member(C, Added), C = cand(_, a1, via(no_spill, pour_z, _))),
    paper_added(Best.put(slope, 0.05), _{slope:0.1, breadth:3}, Explored, [], None),
    None == [].

:- end_tests(curiosity_paper).
