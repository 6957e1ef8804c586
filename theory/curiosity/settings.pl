:- module(curiosity_settings,
          [ settings/2,               % +Options, -Settings
            course_options/2,         % +Settings, -Names
            recorded_settings/4       % +Settings, +OracleVersion, -Facts, -Antecedents
          ]).
/** <module> The settings of an exploration

Read the options of explore/1 into one dict, the Settings every part of
the loop reads: each option checked, and those not given taken from the
defaults of theory/defaults.pl. A bad option raises
=|exploration_error(Text)|= with one line saying which and why. From the
same table: the options that decide a run's course (its run key) and the
setting/2 facts of its learned theory.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module('../vocabulary').
:- use_module('../validity').
:- use_module('../default_values').
:- use_module(library(aggregate)).
:- use_module(library(yall)).
:- use_module(interface, [curiosity_module/2, curiosity_unsaid/3]).

%!  settings(+Options:list, -Settings:dict) is det.
%
%   Settings holds every option of explore/1 (see run.pl), as the
%   option table of theory/defaults.pl declares them: those of Options,
%   checked against their type and range, the others their defaults. The
%   curiosity is read first; store, workers, ray_address and
%   oracle_options are keys only when given.
%
%   @error exploration_error(Text) for the first bad option.
settings(Options, S) :-
    must_be(list, Options),
    maplist(known_option, Options),
    setting_value(curiosity, Options, _, Curiosity),
    maplist(option_of_curiosity(Curiosity), Options),
    findall(Key-Value,
            ( table_option(Key, _, _, _),
              Key \== curiosity,
              setting_value(Key, Options, Curiosity, Value)
            ), Pairs),
    dict_pairs(S0, _, [curiosity-Curiosity|Pairs]),
    (   option(oracle_options(OracleOptions), Options)
    ->  (   is_dict(OracleOptions) -> true
        ;   throw(exploration_error("oracle_options: expected a dict"))
        ),
        put_dict(oracle_options, S0, OracleOptions, S)
    ;   S = S0
    ).

%!  course_options(+Settings:dict, -Names:list) is det.
%
%   Names are the options that decide the course of the run of Settings:
%   those of course/2 (theory/defaults.pl's, or the module's of the
%   curiosity that declares the option) whose every condition holds,
%   in the option table's order. Python hashes them into the run key.
course_options(S, Names) :-
    course_names(S, true, Names).

%   course_names(+Settings, +Nonzero, -Names): the options of course/2
%   whose conditions hold for Settings, in the option table's order; with
%   Nonzero false, a condition nonzero(Option) counts as holding.
course_names(S, Nonzero, Names) :-
    findall(Name, ( table_option(Name, _, _, _),
                    once(option_course(Name, _)),
                    forall(option_course(Name, When), course_holds(When, Nonzero, S)) ),
            Names).

course_holds(every, _, _).
course_holds(C, _, S) :- curiosity_choice(C), get_dict(curiosity, S, C).
course_holds(other_than(C), _, S) :- \+ get_dict(curiosity, S, C).
course_holds(nonzero(Option), Nonzero, S) :-
    (   Nonzero == true -> get_dict(Option, S, V), V =\= 0 ; true ).

%!  recorded_settings(+Settings:dict, +OracleVersion, -Facts:list, -Antecedents:list) is det.
%
%   The setting/2 facts of the learned theory of the run of Settings: the
%   options of its course (those of course/2 for its curiosity, at 0 too:
%   nonzero/1 only keeps the run keys of runs without an option) and
%   those of recorded/1 in theory/defaults.pl, in the option table's
%   order. Facts: a permille option as Name_permille in
%   thousandths, the oracle followed by oracle_version(OracleVersion), the
%   others as they are; Antecedents: setting(Name, Prop) for each
%   proposition of an antecedent option (which the theory writes after
%   the run's own facts).
recorded_settings(S, Version, Facts, Antecedents) :-
    course_names(S, false, Course),
    findall(Name-Type, ( table_option(Name, Type, _, _),
                         ( memberchk(Name, Course) ; defaults:recorded(Name) ) ),
            Recorded),
    findall(F, ( member(Name-Type, Recorded), Type \== antecedent,
                 get_dict(Name, S, V), recorded_fact(Type, Name, V, Version, F) ),
            Facts),
    findall(setting(Name, P), ( member(Name-antecedent, Recorded),
                                get_dict(Name, S, Props), member(P, Props) ),
            Antecedents).

recorded_fact(permille, Name, V, _, setting(Key, Permille)) :- !,
    atom_concat(Name, '_permille', Key),
    Permille is round(V * 1000).
recorded_fact(oracle, Name, V, Version, F) :- !,
    (   F = setting(Name, V)
    ;   atom_concat(Name, '_version', Key),
        F = setting(Key, Version)
    ).
recorded_fact(_, Name, V, _, setting(Name, V)).

%   known_option(+Option): Option is Name(Value) or Name = Value, Name an
%   option of the table or oracle_options; else the error names it (a
%   misspelt option is refused, not left to its default).
known_option(Option) :-
    (   nonvar(Option),
        ( Option = (Name = _) ; compound(Option), compound_name_arity(Option, Name, 1) ),
        atom(Name),
        ( Name == oracle_options ; table_option(Name, _, _, _) )
    ->  true
    ;   format(string(M), "unknown option ~q (the options of explore/1 are those of docs/options.md)",
               [Option]),
        throw(exploration_error(M))
    ).

%   option_of_curiosity(+Curiosity, +Option): Option (known_option/1) is
%   one that Curiosity reads: option_used_by/2 names it for Curiosity,
%   or names it for none. Else the error names the option, the
%   curiosity, the curiosity's budget when the option is the other's, and
%   the options the curiosity reads that not every curiosity reads.
option_of_curiosity(Curiosity, Option) :-
    (   Option = (Name = _) -> true ; compound_name_arity(Option, Name, 1) ),
    (   \+ option_used_by(Name, _)
    ->  true
    ;   option_used_by(Name, Curiosity)
    ->  true
    ;   findall(O, ( table_option(O, _, _, _), option_used_by(O, Curiosity) ), Own),
        (   memberchk(Name, [budget, pours]),
            member(B, [budget, pours]), memberchk(B, Own)
        ->  format(string(Budget), ", whose budget is ~w(N)", [B])
        ;   Budget = ""
        ),
        findall(C, option_used_by(Name, C), Cs),
        maplist([C, T]>>format(string(T), "curiosity(~w)", [C]), Cs, Ts),
        words_and(Own, OwnText),
        words_and(Ts, ReadersText),
        format(string(M), "~w: not an option of curiosity(~w)~w; its own options are ~w (~w is read by ~w)",
               [Name, Curiosity, Budget, OwnText, Name, ReadersText]),
        throw(exploration_error(M))
    ).

%   words_and(+Words, -Text): "a", "a and b", "a, b and c".
words_and([W], Text) :- !, format(string(Text), "~w", [W]).
words_and(Ws, Text) :-
    append(First, [Last], Ws),
    atomic_list_concat(First, ', ', F),
    format(string(Text), "~w and ~w", [F, Last]).

%   table_option(?Key, ?Type, ?Range, ?Default): a row of the option
%   table, in the table's order: the rows of theory/defaults.pl, each
%   followed by the rows the curiosities' modules declare after it
%   (option_after/2; the curiosity row: the others), the curiosities in
%   the order loaded (the one list's), each in its file's order
%   (theory/option_table.py reads the same rows for Python).
table_option(Key, Type, Range, Default) :-
    atom(Key), !,                       % one row, without a choice point
    (   defaults:option(Key, Type0, Range0, Default0, _)
    ->  true
    ;   curiosity_module(_, M),
        declared(M, option(Key, Type0, Range0, Default0, _))
    ->  true
    ),
    Type = Type0, Range = Range0, Default = Default0.
table_option(Key, Type, Range, Default) :-
    defaults:option(Row, Type0, Range0, Default0, _),
    (   Key = Row, Type = Type0, Range = Range0, Default = Default0
    ;   curiosity_module(_, M),
        declared(M, option(Key, Type, Range, Default, _)),
        once(( declared(M, option_after(Key, At)) ; At = curiosity )),
        At == Row
    ).

%   declared(+Module, ?Fact): Fact, an option/5, option_after/2 or
%   course/2 fact, is a declaration of Module, a curiosity's, of its own
%   options.
declared(M, Fact) :-
    functor(Fact, Name, Arity),
    current_predicate(M:Name/Arity),
    call(M:Fact).

%   option_course(?Name, ?When): course/2 of theory/defaults.pl, or of the
%   module of the curiosity that declares the option.
option_course(Name, When) :-
    defaults:course(Name, When).
option_course(Name, When) :-
    curiosity_module(_, M),
    declared(M, option(Name, _, _, _, _)),
    declared(M, course(Name, When)).

%   option_used_by(?Name, ?Curiosity): used_by/2 of theory/defaults.pl;
%   an option a curiosity's module declares is read by that curiosity alone.
option_used_by(Name, Curiosity) :-
    defaults:used_by(Name, Curiosity).
option_used_by(Name, Curiosity) :-
    curiosity_module(Curiosity, M),
    declared(M, option(Name, _, _, _, _)).

%   curiosity_choice(+C): C is a curiosity, a value of the option table's
%   curiosity row (the one list).
curiosity_choice(C) :-
    table_option(curiosity, choice, Range, _),
    Range =.. [one_of|Choices],
    memberchk(C, Choices).

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
%   given: the curiosity's own (unsaid/2 of its module, interface.pl), the
%   table's default, or one set otherwise (the pours of a batch, a_0, the
%   learned theory).
unsaid(Key, none, Curiosity, Value) :-
    nonvar(Curiosity),
    curiosity_unsaid(Curiosity, Key, Value), !.
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
    table_option(Key, Type, _, _),
    (   Type == permille -> Value is Default / 1000 ; Value = Default ).

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
    ;   Choices = [Only]
    ->  option_error(Key, "expected ~w", [Only])
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

%   default_out(-File): where an exploration writes its theory when not
%   told (default(explore_out, F), relative to the working directory):
%   never the shipped theory.
default_out(File) :-
    default(explore_out, Relative),
    absolute_file_name(Relative, File).

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

