:- module(curiosity_loop,
          [ loop/4,                   % +S0, +Settings, -S, -Stop
            next_move/3,              % +State, +Settings, -Move
            draws/6                   % +Probes, +Settings, +Props, +Attempt, +Probed, -Draws
          ]).
/** <module> The loop of Algorithm 1 and its budget

Each step pops a_c from A_new (when the curiosity probes, the first
candidate whose probe passes: probe.pl), explores it (a batch of
simulations) and lets the run's curiosity queue what comes next and say
what the step records (after_batch of interface.pl: the steepest plane
and modify/5 for the paper's curiosity, paper.pl; the significant planes
and candidates by novelty for the discovering one, discover.pl; what the
pours would teach for the learning one, learn.pl). The state (state.pl)
and a trace of the step are saved after each step
(exploration_checkpoint).

The budget is in pours, as the curiosity counts it (budget of
interface.pl): `pours`, every pour, for the learning curiosity; `budget`
batches for the others (as many antecedents for the paper's curiosity;
the discovering one also spends pours on probes and on more batches of
undecided antecedents). When the curiosity asks for it (priors_due: the
discovering one, with prior_batch(1), the default) the last batch of the
budget (or the next, when A_new is empty) goes to the priors: the empty
antecedent, every parameter drawn from its prior, unprobed and unranked.
A question leaves parameters unsaid, and they follow their priors; the
antecedents curiosity explores set nearly every parameter away from them,
so without this batch the general rules learned from the pours
(bridge/learning/) answer every question by extrapolation. Coming last,
it leaves the curiosity's course before it as it is without the priors
(the budget less one batch).
*/

:- use_module(library(lists)).
:- use_module(foreign).
:- use_module(probe).
:- use_module(interface).
:- use_module('../learned_rules', [antecedent_id/2]).

%!  loop(+S0, +Settings, -S, -Stop) is det.
%
%   Explore antecedents from A_new until it is empty (Stop = a_new_empty)
%   or the budget would be exceeded by another step (Stop = budget). When
%   the priors are due, they take the batch before the step that could
%   exceed the budget with it, or the next when A_new is empty.
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
    by_curiosity(Settings, budget(Settings, Budget)),
    (   by_curiosity(Settings, priors_due(Explored, Settings)),
        Spent + Settings.batch =< Budget,
        ( ANew == [] ; Spent + Most + Settings.batch > Budget )
    ->  Move = priors
    ;   ANew == []
    ->  Move = stop(a_new_empty)
    ;   Spent + Most > Budget
    ->  Move = stop(budget)
    ;   Move = step
    ).

%   spent(+State, +Settings, -Pours): the pours spent so far: a batch per
%   iteration and a probe per candidate set aside after its probe.
spent(st(I, _, _, SetAside), Settings, Pours) :-
    length(SetAside, K),
    by_curiosity(Settings, probe_size(Settings, M)),
    Pours is I * Settings.batch + K * M.

%   step_cost(+Settings, -Pours): the most pours a step spends: its batch,
%   and the probes of the candidates it may set aside. The loop stops when
%   that would exceed the budget, so a step never depends on the budget
%   and a longer run continues a shorter one.
step_cost(Settings, Pours) :-
    by_curiosity(Settings, probe_size(Settings, M)),
    Pours is Settings.batch + (Settings.probe_attempts - 1) * M.

%   step(+S0, +Settings, -S): one iteration of Algorithm 1: pop a_c (when
%   the curiosity probes: the first candidate whose probe passes,
%   choose/6), explore it, and let the curiosity make A_new and the
%   step's trace (after_batch).
step(S0, Settings, st(I1, Explored1, ANew, SetAside)) :-
    S0 = st(I, Explored, _, SetAside0),
    I1 is I + 1,
    choose(S0, Settings, Cand, Attempt, Rest, Probes),
    Cand = cand(Props, _, _),
    findall(aside(I1, K, P), member(probe(P, _, false, K), Probes), NewAside),
    append(SetAside0, NewAside, SetAside),
    explored(Cand, Explored, Id, Explored1),
    (   memberchk(probe(_, _, true, Attempt), Probes)
    ->  by_curiosity(Settings, probe_size(Settings, Probed))  % its probe's pours come first
    ;   Probed = 0
    ),
    call_bridge(exploration_simulate, _{id:Id, antecedent:Props, iteration:I1,
                                        attempt:Attempt, batch:Settings.batch,
                                        seed:Settings.seed, probed:Probed}, Sim),
    by_curiosity(Settings, after_batch(step(I1, Id, Cand, Explored1, Rest, SetAside, Probes, Sim),
                                       Settings, ANew, Trace0)),
    draws(Probes, Settings, Props, Attempt, Probed, Draws),
    Trace = Trace0.put(draws, Draws),
    length(ANew, Left),
    S1 = st(I1, Explored1, ANew, SetAside),
    format(string(State), "~k", [S1]),
    call_bridge(exploration_checkpoint, _{iteration:I1, state:State, trace:Trace,
                                          explored:I1, a_new:Left, out:Settings.out}, _).

%!  draws(+Probes:list, +Settings:dict, +Props:list, +Attempt:integer,
%!        +Probed:integer, -Draws:list) is det.
%
%   Draws are the step's pours as its trace records them, in the order
%   they were simulated: for each candidate probed, the first pours of its
%   attempt's batch, then the pours of the explored antecedent's batch
%   that its probe had not simulated. A draw is antecedent (its
%   propositions), attempt and pours [From, To]: pours From to To - 1 of
%   the batch of `batch` pours sampled with the seed of the iteration and
%   the attempt. The trace is the record of every pour of the run: a
%   resumed exploration and the evaluation draw them again from it, and
%   read their scores from the store.
draws(Probes, Settings, Props, Attempt, Probed, Draws) :-
    by_curiosity(Settings, probe_size(Settings, M)),
    findall(_{antecedent:P, attempt:K, pours:[0, M]}, member(probe(P, _, _, K), Probes), Probing),
    append(Probing, [_{antecedent:Props, attempt:Attempt, pours:[Probed, Settings.batch]}], Draws).

%   explored(+Cand, +Explored, -Id, -Explored1): Explored with the
%   candidate added as the next antecedent, Id (a<N>); for more pours of an
%   explored antecedent (more(Id, K), again(Id)), its Id, and Explored as
%   it is.
explored(cand(Props, Parent, Via), Explored, Id, Explored1) :-
    (   ( Via = more(Id, _) ; Via = again(Id) )
    ->  Explored1 = Explored
    ;   length(Explored, N0),
        N is N0 + 1,
        antecedent_id(N, Id),
        append(Explored, [ant(Id, Props, Parent, Via)], Explored1)
    ).
