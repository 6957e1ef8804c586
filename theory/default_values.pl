:- module(default_values,
          [ default/2,                % ?Key, ?Value
            default_initial/1         % -Props
          ]).
/** <module> The project's defaults, read from theory/defaults.pl

theory/defaults.pl holds every default of the project as ground facts,
written once (those of explore/1's options in its option table, but for
the options one curiosity alone reads, which its own module declares:
theory/curiosity/settings.pl reads those); this module reads them for the
Prolog side (Python reads the same file: pantarhei.theory.defaults).
*/

:- use_module(theory_files).

%!  default(?Key, ?Value) is nondet.
%
%   The defaults of theory/defaults.pl, with permille values as numbers:
%   =|default(Key_permille, V)|= is =|default(Key, V/1000)|=.
default(Key, Value) :-
    defaults:default(Key0, Value0),
    (   atom_concat(Key, '_permille', Key0)
    ->  Value is Value0 / 1000
    ;   Key = Key0, Value = Value0
    ).
default(Key, Value) :-                  % an option's default in the option table
    defaults:option(Key, Type, _, Value0, _),
    Value0 \== none,
    Value0 \= default(_),
    (   Type == permille -> Value is Value0 / 1000 ; Value = Value0 ).


%!  default_initial(-Props:list) is det.
%
%   The initial antecedent a_0 when none is given, as theory/defaults.pl
%   says (default_initial/1 facts, in file order).
default_initial(Props) :-
    findall(P, defaults:default_initial(P), Props).

load_defaults :-
    prolog_load_context(directory, Dir),
    directory_file_path(Dir, 'defaults.pl', File),
    load_facts(File, defaults).

:- load_defaults.
