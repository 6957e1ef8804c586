:- module(curiosity_learn,
          [ teach_queue/7,            % +Explored, +Id, +Props, +Rest, +Settings, -Added, -Queue
            children/4,               % +Props, +Most, +Exclude, -New
            reach/5,                  % +Seed, +N, +Most, +Exclude, -Bodies
            wholes/5                  % +Seed, +N, +Most, +Exclude, -Bodies
          ]).
/** <module> The learning curiosity

Option curiosity(learn), behind the interface of interface.pl. It
explores what questions say: a_0 is the ordinary pour (the empty
antecedent), and each explored
antecedent makes candidates of itself with one proposition more
(children/4), up to `body` propositions. An explored antecedent means what
a question with the same words means, so its pours are those a question
draws, and the rule written for it is one a question can use.

Beyond the children, each step draws `reach` random valid antecedents of
2 to `body` propositions (reach/5, seeded by the run's seed and the
iteration): pairs whose propositions no explored antecedent has met, where
an interaction hides as well as anywhere.

After each batch every candidate, the new ones, those already in A_new
and every explored antecedent (for another batch, again(Id)), is valued by
what its pours would teach the theory (exploration_teach,
bridge/exploration/teaching.py): how far its answer would move from the
one the theory gives it now, how uncertain its likelihoods still are (a
pair of one pose, liquid or bowl, which may interact, so before it has
pours), how unsure the model of every pour is about the very pours of its
next batch, and the chance that they show a behaviour no pour has shown
yet, as learning progress (less where its pours have shown nothing new).
A_new keeps the `queue` most valuable, the most valuable first; the
candidates a step values are so at most `queue`, the new children and the
explored antecedents.

Every `whole_every` steps (every third by default) the next antecedent
is a whole instead: of the random valid antecedents whose parts reach/5
offers, drawn whole, the one whose batch is likeliest to have a
consequent no explored antecedent has (wholes/5, whole_step/2). No
question says a whole, but its pours find what random exploration finds
(the paper's criterion: behaviours not seen before) and teach the model
of every pour beyond the neighbourhood of the ordinary pour. A whole has
no rule of its own (learned_layer/3 of writer.pl); its consequent is in
the theory as an explored antecedent's pours (held/4).
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(random)).
:- use_module('../vocabulary').
:- use_module('../validity').
:- use_module('../default_values', [default/2]).
:- use_module(foreign).
:- use_module(state).
:- use_module(writer).

% The interface of interface.pl: the budget is every pour, pours(N);
% nothing is probed; the theory is one layer, the rules of the explored
% antecedents (learned_layer/3 of writer.pl); its Python side values the
% candidates (exploration_teach).

python_side(['pantarhei.bridge.exploration.teaching']).

% Its own options, read by this curiosity alone: rows of the option table
% (theory/defaults.pl says what option/5, course/2 and prolog_only/1
% mean; theory/option_table.py and settings.pl read them from here).
% Its budget, pours, follows budget, the other curiosities' budget, in the
% table (option_after/2); its other rows follow the curiosity row.
option(pours, count, range(1, 1000000), 775,
  "learn: the budget: every pour the run simulates, in batches").
option(body, count, range(1, 4), 2,
  "learn: the most propositions an explored antecedent says").
option(queue, count, range(1, 100000), 64,
  "learn: the candidates A_new keeps, the most valuable first").
option(uncertainty, permille, range(0, none), 1000,
  "learn: the weight of a candidate's uncertain likelihoods beside how far its answer would move").
option(doubt, permille, range(0, none), 1000,
  "learn: the weight of the model's doubt (entropy, in bits) about the pours of a candidate's next batch, less as its own pours pile up").
option(newness, permille, range(0, none), 2000,
  "learn: the weight of the chance that a pour of a candidate's next batch shows a behaviour no two pours have shown").
option(reach, count, range(0, 100000), 16,
  "learn: random valid antecedents of 2 to `body` propositions drawn as candidates each step, beyond the children of what was explored").
option(whole_every, count, range(0, 100000), 3,
  "learn: every this many steps, the next antecedent is the one of the `reach` uniformly random valid antecedents, drawn whole, whose batch is likeliest to have a consequent no explored antecedent has (0: never)").

course(pours, learn).
course(body, learn).
course(queue, learn).
course(uncertainty, learn).
course(doubt, learn).
course(newness, learn).
course(reach, learn).
course(whole_every, learn).

prolog_only(doubt).
prolog_only(newness).
prolog_only(reach).
prolog_only(whole_every).
option_after(pours, budget).

% A batch is learn_batch pours, and a_0 is the ordinary pour (the empty
% antecedent), unless the run says otherwise.
unsaid(batch, N) :- default(learn_batch, N).
unsaid(initial, []).

budget(Settings, Pours) :-
    Pours = Settings.pours.

progress_bar(Settings, _{total:Total, unit:pour}) :-
    budget(Settings, Total).

probe_size(_, 0).

probed(_, _) :- fail.

priors_due(_, _) :- fail.

after_batch(step(I1, Id, Cand, Explored, Rest, _, _, Sim), Settings, ANew, Trace) :-
    Cand = cand(Props, _, _),
    teach_queue(Explored, Id, Props, Rest, Settings.put(iteration, I1), Added, ANew),
    learn_trace(I1-Id, Cand, Sim, Added, ANew, Trace).

second_layer(Explored, _, Settings, Layer) :-
    learned_layer(Explored, Settings, Layer).

theory_layout(_{rules:false, batches:false,
                header:["%   setting(Key, Value): how the exploration ran."],
                layer_header:[ "% The rules curiosity learned: per expectation, a default (the",
                               "% ordinary pour, the empty antecedent) and the explored antecedents",
                               "% whose likelihoods the rest of the theory does not give",
                               "% (bridge/learning/generalize.py over the explored antecedents).",
                               "% provenance(Id, antecedent, A): the explored antecedent of its body;",
                               "% support: the pours whose description holds the body; kept: how",
                               "% many of them keep the head; confidence_permille: P(head | body), the",
                               "% share of the pours sampled for the body (the rest an ordinary pour)",
                               "% that keep the head, every pour of the run pooled to estimate it.",
                               "% sup/2 below orders the rules that one scene can hold (see",
                               "% bridge/learning/layers.py)." ]}).

%   learn_trace(+I-Id, +Cand, +Sim, +Added, +ANew, -Trace): a step of the
%   learning curiosity in the trace: what was explored, its simulations,
%   the children queued and the head of A_new (the next to explore).
learn_trace(I1-Id, cand(Props, Parent, Via), Sim, Added, ANew, Trace) :-
    findall(P, member(cand(P, _, _), Added), AddedProps),
    format(string(ViaText), "~w", [Via]),
    length(ANew, Left),
    (   ANew = [cand(Next, _, _)|_] -> true ; Next = [] ),
    Trace = _{iteration:I1, id:Id, antecedent:Props, parent:Parent, via:ViaText,
              simulations:Sim.simulations, failed:Sim.failed,
              added:AddedProps, next:Next, a_new:Left}.

%!  teach_queue(+Explored, +Id, +Props, +Rest, +Settings:dict, -Added:list, -Queue:list) is det.
%
%   The learning step after the antecedent Id (Props) was explored at
%   iteration Settings.iteration: the candidates are its children
%   (children/4; not explored, not in Rest), `reach` random antecedents
%   (reach/5, seeded by the run's seed and the iteration), Rest (A_new
%   without what was just explored) and each explored antecedent but a
%   whole for another batch (again(Id)); each is valued, for the next
%   iteration, (exploration_teach) and Queue holds the `queue` most
%   valuable with a value above 0, the most valuable first (ties in the
%   order above). When the next iteration is a whole step (whole_step/2),
%   the wholes the random antecedents are parts of (wholes/5) are valued
%   too, by the chance that their consequent is one no explored
%   antecedent has, and the likeliest goes first in Queue. Added are
%   Queue's new children, in its order.
teach_queue(Explored, Id, Props, Rest, Settings, Added, Queue) :-
    exclusions(Explored, Rest, Exclude),
    children(Props, Settings.body, Exclude, Kids),
    step_seed(Settings, Settings.iteration, Seed),
    append([Props|Kids], Exclude, Known),
    reach(Seed, Settings.reach, Settings.body, Known, Far),
    Next is Settings.iteration + 1,
    (   whole_step(Settings, Next)
    ->  wholes(Seed, Settings.reach, Settings.body, Known, Whole)
    ;   Whole = []
    ),
    findall(cand(P, Id, near), member(P, Kids), Near),
    findall(cand(P, Id, reach), member(P, Far), Reached),
    findall(cand(P, Id, whole), member(P, Whole), Wholes),
    append(Near, Reached, New),
    exclude(again_cand, Rest, Waiting),
    findall(cand(P, A, again(A)), ( member(ant(A, P, _, Via), Explored), Via \== whole ), Again),
    append([New, Waiting, Again], Pool),
    (   Pool == [], Wholes == []
    ->  Added = [], Queue = []
    ;   maplist(entry, Explored, Entries),
        append(Pool, Wholes, Valued),
        findall(P, member(cand(P, _, _), Valued), Cands),
        call_bridge(exploration_teach, _{antecedents:Entries, candidates:Cands, wholes:Whole,
                                         seed:Settings.seed, batch:Settings.batch,
                                         iteration:Next,
                                         uncertainty:Settings.uncertainty,
                                         doubt:Settings.doubt, newness:Settings.newness},
                    Reply),
        findall(Key-C, ( nth1(K, Valued, C), nth1(K, Reply.value, V), V > 0, Key is -V ),
                Keyed),
        keysort(Keyed, Sorted),
        pairs_values(Sorted, All),
        partition(in_list(Wholes), All, Likeliest, Others),
        first_kept(Others, Settings.queue, Kept),
        (   Likeliest = [First|_]
        ->  Queue = [First|Kept]
        ;   Queue = Kept
        ),
        include(in_list(New), Queue, Added)
    ).

%   first_kept(+All, +Most, -Kept): Kept are the first Most of All (all
%   of them if fewer).
first_kept(All, Most, Kept) :-
    length(All, N),
    Keep is min(N, Most),
    length(Kept, Keep),
    append(Kept, _, All).

%   whole_step(+Settings, +I): iteration I explores a whole (every
%   `whole_every` iterations; never when it is 0).
whole_step(Settings, I) :-
    Every = Settings.whole_every,
    Every > 0,
    I mod Every =:= 0.

%!  reach(+Seed:integer, +N:integer, +Most:integer, +Exclude:list, -Bodies:list) is det.
%
%   Bodies are N random valid antecedents of 2 to Most propositions (none
%   when Most is below 2), none in Exclude, each once, in the order drawn:
%   each a random part of a uniformly random valid antecedent of the whole
%   vocabulary (random_antecedents/3), its size uniform. The same Seed
%   gives the same Bodies.
reach(_, _, Most, _, []) :-
    Most < 2, !.
reach(Seed, N, Most, Exclude, Bodies) :-
    random_antecedents(Seed, N, Wholes),
    setup_call_cleanup(
        ( random_property(state(Saved)), set_random(seed(Seed)) ),
        maplist(random_part(Most), Wholes, Parts),
        set_random(state(Saved))),
    exclude(in_list(Exclude), Parts, Parts1),
    list_to_set(Parts1, Bodies).

random_part(Most, Whole, Part) :-
    length(Whole, L),
    Top is min(Most, L),
    random_between(2, Top, K),
    random_permutation(Whole, Shuffled),
    length(Part0, K),
    append(Part0, _, Shuffled),
    sort(Part0, Part).

%!  wholes(+Seed:integer, +N:integer, +Most:integer, +Exclude:list, -Bodies:list) is det.
%
%   Bodies are the first N uniformly random valid antecedents of the whole
%   vocabulary that reach/5 takes its parts from (the same Seed), those of
%   more than Most propositions and in no Exclude, each once: where a
%   behaviour no pour has shown may lie, as random exploration finds them.
wholes(Seed, N, Most, Exclude, Bodies) :-
    random_antecedents(Seed, N, All),
    exclude(in_list(Exclude), All, Fresh),
    include(longer_than(Most), Fresh, Long),
    list_to_set(Long, Bodies).

longer_than(Most, Props) :-
    length(Props, L),
    L > Most.

%   again_cand(+Cand): Cand is another batch of an explored antecedent.
again_cand(cand(_, _, again(_))).

%   in_list(+List, +X): X is an element of List (helpers, not lambdas: the
%   queue does not depend on whether library(yall) was loaded first).
in_list(List, X) :-
    memberchk(X, List).

%!  children(+Props:list, +Most:integer, +Exclude:list, -New:list) is det.
%
%   New are the valid antecedents of Props with one proposition added,
%   from a dimension Props does not use, none in Exclude, none of more than
%   Most propositions; sorted, in the order of the vocabulary's
%   propositions.
children(Props0, Most, Exclude, New) :-
    sort(Props0, Props),
    length(Props, N),
    (   N >= Most
    ->  New = []
    ;   findall(Dim, ( member(P, Props), proposition(P, Dim, _, _) ), Used),
        findall(P1, ( proposition(Q, Dim, _, _), \+ memberchk(Dim, Used),
                      sort([Q|Props], P1),
                      \+ memberchk(P1, Exclude), valid_antecedent(P1) ),
                All),
        list_to_set(All, New)
    ).
