:- module(theory_store,
          [ store_theory/1,         % +File
            clear_theory/0,
            add_theory_fact/1,      % +Fact
            theory_given/0,
            prepare/0,
            check_size/1,           % +File
            fact/1, rule/3, body/2, sup/2, learned/1, provenance/3, explored/2, held/4,
            rule_body/2,            % ?Rule, ?Body
            theory_literal/1,       % ?Literal
            learned_key/2,          % ?Key, ?Rule
            literal_key/2,          % ?Key, ?Rule
            given/1,                % ?Literal
            rule_for/3,             % +Head, -Rule, -Kind
            complement/2,           % ?Literal, ?Complement
            scene_fact/1,           % ?Literal
            loaded/0,
            generation/1,           % -Generation
            next_generation/0
          ]).
/** <module> The current theory: its facts and the indexes it is asked through

The facts of the current theory (fact/1, rule/3, body/2, sup/2,
learned/1, provenance/3, explored/2, held/4; see theory_files.pl), read
from a file (store_theory/1) or added one by one (add_theory_fact/1), and
what prepare/0 derives from them to be asked quickly: each rule's sorted
body (rule_body/2), the rules and facts under a hash of their literal
(rule_for/3, given/1), the indexes of specificity (learned_key/2,
literal_key/2, read by superiority.pl) and the theory's literals in the
order of their dependencies (theory_literal/1). The generation number
(generation/1) changes with the theory and with a scene's facts
(scene_fact/1), so that the tables of defeasible.pl, keyed by it, are
never read for another theory. defeasible.pl loads a theory through this
module, checks its superiority relation (superiority.pl) and draws its
conclusions.
*/

:- use_module(theory_files).
:- use_module(default_values).
:- use_module(library(lists)).
:- use_module(library(apply)).

:- dynamic fact/1, rule/3, body/2, sup/2, learned/1, provenance/3, explored/2, held/4,
   given_theory/1,
   scene_fact/1, rule_body/2, theory_literal/1, loaded/0,
   generation/1, head_key/3, fact_key/2, learned_key/2, literal_key/2.

% Tables are keyed by a generation number that changes with the theory
% (and with the facts of a scene), instead of being abolished: abolishing
% tables between queries from a host language proved fragile in
% SWI-Prolog 9.0. Old generations are dropped when many have piled up.
generation(0).

next_generation :-
    retract(generation(G0)), G is G0 + 1, assertz(generation(G)),
    (   G mod 200 =:= 0 -> abolish_all_tables ; true ).

%!  store_theory(+File) is det.
%
%   Replace the facts of the current theory by those of File (native
%   format), checked: the facts of load_theory/1 of defeasible.pl, before
%   they are prepared and their superiority relation checked.
%
%   @error theory_error(File, Line, Expected) for a malformed file.
store_theory(File) :-
    check_size(File),
    Scratch = defeasible_input,
    forall(current_predicate(Scratch:P/A),
           ( functor(H, P, A), retractall(Scratch:H) )),
    % defined here, so that a theory without rules does not reach the
    % built-in rule/3 that the module would otherwise inherit
    forall(theory_predicate(P, A), dynamic(Scratch:P/A)),
    load_theory_facts(File, Scratch),
    clear_theory,
    forall(theory_predicate(P, A),
           ( functor(H, P, A),
             (   current_predicate(Scratch:P/A)
             ->  forall(Scratch:H, add_theory_fact(H))
             ;   true
             ) )),
    forall(current_predicate(Scratch:P/A),
           ( functor(H, P, A), retractall(Scratch:H) )),
    check_theory(File),
    assertz(given_theory(File)).

% check_size(+File): a theory file of at most theory_bytes_at_most bytes
% (theory/defaults.pl): loading is linear in the file, so this bounds
% what a file may cost.
check_size(File) :-
    default(theory_bytes_at_most, Most),
    (   exists_file(File), size_file(File, Size), Size > Most
    ->  format(string(S), "~D", [Size]),
        format(string(T), "~D", [Most]),
        check_message(too_large, [S, T], M),
        throw(theory_error(File, 0, M))
    ;   true
    ).

theory_predicate(fact, 1).
theory_predicate(rule, 3).
theory_predicate(body, 2).
theory_predicate(sup, 2).
theory_predicate(learned, 1).
theory_predicate(provenance, 3).
theory_predicate(explored, 2).
theory_predicate(held, 4).

check_theory(File) :-
    (   rule(R, K, _), \+ memberchk(K, [strict, defeasible, defeater])
    ->  check_message(kind, [R, K], M),
        throw(theory_error(File, 0, M))
    ;   body(R, _), \+ rule(R, _, _)
    ->  check_message(dangling_body, [R, R, R], M),
        throw(theory_error(File, 0, M))
    ;   rule(R, K1, H1), rule(R, K2, H2), (K1-H1) \== (K2-H2)
    ->  format(string(M), "two rules named ~w", [R]),
        throw(theory_error(File, 0, M))
    ;   true
    ).

%!  clear_theory is det.
%
%   Forget the current theory.
clear_theory :-
    retractall(fact(_)), retractall(rule(_, _, _)), retractall(body(_, _)),
    retractall(sup(_, _)), retractall(learned(_)), retractall(provenance(_, _, _)),
    retractall(explored(_, _)), retractall(held(_, _, _, _)),
    retractall(scene_fact(_)),
    retractall(rule_body(_, _)), retractall(learned_key(_, _)),
    retractall(literal_key(_, _)),
    retractall(theory_literal(_)), retractall(loaded),
    retractall(given_theory(_)),
    next_generation.

%!  add_theory_fact(+Fact) is det.
%
%   Add one fact (fact/1, rule/3, body/2, sup/2, learned/1, provenance/3,
%   explored/2 or held/4) to the
%   current theory. Call load_theory/1, or add facts and then query:
%   derived tables are rebuilt on the next query.
add_theory_fact(F) :-
    F =.. [P|Args], length(Args, A),
    (   theory_predicate(P, A)
    ->  (   P \== fact, call(F) -> true ; assertz(F) ),
        (   given_theory(_) -> true ; assertz(given_theory(added)) ),
        retractall(loaded)
    ;   true
    ).

%!  theory_given is semidet.
%
%   A theory was given: loaded by load_theory/1 or added fact by fact by
%   add_theory_fact/1 since the last clear_theory/0.
theory_given :-
    given_theory(_),
    !.

%!  prepare is det.
%
%   Derive from the theory's facts what it is asked through (see the
%   module comment), and start a new generation.
prepare :-
    retractall(rule_body(_, _)), retractall(learned_key(_, _)),
    retractall(literal_key(_, _)),
    retractall(theory_literal(_)), retractall(head_key(_, _, _)),
    retractall(fact_key(_, _)),
    % literals such as neg(a) all share a functor, so clause indexing on
    % them degenerates: look rules and facts up by a hash of the literal
    forall(rule(R, _, H), ( term_hash(H, K), assertz(head_key(K, H, R)) )),
    forall(fact(F), ( term_hash(F, K), assertz(fact_key(K, F)) )),
    forall(rule(R, _, _),
           ( findall(B, body(R, B), Bs0), sort(Bs0, Bs),
             assertz(rule_body(R, Bs)) )),
    learned_index,
    findall(L, mentioned(L), Ls0), sort(Ls0, Ls),
    dependency_order(Ls, Ordered),
    forall(member(L, Ordered), assertz(theory_literal(L))),
    next_generation,
    assertz(loaded).

% learned_index: each learned rule under a hash of its head and body, and
% each rule under a hash of its head and each literal of its body, so that
% the learned rules a rule is more specific than, and the rules more
% specific than a learned rule, are looked up, not searched for among all
% the rules.
learned_index :-
    forall(( learned(S), rule(S, _, H), rule_body(S, Bs) ),
           ( term_hash(H-Bs, Key), assertz(learned_key(Key, S)) )),
    forall(( rule(S, _, H), rule_body(S, Bs) ),
           forall(member(L, Bs), ( term_hash(H-L, K), assertz(literal_key(K, S)) ))).

% dependency_order(+Literals, -Ordered): the literals with those they
% depend on (through the rules for them and their complements) first, so
% that asking for each in turn finds its dependencies' tables complete
% instead of nesting one tabled call in the next.
:- dynamic seen/1.
dependency_order(Ls, Ordered) :-
    retractall(seen(_)),
    foldl(visit, Ls, [], Rev),
    retractall(seen(_)),
    reverse(Rev, Atoms),
    findall(L, ( member(A, Atoms), ( L = A ; L = neg(A) ) ), Ordered).

visit(L, Acc0, Acc) :-
    literal_atom(L, A),
    (   seen(A)
    ->  Acc = Acc0
    ;   assertz(seen(A)),
        findall(B, depends_on(A, B), Bs),
        foldl(visit, Bs, Acc0, Acc1),
        Acc = [A|Acc1]
    ).

depends_on(A, B) :-
    ( H = A ; H = neg(A) ),
    term_hash(H, K), head_key(K, H, R), body(R, B).

literal_atom(neg(A), A) :- !.
literal_atom(A, A).

mentioned(L) :- ( fact(L0) ; rule(_, _, L0) ; body(_, L0) ), ( L = L0 ; complement(L0, L) ).

%!  complement(?Literal, ?Complement) is det.
%
%   neg(A) and A are each other's complement.
complement(L, C) :-
    (   nonvar(L)
    ->  ( L = neg(A) -> C = A ; C = neg(L) )
    ;   ( C = neg(A) -> L = A ; L = neg(C) )
    ).

given(X) :- term_hash(X, K), fact_key(K, X).
given(X) :- scene_fact(X).

% rule_for(+Head, -Rule, -Kind): the rules with head Head.
rule_for(H, R, K) :- term_hash(H, Key), head_key(Key, H, R), rule(R, K, H).
