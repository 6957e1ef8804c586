:- begin_tests(curiosity_learn).

:- use_module(learn).
:- use_module('../vocabulary').
:- use_module('../validity').

test(children_of_the_ordinary_pour_are_the_propositions_alone) :-
    children([], 2, [], Kids),
    findall([P], ( proposition(P, _, _, _), valid_antecedent([P]) ), Alone0),
    msort(Alone0, Alone),
    msort(Kids, Sorted),
    Sorted == Alone,
    % what is excluded is no child, and nothing past the most propositions
    children([], 2, [[pour_to_side]], Kids1),
    \+ memberchk([pour_to_side], Kids1),
    children([pour_to_side], 1, [], []).

test(children_add_one_proposition_of_an_unused_dimension) :-
    children([pour_to_side], 2, [], Kids),
    Kids \== [],
    forall(member(K, Kids),
           ( length(K, 2), memberchk(pour_to_side, K), valid_antecedent(K) )),
    % no other value of the dimension pour_to_side is of
    proposition(pour_to_side, Dim, _, _),
    forall(( member(K, Kids), member(P, K), P \== pour_to_side ),
           \+ proposition(P, Dim, _, _)).

test(queue_most_valuable_first_bounded,
     [ setup(assertz((bridge:exploration_teach(Req, Reply) :- fake_teach(Req, Reply)))),
       cleanup(retractall(bridge:exploration_teach(_, _))) ]) :-
    Explored = [ant(a1, [], none, initial)],
    teach_queue(Explored, a1, [], [], _{body:1, queue:2, seed:1, batch:4, uncertainty:1.0, doubt:0.0, newness:0.0, reach:4, whole_every:0, iteration:1}, Added, Queue),
    % the two most valuable children, the most valuable first
    Queue == [cand([pour_to_side], a1, near), cand([light_liquid], a1, near)],
    Added == Queue,
    % A_new as it was is valued again, and the explored antecedent is a
    % candidate for another batch; a value of 0 is never queued
    Old = cand([pour_to_side], a1, near),
    teach_queue(Explored, a1, [], [Old], _{body:1, queue:10, seed:1, batch:4, uncertainty:1.0, doubt:0.0, newness:0.0, reach:4, whole_every:0, iteration:1}, Added1, Queue1),
    Queue1 = [Old, cand([light_liquid], a1, near), cand([], a1, again(a1))],
    Added1 == [cand([light_liquid], a1, near)].

%   A stand-in for the bridge's value, with known answers: pouring from the
%   side teaches most, a light liquid next, another batch of the ordinary
%   pour a little, anything else nothing.
fake_teach(Req, _{value:Values}) :-
    _{seed:1, batch:4, uncertainty:1.0, doubt:0.0, newness:0.0, iteration:2} :< Req,
                                        % the settings and the next iteration come with the request
    findall(V, ( member(C, Req.candidates), fake_value(C, V) ), Values).

fake_value([pour_to_side], 3) :- !.
fake_value([light_liquid], 2) :- !.
fake_value([], 1) :- !.
fake_value(_, 0).

test(reach_draws_valid_seeded_bodies_of_two_to_most) :-
    reach(7, 12, 3, [], Bodies),
    Bodies \== [],
    forall(member(B, Bodies),
           ( length(B, L), between(2, 3, L), valid_antecedent(B), msort(B, B) )),
    reach(7, 12, 3, [], Again),
    Again == Bodies,
    reach(8, 12, 3, [], Other),
    Other \== Bodies,
    % what is excluded is never drawn, and a body of one proposition draws nothing
    Bodies = [First|_],
    reach(7, 12, 3, [First], Without),
    \+ memberchk(First, Without),
    reach(7, 12, 1, [], []).

test(a_whole_step_puts_the_likeliest_whole_first,
     [ setup(assertz((bridge:exploration_teach(Req, Reply) :- whole_teach(Req, Reply)))),
       cleanup(retractall(bridge:exploration_teach(_, _))) ]) :-
    Explored = [ant(a1, [], none, initial)],
    Settings = _{body:1, queue:2, seed:1, batch:4, uncertainty:1.0, doubt:0.0, newness:0.0,
                 reach:4, whole_every:3},
    % the next iteration, 3, is a whole step: the whole valued most goes first,
    % before the children as they rank among themselves
    teach_queue(Explored, a1, [], [], Settings.put(iteration, 2), Added, Queue),
    Queue = [cand(Whole, a1, whole), cand([pour_to_side], a1, near), cand([light_liquid], a1, near)],
    length(Whole, L), L > 1, valid_antecedent(Whole),
    Added == [cand([pour_to_side], a1, near), cand([light_liquid], a1, near)],
    % another iteration is no whole step: no whole is drawn or queued
    teach_queue(Explored, a1, [], [], Settings.put(iteration, 3), _, Queue1),
    Queue1 == [cand([pour_to_side], a1, near), cand([light_liquid], a1, near)],
    % and none ever with whole_every(0)
    teach_queue(Explored, a1, [], [], Settings.put(_{iteration:2, whole_every:0}), _, Queue2),
    Queue2 == Queue1.

test(a_whole_explored_gets_no_other_batch,
     [ setup(assertz((bridge:exploration_teach(Req, Reply) :- alike_teach(Req, Reply)))),
       cleanup(retractall(bridge:exploration_teach(_, _))) ]) :-
    % every candidate valued alike: the ordinary pour is one for another batch, the whole is not
    Whole = [bouncy_liquid, heavy_source, pour_very_high],
    Explored = [ant(a1, [], none, initial), ant(a2, Whole, a1, whole)],
    teach_queue(Explored, a1, [], [], _{body:1, queue:1000, seed:1, batch:4, uncertainty:1.0, doubt:0.0,
                                         newness:0.0, reach:4, whole_every:0, iteration:3}, _, Queue),
    memberchk(cand([], a1, again(a1)), Queue),
    \+ memberchk(cand(_, a2, again(a2)), Queue).

%   The bridge's value, every candidate alike.
alike_teach(Req, _{value:Values}) :-
    findall(1, member(_, Req.candidates), Values).

%   The bridge's value for a whole step: the children as fake_value/2 says,
%   a whole (named in the request's wholes) by its length, so the longest
%   whole is the likeliest.
whole_teach(Req, _{value:Values}) :-
    findall(V, ( member(C, Req.candidates),
                 ( memberchk(C, Req.wholes) -> length(C, V) ; fake_value(C, V) ) ), Values).

test(wholes_are_seeded_random_antecedents_of_more_than_most) :-
    wholes(7, 12, 2, [], Wholes),
    Wholes \== [],
    forall(member(W, Wholes),
           ( length(W, L), L > 2, valid_antecedent(W), msort(W, W) )),
    wholes(7, 12, 2, [], Again),
    Again == Wholes,
    % the wholes reach/5 takes its parts from, with the same seed
    random_antecedents(7, 12, Drawn),
    forall(member(W, Wholes), memberchk(W, Drawn)),
    % what is excluded is never drawn
    Wholes = [First|_],
    wholes(7, 12, 2, [First], Without),
    \+ memberchk(First, Without).

:- end_tests(curiosity_learn).
