/*  Panta Rhei in plain SWI-Prolog.

    swipl theory/pantarhei.pl
    ?- what_happens([pour_to_side], O).

Loads every Prolog module of the theory (this list is the one list of
them: the command line and the tests read it from here; the modules that
only they use, fact_reader, theory_store, superiority, theory_checks and
proof_words,
come with them) and the shipped learned theory, so that asking and
explaining need no Python. Exploring (curiosity:explore/1) needs the
oracle, which only `pantarhei prolog` provides.
*/

:- use_module(theory_files).
:- use_module(default_values).
:- use_module(vocabulary).
:- use_module(validity).
:- use_module(defeasible).
:- use_module(learned_rules).
:- use_module(queries).
:- use_module(answer_words).
:- use_module(ask).
:- use_module(theory_view).
:- use_module(curiosity).

:- initialization(load_shipped_theory).

%!  load_shipped_theory is det.
%
%   Make the learned theory that ships with the project
%   (learned/pouring.pl beside this file) the current theory, if it exists.
load_shipped_theory :-
    prolog_load_context(directory, Dir),
    !,
    directory_file_path(Dir, 'learned/pouring.pl', File),
    (   exists_file(File) -> load_theory(File) ; true ).
load_shipped_theory :-
    source_file(load_shipped_theory, Here),
    file_directory_name(Here, Dir),
    directory_file_path(Dir, 'learned/pouring.pl', File),
    (   exists_file(File) -> load_theory(File) ; true ).
