"""Reasoning with a theory: the defeasible conclusions (Prolog or clingo),
answers to questions (what happens, why, why not), plans of pouring
manners, the validity of scenes, and reading questions written in words."""
