:- module(superiority,
          [ superior/2,             % ?R1, ?R2
            superiority_cycle/1,    % -Cycle
            cycle_message/2,        % +Cycle, -Message
            check_superiority/1     % +File
          ]).
/** <module> The superiority relation of the current theory

sup/2 and specificity: a rule whose body strictly contains the body of a
learned rule with the complementary head is superior to it, unless sup/2
says the opposite (superior/2). The relation must be acyclic, or a rule
could beat itself and both a literal and its complement be concluded:
check_superiority/1 finds a shortest cycle (superiority_cycle/1) and says
it in the words of theory/check_messages.pl (cycle_message/2). Reads the
theory of theory_store.pl, through the indexes its prepare/0 builds.
*/

:- use_module(theory_store).
:- use_module(theory_files).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(assoc)).
:- use_module(library(apply)).

% check_superiority(+File): the superiority relation (sup/2 with
% specificity) must be acyclic, or a rule could beat itself and both a
% literal and its complement be concluded. A cyclic theory is forgotten.
check_superiority(File) :-
    (   superiority_cycle(Cycle)
    ->  clear_theory,
        cycle_message(Cycle, M),
        throw(theory_error(File, 0, M))
    ;   true
    ).

% cycle_message(+Cycle, -Message): what is said of a superiority cycle
% (its text is theory/check_messages.pl's, which Python says too).
cycle_message(Cycle, Message) :-
    atomic_list_concat(Cycle, ' > ', Text),
    check_message(superiority_cycle, [Text], Message).

% superiority_cycle(-Cycle): a shortest cycle [R, ..., R] of superior/2
% through the first rule (in standard order) of sup/2 that lies on one.
% Specificity alone has no cycle (it makes bodies strictly larger), so a
% cycle goes through sup/2, and only its rules need be started from.
superiority_cycle(Cycle) :-
    findall(R, sup(R, _), Rs0), sort(Rs0, Rs),
    \+ acyclic_from(Rs),
    member(R, Rs),
    findall([S, R], superior(R, S), Queue),
    empty_assoc(Seen),
    cycle_back(Queue, [], R, Seen, Cycle), !.

% acyclic_from(+Rs): no cycle of superior/2 is reachable from the rules
% Rs: depth first, each rule left once, so that the check is linear in
% the relation (a breadth-first search from every rule of a chain of
% 2,000 took minutes); only a theory with a cycle is searched for it.
acyclic_from(Rs) :-
    empty_assoc(Marks),
    foldl(left_acyclic, Rs, Marks, _).

left_acyclic(R, Marks0, Marks) :-
    (   get_assoc(R, Marks0, Mark)
    ->  Mark == done, Marks = Marks0
    ;   put_assoc(R, Marks0, open, Marks1),
        findall(S, superior(R, S), Ss),
        foldl(left_acyclic, Ss, Marks1, Marks2),
        put_assoc(R, Marks2, done, Marks)
    ).

% cycle_back(+Queue, +Next, +R, +Seen, -Cycle): breadth first, a level
% (Queue) at a time, the paths of the next level gathered in Next.
cycle_back([], [], _, _, _) :- !, fail.
cycle_back([], Next, R, Seen, Cycle) :- !,
    cycle_back(Next, [], R, Seen, Cycle).
cycle_back([[N|P]|_], _, R, _, Cycle) :-
    N == R, !,
    reverse([N|P], Cycle).
cycle_back([[N|P]|Queue], Next, R, Seen, Cycle) :-
    (   get_assoc(N, Seen, _)
    ->  cycle_back(Queue, Next, R, Seen, Cycle)
    ;   put_assoc(N, Seen, t, Seen1),
        findall([M, N|P], superior(N, M), More),
        append(More, Next, Next1),
        cycle_back(Queue, Next1, R, Seen1, Cycle)
    ).

%!  superior(?R1, ?R2) is nondet.
%
%   R1 is superior to R2: sup(R1, R2), or R2 is a learned rule, R1 a rule
%   (learned or not) with the complementary head whose body strictly
%   contains that of R2 (specificity), unless sup(R2, R1). Specificity is looked up when
%   asked, through the indexes learned_index/0 builds, never held pair by
%   pair: the pairs grow with the square of the rules, the indexes with
%   the rules.
superior(R, S) :- sup(R, S).
superior(R, S) :-
    (   nonvar(R)
    ->  more_specific(R, S)
    ;   nonvar(S)
    ->  less_specific(S, R)
    ;   \+ \+ learned(_),            % no learned rule: no specificity
        rule(R, _, _), more_specific(R, S)
    ).

% more_specific(+R, ?S): R is more specific than the learned S.
more_specific(R, S) :-
    rule(R, _, H), complement(H, NH), rule_body(R, BR),
    (   nonvar(S)
    ->  learned(S), rule(S, _, NH), rule_body(S, BS),
        ord_subset(BS, BR), BS \== BR
    ;   length(BR, K), K < 12
    ->  subsequence(BR, BS), BS \== BR,
        term_hash(NH-BS, Key), learned_key(Key, S),
        rule(S, _, NH), rule_body(S, BS)
    ;   rule_for(NH, S, _), learned(S), rule_body(S, BS),
        ord_subset(BS, BR), BS \== BR
    ),
    \+ sup(S, R).

% less_specific(+S, -R): R is more specific than the learned S: among the
% rules for the complementary head that hold the first literal of S's
% body (or, for S without a body, all those with one).
less_specific(S, R) :-
    learned(S), rule(S, _, NH), complement(NH, H), rule_body(S, BS),
    (   BS = [L|_]
    ->  term_hash(H-L, Key), literal_key(Key, R),
        rule(R, _, H), rule_body(R, BR)
    ;   rule_for(H, R, _), rule_body(R, BR)
    ),
    ord_subset(BS, BR), BS \== BR,
    \+ sup(S, R).

subsequence([], []).
subsequence([X|Xs], [X|Ys]) :- subsequence(Xs, Ys).
subsequence([_|Xs], Ys) :- subsequence(Xs, Ys).
