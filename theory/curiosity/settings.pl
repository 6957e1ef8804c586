:- module(curiosity_settings,
          [ settings/2                % +Options, -Settings
          ]).
/** <module> The settings of an exploration

Read the options of explore/1 into one dict, the Settings every part of
the loop reads: each option checked, and those not given taken from the
defaults of theory/defaults.pl. A bad option raises
=|exploration_error(Text)|= with one line saying which and why.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(http/json)).
:- use_module('../vocabulary').
:- use_module('../validity').
:- use_module('../default_values').
:- use_module(library(aggregate)).

%!  settings(+Options:list, -Settings:dict) is det.
%
%   Settings holds every option of explore/1 (see explore.pl), as the
%   option table of theory/defaults.pl declares them: those of Options,
%   checked against their type and range, the others their defaults. The
%   curiosity is read first; store, workers, ray_address and
%   oracle_options are keys only when given.
%
%   @error exploration_error(Text) for the first bad option.
settings(Options, S) :-
    must_be(list, Options),
    setting_value(curiosity, Options, discover, Curiosity),
    findall(Key-Value,
            ( table_option(Key, _, _, _),
              Key \== curiosity,
              setting_value(Key, Options, Curiosity, Value)
            ), Pairs),
    dict_pairs(S0, _, [curiosity-Curiosity|Pairs]),
    (   option(oracle_options(OO), Options)
    ->  (   is_dict(OO) -> OracleOptions = OO ; atom_json_dict(OO, OracleOptions, []) ),
        put_dict(oracle_options, S0, OracleOptions, S)
    ;   S = S0
    ).

%   table_option(?Key, ?Type, ?Range, ?Default): a row of the option
%   table (theory/defaults.pl).
table_option(Key, Type, Range, Default) :-
    defaults:option(Key, Type, Range, Default, _).

%   setting_value(+Key, +Options, +Curiosity, -Value): the option Key of
%   Options, checked, or its default; fails for an option without a
%   default that is not given (store, workers, ray_address).
setting_value(Key, Options, Curiosity, Value) :-
    table_option(Key, Type, Range, Default),
    Option =.. [Key, Given],
    (   option(Option, Options)
    ->  check_option(Type, Range, Key, Given, Value)
    ;   unsaid(Key, Default, Curiosity, Value0)
    ->  check_option(Type, Range, Key, Value0, Value)
    ).

%   unsaid(+Key, +Default, +Curiosity, -Value): the value of an option not
%   given: the table's default, or one set otherwise (the pours of a
%   batch, a_0, the learned theory).
unsaid(batch, none, _, N) :- !,
    aggregate_all(count, parameter(_, _, _, _, _), NParams),
    N is NParams + 1.
unsaid(initial, none, _, Initial) :- !,
    default_initial(Initial).
unsaid(out, _, _, File) :- !,
    default_out(File).
unsaid(Key, Default, _, Value) :-
    Default \== none,
    Default \= default(_),
    default(Key, Value).

%   check_option(+Type, +Range, +Key, +Value0, -Value): Value0 is of the
%   option's type and in its range (Value, as the settings hold it), else
%   the error names the option Key.
check_option(count, range(Low, High), Key, N, N) :- !,
    (   integer(N), N >= Low
    ->  (   ( High == none ; N =< High )
        ->  true
        ;   option_error(Key, "expected a whole number at most ~w", [High])
        )
    ;   Low =:= 1
    ->  option_error(Key, "expected a whole number above 0", [])
    ;   option_error(Key, "expected a whole number >= ~w", [Low])
    ).
check_option(permille, range(Low, High), Key, X, Value) :- !,
    (   number(X), X * 1000 >= Low, ( High == none ; X * 1000 =< High )
    ->  Value is float(X)
    ;   unit(Low, L),
        (   High == none
        ->  option_error(Key, "expected a number >= ~w", [L])
        ;   unit(High, H),
            option_error(Key, "expected a number from ~w to ~w", [L, H])
        )
    ).
check_option(choice, Range, Key, V, V) :- !,
    Range =.. [one_of|Choices],
    (   memberchk(V, Choices)
    ->  true
    ;   append(First, [Last], Choices),
        atomic_list_concat(First, ', ', Text),
        option_error(Key, "expected ~w or ~w", [Text, Last])
    ).
check_option(oracle, _, _, V, V) :- !.      % the bridge knows the oracles (test ones too)
check_option(flag, _, Key, V, V) :- !,
    (   memberchk(V, [true, false]) -> true ; option_error(Key, "expected true or false", []) ).
check_option(antecedent, _, _, Props, Set) :- !,
    check_initial(Props, Set).
check_option(path, _, _, File, Absolute) :- !,
    absolute_file_name(File, Absolute).
check_option(text, _, _, V, V).

%   unit(+Permille, -Number): thousandths as the number they stand for
%   (a whole number when they are whole).
unit(P, N) :- ( P mod 1000 =:= 0 -> N is P // 1000 ; N is P / 1000 ).

%   option_error(+Key, +Format, +Args): raise exploration_error("Key: ...").
option_error(Key, Format, Args) :-
    format(string(Why), Format, Args),
    format(string(M), "~w: ~s", [Key, Why]),
    throw(exploration_error(M)).

%   default_out(-File): the default learned theory, relative to theory/
%   (the folder above this one).
default_out(File) :-
    module_property(curiosity_settings, file(Here)),
    file_directory_name(Here, CuriosityDir),
    file_directory_name(CuriosityDir, Dir),
    default(theory, Relative),
    directory_file_path(Dir, Relative, File).

%   check_initial(+Props, -Set): Props, a list of propositions, sorted, is
%   a valid antecedent (the first reason it is not is the error).
check_initial(Props, Set) :-
    (   is_list(Props) -> true
    ;   throw(exploration_error("initial: expected a list of propositions"))
    ),
    sort(Props, Set),
    violations(Set, Why),
    (   Why = [] -> true
    ;   Why = [unknown(_, W)|_]
    ->  format(string(M), "initial antecedent: ~s", [W]),
        throw(exploration_error(M))
    ;   Why = [violation(_, _, _, W)|_],
        format(string(M), "initial antecedent is invalid: ~s", [W]),
        throw(exploration_error(M))
    ).

