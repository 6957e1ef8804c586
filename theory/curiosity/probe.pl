:- module(curiosity_probe,
          [ choose/6                  % +State, +Settings, -Cand, -Attempt, -Rest, -Probes
          ]).
/** <module> Probes: which candidate of A_new a step explores

When the run's curiosity probes a candidate (its probe policy, probed of
interface.pl: the discovering curiosity's), the guess that it shows
something new is checked before a batch is spent on it: the first `probe`
pours of the candidate's batch are simulated, and when they do not show a
new, reproducible consequent the candidate is set aside and the next one
probed, at most `probe_attempts` of them (choose/6). The probes are spent
from the budget (loop.pl).
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(foreign).
:- use_module(state).
:- use_module(interface).

%!  choose(+State, +Settings:dict, -Cand, -Attempt:integer, -Rest:list, -Probes:list) is det.
%
%   Cand is the candidate this iteration explores, Attempt the attempt
%   whose pours its batch is (0: the iteration's own), Rest A_new
%   without it and the candidates probed before it, and Probes, probe(Props,
%   Score, Kept, Attempt) for each candidate probed, in the order of
%   A_new. When the curiosity does not probe the head of A_new (probed
%   of interface.pl: not the paper's or the learning curiosity, nor
%   probe(0), a_0 and more batches) it is the head. Otherwise
%   the first `probe` pours of the head's batch are simulated, and it
%   is explored when they show a new, reproducible consequent
%   (exploration_probe); else the next is probed, at most
%   `probe_attempts` of them, and the one whose probe scored best is
%   explored.
choose(st(I, Explored, [C|Rest], _), Settings, Cand, Attempt, Rest1, Probes) :-
    (   unprobed(C, Settings)
    ->  Cand = C, Attempt = 0, Rest1 = Rest, Probes = []
    ;   I1 is I + 1,
        maplist(entry, Explored, Entries),
        probe_loop([C|Rest], Entries, Settings, I1, 0, [], Cand, Attempt, Rest1, Probes)
    ).

%   unprobed(+Cand, +Settings): Cand is explored without a probe, as the
%   curiosity's probe policy says.
unprobed(Cand, Settings) :-
    \+ by_curiosity(Settings, probed(Cand, Settings)).

%   probe_loop(+Cands, +Entries, +Settings, +I1, +K, +Tried, -Cand,
%              -Attempt, -Rest, -Probes): probe the head of Cands as
%   attempt K, Tried the attempts before it (t(Score, K, Cand), the
%   latest first); see choose/6.
probe_loop([C|Rest], Entries, Settings, I1, K, Tried, Cand, Attempt, Rest1, Probes) :-
    C = cand(Props, _, _),
    call_bridge(exploration_probe, _{antecedents:Entries, antecedent:Props,
                                     iteration:I1, attempt:K, batch:Settings.batch,
                                     seed:Settings.seed, probe:Settings.probe,
                                     qualify:Settings.qualify}, R),
    Tried1 = [t(R.score, K, C)|Tried],
    K1 is K + 1,
    (   R.pass == true
    ->  probe_end(Tried1, K, Rest, Cand, Attempt, Rest1, Probes)
    ;   K1 < Settings.probe_attempts,
        Rest = [Next|_], \+ unprobed(Next, Settings)
    ->  probe_loop(Rest, Entries, Settings, I1, K1, Tried1, Cand, Attempt, Rest1, Probes)
    ;   best_probe(Tried1, Best),
        probe_end(Tried1, Best, Rest, Cand, Attempt, Rest1, Probes)
    ).

%   probe_end(+Tried, +Chosen, +Rest, -Cand, -Attempt, -Rest, -Probes):
%   the attempt Chosen of Tried is explored, the others are set aside.
probe_end(Tried, Chosen, Rest, Cand, Chosen, Rest, Probes) :-
    memberchk(t(_, Chosen, Cand), Tried),
    reverse(Tried, InOrder),
    findall(probe(P, Sc, Kept, K),
            ( member(t(Sc, K, cand(P, _, _)), InOrder),
              ( K == Chosen -> Kept = true ; Kept = false ) ),
            Probes).

%   best_probe(+Tried, -K): the attempt whose probe scored best (the
%   earliest of equals).
best_probe(Tried, K) :-
    reverse(Tried, InOrder),
    findall(Key-A, ( member(t(Sc, A, _), InOrder), Key is -Sc ), Keyed),
    keysort(Keyed, [_-K|_]).
