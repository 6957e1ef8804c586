:- module(curiosity_state,
          [ initial_state/3,          % +Begun, +Settings, -State
            exclusions/3,             % +Explored, +Away, -Exclude
            entry/2,                  % +Ant, -Entry
            step_seed/3               % +Settings, +Iteration, -Seed
          ]).
/** <module> The state of the exploration loop

The loop's state is the term st(Iteration, Explored, ANew, SetAside):
Explored lists ant(Id, Props, Parent, Via) in the order of exploration,
ANew lists cand(Props, Parent, Via) in the order they are popped (for the
paper's curiosity a queue, the oldest first; for the discovering one the
most novel first). Via is `initial`; `prior` for the empty antecedent
explored last (prior/1); via(Expectation, Param, Sign) for the plane,
parameter and sign (up or down) that produced it; `near` for a neighbour
of the antecedent explored before it; `jump` for a random valid
antecedent; more(Id, K) for the K-th more batch of an explored
antecedent; or again(Id) for another batch of an explored antecedent
chosen by the learning curiosity (learn.pl). SetAside lists aside(Iteration, Attempt, Props) for each
candidate set aside after its probe (probe.pl). The state is saved after
every explored antecedent, so an exploration can resume.
*/

:- use_module(library(lists)).

%!  initial_state(+Begun:dict, +Settings:dict, -State) is det.
%
%   The state the loop starts from: the one saved, when the exploration
%   resumes (Begun, the reply of exploration_begin, holds it as text),
%   else a_0 (Settings.initial) alone in A_new.
initial_state(Begun, Settings, S) :-
    (   get_dict(state, Begun, Text), Text \== '', Text \== ""
    ->  term_string(S, Text)
    ;   S = st(0, [], [cand(Settings.initial, none, initial)], [])
    ).

%!  exclusions(+Explored:list, +Away:list, -Exclude:list) is det.
%
%   Exclude lists the antecedents that are no new candidates: those of
%   Explored (ant/4) and of Away (cand/3 of A_new, aside/3 of those set
%   aside after their probe).
exclusions(Explored, Away, Exclude) :-
    findall(P, ( member(ant(_, P, _, _), Explored)
               ; member(cand(P, _, _), Away)
               ; member(aside(_, _, P), Away) ), Exclude).

%!  entry(+Ant, -Entry:dict) is det.
%
%   Entry is the explored antecedent Ant (ant/4) as the foreign
%   predicates take it: its id and propositions.
entry(ant(Id, Props, _, _), _{id:Id, antecedent:Props}).

%!  step_seed(+Settings:dict, +Iteration:integer, -Seed:integer) is det.
%
%   Seed is the seed of a step's random candidates (the discovering
%   curiosity's jumps, the learning curiosity's reach): derived from the
%   run's seed and the iteration, so a resumed run draws what the
%   uninterrupted one drew.
step_seed(Settings, I, Seed) :-
    Seed is Settings.seed * 1000003 + I.
