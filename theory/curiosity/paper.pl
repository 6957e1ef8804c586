:- module(curiosity_paper,
          [ paper_added/5             % +Best, +Settings, +Explored, +Rest, -Added
          ]).
/** <module> The paper's curiosity: Algorithm 1 as the paper states it

Option curiosity(paper). A_new is a queue, the oldest first. After each
batch the steepest plane of every explored antecedent
(exploration_steepest_plane) is followed when its slope exceeds
slope(X): modify/5 moves the parameters of its breadth(N) largest
gradient components by one rank, and the new antecedents join the end
of A_new. Nothing is probed; the budget is `budget` explored antecedents
(a batch each). The interface of a curiosity is interface.pl's.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(foreign).
:- use_module(state).
:- use_module(modify).
:- use_module(plane_steps).

% The interface of interface.pl; its Python side fits the planes
% (exploration_steepest_plane).

python_side(['pantarhei.bridge.exploration.steepest']).

% Its own options, read by this curiosity alone: rows of the option table
% (theory/defaults.pl says what option/5, course/2 and prolog_only/1
% mean; theory/option_table.py and settings.pl read them from here).
option(slope, permille, range(0, none), 100,
  "paper: the plane slope below which nothing new is explored").
option(breadth, count, range(1, 1000000), 3,
  "paper: modify steps the parameters of this many largest gradient components").

course(slope, paper).
course(breadth, every).

prolog_only(slope).
prolog_only(breadth).

budget(Settings, Pours) :-
    Pours is Settings.budget * Settings.batch.

progress_bar(Settings, _{total:Total, unit:rule}) :-
    Total = Settings.budget.

probe_size(_, 0).

probed(_, _) :- fail.

priors_due(_, _) :- fail.

after_batch(step(I1, Id, Cand, Explored, Rest, _, _, Sim), Settings, ANew, Trace) :-
    maplist(entry, Explored, Entries),
    call_bridge(exploration_steepest_plane, _{antecedents:Entries, ridge:Settings.ridge}, Best),
    paper_added(Best, Settings, Explored, Rest, Added),
    append(Rest, Added, ANew),
    length(ANew, Left),
    (   Best.slope > Settings.slope -> Followed = true ; Followed = false ),
    plane_step_trace(Best, Followed, I1-Id, Cand, Sim, Added, Left, Trace).

second_layer(_, Facts, Settings, General) :-
    general_layer_if_asked(Facts, Settings, General).

theory_layout(_{rules:true, batches:false,
                header:["%   setting(Key, Value): how the exploration ran."],
                layer_header:Lines}) :-
    general_layer_header(Lines).

%!  paper_added(+Best:dict, +Settings:dict, +Explored:list, +Rest:list, -Added:list) is det.
%
%   The paper's step: modify/5 along the steepest plane's signed
%   gradient, when its slope exceeds the slope setting (else nothing is
%   added). Explored are the explored antecedents and Rest A_new: neither
%   is a new candidate.
paper_added(Best, Settings, Explored, Rest, Added) :-
    (   Best.slope > Settings.slope
    ->  memberchk(ant(Best.antecedent, MProps, _, _), Explored),
        dict_pairs(Best.gradient, _, Gradient),
        direction(Gradient, Best.mean, Direction),
        exclusions(Explored, Rest, Exclude),
        modify(MProps, Direction, Settings.breadth, Exclude, Mods),
        findall(cand(P, Best.antecedent, via(Best.expectation, X, Sign)),
                member(mod(P, X, Sign), Mods), Added)
    ;   Added = []
    ).
