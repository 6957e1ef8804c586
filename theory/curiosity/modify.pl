:- module(curiosity_modify,
          [ direction/3,              % +Gradient, +MeanScore, -Direction
            modify/5,                 % +Props, +Direction, +Breadth, +Exclude, -New
            modify_past/4,            % +Props, +Moves, +Exclude, -New
            top/3,                    % +Direction, +K, -Top
            candidate_any/3,          % +Props, +Param, -Props1
            parameter_mean/3          % +Props, +Param, -Mean
          ]).
/** <module> Direction and modify: new antecedents from a plane

A plane fitted to an antecedent's weighted pours says which parameters
move an expectation's score. These predicates turn it into new
antecedents, by the vocabulary alone (no simulation): direction/3 signs the
gradient towards the other verdict; modify/5 is the paper's modify, one
rank along the largest components; modify_past/4 is the discovering
curiosity's, any value of a dimension that moves the pours past where the
plane's verdict flips. parameter_mean/3 is the mean of a parameter under
an antecedent, by which both judge a move.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module('../vocabulary').
:- use_module('../validity').
:- use_module('../default_values').

%!  direction(+Gradient:list, +MeanScore:number, -Direction:list) is det.
%
%   Gradient is a list Param-Component of a plane (score per normalised
%   unit). Direction is the same line, signed towards the other verdict:
%   where the antecedent's weighted mean score is above the verdict
%   threshold (theory/defaults.pl; the expectation mostly holds), against
%   the gradient, else along it.
direction(Gradient, Mean, Direction) :-
    once(default(verdict_threshold, Holds)),
    (   Mean > Holds -> Sign = -1 ; Sign = 1 ),
    findall(X-D, ( member(X-G, Gradient), D is Sign * G ), Direction).

%!  modify(+Props:list, +Direction:list, +Breadth:integer, +Exclude:list, -New:list) is det.
%
%   New lists mod(Props1, Param, Sign) for antecedents Props1 (sorted)
%   obtained from Props by moving along Direction: for each of the Breadth
%   parameters with the largest components |D| of Direction (Sign is up for
%   D > 0, down for D < 0),
%
%     - if a proposition of Props draws the parameter, it is replaced by its
%       neighbour in its dimension (one rank up or down) that moves the
%       parameter's mean in the direction's sign;
%     - otherwise each proposition that draws the parameter, of a dimension
%       Props does not use, and that moves the parameter's mean in the
%       direction's sign from its prior mean, is added.
%
%   Only valid antecedents are kept, none that is in Exclude (a list of
%   sorted antecedents: those explored and those already in A_new), each
%   once, in the order of the parameters, then of the vocabulary.
modify(Props0, Direction, Breadth, Exclude, New) :-
    sort(Props0, Props),
    top(Direction, Breadth, Top),
    foldl(param_mods(Props), Top, [], RevMods),
    reverse(RevMods, Mods0),
    exclude(excluded(Exclude), Mods0, New).

%   excluded(+Exclude, +Mod): the antecedent of Mod is in Exclude.
excluded(Exclude, mod(P, _, _)) :- memberchk(P, Exclude).

%   param_mods(+Props, +X-D, +Acc0, -Acc): the moves of Props one rank
%   along parameter X (component D) added to Acc0, each antecedent once.
param_mods(Props, X-D, Acc0, Acc) :-
    (   D > 0 -> Sign = up ; Sign = down ),
    findall(P1, candidate(Props, X, D, P1), Cands),
    foldl(add_new(X, Sign), Cands, Acc0, Acc).

add_new(X, Sign, P, Acc0, Acc) :-
    (   memberchk(mod(P, _, _), Acc0) -> Acc = Acc0 ; Acc = [mod(P, X, Sign)|Acc0] ).

%!  top(+Direction:list, +K:integer, -Top:list) is det.
%
%   Top are the K pairs Param-Component of Direction with the largest
%   |component| above zero, largest first (ties in parameter order).
%   top/4 keeps only those of at least Share times the largest.
top(Direction, K, Top) :-
    top(Direction, K, 0, Top).

top(Direction, K, Share, Top) :-
    findall(N-(X-D), ( nth1(I, Direction, X-D), D =\= 0, N0 is -abs(D), N = N0-I ), Keyed),
    keysort(Keyed, Sorted),
    pairs_values(Sorted, All0),
    (   All0 = [_-D0|_]
    ->  Min is abs(D0) * Share,
        include(large(Min), All0, All)
    ;   All = []
    ),
    length(All, Len),
    Take is min(K, Len),
    length(Top, Take),
    append(Top, _, All).

large(Min, _-D) :- abs(D) >= Min.

%   candidate(+Props, +X, +D, -Props1): Props moved one rank along X, or
%   with a proposition that draws X added, so that the mean of X moves in
%   the sign of D; valid.
candidate(Props, X, D, Props1) :-
    (   member(P, Props), model(P, X, _)
    ->  proposition(P, Dim, R, _),
        ( R1 is R + 1 ; R1 is R - 1 ),
        proposition(P1, Dim, R1, _),
        selectchk(P, Props, Rest),
        sort([P1|Rest], Props1)
    ;   with_new_dimension(Props, X, Props1)
    ),
    parameter_mean(Props, X, M0),
    parameter_mean(Props1, X, M1),
    (M1 - M0) * D > 0,
    valid_antecedent(Props1).

%!  modify_past(+Props:list, +Moves:list, +Exclude:list, -New:list) is det.
%
%   New lists mod(Props1, Expectation, Param, Sign) for the antecedents
%   Props1 (sorted) that move the pours of Props past the point where a
%   plane's verdict flips. Moves lists move(Expectation, Param, Sign, Flip):
%   the plane of Expectation says its verdict flips where Param passes the
%   value Flip (theory units) going up or down (Sign). For each move,
%
%     - if a proposition of Props draws Param, it is replaced by any other
%       proposition of its dimension (any rank, not only the next);
%     - otherwise any proposition that draws Param, of a dimension Props
%       does not use, is added;
%
%   keeping the valid antecedents not in Exclude whose mean of Param lies
%   past Flip (parameter_mean/3); when none does, those that move the mean
%   farthest towards it. Each antecedent once (its first move), in the
%   order of Moves, then of the vocabulary.
modify_past(Props0, Moves, Exclude, New) :-
    sort(Props0, Props),
    foldl(move_mods(Props, Exclude), Moves, [], RevMods),
    reverse(RevMods, New).

%   move_mods(+Props, +Exclude, +Move, +Acc0, -Acc): the antecedents of
%   one move (modify_past/4) added to Acc0, each antecedent once.
move_mods(Props, Exclude, move(E, X, Sign, Flip), Acc0, Acc) :-
    parameter_mean(Props, X, M0),
    findall(Gain-P1,
            ( candidate_any(Props, X, P1),
              \+ memberchk(P1, Exclude),
              parameter_mean(P1, X, M1),
              signed(Sign, M1 - M0, Gain),
              Gain > 0,
              valid_antecedent(P1) ),
            Moved),
    signed(Sign, Flip - M0, Need),
    findall(P1, ( member(G-P1, Moved), G >= Need ), Past),
    (   Past \== []
    ->  Chosen = Past
    ;   Moved == []
    ->  Chosen = []
    ;   aggregate_all(max(G), member(G-_, Moved), Far),
        findall(P1, member(Far-P1, Moved), Chosen)
    ),
    foldl(add_move(E, X, Sign), Chosen, Acc0, Acc).

add_move(E, X, Sign, P, Acc0, Acc) :-
    (   memberchk(mod(P, _, _, _), Acc0) -> Acc = Acc0 ; Acc = [mod(P, E, X, Sign)|Acc0] ).

signed(up, D, V) :- V is D.
signed(down, D, V) :- V is -(D).

%!  candidate_any(+Props:list, +X, -Props1:list) is nondet.
%
%   Props1 is Props with the proposition that draws X replaced by another
%   of its dimension, or, when none draws X, with a proposition that draws
%   X added from a dimension Props does not use. Props1 need not be valid.
candidate_any(Props, X, Props1) :-
    (   member(P, Props), model(P, X, _)
    ->  proposition(P, Dim, _, _),
        proposition(P1, Dim, _, _),
        P1 \== P,
        selectchk(P, Props, Rest),
        sort([P1|Rest], Props1)
    ;   with_new_dimension(Props, X, Props1)
    ).

%   with_new_dimension(+Props, +X, -Props1): Props with a proposition that
%   draws X added, from a dimension Props does not use.
with_new_dimension(Props, X, Props1) :-
    findall(Dim, ( member(P, Props), proposition(P, Dim, _, _) ), Dims),
    proposition(P1, Dim1, _, _),
    model(P1, X, _),
    \+ memberchk(Dim1, Dims),
    sort([P1|Props], Props1).

%!  parameter_mean(+Props:list, +Param, -Mean:number) is det.
%
%   The mean of Param under the antecedent's generative models (its
%   prior's mean if no proposition of Props draws it), clipped to its
%   bounds; a relative model adds its offset's mean to its base's mean.
parameter_mean(Props, X, Mean) :-
    parameter(X, _, _, Lo, Hi),
    (   member(P, Props), model(P, X, Model)
    ->  model_mean(Model, Props, Lo, Hi, Mean)
    ;   prior(X, uniform(PL, PH)),
        Mean is (PL + PH) / 2
    ).

%   model_mean(+Model, +Props, +Lo, +Hi, -Mean): the mean of a generative
%   model, clipped to the parameter's bounds [Lo, Hi].
model_mean(uniform(L, H), _, Lo, Hi, Mean) :-
    Mean is (max(L, Lo) + min(H, Hi)) / 2.
model_mean(relative(Base, L, H), Props, Lo, Hi, Mean) :-
    parameter_mean(Props, Base, MB),
    Mean is max(Lo, min(Hi, MB + (L + H) / 2)).

