:- module(curiosity_discover,
          [ discover_queue/10,        % +Best, +Explored, +Id, +Props, +Away, +Rest, +Settings, +I, -Added, -Queue
            more/7,                   % +Added, +Settings, +Id, +Props, +Parent, +Via, -More
            jumps/4,                  % +Settings, +Iteration, +Exclude, -New
            neighbours/3,             % +Props, +Exclude, -New
            probe_entry/2             % +Probe, -Entry
          ]).
/** <module> The discovering curiosity

Option curiosity(discover), behind the interface of interface.pl. After
each explored antecedent, the discovering curiosity makes A_new anew. A plane's slopes count only where
they beat shuffles of the same weighted pours (a permutation test at the
significance level given as significance(X)). The candidates of a step are the
antecedents that move the pours past the point where a significant plane's
verdict flips (modify_past/4, every significant plane and parameter), the
neighbours of the antecedent just explored (neighbours/3), and `jumps`
uniformly random valid antecedents (far from anything explored; as many as
a batch has pours by default).

Each candidate and each of A_new gets its novelty, the chance that it
shows a behaviour not yet got as a forest of every pour so far predicts it
(bridge/exploration/novelty.py); A_new keeps the most novel of those that
reach the novelty level. When
nothing reaches it, the antecedent just explored gets more pours
(resample/1, more/7), which may change the forest's mind; when that is
spent too and A_new is empty, the exploration stops.

Before a candidate's batch, its first `probe` pours are simulated
(probe.pl); the budget is `budget` batches' worth of pours, batches and
probes together; with prior_batch(1) the priors take the budget's last
batch (loop.pl). Its theory's second layer is the general rules.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module('../vocabulary').
:- use_module('../validity').
:- use_module(foreign).
:- use_module(state).
:- use_module(modify).
:- use_module(plane_steps).

% The interface of interface.pl; its Python side tests the planes
% (exploration_significant_planes) and predicts and probes the novelty of
% candidates (exploration_predict, exploration_probe).

python_side(['pantarhei.bridge.exploration.steepest',
             'pantarhei.bridge.exploration.novelty']).

% Its own options, read by this curiosity alone: rows of the option table
% (theory/defaults.pl says what option/5, course/2 and prolog_only/1
% mean; theory/option_table.py and settings.pl read them from here).
option(significance, permille, range(0, 1000), 50,
  "discover: the significance level of the permutation test of the planes").
option(permutations, count, range(1, 1000000), 199,
  "discover: shuffles of the permutation test").
option(resample, count, range(0, 1000000), 2,
  "discover: more batches of an antecedent whose planes are all undecided and that queued nothing new").
option(novelty, permille, range(0, 1000), 100,
  "discover: the predicted novelty, from 0 to 1, a candidate needs to be queued").
option(jumps, count, range(1, 1000000), 31,
  "discover: uniformly random valid antecedents drawn as candidates each step").
option(probe, count, range(0, 10000), 8,
  "discover: simulate this many pours of a candidate's batch first, and set it aside for the next when they show no new, reproducible consequent; 0: no probes").
option(probe_attempts, count, range(1, 1000000), 3,
  "discover: candidates probed at most in a step; then the one whose probe scored best is explored").
option(prior_batch, choice, one_of(0, 1), 1,
  "discover: 1 to explore the priors (nothing said: every parameter from its prior, as a question's unsaid ones) with the budget's last batch, 0 not to").

course(significance, discover).
course(permutations, discover).
course(resample, discover).
course(novelty, discover).
course(jumps, discover).
course(probe, discover).
course(probe, nonzero(probe)).
course(probe_attempts, discover).
course(probe_attempts, nonzero(probe)).
course(prior_batch, discover).
course(prior_batch, nonzero(prior_batch)).

prolog_only(significance).
prolog_only(permutations).
prolog_only(resample).
prolog_only(novelty).
prolog_only(jumps).
prolog_only(probe).
prolog_only(probe_attempts).
prolog_only(prior_batch).

budget(Settings, Pours) :-
    Pours is Settings.budget * Settings.batch.

progress_bar(Settings, _{total:Total, unit:pour}) :-
    budget(Settings, Total).

probe_size(Settings, Pours) :-
    Pours is min(Settings.probe, Settings.batch).

%   A candidate is probed unless probes are off (probe(0)), or it is a_0,
%   the priors or more pours of an explored antecedent.
probed(cand(_, _, Via), Settings) :-
    Settings.probe =\= 0,
    Via \== initial,
    Via \== prior,
    Via \= more(_, _).

priors_due(Explored, Settings) :-
    Settings.prior_batch =:= 1,
    \+ memberchk(ant(_, [], _, prior), Explored).

after_batch(step(I1, Id, Cand, Explored, Rest, SetAside, Probes, Sim), Settings, ANew, Trace) :-
    Cand = cand(Props, Parent, Via),
    maplist(entry, Explored, Entries),
    call_bridge(exploration_significant_planes,
                _{antecedents:Entries, ridge:Settings.ridge, seed:Settings.seed,
                  permutations:Settings.permutations,
                  significance:Settings.significance}, Best),
    append(Rest, SetAside, Away),
    discover_queue(Best, Explored, Id, Props, Away, Rest, Settings, I1, Added, Queue),
    more(Added, Settings, Id, Props, Parent, Via, More),
    append(More, Queue, ANew),
    length(ANew, Left),
    plane_step_trace(Best, Best.significant, I1-Id, Cand, Sim, Added, Left, Trace0),
    findall(_{expectation:E, parameters:Xs},
            ( member(Dn, Best.directions), get_dict(expectation, Dn, E),
              get_dict(moves, Dn, Ms),
              findall(X, ( member(M, Ms), get_dict(parameter, M, X) ), Xs) ),
            Planes),
    maplist(probe_entry, Probes, ProbeTrace),
    Trace = Trace0.put(_{best:Trace0.best.put(_{significant:Best.significant, planes:Planes}),
                         probes:ProbeTrace}).

second_layer(_, Facts, Settings, General) :-
    general_layer_if_asked(Facts, Settings, General).

theory_layout(_{rules:true, batches:true,
                header:[ "%   setting(Key, Value): how the exploration ran;",
                         "%   set_aside(Iteration, Attempt, Prop): a proposition of a candidate whose",
                         "%   probe (the Attempt-th of the Iteration, from 0) set it aside." ],
                layer_header:Lines}) :-
    general_layer_header(Lines).

%!  probe_entry(+Probe, -Entry:dict) is det.
%
%   Entry is a probe(Props, Score, Kept, Attempt) of probe.pl as the trace
%   holds it.
probe_entry(probe(P, Sc, K, _), _{antecedent:P, score:Sc, kept:K}).

%!  more(+Added:list, +Settings:dict, +Id, +Props:list, +Parent, +Via, -More:list) is det.
%
%   When no plane led to a new antecedent (Added is empty: none is
%   significant, or its moves are all explored), More holds the antecedent
%   just explored (Id, Props), to be sampled again next (at most
%   `resample` more batches of it): planes that are undecided get more
%   pours before the exploration moves on or stops. Else More is empty.
more(Added, Settings, Id, Props, Parent, Via, More) :-
    (   Via = more(_, K) -> true ; K = 0 ),
    (   Added == [], K < Settings.resample
    ->  K1 is K + 1,
        More = [cand(Props, Parent, more(Id, K1))]
    ;   More = []
    ).

%!  discover_queue(+Best, +Explored, +Id, +Props, +Away, +Rest, +Settings, +I, -Added, -Queue) is det.
%
%   The discovering step of iteration I, after the antecedent Id (Props).
%   Away are antecedents that are no candidates: A_new and those set aside
%   after their probe.
%   The candidates are those of modify_past/4 for every significant plane
%   and parameter of every antecedent with a significant plane (steepest
%   first), every valid antecedent one proposition away from Props
%   (neighbours/3), random valid antecedents (jumps/4), then A_new as it was
%   (Rest). Each gets its novelty (exploration_predict); Queue, the new
%   A_new, holds those that reach the novelty level, the most novel first
%   (ties in the order above). Added are the new ones of Queue, in its
%   order.
discover_queue(Best, Explored, Id, Props, Away, Rest, Settings, I, Added, Queue) :-
    exclusions(Explored, Away, Exclude0),
    foldl(follow(Explored), Best.followed, Exclude0-[], Exclude1-RevFollowed),
    append(RevFollowed, Followed),
    neighbours(Props, Exclude1, Near),
    findall(cand(P, Id, near), member(P, Near), Neighbours),
    append(Exclude1, Near, Exclude2),
    jumps(Settings, I, Exclude2, Far),
    findall(cand(P, none, jump), member(P, Far), Jumps),
    append([Followed, Neighbours, Jumps, Rest], Pool),
    (   Pool == []
    ->  Added = [], Queue = []
    ;   maplist(entry, Explored, Entries),
        findall(P, member(cand(P, _, _), Pool), Cands),
        call_bridge(exploration_predict, _{antecedents:Entries, candidates:Cands,
                                           seed:Settings.seed, batch:Settings.batch,
                                           qualify:Settings.qualify,
                                           novelty:Settings.novelty}, Reply),
        findall(Key-C, ( nth1(K, Pool, C), nth1(K, Reply.queued, true),
                         nth1(K, Reply.novelty, N), Key is -N ),
                Keyed),
        keysort(Keyed, Sorted),
        pairs_values(Sorted, Queue),
        append([Followed, Neighbours, Jumps], New),
        include(in_list(New), Queue, Added)
    ).

%!  jumps(+Settings:dict, +Iteration:integer, +Exclude:list, -New:list) is det.
%
%   New are Settings.jumps valid antecedents drawn uniformly
%   (validity:random_antecedents/3, seeded by the run's seed and the
%   iteration), none in Exclude, each once.
jumps(Settings, I, Exclude, New) :-
    step_seed(Settings, I, Seed),
    random_antecedents(Seed, Settings.jumps, All),
    exclude(in_list(Exclude), All, New0),
    list_to_set(New0, New).

%   in_list(+List, +X): X is an element of List (no lambda: the
%   candidates do not depend on whether library(yall) was loaded first).
in_list(List, X) :-
    memberchk(X, List).

%   follow(+Explored, +F, +Exclude0-Acc0, -Exclude-Acc): the candidates
%   of modify_past/4 for every move of the significant planes of one
%   antecedent (F, from the reply of exploration_significant_planes) added, the
%   new ones also to the exclusions.
follow(Explored, F, Exclude0-Acc0, Exclude-[Added|Acc0]) :-
    get_dict(antecedent, F, AId),
    get_dict(directions, F, Directions),
    memberchk(ant(AId, MProps, _, _), Explored),
    findall(move(E, X, Sign, Flip),
            ( member(Dn, Directions), get_dict(expectation, Dn, E),
              get_dict(moves, Dn, Ms), member(M, Ms),
              get_dict(parameter, M, X), get_dict(sign, M, Sign), get_dict(flip, M, Flip) ),
            Moves),
    modify_past(MProps, Moves, Exclude0, Mods),
    findall(cand(P, AId, via(E, X, Sign)), member(mod(P, E, X, Sign), Mods), Added),
    findall(P, member(mod(P, _, _, _), Mods), Cands),
    append(Exclude0, Cands, Exclude).

%!  neighbours(+Props:list, +Exclude:list, -New:list) is det.
%
%   The valid antecedents not in Exclude that differ from Props by one
%   proposition: one replaced by another value of its dimension, or one of
%   a dimension Props does not use added. Sorted, each once, in the order
%   of the vocabulary's parameters.
neighbours(Props0, Exclude, New) :-
    sort(Props0, Props),
    findall(P1, ( parameter(X, _, _, _, _), candidate_any(Props, X, P1),
                  \+ memberchk(P1, Exclude), valid_antecedent(P1) ),
            All),
    list_to_set(All, New).
