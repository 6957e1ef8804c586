:- module(curiosity_loop,
          [ loop/4,                   % +S0, +Settings, -S, -Stop
            next_move/3,              % +State, +Settings, -Move
            progress_bar/2,           % +Settings, -Bar
            probe_size/2              % +Settings, -Pours
          ]).
/** <module> The loop of Algorithm 1 and its budget

Each step pops a_c from A_new (for the discovering curiosity with probes,
the first candidate whose probe passes: probe.pl), explores it (a batch of
simulations), fits the planes of every explored antecedent, and queues the
new antecedents of the steepest plane: for the paper's curiosity,
modify/5 along it when its slope exceeds the slope setting (paper_added/5);
for the discovering one, its candidates by novelty (discover.pl). The
state (state.pl) and a trace of the step are saved after each step
(exploration_checkpoint).

For the learning curiosity the step queues what the antecedent's pours
teach (teach.pl) and fits no plane, and the budget is `pours`, every pour.
Otherwise the budget is `budget` batches of simulations: as many antecedents for
the paper's curiosity; the discovering one also spends pours on probes
and on more batches of undecided antecedents. With prior_batch(1) (the default)
the last batch of the budget (or the next, when A_new is empty) goes to
the priors: the empty antecedent, every parameter drawn from its prior,
unprobed and unranked. A question leaves parameters unsaid, and they
follow their priors; the antecedents curiosity explores set nearly every
parameter away from them, so without this batch the general rules learned
from the pours (bridge/learning/) answer every question by extrapolation.
Coming last, it leaves the curiosity's course before it as it is without
the priors (the budget less one batch).
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(bridge).
:- use_module(state).
:- use_module(probe).
:- use_module(discover).
:- use_module(teach).
:- use_module(modify).

%!  loop(+S0, +Settings, -S, -Stop) is det.
%
%   Explore antecedents from A_new until it is empty (Stop = a_new_empty)
%   or the budget of `budget` batches of simulations would be exceeded by
%   another step (Stop = budget): as many antecedents for the paper's
%   curiosity, which samples each once; the discovering one may sample an
%   undecided antecedent again and spends pours on probes, and so explores
%   at most as many with the same budget of pours. With prior_batch(1) the
%   priors take the batch before the step that could exceed the budget
%   with it, or the next when A_new is empty (priors_pending/2).
loop(S0, Settings, S, Stop) :-
    next_move(S0, Settings, Move),
    (   Move = stop(Stop)
    ->  S = S0
    ;   Move == priors
    ->  S0 = st(I, Explored, ANew, SetAside),
        step(st(I, Explored, [cand([], none, prior)|ANew], SetAside), Settings, S1),
        loop(S1, Settings, S, Stop)
    ;   step(S0, Settings, S1),
        loop(S1, Settings, S, Stop)
    ).

%!  next_move(+State, +Settings:dict, -Move) is det.
%
%   Move is what the loop does next in State: `priors` (their batch),
%   `step` (the next of A_new) or stop(Why).
next_move(S0, Settings, Move) :-
    S0 = st(_, Explored, ANew, _),
    spent(S0, Settings, Spent),
    step_cost(Settings, Most),
    budget(Settings, Budget),
    (   priors_pending(Explored, Settings),
        Spent + Settings.batch =< Budget,
        ( ANew == [] ; Spent + Most + Settings.batch > Budget )
    ->  Move = priors
    ;   ANew == []
    ->  Move = stop(a_new_empty)
    ;   Spent + Most > Budget
    ->  Move = stop(budget)
    ;   Move = step
    ).

%   priors_pending(+Explored, +Settings): the priors are to be explored
%   (prior_batch(1)) and have not been yet. Their batch is the last of the
%   budget, or comes when A_new is empty: their pours then teach the
%   general rules without changing the course of the curiosity before
%   them.
priors_pending(Explored, Settings) :-
    Settings.curiosity == discover,
    Settings.prior_batch =:= 1,
    \+ memberchk(ant(_, [], _, prior), Explored).

%   budget(+Settings, -Pours): the budget in pours: `pours` for the
%   learning curiosity (every pour the run simulates), the pours of
%   `budget` batches for the others.
budget(Settings, Pours) :-
    (   Settings.curiosity == learn
    ->  Pours = Settings.pours
    ;   Pours is Settings.budget * Settings.batch
    ).

%!  progress_bar(+Settings:dict, -Bar:dict) is det.
%
%   Bar is what the progress bar counts, _{total:Total, unit:Unit}: the
%   budget in pours (unit `pour`) for the learning and the discovering
%   curiosity, in explored antecedents (unit `rule`) for the paper's.
progress_bar(Settings, _{total:Total, unit:Unit}) :-
    (   Settings.curiosity == paper
    ->  Total = Settings.budget, Unit = rule
    ;   budget(Settings, Total), Unit = pour
    ).

%   spent(+State, +Settings, -Pours): the pours spent so far: a batch per
%   iteration and a probe per candidate set aside after its probe.
spent(st(I, _, _, SetAside), Settings, Pours) :-
    length(SetAside, K),
    probe_size(Settings, M),
    Pours is I * Settings.batch + K * M.

%   step_cost(+Settings, -Pours): the most pours a step spends: its batch,
%   and the probes of the candidates it may set aside. The loop stops when
%   that would exceed the budget, so a step never depends on the budget
%   and a longer run continues a shorter one.
step_cost(Settings, Pours) :-
    probe_size(Settings, M),
    Pours is Settings.batch + (Settings.probe_attempts - 1) * M.

%!  probe_size(+Settings:dict, -Pours:integer) is det.
%
%   Pours are those a probe simulates: the first `probe` of a batch (the
%   discovering curiosity), or none.
probe_size(Settings, M) :-
    (   Settings.curiosity == discover
    ->  M is min(Settings.probe, Settings.batch)
    ;   M = 0
    ).

%   step(+S0, +Settings, -S): one iteration of Algorithm 1: pop a_c (for
%   the discovering curiosity with probes: the first candidate whose probe
%   passes, choose/6), explore it, fit the planes of every explored
%   antecedent, and modify the one with the steepest plane (for the
%   discovering curiosity: the steepest significant plane).
step(S0, Settings, st(I1, Explored1, ANew, SetAside)) :-
    S0 = st(I, Explored, _, SetAside0),
    I1 is I + 1,
    choose(S0, Settings, Cand, Attempt, Rest, Probes),
    Cand = cand(Props, _, _),
    findall(aside(I1, K, P), member(probe(P, _, false, K), Probes), NewAside),
    append(SetAside0, NewAside, SetAside),
    explored(Cand, Explored, Id, Explored1),
    (   memberchk(probe(_, _, true, Attempt), Probes)
    ->  probe_size(Settings, Probed)      % its probe's pours are the batch's first
    ;   Probed = 0
    ),
    call_bridge(exploration_simulate, _{id:Id, antecedent:Props, iteration:I1,
                                        attempt:Attempt, batch:Settings.batch,
                                        seed:Settings.seed, probed:Probed}, Sim),
    (   Settings.curiosity == learn
    ->  teach_queue(Explored1, Id, Props, Rest, Settings, Added, ANew),
        length(ANew, Left),
        learn_trace(I1-Id, Cand, Sim, Added, ANew, Trace)
    ;   maplist(entry, Explored1, Entries),
        best_plane(Settings, Entries, Best),
        a_new(Best, Settings, Explored1, Id, Cand, Rest, SetAside, I1, Added, ANew),
        length(ANew, Left),
        step_trace(Best, Settings, I1-Id, Cand, Sim, Probes, Added, Left, Trace)
    ),
    S1 = st(I1, Explored1, ANew, SetAside),
    format(string(State), "~k", [S1]),
    call_bridge(exploration_checkpoint, _{iteration:I1, state:State, trace:Trace,
                                          explored:I1, a_new:Left, out:Settings.out}, _).

%   best_plane(+Settings, +Entries, -Best): the plane the step follows:
%   the significant planes of the explored antecedents (Entries) for the
%   discovering curiosity (exploration_significant_planes), the steepest
%   for the paper's (exploration_steepest_plane).
best_plane(Settings, Entries, Best) :-
    (   Settings.curiosity == discover
    ->  call_bridge(exploration_significant_planes,
                    _{antecedents:Entries, ridge:Settings.ridge, seed:Settings.seed,
                      permutations:Settings.permutations,
                      significance:Settings.significance}, Best)
    ;   call_bridge(exploration_steepest_plane,
                    _{antecedents:Entries, ridge:Settings.ridge}, Best)
    ).

%   explored(+Cand, +Explored, -Id, -Explored1): Explored with the
%   candidate added as the next antecedent, Id (a<N>); for more pours of an
%   explored antecedent (more(Id, K), again(Id)), its Id, and Explored as
%   it is.
explored(cand(Props, Parent, Via), Explored, Id, Explored1) :-
    (   ( Via = more(Id, _) ; Via = again(Id) )
    ->  Explored1 = Explored
    ;   length(Explored, N0),
        N is N0 + 1,
        format(atom(Id), "a~w", [N]),
        append(Explored, [ant(Id, Props, Parent, Via)], Explored1)
    ).

%   a_new(+Best, +Settings, +Explored, +Id, +Cand, +Rest, +SetAside, +I,
%         -Added, -ANew): A_new after the step that explored Cand (Id),
%   Rest the A_new before it without Cand, and Added the new candidates.
a_new(Best, Settings, Explored1, Id, cand(Props, Parent, Via), Rest, SetAside, I1, Added, ANew) :-
    (   Settings.curiosity == discover
    ->  append(Rest, SetAside, Away),
        discover_queue(Best, Explored1, Id, Props, Away, Rest, Settings, I1, Added, Queue),
        more(Added, Settings, Id, Props, Parent, Via, More),
        append(More, Queue, ANew)
    ;   paper_added(Best, Settings, Explored1, Rest, Added),
        append(Rest, Added, ANew)
    ).

%   step_trace(+Best, +Settings, +I-Id, +Cand, +Sim, +Probes, +Added,
%              +Left, -Trace): the step in the trace: what was explored,
%   its simulations, the best plane, what was added to A_new and, for the
%   discovering curiosity, the probes.
step_trace(Best, Settings, I1-Id, cand(Props, Parent, Via), Sim, Probes, Added, Left, Trace) :-
    findall(P, member(cand(P, _, _), Added), AddedProps),
    best_trace(Best, Settings, BestT),
    format(string(ViaText), "~w", [Via]),
    Trace0 = _{iteration:I1, id:Id, antecedent:Props, parent:Parent, via:ViaText,
               simulations:Sim.simulations, failed:Sim.failed,
               best:BestT, added:AddedProps, a_new:Left},
    (   Settings.curiosity == discover
    ->  maplist(probe_entry, Probes, ProbeTrace),
        Trace = Trace0.put(probes, ProbeTrace)
    ;   Trace = Trace0
    ).

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

%   best_trace(+Best, +Settings, -BestT): the best plane in the trace: its
%   antecedent, expectation, slope and mean score, the five largest
%   components of its direction when it is followed, and for the
%   discovering curiosity whether it is significant and the parameters of
%   each significant plane.
best_trace(Best, Settings, BestT) :-
    dict_pairs(Best.gradient, _, Gradient),
    findall(_{parameter:X, component:G},
            ( followed(Best, Settings),
              direction(Gradient, Best.mean, D), top(D, 5, Top), member(X-G, Top) ),
            Dir),
    Best0 = _{antecedent:Best.antecedent, expectation:Best.expectation,
              slope:Best.slope, mean:Best.mean, direction:Dir},
    (   Settings.curiosity == discover
    ->  findall(_{expectation:E, parameters:Xs},
                ( member(Dn, Best.directions), get_dict(expectation, Dn, E),
                  get_dict(moves, Dn, Ms),
                  findall(X, ( member(M, Ms), get_dict(parameter, M, X) ), Xs) ),
                Planes),
        BestT = Best0.put(_{significant:Best.significant, planes:Planes})
    ;   BestT = Best0
    ).

%   the paper's curiosity, significant for the discovering one).
followed(Best, Settings) :-
    (   Settings.curiosity == discover
    ->  Best.significant == true
    ;   Best.slope > Settings.slope
    ).

%   paper_added(+Best, +Settings, +Explored, +Rest, -Added): the paper's
%   step: modify/5 along the steepest plane's signed gradient, when its
%   slope exceeds the slope setting (else nothing is added).
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
