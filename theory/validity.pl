:- module(validity,
          [ valid_antecedent/1,     % +Props
            violations/2,           % +Props, -Why
            violation/4,            % +Props, ?Constraint, ?P1, ?P2
            count_valid/1,          % -Count
            count_valid/2,          % +Dims, -Count
            brute_force_count/2,    % +Dims, -Count
            random_antecedents/3    % +Seed, +N, -Antecedents
          ]).
/** <module> Which antecedents make sense

An antecedent is a set of scene propositions. It is valid when it breaks no
constraint of =|theory/vocabulary/constraints.pl|=: at most one value per
dimension, at most one proposition setting each parameter, and no pair of
propositions listed as a conflict. theory/violations.lp derives the same
checks for clingo from the same facts.
*/

:- use_module(vocabulary).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(aggregate)).
:- use_module(library(ugraphs)).
:- use_module(library(random)).

%!  valid_antecedent(+Props:list) is semidet.
%
%   Props (a list of proposition names) is a valid antecedent.
valid_antecedent(Props) :-
    violations(Props, []).

%!  violations(+Props:list, -Why:list) is det.
%
%   Why lists each violated constraint as
%   =|violation(Constraint, P1, P2, Words)|=, and each unknown name as
%   =|unknown(Name, Words)|=.
violations(Props, Why) :-
    sort(Props, Set),
    findall(unknown(P, Words),
            ( member(P, Set), \+ proposition(P, _, _, _),
              format(string(Words), "~w is not a known proposition", [P]) ),
            Unknown),
    findall(violation(C, P1, P2, Words),
            ( violation(Set, C, P1, P2),
              constraint(C, Gloss),
              format(string(Words), "~w and ~w: ~s", [P1, P2, Gloss]) ),
            Violated),
    append(Unknown, Violated, Why).

%!  violation(+Props:list, ?Constraint, ?P1, ?P2) is nondet.
%
%   P1 and P2 of the set Props break Constraint. Pairs of the two generic
%   constraints come ordered (P1 @< P2); conflict pairs come as written.
violation(Set, one_value_per_dimension, P1, P2) :-
    member(P1, Set), member(P2, Set), P1 @< P2,
    proposition(P1, D, _, _), proposition(P2, D, _, _).
violation(Set, one_model_per_parameter, P1, P2) :-
    member(P1, Set), member(P2, Set), P1 @< P2,
    proposition(P1, D1, _, _), proposition(P2, D2, _, _), D1 \== D2,
    model(P1, X, _), model(P2, X, _).
violation(Set, C, P1, P2) :-
    conflict(C, P1, P2),
    memberchk(P1, Set), memberchk(P2, Set).

%!  count_valid(-Count:integer) is det.
%
%   Count is the number of valid antecedents over the whole vocabulary
%   (the empty antecedent included), computed without enumerating them.
count_valid(Count) :-
    findall(D, dimension(D, _, _, _), Dims),
    count_valid(Dims, Count).

%!  count_valid(+Dims:list, -Count:integer) is det.
%
%   Count is the number of valid antecedents built from the propositions of
%   the dimensions Dims. Dimensions are linked when a constraint can join
%   propositions of both; the count is the product, over the connected
%   components of that graph, of the valid choices within the component
%   (each dimension contributing one of its values, or none).
count_valid(Dims, Count) :-
    dimension_components(Dims, Components),
    foldl(multiply_component, Components, 1, Count).

dimension_components(Dims, Components) :-
    sort(Dims, Vs),
    findall(D1-D2, ( member(D1, Vs), member(D2, Vs), D1 \== D2, linked(D1, D2) ), Es),
    vertices_edges_to_ugraph(Vs, Es, G),
    components(G, Components).

linked(D1, D2) :-
    proposition(P1, D1, _, _), proposition(P2, D2, _, _),
    (   model(P1, X, _), model(P2, X, _)
    ;   conflict(_, P1, P2)
    ;   conflict(_, P2, P1)
    ), !.

components(G, []) :- G == [], !.
components(G, [C|Cs]) :-
    G = [V-_|_],
    reachable(V, G, C),
    del_vertices(G, C, Rest),
    components(Rest, Cs).

multiply_component(Dims, Acc, Count) :-
    aggregate_all(count, ( choose(Dims, Props), valid_antecedent(Props) ), N),
    Count is Acc * N.

% choose(+Dims, -Props): one value or none from each dimension.
choose([], []).
choose([D|Ds], Props) :-
    choose(Ds, Rest),
    (   Props = Rest
    ;   proposition(P, D, _, _), Props = [P|Rest]
    ).

%!  brute_force_count(+Dims:list, -Count:integer) is det.
%
%   Count the valid antecedents over the propositions of Dims by testing
%   every subset of those propositions. Exponential: for checking
%   count_valid/2 on small sub-vocabularies.
brute_force_count(Dims, Count) :-
    findall(P, ( member(D, Dims), proposition(P, D, _, _) ), Ps),
    aggregate_all(count, ( subset_of(Ps, S), valid_antecedent(S) ), Count).

subset_of([], []).
subset_of([X|Xs], S) :-
    subset_of(Xs, S0),
    ( S = S0 ; S = [X|S0] ).

%!  random_antecedents(+Seed:integer, +N:integer, -Antecedents:list) is det.
%
%   N antecedents drawn uniformly at random from all valid antecedents of
%   the whole vocabulary (independently, with replacement), each a sorted
%   list of propositions. Uniform without enumerating: each connected
%   component of dimensions contributes one of its valid choices, drawn
%   uniformly, and the components are independent. The same Seed gives the
%   same antecedents.
random_antecedents(Seed, N, Antecedents) :-
    findall(D, dimension(D, _, _, _), Dims),
    dimension_components(Dims, Components),
    findall(Choices,
            ( member(C, Components),
              findall(Ps, ( choose(C, Ps), valid_antecedent(Ps) ), Choices) ),
            PerComponent),
    setup_call_cleanup(
        ( random_property(state(Saved)), set_random(seed(Seed)) ),
        length_draws(N, PerComponent, Antecedents),
        set_random(state(Saved))).

length_draws(N, PerComponent, Antecedents) :-
    length(Antecedents, N),
    maplist(draw_antecedent(PerComponent), Antecedents).

draw_antecedent(PerComponent, Antecedent) :-
    foldl(draw_choice, PerComponent, [], Props),
    sort(Props, Antecedent).

draw_choice(Choices, Acc, Props) :-
    random_member(Choice, Choices),
    append(Choice, Acc, Props).
