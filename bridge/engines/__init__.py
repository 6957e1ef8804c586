"""The two reasoning engines hosted in this process: SWI-Prolog through
pyswip (`swipl`) and clingo (`asp`). Everything that starts an engine, loads
the theory's modules into it or builds a clingo control goes through here."""
