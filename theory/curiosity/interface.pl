:- module(curiosity_interface,
          [ by_curiosity/2,           % +Settings, +Goal
            curiosity_module/2        % ?Curiosity, ?Module
          ]).
/** <module> The curiosities: one module each, behind one interface

Each curiosity (option curiosity/1) is one module, named here once
(curiosity_module/2): the loop (loop.pl), the probes (probe.pl) and
explore/1 (run.pl) ask the run's curiosity through by_curiosity/2,
and nowhere else is a curiosity named. A curiosity's module defines these
predicates (unexported; called as Module:Goal):

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
    header of the second layer.

The modules: learn.pl (`learn`), discover.pl (`discover`), paper.pl
(`paper`).
*/

:- use_module(learn).
:- use_module(discover).
:- use_module(paper).

%!  curiosity_module(?Curiosity:atom, ?Module:atom) is nondet.
%
%   Module implements Curiosity, a value of the option curiosity/1.
curiosity_module(learn, curiosity_learn).
curiosity_module(discover, curiosity_discover).
curiosity_module(paper, curiosity_paper).

%!  by_curiosity(+Settings:dict, +Goal) is semidet.
%
%   Call Goal, a predicate of the interface above, in the module of the
%   curiosity of Settings.
by_curiosity(Settings, Goal) :-
    curiosity_module(Settings.curiosity, Module),
    !,
    call(Module:Goal).
