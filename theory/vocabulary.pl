:- module(vocabulary,
          [ parameter/5,          % ?Name, ?Group, ?Unit, ?Low, ?High
            prior/2,              % ?Name, ?Distribution
            parameter_gloss/2,    % ?Name, ?Gloss
            scene/3,              % ?Constant, ?Unit, ?Value
            dimension/4,          % ?Dim, ?Aspect, ?Schema, ?Gloss
            proposition/4,        % ?Name, ?Dim, ?Rank, ?Gloss
            model/3,              % ?Name, ?Param, ?Model
            role/2,               % ?Dim, ?Role
            expectation/3,        % ?Name, ?Stage, ?Gloss
            constraint/2,         % ?Name, ?Gloss
            conflict/3,           % ?Name, ?P1, ?P2
            image_schema/2,       % ?Proposition, ?Schema
            constrains/2          % ?Proposition, ?Param
          ]).
/** <module> The qualitative vocabulary of pouring

Loads the fact files under =|theory/vocabulary/|= (the same files that
clingo reads) and offers them as predicates: the 30 scene parameters, the 86
scene propositions with their generative models, the 9 expectations, and the
validity constraints.
*/

:- use_module(theory_files).

:- dynamic parameter/5, prior/2, parameter_gloss/2, scene/3, dimension/4,
   proposition/4, model/3, role/2, expectation/3, constraint/2, conflict/3.

vocabulary_file(parameters).
vocabulary_file(propositions).
vocabulary_file(expectations).
vocabulary_file(constraints).

load_vocabulary :-
    prolog_load_context(directory, Dir),
    forall(vocabulary_file(Base),
           (   format(atom(File), "~w/vocabulary/~w.pl", [Dir, Base]),
               load_facts(File, vocabulary)
           )).

%!  image_schema(?Proposition, ?Schema) is nondet.
%
%   Schema is the image schema of Proposition (that of its dimension).
image_schema(P, Schema) :-
    proposition(P, Dim, _, _),
    dimension(Dim, _, Schema, _).

%!  constrains(?Proposition, ?Param) is nondet.
%
%   Proposition's generative model draws Param.
constrains(P, Param) :-
    model(P, Param, _).

:- load_vocabulary.
