:- module(queries,
          [ what_happens/2,         % +SceneProps, -Outcomes
            what_happens/3,         % +SceneProps, +Options, -Outcomes
            why/3,                  % +SceneProps, +Literal, -Proof
            why/4,                  % +SceneProps, +Literal, +Options, -Proof
            why_brief/4,            % +SceneProps, +Literal, +Options, -Proof
            proof_text/2,           % +Proof, -Text
            explain/4,              % +SceneProps, +Literal, +Options, -Text
            explain_brief/4         % +SceneProps, +Literal, +Options, -Text
          ]).
/** <module> Questions to a defeasible theory of pouring

The scene propositions of a question become facts of the current theory
(defeasible:load_theory/1); the 9 expectations of the vocabulary are the
literals asked about. what_happens/2 predicts, why/3 explains a
conclusion, or why a literal is not concluded (why-not), as a proof term
that proof_text/2 puts into words. why_brief/4 gives a short why-not for
large theories: the rules that come nearest to deciding the literal.
*/

:- use_module(defeasible).
:- use_module(vocabulary).
:- use_module(validity).
:- use_module(learned_rules, []).
:- use_module(proof_words).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(aggregate)).
:- use_module(library(pairs)).

%!  what_happens(+SceneProps:list, -Outcomes:list) is det.
%!  what_happens(+SceneProps:list, +Options:list, -Outcomes:list) is det.
%
%   Outcomes has one =|outcome(Expectation, Value, Likelihood, Rule)|= per
%   expectation, in the vocabulary's order. Rule is the deciding rule (of
%   the applicable, unbeaten rules for the concluded literal, the highest
%   ranked: the larger body, the general layer, the surer, the id), =fact=
%   for a given literal, or =none=. Likelihood is the share of such pours
%   in which the expectation holds, from the deciding rule's confidence
%   (its =|provenance(R, confidence_permille, C)|= fact), or =none= for a
%   rule that records none. Value is =holds= (the theory defeasibly
%   concludes the expectation), =fails= (it concludes its negation),
%   =uncertain= (it concludes one of them, but the likelihood lies within
%   the band of theory/defaults.pl's =uncertain_band= around one half:
%   such pours split) or =unknown= (it concludes neither). Options select
%   the semantics (defeasible:semantics/2).
what_happens(Scene, Outcomes) :-
    what_happens(Scene, [], Outcomes).
what_happens(Scene, Options, Outcomes) :-
    must_be_scene(Scene, what_happens/3),
    must_have_theory(what_happens/3),
    semantics(Options, S),
    with_scene(Scene,
               findall(outcome(E, V, P, R),
                       ( expectation(E, _, _), outcome(S, E, V, P, R) ),
                       Outcomes)).

% must_be_scene(+Scene, +Where): a scene is a list of known propositions,
% valid together (validity:violations/2), as `pantarhei ask` checks it:
% an instantiation error for an unbound scene, one domain error in words
% for any other.
must_be_scene(Scene, Where) :-
    must_be(list, Scene),
    (   member(P, Scene), var(P)
    ->  instantiation_error(Scene)
    ;   true
    ),
    validity:violations(Scene, Why),
    (   Why == []
    ->  true
    ;   findall(W, ( member(V, Why), arg(_, V, W), string(W) ), Words),
        atomic_list_concat(Words, '; ', Text),
        format(string(Message), "~w (see pantarhei vocab)", [Text]),
        throw(error(domain_error(scene, Scene), context(Where, Message)))
    ).

% must_have_theory(+Where): a question needs a theory to answer it.
must_have_theory(Where) :-
    (   theory_given
    ->  true
    ;   throw(error(existence_error(theory, learned),
                    context(Where, "no theory is loaded: call defeasible:load_theory(File), or start with swipl theory/pantarhei.pl, which loads the shipped theory")))
    ).

outcome(S, E, V, P, R) :-
    (   truth(S, defeasibly(S, E), true)
    ->  deciding_rule(S, E, R), likelihood(R, E, P), verdict(holds, P, V)
    ;   truth(S, defeasibly(S, neg(E)), true)
    ->  deciding_rule(S, neg(E), R), likelihood(R, neg(E), P), verdict(fails, P, V)
    ;   V = unknown, R = none, P = none
    ).

% likelihood(+Rule, +Literal, -P): the share of such pours in which the
% expectation holds, as the rule that concludes Literal records it
% (learned_rules:likelihood/3).
likelihood(fact, L, P) :-
    !,
    (   L = neg(_) -> P = 0.0 ; P = 1.0 ).
likelihood(R, L, P) :-
    confidence(R, C),
    learned_rules:likelihood(C, L, P).

% confidence(+Rule, -C): the rule's confidence in permille, or none.
confidence(R, C) :-
    (   defeasible:provenance(R, confidence_permille, C0), number(C0)
    ->  C = C0
    ;   C = none
    ).

% verdict(+Concluded, +Likelihood, -Value): uncertain where such pours
% split (learned_rules:verdict/3).
verdict(V0, P, V) :-
    learned_rules:verdict(V0, P, V).

% rank_key(+Rule, -Key): how the deciding rule is chosen among the
% applicable, unbeaten rules for one literal (learned_rules:rank_key/2):
% the larger body, the general layer, the surer, the id.
rank_key(R, Key) :-
    rule_body(R, Bs), length(Bs, N),
    (   defeasible:provenance(R, layer, general) -> L = general ; L = rule ),
    confidence(R, C),
    (   C == none -> P = none ; P is C / 1000 ),
    learned_rules:rank_key(rule(R, N, L, P), Key).

% deciding_rule(+S, +L, -R): why L is concluded, in one rule.
deciding_rule(S, L, R) :-
    (   defeasible:given(L)
    ->  R = fact
    ;   rule(R, strict, L), truth(S, definitely(S, L), true), applicable_definitely(S, R)
    ->  true
    ;   applicable_for(S, L, Rs),
        (   member(R, Rs), \+ beaten(S, R, L)
        ->  true
        ;   Rs = [R|_]
        ->  true
        ;   R = none
        )
    ).

applicable_definitely(S, R) :-
    rule_body(R, Bs),
    forall(member(B, Bs), truth(S, definitely(S, B), true)).

applicable_for(S, L, Rs) :-
    findall(Key-R, ( rule(R, K, L), K \== defeater, applicable(S, R, true),
                     rank_key(R, Key) ), Keyed),
    sort(1, @>=, Keyed, Sorted),
    pairs_values(Sorted, Rs).

beaten(S, R, L) :-
    complement(L, NL), rule(A, _, NL), superior(A, R), applicable(S, A, true).

rule(R, K, H) :- defeasible:rule(R, K, H).

%!  why(+SceneProps:list, +Literal, -Proof) is det.
%!  why(+SceneProps:list, +Literal, +Options, -Proof) is det.
%
%   Proof explains the status of Literal in the scene:
%
%     - given(L): L is a fact (or a scene proposition);
%     - definite(R, L, Proofs): the strict rule R with definite body;
%     - defeasible(R, L, Proofs, Rebuttals): rule R applies and each rule
%       for the complement is inapplicable(A, B) (its body literal B is not
%       provable) or beaten(A, T) (the superior rule T applies);
%     - not_concluded(L, Reasons) (why-not), with Reasons among
%       complement_definite(NL), no_rule(L), blocked(R, B) (body literal
%       B of rule R is not provable), undecided_body(R, B),
%       attacked(R, A) (rule A for the complement applies and R does not
%       beat it), and looping(L).
why(Scene, L, Proof) :-
    why(Scene, L, [], Proof).
why(Scene, L, Options, Proof) :-
    semantics(Options, S),
    with_scene(Scene, proof(S, L, [], Proof)).

proof(S, L, Seen, Proof) :-
    truth(S, defeasibly(S, L), V),
    (   V == true
    ->  positive_proof(S, L, [L|Seen], Proof)
    ;   why_not(S, L, V, Proof)
    ).

positive_proof(S, L, Seen, Proof) :-
    (   defeasible:given(L)
    ->  Proof = given(L)
    ;   rule(R, strict, L), applicable_definitely(S, R)
    ->  rule_body(R, Bs),
        maplist(sub_proof(S, Seen), Bs, Ps),
        Proof = definite(R, L, Ps)
    ;   deciding_rule(S, L, R),
        rule_body(R, Bs),
        maplist(sub_proof(S, Seen), Bs, Ps),
        complement(L, NL),
        findall(Reb, ( rule(A, _, NL), rebuttal(S, A, L, Reb) ), Rebs),
        Proof = defeasible(R, L, Ps, Rebs)
    ).

sub_proof(S, Seen, B, P) :-
    (   memberchk(B, Seen) -> P = given(B)
    ;   proof(S, B, Seen, P)
    ).

rebuttal(S, A, L, Reb) :-
    rule_body(A, Bs),
    (   member(B, Bs), \+ truth(S, defeasibly(S, B), true)
    ->  Reb = inapplicable(A, B)
    ;   rule(T, K, L), K \== defeater, superior(T, A), applicable(S, T, true)
    ->  Reb = beaten(A, T)
    ;   Reb = standing(A)
    ).

why_not(S, L, V, not_concluded(L, Reasons)) :-
    complement(L, NL),
    (   truth(S, definitely(S, NL), true)
    ->  Reasons = [complement_definite(NL)]
    ;   findall(R, ( rule(R, K, L), K \== defeater ), Rs),
        (   Rs == []
        ->  Reasons0 = [no_rule(L)]
        ;   foldl(rule_reason(S, L, NL), Rs, [], Reasons0)
        ),
        (   V == undefined, Reasons0 == []
        ->  Reasons = [looping(L)]
        ;   Reasons = Reasons0
        )
    ).

rule_reason(S, _, _, R, Acc, [Reason|Acc]) :-
    rule_body(R, Bs),
    member(B, Bs), truth(S, defeasibly(S, B), VB), VB \== true, !,
    (   VB == false -> Reason = blocked(R, B) ; Reason = undecided_body(R, B) ).
rule_reason(S, _, NL, R, Acc, [attacked(R, A)|Acc]) :-
    rule(A, _, NL), \+ superior(R, A), applicable(S, A, true), !.
rule_reason(_, L, _, _, Acc, [looping(L)|Acc]).

%!  why_brief(+SceneProps:list, +Literal, +Options, -Proof) is det.
%
%   As why/4 when Literal is concluded. Otherwise a short why-not,
%   =|not_concluded(L, Reasons)|=, that names few rules however large the
%   theory is, looking at the rules for Literal and for its complement
%   (defeaters aside):
%
%     - [complement_definite(NL)] as why/4;
%     - [complement_concluded(NL, R)]: rule R concludes the complement;
%     - [conflict(A, B)]: rules A and B for opposite heads both apply and
%       neither is superior to the other;
%     - [attacked(A, B)]: A applies, and the rule B for the opposite head
%       applies too and is not overridden by A;
%     - [overridden(A, B)]: A applies and is overridden by B (a defeater,
%       say), which applies;
%     - [no_rule_either(L, NL)]: no rule concludes L or NL;
%     - none_applies(L, NL) followed by up to three nearest(R, Missing):
%       no rule for L or NL applies, and R are the rules that miss the
%       fewest body literals in the scene (then the fewest that the scene
%       contradicts, then in theory order); Missing lists each body literal
%       that is not concluded as missing(B, V, Instead), V =false= or
%       =undefined=, Instead the scene's proposition of B's dimension (or
%       =none=);
%     - [looping(L)] otherwise (a rule applies, yet nothing opposes it:
%       ambiguity propagation or a loop).
why_brief(Scene, L, Options, Proof) :-
    semantics(Options, S),
    with_scene(Scene, brief_proof(S, Scene, L, Proof)).

brief_proof(S, Scene, L, Proof) :-
    truth(S, defeasibly(S, L), V),
    (   V == true
    ->  positive_proof(S, L, [L], Proof)
    ;   Proof = not_concluded(L, Reasons),
        brief_reasons(S, Scene, L, Reasons)
    ).

brief_reasons(S, Scene, L, Reasons) :-
    complement(L, NL),
    findall(R, ( member(H, [L, NL]), rule(R, K, H), K \== defeater ), Rs),
    (   truth(S, definitely(S, NL), true)
    ->  Reasons = [complement_definite(NL)]
    ;   truth(S, defeasibly(S, NL), true)
    ->  deciding_rule(S, NL, R),
        Reasons = [complement_concluded(NL, R)]
    ;   Rs == []
    ->  Reasons = [no_rule_either(L, NL)]
    ;   findall(A, ( member(A, Rs), applicable(S, A, true) ), As),
        As \== []
    ->  (   member(A, As), opponent(S, A, B), \+ superior(A, B), \+ superior(B, A)
        ->  Reasons = [conflict(A, B)]
        ;   member(A, As), opponent(S, A, B), \+ superior(A, B)
        ->  Reasons = [attacked(A, B)]
        ;   member(A, As), opponent(S, A, B)
        ->  Reasons = [overridden(A, B)]
        ;   Reasons = [looping(L)]
        )
    ;   findall(key(N, C, I)-nearest(R, Ms),
                ( nth1(I, Rs, R),
                  missing(S, Scene, R, Ms), Ms \== [],
                  length(Ms, N),
                  aggregate_all(count, ( member(missing(_, _, P), Ms), P \== none ), C) ),
                Keyed),
        Keyed \== []
    ->  keysort(Keyed, Sorted),
        pairs_values(Sorted, Nearest),
        (   length(Firsts, 3), append(Firsts, _, Nearest)
        ->  true
        ;   Firsts = Nearest
        ),
        Reasons = [none_applies(L, NL)|Firsts]
    ;   Reasons = [looping(L)]
    ).

% opponent(+S, +A, -B): B is an applicable rule (or defeater) for the
% complement of A's head.
opponent(S, A, B) :-
    rule(A, _, H), complement(H, NH),
    rule(B, _, NH), applicable(S, B, true).

% missing(+S, +Scene, +R, -Missing): the body literals of R not concluded.
missing(S, Scene, R, Ms) :-
    rule_body(R, Bs),
    findall(missing(B, V, P),
            ( member(B, Bs), truth(S, defeasibly(S, B), V), V \== true,
              instead(Scene, B, P) ),
            Ms).

% instead(+Scene, +B, -P): the scene's proposition P of B's dimension, or none.
instead(Scene, B, P) :-
    (   proposition(B, D, _, _), member(P, Scene), P \== B, proposition(P, D, _, _)
    ->  true
    ;   P = none
    ).

%!  explain(+SceneProps:list, +Literal, +Options, -Text:string) is det.
%
%   why/4 in words.
explain(Scene, L, Options, Text) :-
    why(Scene, L, Options, Proof),
    proof_text(Proof, Text).

%!  explain_brief(+SceneProps:list, +Literal, +Options, -Text:string) is det.
%
%   why_brief/4 in words: the same as explain/4 when Literal is
%   concluded, a why-not of at most five sentences when it is not.
explain_brief(Scene, L, Options, Text) :-
    why_brief(Scene, L, Options, Proof),
    proof_text(Proof, Text).
