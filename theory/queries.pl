:- module(queries,
          [ what_happens/2,         % +SceneProps, -Outcomes
            what_happens/3,         % +SceneProps, +Options, -Outcomes
            why/3,                  % +SceneProps, +Literal, -Proof
            why/4,                  % +SceneProps, +Literal, +Options, -Proof
            proof_text/2,           % +Proof, -Text
            explain/4               % +SceneProps, +Literal, +Options, -Text
          ]).
/** <module> Questions to a defeasible theory of pouring

The scene propositions of a question become facts of the current theory
(defeasible:load_theory/1); the 9 expectations of the vocabulary are the
literals asked about. what_happens/2 predicts, why/3 explains a
conclusion, or why a literal is not concluded (why-not), as a proof term
that proof_text/2 puts into words.
*/

:- use_module(defeasible).
:- use_module(vocabulary).
:- use_module(library(lists)).
:- use_module(library(apply)).

%!  what_happens(+SceneProps:list, -Outcomes:list) is det.
%!  what_happens(+SceneProps:list, +Options:list, -Outcomes:list) is det.
%
%   Outcomes has one =|outcome(Expectation, Value, Rule)|= per expectation,
%   in the vocabulary's order. Value is =holds= (the theory defeasibly
%   concludes the expectation), =fails= (it concludes its negation) or
%   =unknown=; Rule is the deciding rule, =fact= for a given literal, or
%   =none=. Options select the semantics (defeasible:semantics/2).
what_happens(Scene, Outcomes) :-
    what_happens(Scene, [], Outcomes).
what_happens(Scene, Options, Outcomes) :-
    semantics(Options, S),
    with_scene(Scene,
               findall(outcome(E, V, R),
                       ( expectation(E, _, _), outcome(S, E, V, R) ),
                       Outcomes)).

outcome(S, E, V, R) :-
    (   truth(S, defeasibly(S, E), true)
    ->  V = holds, deciding_rule(S, E, R)
    ;   truth(S, defeasibly(S, neg(E)), true)
    ->  V = fails, deciding_rule(S, neg(E), R)
    ;   V = unknown, R = none
    ).

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
    findall(R, ( rule(R, K, L), K \== defeater, applicable(S, R, true) ), Rs).

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

%!  proof_text(+Proof, -Text:string) is det.
%
%   Proof in words, one sentence per step, separated by "; ".
proof_text(Proof, Text) :-
    phrase_proof(Proof, Parts),
    atomic_list_concat(Parts, '; ', A),
    atom_string(A, Text).

phrase_proof(given(L), [P]) :-
    format(atom(P), "~w is given", [L]).
phrase_proof(definite(R, L, Ps), [P|Sub]) :-
    format(atom(P), "~w holds by the strict rule ~w", [L, R]),
    sub_texts(Ps, Sub).
phrase_proof(defeasible(R, L, Ps, Rebs), [P|More]) :-
    rule_words(R, RW),
    format(atom(P), "~w by rule ~w", [L, RW]),
    sub_texts(Ps, Sub),
    maplist(rebuttal_text, Rebs, RT),
    append(Sub, RT, More).
phrase_proof(not_concluded(L, Reasons), [P|RT]) :-
    format(atom(P), "~w is not concluded", [L]),
    maplist(reason_text, Reasons, RT).

sub_texts(Ps, Texts) :-
    foldl(sub_text, Ps, [], Rev), reverse(Rev, Texts).
sub_text(given(_), Acc, Acc) :- !.
sub_text(P, Acc, [T|Acc]) :- proof_text(P, S), atom_string(T, S).

rule_words(R, W) :-
    rule(R, K, H), rule_body(R, Bs),
    arrow(K, Arrow),
    atomic_list_concat(Bs, ', ', BT),
    (   Bs == []
    ->  format(atom(W), "~w (~w ~w)", [R, Arrow, H])
    ;   format(atom(W), "~w (~w ~w ~w)", [R, BT, Arrow, H])
    ).

arrow(strict, '->').
arrow(defeasible, '=>').
arrow(defeater, '~>').

rebuttal_text(inapplicable(A, B), T) :-
    format(atom(T), "the opposing rule ~w does not apply (~w is not concluded)", [A, B]).
rebuttal_text(beaten(A, T0), T) :-
    format(atom(T), "the opposing rule ~w is overridden by ~w (~w > ~w)", [A, T0, T0, A]).
rebuttal_text(standing(A), T) :-
    format(atom(T), "the opposing rule ~w is beaten by the rules for it together", [A]).

reason_text(complement_definite(NL), T) :-
    format(atom(T), "its complement ~w is definitely true", [NL]).
reason_text(no_rule(L), T) :-
    format(atom(T), "no rule concludes ~w", [L]).
reason_text(blocked(R, B), T) :-
    rule_words(R, W),
    format(atom(T), "rule ~w does not apply: ~w is not concluded", [W, B]).
reason_text(undecided_body(R, B), T) :-
    rule_words(R, W),
    format(atom(T), "rule ~w may not apply: ~w is undecided", [W, B]).
reason_text(attacked(R, A), T) :-
    rule_words(A, W),
    format(atom(T), "rule ~w is opposed by rule ~w, which it does not override", [R, W]).
reason_text(looping(L), T) :-
    format(atom(T), "the support for ~w is ambiguous or circular", [L]).

%!  explain(+SceneProps:list, +Literal, +Options, -Text:string) is det.
%
%   why/4 in words.
explain(Scene, L, Options, Text) :-
    why(Scene, L, Options, Proof),
    proof_text(Proof, Text).
