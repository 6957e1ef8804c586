:- module(curiosity_probe,
          [ choose/6,                 % +State, +Settings, -Cand, -Attempt, -Rest, -Probes
            fewest/5,                 % +Rest, +Exclude, +Settings, +I, -Rest2
            probe_entry/5             % +Props, +Score, +Kept, +By, -Entry
          ]).
/** <module> Probes: which candidate of A_new a step explores

For the discovering curiosity, the forest's guess that a candidate shows
something new is checked before a batch is spent on it: the first `probe`
pours of the candidate's batch are simulated, and when they do not show a
new, reproducible consequent the candidate is set aside and the next one
probed, at most `probe_attempts` of them (choose/6). With cover(N) above 0
the last probe of a step goes where the pours so far are fewest
(fewest/5). The budget is then in pours: `budget` batches' worth,
batches and probes together (loop.pl).
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(bridge).
:- use_module(state).
:- use_module(discover).

%!  choose(+State, +Settings:dict, -Cand, -Attempt:integer, -Rest:list, -Probes:list) is det.
%
%   Cand is the candidate this iteration explores, Attempt the attempt
%   whose pours its batch is (0: the iteration's own), Rest A_new
%   without it and the candidates set aside, and Probes, probe(Props,
%   Score, Kept, Attempt, By) for each candidate probed, By `novelty`
%   (the next of A_new) or `fewest` (the last attempt, where the pours
%   are fewest: fewest/5). Without probes (the paper's curiosity,
%   probe(0), a_0 and more batches) it is the head of A_new. Otherwise
%   the first `probe` pours of the head's batch are simulated, and it
%   is explored when they show a new, reproducible consequent
%   (exploration_probe); else the next is probed, at most
%   `probe_attempts` of them, and the one whose probe scored best is
%   explored.
choose(st(I, Explored, [C|Rest], SetAside), Settings, Cand, Attempt, Rest1, Probes) :-
    (   unprobed(C, Settings)
    ->  Cand = C, Attempt = 0, Rest1 = Rest, Probes = []
    ;   I1 is I + 1,
        maplist(entry, Explored, Entries),
        append([C|Rest], SetAside, Away),
        exclusions(Explored, Away, Exclude),
        probe_loop([C|Rest], Entries-Exclude, Settings, I1, 0, novelty, [], Cand, Attempt,
                   Rest1, Probes)
    ).

%   unprobed(+Cand, +Settings): Cand is explored without a probe.
unprobed(cand(_, _, Via), Settings) :-
    (   Settings.curiosity \== discover
    ;   Settings.probe =:= 0
    ;   Via = initial
    ;   Via = prior
    ;   Via = more(_, _)
    ), !.

%   probe_loop(+Cands, +Entries-Exclude, +Settings, +I1, +K, +By, +Tried,
%              -Cand, -Attempt, -Rest, -Probes): probe the head of Cands
%   as attempt K (By novelty or fewest), Tried the attempts before it
%   (t(Score, K, By, Cand), the latest first); see choose/6.
probe_loop([C|Rest], Known, Settings, I1, K, By, Tried, Cand, Attempt, Rest1, Probes) :-
    Known = Entries-Exclude,
    C = cand(Props, _, _),
    call_bridge(exploration_probe, _{antecedents:Entries, antecedent:Props,
                                     iteration:I1, attempt:K, by:By}, R),
    Tried1 = [t(R.score, K, By, C)|Tried],
    K1 is K + 1,
    (   R.pass == true
    ->  probe_end(Tried1, K, Rest, Cand, Attempt, Rest1, Probes)
    ;   K1 < Settings.probe_attempts,
        Rest = [Next|_], \+ unprobed(Next, Settings)
    ->  (   K1 =:= Settings.probe_attempts - 1, K1 > 0, Settings.cover > 0,
            fewest(Rest, Exclude, Settings, I1, Rest2)
        ->  probe_loop(Rest2, Known, Settings, I1, K1, fewest, Tried1, Cand, Attempt, Rest1, Probes)
        ;   probe_loop(Rest, Known, Settings, I1, K1, novelty, Tried1, Cand, Attempt, Rest1, Probes)
        )
    ;   best_probe(Tried1, Best),
        probe_end(Tried1, Best, Rest, Cand, Attempt, Rest1, Probes)
    ).

%!  fewest(+Rest:list, +Exclude:list, +Settings:dict, +I:integer, -Rest2:list) is semidet.
%
%   The last probe of a step goes where the pours are fewest: to the
%   candidate of A_new (Rest) or of this step's random valid
%   antecedents (jumps/4, none in Exclude) whose rarest proposition
%   the fewest pours so far hold, when fewer than `cover` do
%   (exploration_fewest; the earliest of equals). Rest2 is Rest with
%   it first. Fails when `cover` pours or more hold every proposition
%   of every candidate.
fewest(Rest, Exclude, Settings, I, [Chosen|Others]) :-
    include([C]>>( \+ unprobed(C, Settings) ), Rest, InQueue),
    jumps(Settings, I, Exclude, Far),
    findall(cand(P, none, jump), member(P, Far), Jumps),
    append(InQueue, Jumps, Pool),
    findall(P, member(cand(P, _, _), Pool), Cands),
    call_bridge(exploration_fewest, _{candidates:Cands, enough:Settings.cover}, Reply),
    Reply.index >= 0,
    nth0(Reply.index, Pool, Chosen),
    (   selectchk(Chosen, Rest, Others) -> true ; Others = Rest ).

%   probe_end(+Tried, +Chosen, +Rest, -Cand, -Attempt, -Rest, -Probes):
%   the attempt Chosen of Tried is explored, the others are set aside.
probe_end(Tried, Chosen, Rest, Cand, Chosen, Rest, Probes) :-
    memberchk(t(_, Chosen, _, Cand), Tried),
    reverse(Tried, InOrder),
    findall(probe(P, Sc, Kept, K, By),
            ( member(t(Sc, K, By, cand(P, _, _)), InOrder),
              ( K == Chosen -> Kept = true ; Kept = false ) ),
            Probes).

%   best_probe(+Tried, -K): the attempt whose probe scored best (the
%   earliest of equals).
best_probe(Tried, K) :-
    reverse(Tried, InOrder),
    findall(Key-A, ( member(t(Sc, A, _, _), InOrder), Key is -Sc ), Keyed),
    keysort(Keyed, [_-K|_]).

%!  probe_entry(+Props:list, +Score:number, +Kept:boolean, +By:atom, -Entry:dict) is det.
%
%   Entry is a probe in the trace; one that went where the pours are
%   fewest (fewest/5) says so.
probe_entry(P, Sc, K, novelty, _{antecedent:P, score:Sc, kept:K}).
probe_entry(P, Sc, K, fewest, _{antecedent:P, score:Sc, kept:K, by:fewest}).

