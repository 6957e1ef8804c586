:- module(defeasible,
          [ load_theory/1,          % +File
            clear_theory/0,
            add_theory_fact/1,      % +Fact
            theory_loaded/0,
            theory_given/0,
            semantics/2,            % +Options, -Sem
            truth/3,                % +Sem, +Goal, -Value
            conclusion/3,           % +Sem, ?Tag, ?Literal
            conclusions/3,          % +Sem, +Tag, -Literals
            theory_literal/1,       % ?Literal
            complement/2,           % ?Literal, ?Complement
            superior/2,             % ?R1, ?R2
            rule_body/2,            % ?Rule, ?Body
            with_scene/2,           % +Facts, :Goal
            definitely/2,           % +Sem, +Literal
            defeasibly/2,           % +Sem, +Literal
            supported/2,            % +Sem, +Literal
            applicable/3            % +Sem, +Rule, ?Value
          ]).
/** <module> Defeasible logic over the native theory files

A theory is a set of ground facts (see theory_files.pl):

    fact(L).  rule(Id, Kind, Head).  body(Id, L).  sup(R1, R2).  learned(Id).

Kind is =strict=, =defeasible= or =defeater=; a literal is an atom or a
term with constant arguments, or its negation =|neg(L)|=. A rule whose
body strictly contains the body of a learned rule with the complementary
head is superior to it (specificity), unless sup/2 says the opposite: a
learned rule is overridden by any more specific rule, learned or written
by hand; a rule written by hand (no learned/1 fact) only by sup/2.

The logic is the defeasible logic of Antoniou, Billington, Governatori
and Maher, given by its meta-program (Antoniou et al., "Embedding
defeasible logic into logic programming", TPLP 2006) and evaluated with
SWI-Prolog's tabling under the well-founded semantics. Three switches
select the variant, as a term =|sem(Ambiguity, TeamDefeat, WellFounded)|=:

  - Ambiguity: =blocking= (default) or =propagation= (attackers need
    only be supported, +Sigma, to block a conclusion).
  - TeamDefeat: =true= (default: the rules for a literal together beat the
    attackers) or =false= (one rule must beat every attacker).
  - WellFounded: =true= (default: literals whose proofs only loop fail) or
    =false= (Kunen semantics of the meta-program: loops stay undecided).
    The second is obtained by routing every positive dependency through a
    double tabled negation, which turns the well-founded model into the
    Fitting (Kunen) model.

A literal L then has the conclusions +D (definitely provable: the meta
atom definitely(L) is true), -D (definitely(L) is false), +d and -d
(likewise for defeasibly(L)). Undecided literals have neither.
theory/defeasible.lp computes the same conclusions with clingo.
*/

:- use_module(theory_files).
:- use_module(default_values).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(assoc)).
:- use_module(library(apply)).

% SWI-Prolog 9.0 can reclaim an atom that a table's trie still holds
% (pl-trie.c: unify_key assertion) when theories are loaded over and over;
% theories have few atoms, so keep them.
:- set_prolog_flag(agc_margin, 0).

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

internal(sem(A, T, W), sem(A, T, W, G)) :- !, generation(G).
internal(S, S).

:- table definitely/2, defeasibly/2, supported/2, overruled/2,
   overruled_by/3, defeated/3, support_beaten/3,
   not_definitely/2, not_defeasibly/2, not_supported/2.

                 /*******************************
                 *        LOADING A THEORY      *
                 *******************************/

%!  load_theory(+File) is det.
%
%   Replace the current theory by the facts of File (native format).
%   provenance/3 facts are kept (a learned rule's confidence and layer),
%   and explored/2 and held/4 (the pours of the explored antecedents,
%   which answers cite);
%   facts of other predicates (settings, set_aside) are ignored.
%
%   @error theory_error(File, Line, Expected) for a malformed file.
load_theory(File) :-
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
    assertz(given_theory(File)),
    prepare,
    check_superiority(File).

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

%!  theory_loaded is semidet.
%
%   A theory is loaded (possibly empty).
theory_loaded :-
    (   loaded -> true ; prepare, check_superiority('<theory>') ).

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

subsequence([], []).
subsequence([X|Xs], [X|Ys]) :- subsequence(Xs, Ys).
subsequence([_|Xs], Ys) :- subsequence(Xs, Ys).

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

%!  with_scene(+Facts:list, :Goal) is semidet.
%
%   Call Goal with Facts added to the theory's facts (the literals of a
%   scene), and remove them afterwards.
:- meta_predicate with_scene(+, 0).
with_scene(Facts, Goal) :-
    theory_loaded,
    setup_call_cleanup(
        ( forall(member(F, Facts), assertz(scene_fact(F))), next_generation ),
        once(Goal),
        ( retractall(scene_fact(_)), next_generation )).

given(X) :- term_hash(X, K), fact_key(K, X).
given(X) :- scene_fact(X).

% rule_for(+Head, -Rule, -Kind): the rules with head Head.
rule_for(H, R, K) :- term_hash(H, Key), head_key(Key, H, R), rule(R, K, H).

                 /*******************************
                 *          SEMANTICS           *
                 *******************************/

%!  semantics(+Options:list, -Sem) is det.
%
%   The semantics term for Options: ambiguity(blocking|propagation),
%   team_defeat(Bool), well_founded(Bool); defaults blocking, true, true.
semantics(Options, sem(A, T, W)) :-
    option_value(ambiguity(A), Options, blocking, [blocking, propagation]),
    option_value(team_defeat(T), Options, true, [true, false]),
    option_value(well_founded(W), Options, true, [true, false]).

option_value(Opt, Options, Default, Allowed) :-
    functor(Opt, Name, 1), arg(1, Opt, V),
    functor(Q, Name, 1),
    (   memberchk(Q, Options) -> arg(1, Q, V0) ; V0 = Default ),
    (   memberchk(V0, Allowed) -> V = V0
    ;   domain_error(Allowed, V0)
    ).

% pos(+Sem, +Goal): a positive dependency on a tabled meta atom. Under the
% Kunen variant it goes through two tabled negations.
pos(sem(_, _, true, _), G) :- call(G).
pos(sem(_, _, false, _), G) :- G =.. [P, S, X], not_(P, S, X).

not_(definitely, S, X) :- tnot(not_definitely(S, X)).
not_(defeasibly, S, X) :- tnot(not_defeasibly(S, X)).
not_(supported, S, X) :- tnot(not_supported(S, X)).

not_definitely(S, X) :- tnot(definitely(S, X)).
not_defeasibly(S, X) :- tnot(defeasibly(S, X)).
not_supported(S, X) :- tnot(supported(S, X)).

all_pos([], _, _).
all_pos([B|Bs], S, P) :-
    G =.. [P, S, B],
    pos(S, G),
    all_pos(Bs, S, P).

supportive(R, X) :- rule_for(X, R, K), K \== defeater.

%!  definitely(+Sem, +Literal) is nondet.
%
%   The meta atom of +D (tabled; true, false or undefined). Ask for it
%   through truth/3, which gives Sem the theory's current generation.
definitely(_, X) :- given(X).
definitely(S, X) :- rule_for(X, R, strict), rule_body(R, Bs), all_pos(Bs, S, definitely).

%!  defeasibly(+Sem, +Literal) is nondet.
%
%   The meta atom of +d (tabled; true, false or undefined).
defeasibly(S, X) :- pos(S, definitely(S, X)).
defeasibly(S, X) :-
    complement(X, NX),
    supportive(R, X), rule_body(R, Bs), all_pos(Bs, S, defeasibly),
    tnot(definitely(S, NX)),
    not_overruled(S, R, X).

not_overruled(S, _, X) :- S = sem(_, true, _, _), tnot(overruled(S, X)).
not_overruled(S, R, X) :- S = sem(_, false, _, _), tnot(overruled_by(S, R, X)).

% an attacker A of X is applicable: its body is provable (ambiguity
% blocking) or merely supported (ambiguity propagation).
attacks(S, A) :- S = sem(blocking, _, _, _), rule_body(A, Bs), all_pos(Bs, S, defeasibly).
attacks(S, A) :- S = sem(propagation, _, _, _), rule_body(A, Bs), all_pos(Bs, S, supported).

% team defeat: some applicable attacker is not beaten by any applicable
% rule for X.
overruled(S, X) :-
    complement(X, NX), rule_for(NX, A, _), attacks(S, A), tnot(defeated(S, A, X)).

defeated(S, A, X) :-
    superior(T, A), supportive(T, X), rule_body(T, Bs), all_pos(Bs, S, defeasibly).

% no team defeat: rule R must itself be superior to every applicable attacker.
overruled_by(S, R, X) :-
    complement(X, NX), rule_for(NX, A, _), \+ superior(R, A), attacks(S, A).

%!  supported(+Sem, +Literal) is nondet.
%
%   The meta atom of +Sigma (support), used by ambiguity propagation.
supported(S, X) :- pos(S, definitely(S, X)).
supported(S, X) :-
    supportive(R, X), rule_body(R, Bs), all_pos(Bs, S, supported),
    tnot(support_beaten(S, R, X)).

support_beaten(S, R, X) :-
    complement(X, NX), rule_for(NX, A, _), superior(A, R),
    rule_body(A, Bs), all_pos(Bs, S, defeasibly).

                 /*******************************
                 *          CONCLUSIONS         *
                 *******************************/

%!  truth(+Sem, +Goal, -Value) is det.
%
%   Value is =true=, =false= or =undefined=: the well-founded value of
%   a meta atom Goal (definitely(Sem, L), defeasibly(Sem, L), ...) of the
%   current theory.
truth(_, G0, V) :-
    theory_loaded,
    G0 =.. [P, S0|Args], internal(S0, S), G =.. [P, S|Args],
    (   call_delays(G, D)
    ->  ( D == true -> V = true ; V = undefined )
    ;   V = false
    ).

%!  applicable(+Sem, +Rule, -Value) is det.
%
%   Value is the truth of "every body literal of Rule is defeasibly
%   provable": true, false or undefined.
applicable(S, R, V) :-
    rule_body(R, Bs),
    foldl(and_body(S), Bs, true, V).

and_body(_, _, false, false) :- !.
and_body(S, B, V0, V) :-
    truth(S, defeasibly(S, B), VB),
    (   VB == false -> V = false
    ;   VB == undefined -> V = undefined
    ;   V = V0
    ).

%!  conclusion(+Sem, ?Tag, ?Literal) is nondet.
%
%   Literal (of the theory, or the complement of one) has the conclusion
%   Tag: '+D', '-D', '+d' or '-d'.
conclusion(S, Tag, L) :-
    theory_loaded,
    theory_literal(L),
    member(Tag-Meta-Want, ['+D'-definitely-true, '-D'-definitely-false,
                           '+d'-defeasibly-true, '-d'-defeasibly-false]),
    G =.. [Meta, S, L],
    truth(S, G, Want).

%!  conclusions(+Sem, +Tag, -Literals:list) is det.
%
%   The sorted literals with conclusion Tag.
conclusions(S, Tag, Ls) :-
    findall(L, conclusion(S, Tag, L), Ls0),
    sort(Ls0, Ls).
