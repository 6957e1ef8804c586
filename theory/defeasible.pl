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
theory/derivability.lp computes the same conclusions with clingo.

The theory's facts, and the indexes they are asked through, are
theory_store.pl's; the superiority relation (sup/2 and specificity) and
its check for cycles are superiority.pl's. This module loads a theory
through both and draws its conclusions.
*/

:- use_module(theory_store).
:- use_module(superiority).
:- use_module(library(lists)).
:- use_module(library(apply)).

% SWI-Prolog 9.0 can reclaim an atom that a table's trie still holds
% (pl-trie.c: unify_key assertion) when theories are loaded over and over;
% theories have few atoms, so keep them.
:- set_prolog_flag(agc_margin, 0).

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
    store_theory(File),
    prepare,
    check_superiority(File).

%!  theory_loaded is semidet.
%
%   A theory is loaded (possibly empty).
theory_loaded :-
    (   loaded -> true ; prepare, check_superiority('<theory>') ).

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
