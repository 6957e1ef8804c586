:- module(curiosity_oracle_prompt,
          [ sample/4,                 % +Props, +N, +Seed, -Rows
            describe/2,               % +Row, -Props
            simulate/3                % +Rows, +Options, -Scores
          ]).
/** <module> The oracle at the Prolog prompt

Draw parameterizations of an antecedent, describe a parameterization by
its propositions, and simulate pours, from Prolog (`pantarhei prolog`):
the same oracle the exploration calls, through the foreign predicates
oracle_sample, oracle_describe and oracle_simulate (foreign.pl).
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(pairs)).
:- use_module('../vocabulary').
:- use_module('../default_values').
:- use_module(foreign).

%!  sample(+Props:list, +N:integer, +Seed:integer, -Rows:list) is det.
%
%   Rows are N parameterizations drawn from P(p|Props): lists of 30 numbers
%   in the vocabulary's parameter order (theory units).
sample(Props, N, Seed, Rows) :-
    call_bridge(oracle_sample, _{antecedent:Props, n:N, seed:Seed}, Reply),
    Rows = Reply.rows.

%!  describe(+Row:list, -Props:list) is det.
%
%   Props are the propositions whose generative models hold the
%   parameterization Row (30 numbers in the vocabulary's parameter order):
%   per dimension the value whose support contains Row, none where it falls
%   between values. Every row that sample/4 draws for an antecedent is
%   described by a superset of it.
describe(Row, Props) :-
    call_bridge(oracle_describe, _{rows:[Row]}, Reply),
    Reply.props = [Props0],
    maplist(text_atom, Props0, Props).

%   text_atom(+Text, -Atom): a proposition of a reply (text) as an atom.
text_atom(Text, Atom) :-
    atom_string(Atom, Text).

%!  simulate(+Rows:list, +Options:list, -Scores:list) is det.
%
%   Scores are the 9 expectation scores of each row (a list of
%   Expectation-Score pairs per row; a failed simulation scores nan).
%   Options: oracle(Name) and executor(E) (defaults: theory/defaults.pl),
%   store(File), workers(N). Results are kept in the store, and stored ones are not
%   simulated again.
simulate(Rows, Options, Scores) :-
    default(oracle, DefaultOracle),
    option(oracle(Oracle), Options, DefaultOracle),
    default(executor, DefaultExecutor),
    option(executor(Executor), Options, DefaultExecutor),
    Request0 = _{rows:Rows, oracle:Oracle, executor:Executor},
    (   option(store(Store), Options)
    ->  absolute_file_name(Store, Abs), put_dict(store, Request0, Abs, Request1)
    ;   Request1 = Request0
    ),
    (   option(workers(W), Options) -> put_dict(workers, Request1, W, Request) ; Request = Request1 ),
    call_bridge(oracle_simulate, Request, Reply),
    findall(E, expectation(E, _, _), Es),
    findall(Row, ( member(S, Reply.scores), pairs_keys_values(Row, Es, S) ), Scores).
