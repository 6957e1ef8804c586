:- module(curiosity_interface,
          [ by_curiosity/2,           % +Settings, +Goal
            curiosity_module/2,       % ?Curiosity, ?Module
            curiosity_python_side/2,  % ?Curiosity, -PythonModules
            curiosity_unsaid/3,       % +Curiosity, +Key, -Value
            load_curiosity/2          % +Curiosity, +File
          ]).
/** <module> The curiosities: one module each, behind one interface

Each curiosity (a value of option curiosity/1, the one list: the
`curiosity` row of the option table, theory/defaults.pl) is one module,
the file of its name beside this one (learn.pl for `learn`). This module
loads the module of each value of the list, checks it against the
interface below, and records it (curiosity_module/2): the loop (loop.pl),
the probes (probe.pl), explore/1 (run.pl) and Python ask the run's
curiosity through by_curiosity/2 and curiosity_python_side/2, and nowhere
else is a curiosity named. A curiosity's module defines these predicates
(unexported; called as Module:Goal):

  - budget(+Settings, -Pours): the budget, in pours;
  - progress_bar(+Settings, -Bar): what the progress bar counts,
    _{total:Total, unit:Unit}, Unit `pour` or `rule` (explored
    antecedents);
  - probe_size(+Settings, -Pours): the pours a probe simulates before a
    candidate's batch (0: it probes nothing);
  - probed(+Cand, +Settings): the candidate is probed before its batch
    (the probe policy; probe.pl);
  - priors_due(+Explored, +Settings): the priors' batch is still to come
    (loop.pl says when);
  - after_batch(+Step, +Settings, -ANew, -Trace): what a step queues and
    records once its batch is simulated. Step is step(I, Id, Cand,
    Explored, Rest, SetAside, Probes, Sim): the iteration, the id and the
    candidate just explored, the explored antecedents with it, A_new
    without it, those set aside after their probe, the step's probes and
    the reply of its simulation. ANew is the new A_new (the candidates),
    Trace the step's line of the trace (what a step records);
  - second_layer(+Explored, +Facts, +Settings, -General): the facts the
    theory writes after those of Algorithm 1's rules (writer.pl);
  - theory_layout(-Layout): what its theory file holds (writer.pl writes
    it): _{rules:R, batches:B, header:H, layer_header:L}, R true when
    Algorithm 1's rules of the explored antecedents are written, B true
    when their provenance counts their batches, H the lines the file's
    header ends with (what its setting/2 and other facts mean) and L the
    header of the second layer;

and may define

  - python_side(-Modules): its Python side, the Python modules (dotted
    names, as atoms) that declare the handlers of its foreign predicates
    (bridge/exploration/curiosity_sides.py); none ([]) when it does not
    define it: its numbers are all Prolog's;
  - unsaid(+Key, -Value): the value of an option of the table without a
    default (`none`), such as batch or initial, when the run does not give
    it (settings.pl); the table's rule for the others;
  - option/5, course/2, prolog_only/1 and option_after/2: the options it
    alone reads, rows of the option table as those of theory/defaults.pl
    (which says what the facts mean), read by settings.pl and by Python
    (theory/option_table.py). An option it declares that the table has
    already is refused as it loads.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module('../default_values').

:- dynamic curiosity_module/2.

:- multifile prolog:message//1.

prolog:message(curiosity_interface(C, File, Problem)) -->
    [ 'the curiosity ~w (~w) '-[C, File] ],
    problem(Problem).

problem(lacks(P/N)) -->
    [ 'does not define ~w/~w of the curiosity interface (theory/curiosity/interface.pl)'-[P, N] ].
problem(python_side(Modules)) -->
    [ 'declares python_side(~q): it takes a list of Python module names'-[Modules] ].
problem(no_module) -->
    [ 'is not a module' ].
problem(option_twice(Name)) -->
    [ 'declares the option ~w, which the option table has already'-[Name] ].

%!  curiosity_module(?Curiosity:atom, ?Module:atom) is nondet.
%
%   Module implements Curiosity, a value of the option curiosity/1 (or a
%   curiosity loaded by load_curiosity/2).

%!  interface_predicate(?PI) is nondet.
%
%   The predicates every curiosity's module defines (above).
interface_predicate(budget/2).
interface_predicate(progress_bar/2).
interface_predicate(probe_size/2).
interface_predicate(probed/2).
interface_predicate(priors_due/2).
interface_predicate(after_batch/4).
interface_predicate(second_layer/4).
interface_predicate(theory_layout/1).

%!  load_curiosity(+Curiosity:atom, +File) is det.
%
%   Load the module of Curiosity from File, check it against the interface
%   and record it as Curiosity's module (curiosity_module/2).
%
%   @error curiosity_interface(Curiosity, File, Problem) when File is no
%   module, lacks a predicate of the interface, declares a Python side
%   that is no list of module names, or an option the table has already.
load_curiosity(C, File) :-
    absolute_file_name(File, Path, [file_type(prolog), access(read)]),
    use_module(Path, []),
    (   module_property(M, file(Path)) -> true
    ;   throw(curiosity_interface(C, Path, no_module))
    ),
    forall(interface_predicate(P/N),
           (   current_predicate(M:P/N) -> true
           ;   throw(curiosity_interface(C, Path, lacks(P/N)))
           )),
    (   current_predicate(M:python_side/1), M:python_side(Modules),
        \+ ( is_list(Modules), maplist(atom, Modules) )
    ->  throw(curiosity_interface(C, Path, python_side(Modules)))
    ;   true
    ),
    (   current_predicate(M:option/5), M:option(Name, _, _, _, _),
        (   defaults:option(Name, _, _, _, _)
        ;   curiosity_module(Other, OM), Other \== C,
            current_predicate(OM:option/5), OM:option(Name, _, _, _, _)
        )
    ->  throw(curiosity_interface(C, Path, option_twice(Name)))
    ;   true
    ),
    retractall(curiosity_module(C, _)),
    assertz(curiosity_module(C, M)).

%!  curiosity_python_side(?Curiosity:atom, -Modules:list(atom)) is nondet.
%
%   Modules are the Python side of Curiosity: its module's python_side/1,
%   or [] when it defines none.
curiosity_python_side(C, Modules) :-
    curiosity_module(C, M),
    (   current_predicate(M:python_side/1) -> M:python_side(Modules) ; Modules = [] ).

%!  curiosity_unsaid(+Curiosity:atom, +Key:atom, -Value) is semidet.
%
%   Value is the option Key of a run of Curiosity that does not give it,
%   as the curiosity's module sets it (its unsaid/2); fails when it does not.
curiosity_unsaid(C, Key, Value) :-
    curiosity_module(C, M),
    current_predicate(M:unsaid/2),
    M:unsaid(Key, Value),
    !.

%!  by_curiosity(+Settings:dict, +Goal) is semidet.
%
%   Call Goal, a predicate of the interface above, in the module of the
%   curiosity of Settings.
by_curiosity(Settings, Goal) :-
    curiosity_module(Settings.curiosity, Module),
    !,
    call(Module:Goal).

%   load_curiosities: load the module of each value of the one list, the
%   file of its name beside this one.
load_curiosities :-
    prolog_load_context(directory, Dir),
    defaults:option(curiosity, choice, Range, _, _),
    Range =.. [one_of|Curiosities],
    forall(member(C, Curiosities),
           ( directory_file_path(Dir, C, File), load_curiosity(C, File) )).

:- load_curiosities.
